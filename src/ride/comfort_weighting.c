/* The frequency weightings of ISO 2631-1, analogue and digital (docs/models.md section 10).
 * SPDX-License-Identifier: Apache-2.0
 *
 * ISO 2631-1 Annex A (parameters repeated in ISO 8041's table) defines each weighting as the
 * product of four analogue factors, with omega_i = 2 pi f_i:
 *   band-limiting high-pass  H_h = s^2 / (s^2 + omega_1 s/Q_1 + omega_1^2)
 *   band-limiting low-pass   H_l = omega_2^2 / (s^2 + omega_2 s/Q_2 + omega_2^2)
 *   a-v transition           H_t = (1 + s/omega_3) / (1 + s/(Q_4 omega_4) + s^2/omega_4^2)
 *   upward step              H_s = (1 + s/(Q_5 omega_5) + s^2/omega_5^2)
 *                                  / (1 + s/(Q_6 omega_6) + s^2/omega_6^2) * (omega_5/omega_6)^2
 * with f_1 = 0.4 Hz, f_2 = 100 Hz, Q_1 = Q_2 = 1/sqrt(2) for all three weightings here; the
 * step, present in Wk only, rises from (f_5/f_6)^2 to 1; the factor (omega_5/omega_6)^2 makes
 * it (s^2 + omega_5 s/Q_5 + omega_5^2) / (s^2 + omega_6 s/Q_6 + omega_6^2), the form used.
 * At the nominal one-third-octave frequencies these products give the factors of Tables 3
 * and 4 within one unit of their last printed digit (tests/ride/test_comfort.c).
 *
 * The digital filter is the same product, factor by factor, through the bilinear transform
 * s = K (1 - z^-1)/(1 + z^-1). It maps the analogue frequency Omega to the digital omega by
 * Omega = K tan(omega/(2 fs)), and K = omega_p / tan(omega_p/(2 fs)) ("pre-warping") makes
 * the two agree at omega_p; each factor gets its own omega_p where its shape changes: f_1,
 * f_2, f_4, and for the step the geometric mean of f_5 and f_6 (one K for both corners keeps
 * its plateau (f_5/f_6)^2 exact; warping each corner on its own would shift it by 4e-5 at
 * 1 kHz). Every factor is then exact at DC, at its pre-warping frequency and wherever it is
 * flat. What is left is the compression of the frequency axis on the slopes. The largest is
 * the a-v transition's 1/f fall above f_4, which the transform lowers by about x/tan(x),
 * x = pi f/fs; the low-pass below its corner errs the other way, by less, and the high-pass
 * and step sit where x is tiny. Below 100 Hz the relative error of the cascade thus stays
 * within 1 - x/tan(x) (x taken at 1 Hz at least, for the high-pass), checked densely by the
 * tests. Above 100 Hz the low-pass's zero at fs/2 takes over: the filter is not meant to
 * reproduce the weighting there. */
#include "tirenv/comfort.h"

#include <complex.h>
#include <ctype.h>
#include <math.h>
#include <string.h>

/* The parameters of one weighting, Hz and dimensionless; f_5 = f_6 = INFINITY: no step. */
typedef struct {
    const char *name;
    double f3, f4, Q4;     /* a-v transition */
    double f5, Q5, f6, Q6; /* upward step */
} weighting_params;

static const double F1 = 0.4;      /* band-limiting high-pass corner, Hz */
static const double F2 = 100.0;    /* band-limiting low-pass corner, Hz */

static const weighting_params PARAMS[] = {
    [TIRENV_WK] = {"Wk", 12.5, 12.5, 0.63, 2.37, 0.91, 3.35, 0.91},
    [TIRENV_WD] = {"Wd", 2.0, 2.0, 0.63, INFINITY, 1.0, INFINITY, 1.0},
    [TIRENV_WE] = {"We", 1.0, 1.0, 0.63, INFINITY, 1.0, INFINITY, 1.0},
};
enum { N_WEIGHTINGS = sizeof PARAMS / sizeof PARAMS[0] };

static const weighting_params *params_of(tirenv_weighting w)
{
    return (unsigned)w < N_WEIGHTINGS ? &PARAMS[w] : NULL;
}

const char *tirenv_weighting_name(tirenv_weighting w)
{
    const weighting_params *p = params_of(w);
    return p ? p->name : NULL;
}

int tirenv_weighting_parse(const char *name, tirenv_weighting *w, tirenv_diag *diag)
{
    for (unsigned k = 0; name && k < N_WEIGHTINGS; k++) {
        const char *ref = PARAMS[k].name;
        if (strlen(name) == 2 && tolower((unsigned char)name[0]) == tolower(ref[0])
            && tolower((unsigned char)name[1]) == tolower(ref[1])) {
            *w = (tirenv_weighting)k;
            return TIRENV_OK;
        }
    }
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, "weighting",
                        "unknown frequency weighting '%s'; expected Wk, Wd or We",
                        name ? name : "(null)");
}

/* A second-order factor (n2 s^2 + n1 s + n0) / (s^2 + d1 s + d0) of the product above, and
 * the frequency f_p (Hz) at which its digital version is to match it. */
typedef struct {
    double n2, n1, n0, d1, d0;
    double f_p;
} analogue_factor;

/* The factors of p in order high-pass, low-pass, transition, step; returns how many. */
static size_t factors(const weighting_params *p, analogue_factor out[4])
{
    const double w1 = 2.0 * M_PI * F1, w2 = 2.0 * M_PI * F2;
    const double w3 = 2.0 * M_PI * p->f3, w4 = 2.0 * M_PI * p->f4;
    out[0] = (analogue_factor){1.0, 0.0, 0.0, M_SQRT2 * w1, w1 * w1, F1};
    out[1] = (analogue_factor){0.0, 0.0, w2 * w2, M_SQRT2 * w2, w2 * w2, F2};
    /* (1 + s/w3) / (1 + s/(Q4 w4) + s^2/w4^2), numerator and denominator times w4^2. */
    out[2] = (analogue_factor){0.0, w4 * w4 / w3, w4 * w4, w4 / p->Q4, w4 * w4, p->f4};
    if (!isfinite(p->f5))
        return 3;
    const double w5 = 2.0 * M_PI * p->f5, w6 = 2.0 * M_PI * p->f6;
    out[3] = (analogue_factor){1.0, w5 / p->Q5, w5 * w5, w6 / p->Q6, w6 * w6,
                               sqrt(p->f5 * p->f6)};
    return 4;
}

static double complex factor_at(const analogue_factor *a, double complex s)
{
    return ((a->n2 * s + a->n1) * s + a->n0) / ((s + a->d1) * s + a->d0);
}

int tirenv_weighting_response(tirenv_weighting w, double f, double *re, double *im)
{
    const weighting_params *p = params_of(w);
    if (!p || !isfinite(f))
        return TIRENV_EINVAL;
    analogue_factor a[4];
    const size_t n = factors(p, a);
    const double complex s = I * 2.0 * M_PI * f;
    double complex H = 1.0;
    for (size_t k = 0; k < n; k++)
        H *= factor_at(&a[k], s);
    *re = creal(H);
    *im = cimag(H);
    return TIRENV_OK;
}

double tirenv_weighting_gain(tirenv_weighting w, double f)
{
    double re, im;
    if (tirenv_weighting_response(w, f, &re, &im) != TIRENV_OK)
        return NAN;
    return hypot(re, im);
}

/* The bilinear transform of one factor, pre-warped at its f_p: with
 * s = K (1 - z^-1)/(1 + z^-1), multiplying through by (1 + z^-1)^2 turns c2 s^2 + c1 s + c0
 * into (c2 K^2 + c1 K + c0) + 2 (c0 - c2 K^2) z^-1 + (c2 K^2 - c1 K + c0) z^-2. */
static tirenv_biquad bilinear(const analogue_factor *a, double fs)
{
    const double K = 2.0 * M_PI * a->f_p / tan(M_PI * a->f_p / fs), K2 = K * K;
    const double A0 = K2 + a->d1 * K + a->d0;
    return (tirenv_biquad){
        .b0 = (a->n2 * K2 + a->n1 * K + a->n0) / A0,
        .b1 = 2.0 * (a->n0 - a->n2 * K2) / A0,
        .b2 = (a->n2 * K2 - a->n1 * K + a->n0) / A0,
        .a1 = 2.0 * (a->d0 - K2) / A0,
        .a2 = (K2 - a->d1 * K + a->d0) / A0,
    };
}

int tirenv_weighting_filter_init(tirenv_weighting_filter *flt, tirenv_weighting w, double fs,
                                 tirenv_diag *diag)
{
    const weighting_params *p = params_of(w);
    if (!p)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "weighting",
                            "unknown frequency weighting %d; expected TIRENV_WK, TIRENV_WD or "
                            "TIRENV_WE", (int)w);
    if (!(fs >= TIRENV_COMFORT_FS_MIN && fs <= TIRENV_COMFORT_FS_MAX))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "fs",
                            "sample rate %g Hz is outside %g to %g Hz for the %s weighting: "
                            "below, the digital filter cannot follow the weighting up to 80 Hz "
                            "(ISO 2631-1's band; it needs 4 samples per period), above, its "
                            "0.4 Hz high-pass loses precision; resample the series",
                            fs, TIRENV_COMFORT_FS_MIN, TIRENV_COMFORT_FS_MAX, p->name);
    analogue_factor a[4];
    const size_t n = factors(p, a);
    memset(flt, 0, sizeof *flt);
    flt->w = w;
    flt->fs = fs;
    flt->n = n;
    for (size_t k = 0; k < n; k++)
        flt->s[k] = bilinear(&a[k], fs);
    return TIRENV_OK;
}

void tirenv_weighting_filter_reset(tirenv_weighting_filter *flt)
{
    for (size_t k = 0; k < flt->n; k++)
        flt->s[k].s1 = flt->s[k].s2 = 0.0;
}

/* Transposed direct form II: its two states per section stay of the order of the signals,
 * whereas direct form II's internal signal x/A(z) is amplified about 1/(2 pi f_1/fs)^2 times at
 * the 0.4 Hz high-pass, whose poles lie near z = 1. */
double tirenv_weighting_filter_step(tirenv_weighting_filter *flt, double a)
{
    double x = a;
    for (size_t k = 0; k < flt->n; k++) {
        tirenv_biquad *q = &flt->s[k];
        const double y = q->b0 * x + q->s1;
        q->s1 = q->b1 * x - q->a1 * y + q->s2;
        q->s2 = q->b2 * x - q->a2 * y;
        x = y;
    }
    return x;
}

void tirenv_weighting_filter_run(tirenv_weighting_filter *flt, const double a[], double a_w[],
                                 size_t n)
{
    for (size_t j = 0; j < n; j++)
        a_w[j] = tirenv_weighting_filter_step(flt, a[j]);
}

void tirenv_weighting_filter_response(const tirenv_weighting_filter *flt, double f, double *re,
                                      double *im)
{
    const double complex z1 = cexp(-I * 2.0 * M_PI * f / flt->fs); /* z^-1 */
    double complex H = 1.0;
    for (size_t k = 0; k < flt->n; k++) {
        const tirenv_biquad *q = &flt->s[k];
        H *= (q->b0 + (q->b1 + q->b2 * z1) * z1) / (1.0 + (q->a1 + q->a2 * z1) * z1);
    }
    *re = creal(H);
    *im = cimag(H);
}

double tirenv_weighting_filter_gain(const tirenv_weighting_filter *flt, double f)
{
    double re, im;
    tirenv_weighting_filter_response(flt, f, &re, &im);
    return hypot(re, im);
}

int tirenv_weighting_apply(tirenv_weighting w, double fs, const double a[], double a_w[],
                           size_t n, tirenv_diag *diag)
{
    tirenv_weighting_filter flt;
    const int status = tirenv_weighting_filter_init(&flt, w, fs, diag);
    if (status)
        return status;
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "n",
                            "empty series: nothing to weight");
    tirenv_weighting_filter_run(&flt, a, a_w, n);
    return TIRENV_OK;
}
