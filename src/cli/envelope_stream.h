/* SPDX-License-Identifier: Apache-2.0 */
/* A streamed sweep on several threads (tirenv envelope --stream --jobs N): the road read once,
 * in order, as the chunks of whole mode (envelope_chunks.h) need it, each chunk computed on
 * the piece of road within the tire's reach of its positions, the points written in order. */
#ifndef TIRENV_CLI_ENVELOPE_STREAM_H
#define TIRENV_CLI_ENVELOPE_STREAM_H

#include "cli/cli.h"
#include "tirenv/stream.h"

/* The most road (m) a chunk of positions, CLI_CHUNK*dx, may span for --stream to run its
 * chunks on several threads: each round holds its chunks' road, so a sparser sweep (dx above
 * 256 m / 8192 = 31.25 mm) streams on one thread, whose window is the tire's reach (the same
 * points): memory bounded whatever dx, not the whole road in one chunk at --dx 10. */
#define CLI_STREAM_CHUNK_SPAN_M 256.0

/* tirenv_model_stream_tracks (tirenv/stream.h) over n_tracks tracks (equal weights) for the
 * model m of the given type (o as cli_chunks_open's), on up to jobs threads: the
 * positions x_from + k*dx up to x_to in the chunks of CLI_CHUNK positions of whole mode, each
 * from the cold state, so that the points, and the order they reach sink in, are
 * tirenv_model_stream_tracks's, bit for bit, for every jobs. Rows are taken from source only
 * on the caller's thread or one worker at a time, in order, a round of chunks ahead of the
 * computing (cli_chunks_round); sink is called in position order, one call at a time.
 * Memory: two rounds of chunk windows (each the rows from x_k0 - r to x_k1 + r, r the model's
 * reach) and of points, whatever the road's length. Not for a network (its windows are told
 * where they sit in the road: run it through tirenv_model_stream_tracks). On failure the
 * first in position order: a row the source refuses counts before the chunk it was read for.
 * warnings (warnings_size bytes, may be NULL) receives cli_chunks_warnings'. */
int cli_stream_chunks(tirenv_model *m, const tirenv_model_type *type, const cli_options *o,
                      size_t n_tracks, tirenv_row_source source, void *source_ctx,
                      double x_from, double x_to, double dx, double load, size_t jobs,
                      tirenv_point_sink sink, void *sink_ctx, char *warnings,
                      size_t warnings_size, tirenv_diag *diag);

#endif
