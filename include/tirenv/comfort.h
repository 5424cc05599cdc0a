/* tirenv: ride comfort by ISO 2631-1:1997 (frequency weightings Wk, Wd, We, the r.m.s., peak,
 * crest factor, VDV, MTVV and the vibration total value) and Welch's PSD estimate for
 * seat-acceleration spectra (docs/models.md section 10).
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_COMFORT_H
#define TIRENV_COMFORT_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"

TIRENV_BEGIN_DECLS

/* ---- Frequency weightings (ISO 2631-1 Annex A; src/ride/comfort_weighting.c) ---- */

/* The weightings of ISO 2631-1 that a seated tractor driver needs. */
typedef enum {
    TIRENV_WK = 0,  /* vertical z, seat surface (seated, standing) */
    TIRENV_WD,      /* horizontal x, y, seat surface */
    TIRENV_WE       /* rotational rx, ry, rz, seat surface; input in rad/s^2 */
} tirenv_weighting;

/* Sample rates the digital weighting filters accept, Hz. The minimum is 4 times 80 Hz, the top
 * of ISO 2631-1's band: there the filters are within 1 % of the weighting up to 17.6 Hz and
 * 15 % (1.4 dB) low at 80 Hz. The maximum keeps the 0.4 Hz high-pass's poles far enough from
 * z = 1 for double precision. Accuracy in between: see tirenv_weighting_filter_init. */
#define TIRENV_COMFORT_FS_MIN 320.0
#define TIRENV_COMFORT_FS_MAX 100000.0

/* "Wk", "Wd", "We"; NULL for any other value. */
const char *tirenv_weighting_name(tirenv_weighting w);

/* The weighting named name ("Wk", "Wd", "We"; case-insensitive) in *w; TIRENV_EINVAL
 * otherwise, with the names expected in diag. */
int tirenv_weighting_parse(const char *name, tirenv_weighting *w, tirenv_diag *diag);

/* The analogue transfer function H(j 2 pi f) of ISO 2631-1 Annex A at frequency f (Hz) in
 * *re, *im (dimensionless). TIRENV_EINVAL if w is unknown or f is not finite. */
int tirenv_weighting_response(tirenv_weighting w, double f, double *re, double *im);

/* |H(j 2 pi f)|, the weighting factor of ISO 2631-1 Tables 3 and 4 at f (Hz); NAN if w is
 * unknown or f is not finite. */
double tirenv_weighting_gain(tirenv_weighting w, double f);

/* One second-order section y/x = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2). */
typedef struct {
    double b0, b1, b2;     /* numerator (1) */
    double a1, a2;         /* denominator, a0 = 1 (1) */
    double s1, s2;         /* state of the transposed direct form II */
} tirenv_biquad;

/* A weighting as a causal digital filter: one biquad per factor of the product, each from the
 * bilinear transform pre-warped at the factor's corner. A value type: no allocation; copy it
 * to fork a state. */
typedef struct {
    tirenv_weighting w;    /* the weighting realised */
    double fs;             /* sample rate, Hz */
    size_t n;              /* sections in use: 4 with the upward step (Wk), else 3 */
    tirenv_biquad s[4];    /* high-pass, low-pass, a-v transition, upward step */
} tirenv_weighting_filter;

/* Designs the filter of w for sample rate fs (Hz) at rest. Its gain G_d differs from the
 * analogue |H| by |G_d/|H| - 1| <= 1 - x/tan(x), x = pi*max(f, 1 Hz)/fs, for f <= 100 Hz:
 * within 1 % below fs/18.2, 2 % below fs/12.9, 5 % below fs/8.2. TIRENV_EINVAL (diag says why)
 * if w is unknown or fs is outside [TIRENV_COMFORT_FS_MIN, TIRENV_COMFORT_FS_MAX]. */
int tirenv_weighting_filter_init(tirenv_weighting_filter *flt, tirenv_weighting w, double fs,
                                 tirenv_diag *diag);

/* Sets the filter at rest (zero state), as a meter switched on. */
void tirenv_weighting_filter_reset(tirenv_weighting_filter *flt);

/* Filters one sample a (m/s^2 or rad/s^2) and returns the weighted sample (same unit). */
double tirenv_weighting_filter_step(tirenv_weighting_filter *flt, double a);

/* Filters n samples a[] into a_w[] (a_w may equal a), continuing from the filter's state. */
void tirenv_weighting_filter_run(tirenv_weighting_filter *flt, const double a[], double a_w[],
                                 size_t n);

/* The digital response H(e^(j 2 pi f/fs)) at f (Hz) in *re, *im, and its modulus. */
void tirenv_weighting_filter_response(const tirenv_weighting_filter *flt, double f, double *re,
                                      double *im);
double tirenv_weighting_filter_gain(const tirenv_weighting_filter *flt, double f);

/* Weights a whole series sampled at fs (Hz): a filter at rest run over a[0..n-1] into a_w[]
 * (a_w may equal a). Causal, as a meter; never forward-backward. TIRENV_EINVAL as
 * tirenv_weighting_filter_init, or if n == 0. */
int tirenv_weighting_apply(tirenv_weighting w, double fs, const double a[], double a_w[],
                           size_t n, tirenv_diag *diag);

/* ---- Metrics of a weighted series (ISO 2631-1 clause 6; src/ride/comfort_metrics.c) ---- */

/* Integration time of the running r.m.s. behind the MTVV, s (ISO 2631-1 6.3). */
#define TIRENV_COMFORT_TAU 1.0
/* Crest factor above which the r.m.s. alone may underestimate the effect (ISO 2631-1 6.2),
 * and the VDV or MTVV should be reported too (1). */
#define TIRENV_COMFORT_CREST_LIMIT 9.0

/* Multiplying factors k of ISO 2631-1 for a seated person at the seat surface. Translational
 * ones are dimensionless; rotational ones in m/rad turn rad/s^2 into m/s^2. */
#define TIRENV_COMFORT_K_X 1.0     /* comfort (8.2), fore-aft, with Wd */
#define TIRENV_COMFORT_K_Y 1.0     /* comfort, lateral, with Wd */
#define TIRENV_COMFORT_K_Z 1.0     /* comfort, vertical, with Wk */
#define TIRENV_COMFORT_K_RX 0.63   /* comfort, roll, with We, m/rad */
#define TIRENV_COMFORT_K_RY 0.40   /* comfort, pitch, with We, m/rad */
#define TIRENV_COMFORT_K_RZ 0.20   /* comfort, yaw, with We, m/rad */
#define TIRENV_HEALTH_K_X 1.4      /* health (7.2), fore-aft, with Wd */
#define TIRENV_HEALTH_K_Y 1.4      /* health, lateral, with Wd */
#define TIRENV_HEALTH_K_Z 1.0      /* health, vertical, with Wk */

/* Everything clause 6 asks of one weighted series. Units are those of the input: m/s^2 for
 * Wk and Wd, rad/s^2 for We (and s^1.75 in place of s^2 for the VDV). */
typedef struct {
    double duration;       /* T = n/fs, s */
    double rms;            /* weighted r.m.s. a_w over T */
    double peak;           /* max |a_w(t)| */
    double crest;          /* peak/rms (1); NAN if rms = 0 (no vibration: no ratio) */
    double vdv;            /* vibration dose value (int_0^T a_w^4 dt)^(1/4), m/s^1.75 */
    double mtvv;           /* maximum transient vibration value: max running r.m.s., tau 1 s */
} tirenv_comfort_metrics;

/* r.m.s. (sum a_w^2 / n)^(1/2) of n samples into *rms. TIRENV_EINVAL if n == 0 or a sample is
 * not finite (diag: line = 1-based sample index); TIRENV_ERANGE if the sum of squares
 * overflows (samples beyond about 1e154). */
int tirenv_comfort_rms(const double a_w[], size_t n, double *rms, tirenv_diag *diag);

/* max |a_w| of n samples into *peak; errors as tirenv_comfort_rms. */
int tirenv_comfort_peak(const double a_w[], size_t n, double *peak, tirenv_diag *diag);

/* VDV = (sum a_w^4 / fs)^(1/4) of n samples at fs (Hz) into *vdv; TIRENV_EINVAL also if fs
 * is not positive and finite; TIRENV_ERANGE if the sum of fourth powers overflows (samples
 * beyond about 1e77). */
int tirenv_comfort_vdv(const double a_w[], size_t n, double fs, double *vdv,
                       tirenv_diag *diag);

/* The running r.m.s. of ISO 2631-1 6.3 (linear integration) at every sample j = 0..n-1:
 * out[j] = (sum of a_w^2 over the N = round(tau*fs) samples ending at j, / N)^(1/2), samples
 * before the start counting as zero (a meter at rest); out has n elements, tau is in s.
 * TIRENV_EINVAL as tirenv_comfort_vdv, or if tau*fs rounds to 0 samples; TIRENV_ERANGE as
 * tirenv_comfort_rms. */
int tirenv_comfort_running_rms(const double a_w[], size_t n, double fs, double tau,
                               double out[], tirenv_diag *diag);

/* MTVV = max_j of the running r.m.s. above (tau = TIRENV_COMFORT_TAU per the standard), without
 * storing it; errors as tirenv_comfort_running_rms. */
int tirenv_comfort_mtvv(const double a_w[], size_t n, double fs, double tau, double *mtvv,
                        tirenv_diag *diag);

/* All metrics of a weighted series sampled at fs (Hz); errors as tirenv_comfort_vdv. */
int tirenv_comfort_metrics_compute(const double a_w[], size_t n, double fs,
                                   tirenv_comfort_metrics *m, tirenv_diag *diag);

/* Weights an unweighted series a[] (m/s^2 or rad/s^2, at fs Hz) with w into a_w[] (n
 * elements, may equal a; the caller keeps it, e.g. to plot) and computes its metrics in *m.
 * Errors as tirenv_weighting_apply and tirenv_comfort_metrics_compute. */
int tirenv_comfort_evaluate(tirenv_weighting w, double fs, const double a[], double a_w[],
                            size_t n, tirenv_comfort_metrics *m, tirenv_diag *diag);

/* The vibration total value a_v = (sum_i (k_i a_w,i)^2)^(1/2) of n axes (m/s^2, ISO 2631-1
 * 6.5) into *a_v; TIRENV_EINVAL if n == 0 or a k_i or a_w,i is negative or not finite;
 * TIRENV_ERANGE if the sum of squares overflows. */
int tirenv_comfort_total_value(const double k[], const double a_w[], size_t n, double *a_v,
                               tirenv_diag *diag);

/* ---- Spectrum (src/ride/spectrum.c) ---- */

/* Workspace of Welch's estimate for segments of n_seg samples: the window and one buffer. */
typedef struct tirenv_welch tirenv_welch;

/* Allocates a workspace for segments of n_seg samples, a power of two >= 2. *out is NULL on
 * failure: TIRENV_EINVAL (n_seg) or TIRENV_ENOMEM. */
int tirenv_welch_alloc(size_t n_seg, tirenv_welch **out, tirenv_diag *diag);

/* Frees a workspace; NULL is a no-op. */
void tirenv_welch_free(tirenv_welch *w);

/* Number of one-sided bins, n_seg/2 + 1; bin k is at frequency k*fs/n_seg (Hz). */
size_t tirenv_welch_bins(const tirenv_welch *w);

/* One-sided PSD of x[0..n-1] sampled at fs (Hz) by Welch's method: Hann segments of n_seg
 * samples overlapping by half, no detrending, psd[k] (unit^2/Hz, tirenv_welch_bins values) the
 * average over the segments, so that sum_k psd[k] * fs/n_seg is the (Hann-weighted) mean square
 * of x. The number of segments in *segments (may be NULL); samples past the last whole segment
 * are not used. TIRENV_EINVAL if fs is not positive and finite, n < n_seg, or a sample is not
 * finite; TIRENV_ERANGE if a bin's power overflows (psd then holds no estimate). Never
 * allocates. */
int tirenv_welch_psd(tirenv_welch *w, const double x[], size_t n, double fs, double psd[],
                     size_t *segments, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
