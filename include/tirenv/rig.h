/* tirenv: rig logs (t, x, z of the tire centre) to enveloping curves, and the virtual rig
 * (MODEL.md section 5; the paper's Figure 2). */
#ifndef TIRENV_RIG_H
#define TIRENV_RIG_H

#include <stddef.h>
#include "tirenv/curve.h"
#include "tirenv/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What the import needs to know about the run, and the output grid. */
typedef struct {
    double L;              /* obstacle length, m */
    double H;              /* obstacle height, m */
    double R0;             /* tire free radius, m */
    double contact_length; /* working regime l_c, m (fixes the x_N origin) */
    double xN_from;        /* output grid start (may be negative: early rise), default -0.25 */
    double xN_to;          /* output grid end, default 1 */
    double dxN;            /* output grid step, default 0.0125 */
    double smooth;         /* smoothing half-width, m; 0 = chosen from the estimated noise */
} tirenv_import_settings;

/* Defaults for the grid and smoothing; L, H, R0, contact_length are NaN (must be set). */
tirenv_import_settings tirenv_import_default(void);

/* Imports a raw log from samples (any order, any rate, either direction, repeated or missing
 * samples, constant offsets, noise): removes the flat baseline, locates the obstacle, maps to
 * obstacle coordinates and x_N, keeps the approach half, filters without shifting, resamples.
 * TIRENV_EINVAL with a reason if the log does not hold a whole passage over the obstacle. */
int tirenv_rig_import_samples(size_t n, const double t[], const double x[], const double z[],
                              const tirenv_import_settings *s, tirenv_curve *out,
                              tirenv_diag *diag);

/* The same from a CSV log "t_s,x_m,z_m"; errors name file, line and column. */
int tirenv_rig_import(const char *path, const tirenv_import_settings *s, tirenv_curve *out,
                      tirenv_diag *diag);

#ifdef __cplusplus
}
#endif
#endif
