/* SPDX-License-Identifier: Apache-2.0 */
/* The ground as the ring's continuous tread sees it (docs/models.md section 5.3): the angles
 * of the window cut at every node and at every ground vertex within reach into pieces, along
 * each of which the first ground a ray from the centre meets lies on one segment of the
 * profile, so that the penetration d(phi) = R0 - rho(phi) is smooth there. Each piece gives
 * two quadrature points, its ends, with its one-sided values of d: the trapezoid rule of the
 * tread's energy over the piece (ring_smooth.c); where two pieces meet on one ray (a node on
 * one segment of the ground) their two points are one, weighted by both halves. As the
 * centre moves, the pieces' ends move continuously and a piece appears or vanishes only with
 * zero length, so the sum is continuous in x and z even where d(phi) jumps (a vertical face,
 * a corner that a ray passes). Without vertices off the nodes (flat ground) the points are
 * the nodes' rays, one a node with the weight dtheta: the rays model exactly. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include "profile/profile_impl.h"
#include "core/capacity.h"
#include "model/ring_impl.h"

/* A cut of the window: a node or a ground vertex, at angle phi (rad, from the downward
 * vertical, positive forward) with its sine and cosine, and d(phi)/dz (rad/m): a vertex's
 * angle seen from the centre moves as the centre does, a node's does not. */
typedef struct {
    double phi, s, c, dphi;
    size_t k; /* a vertex's index in the profile */
} cut;

/* The cuts v[0 .. n) in angle order, equal angles in their order (as a stable sort): by
 * insertion, the vertices coming in x order and so mostly in angle order already (O(n) then,
 * where a general sort took some 150 instructions a vertex on a 1 mm road). */
static void sort_by_angle(cut v[], size_t n)
{
    for (size_t i = 1; i < n; ++i) {
        if (!(v[i].phi < v[i - 1].phi))
            continue;
        const cut c = v[i];
        size_t k = i;
        do {
            v[k] = v[k - 1];
            --k;
        } while (k > 0 && c.phi < v[k - 1].phi);
        v[k] = c;
    }
}

/* The angle atan2(dx, dz) (dz > 0, rad) of a vertex seen from the centre, without atan2 where
 * a node j lies close: theta_j + atan(t), t = tan(phi - theta_j) from the node's sine and
 * cosine, by atan's series up to t^13 (|t| <= 0.02: the terms left out are below 3e-27 rad,
 * far below theta's round-off; atan2 itself rounds as much). *jr: the node the last vertex's
 * angle was taken from (M: none), moved to this one's; the vertices come in x order, their
 * angles mostly a node or less apart, so a step or two of *jr finds it, else atan2 does. */
static double cut_angle(const tirenv_ring *r, double dx, double dz, size_t *jr)
{
    const double t_max = r->dth < 0.02 ? r->dth : 0.02;
    size_t j = *jr;
    for (int step = 0; j < r->M && step < 4; ++step) {
        const double sn = r->sin_t[j], cs = r->cos_t[j];
        const double den = dz * cs + dx * sn;
        if (!(den > 0))
            break;
        const double t = (dx * cs - dz * sn) / den;
        if (fabs(t) <= t_max) {
            *jr = j;
            const double t2 = t * t;
            return r->theta[j] +
                   t * (1 - t2 * (1.0 / 3 - t2 * (1.0 / 5 - t2 * (1.0 / 7 - t2 * (1.0 / 9 -
                        t2 * (1.0 / 11 - t2 * (1.0 / 13)))))));
        }
        j = t > 0 ? j + 1 : j - 1; /* j - 1 wraps past 0 to above M: stops */
    }
    const double phi = atan2(dx, dz);
    const double jn = (double)r->i0 + round(phi / r->dth);
    *jr = jn >= 0 && jn < (double)r->M ? (size_t)jn : r->M;
    return phi;
}

/* A point this close to its node's start, in parts of the interval, is at the node (no knot
 * of the shear-coupled tread): a vertex a hair from straight below the centre (x = -1e-200 m
 * before a step at 0) put a knot 1e-200 rad from the node at theta = 0, whose coupling
 * k_s / (R h) and its rate k_s dh / (R h^2) overflowed (Newton did not settle, dF_z/dz was a
 * NaN). Only that node can be met so: elsewhere phi - theta is at least theta's round-off, a
 * part 1e-19 or more. The piece still counts, with its weight, so nothing moves by more than
 * the 1e-100 part of a node's interval. */
static const double s_node = 1e-100;

/* Room for n entries of size sz in *buf (capacity *cap), growing geometrically: the workspace
 * settles at the largest window a profile needs, after which evaluation does not allocate. */
static int reserve(void **buf, size_t *cap, size_t n, size_t sz)
{
    if (n <= *cap)
        return 0;
    const size_t c = tirenv_core__capacity(*cap, 256, n);
    void *nb = realloc(*buf, c * sz);
    if (!nb)
        return TIRENV_ENOMEM;
    *buf = nb;
    *cap = c;
    return 0;
}

/* The points' array: aligned as a point is, to a cache line (ring_impl.h), grown as reserve
 * grows the others (aligned_alloc has no realloc: copied). */
_Static_assert(offsetof(tirenv_ring_point, e) + sizeof(double) <= 64,
               "the fields the Newton steps read lie in a point's first cache line");

static int reserve_pts(tirenv_ring *r, size_t n)
{
    if (n <= r->cap_pts)
        return 0;
    const size_t c = tirenv_core__capacity(r->cap_pts, 256, n);
    tirenv_ring_point *nb = aligned_alloc(_Alignof(tirenv_ring_point), c * sizeof *nb);
    if (!nb)
        return TIRENV_ENOMEM;
    if (r->pts)
        memcpy(nb, r->pts, r->cap_pts * sizeof *nb);
    free(r->pts);
    r->pts = nb;
    r->cap_pts = c;
    return 0;
}

/* The line (L[0], L[1]) - (L[2], L[3]) of the first ground met by the ray from (x, z) in the
 * direction (sx, cz) (cz > 0, not normalised), walking the vertices in the ray's direction from
 * *cursor; 0 if no ground within the horizontal distance reach. The ground is a graph with
 * vertical walls, so the first vertex the ray passes at or above closes the segment that holds
 * the crossing (springs_ray.c argues the same for the springs model's rays). *cursor keeps
 * that vertex: a flatter ray of the same side lies above every vertex before it. */
static inline __attribute__((always_inline)) int first_line(const tirenv_profile *p, double x,
                                                            double z, double sx, double cz,
                                                            double reach, long *cursor,
                                                            double L[4])
{
    const double *X = p->x, *Z = p->z;
    const long n = (long)p->n;
    if (sx == 0) { /* straight down: the segment under the centre */
        const size_t k = tirenv_profile__segment_at(p, x);
        if (x < X[0] || k + 1 >= (size_t)n) {
            const double zf = x < X[0] ? Z[0] : Z[n - 1];
            L[0] = x - 1, L[1] = zf, L[2] = x + 1, L[3] = zf;
        } else {
            L[0] = X[k], L[1] = Z[k], L[2] = X[k + 1], L[3] = Z[k + 1];
        }
        return 1;
    }
    const int dir = sx > 0 ? 1 : -1;
    const double s = fabs(sx);
    long j = *cursor;
    for (; j >= 0 && j < n; j += dir) {
        const double a = dir * (X[j] - x);
        if ((z - Z[j]) * s <= a * cz) { /* the ray at or below vertex j */
            *cursor = j;
            const long jp = j - dir;
            if (jp < 0 || jp >= n) { /* the flat extension before vertex j */
                L[0] = X[j] - dir, L[1] = Z[j], L[2] = X[j], L[3] = Z[j];
            } else {
                L[0] = X[jp], L[1] = Z[jp], L[2] = X[j], L[3] = Z[j];
            }
            if (dir < 0) { /* order the line left to right: its normal faces up */
                double t = L[0];
                L[0] = L[2], L[2] = t;
                t = L[1], L[1] = L[3], L[3] = t;
            }
            return 1;
        }
        if (a > reach) { /* above the ground up to a vertex beyond reach: no crossing */
            *cursor = j;
            return 0;
        }
    }
    *cursor = j;
    /* Past the last vertex the ground is flat at the end height. */
    const long e = dir > 0 ? n - 1 : 0;
    if ((z - Z[e]) * s > reach * cz)
        return 0;
    L[0] = X[e] - 1, L[1] = Z[e], L[2] = X[e] + 1, L[3] = Z[e];
    return 1;
}

/* What rho along a ray to the line L takes that does not depend on the ray (L's run, from the
 * centre (x, z)): computed once for the pieces of a run on one line, the same operations on
 * the same operands as for each ray, so the same bits. */
typedef struct {
    double dX, dZ; /* L[2] - L[0], L[3] - L[1], m */
    double num;    /* (z - L[1]) dX - (x - L[0]) dZ, m^2 */
} line_k;

static inline void line_of(const double L[4], double x, double z, line_k *k)
{
    const double dX = L[2] - L[0], dZ = L[3] - L[1];
    k->dX = dX;
    k->dZ = dZ;
    k->num = (z - L[1]) * dX - (x - L[0]) * dZ;
}

/* rho along the ray at (s, c) (normalised) to the line k, d(rho)/dz along that ray and, where
 * the ray's angle moves with z (moves: a vertex's cut), d(rho)/dphi at that z (else 0: a node's
 * ray, whose d(d)/dz along the cut adds drho_dphi * 0): from (x + rho s - X1) dZ = (z - rho c -
 * Z1) dX. NAN if the line faces away (never for the line a ray of the piece meets first). */
static inline double rho_on(const line_k *k, double s, double c, int moves, double *drho,
                            double *drho_dphi)
{
    const double dX = k->dX, dZ = k->dZ, den = s * dZ + c * dX;
    if (!(den > 0)) {
        *drho = *drho_dphi = 0;
        return NAN;
    }
    *drho = dX / den;
    const double rho = k->num / den;
    *drho_dphi = moves ? -rho * (c * dZ - s * dX) / den : 0;
    return rho;
}

/* Point e of the piece c of node interval c->j (nodes j, j + 1; e = 0 at its first cut, 1 at
 * its second) on the line lk (NULL: the centre inside the ground, rho = 0), marked out of
 * reach (d = -INFINITY) or, within it, given the tread stiffness k_t (with lugs each its own)
 * and its interval added to wl. Every operand is read before the first store: a point's
 * doubles may alias the piece's and the ring's, which the stores would make reloads. nodes: c
 * lies between two nodes (c->nodes, a constant where inlined): its ends are the nodes' angles
 * with d(phi)/dz 0, so its place is 0 or 1 and its d(rho)/dphi term 0 without the tests that
 * find them (the same values, by the same operations where they are computed). */
static inline __attribute__((always_inline)) void
piece_point(const tirenv_ring *r, const tirenv_ring_piece *c, const int e, double x,
            const line_k *lk, double k_t, int lugs, size_t wl[2], double omega, double th,
            tirenv_ring_point *q, const int nodes)
{
    const size_t j = c->j;
    const double phi = e ? c->pb : c->pa, sn = e ? c->sb : c->sa, cs = e ? c->cb : c->ca,
                 dphi = nodes ? 0.0 : e ? c->db : c->da;
    const double R0 = r->R0, t_r = r->par.t_r;
    double s;
    if (nodes) {
        s = e;
    } else if (e == 1 && phi == r->theta[j + 1]) {
        s = 1;
    } else if (e == 0 && phi == th) {
        s = 0;
    } else {
        s = (phi - th) / r->dth; /* fmin(1, fmax(0, s)), inline */
        s = s > s_node ? (s < 1 ? s : 1) : 0;
    }
    double drho = 0, drho_dphi = 0, rho = 0;
    if (lk)
        rho = rho_on(lk, sn, cs, !nodes && dphi != 0, &drho, &drho_dphi);
    const int fin = isfinite(rho);
    const double d = fin ? R0 - rho : -INFINITY;
    q->dd = -drho;
    q->ddt = -(drho + drho_dphi * dphi);
    q->X = x + (fin ? rho : 0) * sn;
    q->sn = sn;
    q->cs = cs;
    q->phi = phi;
    q->omega = omega;
    q->j = j;
    q->ends = e ? 2 : 1;
    q->s = s;
    q->dphi = dphi;
    /* Out of reach, or within it (see the top of tirenv_ring__sample). */
    if (!(d > -t_r)) {
        q->d = -INFINITY;
        return;
    }
    q->d = d;
    wl[0] = j < wl[0] ? j : wl[0];
    wl[1] = j + 1 > wl[1] ? j + 1 : wl[1];
    q->k_t = lugs ? tirenv_ring__tread_kappa(r, phi, x) / (r->R * r->dth) : k_t;
}

/* The piece c's points into q[0], q[1]; returns how many it wrote. same: the piece whose
 * points were written last, q[-1] its second, ends where this one begins, on the same line
 * (its bits). Where c's first cut is that piece's too (c->contig: the cut is its second; else
 * the same cut's bits), c's first point would be the same ray as q[-1], the same operations on
 * the same operands (out of reach both, or within it both): the two are one point, q[-1],
 * weighted by both pieces' halves (the trapezoid rule's two terms of one node on a flat
 * stretch, summed before they are used), which ends the one piece and begins the next; c's
 * interval still counts in the window as its point's did. Only c's second point is written
 * then. */
static inline __attribute__((always_inline)) size_t
piece_points(const tirenv_ring *r, const tirenv_ring_piece *c, int same, double x,
             const line_k *lk, double k_t, int lugs, size_t wl[2], tirenv_ring_point *q,
             const int nodes)
{
    const double omega = 0.5 * (c->pb - c->pa), th = r->theta[c->j];
    tirenv_ring_point *const qp = q - 1;
    if (same && !r->apart &&
        (c->contig ||
         (tirenv_ring__same_bits(&qp->phi, &c->pa, 1) &&
          tirenv_ring__same_bits(&qp->sn, &c->sa, 1) &&
          tirenv_ring__same_bits(&qp->cs, &c->ca, 1) &&
          tirenv_ring__same_bits(&qp->dphi, &c->da, 1)))) {
        qp->omega += omega;
        qp->ends = 3;
        if (qp->d != -INFINITY)
            wl[1] = c->j + 1 > wl[1] ? c->j + 1 : wl[1];
        piece_point(r, c, 1, x, lk, k_t, lugs, wl, omega, th, q, nodes);
        return 1;
    }
    piece_point(r, c, 0, x, lk, k_t, lugs, wl, omega, th, q, nodes);
    piece_point(r, c, 1, x, lk, k_t, lugs, wl, omega, th, q + 1, nodes);
    return 2;
}

/* Whether the last sampling's pieces are this one's (r->pc_*): the same nodes, and the same
 * vertex cuts, each still strictly inside the node interval it cut and in the same order (a
 * vertex's angle moves with x and z): then a build would make the same pieces, none of zero
 * length, with the vertices' new angles at their ends. */
static int same_pieces(const tirenv_ring *r, size_t ja, size_t jb, const cut v[], size_t nv)
{
    if (!r->pc_valid || ja != r->pc_ja || jb != r->pc_jb || nv != r->pc_nv)
        return 0;
    for (size_t i = 0; i < nv; ++i) {
        const size_t j = r->pc_vj[i];
        if (v[i].k != r->pc_vk[i] || !(v[i].phi > r->theta[j] && v[i].phi < r->theta[j + 1]) ||
            (i > 0 && !(v[i - 1].phi < v[i].phi)))
            return 0;
    }
    return 1;
}

/* The count of the pieces c[0 .. n) whose middle rays go backward (sa + sb < 0), into *n_back,
 * and whether they are the first ones (*ordered): the whole pass. */
static void count_back(const tirenv_ring_piece c[], size_t n, size_t *n_back, int *ordered)
{
    size_t nb = 0;
    int ord = 1;
    for (size_t t = 0; t < n; ++t)
        if (c[t].sa + c[t].sb < 0) {
            ord &= nb == t;
            ++nb;
        }
    *n_back = nb;
    *ordered = ord;
}

/* The pieces a vertex cut ends or begins, t_i = (vj[i] - ja) + i and t_i + 1 for each of the nv
 * cuts (sorted, two cuts in one interval sharing one), each taken once: how many go backward
 * (*n_back), how many lie before `below` (*n_below), and whether each goes backward exactly when
 * it lies before `below` (*agree). */
static void vertex_pieces(const tirenv_ring_piece c[], const size_t vj[], size_t ja, size_t nv,
                          size_t below, size_t *n_back, size_t *n_below, int *agree)
{
    size_t nb = 0, nl = 0, last = (size_t)-1;
    int ag = 1;
    for (size_t i = 0; i < nv; ++i)
        for (size_t h = 0; h < 2; ++h) {
            const size_t t = (vj[i] - ja) + i + h;
            if (t == last)
                continue;
            last = t;
            const int back = c[t].sa + c[t].sb < 0;
            nb += back;
            nl += t < below;
            ag &= back == (t < below);
        }
    *n_back = nb, *n_below = nl, *agree = ag;
}

/* count_back's answer for the last sampling's pieces c, kept (same_pieces) with only their
 * vertex ends moved, without the pass over all of them: a piece between two nodes keeps its
 * sa + sb bits, so where the last sampling's were ordered (its first pc_back pieces backward,
 * no other), such a piece is backward if and only if it lies before pc_back; only the vertex
 * cuts' pieces (vertex_pieces) are looked at again, and the count moves by their changes. The
 * pieces are ordered if each vertex piece is backward exactly when it lies before the new count
 * nb: then the vertex pieces before nb number nb - nb0 more than those before nb0, so every
 * piece between nb0 and nb is a vertex piece, and every node piece keeps its place on its side
 * of the count. Returns 0 where the last sampling's counts are unknown or were not ordered (the
 * caller then makes the whole pass). */
static int back_carried(const tirenv_ring *r, const tirenv_ring_piece c[], size_t ja, size_t nv,
                        size_t *n_back, int *ordered)
{
    if (!r->pc_back_ok || !r->pc_ordered)
        return 0;
    const size_t nb0 = r->pc_back;
    size_t vb, below0, below;
    int agree;
    vertex_pieces(c, r->pc_vj, ja, nv, nb0, &vb, &below0, &agree);
    *n_back = nb0 - below0 + vb; /* those before nb0 were the backward ones */
    vertex_pieces(c, r->pc_vj, ja, nv, *n_back, &vb, &below, ordered);
    return 1;
}

/* The window's far stretches (docs/models.md 5.3, What the solve reuses). Of the window's node
 * intervals, those more than SKIP_NEAR nodes beyond the last solve's sub-window and SKIP_EDGE
 * inside the sampled range's ends, whose ground lies, by a bound, below the last evaluation's
 * tread surface by SKIP_MARGIN, are not sampled: their points are free at the answer as the
 * shear-coupled tread's solve checks (free_clear), which checks them by the bound instead
 * (tirenv_ring__gaps_clear), and samples them after all where the bound does not certify them
 * (tirenv_ring__sample_whole). The edges stay sampled so that the window (the nodes whose
 * intervals hold ground within reach) is the whole sampling's. Not where the window holds more
 * than one vertex cut per SKIP_CUTS node intervals (a road): its cost is then the cuts', which
 * a gap does not save, and its contact often needs the whole window (a bump beside the patch),
 * for which the gaps would be sampled again. SKIP_EPS: the bound's slack for its own round-off
 * and the points' (m). */
enum { SKIP_NEAR = 2, SKIP_EDGE = 4, SKIP_STRETCH = 8, SKIP_CUTS = 8 };
static const double SKIP_MARGIN = 5e-4, SKIP_EPS = 1e-9;

/* The highest ground over the abscissae xa .. xb (xa <= xb): of the vertices from the one at
 * or before xa to the first at or after xb, and the flat extensions past the profile's ends
 * where the span reaches them; the polyline there lies below it. */
static double ground_max(const tirenv_profile *p, double xa, double xb)
{
    const double *X = p->x, *Z = p->z;
    const size_t n = p->n;
    double z_max = xb > X[n - 1] ? Z[n - 1] : -INFINITY;
    for (size_t k = xa < X[0] ? 0 : tirenv_profile__segment_at(p, xa); k < n; ++k) {
        z_max = Z[k] > z_max ? Z[k] : z_max;
        if (X[k] >= xb)
            break;
    }
    return z_max;
}

/* The highest ground a point of the nodes j0 .. j1's sector (one side of the vertical) can lie
 * on within reach (m; +INFINITY if the sector holds the vertical): a ground point P there at
 * angle phi lies below the centre by z - Z_P = rho cos(phi), rho >= (z - Z_P) / cos(phi_in)
 * (phi_in the sector's edge nearer the vertical), and horizontally between rho_lo sin(phi_in)
 * and reach sin(phi_out) from it, rho_lo a lower bound of rho: the highest ground in that span,
 * twice refined. Every ground within reach horizontally lies below the centre (the caller
 * checks), so a point's d is that of ground its ray meets, never of a line's extension; in an
 * interval j of the sector, d <= R0 - (z - z_max) / cos(phi_in of j). */
static double sector_max(const tirenv_ring *r, const tirenv_profile *p, double x, double z,
                         size_t j0, size_t j1, double reach)
{
    const double sa = r->sin_t[j0], sb = r->sin_t[j1];
    if (sa < 0 && sb > 0)
        return INFINITY;
    const int fwd = sb > 0;
    const double s_in = fwd ? sa : -sb, s_out = fwd ? sb : -sa,
                 c_in = fwd ? r->cos_t[j0] : r->cos_t[j1];
    double rho_lo = 0, z_max = INFINITY;
    for (int it = 0; it < 2; ++it) {
        const double h0 = rho_lo * s_in, h1 = reach * s_out;
        const double zm = fwd ? ground_max(p, x + h0, x + h1) : ground_max(p, x - h1, x - h0);
        z_max = zm < z_max ? zm : z_max;
        const double lo = (z - z_max) / c_in;
        if (!(lo > rho_lo))
            break;
        rho_lo = lo;
    }
    return z_max;
}

/* Room for the gaps' arrays (per node, and the runs). */
static int reserve_gaps(tirenv_ring *r)
{
    if (r->gap_d)
        return 0;
    r->gap_d = malloc(r->M * sizeof *r->gap_d);
    r->gaps = malloc(2 * r->M * sizeof *r->gaps);
    r->gaps_prev = malloc(2 * r->M * sizeof *r->gaps_prev);
    r->gap_on = calloc(r->M, 1);
    if (!r->gap_d || !r->gaps || !r->gaps_prev || !r->gap_on) {
        free(r->gap_d);
        free(r->gaps);
        free(r->gaps_prev);
        free(r->gap_on);
        r->gap_d = NULL;
        r->gaps = NULL;
        r->gaps_prev = NULL;
        r->gap_on = NULL;
        return TIRENV_ENOMEM;
    }
    return 0;
}

/* Gap entry g: intervals gaps[2 g] .. gaps[2 g + 1] with the bound gap_d[gaps[2 g]], m. */
static void add_gap(size_t *gaps, size_t *n_gaps, size_t j0, size_t j1)
{
    size_t *const e = gaps + 2 * (*n_gaps)++;
    e[0] = j0, e[1] = j1;
}

/* The far intervals of the sampling of nodes ja .. jb at (x, z), nv vertex cuts among them:
 * flagged in r->gap_on, as entries of r->gaps with their bounds in gap_d; returns their count
 * (0: sample all). */
static size_t far_intervals(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                            size_t ja, size_t jb, size_t nv, double reach)
{
    if (!r->near_ok || r->whole_ground || !r->tread || jb - ja < 2 * SKIP_EDGE + 1 ||
        nv * SKIP_CUTS > jb - ja ||
        reserve_gaps(r) || !(ground_max(p, x - reach, x + reach) < z))
        return 0;
    /* r's fields in locals: the flags' stores (chars) may alias them. */
    const double *const u = tirenv_ring__tread_u(r->tread), *const w = r->w,
                        *const cs = r->cos_t, *const sn = r->sin_t;
    const double t_r = r->par.t_r, R0 = r->R0;
    double *const gap_d = r->gap_d;
    unsigned char *const gap_on = r->gap_on;
    size_t *const gaps = r->gaps;
    size_t n_gaps = 0, count = 0;
    const size_t w0 = r->warm_lo, w1 = r->warm_lo + r->warm_n; /* where u and w hold */
    const size_t f0 = ja + SKIP_EDGE, f1 = jb - SKIP_EDGE;
    const size_t a = r->near_a > SKIP_NEAR ? r->near_a - SKIP_NEAR : 0, b = r->near_b + SKIP_NEAR;
    /* Stretches of up to SKIP_STRETCH intervals, their ground's height bounded once: the
     * whole stretch one gap where its bound at its inner end clears its lowest u and w, else
     * interval by interval, each bounded at its own inner end. */
    for (size_t j = f0 > w0 ? f0 : w0; j < f1;) {
        size_t e = j + SKIP_STRETCH < f1 ? j + SKIP_STRETCH : f1; /* intervals j .. e - 1 */
        if (j < a && e > a)
            e = a;
        if (j + 1 >= a && j <= b) {
            j = b + 1;
            continue;
        }
        if (e >= w1)
            break;
        const double z_max = sector_max(r, p, x, z, j, e, reach), h = z - z_max;
        const double dm = R0 - h / (sn[e] > 0 ? cs[j] : cs[e]);
        double um = u[j], wm = w[j];
        for (size_t i = j + 1; i <= e; ++i) {
            um = u[i] < um ? u[i] : um;
            wm = w[i] < wm ? w[i] : wm;
        }
        if (dm + SKIP_MARGIN <= um && dm - wm <= t_r - SKIP_MARGIN) {
            gap_d[j] = dm;
            memset(gap_on + j, 1, e - j);
            add_gap(gaps, &n_gaps, j, e - 1);
            count += e - j;
            j = e;
            continue;
        }
        for (; j < e; ++j) {
            const double dj = R0 - h / (sn[j + 1] > 0 ? cs[j] : cs[j + 1]);
            const double uj = u[j] < u[j + 1] ? u[j] : u[j + 1],
                         wj = w[j] < w[j + 1] ? w[j] : w[j + 1];
            if (!(dj + SKIP_MARGIN <= uj && dj - wj <= t_r - SKIP_MARGIN))
                continue;
            gap_d[j] = dj;
            gap_on[j] = 1;
            add_gap(gaps, &n_gaps, j, j);
            ++count;
        }
    }
    r->n_gaps = n_gaps;
    return count;
}

/* Whether interval j is one of the gaps. */
static inline int in_gap(const tirenv_ring *r, size_t j) { return r->gap_on[j]; }

/* The last sampling's gaps undone (their flags cleared). */
static void clear_gaps(tirenv_ring *r)
{
    for (size_t g = 0; g < r->n_gaps; ++g)
        memset(r->gap_on + r->gaps[2 * g], 0, r->gaps[2 * g + 1] + 1 - r->gaps[2 * g]);
    if (r->n_gaps) /* kept for shift_whole (gaps_prev exists with gaps) */
        memcpy(r->gaps_prev, r->gaps, 2 * r->n_gaps * sizeof *r->gaps);
    r->n_gaps_prev = r->n_gaps;
    r->n_gaps = 0;
}

/* Whether this sampling's gaps are the last one's intervals. */
static int same_gaps(const tirenv_ring *r)
{
    return r->n_gaps == r->n_gaps_prev &&
           (r->n_gaps == 0 ||
            memcmp(r->gaps, r->gaps_prev, 2 * r->n_gaps * sizeof *r->gaps) == 0);
}

int tirenv_ring__gaps_clear(const tirenv_ring *r, const double xw[])
{
    const double t_r = r->par.t_r;
    const size_t lo = r->lo;
    for (size_t g = 0; g < r->n_gaps; ++g) {
        const size_t j0 = r->gaps[2 * g], j1 = r->gaps[2 * g + 1];
        const double dm = r->gap_d[j0];
        double um = xw[2 * (j0 - lo) + 1], wm = xw[2 * (j0 - lo)];
        for (size_t j = j0 + 1; j <= j1 + 1; ++j) {
            const size_t i = j - lo;
            um = xw[2 * i + 1] < um ? xw[2 * i + 1] : um;
            wm = xw[2 * i] < wm ? xw[2 * i] : wm;
        }
        if (!(dm + SKIP_EPS <= um && dm - wm <= t_r - SKIP_EPS))
            return 0;
    }
    return 1;
}

int tirenv_ring__sampled_over(const tirenv_ring *r, size_t a, size_t b)
{
    for (size_t g = 0; g < r->n_gaps; ++g)
        if (r->gaps[2 * g] <= b && r->gaps[2 * g + 1] + 1 >= a)
            return 0;
    return 1;
}

/* The last sampling again, whole (win as tirenv_ring__sample's). */
static int sample_again(tirenv_ring *r, size_t win[2])
{
    const int whole = r->whole_ground;
    r->whole_ground = 1;
    const int st = tirenv_ring__sample(r, r->smp_p, r->smp_x, r->smp_z, r->smp_ja, r->smp_jb,
                                       r->smp_kt, win);
    r->whole_ground = whole;
    ++r->n_regap;
    return st;
}

int tirenv_ring__sample_whole(tirenv_ring *r)
{
    size_t win[2];
    return sample_again(r, win);
}

/* The vertices each side of x nearest to it, where the rays' walks start: the last with X < x
 * (-1: none) and the first with X > x (n: none). */
static inline void walk_starts(const tirenv_profile *p, double x, long *cur_b, long *cur_f)
{
    const double *X = p->x;
    long f = (long)(x < X[0] ? 0 : tirenv_profile__segment_at(p, x));
    if (!(X[f] > x))
        ++f;
    long b = f - 1;
    while (b >= 0 && X[b] >= x)
        --b;
    *cur_b = b, *cur_f = f;
}

/* Whether the walks at x start from the vertices the last fresh sampling's did. */
static int same_starts(const tirenv_ring *r, const tirenv_profile *p, double x)
{
    long cur_b, cur_f;
    walk_starts(p, x, &cur_b, &cur_f);
    return cur_b == r->shift_cur[0] && cur_f == r->shift_cur[1];
}

/* A sampling again, from the last one's points (docs/models.md 5.3; the same bits). Where the
 * pieces are the last sampling's (same_pieces: the same vertex cuts in the same order, each in
 * the same node interval) and so are the gaps, each piece's middle ray still lies between the
 * same two cuts. Its walk ends at the first vertex (outward) that the ray passes at or below,
 * every vertex before it passed above; for a vertex within reach horizontally and below the
 * centre that test is whether the vertex's angle seen from the centre lies beyond the ray's,
 * and every such vertex is a cut, on the same side of the ray as before. At a new x the walks
 * must start from the same vertices and go the same way (the caller checks the vertices each
 * side of the centre and the count of backward rays against the last fresh sampling's): then
 * each walks over the same vertices, and ends where it did. So where each piece's walk ended
 * at such a vertex (or past the profile's last, with the flat extension there within reach by
 * a margin), and each piece is wider than LINE_MARGIN rad (the test's and the angles'
 * round-off, some 1e-15 rad, cannot then order a vertex differently), every piece meets the
 * last sampling's line, and its points lie where that sampling wrote them. A node's point keeps
 * its angle, place, weight, d(d)/dz and stiffness (none depends on x without lugs); only its d
 * and ground abscissa move with x and z, computed again from the line by
 * rho_on's and piece_point's operations: the bits of a fresh sampling, without the walks, the
 * pieces' and points' other fields. The pieces with a vertex cut at an end (its angle moves
 * with z) are written whole, as is a point out of reach (its d is not kept). Returns 0 where a
 * piece's line may not be the same (a walk that passed no cut, a piece without a line outside
 * the gaps, a narrow piece) or a point comes into or out of reach (the window would change):
 * the caller then samples as usual, which writes every point again. wl: the window, the last
 * sampling's. */
static const double LINE_MARGIN = 1e-9;

static int shift_whole(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                       double reach, double k_t, size_t wl[2])
{
    const tirenv_ring_piece *const c = r->lines;
    const size_t n_lines = (r->smp_jb - r->smp_ja) + r->pc_nv;
    const long n = (long)p->n;
    const double *X = p->x, *Z = p->z;
    const double t_r = r->par.t_r, R0 = r->R0;
    tirenv_ring_point *const pts = r->pts;
    line_k lk = {0, 0, 0};
    int moved_last = 0; /* the last point was written whole (its weight only its piece's) */
    long k_line = -2;   /* the walk's end whose line lk holds, on side dir_line; -2: none */
    int dir_line = 0;
    for (size_t t = 0; t < n_lines; ++t) {
        const tirenv_ring_piece *const ct = &c[t];
        if (!ct->hit) { /* in a gap (the same gaps), or no line: then not the same */
            if (!(r->n_gaps && in_gap(r, ct->j)))
                return 0;
            continue;
        }
        const long k = ct->vk;
        const double sx = ct->sa + ct->sb;
        const int dir = sx > 0 ? 1 : -1;
        if (sx == 0) /* straight down: no walk */
            return 0;
        if (k >= 0 && k < n) {
            if ((k != k_line || dir != dir_line) && /* else the piece before's, checked */
                !(fabs(X[k] - x) <= reach && Z[k] < z))
                return 0;
        } else {
            /* Past the profile's last vertex that way, every one passed above (each a cut):
             * the flat extension, met within reach by the margin of its test. */
            const long e = sx > 0 ? n - 1 : 0;
            const double cz = ct->ca + ct->cb, lhs = (z - Z[e]) * fabs(sx);
            if (k != (sx > 0 ? n : -1) || !(lhs < (1 - LINE_MARGIN) * reach * cz))
                return 0;
        }
        if (k != k_line || dir != dir_line) { /* a line of its own (its walk's end) */
            line_of(ct->L, x, z, &lk);
            k_line = k, dir_line = dir;
        }
        tirenv_ring_point *const q = pts + ct->q0 + ct->joined;
        if (ct->da != 0 || ct->db != 0) { /* a vertex cut at an end: written whole */
            if (!(ct->pb - ct->pa > LINE_MARGIN))
                return 0;
            const double omega = 0.5 * (ct->pb - ct->pa), th = r->theta[ct->j];
            if (ct->joined) { /* the point it joins: the piece before's half, and its own */
                q[-1].omega = 0.5 * (c[t - 1].pb - c[t - 1].pa);
                q[-1].omega += omega;
                q[-1].ends = 3;
            }
            size_t w[2] = {wl[0], wl[1]};
            for (int e = ct->joined; e < 2; ++e) {
                tirenv_ring_point *const pe = q + (e - ct->joined);
                const int in = pe->d > -t_r;
                piece_point(r, ct, e, x, &lk, k_t, 0, w, omega, th, pe, 0);
                if ((pe->d > -t_r) != in) /* into or out of reach: the window may change */
                    return 0;
            }
            moved_last = 1;
            continue;
        }
        if (ct->joined && moved_last) { /* written whole with the piece before's half only */
            q[-1].omega += 0.5 * (ct->pb - ct->pa);
            q[-1].ends = 3;
        }
        moved_last = 0;
        for (int e = ct->joined; e < 2; ++e) {
            tirenv_ring_point *const pe = q + (e - ct->joined);
            if (!(pe->d > -t_r)) { /* out of reach: computed again, and must stay so */
                const double omega = 0.5 * (ct->pb - ct->pa), th = r->theta[ct->j];
                size_t w[2] = {wl[0], wl[1]};
                piece_point(r, ct, e, x, &lk, k_t, 0, w, omega, th, pe, 0);
                if (pe->d > -t_r)
                    return 0;
                moved_last = e == 1; /* its weight and ends as the moved pieces' */
                continue;
            }
            /* rho_on's and piece_point's operations on the same operands: the same bits. */
            const double den = pe->sn * lk.dZ + pe->cs * lk.dX, rho = lk.num / den,
                         d = R0 - rho;
            if (!(den > 0) || !isfinite(rho) || !(d > -t_r))
                return 0;
            pe->X = x + rho * pe->sn;
            pe->d = d;
        }
    }
    wl[0] = r->shift_win[0], wl[1] = r->shift_win[1]; /* no point came into or out of reach */
    return 1;
}

/* The points of the pieces r->lines[0 .. n_lines) with a line (hit) into pts, in order;
 * returns their count. by_nodes: a piece between two nodes (c->nodes) has its points written
 * by piece_point's loop for such pieces (the same bits). */
static inline __attribute__((always_inline)) size_t
write_points(tirenv_ring *r, size_t n_lines, int inside, double x, double z, double k_t,
             int lugs, size_t wl[2], tirenv_ring_point *pts, const int by_nodes)
{
    size_t n_pts = 0;
    line_k lk = {0, 0, 0};
    for (size_t i = 0; i < n_lines; ++i) {
        tirenv_ring_piece *c = &r->lines[i];
        if (!c->hit)
            continue;
        /* The points written last are c[-1]'s. With the centre inside the ground no piece
         * has a line (no ray cast, rho = 0 for all): none to compare (c->L was read unwritten,
         * valgrind's "depends on uninitialised value"; either way the values rho = 0 gives).
         * A run of pieces on one line shares its constants. */
        const int same =
            !inside && i > 0 && c[-1].hit && tirenv_ring__same_bits(c->L, c[-1].L, 4);
        if (!inside && !same)
            line_of(c->L, x, z, &lk);
        const line_k *const l = inside ? NULL : &lk;
        tirenv_ring_point *const q = pts + n_pts;
        const size_t w = by_nodes && c->nodes
                             ? piece_points(r, c, same, x, l, k_t, lugs, wl, q, 1)
                             : piece_points(r, c, same, x, l, k_t, lugs, wl, q, 0);
        c->joined = w == 1, c->q0 = n_pts + w - 2;
        n_pts += w;
    }
    return n_pts;
}

/* The points of the window's nodes ja .. jb (ja < jb, all of the lower half): the cuts, the
 * pieces between them, and each piece's line from a ray along its middle. Rays of one side are
 * cast outward from the vertical, so each walk starts where the last one ended. */
int tirenv_ring__sample(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                        size_t ja, size_t jb, double k_t, size_t win[2])
{
    size_t wl[2] = {r->M, 0}; /* win, local while the points are written */
    win[0] = wl[0], win[1] = wl[1];
    /* The last sampling's points may be moved (shift_whole) where it was on the same profile,
     * nodes and tread stiffness. */
    const int was = r->shift_ok && p == r->smp_p && ja == r->smp_ja && jb == r->smp_jb &&
                    tirenv_ring__same_bits(&k_t, &r->smp_kt, 1);
    const int same_x = p == r->smp_p && tirenv_ring__same_bits(&x, &r->smp_x, 1);
    r->shift_ok = 0;
    r->smp_p = p, r->smp_x = x, r->smp_z = z, r->smp_ja = ja, r->smp_jb = jb, r->smp_kt = k_t;
    clear_gaps(r);
    const double *X = p->x, *Z = p->z, reach = r->R0 + r->par.t_r;
    const double phi_a = r->theta[ja], phi_b = r->theta[jb];
    /* The vertices below the centre within reach horizontally, by angle: those a piece's ray
     * can pass (first_line walks that far). A vertex beyond reach is a cut too, though its
     * own point never touches: a piece's end values lie on its middle ray's line, and a
     * piece holding a vertex beyond reach would take them on that line's extension past the
     * vertex, which a steep flank's brings back within reach (a 45 mm tread compression
     * where the ray meets nothing, there at one z and gone a hair above it: F_z jumped by
     * 80 N over 3e-8 m at x = 49.93 m on the 6 in half-round road). */
    size_t nv = 0, jr = r->M;
    size_t k = x - reach < X[0] ? 0 : tirenv_profile__segment_at(p, x - reach);
    for (size_t kk = k; kk < p->n && X[kk] <= x + reach; ++kk) {
        const double dx = X[kk] - x, dz = z - Z[kk];
        if (!(dz > 0))
            continue;
        const double rho = sqrt(dx * dx + dz * dz);
        const double phi = cut_angle(r, dx, dz, &jr);
        if (!(phi > phi_a && phi < phi_b))
            continue;
        if (reserve((void **)&r->cuts, &r->cap_cuts, nv + 1, sizeof(cut)))
            return TIRENV_ENOMEM;
        ((cut *)r->cuts)[nv++] = (cut){phi, dx / rho, dz / rho, -dx / (rho * rho), kk};
    }
    cut *v = r->cuts;
    sort_by_angle(v, nv);
    const size_t n_pieces = (jb - ja) + nv;
    if (reserve_pts(r, 2 * n_pieces) ||
        reserve((void **)&r->lines, &r->cap_lines, n_pieces, sizeof *r->lines))
        return TIRENV_ENOMEM;
    v = r->cuts;
    const int inside = !(z > tirenv_profile_height(p, x)); /* centre in the ground: rho = 0 */
    const int lugs = isnan(k_t);
    /* The pieces in angle order, with their lines still to find; n_back of them first with
     * their rays backward (sx < 0), if ordered. */
    r->n_pts = 0;
    size_t iv = 0, n_lines = 0, n_back = 0;
    int contig = 0, ordered = 1;
    /* (At a new x only where the points may then be moved: on a road, whose window holds a
     * cut every node or more, the cuts seldom stay in their intervals over a step, and
     * comparing them costs more than the pieces' build saves.) */
    const int fresh =
        !((same_x || nv * SKIP_CUTS <= jb - ja) && same_pieces(r, ja, jb, v, nv));
    if (!fresh) {
        /* The last sampling's pieces: only their vertex ends moved (with x and z). Vertex i ends
         * piece (j_i - ja) + i and begins the next, no piece having zero length. */
        tirenv_ring_piece *const c = r->lines;
        for (size_t i = 0; i < nv; ++i) {
            const size_t t = (r->pc_vj[i] - ja) + i;
            c[t].pb = v[i].phi, c[t].sb = v[i].s, c[t].cb = v[i].c, c[t].db = v[i].dphi;
            c[t + 1].pa = v[i].phi, c[t + 1].sa = v[i].s, c[t + 1].ca = v[i].c;
            c[t + 1].da = v[i].dphi;
        }
        n_lines = n_pieces;
        ++r->n_kept;
        /* (Carried only where the cuts are few: on a road, whose window holds a cut every node
         * or more, their pieces are most of the pieces, and looking at them twice costs more
         * than the pass.) */
        if (nv * SKIP_CUTS <= jb - ja && back_carried(r, c, ja, nv, &n_back, &ordered)) {
            ++r->n_back_carried;
            if (r->back_check) {
                size_t nb;
                int ord;
                count_back(c, n_lines, &nb, &ord);
                r->n_back_bad += nb != n_back || ord != ordered;
            }
        } else {
            count_back(c, n_lines, &n_back, &ordered);
        }
    }
    /* Else built afresh, and kept for the next (pieces: their vertices and intervals). */
    const int keep =
        fresh && !reserve((void **)&r->pc_vk, &r->cap_pc, 2 * nv, sizeof *r->pc_vk);
    if (fresh)
        r->pc_vj = r->pc_vk ? r->pc_vk + nv : NULL;
    const double *const th = r->theta, *const sn = r->sin_t, *const cs = r->cos_t;
    const int nodes = !r->nodes_general; /* (for tests: none by the node pieces' writer) */
    for (size_t j = ja; fresh && j < jb; ++j) {
        const double pa = th[j], sa = sn[j], ca = cs[j], pb = th[j + 1], sb = sn[j + 1],
                     cb = cs[j + 1];
        if (!(iv < nv && v[iv].phi < pb) && pb > pa) {
            /* No vertex in the interval: its one piece, node to node (as below, written out:
             * the loop's cut records cost more than the piece's stores). */
            tirenv_ring_piece *c = &r->lines[n_lines];
            c->pa = pa, c->sa = sa, c->ca = ca, c->pb = pb, c->sb = sb, c->cb = cb;
            c->j = j, c->contig = contig, c->da = 0, c->db = 0, c->vk = -1, c->nodes = nodes;
            if (sa + sb < 0) {
                ordered &= n_back == n_lines;
                ++n_back;
            }
            ++n_lines;
            contig = 1;
            continue;
        }
        cut prev = {pa, sa, ca, 0, 0};
        for (;;) {
            cut next = {r->theta[j + 1], r->sin_t[j + 1], r->cos_t[j + 1], 0, 0};
            const int is_vertex = iv < nv && v[iv].phi < next.phi;
            if (is_vertex) {
                if (keep)
                    r->pc_vk[iv] = v[iv].k, r->pc_vj[iv] = j;
                next = v[iv++];
            }
            if (next.phi > prev.phi) {
                tirenv_ring_piece *c = &r->lines[n_lines]; /* its line and hit: below */
                c->pa = prev.phi, c->sa = prev.s, c->ca = prev.c, c->pb = next.phi;
                c->sb = next.s, c->cb = next.c, c->j = j, c->contig = contig;
                c->da = prev.dphi, c->db = next.dphi, c->vk = -1, c->nodes = 0;
                if (prev.s + next.s < 0) {
                    ordered &= n_back == n_lines;
                    ++n_back;
                }
                ++n_lines;
                contig = 1;
            } else {
                contig = 0;
            }
            prev = next;
            if (!is_vertex)
                break;
        }
    }
    if (fresh) {
        r->pc_valid = keep && n_lines == n_pieces;
        r->pc_ja = ja, r->pc_jb = jb, r->pc_nv = nv;
    }
    r->pc_back = n_back, r->pc_ordered = ordered, r->pc_back_ok = 1;
    /* The far intervals (see far_intervals) are left out: no ray, no point. */
    const size_t n_far = inside || lugs ? 0 : far_intervals(r, p, x, z, ja, jb, nv, reach);
    if (was && !fresh && !inside && ordered && nv * SKIP_CUTS <= jb - ja && same_gaps(r) &&
        n_back == r->shift_back && same_starts(r, p, x) &&
        shift_whole(r, p, x, z, reach, k_t, wl)) {
        ++r->n_shifted;
        r->n_pts = r->shift_n_pts;
        r->n_gapped += n_far > 0;
        r->shift_ok = 1;
        win[0] = wl[0], win[1] = wl[1];
        return 0;
    }
    /* Their lines: rays along the middle of each piece, each side walked outward. */
    long cur_b, cur_f;
    walk_starts(p, x, &cur_b, &cur_f);
    r->shift_cur[0] = cur_b, r->shift_cur[1] = cur_f, r->shift_back = n_back;
    if (ordered && inside) {
        for (size_t t = 0; t < n_lines; ++t)
            r->lines[t].hit = 1;
    } else if (ordered) { /* the backward rays' pieces first, outward, then the forward ones' */
        tirenv_ring_piece *const c = r->lines;
        long cb = cur_b, cf = cur_f; /* in registers: the stores to L do not reach them */
        for (size_t t = n_back; t-- > 0;) {
            c[t].hit = !(n_far && in_gap(r, c[t].j)) &&
                       first_line(p, x, z, c[t].sa + c[t].sb, c[t].ca + c[t].cb, reach, &cb,
                                  c[t].L);
            c[t].vk = cb;
        }
        for (size_t t = n_back; t < n_lines; ++t) {
            c[t].hit = !(n_far && in_gap(r, c[t].j)) &&
                       first_line(p, x, z, c[t].sa + c[t].sb, c[t].ca + c[t].cb, reach, &cf,
                                  c[t].L);
            c[t].vk = cf;
        }
    } else {
        for (size_t side = 0; side < 2; ++side) /* backward rays first, then forward */
            for (size_t i = 0; i < n_lines; ++i) {
                tirenv_ring_piece *c = &r->lines[side ? i : n_lines - 1 - i];
                const double sx = c->sa + c->sb, cz = c->ca + c->cb;
                if ((sx < 0) != (side == 0))
                    continue;
                c->vk = -1;
                c->hit = inside || (!(n_far && in_gap(r, c->j)) &&
                                    first_line(p, x, z, sx, cz, reach,
                                               sx < 0 ? &cur_b : &cur_f, c->L));
            }
    }
    /* (The pieces between two nodes written by their own loop where the window holds fewer
     * vertex cuts than node intervals: on a road with vertices 1 mm apart most pieces have a
     * vertex at an end, and the test a piece cost more there than the node pieces saved.) */
    const size_t n_pts =
        nv < jb - ja
            ? write_points(r, n_lines, inside, x, z, k_t, lugs, wl, r->pts, 1)
            : write_points(r, n_lines, inside, x, z, k_t, lugs, wl, r->pts, 0);
    r->n_pts = r->shift_n_pts = n_pts;
    r->shift_ok = ordered && !inside && !lugs;
    if (n_far && !(wl[0] < ja + SKIP_EDGE && wl[1] > jb - SKIP_EDGE)) {
        /* The ground within reach ends inside a gap, or none is sampled at an edge: the window
         * is the whole sampling's only when both edges hold some. */
        return sample_again(r, win);
    }
    r->n_gapped += n_far > 0;
    win[0] = wl[0], win[1] = wl[1];
    r->shift_win[0] = wl[0], r->shift_win[1] = wl[1];
    return 0;
}
