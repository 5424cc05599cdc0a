/* SPDX-License-Identifier: Apache-2.0 */
/* Iterative radix-2 decimation-in-time Cooley-Tukey (Cormen et al., Introduction to
 * Algorithms, 3rd ed., section 30.3): bit-reversal permutation, then log2 n passes of
 * butterflies. Each twiddle factor is computed by cos/sin of its own angle, not by repeated
 * multiplication, so its error stays at round-off whatever n (the error of the transform then
 * grows as log n, as for any FFT); tests/core/test_numerics.c checks it against the direct sum. */
#include "core/fft.h"

#include <math.h>

void tirenv_core__fft(double complex z[], const size_t n, const int sign)
{
    for (size_t i = 1, j = 0; i < n; ++i) {  /* j: i with its log2 n bits reversed */
        size_t bit = n >> 1;
        for (; j & bit; bit >>= 1)
            j ^= bit;
        j |= bit;
        if (i < j) {
            const double complex t = z[i];
            z[i] = z[j];
            z[j] = t;
        }
    }
    for (size_t len = 2; len <= n; len <<= 1) {
        const size_t half = len / 2;
        const double theta = (double)sign * 2.0 * M_PI / (double)len;
        for (size_t k = 0; k < half; ++k) {
            const double complex w = cos(theta * (double)k) + I * sin(theta * (double)k);
            for (size_t i = k; i < n; i += len) {
                const double complex u = z[i], v = z[i + half] * w;
                z[i] = u + v;
                z[i + half] = u - v;
            }
        }
    }
}
