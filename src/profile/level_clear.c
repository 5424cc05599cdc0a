/* SPDX-License-Identifier: Apache-2.0 */
/* Level ground under the tire, with obstacles within reach that it cannot touch
 * (docs/models.md section 11.4): the geometry of the deformable models' shortcut, which
 * returns the flat-ground equilibrium where this holds. */
#include "profile/profile_impl.h"

/* The level line z = level, the centre C = (x, z_c), and what an off-line piece must keep
 * clear of: the disc of radius sqrt(r2) about C; with tan_cut > 0, what every vertex below C
 * must keep clear of once any piece lies off the line: the cone of half-angle atan(tan_cut)
 * about the vertical below C. off and cut say whether the walk has met either so far. */
typedef struct {
    double x, z_c, level;
    double r2;           /* m^2 */
    double tan_cut;
    int off, cut;
} clear_ctx;

/* A vertex outside the cone, or above C (where no ray below the centre meets it). */
static int vertex_clear(const clear_ctx *c, double vx, double vz)
{
    return !(vz < c->z_c) || fabs(vx - c->x) > c->tan_cut * (c->z_c - vz);
}

/* Whether the walk may go on past the piece of ground from A = (xa, za) to B = (xb, zb): it
 * lies on the level line or, all of it, farther than r from C (the nearest point of the
 * segment to C, at the projection's t clamped to [0, 1]; a wall, xa == xb, is a segment like
 * any other); and, once a piece lies off the line, no vertex met lies in the cone. vertices:
 * A and B are the profile's (not the ends of a flat extension). */
static int piece_clear(clear_ctx *c, double xa, double za, double xb, double zb, int vertices)
{
    if (vertices && c->tan_cut > 0 && !(vertex_clear(c, xa, za) && vertex_clear(c, xb, zb)))
        c->cut = 1;
    if (!(za == c->level && zb == c->level)) {
        const double ex = xb - xa, ez = zb - za, qx = c->x - xa, qz = c->z_c - za;
        const double ee = ex * ex + ez * ez;
        double t = ee > 0 ? (qx * ex + qz * ez) / ee : 0;
        t = t > 0 ? (t < 1 ? t : 1) : 0;
        const double dx = qx - t * ex, dz = qz - t * ez;
        if (!(dx * dx + dz * dz > c->r2))
            return 0;
        c->off = 1;
    }
    return !(c->off && c->cut);
}

/* The ground at x gives the line; the walk goes outward from the segment under x, which on
 * ground that is not level there fails at once (a road costs one segment a position). Ground
 * level over the whole reach passes whatever its vertices (the cone is asked only where
 * something lies off the line). To the right the segments k, k + 1, ... that begin at or
 * before hi, to the left k - 1, k - 2, ... that end at or after lo, then the flat extension
 * where the profile ends inside [lo, hi]: the pieces that meet [lo, hi], whole, as a streamed
 * window holds them (src/model/stream.c). */
int tirenv_profile__level_clear(const struct tirenv_profile *p, double x, double reach,
                                double dz, double r, double tan_cut, double *level)
{
    const double *X = p->x, *Z = p->z, lo = x - reach, hi = x + reach;
    const size_t n = p->n, k = tirenv_profile__segment_at(p, x);
    /* A sloped segment under x passes through (x, L), dz from C: refused before any
     * arithmetic, as a road is at nearly every position. */
    if (x >= X[0] && k + 1 < n && Z[k] != Z[k + 1] && dz < r)
        return 0;
    const double L = tirenv_profile__height_in(p, x, k);
    clear_ctx c = {x, L + dz, L, r * r, tan_cut, 0, 0};
    size_t j = k;
    if (x < X[0]) { /* the left extension under x, on the line: the segments from 0 */
        j = 0;
    } else {
        if (j + 1 < n && !piece_clear(&c, X[j], Z[j], X[j + 1], Z[j + 1], 1))
            return 0;
        /* and a wall right behind the last segment read, though it ends before lo: the
         * segment holding lo is read with its vertex's wall, as the level test always did
         * (the window of a stream keeps it, src/model/road_window.c) */
        for (size_t i = k; i-- > 0 && (X[i + 1] >= lo || (X[i] == X[i + 1] &&
                                                           (i + 2 == n || X[i + 2] >= lo)));)
            if (!piece_clear(&c, X[i], Z[i], X[i + 1], Z[i + 1], 1))
                return 0;
        if (X[0] > lo && !piece_clear(&c, lo, Z[0], X[0], Z[0], 0))
            return 0;
        if (j + 1 < n)
            ++j;
    }
    for (; j + 1 < n && X[j] <= hi; ++j)
        if (!piece_clear(&c, X[j], Z[j], X[j + 1], Z[j + 1], 1))
            return 0;
    if (j + 1 == n && X[j] < hi && !piece_clear(&c, X[j], Z[j], hi, Z[j], 0))
        return 0;
    *level = L;
    return 1;
}
