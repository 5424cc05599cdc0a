/* tirenv: what every tirenv plot shares (the comparison figures of the study, the ride's):
 * one line style per model, so that a model keeps its colour from plot to plot, and gnuplot
 * run so that the images appear complete or not at all. Auxiliary layer.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_PLOT_H
#define TIRENV_PLOT_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"

TIRENV_BEGIN_DECLS

/* A line style in gnuplot's terms. */
typedef struct {
    const char *colour;    /* "#rrggbb" (static) */
    int dash;              /* gnuplot dashtype: 1 solid, 2 dashed, 4 dash-dot */
    double width;          /* line width */
} tirenv_plot_style;

/* The style of the model named model (a model type's name, tirenv_model_type_name) on every
 * tirenv plot; a name without a style of its own gets a spare colour chosen by the index i of
 * its line on the plot. */
tirenv_plot_style tirenv_plot_style_of(const char *model, size_t i);

/* Runs gnuplot (the program gnuplot, or "gnuplot" on PATH when NULL or "") in directory dir
 * on the script <base>.gp, setting its variables png_out and svg_out, so that <base>.png and
 * <base>.svg appear complete or not at all. base is a file name without a directory.
 * TIRENV_EIO says what gnuplot printed; a missing gnuplot is named as such. */
int tirenv_plot_draw(const char *dir, const char *base, const char *gnuplot,
                     tirenv_diag *diag);

TIRENV_END_DECLS
#endif
