/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: the library's own seeded random numbers: xoshiro256** (Blackman and Vigna, 2018),
 * seeded through splitmix64, so that a seed gives the same stream on every machine and no
 * third-party generator appears in a public header. Used for network initialisation, batch
 * order, rig noise and random roads (docs/models.md, "Random numbers"). Not for cryptography. */
#ifndef TIRENV_RNG_H
#define TIRENV_RNG_H

#include "tirenv/decls.h"
#include <stddef.h>
#include <stdint.h>

TIRENV_BEGIN_DECLS

typedef struct tirenv_rng tirenv_rng;

/* A generator seeded with seed (tirenv_rng_seed); NULL when out of memory. */
tirenv_rng *tirenv_rng_alloc(uint64_t seed);
/* Frees it; NULL is a no-op. */
void tirenv_rng_free(tirenv_rng *rng);
/* The state from seed: four successive outputs of splitmix64 started at seed (any seed,
 * 0 included, gives a state that is not all zero). */
void tirenv_rng_seed(tirenv_rng *rng, uint64_t seed);
/* Sets the four state words directly (for published test vectors); not all zero. */
void tirenv_rng_set_state(tirenv_rng *rng, const uint64_t s[4]);
/* The next 64-bit output of xoshiro256**. */
uint64_t tirenv_rng_u64(tirenv_rng *rng);
/* Uniform in [0, 1): the top 53 bits of one output, times 2^-53. */
double tirenv_rng_uniform(tirenv_rng *rng);
/* Uniform integer in [0, n), n >= 1, without bias (rejection of the incomplete last block). */
size_t tirenv_rng_uniform_int(tirenv_rng *rng, size_t n);
/* Normal with mean 0 and standard deviation sigma by the Box-Muller transform: two uniforms
 * per value, u1 in (0, 1] and u2, sigma*sqrt(-2 ln u1)*cos(2 pi u2); the sine partner is not
 * kept, so every value draws exactly two outputs. */
double tirenv_rng_gaussian(tirenv_rng *rng, double sigma);
/* Fisher-Yates shuffle of a[0..n-1] (Knuth's algorithm P, from the end). */
void tirenv_rng_shuffle(tirenv_rng *rng, size_t a[], size_t n);

TIRENV_END_DECLS

#endif
