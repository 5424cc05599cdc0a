/* Private to the rig-log import (src/rig/rig_*.c and its tests): the
 * stages of tirenv_rig_import_samples and what they share. docs/models.md sections 1 and 5.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_RIG_IMPL_H
#define TIRENV_RIG_IMPL_H

#include <stddef.h>

#include "tirenv/curve.h"
#include "tirenv/error.h"
#include "tirenv/rig.h"

/* A raw log as read from CSV, with where each sample came from, for messages. */
typedef struct {
    size_t n;
    double *t;             /* s */
    double *x;             /* m */
    double *z;             /* m */
    size_t *line;          /* 1-based file line of sample i */
} tirenv_rig__log_file;

/* Reads a log "t_s,x_m,z_m" (blank and '#' lines skipped). Errors name file, line, column. */
int tirenv_rig__log_read(const char *path, tirenv_rig__log_file *log, tirenv_diag *diag);
void tirenv_rig__log_file_free(tirenv_rig__log_file *log);  /* NULL or empty: no-op */

/* The 1-based column of field 0, 1 or 2 (t, x, z) on a line of the log; 0 if unknown. */
size_t tirenv_rig__log_column(const char *path, size_t line, size_t field);

/* The samples once prepared: one per distinct time, x increasing, the cart moving towards +x
 * (a run the other way is mirrored, x -> -x: the obstacle is symmetric). */
typedef struct {
    size_t n;
    double *x;             /* m, in the log's frame (mirrored if reversed) */
    double *z;             /* m */
    size_t *index;         /* the caller's index of each sample, for messages */
} tirenv_rig__samples;

/* Where the passage is: the flat ground, the noise, the obstacle's axis of symmetry. */
typedef struct {
    double sigma;          /* estimated standard deviation of the z noise, m */
    double baseline;       /* flat-ground z, m */
    double centre;         /* obstacle centre, m, in the frame of tirenv_rig__samples */
    double x_a, x_b;       /* where the bump rises from and falls back to the flat level, m,
                              to a detection bin of width delta (m) */
    double delta;
} tirenv_rig__passage;

/* tirenv_rig_import_samples, also saying what it found (info may be NULL). On failure diag's
 * line is the 1-based index of the sample at fault (0 if none) and its field "t", "x" or "z",
 * so that a file reader can turn them into its own line and column. */
int tirenv_rig__import(size_t n, const double t[], const double x[], const double z[],
                       const tirenv_import_settings *s, tirenv_curve *out,
                       tirenv_import_info *info, tirenv_diag *diag);

/* Stage 2 (rig_passage.c): noise, flat baseline, bump and centre; TIRENV_EINVAL with the
 * reason when the samples do not hold a whole passage. x_0 (m, < 0) sets the bump's scale. */
int tirenv_rig__find_passage(const tirenv_rig__samples *s, double x_0,
                             tirenv_rig__passage *p, tirenv_diag *diag);

/* Stage 3 (rig_smooth.c): fold both halves onto the approach half, filter without shifting
 * and evaluate on the settings' x_N grid. Sets info's half_width, noise_se, target_se and
 * width_capped. */
int tirenv_rig__smooth(const tirenv_rig__samples *s, const tirenv_rig__passage *p,
                       const tirenv_import_settings *set, double x_0, tirenv_curve *out,
                       tirenv_import_info *info, tirenv_diag *diag);

/* Median of v[0..n-1] (n >= 1) using scratch[0..n-1]; v is left unchanged. */
double tirenv_rig__median(const double v[], size_t n, double scratch[]);

#endif
