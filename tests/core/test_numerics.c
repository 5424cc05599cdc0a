/* SPDX-License-Identifier: Apache-2.0 */
/* The library's own numerical pieces that replaced GSL, each against closed forms
 * or published values: the random generator (xoshiro256** test vector, splitmix64 seeding,
 * the moments of its distributions), Brent's root finder (a table of roots, and the cases that
 * must fail), the FFT (against the direct sum), Cholesky (a factor known exactly), the
 * eigenvalues (oscillators, a companion matrix), the ride's integrators (RK4's Taylor
 * polynomial, the RK8(7) tableau's order conditions, an oscillator) and the median. */
#include "testutil.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/brent.h"
#include "core/cholesky.h"
#include "core/eigen.h"
#include "core/fft.h"
#include "core/golden.h"
#include "rig/rig_impl.h"
#include "ride/ode.h"
#include "tirenv/rng.h"

/* xoshiro256** from the state {1, 2, 3, 4}: the reference C code's first six outputs (the
 * test vector that Rust's rand_xoshiro, among others, checks against). splitmix64 from 0:
 * its first four outputs, as its authors' code gives them; tirenv_rng_seed fills the state
 * with exactly those. */
static void test_rng_vectors(void **state)
{
    (void)state;
    static const uint64_t s0[4] = {1, 2, 3, 4};
    static const uint64_t expected[6] = {11520u, 0u, 1509978240u,
                                         UINT64_C(1215971899390074240),
                                         UINT64_C(1216172134540287360),
                                         UINT64_C(607988272756665600)};
    tirenv_rng *a = tirenv_rng_alloc(0), *b = tirenv_rng_alloc(99);
    assert_non_null(a);
    assert_non_null(b);
    tirenv_rng_set_state(a, s0);
    for (int i = 0; i < 6; ++i)
        assert_true(tirenv_rng_u64(a) == expected[i]);
    static const uint64_t split0[4] = {UINT64_C(0xe220a8397b1dcdaf), UINT64_C(0x6e789e6aa1b965f4),
                                       UINT64_C(0x06c45d188009454f), UINT64_C(0xf88bb8a8724c81ec)};
    tirenv_rng_set_state(a, split0);
    tirenv_rng_seed(b, 0);
    for (int i = 0; i < 100; ++i)
        assert_true(tirenv_rng_u64(a) == tirenv_rng_u64(b));
    /* Different seeds, different streams; the same seed, the same one. */
    tirenv_rng_seed(a, 1);
    tirenv_rng_seed(b, 2);
    assert_true(tirenv_rng_u64(a) != tirenv_rng_u64(b));
    tirenv_rng_seed(a, 7);
    tirenv_rng_seed(b, 7);
    for (int i = 0; i < 10; ++i)
        assert_true(tirenv_rng_uniform(a) == tirenv_rng_uniform(b));
    tirenv_rng_free(a);
    tirenv_rng_free(b);
    tirenv_rng_free(NULL);
}

/* Moments over N = 200000 draws, each within 5 standard errors of its expectation (a false
 * failure about once in 1.7 million runs per check): uniform mean 1/2 (SE 0.289/sqrt(N)),
 * Gaussian mean 0 (SE sigma/sqrt(N)) and variance sigma^2 (SE sigma^2 sqrt(2/N)); the
 * integers of [0, 7) each 1/7 of the time (SE sqrt(p(1-p)/N)). Ranges are checked on every
 * draw; a shuffle is a permutation. */
static void test_rng_moments(void **state)
{
    (void)state;
    enum { N = 200000 };
    tirenv_rng *rng = tirenv_rng_alloc(2385);
    double sum_u = 0, sum_g = 0, sum_g2 = 0;
    size_t count[7] = {0};
    const double sigma = 2.385;
    for (size_t i = 0; i < N; ++i) {
        const double u = tirenv_rng_uniform(rng);
        assert_true(u >= 0 && u < 1);
        sum_u += u;
        const double g = tirenv_rng_gaussian(rng, sigma);
        assert_true(isfinite(g));
        sum_g += g;
        sum_g2 += g * g;
        const size_t k = tirenv_rng_uniform_int(rng, 7);
        assert_true(k < 7);
        ++count[k];
    }
    const double n = N;
    assert_near(sum_u / n, 0.5, 5 * sqrt(1.0 / 12 / n), 0);
    assert_near(sum_g / n, 0, 5 * sigma / sqrt(n), 0);
    assert_near(sum_g2 / n, sigma * sigma, 5 * sigma * sigma * sqrt(2 / n), 0);
    for (int k = 0; k < 7; ++k)
        assert_near((double)count[k] / n, 1.0 / 7, 5 * sqrt(1.0 / 7 * 6 / 7 / n), 0);
    assert_true(tirenv_rng_uniform_int(rng, 1) == 0);
    size_t a[50], seen[50] = {0};
    for (size_t i = 0; i < 50; ++i)
        a[i] = i;
    tirenv_rng_shuffle(rng, a, 50);
    size_t moved = 0;
    for (size_t i = 0; i < 50; ++i) {
        assert_true(a[i] < 50);
        ++seen[a[i]];
        moved += a[i] != i;
    }
    for (size_t i = 0; i < 50; ++i)
        assert_int_equal(seen[i], 1);
    assert_true(moved > 0);
    tirenv_rng_free(rng);
}

/* ---- Brent ---------------------------------------------------------------------------- */

static size_t calls;
static double f_pow20(double x, void *p) { (void)p; ++calls; return pow(x, 20) - 1; }
static double f_sin(double x, void *p) { (void)p; ++calls; return sin(x); }
static double f_cos(double x, void *p) { (void)p; ++calls; return cos(x) - x; }
static double f_wallis(double x, void *p) { (void)p; ++calls; return x * x * x - 2 * x - 5; }
static double f_exp(double x, void *p) { (void)p; ++calls; return exp(x) - 2; }
static double f_none(double x, void *p) { (void)p; return x * x + 1; }
static double f_nan(double x, void *p) { (void)p; return x > 0.5 ? NAN : x - 2; }

/* As GSL's roots/test.c: a table of functions with known roots, each to |hi - lo| < 1e-12
 * within 100 iterations, the root within 1e-12 of the closed form (Wallis's cubic: its real
 * root by Cardano, 2.0945514815423265...), the bracket always holding it. */
static void test_brent_table(void **state)
{
    (void)state;
    static const struct {
        tirenv_core__brent_fn f;
        double lo, hi, root;
    } cases[] = {
        {f_pow20, 0.1, 2.385, 1.0},
        {f_sin, 3.0, 4.0, M_PI},
        {f_sin, -4.0, -3.0, -M_PI},
        {f_cos, 0.0, 1.0, 0.73908513321516064166},
        {f_wallis, 2.0, 3.0, 2.09455148154232659148},
        {f_exp, 0.0, 1.0, M_LN2},
        {f_sin, 0.0, 1.0, 0.0},  /* the root at an end */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        tirenv_core__brent br;
        calls = 0;
        assert_int_equal(tirenv_core__brent_set(&br, cases[k].f, NULL, cases[k].lo,
                                                cases[k].hi), 0);
        int it = 0;
        for (; it < 100 && !tirenv_core__brent_converged(&br, 1e-12); ++it) {
            assert_int_equal(tirenv_core__brent_iterate(&br), 0);
            assert_true(br.lo <= br.root && br.root <= br.hi);
            assert_true(br.lo <= cases[k].root + 1e-15 && cases[k].root - 1e-15 <= br.hi);
        }
        print_message("brent case %zu: %.17g after %d iterations, %zu evaluations\n", k,
                      br.root, it, calls);
        assert_true(it < 100);
        assert_near(br.root, cases[k].root, 1e-12, 0);
        /* Started from the ends' values the caller has (as the deformable models' contact
         * length search does): two evaluations fewer, the same iterates to the bit. */
        const size_t calls_set = calls;
        const double f_lo = cases[k].f(cases[k].lo, NULL), f_hi = cases[k].f(cases[k].hi, NULL);
        tirenv_core__brent bv;
        calls = 0;
        assert_int_equal(tirenv_core__brent_set_values(&bv, cases[k].f, NULL, cases[k].lo, f_lo,
                                                       cases[k].hi, f_hi), 0);
        assert_int_equal(calls, 0);
        for (int j = 0; j < it; ++j)
            assert_int_equal(tirenv_core__brent_iterate(&bv), 0);
        assert_int_equal(calls + 2, calls_set);
        assert_true(bv.root == br.root && bv.lo == br.lo && bv.hi == br.hi);
    }
}

/* The cases that must fail with the right code: no sign change, a value that is not finite
 * at an end or during the iteration; and the messages name them. */
static void test_brent_errors(void **state)
{
    (void)state;
    tirenv_core__brent br;
    assert_int_equal(tirenv_core__brent_set(&br, f_none, NULL, -1, 1),
                     TIRENV_CORE__BRENT_NO_BRACKET);
    assert_int_equal(tirenv_core__brent_set(&br, f_nan, NULL, 0, 1),
                     TIRENV_CORE__BRENT_NOT_FINITE);
    assert_int_equal(tirenv_core__brent_set_values(&br, f_none, NULL, -1, 2, 1, 2),
                     TIRENV_CORE__BRENT_NO_BRACKET);
    assert_int_equal(tirenv_core__brent_set_values(&br, f_nan, NULL, 0, -2, 1, NAN),
                     TIRENV_CORE__BRENT_NOT_FINITE);
    assert_non_null(strstr(tirenv_core__brent_strerror(TIRENV_CORE__BRENT_NO_BRACKET),
                           "bracket"));
    assert_non_null(strstr(tirenv_core__brent_strerror(TIRENV_CORE__BRENT_NOT_FINITE),
                           "finite"));
    assert_string_equal(tirenv_core__brent_strerror(0), "success");
}

static double f_nan_mid(double x, void *p)
{
    (void)p;
    return fabs(x - 0.5) < 0.2 ? NAN : x - 0.5;
}

static void test_brent_not_finite_inside(void **state)
{
    (void)state;
    tirenv_core__brent br;
    assert_int_equal(tirenv_core__brent_set(&br, f_nan_mid, NULL, 0.0, 1.0), 0);
    int status = 0;
    for (int it = 0; it < 100 && !status && !tirenv_core__brent_converged(&br, 1e-12); ++it)
        status = tirenv_core__brent_iterate(&br);
    assert_int_equal(status, TIRENV_CORE__BRENT_NOT_FINITE);
}

/* Golden sections: known minima within 1e-6 after 60 steps, the bracket holding the minimum
 * while it is wider than 1e-6 (narrower, f differs by less than its round-off: a search for a
 * minimum resolves only sqrt(eps) of x), each step one evaluation; and the
 * tie rule, on a function constant over the bracket: lower keeps [a, d] at every step and
 * ends at a, upper ends at b. */
static double g_quad(double x, void *p)
{
    (void)p;
    ++calls;
    return (x - 0.7391) * (x - 0.7391);
}
static double g_cosh(double x, void *p)
{
    (void)p;
    ++calls;
    return cosh(x + 2.385);
}
static double g_cos(double x, void *p)
{
    (void)p;
    ++calls;
    return cos(x);
}
static double g_flat(double x, void *p)
{
    (void)p;
    (void)x;
    return 1.0;
}

static void test_golden(void **state)
{
    (void)state;
    static const struct {
        tirenv_core__golden_fn f;
        double a, b, x_min;
    } cases[] = {
        {g_quad, -1.0, 2.0, 0.7391},
        {g_cosh, -4.0, 1.0, -2.385},
        {g_cos, 0.5, 5.0, M_PI},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        tirenv_core__golden g;
        calls = 0;
        tirenv_core__golden_set(&g, cases[k].f, NULL, cases[k].a, cases[k].b,
                                TIRENV_CORE__GOLDEN_TIES_LOWER);
        assert_int_equal(calls, 2);
        for (int i = 0; i < 60; ++i) {
            tirenv_core__golden_iterate(&g);
            assert_true(g.a < g.c && g.c < g.d && g.d < g.b);
            assert_true(g.b - g.a < 1e-6 || (g.a <= cases[k].x_min && cases[k].x_min <= g.b));
        }
        assert_int_equal(calls, 62);
        double f_min;
        const double x = tirenv_core__golden_min(cases[k].f, NULL, cases[k].a, cases[k].b, 60,
                                                 &f_min);
        assert_true(x == 0.5 * (g.a + g.b));  /* the driver takes the same steps */
        assert_true(f_min == cases[k].f(x, NULL));
        assert_near(x, cases[k].x_min, 1e-6, 0);
    }
    tirenv_core__golden lo, hi;
    tirenv_core__golden_set(&lo, g_flat, NULL, 0.0, 1.0, TIRENV_CORE__GOLDEN_TIES_LOWER);
    tirenv_core__golden_set(&hi, g_flat, NULL, 0.0, 1.0, TIRENV_CORE__GOLDEN_TIES_UPPER);
    for (int i = 0; i < 40; ++i) {
        tirenv_core__golden_iterate(&lo);
        tirenv_core__golden_iterate(&hi);
    }
    assert_true(lo.a == 0.0 && lo.b < 1e-8);
    assert_true(hi.b == 1.0 && hi.a > 1 - 1e-8);
}

/* ---- FFT ------------------------------------------------------------------------------ */

/* Against the direct sum (in long double) for lengths 1 to 1024, both signs, on random
 * complex input: the largest error within 1e-14 of the largest output times log2 n + 1
 * (round-off grows as log n in a radix-2 FFT; measured below 3e-16 per level). The
 * backward of the forward is n times the input. */
static void test_fft(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(11);
    for (size_t n = 1; n <= 1024; n *= 4) {
        double complex *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
        for (size_t j = 0; j < n; ++j)
            x[j] = tirenv_rng_uniform(rng) - 0.5 + I * (tirenv_rng_uniform(rng) - 0.5);
        for (int sign = -1; sign <= 1; sign += 2) {
            memcpy(z, x, n * sizeof *z);
            tirenv_core__fft(z, n, sign);
            double err = 0, scale = 0;
            for (size_t k = 0; k < n; ++k) {
                long double re = 0, im = 0;
                for (size_t j = 0; j < n; ++j) {
                    const long double th = (long double)sign * 2 * M_PI * (long double)((j * k) % n) / (long double)n;
                    re += creal(x[j]) * cosl(th) - cimag(x[j]) * sinl(th);
                    im += creal(x[j]) * sinl(th) + cimag(x[j]) * cosl(th);
                }
                err = fmax(err, cabs(z[k] - (double)re - I * (double)im));
                scale = fmax(scale, hypot((double)re, (double)im));
            }
            const double levels = log2((double)n) + 1;
            assert_true(err <= 1e-14 * scale * levels);
        }
        memcpy(z, x, n * sizeof *z);
        tirenv_core__fft(z, n, -1);
        tirenv_core__fft(z, n, +1);
        for (size_t j = 0; j < n; ++j)
            assert_true(cabs(z[j] / (double)n - x[j]) <= 1e-14 * (log2((double)n) + 1));
        free(x);
        free(z);
    }
    tirenv_rng_free(rng);
}

/* ---- Cholesky ------------------------------------------------------------------------- */

/* A = L L^T with L = [[2, 0, 0], [6, 1, 0], [-8, 5, 3]]: every step is exact in binary, so
 * the factor is L to the bit, and A x = b for x = (1.5, -2.25, 0.75) to round-off. A matrix
 * with a zero pivot in column 2 is refused naming it. */
static void test_cholesky(void **state)
{
    (void)state;
    double A[9] = {4, 12, -16, 12, 37, -43, -16, -43, 98};
    const double L[9] = {2, 0, 0, 6, 1, 0, -8, 5, 3};
    const double x_true[3] = {1.5, -2.25, 0.75};
    double b[3] = {0}, x[3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            b[i] += A[i * 3 + j] * x_true[j];
    assert_int_equal(tirenv_core__cholesky(A, 3, 3), 0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j <= i; ++j)
            assert_bits_equal(A[i * 3 + j], L[i * 3 + j]);
    tirenv_core__cholesky_solve(A, 3, 3, b, x);
    for (int i = 0; i < 3; ++i)
        assert_near(x[i], x_true[i], 0, 1e-14);
    double S[4] = {1, 1, 1, 1};  /* singular: pivot 2 is 0 */
    assert_int_equal(tirenv_core__cholesky(S, 2, 2), 2);
    double N[4] = {-1, 0, 0, 1};
    assert_int_equal(tirenv_core__cholesky(N, 2, 2), 1);
}

/* ---- eigenvalues ---------------------------------------------------------------------- */

/* Each expected eigenvalue matched by a distinct computed one within tol. */
static void assert_spectrum(size_t n, const double complex got[],
                            const double complex want[], double tol)
{
    int used[TIRENV_CORE__EIGEN_MAX] = {0};
    for (size_t i = 0; i < n; ++i) {
        size_t best = n;
        double d_best = INFINITY;
        for (size_t j = 0; j < n; ++j)
            if (!used[j] && cabs(got[j] - want[i]) < d_best) {
                d_best = cabs(got[j] - want[i]);
                best = j;
            }
        print_message("  want %.15g%+.15gi, got %.15g%+.15gi\n", creal(want[i]),
                      cimag(want[i]), creal(got[best]), cimag(got[best]));
        assert_true(d_best <= tol);
        used[best] = 1;
    }
}

/* Oscillators m x'' + c x' + k x = 0 as state matrices: lambda = -zeta w +- i w sqrt(1 - zeta^2)
 * with w = sqrt(k/m), zeta = c/(2 sqrt(k m)). One alone; a stiff (1.5e6 N/m over 80 kg, as
 * a tire under an axle) and a soft one (2e4 N/m over 4000 kg) coupled into a 4 x 4 block
 * matrix, permuted so that the blocks are not visible; the companion matrix of
 * (x - 1)(x - 2)(x - 3)(x - 4.5); a rotation (+-i). Relative tolerance 1e-12 of the largest
 * |lambda|: the balanced QR iteration is backward stable, and these roots are well
 * conditioned (measured within 1e-14). */
static void test_eigenvalues(void **state)
{
    (void)state;
    double complex got[8], want[8];
    {
        const double m = 2.385, c = 0.7, k = 31.0;
        const double A[4] = {0, 1, -k / m, -c / m};
        assert_int_equal(tirenv_core__eigenvalues(2, A, got), 0);
        const double w = sqrt(k / m), zeta = c / (2 * sqrt(k * m));
        want[0] = -zeta * w + I * w * sqrt(1 - zeta * zeta);
        want[1] = conj(want[0]);
        assert_spectrum(2, got, want, 1e-12 * w);
    }
    {
        const double m1 = 80, k1 = 1.5e6, c1 = 3000, m2 = 4000, k2 = 2e4, c2 = 900;
        /* state (x1, x2, v1, v2), uncoupled: the spectrum is the two oscillators'. */
        const double A[16] = {0, 0, 1, 0, 0, 0, 0, 1, -k1 / m1, 0, -c1 / m1, 0,
                              0, -k2 / m2, 0, -c2 / m2};
        assert_int_equal(tirenv_core__eigenvalues(4, A, got), 0);
        const double w1 = sqrt(k1 / m1), z1 = c1 / (2 * sqrt(k1 * m1));
        const double w2 = sqrt(k2 / m2), z2 = c2 / (2 * sqrt(k2 * m2));
        want[0] = -z1 * w1 + I * w1 * sqrt(1 - z1 * z1);
        want[1] = conj(want[0]);
        want[2] = -z2 * w2 + I * w2 * sqrt(1 - z2 * z2);
        want[3] = conj(want[2]);
        assert_spectrum(4, got, want, 1e-12 * w1);
    }
    {
        /* x^4 - 10.5 x^3 + 38 x^2 - 55.5 x + 27 = (x - 1)(x - 2)(x - 3)(x - 4.5) */
        const double A[16] = {10.5, -38, 55.5, -27, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
        assert_int_equal(tirenv_core__eigenvalues(4, A, got), 0);
        const double complex r[4] = {1, 2, 3, 4.5};
        assert_spectrum(4, got, r, 1e-10);
    }
    {
        const double A[4] = {0, -1, 1, 0};
        assert_int_equal(tirenv_core__eigenvalues(2, A, got), 0);
        const double complex r[2] = {I, -I};
        assert_spectrum(2, got, r, 1e-14);
    }
    const double bad[1] = {NAN};
    assert_int_equal(tirenv_core__eigenvalues(1, bad, got), 1);
    assert_int_equal(tirenv_core__eigenvalues(9, bad, got), 1);
}

/* ---- integrators ---------------------------------------------------------------------- */

typedef struct {
    double w;              /* rad/s */
    size_t evals;
} osc;

static int f_decay(double t, const double y[], double dydt[], void *p)
{
    (void)t;
    (void)p;
    dydt[0] = -y[0];
    return 0;
}

static int f_osc(double t, const double y[], double dydt[], void *p)
{
    (void)t;
    osc *o = p;
    ++o->evals;
    dydt[0] = y[1];
    dydt[1] = -o->w * o->w * y[0];
    return 0;
}

static int f_fail(double t, const double y[], double dydt[], void *p)
{
    (void)y;
    (void)p;
    dydt[0] = 0;
    return t > 0.25 ? 7 : 0;
}

/* One RK4 step on y' = -y is the Taylor polynomial of e^-h to fourth order: exactly, to
 * round-off, for several h. */
static void test_rk4(void **state)
{
    (void)state;
    const tirenv_ride__ode ode = {f_decay, NULL, 1};
    static const double hs[] = {0.1, 0.2385, 1.0};
    for (size_t k = 0; k < 3; ++k) {
        const double h = hs[k];
        double y[1] = {1.0};
        assert_int_equal(tirenv_ride__rk4_step(&ode, 0.0, h, y), 0);
        assert_near(y[0], 1 - h + h * h / 2 - h * h * h / 6 + h * h * h * h / 24, 0, 1e-15);
    }
    double y[1] = {1.0};
    const tirenv_ride__ode bad = {f_fail, NULL, 1};
    assert_int_equal(tirenv_ride__rk4_step(&bad, 0.2, 0.1, y), 7);
}

/* The RK8(7)13M tableau: every row of A sums to its node (the rows' rational coefficients
 * meet it to 1e-17; rounded to doubles, terms up to 16 in size leave some ulps of 16: 1e-14),
 * and the weights meet the
 * quadrature conditions sum b_i c_i^k = 1/(k + 1) for k < 8 (eighth order), b_hat for
 * k < 7 (seventh), to 1e-14. A transcription error in any digit breaks one of them. */
static void test_rk8_tableau(void **state)
{
    (void)state;
    const double *c, *b, *b_hat;
    const double *a = tirenv_ride__rk8_tableau(&c, &b, &b_hat);
    for (int i = 0; i < 13; ++i) {
        double s = 0;
        for (int j = 0; j < 13; ++j)
            s += a[i * 13 + j];
        assert_near(s, c[i], 1e-14, 0);
    }
    for (int k = 0; k < 8; ++k) {
        double s8 = 0, s7 = 0;
        for (int i = 0; i < 13; ++i) {
            s8 += b[i] * pow(c[i], k);
            s7 += b_hat[i] * pow(c[i], k);
        }
        assert_near(s8, 1.0 / (k + 1), 1e-14, 0);
        if (k < 7)
            assert_near(s7, 1.0 / (k + 1), 1e-14, 0);
    }
    /* sum b_i c_i (A c)_i = 1/8: a condition on A as well. */
    double s = 0;
    for (int i = 0; i < 13; ++i) {
        double ac = 0;
        for (int j = 0; j < 13; ++j)
            ac += a[i * 13 + j] * c[j];
        s += b[i] * c[i] * ac;
    }
    assert_near(s, 1.0 / 8, 1e-14, 0);
}

/* The adaptive integrator on x'' = -w^2 x (w = 2.385 rad/s) from (1, 0), first step 0.01 s,
 * output every second for 20 s (about 7.6 periods): at tolerance 1e-10 per step the error
 * stays below 1e-8 (the local errors add over the steps), and at 1e-6 it is larger, with
 * fewer evaluations (the control works); the outputs land exactly on the requested times. A failing right-hand side stops
 * it with its own status. */
static void test_rk8_oscillator(void **state)
{
    (void)state;
    double err[2];
    size_t evals[2];
    static const double tols[2] = {1e-10, 1e-6};
    for (int k = 0; k < 2; ++k) {
        osc o = {2.385, 0};
        const tirenv_ride__ode ode = {f_osc, &o, 2};
        tirenv_ride__rk8 s;
        tirenv_ride__rk8_init(&s, 0.01, tols[k]);
        double y[2] = {1, 0}, t = 0;
        err[k] = 0;
        for (int n = 1; n <= 20; ++n) {
            const double t_n = n;
            assert_int_equal(tirenv_ride__rk8_advance(&s, &ode, &t, t_n, y), 0);
            assert_true(t == t_n);
            err[k] = fmax(err[k], fmax(fabs(y[0] - cos(o.w * t)),
                                       fabs(y[1] + o.w * sin(o.w * t)) / o.w));
        }
        evals[k] = o.evals;
        print_message("rk8 tol %g: largest error %.3g, %zu evaluations, %zu steps, %zu "
                      "rejected\n", tols[k], err[k], evals[k], s.steps, s.rejected);
    }
    assert_true(err[0] < 1e-8);
    assert_true(err[1] > err[0]);
    assert_true(evals[1] < evals[0]);
    double y[1] = {0}, t = 0;
    const tirenv_ride__ode bad = {f_fail, NULL, 1};
    tirenv_ride__rk8 s;
    tirenv_ride__rk8_init(&s, 0.1, 1e-10);
    assert_int_equal(tirenv_ride__rk8_advance(&s, &bad, &t, 1.0, y), 7);
}

/* ---- median --------------------------------------------------------------------------- */

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Against sorting and reading the middle (the mean of the two middle values for even n),
 * for every n from 1 to 60, on values with many ties and on distinct ones; the input is left
 * as it was. */
static void test_median(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(5);
    double v[60], copy[60], sorted[60], scratch[60];
    for (int ties = 0; ties < 2; ++ties)
        for (size_t n = 1; n <= 60; ++n) {
            for (size_t i = 0; i < n; ++i)
                v[i] = ties ? (double)tirenv_rng_uniform_int(rng, 4)
                            : tirenv_rng_gaussian(rng, 1.0);
            memcpy(copy, v, n * sizeof *v);
            memcpy(sorted, v, n * sizeof *v);
            qsort(sorted, n, sizeof *sorted, cmp_double);
            const double want = n % 2 ? sorted[n / 2]
                                      : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
            assert_bits_equal(tirenv_rig__median(v, n, scratch), want);
            assert_memory_equal(v, copy, n * sizeof *v);
        }
    tirenv_rng_free(rng);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rng_vectors),
        cmocka_unit_test(test_rng_moments),
        cmocka_unit_test(test_brent_table),
        cmocka_unit_test(test_brent_errors),
        cmocka_unit_test(test_brent_not_finite_inside),
        cmocka_unit_test(test_golden),
        cmocka_unit_test(test_fft),
        cmocka_unit_test(test_cholesky),
        cmocka_unit_test(test_eigenvalues),
        cmocka_unit_test(test_rk4),
        cmocka_unit_test(test_rk8_tableau),
        cmocka_unit_test(test_rk8_oscillator),
        cmocka_unit_test(test_median),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
