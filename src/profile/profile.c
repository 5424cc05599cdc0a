/* The ground profile object (docs/models.md section 2): validation, storage, height queries.
 * SPDX-License-Identifier: Apache-2.0 */
#include "profile/profile_impl.h"

#include <math.h>
#include <stdalign.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int tirenv_profile_check_vertex(size_t k, double x, double z, double x_prev, double x_prev2,
                                tirenv_diag *diag)
{
    const size_t line = k + 1;
    if (!isfinite(x))
        return tirenv_error(diag, TIRENV_EINVAL, NULL, line, "x",
                            "vertex %zu: x = %g is not finite; expected a finite number", line,
                            x);
    if (!isfinite(z))
        return tirenv_error(diag, TIRENV_EINVAL, NULL, line, "z",
                            "vertex %zu: z = %g is not finite; expected a finite number", line,
                            z);
    /* Beyond these the models' geometry loses its precision (a ring over a 1e8 m segment
     * gave h 41 mm for 50; the springs model's ray walk overflows near 1e308 m): no road is
     * that long, and a typo or a unit slip is refused rather than computed wrong. */
    if (!(fabs(x) <= TIRENV_PROFILE_MAX_COORDINATE) || !(fabs(z) <= TIRENV_PROFILE_MAX_COORDINATE))
        return tirenv_error(diag, TIRENV_EINVAL, NULL, line, fabs(x) > fabs(z) ? "x" : "z",
                            "vertex %zu: %s = %g m is beyond +-%g m; expected a road's "
                            "coordinates (in m?)", line, fabs(x) > fabs(z) ? "x" : "z",
                            fabs(x) > fabs(z) ? x : z, TIRENV_PROFILE_MAX_COORDINATE);
    if (k >= 1 && x - x_prev > TIRENV_PROFILE_MAX_SEGMENT)
        return tirenv_error(diag, TIRENV_EINVAL, NULL, line, "x",
                            "vertex %zu: x = %.17g is %g m from the previous vertex; expected "
                            "at most %g m (flat ground between two vertices that far apart "
                            "can be given by vertices every %g m, and before the first and "
                            "after the last it continues by itself)", line, x, x - x_prev,
                            TIRENV_PROFILE_MAX_SEGMENT, TIRENV_PROFILE_MAX_SEGMENT);
    if (k >= 1 && x < x_prev)
        return tirenv_error(diag, TIRENV_EINVAL, NULL, line, "x",
                            "vertex %zu: x = %.17g is less than the previous x = %.17g; "
                            "expected non-decreasing x",
                            line, x, x_prev);
    /* A third vertex at one abscissa would make the height there ambiguous. */
    if (k >= 2 && x == x_prev2)
        return tirenv_error(diag, TIRENV_EINVAL, NULL, line, "x",
                            "vertex %zu: x = %.17g is shared by three vertices; expected at "
                            "most two (a vertical wall)",
                            line, x);
    return TIRENV_OK;
}

/* Vertices are checked one by one in order, so the diagnostic names the first bad vertex,
 * which is what a user editing a CSV file wants to jump to. */
int tirenv_profile_validate(size_t n, const double x[], const double z[], tirenv_diag *diag)
{
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, NULL, 0, "",
                            "the profile has no vertices; expected at least one");
    if (!x || !z)
        return tirenv_error(diag, TIRENV_EINVAL, NULL, 0, x ? "z" : "x",
                            "the vertex array is NULL; expected %zu values", n);
    for (size_t k = 0; k < n; k++) {
        const int status = tirenv_profile_check_vertex(k, x[k], z[k], k >= 1 ? x[k - 1] : 0,
                                                       k >= 2 ? x[k - 2] : 0, diag);
        if (status)
            return status;
    }
    return TIRENV_OK;
}

/* The arrays follow the struct in one block, so a profile is one malloc and one free and
 * its vertices sit together in cache for the ray casters. The block maxima add 1/16 to it. */
struct tirenv_profile *tirenv_profile__new(size_t n)
{
    const size_t align = alignof(double);
    const size_t head = (sizeof(struct tirenv_profile) + align - 1) / align * align;
    if (n == 0 || n > (SIZE_MAX - head) / (3 * sizeof(double)))
        return NULL;
    const size_t n_block = (n + TIRENV_PROFILE__BLOCK - 1) / TIRENV_PROFILE__BLOCK;
    unsigned char *block = malloc(head + (2 * n + n_block) * sizeof(double));
    if (!block)
        return NULL;
    struct tirenv_profile *p = (struct tirenv_profile *)block;
    p->n = n;
    p->n_block = n_block;
    p->x = (double *)(block + head);
    p->z = p->x + n;
    p->z_block = p->z + n;
    return p;
}

void tirenv_profile__seal(struct tirenv_profile *p)
{
    static atomic_ullong next_serial = 1;
    p->serial = atomic_fetch_add_explicit(&next_serial, 1, memory_order_relaxed);
    const size_t B = TIRENV_PROFILE__BLOCK;
    for (size_t b = 0; b < p->n_block; b++) {
        const size_t k_end = b * B + B < p->n - 1 ? b * B + B : p->n - 1;
        double z_max = p->z[b * B];
        for (size_t k = b * B + 1; k <= k_end; k++)
            z_max = fmax(z_max, p->z[k]);
        p->z_block[b] = z_max;
    }
    p->z_abs_max = fabs(p->z[0]);
    p->slope_max = 0.0;
    for (size_t k = 1; k < p->n; k++) {
        p->z_abs_max = fmax(p->z_abs_max, fabs(p->z[k]));
        const double dx = p->x[k] - p->x[k - 1];
        if (dx > 0.0)
            p->slope_max = fmax(p->slope_max, fabs(p->z[k] - p->z[k - 1]) / dx);
    }
}

tirenv_profile *tirenv_profile_alloc(size_t n, const double x[], const double z[])
{
    if (tirenv_profile_validate(n, x, z, NULL) != TIRENV_OK)
        return NULL;
    struct tirenv_profile *p = tirenv_profile__new(n);
    if (!p)
        return NULL;
    memcpy(p->x, x, n * sizeof(double));
    memcpy(p->z, z, n * sizeof(double));
    tirenv_profile__seal(p);
    return p;
}

int tirenv_profile_make(size_t n, const double x[], const double z[], const char *name,
                        tirenv_profile **out, tirenv_diag *diag)
{
    *out = NULL;
    const int status = tirenv_profile_validate(n, x, z, diag);
    if (status) {
        if (diag && name) {  /* the vertex is named in the message; it is no line of name */
            snprintf(diag->file, sizeof diag->file, "%s", name);
            diag->line = 0;
        }
        return status;
    }
    if (!(*out = tirenv_profile_alloc(n, x, z)))
        return tirenv_error(diag, TIRENV_ENOMEM, name, 0, "", "out of memory");
    return TIRENV_OK;
}

void tirenv_profile_free(tirenv_profile *p)
{
    free(p);
}

size_t tirenv_profile_size(const tirenv_profile *p)
{
    return p->n;
}

const double *tirenv_profile_x(const tirenv_profile *p)
{
    return p->x;
}

const double *tirenv_profile_z(const tirenv_profile *p)
{
    return p->z;
}

/* Flat extensions outside the polyline; at a wall the higher vertex, because a tire resting
 * on the wall's top edge is held up by it (tirenv_profile__height_in). */
double tirenv_profile_height(const tirenv_profile *p, double x)
{
    return tirenv_profile__height_in(p, x, tirenv_profile__segment_at(p, x));
}

/* The ground is piecewise linear, so its maximum over [x_lo, x_hi] is attained at a vertex
 * inside the interval or at an end of it. Returns NAN if x_lo > x_hi or either is NaN. */
double tirenv_profile_max_height(const tirenv_profile *p, double x_lo, double x_hi)
{
    if (!(x_lo <= x_hi))
        return NAN;
    double z_max = fmax(tirenv_profile_height(p, x_lo), tirenv_profile_height(p, x_hi));
    /* First vertex with x_k >= x_lo: one past the last vertex with x_k < x_lo. */
    size_t k = 0;
    if (x_lo > p->x[0]) {
        k = tirenv_profile__segment_at(p, x_lo);
        while (k < p->n && p->x[k] < x_lo)
            k++;
        while (k > 0 && p->x[k - 1] >= x_lo) /* step back onto a wall's first vertex */
            k--;
    }
    /* Whole blocks from their maxima: z_block[b] covers vertices b*B .. b*B + B, all inside
     * the interval when x_{b*B+B} <= x_hi (x is non-decreasing), and a maximum does not
     * depend on the order it is taken in, so the result is the same bit for bit. */
    const size_t B = TIRENV_PROFILE__BLOCK;
    while (k < p->n && p->x[k] <= x_hi) {
        if (k % B == 0 && k + B < p->n && p->x[k + B] <= x_hi) {
            z_max = fmax(z_max, p->z_block[k / B]);
            k += B;
        } else {
            z_max = fmax(z_max, p->z[k]);
            k++;
        }
    }
    return z_max;
}

void tirenv_profile_extent(const tirenv_profile *p, double *x_first, double *x_last)
{
    if (x_first)
        *x_first = p->x[0];
    if (x_last)
        *x_last = p->x[p->n - 1];
}

int tirenv_profile__finish(struct tirenv_profile *p, tirenv_diag *diag)
{
    const int status = tirenv_profile_validate(p->n, p->x, p->z, diag);
    if (!status)
        tirenv_profile__seal(p);
    return status;
}
