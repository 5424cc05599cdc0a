/* The elliptical cam's lift over a profile, exact on polylines (docs/models.md section 7): the
 * largest touching height over a finite set of candidates, most of them ruled out by bounds
 * that change no bit of the result. The candidates and the bounds are argued at
 * tirenv_cam__lift, at the end. SPDX-License-Identifier: Apache-2.0 */
#include <math.h>

#include "model/cam_impl.h"
#include "profile/profile_impl.h"

/* The best touching point found so far: lift Z, where the cam touches the profile, and
 * which candidate that is (its rank, see tirenv_cam__lift). */
typedef struct {
    double Z, p_x, p_z;
    size_t rank;
} cam_contact;

/* A lift under way: the inputs, the best so far, and the bar under it. */
typedef struct {
    const tirenv_cam__geom *g;
    tirenv_cam__sweep *sweep; /* NULL for a single lift */
    const struct tirenv_profile *p;
    double x;
    size_t k_x;               /* the last vertex at or before x (0 before the profile) */
    double slack;             /* covers the rounding of segments' lifts (bar_under), m */
    cam_contact best;
    double bar;
} cam_scan;

/* The pruning bar under a lift Z that some candidate reaches: a candidate whose bound falls
 * below it is strictly below Z as computed, so skipping it changes neither the lift nor which
 * of equal lifts wins. The margin, 2^-40 of the heights at stake (a competitive point is at
 * most b_e above Z), is far above the few ulps by which a computed vertex lift, or a bound,
 * can differ from its exact value, and far below any difference that matters. A segment's
 * lift adds terms that grow with its slope: the slack covers those (slack_of). */
static inline double bar_under(const cam_scan *sc, double Z)
{
    return Z - 0x1p-40 * (fabs(Z) + sc->g->b_e) - sc->slack;
}

/* The lift Z of a candidate of the given rank (see tirenv_cam__lift). The higher lift wins,
 * and of equal lifts the lower rank: the result is the one a plain scan in the order of rank
 * finds, whatever the order the candidates come in. */
static inline void consider(cam_scan *sc, double Z, double p_x, double p_z, size_t rank)
{
    if (Z > sc->best.Z || (Z == sc->best.Z && rank < sc->best.rank)) {
        sc->best = (cam_contact){Z, p_x, p_z, rank};
        sc->bar = bar_under(sc, Z);
    }
}

/* t^n for a small whole n >= 1, by squaring. */
static inline double ipow(double t, unsigned n)
{
    double r = 1.0;
    for (; n; n >>= 1, t *= t)
        if (n & 1)
            r *= t;
    return r;
}

/* A lower bound on the edge's drop at 0 <= t <= 1 without a pow: the sweep's table if there
 * is one, else (b_e/c_e)*t^n_c (see tirenv_cam__geom_set). */
static inline double drop_floor(const cam_scan *sc, double t)
{
    return sc->sweep ? tirenv_cam__floor_at(&sc->sweep->floor, t)
                     : sc->g->b_over_c * ipow(t, sc->g->n_c);
}

/* Vertex k within reach at t = its distance / a_e as a candidate, once the caller's bound
 * without pow has put it at or above the bar. */
static void vertex(cam_scan *sc, size_t k, double t)
{
    const tirenv_cam__geom *g = sc->g;
    const double x_k = sc->p->x[k], z_k = sc->p->z[k];
    const size_t rank = k <= sc->k_x ? 1 + (sc->k_x - k) : 1 + k;
    double Z = z_k + 0.0; /* t = 0: the edge is at the bottom */
    if (t > 0.0) {
        /* With t^c_e from the first of the edge's two pows, the sharper bound
         * z_k - (b_e/c_e)*t^c_e (see tirenv_cam__geom_set) rules out most of the rest before
         * the second. The drop it bounds exceeds it by at least
         * b_e*(c_e - 1)*t^(2c_e)/(2c_e^2), and the slack (1e-9 relative, 1e-14*b_e absolute)
         * covers the rounding of both where that gap is smaller. Both sides add z_k to the
         * drop last, so its rounding keeps the order. */
        const double tc = pow(t, g->c_e);
        if (z_k + (g->b_e * 1e-14 - g->b_over_c * tc * (1.0 - 1e-9)) < sc->bar)
            return;
        Z = z_k + tirenv_cam__edge(g, tc);
    }
    consider(sc, Z, x_k, z_k, rank);
}

/* Segment k's tangency as a candidate: 1, and its lift *Z at the touching point (*p_x,
 * *p_z), if that lies inside the segment (else an end vertex, or the cam's reach, bounds
 * the touching height there; the reach never wins, as g' -> -infinity at t = 1 makes it grow
 * inward). Walls and flat segments have none of their own (their vertices and the ground
 * under x cover them). The lift is Z = z_a + s*(x - x_a) + rise (cam.c's
 * tirenv_cam__tangent). A sweep keeps the slope, u and the rise per segment (the memo), so
 * that the five exp/log are paid once per segment for both cams, not once per position and
 * cam; it keeps the very values computed here (cam_sweep.c computes them alike), so a hit is
 * bit for bit a miss. */
static int segment_lift(const cam_scan *sc, size_t k, double *Z, double *p_x, double *p_z)
{
    const tirenv_cam__geom *g = sc->g;
    const struct tirenv_profile *p = sc->p;
    const double x = sc->x;
    const double x_a = p->x[k], x_b = p->x[k + 1], z_a = p->z[k], z_b = p->z[k + 1];
    if (!(x_b > x_a) || z_b == z_a)
        return 0;
    tirenv_cam__tangent_memo *slot = sc->sweep ? tirenv_cam__memo_slot(sc->sweep, k) : NULL;
    const int hit = slot && slot->tag == k + 1;
    const double s = hit ? slot->s : (z_b - z_a) / (x_b - x_a);
    /* A rising segment touches ahead of the bottom (needs x_b > x), a falling one behind it
     * (x > x_a). On a road the sign is a coin toss: the tests below pick their operands by it
     * rather than branch on it. */
    const int rising = s > 0;
    if (!((rising ? x_b : x) > (rising ? x : x_a)))
        return 0;
    /* A shallow segment (m < 1) touches at t = k*P <= k = m^(1/(c_e-1)), and k <= m when
     * c_e <= 2: a segment beyond a_e*m from x (the usual case on a road, where m is small)
     * cannot hold the tangency point, which is known before any exp or log: it needs
     * x + u_max > x_a (rising) or x_b > x - u_max (falling). The relative slack 1e-9 covers
     * the rounding of k, P and t, so that the point computed below would fail the test at
     * the end as well: the result is the same bit for bit. */
    const double m = fabs(s) * g->a_over_b;
    if (m < 1.0 && g->c_e <= 2.0) {
        const double u_max = g->a_e * (m * (1.0 + 1e-9));
        if (!((rising ? x + u_max : x_b) > (rising ? x_a : x - u_max)))
            return 0;
    }
    double u, rise;
    if (hit) {
        u = slot->u;
        rise = slot->rise;
    } else {
        tirenv_cam__tangent(g, m, &u, &rise);
        if (slot) {
            *slot = (tirenv_cam__tangent_memo){.tag = k + 1, .s = s, .u = u, .rise = rise};
            tirenv_cam__memo_ahead(sc->sweep, g, p, k);
        }
    }
    const double xi = x + (rising ? u : -u); /* x - u, bit for bit, when falling */
    if (!(xi > x_a && xi < x_b))
        return 0;
    *Z = z_a + s * (x - x_a) + rise;
    *p_x = xi;
    *p_z = z_a + s * (xi - x_a);
    return 1;
}

/* Segment k's tangency as a candidate, with no bound. */
static void segment_try(cam_scan *sc, size_t k)
{
    double Z, p_x, p_z;
    if (segment_lift(sc, k, &Z, &p_x, &p_z))
        consider(sc, Z, p_x, p_z, sc->p->n + 1 + k);
}

/* Segment k, from a vertex within reach (or ending at one), as a candidate, unless the
 * higher of its ends at its nearer end's drop floor drop_near is below the bar. */
static inline void segment(cam_scan *sc, size_t k, double drop_near)
{
    const double z_a = sc->p->z[k], z_b = sc->p->z[k + 1];
    if ((z_a > z_b ? z_a : z_b) - drop_near < sc->bar)
        return;
    segment_try(sc, k);
}

/* The block walks outward from x, one per side, meet the vertices nearest first and the
 * segments from them (a segment's nearer end is the vertex it is met at). Block by block (the
 * profile's block maxima, TIRENV_PROFILE__BLOCK vertices each; a block's maximum covers the
 * next block's first vertex too, so it bounds every segment that starts in it): once a
 * block's highest vertex at the current distance is below the bar, nothing more in it can
 * reach the bar, and the next block that may is found from the blocks' maxima alone, or none
 * (z_cap, the highest ground anywhere, below the bar too), which ends the walk; so does the
 * reach. */
static void walk_right_from(cam_scan *sc, size_t k, double z_cap)
{
    const struct tirenv_profile *p = sc->p;
    const size_t n = p->n, B = TIRENV_PROFILE__BLOCK;
    const double *xs = p->x, *zs = p->z, x = sc->x, inv_a = sc->g->inv_a;
    while (k < n) {
        const size_t b = k / B, k_end = (b + 1) * B < n ? (b + 1) * B : n;
        for (; k < k_end; k++) {
            const double t = (xs[k] - x) * inv_a;
            if (t > 1.0)
                return; /* beyond the reach: so is every vertex and segment from here */
            const double drop = drop_floor(sc, t);
            if (p->z_block[b] - drop < sc->bar)
                break;
            /* Vertex k, and segment k if its other end is not higher, are below the bar
             * when z_k is: one test for both, mostly. */
            const double z_hi = k + 1 < n && zs[k + 1] > zs[k] ? zs[k + 1] : zs[k];
            if (z_hi - drop < sc->bar)
                continue;
            if (k + 1 < n)
                segment(sc, k, drop);
            if (zs[k] - drop >= sc->bar)
                vertex(sc, k, t);
        }
        for (k = k_end; k < n; k += B) { /* the next block that may reach the bar */
            const double t = (xs[k] - x) * inv_a;
            if (t > 1.0)
                return;
            const double drop = drop_floor(sc, t);
            if (z_cap - drop < sc->bar)
                return;
            if (p->z_block[k / B] - drop >= sc->bar)
                break;
        }
    }
}

/* The mirror of walk_right_from: vertices k - 1, k - 2, ... (k is one past the next vertex),
 * where the segment j from vertex j to j + 1 is met at vertex j, its nearer end j + 1 having
 * the drop floor drop_right. Segment k_x is the caller's. */
static void walk_left_from(cam_scan *sc, size_t k, double drop_right, double z_cap)
{
    const struct tirenv_profile *p = sc->p;
    const size_t B = TIRENV_PROFILE__BLOCK;
    const double *xs = p->x, *zs = p->z, x = sc->x, inv_a = sc->g->inv_a;
    while (k > 0) {
        const size_t b = (k - 1) / B;
        for (; k > b * B; k--) {
            const size_t j = k - 1;
            if (j < sc->k_x)
                segment(sc, j, drop_right);
            const double t = (x - xs[j]) * inv_a;
            if (t > 1.0)
                return;
            const double drop = drop_floor(sc, fabs(t)); /* t < 0 only off the start */
            if (p->z_block[b] - drop < sc->bar)
                break;
            if (zs[j] - drop >= sc->bar)
                vertex(sc, j, fabs(t));
            drop_right = drop;
        }
        /* Vertex k - 1 and below, in block b and beyond, need not be walked: find the next
         * block that may reach the bar, by the drop at its last covered vertex, nearest x. */
        for (k = b * B; k > 0; k -= B) {
            const double t = (x - xs[k]) * inv_a;
            if (t > 1.0)
                return;
            const double drop = drop_floor(sc, t);
            if (z_cap - drop < sc->bar)
                return;
            if (p->z_block[(k - 1) / B] - drop >= sc->bar) {
                drop_right = drop;
                break;
            }
        }
    }
}

/* Near x each side is taken in the same three steps at every position of a road, which the
 * processor predicts, rather than in a varying number of short loops, which it cannot: the
 * nearest vertex on its own (on a road, often near the bar), the next NEAR_GROUP as a group,
 * bounded by their highest vertex at the group's nearest distance (one by one if that bound
 * fails), and all the rest by one bound: the rest of the block there, the next two blocks at
 * their distances, z_cap beyond (rest_right, rest_left; the block walk if that fails). On a
 * road this is 1.5 times as fast as the block walks alone (measured). */
enum { NEAR_GROUP = 3 };

/* The bound on a block of the profile whose highest vertex is z_b, from its point nearest x
 * at distance t (in units of a_e): -INFINITY beyond the reach. */
static inline double block_bound(const cam_scan *sc, double z_b, double t)
{
    return t > 1.0 ? -INFINITY : z_b - drop_floor(sc, t);
}

/* An upper bound on every vertex from k on, and the segments from them. */
static double rest_right(const cam_scan *sc, size_t k, double z_cap)
{
    const struct tirenv_profile *p = sc->p;
    const size_t n = p->n, B = TIRENV_PROFILE__BLOCK, b = k / B;
    const double *xs = p->x, x = sc->x, inv_a = sc->g->inv_a;
    double bound = block_bound(sc, p->z_block[b], (xs[k] - x) * inv_a);
    for (size_t i = 1; i <= 2 && (b + i) * B < n; i++) {
        const double z = block_bound(sc, p->z_block[b + i], (xs[(b + i) * B] - x) * inv_a);
        bound = z > bound ? z : bound;
    }
    if ((b + 3) * B < n) {
        const double z = block_bound(sc, z_cap, (xs[(b + 3) * B] - x) * inv_a);
        bound = z > bound ? z : bound;
    }
    return bound;
}

/* An upper bound on every vertex below k, and the segments that start below k - 1: the rest
 * of vertex k - 1's block at its distance, the two blocks below at the distance of their last
 * covered vertex, z_cap beyond. */
static double rest_left(const cam_scan *sc, size_t k, double z_cap)
{
    const struct tirenv_profile *p = sc->p;
    const size_t B = TIRENV_PROFILE__BLOCK, b = (k - 1) / B;
    const double *xs = p->x, x = sc->x, inv_a = sc->g->inv_a;
    double bound = block_bound(sc, p->z_block[b], (x - xs[k - 1]) * inv_a);
    for (size_t i = 1; i <= 2 && i <= b; i++) {
        const double z = block_bound(sc, p->z_block[b - i], (x - xs[(b - i + 1) * B]) * inv_a);
        bound = z > bound ? z : bound;
    }
    if (b >= 3) {
        const double z = block_bound(sc, z_cap, (x - xs[(b - 2) * B]) * inv_a);
        bound = z > bound ? z : bound;
    }
    return bound;
}

/* The highest of z[0] .. z[NEAR_GROUP]: a group's vertices with the far end of its last
 * segment. */
static inline double group_top(const double z[])
{
    double top = z[0];
    for (size_t i = 1; i <= NEAR_GROUP; i++)
        top = z[i] > top ? z[i] : top;
    return top;
}

/* Vertex k right of x, with segment k (whose nearer end it is), as candidates. 0 if k is
 * beyond the reach, and with it everything farther. */
static inline int near_right(cam_scan *sc, size_t k)
{
    const size_t n = sc->p->n;
    const double *zs = sc->p->z;
    const double t = (sc->p->x[k] - sc->x) * sc->g->inv_a;
    if (t > 1.0)
        return 0;
    const double drop = drop_floor(sc, t);
    /* Vertex k, and segment k if its other end is not higher, are below the bar when z_k
     * is: one test for both, mostly. */
    const double z_hi = k + 1 < n && zs[k + 1] > zs[k] ? zs[k + 1] : zs[k];
    if (z_hi - drop < sc->bar)
        return 1;
    if (k + 1 < n)
        segment(sc, k, drop);
    if (zs[k] - drop >= sc->bar)
        vertex(sc, k, t);
    return 1;
}

/* Vertex j left of x, with segment j - 1 (whose nearer end it is), as candidates. 0 if j is
 * beyond the reach, and with it everything farther. */
static inline int near_left(cam_scan *sc, size_t j)
{
    const double *zs = sc->p->z;
    const double t = (sc->x - sc->p->x[j]) * sc->g->inv_a;
    if (t > 1.0)
        return 0;
    const double drop = drop_floor(sc, fabs(t)); /* t < 0 only off the profile's start */
    const double z_hi = j > 0 && zs[j - 1] > zs[j] ? zs[j - 1] : zs[j];
    if (z_hi - drop < sc->bar)
        return 1;
    if (j > 0)
        segment(sc, j - 1, drop);
    if (zs[j] - drop >= sc->bar)
        vertex(sc, j, fabs(t));
    return 1;
}

/* The right side: vertex k_x + 1, the group after it, the rest (see NEAR_GROUP). */
static void walk_right(cam_scan *sc, double z_cap)
{
    const size_t n = sc->p->n, k_0 = sc->k_x + 1, k_rest = k_0 + 1 + NEAR_GROUP;
    if (k_0 >= n || !near_right(sc, k_0))
        return;
    if (k_rest >= n) { /* the end of the profile is near: one by one */
        for (size_t k = k_0 + 1; k < n; k++)
            if (!near_right(sc, k))
                return;
        return;
    }
    const double t = (sc->p->x[k_0 + 1] - sc->x) * sc->g->inv_a;
    if (t > 1.0)
        return;
    if (!(group_top(sc->p->z + k_0 + 1) - drop_floor(sc, t) < sc->bar))
        for (size_t k = k_0 + 1; k < k_rest; k++)
            if (!near_right(sc, k))
                return;
    if (!(rest_right(sc, k_rest, z_cap) < sc->bar))
        walk_right_from(sc, k_rest, z_cap);
}

/* The left side: vertex k_x (with segment k_x - 1), the group before it, the rest. */
static void walk_left(cam_scan *sc, double z_cap)
{
    const size_t j_0 = sc->k_x;
    if (!near_left(sc, j_0))
        return;
    if (j_0 < 1 + NEAR_GROUP) { /* the start of the profile is near: one by one */
        for (size_t j = j_0; j-- > 0;)
            if (!near_left(sc, j))
                return;
        return;
    }
    const size_t k_rest = j_0 - NEAR_GROUP; /* one past the first vertex of the rest */
    const double *xs = sc->p->x, x = sc->x, inv_a = sc->g->inv_a;
    const double t = (x - xs[j_0 - 1]) * inv_a;
    if (t > 1.0)
        return;
    if (!(group_top(sc->p->z + j_0 - 1 - NEAR_GROUP) - drop_floor(sc, t) < sc->bar))
        for (size_t j = j_0 - 1; j >= k_rest; j--)
            if (!near_left(sc, j))
                return;
    /* The block walk meets segment k_rest - 1 again: the same candidate, no harm. */
    if (!(rest_left(sc, k_rest, z_cap) < sc->bar))
        walk_left_from(sc, k_rest, drop_floor(sc, (x - xs[k_rest]) * inv_a), z_cap);
}

/* The rounding of the lift z_a + s*(x - x_a) + rise at a segment's tangency is a few ulps of
 * its terms: |z_a|, and at most |s|*(2 a_e + dx) = 2 a_e |s| + |dz| each for the others (for
 * the segments a bound may rule out, the nearer end is within reach, so |x - x_a| <= a_e + dx,
 * and rise <= |s|*a_e, the super-ellipse's support function being at most m + 1). 2^-44 of
 * their sum, bounded by the profile's largest |z| (|dz| is at most twice that) and steepest
 * slope, covers it some 30 times over: on a road a few 1e-16 m, on a profile with a
 * near-vertical segment more, still far below any difference that matters. */
static double slack_of(const tirenv_cam__geom *g, const struct tirenv_profile *p)
{
    return 0x1p-44 * (3.0 * p->z_abs_max + 2.0 * g->a_e * p->slope_max);
}

/* Candidates, and why they suffice. The lift is the largest touching height over the profile
 * within reach, [x - a_e, x + a_e]. On each straight segment the touching height is concave
 * (see tirenv_cam__tangent), so its maximum over the part within reach is the tangency point
 * if that lies inside, or else a vertex (the ends of the reach never win). A flat segment's
 * tangency is straight below the bottom (u = 0), which is the ground height under x. A
 * vertical wall's points differ only in height, so only its top vertex can win. Hence: the
 * ground under x, every vertex within reach, and the tangency points of the sloped segments
 * with an end within reach or x on them. Of equal lifts the first in this order wins (its
 * rank): the ground under x (0); the vertices nearest first, left of x (1 + k_x - k) then
 * right (1 + k); the segments left to right (n + 1 + k).
 *
 * Pruning, which changes no result, ties included: a candidate is skipped only if a bound
 * puts it strictly below a lift some candidate reaches (bar_under). A point at height z and
 * distance t*a_e from the bottom touches at most z - drop_floor(t) high, so most candidates
 * are ruled out by a few multiplications, without a pow, and whole blocks of the profile by
 * their maxima. One search finds x; the walks outward from it are O(vertices within reach),
 * and on a long road a few vertices and blocks. No allocation.
 *
 * A sweep and a track add, without changing a bit of the result: a sharper floor, the
 * tangencies from the memo, and the search for x from the last position's segment. */
double tirenv_cam__lift(const tirenv_cam__geom *g, const tirenv_profile *p, double x,
                        double z_cap, tirenv_cam__sweep *sweep, tirenv_cam__track *track,
                        double *px, double *pz)
{
    const size_t n = p->n;
    /* The ground under x (at a wall the higher vertex; off the ends the flat extensions). */
    const size_t k_x = track ? tirenv_profile__segment_near(p, track->k_x < n ? track->k_x : 0, x)
                             : tirenv_profile__segment_at(p, x);
    const double q_x = tirenv_profile__height_in(p, x, k_x);
    cam_scan sc = {.g = g, .sweep = sweep, .p = p, .x = x, .k_x = k_x,
                   .slack = slack_of(g, p),
                   .best = {q_x, x, q_x, 0}};
    sc.bar = bar_under(&sc, q_x);
    if (k_x + 1 < n) /* the segment under x (or beside it, before the profile's start) */
        segment_try(&sc, k_x);
    walk_left(&sc, z_cap);
    walk_right(&sc, z_cap);
    if (track)
        track->k_x = k_x;
    if (px)
        *px = sc.best.p_x;
    if (pz)
        *pz = sc.best.p_z;
    return sc.best.Z;
}
