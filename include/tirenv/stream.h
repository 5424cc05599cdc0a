/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: the enveloping curve over a profile taken as it goes from a vertex source (a file
 * reader, a generator, a simulator's road), in memory bounded by the tire's reach rather than
 * by the road's length. */
#ifndef TIRENV_STREAM_H
#define TIRENV_STREAM_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/model.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

/* Where a streamed sweep gets its ground, one vertex at a time: the next vertex (m) in *x, *z
 * with *got = 1, or *got = 0 at the end of the profile. Vertices come in profile order (x
 * non-decreasing, at most two at one x: a wall); a nonzero return (a TIRENV_ code, with diag
 * filled) stops the sweep. A file format provides one (an OpenCRG track's,
 * tirenv_crg_track_reader_source in crg.h; every road format's rows of tracks come as a
 * tirenv_row_source, below, from tirenv_profile_file_reader_source in profile_file.h). */
typedef int (*tirenv_vertex_source)(void *ctx, double *x, double *z, int *got,
                                    tirenv_diag *diag);

/* The level segment's length for a tire (m): its free diameter 2*R0. Obstacles shorter than
 * it are what the tire envelopes, longer undulations, steps and grades ground it follows
 * (docs/models.md section 2.6). */
double tirenv_level_width(const tirenv_tire *tire);

/* The road's local level (tirenv_profile_level) along a sweep in x order, its vertices taken
 * from a source as the sweep needs them, the whole profile never held: a window of the
 * vertices within width (m) of x, rebuilt every few widths of travel, as tirenv_model_stream's
 * (a tirenv_road_window of one track). NULL when out of memory or source is NULL; _free(NULL)
 * is a no-op. _at gives the level (m) at x (m), x not below the last call's (TIRENV_EINVAL,
 * field "x", for one below it or not a number: the ground there is dropped); the source's
 * errors pass through, and its vertices are checked as tirenv_road_window_fill checks them. */
typedef struct tirenv_level_stream tirenv_level_stream;
tirenv_level_stream *tirenv_level_stream_alloc(tirenv_vertex_source source, void *ctx,
                                               double width);
void tirenv_level_stream_free(tirenv_level_stream *s);
int tirenv_level_stream_at(tirenv_level_stream *s, double x, double *level, tirenv_diag *diag);

/* Receives each position as it is computed; a nonzero return stops the sweep with that
 * status (use a TIRENV_ code, e.g. TIRENV_EIO). */
typedef int (*tirenv_point_sink)(void *ctx, const tirenv_point *pt);

/* What a streamed sweep did, for callers and tests of its memory bound. */
typedef struct {
    size_t positions;      /* positions passed to the sink */
    size_t vertices_read;  /* vertices taken from the source */
    size_t window_max;     /* most vertices held in the window at once */
    size_t rebuilds;       /* windows built */
} tirenv_stream_stats;

/* Most positions a sweep may have (1e12: a million kilometres at 1 mm; beyond it a sweep is
 * a mistake, and (double)k stays exact far past it). Callers cap lower for what they hold. */
#define TIRENV_POSITIONS_MAX 1e12

/* Number of positions x_k = x_from + k*dx (m, dx > 0, x_to >= x_from) up to x_to plus a
 * billionth of a step, so that 0 .. 1 at 0.1 gives 11 despite rounding: the sweeps of the CLI
 * and of tirenv_model_stream. Returns 0 (never a valid count) if an argument is not finite,
 * dx <= 0, x_to < x_from, the count would pass TIRENV_POSITIONS_MAX, or dx is too small to
 * move x at the ends (x + dx == x). Constant time. */
size_t tirenv_positions_count(double x_from, double x_to, double dx);

/* A sweep: the positions x_k = x_from + k*dx up to x_to, tirenv_positions_count of them. */
typedef struct {
    double x_from;         /* first position, m */
    double x_to;           /* last position, m (reached within a billionth of dx) */
    double dx;             /* spacing, m (> 0) */
} tirenv_positions;

/* tirenv envelope's sweep for a tire of free radius R0 (m) over ground whose vertices run
 * from x_first to x_last (m, tirenv_profile_extent): every 1 mm from R0 + 2 cm before
 * x_first to R0 + 2 cm after x_last. Edit the fields to sweep otherwise. */
tirenv_positions tirenv_positions_default(double x_first, double x_last, double R0);

/* Positions a warm-start chain runs before it starts again from the model's state right
 * after it was set: tirenv envelope's whole-mode chunks and the stream's blocks, so that the
 * two give the same bytes. */
enum { TIRENV_ENVELOPE_BLOCK = 8192 };

/* Evaluates the positions x_k = x_from + k*dx (m) up to x_to (m; as the CLI's sweep) at load
 * (N), taking vertices from source (called with source_ctx) only as far as the tire's reach
 * ahead needs, and passing each point to sink (called with ctx). Equals tirenv envelope's
 * whole mode over the whole profile bit for bit, iterations included: tirenv_model_set, then
 * the positions in blocks of TIRENV_ENVELOPE_BLOCK counted from x_from, each starting from the
 * model's state right after the set (several tracks: set again), the warm start carrying over
 * within a block as the window moves; the check that the hub clears the ground within reach
 * included (tirenv_model_eval), so any elevation and grade stream. A network's positions go
 * through tirenv_model_envelope a block at a time (a single cleat's slopes are one-sided at a
 * block's ends).
 * Vertices out of order, or not finite, stop it with TIRENV_EINVAL naming the vertex. stats
 * may be NULL. Takes the vertices from where the source stands. */
int tirenv_model_stream(tirenv_model *m, tirenv_vertex_source source, void *source_ctx,
                        double x_from, double x_to, double dx, double load,
                        tirenv_point_sink sink, void *ctx, tirenv_stream_stats *stats,
                        tirenv_diag *diag);

/* Where a streamed sweep over several tracks across the tire's width (tracks.h) gets its
 * ground: the next row, its x (m) in *x and the height (m) of each track there in z[n], with
 * *got = 1, or *got = 0 at the end. Rows come in profile order, as the vertices of a
 * tirenv_vertex_source; a nonzero return (a TIRENV_ code, with diag filled) stops the sweep. */
typedef int (*tirenv_row_source)(void *ctx, double *x, double z[], int *got,
                                 tirenv_diag *diag);

/* A road window: the rows of a row source read in order, holding those a moving stretch
 * [x_keep, x_need] (m) needs, from the last row before x_keep (both rows of a wall there) to
 * the first after x_need, so that each segment meeting the stretch lies whole in it, and the
 * models see what they see over the whole road; the rows behind go when its arrays fill (a
 * few hundred may stay), so memory is bounded by the stretch, not by the road.
 * tirenv_model_stream_tracks keeps one around the tire's reach; a caller sweeping stretches
 * of its own (several threads, each on its stretch) keeps one too. */
typedef struct tirenv_road_window tirenv_road_window;

/* An empty window on source (called with ctx), n_tracks >= 1 heights a row; reads nothing yet,
 * then from where the source stands. NULL when out of memory, source is NULL or n_tracks 0.
 * _free(NULL) is a no-op. */
tirenv_road_window *tirenv_road_window_alloc(tirenv_row_source source, void *ctx,
                                             size_t n_tracks);
void tirenv_road_window_free(tirenv_road_window *w);

/* Makes w cover [x_keep, x_need] (m; x_keep not below the last call's: rows dropped are not
 * read again): drops the rows before the last one left of x_keep, and reads until a row lies
 * beyond x_need or the source ends, dropping again whenever the arrays are full, so a far
 * x_keep costs no memory.
 * Each row is checked as it comes: x or a height not finite, x going back, or a third row at
 * one x stop it with TIRENV_EINVAL naming the vertex (its 1-based index in the source, as
 * diag's line); the source's errors pass through; TIRENV_ENOMEM; TIRENV_EINVAL for w NULL,
 * for x_keep below the last call's or not a number (field "x_keep"), and for x_need not a
 * number, the window left as it was. */
int tirenv_road_window_fill(tirenv_road_window *w, double x_keep, double x_need,
                            tirenv_diag *diag);

/* 1 if w holds a row beyond x (m) or the source has ended (so nothing more up to x will
 * come), else 0 (also for w NULL). */
int tirenv_road_window_covers(const tirenv_road_window *w, double x);

/* The rows held as one profile per track into p[n_tracks], each the caller's to
 * tirenv_profile_free. On failure (TIRENV_EINVAL with the offending vertex of the window, as
 * tirenv_profile_validate, e.g. no row; TIRENV_ENOMEM) the tracks made before stay in p for
 * the caller to free, the failing one's is NULL and those after it are left as they were;
 * TIRENV_EINVAL for w or p NULL. */
int tirenv_road_window_profiles(const tirenv_road_window *w, tirenv_profile *p[],
                                tirenv_diag *diag);

/* tirenv_model_stream over n >= 1 tracks with weights[n] (NULL: equal), as
 * tirenv_model_set_tracks: a window per track, combined by the type's rule. Equals
 * tirenv_model_set_tracks with the whole tracks (separate profiles) + tirenv_model_envelope
 * bit for bit, as tirenv_model_stream does for one; n = 1 is tirenv_model_stream. */
int tirenv_model_stream_tracks(tirenv_model *m, size_t n, const double weights[],
                               tirenv_row_source source, void *source_ctx, double x_from,
                               double x_to, double dx, double load, tirenv_point_sink sink,
                               void *ctx, tirenv_stream_stats *stats, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
