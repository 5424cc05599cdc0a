/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model (docs/models.md section 4): closed forms, limits, LCP conditions, symmetry,
 * refinement, derivatives, methods, and an independent implementation. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "tirenv/rng.h"
#include "testutil.h"
#include "tirenv/tirenv.h"

/* The contact the tests below run with (main runs them with both). */
static tirenv_springs_contact contact_mode = TIRENV_SPRINGS_CONTINUOUS;

/* The default tire with the contact under test. */
static tirenv_tire default_tire(void)
{
    tirenv_tire t = tirenv_tire_default();
    t.springs.contact = contact_mode;
    return t;
}

static tirenv_tire tire_with(double R0, double c_r, double c_b, double dphi)
{
    tirenv_tire t = tirenv_tire_default();
    t.springs = (tirenv_springs_params){R0, c_r, c_b, M_PI, dphi, contact_mode, 0, 0};
    return t;
}

/* Sweeps the model over x = x0 + k*dx, k < n, at contact length l_c. */
static void sweep(const tirenv_tire *t, const tirenv_profile *p, double l_c, double x0,
                  double dx, size_t n, tirenv_point out[])
{
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, t);
    assert_non_null(m);
    tirenv_diag diag;
    double G;
    assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &G, &diag), TIRENV_OK);
    assert_int_equal(tirenv_model_set(m, p, G, &diag), TIRENV_OK);
    for (size_t k = 0; k < n; ++k) {
        const int status = tirenv_model_eval(m, x0 + (double)k * dx, &out[k], &diag);
        if (status)
            print_error("%s\n", diag.message);
        assert_int_equal(status, TIRENV_OK);
    }
    tirenv_model_free(m);
}

/* With c_b = 0 on flat ground the element sum is a Riemann sum of
 * F_z = 2 c_r (R0 sin a - z a), a = acos(z/R0), whose integrand g = c_r (R0 cos(theta) - z)
 * is smooth inside (-a, a) and has a kink where it reaches 0 at +-a. The inner error is at most
 * 2a dphi^2 max|g''|/12 and each kink cell adds at most dphi^2 |g'(a)|/2, so
 * |error| <= c_r R0 dphi^2 (a/6 + sin a): second order, which the test demands at every dphi. */
static void test_flat_closed_form(void **state)
{
    (void)state;
    const double R0 = 0.6837, c_r = 1.583e6;
    tirenv_profile *flat = tirenv_test_flat_ground();
    const double zs[] = {0.6711, 0.6502, 0.6234};
    for (size_t iz = 0; iz < 3; ++iz) {
        const double z = zs[iz], a = acos(z / R0);
        const double exact = 2 * c_r * (R0 * sin(a) - z * a);
        for (double dphi = M_PI / 90; dphi > M_PI / 6000; dphi /= 2) {
            const tirenv_tire t = tire_with(R0, c_r, 0, dphi);
            tirenv_springs *s = tirenv_springs_alloc(&t.springs);
            double fx, fz;
            assert_int_equal(
                tirenv_springs_forces(s, flat, 0.0123, z, &fx, &fz, NULL, NULL, NULL), 0);
            assert_near(fz, exact, c_r * R0 * dphi * dphi * (a / 6 + sin(a)), 0);
            assert_near(fx, 0, 1e-9 * exact, 0); /* symmetric patch: no longitudinal force */
            tirenv_springs_free(s);
        }
    }
    tirenv_profile_free(flat);
}

/* The LCP's three conditions hold to round-off on random obstacles and stiffnesses. */
static void test_lcp_conditions(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 20261123);
    enum { N_MAX = 400 };
    static double d[N_MAX], w[N_MAX], p[N_MAX], work[4 * N_MAX];
    for (int trial = 0; trial < 300; ++trial) {
        const size_t n = 1 + tirenv_rng_uniform_int(rng, N_MAX);
        const double k_r = pow(10, 2 + 6 * tirenv_rng_uniform(rng));
        const double k_ir = trial % 7 == 0 ? 0 : k_r * pow(10, -3 + 7 * tirenv_rng_uniform(rng));
        double scale = 0;
        for (size_t i = 0; i < n; ++i) {
            d[i] = tirenv_rng_uniform(rng) < 0.4 ? 0 : 0.05 * tirenv_rng_uniform(rng);
            scale = fmax(scale, d[i]);
        }
        size_t passes;
        assert_int_equal(tirenv_springs_lcp(n, k_r, k_ir, d, w, p, work, 2 * n + 2, &passes),
                         TIRENV_OK);
        /* Round-off scale: the largest force term, times a few hundred ulps. */
        const double f_tol = 1e-12 * (k_r + 4 * k_ir) * (scale + 1e-3);
        const double w_tol = 1e-12 * (scale + 1e-3);
        for (size_t i = 0; i < n; ++i) {
            const double w_l = i > 0 ? w[i - 1] : 0, w_r = i + 1 < n ? w[i + 1] : 0;
            const double nb = (double)((i > 0) + (i + 1 < n));
            const double Kw = (k_r + nb * k_ir) * w[i] - k_ir * (w_l + w_r);
            assert_near(Kw, p[i], f_tol, 0);
            assert_true(w[i] >= d[i] - w_tol);
            assert_true(p[i] >= -f_tol);
            assert_true(fabs(p[i] * (w[i] - d[i])) <= f_tol * w_tol);
        }
    }
    tirenv_rng_free(rng);
}

/* Curves agree with an independent implementation of docs/models.md section 4
 * (tests/data/springs-reference.csv). The file has 9 decimals
 * (5e-10 m rounding) and our equilibrium stops within 1e-10 m, so 1e-9 m is the bound; the
 * issue asks for 0.1 mm. */
static void test_reference_curves(void **state)
{
    (void)state;
    FILE *f = fopen(TIRENV_TEST_DATA "/springs-reference.csv", "r");
    assert_non_null(f);
    char line[512];
    assert_non_null(fgets(line, sizeof line, f));
    size_t rows = 0;
    while (fgets(line, sizeof line, f)) {
        int c;
        double R0, c_r, c_b, dphi, phi, l_c, L, H, x, h, load;
        assert_int_equal(sscanf(line, "%d,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &c, &R0,
                                &c_r, &c_b, &dphi, &phi, &l_c, &L, &H, &x, &h, &load),
                         12);
        tirenv_tire t = tire_with(R0, c_r, c_b, dphi);
        t.springs.phi = phi;
        t.springs.contact = TIRENV_SPRINGS_RAYS; /* the reference casts rays */
        tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
        tirenv_profile *p = tirenv_profile_cleat(L, H);
        tirenv_diag diag;
        double G;
        tirenv_point pt;
        /* The reference's regime is the chord of the free circle, l_c = 2 sqrt(R0^2 - z^2)
         * (the springs model's contact length before it became the length its tread touches,
         * docs/models.md section 1.3): its load is the model's at that centre height. */
        tirenv_flat fl;
        assert_int_equal(tirenv_model_flat_at_height(m, sqrt(R0 * R0 - 0.25 * l_c * l_c), &fl,
                                                     &diag), TIRENV_OK);
        G = fl.load;
        assert_near(G, load, 1e-6, 0);  /* the file gives the load to 1e-6 N */
        assert_int_equal(tirenv_model_set(m, p, G, &diag), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
        assert_near(pt.h, h, 1e-9, 0);
        tirenv_model_free(m);
        tirenv_profile_free(p);
        ++rows;
    }
    fclose(f);
    assert_int_equal(rows, 40);
}

/* Symmetric obstacles give symmetric curves, and the curve is flat far away. The sweeps run
 * in opposite directions from different warm starts, so they agree to a few eps_z. */
static void test_symmetry_and_far_field(void **state)
{
    (void)state;
    const tirenv_tire t = default_tire();
    tirenv_profile *obstacles[] = {tirenv_profile_cleat(0.2931, 0.0717),
                                   tirenv_profile_trapezoid(0.11, 0.27, 0.063),
                                   tirenv_profile_half_cylinder(0.083, 64)};
    enum { N = 241 };
    static tirenv_point fwd[N], back[N];
    for (size_t o = 0; o < 3; ++o) {
        sweep(&t, obstacles[o], 0.3317, -1.2, 0.01, N, fwd);
        sweep(&t, obstacles[o], 0.3317, 1.2, -0.01, N, back);
        double peak = 0;
        for (size_t k = 0; k < N; ++k) {
            assert_near(fwd[k].h, back[k].h, 1e-9, 0);
            /* Mirror symmetry of the longitudinal force. Both sweeps reach the same
             * equilibrium to round-off in practice (measured), so a tight 1e-6 N + 1e-9
             * relative is used: it catches a sign or mirror error, the point of the check. */
            assert_near(fwd[k].fx, -back[k].fx, 1e-6, 1e-9);
            peak = fmax(peak, fwd[k].h);
        }
        assert_true(peak > 0.02);
        /* |x| = 1.2 m is beyond R0 + half the obstacle: flat ground, h = 0 to the tolerance. */
        assert_near(fwd[0].h, 0, 1e-10, 0);
        assert_near(fwd[N - 1].h, 0, 1e-10, 0);
        tirenv_profile_free(obstacles[o]);
    }
}

/* Level ground within reach skips the solver: no force evaluation, z exactly
 * z_flat + level, and the same point the solver finds, to its tolerance: a bump of 1e-12 m
 * under the tread (at x + 0.1 m; one beyond R0 of the centre is clear ground, skipped too,
 * docs/models.md section 11.4) makes the ground not level there, so the full equilibrium
 * runs; the two heights agree within eps_z = 1e-10 m plus the force tolerance over the
 * stiffness (1e-6 N / 8e5 N/m). A lugged ring, not the same at every x, never skips. */
static void test_level_ground_skip(void **state)
{
    (void)state;
    const tirenv_tire t = default_tire();
    const double level = 0.0371, x = 3.3;
    const double xs[] = {-5, 5}, zs[] = {level, level};
    const double xb[] = {-5, x + 0.1, x + 0.1, 5}, zb[] = {level, level, level + 1e-12, level};
    tirenv_profile *flat = tirenv_profile_alloc(2, xs, zs);
    tirenv_profile *bump = tirenv_profile_alloc(4, xb, zb);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
    assert_non_null(flat);
    assert_non_null(bump);
    assert_non_null(m);
    tirenv_diag diag;
    tirenv_flat f;
    assert_int_equal(tirenv_model_flat(m, 1.2e4, &f, &diag), 0);
    assert_int_equal(tirenv_model_set(m, flat, 1.2e4, &diag), 0);
    tirenv_point skip, full;
    assert_int_equal(tirenv_model_eval(m, x, &skip, &diag), 0);
    assert_true(skip.iterations == 0 && skip.z == f.z_flat + level && skip.h == level);
    assert_true(skip.contacts > 0 && skip.slope == 0);
    assert_near(skip.fz, 1.2e4, 1e-6, 0);
    assert_int_equal(tirenv_model_set(m, bump, 1.2e4, &diag), 0);
    assert_int_equal(tirenv_model_eval(m, x, &full, &diag), 0);
    assert_true(full.iterations > 0);
    assert_near(full.z, skip.z, 1e-10 + 1e-6 / f.stiffness, 0);
    assert_true(full.contacts == skip.contacts);
    tirenv_model_free(m);

    tirenv_tire lugged = default_tire();
    lugged.ring.lug_count = 24;
    lugged.ring.lug_fraction = 0.4;
    lugged.ring.lug_ratio = 0.5;
    m = tirenv_model_alloc(tirenv_model_ring, &lugged);
    assert_non_null(m);
    assert_int_equal(tirenv_model_set(m, flat, 1.2e4, &diag), 0);
    assert_int_equal(tirenv_model_eval(m, x, &full, &diag), 0);
    assert_true(full.iterations > 0);
    tirenv_model_free(m);
    tirenv_profile_free(flat);
    tirenv_profile_free(bump);
}

/* F_z never increases with z, and dF_z/dz equals a central difference away from kinks. */
static void test_force_monotone_and_derivative(void **state)
{
    (void)state;
    tirenv_tire t = default_tire();
    t.springs.c_b = 2.37e4;
    tirenv_springs *s = tirenv_springs_alloc(&t.springs);
    tirenv_profile *p = tirenv_profile_cleat(0.1, 0.1);
    const double xs[] = {-0.4133, -0.2217, -0.0611, 0.0};
    size_t checked = 0;
    for (size_t ix = 0; ix < 4; ++ix) {
        double F_prev = INFINITY;
        for (double z = 0.55; z < 0.8; z += 0.000731) {
            double fx, F, dF;
            assert_int_equal(tirenv_springs_forces(s, p, xs[ix], z, &fx, &F, &dF, NULL, NULL),
                             0);
            assert_true(F <= F_prev + 1e-9 * fabs(F_prev));
            assert_true(dF <= 0);
            F_prev = F;
            if (F < 10)
                continue;
            /* h = 1e-7 m: truncation ~ h^2 F''' is far below 1e-6 relative; round-off ~
             * 1e-16 F / h ~ 1e-5 N/m. A kink inside [z-h, z+h] changes the slope; those few
             * points are detected by one-sided differences disagreeing, and skipped. */
            const double h = 1e-7;
            double Fp, Fm, F0;
            tirenv_springs_forces(s, p, xs[ix], z + h, &fx, &Fp, NULL, NULL, NULL);
            tirenv_springs_forces(s, p, xs[ix], z - h, &fx, &Fm, NULL, NULL, NULL);
            tirenv_springs_forces(s, p, xs[ix], z, &fx, &F0, NULL, NULL, NULL);
            const double fwd = (Fp - F0) / h, bwd = (F0 - Fm) / h;
            if (fabs(fwd - bwd) > 1e-6 * fabs(dF))
                continue;
            assert_near(dF, (Fp - Fm) / (2 * h), 0, 1e-6);
            ++checked;
        }
    }
    assert_true(checked > 200); /* the guard: the comparison really ran */
    tirenv_profile_free(p);
    tirenv_springs_free(s);
}

/* Tiny load or huge stiffness: the tire tends to the rigid disc, never above it. What is left
 * at the limit is the discretisation: a ray that misses a cleat's corner by up to dphi hits the
 * face behind it about R0 tan(psi) dphi further away (psi the corner's angle from the
 * vertical), so the gap must fall about linearly with dphi: by more than 3 when dphi is
 * quartered (4 in the limit; the sampled positions catch the worst miss only roughly). */
static double rigid_gap(const tirenv_profile *p, double c_r, double G, double dphi)
{
    tirenv_tire t = tire_with(0.68, c_r, 1.0e4 * c_r / 1.6e6, dphi);
    t.eq.eps_F = 1e-9 * G + 1e-12 * c_r; /* a force tolerance a stiff tire can meet */
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
    tirenv_diag diag;
    assert_int_equal(tirenv_model_set(m, p, G, &diag), TIRENV_OK);
    double gap = 0;
    for (double x = -0.8; x <= 0.8; x += 0.0173) {
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
        const double z_rigid = tirenv_rigid_height(p, 0.68, x, NULL, NULL);
        assert_true(pt.z <= z_rigid);
        gap = fmax(gap, z_rigid - pt.z);
    }
    tirenv_model_free(m);
    return gap;
}

static void test_rigid_limit(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_cleat(0.2131, 0.0817);
    const double dphi = M_PI / 360;
    const double tiny_load[] = {rigid_gap(p, 1.6e6, 4.6, dphi), rigid_gap(p, 1.6e6, 4.6, dphi / 4)};
    const double stiff[] = {rigid_gap(p, 1.6e10, 15e3, dphi), rigid_gap(p, 1.6e10, 15e3, dphi / 4)};
    print_message("rigid gap, 4.6 N: %.3g mm at 0.5 deg, %.3g mm at 0.125 deg; c_r 1.6e10: "
                  "%.3g, %.3g mm\n", 1e3 * tiny_load[0], 1e3 * tiny_load[1], 1e3 * stiff[0],
                  1e3 * stiff[1]);
    if (contact_mode == TIRENV_SPRINGS_RAYS) {
        assert_true(tiny_load[1] < tiny_load[0] / 3);
        assert_true(stiff[1] < stiff[0] / 3);
        assert_true(tiny_load[0] < 0.68 * dphi); /* tan(psi) < 1 for corners within reach */
    } else {
        /* A continuous tread misses no corner: what is left is elastic (4.6 N on a corner:
         * about 0.023 mm) and the tread's sag between rays on a face, R0 dphi^2 / 8 = 6.5 um
         * at 0.5 deg: under 0.03 mm at every dphi, where rays leave about 2 mm. */
        for (int k = 0; k < 2; ++k) {
            assert_true(tiny_load[k] < 3e-5);
            assert_true(stiff[k] < 3e-5);
        }
    }
    tirenv_profile_free(p);
}

/* The paper's secant, the default Newton and Brent find the same equilibrium, and the
 * default needs fewer force evaluations than the secant. */
static void test_methods_agree(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_cleat(0.3, 0.1);
    enum { N = 301 };
    static tirenv_point pts[3][N];
    size_t evals[3] = {0, 0, 0};
    for (int m = 0; m < 3; ++m) {
        tirenv_tire t = default_tire();
        t.eq.method = (tirenv_eq_method)m;
        sweep(&t, p, 0.38, -0.75, 0.005, N, pts[m]);
        for (size_t k = 0; k < N; ++k)
            evals[m] += pts[m][k].iterations;
    }
    for (size_t k = 0; k < N; ++k) {
        assert_near(pts[TIRENV_EQ_SECANT][k].h, pts[TIRENV_EQ_NEWTON][k].h, 1e-9, 0);
        assert_near(pts[TIRENV_EQ_BRENT][k].h, pts[TIRENV_EQ_NEWTON][k].h, 1e-9, 0);
    }
    assert_true(evals[TIRENV_EQ_NEWTON] < evals[TIRENV_EQ_SECANT]);
    tirenv_profile_free(p);
}

/* Halving dphi converges: the stiffnesses are per radian, so refining does not change the
 * tire. Differences between successive refinements must shrink, and at the default 0.5 deg the
 * curve is within 1.5 mm of the finest one (the corner effect of test_rigid_limit). */
static void test_refinement_converges(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_cleat(0.3, 0.05);
    enum { N = 121, LEVELS = 5 };
    static tirenv_point pts[LEVELS][N];
    for (int l = 0; l < LEVELS; ++l) {
        const tirenv_tire t = tire_with(0.68, 1.6e6, 1.0e4, M_PI / 180 / (1 << l));
        sweep(&t, p, 0.33, -0.6, 0.005, N, pts[l]);
    }
    double diff[LEVELS - 1];
    for (int l = 0; l + 1 < LEVELS; ++l) {
        diff[l] = 0;
        for (size_t k = 0; k < N; ++k)
            diff[l] = fmax(diff[l], fabs(pts[l][k].h - pts[l + 1][k].h));
    }
    /* Corners make it first order: each halving must cut the change by 1.5 or more. */
    for (int l = 0; l + 2 < LEVELS; ++l)
        assert_true(diff[l + 1] < diff[l] / 1.5);
    double to_finest = 0;
    for (size_t k = 0; k < N; ++k)
        to_finest = fmax(to_finest, fabs(pts[1][k].h - pts[LEVELS - 1][k].h));
    print_message("max |h(0.5 deg) - h(0.0625 deg)| = %.3g mm; successive %.3g %.3g %.3g %.3g\n",
                  1e3 * to_finest, 1e3 * diff[0], 1e3 * diff[1], 1e3 * diff[2], 1e3 * diff[3]);
    assert_true(to_finest < 1.5e-3);
    tirenv_profile_free(p);
}

/* Full-length tip state: the sums of eq. 1 over it give the hub force, and the chains
 * outside the contact region are deflected by the interradial springs but carry no load. */
static void test_tips_reproduce_forces(void **state)
{
    (void)state;
    tirenv_tire t = default_tire();
    t.springs.c_b = 3.1e4;
    tirenv_springs *s = tirenv_springs_alloc(&t.springs);
    tirenv_profile *p = tirenv_profile_cleat(0.1, 0.1);
    const size_t n = tirenv_springs_size(s);
    assert_int_equal(n, 361);
    double *d = malloc(n * sizeof *d), *w = malloc(n * sizeof *w), *r = malloc(n * sizeof *r);
    double fx, fz;
    size_t contacts;
    assert_int_equal(
        tirenv_springs_forces(s, p, -0.0731, 0.6521, &fx, &fz, NULL, &contacts, NULL), 0);
    tirenv_springs_tips(s, d, w, r);
    const double *theta = tirenv_springs_theta(s), k_r = t.springs.c_r * t.springs.dphi;
    double sz = 0, sx = 0;
    size_t touching = 0, dragged = 0;
    for (size_t i = 0; i < n; ++i) {
        sz += k_r * w[i] * cos(theta[i]);
        sx -= k_r * w[i] * sin(theta[i]);
        touching += r[i] > 0;
        /* Off the ground (no reaction) yet pulled in by its neighbours: free of its tip. */
        if (r[i] == 0 && w[i] > 0) {
            ++dragged;
            assert_true(w[i] > d[i]);
        }
        assert_true(w[i] >= d[i] - 1e-15 && w[i] >= 0);
    }
    assert_near(sz, fz, 0, 1e-12);
    assert_near(sx, fx, 1e-9, 1e-12);
    assert_int_equal(touching, contacts); /* contacts: elements with a reaction */
    assert_true(dragged > 0);
    free(d);
    free(w);
    free(r);
    tirenv_profile_free(p);
    tirenv_springs_free(s);
}

/* A load the tire cannot carry is an error with context, never a NaN. */
static void test_overload_fails_loudly(void **state)
{
    (void)state;
    const tirenv_tire t = default_tire();
    for (int m = 0; m < 3; ++m) {
        tirenv_tire tm = t;
        tm.eq.method = (tirenv_eq_method)m;
        tirenv_model *model = tirenv_model_alloc(tirenv_model_springs, &tm);
        tirenv_flat flat;
        tirenv_diag diag;
        const int status = tirenv_model_flat(model, 1e9, &flat, &diag);
        assert_true(status == TIRENV_ENOBRACKET || status == TIRENV_ENOCONV);
        assert_true(diag.message[0] != '\0');
        tirenv_model_free(model);
    }
    tirenv_tire bad = t;
    bad.springs.c_r = -1;
    assert_null(tirenv_model_alloc(tirenv_model_springs, &bad));
    assert_null(tirenv_springs_alloc(&bad.springs));
}

static int with_rays(void **state)
{
    (void)state;
    contact_mode = TIRENV_SPRINGS_RAYS;
    return 0;
}

int main(void)
{
    /* Every test with the default continuous contact, then with the paper's rays. */
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flat_closed_form),
        cmocka_unit_test(test_lcp_conditions),
        cmocka_unit_test(test_reference_curves),
        cmocka_unit_test(test_symmetry_and_far_field),
        cmocka_unit_test(test_force_monotone_and_derivative),
        cmocka_unit_test(test_rigid_limit),
        cmocka_unit_test(test_methods_agree),
        cmocka_unit_test(test_refinement_converges),
        cmocka_unit_test(test_tips_reproduce_forces),
        cmocka_unit_test(test_overload_fails_loudly),
        cmocka_unit_test(test_level_ground_skip),
    };
    const int failed = cmocka_run_group_tests_name("continuous", tests, NULL, NULL);
    return failed + cmocka_run_group_tests_name("rays", tests, with_rays, NULL);
}
