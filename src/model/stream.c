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
 * the memory is O(r / vertex spacing), whatever the road's length. The vertices come from a
 * callback (tirenv_vertex_source), so the core knows no file format: the CSV reader is one
 * source, in the auxiliary layer.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/stream.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double *x, *z;         /* vertices, m */
    size_t n, cap;
    int bof;               /* x[0] is the file's first vertex */
    int eof;               /* the file's last vertex has been read */
    size_t read;           /* vertices read from the file */
    size_t max;            /* largest n so far */
    double x_last;         /* the last vertex taken, m */
    size_t same_x;         /* vertices taken at x_last */
} window;

static int window_grow(window *w)
{
    const size_t cap = w->cap ? 2 * w->cap : 256;
    if (cap > SIZE_MAX / sizeof(double))
        return TIRENV_ENOMEM;
    double *x = realloc(w->x, cap * sizeof *x);
    if (!x)
        return TIRENV_ENOMEM;
    w->x = x;
    double *z = realloc(w->z, cap * sizeof *z);
    if (!z)
        return TIRENV_ENOMEM;
    w->z = z;
    w->cap = cap;
    return TIRENV_OK;
}

/* The source and what the sweep checks of it. */
typedef struct {
    tirenv_vertex_source next;
    void *ctx;
} vertex_source;

/* The order a profile needs (x non-decreasing, at most two vertices at one x) is checked as
 * each vertex comes, against the last one taken: a source other than the checked CSV reader
 * may hand anything. */
static int vertex_check(window *w, double x, double z, tirenv_diag *diag)
{
    const size_t k = w->read + 1;  /* 1-based index of this vertex in the source */
    if (!isfinite(x) || !isfinite(z))
        return tirenv_error(diag, TIRENV_EINVAL, "", k, isfinite(x) ? "z" : "x",
                            "vertex %zu of the source is not finite (x %g m, z %g m)", k, x, z);
    if (w->read > 0 && x < w->x_last)
        return tirenv_error(diag, TIRENV_EINVAL, "", k, "x",
                            "vertex %zu of the source goes back: x %.9g m after %.9g m", k, x,
                            w->x_last);
    w->same_x = w->read > 0 && x == w->x_last ? w->same_x + 1 : 1;
    w->x_last = x;
    if (w->same_x > 2)
        return tirenv_error(diag, TIRENV_EINVAL, "", k, "x",
                            "vertex %zu of the source is the third at x = %.9g m (a wall has "
                            "two)", k, x);
    return TIRENV_OK;
}

/* Drops the vertices before the last one left of x_keep (they cannot touch the tire again). */
static void window_drop(window *w, double x_keep)
{
    size_t lo = 0;
    while (lo + 1 < w->n && w->x[lo + 1] < x_keep)
        ++lo;
    if (lo == 0)
        return;
    memmove(w->x, w->x + lo, (w->n - lo) * sizeof *w->x);
    memmove(w->z, w->z + lo, (w->n - lo) * sizeof *w->z);
    w->n -= lo;
    w->bof = 0;
}

/* Makes the window cover [x_keep, x_need]: reads until a vertex lies beyond x_need or the
 * file ends, dropping what falls behind x_keep as it goes so that a far x_from costs no
 * memory either. */
static int window_fill(window *w, const vertex_source *in, double x_keep, double x_need,
                       tirenv_diag *diag)
{
    window_drop(w, x_keep);
    while (!w->eof && !(w->n > 0 && w->x[w->n - 1] > x_need)) {
        double x, z;
        int got = 0;
        int status = in->next(in->ctx, &x, &z, &got, diag);
        if (!status && got)
            status = vertex_check(w, x, z, diag);
        if (status)
            return status;
        if (!got) {
            w->eof = 1;
            break;
        }
        if (w->n == w->cap) {
            window_drop(w, x_keep);
            if (w->n == w->cap && window_grow(w) != TIRENV_OK)
                return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        }
        w->x[w->n] = x;
        w->z[w->n] = z;
        w->n++;
        w->read++;
        if (w->n > w->max)
            w->max = w->n;
    }
    return TIRENV_OK;
}

/* The window as a profile, handed to the model; the previous one is freed once replaced. */
static int window_profile(const window *w, tirenv_profile **p, tirenv_diag *diag)
{
    *p = tirenv_profile_alloc(w->n, w->x, w->z);
    return *p ? TIRENV_OK : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
}

size_t tirenv_positions_count(double x_from, double x_to, double dx)
{
    const double limit = x_to + dx * 1e-9;
    size_t n = (size_t)floor((limit - x_from) / dx) + 1;
    /* The division can land one step off either way; the product decides. */
    while (n > 1 && x_from + (double)(n - 1) * dx > limit)
        --n;
    while (x_from + (double)n * dx <= limit)
        ++n;
    return n;
}

int tirenv_model_stream(tirenv_model *m, tirenv_vertex_source source, void *source_ctx,
                        double x_from, double x_to, double dx, double load,
                        tirenv_point_sink sink, void *ctx, tirenv_stream_stats *stats,
                        tirenv_diag *diag)
{
    const vertex_source src = {source, source_ctx};
    const vertex_source *in = &src;
    if (stats)
        *stats = (tirenv_stream_stats){0};
    if (!(isfinite(x_from) && isfinite(x_to) && dx > 0 && isfinite(dx) && x_to >= x_from))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "expected dx > 0 and x_to >= x_from, got dx %g m from %g to %g m",
                            dx, x_from, x_to);
    if (!((x_to - x_from) / dx < 1e15))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx", "too many positions");
    window w = {.bof = 1};
    tirenv_profile *p = NULL, *next = NULL;
    size_t rebuilds = 0, done = 0;
    /* One vertex is enough to set the load and find z_flat; only then is the reach at that
     * load known (the cam's tandem base depends on it), and the window is read to fit it. */
    int status = window_fill(&w, in, -INFINITY, -INFINITY, diag);
    if (!status && !(status = window_profile(&w, &p, diag)))
        status = tirenv_model_set(m, p, load, diag);
    const double r = tirenv_model_reach(m), ahead = 2 * r;
    const size_t n = status ? 0 : tirenv_positions_count(x_from, x_to, dx);
    int have_window = 0;
    for (size_t k = 0; k < n && !status; ++k) {
        const double x = x_from + (double)k * dx;
        if (!have_window || !(w.eof || w.x[w.n - 1] > x + r)) {
            if ((status = window_fill(&w, in, x - r, x + r + ahead, diag)) ||
                (status = window_profile(&w, &next, diag)) ||
                (status = tirenv_model_set_profile(m, next, diag)))
                break;
            tirenv_profile_free(p);
            p = next;
            next = NULL;
            have_window = 1;
            ++rebuilds;
        }
        tirenv_point pt;
        if ((status = tirenv_model_eval(m, x, &pt, diag)))
            break;
        if ((status = sink(ctx, &pt)))
            break;
        ++done;
    }
    if (stats)
        *stats = (tirenv_stream_stats){.positions = done, .vertices_read = w.read,
                                       .window_max = w.max, .rebuilds = rebuilds};
    /* The model must not keep pointing at a freed window: it is left unset. */
    if (p && m)
        tirenv_model_set_profile(m, NULL, NULL);
    tirenv_profile_free(next);
    tirenv_profile_free(p);
    free(w.x);
    free(w.z);
    return status;
}
