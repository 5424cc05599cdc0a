/* SPDX-License-Identifier: Apache-2.0 */
/* A streamed sweep on several threads (envelope_stream.h).
 *
 * tirenv_model_stream_tracks restarts its warm-start chain from the model's cold state every
 * CLI_CHUNK positions, as whole mode's chunks do, so a chunk's points depend on nothing but
 * the ground within the model's reach r of its positions: a chunk can be computed anywhere,
 * at any time, on a window of the road from the last row before x_k0 - r to the first row
 * after x_k1 + r (its first and last positions), and the points are the same bytes. The
 * serial stream's windows rest on the same fact (stream.c): a segment that meets
 * [x - r, x + r] lies whole in the window, and where the window starts at the road's first
 * row or ends at its last, its flat extension is the road's.
 *
 * The road is read once, in order: a round of chunks' windows (cli_chunks_round) ahead of the
 * round being computed, by one work item beside the chunks, which also passes the previous
 * round's points to the sink (the writer of whole mode's rounds). So at most two rounds of
 * windows and of points are held, and the reading and writing take a worker's time, not a
 * pause between rounds. Consecutive windows overlap by some 2r: the rows a window shares with
 * the next stay in the reader's window (tirenv_road_window_fill drops only what falls behind
 * the next chunk's reach). The window checks each row as it comes (x and heights finite, x
 * not going back, at most two rows at one x), as the serial stream's does, so both refuse an
 * unchecked source's rows with the same messages. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/envelope_chunks.h"
#include "cli/envelope_stream.h"
#include "tirenv/tracks.h"

static int no_memory(tirenv_diag *diag)
{
    return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
}

/* The sweep under way. */
typedef struct {
    tirenv_road_window *in;  /* the rows read and not yet behind every chunk to come */
    size_t tracks;
    double x_from, dx, r;  /* m; r the model's reach */
    size_t n, n_chunks;    /* positions, chunks */
    size_t round;          /* chunks a round */
    tirenv_profile **win[2];  /* a round's windows, [round * tracks] each */
    /* the reader's work for the next round: its chunks and where their windows go */
    size_t read_c0;
    int read_b;
    int read_status;       /* a failure of the reading, reported after the round's chunks */
    tirenv_diag read_diag;
    /* the writer's: the points computed and not yet passed on */
    const tirenv_point *pt;
    size_t pending;
    tirenv_point_sink sink;
    void *sink_ctx;
} sweep;

static void windows_free(tirenv_profile **w, size_t n)
{
    for (size_t k = 0; w && k < n; ++k) {
        tirenv_profile_free(w[k]);
        w[k] = NULL;
    }
}

/* The windows of the chunks [c0, c0 + round) into win[b], those of the round before freed. */
static int read_round(sweep *s, size_t c0, int b, tirenv_diag *diag)
{
    windows_free(s->win[b], s->round * s->tracks);
    int status = TIRENV_OK;
    for (size_t i = 0; i < s->round && c0 + i < s->n_chunks && !status; ++i) {
        const size_t k0 = (c0 + i) * CLI_CHUNK;
        const size_t k1 = (k0 + CLI_CHUNK < s->n ? k0 + CLI_CHUNK : s->n) - 1;
        const double x0 = s->x_from + (double)k0 * s->dx, x1 = s->x_from + (double)k1 * s->dx;
        if (!(status = tirenv_road_window_fill(s->in, x0 - s->r, x1 + s->r, diag)))
            status = tirenv_road_window_profiles(s->in, s->win[b] + i * s->tracks, diag);
    }
    return status;
}

/* The work item beside a round's chunks: the previous round's points to the sink (a failure
 * there is the first in position order), then the next round's windows (a failure there
 * comes after this round's chunks: kept for then). */
static int beside(void *ctx, tirenv_diag *diag)
{
    sweep *s = ctx;
    (void)diag;  /* the sink fills none (its caller knows why), the reader read_diag */
    for (size_t k = 0; k < s->pending; ++k) {
        const int status = s->sink(s->sink_ctx, &s->pt[k]);
        if (status)
            return status;
    }
    s->pending = 0;
    if (s->read_c0 < s->n_chunks)
        s->read_status = read_round(s, s->read_c0, s->read_b, &s->read_diag);
    return TIRENV_OK;
}

int cli_stream_chunks(tirenv_model *m, const tirenv_model_type *type, const cli_options *o,
                      size_t n_tracks, tirenv_row_source source, void *source_ctx,
                      double x_from, double x_to, double dx, double load, size_t jobs,
                      tirenv_point_sink sink, void *sink_ctx, char *warnings,
                      size_t warnings_size, tirenv_diag *diag)
{
    const size_t n = tirenv_positions_count(x_from, x_to, dx);
    if (n_tracks == 0 || n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "expected at least one track and one position, got %zu and %zu",
                            n_tracks, n);
    sweep s = {.in = tirenv_road_window_alloc(source, source_ctx, n_tracks),
               .tracks = n_tracks, .x_from = x_from, .dx = dx, .n = n,
               .n_chunks = n / CLI_CHUNK + (n % CLI_CHUNK != 0), .sink = sink,
               .sink_ctx = sink_ctx};
    tirenv_diag_clear(&s.read_diag);
    tirenv_profile **first = calloc(n_tracks, sizeof *first);
    cli_chunks *c = NULL;
    tirenv_point *pt[2] = {NULL, NULL};
    int status = s.in && first ? TIRENV_OK : no_memory(diag);
    /* One row is enough to set the load and find z_flat; only then is the reach at that load
     * known (the cam's tandem base depends on it), as in tirenv_model_stream_tracks, whose
     * cold state this is too. */
    if (!status && !(status = tirenv_road_window_fill(s.in, -INFINITY, -INFINITY, diag)) &&
        !(status = tirenv_road_window_profiles(s.in, first, diag)))
        status = tirenv_model_set_tracks(m, n_tracks, (const tirenv_profile *const *)first,
                                         NULL, load, diag);
    if (!status) {
        s.r = tirenv_model_reach(m);
        status = cli_chunks_open(m, type, o, n_tracks, (const tirenv_profile *const *)first,
                                 load, x_from, dx, n, jobs, &c, diag);
    }
    if (!status) {
        s.round = cli_chunks_round(c);
        const size_t cap = s.round * CLI_CHUNK < n ? s.round * CLI_CHUNK : n;
        for (int b = 0; b < 2 && !status; ++b)
            if (!(pt[b] = malloc(cap * sizeof *pt[b])) ||
                !(s.win[b] = calloc(s.round * n_tracks, sizeof *s.win[b])))
                status = no_memory(diag);
    }
    if (!status)
        status = read_round(&s, 0, 0, diag);
    /* Round i computes its chunks on win[b] into pt[b], while beside them the points of
     * round i - 1 (in pt[b ^ 1]) go to the sink and the windows of round i + 1 are read into
     * win[b ^ 1]. */
    for (size_t c0 = 0, b = 0; c0 < s.n_chunks && !status; c0 += s.round, b ^= 1) {
        s.read_c0 = c0 + s.round;
        s.read_b = (int)(b ^ 1);
        size_t n_k = 0;
        status = cli_chunks_run_on(c, c0, s.round, (const tirenv_profile *const *)s.win[b],
                                   pt[b], &n_k, beside, &s, diag);
        if (!status && s.read_status) {
            status = s.read_status;
            *diag = s.read_diag;
        }
        s.pt = pt[b];
        s.pending = n_k;
    }
    s.read_c0 = s.n_chunks;  /* the last round's points, nothing more to read */
    if (!status)
        status = beside(&s, diag);
    /* The caller's model points at none of these profiles once they are freed. */
    tirenv_model_set_profile(m, NULL, NULL);
    if (warnings && warnings_size)
        snprintf(warnings, warnings_size, "%s", c ? cli_chunks_warnings(c) : "");
    cli_chunks_free(c);
    for (int b = 0; b < 2; ++b) {
        windows_free(s.win[b], s.round * n_tracks);
        free(s.win[b]);
        free(pt[b]);
    }
    windows_free(first, n_tracks);
    free(first);
    tirenv_road_window_free(s.in);
    return status;
}
