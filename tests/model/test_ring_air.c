/* SPDX-License-Identifier: Apache-2.0 */
/* The ring reference tire carried by its air (docs/models.md section 5.1): the follower load
 * of the pressure on the belt polygon against finite differences of its virtual work, the
 * sidewall membranes' stiffness against finite differences of the arc, the vertical stiffness
 * at twice the pressure, and the limits (no air; no air and no carcass). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "testutil.h"
#include "tirenv/tirenv.h"
#include "model/ring_impl.h"

/* The work of the air and the belt on the polygon of M nodes at radius R - w[j]: the potential
 * -p b A + T_p L, A its area, L its perimeter, T_p = p b R cos(dtheta/2). */
static double follower_potential(size_t M, double R, double p, double b, const double w[])
{
    const double dth = 2 * M_PI / (double)M, T_p = p * b * R * cos(0.5 * dth);
    double A = 0, L = 0;
    for (size_t j = 0; j < M; ++j) {
        const double r1 = R - w[j], r2 = R - w[(j + 1) % M];
        A += 0.5 * r1 * r2 * sin(dth);
        L += sqrt(r1 * r1 + r2 * r2 - 2 * r1 * r2 * cos(dth));
    }
    return -p * b * A + T_p * L;
}

/* The stencil's tension part is the Hessian of that potential at w = 0: central second
 * differences of the potential (step 1e-5 m: the round-off of a potential of order
 * p b R^2 = 1.8e4 J over h^2 = 1e-10 m^2 is about 1.8e4 * 2e-16 / 1e-10 = 0.04 N/m, the
 * truncation O(h^2) smaller still, against entries of 3.5e5 N/m; tolerance 1e-6 of them,
 * 0.35 N/m) equal s[0], s[1] and 0 for s[2] once the foundation's R dtheta k_f is taken off
 * the diagonal. The first derivatives vanish: T_p balances the air at w = 0. A coarse ring
 * (M = 48) so that the polygon's corrections to the continuous form of the tension
 * (about 7/6 (dtheta/2)^2 = 0.5 %, 1700 N/m) are far above the tolerance. */
static void test_follower_load_is_the_virtual_work(void **state)
{
    (void)state;
    const size_t M = 48;
    const double R = 0.6371, p = 1.4137e5, b = 0.3217;
    tirenv_ring_params par = tirenv_tire_default().ring;
    par.EI = 0;
    par.T = 0;
    par.k_c = 0;
    par.p = p;
    par.b_p = b;
    par.dtheta = 2 * M_PI / (double)M;
    tirenv_ring_belt *belt = tirenv_ring__belt_alloc(M, R, &par);
    assert_non_null(belt);
    const double *s = tirenv_ring__belt_stencil(belt);
    const double k_f = tirenv_ring__foundation(&par);
    const double expect[3] = {s[0] - R * par.dtheta * k_f, s[1], s[2]};
    assert_true(fabs(expect[1]) > 1e4); /* not all zero */
    double *w = calloc(M, sizeof *w);
    assert_non_null(w);
    const double h = 1e-5;
    const size_t j = 7;
    /* The gradient at w = 0: zero up to round-off (the tension balances the air). */
    w[j] = h;
    const double up = follower_potential(M, R, p, b, w);
    w[j] = -h;
    const double down = follower_potential(M, R, p, b, w);
    w[j] = 0;
    assert_near((up - down) / (2 * h), 0, 1e-6 * p * b * R, 0);
    for (size_t k = 0; k < 3; ++k) {
        double f[4];
        const double si[4] = {1, 1, -1, -1}, sk[4] = {1, -1, 1, -1};
        for (size_t c = 0; c < 4; ++c) {
            w[j] += si[c] * h;
            w[j + k] += sk[c] * h;
            f[c] = follower_potential(M, R, p, b, w);
            w[j] -= si[c] * h;
            w[j + k] -= sk[c] * h;
        }
        /* d2/dw_j dw_{j+k}; for k = 0 the four points are w_j +-2h and twice w_j. */
        const double H = k == 0 ? (f[0] - 2 * follower_potential(M, R, p, b, w) + f[3]) /
                                      (4 * h * h)
                                : (f[0] - f[1] - f[2] + f[3]) / (4 * h * h);
        print_message("k=%zu: stencil %.9g, finite differences %.9g\n", k, expect[k], H);
        assert_near(H, expect[k], 1e-6 * fabs(expect[1]), 0);
    }
    free(w);
    tirenv_ring__belt_free(belt);
}

/* gamma(alpha) p is the rate at which the two sidewalls' pull on the crown falls as it comes
 * in: each an arc of length l and half angle alpha, radius r = l / (2 alpha), pulling with
 * N cos(alpha) = p r cos(alpha) along its chord c = 2 r sin(alpha). Central differences in
 * alpha (step 1e-6: error ~1e-12 relative) against the closed form, at three angles. */
static void test_sidewall_membrane(void **state)
{
    (void)state;
    const double angles[] = {0.7137, 1.05, 1.4731}, l = 0.2913, p = 1.1731e5, h = 1e-6;
    for (size_t i = 0; i < 3; ++i) {
        const double a = angles[i];
        double pull[2], chord[2];
        for (int k = 0; k < 2; ++k) {
            const double ak = a + (k ? h : -h), r = l / (2 * ak);
            pull[k] = p * r * cos(ak);
            chord[k] = 2 * r * sin(ak);
        }
        const double rate = 2 * (pull[1] - pull[0]) / (chord[1] - chord[0]);
        assert_near(rate, tirenv_ring__sidewall_gamma(a) * p, 1e-7 * rate, 0);
    }
}

/* The height at which the ring carries load on flat ground (bisection to 1e-13 m), and its
 * vertical stiffness -dF_z/dz there. */
static double stiffness_at(const tirenv_tire *t, double load)
{
    tirenv_ring *r = tirenv_ring_alloc(t->springs.R0, &t->ring);
    assert_non_null(r);
    tirenv_profile *flat = tirenv_test_flat_ground();
    double lo = 0.5 * t->springs.R0, hi = t->springs.R0, fx, fz, k = 0;
    for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
        const double z = 0.5 * (lo + hi);
        assert_int_equal(tirenv_ring_forces(r, flat, 0, z, &fx, &fz, &k, NULL, NULL), 0);
        if (fz > load)
            lo = z;
        else
            hi = z;
    }
    assert_int_equal(tirenv_ring_forces(r, flat, 0, lo, &fx, &fz, &k, NULL, NULL), 0);
    tirenv_profile_free(flat);
    tirenv_ring_free(r);
    return -k; /* F_z falls as the centre rises */
}

/* The air carries most of the load (docs/models.md section 5.1): at the rated 17.8 kN the vertical stiffness at
 * twice the shipped pressure is at least 1.5 times that at it, and at half of it at most
 * 1/1.3 of it; without air the carcass alone (FOUNDATION_STIFFNESS, the tread, the belt's
 * bending) keeps less than half of the stiffness. */
static void test_air_carries_the_load(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    const double p = t.ring.p, load = 17848;
    const double k1 = stiffness_at(&t, load);
    t.ring.p = 2 * p;
    const double k2 = stiffness_at(&t, load);
    t.ring.p = 0.5 * p;
    const double k_half = stiffness_at(&t, load);
    t.ring.p = 0;
    const double k0 = stiffness_at(&t, 0.3 * load);
    print_message("K at p/2, p, 2p: %.0f %.0f %.0f N/m (ratio %.3f); no air %.0f N/m\n",
                  k_half, k1, k2, k2 / k1, k0);
    assert_true(k2 >= 1.5 * k1);
    assert_true(k_half * 1.3 <= k1);
    assert_true(k0 < 0.5 * k1);
}

/* Limits: with neither air nor carcass the sidewalls carry nothing and the tire is refused
 * naming the key; a negative pressure is refused by name. */
static void test_no_air_no_carcass_refused(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    t.ring.p = 0;
    t.ring.k_c = 0;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    assert_int_equal(tirenv_tire_check(&t, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "FOUNDATION_STIFFNESS");
    assert_null(tirenv_ring_alloc(t.springs.R0, &t.ring));
    t = tirenv_tire_default();
    t.ring.p = -1;
    tirenv_diag_clear(&d);
    assert_int_equal(tirenv_tire_check(&t, &d), TIRENV_EINVAL);
    assert_string_equal(d.field, "INFLPRES");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_follower_load_is_the_virtual_work),
        cmocka_unit_test(test_sidewall_membrane),
        cmocka_unit_test(test_air_carries_the_load),
        cmocka_unit_test(test_no_air_no_carcass_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
