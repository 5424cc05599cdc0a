/* tirenv envelope --plot (envelope_plot.c). SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_ENVELOPE_PLOT_H
#define TIRENV_CLI_ENVELOPE_PLOT_H

#include "tirenv/error.h"
#include "tirenv/profile.h"

/* Draws the curve in csv (the CSV file envelope wrote) of the model named model over road
 * from x_from to x_to (m) into file (FILE.png: FILE.png and FILE.svg, beside them FILE.gp,
 * the gnuplot script, and FILE-road.dat, the road it draws), under title. Each file complete
 * or not at all. */
/* Before any work: file names a file in a directory this process can write into. */
int cli_envelope_plot_check(const char *file, tirenv_diag *diag);

int cli_envelope_plot(const char *file, const char *csv, const char *model, const char *title,
                      const tirenv_profile *road, double x_from, double x_to, tirenv_diag *diag);

#endif
