/* The road's local level (docs/models.md section 2.6): the morphological opening of the ground
 * by a level segment, exact on the polyline. SPDX-License-Identifier: Apache-2.0
 *
 * With a = width/2, the opening at x is
 *     O(x) = max over y in [x - a, x + a] of E(y),   E(y) = min of q over [y - a, y + a]:
 * the highest level segment of the given width lying nowhere above the ground and covering x.
 * E(y) is the lowest of three things: the ground at the window's left end, at its right end,
 * and the vertices strictly inside it. Between two consecutive events (where an end of the
 * window passes a vertex: y = x_k - a or x_k + a) the ends run along one straight segment each
 * and the inside vertices do not change, so E is the minimum of two straight lines and a
 * constant, a concave function whose maximum over the interval is at one of its ends or where
 * two of the three cross. So O(x) is the largest E over those candidates, found in one sweep
 * of the events with the inside minimum kept by a monotone deque: O(vertices within 2a of x),
 * after a binary search. Beyond the profile's ends the ground is flat at their heights; at a
 * wall the window's end takes the side it runs on, and a wall inside the window counts with
 * both of its vertices (its foot is ground too). */
#include "profile/profile_impl.h"

#include <math.h>

/* The ground along the window's end u = y + shift, as the line g0 + s*(y - y0) on the
 * interval of y being swept, from the vertex k at or before u (k = n - 1 or u before the
 * profile: flat). */
typedef struct {
    double g0, s, y0;
} end_line;

static end_line end_at(const struct tirenv_profile *p, size_t k, double u, double y0,
                       double shift)
{
    const double *xs = p->x, *zs = p->z;
    if (u < xs[0])
        return (end_line){zs[0], 0.0, y0};
    if (k + 1 >= p->n)
        return (end_line){zs[p->n - 1], 0.0, y0};
    const double s = (zs[k + 1] - zs[k]) / (xs[k + 1] - xs[k]);
    return (end_line){zs[k] + s * (y0 + shift - xs[k]), s, y0};
}

static double line_at(const end_line *l, double y)
{
    return l->g0 + l->s * (y - l->y0);
}

/* The largest of min(L(y), R(y), v) over [y0, y1]: at the ends or where two cross. */
static double interval_max(const end_line *L, const end_line *R, double v, double y0,
                           double y1)
{
    double cand[5] = {y0, y1, y0, y0, y0};
    size_t n = 2;
    if (L->s != R->s) {  /* L(y) = R(y) */
        const double y = y0 + (R->g0 - L->g0) / (L->s - R->s);
        if (y > y0 && y < y1)
            cand[n++] = y;
    }
    if (L->s != 0 && isfinite(v)) {
        const double y = y0 + (v - L->g0) / L->s;
        if (y > y0 && y < y1)
            cand[n++] = y;
    }
    if (R->s != 0 && isfinite(v)) {
        const double y = y0 + (v - R->g0) / R->s;
        if (y > y0 && y < y1)
            cand[n++] = y;
    }
    double best = -INFINITY;
    for (size_t i = 0; i < n; ++i) {
        const double e = fmin(fmin(line_at(L, cand[i]), line_at(R, cand[i])), v);
        best = fmax(best, e);
    }
    return best;
}

/* The first vertex with x_k > u (n if none). */
static size_t first_after(const struct tirenv_profile *p, double u)
{
    size_t lo = 0, hi = p->n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (p->x[mid] <= u)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* Deque capacity on the stack; windows with more vertices inside fall back to a scan of
 * the inside vertices per interval (correct, slower), which no road at a millimetre spacing
 * and a tire's width reaches. */
enum { LEVEL_DEQUE = 4096 };

double tirenv_profile_level(const tirenv_profile *p, double width, double x)
{
    if (!(width > 0) || !isfinite(width) || !isfinite(x))
        return NAN;
    const double a = 0.5 * width, *xs = p->x, *zs = p->z;
    const size_t n = p->n;
    const double y_lo = x - a, y_hi = x + a;
    /* Events: x_k - a for x < x_k < x + 2a (the right end passes vertex k), x_k + a for
     * x - 2a < x_k < x (the left end passes it), in increasing order; iA and iB walk them. */
    size_t iA = first_after(p, x), iB = first_after(p, x - 2 * a);
    /* The window's ends at the sweep's start, and the vertices strictly inside it: the
     * inside set is (kL, kR] with kL the last vertex at or before the left end u_L, kR the
     * last before the right end (index + 1 as first_after gives). */
    size_t kL = iB, kR = iA;  /* first_after(u_L), first_after(u_R) at the first interval */
    size_t dq[LEVEL_DEQUE], head = 0, tail = 0, next_in = 0;
    int deque_ok = 1;
    double best = -INFINITY, y0 = y_lo;
    while (y0 < y_hi) {
        double y1 = y_hi;
        while (iA < n && xs[iA] - a <= y0)
            ++iA;
        while (iB < n && xs[iB] + a <= y0)
            ++iB;
        if (iA < n && xs[iA] < x + 2 * a)
            y1 = fmin(y1, xs[iA] - a);
        if (iB < n && xs[iB] < x)
            y1 = fmin(y1, xs[iB] + a);
        if (!(y1 > y0))  /* cannot happen: every event left is beyond y0 */
            break;
        const double ym = 0.5 * (y0 + y1), uL = ym - a, uR = ym + a;
        while (kL < n && xs[kL] <= uL)
            ++kL;
        while (kR < n && xs[kR] <= uR)
            ++kR;
        /* Inside: vertices kL .. kR - 1 (x_kL > u_L, x_{kR-1} <= u_R, and none equals u_R
         * away from rounding, as ym is strictly between events). */
        if (next_in < kL)
            next_in = kL;
        double v = INFINITY;
        if (deque_ok) {
            for (; next_in < kR; ++next_in) {
                while (tail > head && zs[dq[(tail - 1) % LEVEL_DEQUE]] >= zs[next_in])
                    --tail;
                if (tail - head == LEVEL_DEQUE) {
                    deque_ok = 0;
                    break;
                }
                dq[tail++ % LEVEL_DEQUE] = next_in;
            }
            while (tail > head && dq[head % LEVEL_DEQUE] < kL)
                ++head;
            if (deque_ok && tail > head)
                v = zs[dq[head % LEVEL_DEQUE]];
        }
        if (!deque_ok) {
            v = INFINITY;
            for (size_t k = kL; k < kR; ++k)
                v = fmin(v, zs[k]);
        }
        const end_line L = end_at(p, kL > 0 ? kL - 1 : 0, uL, y0, -a);
        const end_line R = end_at(p, kR > 0 ? kR - 1 : 0, uR, y0, a);
        best = fmax(best, interval_max(&L, &R, v, y0, y1));
        y0 = y1;
    }
    return best;
}
