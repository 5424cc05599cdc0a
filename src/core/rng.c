/* SPDX-License-Identifier: Apache-2.0 */
/* The library's random numbers (tirenv/rng.h): xoshiro256** 1.0 as published by Blackman and
 * Vigna ("Scrambled linear pseudorandom number generators", ACM TOMS 47, 2021; reference code
 * at prng.di.unimi.it, public domain), its state filled by splitmix64 as the authors
 * recommend. A small state (32 bytes), a period of 2^256 - 1, and it passes BigCrush; the
 * test checks the reference implementation's first outputs from the state {1, 2, 3, 4}. */
#include "tirenv/rng.h"

#include <math.h>
#include <stdlib.h>

struct tirenv_rng {
    uint64_t s[4];
};

static uint64_t rotl(const uint64_t x, const int k)
{
    return (x << k) | (x >> (64 - k));
}

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += UINT64_C(0x9e3779b97f4a7c15));
    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

tirenv_rng *tirenv_rng_alloc(const uint64_t seed)
{
    tirenv_rng *rng = malloc(sizeof *rng);
    if (rng)
        tirenv_rng_seed(rng, seed);
    return rng;
}

void tirenv_rng_free(tirenv_rng *rng)
{
    free(rng);
}

void tirenv_rng_seed(tirenv_rng *rng, const uint64_t seed)
{
    uint64_t x = seed;
    for (int i = 0; i < 4; ++i)
        rng->s[i] = splitmix64(&x);
}

void tirenv_rng_set_state(tirenv_rng *rng, const uint64_t s[4])
{
    for (int i = 0; i < 4; ++i)
        rng->s[i] = s[i];
}

uint64_t tirenv_rng_u64(tirenv_rng *rng)
{
    uint64_t *s = rng->s;
    const uint64_t result = rotl(s[1] * 5, 7) * 9;
    const uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return result;
}

double tirenv_rng_uniform(tirenv_rng *rng)
{
    return (double)(tirenv_rng_u64(rng) >> 11) * 0x1.0p-53;
}

/* Rejects the outputs in the last, incomplete block of n values, so every residue is equally
 * likely; at most half the outputs are rejected (n > 2^63), usually a vanishing share. */
size_t tirenv_rng_uniform_int(tirenv_rng *rng, const size_t n)
{
    const uint64_t m = (uint64_t)n;
    const uint64_t limit = UINT64_MAX - UINT64_MAX % m;  /* a multiple of m, >= 2^63 */
    uint64_t x;
    do
        x = tirenv_rng_u64(rng);
    while (x >= limit);
    return (size_t)(x % m);
}

double tirenv_rng_gaussian(tirenv_rng *rng, const double sigma)
{
    const double u1 = 1.0 - tirenv_rng_uniform(rng);  /* (0, 1]: the log is finite */
    const double u2 = tirenv_rng_uniform(rng);
    return sigma * sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
}

void tirenv_rng_shuffle(tirenv_rng *rng, size_t a[], const size_t n)
{
    for (size_t i = n; i > 1; --i) {
        const size_t j = tirenv_rng_uniform_int(rng, i);
        const size_t t = a[i - 1];
        a[i - 1] = a[j];
        a[j] = t;
    }
}
