/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the core: the profile's layout (src/profile builds it), shared with the models
 * that walk its segments directly (the rigid disc, the springs model's ray caster, the cam,
 * the ring). It lives beside the code that builds it, in src/profile, the one core module's
 * private header that the models include. Not part of the public API. */
#ifndef TIRENV_PROFILE_IMPL_H
#define TIRENV_PROFILE_IMPL_H

#include <math.h>
#include <stddef.h>

#include "tirenv/profile.h"

/* Vertices per block of the block-maximum index (a power of two). */
#define TIRENV_PROFILE__BLOCK 16

/* One allocation: the struct, then x[0..n-1], then z[0..n-1], then z_block[0..n_block-1].
 * Invariants (checked by tirenv_profile_validate): n >= 1, all finite, x non-decreasing, at
 * most two equal x; and, once sealed, z_block[b] is the highest z_k over the vertices
 * k = b*B .. min(b*B + B, n - 1) (B = TIRENV_PROFILE__BLOCK): block b's own vertices and the
 * next block's first, so that it bounds every point of the segments b*B .. b*B + B - 1. */
struct tirenv_profile {
    size_t n;        /* number of vertices */
    size_t n_block;  /* number of blocks, ceil(n / B) */
    double *x;       /* abscissae (m), non-decreasing */
    double *z;       /* heights (m) */
    double *z_block; /* block maxima of z (m), see above */
    /* Once sealed, also: the largest |z_k| (m), and the steepest |z_k+1 - z_k|/(x_k+1 - x_k)
     * of the segments that are not walls (x_k+1 > x_k), 0 if none. The cam bounds the
     * rounding of its lifts by them (src/model/cam_lift.c). */
    double z_abs_max;
    double slope_max;
    /* Once sealed: a number no other profile of this process has had, so that a model may
     * keep what it found on this profile and know it is still the same ground even when a
     * new profile comes to sit at a freed one's address (src/model/springs.c). */
    unsigned long long serial;
};

/* An uninitialised profile of n >= 1 vertices in one block, for generators that fill the
 * arrays in place; the caller must establish the invariants above, then call
 * tirenv_profile__seal. NULL if out of memory. */
struct tirenv_profile *tirenv_profile__new(size_t n);

/* Builds the block maxima (and z_abs_max, slope_max) from x and z, once they are final,
 * and gives the profile its serial. O(n). */
void tirenv_profile__seal(struct tirenv_profile *p);

/* A generator's last step: validates the filled profile (tirenv_profile_validate's errors)
 * and seals it. On failure the caller still owns and frees p. */
int tirenv_profile__finish(struct tirenv_profile *p, tirenv_diag *diag);

/* The binary search of both lookups below: the count of x_k <= x known to lie in [lo, hi],
 * the index of the last such vertex (0 when there is none). */
static inline size_t tirenv_profile__segment_in(const double xs[], size_t lo, size_t hi,
                                                double x)
{
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (xs[mid] <= x)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo == 0 ? 0 : lo - 1;
}

/* Index k of the last vertex with x_k <= x, found by binary search in O(log n); 0 when
 * x < x_0 (callers tell the left flat extension apart by x < p->x[0]). At a wall
 * (x_k == x_{k+1} == x) this is the wall's second vertex k+1. Segment k is [x_k, x_{k+1}]
 * for k < n-1; k = n-1 means x lies on or beyond the last vertex (right extension). */
static inline size_t tirenv_profile__segment_at(const struct tirenv_profile *p, double x)
{
    return tirenv_profile__segment_in(p->x, 0, p->n, x);
}

/* The same index as tirenv_profile__segment_at(p, x), found from a nearby index k_hint < n
 * by an exponential search outward and a binary search within the last step: O(log d) for
 * a vertex d places away, and in cache when d is small. */
static inline size_t tirenv_profile__segment_near(const struct tirenv_profile *p, size_t k_hint,
                                                  double x)
{
    const double *xs = p->x;
    const size_t n = p->n;
    size_t lo, hi; /* the answer, the count of x_k <= x, lies in [lo, hi] */
    if (xs[k_hint] <= x) {
        lo = k_hint + 1;
        size_t step = 1;
        while (lo + step <= n && xs[lo + step - 1] <= x) {
            lo += step;
            step *= 2;
        }
        hi = lo + step <= n ? lo + step - 1 : n;
    } else {
        hi = k_hint;
        size_t step = 1;
        while (step <= hi && xs[hi - step] > x) {
            hi -= step;
            step *= 2;
        }
        lo = step <= hi ? hi - step + 1 : 0;
    }
    return tirenv_profile__segment_in(xs, lo, hi, x);
}

/* tirenv_profile_height(p, x) given k = tirenv_profile__segment_at(p, x) (or _near's, the same
 * index): the flat extensions outside the polyline, at a wall the higher vertex, else
 * z_k + (z_{k+1} - z_k) t with t = (x - x_k) / (x_{k+1} - x_k), whose denominator is positive
 * since walls are handled before it is formed. The one formula of the ground's height, for a
 * caller that has the segment already (no second search). */
static inline double tirenv_profile__height_in(const struct tirenv_profile *p, double x,
                                               size_t k)
{
    const double *xs = p->x, *zs = p->z;
    if (x < xs[0])
        return zs[0];
    if (x == xs[k] && k >= 1 && xs[k - 1] == xs[k])
        return fmax(zs[k - 1], zs[k]);
    if (k == p->n - 1)
        return zs[k];
    const double t = (x - xs[k]) / (xs[k + 1] - xs[k]);
    return zs[k] + (zs[k + 1] - zs[k]) * t;
}

/* Whether the ground within reach (m) of x is level under the centre, C = (x, level + dz), but
 * for pieces the tire cannot touch: every segment, wall or flat extension meeting
 * [x - reach, x + reach] lies on the line z = level through the ground at x, or all of it
 * farther than r (m) from C; with tan_cut > 0 and any piece off the line, every vertex of
 * those segments below C also lies outside the cone |X - x| <= tan_cut*(z_C - Z). The line's
 * height in *level. O(1) where the ground at x is not level, O(vertices within reach) else
 * (src/profile/level_clear.c). */
int tirenv_profile__level_clear(const struct tirenv_profile *p, double x, double reach,
                                double dz, double r, double tan_cut, double *level);

#endif
