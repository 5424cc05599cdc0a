/* The feed-forward network of the empirical model (paper, Tables 1 and 2;
 * docs/models.md section 6): layout, initialisation, evaluation (one sample and batches),
 * back-propagation; its forms, scaling and ranges are nn_scaling.c's.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/nn.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "nn/nn_impl.h"
#include "tirenv/xn.h"



const char *tirenv_nn_input_form_name(tirenv_nn_input_form f)
{
    return f == TIRENV_NN_INPUT_PAPER ? "paper" : f == TIRENV_NN_INPUT_EVEN ? "even" : NULL;
}

const char *tirenv_nn_target_form_name(tirenv_nn_target_form f)
{
    return f == TIRENV_NN_TARGET_H ? "h" : f == TIRENV_NN_TARGET_H_OVER_H ? "h/H" : NULL;
}

int tirenv_nn_input_form_find(const char *name)
{
    for (int f = TIRENV_NN_INPUT_PAPER; f <= TIRENV_NN_INPUT_EVEN; ++f)
        if (name && strcmp(name, tirenv_nn_input_form_name((tirenv_nn_input_form)f)) == 0)
            return f;
    return -1;
}

int tirenv_nn_target_form_find(const char *name)
{
    for (int f = TIRENV_NN_TARGET_H; f <= TIRENV_NN_TARGET_H_OVER_H; ++f)
        if (name && strcmp(name, tirenv_nn_target_form_name((tirenv_nn_target_form)f)) == 0)
            return f;
    return -1;
}

const char *tirenv_nn_input_name(size_t i)
{
    static const char *const names[TIRENV_NN_INPUTS] = {"x_N", "contact_length_m",
                                                        "obstacle_height_m",
                                                        "obstacle_length_m"};
    return i < TIRENV_NN_INPUTS ? names[i] : NULL;
}

tirenv_nn_topology tirenv_nn_topology_default(void)
{
    return (tirenv_nn_topology){.n_layers = 3, .size = {TIRENV_NN_INPUTS, 8, 1}};
}

int tirenv_nn_topology_check(const tirenv_nn_topology *t, tirenv_diag *diag)
{
    if (t->n_layers < 2 || t->n_layers > TIRENV_NN_MAX_LAYERS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "topology",
                            "%zu layers; expected 2 to %d counting input and output",
                            t->n_layers, TIRENV_NN_MAX_LAYERS);
    for (size_t l = 0; l < t->n_layers; ++l)
        if (t->size[l] < 1 || t->size[l] > TIRENV_NN_MAX_WIDTH)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "topology",
                                "layer %zu has %zu neurons; expected 1 to %d", l, t->size[l],
                                TIRENV_NN_MAX_WIDTH);
    if (t->size[t->n_layers - 1] != 1)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "topology",
                            "output layer has %zu neurons; expected 1",
                            t->size[t->n_layers - 1]);
    return TIRENV_OK;
}

static size_t padded(size_t n)
{
    return (n + NN_LANES - 1) / NN_LANES * NN_LANES;
}

/* One malloc, genann style: the struct, then every array, the block workspace last and
 * rounded up to a 64-byte boundary (a cache line, an AVX-512 register) for aligned loads.
 * The members of an ensemble share everything but their weights. */
tirenv_nn *tirenv_nn_alloc_ensemble(const tirenv_nn_topology *t, size_t members)
{
    if (!t || tirenv_nn_topology_check(t, NULL) || members < 1 ||
        members > TIRENV_NN_MAX_MEMBERS)
        return NULL;
    size_t member_weights = 0, n_act = padded(t->size[0]);
    for (size_t l = 1; l < t->n_layers; ++l) {
        member_weights += (1 + t->size[l - 1]) * t->size[l];
        n_act += padded(t->size[l]);
    }
    const size_t n_weights = members * member_weights;
    const size_t n_in = t->size[0];
    const size_t n_doubles = n_weights + NN_LANES + 5 * n_in + 2 * n_act + NN_BLOCK * n_act;
    tirenv_nn *nn = malloc(sizeof *nn + (n_doubles + 8) * sizeof(double));
    if (!nn)
        return NULL;
    memset(nn, 0, sizeof *nn);
    nn->top = *t;
    nn->n_in = n_in;
    nn->members = members;
    nn->member_weights = member_weights;
    nn->n_weights = n_weights;
    nn->input_form = TIRENV_NN_INPUT_PAPER;
    nn->target_form = TIRENV_NN_TARGET_H;
    nn->even_width = TIRENV_NN_EVEN_WIDTH;
    nn->n_act = n_act;
    nn->net_max = NN_NET_MAX;
    size_t w_off = 0, a_off = padded(t->size[0]);
    for (size_t l = 1; l < t->n_layers; ++l) {
        nn->w_off[l] = w_off;
        nn->a_off[l] = a_off;
        w_off += (1 + t->size[l - 1]) * t->size[l];
        a_off += padded(t->size[l]);
    }
    double *p = (double *)(nn + 1);
    nn->w = p, p += n_weights + NN_LANES;
    nn->in_mean = p, p += n_in;
    nn->in_std = p, p += n_in;
    nn->in_inv_std = p, p += n_in;
    nn->in_lo = p, p += n_in;
    nn->in_hi = p, p += n_in;
    nn->a = p, p += n_act;
    nn->delta = p, p += n_act;
    const uintptr_t misalign = (uintptr_t)p % 64;
    nn->blk = misalign ? p + (64 - misalign) / sizeof(double) : p;
    memset(nn->w, 0, (n_weights + NN_LANES) * sizeof(double));
    memset(nn->a, 0, 2 * n_act * sizeof(double));
    memset(nn->blk, 0, NN_BLOCK * n_act * sizeof(double));
    for (size_t i = 0; i < n_in; ++i) {
        nn->in_mean[i] = 0;
        nn->in_std[i] = nn->in_inv_std[i] = 1;
        nn->in_lo[i] = -INFINITY;
        nn->in_hi[i] = INFINITY;
    }
    nn->out_mean = 0;
    nn->out_std = 1;
    return nn;
}

tirenv_nn *tirenv_nn_alloc(const tirenv_nn_topology *t)
{
    return tirenv_nn_alloc_ensemble(t, 1);
}

void tirenv_nn_free(tirenv_nn *nn)
{
    free(nn);
}

static int same_topology(const tirenv_nn *a, const tirenv_nn *b)
{
    return a->top.n_layers == b->top.n_layers &&
           memcmp(a->top.size, b->top.size, a->top.n_layers * sizeof a->top.size[0]) == 0;
}

/* Scaling, ranges and forms: what the members of an ensemble share. */
static void copy_shared(tirenv_nn *dst, const tirenv_nn *src)
{
    const size_t n = src->n_in * sizeof(double);
    memcpy(dst->in_mean, src->in_mean, n);
    memcpy(dst->in_std, src->in_std, n);
    memcpy(dst->in_inv_std, src->in_inv_std, n);
    memcpy(dst->in_lo, src->in_lo, n);
    memcpy(dst->in_hi, src->in_hi, n);
    dst->out_mean = src->out_mean;
    dst->out_std = src->out_std;
    dst->input_form = src->input_form;
    dst->target_form = src->target_form;
    dst->even_width = src->even_width;
}

static int same_shared(const tirenv_nn *a, const tirenv_nn *b)
{
    const size_t n = a->n_in * sizeof(double);
    return memcmp(a->in_mean, b->in_mean, n) == 0 && memcmp(a->in_std, b->in_std, n) == 0 &&
           memcmp(a->in_lo, b->in_lo, n) == 0 && memcmp(a->in_hi, b->in_hi, n) == 0 &&
           memcmp(&a->out_mean, &b->out_mean, sizeof a->out_mean) == 0 &&
           memcmp(&a->out_std, &b->out_std, sizeof a->out_std) == 0 &&
           a->input_form == b->input_form && a->target_form == b->target_form &&
           memcmp(&a->even_width, &b->even_width, sizeof a->even_width) == 0;
}

int tirenv_nn_copy(tirenv_nn *dst, const tirenv_nn *src)
{
    if (!same_topology(dst, src) || dst->members != src->members)
        return TIRENV_EINVAL;
    memcpy(dst->w, src->w, src->n_weights * sizeof(double));
    copy_shared(dst, src);
    return TIRENV_OK;
}

tirenv_nn *tirenv_nn_ensemble(const tirenv_nn *const nets[], size_t n)
{
    if (!nets || n < 1 || n > TIRENV_NN_MAX_MEMBERS)
        return NULL;
    for (size_t k = 0; k < n; ++k)
        if (!nets[k] || nets[k]->members != 1 || !same_topology(nets[0], nets[k]) ||
            !same_shared(nets[0], nets[k]))
            return NULL;
    tirenv_nn *e = tirenv_nn_alloc_ensemble(&nets[0]->top, n);
    if (!e)
        return NULL;
    copy_shared(e, nets[0]);
    for (size_t k = 0; k < n; ++k)
        memcpy(e->w + k * e->member_weights, nets[k]->w, e->member_weights * sizeof(double));
    return e;
}

tirenv_nn *tirenv_nn_member(const tirenv_nn *nn, size_t k)
{
    if (k >= nn->members)
        return NULL;
    tirenv_nn *m = tirenv_nn_alloc(&nn->top);
    if (!m)
        return NULL;
    copy_shared(m, nn);
    memcpy(m->w, nn->w + k * nn->member_weights, nn->member_weights * sizeof(double));
    return m;
}

tirenv_nn *tirenv_nn_clone(const tirenv_nn *nn)
{
    tirenv_nn *c = tirenv_nn_alloc_ensemble(&nn->top, nn->members);
    if (c)
        tirenv_nn_copy(c, nn);
    return c;
}

const tirenv_nn_topology *tirenv_nn_topology_of(const tirenv_nn *nn) { return &nn->top; }
size_t tirenv_nn_n_inputs(const tirenv_nn *nn) { return nn->n_in; }
size_t tirenv_nn_n_members(const tirenv_nn *nn) { return nn->members; }
size_t tirenv_nn_n_weights(const tirenv_nn *nn) { return nn->n_weights; }
double *tirenv_nn_weights(tirenv_nn *nn) { return nn->w; }
const double *tirenv_nn_weights_const(const tirenv_nn *nn) { return nn->w; }

size_t tirenv_nn_weight_index(const tirenv_nn *nn, size_t l, size_t i, size_t j)
{
    return nn->w_off[l] + i * nn->top.size[l] + j;
}

/* Nguyen and Widrow (1990): spread the hidden neurons' active regions over the input space,
 * which they assume to be [-1, 1]^n_in; the standardised inputs are close to that. The
 * uniform draws come from the caller's rng, so a seed fixes the weights bit for bit. */
/* One member's weights w (its layers in tirenv_nn_weights order). */
static void init_member(const tirenv_nn_topology *top, const size_t w_off[], double *w0,
                        tirenv_rng *rng)
{
    const size_t L = top->n_layers - 1;
    for (size_t l = 1; l <= L; ++l) {
        const size_t n_in = top->size[l - 1], n_out = top->size[l];
        double *w = w0 + w_off[l];
        if (l == L) {
            for (size_t k = 0; k < (1 + n_in) * n_out; ++k)
                w[k] = tirenv_rng_uniform(rng) - 0.5;
            continue;
        }
        const double beta = 0.7 * pow((double)n_out, 1.0 / (double)n_in);
        for (size_t j = 0; j < n_out; ++j) {
            double norm2 = 0;
            for (size_t i = 1; i <= n_in; ++i) {
                const double v = tirenv_rng_uniform(rng) - 0.5;
                w[i * n_out + j] = v;
                norm2 += v * v;
            }
            const double scale = norm2 > 0 ? beta / sqrt(norm2) : 0;
            for (size_t i = 1; i <= n_in; ++i)
                w[i * n_out + j] *= scale;
            w[j] = beta * (2 * tirenv_rng_uniform(rng) - 1);
        }
    }
}

void tirenv_nn_init_weights(tirenv_nn *nn, tirenv_rng *rng)
{
    for (size_t m = 0; m < nn->members; ++m)
        init_member(&nn->top, nn->w_off, nn->w + m * nn->member_weights, rng);
}

/* exp(x) for |x| <= NN_NET_MAX, within 3 ulp of libm's, in straight-line code the vectoriser
 * can take (a call to libm's exp stops it): Cody-Waite reduction x = k*ln2 + r, |r| <= ln2/2,
 * with ln2 split so that k*ln2_hi is exact; e^r by its Taylor polynomial to degree 12 (the
 * remainder r^13/13! < 2e-16), summed by Estrin's scheme, a tree of depth 4 rather than
 * Horner's chain of 12 (single-sample evaluation is bound by this latency); 2^k written
 * straight into the exponent bits. Rounding x/ln2 to k adds and subtracts 1.5*2^52, which
 * leaves k in the low mantissa bits of t. */
NN_INLINE double nn_exp(double x)
{
    const double log2e = 1.4426950408889634074, ln2_hi = 6.93147180369123816490e-01,
                 ln2_lo = 1.90821492927058770002e-10, shifter = 0x1.8p52;
    const double t = x * log2e + shifter;
    const double k = t - shifter;
    const double r = (x - k * ln2_hi) - k * ln2_lo;
    const double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    const double p01 = 1.0 + r, p23 = 0.5 + r * (1.0 / 6.0),
                 p45 = 1.0 / 24.0 + r * (1.0 / 120.0), p67 = 1.0 / 720.0 + r * (1.0 / 5040.0),
                 p89 = 1.0 / 40320.0 + r * (1.0 / 362880.0),
                 p1011 = 1.0 / 3628800.0 + r * (1.0 / 39916800.0), p12 = 1.0 / 479001600.0;
    const double p03 = p01 + r2 * p23, p47 = p45 + r2 * p67, p811 = p89 + r2 * p1011;
    const double p07 = p03 + r4 * p47, p812 = p811 + r4 * p12;
    const double p = p07 + r8 * p812;
    uint64_t bits;
    memcpy(&bits, &t, sizeof bits);
    bits = (bits << 52) + UINT64_C(0x3ff0000000000000);  /* (k + 1023) << 52: 2^k */
    double two_k;
    memcpy(&two_k, &bits, sizeof two_k);
    return p * two_k;
}

/* The logistic f(a) = 1/(1 + e^-a) of Table 1, its net input clamped to +-net_max (where f
 * is 0 or 1 to 307 digits anyway). */
NN_INLINE double nn_logistic(double a, double net_max)
{
    a = a < -net_max ? -net_max : a;
    a = a > net_max ? net_max : a;
    return 1.0 / (1.0 + nn_exp(-a));
}

/* The single-sample path works on NN_LANES neurons at once in GCC's generic vectors, which
 * the compiler maps onto whatever registers the target has (4 SSE2, 2 AVX2 or 1 AVX-512
 * register). Written out rather than left to the vectoriser: at -O3 GCC vectorises the loop
 * over inputs instead, as an in-order reduction, and leaves the exponentials scalar, which
 * measured 2.6 times slower. Each lane does exactly the scalar operations of nn_exp and
 * nn_logistic, so the results are the same bits as the batch path's. */
#if defined(__GNUC__)
typedef double nn_vec __attribute__((vector_size(NN_LANES * sizeof(double))));
typedef int64_t nn_veci __attribute__((vector_size(NN_LANES * sizeof(int64_t))));

/* Vectors go by pointer: by value, 64-byte vectors have an ABI GCC warns about (-Wpsabi),
 * although these are always inlined. */
NN_INLINE void nn_vec_exp(nn_vec *v)
{
    const nn_vec x = *v;
    const double log2e = 1.4426950408889634074, ln2_hi = 6.93147180369123816490e-01,
                 ln2_lo = 1.90821492927058770002e-10, shifter = 0x1.8p52;
    const nn_vec t = x * log2e + shifter;
    const nn_vec k = t - shifter;
    const nn_vec r = (x - k * ln2_hi) - k * ln2_lo;
    const nn_vec r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    const nn_vec p01 = 1.0 + r, p23 = 0.5 + r * (1.0 / 6.0),
                 p45 = 1.0 / 24.0 + r * (1.0 / 120.0), p67 = 1.0 / 720.0 + r * (1.0 / 5040.0),
                 p89 = 1.0 / 40320.0 + r * (1.0 / 362880.0),
                 p1011 = 1.0 / 3628800.0 + r * (1.0 / 39916800.0);
    const double p12 = 1.0 / 479001600.0;
    const nn_vec p03 = p01 + r2 * p23, p47 = p45 + r2 * p67, p811 = p89 + r2 * p1011;
    const nn_vec p07 = p03 + r4 * p47, p812 = p811 + r4 * p12;
    const nn_vec p = p07 + r8 * p812;
    nn_veci bits;
    memcpy(&bits, &t, sizeof bits);
    bits = (bits << 52) + INT64_C(0x3ff0000000000000);
    nn_vec two_k;
    memcpy(&two_k, &bits, sizeof two_k);
    *v = p * two_k;
}

/* The clamp as a blend on comparison masks (C has no ?: on vectors): a NaN compares false
 * and passes through, as in the scalar version. */
NN_INLINE void nn_vec_logistic(nn_vec *v, double net_max)
{
    nn_vec a = *v;
    const nn_vec lo = (nn_vec){0} - net_max, hi = (nn_vec){0} + net_max;
    nn_veci ai, loi, hii;
    memcpy(&ai, &a, sizeof ai);
    memcpy(&loi, &lo, sizeof loi);
    memcpy(&hii, &hi, sizeof hii);
    const nn_veci below = a < lo;
    ai = (loi & below) | (ai & ~below);
    memcpy(&a, &ai, sizeof a);
    const nn_veci above = a > hi;
    ai = (hii & above) | (ai & ~above);
    memcpy(&a, &ai, sizeof a);
    nn_vec e = -a;
    nn_vec_exp(&e);
    *v = 1.0 / (1.0 + e);
}

/* One layer, one sample: out_j = f(b_j + sum_i w_ij in_i), inputs added in order, as the
 * batch version below does, so both give the same bits. A group past the layer's last neuron
 * reads the next row of weights (or the zeros after the last one) into lanes whose results
 * land in the activation padding, which nobody reads. */
NN_INLINE void layer_run(size_t n_in, size_t n_out, const double *restrict w,
                         const double *restrict in, double *restrict out, int logistic,
                         double net_max)
{
    for (size_t j0 = 0; j0 < n_out; j0 += NN_LANES) {
        nn_vec acc, w_i;
        memcpy(&acc, w + j0, sizeof acc);
        for (size_t i = 0; i < n_in; ++i) {
            memcpy(&w_i, w + (1 + i) * n_out + j0, sizeof w_i);
            acc += w_i * in[i];
        }
        if (logistic)
            nn_vec_logistic(&acc, net_max);
        memcpy(out + j0, &acc, sizeof acc);
    }
}
#else
/* Without GCC's vectors (a compiler other than GCC or Clang): the same sums, lane by lane. */
NN_INLINE void layer_run(size_t n_in, size_t n_out, const double *restrict w,
                         const double *restrict in, double *restrict out, int logistic,
                         double net_max)
{
    for (size_t j = 0; j < n_out; ++j)
        out[j] = w[j];
    for (size_t i = 0; i < n_in; ++i)
        for (size_t j = 0; j < n_out; ++j)
            out[j] += w[(1 + i) * n_out + j] * in[i];
    if (logistic)
        for (size_t j = 0; j < n_out; ++j)
            out[j] = nn_logistic(out[j], net_max);
}
#endif

/* One layer, NN_BLOCK samples stored neuron-major (in[i*NN_BLOCK + s]): weights outside,
 * samples inside, so every inner loop is a fixed-length vector operation. */
NN_INLINE void layer_run_block(size_t n_in, size_t n_out, const double *restrict w,
                               const double *restrict in, double *restrict out, int logistic,
                               double net_max)
{
    for (size_t j = 0; j < n_out; ++j) {
        double *restrict o = out + j * NN_BLOCK;
        const double b = w[j];
        for (size_t s = 0; s < NN_BLOCK; ++s)
            o[s] = b;
        for (size_t i = 0; i < n_in; ++i) {
            const double w_ij = w[(1 + i) * n_out + j];
            const double *restrict x = in + i * NN_BLOCK;
            for (size_t s = 0; s < NN_BLOCK; ++s)
                o[s] += w_ij * x[s];
        }
        if (logistic)
            for (size_t s = 0; s < NN_BLOCK; ++s)
                o[s] = nn_logistic(o[s], net_max);
    }
}

/* The scaled features of one sample into layer 0. */
NN_INLINE void features_run(const tirenv_nn *nn, const double x[], double *restrict a)
{
    for (size_t i = 0; i < nn->n_in; ++i)
        a[i] = (feature(nn, i, x[i]) - nn->in_mean[i]) * nn->in_inv_std[i];
}

/* Member k's scaled output o_k from the features in layer 0. */
NN_INLINE double member_run(tirenv_nn *nn, size_t k)
{
    double *a = nn->a;
    const double *w = nn->w + k * nn->member_weights;
    const size_t L = nn->top.n_layers - 1;
    for (size_t l = 1; l <= L; ++l)
        layer_run(nn->top.size[l - 1], nn->top.size[l], w + nn->w_off[l],
                  a + nn->a_off[l - 1], a + nn->a_off[l], l < L, nn->net_max);
    return a[nn->a_off[L]];
}

/* y from the sum of the members' outputs: the mean, unscaled, times H for h/H. Dividing by
 * one member is exact, so a single network gives the bits it always did. */
NN_INLINE double output_of(const tirenv_nn *nn, const double x[], double sum)
{
    const double y = nn->out_mean + nn->out_std * (sum / (double)nn->members);
    return nn->target_form == TIRENV_NN_TARGET_H_OVER_H ? y * x[TIRENV_NN_HEIGHT] : y;
}

NN_CLONES double tirenv_nn_run(tirenv_nn *nn, const double x[])
{
    features_run(nn, x, nn->a);
    double sum = member_run(nn, 0);
    for (size_t k = 1; k < nn->members; ++k)
        sum += member_run(nn, k);
    return output_of(nn, x, sum);
}

/* Member k's forward pass for the gradient, compiled per instruction set like
 * tirenv_nn_run so that both give the same bits (they do on every clone anyway: see
 * NN_CLONES). */
NN_CLONES static double member_forward(tirenv_nn *nn, size_t k)
{
    return member_run(nn, k);
}

NN_CLONES void tirenv_nn_run_batch(tirenv_nn *nn, size_t n, const double x[], double y[])
{
    const size_t n_in = nn->n_in, L = nn->top.n_layers - 1;
    double *blk = nn->blk;
    double sum[NN_BLOCK];
    for (size_t s0 = 0; s0 < n; s0 += NN_BLOCK) {
        const size_t m = n - s0 < NN_BLOCK ? n - s0 : NN_BLOCK;
        const double *xs = x + s0 * n_in;
        /* Transpose and scale into the block; a short last block is padded with zeros. */
        for (size_t i = 0; i < n_in; ++i) {
            const double mean = nn->in_mean[i], inv_std = nn->in_inv_std[i];
            double *u = blk + i * NN_BLOCK;
            if (nn->input_form == TIRENV_NN_INPUT_EVEN && i == TIRENV_NN_X_N)
                for (size_t s = 0; s < m; ++s)
                    u[s] = (even_feature(xs[s * n_in + i], nn->even_width) - mean) * inv_std;
            else
                for (size_t s = 0; s < m; ++s)
                    u[s] = (xs[s * n_in + i] - mean) * inv_std;
            for (size_t s = m; s < NN_BLOCK; ++s)
                u[s] = 0;
        }
        const double *o = blk + nn->a_off[L] * NN_BLOCK;
        for (size_t k = 0; k < nn->members; ++k) {
            const double *w = nn->w + k * nn->member_weights;
            for (size_t l = 1; l <= L; ++l)
                layer_run_block(nn->top.size[l - 1], nn->top.size[l], w + nn->w_off[l],
                                blk + nn->a_off[l - 1] * NN_BLOCK,
                                blk + nn->a_off[l] * NN_BLOCK, l < L, nn->net_max);
            if (k == 0)
                for (size_t s = 0; s < NN_BLOCK; ++s)
                    sum[s] = o[s];
            else
                for (size_t s = 0; s < NN_BLOCK; ++s)
                    sum[s] += o[s];
        }
        for (size_t s = 0; s < m; ++s)
            y[s0 + s] = output_of(nn, xs + s * n_in, sum[s]);
    }
}

/* Back-propagation: delta_j = dy/d(net input of j), from the output (identity, scaled:
 * out_std) down, through the logistic's f' = f(1 - f); dy/dw_ij = delta_j * a_i with a_0 = 1
 * for the bias. */
static void member_backprop(tirenv_nn *nn, size_t k, double dy_do, double grad[])
{
    const double *a = nn->a;
    double *d = nn->delta;
    const size_t L = nn->top.n_layers - 1;
    d[nn->a_off[L]] = dy_do;
    for (size_t l = L; l >= 1; --l) {
        const size_t n_in = nn->top.size[l - 1], n_out = nn->top.size[l];
        const double *d_out = d + nn->a_off[l];
        const double *a_in = a + nn->a_off[l - 1];
        const double *w = nn->w + k * nn->member_weights + nn->w_off[l];
        double *g = grad + k * nn->member_weights + nn->w_off[l];
        for (size_t j = 0; j < n_out; ++j)
            g[j] = d_out[j];
        for (size_t i = 0; i < n_in; ++i)
            for (size_t j = 0; j < n_out; ++j)
                g[(1 + i) * n_out + j] = d_out[j] * a_in[i];
        if (l > 1) {
            double *d_in = d + nn->a_off[l - 1];
            for (size_t i = 0; i < n_in; ++i) {
                double sum = 0;
                for (size_t j = 0; j < n_out; ++j)
                    sum += w[(1 + i) * n_out + j] * d_out[j];
                d_in[i] = sum * a_in[i] * (1 - a_in[i]);
            }
        }
    }
}

/* Member by member: its forward pass leaves its activations in nn->a, its backward pass
 * turns them into its block of the gradient, with dy/do_k = out_std/K (times H for h/H). */
double tirenv_nn_gradient(tirenv_nn *nn, const double x[], double grad[])
{
    double dy_do = nn->out_std / (double)nn->members;
    if (nn->target_form == TIRENV_NN_TARGET_H_OVER_H)
        dy_do *= x[TIRENV_NN_HEIGHT];
    features_run(nn, x, nn->a);
    double sum = 0;
    for (size_t k = 0; k < nn->members; ++k) {
        const double o = member_forward(nn, k);
        sum = k ? sum + o : o;
        member_backprop(nn, k, dy_do, grad);
    }
    return output_of(nn, x, sum);
}

void tirenv_nn_jacobian(tirenv_nn *nn, size_t n, const double x[], double y[], double J[])
{
    for (size_t s = 0; s < n; ++s) {
        const double ys = tirenv_nn_gradient(nn, x + s * nn->n_in, J + s * nn->n_weights);
        if (y)
            y[s] = ys;
    }
}

/* The curve in blocks of inputs on the stack, so that it needs no workspace from the caller
 * and still goes through the vectorised batch path. A cleat only raises the ground, so the
 * centre never sinks below its flat-ground height: a network output below 0 (its error near
 * first contact is of the order of its RMS error, a millimetre or two) is clamped to 0, as is
 * everything before the first x_N it was trained on. */
int tirenv_nn_envelope(tirenv_nn *nn, double R0, double l_c, double L, double H, size_t n,
                       const double x[], double h[], tirenv_diag *diag)
{
    if (nn->n_in != TIRENV_NN_INPUTS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "topology",
                            "the enveloping model needs %d inputs (x_N, l_c, H, L); this "
                            "network has %zu", TIRENV_NN_INPUTS, nn->n_in);
    if (!(R0 > 0) || !(l_c > 0) || !(l_c < 2 * R0) || !(L > 0) || !(H > 0) || !isfinite(R0) ||
        !isfinite(L) || !isfinite(H))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "",
                            "expected R0 > 0, 0 < l_c < 2*R0, L > 0, H > 0 (m); got R0 %g, "
                            "l_c %g, L %g, H %g", R0, l_c, L, H);
    /* The chord height (docs/models.md section 1). */
    const double z_c = sqrt(R0 * R0 - 0.25 * l_c * l_c);
    const double x_0 = tirenv_xN_origin(R0, l_c, L, H);
    if (!(H < z_c) || !(x_0 < 0))
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "obstacle_height_m",
                            "a %g m high cleat reaches the centre height %g m of a tire of "
                            "radius %g m at contact length %g m: the enveloping models do not "
                            "apply", H, z_c, R0, l_c);
    const double x_N_min = nn->in_lo[TIRENV_NN_X_N];
    double in[NN_BLOCK * TIRENV_NN_INPUTS];
    double x_N[NN_BLOCK];
    for (size_t k0 = 0; k0 < n; k0 += NN_BLOCK) {
        const size_t m = n - k0 < NN_BLOCK ? n - k0 : NN_BLOCK;
        for (size_t k = 0; k < m; ++k) {
            x_N[k] = tirenv_xN(-fabs(x[k0 + k]), x_0);
            double *u = in + k * TIRENV_NN_INPUTS;
            u[TIRENV_NN_X_N] = x_N[k];
            u[TIRENV_NN_CONTACT_LENGTH] = l_c;
            u[TIRENV_NN_HEIGHT] = H;
            u[TIRENV_NN_LENGTH] = L;
        }
        tirenv_nn_run_batch(nn, m, in, h + k0);
        for (size_t k = 0; k < m; ++k)
            if (x_N[k] < x_N_min || !(h[k0 + k] >= 0))
                h[k0 + k] = 0;
    }
    return TIRENV_OK;
}
