/* Private to tirenv bench: its sections in their own files.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_CLI_BENCH_H
#define TIRENV_CLI_BENCH_H

#include "cli/cli.h"

/* The ride over the bench road (profile road, centre positions x[0..n-1] on a uniform grid)
 * with the default tractor, point / cam / nn (skipped if nn is NULL) / springs, printing the
 * real-time factor of each; best of repeat. */
int cli_bench_ride(const tirenv_tire *tire, const tirenv_profile *road, const tirenv_nn *nn,
                   size_t n, const double x[], long repeat, tirenv_diag *diag);

/* The CSV number formatter against snprintf's "%.9g" on 10^6 values, best of repeat: prints
 * both and their ratio, fails if a byte differs; the times per number in ns. */
int cli_bench_fmt(long repeat, double *ns_fmt, double *ns_printf);

#endif
