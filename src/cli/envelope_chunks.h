/* SPDX-License-Identifier: Apache-2.0 */
/* One sweep on several threads (tirenv envelope --jobs): the positions in chunks of a fixed
 * size, each chunk solved from a cold start at its first position, so that the points are the
 * same, bit for bit, whatever the number of threads. */
#ifndef TIRENV_CLI_ENVELOPE_CHUNKS_H
#define TIRENV_CLI_ENVELOPE_CHUNKS_H

#include "cli/cli.h"
#include "tirenv/stream.h"

/* Positions a chunk: the warm-start chain restarts from the model's cold state every
 * CLI_CHUNK positions (position k = x_from + k*dx starts a chain when k % CLI_CHUNK == 0), as
 * the stream's blocks do (tirenv/stream.h). */
enum { CLI_CHUNK = TIRENV_ENVELOPE_BLOCK };

typedef struct cli_chunks cli_chunks;

/* A sweep of n positions x_from + k*dx for the model m, already set on its tracks (its state
 * now is the cold state every chunk starts from), on up to jobs threads: jobs - 1 more models
 * of m's type and tire (with o's network) are set on the same tracks at the same load.
 * Prints nothing; returns a status with diag. */
int cli_chunks_open(tirenv_model *m, const tirenv_model_type *type, const cli_options *o,
                    size_t n_tracks, const tirenv_profile *const tracks[], double load,
                    double x_from, double dx, size_t n, size_t jobs, cli_chunks **out,
                    tirenv_diag *diag);

/* The chunks a call of cli_chunks_run computes at most: a round, jobs chunks per thread. */
size_t cli_chunks_round(const cli_chunks *c);

/* Computes the chunks [c0, c0 + n_c) (clipped to the sweep) into pt[] (their first position
 * at pt[0]), the chunks side by side; *n_out is how many points that is. If side is not NULL,
 * side(side_ctx, diag) runs once beside them, as the item before the first chunk (a writer of
 * the previous round's points, which must not touch pt). On failure, the failure of the
 * first item that failed (side, then the chunks by position), as the serial loop reports it. */
int cli_chunks_run(cli_chunks *c, size_t c0, size_t n_c, tirenv_point pt[], size_t *n_out,
                   int (*side)(void *side_ctx, tirenv_diag *diag), void *side_ctx,
                   tirenv_diag *diag);

/* cli_chunks_run with each chunk's own tracks: chunk c0 + i on windows[i * n_tracks ..] (the
 * n_tracks of cli_chunks_open), pieces of the tracks holding the ground within the model's
 * reach of the chunk's positions (a streamed road's: envelope_stream.h), on which a chunk's
 * model is set before it is restored to the cold state, and unset after. windows NULL is
 * cli_chunks_run. */
int cli_chunks_run_on(cli_chunks *c, size_t c0, size_t n_c,
                      const tirenv_profile *const windows[], tirenv_point pt[], size_t *n_out,
                      int (*side)(void *side_ctx, tirenv_diag *diag), void *side_ctx,
                      tirenv_diag *diag);

/* What the chunks' models had to say (tirenv_model_warnings after each chunk): the first
 * chunk's in position order that said anything, so the same whatever the threads; "" if
 * none. Valid until cli_chunks_free. */
const char *cli_chunks_warnings(const cli_chunks *c);

/* Frees the models it made (not m). NULL does nothing. */
void cli_chunks_free(cli_chunks *c);

#endif
