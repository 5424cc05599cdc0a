/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv_road_window: the rows of a road read in order, holding only those a moving stretch
 * [x_keep, x_need] needs (stream.h). The serial stream (stream.c) keeps one on the tire's
 * reach around its position, the CLI's parallel stream one on its chunks' reach, and the road's
 * level along a stream (level_stream.c) one of a track on a few level widths, so all read and
 * check a source the same way.
 *
 * A stretch is covered from the last row before x_keep (with its wall's other row) to the
 * first row after x_need, so each segment that meets it lies whole in the window; rows behind
 * x_keep are dropped as the reading goes, so memory is bounded by the stretch, not by the
 * road or a far x_keep.
 * The arrays double when full (after a drop), so the copying costs O(1) a row amortised. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "model/road_window_impl.h"

tirenv_road_window *tirenv_road_window_alloc(tirenv_row_source source, void *ctx,
                                             size_t n_tracks)
{
    if (!source || n_tracks == 0 || n_tracks > SIZE_MAX / sizeof(double))
        return NULL;
    tirenv_road_window *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    *w = (tirenv_road_window){.next = source, .ctx = ctx, .tracks = n_tracks, .bof = 1,
                              .keep = -INFINITY};
    w->z = calloc(n_tracks, sizeof *w->z);
    w->row = malloc(n_tracks * sizeof *w->row);
    if (!w->z || !w->row) {
        tirenv_road_window_free(w);
        return NULL;
    }
    return w;
}

void tirenv_road_window_free(tirenv_road_window *w)
{
    if (!w)
        return;
    free(w->x);
    for (size_t k = 0; w->z && k < w->tracks; ++k)
        free(w->z[k]);
    free(w->z);
    free(w->row);
    free(w);
}

static int window_grow(tirenv_road_window *w)
{
    const size_t cap = w->cap ? 2 * w->cap : 256;
    if (cap > SIZE_MAX / sizeof(double))
        return TIRENV_ENOMEM;
    double *x = realloc(w->x, cap * sizeof *x);
    if (!x)
        return TIRENV_ENOMEM;
    w->x = x;
    for (size_t k = 0; k < w->tracks; ++k) {
        double *z = realloc(w->z[k], cap * sizeof *z);
        if (!z)
            return TIRENV_ENOMEM;
        w->z[k] = z;
    }
    w->cap = cap;
    return TIRENV_OK;
}

/* The order a profile needs (x non-decreasing, at most two rows at one x) is checked as each
 * row comes, against the last one taken: a source other than the checked readers may hand
 * anything. */
static int vertex_check(tirenv_road_window *w, double x, const double z[], tirenv_diag *diag)
{
    const size_t k = w->read + 1;  /* 1-based index of this vertex in the source */
    for (size_t j = 0; j < w->tracks; ++j)
        if (!isfinite(x) || !isfinite(z[j]))
            return tirenv_error(diag, TIRENV_EINVAL, "", k, isfinite(x) ? "z" : "x",
                                "vertex %zu of the source is not finite (x %g m, z %g m%s)", k,
                                x, z[j], w->tracks > 1 ? " on one of its tracks" : "");
    if (w->read > 0 && x < w->x_last)
        return tirenv_error(diag, TIRENV_EINVAL, "", k, "x",
                            "vertex %zu of the source goes back: x %.9g m after %.9g m", k, x,
                            w->x_last);
    if (w->read == 0)
        w->x_first = x;
    w->same_x = w->read > 0 && x == w->x_last ? w->same_x + 1 : 1;
    w->x_last = x;
    if (w->same_x > 2)
        return tirenv_error(diag, TIRENV_EINVAL, "", k, "x",
                            "vertex %zu of the source is the third at x = %.9g m (a wall has "
                            "two)", k, x);
    return TIRENV_OK;
}

/* Drops the rows before the last one left of x_keep (they cannot touch the tire again). If
 * that row is a wall's second, its first stays too: the deformable models' test for level
 * ground within reach (tirenv_profile__level_clear) reads that wall over the whole profile,
 * and a window without it took that shortcut where the whole profile does not. */
static void window_drop(tirenv_road_window *w, double x_keep)
{
    size_t lo = 0;
    while (lo + 1 < w->n && w->x[lo + 1] < x_keep)
        ++lo;
    if (lo > 0 && w->x[lo - 1] == w->x[lo])
        --lo;
    if (lo == 0)
        return;
    memmove(w->x, w->x + lo, (w->n - lo) * sizeof *w->x);
    for (size_t k = 0; k < w->tracks; ++k)
        memmove(w->z[k], w->z[k] + lo, (w->n - lo) * sizeof *w->z[k]);
    w->n -= lo;
    w->bof = 0;
}

int tirenv_road_window_fill(tirenv_road_window *w, double x_keep, double x_need,
                            tirenv_diag *diag)
{
    if (!w)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no road window (NULL)");
    /* The rows behind the last stretch are gone: a stretch behind it would be covered by the
     * flat extension of the window's first row, silently. */
    if (!(x_keep >= w->keep))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x_keep",
                            "x_keep %g m is behind the last fill's %g m, whose rows behind it "
                            "are dropped and not read again; expected x_keep not below it",
                            x_keep, w->keep);
    if (isnan(x_need))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x_need", "x_need is not a number");
    w->keep = x_keep;
    window_drop(w, x_keep);
    while (!tirenv_road_window_covers(w, x_need)) {
        double x;
        int got = 0;
        int status = w->next(w->ctx, &x, w->row, &got, diag);
        if (!status && got)
            status = vertex_check(w, x, w->row, diag);
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
        for (size_t k = 0; k < w->tracks; ++k)
            w->z[k][w->n] = w->row[k];
        w->n++;
        w->read++;
        if (w->n > w->max)
            w->max = w->n;
    }
    return TIRENV_OK;
}

int tirenv_road_window_covers(const tirenv_road_window *w, double x)
{
    return w && (w->eof || (w->n > 0 && w->x[w->n - 1] > x));
}

/* Rows a source passed unchecked are refused saying why (their vertex within the window),
 * not as memory run out. */
int tirenv_road_window_profiles(const tirenv_road_window *w, tirenv_profile *p[],
                                tirenv_diag *diag)
{
    if (!w || !p)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no road window or profiles (NULL)");
    for (size_t k = 0; k < w->tracks; ++k) {
        if ((p[k] = tirenv_profile_alloc(w->n, w->x, w->z[k])))
            continue;
        const int status = tirenv_profile_validate(w->n, w->x, w->z[k], diag);
        return status ? status : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    return TIRENV_OK;
}
