/* SPDX-License-Identifier: Apache-2.0 */
/* Ground that slips between two rays (docs/models.md section 4, "geometric penetration"): a
 * feature narrower than the ray spacing at its distance that pokes into the tread while no
 * ray meets it. The elements touch the ground only along their rays, so such a feature is
 * invisible to the model, while a real tread, a continuous band, would rest on it. */
#include "model/springs_impl.h"

#include <math.h>
#include "profile/profile_impl.h"

/* A ground point a ray stands for, and the vertex count up to it. */
typedef struct {
    double X, Z;  /* m; Z only once needed (has_Z) */
    size_t le;    /* how many vertices lie at or before X */
    int crossing; /* X, Z is the ray's first crossing (else the ground under its tip) */
    int has_Z;
} anchor;

/* What ray i sees of the ground: its first crossing if it has one within reach; else the
 * ground under the tip of the ray (it met no ground that far). Its vertex count le, searched
 * from the vertex hint (where the ray's walk ended, if known: then O(1)). */
static anchor anchor_of(const tirenv_profile *p, const tirenv_springs__fan_rays *r, double x,
                        double z, size_t i, const double rho[], size_t hint)
{
    const double *X = p->x;
    const size_t n = p->n;
    anchor A = {.crossing = isfinite(rho[i])};
    const double len = A.crossing ? rho[i] : r->rho_max;
    A.X = x + len * r->sin_t[i];
    if (A.crossing) {
        A.Z = z - len * r->cos_t[i];
        A.has_Z = 1;
    }
    size_t le = hint < n ? hint : n;
    while (le > 0 && X[le - 1] > A.X)
        --le;
    while (le < n && X[le] <= A.X)
        ++le;
    A.le = le;
    return A;
}

/* The ground height under an anchor that is not a crossing (tirenv_profile_height's rule). */
static void anchor_Z(const tirenv_profile *p, anchor *A)
{
    if (A->has_Z)
        return;
    const double *X = p->x, *Z = p->z;
    const size_t n = p->n;
    if (A->le == 0)
        A->Z = Z[0];
    else if (A->le == n)
        A->Z = Z[n - 1];
    else {
        const size_t k = A->le - 1; /* X[k] <= A->X < X[k + 1] */
        A->Z = A->X == X[k] && k >= 1 && X[k - 1] == X[k]
                   ? fmax(Z[k - 1], Z[k])
                   : Z[k] + (Z[k + 1] - Z[k]) * ((A->X - X[k]) / (X[k + 1] - X[k]));
    }
    A->has_Z = 1;
}

/* How far (X, Z) lies inside the tread between rays k and k + 1: on the centre's side of the
 * chord joining their tread points (m, negative outside). */
static double into_tread(const tirenv_springs__fan_rays *r, double x, double z, size_t k,
                         const double tread[], double X, double Z)
{
    const double ax = x + tread[k] * r->sin_t[k], az = z - tread[k] * r->cos_t[k];
    const double bx = x + tread[k + 1] * r->sin_t[k + 1], bz = z - tread[k + 1] * r->cos_t[k + 1];
    const double ex = bx - ax, ez = bz - az, len = hypot(ex, ez);
    if (!(len > 0))
        return -INFINITY;
    /* Signed distances from the chord, positive on the centre's side. */
    const double side_c = (ex * (z - az) - ez * (x - ax)) / len;
    const double side_p = (ex * (Z - az) - ez * (X - ax)) / len;
    return side_c > 0 ? side_p : -side_p;
}

/* The ray pair (k, k + 1) among rays lo..hi (consecutive, lo < hi, angles ascending) whose
 * wedge holds (X, Z), the nearest one if none does. */
static size_t wedge_of(const tirenv_springs__fan_rays *r, double x, double z, size_t lo,
                       size_t hi, double X, double Z)
{
    const double phi = atan2(X - x, z - Z);
    size_t k = lo;
    while (k + 1 < hi && atan2(r->sin_t[k + 1], r->cos_t[k + 1]) < phi)
        ++k;
    return k;
}

/* The width of the ground around vertex v (inside the tread) where it is inside the tread:
 * outward from v to the first vertex outside on either side (not beyond the vertices lo_v
 * and hi_v), the crossing interpolated on the last segment. */
static double width_in_tread(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                             double x, double z, size_t lo, size_t hi, const double tread[],
                             long v, long end_a, long end_b)
{
    const double *X = p->x, *Z = p->z;
    double edge[2];
    const long ends[2] = {end_a, end_b};
    for (int e = 0; e < 2; ++e) {
        const long step = ends[e] < v ? -1 : 1;
        long j = v;
        double d_in = into_tread(r, x, z, wedge_of(r, x, z, lo, hi, X[j], Z[j]), tread, X[j],
                                 Z[j]);
        edge[e] = X[j];
        while (j != ends[e]) {
            const long k = j + step;
            const double d = into_tread(r, x, z, wedge_of(r, x, z, lo, hi, X[k], Z[k]), tread,
                                        X[k], Z[k]);
            if (!(d > 0)) {
                edge[e] = X[j] + (X[k] - X[j]) * (d_in / (d_in - d));
                break;
            }
            j = k;
            d_in = d;
            edge[e] = X[j];
        }
    }
    return fabs(edge[1] - edge[0]);
}

/* Looks for an unseen feature between the anchors A and B of rays lo < hi: the vertices
 * strictly between them in X, their height above the line A B (towards the centre), and
 * the runs of them that stand above it. A feature lies wholly between the rays, narrower
 * than their spacing, if its run rises from the line and falls back to it between them; a
 * run that begins at the first vertex or ends at the last is ground that goes on beyond a
 * ray (a corner a ray lands on, an obstacle whose edge has just come between two rays),
 * which the rays do see. It counts if it stands more than tol above the line and reaches
 * more than tol into the tread. */
static int check_pair(const tirenv_profile *p, const tirenv_springs__fan_rays *r, double x,
                      double z, size_t lo, size_t hi, anchor *pA, anchor *pB,
                      const double tread[], double tol, tirenv_springs__feature *f)
{
    anchor_Z(p, pA);
    anchor_Z(p, pB);
    const anchor A = *pA, B = *pB;
    const double *X = p->x, *Z = p->z;
    const int dir = B.X > A.X ? 1 : -1;
    /* The vertices strictly between A.X and B.X, in walking order from A. */
    const anchor L = dir > 0 ? A : B, R = dir > 0 ? B : A;
    const long first = (long)L.le;
    long last = (long)R.le - 1;
    while (last >= 0 && X[last] >= R.X)
        --last;
    if (last - first + 1 < 3)
        return 0;
    const double ex = B.X - A.X, ez = B.Z - A.Z, len = hypot(ex, ez);
    const double side_c = (ex * (z - A.Z) - ez * (x - A.X)) / len;
    const double sgn = side_c > 0 ? 1 : -1;
    const long start = dir > 0 ? first : last, stop = dir > 0 ? last : first;
    /* Above the line means by more than its rounding: ground that lies on the line (a flat
     * between two crossings on it) is not above it. */
    const double on_line = 1e-9 * (len + fabs(A.Z) + fabs(B.Z) + fabs(A.X) + fabs(B.X));
    long run_start = -1;
    double best_h = 0;
    for (long j = start;; j += dir) {
        const int inside = j != stop + dir;
        const double h = inside ? sgn * (ex * (Z[j] - A.Z) - ez * (X[j] - A.X)) / len : 0;
        if (inside && h > on_line) {
            if (run_start < 0) {
                run_start = j;
                best_h = 0;
            }
            best_h = h > best_h ? h : best_h;
            continue;
        }
        if (run_start >= 0) {
            const long run_end = j - dir;
            const int seen = run_start == start || run_end == stop;
            if (!seen && best_h > tol) {
                /* Any vertex of it deeper into the tread than the rays' spacing there: beyond
                 * the model's own resolution (a ray misses a corner by up to about a spacing
                 * too). */
                for (long v = run_start; v != j; v += dir) {
                    const size_t w = wedge_of(r, x, z, lo, hi, X[v], Z[v]);
                    const double depth = into_tread(r, x, z, w, tread, X[v], Z[v]);
                    const double dist = hypot(X[v] - x, z - Z[v]);
                    const double dot =
                        r->sin_t[w] * r->sin_t[w + 1] + r->cos_t[w] * r->cos_t[w + 1];
                    const double cross =
                        r->sin_t[w] * r->cos_t[w + 1] - r->cos_t[w] * r->sin_t[w + 1];
                    const double spacing = dist * atan2(fabs(cross), dot);
                    if (depth > spacing && depth > tol) {
                        *f = (tirenv_springs__feature){
                            .X = X[v], .Z = Z[v], .rise = best_h, .depth = depth,
                            .width = width_in_tread(p, r, x, z, lo, hi, tread, v,
                                                    run_start - dir, j),
                            .distance = dist, .spacing = spacing};
                        return 1;
                    }
                }
            }
            run_start = -1;
        }
        if (!inside)
            break;
    }
    return 0;
}

/* Checks the pair of rays k and m of one side; *hint: a vertex near k's anchor. */
static int check_rays(const tirenv_profile *p, const tirenv_springs__fan_rays *r, double x,
                      double z, size_t k, size_t m, const double rho[], const double tread[],
                      double tol, size_t *hint, tirenv_springs__feature *f)
{
    anchor A = anchor_of(p, r, x, z, k, rho, *hint);
    anchor B = anchor_of(p, r, x, z, m, rho, A.le);
    *hint = B.le;
    if ((A.le < B.le ? B.le - A.le : A.le - B.le) < 3)
        return 0;
    return check_pair(p, r, x, z, k < m ? k : m, k < m ? m : k, &A, &B, tread, tol, f);
}

int tirenv_springs__unseen_pairs(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                                 double x, double z, const double rho[], const double tread[],
                                 const size_t pairs[], size_t n_pairs, double tol,
                                 tirenv_springs__feature *f)
{
    size_t hint = tirenv_profile__segment_at(p, x);
    for (size_t q = 0; q < n_pairs; ++q)
        if (check_rays(p, r, x, z, pairs[2 * q], pairs[2 * q + 1], rho, tread, tol, &hint, f))
            return 1;
    return 0;
}

int tirenv_springs__unseen_feature(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                                   double x, double z, size_t a, size_t b, const double rho[],
                                   const double tread[], double tol,
                                   tirenv_springs__feature *f)
{
    const size_t i0 = r->i0;
    size_t hint = tirenv_profile__segment_at(p, x);
    for (int side = 0; side < 2; ++side) {
        const long dir = side ? 1 : -1;
        const size_t count = side ? b - i0 : i0 - a; /* rays beyond i0 on this side */
        /* Each ray with its two inner neighbours: a feature between neighbours, and one only
         * the ray between two others meets, on its side (not resolved either). */
        for (size_t step = 1; step <= count; ++step) {
            const size_t m = (size_t)((long)i0 + dir * (long)step);
            for (size_t gap = 1; gap <= 2 && gap <= step; ++gap)
                if (check_rays(p, r, x, z, (size_t)((long)m - dir * (long)gap), m, rho, tread,
                               tol, &hint, f))
                    return 1;
        }
    }
    /* And the two rays either side of the straight-down one. */
    return a < i0 && i0 < b &&
           check_rays(p, r, x, z, i0 - 1, i0 + 1, rho, tread, tol, &hint, f);
}
