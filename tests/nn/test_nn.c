/* The network (docs/models.md section 6): layout, initialisation, scaling, evaluation against a
 * plain reference, batch against single samples, back-propagation against finite
 * differences, and the enveloping model built on it.
 * SPDX-License-Identifier: Apache-2.0
 *
 * Tolerances.
 * - Reference evaluation: the network's own exp is within 3 ulp of libm's, so a logistic
 *   differs by about 1e-16 relative; summed through layers of at most 64 weights of size ~1
 *   it stays below 1e-14 of the output scale out_std, or of the output itself where a
 *   saturated linear net makes it large. REF_TOL = 1e-13, on both, leaves a factor 10.
 * - Finite differences: central, step h = 1e-6*max(1, |w|). Outputs are ~0.1 (m-like
 *   scaling), so round-off in y is ~1e-17 and costs 1e-17/h = 1e-11 in the difference
 *   quotient; the truncation term h^2/6*y''' is ~1e-13. FD_ABS = 1e-9 and FD_REL = 1e-6 leave
 *   a factor 100 over both.
 * - Batch against single sample, Jacobian against gradient, seeds, envelope mirror: exact
 *   (the same operations in the same order). */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tirenv/rng.h"

#include "tirenv/curve.h"
#include "tirenv/nn.h"

#define REF_TOL 1e-13
#define FD_ABS 1e-9
#define FD_REL 1e-6

/* Topologies every test loops over: the paper's, deeper, wider than a lane group, the
 * widest, and the degenerate linear net. */
static const tirenv_nn_topology topologies[] = {
    {3, {4, 8, 1}},
    {4, {4, 5, 3, 1}},
    {3, {3, 13, 1}},
    {4, {2, 64, 9, 1}},
    {6, {4, 7, 6, 5, 4, 1}},
    {2, {4, 1}},
};
enum { N_TOPOLOGIES = sizeof topologies / sizeof topologies[0] };

/* A network with initial weights perturbed (so that no weight is special), and scaling with
 * nonzero means and unequal deviations. */
static tirenv_nn *make_net(const tirenv_nn_topology *t, unsigned long seed)
{
    tirenv_nn *nn = tirenv_nn_alloc(t);
    assert_non_null(nn);
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, seed);
    tirenv_nn_init_weights(nn, rng);
    double *w = tirenv_nn_weights(nn);
    for (size_t k = 0; k < tirenv_nn_n_weights(nn); ++k)
        w[k] += 0.3 * (tirenv_rng_uniform(rng) - 0.5);
    double mean[TIRENV_NN_MAX_WIDTH], std[TIRENV_NN_MAX_WIDTH];
    for (size_t i = 0; i < t->size[0]; ++i) {
        mean[i] = 0.137 * (double)i - 0.0412;
        std[i] = 0.731 + 0.219 * (double)i;
    }
    assert_int_equal(tirenv_nn_set_scaling(nn, mean, std, 0.0123, 0.0271, NULL), TIRENV_OK);
    tirenv_rng_free(rng);
    return nn;
}

static void fill_inputs(tirenv_rng *rng, size_t n, size_t n_in, double x[])
{
    for (size_t k = 0; k < n * n_in; ++k)
        x[k] = 2.385 * (tirenv_rng_uniform(rng) - 0.5) + 0.1 * (double)(k % n_in);
}

/* The plain definition: the features (sqrt((1 - x_N)^2 + a^2) - a for the even input), scaled,
 * libm's exp,
 * sums in any order, the mean over the members, times H for the h/H target. */
static double reference_run(const tirenv_nn *nn, const double x[])
{
    const tirenv_nn_topology *t = tirenv_nn_topology_of(nn);
    const double *w = tirenv_nn_weights_const(nn);
    const size_t K = tirenv_nn_n_members(nn), per = tirenv_nn_n_weights(nn) / K;
    double mean[TIRENV_NN_MAX_WIDTH], std[TIRENV_NN_MAX_WIDTH], out_mean, out_std;
    double a[TIRENV_NN_MAX_WIDTH], b[TIRENV_NN_MAX_WIDTH];
    tirenv_nn_input_form in;
    tirenv_nn_target_form target;
    tirenv_nn_scaling(nn, mean, std, &out_mean, &out_std);
    tirenv_nn_form(nn, &in, &target);
    double sum = 0;
    for (size_t k = 0; k < K; ++k) {
        for (size_t i = 0; i < t->size[0]; ++i) {
            const double width = tirenv_nn_even_width(nn);
            const double f = in == TIRENV_NN_INPUT_EVEN && i == 0
                                 ? hypot(1 - x[0], width) - width
                                 : x[i];
            a[i] = (f - mean[i]) / std[i];
        }
        for (size_t l = 1; l < t->n_layers; ++l) {
            for (size_t j = 0; j < t->size[l]; ++j) {
                double net = w[k * per + tirenv_nn_weight_index(nn, l, 0, j)];
                for (size_t i = 0; i < t->size[l - 1]; ++i)
                    net += w[k * per + tirenv_nn_weight_index(nn, l, 1 + i, j)] * a[i];
                b[j] = l + 1 < t->n_layers ? 1 / (1 + exp(-net)) : net;
            }
            memcpy(a, b, t->size[l] * sizeof a[0]);
        }
        sum += a[0];
    }
    const double y = out_mean + out_std * sum / (double)K;
    return target == TIRENV_NN_TARGET_H_OVER_H ? y * x[TIRENV_NN_HEIGHT] : y;
}

/* The variants of the enveloping model's network: members, input form, target form. */
typedef struct {
    size_t members;
    tirenv_nn_input_form input;
    tirenv_nn_target_form target;
} variant;

static const variant variants[] = {
    {1, TIRENV_NN_INPUT_EVEN, TIRENV_NN_TARGET_H},
    {3, TIRENV_NN_INPUT_PAPER, TIRENV_NN_TARGET_H_OVER_H},
    {5, TIRENV_NN_INPUT_EVEN, TIRENV_NN_TARGET_H_OVER_H},
};
enum { N_VARIANTS = sizeof variants / sizeof variants[0] };

/* A network of topology t with the variant's members (each from its own seed, through
 * make_net, so they share scaling) and forms. */
static tirenv_nn *make_variant(const tirenv_nn_topology *t, const variant *v,
                               unsigned long seed)
{
    tirenv_nn *nets[8];
    assert_true(v->members <= 8);
    for (size_t k = 0; k < v->members; ++k) {
        nets[k] = make_net(t, seed + 1000 * k);
        assert_int_equal(tirenv_nn_set_form(nets[k], v->input, v->target, NULL), TIRENV_OK);
    }
    tirenv_nn *e = tirenv_nn_ensemble((const tirenv_nn *const *)nets, v->members);
    assert_non_null(e);
    for (size_t k = 0; k < v->members; ++k)
        tirenv_nn_free(nets[k]);
    return e;
}

static void test_topology(void **state)
{
    (void)state;
    tirenv_nn_topology t = tirenv_nn_topology_default();
    assert_int_equal(t.n_layers, 3);
    assert_int_equal(t.size[0], TIRENV_NN_INPUTS);
    assert_int_equal(t.size[1], 8);
    assert_int_equal(t.size[2], 1);
    assert_int_equal(tirenv_nn_topology_check(&t, NULL), TIRENV_OK);
    tirenv_nn *nn = tirenv_nn_alloc(&t);
    assert_non_null(nn);
    assert_int_equal(tirenv_nn_n_weights(nn), 5 * 8 + 9 * 1);
    assert_int_equal(tirenv_nn_n_inputs(nn), 4);
    tirenv_nn_free(nn);
    tirenv_nn_free(NULL);

    /* _e cases: each refused, naming the topology. */
    static const tirenv_nn_topology bad[] = {
        {1, {4}},
        {TIRENV_NN_MAX_LAYERS + 1, {4, 8, 8, 8, 8, 8}},
        {3, {4, 0, 1}},
        {3, {4, TIRENV_NN_MAX_WIDTH + 1, 1}},
        {3, {4, 8, 2}},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        assert_int_equal(tirenv_nn_topology_check(&bad[k], &diag), TIRENV_EINVAL);
        assert_string_equal(diag.field, "topology");
        assert_null(tirenv_nn_alloc(&bad[k]));
    }
    assert_string_equal(tirenv_nn_input_name(TIRENV_NN_X_N), "x_N");
    assert_string_equal(tirenv_nn_input_name(TIRENV_NN_CONTACT_LENGTH), "contact_length_m");
    assert_string_equal(tirenv_nn_input_name(TIRENV_NN_HEIGHT), "obstacle_height_m");
    assert_string_equal(tirenv_nn_input_name(TIRENV_NN_LENGTH), "obstacle_length_m");
    assert_null(tirenv_nn_input_name(TIRENV_NN_INPUTS));
}

/* Same seed, same weights to the bit; another seed, other weights. Nguyen-Widrow: every hidden
 * neuron's input weights have norm 0.7*n_hidden^(1/n_in), its bias at most that. */
static void test_init(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    for (size_t k = 0; k < N_TOPOLOGIES; ++k) {
        const tirenv_nn_topology *t = &topologies[k];
        tirenv_nn *a = tirenv_nn_alloc(t), *b = tirenv_nn_alloc(t), *c = tirenv_nn_alloc(t);
        tirenv_rng_seed(rng, 2385);
        tirenv_nn_init_weights(a, rng);
        tirenv_rng_seed(rng, 2385);
        tirenv_nn_init_weights(b, rng);
        tirenv_rng_seed(rng, 2386);
        tirenv_nn_init_weights(c, rng);
        const size_t p = tirenv_nn_n_weights(a);
        assert_memory_equal(tirenv_nn_weights(a), tirenv_nn_weights(b), p * sizeof(double));
        assert_memory_not_equal(tirenv_nn_weights(a), tirenv_nn_weights(c),
                                p * sizeof(double));
        const double *w = tirenv_nn_weights_const(a);
        for (size_t l = 1; l + 1 < t->n_layers; ++l) {
            const double beta = 0.7 * pow((double)t->size[l], 1.0 / (double)t->size[l - 1]);
            for (size_t j = 0; j < t->size[l]; ++j) {
                double norm2 = 0;
                for (size_t i = 1; i <= t->size[l - 1]; ++i) {
                    const double v = w[tirenv_nn_weight_index(a, l, i, j)];
                    norm2 += v * v;
                }
                assert_near(sqrt(norm2), beta, 0, 1e-14);
                assert_true(fabs(w[tirenv_nn_weight_index(a, l, 0, j)]) <= beta);
            }
        }
        const size_t L = t->n_layers - 1;
        for (size_t i = 0; i <= t->size[L - 1]; ++i)
            assert_true(fabs(w[tirenv_nn_weight_index(a, L, i, 0)]) <= 0.5);
        tirenv_nn_free(a);
        tirenv_nn_free(b);
        tirenv_nn_free(c);
    }
    tirenv_rng_free(rng);
}

/* Against the plain definition, over many inputs including saturating ones (where the
 * linear net's output grows large: hence the relative part of the tolerance). */
static void test_run_reference(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 7);
    for (size_t k = 0; k < N_TOPOLOGIES; ++k) {
        tirenv_nn *nn = make_net(&topologies[k], 100 + k);
        const size_t n_in = tirenv_nn_n_inputs(nn);
        double x[TIRENV_NN_MAX_WIDTH];
        for (int s = 0; s < 200; ++s) {
            fill_inputs(rng, 1, n_in, x);
            if (s % 50 == 0)  /* saturate: net inputs of hundreds */
                for (size_t i = 0; i < n_in; ++i)
                    x[i] *= 1e3;
            assert_near(tirenv_nn_run(nn, x), reference_run(nn, x), REF_TOL * 0.0271, REF_TOL);
        }
        tirenv_nn_free(nn);
    }
    tirenv_rng_free(rng);
}

/* The batch path transposes blocks of 64 samples and pads the last one; it must still give
 * exactly the single-sample bits, for every count around the block size. */
static void test_batch_exact(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 11);
    static const size_t counts[] = {0, 1, 7, 63, 64, 65, 200};
    for (size_t k = 0; k < N_TOPOLOGIES; ++k) {
        tirenv_nn *nn = make_net(&topologies[k], 200 + k);
        const size_t n_in = tirenv_nn_n_inputs(nn);
        for (size_t c = 0; c < sizeof counts / sizeof counts[0]; ++c) {
            const size_t n = counts[c];
            double *x = malloc((n + 1) * n_in * sizeof *x);
            double *y = malloc((n + 1) * sizeof *y);
            fill_inputs(rng, n, n_in, x);
            y[n] = 2385.0;  /* a sentinel past the end: must survive */
            tirenv_nn_run_batch(nn, n, x, y);
            for (size_t s = 0; s < n; ++s) {
                const double single = tirenv_nn_run(nn, x + s * n_in);
                assert_memory_equal(&y[s], &single, sizeof single);
            }
            assert_true(y[n] == 2385.0);
            free(x);
            free(y);
        }
        tirenv_nn_free(nn);
    }
    tirenv_rng_free(rng);
}

/* Back-propagation against central differences, with a guard that the gradient is not
 * trivially zero: every weight of these nets moves the output. */
static void test_gradient(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 13);
    for (size_t k = 0; k < N_TOPOLOGIES; ++k) {
        tirenv_nn *nn = make_net(&topologies[k], 300 + k);
        const size_t n_in = tirenv_nn_n_inputs(nn), p = tirenv_nn_n_weights(nn);
        double *grad = malloc(p * sizeof *grad), *w = tirenv_nn_weights(nn);
        double x[TIRENV_NN_MAX_WIDTH];
        for (int s = 0; s < 5; ++s) {
            fill_inputs(rng, 1, n_in, x);
            const double y = tirenv_nn_gradient(nn, x, grad);
            assert_true(y == tirenv_nn_run(nn, x));
            size_t nonzero = 0;
            double largest = 0;
            for (size_t j = 0; j < p; ++j) {
                const double w0 = w[j], h = 1e-6 * fmax(1.0, fabs(w0));
                w[j] = w0 + h;
                const double yp = tirenv_nn_run(nn, x);
                w[j] = w0 - h;
                const double ym = tirenv_nn_run(nn, x);
                w[j] = w0;
                assert_near(grad[j], (yp - ym) / (2 * h), FD_ABS, FD_REL);
                nonzero += grad[j] != 0;
                largest = fmax(largest, fabs(grad[j]));
            }
            assert_int_equal(nonzero, p);
            assert_true(largest > 1e-3);
        }
        free(grad);
        tirenv_nn_free(nn);
    }
    tirenv_rng_free(rng);
}

/* Each Jacobian row is that sample's gradient, to the bit. */
static void test_jacobian(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 17);
    tirenv_nn *nn = make_net(&topologies[1], 400);
    const size_t n = 37, n_in = tirenv_nn_n_inputs(nn), p = tirenv_nn_n_weights(nn);
    double *x = malloc(n * n_in * sizeof *x), *y = malloc(n * sizeof *y);
    double *J = malloc(n * p * sizeof *J), *g = malloc(p * sizeof *g);
    fill_inputs(rng, n, n_in, x);
    tirenv_nn_jacobian(nn, n, x, y, J);
    for (size_t s = 0; s < n; ++s) {
        const double ys = tirenv_nn_gradient(nn, x + s * n_in, g);
        assert_true(ys == y[s]);
        assert_memory_equal(J + s * p, g, p * sizeof *g);
    }
    tirenv_nn_jacobian(nn, n, x, NULL, J);  /* outputs not wanted */
    free(x);
    free(y);
    free(J);
    free(g);
    tirenv_nn_free(nn);
    tirenv_rng_free(rng);
}

/* Scaling from samples: mean and population deviation; a constant input gets std 1; ranges;
 * refusals of bad scalings. */
static void test_scaling(void **state)
{
    (void)state;
    const tirenv_nn_topology t = {3, {3, 4, 1}};
    tirenv_nn *nn = tirenv_nn_alloc(&t);
    const double x[] = {1.0, 0.33, -2.0, 3.0, 0.33, 4.0, 2.0, 0.33, 7.0};
    const double y[] = {0.01, 0.03, 0.05};
    assert_int_equal(tirenv_nn_fit_scaling(nn, 3, x, y, NULL), TIRENV_OK);
    double mean[3], std[3], om, os, lo[3], hi[3];
    tirenv_nn_scaling(nn, mean, std, &om, &os);
    tirenv_nn_input_range(nn, lo, hi);
    assert_near(mean[0], 2.0, 1e-15, 0);
    assert_near(std[0], sqrt(2.0 / 3.0), 0, 1e-15);
    assert_near(mean[1], 0.33, 1e-15, 0);
    assert_true(std[1] == 1.0);
    assert_near(mean[2], 3.0, 1e-15, 0);
    assert_near(std[2], sqrt(42.0 / 3.0), 0, 1e-15);
    assert_near(om, 0.03, 1e-17, 0);
    assert_near(os, sqrt(0.0008 / 3.0), 0, 1e-14);
    assert_true(lo[0] == 1.0 && hi[0] == 3.0 && lo[2] == -2.0 && hi[2] == 7.0);
    const double inside[] = {2.5, 0.33, 0.0}, outside[] = {2.5, 0.34, 9.0};
    assert_int_equal(tirenv_nn_out_of_range(nn, inside, 0), 3);
    assert_int_equal(tirenv_nn_out_of_range(nn, outside, 0), 1);
    assert_int_equal(tirenv_nn_out_of_range(nn, outside, 2), 2);

    tirenv_diag diag;
    const double zero_std[] = {1, 0, 1}, nan_x[] = {1, NAN, 1};
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_set_scaling(nn, mean, zero_std, 0, 1, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "scaling");
    assert_int_equal(tirenv_nn_set_scaling(nn, mean, std, 0, -1, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_nn_fit_scaling(nn, 0, x, y, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_nn_fit_scaling(nn, 1, nan_x, y, NULL), TIRENV_EINVAL);
    const double lo_bad[] = {1, 2, 3}, hi_bad[] = {1, 1, 3};
    assert_int_equal(tirenv_nn_set_input_range(nn, lo_bad, hi_bad, NULL), TIRENV_EINVAL);
    /* Unchanged by the refusals. */
    double std2[3];
    tirenv_nn_scaling(nn, NULL, std2, NULL, NULL);
    assert_memory_equal(std, std2, sizeof std);

    /* Copy and clone carry weights, scaling, ranges; copy refuses another shape. */
    tirenv_nn *c = tirenv_nn_clone(nn);
    assert_non_null(c);
    assert_true(tirenv_nn_run(c, inside) == tirenv_nn_run(nn, inside));
    const tirenv_nn_topology t2 = {3, {3, 5, 1}};
    tirenv_nn *other = tirenv_nn_alloc(&t2);
    assert_int_equal(tirenv_nn_copy(other, nn), TIRENV_EINVAL);
    tirenv_nn_free(other);
    tirenv_nn_free(c);
    tirenv_nn_free(nn);
}

/* The enveloping model: the network at x_N on the approach half, its mirror image beyond the
 * centre, 0 before the first x_N seen in training; refusals. */
static void test_envelope(void **state)
{
    (void)state;
    tirenv_nn *nn = make_net(&topologies[0], 500);
    const double lo[] = {-0.05, 0.28, 0.05, 0.1}, hi[] = {1.0, 0.38, 0.1, 0.3};
    assert_int_equal(tirenv_nn_set_input_range(nn, lo, hi, NULL), TIRENV_OK);
    const double R0 = 0.68, l_c = 0.3317, L = 0.2113, H = 0.0731;
    const double x_0 = tirenv_xN_origin(R0, l_c, L, H);
    assert_true(x_0 < 0);
    enum { N = 301 };
    double x[N], h[N];
    for (size_t k = 0; k < N; ++k)
        x[k] = 0.75 * (2.0 * (double)k - (N - 1)) / (N - 1);  /* x[N-1-k] = -x[k] exactly */
    assert_int_equal(tirenv_nn_envelope(nn, R0, l_c, L, H, N, x, h, NULL), TIRENV_OK);
    size_t zeros = 0;
    for (size_t k = 0; k < N; ++k) {
        assert_true(h[k] == h[N - 1 - k]);  /* x is symmetric about 0 */
        const double x_N = tirenv_xN(-fabs(x[k]), x_0);
        const double u[] = {x_N, l_c, H, L};
        const double want = tirenv_nn_run(nn, u);
        if (x_N < lo[0] || want < 0) {
            assert_true(h[k] == 0);
            zeros += x_N < lo[0];
        } else {
            assert_memory_equal(&h[k], &want, sizeof want);
        }
    }
    assert_true(zeros > 0 && zeros < N);

    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    /* A cleat taller than the chord height is out of reach. */
    assert_int_equal(tirenv_nn_envelope(nn, R0, l_c, L, 0.9, N, x, h, &diag), TIRENV_ERANGE);
    assert_int_equal(tirenv_nn_envelope(nn, R0, 2 * R0, L, H, N, x, h, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_nn_envelope(nn, R0, l_c, -L, H, N, x, h, NULL), TIRENV_EINVAL);
    tirenv_nn_free(nn);
    tirenv_nn *three = make_net(&topologies[2], 501);
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_envelope(three, R0, l_c, L, H, N, x, h, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "topology");
    tirenv_nn_free(three);
}


/* Every variant (ensembles, the even input, the h/H target) against the plain definition,
 * batch against single samples to the bit, back-propagation against central differences. */
static void test_variants(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 19);
    const tirenv_nn_topology *t4[] = {&topologies[0], &topologies[1]};
    for (size_t k = 0; k < 2; ++k)
        for (size_t v = 0; v < N_VARIANTS; ++v) {
            tirenv_nn *nn = make_variant(t4[k], &variants[v], 600 + 10 * k + v);
            assert_int_equal(tirenv_nn_n_members(nn), variants[v].members);
            const size_t n = 130, p = tirenv_nn_n_weights(nn);
            double x[130 * 4], y[130], *grad = malloc(p * sizeof *grad);
            double *w = tirenv_nn_weights(nn);
            fill_inputs(rng, n, 4, x);
            for (size_t s = 0; s < n; ++s)  /* H > 0, as the h/H target needs */
                x[s * 4 + TIRENV_NN_HEIGHT] = 0.02 + 0.1 * tirenv_rng_uniform(rng);
            tirenv_nn_run_batch(nn, n, x, y);
            for (size_t s = 0; s < n; ++s) {
                const double single = tirenv_nn_run(nn, x + 4 * s);
                assert_memory_equal(&y[s], &single, sizeof single);
                assert_near(single, reference_run(nn, x + 4 * s), REF_TOL * 0.0271, REF_TOL);
            }
            for (size_t s = 0; s < 3; ++s) {
                const double *xs = x + 4 * s;
                assert_true(tirenv_nn_gradient(nn, xs, grad) == tirenv_nn_run(nn, xs));
                for (size_t j = 0; j < p; ++j) {
                    const double w0 = w[j], h = 1e-6 * fmax(1.0, fabs(w0));
                    w[j] = w0 + h;
                    const double yp = tirenv_nn_run(nn, xs);
                    w[j] = w0 - h;
                    const double ym = tirenv_nn_run(nn, xs);
                    w[j] = w0;
                    assert_near(grad[j], (yp - ym) / (2 * h), FD_ABS, FD_REL);
                }
            }
            free(grad);
            tirenv_nn_free(nn);
        }
    tirenv_rng_free(rng);
}

/* The even input makes the mirrored curve smooth over the centre by construction: the
 * network sees a smooth even function of 1 - x_N, so its outputs at 1 + e and 1 - e are the
 * same number and its slope at x_N = 1 is zero to round-off (the central difference is
 * exactly 0, the one-sided one shrinks like e: a factor 100 from e = 1e-2 to 1e-4, bound
 * 2e-2 for the curvature's own change); the same weights fed x_N itself have a slope there.
 * Over the enveloping curve, the slope just before the centre shrinks with the step
 * likewise. */
static void test_even_symmetry(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 23);
    for (size_t k = 0; k < 4; ++k) {
        tirenv_nn *even = make_variant(&topologies[0], &variants[k % 2 ? 2 : 0], 700 + k);
        tirenv_nn *paper = tirenv_nn_clone(even);
        tirenv_nn_target_form target;
        tirenv_nn_form(even, NULL, &target);
        assert_int_equal(tirenv_nn_set_form(paper, TIRENV_NN_INPUT_PAPER, target, NULL),
                         TIRENV_OK);
        const double l_c = 0.28 + 0.15 * tirenv_rng_uniform(rng),
                     H = 0.025 + 0.075 * tirenv_rng_uniform(rng),
                     L = 0.05 + 0.25 * tirenv_rng_uniform(rng);
        double slope_e[2], slope_p = 0;
        for (int i = 0; i < 2; ++i) {
            const double e = i ? 1e-4 : 1e-2;
            const double up[] = {1 + e, l_c, H, L}, dn[] = {1 - e, l_c, H, L},
                         at[] = {1, l_c, H, L};
            assert_true(tirenv_nn_run(even, up) == tirenv_nn_run(even, dn));
            slope_e[i] = (tirenv_nn_run(even, at) - tirenv_nn_run(even, dn)) / e;
            if (i)
                slope_p = (tirenv_nn_run(paper, up) - tirenv_nn_run(paper, dn)) / (2 * e);
        }
        print_message("net %zu: dh/dx_N at x_N = 1, one-sided: %.3g (e = 0.01), %.3g (e = "
                      "1e-4) even; %.3g paper\n", k, slope_e[0], slope_e[1], slope_p);
        assert_true(fabs(slope_e[1]) <= 2e-2 * fabs(slope_e[0]) + 1e-12);
        /* The paper form's slope is a first derivative, the even form's quotient at e = 1e-4
         * a curvature times e/2: measured 586 to 3424 times apart over these four nets
         * (1000 was the bound until the generator changed, version 0.1, and net 0's draw
         * came to 586); 100 keeps a factor 5 below the least. */
        assert_true(fabs(slope_p) > 100 * fabs(slope_e[1]));

        /* The curve: the left difference quotient at the centre shrinks with the step. */
        const double R0 = 0.68, x_m[] = {-1e-3, -1e-6, 0};
        double h[3], hp[3];
        assert_int_equal(tirenv_nn_envelope(even, R0, l_c, L, H, 3, x_m, h, NULL), TIRENV_OK);
        assert_int_equal(tirenv_nn_envelope(paper, R0, l_c, L, H, 3, x_m, hp, NULL),
                         TIRENV_OK);
        const double d3 = (h[2] - h[0]) / 1e-3, d6 = (h[2] - h[1]) / 1e-6;
        assert_true(fabs(d6) <= 2e-3 * fabs(d3) + 1e-12);
        assert_true(fabs((hp[2] - hp[1]) / 1e-6) > 1e3 * fabs(d6));
        tirenv_nn_free(even);
        tirenv_nn_free(paper);
    }
    tirenv_rng_free(rng);
}

/* An ensemble: the mean of its members (to round-off: the same sums in another order),
 * members taken out and put together again to the bit, each member's block of the gradient
 * its own gradient over K; refusals. */
static void test_ensemble(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 29);
    const variant v = {3, TIRENV_NN_INPUT_PAPER, TIRENV_NN_TARGET_H};
    tirenv_nn *e = make_variant(&topologies[0], &v, 800);
    const size_t p = tirenv_nn_n_weights(e), per = p / 3;
    assert_int_equal(per, 49);
    tirenv_nn *m[3];
    for (size_t k = 0; k < 3; ++k) {
        m[k] = tirenv_nn_member(e, k);
        assert_non_null(m[k]);
        assert_int_equal(tirenv_nn_n_members(m[k]), 1);
        assert_memory_equal(tirenv_nn_weights(m[k]), tirenv_nn_weights(e) + k * per,
                            per * sizeof(double));
    }
    assert_null(tirenv_nn_member(e, 3));
    double *g = malloc(p * sizeof *g), *gk = malloc(per * sizeof *gk);
    for (int s = 0; s < 20; ++s) {
        double x[4];
        fill_inputs(rng, 1, 4, x);
        const double y = tirenv_nn_gradient(e, x, g);
        double mean = 0;
        for (size_t k = 0; k < 3; ++k) {
            mean += tirenv_nn_gradient(m[k], x, gk) / 3;
            for (size_t j = 0; j < per; ++j)
                assert_near(g[k * per + j], gk[j] / 3, 1e-16, 1e-14);
        }
        assert_near(y, mean, 1e-15, 1e-14);
    }
    tirenv_nn *again = tirenv_nn_ensemble((const tirenv_nn *const *)m, 3);
    assert_non_null(again);
    assert_memory_equal(tirenv_nn_weights(again), tirenv_nn_weights(e), p * sizeof(double));
    /* Refused: another scaling, another form, an ensemble as a member, no members. */
    double mean[4] = {0, 0, 0, 0}, std[4] = {1, 1, 1, 1};
    tirenv_nn *odd = tirenv_nn_clone(m[1]);
    const tirenv_nn *pair[2] = {m[0], odd};
    assert_int_equal(tirenv_nn_set_scaling(odd, mean, std, 0, 1, NULL), TIRENV_OK);
    assert_null(tirenv_nn_ensemble(pair, 2));
    tirenv_nn_copy(odd, m[1]);
    assert_int_equal(tirenv_nn_set_form(odd, TIRENV_NN_INPUT_EVEN, TIRENV_NN_TARGET_H, NULL),
                     TIRENV_OK);
    assert_null(tirenv_nn_ensemble(pair, 2));
    pair[1] = e;
    assert_null(tirenv_nn_ensemble(pair, 2));
    assert_null(tirenv_nn_ensemble(pair, 0));
    assert_null(tirenv_nn_alloc_ensemble(&topologies[0], 0));
    assert_null(tirenv_nn_alloc_ensemble(&topologies[0], TIRENV_NN_MAX_MEMBERS + 1));
    assert_int_equal(tirenv_nn_copy(m[0], e), TIRENV_EINVAL);  /* other member count */
    /* Forms need the enveloping model's four inputs. */
    tirenv_nn *three = make_net(&topologies[2], 801);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_set_form(three, TIRENV_NN_INPUT_EVEN, TIRENV_NN_TARGET_H,
                                        &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "form");
    assert_int_equal(tirenv_nn_set_form(three, TIRENV_NN_INPUT_PAPER, TIRENV_NN_TARGET_H,
                                        NULL), TIRENV_OK);
    tirenv_nn_free(three);
    free(g);
    free(gk);
    tirenv_nn_free(odd);
    tirenv_nn_free(again);
    for (size_t k = 0; k < 3; ++k)
        tirenv_nn_free(m[k]);
    tirenv_nn_free(e);
    tirenv_rng_free(rng);
}

/* Scaling from samples under the forms: the mean and deviation of the even feature
 * sqrt((1 - x_N)^2 + a^2) - a (with a = 0.75, where the three x_N give 0.5, 0.15139 and 0)
 * and of the target h/H; the input ranges stay those of x_N and of the raw inputs. */
static void test_scaling_forms(void **state)
{
    (void)state;
    tirenv_nn *nn = tirenv_nn_alloc(&topologies[0]);
    assert_true(tirenv_nn_even_width(nn) == TIRENV_NN_EVEN_WIDTH);
    assert_int_equal(tirenv_nn_set_form(nn, TIRENV_NN_INPUT_EVEN, TIRENV_NN_TARGET_H_OVER_H,
                                        NULL), TIRENV_OK);
    assert_int_equal(tirenv_nn_set_even_width(nn, 0.75, NULL), TIRENV_OK);
    assert_int_equal(tirenv_nn_set_even_width(nn, 0, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_nn_set_even_width(nn, INFINITY, NULL), TIRENV_EINVAL);
    assert_true(tirenv_nn_even_width(nn) == 0.75);
    const double x[] = {0.0, 0.3, 0.05, 0.1, 0.5, 0.3, 0.1, 0.1, 1.0, 0.3, 0.025, 0.1};
    const double y[] = {0.01, 0.06, 0.02};  /* h/H: 0.2, 0.6, 0.8 */
    assert_int_equal(tirenv_nn_fit_scaling(nn, 3, x, y, NULL), TIRENV_OK);
    double mean[4], std[4], om, os, lo[4], hi[4];
    tirenv_nn_scaling(nn, mean, std, &om, &os);
    tirenv_nn_input_range(nn, lo, hi);
    const double f1 = 0.5, f2 = sqrt(0.25 + 0.5625) - 0.75;  /* x_N = 0 and 0.5; 1 gives 0 */
    const double f_mean = (f1 + f2 + 0.0) / 3;
    assert_near(mean[0], f_mean, 1e-15, 0);
    assert_near(std[0], sqrt((pow(f1 - f_mean, 2) + pow(f2 - f_mean, 2) + f_mean * f_mean) /
                             3), 0, 1e-14);
    assert_true(lo[0] == 0.0 && hi[0] == 1.0);
    assert_near(om, 1.6 / 3, 1e-15, 0);
    assert_near(os, sqrt((pow(0.2 - 1.6 / 3, 2) + pow(0.6 - 1.6 / 3, 2) +
                          pow(0.8 - 1.6 / 3, 2)) / 3), 0, 1e-14);
    const double no_height[] = {0.5, 0.3, 0.0, 0.1};
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_fit_scaling(nn, 1, no_height, y, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "obstacle_height_m");
    tirenv_nn_free(nn);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_topology),     cmocka_unit_test(test_init),
        cmocka_unit_test(test_run_reference), cmocka_unit_test(test_batch_exact),
        cmocka_unit_test(test_gradient),     cmocka_unit_test(test_jacobian),
        cmocka_unit_test(test_scaling),      cmocka_unit_test(test_envelope),
        cmocka_unit_test(test_variants),     cmocka_unit_test(test_even_symmetry),
        cmocka_unit_test(test_ensemble),     cmocka_unit_test(test_scaling_forms),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
