/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the core: an in-place radix-2 complex FFT, for the ISO 8608 roads and Welch's
 * spectra (lengths that are powers of two, up to a few million). */
#ifndef TIRENV_CORE_FFT_H
#define TIRENV_CORE_FFT_H

#include <complex.h>
#include <stddef.h>

/* z_k <- sum_j z_j exp(sign 2 pi i j k / n), k = 0..n-1, unnormalised; n a power of two
 * >= 1, sign -1 (forward) or +1 (backward). */
void tirenv_core__fft(double complex z[], size_t n, int sign);

#endif
