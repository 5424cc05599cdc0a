/* Rig logs to enveloping curves (docs/models.md section 5): the settings, stage 1 (put the samples
 * in order: one per time, x increasing) and the driver that runs the stages
 *   1. prepare (here): sort by time, drop repeated times, mirror a run towards -x;
 *   2. tirenv_rig__find_passage (rig_passage.c): noise, flat baseline, bump, centre;
 *   3. tirenv_rig__smooth (rig_smooth.c): fold, zero-phase filter, resample on x_N.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rig/rig_impl.h"
#include "io/io.h"

/* Below this there cannot be flat ground on both sides of a bump and a bump to fit; the
 * real limits (flat samples on each side, samples per smoothing window) are checked later,
 * with their own reasons. */
enum { RIG_MIN_SAMPLES = 50 };

/* The output grid of the paper's Figure 5: from before first contact (a real tire whose patch
 * is shorter than the chord rises early, docs/models.md section 1) to the centre, 101 points. */
tirenv_import_settings tirenv_import_default(void)
{
    return (tirenv_import_settings){
        .L = NAN,
        .H = NAN,
        .R0 = NAN,
        .contact_length = NAN,
        .xN_from = -0.25,
        .xN_to = 1.0,
        .dxN = 0.0125,
        .smooth = 0.0,
    };
}

/* The x_N origin x_0 doubles as the check that the geometry is possible. */
static int settings_check(const tirenv_import_settings *s, double *x_0, tirenv_diag *diag)
{
    if (!s)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no import settings given");
    if (!(s->L > 0 && isfinite(s->L)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "L",
                            "obstacle length must be a positive length in m, got %g", s->L);
    if (!(s->H > 0 && isfinite(s->H)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "H",
                            "obstacle height must be a positive length in m, got %g", s->H);
    if (!(s->R0 > 0 && isfinite(s->R0)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "R0",
                            "tire radius must be a positive length in m, got %g", s->R0);
    if (!(s->contact_length > 0 && s->contact_length < 2 * s->R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact_length",
                            "must lie in (0, 2*R0) = (0, %g) m, got %g", 2 * s->R0,
                            s->contact_length);
    if (!isfinite(s->xN_from) || !isfinite(s->xN_to) || !(s->xN_to > s->xN_from))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "xN_to",
                            "the x_N grid must run from a finite start to a larger finite end, "
                            "got %g to %g", s->xN_from, s->xN_to);
    if (!(s->dxN > 0 && isfinite(s->dxN)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dxN",
                            "the x_N grid step must be positive, got %g", s->dxN);
    if (!(s->smooth >= 0 && isfinite(s->smooth)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "smooth",
                            "the smoothing half-width must be 0 (automatic) or a positive "
                            "length in m, got %g", s->smooth);
    *x_0 = tirenv_xN_origin(s->R0, s->contact_length, s->L, s->H);
    if (!(*x_0 < 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "H",
                            "a free tire of radius %g m at the chord height of contact length "
                            "%g m cannot reach the top corner of a %g m high obstacle",
                            s->R0, s->contact_length, s->H);
    return TIRENV_OK;
}

/* ---- stage 1: put the samples in order --------------------------------------------------- */

typedef struct {
    double t, x, z;
    size_t index;          /* caller's index: the tie-break that makes qsort stable */
} rig_sample;

static int by_time(const void *a, const void *b)
{
    const rig_sample *p = a, *q = b;
    if (p->t != q->t)
        return p->t < q->t ? -1 : 1;
    return p->index < q->index ? -1 : p->index > q->index;
}

static int by_position(const void *a, const void *b)
{
    const rig_sample *p = a, *q = b;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    return p->t < q->t ? -1 : p->t > q->t;
}

static int is_sorted(const rig_sample r[], size_t n, int (*cmp)(const void *, const void *))
{
    for (size_t i = 1; i < n; i++)
        if (cmp(&r[i - 1], &r[i]) > 0)
            return 0;
    return 1;
}

static int check_finite(size_t n, const double t[], const double x[], const double z[],
                        tirenv_diag *diag)
{
    const double *const v[3] = {t, x, z};
    static const char *const name[3] = {"t", "x", "z"};
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < 3; k++)
            if (!isfinite(v[k][i]))
                return tirenv_error(diag, TIRENV_EINVAL, "", i + 1, name[k],
                                    "sample %zu: expected a finite number, got %g", i + 1,
                                    v[k][i]);
    return TIRENV_OK;
}

static int too_few_samples(size_t n, tirenv_diag *diag)
{
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, "t",
                        "fewer than %d samples: the log has %zu distinct times; a passage "
                        "needs flat ground, the bump and flat ground again",
                        RIG_MIN_SAMPLES, n);
}

/* A logger that writes one sample twice gives two rows with the same time; the first one
 * (in the caller's order) is kept, so the result does not depend on how the sort breaks
 * ties. Returns the number kept. */
static size_t drop_repeated_times(rig_sample r[], size_t n)
{
    size_t kept = n ? 1 : 0;
    for (size_t i = 1; i < n; i++)
        if (r[i].t != r[kept - 1].t)
            r[kept++] = r[i];
    return kept;
}

/* The direction of travel is that of the whole run (first to last sample in time), which
 * noise on x cannot reverse. A run towards -x is mirrored: the obstacle is symmetric. */
static int mirror_if_reversed(rig_sample r[], size_t n, int *reversed, tirenv_diag *diag)
{
    const double run = r[n - 1].x - r[0].x;
    if (run == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", r[n - 1].index + 1, "x",
                            "the cart did not move: x is %g m at the start and at the end of "
                            "the log", r[0].x);
    *reversed = run < 0;
    if (*reversed)
        for (size_t i = 0; i < n; i++)
            r[i].x = -r[i].x;
    return TIRENV_OK;
}

/* Time order decides repeats and direction; the later stages work along x. A log already in
 * order (the usual case) costs one pass. The records live only as long as this stage, so
 * the next stages' scratch arrays can reuse their memory. */
static int prepare_samples(size_t n, const double t[], const double x[], const double z[],
                           tirenv_rig__samples *s, tirenv_import_info *info, tirenv_diag *diag)
{
    rig_sample *r = malloc(n * sizeof *r);
    if (!r)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for %zu samples", n);
    for (size_t i = 0; i < n; i++)
        r[i] = (rig_sample){t[i], x[i], z[i], i};
    if (!is_sorted(r, n, by_time))
        qsort(r, n, sizeof *r, by_time);
    const size_t kept = drop_repeated_times(r, n);
    info->n_repeated = n - kept;
    info->n_samples = kept;
    int status = kept < RIG_MIN_SAMPLES ? too_few_samples(kept, diag)
                                        : mirror_if_reversed(r, kept, &info->reversed, diag);
    if (status == TIRENV_OK) {
        if (!is_sorted(r, kept, by_position))
            qsort(r, kept, sizeof *r, by_position);
        s->n = kept;
        for (size_t i = 0; i < kept; i++) {
            s->x[i] = r[i].x;
            s->z[i] = r[i].z;
            s->index[i] = r[i].index;
        }
    }
    free(r);
    return status;
}

/* ---- the result against the obstacle and the tire ---------------------------------------- */

/* A tire of free radius R0 touches no ground farther than R0 from its centre (5 % more for a
 * tread standing out, docs/models.md section 1.5), so the bump cannot begin before the centre
 * is that close to the obstacle's edge: L/2 + 1.05 R0 from its centre, to a detection bin. And
 * the centre rises over the obstacle at most by H plus the tire's deflection, which is less
 * than R0: h <= H + R0. A log in other units than metres breaks one or the other (z in mm put
 * the peak of a 0.1 m cleat at 98.7 m; x in mm stretches the bump a thousandfold), as does a
 * wrong obstacle or tire: refused with the reason rather than imported. */
static const double REACH_FACTOR = 1.05;

/* Under its constant load the centre rises over the cleat at most by H: ground nowhere above
 * the cleat's top lifts it no higher than level ground raised by H would, to z_flat + H (h
 * = H where the tire stands on a cleat longer than its patch). The imported peak exceeds H
 * only by the smoothing's noise, a few noise_se, and the bias at the curve's kinks (under 0.5
 * mm, docs/models.md section 5.7): the embedded data sets' 56 curves by at most 0.09 mm. A
 * peak beyond HEIGHT_FACTOR*H + NOISE_SES*noise_se is a log over a higher obstacle than
 * --cleat says (a 0.10 m cleat's log imported as 0.05 m gave a 90 mm peak over it). */
static const double HEIGHT_FACTOR = 1.1, NOISE_SES = 6;

static int plausible(const tirenv_import_settings *set, const tirenv_rig__passage *p,
                     const tirenv_curve *c, const tirenv_import_info *found, tirenv_diag *diag)
{
    const double reach = 0.5 * set->L + REACH_FACTOR * set->R0 + p->delta;
    const double before = p->centre - p->x_a, after = p->x_b - p->centre;
    if (before > reach || after > reach)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x",
                            "the bump rises %.4g m before the obstacle's centre and falls back "
                            "%.4g m after it, but a tire of free radius %g m touches a %g m "
                            "long obstacle only within %.4g m of its centre (L/2 + %.2f R0): "
                            "x is not in metres, or the obstacle or the tire is not the one "
                            "logged", before, after, set->R0, set->L, reach, REACH_FACTOR);
    double peak = -INFINITY;
    size_t at = 0;
    for (size_t k = 0; k < c->n; ++k)
        if (c->h[k] > peak) {
            peak = c->h[k];
            at = k;
        }
    if (peak > set->H + set->R0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "z",
                            "the curve peaks at h = %.4g m (x_N = %.4g), but over a %g m high "
                            "obstacle a tire of free radius %g m rises at most H + R0 = %.4g m "
                            "(H plus its deflection): z is not in metres, or the obstacle or the "
                            "tire is not the one logged", peak, c->x_N[at], set->H, set->R0,
                            set->H + set->R0);
    const double top = HEIGHT_FACTOR * set->H + NOISE_SES * found->noise_se;
    if (peak > top)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "z",
                            "the curve peaks at h = %.4g m (x_N = %.4g), above the %g m high "
                            "obstacle, which lifts a tire at constant load by at most H (%.4g m "
                            "allowed for %.0f %% and the smoothing's noise): the obstacle logged "
                            "is higher than the one given", peak, c->x_N[at], set->H, top,
                            100 * (HEIGHT_FACTOR - 1));
    return TIRENV_OK;
}

/* ---- the driver --------------------------------------------------------------------------- */

int tirenv_rig__import(size_t n, const double t[], const double x[], const double z[],
                       const tirenv_import_settings *set, tirenv_curve *out,
                       tirenv_import_info *info, tirenv_diag *diag)
{
    *out = (tirenv_curve){0};
    tirenv_import_info found = {0};
    double x_0 = NAN;
    int status = settings_check(set, &x_0, diag);
    if (status == TIRENV_OK)
        status = check_finite(n, t, x, z, diag);
    if (status == TIRENV_OK && n < RIG_MIN_SAMPLES)
        status = too_few_samples(n, diag);
    if (status != TIRENV_OK)
        return status;
    /* The prepared samples, which every stage reads. */
    double *xz = malloc(2 * n * sizeof *xz);
    size_t *index = malloc(n * sizeof *index);
    tirenv_rig__samples s = {0, xz, xz + n, index};
    tirenv_rig__passage p;
    if (!xz || !index)
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for %zu samples", n);
    if (status == TIRENV_OK)
        status = prepare_samples(n, t, x, z, &s, &found, diag);
    if (status == TIRENV_OK)
        status = tirenv_rig__find_passage(&s, x_0, &p, diag);
    if (status == TIRENV_OK)
        status = tirenv_rig__smooth(&s, &p, set, x_0, out, &found, diag);
    if (status == TIRENV_OK && (status = plausible(set, &p, out, &found, diag)))
        tirenv_curve_free(out);
    if (status == TIRENV_OK) {
        found.sigma = p.sigma;
        found.baseline = p.baseline;
        found.centre = found.reversed ? -p.centre : p.centre;
        found.x_0 = x_0;
    }
    free(xz);
    free(index);
    if (info)
        *info = found;
    return status;
}

int tirenv_rig_import_samples(size_t n, const double t[], const double x[], const double z[],
                              const tirenv_import_settings *s, tirenv_curve *out,
                              tirenv_diag *diag)
{
    return tirenv_rig__import(n, t, x, z, s, out, NULL, diag);
}

/* The stages speak of sample indices and the arrays "t", "x", "z"; a reader of the file wants
 * its line, column and header name. */
static void diag_to_file(tirenv_diag *diag, const char *path,
                         const tirenv_rig__log_file *log)
{
    if (!diag)
        return;
    static const char *const array[3] = {"t", "x", "z"};
    static const char *const column[3] = {"t_s", "x_m", "z_m"};
    const size_t i = diag->line;
    diag->line = 0;
    diag->column = 0;
    for (size_t k = 0; k < 3; k++) {
        if (strcmp(diag->field, array[k]) != 0)
            continue;
        snprintf(diag->field, sizeof diag->field, "%s", column[k]);
        if (i >= 1 && i <= log->n) {
            diag->line = log->line[i - 1];
            diag->column = tirenv_rig__log_column(path, diag->line, k);
        }
    }
    if (!diag->file[0])
        snprintf(diag->file, sizeof diag->file, "%s", path);
}

int tirenv_rig_import_file(const char *path, const tirenv_import_settings *s,
                           tirenv_curve *out, tirenv_import_info *info, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = (tirenv_curve){0};
    if (info)
        *info = (tirenv_import_info){0};
    /* Settings first: their errors are not the file's. */
    double x_0 = NAN;
    int status = settings_check(s, &x_0, diag);
    if (status != TIRENV_OK)
        return status;
    if (!path || !path[0])  /* fopen(NULL) would say EIO "Bad address" */
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no log file named");
    tirenv_rig__log_file log;
    status = tirenv_rig__log_read(path, &log, diag);
    if (status != TIRENV_OK)
        return status;
    status = tirenv_rig__import(log.n, log.t, log.x, log.z, s, out, info, diag);
    if (status != TIRENV_OK)
        diag_to_file(diag, path, &log);
    tirenv_rig__log_file_free(&log);
    return status;
}

int tirenv_rig_import(const char *path, const tirenv_import_settings *s, tirenv_curve *out,
                      tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_rig_import_file(path, s, out, NULL, diag);
}
