/* SPDX-License-Identifier: Apache-2.0 */
/* The flexible-ring reference tire (docs/models.md section 5): the prototype's figures, the
 * limit where it is the springs model, the contact conditions of tread and belt, symmetry,
 * derivative, blades, lugs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "tirenv/rng.h"
#include "model/ring_impl.h"
#include "testutil.h"
#include "tirenv/tirenv.h"

/* The independent prototype's tire (docs/models.md section 5's starting values). */
static tirenv_tire prototype_tire(void)
{
    tirenv_tire t = tirenv_tire_default();
    t.springs.R0 = 0.68;
    t.ring = (tirenv_ring_params){
        .t_r = 0.04,
        .EI = 500,
        .T = 34e3,
        .k_c = 1e6,
        .k_t = 4e6,
        .dtheta = M_PI / 360.0,
        .lug_count = 0,
        .lug_fraction = 0.5,
        .lug_ratio = 1,
        .alpha_s = 1.05, /* no air (p = 0): T and k_f are the whole tension and foundation */
        .contact = TIRENV_RING_RAYS, /* the prototype's: one ray per node */
    };
    return t;
}

/* Flat-ground loads at given deflections equal the independent prototype's
 * (tests/data/ring-prototype-flat.csv, 3 decimals: 5e-4 N rounding). The two
 * discretise the belt the same way, so only the rounding is left. Up to 50 mm deflection the
 * prototype's tread is not compressed through, and ours does not touch with the belt. */
static void test_flat_loads_match_prototype(void **state)
{
    (void)state;
    const tirenv_tire t = prototype_tire();
    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    tirenv_profile *flat = tirenv_test_flat_ground();
    FILE *f = fopen(TIRENV_TEST_DATA "/ring-prototype-flat.csv", "r");
    assert_non_null(f);
    char line[256];
    size_t rows = 0;
    while (fgets(line, sizeof line, f)) {
        double defl, load, patch;
        if (sscanf(line, "%lf,%lf,%lf", &defl, &load, &patch) != 3)
            continue;
        double fx, fz;
        assert_int_equal(tirenv_ring_forces(r, flat, 0.0, t.springs.R0 - defl, &fx, &fz, NULL,
                                            NULL, NULL), 0);
        assert_int_equal(tirenv_ring_belt_contacts(r), 0);
        assert_true(tirenv_ring_tread_max(r) < t.ring.t_r);
        assert_near(fz, load, 5e-4, 0);
        assert_near(fx, 0, 1e-9 * load, 0);
        /* The prototype's patch is the span of the nodes with pressure; ours interpolates the
         * edges between nodes, so they differ by up to two node spacings (2 * 6 mm). */
        assert_near(tirenv_ring_patch_length(r), patch, 2 * t.springs.R0 * t.ring.dtheta, 0);
        ++rows;
    }
    fclose(f);
    assert_int_equal(rows, 5);
    tirenv_profile_free(flat);
    tirenv_ring_free(r);
}

/* Curves over the three Table 3 cleats against the prototype's (7 decimals), which has no belt
 * contact: where our equilibrium has none either (one more evaluation at its height says; where
 * the equilibrium sits on a jump of F_z, a ray sweeping over a corner, that is one side of it),
 * the same (10 micrometres: equilibrium within 1e-10 m, rounding 5e-8 m); where the tread is
 * compressed through, the belt carries more and the hub rides higher. Both kinds must occur. */
static void test_cleat_curves_match_prototype(void **state)
{
    (void)state;
    const tirenv_tire t = prototype_tire();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_ring, &t);
    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    FILE *f = fopen(TIRENV_TEST_DATA "/ring-prototype-cleats.csv", "r");
    assert_non_null(f);
    char line[256], current = 0;
    tirenv_profile *p = NULL;
    tirenv_diag diag;
    double worst = 0;
    size_t rows = 0, same = 0, lifted = 0;
    while (fgets(line, sizeof line, f)) {
        char label;
        double G, L, H, x, h;
        if (sscanf(line, "%c,%lf,%lf,%lf,%lf,%lf", &label, &G, &L, &H, &x, &h) != 6)
            continue;
        if (label != current) {
            current = label;
            tirenv_profile_free(p);
            p = tirenv_profile_cleat(L, H);
            assert_int_equal(tirenv_model_set(m, p, G, &diag), TIRENV_OK);
        }
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
        double fx, fz;
        assert_int_equal(tirenv_ring_forces(r, p, x, pt.z, &fx, &fz, NULL, NULL, NULL), 0);
        if (tirenv_ring_belt_contacts(r) == 0) {
            worst = fmax(worst, fabs(pt.h - h));
            ++same;
        } else {
            assert_true(pt.h > h);
            ++lifted;
        }
        ++rows;
    }
    print_message("ring vs prototype: max |dh| = %.3g mm over %zu points without belt contact; "
                  "%zu points lifted by the belt\n", 1e3 * worst, same, lifted);
    assert_true(worst < 1e-5);
    assert_int_equal(rows, 33);
    assert_true(same >= 10 && lifted >= 5);
    fclose(f);
    tirenv_profile_free(p);
    tirenv_ring_free(r);
    tirenv_model_free(m);
}

/* A tread too thick to be compressed through gives the ring of before the belt contact:
 * tests/data/ring-thick-tread.csv was written by it (17 digits). The belt is now solved on its
 * banded stiffness instead of the compliance, so the curves agree to round-off, not bit for
 * bit: 1e-9 m in h (the equilibrium's eps_z is 1e-10 m) and 1e-5 N in fx. */
static void test_thick_tread_unchanged(void **state)
{
    (void)state;
    tirenv_tire t = prototype_tire();
    t.ring.t_r = 0.12;
    tirenv_model *m = tirenv_model_alloc(tirenv_model_ring, &t);
    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    FILE *f = fopen(TIRENV_TEST_DATA "/ring-thick-tread.csv", "r");
    assert_non_null(f);
    char line[256], current = 0;
    tirenv_profile *p = NULL;
    tirenv_diag diag;
    double worst_h = 0, worst_fx = 0, tread_max = 0;
    size_t rows = 0;
    while (fgets(line, sizeof line, f)) {
        char label;
        double G, L, H, x, h, fx_ref;
        if (sscanf(line, "%c,%lf,%lf,%lf,%lf,%lf,%lf", &label, &G, &L, &H, &x, &h, &fx_ref) != 7)
            continue;
        if (label != current) {
            current = label;
            tirenv_profile_free(p);
            p = tirenv_profile_cleat(L, H);
            assert_int_equal(tirenv_model_set(m, p, G, &diag), TIRENV_OK);
        }
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
        worst_h = fmax(worst_h, fabs(pt.h - h));
        worst_fx = fmax(worst_fx, fabs(pt.fx - fx_ref));
        double fx, fz;
        assert_int_equal(tirenv_ring_forces(r, p, x, pt.z, &fx, &fz, NULL, NULL, NULL), 0);
        assert_int_equal(tirenv_ring_belt_contacts(r), 0);
        tread_max = fmax(tread_max, tirenv_ring_tread_max(r));
        ++rows;
    }
    print_message("thick tread vs the ring without belt contact: max |dh| = %.3g m, max |dfx| = "
                  "%.3g N; largest tread compression %.1f mm of 120\n", worst_h, worst_fx,
                  1e3 * tread_max);
    assert_int_equal(rows, 39);
    assert_true(worst_h < 1e-9);
    assert_true(worst_fx < 1e-5);
    assert_true(tread_max > 0.08); /* the thick tread is compressed far beyond 40 mm */
    fclose(f);
    tirenv_profile_free(p);
    tirenv_ring_free(r);
    tirenv_model_free(m);
}

/* With no bending, no pretension and a rigid tread the ring is the pure radial springs model
 * with c_r = k_f R (docs/models.md section 5). The tread's compliance 1/k_t is left: with
 * k_t = 1e6 k_f the curves differ by about 1e-6 of the deflection, far below 1e-7 m. The
 * springs model's rays let a cleat corner between two of them pass; the ring's belt does not
 * (ground vertices within a node's sector hold it), so the tread is made thicker than the
 * cleat: the belt then never touches and the limit is the springs model's. */
static void test_reduces_to_springs(void **state)
{
    (void)state;
    tirenv_tire t = prototype_tire();
    t.ring.EI = 0;
    t.ring.T = 0;
    t.ring.t_r = 0.15;
    t.ring.k_c = 1.137e6;
    t.ring.k_t = 1e6 * t.ring.k_c;
    t.springs.c_r = t.ring.k_c * (t.springs.R0 - t.ring.t_r);
    t.springs.c_b = 0;
    t.springs.dphi = t.ring.dtheta;
    t.springs.contact = TIRENV_SPRINGS_RAYS; /* the ring's tread casts the same rays */
    tirenv_model *ring = tirenv_model_alloc(tirenv_model_ring, &t);
    tirenv_model *springs = tirenv_model_alloc(tirenv_model_springs, &t);
    tirenv_profile *p = tirenv_profile_cleat(0.1, 0.1);
    tirenv_diag diag;
    const double G = 9137.2;
    assert_int_equal(tirenv_model_set(ring, p, G, &diag), TIRENV_OK);
    assert_int_equal(tirenv_model_set(springs, p, G, &diag), TIRENV_OK);
    for (double x = -0.6; x <= 0.6; x += 0.0137) {
        tirenv_point a, b;
        assert_int_equal(tirenv_model_eval(ring, x, &a, &diag), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(springs, x, &b, &diag), TIRENV_OK);
        assert_near(a.h, b.h, 1e-7, 0);
        assert_near(a.fx, b.fx, 1e-6 * G, 0);
    }
    tirenv_profile_free(p);
    tirenv_model_free(ring);
    tirenv_model_free(springs);
}

/* Checks the contact law of section 5 at every node of the last evaluation, from the public
 * state: f >= 0; the tread compression e = d - w never beyond t_r; the belt out of the ground,
 * w >= b - t_r; its reaction g >= 0 and zero unless w = b - t_r; the tread force f - g =
 * kappa max(0, e). Tolerances are round-off: 1e-12 m on lengths (w on a belt node is b - t_r
 * by construction, e on a tread node d - w), 1e-9 N on forces of order 1e3 N. Counts the nodes
 * in belt contact and returns the largest tread compression. */
static double check_contact_law(const tirenv_ring *r, const tirenv_ring_params *par,
                                double R0, double fz, size_t contacts, size_t *belt)
{
    const size_t M = tirenv_ring_size(r);
    const double *theta = tirenv_ring_theta(r);
    const double kappa = par->k_t * (R0 - par->t_r) * par->dtheta, t_r = par->t_r;
    double *w = malloc(4 * M * sizeof *w), *f = w + M, *d = w + 2 * M, *b = w + 3 * M;
    double *g = malloc(M * sizeof *g);
    assert_non_null(w);
    assert_non_null(g);
    tirenv_ring_state(r, w, f);
    tirenv_ring_contact(r, d, b, g);
    double sum = 0, e_max = 0;
    size_t n_pos = 0, n_belt = 0;
    for (size_t j = 0; j < M; ++j) {
        assert_true(f[j] >= 0);
        assert_true(g[j] >= 0);
        assert_true(g[j] <= f[j]);
        assert_true(b[j] >= d[j]);
        n_pos += f[j] > 0;
        n_belt += g[j] > 0;
        sum += f[j] * cos(theta[j]);
        if (b[j] == -INFINITY) {
            assert_true(f[j] == 0);
            continue;
        }
        const double gap = w[j] - (b[j] - t_r); /* belt clearance */
        assert_true(gap >= -1e-12);
        if (g[j] > 0)
            assert_true(fabs(gap) <= 1e-12);
        if (d[j] == -INFINITY) {
            assert_true(f[j] == g[j]); /* no tread on ground its ray misses */
            continue;
        }
        const double e = d[j] - w[j];
        assert_true(e <= t_r + 1e-12);
        e_max = fmax(e_max, e);
        assert_near(f[j] - g[j], kappa * fmax(0, e), 1e-9 + 1e-12 * kappa, 0);
    }
    assert_int_equal(n_pos, contacts);
    assert_int_equal(n_belt, tirenv_ring_belt_contacts(r));
    assert_near(sum, fz, 1e-9, 1e-12);
    assert_near(tirenv_ring_tread_max(r), fmin(e_max, t_r), 1e-12, 0);
    free(w);
    free(g);
    *belt = n_belt;
    return e_max;
}

/* The contact law at equilibrium positions over random cleats, 5 mm blades 50 to 300 mm tall
 * and steps up and down (seeded), and at fixed heights over a cleat. The belt must come into
 * play in many of them, and the tread never be compressed beyond its thickness. */
static void test_contact_law(void **state)
{
    (void)state;
    const tirenv_tire t = prototype_tire();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_ring, &t);
    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    assert_int_equal(tirenv_ring_size(r), 720);
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 11);
    tirenv_diag diag;
    size_t checked = 0, with_belt = 0, at_limit = 0;
    for (int k = 0; k < 24; ++k) {
        tirenv_profile *p;
        const int kind = k % 3;
        if (kind == 0)
            p = tirenv_profile_cleat(0.02 + 0.3 * tirenv_rng_uniform(rng),
                                     0.01 + 0.14 * tirenv_rng_uniform(rng));
        else if (kind == 1)
            p = tirenv_profile_cleat(0.005, 0.05 + 0.25 * tirenv_rng_uniform(rng));
        else
            p = tirenv_profile_step(0, (tirenv_rng_uniform(rng) < 0.5 ? -1 : 1) *
                                           (0.02 + 0.1 * tirenv_rng_uniform(rng)));
        const double G = 6000 + 20000 * tirenv_rng_uniform(rng);
        assert_int_equal(tirenv_model_set(m, p, G, &diag), TIRENV_OK);
        for (double x = -0.5 + 0.1 * tirenv_rng_uniform(rng); x < 0.5; x += 0.0537) {
            tirenv_point pt;
            const int st = tirenv_model_eval(m, x, &pt, &diag);
            if (st) {
                char msg[600];
                print_message("kind %d x %g G %g: %s\n", kind, x, G, tirenv_diag_format(&diag, msg, sizeof msg));
            }
            assert_int_equal(st, TIRENV_OK);
            double fx, fz;
            size_t contacts, belt;
            assert_int_equal(tirenv_ring_forces(r, p, x, pt.z, &fx, &fz, NULL, &contacts, NULL), 0);
            const double e_max = check_contact_law(r, &t.ring, t.springs.R0, fz, contacts, &belt);
            with_belt += belt > 0;
            at_limit += e_max > t.ring.t_r - 1e-9;
            ++checked;
        }
        tirenv_profile_free(p);
    }
    /* Fixed heights, deep into a cleat, where the warm start does not help. */
    tirenv_profile *p = tirenv_profile_cleat(0.1, 0.1);
    const double xs[] = {-0.3117, -0.1533, -0.0411, 0.0};
    for (size_t ix = 0; ix < 4; ++ix)
        for (double z = 0.62; z < 0.78; z += 0.0213) {
            double fx, fz;
            size_t contacts, belt;
            assert_int_equal(tirenv_ring_forces(r, p, xs[ix], z, &fx, &fz, NULL, &contacts, NULL), 0);
            check_contact_law(r, &t.ring, t.springs.R0, fz, contacts, &belt);
            with_belt += belt > 0;
            ++checked;
        }
    print_message("contact law at %zu states, %zu with belt contact, %zu with the tread "
                  "compressed through at some node\n", checked, with_belt, at_limit);
    assert_true(with_belt > checked / 5);
    assert_true(at_limit > 0);
    tirenv_profile_free(p);
    tirenv_rng_free(rng);
    tirenv_ring_free(r);
    tirenv_model_free(m);
}

/* Inside the window the belt displacements come from the banded stiffness condensed onto it;
 * the independent check is the compliance of the whole ring, computed here from the Fourier
 * symbol of tirenv/tire.h (the inverse DCT of 1/lambda_n): w = C f at every node, to 1e-9 of
 * the largest displacement. Over a cleat with belt contact, so that both kinds of row occur. */
static void test_window_matches_compliance(void **state)
{
    (void)state;
    const tirenv_tire t = prototype_tire();
    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    tirenv_profile *p = tirenv_profile_cleat(0.1, 0.1);
    const size_t M = tirenv_ring_size(r);
    double *c = malloc(3 * M * sizeof *c), *w = c + M, *f = c + 2 * M;
    assert_non_null(c);
    const double R = t.springs.R0 - t.ring.t_r, dth = 2 * M_PI / (double)M;
    for (size_t m = 0; m < M; ++m) {
        double sum = 0;
        for (size_t n = 0; n < M; ++n) {
            const double s = 2 * sin(M_PI * (double)n / (double)M) / dth, sg = s * s - 1;
            const double lambda = R * dth * (t.ring.EI * sg * sg / (R * R * R * R) +
                                             t.ring.T * sg / (R * R) + t.ring.k_c);
            sum += cos(2 * M_PI * (double)((n * m) % M) / (double)M) / lambda;
        }
        c[m] = sum / (double)M;
    }
    const double zs[] = {0.70, 0.66, 0.63};
    for (size_t iz = 0; iz < 3; ++iz) {
        double fx, fz;
        assert_int_equal(tirenv_ring_forces(r, p, -0.0731, zs[iz], &fx, &fz, NULL, NULL, NULL), 0);
        tirenv_ring_state(r, w, f);
        double w_max = 0, err = 0;
        for (size_t j = 0; j < M; ++j) {
            double cw = 0;
            for (size_t k = 0; k < M; ++k)
                cw += c[j > k ? j - k : k - j] * f[k];
            w_max = fmax(w_max, fabs(cw));
            err = fmax(err, fabs(cw - w[j]));
        }
        print_message("z = %.2f m: %zu belt nodes, max |w - C f| = %.2g m of max |w| %.3g m\n",
                      zs[iz], tirenv_ring_belt_contacts(r), err, w_max);
        assert_true(err <= 1e-9 * w_max);
    }
    assert_true(tirenv_ring_belt_contacts(r) > 0);
    free(c);
    tirenv_profile_free(p);
    tirenv_ring_free(r);
}

/* A blade 5 mm wide (narrower than the 5.9 mm between nodes at the tread) and 300 mm tall at
 * 13 kN: the belt rides on it, so the hub is lifted by most of its height at every position
 * near it, never falling between two rays; the tread at the blade is compressed through. */
static void test_blade_lifts_the_hub(void **state)
{
    (void)state;
    const tirenv_tire t = prototype_tire();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_ring, &t);
    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    tirenv_profile *p = tirenv_profile_cleat(0.005, 0.3);
    tirenv_diag diag;
    assert_int_equal(tirenv_model_set(m, p, 13000, &diag), TIRENV_OK);
    double h_min = INFINITY, h0 = 0;
    for (double x = -0.0503; x <= 0.0503; x += 0.00041) {
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), TIRENV_OK);
        h_min = fmin(h_min, pt.h);
        double fx, fz;
        assert_int_equal(tirenv_ring_forces(r, p, x, pt.z, &fx, &fz, NULL, NULL, NULL), 0);
        assert_true(tirenv_ring_belt_contacts(r) > 0);
        assert_true(tirenv_ring_tread_max(r) <= t.ring.t_r);
    }
    tirenv_point pt;
    assert_int_equal(tirenv_model_eval(m, 0, &pt, &diag), TIRENV_OK);
    h0 = pt.h;
    print_message("5 x 300 mm blade at 13 kN: h(0) = %.1f mm, lowest h within 50 mm of it "
                  "%.1f mm\n", 1e3 * h0, 1e3 * h_min);
    assert_true(h0 > 0.2 && h0 < 0.3);
    assert_true(h_min > 0.2);
    tirenv_profile_free(p);
    tirenv_ring_free(r);
    tirenv_model_free(m);
}

/* Symmetric curve over a symmetric cleat, flat far away, and dF_z/dz equal to a central
 * difference wherever the active set does not change within the step. The step is 1e-5 m:
 * the belt's reaction is a residual of stiffnesses near 1e10 N/m times displacements near
 * 0.03 m, so F carries round-off near 1e-7 N, 1e-8 relative of the slope times the step; the
 * truncation error of the central difference is far smaller (F is piecewise linear in z but for
 * the rays' and vertices' geometry). Both kinds of state, with and without belt contact, must
 * be checked. */
static void test_symmetry_and_derivative(void **state)
{
    (void)state;
    const tirenv_tire t = prototype_tire();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_ring, &t);
    tirenv_profile *p = tirenv_profile_cleat(0.2131, 0.0617);
    tirenv_diag diag;
    double G;
    assert_int_equal(tirenv_model_load_for_contact_length(m, 0.3317, &G, &diag), TIRENV_OK);
    tirenv_flat flat;
    assert_int_equal(tirenv_model_flat(m, G, &flat, &diag), TIRENV_OK);
    assert_near(flat.contact_length, 0.3317, 1e-9, 0);
    assert_int_equal(tirenv_model_set(m, p, G, &diag), TIRENV_OK);
    enum { N = 49 };
    double h[N];
    for (size_t k = 0; k < N; ++k) {
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, -1.2 + 0.05 * (double)k, &pt, &diag), TIRENV_OK);
        h[k] = pt.h;
    }
    for (size_t k = 0; k < N; ++k)
        assert_near(h[k], h[N - 1 - k], 1e-9, 0);
    assert_near(h[0], 0, 1e-10, 0);

    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    size_t checked = 0, checked_belt = 0;
    const double xs[] = {-0.1711, -0.0322};
    for (size_t ix = 0; ix < 2; ++ix)
        for (double z = 0.62; z < 0.70; z += 0.00137) {
            int belt;
            if (tirenv_test_ring_dfdz(r, p, xs[ix], z, 1e-5, &belt)) {
                ++checked;
                checked_belt += belt;
            }
        }
    print_message("dF_z/dz against central differences at %zu states, %zu with belt contact\n",
                  checked, checked_belt);
    assert_true(checked > 40);
    assert_true(checked_belt > 10);
    tirenv_ring_free(r);
    tirenv_profile_free(p);
    tirenv_model_free(m);
}

/* Lugs turn with the tread: on flat ground the load at a fixed height varies with x with the
 * lug pitch 2 pi R0 / n, and a smooth tread does not vary at all. */
static void test_lugs_roll_with_the_tread(void **state)
{
    (void)state;
    tirenv_tire t = prototype_tire();
    t.ring.lug_count = 23;
    t.ring.lug_ratio = 0.3;
    tirenv_ring *lugged = tirenv_ring_alloc(t.springs.R0, &t.ring);
    t.ring.lug_count = 0;
    tirenv_ring *smooth = tirenv_ring_alloc(t.springs.R0, &t.ring);
    tirenv_profile *flat = tirenv_test_flat_ground();
    const double pitch = 2 * M_PI * t.springs.R0 / 23, z = 0.641;
    double F_min = INFINITY, F_max = 0, fx, F, F_smooth0;
    tirenv_ring_forces(smooth, flat, 0, z, &fx, &F_smooth0, NULL, NULL, NULL);
    for (int k = 0; k < 17; ++k) {
        /* Mid-steps: a node exactly on a lug edge would flip with the last bit of x. */
        const double x = (k + 0.5) * pitch / 17;
        double Fs;
        tirenv_ring_forces(lugged, flat, x, z, &fx, &F, NULL, NULL, NULL);
        F_min = fmin(F_min, F);
        F_max = fmax(F_max, F);
        double F_next;
        tirenv_ring_forces(lugged, flat, x + pitch, z, &fx, &F_next, NULL, NULL, NULL);
        /* Same contact one pitch on: equal but for the rounding of theta + x/R0 (~1e-16
         * relative), which 1e-9 relative of ~1e4 N covers with room. */
        assert_near(F_next, F, 1e-6, 1e-9);
        tirenv_ring_forces(smooth, flat, x, z, &fx, &Fs, NULL, NULL, NULL);
        /* Flat ground, smooth tread: x does not enter at all, up to round-off. */
        assert_near(Fs, F_smooth0, 1e-6, 1e-12);
    }
    assert_true(F_max - F_min > 1e-3 * F_max);
    assert_true(F_max < F_smooth0); /* softer grooves carry less */
    tirenv_profile_free(flat);
    tirenv_ring_free(lugged);
    tirenv_ring_free(smooth);
}

/* A pretension the foundation cannot hold buckles the belt: refused, not solved. */
static void test_buckling_refused(void **state)
{
    (void)state;
    tirenv_tire t = prototype_tire();
    t.ring.T = 1e7;
    assert_null(tirenv_ring_alloc(t.springs.R0, &t.ring));
}

/* The continuous Winkler tread keeps its factor when the next system's matrix is the same
 * (level ground, the same points in contact: src/model/ring_smooth.c): evaluations of one
 * ring at heights a few tenths of a micrometre apart, each reusing the last one's factor, give
 * the bits of a fresh ring evaluated at that height alone (the same final system, factorised
 * afresh), and so does a height where more points touch (a new factor). A stale factor would
 * be off by far more than a bit. */
static void test_factor_reuse_is_exact(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    t.ring.G_t = 0;                 /* the Winkler tread (the default's layer counts no factors) */
    t.ring.dtheta = M_PI / 1440.0;  /* 0.125 degrees, the Winkler tread's converged spacing */
    tirenv_profile *p = tirenv_test_flat_ground();
    tirenv_ring *warm = tirenv_ring_alloc(t.springs.R0, &t.ring);
    assert_non_null(warm);
    const double zs[] = {0.6413, 0.6413 + 3.1e-7, 0.6413 - 2.3e-7, 0.6321, 0.6321 + 1.7e-7};
    size_t cold_factors = 0;
    for (size_t k = 0; k < sizeof zs / sizeof zs[0]; ++k) {
        tirenv_ring *cold = tirenv_ring_alloc(t.springs.R0, &t.ring);
        assert_non_null(cold);
        double fx1, fz1, d1, fx2, fz2, d2;
        assert_int_equal(tirenv_ring_forces(warm, p, 0.0173, zs[k], &fx1, &fz1, &d1, NULL, NULL),
                         0);
        assert_int_equal(tirenv_ring_forces(cold, p, 0.0173, zs[k], &fx2, &fz2, &d2, NULL, NULL),
                         0);
        assert_true(fz1 > 1000);
        assert_bits_equal(fz1, fz2);
        assert_bits_equal(d1, d2);
        assert_bits_equal(fx1, fx2);
        cold_factors += cold->n_factor;
        tirenv_ring_free(cold);
    }
    /* and the warm ring did keep factors: fewer factorisations than the fresh rings' */
    print_message("factorisations: kept ring %zu, fresh rings %zu\n", warm->n_factor,
                  cold_factors);
    assert_true(warm->n_factor < cold_factors);
    tirenv_ring_free(warm);
    tirenv_profile_free(p);
}

/* The continuous Winkler tread is solved on the sub-window of the nodes in contact
 * (src/model/ring_smooth.c, docs/models.md section 5.2), its free ends condensed out. Its
 * answer must be the minimum over the whole window: the belt force (S w)_j of the whole
 * window's condensed stiffness equals the points' force F_j at every window node, the free
 * ends included (where F_j = 0), to 1e-6 of the largest node force (measured: at most
 * 1.1e-7 of it, 6.7e-5 N; round-off of S's stencil entries near 1e11 N/m against w of
 * centimetres, where a wrong coupling would leave newtons). And its bits must not depend on
 * what the ring evaluated before: a ring that swept the cleat against a fresh one at each
 * position. Over the bench's 0.30 x 0.10 m cleat,
 * at positions and heights of its enveloping curve at 23.75 kN; most of them answered on a
 * sub-window (counted), so the test exercises it. */
static void test_sub_window_is_whole_window(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    t.ring.G_t = 0; /* the Winkler tread at 0.125 degrees, whose solve the sub-window is */
    t.ring.dtheta = M_PI / 1440.0;
    tirenv_profile *p = tirenv_profile_cleat(0.30, 0.10);
    tirenv_ring *warm = tirenv_ring_alloc(t.springs.R0, &t.ring);
    assert_non_null(warm);
    static const double xz[][2] = {{-0.55, 0.606993869}, {-0.45, 0.620697607},
                                   {-0.3, 0.644308509},  {-0.2, 0.677465111},
                                   {-0.1, 0.696149734},  {0.0, 0.703005945},
                                   {0.1, 0.696149734},   {0.25, 0.662826672}};
    const size_t n_xz = sizeof xz / sizeof xz[0];
    for (size_t k = 0; k < n_xz; ++k) {
        tirenv_ring *cold = tirenv_ring_alloc(t.springs.R0, &t.ring);
        assert_non_null(cold);
        double fx1, fz1, d1, fx2, fz2, d2;
        assert_int_equal(tirenv_ring_forces(warm, p, xz[k][0], xz[k][1], &fx1, &fz1, &d1, NULL,
                                            NULL), 0);
        assert_int_equal(tirenv_ring_forces(cold, p, xz[k][0], xz[k][1], &fx2, &fz2, &d2, NULL,
                                            NULL), 0);
        assert_true(fz1 > 1000);
        assert_bits_equal(fz1, fz2);
        assert_bits_equal(fx1, fx2);
        assert_bits_equal(d1, d2);
        const double(*q4)[4] = tirenv_ring__belt_end(warm->belt, warm->n);
        double res = 0, f_max = 0;
        for (size_t i = 0; i < warm->n; ++i) {
            const double F = warm->F[warm->lo + i];
            res = fmax(res, fabs(tirenv_ring__belt_force(warm, q4, warm->w + warm->lo, i) - F));
            f_max = fmax(f_max, fabs(F));
        }
        print_message("x = %+.2f m: %zu window nodes, largest |S w - F| %.3g N of %.3g N\n",
                      xz[k][0], warm->n, res, f_max);
        assert_true(res <= 1e-6 * f_max);
        tirenv_ring_free(cold);
    }
    print_message("answered on a sub-window: %zu of %zu\n", warm->n_sub, n_xz);
    assert_true(warm->n_sub >= n_xz - 2);
    tirenv_ring_free(warm);
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flat_loads_match_prototype),
        cmocka_unit_test(test_cleat_curves_match_prototype),
        cmocka_unit_test(test_thick_tread_unchanged),
        cmocka_unit_test(test_reduces_to_springs),
        cmocka_unit_test(test_contact_law),
        cmocka_unit_test(test_window_matches_compliance),
        cmocka_unit_test(test_sub_window_is_whole_window),
        cmocka_unit_test(test_blade_lifts_the_hub),
        cmocka_unit_test(test_symmetry_and_derivative),
        cmocka_unit_test(test_lugs_roll_with_the_tread),
        cmocka_unit_test(test_buckling_refused),
        cmocka_unit_test(test_factor_reuse_is_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
