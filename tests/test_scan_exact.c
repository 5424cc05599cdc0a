/* The pruned scans of the rigid disc (block maxima, MODEL.md section 3) against the plain
 * scan they replace, on long random polylines: equal bit for bit, contact point included.
 * SPDX-License-Identifier: GPL-3.0-or-later
 *
 * Exact equality is the contract, not a tolerance: the pruning only skips candidates strictly
 * below the final best and keeps the others in the plain scan's order, so even ties resolve
 * the same way. */
#include "testutil.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

#include "tirenv/profile.h"
#include "tirenv/cam.h"
#include "tirenv/rigid.h"
#include "model/rigid_impl.h"

/* The plain scan, as rigid.c had it before the block maxima: every vertex and every sloped
 * segment's tangency within [x - R0, x + R0], left to right, plus the flat extensions. */
static double plain_rigid(size_t n, const double xs[], const double zs[], double R0, double x,
                          double *px, double *pz)
{
    double z_c = -INFINITY, p_x = NAN, p_z = NAN;
#define CONSIDER(Z, X, P)                                                                    \
    do {                                                                                     \
        if ((Z) > z_c) {                                                                     \
            z_c = (Z);                                                                       \
            p_x = (X);                                                                       \
            p_z = (P);                                                                       \
        }                                                                                    \
    } while (0)
    if (x <= xs[0])
        CONSIDER(zs[0] + R0, x, zs[0]);
    if (x >= xs[n - 1])
        CONSIDER(zs[n - 1] + R0, x, zs[n - 1]);
    const double x_lo = x - R0, x_hi = x + R0;
    size_t k0 = 0;
    while (k0 + 1 < n && xs[k0 + 1] <= x_lo)
        k0++;
    for (size_t k = k0; k < n && xs[k] <= x_hi; k++) {
        if (xs[k] >= x_lo) {
            const double u = x - xs[k];
            CONSIDER(zs[k] + sqrt(fmax(0.0, (R0 - u) * (R0 + u))), xs[k], zs[k]);
        }
        if (k + 1 == n || !(xs[k + 1] > xs[k]))
            continue;
        const double dx = xs[k + 1] - xs[k], dz = zs[k + 1] - zs[k];
        const double len = hypot(dx, dz);
        const double P_x = x + R0 * (dz / len);
        if (P_x > xs[k] && P_x < xs[k + 1]) {
            const double P_z = zs[k] + dz * ((P_x - xs[k]) / dx);
            CONSIDER(P_z + R0 * (dx / len), P_x, P_z);
        }
    }
#undef CONSIDER
    *px = p_x;
    *pz = p_z;
    return z_c;
}

/* A random polyline of n vertices: spacing 0 (a wall, never three at one x), 1 mm or up to
 * 30 mm; heights a random walk with occasional jumps and flat runs, so that ties and walls
 * both occur. */
static tirenv_profile *random_polyline(gsl_rng *rng, size_t n, double *x_end)
{
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    assert_non_null(x);
    assert_non_null(z);
    x[0] = -1.379;
    z[0] = 0.0;
    for (size_t k = 1; k < n; k++) {
        const double r = gsl_rng_uniform(rng);
        const int wall_ok = k < 2 || x[k - 1] != x[k - 2];
        x[k] = x[k - 1] + (r < 0.05 && wall_ok ? 0.0 : r < 0.3 ? 0.001 : 0.03 * r);
        const double s = gsl_rng_uniform(rng);
        z[k] = s < 0.2 ? z[k - 1] : z[k - 1] + (s < 0.25 ? 0.2 : 0.01) * (s - 0.6);
    }
    tirenv_profile *p = tirenv_profile_alloc(n, x, z);
    assert_non_null(p);
    *x_end = x[n - 1];
    free(x);
    free(z);
    return p;
}

static void test_rigid_equals_plain(void **state)
{
    (void)state;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 2385);
    static const double radii[] = {0.6837, 0.0213, 2.385};
    for (size_t trial = 0; trial < 6; trial++) {
        double x_end;
        tirenv_profile *p = random_polyline(rng, 3000 + 1000 * trial, &x_end);
        const size_t n = tirenv_profile_size(p);
        const double *xs = tirenv_profile_x(p), *zs = tirenv_profile_z(p);
        const double R0 = radii[trial % 3];
        size_t hint = n / 2;
        for (size_t i = 0; i < 4000; i++) {
            /* Uniform over the profile and beyond both ends, and exactly at vertices. */
            const double x = i % 4 == 0 ? xs[gsl_rng_uniform_int(rng, n)]
                                        : xs[0] - 3.0 + (x_end - xs[0] + 6.0) *
                                                            gsl_rng_uniform(rng);
            double px, pz, px_ref, pz_ref;
            const double z = tirenv_rigid_height(p, R0, x, &px, &pz);
            const double z_ref = plain_rigid(n, xs, zs, R0, x, &px_ref, &pz_ref);
            if (z != z_ref || px != px_ref || pz != pz_ref)
                fail_msg("trial %zu, R0 %g, x = %.17g: z %.17g px %.17g pz %.17g, plain scan "
                         "z %.17g px %.17g pz %.17g", trial, R0, x, z, px, pz, z_ref, px_ref,
                         pz_ref);
            /* The models' hinted search, from the last position's segment (random jumps: a
             * stale hint), must give the same bits. */
            double px_h, pz_h;
            if (tirenv_rigid__height_hint(p, R0, x, &hint, &px_h, &pz_h) != z || px_h != px ||
                pz_h != pz)
                fail_msg("trial %zu, x = %.17g: the hinted search differs", trial, x);
        }
        tirenv_profile_free(p);
    }
    gsl_rng_free(rng);
}

/* The cam's touching height over a vertex at t = |u|/a_e, and over a sloped segment's
 * tangency point, by the same operations as cam.c, without any pruning. */
static double plain_edge(double b_e, double c_e, double t)
{
    if (t <= 0.0)
        return 0.0;
    const double tc = pow(t, c_e);
    return b_e * (pow(1.0 - tc, 1.0 / c_e) - 1.0);
}

static int plain_tangency(double a_e, double b_e, double c_e, double x, double x_k, double z_k,
                          double x_k1, double s, double *Z, double *p_x)
{
    const double inv_c = 1.0 / c_e, inv_c1 = 1.0 / (c_e - 1.0), p = c_e / (c_e - 1.0);
    const double m = fabs(s) * (a_e / b_e);
    const double lm = log(m);
    double t, rise_m1;
    if (m < 1.0) {
        const double k = exp(lm * inv_c1), j = k * m;
        const double L = log1p(j), P = exp(-inv_c * L);
        t = k * P;
        rise_m1 = j * P + expm1(-inv_c * L);
    } else {
        const double j = exp(-lm * p), L = log1p(j), P = exp(-inv_c * L);
        t = P;
        rise_m1 = m * (1.0 + j) * P - 1.0;
    }
    const double xi = s > 0 ? x + a_e * t : x - a_e * t;
    if (!(xi > x_k && xi < x_k1))
        return 0;
    *Z = z_k + s * (x - x_k) + b_e * rise_m1;
    *p_x = xi;
    return 1;
}

/* The cam's lift as a plain scan in cam.c's order: the ground under x, the vertices within
 * reach nearest first on each side, then every sloped segment between them. */
static double plain_cam(size_t n, const double xs[], const double zs[],
                        const tirenv_cam_shape *cam, double x, double *px, double *pz)
{
    const double a_e = cam->a_e, b_e = cam->b_e, c_e = cam->c_e, inv_a = 1.0 / a_e;
    size_t k_x = 0;
    while (k_x + 1 < n && xs[k_x + 1] <= x)
        k_x++;
    double q_x;
    if (x < xs[0])
        q_x = zs[0];
    else if (x == xs[k_x] && k_x >= 1 && xs[k_x - 1] == x)
        q_x = fmax(zs[k_x - 1], zs[k_x]);
    else if (k_x == n - 1)
        q_x = zs[n - 1];
    else
        q_x = zs[k_x] + (zs[k_x + 1] - zs[k_x]) * ((x - xs[k_x]) / (xs[k_x + 1] - xs[k_x]));
    double z_c = q_x, p_x = x, p_z = q_x;
#define CONSIDER(Z, X, P)                                                                    \
    do {                                                                                     \
        if ((Z) > z_c) {                                                                     \
            z_c = (Z);                                                                       \
            p_x = (X);                                                                       \
            p_z = (P);                                                                       \
        }                                                                                    \
    } while (0)
    size_t k_left = 0, k_right = n - 1;
    for (size_t k = k_x + 1; k-- > 0;) {
        const double t = fabs((x - xs[k]) * inv_a);
        if ((x - xs[k]) * inv_a > 1.0) {
            k_left = k;
            break;
        }
        CONSIDER(zs[k] + plain_edge(b_e, c_e, t), xs[k], zs[k]);
    }
    for (size_t k = k_x + 1; k < n; k++) {
        const double t = (xs[k] - x) * inv_a;
        if (t > 1.0) {
            k_right = k;
            break;
        }
        CONSIDER(zs[k] + plain_edge(b_e, c_e, fabs(t)), xs[k], zs[k]);
    }
    for (size_t k = k_left; k < k_right; k++) {
        const double x_a = xs[k], x_b = xs[k + 1], z_a = zs[k], z_b = zs[k + 1];
        if (!(x_b > x_a) || z_b == z_a)
            continue;
        const double s = (z_b - z_a) / (x_b - x_a);
        if (s > 0 ? !(x_b > x) : !(x_a < x))
            continue;
        double Z, xi;
        if (plain_tangency(a_e, b_e, c_e, x, x_a, z_a, x_b, s, &Z, &xi))
            CONSIDER(Z, xi, z_a + s * (xi - x_a));
    }
#undef CONSIDER
    *px = p_x;
    *pz = p_z;
    return z_c;
}

static void test_cam_equals_plain(void **state)
{
    (void)state;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 4357);
    static const tirenv_cam_shape shapes[] = {
        {.a_e = 1.0245, .b_e = 0.6686, .c_e = 1.5257}, /* the default tire's */
        {.a_e = 0.0213, .b_e = 0.0417, .c_e = 1.13},
        {.a_e = 0.385, .b_e = 0.2385, .c_e = 3.7},
    };
    for (size_t trial = 0; trial < 6; trial++) {
        double x_end;
        tirenv_profile *p = random_polyline(rng, 2000 + 500 * trial, &x_end);
        const size_t n = tirenv_profile_size(p);
        const double *xs = tirenv_profile_x(p), *zs = tirenv_profile_z(p);
        const tirenv_cam_shape *cam = &shapes[trial % 3];
        for (size_t i = 0; i < 2000; i++) {
            const double x = i % 4 == 0 ? xs[gsl_rng_uniform_int(rng, n)]
                                        : xs[0] - 3.0 + (x_end - xs[0] + 6.0) *
                                                            gsl_rng_uniform(rng);
            double px, pz, px_ref, pz_ref;
            const double z = tirenv_cam_lift(p, cam, x, &px, &pz);
            const double z_ref = plain_cam(n, xs, zs, cam, x, &px_ref, &pz_ref);
            if (z != z_ref || px != px_ref || pz != pz_ref)
                fail_msg("trial %zu, x = %.17g: z %.17g px %.17g pz %.17g, plain scan "
                         "z %.17g px %.17g pz %.17g", trial, x, z, px, pz, z_ref, px_ref,
                         pz_ref);
        }
        tirenv_profile_free(p);
    }
    gsl_rng_free(rng);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rigid_equals_plain),
        cmocka_unit_test(test_cam_equals_plain),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
