/* tirenv_model_stream: the enveloping curve over a profile file of any length, holding only
 * the vertices within the tire's reach of the current position.
 *
 * Every model reads the ground only within tirenv_model_reach = r of the centre's x. The
 * window holds the vertices from the last one before x - r to the first one after
 * x + r + ahead, so each segment that meets [x - r, x + r] lies whole in it, and the model
 * sees the same segments as over the whole profile; where the window starts at the file's
 * first vertex or ends at its last, its flat extension is the whole profile's. With
 * ahead = 2r a window serves about 2r of travel before it is rebuilt, so the rebuilding
 * (an allocation of the window's few hundred vertices) costs O(1) per position amortised, and
 * the memory is O(r / vertex spacing), whatever the road's length. The window is a
 * tirenv_road_window (road_window.c), which checks each vertex as it comes; the CLI's parallel
 * stream keeps one too. The vertices come from a callback (tirenv_vertex_source), so the core
 * knows no file format: the CSV reader is one source, in the auxiliary layer. Several tracks
 * across the tire's width (tracks.h) come as rows, one x and a height per track
 * (tirenv_row_source), and the window makes a profile per track.
 * A model whose results depend on where a window sits in the road as well (the network: its
 * decomposition's grid is anchored at the road's first vertex, docs/models.md section 12.1)
 * is told before each set (tirenv_model__stream_window), and evaluates through its batch
 * path in blocks (stream_block).
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/stream.h"
#include "tirenv/tracks.h"

#include "model/model_impl.h"
#include "model/road_window_impl.h"

#include <math.h>
#include <stdlib.h>

/* Tells the model where the window it is about to be set with sits in the file. */
static void window_tell(tirenv_model *m, const tirenv_road_window *w)
{
    if (!m)
        return;
    const tirenv_nn_road_window where = {.x_first = w->x_first, .bof = w->bof, .eof = w->eof};
    tirenv_model__stream_window(m, &where);
}

static void profiles_free(tirenv_profile *p[], size_t n)
{
    for (size_t k = 0; k < n; ++k) {
        tirenv_profile_free(p[k]);
        p[k] = NULL;
    }
}

enum { stream_block = TIRENV_ENVELOPE_BLOCK };

typedef struct {
    int on;
    double *x;             /* [stream_block], m */
    tirenv_point *pt;      /* [stream_block] */
} batch;

static int batch_alloc(batch *b, tirenv_diag *diag)
{
    b->x = malloc(stream_block * sizeof *b->x);
    b->pt = malloc(stream_block * sizeof *b->pt);
    if (!b->x || !b->pt)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    return TIRENV_OK;
}

/* A sink's nonzero status, said in diag: the sink has none of its own to fill, and the
 * caller's diag would otherwise keep whatever an earlier call left in it. */
static int sink_stopped(int status, size_t k, double x, tirenv_diag *diag)
{
    return tirenv_error(diag, status, "", 0, "sink",
                        "the point sink stopped the sweep at position %zu (x = %.9g m) with "
                        "status %d (%s)", k, x, status, tirenv_strerror(status));
}

int tirenv_model_stream_tracks(tirenv_model *m, size_t n_tracks, const double weights[],
                               tirenv_row_source source, void *source_ctx, double x_from,
                               double x_to, double dx, double load, tirenv_point_sink sink,
                               void *ctx, tirenv_stream_stats *stats, tirenv_diag *diag)
{
    if (stats)
        *stats = (tirenv_stream_stats){0};
    if (n_tracks == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tracks", "expected at least one track");
    if (!(isfinite(x_from) && isfinite(x_to) && dx > 0 && isfinite(dx) && x_to >= x_from))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "expected dx > 0 and x_to >= x_from, got dx %g m from %g to %g m",
                            dx, x_from, x_to);
    if (tirenv_positions_count(x_from, x_to, dx) == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "%.3g positions from %g to %g m every %g m; expected at most %.0e "
                            "and a step that moves x (x + dx != x)",
                            floor((x_to - x_from) / dx) + 1, x_from, x_to, dx,
                            TIRENV_POSITIONS_MAX);
    tirenv_road_window *w = tirenv_road_window_alloc(source, source_ctx, n_tracks);
    /* The window's profiles, the next ones being built, and the same as const for the model. */
    tirenv_profile **p = calloc(3 * n_tracks, sizeof *p);
    tirenv_profile **next = p ? p + n_tracks : NULL;
    const tirenv_profile **use = p ? (const tirenv_profile **)(p + 2 * n_tracks) : NULL;
    if (!p || !w) {
        free(p);
        tirenv_road_window_free(w);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    size_t rebuilds = 0, done = 0;
    /* One vertex is enough to set the load and find z_flat; only then is the reach at that
     * load known (the cam's tandem base depends on it), and the window is read to fit it. */
    int status = tirenv_road_window_fill(w, -INFINITY, -INFINITY, diag);
    if (!status && !(status = tirenv_road_window_profiles(w, p, diag))) {
        for (size_t k = 0; k < n_tracks; ++k)
            use[k] = p[k];
        window_tell(m, w);
        status = tirenv_model_set_tracks(m, n_tracks, use, weights, load, diag);
    }
    const double r = tirenv_model_reach(m), ahead = 2 * r;
    const size_t n = status ? 0 : tirenv_positions_count(x_from, x_to, dx);
    /* A network's positions go through its batch path (tirenv_model_envelope), in blocks
     * that start where the CLI's whole-mode chunks start (stream_block), so that a single
     * cleat's one-sided slopes at a block's ends fall where they fall there. */
    batch b = {0};
    if (!status && m->type->network && !(status = batch_alloc(&b, diag)))
        b.on = 1;
    /* Any other model starts each block as tirenv envelope's whole mode starts a chunk: from
     * the state it had right after it was set (one track), or set again (several), so that
     * its warm starts, and with them the iterations, are the same at every position. */
    const size_t cold_size = !status && !b.on && n_tracks == 1 ? tirenv_model_state_size(m) : 0;
    void *cold = cold_size ? malloc(cold_size) : NULL;
    if (cold_size && !cold)
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    else if (cold)
        status = tirenv_model_state_save(m, cold, cold_size, diag);
    int have_window = 0;
    for (size_t k = 0; k < n && !status;) {
        const double x = x_from + (double)k * dx;
        if (!have_window || !tirenv_road_window_covers(w, x + r)) {
            if ((status = tirenv_road_window_fill(w, x - r, x + r + ahead, diag)) ||
                (status = tirenv_road_window_profiles(w, next, diag)))
                break;
            for (size_t j = 0; j < n_tracks; ++j)
                use[j] = next[j];
            window_tell(m, w);
            if ((status = tirenv_model_set_track_profiles(m, n_tracks, use, diag)))
                break;
            profiles_free(p, n_tracks);
            for (size_t j = 0; j < n_tracks; ++j) {
                p[j] = next[j];
                next[j] = NULL;
            }
            have_window = 1;
            ++rebuilds;
        }
        if (b.on) {
            /* The block's positions this window serves: the first always. */
            const size_t block_end = (k / stream_block + 1) * stream_block;
            const size_t end = n < block_end ? n : block_end;
            size_t nb = 1;
            b.x[0] = x;
            for (; k + nb < end; ++nb) {
                const double x_k = x_from + (double)(k + nb) * dx;
                if (!tirenv_road_window_covers(w, x_k + r))
                    break;
                b.x[nb] = x_k;
            }
            if ((status = tirenv_model_envelope(m, nb, b.x, b.pt, NULL, diag)))
                break;
            for (size_t j = 0; j < nb && !status; ++j)
                if (!(status = sink(ctx, &b.pt[j])))
                    ++done;
                else
                    status = sink_stopped(status, done, b.pt[j].x, diag);
            k += nb;
            continue;
        }
        if (k > 0 && k % stream_block == 0 &&
            (status = n_tracks == 1 ? tirenv_model_state_restore(m, cold, cold_size, diag)
                                    : tirenv_model_set_tracks(m, n_tracks, use, weights, load,
                                                              diag)))
            break;
        tirenv_point pt;
        if ((status = tirenv_model_eval(m, x, &pt, diag)))
            break;
        if ((status = sink(ctx, &pt))) {
            status = sink_stopped(status, done, x, diag);
            break;
        }
        ++done;
        ++k;
    }
    free(b.x);
    free(b.pt);
    free(cold);
    if (stats)
        *stats = (tirenv_stream_stats){.positions = done, .vertices_read = w->read,
                                       .window_max = w->max, .rebuilds = rebuilds};
    /* The model must not keep pointing at a freed window: it is left unset, and takes whole
     * profiles again. */
    if (p[0] && m)
        tirenv_model_set_profile(m, NULL, NULL);
    if (m)
        tirenv_model__stream_window(m, NULL);
    profiles_free(next, n_tracks);
    profiles_free(p, n_tracks);
    free(p);
    tirenv_road_window_free(w);
    return status;
}

/* One track: the vertex source read as rows of one height. */
typedef struct {
    tirenv_vertex_source next;
    void *ctx;
} one_track;

static int one_track_row(void *ctx, double *x, double z[], int *got, tirenv_diag *diag)
{
    const one_track *o = ctx;
    return o->next(o->ctx, x, &z[0], got, diag);
}

int tirenv_model_stream(tirenv_model *m, tirenv_vertex_source source, void *source_ctx,
                        double x_from, double x_to, double dx, double load,
                        tirenv_point_sink sink, void *ctx, tirenv_stream_stats *stats,
                        tirenv_diag *diag)
{
    one_track o = {source, source_ctx};
    return tirenv_model_stream_tracks(m, 1, NULL, one_track_row, &o, x_from, x_to, dx, load,
                                      sink, ctx, stats, diag);
}
