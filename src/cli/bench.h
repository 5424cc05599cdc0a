/* Private to tirenv bench: its sections in their own files.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_BENCH_H
#define TIRENV_CLI_BENCH_H

#include "cli/cli.h"

/* What tirenv bench reports: the human table (cli_bench_say, printf-like; silent with --json)
 * and every figure by name (cli_bench_figure: one number each, printed as one JSON object
 * with --json). */
void cli_bench_say(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
void cli_bench_figure(const char *name, double value);

/* The median of v[0 .. n - 1] (n >= 1), which it sorts: the bench's ratios over rounds. */
double cli_bench_median(double v[], size_t n);

/* The directory for the bench's scratch files: $TMPDIR where set (its road files can be
 * hundreds of MB, more than a small /tmp holds), else /tmp. */
const char *cli_bench_tmpdir(void);

/* The ride over the bench road (profile road, centre positions x[0..n-1] on a uniform grid)
 * with the default tractor, point / cam / nn (skipped if nn is NULL) / springs, printing the
 * real-time factor of each; best of repeat. */
int cli_bench_ride(const tirenv_tire *tire, const tirenv_profile *road, const tirenv_nn *nn,
                   size_t n, const double x[], long repeat, tirenv_diag *diag);

/* The CSV number formatter against snprintf's "%.9g" on 10^6 values, best of repeat: the
 * time of each per number (figures csv_fmt_ns, csv_snprintf_ns) and their ratio
 * (csv_fmt_speedup); fails if a byte differs. */
int cli_bench_fmt(long repeat);

/* The cam and the springs model (and nn if not NULL) over the road at contact length l_c (m),
 * position by position, at a fixed load and with tirenv_model_set_load before every position,
 * interleaved, best of repeat: the microseconds of a step of each and their ratio. */
int cli_bench_set_load(const tirenv_tire *tire, const tirenv_profile *road, const tirenv_nn *nn,
                       double l_c, size_t n, const double x[], long repeat, tirenv_diag *diag);

/* tirenv envelope's chunked sweep (envelope_chunks.h) of the springs model over the road at
 * contact length l_c (m), n positions from x_from every dx (m), on 1 and on 2 threads, over
 * 2 repeat + 1 interleaved rounds: the best wall times (envelope_jobs1_s, envelope_jobs2_s),
 * the median of the rounds' ratios (envelope_jobs2_over_jobs1; the best times' ratio
 * envelope_jobs2_over_jobs1_best, the rounds envelope_jobs_rounds) and whether the points
 * are the same bits (envelope_jobs_identical; fails if not); then the same sweep streamed from
 * the road's vertices (tirenv envelope --stream), --jobs 1 and 2 interleaved:
 * envelope_stream_jobs1_s, envelope_stream_jobs2_s, envelope_stream_jobs2_over_jobs1 and
 * envelope_stream_identical (both whole mode's points; fails if not). */
int cli_bench_jobs(const tirenv_tire *tire, const tirenv_profile *road, double l_c,
                   double x_from, double dx, size_t n, long repeat, tirenv_diag *diag);

/* tirenv envelope --model cam in whole mode (contact length 0.33 m, the tire file tire_path,
 * without --set; tire gives its radius for the count of positions) over a class C road of
 * length m at 1 mm (seed 1), into a CSV file, run as a child process of this program after
 * tirenv road has written the road to a scratch directory (removed after, or by a signal):
 * its peak resident set (envelope_whole_peak_mb, 10^6 bytes), wall time (envelope_whole_s),
 * the road's length (envelope_whole_road_m) and positions (envelope_whole_positions); then
 * --stream --jobs 1 over the road converted to RDF (envelope_stream_rdf_peak_mb, _s), and
 * --stream --jobs 2 (envelope_stream_rdf_jobs2_peak_mb, _s). */
int cli_bench_memory(const char *tire_path, const tirenv_tire *tire, double length,
                     tirenv_diag *diag);

/* The same figures from a fresh process, tirenv bench --memory --json (--quick where quick),
 * run as a child and its figures taken as this bench's: the kernel counts the resident set
 * of the process a child is forked from in the child's peak, which a bench that has run its
 * timings would add. */
int cli_bench_memory_fresh(const char *tire_path, int quick, tirenv_diag *diag);

#endif
