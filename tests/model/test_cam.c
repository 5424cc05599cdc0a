/* The tandem elliptical cam (docs/models.md section 7): the basic function against its closed form,
 * a brute-force oracle, its limits, the tandem's symmetry and double hump, the model type and
 * the MF-Swift example file, and the model's sweeps against single lifts, bit for bit.
 * SPDX-License-Identifier: Apache-2.0
 *
 * Tolerances. Heights are below 1 m; the lift and each closed form take a handful of correctly
 * rounded operations (pow, exp, log, expm1, log1p: glibc's are within 1 ulp), so they agree to
 * about 10 ulp of 1 m, 2e-15 m. TOL = 1e-14 m leaves a factor 5 and is still far below any error
 * that matters (a missed candidate is off by more than 1e-6 m in these cases). The oracle,
 * the limits and the contact law have their own, derived, bounds below. */
#include "testutil.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>

#include "tirenv/tirenv.h"

#define TOL 1e-14

/* Shapes of high entropy: the default tractor cam (R0 0.68), a rounder and a squarer one. */
static const tirenv_cam_shape shapes[] = {
    {0.995112, 0.649468, 1.5257},
    {0.8137, 0.4271, 2.0},
    {1.1093, 0.7219, 3.7113},
    {0.6917, 0.3391, 1.1873},
};
#define N_SHAPES (sizeof shapes / sizeof shapes[0])

/* The cam's edge above its bottom at distance d: b_e*(g(|d|/a_e) - 1), g = (1 - t^c)^(1/c),
 * the plain formula (the library's uses expm1/log1p); -inf beyond the reach. */
static double edge(const tirenv_cam_shape *s, double d)
{
    const double t = fabs(d) / s->a_e;
    return t <= 1 ? s->b_e * (pow(1 - pow(t, s->c_e), 1 / s->c_e) - 1) : -INFINITY;
}

/* docs/models.md section 7: over a step of height h < b_e the rise starts
 * x_0 = a_e*(1 - (1 - h/b_e)^c_e)^(1/c_e) before the step, where the edge reaches its top. */
static double x_rise(const tirenv_cam_shape *s, double h)
{
    return s->a_e * pow(1 - pow(1 - h / s->b_e, s->c_e), 1 / s->c_e);
}

/* --- the basic function -------------------------------------------------------------- */

/* Step up of H at x_s: ahead of the step the corner (x_s, H) lifts the cam once it is
 * higher than the flat ground, Z = max(0, H + edge(x_s - x)); on the upper level Z = H. Step
 * down: the edge (x_s, 0) holds the cam above the lower level -H until it slides off. */
static void test_step(void **state)
{
    (void)state;
    const double x_s = 0.1379, H = 0.0562;
    tirenv_profile *up = tirenv_profile_step(x_s, H);
    tirenv_profile *down = tirenv_profile_step(x_s, -H);
    assert_non_null(up);
    assert_non_null(down);
    for (size_t i = 0; i < N_SHAPES; i++) {
        const tirenv_cam_shape *s = &shapes[i];
        for (double x = x_s - s->a_e - 0.2113; x <= x_s + s->a_e + 0.2; x += 0.00617) {
            const double z_up = x >= x_s ? H : fmax(0.0, H + edge(s, x_s - x));
            const double z_down = x <= x_s ? 0.0 : fmax(-H, edge(s, x - x_s));
            assert_near(tirenv_cam_lift(up, s, x, NULL, NULL), z_up, TOL, 0);
            assert_near(tirenv_cam_lift(down, s, x, NULL, NULL), z_down, TOL, 0);
        }
        /* The rise starts exactly at x_0 before the step: flat ground (0, exactly) before,
         * the corner after. */
        const double x_0 = x_rise(s, H);
        print_message("shape %zu: rise starts %.6f m before the step\n", i, x_0);
        assert_true(tirenv_cam_lift(up, s, x_s - x_0 - 1e-9, NULL, NULL) == 0.0);
        assert_near(tirenv_cam_lift(up, s, x_s - x_0, NULL, NULL), 0.0, TOL, 0);
        double px, pz;
        assert_true(tirenv_cam_lift(up, s, x_s - x_0 + 1e-6, &px, &pz) > 0.0);
        assert_true(px == x_s && pz == H); /* riding on the corner */
        assert_true(tirenv_cam_lift(up, s, x_s - 0.0311, &px, &pz) > 0.0);
        assert_true(px == x_s && pz == H);
        /* Stepping down, the lower level takes over at the same distance past the step. */
        assert_true(tirenv_cam_lift(down, s, x_s + x_0 + 1e-9, NULL, NULL) == -H);
    }
    tirenv_profile_free(up);
    tirenv_profile_free(down);
}

/* A cam on a straight slope z = t*x: tangent to it, the lift is t*x + b_e*((1 + m^p)^(1/p)
 * - 1) with m = |t| a_e/b_e and p = c_e/(c_e - 1) (the support function of the super-ellipse),
 * touching at u = a_e*k/(1 + k^c)^(1/c) ahead (uphill), k = m^(1/(c-1)). Written here in the
 * plain form, without the library's overflow-safe split at m = 1. The lift is checked to TOL
 * scaled by the slope (the ground term t*x grows with it), the touching point to 1e-12 m: at a
 * tangency the touching height is flat, so the point, though exact in closed form, is only
 * as well conditioned as the root of a derivative (a 1000-fold margin on round-off is ample
 * for these slopes, and a wrong root is off by millimetres). */
static void test_slope(void **state)
{
    (void)state;
    const double slopes[] = {0.0173, -0.2417, 0.8131, -1.9377, 4.3183};
    for (size_t i = 0; i < N_SHAPES; i++)
        for (size_t j = 0; j < sizeof slopes / sizeof slopes[0]; j++) {
            const tirenv_cam_shape *s = &shapes[i];
            const double t = slopes[j], c = s->c_e, p = c / (c - 1);
            const double xs[] = {-50.0, 50.0}, zs[] = {-50.0 * t, 50.0 * t};
            tirenv_profile *prof = tirenv_profile_alloc(2, xs, zs);
            assert_non_null(prof);
            const double m = fabs(t) * s->a_e / s->b_e, k = pow(m, 1 / (c - 1));
            const double u = copysign(s->a_e * k / pow(1 + pow(k, c), 1 / c), t);
            for (double x = -1.7131; x < 1.8; x += 0.1371) {
                const double Z = t * x + s->b_e * (pow(1 + pow(m, p), 1 / p) - 1);
                double px, pz;
                assert_near(tirenv_cam_lift(prof, s, x, &px, &pz), Z, TOL * (1 + fabs(t)), 0);
                assert_near(px, x + u, 1e-12, 0);
                assert_near(pz, t * px, 1e-12 * (1 + fabs(t)), 0);
            }
            tirenv_profile_free(prof);
        }
}

/* --- brute-force oracle -------------------------------------------------------------- */

/* A 64-bit LCG (Knuth's MMIX constants): fixed seed, same profiles on every platform. */
static uint64_t lcg_state = 0x2545F4914F6CDD1Dull;
static double uniform(void)
{
    lcg_state = lcg_state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(lcg_state >> 11) * 0x1.0p-53;
}

#define N_VERT 14
#define N_SAMPLE 4001

/* Bounds on the largest touching height q(xi) + edge(xi - x) over the part of the straight
 * piece (xa, za)-(xb, zb) within reach of x, from N_SAMPLE evenly spaced points f_i (ends
 * included). Lower: the best sample. Upper: along a straight piece the touching height is
 * concave (linear plus concave), so between samples u_i and u_{i+1} it lies below the
 * tangent at u_i, whose slope is at most the secant slope from u_{i-1}: f <= f_i + (f_i -
 * f_{i-1}), and from the other side f <= f_{i+1} + (f_{i+1} - f_{i+2}); every gap is covered
 * by one of them. No assumption on the implementation's formulas. */
static void sample_piece(const tirenv_cam_shape *s, double x, double xa, double za, double xb,
                         double zb, double *lo, double *hi)
{
    const double u_lo = fmax(xa, x - s->a_e), u_hi = fmin(xb, x + s->a_e);
    if (!(u_lo <= u_hi))
        return;
    static double f[N_SAMPLE];
    const size_t n = u_lo < u_hi ? N_SAMPLE : 1;
    for (size_t i = 0; i < n; i++) {
        const double xi = n == 1 ? u_lo : u_lo + (u_hi - u_lo) * (double)i / (double)(n - 1);
        const double q = isinf(xa) || isinf(xb) ? za : za + (zb - za) * (xi - xa) / (xb - xa);
        f[i] = q + edge(s, fmax(-s->a_e, fmin(s->a_e, xi - x))); /* u_lo, u_hi may round out */
    }
    for (size_t i = 0; i < n; i++) {
        *lo = fmax(*lo, f[i]);
        double rise = 0.0;
        if (i >= 1)
            rise = fmax(rise, f[i] - f[i - 1]);
        if (i + 1 < n)
            rise = fmax(rise, f[i] - f[i + 1]);
        *hi = fmax(*hi, f[i] + rise);
    }
}

/* Random polylines with walls, ground above and below 0, every shape: the exact lift lies
 * within the oracle's bracket (to TOL), and the bracket is narrow (it is about the samples'
 * spacing times the touching height's slope next to the maximum, up to ~1e-4 m where a
 * corner wins, far less at a tangency). */
static void test_oracle(void **state)
{
    (void)state;
    double widest = 0;
    for (int trial = 0; trial < 3; trial++) {
        double x[N_VERT], z[N_VERT];
        x[0] = -0.7 + 0.1 * uniform();
        z[0] = -0.05 + 0.2 * uniform();
        for (size_t k = 1; k < N_VERT; k++) {
            const int wall = uniform() < 0.2 && !(k >= 2 && x[k - 1] == x[k - 2]);
            x[k] = x[k - 1] + (wall ? 0.0 : 0.03 + 0.17 * uniform());
            z[k] = -0.05 + 0.2 * uniform();
        }
        tirenv_profile *p = tirenv_profile_alloc(N_VERT, x, z);
        assert_non_null(p);
        for (size_t i = 0; i < N_SHAPES; i++) {
            const tirenv_cam_shape *s = &shapes[i];
            const double x_lo = x[0] - s->a_e - 0.05, x_hi = x[N_VERT - 1] + s->a_e + 0.05;
            for (int j = 0; j <= 16; j++) {
                const double xc = x_lo + (x_hi - x_lo) * (j + 0.5 * uniform()) / 17.0;
                double lo = -INFINITY, hi = -INFINITY;
                sample_piece(s, xc, -INFINITY, z[0], x[0], z[0], &lo, &hi);
                sample_piece(s, xc, x[N_VERT - 1], z[N_VERT - 1], INFINITY, z[N_VERT - 1],
                             &lo, &hi);
                for (size_t k = 0; k + 1 < N_VERT; k++) {
                    if (x[k + 1] == x[k]) { /* a wall: only its ends can touch first */
                        sample_piece(s, xc, x[k], z[k], x[k], z[k], &lo, &hi);
                        sample_piece(s, xc, x[k], z[k + 1], x[k], z[k + 1], &lo, &hi);
                    } else {
                        sample_piece(s, xc, x[k], z[k], x[k + 1], z[k + 1], &lo, &hi);
                    }
                }
                double px, pz;
                const double exact = tirenv_cam_lift(p, s, xc, &px, &pz);
                assert_true(exact >= lo - TOL); /* attained by a point of the profile... */
                assert_true(exact <= hi + TOL); /* ...and no point lifts the cam higher */
                assert_true(hi - lo < 1e-4); /* the oracle is sharp: 5.6e-5 m at most seen */
                widest = fmax(widest, hi - lo);
                /* The touching point is on the profile and on the cam's edge. */
                assert_near(pz, tirenv_profile_height(p, px), TOL, 0);
                assert_near(pz + edge(s, px - xc), exact, TOL, 0);
            }
        }
        tirenv_profile_free(p);
    }
    print_message("widest oracle bracket %.2g m\n", widest);
}

/* --- limits -------------------------------------------------------------------------- */

/* With c_e = 2 and a_e = b_e = R0 the cam is the circle of radius R0 and its bottom sits R0
 * below the centre: the lift is exactly the rigid disc's centre height minus R0. */
static void test_rigid_disc(void **state)
{
    (void)state;
    const double R0 = 0.6837;
    const tirenv_cam_shape disc = {R0, R0, 2.0};
    tirenv_profile *ps[] = {
        tirenv_profile_cleat(0.2931, 0.0743),
        tirenv_profile_step(0.1379, -0.0562),
        tirenv_profile_trapezoid(0.1187, 0.3413, 0.1029),
        tirenv_profile_half_cylinder(0.2173, 7),
        tirenv_profile_sine(0.0311, 0.8713, 2.5, 64),
    };
    for (size_t i = 0; i < sizeof ps / sizeof ps[0]; i++) {
        assert_non_null(ps[i]);
        for (double x = -1.3117; x <= 1.3117; x += 0.00731)
            assert_near(tirenv_cam_lift(ps[i], &disc, x, NULL, NULL) + R0,
                        tirenv_rigid_height(ps[i], R0, x, NULL, NULL), TOL, 0);
        tirenv_profile_free(ps[i]);
    }
}

/* What a huge or tiny b_e tends to (an early draft of the spec said "the rigid disc"; that holds for
 * c_e = 2, a_e = b_e = R0 above, not for b_e -> infinity). As b_e grows the edge's drop
 * b_e*(1 - g(t)) >= b_e*t^c/c (from (1 - y)^(1/c) <= 1 - y/c) grows without bound at any
 * t > 0: the cam becomes a point follower, Z -> q(x). A corner of height H above the ground
 * under x can only lift it within d_max = a_e*(c*H/b_e)^(1/c) of the corner, and elsewhere
 * Z = q(x) exactly. As b_e -> 0 the cam becomes a plank: q(xi) - b_e <= Z <= max q over the
 * reach, since the edge is between b_e and 0 below the bottom. */
static void test_limits(void **state)
{
    (void)state;
    const double L = 0.2931, H = 0.0743;
    tirenv_profile *p = tirenv_profile_cleat(L, H);
    assert_non_null(p);
    for (size_t i = 0; i < N_SHAPES; i++) {
        const tirenv_cam_shape tall = {shapes[i].a_e, 1e4, shapes[i].c_e};
        const tirenv_cam_shape flat = {shapes[i].a_e, 1e-9, shapes[i].c_e};
        const double d_max = tall.a_e * pow(tall.c_e * H / tall.b_e, 1 / tall.c_e);
        print_message("c_e %.4f: b_e 1e4 m lifts the cam within %.3g m of a corner\n",
                      tall.c_e, d_max);
        for (double x = -1.5117; x <= 1.5117; x += 0.000731) {
            const double Z = tirenv_cam_lift(p, &tall, x, NULL, NULL);
            const double q = tirenv_profile_height(p, x);
            if (fabs(fabs(x) - L / 2) > d_max)
                assert_true(Z == q);
            else
                assert_true(Z >= q && Z <= H);
            const double q_max = tirenv_profile_max_height(p, x - flat.a_e, x + flat.a_e);
            const double Z_plank = tirenv_cam_lift(p, &flat, x, NULL, NULL);
            assert_true(Z_plank <= q_max && Z_plank >= q_max - flat.b_e - TOL);
        }
    }
    tirenv_profile_free(p);
}

static void test_invalid(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_cleat(0.2931, 0.0743);
    assert_non_null(p);
    const tirenv_cam_shape bad[] = {
        {0.0, 0.5, 1.5}, {0.9, -0.5, 1.5}, {0.9, 0.5, 1.0}, {0.9, 0.5, 0.7},
        {NAN, 0.5, 1.5}, {0.9, INFINITY, 1.5}, {0.9, 0.5, INFINITY},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        double px = 0, pz = 0, w = 7, tb = 7;
        assert_true(isnan(tirenv_cam_lift(p, &bad[i], 0.1, &px, &pz)));
        assert_true(isnan(px) && isnan(pz));
        assert_int_equal(tirenv_cam_tandem(p, &bad[i], 0.27, 0.1, &w, &tb), TIRENV_EINVAL);
        assert_true(w == 7 && tb == 7);
    }
    double w = 7, tb = 7;
    assert_true(isnan(tirenv_cam_lift(p, &shapes[0], NAN, NULL, NULL)));
    assert_int_equal(tirenv_cam_tandem(p, &shapes[0], 0.0, 0.1, &w, &tb), TIRENV_EINVAL);
    assert_int_equal(tirenv_cam_tandem(p, &shapes[0], -0.2, 0.1, &w, &tb), TIRENV_EINVAL);
    assert_int_equal(tirenv_cam_tandem(p, &shapes[0], 0.27, INFINITY, &w, &tb), TIRENV_EINVAL);
    assert_true(w == 7 && tb == 7);
    tirenv_profile_free(p);
}

/* --- the tandem ---------------------------------------------------------------------- */

/* Flat ground at any level z0: both cams sit on it, w = z0 and tan(beta) = 0 exactly. */
static void test_tandem_flat(void **state)
{
    (void)state;
    const double levels[] = {0.0, 0.0371, -0.0913};
    for (size_t i = 0; i < 3; i++) {
        const double xs[] = {-0.4417, -0.1031, 0.0277, 0.3912};
        const double zs[] = {levels[i], levels[i], levels[i], levels[i]};
        tirenv_profile *p = tirenv_profile_alloc(4, xs, zs);
        assert_non_null(p);
        for (size_t j = 0; j < N_SHAPES; j++)
            for (double x = -1.9371; x < 1.9; x += 0.0517) {
                double w, tb;
                assert_int_equal(tirenv_cam_tandem(p, &shapes[j], 0.2713, x, &w, &tb), 0);
                assert_true(w == levels[i] && tb == 0.0);
            }
        tirenv_profile_free(p);
    }
}

/* A symmetric obstacle gives w(x) = w(-x) and tan(beta)(x) = -tan(beta)(-x): the front cam at
 * x is the rear cam at -x mirrored. To round-off: the two sides visit the segments in a
 * different order. */
static void test_tandem_symmetry(void **state)
{
    (void)state;
    tirenv_profile *ps[] = {
        tirenv_profile_cleat(0.2931, 0.0743),
        tirenv_profile_trapezoid(0.1187, 0.3413, 0.1029),
        tirenv_profile_half_cylinder(0.1517, 40),
    };
    for (size_t i = 0; i < sizeof ps / sizeof ps[0]; i++) {
        assert_non_null(ps[i]);
        for (size_t j = 0; j < N_SHAPES; j++)
            for (double x = 0.0; x <= 1.3; x += 0.00419) {
                double w_p, tb_p, w_m, tb_m;
                assert_int_equal(tirenv_cam_tandem(ps[i], &shapes[j], 0.2713, x, &w_p, &tb_p), 0);
                assert_int_equal(tirenv_cam_tandem(ps[i], &shapes[j], 0.2713, -x, &w_m, &tb_m), 0);
                assert_near(w_p, w_m, TOL, 0);
                assert_near(tb_p, -tb_m, TOL / 0.2713, 0);
            }
        tirenv_profile_free(ps[i]);
    }
}

/* Local maxima of a sampled curve, plateaus counted once: rises then falls by more than
 * round-off. */
static size_t count_maxima(size_t n, const double w[])
{
    size_t maxima = 0;
    int dir = 0;
    for (size_t k = 1; k < n; k++) {
        const double d = w[k] - w[k - 1];
        if (fabs(d) <= 1e-12)
            continue;
        if (dir > 0 && d < 0)
            maxima++;
        dir = d > 0 ? 1 : -1;
    }
    return maxima;
}

/* The default tractor tire at its 0.33 m patch: tandem base l_s = 0.8328*0.33 m. Over a cleat
 * L x H shorter than l_s, at x = 0 the cams stand beside it, d0 = (l_s - L)/2 from its sides.
 * A single cam rises only within x_0 of the cleat (x_rise above), so if d0 > x_0 neither cam
 * touches it: w = 0 for |x| <= d0 - x_0, between two humps of at least H/2 where one cam is on
 * the cleat. This is the double hump of a tire bridging a short cleat. (With d0 < x_0 a small
 * third hump appears at x = 0; the 20 mm cleat below shows it.) Over a cleat longer than l_s
 * both cams stand on it at x = 0 and the curve has one flat top. */
static void test_double_hump(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &tire);
    assert_non_null(m);
    tirenv_diag diag;
    double G;
    assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G, &diag), 0);
    const double R0 = tire.springs.R0, l_s = tire.cam.shift * 0.33;
    const tirenv_cam_shape s = {tire.cam.length * R0, tire.cam.height * R0, tire.cam.order};
    const double L = 0.0517, d0 = (l_s - L) / 2;
    const double heights[] = {0.0103, 0.0203, 0.0203};
    const double lengths[] = {L, L, 0.4013};
    const size_t maxima[] = {2, 3, 1};
    enum { N = 2401 };
    static double w[N];
    for (size_t i = 0; i < 3; i++) {
        const double H = heights[i], x_0 = x_rise(&s, H);
        tirenv_profile *p = tirenv_profile_cleat(lengths[i], H);
        assert_non_null(p);
        assert_int_equal(tirenv_model_set(m, p, G, &diag), 0);
        tirenv_point pt;
        for (size_t k = 0; k < N; k++) {
            assert_int_equal(tirenv_model_eval(m, -0.6 + 0.0005 * (double)k, &pt, &diag), 0);
            w[k] = pt.h;
        }
        print_message("cleat %.4f x %.4f m, l_s %.4f m, d0 %.4f m, x_0 %.4f m: w(0) %.3f mm, "
                      "%zu maxima\n", lengths[i], H, l_s, d0, x_0, w[N / 2] * 1e3,
                      count_maxima(N, w));
        assert_int_equal(count_maxima(N, w), maxima[i]);
        assert_int_equal(tirenv_model_eval(m, 0.0, &pt, &diag), 0);
        if (i == 0) {
            assert_true(d0 > x_0);
            assert_true(pt.h == 0.0); /* the dip: neither cam touches the cleat */
            assert_int_equal(tirenv_model_eval(m, d0 - x_0 - 1e-9, &pt, &diag), 0);
            assert_true(pt.h == 0.0);
        } else if (i == 1) {
            assert_true(d0 < x_0); /* both cams touch it: w(0) = H + edge(d0) */
            assert_near(pt.h, H + edge(&s, d0), TOL, 0);
        } else {
            assert_true(pt.h == H); /* both cams on the top */
        }
        if (i < 2) { /* one cam on the cleat: at least H/2, symmetric */
            double w_left, w_right;
            assert_int_equal(tirenv_model_eval(m, -l_s / 2, &pt, &diag), 0);
            w_left = pt.h;
            assert_int_equal(tirenv_model_eval(m, l_s / 2, &pt, &diag), 0);
            w_right = pt.h;
            assert_true(w_left >= H / 2 && w_right >= H / 2);
            assert_near(w_left, w_right, TOL, 0);
        }
        tirenv_profile_free(p);
    }
    tirenv_model_free(m);
}

/* --- the model type ------------------------------------------------------------------ */

/* MF-Tyre's contact half length at deflection rho. */
static double half_length(const tirenv_tire *t, double rho)
{
    const double R0 = t->springs.R0, r = rho / R0;
    return R0 * (t->cam.q_ra2 * r + t->cam.q_ra1 * sqrt(r));
}

/* Flat ground with the linear vertical law (Q_FZ2 = 0): rho = G/VERTICAL_STIFFNESS exactly,
 * contact length 2a, and the load for a contact length inverts it (closed form: agreement to a
 * few ulp, 1e-12 relative allows 4500). Laws with Q_RA2 > 0, = 0, < 0 and Q_RA1 = 0. */
static void test_flat_and_contact_length(void **state)
{
    (void)state;
    const double q[][2] = {{0.79, 0.86}, {0.6715, 0.7308}, {1.2931, 0.0}, {1.2518, -0.9729},
                           {0.0, 2.3711}};
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
        tirenv_tire t = tirenv_tire_default();
        t.cam.q_fz2 = 0;
        t.cam.q_ra1 = q[i][0];
        t.cam.q_ra2 = q[i][1];
        tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
        assert_non_null(m);
        assert_string_equal(tirenv_model_name(m), "cam");
        tirenv_diag diag;
        const double loads[] = {3917.3, 10431.7, 17293.1};
        for (size_t j = 0; j < 3; j++) {
            tirenv_flat f;
            assert_int_equal(tirenv_model_flat(m, loads[j], &f, &diag), 0);
            const double rho = loads[j] / t.cam.c_z;
            assert_near(f.deflection, rho, 0, 1e-15);
            assert_near(f.z_flat, t.springs.R0 - rho, TOL, 0);
            assert_near(f.contact_length, 2 * half_length(&t, rho), TOL, 0);
            assert_true(f.stiffness == t.cam.c_z && f.load == loads[j]);
            double G;
            assert_int_equal(tirenv_model_load_for_contact_length(m, f.contact_length, &G,
                                                                  &diag), 0);
            assert_near(G, loads[j], 0, 1e-12);
        }
        /* Outside (0, 2 R0), and a deflection beyond R0. */
        double G = -1;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.0, &G, &diag),
                         TIRENV_EINVAL);
        assert_int_equal(tirenv_model_load_for_contact_length(m, 2 * t.springs.R0, &G, &diag),
                         TIRENV_EINVAL);
        tirenv_flat f;
        assert_int_equal(tirenv_model_flat(m, 1.01 * t.cam.c_z * t.springs.R0, &f, &diag),
                         TIRENV_ENOBRACKET);
        assert_string_equal(diag.field, "load");
        if (q[i][1] < 0) {
            /* The law peaks at sqrt(rho/R0) = Q_RA1/(2|Q_RA2|): longer patches, or loads
             * beyond the peak's, are refused. */
            const double y = q[i][0] / (-2 * q[i][1]), rho = t.springs.R0 * y * y;
            const double l_max = 2 * half_length(&t, rho);
            assert_int_equal(tirenv_model_load_for_contact_length(m, 1.001 * l_max, &G, &diag),
                             TIRENV_ERANGE);
            assert_int_equal(tirenv_model_load_for_contact_length(m, 0.999 * l_max, &G, &diag),
                             0);
            assert_true(G < t.cam.c_z * rho);
            assert_int_equal(tirenv_model_flat(m, 1.001 * t.cam.c_z * rho, &f, &diag),
                             TIRENV_ERANGE);
        }
        tirenv_model_free(m);
    }
    assert_true(tirenv_model_type_find("cam") == tirenv_model_cam);
    assert_string_equal(tirenv_model_type_name(tirenv_model_cam), "cam");
}

/* What a position reports: the tandem of the tire's cam with l_s = ELLIPS_SHIFT * 2a, on top
 * of the flat-ground centre height; no iteration, two contacts. */
static void test_model_point(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    t.springs.R0 = 0.7125;
    t.cam.shift = 0.9137;
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
    assert_non_null(m);
    tirenv_profile *p = tirenv_profile_trapezoid(0.1187, 0.3413, 0.1029);
    assert_non_null(p);
    tirenv_diag diag;
    const double G = 12731.9;
    tirenv_flat f;
    assert_int_equal(tirenv_model_flat(m, G, &f, &diag), 0);
    assert_int_equal(tirenv_model_set(m, p, G, &diag), 0);
    const tirenv_cam_shape s = {t.cam.length * t.springs.R0, t.cam.height * t.springs.R0,
                                t.cam.order};
    const double l_s = t.cam.shift * f.contact_length;
    int rising = 0, falling = 0;
    for (double x = -1.2117; x < 1.2; x += 0.0131) {
        tirenv_point pt;
        assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), 0);
        double w, tb;
        assert_int_equal(tirenv_cam_tandem(p, &s, l_s, x, &w, &tb), 0);
        assert_true(pt.x == x);
        assert_near(pt.h, w, TOL, 0);
        assert_near(pt.z, f.z_flat + w, TOL, 0);
        assert_near(pt.fx, -G * tb, 1e-9, 0);
        assert_near(pt.slope, tb, 1e-12, 0);  /* -fx/G: round-off of one product, one quotient */
        assert_true(pt.fz == G && pt.contacts == 2 && pt.iterations == 0);
        /* A road rising in front pushes back. */
        rising += x < -0.2 && pt.fx < 0;
        falling += x > 0.2 && pt.fx > 0;
        assert_false(x < -0.2 && pt.fx > 0);
        assert_false(x > 0.2 && pt.fx < 0);
    }
    assert_true(rising > 10 && falling > 10);
    /* Ground that rises to the centre within R0 of it is outside the model's domain: set
     * takes any profile; before a wall a short cam (a_e = R0/2) does not reach, a position
     * within R0 is refused, one farther is not. (The tire's own cam, a_e = 1.46 R0, climbs
     * any wall before it comes within R0.) */
    tirenv_tire t_short = t;
    t_short.cam.length = 0.5;
    tirenv_model *m_short = tirenv_model_alloc(tirenv_model_cam, &t_short);
    assert_non_null(m_short);
    tirenv_profile *tall = tirenv_profile_cleat(0.3, 2 * t.springs.R0);
    assert_non_null(tall);
    assert_int_equal(tirenv_model_set(m_short, tall, G, &diag), TIRENV_OK);
    tirenv_point near;
    const double R0 = t.springs.R0;
    assert_int_equal(tirenv_model_eval(m_short, -0.15 - 0.95 * R0, &near, &diag), TIRENV_ERANGE);
    assert_string_equal(diag.field, "profile");
    assert_int_equal(tirenv_model_eval(m_short, -0.15 - 1.01 * R0, &near, &diag), TIRENV_OK);
    tirenv_model_free(m_short);
    tirenv_profile_free(tall);
    tirenv_profile_free(p);
    tirenv_model_free(m);
}

/* The model's positions against tirenv_cam_tandem, bit for bit (memcmp, so that even -0 and
 * +0 would differ): the model lifts its cams through a sweep (a floor table, a memo of
 * tangencies shared by the two cams, the last position of each), tirenv_cam_tandem through
 * none, and both must equal the plain scan exactly (test_scan_exact), so no tolerance. */
static void check_against_tandem(tirenv_model *m, const tirenv_profile *p,
                                 const tirenv_cam_shape *s, double l_s, double G, double x,
                                 const char *what)
{
    tirenv_diag diag;
    tirenv_point pt;
    double w, tb;
    assert_int_equal(tirenv_model_eval(m, x, &pt, &diag), 0);
    assert_int_equal(tirenv_cam_tandem(p, s, l_s, x, &w, &tb), 0);
    const double fx = -G * tb;
    if (memcmp(&pt.h, &w, sizeof w) || memcmp(&pt.fx, &fx, sizeof fx))
        fail_msg("%s, x = %.17g: model h %.17g fx %.17g, tandem w %.17g -G*tan(beta) %.17g",
                 what, x, pt.h, pt.fx, w, fx);
}

/* The model over long roads, as the bench runs it (in order, the default tire at a 0.33 m
 * patch), and out of order: backward, at random, after tirenv_model_set_profile to another
 * road and to a window of the first (as tirenv_model_stream does), and back. Each position
 * equals tirenv_cam_tandem's, bit for bit. */
static void test_model_sweep_exact(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
    assert_non_null(m);
    tirenv_diag diag;
    double G;
    assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G, &diag), 0);
    tirenv_flat f;
    assert_int_equal(tirenv_model_flat(m, G, &f, &diag), 0);
    const double R0 = t.springs.R0, l_s = t.cam.shift * f.contact_length;
    const tirenv_cam_shape s = {t.cam.length * R0, t.cam.height * R0, t.cam.order};

    tirenv_road_settings rs = tirenv_road_default();
    rs.length = 41.3;
    rs.seed = 17;
    tirenv_profile *road = NULL, *fine = NULL, *window = NULL;
    assert_int_equal(tirenv_road_iso8608(&rs, &road, &diag), 0);
    rs.road_class = 'E';
    rs.length = 4.7;
    rs.dx = 0.001;
    assert_int_equal(tirenv_road_iso8608(&rs, &fine, &diag), 0);
    /* A window of the road: its vertices 1200 .. 2399, x from 12 m to 23.99 m. */
    const double *xs = tirenv_profile_x(road), *zs = tirenv_profile_z(road);
    window = tirenv_profile_alloc(1200, xs + 1200, zs + 1200);
    assert_non_null(window);

    assert_int_equal(tirenv_model_set(m, road, G, &diag), 0);
    for (size_t k = 0; k <= 4130; k++) /* forward, at 10 mm, off both ends */
        check_against_tandem(m, road, &s, l_s, G, -0.5 + 0.01 * (double)k, "forward");
    for (size_t k = 4130; k-- > 0;) /* backward, at 7.31 mm, between the vertices */
        check_against_tandem(m, road, &s, l_s, G, 0.00731 * (double)k, "backward");
    for (size_t k = 0; k < 1500; k++) /* at random */
        check_against_tandem(m, road, &s, l_s, G, -1.5 + 44.0 * uniform(), "random");

    assert_int_equal(tirenv_model_set_profile(m, fine, &diag), 0);
    for (size_t k = 0; k <= 6000; k++) /* forward at 0.9 mm on another road */
        check_against_tandem(m, fine, &s, l_s, G, -0.2 + 0.0009 * (double)k, "fine");
    assert_int_equal(tirenv_model_set_profile(m, window, &diag), 0);
    for (size_t k = 0; k <= 1300; k++)
        check_against_tandem(m, window, &s, l_s, G, 11.5 + 0.01 * (double)k, "window");
    assert_int_equal(tirenv_model_set_profile(m, road, &diag), 0);
    for (size_t k = 0; k < 1500; k++)
        check_against_tandem(m, road, &s, l_s, G, 10.0 + 3.0 * uniform(), "back, random");

    tirenv_profile_free(window);
    tirenv_profile_free(fine);
    tirenv_profile_free(road);
    tirenv_model_free(m);
}

/* Each cam key out of range is refused by tirenv_tire_check, naming the key. */
static void test_tire_check(void **state)
{
    (void)state;
    const struct {
        size_t offset;
        double value;
        const char *key;
    } cases[] = {
        {offsetof(tirenv_cam_params, c_z), 0.0, "VERTICAL_STIFFNESS"},
        {offsetof(tirenv_cam_params, c_z), INFINITY, "VERTICAL_STIFFNESS"},
        {offsetof(tirenv_cam_params, q_ra1), -0.1, "Q_RA1"},
        {offsetof(tirenv_cam_params, q_ra2), NAN, "Q_RA2"},
        {offsetof(tirenv_cam_params, shift), 0.0, "ELLIPS_SHIFT"},
        {offsetof(tirenv_cam_params, length), -1.4, "ELLIPS_LENGTH"},
        {offsetof(tirenv_cam_params, height), 0.0, "ELLIPS_HEIGHT"},
        {offsetof(tirenv_cam_params, order), 1.0, "ELLIPS_ORDER"},
        {offsetof(tirenv_cam_params, order), 0.5, "ELLIPS_ORDER"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tirenv_tire t = tirenv_tire_default();
        memcpy((unsigned char *)&t.cam + cases[i].offset, &cases[i].value, sizeof(double));
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        assert_int_equal(tirenv_tire_check(&t, &diag), TIRENV_EINVAL);
        assert_string_equal(diag.field, cases[i].key);
        assert_null(tirenv_model_alloc(tirenv_model_cam, &t));
    }
    /* Q_RA1 = 0 needs a positive Q_RA2, else there is no patch at all. */
    tirenv_tire t = tirenv_tire_default();
    t.cam.q_ra1 = 0;
    t.cam.q_ra2 = 0;
    tirenv_diag diag;
    assert_int_equal(tirenv_tire_check(&t, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "Q_RA2");
}

/* MF-Tyre's quadratic vertical law (docs/models.md section 7.3) with Q_FZ2 > 0 (the default
 * tire's) and < 0: at each load the deflection satisfies G = FNOMIN*(Q_FZ1*s + Q_FZ2*s^2) to
 * 1e-13 relative (a closed-form root: a few ulp), the stiffness is its tangent (against a
 * central difference of the law's loads at a step of 1e-6 of rho: the law is quadratic in s,
 * so the difference has no truncation error, only the cancellation in sp - sm and
 * sp^2 - sm^2, a few ulp of s over 2e-6 s, about 4e-10 relative; 1e-9, measured up to
 * 1.1e-10), and at FNOMIN that tangent is VERTICAL_STIFFNESS (1e-12); the contact
 * length gives back the load (1e-12). Q_FZ2 < 0: beyond the law's peak load refused, naming
 * the load; Q_FZ2 too large for a Q_FZ1: refused naming Q_FZ2. */
static void test_vertical_law_quadratic(void **state)
{
    (void)state;
    const double q_fz2[] = {29.4, 13.71, -7.93};
    for (size_t i = 0; i < sizeof q_fz2 / sizeof q_fz2[0]; i++) {
        tirenv_tire t = tirenv_tire_default();
        t.cam.q_fz2 = q_fz2[i];
        const double R0 = t.springs.R0, F0 = t.cam.fnomin, k = t.cam.c_z * R0 / F0;
        const double q1 = sqrt(k * k - 4 * q_fz2[i]);
        tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
        assert_non_null(m);
        tirenv_diag diag;
        const double loads[] = {5931.7, 12963.52, F0, 23751.9};
        for (size_t j = 0; j < sizeof loads / sizeof loads[0]; j++) {
            tirenv_flat f;
            assert_int_equal(tirenv_model_flat(m, loads[j], &f, &diag), TIRENV_OK);
            const double s = f.deflection / R0;
            assert_near(F0 * (q1 * s + q_fz2[i] * s * s), loads[j], 0, 1e-13);
            const double d = 1e-6 * f.deflection, sp = (f.deflection + d) / R0,
                         sm = (f.deflection - d) / R0;
            const double dG = F0 * (q1 * (sp - sm) + q_fz2[i] * (sp * sp - sm * sm));
            assert_near(f.stiffness, dG / (2 * d), 0, 1e-9);
            if (loads[j] == F0)
                assert_near(f.stiffness, t.cam.c_z, 0, 1e-12);
            double G;
            assert_int_equal(tirenv_model_load_for_contact_length(m, f.contact_length, &G,
                                                                  &diag), TIRENV_OK);
            assert_near(G, loads[j], 0, 1e-12);
        }
        if (q_fz2[i] < 0) {
            const double G_peak = F0 * q1 * q1 / (-4 * q_fz2[i]);
            tirenv_flat f;
            assert_int_equal(tirenv_model_flat(m, 1.001 * G_peak, &f, &diag), TIRENV_ERANGE);
            assert_string_equal(diag.field, "load");
        }
        tirenv_model_free(m);
    }
    tirenv_tire t = tirenv_tire_default();
    const double k = t.cam.c_z * t.springs.R0 / t.cam.fnomin;
    t.cam.q_fz2 = 0.2501 * k * k;
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
    assert_non_null(m);
    tirenv_flat f;
    tirenv_diag diag;
    assert_int_equal(tirenv_model_flat(m, 15000, &f, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "Q_FZ2");
    tirenv_model_free(m);
    /* Q_FZ2 without FNOMIN: refused by the tire check. */
    t = tirenv_tire_default();
    t.cam.fnomin = 0;
    assert_int_equal(tirenv_tire_check(&t, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "Q_FZ2");
}

/* The cam's vertical law is MF-Tyre 6.1's at standstill (docs/models.md section 7.3), with a
 * tire's own Q_FZ1 and PFZ1's pressure factor f = 1 + PFZ1*(INFLPRES - NOMPRES)/NOMPRES:
 * F_z = f*FNOMIN*(Q_FZ1*s + Q_FZ2*s^2). Q_FZ1 12.3 is 34 % above the 9.15 that the default's
 * VERTICAL_STIFFNESS gives, f = 1.2075 (1.5 bar on 1.2 bar nominal, PFZ1 0.83); each alone,
 * both, and each on a linear law (Q_FZ2 0). At FNOMIN and two other loads the deflection is the
 * closed form's, the textbook root (-Q_FZ1 + sqrt(Q_FZ1^2 + 4 Q_FZ2 g))/(2 Q_FZ2) of
 * g = F_z/(f*FNOMIN) (g/Q_FZ1 without Q_FZ2), another form than the cam's, whose cancellation
 * costs a few ulp: 1e-12 relative; the stiffness is the law's tangent and the contact length
 * MF-Tyre's at that deflection (1e-12), and the load comes back from the contact length. A
 * Q_FZ1 equal to the one VERTICAL_STIFFNESS gives, and a PFZ1 at INFLPRES = NOMPRES, leave
 * every bit as it was. Bad keys are refused naming them. */
static void test_vertical_law_own_q_fz1_and_pressure(void **state)
{
    (void)state;
    const tirenv_tire def = tirenv_tire_default();
    const double R0 = def.springs.R0, F0 = def.cam.fnomin;
    const struct { double q_fz1, q_fz2, pfz1; } cases[] = {
        {12.3, 28.7, 0}, {0, 28.7, 0.83}, {12.3, 28.7, 0.83}, {0, 0, 0.83}, {12.3, 0, 0},
        {12.3, -7.93, 0.83},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tirenv_tire t = def;
        t.cam.q_fz1 = cases[i].q_fz1;
        t.cam.q_fz2 = cases[i].q_fz2;
        t.cam.pfz1 = cases[i].pfz1;
        t.ring.p = 1.5e5;
        t.ring.p_nom = 1.2e5;
        tirenv_diag diag;
        assert_int_equal(tirenv_tire_check(&t, &diag), TIRENV_OK);
        const double f = 1 + cases[i].pfz1 * 0.25, q2 = cases[i].q_fz2;
        const double q1 = cases[i].q_fz1 != 0 ? cases[i].q_fz1
                                              : tirenv_cam_q_fz1(t.cam.c_z, R0, F0, q2);
        tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
        assert_non_null(m);
        const double loads[] = {F0, 0.5 * F0, 1.5 * F0};
        for (size_t j = 0; j < 3; j++) {
            const double g = loads[j] / (f * F0);
            const double s = q2 == 0 ? g / q1 : (-q1 + sqrt(q1 * q1 + 4 * q2 * g)) / (2 * q2);
            tirenv_flat fl;
            assert_int_equal(tirenv_model_flat(m, loads[j], &fl, &diag), TIRENV_OK);
            print_message("Q_FZ1 %g, Q_FZ2 %g, PFZ1 %g: %.0f N deflects %.4f mm (closed form "
                          "%.4f mm)\n", cases[i].q_fz1, q2, cases[i].pfz1, loads[j],
                          1e3 * fl.deflection, 1e3 * R0 * s);
            assert_near(fl.deflection, R0 * s, 0, 1e-12);
            assert_near(fl.stiffness, f * F0 / R0 * (q1 + 2 * q2 * s), 0, 1e-12);
            assert_near(fl.contact_length,
                        2 * R0 * (t.cam.q_ra2 * s + t.cam.q_ra1 * sqrt(s)), 0, 1e-12);
            double G;
            assert_int_equal(tirenv_model_load_for_contact_length(m, fl.contact_length, &G,
                                                                  &diag), TIRENV_OK);
            assert_near(G, loads[j], 0, 1e-12);
        }
        tirenv_model_free(m);
    }
    /* Neutral values change no bit. */
    tirenv_tire same = def;
    same.cam.q_fz1 = tirenv_cam_q_fz1(def.cam.c_z, R0, F0, def.cam.q_fz2);
    same.cam.pfz1 = 0.83;  /* INFLPRES = NOMPRES */
    tirenv_model *m0 = tirenv_model_alloc(tirenv_model_cam, &def);
    tirenv_model *m1 = tirenv_model_alloc(tirenv_model_cam, &same);
    assert_non_null(m0);
    assert_non_null(m1);
    tirenv_diag diag;
    for (double G = 6000; G < 26000; G += 3917.3) {
        tirenv_flat a, b;
        assert_int_equal(tirenv_model_flat(m0, G, &a, &diag), TIRENV_OK);
        assert_int_equal(tirenv_model_flat(m1, G, &b, &diag), TIRENV_OK);
        assert_memory_equal(&a, &b, sizeof a);
    }
    tirenv_model_free(m0);
    tirenv_model_free(m1);
    /* Refused: a negative Q_FZ1, a Q_FZ1 without FNOMIN, PFZ1 without NOMPRES, and a pressure
     * factor that leaves no load (PFZ1 -5 at 1.25 times NOMPRES: f = -0.25). */
    tirenv_tire t = def;
    t.cam.q_fz1 = -3;
    assert_int_equal(tirenv_tire_check(&t, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "Q_FZ1");
    t = def;
    t.cam.q_fz1 = 12.3;
    t.cam.q_fz2 = 0;
    t.cam.fnomin = 0;
    assert_int_equal(tirenv_tire_check(&t, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "Q_FZ1");
    t = def;
    t.cam.pfz1 = 0.5;
    t.ring.p_nom = 0;
    assert_int_equal(tirenv_tire_check(&t, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "PFZ1");
    t = def;
    t.cam.pfz1 = -5;
    t.ring.p = 1.5e5;
    assert_int_equal(tirenv_tire_check(&t, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "PFZ1");
    assert_non_null(strstr(diag.message, "-0.25"));
    assert_null(tirenv_model_alloc(tirenv_model_cam, &t));  /* it checks the tire too */
}

/* The two least-squares fits of MF-Tyre's laws (tirenv_cam_fit_vertical_law and
 * tirenv_cam_fit_contact_law, one 2x2 normal-equation solve): on states made by each law from
 * known keys, both keys come back. The states are exact to a few ulp, so the keys' error is
 * that round-off times the normal matrices' condition numbers, 1.1e3 and 3.4e2 here (s = rho/R0
 * from 0.03 to 0.12): at most about 1e-12 relative, measured 1.2e-15; 1e-9 leaves a wide margin
 * and still catches a wrong row or a swapped key. One state, or states all alike, do not
 * separate the two terms: TIRENV_EINVAL with the outputs untouched. */
static void test_law_fits(void **state)
{
    (void)state;
    const double R0 = 0.5137, F0 = 4123.7, q_fz1 = 9.873, q_fz2 = 17.31, q_ra1 = 0.4613,
                 q_ra2 = 0.8912;
    const double rho[] = {0.0163, 0.0291, 0.03574, 0.0469, 0.0617};
    enum { N = sizeof rho / sizeof rho[0] };
    double G[N], l[N];
    for (size_t i = 0; i < N; i++) {
        const double s = rho[i] / R0, r = sqrt(s);
        G[i] = F0 * (q_fz1 * s + q_fz2 * s * s);
        l[i] = 2 * R0 * (q_ra2 * r * r + q_ra1 * r);
    }
    double p = 0, q = 0;
    assert_int_equal(tirenv_cam_fit_vertical_law(R0, F0, N, rho, G, &p, &q), TIRENV_OK);
    assert_near(p, q_fz1, 0, 1e-9);
    assert_near(q, q_fz2, 0, 1e-9);
    assert_int_equal(tirenv_cam_fit_contact_law(R0, N, rho, l, &p, &q), TIRENV_OK);
    assert_near(p, q_ra1, 0, 1e-9);
    assert_near(q, q_ra2, 0, 1e-9);
    const double same_rho[] = {rho[2], rho[2], rho[2]}, same_G[] = {G[2], G[2], G[2]},
                 same_l[] = {l[2], l[2], l[2]};
    for (size_t n = 1; n <= 3; n += 2) {
        p = q = 2.385;
        assert_int_equal(tirenv_cam_fit_vertical_law(R0, F0, n, same_rho, same_G, &p, &q),
                         TIRENV_EINVAL);
        assert_int_equal(tirenv_cam_fit_contact_law(R0, n, same_rho, same_l, &p, &q),
                         TIRENV_EINVAL);
        assert_true(p == 2.385 && q == 2.385);
    }
}

/* The shipped MF-Swift example loads unchanged over the default tire: its radius, vertical
 * stiffness and cam, and tirenv's own sections for this tire (a car-sized ring with a softening
 * carcass identified on TNO's laws, and the springs model identified on that ring:
 * docs/models.md 14.2); the ring's lugs stay the default's. At 4 kN its patch is 2a = 0.1318 m
 * and the tandem base 0.1097 m. */
static void test_mfswift_file(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_tir_read(TIRENV_DATA_DIR "/tires/205-60R15-mfswift.tir", &t, &diag),
                     TIRENV_OK);
    tirenv_tire expected = tirenv_tire_default();
    expected.springs.R0 = 0.3135;
    expected.springs.c_r = 4.456e5;
    expected.springs.c_b = 9821;
    expected.springs.k_s = 6.223e5;
    expected.springs.F_s0 = 2584;
    expected.ring.t_r = 0.010;
    expected.ring.EI = 3.27;
    expected.ring.T = 0;
    expected.ring.k_c = 1.14e6;
    expected.ring.w_cs = 0.00448;
    expected.ring.w_c0 = 0.00111;
    expected.ring.k_t = 1.42e7;
    expected.ring.b_p = 0.085;
    expected.ring.alpha_s = 1.2;
    expected.ring.p = 220000;
    expected.ring.p_nom = 220000;
    expected.ring.G_t = 5e5;             /* the file's tread coupled in shear at 0.25 degrees */
    expected.ring.dtheta = M_PI / 720.0;
    expected.cam = (tirenv_cam_params){.c_z = 209651.5, .fnomin = 4000, .q_fz2 = 0,
                                       .q_ra1 = 0.6715, .q_ra2 = 0.7308,
                                       .shift = 0.8328, .length = 1.4634, .height = 0.9551,
                                       .order = 1.5257, .given = TIRENV_CAM_ALL,
                                       .max_step = 0.025};
    assert_memory_equal(&t.springs, &expected.springs, sizeof t.springs);
    assert_memory_equal(&t.ring, &expected.ring, sizeof t.ring);
    /* up to given, then max_step: not the padding between */
    assert_memory_equal(&t.cam, &expected.cam,
                        offsetof(tirenv_cam_params, given) + sizeof t.cam.given);
    assert_true(t.cam.max_step == expected.cam.max_step);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
    assert_non_null(m);
    tirenv_flat f;
    assert_int_equal(tirenv_model_flat(m, 4000, &f, &diag), 0);
    print_message("205/60R15 at 4 kN: deflection %.2f mm, contact length %.4f m\n",
                  f.deflection * 1e3, f.contact_length);
    assert_near(f.contact_length, 0.131753, 1e-6, 0);
    tirenv_model_free(m);
}

/* ELLIPS_MAX_STEP changes no result; where a cam first touches the ground more than that
 * above its lowest point (the cleat's edge, at the curve's first rise), the warnings say
 * where and how high, and a set on other ground starts afresh. */
static void max_step_sweep(double max_step, double H, tirenv_point pt[], size_t n,
                           char said[], size_t said_size)
{
    tirenv_tire t = tirenv_tire_default();
    t.cam.max_step = max_step;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &t);
    tirenv_profile *tall = tirenv_profile_cleat(0.10, H), *low = tirenv_profile_cleat(0.10, 0.01);
    assert_non_null(m);
    assert_non_null(tall);
    assert_non_null(low);
    double *x = malloc(n * sizeof *x);
    assert_non_null(x);
    for (size_t k = 0; k < n; ++k)
        x[k] = -1.5 + 1e-3 * (double)k;
    assert_int_equal(tirenv_model_set(m, tall, 17900, &diag), TIRENV_OK);
    assert_string_equal(tirenv_model_warnings(m), "");  /* nothing evaluated yet */
    assert_int_equal(tirenv_model_envelope(m, n, x, pt, NULL, &diag), TIRENV_OK);
    snprintf(said, said_size, "%s", tirenv_model_warnings(m));
    assert_int_equal(tirenv_model_set(m, low, 17900, &diag), TIRENV_OK);
    assert_int_equal(tirenv_model_envelope(m, n, x, pt + n, NULL, &diag), TIRENV_OK);
    assert_string_equal(tirenv_model_warnings(m), "");
    free(x);
    tirenv_profile_free(tall);
    tirenv_profile_free(low);
    tirenv_model_free(m);
}

static void test_max_step(void **state)
{
    (void)state;
    enum { N = 1501 };
    tirenv_point *a = malloc(2 * N * sizeof *a), *b = malloc(2 * N * sizeof *b);
    assert_non_null(a);
    assert_non_null(b);
    char said[512];
    max_step_sweep(0, 0.03, a, N, said, sizeof said);
    assert_string_equal(said, "");  /* none declared */
    max_step_sweep(0.025, 0.02, b, N, said, sizeof said);
    assert_string_equal(said, "");  /* lower than declared */
    assert_memory_equal(a + N, b + N, N * sizeof *a);
    max_step_sweep(0.025, 0.03, b, N, said, sizeof said);
    assert_memory_equal(a, b, 2 * N * sizeof *a);  /* the same points, warned or not */
    size_t first = 0;
    while (first < N && !(a[first].h > 0))
        ++first;
    assert_true(first < N);
    double x = NAN, dz = NAN;
    print_message("%s\n", said);
    assert_int_equal(sscanf(said, "at x = %lf m a cam touches the ground %lf mm", &x, &dz), 2);
    assert_true(fabs(x - a[first].x) < 1e-6);  /* as printed, %.6g */
    assert_true(dz > 25 && dz <= 30);
    assert_non_null(strstr(said, "ELLIPS_MAX_STEP (25 mm)"));
    free(a);
    free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_step),
        cmocka_unit_test(test_slope),
        cmocka_unit_test(test_oracle),
        cmocka_unit_test(test_rigid_disc),
        cmocka_unit_test(test_limits),
        cmocka_unit_test(test_invalid),
        cmocka_unit_test(test_tandem_flat),
        cmocka_unit_test(test_tandem_symmetry),
        cmocka_unit_test(test_double_hump),
        cmocka_unit_test(test_flat_and_contact_length),
        cmocka_unit_test(test_vertical_law_quadratic),
        cmocka_unit_test(test_vertical_law_own_q_fz1_and_pressure),
        cmocka_unit_test(test_law_fits),
        cmocka_unit_test(test_model_point),
        cmocka_unit_test(test_model_sweep_exact),
        cmocka_unit_test(test_tire_check),
        cmocka_unit_test(test_mfswift_file),
        cmocka_unit_test(test_max_step),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
