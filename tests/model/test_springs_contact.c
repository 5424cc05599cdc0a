/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model's continuous contact (docs/models.md section 4.3): h continuous in x at
 * every vertex of seeded random obstacles, the QP's optimality conditions to round-off,
 * every ground vertex outside the tread, narrow features carried, dF_z/dz against finite
 * differences over roads, results that do not depend on the warm start nor on the factors
 * the solver keeps between solves, the confirming evaluation's update the QP's solution,
 * Newton's step on the working set the equilibrium where the update takes it, an
 * evaluation far from the last (Brent's bracket end) trying the closed form first, a
 * lone vertex's hub stiffness the same along the tread and the 1 mm second difference of h
 * over it. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testutil.h"
#include "model/springs_impl.h"
#include "tirenv/tirenv.h"

static uint64_t rng_state;
static double uniform(void) { return tirenv_test_uniform(&rng_state); }

/* A random obstacle of the kinds the issue names: cleat, step (up or down), blade (a cleat
 * a few mm wide), trapezoid, triangle. */
static tirenv_profile *random_obstacle(int kind)
{
    switch (kind % 5) {
    case 0:
        return tirenv_profile_cleat(0.02 + 0.4 * uniform(), 0.01 + 0.11 * uniform());
    case 1:
        return tirenv_profile_step(0.0, (uniform() < 0.5 ? -1 : 1) * (0.01 + 0.1 * uniform()));
    case 2:
        return tirenv_profile_cleat(0.001 + 0.004 * uniform(), 0.02 + 0.1 * uniform());
    case 3: {
        const double top = 0.05 + 0.2 * uniform();
        return tirenv_profile_trapezoid(top, top + 0.02 + 0.2 * uniform(),
                                        0.02 + 0.08 * uniform());
    }
    default:
        return tirenv_profile_triangle(0.05 + 0.3 * uniform(), 0.02 + 0.08 * uniform());
    }
}

/* A road: n vertices dx apart, a random walk of slopes (rough like an ISO class C-D road at
 * that spacing), plus a few spikes. */
static tirenv_profile *random_road(size_t n, double dx, int spikes)
{
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    double level = 0, slope = 0;
    for (size_t k = 0; k < n; ++k) {
        x[k] = -0.5 * (double)n * dx + (double)k * dx;
        slope = 0.97 * slope + 0.02 * (uniform() - 0.5);
        level += slope * dx;
        z[k] = level;
    }
    for (int s = 0; s < spikes; ++s) {
        const size_t k = 1 + (size_t)(uniform() * (double)(n - 2));
        z[k] += 0.005 + 0.03 * uniform();
    }
    tirenv_profile *p = tirenv_profile_alloc(n, x, z);
    free(x);
    free(z);
    return p;
}

static tirenv_tire continuous_tire(void)
{
    tirenv_tire t = tirenv_tire_default();
    t.springs.contact = TIRENV_SPRINGS_CONTINUOUS;
    return t;
}

/* The target: |h(x) - h(x +- 1e-12 m)| <= 1e-6 m at every edge. At every vertex X
 * of 40 seeded random obstacles, with the centre exactly over it and 1e-12 m either side,
 * at 13 kN; and at the two positions, where rays jumped by 6.8 and 0.95 mm. */
static void test_continuous_at_vertices(void **state)
{
    (void)state;
    rng_state = 20261205;
    const tirenv_tire t = continuous_tire();
    size_t checked = 0;
    double worst = 0;
    for (int trial = 0; trial < 40; ++trial) {
        tirenv_profile *p = random_obstacle(trial);
        tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
        tirenv_diag diag;
        assert_int_equal(tirenv_model_set(m, p, 13000, &diag), TIRENV_OK);
        const size_t n = tirenv_profile_size(p);
        const double *X = tirenv_profile_x(p);
        for (size_t k = 0; k < n; ++k) {
            tirenv_point a, b, c;
            assert_int_equal(tirenv_model_eval(m, X[k], &a, &diag), TIRENV_OK);
            assert_int_equal(tirenv_model_eval(m, X[k] - 1e-12, &b, &diag), TIRENV_OK);
            assert_int_equal(tirenv_model_eval(m, X[k] + 1e-12, &c, &diag), TIRENV_OK);
            worst = fmax(worst, fmax(fabs(a.h - b.h), fabs(a.h - c.h)));
            assert_near(a.h, b.h, 1e-6, 0);
            assert_near(a.h, c.h, 1e-6, 0);
            ++checked;
        }
        tirenv_model_free(m);
        tirenv_profile_free(p);
    }
    const double L[] = {0.30, 0.10}, H[] = {0.08, 0.10};
    const double x[2][2] = {{-0.15000000000000002, -0.15}, {-0.0500000000000001, -0.05}};
    for (int k = 0; k < 2; ++k) {
        tirenv_profile *p = tirenv_profile_cleat(L[k], H[k]);
        tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
        tirenv_diag diag;
        tirenv_point a, b;
        assert_int_equal(tirenv_model_set(m, p, 13000, &diag), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, x[k][0], &a, &diag), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, x[k][1], &b, &diag), TIRENV_OK);
        assert_near(a.h, b.h, 1e-6, 0);
        tirenv_model_free(m);
        tirenv_profile_free(p);
    }
    print_message("%zu vertices: largest |h(X) - h(X +- 1e-12)| %.3g m\n", checked, worst);
    assert_true(checked > 100);
}

/* The largest |h(b) - h(a)| left when [a, b] is bisected down to 1e-12 m, following the half
 * with the larger change: a jump survives, a continuous curve leaves ~slope * 1e-12. */
static double bisect_jump(tirenv_model *m, double a, double b, double ha, double hb)
{
    tirenv_diag diag;
    while (b - a > 1e-12) {
        const double c = 0.5 * (a + b);
        if (c <= a || c >= b)
            break;
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, c, &pt, &diag), TIRENV_OK);
        if (fabs(pt.h - ha) > fabs(hb - pt.h)) {
            b = c;
            hb = pt.h;
        } else {
            a = c;
            ha = pt.h;
        }
    }
    return fabs(hb - ha);
}

/* Sweeps of 0.5 mm over seeded random obstacles and roads: wherever h moves faster than a
 * slope of 0.4 between neighbours, the interval is bisected to 1e-12 m and what is left must be
 * under 1e-6 m. With rays the same search finds the jump on the 0.30 x 0.08 cleat
 * (the guard: the search does find jumps). */
static size_t largest_jump(const tirenv_tire *t, const tirenv_profile *p, double x0,
                           double x1, double *worst)
{
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, t);
    tirenv_diag diag;
    assert_int_equal(tirenv_model_set(m, p, 13000, &diag), TIRENV_OK);
    tirenv_point prev, pt;
    assert_int_equal(tirenv_model_eval(m, x0, &prev, &diag), TIRENV_OK);
    size_t searched = 0;
    *worst = 0;
    for (double x = x0 + 5e-4; x <= x1; x += 5e-4) {
        assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
        if (fabs(pt.h - prev.h) > 0.4 * 5e-4) {
            *worst = fmax(*worst, bisect_jump(m, x - 5e-4, x, prev.h, pt.h));
            ++searched;
            assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
        }
        prev = pt;
    }
    tirenv_model_free(m);
    return searched;
}

static void test_no_jumps_in_sweeps(void **state)
{
    (void)state;
    rng_state = 31337;
    tirenv_tire t = continuous_tire();
    size_t searched = 0;
    double worst_all = 0, worst;
    for (int trial = 0; trial < 8; ++trial) {
        tirenv_profile *p = trial < 5 ? random_obstacle(trial) : random_road(1500, 0.001, 2);
        searched += largest_jump(&t, p, -0.45, 0.45, &worst);
        worst_all = fmax(worst_all, worst);
        assert_true(worst <= 1e-6);
        tirenv_profile_free(p);
    }
    print_message("continuous: %zu fast intervals bisected, largest change left %.3g m\n",
                  searched, worst_all);
    tirenv_profile *cleat = tirenv_profile_cleat(0.30, 0.08);
    t.springs.contact = TIRENV_SPRINGS_RAYS;
    largest_jump(&t, cleat, -0.2, -0.1, &worst);
    print_message("rays over the 0.30 x 0.08 cleat: a jump of %.3g m\n", worst);
    assert_true(worst > 1e-4);
    tirenv_profile_free(cleat);
}

/* The rows' problem at a state, checked from outside the solver: the KKT conditions of
 * min 1/2 w^T K w subject to the rows, each between elements with its own compliance
 * (G w + C lambda >= h; primal and dual feasibility, complementarity,
 * stationarity over the whole tire with the free chains), and, independently of how the
 * rows were built, every ground vertex under the segment outside the tread (the tread at the
 * vertex's angle computed here from w and the weights). */
typedef struct {
    size_t N;
    double *diag, *lq, *rq, *L_D, *R_D, *d, *w, *pe, *ob, *Kw;
    tirenv_springs__cc_tire T;
    double *theta, *sin_t, *cos_t;
} tire_setup;

static void setup_tire(tire_setup *S, const tirenv_springs_params *par)
{
    const size_t i0 = (size_t)floor(0.5 * par->phi / par->dphi * (1 + 1e-12));
    const size_t N = 2 * i0 + 1;
    S->N = N;
    double **arrays[] = {&S->diag, &S->lq, &S->rq, &S->L_D, &S->R_D, &S->d, &S->pe,
                         &S->ob, &S->Kw, &S->theta, &S->sin_t, &S->cos_t};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; ++k)
        *arrays[k] = calloc(N, sizeof(double));
    S->w = calloc(N + 2, sizeof(double));
    const double k_r = par->c_r * par->dphi, k_ir = par->c_b / par->dphi;
    for (size_t i = 0; i < N; ++i) {
        S->theta[i] = ((double)i - (double)i0) * par->dphi;
        S->sin_t[i] = sin(S->theta[i]);
        S->cos_t[i] = cos(S->theta[i]);
        S->diag[i] = k_r + (double)((i > 0) + (i + 1 < N)) * k_ir;
    }
    for (size_t j = 0; j < N; ++j) {
        S->L_D[j] = j == 0 ? S->diag[0] : S->diag[j] - k_ir * k_ir / S->L_D[j - 1];
        S->lq[j] = k_ir / S->L_D[j];
    }
    for (size_t j = N; j-- > 0;) {
        S->R_D[j] = j == N - 1 ? S->diag[j] : S->diag[j] - k_ir * k_ir / S->R_D[j + 1];
        S->rq[j] = k_ir / S->R_D[j];
    }
    S->T = (tirenv_springs__cc_tire){.N = N, .i0 = i0, .R0 = par->R0, .k_r = k_r,
                                     .k_ir = k_ir, .sin_t = S->sin_t, .cos_t = S->cos_t, .diag = S->diag,
                                     .lq = S->lq, .rq = S->rq};
    tirenv_springs__cc_tire_shape(&S->T);
}

/* The penetrations d[0..N) at (x, z) from single rays (the reference caster), and, when dd is
 * not NULL, their slopes dd[i] = d(d_i)/dz (0 where a ray misses the ground). */
static void cast_rays(const tire_setup *S, const tirenv_profile *p, double x, double z,
                      double R0, double d[], double dd[])
{
    for (size_t i = 0; i < S->N; ++i) {
        double dr;
        const double rho = tirenv_springs__ray(p, x, z, S->sin_t[i], S->cos_t[i], R0, &dr);
        d[i] = rho < R0 ? R0 - rho : 0;
        if (dd)
            dd[i] = rho < R0 ? -dr : 0;
    }
}

static void free_tire(tire_setup *S)
{
    double *arrays[] = {S->diag, S->lq, S->rq, S->L_D, S->R_D, S->d, S->pe,
                        S->ob, S->Kw, S->theta, S->sin_t, S->cos_t, S->w};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; ++k)
        free(arrays[k]);
}

static void test_kkt_conditions(void **state)
{
    (void)state;
    rng_state = 777;
    size_t states = 0, active_rows = 0, coupled = 0, forced = 0;
    double worst = 0; /* the deepest a vertex lies inside the tread, m */
    for (int trial = 0; trial < 400; ++trial) {
        tirenv_springs_params par = continuous_tire().springs;
        par.c_b *= pow(10, -2 + 4 * uniform());
        par.dphi = M_PI / (90 + floor(600 * uniform()));
        tire_setup S;
        setup_tire(&S, &par);
        const size_t N = S.N;
        tirenv_profile *p = trial % 2 ? random_road(200 + (size_t)(2000 * uniform()),
                                                    0.0005 + 0.01 * uniform(), trial % 3)
                                      : random_obstacle(trial / 2);
        const double x = -0.3 + 0.6 * uniform();
        const double g = tirenv_profile_max_height(p, x - 0.7, x + 0.7);
        const double z = g + par.R0 - 0.02 - 0.1 * uniform();
        cast_rays(&S, p, x, z, par.R0, S.d, NULL);
        tirenv_springs__cc c;
        assert_int_equal(tirenv_springs__cc_init(&c, N), TIRENV_OK);
        tirenv_diag diag;
        int st = tirenv_springs__cc_rows(&c, &S.T, p, x, z, 0, N - 1, S.d, &diag);
        if (!st)
            st = tirenv_springs__cc_solve(&c, &S.T, x, z, S.w + 1, S.pe, S.ob, &diag);
        if (st)
            print_error("%s\n", diag.message);
        assert_int_equal(st, TIRENV_OK);
        ++states;
        forced += c.n_forced > 0; /* a row the hull dropped was violated and added */
        double *w = S.w + 1;
        if (c.f0 <= c.f1) {
            /* The whole tire: the free chains carried out to both ends. */
            for (size_t j = c.f0; j-- > 0;)
                w[j] = S.lq[j] * w[j + 1];
            for (size_t j = c.f1 + 1; j < N; ++j)
                w[j] = S.rq[j] * w[j - 1];
            double w_max = 0, l_max = 0;
            for (size_t i = 0; i < N; ++i)
                w_max = fmax(w_max, fabs(w[i]));
            memset(S.Kw, 0, N * sizeof *S.Kw);
            for (size_t r = 0; r < c.n_rows; ++r) {
                const tirenv_springs__cc_row *R = &c.rows[r];
                const double lam = c.lambda[r];
                /* a row between elements with its own compliance (section 4.8) */
                const double s = R->ga * w[R->i] + (R->t > 0 ? R->gb * w[R->j] : 0) +
                                 R->cmp * lam - R->h;
                l_max = fmax(l_max, lam);
                assert_true(s >= -1e-12 * par.R0);           /* primal feasibility */
                assert_true(lam >= 0);                        /* dual feasibility */
                assert_true(lam * s <= 1e-12 * par.R0 * (lam + 1)); /* complementarity */
                if (lam > 0) {
                    ++active_rows;
                    coupled += R->t > 0;
                }
                S.Kw[R->i] += R->ga * lam;
                if (R->t > 0)
                    S.Kw[R->j] += R->gb * lam;
            }
            /* Stationarity: K w = G^T lambda over all N elements. */
            for (size_t i = 0; i < N; ++i) {
                const double Kw = S.diag[i] * w[i] - S.T.k_ir * ((i > 0 ? w[i - 1] : 0) +
                                                                 (i + 1 < N ? w[i + 1] : 0));
                assert_near(Kw, S.Kw[i], 1e-9 * (l_max + S.diag[i] * w_max) + 1e-9, 0);
            }
        } else {
            for (size_t i = 0; i < N; ++i)
                w[i] = 0;
        }
        /* Every vertex below the centre within R0 and inside the segment: outside the tread,
         * R0 - (a w_i + b w_(i+1) + c lambda) at its angle (a, b the weights at its chord
         * parameter, c lambda the row's own compliance times its reaction where the vertex
         * is a row between elements, else 0). */
        const double *X = tirenv_profile_x(p), *Z = tirenv_profile_z(p);
        double *own = calloc(tirenv_profile_size(p), sizeof *own);
        assert_non_null(own);
        for (size_t r = 0; r < c.n_rows; ++r)
            if (c.rows[r].id >= 0 && c.rows[r].t > 0)
                own[c.rows[r].id] = c.rows[r].cmp * c.lambda[r];
        for (size_t k = 0; k < tirenv_profile_size(p); ++k) {
            const double dx = X[k] - x, dz = z - Z[k], rho = hypot(dx, dz);
            if (!(dz > 0) || !(rho < par.R0))
                continue;
            const double psi = atan2(dx, dz);
            const double u = psi / par.dphi + (double)S.T.i0;
            if (u < 0 || u > (double)(N - 1))
                continue;
            size_t i = (size_t)floor(u);
            if (i == N - 1)
                i = N - 2;
            const double s_i = sin(psi - S.theta[i]), s_n = sin(S.theta[i + 1] - psi);
            const double t = s_i / (s_i + s_n);
            double a, b, da, db;
            tirenv_springs__cc_weights(&S.T, t, &a, &b, &da, &db);
            const double tread = a * w[i] + b * w[i + 1] + own[k];
            /* Round-off (1e-12 R0, the solver's tolerance), and where the vertex lies within
             * the snap of an element (t_snap = 1e-6 in springs_rows.c; 2e-6 here, for this
             * t's own rounding) the tread's move over it, t_snap |w_(i+1) - w_i|: its row is
             * the element's. */
            const double snap = t < 2e-6 || t > 1 - 2e-6 ? 1e-6 * fabs(w[i + 1] - w[i]) : 0;
            worst = fmax(worst, par.R0 - rho - tread);
            assert_true(tread >= par.R0 - rho - 1e-12 * par.R0 - snap);
        }
        free(own);
        /* The model's forces, which solve the elements' own rows first and the QP only if a
         * row between elements fails there: the QP's, to round-off. */
        double Fz = 0, Fx = 0, fx, fz;
        for (size_t i = 0; i < N; ++i) {
            Fz += S.T.k_r * w[i] * S.cos_t[i];
            Fx -= S.T.k_r * w[i] * S.sin_t[i];
        }
        tirenv_springs *model = tirenv_springs_alloc(&par);
        assert_int_equal(tirenv_springs_forces(model, p, x, z, &fx, &fz, NULL, NULL, NULL), 0);
        assert_near(fz, Fz, 1e-9 * fabs(Fz) + 1e-6, 0);
        assert_near(fx, Fx, 1e-9 * fabs(Fz) + 1e-6, 0);
        tirenv_springs_free(model);
        tirenv_springs__cc_free(&c);
        tirenv_profile_free(p);
        free_tire(&S);
    }
    print_message("%zu states, %zu active rows, %zu of them between two elements; %zu states "
                  "with a row under the hull added; deepest vertex %.3g m inside the tread\n",
                  states, active_rows, coupled, forced, worst);
    assert_true(coupled > 100); /* the guard: coupled rows really were exercised */
    assert_true(forced > 0);    /* and a row under the hull that binds (draw 147) */
}

/* A needle and a 4 mm plate, which rays refuse (they slip between them), are carried by the
 * tread: h > 0 over them and never above the rigid disc's, which follows them exactly. */
static void test_narrow_features_carried(void **state)
{
    (void)state;
    const tirenv_tire t = continuous_tire();
    const double widths[] = {1e-9, 0.004};
    for (int k = 0; k < 2; ++k) {
        tirenv_profile *p = tirenv_profile_cleat(widths[k], 0.1);
        tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
        tirenv_diag diag;
        assert_int_equal(tirenv_model_set(m, p, 13000, &diag), TIRENV_OK);
        for (double x = -0.3; x <= 0.3; x += 0.0037) {
            tirenv_point pt;
            assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
            const double rigid = tirenv_rigid_height(p, t.springs.R0, x, NULL, NULL);
            assert_true(pt.z <= rigid);
            if (fabs(x) < 0.1)
                assert_true(pt.h > 0.03);
        }
        tirenv_model_free(m);
        tirenv_profile_free(p);
    }
}

/* dF_z/dz is exact on the piece (active set fixed) with rows whose weights move with z:
 * against a central difference over random roads, where one-sided differences agree (a kink
 * inside [z - h, z + h] is skipped). */
static void test_derivative_on_roads(void **state)
{
    (void)state;
    rng_state = 4242;
    const tirenv_tire t = continuous_tire();
    size_t checked = 0;
    for (int trial = 0; trial < 30; ++trial) {
        tirenv_profile *p = random_road(2000, 0.001, trial % 4);
        tirenv_springs *s = tirenv_springs_alloc(&t.springs);
        for (int k = 0; k < 20; ++k) {
            const double x = -0.3 + 0.6 * uniform();
            const double z = tirenv_profile_height(p, x) + 0.6 + 0.07 * uniform();
            double fx, F, dF, Fp, Fm, F0;
            assert_int_equal(tirenv_springs_forces(s, p, x, z, &fx, &F, &dF, NULL, NULL), 0);
            if (F < 10)
                continue;
            const double h = 1e-7;
            assert_int_equal(tirenv_springs_forces(s, p, x, z + h, &fx, &Fp, NULL, NULL, NULL), 0);
            assert_int_equal(tirenv_springs_forces(s, p, x, z - h, &fx, &Fm, NULL, NULL, NULL), 0);
            assert_int_equal(tirenv_springs_forces(s, p, x, z, &fx, &F0, NULL, NULL, NULL), 0);
            assert_true(dF <= 0);
            assert_true(Fp <= F0 && F0 <= Fm);
            const double fwd = (Fp - F0) / h, bwd = (F0 - Fm) / h;
            if (fabs(fwd - bwd) > 1e-6 * fabs(dF))
                continue;
            /* truncation ~ h^2 F''' and round-off ~ 1e-16 F / h: far below 1e-6 relative */
            assert_near(dF, (Fp - Fm) / (2 * h), 1e-6 * fabs(dF), 0);
            ++checked;
        }
        tirenv_springs_free(s);
        tirenv_profile_free(p);
    }
    print_message("%zu derivatives checked\n", checked);
    assert_true(checked > 300);
}

/* The result depends on the final active set only, not on the warm start: a sweep's every
 * position evaluated again by a fresh model gives the same forces, to round-off: a position
 * the start at a new x settled (springs.c, tirenv_springs__start) reports the update's state
 * on the last position's working set, the QP's solution to some 1e-14 R0 in w (its own
 * arithmetic, not the closed form's), so within 1e-9 of F_z as the root's test allows. */
static void test_warm_start_invisible(void **state)
{
    (void)state;
    rng_state = 99;
    const tirenv_tire t = continuous_tire();
    tirenv_profile *p = random_road(3000, 0.001, 3);
    tirenv_model *warm = tirenv_model_alloc(tirenv_model_springs, &t);
    tirenv_diag diag;
    assert_int_equal(tirenv_model_set(warm, p, 15000, &diag), TIRENV_OK);
    for (double x = -0.4; x <= 0.4; x += 0.0231) {
        tirenv_point a, b;
        assert_int_equal(tirenv_model_eval(warm, x, &a, &diag), TIRENV_OK);
        tirenv_springs *cold = tirenv_springs_alloc(&t.springs);
        double fx, fz, dfz;
        assert_int_equal(tirenv_springs_forces(cold, p, x, a.z, &fx, &fz, &dfz, NULL, NULL), 0);
        b.fx = fx;
        b.fz = fz;
        assert_near(a.fz, b.fz, 1e-9 * fabs(b.fz), 0);
        assert_near(a.fx, b.fx, 1e-9 * fabs(b.fz), 0);
        tirenv_springs_free(cold);
    }
    tirenv_model_free(warm);
    tirenv_profile_free(p);
}

/* A ray's d(rho)/dz kept with the face its walk ended on and taken again at the next x
 * (springs.c, ray_drho; docs/models.md section 4.8, Faces kept) is the one computed afresh: two
 * models evaluated at the same states, one of which forgets its faces before each, give the
 * same bits (F_z, F_x, dF_z/dz, the contacts). Sweeps every 1 mm over seeded random obstacles
 * and a road, each interrupted by a few positions on another profile (the faces kept belong
 * to the profile, and must be forgotten with it), at two heights a position. */
static void test_faces_kept_invisible(void **state)
{
    (void)state;
    rng_state = 4711;
    const tirenv_tire t = continuous_tire();
    tirenv_springs *kept = tirenv_springs_alloc(&t.springs);
    tirenv_springs *fresh = tirenv_springs_alloc(&t.springs);
    assert_non_null(kept);
    assert_non_null(fresh);
    size_t states = 0;
    for (int trial = 0; trial < 12; ++trial) {
        tirenv_profile *p = trial == 11 ? random_road(1500, 0.001, 2) : random_obstacle(trial);
        tirenv_profile *other = random_obstacle(trial + 1);
        const double x0 = -0.5 + 0.3 * uniform(), sink = 0.02 + 0.05 * uniform();
        for (int k = 0; k < 300; ++k) {
            const int away = k % 100 >= 95;
            const tirenv_profile *q = away ? other : p;
            const double x = x0 + 0.001 * k;
            const double g = tirenv_profile_max_height(q, x - 0.3, x + 0.3);
            for (int h = 0; h < 2; ++h) {
                const double z = g + t.springs.R0 - sink + 1.37e-5 * h;
                double fx[2], fz[2], dfz[2];
                size_t n[2];
                tirenv_springs__faces_forget(fresh);
                assert_int_equal(tirenv_springs_forces(kept, q, x, z, &fx[0], &fz[0], &dfz[0],
                                                       &n[0], NULL), TIRENV_OK);
                assert_int_equal(tirenv_springs_forces(fresh, q, x, z, &fx[1], &fz[1],
                                                       &dfz[1], &n[1], NULL), TIRENV_OK);
                assert_memory_equal(&fz[0], &fz[1], sizeof fz[0]);
                assert_memory_equal(&fx[0], &fx[1], sizeof fx[0]);
                assert_memory_equal(&dfz[0], &dfz[1], sizeof dfz[0]);
                assert_int_equal(n[0], n[1]);
                ++states;
            }
        }
        tirenv_profile_free(other);
        tirenv_profile_free(p);
    }
    print_message("%zu states, %zu d(rho)/dz from the faces kept\n", states,
                  tirenv_springs__face_hits(kept));
    assert_int_equal(tirenv_springs__face_hits(fresh), 0);
    assert_true(tirenv_springs__face_hits(kept) > states);
    tirenv_springs_free(kept);
    tirenv_springs_free(fresh);
}

/* The solver keeps K_FF's factor and the KKT layout from one solve to the next while the rows
 * and the working set stay (the confirming evaluation a hair above, the next millimetre):
 * what it then computes must be the bits a fresh workspace computes, the same final active
 * set solved by the same arithmetic. Sweeps over seeded random obstacles, two heights a
 * position, one workspace kept against a fresh one at every state: w, the reactions and
 * dw/dz compared exactly (==: a zero's sign aside). */
static void test_kept_factor_invisible(void **state)
{
    (void)state;
    rng_state = 4242;
    size_t states = 0, between = 0, kept = 0;
    const tirenv_springs_params par = continuous_tire().springs;
    tire_setup S;
    setup_tire(&S, &par);
    const size_t N = S.N;
    double *w_cold = calloc(N + 2, sizeof *w_cold), *dd = calloc(N, sizeof *dd);
    double *dw_hot = calloc(N, sizeof *dw_hot), *dw_cold = calloc(N, sizeof *dw_cold);
    double *pe_cold = calloc(N, sizeof *pe_cold), *ob_cold = calloc(N, sizeof *ob_cold);
    assert_non_null(w_cold);
    assert_non_null(dd);
    assert_non_null(dw_hot);
    assert_non_null(dw_cold);
    assert_non_null(pe_cold);
    assert_non_null(ob_cold);
    for (int trial = 0; trial < 30; ++trial) {
        tirenv_profile *p = random_obstacle(trial % 2 ? 0 : trial / 2);
        tirenv_springs__cc hot;
        assert_int_equal(tirenv_springs__cc_init(&hot, N), TIRENV_OK);
        const double x0 = -0.45 + 0.4 * uniform(), dz = 0.02 + 0.06 * uniform();
        for (int k = 0; k < 120; ++k) {
            const double x = x0 + 0.004 * k;
            const double g = tirenv_profile_max_height(p, x - 0.3, x + 0.3);
            for (int confirm = 0; confirm < 2; ++confirm) {
                const double z = g + par.R0 - dz + (confirm ? 1e-9 : 0);
                cast_rays(&S, p, x, z, par.R0, S.d, dd);
                tirenv_springs__cc cold;
                assert_int_equal(tirenv_springs__cc_init(&cold, N), TIRENV_OK);
                tirenv_diag diag;
                assert_int_equal(tirenv_springs__cc_rows(&hot, &S.T, p, x, z, 0, N - 1, S.d,
                                                         &diag), TIRENV_OK);
                assert_int_equal(tirenv_springs__cc_rows(&cold, &S.T, p, x, z, 0, N - 1, S.d,
                                                         &diag), TIRENV_OK);
                const int st_hot = tirenv_springs__cc_solve(&hot, &S.T, x, z, S.w + 1, S.pe,
                                                            S.ob, &diag);
                const int st_cold = tirenv_springs__cc_solve(&cold, &S.T, x, z, w_cold + 1,
                                                             pe_cold, ob_cold, &diag);
                assert_int_equal(st_hot, st_cold);
                if (st_hot == TIRENV_OK && hot.f0 <= hot.f1) {
                    ++states;
                    between += hot.n_warm > 0;
                    kept += hot.factor_kept && hot.use_schur;
                    tirenv_springs__cc_slope(&hot, &S.T, S.w + 1, dd, dw_hot);
                    tirenv_springs__cc_slope(&cold, &S.T, w_cold + 1, dd, dw_cold);
                    for (size_t e = hot.f0; e <= hot.f1; ++e) {
                        assert_true(S.w[e + 1] == w_cold[e + 1]);
                        assert_true(S.pe[e] == pe_cold[e]);
                        assert_true(dw_hot[e] == dw_cold[e]);
                    }
                    for (size_t r = 0; r < hot.n_rows; ++r)
                        assert_true(hot.lambda[r] == cold.lambda[r]);
                }
                tirenv_springs__cc_free(&cold);
            }
        }
        tirenv_springs__cc_free(&hot);
        tirenv_profile_free(p);
    }
    print_message("%zu states, %zu with a row between elements working, %zu on a kept "
                  "factor\n", states, between, kept);
    /* The path under test taken: rows between elements working, factors kept. */
    assert_true(between > 200);
    assert_true(kept > 200);
    free(w_cold);
    free(dd);
    free(dw_hot);
    free(dw_cold);
    free(pe_cold);
    free(ob_cold);
    free_tire(&S);
}

/* Newton's confirming evaluation by the last solve's tangent (tirenv_springs__cc_update,
 * docs/models.md section 4.8, The confirming evaluation): a state it accepts at z0 + dz is the QP's
 * solution there, the one a fresh workspace finds by building the rows and solving (the QP is
 * strictly convex: its KKT point is unique, so a wrong acceptance would show as a different w).
 * Seeded random obstacles and roads, dz from 1e-10 to 1e-6 m either way; w within 1e-13 R0
 * (a few hundred units of round-off of w: the update's KKT residuals are held to 1e-14 R0)
 * and each element's reaction within 1e-9 of the largest (round-off of sums over tens of
 * elements, as test_springs_solve's kept state allows), and its count of the elements pressed
 * that of its pe > 0. Most states taken, and a step past the update's reach refused. */
static void test_update_is_the_solution(void **state)
{
    (void)state;
    rng_state = 2718;
    size_t states = 0, accepted = 0, between = 0;
    double worst_w = 0, worst_pe = 0;
    const tirenv_springs_params par = continuous_tire().springs;
    tire_setup S;
    setup_tire(&S, &par);
    const size_t N = S.N;
    double *dd = calloc(N, sizeof *dd), *dw = calloc(N, sizeof *dw);
    double *d1 = calloc(N, sizeof *d1), *w_up = calloc(N + 2, sizeof *w_up);
    double *pe_up = calloc(N, sizeof *pe_up), *ob_up = calloc(N, sizeof *ob_up);
    double *w_cold = calloc(N + 2, sizeof *w_cold), *pe_cold = calloc(N, sizeof *pe_cold);
    double *ob_cold = calloc(N, sizeof *ob_cold);
    assert_true(dd && dw && d1 && w_up && pe_up && ob_up && w_cold && pe_cold && ob_cold);
    for (int trial = 0; trial < 40; ++trial) {
        tirenv_profile *p = trial % 4 == 3 ? random_road(1500, 0.001, 2)
                                           : random_obstacle(trial);
        tirenv_springs__cc hot;
        assert_int_equal(tirenv_springs__cc_init(&hot, N), TIRENV_OK);
        const double x0 = -0.45 + 0.4 * uniform(), sink = 0.02 + 0.06 * uniform();
        for (int k = 0; k < 60; ++k) {
            const double x = x0 + 0.0137 * k;
            const double g = tirenv_profile_max_height(p, x - 0.3, x + 0.3);
            const double z0 = g + par.R0 - sink;
            cast_rays(&S, p, x, z0, par.R0, S.d, dd);
            tirenv_diag diag;
            assert_int_equal(tirenv_springs__cc_rows(&hot, &S.T, p, x, z0, 0, N - 1, S.d,
                                                     &diag), TIRENV_OK);
            if (tirenv_springs__cc_solve(&hot, &S.T, x, z0, S.w + 1, S.pe, S.ob, &diag) ||
                hot.f0 > hot.f1)
                continue;
            assert_int_equal(tirenv_springs__cc_slope(&hot, &S.T, S.w + 1, dd, dw), TIRENV_OK);
            /* the base, as springs.c sets it */
            memcpy(hot.base_w + hot.f0, S.w + hot.f0, (hot.f1 - hot.f0 + 3) * sizeof *S.w);
            hot.base_z = z0;
            hot.base_ok = 1;
            const double dz = (uniform() < 0.5 ? -1 : 1) * pow(10, -10 + 4 * uniform());
            const double z1 = z0 + dz;
            cast_rays(&S, p, x, z1, par.R0, d1, NULL);
            const size_t f0 = hot.f0, f1 = hot.f1;
            const int took = hot.use_schur && hot.n_warm > 0; /* the states the update is for */
            ++states;
            /* past its reach the update does not try */
            hot.base_z = z0 + 2e-6;
            size_t contacts = SIZE_MAX;
            assert_int_equal(tirenv_springs__cc_update(&hot, &S.T, p, x, z1, 0, N - 1, d1, dw,
                                                       w_up + 1, pe_up, ob_up, &contacts), 0);
            hot.base_z = z0;
            if (!tirenv_springs__cc_update(&hot, &S.T, p, x, z1, 0, N - 1, d1, dw, w_up + 1,
                                           pe_up, ob_up, &contacts))
                continue;
            /* its count of the elements pressed: those of its pe > 0, as the hub's pass
             * counts them */
            size_t pressed = 0;
            for (size_t e = f0; e <= f1; ++e)
                pressed += pe_up[e] > 0;
            assert_int_equal(contacts, pressed);
            ++accepted;
            between += took;
            tirenv_springs__cc cold;
            assert_int_equal(tirenv_springs__cc_init(&cold, N), TIRENV_OK);
            assert_int_equal(tirenv_springs__cc_rows(&cold, &S.T, p, x, z1, 0, N - 1, d1,
                                                     &diag), TIRENV_OK);
            assert_int_equal(tirenv_springs__cc_solve(&cold, &S.T, x, z1, w_cold + 1, pe_cold,
                                                      ob_cold, &diag), TIRENV_OK);
            /* the same span: no row came or went at its ends */
            assert_true(cold.f0 == f0 && cold.f1 == f1);
            double pe_max = 0;
            for (size_t e = f0; e <= f1; ++e)
                pe_max = fmax(pe_max, fabs(pe_cold[e]));
            for (size_t e = f0 - (f0 > 0); e <= f1 + 1 && e < N; ++e) {
                const double dw_e = fabs(w_up[e + 1] - w_cold[e + 1]);
                worst_w = fmax(worst_w, dw_e);
                assert_true(dw_e <= 1e-13 * par.R0);
            }
            for (size_t e = f0; e <= f1; ++e) {
                const double dp = fabs(pe_up[e] - pe_cold[e]);
                worst_pe = fmax(worst_pe, dp / pe_max);
                assert_true(dp <= 1e-9 * pe_max);
                assert_true((pe_up[e] > 0) == (pe_cold[e] > 0) || dp <= 1e-9 * pe_max);
                assert_true(ob_up[e] == ob_cold[e]);
            }
            tirenv_springs__cc_free(&cold);
        }
        tirenv_springs__cc_free(&hot);
        tirenv_profile_free(p);
    }
    print_message("%zu states: %zu updates accepted (%zu with a row between elements "
                  "working); w within %.3g m, reactions within %.3g of the largest\n", states,
                  accepted, between, worst_w, worst_pe);
    assert_true(accepted > states / 2);
    assert_true(between > 100);
    free(dd);
    free(dw);
    free(d1);
    free(w_up);
    free(pe_up);
    free(ob_up);
    free(w_cold);
    free(pe_cold);
    free(ob_cold);
    free_tire(&S);
}

/* A fresh model's forces at (x, z) on p against hot's, just evaluated there (fx_h, fz_h in N,
 * c_h contacts): F_z and F_x within 1e-9 of F_z (round-off of a state reached another way),
 * the same contacts, every tip within 1e-13 R0 (w_h, w_c: N doubles of room; *worst_w the
 * largest tip difference so far, m). Returns the fresh model's F_z (N). */
static double same_as_fresh(const tirenv_tire *t, tirenv_springs *hot, const tirenv_profile *p,
                            double x, double z, double fx_h, double fz_h, size_t c_h,
                            double w_h[], double w_c[], double *worst_w)
{
    tirenv_springs *cold = tirenv_springs_alloc(&t->springs);
    assert_non_null(cold);
    const size_t N = tirenv_springs_size(cold);
    double fx_c, fz_c, d_c;
    size_t c_c;
    assert_int_equal(tirenv_springs_forces(cold, p, x, z, &fx_c, &fz_c, &d_c, &c_c, NULL),
                     TIRENV_OK);
    assert_true(fabs(fz_h - fz_c) <= 1e-9 * fz_c);
    assert_true(fabs(fx_h - fx_c) <= 1e-9 * fz_c);
    assert_int_equal(c_h, c_c);
    tirenv_springs_tips(hot, NULL, w_h, NULL);
    tirenv_springs_tips(cold, NULL, w_c, NULL);
    for (size_t e = 0; e < N; ++e) {
        *worst_w = fmax(*worst_w, fabs(w_h[e] - w_c[e]));
        assert_true(fabs(w_h[e] - w_c[e]) <= 1e-13 * t->springs.R0);
    }
    tirenv_springs_free(cold);
    return fz_c;
}

/* Newton's step on the last QP solve's working set (tirenv_springs__root, springs_root.c;
 * docs/models.md section 4.8, Newton's step on the working set): after a full evaluation at z0, a
 * load G = F0 + dF0 dz, dz from 1e-6 to 1e-3 m either way. The workspace's own evaluation at the
 * height the root gives (the update from the root's state where its checks hold, else a full one)
 * gives a fresh model's forces (to 1e-9 of F_z, sums over some 360 elements) and tips (1e-13 R0, as
 * test_update_is_the_solution); where it was the update (the working set held), a fresh model's F_z
 * there is G to within 1e-6 N (against some 3e4 N: the root is taken to 1e-15 R0 in z, and F_z's
 * round-off is some 1e-9 N; the equilibrium's force tolerance, 1e-4 N by default, is a hundred
 * times looser). Where the working set changes on the way (a ray onto another face, a row coming or
 * going) the root is off, the update refuses it, and Newton goes on from the full evaluation.
 * Seeded random obstacles and roads; most roots taken. */
static void test_root_is_the_equilibrium(void **state)
{
    (void)state;
    rng_state = 31415;
    const tirenv_tire t = continuous_tire();
    const double R0 = t.springs.R0;
    tirenv_springs *probe = tirenv_springs_alloc(&t.springs);
    assert_non_null(probe);
    const size_t N = tirenv_springs_size(probe);
    tirenv_springs_free(probe);
    double *w_h = malloc(N * sizeof *w_h), *w_c = malloc(N * sizeof *w_c);
    assert_true(w_h && w_c);
    size_t tried = 0, found = 0, accepted = 0;
    double worst_F = 0, worst_w = 0;
    for (int trial = 0; trial < 40; ++trial) {
        tirenv_profile *p = trial % 4 == 3 ? random_road(1500, 0.001, 2)
                                           : random_obstacle(trial);
        tirenv_springs *hot = tirenv_springs_alloc(&t.springs);
        assert_non_null(hot);
        const double x0 = -0.45 + 0.4 * uniform(), sink = 0.02 + 0.06 * uniform();
        for (int k = 0; k < 40; ++k) {
            const double x = x0 + 0.0137 * k;
            const double g = tirenv_profile_max_height(p, x - 0.3, x + 0.3);
            const double z0 = g + R0 - sink;
            double fx, F0, dF0, z_r;
            size_t contacts;
            assert_int_equal(tirenv_springs_forces(hot, p, x, z0, &fx, &F0, &dF0, &contacts,
                                                   NULL), TIRENV_OK);
            const double dz = (uniform() < 0.5 ? -1 : 1) * pow(10, -6 + 3 * uniform());
            const double G = F0 + dF0 * dz;
            ++tried;
            if (!tirenv_springs__root(hot, p, x, z0, G, F0, dF0, &z_r))
                continue;
            ++found;
            double fx_h, fz_h, d_h;
            size_t c_h;
            const size_t updates = tirenv_springs__updates(hot);
            assert_int_equal(tirenv_springs_forces(hot, p, x, z_r, &fx_h, &fz_h, &d_h, &c_h,
                                                   NULL), TIRENV_OK);
            const int upd = tirenv_springs__updates(hot) > updates;
            const double fz_c = same_as_fresh(&t, hot, p, x, z_r, fx_h, fz_h, c_h, w_h, w_c,
                                              &worst_w);
            if (upd) { /* the root's state held: it was the QP's solution there */
                ++accepted;
                worst_F = fmax(worst_F, fabs(fz_c - G));
                assert_true(fabs(fz_c - G) <= 1e-6);
            }
        }
        tirenv_springs_free(hot);
        tirenv_profile_free(p);
    }
    print_message("%zu full evaluations: a root on the working set from %zu, the update "
                  "taken there %zu times, a fresh model's F_z within %.3g N of the load; the "
                  "tips within %.3g m\n", tried, found, accepted, worst_F, worst_w);
    assert_true(found > tried / 4);
    assert_true(accepted > found / 4);
    free(w_h);
    free(w_c);
}

/* At a new x the model proposes the height where F_z = G on the last QP solve's working set
 * (tirenv_springs__start, springs_root.c's tirenv_springs__cc_root_at): its evaluation there is the
 * update's check at that x, and where the update accepts it the state must be the QP's solution, so
 * a fresh model's F_z there within 1e-6 N of the load (as the root at the same x above; from the
 * closed form's pins the update is also tried where a held ray passed a vertex on the way, which
 * would leave F_z off the load by that ray's kink: not met on these seeds, and the forces are a
 * fresh model's either way); where it refuses (a contact that begins or ends, a vertex entering a
 * sector, a ray onto another face) the evaluation is the full one, so the forces and tips are a
 * fresh model's either way (1e-9 of F_z, 1e-13 R0 as above). Seeded random obstacles and roads,
 * steps of 0.5 to 3 mm, loads 1e-6 to 1e-3 m off the last evaluation; then a start 40 mm on, where
 * the working set cannot hold (each refused or, found, checked). The starts whose working rows
 * moved into the next sector (tirenv_springs__cc_rows_across: the crossed element let go, the
 * span grown), those that let a row go for a reaction below 0 at the root and those that
 * entered a vertex's row where it crossed a held element's ray (the element let go) are
 * counted, and must be taken by the update at some roots: their forces and tips checked as
 * every other. */
static void test_start_is_the_equilibrium(void **state)
{
    (void)state;
    rng_state = 27182;
    const tirenv_tire t = continuous_tire();
    const double R0 = t.springs.R0;
    tirenv_springs *probe = tirenv_springs_alloc(&t.springs);
    assert_non_null(probe);
    const size_t N = tirenv_springs_size(probe);
    tirenv_springs_free(probe);
    double *w_h = malloc(N * sizeof *w_h), *w_c = malloc(N * sizeof *w_c);
    assert_true(w_h && w_c);
    size_t tried = 0, found = 0, accepted = 0, refused = 0, far_found = 0, far_taken = 0;
    size_t sector = 0, sector_checked = 0;
    /* starts whose working rows moved into the next sector (found, and the update taken
     * there), and those that let a row go for a reaction below 0 */
    size_t across_found = 0, across_taken = 0, release_found = 0, release_taken = 0;
    size_t enter_found = 0, enter_taken = 0; /* a vertex's row entered at a held ray */
    int check_next = 0;
    double worst_F = 0, worst_w = 0;
    for (int trial = 0; trial < 40; ++trial) {
        tirenv_profile *p = trial % 4 == 3 ? random_road(1500, 0.001, 2)
                                           : random_obstacle(trial);
        tirenv_springs *hot = tirenv_springs_alloc(&t.springs);
        assert_non_null(hot);
        check_next = 0;
        const double x0 = -0.45 + 0.4 * uniform(), sink = 0.02 + 0.06 * uniform();
        double x = x0;
        for (int k = 0; k < 41; ++k) {
            const int far = k == 40; /* the last: 40 mm on */
            const double g = tirenv_profile_max_height(p, x - 0.3, x + 0.3);
            const double z0 = g + R0 - sink;
            double fx, F0, dF0;
            size_t contacts;
            assert_int_equal(tirenv_springs_forces(hot, p, x, z0, &fx, &F0, &dF0, &contacts,
                                                   NULL), TIRENV_OK);
            if (check_next) {
                same_as_fresh(&t, hot, p, x, z0, fx, F0, contacts, w_h, w_c, &worst_w);
                ++sector_checked;
                check_next = 0;
            }
            const double dz = (uniform() < 0.5 ? -1 : 1) * pow(10, -6 + 3 * uniform());
            const double G = F0 + dF0 * dz;
            x += far ? 0.04 : 0.0005 + 0.0025 * uniform();
            size_t s0, u0, s1, u1;
            tirenv_springs__start_counts(hot, &s0, &u0);
            const size_t sec0 = tirenv_springs__start_sector(hot);
            size_t ac0, re0, en0, ac1, re1, en1;
            tirenv_springs__start_moves(hot, &ac0, &re0, &en0);
            double z_s;
            ++tried;
            if (!tirenv_springs__start(hot, p, x, z0, G, &z_s)) {
                /* refused, a row's vertex gone into the next sector among the reasons: the
                 * next evaluation, at this x, is checked against a fresh model's */
                const size_t moved = tirenv_springs__start_sector(hot) - sec0;
                sector += moved;
                check_next = moved > 0;
                continue;
            }
            found += !far;
            far_found += far;
            tirenv_springs__start_moves(hot, &ac1, &re1, &en1);
            const int across = ac1 > ac0, release = re1 > re0, enter = en1 > en0;
            across_found += across;
            release_found += release;
            enter_found += enter;
            double fx_h, fz_h, d_h;
            size_t c_h;
            assert_int_equal(tirenv_springs_forces(hot, p, x, z_s, &fx_h, &fz_h, &d_h, &c_h,
                                                   NULL), TIRENV_OK);
            tirenv_springs__start_counts(hot, &s1, &u1);
            assert_int_equal(s1, s0 + 1);
            const int upd = u1 > u0;
            const double fz_c = same_as_fresh(&t, hot, p, x, z_s, fx_h, fz_h, c_h, w_h, w_c,
                                              &worst_w);
            if (upd) { /* the working set held at the new x: the QP's solution there */
                accepted += !far;
                far_taken += far;
                across_taken += across;
                release_taken += release;
                enter_taken += enter;
                worst_F = fmax(worst_F, fabs(fz_c - G));
                assert_true(fabs(fz_c - G) <= 1e-6);
            } else {
                refused += !far;
            }
        }
        tirenv_springs_free(hot);
        tirenv_profile_free(p);
    }
    print_message("%zu new positions: a root on the last working set at %zu, the update "
                  "taken there %zu times and refused %zu (40 mm on: %zu roots, %zu taken), a "
                  "fresh model's F_z within %.3g N of the load; the tips within %.3g m\n",
                  tried, found, accepted, refused, far_found, far_taken, worst_F, worst_w);
    print_message("%zu starts refused because a working row's vertex left its sector, the "
                  "evaluation after %zu of them a fresh model's\n", sector, sector_checked);
    print_message("a working row moved into the next sector at %zu roots (the update taken "
                  "at %zu), a row let go at %zu (taken at %zu), a vertex's row entered at a "
                  "held ray at %zu (taken at %zu)\n", across_found, across_taken,
                  release_found, release_taken, enter_found, enter_taken);
    assert_true(found > tried / 4);
    assert_true(accepted > found / 2);
    assert_true(refused > 0);
    /* the sector change exercised: rows moved into the next sector, and a row let go, each
     * at roots the update took (a fresh model's forces and tips above, F_z at the load) */
    assert_true(across_taken > 0);
    assert_true(release_taken > 0);
    assert_true(enter_taken > 0);
    /* and a start refused for a row's vertex gone past its sector, the next evaluation
     * checked against a fresh model's (46 such refusals, 23 checked, on these seeds) */
    assert_true(sector_checked > 0);
    free(w_h);
    free(w_c);
}

/* A working row between elements sends the next evaluation straight to the QP only near
 * its height (tirenv_springs__qp_first, docs/models.md section 11.2): Brent's bracket end,
 * the centre at the ground under it, tries the elements' own rows first, which hold there
 * (the flag is cleared), and gives the forces a fresh model finds, to round-off (1e-9 of
 * F_z: sums over some 360 elements, the closed form's against the QP's). Over the bench
 * cleat at the sinks of its equilibria; the saved state carries the flag's height. */
static void test_far_evaluation_tries_the_closed_form(void **state)
{
    (void)state;
    const tirenv_tire t = continuous_tire();
    const double R0 = t.springs.R0;
    tirenv_profile *p = tirenv_profile_cleat(0.30, 0.10);
    tirenv_springs *hot = tirenv_springs_alloc(&t.springs);
    assert_non_null(p);
    assert_non_null(hot);
    const size_t size = tirenv_springs__state_size(hot, 0);
    unsigned char *buf = malloc(size);
    assert_non_null(buf);
    size_t flagged = 0, far = 0;
    for (int k = 0; k < 60; ++k) {
        const double x = -0.35 + 0.0107 * k;
        const double g = tirenv_profile_max_height(p, x - R0, x + R0);
        const double z1 = g + R0 - 0.03 - 0.0005 * (k % 7);
        double fx, fz, dfz;
        size_t contacts;
        assert_int_equal(tirenv_springs_forces(hot, p, x, z1, &fx, &fz, &dfz, &contacts, NULL),
                         TIRENV_OK);
        if (!tirenv_springs__qp_first(hot, z1))
            continue;
        ++flagged;
        /* near: the flag stands; at the ground: it does not */
        assert_true(tirenv_springs__qp_first(hot, z1 + 0.04 * R0));
        const double z_far = tirenv_profile_height(p, x);
        assert_false(tirenv_springs__qp_first(hot, z_far));
        /* the state carries it: a model restored from it decides the same */
        tirenv_springs__state_save(hot, p, 0, buf);
        tirenv_springs *back = tirenv_springs_alloc(&t.springs);
        assert_non_null(back);
        assert_int_equal(tirenv_springs__state_restore(back, p, 0, buf), TIRENV_OK);
        assert_true(tirenv_springs__qp_first(back, z1 + 0.04 * R0));
        assert_false(tirenv_springs__qp_first(back, z_far));
        tirenv_springs_free(back);
        double fx_h, fz_h, fx_c, fz_c, d_h, d_c;
        size_t c_h, c_c;
        assert_int_equal(tirenv_springs_forces(hot, p, x, z_far, &fx_h, &fz_h, &d_h, &c_h,
                                               NULL), TIRENV_OK);
        tirenv_springs *cold = tirenv_springs_alloc(&t.springs);
        assert_non_null(cold);
        assert_int_equal(tirenv_springs_forces(cold, p, x, z_far, &fx_c, &fz_c, &d_c, &c_c,
                                               NULL), TIRENV_OK);
        tirenv_springs_free(cold);
        assert_true(fz_c > 0);
        assert_true(fabs(fz_h - fz_c) <= 1e-9 * fz_c);
        assert_true(fabs(fx_h - fx_c) <= 1e-9 * fz_c);
        assert_int_equal(c_h, c_c);
        /* the elements' own rows held: no row between elements is left working */
        far += !tirenv_springs__qp_first(hot, z_far);
    }
    print_message("%zu states with a row between elements working; at the ground under "
                  "the centre the closed form held in %zu\n", flagged, far);
    assert_true(flagged >= 10);
    assert_int_equal(far, flagged);
    free(buf);
    tirenv_springs_free(hot);
    tirenv_profile_free(p);
}

/* A lone sharp vertex meets the same hub stiffness anywhere along the tread (section 4.8):
 * the apex of a 0.2 x 0.08 m triangle (nothing else within R0), the centre 0.05 m inside
 * the free tread from it, on element i0's ray (t = 0) and a quarter, half and three quarters
 * of the way to the next. The resultant hub force is the same to 1e-4: what is left is the
 * cosine weighting of the chain's deflections, O(dphi^2) (measured under 2e-5). Without the
 * row's own compliance the tips carried (a + b) times the load: 0.50, 0.66 and 0.50 % more
 * at t = 1/4, 1/2, 3/4, the cause of a 0.40 mm ripple of h at the element spacing. */
static void test_lone_vertex_stiffness(void **state)
{
    (void)state;
    const tirenv_tire t = continuous_tire();
    tirenv_profile *p = tirenv_profile_triangle(0.2, 0.08);
    tirenv_springs *s = tirenv_springs_alloc(&t.springs);
    assert_non_null(s);
    const double rho = t.springs.R0 - 0.05, dphi = t.springs.dphi;
    double F0 = 0;
    for (int q = 0; q <= 3; ++q) {
        const double psi = 0.25 * q * dphi; /* the apex's angle from the centre */
        const double x = -rho * sin(psi), z = 0.08 + rho * cos(psi);
        double fx, fz;
        size_t contacts;
        assert_int_equal(tirenv_springs_forces(s, p, x, z, &fx, &fz, NULL, &contacts, NULL), 0);
        assert_true(contacts <= 2); /* the apex alone: on one element or two */
        const double F = hypot(fx, fz);
        if (q == 0) {
            F0 = F;
            continue;
        }
        print_message("t = %.2f: hub force %.6f of the element's\n", 0.25 * q, F / F0);
        assert_near(F / F0, 1, 1e-4, 0);
    }
    tirenv_springs_free(s);
    tirenv_profile_free(p);
}

/* h over x from -0.5 m to 0.5 m every 1 mm (n = 1001) at 13 kN, for tire t over p. */
static double *sweep_1mm(const tirenv_tire *t, const tirenv_profile *p)
{
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, t);
    tirenv_diag diag;
    assert_int_equal(tirenv_model_set(m, p, 13000, &diag), TIRENV_OK);
    double *h = malloc(1001 * sizeof *h);
    assert_non_null(h);
    for (size_t j = 0; j < 1001; ++j) {
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, -0.5 + 0.001 * (double)j, &pt, &diag), TIRENV_OK);
        h[j] = pt.h;
    }
    tirenv_model_free(m);
    return h;
}

/* The target (models.md 4.8): on a 1 mm sweep at 13 kN the second difference of h
 * stays below 0.2 mm away from the obstacle's edges (positions within 3 mm of a vertex's x
 * left out), over the two obstacles whose lone corner or apex carried the load: the
 * 0.2 x 0.08 m triangle and the 0.30 x 0.08 m cleat. Without the rows' own compliance
 * 0.53 mm at both. What is left is a kink of the curve itself where a contact starts or the
 * tread leaves the ground (the triangle's 0.19 mm at x = -0.169 m at half and a quarter of
 * the element angle alike): where the curve at half the element angle has a second
 * difference of 0.15 mm or more, the staircase the target is about is what the elements add
 * to it, asked below 0.05 mm (a 0.1 mm staircase fails). */
static void test_second_difference_lone_vertex(void **state)
{
    (void)state;
    const tirenv_tire t = continuous_tire();
    tirenv_tire half = t;
    half.springs.dphi = 0.5 * t.springs.dphi;
    tirenv_profile *obstacles[2] = {tirenv_profile_triangle(0.2, 0.08),
                                    tirenv_profile_cleat(0.30, 0.08)};
    const double vertices[2][3] = {{-0.1, 0, 0.1}, {-0.15, 0.15, 0.15}};
    for (int k = 0; k < 2; ++k) {
        double *h = sweep_1mm(&t, obstacles[k]), *h2 = sweep_1mm(&half, obstacles[k]);
        double worst = 0, at = 0, worst_kink = 0;
        size_t checked = 0, kinks = 0;
        for (size_t j = 1; j + 1 < 1001; ++j) {
            const double x = -0.5 + 0.001 * (double)j;
            int near = 0;
            for (int v = 0; v < 3; ++v)
                near |= fabs(x - vertices[k][v]) <= 0.003 + 1e-9;
            if (near)
                continue;
            const double d2 = fabs(h[j - 1] - 2 * h[j] + h[j + 1]);
            const double d2_half = fabs(h2[j - 1] - 2 * h2[j] + h2[j + 1]);
            if (d2_half >= 0.15e-3) { /* a kink of the converged curve */
                ++kinks;
                worst_kink = fmax(worst_kink, fabs(d2 - d2_half));
            } else if (d2 > worst) {
                worst = d2;
                at = x;
            }
            ++checked;
        }
        print_message("%s: largest second difference %.4f mm at x = %.3f m (%zu positions); "
                      "%zu at kinks of the curve, the elements adding at most %.4f mm\n",
                      k == 0 ? "triangle 0.2 x 0.08" : "cleat 0.30 x 0.08", worst * 1e3, at,
                      checked, kinks, worst_kink * 1e3);
        assert_true(checked > 950);
        assert_true(kinks <= 4);
        assert_true(worst < 0.2e-3);
        assert_true(worst_kink < 0.05e-3);
        free(h);
        free(h2);
        tirenv_profile_free(obstacles[k]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_continuous_at_vertices),
        cmocka_unit_test(test_no_jumps_in_sweeps),
        cmocka_unit_test(test_kkt_conditions),
        cmocka_unit_test(test_narrow_features_carried),
        cmocka_unit_test(test_derivative_on_roads),
        cmocka_unit_test(test_warm_start_invisible),
        cmocka_unit_test(test_faces_kept_invisible),
        cmocka_unit_test(test_kept_factor_invisible),
        cmocka_unit_test(test_update_is_the_solution),
        cmocka_unit_test(test_root_is_the_equilibrium),
        cmocka_unit_test(test_start_is_the_equilibrium),
        cmocka_unit_test(test_far_evaluation_tries_the_closed_form),
        cmocka_unit_test(test_lone_vertex_stiffness),
        cmocka_unit_test(test_second_difference_lone_vertex),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
