/* Private to the study module: one comparison plot per case, in the manner of the paper's
 * Figure 5 (h in mm over x_N, measured points, one line per model), written as a data file and
 * a gnuplot script, and drawn as PNG and SVG by running gnuplot on it.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_STUDY_PLOT_H
#define TIRENV_STUDY_PLOT_H

#include <stddef.h>

#include "tirenv/dataset.h"
#include "tirenv/error.h"

/* One model's curve on the plot. */
typedef struct {
    const char *name;      /* model name ("springs"): data column and line style */
    const char *label;     /* legend text */
    const double *h;       /* the case's curve.n heights, m; NaN where the model failed */
    const char *failure;   /* why the model has no curve on this case, or NULL */
} tirenv_plot__series;

/* How to draw. */
typedef struct {
    const char *dir;       /* output directory (must exist) */
    int simulated;         /* 1: the measured curve is simulated: said in title and files */
    const char *simulated_by; /* the reference model's name, or NULL */
    const char *gnuplot;   /* program to run; NULL: "gnuplot" on PATH */
    int raw;               /* 1: simulated_by's own curves, not through the virtual rig */
} tirenv_plot__settings;

/* The file base of a case's plot files: its name with every character outside
 * [A-Za-z0-9._-] replaced by '_' (case names come from a user's manifest). */
void tirenv_plot__base(const char *case_name, char *base, size_t size);

/* Writes <dir>/<base>.dat and <dir>/<base>.gp, each all or nothing. TIRENV_EIO names the
 * file. */
int tirenv_plot__case(const tirenv_plot__settings *ps, const tirenv_case *c, size_t n_series,
                      const tirenv_plot__series series[], tirenv_diag *diag);

/* Runs gnuplot on <dir>/<base>.gp so that <base>.png and <base>.svg appear complete or not at
 * all. TIRENV_EIO says what gnuplot printed; a missing gnuplot is named as such. */
int tirenv_plot__draw(const tirenv_plot__settings *ps, const char *case_name,
                      tirenv_diag *diag);

/* Runs "gnuplot -e 'png_out=...; svg_out=...' script" with dir as working directory (the
 * variables are what the script writes to), capturing its output for the message.
 * TIRENV_EIO if it cannot be started or exits non-zero. */
int tirenv_plot__run(const char *gnuplot, const char *dir, const char *script,
                     const char *assignments, tirenv_diag *diag);

#endif
