/* SPDX-License-Identifier: Apache-2.0 */
/* Ray casting of the radial elements onto the ground polyline (docs/models.md section 4,
 * "geometric penetration"). */
#include "model/springs_impl.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "profile/profile_impl.h"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* How a walk ended, at vertex j: */
enum {
    RAY_HIT,   /* f(j) <= 0: the first crossing lies on the segment ending at j */
    RAY_WALL,  /* the same on a vertical wall: rho does not depend on z */
    RAY_REACH, /* f(j) > 0 but j lies beyond the ray's reach: no crossing */
    RAY_END,   /* every vertex passed: the flat extension past the last one decides */
    RAY_DOWN,  /* the ray straight down (no walk) */
    RAY_NONE   /* the centre on or below the ground: nothing to reuse */
};

/* The ground is a graph z = g(X) with vertical walls and the centre lies above it, so walking
 * from the centre along X in the ray's direction, the first vertex where the ray is at or below
 * the ground closes the segment that holds the first crossing: f(X) = ray height - ground is
 * linear between vertices. The walk starts at vertex j, whose predecessor on the walk (the
 * centre if j is first_j, the first vertex ahead of x, else vertex j - dir) is known to lie
 * above the ground with everything before it. *f_min takes the minimum of f over every point
 * passed (all of them strictly before the vertex that ends the walk); it is what bounds how far
 * the centre may sink before the walk could end elsewhere. With s = |sin_t|, inv_s = 1/s (the
 * ray's length per metre of walk), drop = cos_t / s (its descent per metre of walk) and
 * reach = rho_max s (the walk length of the whole ray) come from the caller. The slope of the
 * face hit is left to slope_drho: most rays of a fan never need it. */
static inline double walk(const tirenv_profile *p, double x, double z, double f0, long first_j,
                          long j, int dir, double inv_s, double drop, double reach,
                          double cos_t, double rho_max, long *j_end, int *kind, double *f_min)
{
    const double *X = p->x, *Z = p->z;
    const long n = (long)p->n;
    double a_prev, f_prev;                  /* walk distance and f at the last check point */
    if (j == first_j) {
        a_prev = 0;
        f_prev = f0;
    } else {
        const long jp = j - dir;
        a_prev = dir * (X[jp] - x);
        f_prev = z - a_prev * drop - Z[jp];
    }
    double fm = f_prev < *f_min ? f_prev : *f_min;
    for (; j >= 0 && j < n; j += dir) {
        const double a = dir * (X[j] - x);
        const double f = z - a * drop - Z[j];
        if (f <= 0) {
            *j_end = j;
            *f_min = fm;
            if (a == a_prev) {              /* a vertical wall: rho does not depend on z */
                *kind = RAY_WALL;
                return a <= reach ? a * inv_s : INFINITY;
            }
            *kind = RAY_HIT;
            const double a_hit = a_prev + f_prev * (a - a_prev) / (f_prev - f);
            return a_hit > reach ? INFINITY : a_hit * inv_s;
        }
        if (a > reach) {                    /* f(j) > 0 is checked again on reuse */
            *j_end = j;
            *kind = RAY_REACH;
            *f_min = fm;
            return INFINITY;
        }
        fm = f < fm ? f : fm;
        a_prev = a;
        f_prev = f;
    }
    *j_end = j;
    *kind = RAY_END;
    *f_min = fm;
    /* Past the last vertex the ground is flat at the end height, and f > 0 at a_prev. */
    if (cos_t <= 0)
        return INFINITY;
    const double rho = (z - Z[dir > 0 ? n - 1 : 0]) / cos_t;
    return rho > rho_max ? INFINITY : rho;
}

/* d(rho)/dz of a ray whose walk ended at vertex j in the way kind, with rho finite: on a face
 * of slope dZ/dX, rho (cos_t + sin_t slope) = z - (the face's height under the centre). */
static double slope_drho(const tirenv_profile *p, long j, int dir, int kind, double sin_t,
                         double cos_t)
{
    const double *X = p->x, *Z = p->z;
    const long n = (long)p->n;
    switch (kind) {
    case RAY_HIT: {
        const long jp = j - dir;            /* the hit segment is [jp, j]; -1 or n: flat */
        if (!(jp >= 0 && jp < n))
            return 1 / cos_t;
        /* 1 / (cos_t + sin_t slope) with slope = dZ/dX, in one division: dX != 0 (not a
         * wall). */
        const double dX = X[j] - X[jp], dZ = Z[j] - Z[jp];
        return dX / (cos_t * dX + sin_t * dZ);
    }
    case RAY_END:
        return 1 / cos_t;
    case RAY_DOWN:
        return 1;
    default:                                /* a wall, or no crossing */
        return 0;
    }
}

/* First vertex strictly ahead of x in each direction, given k = segment_at(x). */
static long first_vertex(const tirenv_profile *p, double x, size_t k, int dir)
{
    const double *X = p->x;
    if (dir > 0)
        return X[k] <= x ? (long)k + 1 : (long)k;
    long j = X[k] < x ? (long)k : (long)k - 1;
    while (j >= 0 && X[j] >= x)
        --j;
    return j;
}

/* The ground's height at x as a ray leaving x toward dir meets it: at a wall under x (two
 * vertices at x, k = segment_at(x) its last, first_back = first_vertex(x, -1) the vertex
 * before its first, read only for dir < 0) the wall's end on that side, its first vertex
 * behind and its last ahead; else g, the height under x. A walk anchors its first segment
 * there: with g, the higher end of the wall, a ray leaving a step's foot crossed the line from
 * the wall's top to the next vertex, ground that is not there (over
 * tests/data/profile_good.csv's wall, the rays behind the centre up to 43 mm deeper than at
 * x +- 1e-12 m, F_z 167 N higher). */
static double side_height(const tirenv_profile *p, double x, size_t k, long first_back,
                          double g, int dir)
{
    const double *X = p->x, *Z = p->z;
    if (!(k >= 1 && X[k] == x && X[k - 1] == x))
        return g;
    return dir > 0 ? Z[k] : Z[first_back + 1];
}

double tirenv_springs__ray(const tirenv_profile *p, double x, double z, double sin_t,
                           double cos_t, double rho_max, double *drho_dz)
{
    return tirenv_springs__ray_at(p, x, tirenv_profile__segment_at(p, x),
                                  tirenv_profile_height(p, x), z, sin_t, cos_t, rho_max,
                                  drho_dz);
}

/* The walk itself; k and g depend on x alone, so a caller casting many rays from one centre
 * finds them once (two binary searches saved per ray). Most rays hit the segment under the
 * centre, so this is O(1) per ray after one O(log n) search. */
double tirenv_springs__ray_at(const tirenv_profile *p, double x, size_t k, double g, double z,
                              double sin_t, double cos_t, double rho_max, double *drho_dz)
{
    const double f0 = z - g;
    *drho_dz = 0;
    if (f0 <= 0)
        return 0; /* centre on or below the ground */
    if (sin_t == 0) {
        *drho_dz = 1;
        return f0 <= rho_max ? f0 : INFINITY;
    }
    const int dir = sin_t > 0 ? 1 : -1;
    const double s = fabs(sin_t);
    const long first_j = first_vertex(p, x, k, dir);
    const double f_side = z - side_height(p, x, k, first_j, g, dir);
    long j_end;
    int kind;
    double f_min = f_side;
    const double rho = walk(p, x, z, f_side, first_j, first_j, dir, 1 / s, cos_t / s,
                            rho_max * s, cos_t, rho_max, &j_end, &kind, &f_min);
    if (isfinite(rho))
        *drho_dz = slope_drho(p, j_end, dir, kind, sin_t, cos_t);
    return rho;
}

void tirenv_springs__fan_rays_fill(size_t n, const double sin_t[], const double cos_t[],
                                   double rho_max, double inv_s[], double drop[],
                                   double reach[])
{
    for (size_t i = 0; i < n; ++i) {
        const double s = fabs(sin_t[i]);
        inv_s[i] = 1 / s;
        drop[i] = cos_t[i] / s; /* +-infinity straight down: never used there */
        reach[i] = rho_max * s;
    }
}

int tirenv_springs__fan_rays_ordered(const tirenv_springs__fan_rays *r, size_t n)
{
    const size_t i0 = r->i0;
    if (!(i0 < n))
        return 0;
    for (int side = 0; side < 2; ++side) { /* the first ray's are INFINITY and 0 */
        double drop_prev = INFINITY, reach_prev = 0;
        for (size_t step = 1, count = side ? n - 1 - i0 : i0; step <= count; ++step) {
            const size_t i = side ? i0 + step : i0 - step;
            if (!(r->drop[i] <= drop_prev && r->reach[i] >= reach_prev))
                return 0;
            drop_prev = r->drop[i];
            reach_prev = r->reach[i];
        }
    }
    return 1;
}

/* fmax for finite heights, inlined (GCC calls libm's for its NaN rules: 2 % of the springs
 * model over a road). */
static inline double higher(double a, double b) { return b > a ? b : a; }

/* An upper bound of the ground over [x, x + dir len]: g, every vertex inside, and the first
 * vertex beyond (which bounds the segment that crosses the end), whole blocks at a time from
 * the block maxima where a block lies inside. */
static double side_max(const tirenv_profile *p, double x, double g, long j, int dir, double len,
                       long *j_end)
{
    const double *X = p->x, *Z = p->z, *Zb = p->z_block;
    const long n = (long)p->n, B = TIRENV_PROFILE__BLOCK;
    double m = g;
    if (dir > 0) {
        const double lim = x + len;
        while (j < n) {
            if (j % B == 0 && j + B < n && X[j + B] <= lim) { /* block j/B: vertices j..j+B */
                m = higher(m, Zb[j / B]);
                j += B;
                continue;
            }
            m = higher(m, Z[j]);
            if (X[j] > lim)
                break;
            ++j;
        }
    } else {
        const double lim = x - len;
        while (j >= 0) {
            if (j % B == 0 && j >= B && X[j - B] >= lim) { /* block j/B - 1: j-B..j */
                m = higher(m, Zb[j / B - 1]);
                j -= B;
                continue;
            }
            m = higher(m, Z[j]);
            if (X[j] < lim)
                break;
            --j;
        }
    }
    *j_end = j;
    return m;
}

void tirenv_springs__fan_origin_at(const tirenv_profile *p, double x, double rho_max,
                                   size_t k_hint, tirenv_springs__fan_origin *o)
{
    const size_t k = tirenv_profile__segment_near(p, k_hint, x);
    o->k = k;
    o->x = x;
    o->g = tirenv_profile__height_in(p, x, k);
    o->first[0] = first_vertex(p, x, k, -1);
    o->first[1] = first_vertex(p, x, k, 1);
    o->g_side[0] = side_height(p, x, k, o->first[0], o->g, -1);
    o->g_side[1] = side_height(p, x, k, o->first[0], o->g, 1);
    long end[2];
    o->z_max[0] = side_max(p, x, o->g, o->first[0], -1, rho_max, &end[0]);
    o->z_max[1] = side_max(p, x, o->g, o->first[1], 1, rho_max, &end[1]);
    o->n_reach = end[1] - end[0];
    /* The reuse test compares computed f = (z - a drop) - Z at two heights; each rounding is
     * at most an ulp of |z| + a drop + |Z| <= |z| + rho_max + max |Z| for every point a walk
     * passes (a <= reach), and the centre can sink at most by f0 <= |z| + |g|: see
     * tirenv_springs__fan_reuse. */
    o->tol = 8 * DBL_EPSILON * (fabs(o->g) + rho_max + p->z_abs_max);
}

/* The rounding allowance at centre height z. */
static double fan_tol(const tirenv_springs__fan_origin *o, double z)
{
    return o->tol + 8 * DBL_EPSILON * fabs(z);
}

/* Why reuse is exact. Along one ray from one x, f_k(z) = (z - a_k drop) - Z_k at every point
 * k; rounding is monotone, so the computed f_k never decreases when z grows. A walk that
 * ended at vertex j with every earlier point above the ground (f > 0) therefore ends at j
 * again at any higher z as long as j itself is still at or below the ray (checked by
 * computing f_j at the new z, exactly as the walk would); at a lower z it does if the centre
 * sank by less than the smallest earlier f, less the rounding allowance (z > z_low). The
 * crossing on the segment ending at j is then computed from the same two points with the
 * same operations as the walk: the same bits. The rounding allowance: with t = a drop <=
 * rho_max for every point passed (a <= reach), the computed f at the lower height z' stays
 * positive if z - z' < f_min - u (|z - t| + |z' - t|) - 2 u f_min (u the unit roundoff, the
 * last term the rounding of z_low itself); 8 DBL_EPSILON (|z| + |g| + rho_max + max |Z|) =
 * 16 u (...) exceeds that, since f_min <= f0 = z - g. */
/* Ray i's rho at z from its memo, where the memo provably holds (see above): 1, or 0 with
 * nothing written. f0 = z - o->g > 0; side is ray i's (0: i < i0, 1: i > i0; either for
 * the straight-down ray, whose memo needs neither), a constant where the callers inline it,
 * so that the direction and the side's first vertex are not found again for every ray. The
 * commonest kind is tested first. */
static inline int reuse_ray(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                            const tirenv_springs__fan_rays *r, double z, double f0, size_t i,
                            int side, double rho[], const tirenv_springs__ray_memo *m)
{
    const double *X = p->x, *Z = p->z;
    const double x = o->x;
    if (!(z > m->z_low))
        return 0;
    const int dir = side ? 1 : -1;
    const long j = m->j;
    const int kind = m->kind;
    if (kind == RAY_HIT || kind == RAY_WALL) {
        const double a_j = dir * (X[j] - x);
        const double f = z - a_j * r->drop[i] - Z[j];
        if (f > 0)
            return 0; /* the crossing moved past j */
        const double reach = r->reach[i];
        if (kind == RAY_WALL) {
            rho[i] = a_j <= reach ? a_j * r->inv_s[i] : INFINITY;
            return 1;
        }
        double a_prev, f_prev;
        if (j == o->first[side]) {
            a_prev = 0;
            f_prev = z - o->g_side[side];
        } else {
            a_prev = dir * (X[j - dir] - x);
            f_prev = z - a_prev * r->drop[i] - Z[j - dir];
        }
        const double a_hit = a_prev + f_prev * (a_j - a_prev) / (f_prev - f);
        rho[i] = a_hit > reach ? INFINITY : a_hit * r->inv_s[i];
        return 1;
    }
    switch (kind) {
    case RAY_DOWN:
        rho[i] = f0 <= r->rho_max ? f0 : INFINITY;
        return 1;
    case RAY_REACH: {
        const double a_j = dir * (X[j] - x);
        if (!(z - a_j * r->drop[i] - Z[j] > 0))
            return 0; /* the ground beyond reach came up to the ray: walk again */
        rho[i] = INFINITY;
        return 1;
    }
    case RAY_END: {
        const double cos_t = r->cos_t[i];
        if (cos_t <= 0) {
            rho[i] = INFINITY;
            return 1;
        }
        const double rr = (z - Z[dir > 0 ? (long)p->n - 1 : 0]) / cos_t;
        rho[i] = rr > r->rho_max ? INFINITY : rr;
        return 1;
    }
    default:
        return 0;
    }
}

/* The rays of one side (side 0: i0 - step, 1: i0 + step) from step 1 outward whose memos
 * hold at z, their rho written: the first step whose memo fails (count + 1 if none). */
static inline size_t reuse_side(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                const tirenv_springs__fan_rays *r, double z, double f0,
                                int side, size_t count, double rho[],
                                const tirenv_springs__ray_memo memo[])
{
    const size_t i0 = r->i0;
    size_t step = 1;
    while (step <= count && reuse_ray(p, o, r, z, f0, side ? i0 + step : i0 - step, side, rho,
                                      &memo[side ? i0 + step : i0 - step]))
        ++step;
    return step;
}

typedef double v2d __attribute__((vector_size(2 * sizeof(double))));
typedef long long v2l __attribute__((vector_size(2 * sizeof(long long))));

/* Two doubles from p and p + 1, in that order (p need not be aligned to 16 bytes). */
static inline v2d load2(const double *p)
{
    v2d v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void store2(double *p, v2d v) { memcpy(p, &v, sizeof v); }

/* Lane by lane, INFINITY where a > b or (if check_c) c <= 0, else v (a NaN compares false,
 * as in the scalar selects it pairs with): the walk's rho past reach. With SSE2 in its
 * instructions: GCC takes the masks of its vector extensions'
 * comparisons as booleans, through the integer registers lane by lane (some 14 instructions
 * a pair instead of 5). */
static inline v2d inf_past(v2d a, v2d b, v2d c, const int check_c, v2d v)
{
    const v2d inf = {INFINITY, INFINITY}, zero = {0, 0};
#if defined(__SSE2__)
    __m128d out = _mm_cmpgt_pd((__m128d)a, (__m128d)b);
    if (check_c)
        out = _mm_or_pd(out, _mm_cmple_pd((__m128d)c, (__m128d)zero));
    return (v2d)_mm_or_pd(_mm_and_pd(out, (__m128d)inf), _mm_andnot_pd(out, (__m128d)v));
#else
    const v2l out = check_c ? (a > b) | (c <= zero) : a > b;
    return (v2d)(((v2l)inf & out) | ((v2l)v & ~out));
#endif
}

/* Whether a <= b in both lanes (with SSE2 by its mask: see inf_past). */
static inline int both_le(v2d a, v2d b)
{
#if defined(__SSE2__)
    return _mm_movemask_pd(_mm_cmple_pd((__m128d)a, (__m128d)b)) == 3;
#else
    const v2l in = a <= b;
    return in[0] && in[1];
#endif
}

/* A run's memo, kept as two 16-byte halves where a memo is 32 bytes (LP64), stored into two
 * memos side by side: GCC stores a memo assigned whole field by field, four stores; with SSE2
 * two. */
enum { memo_halves = sizeof(tirenv_springs__ray_memo) == 32 };
typedef struct {
    tirenv_springs__ray_memo m;
#if defined(__SSE2__)
    __m128i h[2];
#endif
} run_memo;

static inline run_memo run_memo_of(const tirenv_springs__ray_memo *m)
{
    run_memo r = {.m = *m};
#if defined(__SSE2__)
    if (memo_halves) {
        r.h[0] = _mm_loadu_si128((const __m128i *)(const void *)m);
        r.h[1] = _mm_loadu_si128((const __m128i *)(const void *)m + 1);
    }
#endif
    return r;
}

static inline void store_memo2(tirenv_springs__ray_memo *m, const run_memo *r)
{
#if defined(__SSE2__)
    if (memo_halves) {
        __m128i *const q = (__m128i *)(void *)m;
        _mm_storeu_si128(q, r->h[0]);
        _mm_storeu_si128(q + 1, r->h[1]);
        _mm_storeu_si128(q + 2, r->h[0]);
        _mm_storeu_si128(q + 3, r->h[1]);
        return;
    }
#endif
    m[0] = r->m;
    m[1] = r->m;
}

/* Runs of rays that end alike, for a fresh fan with its resumption order known
 * (r->ordered): each ray as walk() resumed at j would take it, by the same operations on the
 * same operands (the same bits), without the walk's setup. Each returns the first step it did
 * not take, with *f_min the running minimum after the last ray it took.
 *
 * A run's memos are one: its first ray's f_prev bounds every later one's from below, so the
 * running minimum, and z_low, are the same after each ray of the run. From the centre f_prev
 * is f_side for all; else at the vertex before j (a > 0, passed) a ray further out has a drop
 * no larger (r->ordered), so its computed f = (z - a drop) - Z is no smaller (rounding is
 * monotone). That first f_prev is taken even where the first ray leaves the run: walk(),
 * resumed at j for it, takes the same minimum first. With the memos one, two rays are taken
 * a step, side by side in memory (lanes apart, each lane the one-by-one loop's operations). */

/* The running minimum after the first ray of a run at step (from the centre, f_side; else
 * its f at the vertex before j, a_p ahead at height Z_p). */
static inline double run_f_min(const tirenv_springs__fan_rays *r, double z, int side,
                               size_t step, int from_centre, double f_side, double a_p,
                               double Z_p, double fm)
{
    const size_t i = side ? r->i0 + step : r->i0 - step;
    const double f_prev = from_centre ? f_side : z - a_p * r->drop[i] - Z_p;
    return f_prev < fm ? f_prev : fm;
}

/* After a walk that passed the profile's last vertex (j = -1 or n): every ray further out
 * passes it too (it lies higher at every vertex), and ends on the flat ground past the end. */
static inline size_t end_run(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                             const tirenv_springs__fan_rays *r, double z, int side,
                             size_t step, size_t count, long j, double *f_min, double tol,
                             double rho[], tirenv_springs__ray_memo memo[])
{
    const long n = (long)p->n, first_j = o->first[side];
    const int dir = side ? 1 : -1;
    const size_t i0 = r->i0;
    const double rho_max = r->rho_max, zZ = z - p->z[dir > 0 ? n - 1 : 0];
    const int from_centre = j == first_j; /* no vertex passed: the anchor before j */
    const double a_prev = from_centre ? 0 : dir * (p->x[j - dir] - o->x);
    const double Z_prev = from_centre ? 0 : p->z[j - dir], f_side = z - o->g_side[side];
    const double fm = run_f_min(r, z, side, step, from_centre, f_side, a_prev, Z_prev, *f_min);
    const tirenv_springs__ray_memo mm = {.j = j, .kind = RAY_END, .z_low = z - (fm - tol),
                                         .drho = NAN};
    const run_memo rm = run_memo_of(&mm);
    const v2d zz = {zZ, zZ}, big = {rho_max, rho_max};
    const double *const cos_r = r->cos_t; /* (in a local: see hit_pairs) */
    for (; step + 1 <= count; step += 2) {
        const size_t lo = side ? i0 + step : i0 - step - 1; /* the pair's first in memory */
        const v2d c = load2(cos_r + lo), q = zz / c;
        /* the walk's: INFINITY where cos_t <= 0, or where q > rho_max, else q */
        store2(rho + lo, inf_past(q, big, c, 1, q));
        store_memo2(memo + lo, &rm);
    }
    if (step <= count) {
        const size_t i = side ? i0 + step : i0 - step;
        const double cos_t = r->cos_t[i];
        double v = INFINITY;
        if (!(cos_t <= 0)) {
            const double q = zZ / cos_t;
            v = q > rho_max ? INFINITY : q;
        }
        rho[i] = v;
        memo[i] = mm;
        ++step;
    }
    *f_min = fm;
    return step;
}

/* hit_run's pairs from step while both rays meet the ground at j, compiled apart for a run
 * from the centre (f_prev = f_side) and from a vertex (f_prev at a_p, Z_p): the first step
 * not taken. */
static inline __attribute__((always_inline)) size_t
hit_pairs(const tirenv_springs__fan_rays *r, double z, int side, size_t step, size_t count,
          double a_j, double Z_j, double a_p, double Z_p, double f_side,
          const tirenv_springs__ray_memo *mm, const int from_centre, double rho[],
          tirenv_springs__ray_memo memo[])
{
    const size_t i0 = r->i0;
    /* (the arrays in locals: the stores would make them be read again at every pair) */
    const double *const drop_r = r->drop, *const reach = r->reach, *const inv_s = r->inv_s;
    const run_memo rm = run_memo_of(mm);
    const v2d zv = {z, z}, av = {a_j, a_j}, Zv = {Z_j, Z_j}, fs = {f_side, f_side};
    const v2d ap = {a_p, a_p}, Zp = {Z_p, Z_p}, da = {a_j - a_p, a_j - a_p}, zero = {0, 0};
    for (; step + 1 <= count; step += 2) {
        const size_t lo = side ? i0 + step : i0 - step - 1; /* the pair's first in memory */
        const v2d drop = load2(drop_r + lo), f = zv - av * drop - Zv;
        if (!both_le(f, zero))
            break; /* the rest one by one */
        const v2d f_prev = from_centre ? fs : zv - ap * drop - Zp;
        const v2d a_hit = ap + f_prev * da / (f_prev - f);
        store2(rho + lo, inf_past(a_hit, load2(reach + lo), zero, 0, a_hit * load2(inv_s + lo)));
        store_memo2(memo + lo, &rm);
    }
    return step;
}

/* After a walk that hit the segment [j - dir, j] (not a wall): the rays further out that
 * are at or below the ground at j hit it too. */
static inline size_t hit_run(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                             const tirenv_springs__fan_rays *r, double z, int side,
                             size_t step, size_t count, long j, double *f_min, double tol,
                             double rho[], tirenv_springs__ray_memo memo[])
{
    const long first_j = o->first[side];
    const int dir = side ? 1 : -1;
    const size_t i0 = r->i0;
    const int from_centre = j == first_j;
    const double a_j = dir * (p->x[j] - o->x), Z_j = p->z[j];
    const double a_p = from_centre ? 0 : dir * (p->x[j - dir] - o->x);
    const double Z_p = from_centre ? 0 : p->z[j - dir], f_side = z - o->g_side[side];
    const double fm = run_f_min(r, z, side, step, from_centre, f_side, a_p, Z_p, *f_min);
    const tirenv_springs__ray_memo mm = {.j = j, .kind = RAY_HIT, .z_low = z - (fm - tol),
                                         .drho = NAN};
    step = from_centre ? hit_pairs(r, z, side, step, count, a_j, Z_j, a_p, Z_p, f_side, &mm, 1,
                                   rho, memo)
                       : hit_pairs(r, z, side, step, count, a_j, Z_j, a_p, Z_p, f_side, &mm, 0,
                                   rho, memo);
    for (; step <= count; ++step) {
        const size_t i = side ? i0 + step : i0 - step;
        const double drop = r->drop[i];
        const double f = z - a_j * drop - Z_j;
        if (!(f <= 0))
            break;
        const double f_prev = from_centre ? f_side : z - a_p * drop - Z_p;
        const double a_hit = a_p + f_prev * (a_j - a_p) / (f_prev - f);
        rho[i] = a_hit > r->reach[i] ? INFINITY : a_hit * r->inv_s[i];
        memo[i] = mm;
    }
    *f_min = fm;
    return step;
}

/* The rays step..count of one side (side 0: i0 - step, 1: i0 + step) as the fan walks them,
 * each resuming where its inner neighbour ended: at vertex j with the running minimum f_min,
 * that ray's drop and reach being drop_prev and reach_prev. With reuse, a ray after the
 * first walked whose memo holds at z is kept (tirenv_springs__fan_update). Returns the rays
 * walked. */
/* (Forced inline: each side's walk compiled for its direction in the fan and in its update
 * alike; with fresh_side beside it GCC inlined neither side into the fan.) */
static inline __attribute__((always_inline)) size_t
fan_side(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
         const tirenv_springs__fan_rays *r, double z, int side, size_t step, size_t count,
         long j, double f_min, double drop_prev, double reach_prev, int reuse, double rho[],
         tirenv_springs__ray_memo memo[])
{
    const double f0 = z - o->g_side[side], rho_max = r->rho_max, tol = fan_tol(o, z);
    const size_t i0 = r->i0;
    const int dir = side ? 1 : -1;
    const long first_j = o->first[side];
    size_t cast = 0;
    for (; step <= count; ++step) {
        const size_t i = side ? i0 + step : i0 - step;
        const double drop = r->drop[i], reach = r->reach[i];
        /* The resumption is exact only if this ray lies above the last at every vertex
         * (its computed descent is no steeper) and reaches at least as far; the element
         * layout gives both, but the computed values decide. */
        if (!(drop <= drop_prev && reach >= reach_prev)) {
            j = first_j;
            f_min = f0;
        }
        drop_prev = drop;
        reach_prev = reach;
        tirenv_springs__ray_memo *const m = &memo[i];
        if (reuse && cast && reuse_ray(p, o, r, z, f0, i, side, rho, m)) {
            j = m->j;
            f_min = z - m->z_low; /* f_min(z) >= this (above) */
            continue;
        }
        long j_end;
        int kind;
        rho[i] = walk(p, o->x, z, f0, first_j, j, dir, r->inv_s[i], drop, reach, r->cos_t[i],
                      rho_max, &j_end, &kind, &f_min);
        *m = (tirenv_springs__ray_memo){.j = j_end, .kind = kind, .z_low = z - (f_min - tol),
                                        .drho = NAN};
        j = j_end;
        ++cast;
    }
    return cast;
}

/* A fresh fan's side (fan_side without reuse) where the rays' resumption order is known
 * (r->ordered): each walk resumes where its inner neighbour ended, and after a walk past the
 * profile's end, or onto a segment, the rays further out that end alike are taken as a run.
 * A loop of its own: fan_side's, which the reuse shares, keeps its registers (with the runs
 * in it the walks over a road sampled at 10 mm cost 20 % more). */
static inline __attribute__((always_inline)) size_t
fresh_side(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
           const tirenv_springs__fan_rays *r, double z, int side, size_t count, double rho[],
           tirenv_springs__ray_memo memo[])
{
    const double f0 = z - o->g_side[side], rho_max = r->rho_max, tol = fan_tol(o, z);
    const size_t i0 = r->i0;
    const int dir = side ? 1 : -1;
    const long first_j = o->first[side];
    /* the arrays and x in locals: the stores to rho and memo would make them be read again
     * at every ray */
    const double *const inv_s = r->inv_s, *const drop = r->drop, *const reach = r->reach;
    const double *const cos_t = r->cos_t, x = o->x;
    long j = first_j;
    double f_min = f0;
    for (size_t step = 1; step <= count; ++step) {
        const size_t i = side ? i0 + step : i0 - step;
        long j_end;
        int kind;
        rho[i] = walk(p, x, z, f0, first_j, j, dir, inv_s[i], drop[i], reach[i], cos_t[i],
                      rho_max, &j_end, &kind, &f_min);
        memo[i] = (tirenv_springs__ray_memo){.j = j_end, .kind = kind,
                                             .z_low = z - (f_min - tol), .drho = NAN};
        j = j_end;
        if (kind == RAY_END) { /* the rest pass the end too */
            if (step < count)
                end_run(p, o, r, z, side, step + 1, count, j, &f_min, tol, rho, memo);
            return count;
        }
        if (step < count && kind == RAY_HIT)
            step = hit_run(p, o, r, z, side, step + 1, count, j, &f_min, tol, rho, memo) - 1;
    }
    return count;
}

void tirenv_springs__fan(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                         const tirenv_springs__fan_rays *r, double z, size_t a, size_t b,
                         double rho[], tirenv_springs__ray_memo memo[])
{
    const double f0 = z - o->g, rho_max = r->rho_max;
    const size_t i0 = r->i0;
    if (!(f0 > 0)) { /* centre on or below the ground: every ray has length 0 */
        for (size_t i = a; i <= b; ++i) {
            rho[i] = 0;
            memo[i] = (tirenv_springs__ray_memo){.j = 0, .kind = RAY_NONE, .z_low = INFINITY,
                                                 .drho = 0};
        }
        return;
    }
    rho[i0] = f0 <= rho_max ? f0 : INFINITY;
    memo[i0] = (tirenv_springs__ray_memo){.j = 0, .kind = RAY_DOWN, .z_low = o->g, .drho = 1};
    /* each side's walk compiled for its direction; with the runs where the ground within
     * reach has few vertices for the rays (a cleat, a step): on a road sampled finely each
     * ray ends on a face of its own, and the walks' loop without them is the faster */
    if (r->ordered && 4 * o->n_reach < (long)(b - a + 1)) {
        fresh_side(p, o, r, z, 0, i0 - a, rho, memo);
        fresh_side(p, o, r, z, 1, b - i0, rho, memo);
        return;
    }
    fan_side(p, o, r, z, 0, 1, i0 - a, o->first[0], z - o->g_side[0], INFINITY, 0, 0, rho,
             memo);
    fan_side(p, o, r, z, 1, 1, b - i0, o->first[1], z - o->g_side[1], INFINITY, 0, 0, rho,
             memo);
}

double tirenv_springs__fan_drho(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                                size_t i, tirenv_springs__ray_memo *m)
{
    if (isnan(m->drho)) /* the face does not change while the memo holds */
        m->drho = slope_drho(p, m->j, i > r->i0 ? 1 : -1, m->kind, r->sin_t[i], r->cos_t[i]);
    return m->drho;
}

/* Whether memo m's face is within w: a segment's vertices among its; the flat ground past a
 * profile's first (last) vertex only where that vertex lies after x_lo (before x_hi): a
 * window's first vertex at or before x_lo (last after x_hi) need not be the road's. */
static inline int face_within(const tirenv_profile *p, const tirenv_springs__face_window *w,
                              long j, long jp, int kind)
{
    if (kind != RAY_HIT && kind != RAY_WALL)
        return 1;
    if (!(j >= w->k_lo && j <= w->k_hi))
        return 0;
    if (kind == RAY_WALL || (jp >= w->k_lo && jp <= w->k_hi))
        return 1;
    return jp < 0 ? p->x[j] > w->x_lo : jp >= (long)p->n && p->x[j] < w->x_hi;
}

/* Ray i's rho from (o->x, z) on the face memo m's walk ended on, as a line; NAN if none, or
 * if the face is not within w. */
static inline double face_rho(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                              const tirenv_springs__fan_rays *r, size_t i,
                              const tirenv_springs__ray_memo *m, double z,
                              const tirenv_springs__face_window *w)
{
    const double *X = p->x, *Z = p->z, x = o->x;
    const long n = (long)p->n, j = m->j;
    const int dir = i > r->i0 ? 1 : -1;
    if (!face_within(p, w, j, j - dir, m->kind))
        return NAN;
    switch (m->kind) {
    case RAY_HIT: { /* the line through the segment [j - dir, j], as walk() crosses it */
        const long jp = j - dir;
        if (!(jp >= 0 && jp < n)) /* the flat ground beyond the profile's end, at Z[j] */
            return r->cos_t[i] > 0 ? (z - Z[j]) / r->cos_t[i] : NAN;
        const double drop = r->drop[i], a_j = dir * (X[j] - x), a_p = dir * (X[jp] - x);
        const double f_j = z - a_j * drop - Z[j], f_p = z - a_p * drop - Z[jp];
        return f_p != f_j ? (a_p + f_p * (a_j - a_p) / (f_p - f_j)) * r->inv_s[i] : NAN;
    }
    case RAY_DOWN:
        return i == r->i0 ? z - o->g : NAN;
    case RAY_WALL: {
        const double a_j = dir * (X[j] - x);
        return a_j > 0 ? a_j * r->inv_s[i] : NAN;
    }
    case RAY_END: { /* the flat ground past the profile's end vertex, which must be the
                     * road's: after x_lo (before x_hi) */
        const double cos_t = r->cos_t[i];
        const long e = dir > 0 ? n - 1 : 0;
        const int end = dir > 0 ? X[e] < w->x_hi : X[e] > w->x_lo;
        return cos_t > 0 && end ? (z - Z[e]) / cos_t : NAN;
    }
    default:
        return NAN;
    }
}

int tirenv_springs__memo_across(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                const tirenv_springs__fan_rays *r, size_t i, long v, double z,
                                tirenv_springs__ray_memo *m)
{
    const double *X = p->x, *Z = p->z;
    const long n = (long)p->n;
    const int dir = i > r->i0 ? 1 : -1;
    m->drho = NAN;
    m->j = -2; /* no face (face_rho refuses it), unless one of v's is found */
    m->kind = RAY_HIT;
    /* No proof that the ray passes above every point before the new face (z_low is the old
     * walk's): the fan walks it again rather than reuse it below z (reuse_ray). Kept, a
     * start that gave up after moving the memo at a height far above the root (a restored
     * history's) had the evaluations below reuse it past the face the ray meets first. */
    m->z_low = INFINITY;
    if (!(v - 1 >= 0 && v + 1 < n))
        return 0;
    /* walk()'s f at v and its neighbours: the ray below v's height at v's X ends the walk on
     * the face into v, else on the one out of it */
    const double drop = r->drop[i];
    const long jv = v;
    const double f_v = z - dir * (X[jv] - o->x) * drop - Z[jv];
    const long j = f_v <= 0 ? jv : jv + dir, jp = j - dir;
    const double f_p = z - dir * (X[jp] - o->x) * drop - Z[jp];
    const double f_j = z - dir * (X[j] - o->x) * drop - Z[j];
    /* (a face under the centre: the walk enters it at the centre, above the ground) */
    if (!((f_p > 0 || dir * (X[jp] - o->x) < 0) && f_j <= 0))
        return 0;
    m->j = j;
    m->kind = X[j] == X[jp] ? RAY_WALL : RAY_HIT;
    return 1;
}

int tirenv_springs__memo_fits(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                              const tirenv_springs__fan_rays *r, size_t i,
                              const tirenv_springs__ray_memo *m)
{
    const long n = (long)p->n, j = m->j;
    const int side = i > r->i0;
    const long jp = side ? j - 1 : j + 1;
    switch (m->kind) {
    case RAY_HIT:
    case RAY_WALL:
    case RAY_REACH: /* a walk from the centre resumes at j, reading j's vertex before it */
        return j >= 0 && j < n && (!o || j == o->first[side] || (jp >= 0 && jp < n));
    case RAY_END: /* (off the profile's end on the ray's side) */
        return o ? j == (side ? n : -1) : j == -1 || j == n;
    case RAY_DOWN:
        return !o || i == r->i0;
    case RAY_NONE:
        return 1;
    default:
        return 0;
    }
}

long tirenv_springs__memo_passed(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                 const tirenv_springs__fan_rays *r, size_t i, double z,
                                 const tirenv_springs__ray_memo *m)
{
    const long n = (long)p->n, j = m->j;
    const int dir = i > r->i0 ? 1 : -1;
    if (m->kind != RAY_HIT || j - dir < 0 || j - dir >= n || j < 0 || j >= n)
        return -1;
    /* walk()'s f at the face's far end: the ray above the ground there has passed it */
    const double f_j = z - dir * (p->x[j] - o->x) * r->drop[i] - p->z[j];
    return f_j > 0 ? j : -1;
}

void tirenv_springs__face_window_at(const tirenv_profile *p, double x_lo, double x_hi,
                                    tirenv_springs__face_window *w)
{
    const size_t k_hi = tirenv_profile__segment_at(p, x_hi);
    *w = (tirenv_springs__face_window){
        .k_lo = (long)tirenv_profile__segment_at(p, x_lo),
        .k_hi = (long)(k_hi + 1 < p->n ? k_hi + 1 : k_hi),
        .x_lo = x_lo,
        .x_hi = x_hi};
}

int tirenv_springs__face_window_has(const tirenv_springs__face_window *w, long id)
{
    return id >= w->k_lo && id <= w->k_hi;
}

double tirenv_springs__face_rho(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                const tirenv_springs__fan_rays *r, size_t i,
                                const tirenv_springs__ray_memo *m, double z,
                                const tirenv_springs__face_window *w)
{
    return face_rho(p, o, r, i, m, z, w);
}

void tirenv_springs__memo_reprofile(const tirenv_profile *old, const tirenv_profile *p,
                                    long off, tirenv_springs__ray_memo *m)
{
    const long n_old = (long)old->n, n = (long)p->n, j = m->j, k = j + off;
    switch (m->kind) {
    case RAY_HIT:
    case RAY_WALL:
    case RAY_REACH:
        m->j = j >= 0 && j < n_old && k >= 0 && k < n && p->x[k] == old->x[j] &&
                       p->z[k] == old->z[j]
                   ? k
                   : -2; /* no face here: face_rho refuses it */
        break;
    case RAY_END:
        m->j = j < 0 ? -1 : n;
        break;
    default:
        break;
    }
}

/* How faces_rho takes rho on a run's face, decided once a run: */
enum {
    FACE_SEG,  /* a segment: (z - its height under the centre) d(rho)/dz */
    FACE_FLAT, /* the flat ground past the profile's end at height Z: (z - Z) / cos_t */
    FACE_WALL, /* a wall a_j ahead along the ground: a_j / |sin_t| */
    FACE_DOWN  /* the straight-down ray: z - g */
};

/* faces_side's rays from rays[k] on while they end on face (j, kind), rho taken there as
 * how with c (faces_side decides both): the first k not on it, or SIZE_MAX where a ray's rho
 * is not finite. Compiled apart for the common faces (how a constant). */
static inline __attribute__((always_inline)) size_t
face_run(const tirenv_profile *p, const tirenv_springs__fan_rays *r, const size_t rays[],
         size_t k, size_t k1, const int dir, tirenv_springs__ray_memo memo[],
         tirenv_springs__ray_memo kept[], double rho[], double drho[],
         tirenv_springs__ray_memo faces[], long j, int kind, const int how, double c)
{
    const double *const cos_t = r->cos_t, *const inv_s = r->inv_s;
    for (; k < k1; ++k) {
        const size_t i = rays[k];
        tirenv_springs__ray_memo *m = &memo[i];
        if (m->j != j || m->kind != kind)
            break;
        if (isnan(m->drho)) { /* the face's, kept where this ray last ended on it */
            const tirenv_springs__ray_memo *f = &kept[i];
            if (f->j == j && f->kind == kind && !isnan(f->drho)) {
                m->drho = f->drho;
            } else {
                m->drho = slope_drho(p, j, dir, kind, r->sin_t[i], cos_t[i]);
                kept[i] = *m;
            }
        }
        double v;
        if (how == FACE_SEG) {
            v = c * m->drho;
        } else if (how == FACE_FLAT) {
            if (!(cos_t[i] > 0))
                return SIZE_MAX;
            v = c / cos_t[i];
        } else if (how == FACE_WALL) {
            v = c * inv_s[i];
        } else {
            if (i != r->i0)
                return SIZE_MAX;
            v = c;
        }
        if (!isfinite(v))
            return SIZE_MAX;
        rho[i] = v;
        drho[i] = m->drho;
        faces[i] = *m;
    }
    return k;
}

/* tirenv_springs__faces_rho for rays[k0..k1), all on the side dir (1: after the straight-down
 * ray, -1: at or before it), each side's loop compiled for its direction. */
static inline __attribute__((always_inline)) int
faces_side(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
           const tirenv_springs__fan_rays *r, const size_t rays[], size_t k0, size_t k1,
           const int dir, tirenv_springs__ray_memo memo[], tirenv_springs__ray_memo kept[],
           double z, const tirenv_springs__face_window *w, double rho[], double drho[],
           tirenv_springs__ray_memo faces[])
{
    const double *X = p->x, *Z = p->z;
    const long n_p = (long)p->n;
    /* Face by face (held rays come in runs on two or three faces): whether it is within w,
     * how rho is taken on it, and that rule's one quantity of the face (c), asked once a
     * face. A segment's rho is the line's, linear in z as the root takes it; the other
     * faces' are face_rho's, by its operations (its bits). */
    size_t k = k0;
    while (k < k1) {
        const tirenv_springs__ray_memo *m = &memo[rays[k]];
        const long j = m->j, jp = j - dir;
        const int kind = m->kind;
        if (!face_within(p, w, j, jp, kind))
            return 0; /* (a window's rows hold it) */
        int how;
        double c;
        switch (kind) {
        case RAY_HIT:
            if (jp >= 0 && jp < n_p) {
                /* rho (cos + sin dZ/dX) = z - (the face's height under the centre) */
                const double X0 = X[jp], Z0 = Z[jp], dX = X[j] - X0, dZ = Z[j] - Z0;
                how = FACE_SEG;
                c = z - (dZ == 0 ? Z0 : Z0 + dZ * ((o->x - X0) / dX));
            } else { /* the flat ground beyond the profile's end, at Z[j] */
                how = FACE_FLAT;
                c = z - Z[j];
            }
            break;
        case RAY_END: { /* past the profile's end vertex, which must be the road's */
            const long e = dir > 0 ? n_p - 1 : 0;
            if (!(dir > 0 ? X[e] < w->x_hi : X[e] > w->x_lo))
                return 0;
            how = FACE_FLAT;
            c = z - Z[e];
            break;
        }
        case RAY_WALL:
            c = dir * (X[j] - o->x);
            if (!(c > 0))
                return 0;
            how = FACE_WALL;
            break;
        case RAY_DOWN:
            how = FACE_DOWN;
            c = z - o->g;
            break;
        default:
            return 0;
        }
        if (how == FACE_SEG)
            k = face_run(p, r, rays, k, k1, dir, memo, kept, rho, drho, faces, j, kind,
                         FACE_SEG, c);
        else if (how == FACE_FLAT)
            k = face_run(p, r, rays, k, k1, dir, memo, kept, rho, drho, faces, j, kind,
                         FACE_FLAT, c);
        else
            k = face_run(p, r, rays, k, k1, dir, memo, kept, rho, drho, faces, j, kind, how, c);
        if (k == SIZE_MAX)
            return 0;
    }
    return 1;
}

int tirenv_springs__faces_rho(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                              const tirenv_springs__fan_rays *r, const size_t rays[], size_t n,
                              tirenv_springs__ray_memo memo[], tirenv_springs__ray_memo kept[],
                              double z, const tirenv_springs__face_window *w, double rho[],
                              double drho[], tirenv_springs__ray_memo faces[])
{
    /* rays ascending: those at or before the straight-down one first */
    const size_t i0 = r->i0;
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (rays[mid] <= i0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return faces_side(p, o, r, rays, 0, lo, -1, memo, kept, z, w, rho, drho, faces) &&
           faces_side(p, o, r, rays, lo, n, 1, memo, kept, z, w, rho, drho, faces);
}

void tirenv_springs__fan_drho_neg(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                                  size_t first, size_t last, const unsigned char mask[],
                                  tirenv_springs__ray_memo memo[], double dd[])
{
    for (size_t i = first; i <= last; ++i)
        if (mask[i])
            dd[i] = -tirenv_springs__fan_drho(p, r, i, &memo[i]); /* inlined here */
}

int tirenv_springs__fan_reuse(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                              const tirenv_springs__fan_rays *r, double z, size_t a, size_t b,
                              double rho[], const tirenv_springs__ray_memo memo[])
{
    const double f0 = z - o->g;
    if (!(f0 > 0))
        return 0;
    const size_t i0 = r->i0;
    for (size_t i = a; i <= b; ++i)
        if (!reuse_ray(p, o, r, z, f0, i, i > i0, rho, &memo[i]))
            return 0;
    return 1;
}

/* Why a ray may be cast again alone. Each memo is a proof about its own ray (its z_low
 * bounds that ray's f over every point before its end: the fan's running minimum is over the
 * inner rays' points, where this ray lies higher), so the rays whose memos hold keep them,
 * and a ray whose memo fails is walked again from where its inner neighbour ends at z (a
 * fresh fan's resumption: every vertex before that end lies below this ray). The running
 * minimum it starts from is the neighbour's at z: a memo made at z' with z_low gives
 * f_min(z') = z' - z_low + tol(z'), and f moves with z one for one, so f_min(z) >=
 * z - z_low up to rounding far below the allowance tol; that lower bound is what the walk
 * starts from (its memo's z_low is then at most tol above the neighbour's). The rays cast
 * again end where a fresh fan's would, and their rho is computed by the same walk: bit for
 * bit tirenv_springs__ray_at's. */
size_t tirenv_springs__fan_update(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                  const tirenv_springs__fan_rays *r, double z, size_t a,
                                  size_t b, double rho[], tirenv_springs__ray_memo memo[])
{
    const double f0 = z - o->g;
    const size_t i0 = r->i0;
    if (!(f0 > 0) || !reuse_ray(p, o, r, z, f0, i0, 0, rho, &memo[i0])) {
        tirenv_springs__fan(p, o, r, z, a, b, rho, memo);
        return b - a + 1;
    }
    size_t cast = 0;
    for (int side = 0; side < 2; ++side) {
        const size_t count = side ? b - i0 : i0 - a;
        /* the rays whose memos hold, outward to the first that fails */
        /* each side's loop compiled for its direction */
        const size_t step = side ? reuse_side(p, o, r, z, f0, 1, count, rho, memo)
                                 : reuse_side(p, o, r, z, f0, 0, count, rho, memo);
        if (step > count)
            continue;
        /* from there on as the fan, each ray resuming where its inner neighbour ends; the
         * running minimum from a kept memo is bounded below (above) */
        long j = o->first[side];
        double f_min = z - o->g_side[side], drop_prev = INFINITY, reach_prev = 0;
        if (step > 1) {
            const size_t in = side ? i0 + step - 1 : i0 - step + 1;
            j = memo[in].j;
            f_min = z - memo[in].z_low;
            drop_prev = r->drop[in];
            reach_prev = r->reach[in];
        }
        cast += side ? fan_side(p, o, r, z, 1, step, count, j, f_min, drop_prev, reach_prev, 1,
                                rho, memo)
                     : fan_side(p, o, r, z, 0, step, count, j, f_min, drop_prev, reach_prev, 1,
                                rho, memo);
    }
    return cast;
}

size_t tirenv_springs__fan_pairs(const tirenv_springs__fan_origin *o,
                                 const tirenv_springs__fan_rays *r, size_t a, size_t b,
                                 const tirenv_springs__ray_memo memo[], size_t pairs[])
{
    /* Forward, a walk that ended at vertex j has every vertex before j at or before its
     * anchor (springs_feature.c: its crossing, or the ground under its tip, which lies past
     * the last vertex the walk passed) and no vertex from j on strictly before it (the
     * crossing lies on the segment ending at j, the tip before j). So at most j_m - j_k
     * vertices lie strictly between the anchors of an inner ray k and an outer ray m: a
     * feature, which needs three, needs j_m - j_k >= 3. Backward the same mirrored; the
     * straight-down ray's anchor is under x, between first[0] and first[1]. The pairs come in
     * the order tirenv_springs__unseen_feature looks at them. */
    const size_t i0 = r->i0;
    size_t n = 0;
    for (int side = 0; side < 2; ++side) {
        const long dir = side ? 1 : -1;
        const size_t count = side ? b - i0 : i0 - a;
        const tirenv_springs__ray_memo *mm = memo + i0;
        long j1 = o->first[side], j2 = j1;
        for (size_t step = 1; step <= count; ++step) {
            const long jm = mm[dir * (long)step].j;
            const size_t m = side ? i0 + step : i0 - step;
            if (dir * (jm - j1) >= 3) {
                pairs[2 * n] = side ? m - 1 : m + 1;
                pairs[2 * n++ + 1] = m;
            }
            if (step >= 2 && dir * (jm - j2) >= 3) {
                pairs[2 * n] = side ? m - 2 : m + 2;
                pairs[2 * n++ + 1] = m;
            }
            j2 = j1;
            j1 = jm;
        }
    }
    /* The two rays either side of the straight-down one: vertices j_back + 1 .. j_fwd - 1 at
     * most lie between their anchors. */
    if (a < i0 && i0 < b && memo[i0 + 1].j - memo[i0 - 1].j - 1 >= 3) {
        pairs[2 * n] = i0 - 1;
        pairs[2 * n++ + 1] = i0 + 1;
    }
    return n;
}
