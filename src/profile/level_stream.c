/* SPDX-License-Identifier: Apache-2.0 */
/* The road's local level along a sweep (tirenv_level_stream, stream.h): the opening of
 * docs/models.md section 2.6 over a window of the ground taken from a vertex source as the
 * sweep moves, so that a road read as it goes has its level without being held whole. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/profile.h"
#include "tirenv/stream.h"
#include "tirenv/tire.h"

/* Obstacles shorter than the tire's diameter are what it envelopes; longer undulations, steps
 * and grades are ground it follows (docs/models.md section 2.6). */
double tirenv_level_width(const tirenv_tire *tire)
{
    return 2 * tire->springs.R0;
}

struct tirenv_level_stream {
    tirenv_vertex_source next;
    void *ctx;
    double width;          /* m */
    double *x, *z;         /* the window's vertices, m */
    size_t n, cap;
    int bof, eof;          /* the window starts at the source's first vertex; it is read out */
    tirenv_profile *p;     /* the window as a profile, NULL until built */
};

tirenv_level_stream *tirenv_level_stream_alloc(tirenv_vertex_source source, void *ctx,
                                               double width)
{
    tirenv_level_stream *s = calloc(1, sizeof *s);
    if (s)
        *s = (tirenv_level_stream){.next = source, .ctx = ctx, .width = width, .bof = 1};
    return s;
}

void tirenv_level_stream_free(tirenv_level_stream *s)
{
    if (!s)
        return;
    free(s->x);
    free(s->z);
    tirenv_profile_free(s->p);
    free(s);
}

/* The level at x reads the ground over [x - width, x + width] and the segments reaching into
 * it: the window must hold the last vertex before x - width (or the source's first) and the
 * first after x + width (or its last). */
static int covers(const tirenv_level_stream *s, double x)
{
    return s->p && s->n > 0 && (s->bof || s->x[0] < x - s->width) &&
           (s->eof || s->x[s->n - 1] > x + s->width);
}

/* Drops what falls behind, reads up to 3 widths ahead, and rebuilds the profile. */
static int refill(tirenv_level_stream *s, double x, tirenv_diag *diag)
{
    size_t lo = 0;
    while (lo + 1 < s->n && s->x[lo + 1] < x - s->width)
        ++lo;
    if (lo > 0) {
        memmove(s->x, s->x + lo, (s->n - lo) * sizeof *s->x);
        memmove(s->z, s->z + lo, (s->n - lo) * sizeof *s->z);
        s->n -= lo;
        s->bof = 0;
    }
    while (!s->eof && !(s->n > 0 && s->x[s->n - 1] > x + 3 * s->width)) {
        double vx, vz;
        int got = 0;
        const int status = s->next(s->ctx, &vx, &vz, &got, diag);
        if (status)
            return status;
        if (!got) {
            s->eof = 1;
            break;
        }
        if (s->n == s->cap) {
            const size_t cap = s->cap ? 2 * s->cap : 256;
            double *nx = realloc(s->x, cap * sizeof *nx);
            if (nx)
                s->x = nx;
            double *nz = nx ? realloc(s->z, cap * sizeof *nz) : NULL;
            if (!nz)
                return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
            s->z = nz;
            s->cap = cap;
        }
        s->x[s->n] = vx;
        s->z[s->n++] = vz;
    }
    if (s->n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "profile", "the profile has no vertex");
    tirenv_profile_free(s->p);
    s->p = tirenv_profile_alloc(s->n, s->x, s->z);
    return s->p ? TIRENV_OK : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
}

int tirenv_level_stream_at(tirenv_level_stream *s, double x, double *level, tirenv_diag *diag)
{
    if (!covers(s, x)) {
        const int status = refill(s, x, diag);
        if (status)
            return status;
    }
    *level = tirenv_profile_level(s->p, s->width, x);
    return TIRENV_OK;
}
