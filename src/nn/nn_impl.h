/* SPDX-License-Identifier: Apache-2.0 */
/* Private to src/nn: the network's one allocation (network.c lays it out and evaluates it,
 * nn_scaling.c sets its forms, scaling and ranges). */
#ifndef TIRENV_NN_IMPL_H
#define TIRENV_NN_IMPL_H

#include <math.h>
#include <stddef.h>

#include "tirenv/nn.h"

/* Samples evaluated together by tirenv_nn_run_batch. A block of activations of a 4-8-1 net
 * is 13*64 doubles (6.5 KiB), well inside L1; a compile-time trip count is what lets GCC's
 * -O2 vectoriser (its "very cheap" cost model) take the loops over samples. */
enum { NN_BLOCK = 64 };

/* Neurons are evaluated in groups of NN_LANES (one AVX-512 register of doubles), so each
 * layer's activations are padded to a multiple of it. */
enum { NN_LANES = 8 };

/* exp(708) is near the largest double; beyond it the exponent trick in nn_exp overflows. */
#define NN_NET_MAX 708.0

struct tirenv_nn {
    tirenv_nn_topology top;
    size_t n_in;                          /* inputs, top.size[0] */
    size_t members;                       /* K: networks averaged (1: a single one) */
    size_t member_weights;                /* weights of one member */
    size_t n_weights;                     /* K*member_weights */
    tirenv_nn_input_form input_form;
    tirenv_nn_target_form target_form;
    double even_width;                    /* a of the even form */
    size_t n_act;                         /* neurons over all layers, with padding */
    size_t w_off[TIRENV_NN_MAX_LAYERS];   /* first weight of layer l, l >= 1 */
    size_t a_off[TIRENV_NN_MAX_LAYERS];   /* first activation of layer l, a multiple of
                                             NN_LANES */
    /* The clamp of a logistic's net input, NN_NET_MAX. Read from here rather than written as
     * a literal: with a literal GCC threads the clamped branch into a constant result, and
     * the resulting control flow stops it vectorising the loop. */
    double net_max;
    double out_mean, out_std;             /* output scaling, units of the output */
    double *w;                            /* n_weights (member after member), then NN_LANES
                                             zeros (read, never used, by the last group of
                                             layer_run) */
    double *in_mean, *in_std, *in_inv_std;/* n_in each: input scaling */
    double *in_lo, *in_hi;                /* n_in each: range seen in training */
    double *a;                            /* n_act: activations of one sample, layers
                                             padded to NN_LANES; layer 0 holds the scaled
                                             inputs */
    double *delta;                        /* n_act: dy/d(net input) of each neuron */
    double *blk;                          /* NN_BLOCK*n_act, 64-byte aligned: activations of a
                                             block of samples, neuron-major */
};

/* The evaluation entry points are compiled once per instruction set and the best one the
 * processor has is picked when the program loads (GCC's target_clones, through an ELF
 * ifunc). No FMA contraction happens in any clone (ISO C mode: -ffp-contract=off), so every
 * clone gives the same bits. The helpers are forced inline so that they are compiled for
 * the clone's instruction set too. Not under ThreadSanitizer (GCC's __SANITIZE_THREAD__):
 * the ifunc resolver runs before TSan's runtime is ready and crashed the program at load. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__) &&     \
    !defined(TIRENV_NN_NO_CLONES) && !defined(__SANITIZE_THREAD__)
#define NN_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define NN_CLONES
#endif
#if defined(__GNUC__)
#define NN_INLINE static inline __attribute__((always_inline))
#else
#define NN_INLINE static inline
#endif

/* The even form's feature of x_N: the distance 1 - x_N from the centre, rounded over the
 * width a. */
NN_INLINE double even_feature(double x_N, double a)
{
    const double d = 1 - x_N;
    return sqrt(d * d + a * a) - a;
}

/* The feature the network sees for input i of value v: the even form's for x_N, else the
 * input itself. */
NN_INLINE double feature(const tirenv_nn *nn, size_t i, double v)
{
    return nn->input_form == TIRENV_NN_INPUT_EVEN && i == TIRENV_NN_X_N
               ? even_feature(v, nn->even_width)
               : v;
}

#endif
