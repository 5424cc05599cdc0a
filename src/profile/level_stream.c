/* SPDX-License-Identifier: Apache-2.0 */
/* The road's local level along a sweep (tirenv_level_stream, stream.h): the opening of
 * docs/models.md section 2.6 over a window of the ground taken from a vertex source as the
 * sweep moves, so that a road read as it goes has its level without being held whole. */
#include <math.h>
#include <stdlib.h>

#include "tirenv/profile.h"
#include "tirenv/stream.h"
#include "tirenv/tire.h"

#include "model/road_window_impl.h"

/* Obstacles shorter than the tire's diameter are what it envelopes; longer undulations, steps
 * and grades are ground it follows (docs/models.md section 2.6). */
double tirenv_level_width(const tirenv_tire *tire)
{
    return 2 * tire->springs.R0;
}

/* The window is the streams' road window (road_window.c) on one track: it reads and checks
 * the vertices as they come and drops what falls behind. */
struct tirenv_level_stream {
    tirenv_road_window *w;
    double width;          /* m */
    tirenv_profile *p;     /* the window as a profile, NULL until built */
    double x_last;         /* the last position asked for, m (-INFINITY before any) */
};

tirenv_level_stream *tirenv_level_stream_alloc(tirenv_vertex_source source, void *ctx,
                                               double width)
{
    tirenv_level_stream *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    *s = (tirenv_level_stream){.w = tirenv_road_window_alloc(source, ctx, 1), .width = width,
                               .x_last = -INFINITY};
    if (!s->w) {
        free(s);
        return NULL;
    }
    return s;
}

void tirenv_level_stream_free(tirenv_level_stream *s)
{
    if (!s)
        return;
    tirenv_road_window_free(s->w);
    tirenv_profile_free(s->p);
    free(s);
}

/* The level at x reads the ground over [x - width, x + width] and the segments reaching into
 * it: the window must hold the last vertex before x - width (or the source's first) and the
 * first after x + width (or its last). */
static int covers(const tirenv_level_stream *s, double x)
{
    const tirenv_road_window *w = s->w;
    return s->p && w->n > 0 && (w->bof || w->x[0] < x - s->width) &&
           (w->eof || w->x[w->n - 1] > x + s->width);
}

/* Drops what falls behind, reads up to 3 widths ahead, and rebuilds the profile. */
static int refill(tirenv_level_stream *s, double x, tirenv_diag *diag)
{
    const int status = tirenv_road_window_fill(s->w, x - s->width, x + 3 * s->width, diag);
    if (status)
        return status;
    if (s->w->n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "profile", "the profile has no vertex");
    tirenv_profile_free(s->p);
    s->p = NULL;
    return tirenv_road_window_profiles(s->w, &s->p, diag);
}

int tirenv_level_stream_at(tirenv_level_stream *s, double x, double *level, tirenv_diag *diag)
{
    /* Behind the last position the window has dropped the ground. */
    if (!(x >= s->x_last))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x",
                            "the level at x = %g m after one at %g m: expected positions in "
                            "x order", x, s->x_last);
    s->x_last = x;
    if (!covers(s, x)) {
        const int status = refill(s, x, diag);
        if (status)
            return status;
    }
    *level = tirenv_profile_level(s->p, s->width, x);
    return TIRENV_OK;
}
