/* The rigid disc (docs/models.md section 3) against closed forms and a brute-force oracle.
 * SPDX-License-Identifier: Apache-2.0
 *
 * Tolerances. Centre heights are below 1 m; the implementation and each closed form take a
 * handful of correctly rounded operations (a square root, a hypot, a few products), so they
 * agree to about 10 ulp of 1 m, 2e-15 m. TOL = 1e-14 m leaves a factor 5 margin and is still
 * ten orders below any modelling error that matters (a wrong candidate is off by > 1e-6 m).
 * The half-cylinder and the dense-sampling oracle have their own, derived, bounds below. */
#include "testutil.h"

#include <math.h>
#include <stdint.h>

#include "tirenv/model.h"
#include "tirenv/profile.h"
#include "tirenv/rigid.h"

#define TOL 1e-14

static const double R0 = 0.6837;

/* Disc height over a single point at horizontal distance u, or -inf when out of reach. */
static double over(double u, double p_z)
{
    return fabs(u) <= R0 ? p_z + sqrt(R0 * R0 - u * u) : -INFINITY;
}

/* The contact point lies on the ground and on the disc's rim, to round-off. */
static void assert_contact(const tirenv_profile *p, double x)
{
    double px = NAN, pz = NAN;
    const double z = tirenv_rigid_height(p, R0, x, &px, &pz);
    assert_true(fabs(px - x) <= R0);
    assert_near(pz, tirenv_profile_height(p, px), TOL, 0);
    assert_near(hypot(x - px, z - pz), R0, TOL, 0);
}

static void test_flat(void **state)
{
    (void)state;
    const double x1 = 0.1234, z1 = 0.0;
    tirenv_profile *one = tirenv_profile_alloc(1, &x1, &z1);
    const double xs[] = {-0.4417, -0.1031, 0.0277, 0.3912}, zs[] = {0, 0, 0, 0};
    tirenv_profile *many = tirenv_profile_alloc(4, xs, zs);
    assert_non_null(one);
    assert_non_null(many);
    for (double x = -1.9371; x < 1.9; x += 0.0517) {
        double px, pz;
        assert_true(tirenv_rigid_height(one, R0, x, &px, &pz) == R0);
        assert_true(px == x && pz == 0.0);
        assert_true(tirenv_rigid_height(many, R0, x, NULL, NULL) == R0);
        assert_contact(many, x);
    }
    tirenv_profile_free(one);
    tirenv_profile_free(many);
}

static void test_invalid(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_cleat(0.2931, 0.0743);
    assert_non_null(p);
    const double bad_R0[] = {0.0, -0.6837, NAN, INFINITY};
    for (size_t i = 0; i < 4; i++) {
        double px = 0, pz = 0;
        assert_true(isnan(tirenv_rigid_height(p, bad_R0[i], 0.1, &px, &pz)));
        assert_true(isnan(px) && isnan(pz));
    }
    assert_true(isnan(tirenv_rigid_height(p, R0, NAN, NULL, NULL)));
    assert_true(isnan(tirenv_rigid_height(p, R0, -INFINITY, NULL, NULL)));
    tirenv_profile_free(p);
}

/* Rectangular cleat L x H: on top the centre is at H + R0; in front it pivots on the corner
 * (-L/2, H) once that is higher than the flat ground, i.e. from
 * x_rise = -L/2 - sqrt(R0^2 - (R0 - H)^2) on; behind, the mirror image. */
static void test_cleat(void **state)
{
    (void)state;
    const double L = 0.2931, H = 0.0743;
    tirenv_profile *p = tirenv_profile_cleat(L, H);
    assert_non_null(p);
    const double x_rise = -L / 2 - sqrt(R0 * R0 - (R0 - H) * (R0 - H));
    for (double x = -1.3117; x <= 1.3117; x += 0.00731) {
        const double u = fabs(x) - L / 2; /* distance past the nearer corner */
        const double z_exact = u <= 0 ? H + R0 : fmax(R0, over(u, H));
        assert_near(tirenv_rigid_height(p, R0, x, NULL, NULL), z_exact, TOL, 0);
        assert_contact(p, x);
    }
    assert_true(tirenv_rigid_height(p, R0, x_rise - 1e-9, NULL, NULL) == R0);
    assert_true(tirenv_rigid_height(p, R0, -L / 2 - R0 - 0.0193, NULL, NULL) == R0);
    assert_near(tirenv_rigid_height(p, R0, x_rise, NULL, NULL), R0, TOL, 0);
    double px, pz;
    assert_true(tirenv_rigid_height(p, R0, x_rise + 1e-6, &px, &pz) > R0);
    assert_true(px == -L / 2 && pz == H); /* pivoting on the corner */
    assert_near(tirenv_rigid_height(p, R0, -L / 2, NULL, NULL), H + R0, TOL, 0);
    assert_near(tirenv_rigid_height(p, R0, 0.0311, NULL, NULL), H + R0, TOL, 0);
    tirenv_profile_free(p);
}

/* Step of H at x0: up, the corner (x0, H) lifts the disc before x0 and the upper level
 * carries it after; down, the upper edge (x0, 0) holds it until the lower level takes over. */
static void test_step(void **state)
{
    (void)state;
    const double x0 = 0.1379, H_up = 0.0562;
    tirenv_profile *up = tirenv_profile_step(x0, H_up);
    tirenv_profile *down = tirenv_profile_step(x0, -H_up);
    assert_non_null(up);
    assert_non_null(down);
    for (double x = x0 - R0 - 0.2113; x <= x0 + R0 + 0.2; x += 0.00617) {
        const double z_up = x >= x0 ? H_up + R0 : fmax(R0, over(x - x0, H_up));
        const double z_down = x <= x0 ? R0 : fmax(R0 - H_up, over(x - x0, 0.0));
        assert_near(tirenv_rigid_height(up, R0, x, NULL, NULL), z_up, TOL, 0);
        assert_near(tirenv_rigid_height(down, R0, x, NULL, NULL), z_down, TOL, 0);
        assert_contact(up, x);
        assert_contact(down, x);
    }
    tirenv_profile_free(up);
    tirenv_profile_free(down);
}

/* Centre height over a smooth half-cylinder of radius rho on the ground: the disc touches
 * the arc while its centre is at distance R0 + rho from the cylinder's centre, else the
 * ground. */
static double z_cylinder(double rho, double x)
{
    const double s = R0 + rho;
    return fabs(x) < s ? fmax(R0, sqrt(s * s - x * x)) : R0;
}

/* The polyline of n segments is inscribed in the circle of radius r, and each chord
 * (subtending pi/n) lies at distance r_a = r cos(pi/(2n)) from the centre. With the ground,
 * the polygon is convex, so it contains the half-disc of radius r_a and is contained in the
 * half-disc of radius r. The rigid height only grows with the obstacle, so
 *   z_cylinder(r_a, x) <= z(x) <= z_cylinder(r, x),
 * and, as d z_cylinder / d rho = (R0 + rho) / z_cylinder <= (R0 + r) / R0, the discretisation
 * error is at most r (1 - cos(pi/(2n))) (1 + r/R0), about r pi^2 / (8 n^2) (1 + r/R0).
 * Both bounds are attained at x = 0: the apex vertex (even n) or the top chord (odd n). */
static void test_half_cylinder(void **state)
{
    (void)state;
    const double r = 0.2173;
    const size_t segs[] = {7, 8, 64, 511};
    for (size_t i = 0; i < sizeof segs / sizeof segs[0]; i++) {
        const size_t n = segs[i];
        const double r_a = r * cos(M_PI / (2.0 * (double)n));
        const double bound = (r - r_a) * (1.0 + r / R0);
        tirenv_profile *p = tirenv_profile_half_cylinder(r, n);
        assert_non_null(p);
        for (double x = -1.0131; x <= 1.0131; x += 0.00377) {
            const double z = tirenv_rigid_height(p, R0, x, NULL, NULL);
            assert_true(z >= z_cylinder(r_a, x) - TOL);
            assert_true(z <= z_cylinder(r, x) + TOL);
            assert_near(z, z_cylinder(r, x), bound + TOL, 0);
            assert_contact(p, x);
        }
        const double z0 = tirenv_rigid_height(p, R0, 0.0, NULL, NULL);
        assert_near(z0, n % 2 == 0 ? R0 + r : R0 + r_a, TOL, 0);
        tirenv_profile_free(p);
    }
}

/* Disc over a slope rising at angle alpha from (x_foot, 0) (tan alpha = t): tangent to it,
 * the centre runs on the parallel line R0 / cos(alpha) higher, while the tangency point
 * P_x = x + R0 sin(alpha) lies on the slope. */
static double z_slope(double x, double x_foot, double t)
{
    const double cos_a = 1.0 / sqrt(1.0 + t * t);
    return (x - x_foot) * t + R0 / cos_a;
}

/* Symmetric trapezoid (L_top = 0: triangle) of height H: ground, slope, top corner, top,
 * by ranges of x, with the ranges' ends where the tangency point reaches a vertex. The flat
 * ground wins over the slope near its foot, and over the top corner too when the slope is
 * steep: H + R0 cos(alpha) < R0 when H < R0 (1 - cos(alpha)). */
static double z_trapezoid(double L_top, double L_base, double H, double x)
{
    const double a = -fabs(x); /* mirror onto the approach side */
    const double t = H / ((L_base - L_top) / 2);
    const double sin_a = t / sqrt(1.0 + t * t);
    if (a < -L_base / 2 - R0 * sin_a)
        return R0;
    if (a < -L_top / 2 - R0 * sin_a)
        return fmax(R0, z_slope(a, -L_base / 2, t));
    if (a < -L_top / 2)
        return fmax(R0, H + sqrt(R0 * R0 - (a + L_top / 2) * (a + L_top / 2)));
    return H + R0;
}

static void test_triangle_trapezoid(void **state)
{
    (void)state;
    const double T = 0.1187, B = 0.4127, H = 0.0891;
    tirenv_profile *tri = tirenv_profile_triangle(B, H);
    tirenv_profile *trap = tirenv_profile_trapezoid(T, B, H);
    assert_non_null(tri);
    assert_non_null(trap);
    for (double x = -1.2219; x <= 1.2219; x += 0.00533) {
        assert_near(tirenv_rigid_height(tri, R0, x, NULL, NULL), z_trapezoid(0.0, B, H, x),
                    TOL, 0);
        assert_near(tirenv_rigid_height(trap, R0, x, NULL, NULL), z_trapezoid(T, B, H, x),
                    TOL, 0);
        assert_contact(tri, x);
        assert_contact(trap, x);
    }
    /* First rise over the triangle: where the slope's offset line meets z = R0. */
    const double t = 2 * H / B, cos_a = 1.0 / sqrt(1.0 + t * t);
    const double x_rise = -B / 2 + R0 * (1.0 - 1.0 / cos_a) / t;
    assert_near(tirenv_rigid_height(tri, R0, x_rise, NULL, NULL), R0, TOL, 0);
    assert_true(tirenv_rigid_height(tri, R0, x_rise + 1e-6, NULL, NULL) > R0);
    tirenv_profile_free(tri);
    tirenv_profile_free(trap);
}

/* Symmetric obstacles give z(x) = z(-x); the two sides visit different segments in a
 * different order, so the agreement is to round-off (TOL), not bitwise. */
static void test_symmetry(void **state)
{
    (void)state;
    tirenv_profile *ps[] = {
        tirenv_profile_cleat(0.2931, 0.0743),
        tirenv_profile_triangle(0.4127, 0.0891),
        tirenv_profile_trapezoid(0.1187, 0.3413, 0.1029),
        tirenv_profile_half_cylinder(0.2173, 7),
        tirenv_profile_half_cylinder(0.1517, 40),
    };
    for (size_t i = 0; i < sizeof ps / sizeof ps[0]; i++) {
        assert_non_null(ps[i]);
        for (double x = 0.0; x <= 1.1; x += 0.00419)
            assert_near(tirenv_rigid_height(ps[i], R0, x, NULL, NULL),
                        tirenv_rigid_height(ps[i], R0, -x, NULL, NULL), TOL, 0);
        tirenv_profile_free(ps[i]);
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
#define N_SAMPLE 100000

/* Max of p_z + sqrt(R0^2 - (x - p_x)^2) over N_SAMPLE evenly spaced points (ends included)
 * of the part of the segment (xa, za)-(xb, zb) within reach of x. */
static double sample_segment(double x, double xa, double za, double xb, double zb)
{
    double best = -INFINITY;
    if (xa == xb) { /* a wall: sample its height */
        for (size_t i = 0; i < N_SAMPLE; i++)
            best = fmax(best, over(x - xa, za + (zb - za) * (double)i / (N_SAMPLE - 1)));
        return best;
    }
    const double lo = fmax(xa, x - R0), hi = fmin(xb, x + R0);
    if (lo > hi)
        return best;
    for (size_t i = 0; i < N_SAMPLE; i++) {
        const double p_x = lo + (hi - lo) * (double)i / (N_SAMPLE - 1);
        const double p_z =
            isinf(xa) || isinf(xb) ? za : za + (zb - za) * (p_x - xa) / (xb - xa);
        best = fmax(best, over(x - p_x, p_z));
    }
    return best;
}

/* The oracle samples boundary points, so it can only be below the exact maximum (to
 * round-off). How far below: the maximum is a vertex (sampled exactly) or a tangency point,
 * and the nearest sample is within delta = h/2 of it, h = 2 R0 / (N_SAMPLE - 1) the largest
 * spacing. Near a tangency with upward normal component n_z the touching height has
 * curvature |f''| = R0^2 / (R0^2 - u^2)^(3/2) = 1 / (R0 n_z^3), so the loss is at most
 * |f''| delta^2 / 2; doubling it covers |f''| growing within delta of the tangency. With
 * these profiles (n_z >= 0.199) the bound is at most 9e-9 m; the gap seen is about 3e-11 m. */
/* The effective slope -fx/fz is the envelope's own slope dz/dx for a rigid disc (the ground
 * force is normal to the rim, and the envelope is the rim's locus), checked by central
 * differences of step d = 1e-6 m away from the kinks where the contact point jumps. The
 * difference's truncation error is d^2 |z'''| / 6 < 1e-12 and its round-off 2e-16 / d = 2e-10,
 * so 1e-8 is a safe bound that a sign or factor error would break by orders. */
static void test_slope(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.springs.R0 = R0;
    tirenv_model *m = tirenv_model_alloc(tirenv_model_rigid, &tire);
    tirenv_profile *p = tirenv_profile_cleat(0.2931, 0.0743);
    assert_non_null(m);
    assert_non_null(p);
    tirenv_diag diag;
    assert_int_equal(tirenv_model_set(m, p, 1e4, &diag), 0);
    const double d = 1e-6;
    int checked = 0;
    for (double x = -0.9173; x < 0.92; x += 0.0311) {
        tirenv_point a, b, c;
        double pa, pb, pz;
        tirenv_rigid_height(p, R0, x - d, &pa, &pz);
        tirenv_rigid_height(p, R0, x + d, &pb, &pz);
        if (fabs(pa - pb) > 4 * d)  /* the contact jumps: a kink of the envelope */
            continue;
        assert_int_equal(tirenv_model_eval(m, x - d, &a, &diag), 0);
        assert_int_equal(tirenv_model_eval(m, x, &b, &diag), 0);
        assert_int_equal(tirenv_model_eval(m, x + d, &c, &diag), 0);
        assert_near(b.slope, (c.z - a.z) / (2 * d), 1e-8, 0);
        ++checked;
    }
    assert_true(checked > 50);
    tirenv_profile_free(p);
    tirenv_model_free(m);
}

static void test_oracle(void **state)
{
    (void)state;
    for (int trial = 0; trial < 4; trial++) {
        double x[N_VERT], z[N_VERT];
        x[0] = -0.7 + 0.1 * uniform();
        z[0] = -0.05 + 0.2 * uniform();
        double n_z_min = 1.0; /* the flat extensions have n_z = 1 */
        for (size_t k = 1; k < N_VERT; k++) {
            const int wall = uniform() < 0.2 && !(k >= 2 && x[k - 1] == x[k - 2]);
            x[k] = x[k - 1] + (wall ? 0.0 : 0.03 + 0.17 * uniform());
            z[k] = -0.05 + 0.2 * uniform();
            if (!wall) {
                const double dx = x[k] - x[k - 1], dz = z[k] - z[k - 1];
                n_z_min = fmin(n_z_min, dx / hypot(dx, dz));
            }
        }
        tirenv_profile *p = tirenv_profile_alloc(N_VERT, x, z);
        assert_non_null(p);
        const double delta = R0 / (N_SAMPLE - 1);
        const double tol = delta * delta / (R0 * pow(n_z_min, 3)) + TOL;
        print_message("trial %d: n_z_min %.3f, tol %.2g m\n", trial, n_z_min, tol);
        const double x_lo = x[0] - R0 - 0.05, x_hi = x[N_VERT - 1] + R0 + 0.05;
        for (int j = 0; j <= 24; j++) {
            const double xc = x_lo + (x_hi - x_lo) * (j + 0.5 * uniform()) / 25.0;
            double oracle = fmax(sample_segment(xc, -INFINITY, z[0], x[0], z[0]),
                                 sample_segment(xc, x[N_VERT - 1], z[N_VERT - 1], INFINITY,
                                                z[N_VERT - 1]));
            for (size_t k = 0; k + 1 < N_VERT; k++)
                oracle = fmax(oracle, sample_segment(xc, x[k], z[k], x[k + 1], z[k + 1]));
            const double exact = tirenv_rigid_height(p, R0, xc, NULL, NULL);
            assert_true(oracle <= exact + TOL);  /* no boundary point holds the disc higher */
            assert_true(exact - oracle <= tol);  /* and the exact value is attained */
            assert_contact(p, xc);
        }
        tirenv_profile_free(p);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flat),
        cmocka_unit_test(test_invalid),
        cmocka_unit_test(test_cleat),
        cmocka_unit_test(test_step),
        cmocka_unit_test(test_half_cylinder),
        cmocka_unit_test(test_triangle_trapezoid),
        cmocka_unit_test(test_symmetry),
        cmocka_unit_test(test_oracle),
        cmocka_unit_test(test_slope),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
