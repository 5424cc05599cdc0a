/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: rig logs (t, x, z of the tire centre) to enveloping curves, and the virtual rig
 * (docs/models.md section 5; the paper's Figure 2). */
#ifndef TIRENV_RIG_H
#define TIRENV_RIG_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/curve.h"
#include "tirenv/error.h"
#include "tirenv/model.h"

TIRENV_BEGIN_DECLS

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

/* The points of the output grid, x_N = xN_from + k*dxN up to xN_to (with a 1e-9 step's
 * allowance for round-off): what an imported curve holds; 0 if more than a million. */
size_t tirenv_import_grid_points(const tirenv_import_settings *s);

/* Imports a raw log from samples (any order, any rate, either direction, repeated or missing
 * samples, constant offsets, noise): removes the flat baseline, locates the obstacle, maps to
 * obstacle coordinates and x_N, keeps the approach half, filters without shifting, resamples.
 * TIRENV_EINVAL with a reason if the log does not hold a whole passage over the obstacle. */
int tirenv_rig_import_samples(size_t n, const double t[], const double x[], const double z[],
                              const tirenv_import_settings *s, tirenv_curve *out,
                              tirenv_diag *diag);

/* The same from a CSV log "t_s,x_m,z_m"; errors name file, line and column; TIRENV_EINVAL for
 * a NULL or empty path. */
int tirenv_rig_import(const char *path, const tirenv_import_settings *s, tirenv_curve *out,
                      tirenv_diag *diag);

/* Everything an import found, for a summary line (tirenv import's) and for tests. */
typedef struct {
    size_t n_samples;      /* distinct samples used */
    size_t n_repeated;     /* samples dropped because their time repeats an earlier one */
    int reversed;          /* 1 if the cart moved towards -x */
    double sigma;          /* estimated z noise, m */
    double baseline;       /* flat-ground z of the log, m */
    double centre;         /* obstacle centre in the log's own x, m */
    double x_0;            /* x_N origin in obstacle coordinates (docs/models.md section 1), m */
    double half_width;     /* smoothing half-width used, m */
    double noise_se;       /* standard error of h that the noise leaves after smoothing, m */
    double target_se;      /* the standard error the automatic half-width aims at, m */
    int width_capped;      /* 1: the automatic half-width stopped at its cap, which keeps the
                              curve's shape (docs/models.md section 5.7), short of what the
                              noise or the sampling asked for: noise_se may exceed target_se */
} tirenv_import_info;

/* tirenv_rig_import, also saying what it found in *info (may be NULL). */
int tirenv_rig_import_file(const char *path, const tirenv_import_settings *s,
                           tirenv_curve *out, tirenv_import_info *info, tirenv_diag *diag);

/* The virtual rig (paper, Figure 2): a cart moves the tire at constant speed over the
 * profile at constant load; x(t), z(t) of the centre are sampled with sensor noise. */
typedef struct {
    double speed;          /* cart speed, m/s (default 0.1: quasi-static) */
    double rate;           /* sampling rate, Hz (default 100) */
    double noise_x;        /* sensor noise sigma on x, m (default 5e-5) */
    double noise_z;        /* sensor noise sigma on z, m (default 2e-4) */
    double x_offset;       /* rig x reading at the profile's x = 0, m (default 0) */
    double z_offset;       /* rig z reading with the centre at z = 0, m (default 0) */
    double run_up;         /* flat ground before first and after last reach, m (default 0.3) */
    unsigned long seed;    /* noise seed (default 1) */
} tirenv_rig_settings;

tirenv_rig_settings tirenv_rig_default(void);

/* A raw log: n samples of time (s) and centre position (m), owned arrays. */
typedef struct {
    size_t n;
    double *t, *x, *z;
} tirenv_rig_log;

void tirenv_rig_log_free(tirenv_rig_log *log);  /* frees the arrays, zeroes log */

/* Runs the rig over the profile with model m, whose profile and load the caller has set with
 * tirenv_model_set (the model decides how the tire deforms: the data set uses "ring").
 * TIRENV_EINVAL naming the setting and its value for a bad one, or for m, p or s NULL. */
int tirenv_rig_simulate(tirenv_model *m, const tirenv_profile *p, const tirenv_rig_settings *s,
                        tirenv_rig_log *out, tirenv_diag *diag);

/* The model's own curve on the x_N grid of s (L, H, R0, contact_length set; xN_from, xN_to,
 * dxN as tirenv_import_default gives them or as wanted), the obstacle centred at x = 0: h at
 * x = x_0 (1 - x_N), x_0 the x_N origin (tirenv_xN_origin). It is what the import of a
 * noiseless, densely sampled log of the model approaches, for a model whose profile and load
 * the caller has set with tirenv_model_set. TIRENV_ERANGE where the cleat's corner is out of
 * reach (no origin), TIRENV_EINVAL for a grid of no point or more than a million; a model's
 * failure as the model reports it. */
int tirenv_rig_model_curve(tirenv_model *m, const tirenv_import_settings *s, tirenv_curve *out,
                           tirenv_diag *diag);

/* Writes a log as CSV "t_s,x_m,z_m" (the header, then '#' comment lines if comment is not NULL;
 * comment may hold several lines separated by '\n'), atomically. */
int tirenv_rig_write_log(const char *path, const tirenv_rig_log *log, const char *comment,
                         tirenv_diag *diag);

TIRENV_END_DECLS
#endif
