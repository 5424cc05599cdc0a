/* Metrics of a frequency-weighted acceleration by ISO 2631-1 clause 6 (docs/models.md
 * section 10).
 * SPDX-License-Identifier: Apache-2.0
 *
 * For samples a_j = a_w(j/fs), j = 0..n-1, of a weighted acceleration over T = n/fs:
 *   r.m.s.        a_w  = (1/T int_0^T a_w^2 dt)^(1/2)  ~ (sum a_j^2 / n)^(1/2)       (6.1)
 *   crest factor  CF   = max |a_j| / a_w                                               (6.2)
 *   running r.m.s.     a_w(t_0) = (1/tau int_(t_0 - tau)^(t_0) a_w^2 dt)^(1/2)
 *   MTVV               = max over t_0 of a_w(t_0), tau = 1 s                           (6.3)
 *   VDV                = (int_0^T a_w^4 dt)^(1/4)  ~ (sum a_j^4 / fs)^(1/4)            (6.3)
 *   total value   a_v  = (sum_i (k_i a_w,i)^2)^(1/2) over axes i                       (6.5)
 * The integrals are rectangle sums, which equal the trapezoid rule's when the series starts
 * and ends at rest. The running r.m.s. is the standard's linear integration over the last
 * N = round(tau fs) samples, divided by N even while fewer have arrived: a meter switched on
 * at t = 0 has seen zeros before, as the weighting filter, started at rest, has. */
#include "tirenv/comfort.h"

#include <math.h>

/* TIRENV_EINVAL for an empty series or a sample that is not finite (line = its 1-based
 * index), so that one NaN cannot silently become every metric. */
static int check_samples(const double a_w[], size_t n, tirenv_diag *diag)
{
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "n",
                            "empty series: a metric needs at least one sample");
    for (size_t j = 0; j < n; j++)
        if (!isfinite(a_w[j]))
            return tirenv_error(diag, TIRENV_EINVAL, "", j + 1, "a_w",
                                "sample %zu is %g; expected a finite acceleration", j + 1,
                                a_w[j]);
    return TIRENV_OK;
}

/* TIRENV_ERANGE for a sum of powers of the samples that overflowed: an r.m.s. or VDV of inf,
 * and a running r.m.s. of NaN that fmax passed over (the MTVV of samples of 1e200 came out as
 * 0.0086), returned as if computed. */
static int overflowed(const double a_w[], size_t n, const char *what, tirenv_diag *diag)
{
    double peak = 0.0;
    for (size_t j = 0; j < n; j++)
        peak = fmax(peak, fabs(a_w[j]));
    return tirenv_error(diag, TIRENV_ERANGE, "", 0, "a_w",
                        "the %s of values up to %g overflows a double; expected "
                        "accelerations whose powers it holds", what, peak);
}

static int check_fs(double fs, tirenv_diag *diag)
{
    if (!(fs > 0 && isfinite(fs)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "fs",
                            "sample rate must be positive and finite in Hz, got %g", fs);
    return TIRENV_OK;
}

int tirenv_comfort_rms(const double a_w[], size_t n, double *rms, tirenv_diag *diag)
{
    const int status = check_samples(a_w, n, diag);
    if (status)
        return status;
    double sum = 0.0;
    for (size_t j = 0; j < n; j++)
        sum += a_w[j] * a_w[j];
    if (isinf(sum))
        return overflowed(a_w, n, "r.m.s.", diag);
    *rms = sqrt(sum / (double)n);
    return TIRENV_OK;
}

int tirenv_comfort_peak(const double a_w[], size_t n, double *peak, tirenv_diag *diag)
{
    const int status = check_samples(a_w, n, diag);
    if (status)
        return status;
    double m = 0.0;
    for (size_t j = 0; j < n; j++)
        m = fmax(m, fabs(a_w[j]));
    *peak = m;
    return TIRENV_OK;
}

int tirenv_comfort_vdv(const double a_w[], size_t n, double fs, double *vdv,
                       tirenv_diag *diag)
{
    int status = check_fs(fs, diag);
    if (!status)
        status = check_samples(a_w, n, diag);
    if (status)
        return status;
    double sum = 0.0;
    for (size_t j = 0; j < n; j++) {
        const double a2 = a_w[j] * a_w[j];
        sum += a2 * a2;
    }
    if (!isfinite(sum / fs))
        return overflowed(a_w, n, "vibration dose value", diag);
    *vdv = pow(sum / fs, 0.25);
    return TIRENV_OK;
}

/* The window of the running r.m.s., N = round(tau fs) samples, as a count for the division
 * (N_div) and for indexing (N, capped at n + 1: a window longer than the series never drops a
 * sample, and the cap keeps huge tau*fs out of size_t). */
static int window(size_t n, double fs, double tau, double *N_div, size_t *N, tirenv_diag *diag)
{
    int status = check_fs(fs, diag);
    if (status)
        return status;
    if (!(tau > 0 && isfinite(tau)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tau",
                            "integration time must be positive and finite in s, got %g", tau);
    const double Nd = round(tau * fs);
    if (!(Nd >= 1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tau",
                            "integration time %g s holds no sample at %g Hz; expected at "
                            "least 1/fs = %g s", tau, fs, 1.0 / fs);
    *N_div = Nd;
    *N = Nd > (double)n ? n + 1 : (size_t)Nd;
    return TIRENV_OK;
}

/* Neumaier's compensated summation: adds x to the sum *s with the running correction *c. */
static void add(double *s, double *c, double x)
{
    const double t = *s + x;
    *c += fabs(*s) >= fabs(x) ? (*s - t) + x : (x - t) + *s;
    *s = t;
}

/* The running r.m.s. at every sample into out (if not NULL) and its maximum into *max. The
 * window's sum of squares is updated by adding the newest and dropping the oldest square.
 * After a shock, the plain sum would keep the rounding error of the large squares it once
 * held, about 1e-16 of them, in the sum of the small ones that follow (1e-4 relative for a
 * shock 1e3 times the later signal); the compensated sum keeps it at 1e-16 of the current
 * sum, and summing afresh every N samples stops the corrections' own errors from growing
 * with the length of the series. */
static int running(const double a_w[], size_t n, double N_div, size_t N, double out[],
                   double *max)
{
    double sum = 0.0, c = 0.0, m = 0.0;
    for (size_t j = 0; j < n; j++) {
        if (j % N == 0) {
            sum = c = 0.0;
            for (size_t i = j >= N - 1 ? j - (N - 1) : 0; i <= j; i++)
                add(&sum, &c, a_w[i] * a_w[i]);
        } else {
            add(&sum, &c, a_w[j] * a_w[j]);
            if (j >= N)
                add(&sum, &c, -a_w[j - N] * a_w[j - N]);
        }
        if (!isfinite(sum + c))
            return TIRENV_ERANGE;
        const double r = sqrt(fmax(sum + c, 0.0) / N_div);
        if (out)
            out[j] = r;
        m = fmax(m, r);
    }
    *max = m;
    return TIRENV_OK;
}

/* The checks both public entries need, then the running r.m.s. */
static int checked_running(const double a_w[], size_t n, double fs, double tau, double out[],
                           double *max, tirenv_diag *diag)
{
    double N_div = 1.0;
    size_t N = 1;
    int status = window(n, fs, tau, &N_div, &N, diag);
    if (!status)
        status = check_samples(a_w, n, diag);
    if (!status && running(a_w, n, N_div, N, out, max))
        status = overflowed(a_w, n, "running r.m.s.", diag);
    return status;
}

int tirenv_comfort_running_rms(const double a_w[], size_t n, double fs, double tau,
                               double out[], tirenv_diag *diag)
{
    double max;
    return checked_running(a_w, n, fs, tau, out, &max, diag);
}

int tirenv_comfort_mtvv(const double a_w[], size_t n, double fs, double tau, double *mtvv,
                        tirenv_diag *diag)
{
    return checked_running(a_w, n, fs, tau, NULL, mtvv, diag);
}

int tirenv_comfort_metrics_compute(const double a_w[], size_t n, double fs,
                                   tirenv_comfort_metrics *m, tirenv_diag *diag)
{
    int status = tirenv_comfort_vdv(a_w, n, fs, &m->vdv, diag);
    if (!status)
        status = tirenv_comfort_rms(a_w, n, &m->rms, diag);
    if (!status)
        status = tirenv_comfort_peak(a_w, n, &m->peak, diag);
    if (!status)
        status = tirenv_comfort_mtvv(a_w, n, fs, TIRENV_COMFORT_TAU, &m->mtvv, diag);
    if (status)
        return status;
    m->duration = (double)n / fs;
    m->crest = m->rms > 0 ? m->peak / m->rms : NAN;
    return TIRENV_OK;
}

int tirenv_comfort_evaluate(tirenv_weighting w, double fs, const double a[], double a_w[],
                            size_t n, tirenv_comfort_metrics *m, tirenv_diag *diag)
{
    const int status = tirenv_weighting_apply(w, fs, a, a_w, n, diag);
    if (status)
        return status;
    return tirenv_comfort_metrics_compute(a_w, n, fs, m, diag);
}

int tirenv_comfort_total_value(const double k[], const double a_w[], size_t n, double *a_v,
                               tirenv_diag *diag)
{
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "n",
                            "no axis: the total value needs at least one");
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        if (!(k[i] >= 0 && isfinite(k[i])))
            return tirenv_error(diag, TIRENV_EINVAL, "", i + 1, "k",
                                "factor of axis %zu is %g; expected zero or positive", i + 1,
                                k[i]);
        if (!(a_w[i] >= 0 && isfinite(a_w[i])))
            return tirenv_error(diag, TIRENV_EINVAL, "", i + 1, "a_w",
                                "r.m.s. of axis %zu is %g; expected zero or positive", i + 1,
                                a_w[i]);
        sum += (k[i] * a_w[i]) * (k[i] * a_w[i]);
    }
    if (isinf(sum))
        return overflowed(a_w, n, "total value", diag);
    *a_v = sqrt(sum);
    return TIRENV_OK;
}
