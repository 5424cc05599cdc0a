/* Welch's estimate of a one-sided power spectral density, for seat-acceleration spectra
 * (docs/models.md section 10).
 * SPDX-License-Identifier: Apache-2.0
 *
 * The series is cut into K segments of N samples (a power of two, for the radix-2 FFT of core/fft.c)
 * starting every N/2 samples, each multiplied by the periodic Hann window
 * w_i = (1 - cos(2 pi i/N))/2, whose half-overlapped copies sum to a constant so that every
 * sample away from the ends counts equally. With X_k the DFT of one windowed segment and
 * U = sum w_i^2, the one-sided density at f_k = k fs/N, averaged over the segments, is
 *   P_k = c_k |X_k|^2 / (fs U),  c_k = 1 at k = 0 and k = N/2, else 2 (the negative bins).
 * Parseval's sum_k |X_k|^2 = N sum_i (w_i x_i)^2 then gives
 *   sum_k P_k fs/N = (1/K) sum over segments of sum_i w_i^2 x_i^2 / U,
 * the mean square of x weighted by the window: the integral of the PSD over frequency is the
 * mean square up to how the window weighs the samples, and equals it in expectation for a
 * stationary series. The mean is not removed: it stays in the bins 0 and 1, and the caller who
 * wants the variance subtracts it first. For white noise of variance s^2 every P_k has the
 * expectation 2 s^2/fs (s^2/fs at k = 0 and N/2). */
#include "tirenv/comfort.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include "core/fft.h"

struct tirenv_welch {
    size_t n_seg;          /* N, samples per segment */
    double U;              /* sum of w_i^2 (1) */
    double *w;             /* Hann window, N values */
    double complex *seg;   /* the windowed segment, transformed in place; N values */
};

int tirenv_welch_alloc(size_t n_seg, tirenv_welch **out, tirenv_diag *diag)
{
    *out = NULL;
    if (n_seg < 2 || (n_seg & (n_seg - 1)) != 0 || n_seg > SIZE_MAX / (4 * sizeof(double)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "n_seg",
                            "segment length %zu is not a power of two >= 2 (the radix-2 FFT "
                            "needs one); try 256, 1024 or 4096", n_seg);
    tirenv_welch *w = malloc(sizeof *w);
    double *buf = malloc(n_seg * sizeof *buf);
    double complex *seg = malloc(n_seg * sizeof *seg);
    if (!w || !buf || !seg) {
        free(w);
        free(buf);
        free(seg);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "n_seg",
                            "out of memory for segments of %zu samples", n_seg);
    }
    w->n_seg = n_seg;
    w->w = buf;
    w->seg = seg;
    w->U = 0.0;
    for (size_t i = 0; i < n_seg; i++) {
        w->w[i] = 0.5 * (1.0 - cos(2.0 * M_PI * (double)i / (double)n_seg));
        w->U += w->w[i] * w->w[i];
    }
    *out = w;
    return TIRENV_OK;
}

void tirenv_welch_free(tirenv_welch *w)
{
    if (!w)
        return;
    free(w->w);
    free(w->seg);
    free(w);
}

size_t tirenv_welch_bins(const tirenv_welch *w)
{
    return w->n_seg / 2 + 1;
}

int tirenv_welch_psd(tirenv_welch *w, const double x[], size_t n, double fs, double psd[],
                     size_t *segments, tirenv_diag *diag)
{
    const size_t N = w->n_seg, hop = N / 2, bins = N / 2 + 1;
    if (!(fs > 0 && isfinite(fs)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "fs",
                            "sample rate must be positive and finite in Hz, got %g", fs);
    if (n < N)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "n",
                            "series of %zu samples is shorter than one segment of %zu; "
                            "choose a shorter segment", n, N);
    for (size_t j = 0; j < n; j++)
        if (!isfinite(x[j]))
            return tirenv_error(diag, TIRENV_EINVAL, "", j + 1, "x",
                                "sample %zu is %g; expected a finite value", j + 1, x[j]);
    for (size_t k = 0; k < bins; k++)
        psd[k] = 0.0;
    size_t K = 0;
    for (size_t start = 0; start + N <= n; start += hop, K++) {
        for (size_t i = 0; i < N; i++)
            w->seg[i] = w->w[i] * x[start + i];
        tirenv_core__fft(w->seg, N, -1);
        /* X_0 and X_N/2 are real; X_N-k is the conjugate of X_k. */
        psd[0] += creal(w->seg[0]) * creal(w->seg[0]);
        for (size_t k = 1; k < N / 2; k++)
            psd[k] += 2.0 * (creal(w->seg[k]) * creal(w->seg[k]) +
                             cimag(w->seg[k]) * cimag(w->seg[k]));
        psd[N / 2] += creal(w->seg[N / 2]) * creal(w->seg[N / 2]);
    }
    const double scale = 1.0 / (fs * w->U * (double)K);
    for (size_t k = 0; k < bins; k++) {
        psd[k] *= scale;
        /* Squares that overflowed (samples of 1e200) came back as inf with TIRENV_OK. */
        if (isinf(psd[k]))
            return tirenv_error(diag, TIRENV_ERANGE, "", 0, "x",
                                "the power at bin %zu (%g Hz) overflows a double; expected "
                                "samples whose squares it holds", k, (double)k * fs / (double)N);
    }
    if (segments)
        *segments = K;
    return TIRENV_OK;
}
