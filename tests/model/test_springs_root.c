/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model's root at a new x (src/model/springs_root.c): the slope Newton's steps
 * take, d/dz of the working rows' share of F_z on root_at's path (no base reactions), against
 * central differences of the share itself. Its static functions are reached by compiling the
 * file into this test (it defines every symbol of springs_root.c, so the library's copy is
 * not linked). Seeded rows between elements on a fan of eight rays, one to three of them,
 * some slots held. */
#include "../../src/model/springs_root.c"

#include "testutil.h"

static uint64_t rng_state = 16180;

static double uniform(void)
{
    return tirenv_test_uniform(&rng_state);
}

enum { n_el = 8 };

/* d(dF)/dz from at_height_slope against (dF(z + e) - dF(z - e)) / (2 e), e = 1e-7 m: the rows
 * bend by about e^2 / |V - C| between, so the difference is within 1e-6 of the slope; the
 * slopes must not all be zero. */
static void test_slope_is_the_derivative(void **state)
{
    (void)state;
    double theta[n_el], st[n_el], ct[n_el];
    for (size_t i = 0; i < n_el; ++i) {
        theta[i] = (i - 3.5) * 0.0437;
        st[i] = sin(theta[i]);
        ct[i] = cos(theta[i]);
    }
    tirenv_springs__cc_tire T = {0};
    T.N = n_el;
    T.R0 = 0.3137;
    T.k_r = 1.738e5;
    T.k_ir = 3.215e6;
    T.sin_t = st;
    T.cos_t = ct;
    tirenv_springs__cc_tire_shape(&T);
    size_t checked = 0;
    double worst = 0, largest = 0;
    for (int trial = 0; trial < 200; ++trial) {
        root_rows W = {0};
        tirenv_springs__cc_cols col = {0};
        const size_t k = 1 + (size_t)(3 * uniform());
        W.k = k;
        W.no_l = 1;
        W.col = &col;
        const double x = 0.0123 * (uniform() - 0.5), z = T.R0 - 0.02 - 0.03 * uniform();
        for (size_t q = 0; q < k; ++q) {
            const size_t i = 2 * q + (size_t)(2 * uniform()); /* sectors apart */
            const double phi = theta[i] + (0.1 + 0.8 * uniform()) * (theta[i + 1] - theta[i]);
            const double r = T.R0 - 0.002 - 0.02 * uniform();
            W.el[2 * q] = i;
            W.el[2 * q + 1] = i + 1;
            W.X[q] = x + r * sin(phi);
            W.Z[q] = z - r * cos(phi);
        }
        /* Y symmetric positive definite (m/N): a diagonal of 2e-6 and small couplings */
        for (size_t s = 0; s < 2 * k; ++s) {
            W.fr[s] = uniform() < 0.85;
            W.w_T[s] = 0.01 + 0.02 * uniform();
            W.dw[s] = 0.3 + 0.5 * uniform();
            col.phi[s] = 0.2 + 0.7 * uniform();
            for (size_t r = 0; r <= s; ++r)
                col.Y[s][r] = col.Y[r][s] = r == s ? 2e-6 : 2e-7 * uniform();
        }
        double lam[K_MAX], B[S_MAX], g[S_MAX], dF, ddF, dF_p, dF_m;
        const double e = 1e-7;
        if (!at_height_slope(&T, &W, x, z, 0, lam, B, g, &dF, &ddF) ||
            !at_height(&T, &W, x, z + e, e, lam, B, g, &dF_p) ||
            !at_height(&T, &W, x, z - e, -e, lam, B, g, &dF_m))
            continue;
        double dF_0;
        assert_true(at_height(&T, &W, x, z, 0, lam, B, g, &dF_0));
        assert_true(dF_0 == dF); /* the slope's evaluation is at_height's, bit for bit */
        const double fd = (dF_p - dF_m) / (2 * e);
        assert_near(ddF, fd, 1e-3, 1e-6);
        worst = fmax(worst, fabs(ddF - fd) / fmax(fabs(fd), 1));
        largest = fmax(largest, fabs(ddF));
        ++checked;
    }
    print_message("%zu sets of rows: the slope within %.3g of central differences (largest "
                  "%.3g N/m)\n", checked, worst, largest);
    assert_true(checked > 100);
    assert_true(largest > 1); /* not all zero */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_slope_is_the_derivative),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
