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
#include "tirenv/rigid.h"

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
        }
        tirenv_profile_free(p);
    }
    gsl_rng_free(rng);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rigid_equals_plain),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
