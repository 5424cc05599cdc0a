/* SPDX-License-Identifier: Apache-2.0 */
/* The ring's own step in z (src/model/ring_root.c, docs/models.md 5.3, What the solve reuses):
 * the curvature it measures and the parabola's root it steps to, on parabolas with known
 * roots, its guards, and the model's equilibria with it against Brent's (which takes no model
 * step) over seeded cleats, steps, blades and a class C road; the start at a new x from the
 * mean slope of the last steps; and the warm start that keeps the last answer's contact
 * (ring_shear.c's warm_span, warm_shift) against one that does not. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "testutil.h"
#include "tirenv/tirenv.h"
#include "model/ring_impl.h"

/* F(z) = G + k (z - z_r) + c/2 (z - z_r)^2 and its slope. */
typedef struct {
    double G, k, c, z_r;
} parabola;

static double F_of(const parabola *p, double z)
{
    const double u = z - p->z_r;
    return p->G + p->k * u + 0.5 * p->c * u * u;
}

static double dF_of(const parabola *p, double z) { return p->k + p->c * (z - p->z_r); }

static tirenv_ring *default_ring(void)
{
    const tirenv_tire t = tirenv_tire_default();
    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    assert_non_null(r);
    return r;
}

/* A class C road of length m with vertices 10 mm apart, from seed. */
static tirenv_profile *class_c_road(double length, unsigned long seed)
{
    tirenv_road_settings s = tirenv_road_default();
    s.road_class = 'C';
    s.length = length;
    s.dx = 0.01;
    s.seed = seed;
    tirenv_profile *p = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_road_iso8608(&s, &p, &d), TIRENV_OK);
    return p;
}

/* One position on parabola p: the step from z0, then the evaluation at the step (measured).
 * Returns whether the ring gave its own step, *z_next where Newton goes. */
static int position(tirenv_ring *r, const parabola *p, double x, double z0, double *z_next)
{
    double z_root = NAN;
    const int has = tirenv_ring__root(r, x, z0, F_of(p, z0), dF_of(p, z0), p->G, &z_root);
    *z_next = has ? z_root : z0 - (F_of(p, z0) - p->G) / dF_of(p, z0);
    tirenv_ring__root_seen(r, x, *z_next, F_of(p, *z_next));
    return has;
}

/* Without a curvature the step is Newton's own; after one position on each side the steps
 * land on a parabola of that curvature's root to round-off, where the linear step misses it
 * by c dz^2 / (2 k). The curvature is kept by the step's side, the median of the last three:
 * one outlier among them is not taken. A measurement at another x, or over a step shorter
 * than 1e-6 m, is none, and a parabola whose bend is more than a tenth of the residual gives
 * no step. */
static void test_parabola(void **state)
{
    (void)state;
    tirenv_ring *r = default_ring();
    const double G = 30152.19, k = -4.0217e5, c = 2.413e6;
    parabola p = {G, k, c, 0.6295762};
    double z;
    assert_false(position(r, &p, -0.3, p.z_r + 2.1e-5, &z)); /* up-side none yet */
    assert_false(position(r, &p, -0.299, p.z_r - 1.7e-5, &z)); /* down-side none yet */
    assert_int_equal((int)r->root.n[0] + (int)r->root.n[1], 2);
    assert_near(r->root.c[1][0], c, 1e-6 * c, 0); /* a step down, from above the root */
    assert_near(r->root.c[0][0], c, 1e-6 * c, 0);
    double worst_root = 0, worst_linear = 0;
    for (int i = 0; i < 8; ++i) {
        const double dz0 = (i % 2 ? -1 : 1) * (0.7 + 0.31 * i) * 1e-5;
        p.z_r = 0.6295762 + 1.3e-5 * i;
        const double x = -0.298 + 0.001 * i, z0 = p.z_r + dz0;
        const double z_lin = z0 - (F_of(&p, z0) - G) / dF_of(&p, z0);
        assert_true(position(r, &p, x, z0, &z));
        worst_root = fmax(worst_root, fabs(z - p.z_r));
        worst_linear = fmax(worst_linear, fabs(z_lin - p.z_r));
    }
    print_message("parabola: the ring's step lands %.3g m from the root, the linear one %.3g m\n",
                  worst_root, worst_linear);
    assert_true(worst_linear > 1e-10);   /* the linear step misses by more than eps_z */
    assert_true(worst_root < 2e-13);     /* the parabola's step to round-off */
    /* An outlier (a state changing on the way: 100 times the curvature) among the last
     * three of a side: the median is still c. */
    parabola q = {G, k, 100 * c, 0.63};
    position(r, &q, -0.2, q.z_r + 1.5e-5, &z); /* measured on the up side (z below z0) */
    assert_near(r->root.c[1][0], 100 * c, 1e-6 * c, 0);
    p.z_r = 0.6301;
    assert_true(position(r, &p, -0.199, p.z_r + 1.9e-5, &z));
    assert_near(z, p.z_r, 2e-13, 0);
    /* Elsewhere in x, or too short a step: not measured. */
    const double n0 = r->root.n[0], n1 = r->root.n[1], c0 = r->root.c[0][0];
    double zr;
    tirenv_ring__root(r, 0.1, p.z_r + 3e-5, F_of(&p, p.z_r + 3e-5), dF_of(&p, p.z_r + 3e-5),
                      G, &zr);
    tirenv_ring__root_seen(r, 0.1001, p.z_r, F_of(&p, p.z_r)); /* another x */
    tirenv_ring__root(r, 0.2, p.z_r - 3e-7, F_of(&p, p.z_r - 3e-7), dF_of(&p, p.z_r - 3e-7),
                      G, &zr);
    tirenv_ring__root_seen(r, 0.2, p.z_r, F_of(&p, p.z_r)); /* a step of 3e-7 m */
    assert_true(r->root.n[0] == n0 && r->root.n[1] == n1 && r->root.c[0][0] == c0);
    /* A bend of more than a tenth of the residual: no step (Newton's linear one). */
    parabola far = {G, k, c, 0.62};
    assert_false(tirenv_ring__root(r, 0.3, far.z_r - 0.08, F_of(&far, far.z_r - 0.08),
                                   dF_of(&far, far.z_r - 0.08), G, &zr));
    /* A cold start (a restored or cleared state) has none. */
    tirenv_ring__root_clear(r);
    assert_false(tirenv_ring__root(r, 0.4, p.z_r + 1e-5, F_of(&p, p.z_r + 1e-5),
                                   dF_of(&p, p.z_r + 1e-5), G, &zr));
    tirenv_ring_free(r);
}

/* Newton's equilibrium at x on p by hand, as src/core/eq_newton.c takes it near the root:
 * from z0, the ring's own step where root is set and it gives one, else the linear one,
 * until |F_z - G| <= eps_F and the next correction <= eps_z. Returns the evaluations, the
 * answer's z in *z. */
static int newton_at(tirenv_ring *r, const tirenv_profile *p, double x, double G,
                     const tirenv_tire *t, int root, double *z)
{
    for (int n = 1; n <= 20; ++n) {
        double fx, F, k, z_root;
        assert_int_equal(tirenv_ring_forces(r, p, x, *z, &fx, &F, &k, NULL, NULL), 0);
        if (root)
            tirenv_ring__root_seen(r, x, *z, F);
        const double dz = -(F - G) / k;
        if (fabs(F - G) <= t->eq.eps_F && fabs(dz) <= t->eq.eps_z)
            return n;
        *z = root && fabs(F - G) > t->eq.eps_F && tirenv_ring__root(r, x, *z, F, k, G, &z_root)
                 ? z_root
                 : *z + dz;
    }
    fail_msg("no equilibrium at x = %g", x);
    return 0;
}

/* On the real ring over seeded cleats, a step and a 5 mm blade at 1 mm steps (the curvature of
 * the positions before at hand), each position started from the line through the last two
 * equilibria: with the ring's step the same equilibria within 2 eps_z (each within eps_z of
 * the root) and fewer evaluations than with the linear step, where the third, only
 * confirming one followed a step that landed some 2e-10 m off. */
static void test_fewer_evaluations(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_tire_default();
    tirenv_rng *rng = tirenv_rng_alloc(19);
    assert_non_null(rng);
    size_t ev[2] = {0, 0}, n = 0;
    double worst = 0;
    for (int c = 0; c < 3; ++c) {
        tirenv_profile *p = c == 0 ? tirenv_profile_cleat(0.1 + 0.2 * tirenv_rng_uniform(rng),
                                                          0.03 + 0.07 * tirenv_rng_uniform(rng))
                            : c == 1 ? tirenv_profile_step(0.0113, 0.05)
                                     : tirenv_profile_cleat(0.005, 0.0237);
        tirenv_ring *r[2] = {default_ring(), default_ring()};
        const double G = 20000 + 10000 * tirenv_rng_uniform(rng), x0 = -0.45;
        /* The flat-ground height at G, from the linear steps on the level ground before. */
        double z1 = 0.63, zs[2];
        (void)newton_at(r[1], p, -0.9, G, &t, 0, &z1);
        zs[0] = zs[1] = z1;
        double za[2][2] = {{z1, z1}, {z1, z1}}; /* the last two equilibria of each */
        for (int i = 0; i < 150; ++i) {
            const double x = x0 + 0.001 * i;
            for (int m = 0; m < 2; ++m) {
                double z = i < 2 ? za[m][0] : 2 * za[m][0] - za[m][1];
                ev[m] += (size_t)newton_at(r[m], p, x, G, &t, m == 0, &z);
                za[m][1] = za[m][0];
                za[m][0] = z;
                zs[m] = z;
            }
            assert_near(zs[0], zs[1], 2 * t.eq.eps_z, 0);
            worst = fmax(worst, fabs(zs[0] - zs[1]));
            ++n;
        }
        tirenv_ring_free(r[0]);
        tirenv_ring_free(r[1]);
        tirenv_profile_free(p);
    }
    tirenv_rng_free(rng);
    print_message("%zu positions: %.3f evaluations a position with the ring's step, %.3f with the "
                  "linear one; z within %.3g m\n", n, (double)ev[0] / (double)n,
                  (double)ev[1] / (double)n, worst);
    assert_true(ev[0] < ev[1]);
}

/* The start at a new x (tirenv_ring__root_start): the last evaluation at each x is taken as
 * its equilibrium, and with TIRENV_RING_START_KEEP of them a step apart up to x the start is
 * the last continued by their mean slope, where that has predicted the equilibria before
 * better than the line through the last two: over a ripple (h alternating about a slope, as
 * the node spacing makes it at 1 mm) it has, over a smooth curve (a parabola, as a cleat's
 * flank at coarse steps) the line has, and there is none. None over a gap in x (a level
 * stretch evaluated nothing) or after a clear. */
static double rippled(int i) { return 0.6295 + 2.7e-3 * i + (i % 2 ? 3.1e-6 : -2.3e-6); }
static double curved(int i) { return 0.6295 + 2.7e-3 * i + 4.1e-4 * i * i; }

static void test_start_record(void **state)
{
    (void)state;
    enum { K = TIRENV_RING_START_KEEP };
    const double h = 0.001, x0 = -0.4137;
    for (int c = 0; c < 2; ++c) {
        double (*zf)(int) = c == 0 ? rippled : curved;
        tirenv_ring *r = default_ring();
        double z;
        int given = 0;
        for (int i = 0; i < 3 * K; ++i) {
            const double x = x0 + h * i;
            if (tirenv_ring__root_start(r, x, &z)) {
                const double want = zf(i - 1) + (zf(i - 1) - zf(i - K)) / (K - 1);
                assert_near(z, want, 1e-15, 0);
                ++given;
            }
            tirenv_ring__root_eval(r, x, zf(i) + 2.3e-5); /* Newton's iterates at x ... */
            tirenv_ring__root_eval(r, x, zf(i));          /* ... the last its equilibrium */
        }
        if (c == 0)
            assert_int_equal(given, 3 * K - (K + 1)); /* from the first position scored on */
        else
            assert_int_equal(given, 0);
        /* A gap in x: none; and none after a clear. */
        assert_int_equal(tirenv_ring__root_start(r, x0 + h * (3 * K + 3), &z), 0);
        tirenv_ring__root_clear(r);
        assert_int_equal(tirenv_ring__root_start(r, x0, &z), 0);
        tirenv_ring_free(r);
    }
}

/* Over seeded cleats and a 5 mm blade at 1 mm steps, Newton by hand with the ring's step from
 * the start of tirenv_ring__root_start where it gives one, against from the line through the
 * last two equilibria (each ring its own curvatures): the same equilibria within 2 eps_z, and
 * where the mean slope was taken (233 of 450 positions, measured) starts closer to them (4.9e-6
 * against 8.9e-6 m on average, measured; the evaluations 1.638 against 1.647 a position). */
static void test_start_closer(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_tire_default();
    tirenv_rng *rng = tirenv_rng_alloc(23);
    assert_non_null(rng);
    size_t ev[2] = {0, 0}, n = 0, started = 0;
    double worst = 0, off[2] = {0, 0};
    for (int c = 0; c < 3; ++c) {
        tirenv_profile *p = c < 2 ? tirenv_profile_cleat(0.1 + 0.2 * tirenv_rng_uniform(rng),
                                                         0.03 + 0.07 * tirenv_rng_uniform(rng))
                                  : tirenv_profile_cleat(0.005, 0.0237);
        tirenv_ring *r[2] = {default_ring(), default_ring()};
        const double G = 20000 + 10000 * tirenv_rng_uniform(rng), x0 = -0.45;
        double z1 = 0.63;
        (void)newton_at(r[1], p, -0.9, G, &t, 0, &z1);
        double za[2][2] = {{z1, z1}, {z1, z1}};
        for (int i = 0; i < 150; ++i) {
            const double x = x0 + 0.001 * i;
            double zs[2], z_start[2];
            int by_slope = 0;
            for (int m = 0; m < 2; ++m) {
                double z = i < 2 ? za[m][0] : 2 * za[m][0] - za[m][1], zm;
                if (m == 0 && tirenv_ring__root_start(r[m], x, &zm)) {
                    z = zm;
                    by_slope = 1;
                }
                z_start[m] = z;
                ev[m] += (size_t)newton_at(r[m], p, x, G, &t, 1, &z);
                if (m == 0) /* the model records every evaluation; its last is the answer */
                    tirenv_ring__root_eval(r[m], x, z);
                za[m][1] = za[m][0];
                za[m][0] = z;
                zs[m] = z;
            }
            assert_near(zs[0], zs[1], 2 * t.eq.eps_z, 0);
            worst = fmax(worst, fabs(zs[0] - zs[1]));
            if (by_slope) {
                ++started;
                for (int m = 0; m < 2; ++m)
                    off[m] += fabs(z_start[m] - zs[m]);
            }
            ++n;
        }
        tirenv_ring_free(r[0]);
        tirenv_ring_free(r[1]);
        tirenv_profile_free(p);
    }
    tirenv_rng_free(rng);
    print_message("%zu positions, %zu started by the mean slope, %.3g m off on average (the "
                  "line %.3g m); %.3f evaluations a position (the line %.3f); z within %.3g m\n",
                  n, started, off[0] / (double)started, off[1] / (double)started,
                  (double)ev[0] / (double)n, (double)ev[1] / (double)n, worst);
    assert_true(started > n / 4);
    assert_true(off[0] < 0.8 * off[1]);
}

/* The equilibria with the ring's step (Newton, the default) against Brent's, which takes no
 * model step and brackets the root to eps_z, over seeded cleats, steps and 5 mm blades and
 * a class C road at 1 mm steps: h within 1e-9 m and F_x within 1e-3 N (the comparison rules
 * of docs/performance.md 2.19). */
static void test_equilibria_as_brent(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default(), tb = t;
    tb.eq.method = TIRENV_EQ_BRENT;
    tirenv_rng *rng = tirenv_rng_alloc(19);
    assert_non_null(rng);
    double worst_h = 0, worst_fx = 0;
    size_t compared = 0;
    for (int c = 0; c < 4; ++c) {
        tirenv_profile *p = NULL;
        double x0 = -0.3;
        const double u = tirenv_rng_uniform(rng);
        if (c == 0) {
            p = tirenv_profile_cleat(0.05 + 0.25 * u, 0.02 + 0.06 * tirenv_rng_uniform(rng));
        } else if (c == 1) {
            p = tirenv_profile_step(0.0113 * u, 0.02 + 0.05 * tirenv_rng_uniform(rng));
            x0 = -0.25;
        } else if (c == 2) {
            p = tirenv_profile_cleat(0.005, 0.01 + 0.03 * u);
        } else {
            p = class_c_road(3, 19);
            x0 = 0.8;
        }
        assert_non_null(p);
        tirenv_model *m = tirenv_model_alloc(tirenv_model_ring, &t),
                     *b = tirenv_model_alloc(tirenv_model_ring, &tb);
        assert_true(m && b);
        tirenv_diag d;
        const double load = 18000 + 12000 * tirenv_rng_uniform(rng);
        assert_int_equal(tirenv_model_set(m, p, load, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set(b, p, load, &d), TIRENV_OK);
        for (int i = 0; i < 120; ++i) {
            const double x = x0 + 0.001 * i;
            tirenv_point pm, pb;
            assert_int_equal(tirenv_model_eval(m, x, &pm, &d), TIRENV_OK);
            if (i % 4 == 0) {
                assert_int_equal(tirenv_model_eval(b, x, &pb, &d), TIRENV_OK);
                assert_near(pm.h, pb.h, 1e-9, 0);
                assert_near(pm.fx, pb.fx, 1e-3, 0);
                worst_h = fmax(worst_h, fabs(pm.h - pb.h));
                worst_fx = fmax(worst_fx, fabs(pm.fx - pb.fx));
                compared += pm.h > 1e-4; /* the obstacle lifts the hub there */
            }
        }
        tirenv_model_free(m);
        tirenv_model_free(b);
        tirenv_profile_free(p);
    }
    tirenv_rng_free(rng);
    print_message("against Brent: max |dh| %.3g m, max |dF_x| %.3g N over %zu lifted positions\n",
                  worst_h, worst_fx, compared);
    assert_true(compared > 40);
}

/* The warm start of an evaluation keeps what the last answer's contact says (ring_shear.c):
 * its nodes, which the first sub-window holds (warm_span), and its ground, along which the
 * tread surface moves at a new x (warm_shift). Over a class C road at 1 mm steps, where the
 * warm start alone predicted a contact tens of nodes short and Newton's first steps changed
 * tens of states, a ring that keeps them against one made to forget them before each
 * evaluation (tirenv_ring__tread_forget): the same forces within 1e-9 of the load (both are
 * the minimum; the same bits, measured) and fewer Newton steps (factorisations). The record
 * of the nodes is what a state saves (the last of the tread's warm doubles,
 * tirenv_ring__tread_warm_size). */
static void test_first_sub_window(void **state)
{
    (void)state;
    const tirenv_tire t = tirenv_tire_default();
    tirenv_profile *p = class_c_road(4, 3);
    tirenv_ring *r[2] = {default_ring(), default_ring()};
    const size_t M = tirenv_ring_size(r[1]);
    const double *span = tirenv_ring__tread_u(r[0]->tread) + 3 * M + 3; /* 1 if it holds one */
    assert_int_equal(tirenv_ring__tread_warm_size(r[1]->tread), 3 * M + 3 + 4);
    const double G = 21000;
    double z = 0.64, worst = 0;
    (void)newton_at(r[0], p, 1.5, G, &t, 0, &z); /* a height near the equilibria */
    size_t kept = 0;
    for (int i = 0; i < 80; ++i) {
        const double x = 1.5 + 0.001 * i, dz[3] = {1.3e-5, -1.1e-5, 2e-7};
        for (int k = 0; k < 3; ++k) {
            double fx[2], fz[2], slope[2];
            kept += span[0] == 1;
            tirenv_ring__tread_forget(r[1]->tread);
            for (int m = 0; m < 2; ++m)
                assert_int_equal(tirenv_ring_forces(r[m], p, x, z + dz[k], &fx[m], &fz[m],
                                                    &slope[m], NULL, NULL), 0);
            assert_near(fz[0], fz[1], 1e-9 * G, 0);
            assert_near(fx[0], fx[1], 1e-9 * G, 0);
            worst = fmax(worst, fabs(fz[0] - fz[1]));
        }
        z += 1e-5 * sin(0.1 * i);
    }
    const size_t steps[2] = {tirenv_ring__tread_newton_steps(r[0]->tread),
                             tirenv_ring__tread_newton_steps(r[1]->tread)};
    print_message("warm start: %zu Newton steps with the last contact's nodes and ground, %zu "
                  "without; F_z within %.3g N\n", steps[0], steps[1], worst);
    assert_true(kept > 200); /* the record was there */
    assert_true(steps[0] < steps[1]);
    tirenv_ring_free(r[0]);
    tirenv_ring_free(r[1]);
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parabola),
        cmocka_unit_test(test_fewer_evaluations),
        cmocka_unit_test(test_start_record),
        cmocka_unit_test(test_start_closer),
        cmocka_unit_test(test_equilibria_as_brent),
        cmocka_unit_test(test_first_sub_window),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
