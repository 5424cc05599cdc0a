/* SPDX-License-Identifier: Apache-2.0 */
/* The flexible-ring reference tire (docs/models.md section 5): a belt on an elastic foundation
 * with a tread of radial brush springs of finite thickness, in contact with the ground along
 * rays from the centre; where the tread is compressed through, the belt itself meets the
 * ground. This file casts the rays and owns the public API; ring_contact.c solves the contact,
 * ring_belt.c holds the belt's stiffness and the banded solver.
 *
 * The contact per node j (in the window of nodes that can touch, see cast_window):
 *   d_j = R0 - rho_j      penetration of the node's ray (rho_j: distance to the ground along it)
 *   b_j >= d_j            penetration of the nearest ground in the node's sector
 *                         |theta - theta_j| <= dtheta/2: the ray's, or a ground vertex's there
 *   w_j                   inward radial displacement of the belt
 *   e_j = d_j - w_j       tread compression
 *   F_j                   ground force on the node (N), radial: F_j = (S w)_j with S the belt's
 *                         stiffness condensed onto the window (ring_belt.c)
 *   tread:  F_j - g_j = kappa_j max(0, e_j)
 *   belt:   w_j >= b_j - t_r,  g_j >= 0,  g_j (w_j - b_j + t_r) = 0
 * so e_j <= t_r - (b_j - d_j) <= t_r: the tread is never compressed beyond its thickness, and
 * no ground point comes closer to the centre than the belt minus t_r at its node, even one
 * between two rays (a blade narrower than the node spacing). Each node is free (F = 0), in tread
 * contact (F = kappa (d - w)) or held by the belt (w = b - t_r, F = (S w)_j). With the states
 * fixed the belt displacements solve one symmetric positive definite banded system (S +
 * diag(kappa) on tread rows; identity rows holding w = b - t_r on belt rows, their values moved
 * to the right-hand side), whose factor also gives dF_z/dz exactly. */
#include "tirenv/ring.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "model/ring_impl.h"
#include "model/springs_impl.h"
#include "profile/profile_impl.h"

/* The smallest window the band solver takes (ring_impl.h). */
enum { RING_MIN_WINDOW = 6 };

enum { FREE = TIRENV_RING_FREE, T_BASIC = TIRENV_RING_T_BASIC, B_BASIC = TIRENV_RING_B_BASIC };

/* Fourier symbol of the belt per node: for w_j = cos(n theta_j) the energy per unit length
 * 1/2 EI ((w''+w)/R^2)^2 + 1/2 k_f w^2, with w'' the second difference (giving sigma =
 * (2 sin(n dtheta/2)/dtheta)^2 for n^2), times the arc R dtheta of a node, plus the tension's
 * c1 sum (dw)^2 + c0 sum w^2 (ring_belt.c), whose symbol is 8 c1 sin(n dtheta/2)^2 + 2 c0. */
static double mode_stiffness(const tirenv_ring *r, size_t n)
{
    const double sn = sin(M_PI * (double)n / (double)r->M), s = 2 * sn / r->dth;
    const double sigma = s * s, R = r->R;
    double c1, c0;
    tirenv_ring__tension(r->M, R, &r->par, &c1, &c0);
    const double e = r->par.EI * (sigma - 1) * (sigma - 1) / (R * R * R * R) +
                     tirenv_ring__foundation(&r->par);
    return R * r->dth * e + 8 * c1 * sn * sn + 2 * c0;
}

/* Whether the belt is stable: every mode's stiffness positive (otherwise the pretension
 * buckles the belt). */
static int belt_stable(const tirenv_ring *r)
{
    for (size_t n = 0; n < r->M; ++n)
        if (!(mode_stiffness(r, n) > 0))
            return 0;
    return 1;
}

/* The belt's compliance is circulant (a uniform ring): one column, the inverse discrete cosine
 * transform of 1/lambda_n. Only the state outside the window uses it (tirenv_ring_state); the
 * contact itself is solved on the banded stiffness. So it is computed there, at the first
 * call that needs it, not at every allocation: an O(M^2) sum, 8 million terms at 0.125 degree
 * nodes, was most of an allocation's cost, and a derivation allocates a ring for each trial
 * (src/formats/tir_derive.c). 0 if memory runs out. */
static int compute_compliance(tirenv_ring *r)
{
    const size_t M = r->M;
    double *inv_lambda = malloc(M * sizeof *inv_lambda), *cos_tab = malloc(M * sizeof *cos_tab);
    int ok = inv_lambda && cos_tab;
    for (size_t n = 0; ok && n < M; ++n) {
        inv_lambda[n] = 1 / mode_stiffness(r, n);
        cos_tab[n] = cos(2 * M_PI * (double)n / (double)M);
    }
    /* cos_tab's index n*m mod M stepped by m, where a division each term cost as much again;
     * the same terms in the same order, so the same bits. */
    for (size_t m = 0; ok && m < M; ++m) {
        double sum = 0;
        for (size_t n = 0, nm = 0; n < M; ++n) {
            sum += cos_tab[nm] * inv_lambda[n];
            nm += m;
            if (nm >= M)
                nm -= M;
        }
        r->c[m] = sum / (double)M;
    }
    free(inv_lambda);
    free(cos_tab);
    r->c_ready = ok;
    return ok;
}

tirenv_ring *tirenv_ring_alloc(double R0, const tirenv_ring_params *par)
{
    tirenv_tire check = tirenv_tire_default();
    check.springs.R0 = R0;
    check.ring = *par;
    if (tirenv_tire_check(&check, NULL))
        return NULL;
    tirenv_ring *r = calloc(1, sizeof *r);
    if (!r)
        return NULL;
    r->R0 = R0;
    r->R = R0 - par->t_r;
    r->par = *par;
    r->M = 2 * (size_t)round(M_PI / par->dtheta);
    r->i0 = r->M / 2;
    r->dth = 2 * M_PI / (double)r->M;
    const size_t M = r->M;
    /* theta, then the other per-node arrays, in one block. */
    double **const arrays[] = {&r->sin_t, &r->cos_t, &r->c,       &r->d,       &r->dd,
                               &r->b,     &r->db,    &r->X,       &r->kappa,   &r->w,
                               &r->F,     &r->rhs,   &r->A.a0,    &r->A.a1,    &r->A.a2,
                               &r->A.bm[0], &r->A.bm[1], &r->pn_w, &r->pn_p,   &r->pn_t,
                               &r->pn_g,  &r->g,     &r->B.a0,    &r->B.a1,    &r->B.a2,
                               &r->B.bm[0], &r->B.bm[1]};
    const size_t n_arrays = sizeof arrays / sizeof arrays[0];
    r->theta = malloc((n_arrays + 1) * M * sizeof(double));
    r->state = calloc(3 * M, 1);
    r->belt = tirenv_ring__belt_alloc(M, r->R, par);
    if (!r->theta || !r->state || !r->belt) {
        tirenv_ring_free(r);
        return NULL;
    }
    for (size_t k = 0; k < n_arrays; ++k)
        *arrays[k] = r->theta + (k + 1) * M;
    r->warm = r->state + M;
    r->flip = r->state + 2 * M;
    for (size_t j = 0; j < M; ++j) {
        r->theta[j] = ((double)j - (double)r->i0) * r->dth;
        r->sin_t[j] = sin(r->theta[j]);
        r->cos_t[j] = cos(r->theta[j]);
        r->d[j] = r->b[j] = -INFINITY;
        r->w[j] = 0; /* the state saves w whole (the warm start), also where no window was */
    }
    if (!belt_stable(r)) {
        tirenv_ring_free(r);
        return NULL;
    }
    /* The shear-coupled tread (TREAD_SHEAR > 0) on the continuous contact; the rays keep the
     * Winkler tread. */
    if (par->contact == TIRENV_RING_CONTINUOUS && tirenv_ring__tread_shear(par) > 0) {
        r->tread = tirenv_ring__tread_alloc(M, r->R, par, tirenv_ring__belt_stencil(r->belt));
        if (!r->tread) {
            tirenv_ring_free(r);
            return NULL;
        }
    }
    return r;
}

void tirenv_ring_free(tirenv_ring *r)
{
    if (!r)
        return;
    free(r->theta);
    free(r->state);
    free(r->pts);
    free(r->cuts);
    free(r->lines);
    free(r->pc_vk);
    free(r->gap_d);
    free(r->gaps);
    free(r->gaps_prev);
    free(r->gap_on);
    free(r->key);
    tirenv_ring__belt_free(r->belt);
    tirenv_ring__tread_free(r->tread);
    free(r);
}

double tirenv_ring_free_radius(const tirenv_ring *r) { return r->R0; }
size_t tirenv_ring_size(const tirenv_ring *r) { return r->M; }
const double *tirenv_ring_theta(const tirenv_ring *r) { return r->theta; }
double tirenv_ring_patch_length(const tirenv_ring *r) { return r->patch; }
double tirenv_ring_tread_max(const tirenv_ring *r) { return r->tread_max; }
size_t tirenv_ring_belt_contacts(const tirenv_ring *r) { return r->n_belt; }

/* Tread stiffness per node: lugs move with the tread, which turns by x/R0 as the tire rolls
 * forward, so the node at theta sees the tread point that was at theta + x/R0 at x = 0. */
double tirenv_ring__tread_kappa(const tirenv_ring *r, double theta, double x)
{
    const tirenv_ring_params *p = &r->par;
    double k_t = p->k_t;
    if (p->lug_count > 0) {
        const double u = (theta + x / r->R0) * p->lug_count / (2 * M_PI);
        if (u - floor(u) >= p->lug_fraction)
            k_t *= p->lug_ratio;
    }
    return k_t * r->R * r->dth;
}

/* The nearest ground of a node's sector, where it is a vertex of the profile: each vertex
 * within reach below the centre raises b of the node whose sector holds its angle. Rays alone
 * would let a blade narrower than the node spacing pass between two nodes. */
static void vertices_in_sectors(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                                double reach, size_t j_lo, size_t j_hi)
{
    const double *X = p->x, *Z = p->z;
    size_t k = x - reach < X[0] ? 0 : tirenv_profile__segment_at(p, x - reach);
    for (; k < p->n && X[k] <= x + reach; ++k) {
        const double dx = X[k] - x, dz = z - Z[k];
        if (!(dz > 0) || X[k] < x - reach)
            continue;
        const double rho = sqrt(dx * dx + dz * dz);
        if (!(rho < reach))
            continue;
        const double jr = (double)r->i0 + round(atan2(dx, dz) / r->dth);
        if (jr < (double)j_lo || jr > (double)j_hi)
            continue;
        const size_t j = (size_t)jr;
        if (r->R0 - rho > r->b[j]) {
            if (r->d[j] == -INFINITY)
                r->X[j] = X[k]; /* the ground point of a node its ray misses */
            r->b[j] = r->R0 - rho;
            r->db[j] = -dz / rho;
        }
    }
}

/* Rays of the lower half that reach the ground within R0 + t_r (the belt bulges outward away
 * from the patch, w < 0, so a ray a little longer than R0 may still touch; the tread thickness
 * bounds the bulge we allow for), and the ground vertices in their sectors. The window is the
 * span of nodes that see ground, widened to the band solver's smallest size. */
static void clear_window(tirenv_ring *r)
{
    for (size_t j = r->lo; j < r->lo + r->n; ++j)
        r->d[j] = r->b[j] = -INFINITY;
    r->n = 0;
}

static void cast_window(tirenv_ring *r, const tirenv_profile *p, double x, double z)
{
    clear_window(r);
    const double reach = r->R0 + r->par.t_r;
    const double gap = z - tirenv_profile_max_height(p, x - reach, x + reach);
    if (gap >= reach)
        return;
    size_t m = r->M / 4; /* up to the horizontal */
    if (gap > 0)
        m = (size_t)fmin((double)m, acos(gap / reach) / r->dth + 1);
    /* What every ray needs of x, found once (the same bits as tirenv_springs__ray). */
    const size_t k_x = tirenv_profile__segment_at(p, x);
    const double g_x = tirenv_profile_height(p, x);
    size_t first = r->M, last = 0;
    for (size_t j = r->i0 - m; j <= r->i0 + m; ++j) {
        if (r->cos_t[j] < 0)
            continue;
        double drho;
        const double rho = tirenv_springs__ray_at(p, x, k_x, g_x, z, r->sin_t[j], r->cos_t[j],
                                                  reach, &drho);
        if (!isfinite(rho))
            continue;
        r->d[j] = r->b[j] = r->R0 - rho;
        r->dd[j] = r->db[j] = -drho;
        r->X[j] = x + rho * r->sin_t[j];
    }
    vertices_in_sectors(r, p, x, z, reach, r->i0 - m, r->i0 + m);
    for (size_t j = r->i0 - m; j <= r->i0 + m; ++j)
        if (r->b[j] > -INFINITY) {
            first = j < first ? j : first;
            last = j;
        }
    if (first > last)
        return;
    /* Widen symmetrically; the window stays well inside the lower half plus two nodes. */
    while (last - first + 1 < RING_MIN_WINDOW) {
        --first;
        if (last - first + 1 < RING_MIN_WINDOW)
            ++last;
    }
    r->lo = first;
    r->n = last - first + 1;
    for (size_t j = first; j <= last; ++j)
        if (r->d[j] > -INFINITY)
            r->kappa[j] = tirenv_ring__tread_kappa(r, r->theta[j], x);
}

/* The ground point (X, Z) within reach: the angle of its ray raises that side's bound, kept
 * as its tangent |dx|/dz (the angle's atan2 once at the end, not a point at a time). */
static void raise_bound(double x, double z, double X, double Z, double tan_ang[2])
{
    const double dx = X - x, dz = z - Z;
    const int side = dx > 0;
    if (!(dz > 0)) { /* level with the centre or above it: the quarter circle */
        tan_ang[side] = INFINITY;
        if (dx == 0)
            tan_ang[!side] = INFINITY;
        return;
    }
    tan_ang[side] = fmax(tan_ang[side], fabs(dx) / dz);
}

/* Whether the ground point (X, Z) is below the centre at an angle from the vertical whose
 * tangent is at most its side's in tan_ang (up to the product's round-off). */
static int within_bound(double x, double z, double X, double Z, const double tan_ang[2])
{
    const double dx = X - x, dz = z - Z;
    return dz > 0 && fabs(dx) <= tan_ang[dx > 0] * dz;
}

/* Segment k of ground_angles (-1: the extension before X[0]; n - 1: the one after X[n-1]):
 * raises ang (tangents) by its points within reach, unless both its ends lie within them. */
static inline void segment_bound(const tirenv_profile *p, double x, double z, double reach,
                                 long k, double ang[2])
{
    const double *X = p->x, *Z = p->z;
    const size_t n = p->n;
    double x1, z1, x2, z2;
    if (k < 0) {
        x1 = x - reach - 1, z1 = Z[0], x2 = X[0], z2 = Z[0];
    } else if (k + 1 == (long)n) {
        x1 = X[n - 1], z1 = Z[n - 1], x2 = fmax(x + reach + 1, X[n - 1]), z2 = Z[n - 1];
    } else {
        x1 = X[k], z1 = Z[k], x2 = X[k + 1], z2 = Z[k + 1];
    }
    if (x1 > x + reach || x2 < x - reach)
        return;
    if (within_bound(x, z, x1, z1, ang) && within_bound(x, z, x2, z2, ang))
        return;
    /* |P1 + t (P2 - P1) - C|^2 = reach^2 for t in [0, 1]. */
    const double ex = x2 - x1, ez = z2 - z1, fx = x1 - x, fz = z1 - z;
    const double a = ex * ex + ez * ez, b = fx * ex + fz * ez,
                 c = fx * fx + fz * fz - reach * reach;
    if (!(a > 0)) {
        if (c < 0)
            raise_bound(x, z, x1, z1, ang);
        return;
    }
    const double disc = b * b - a * c;
    if (!(disc >= 0))
        return;
    const double sq = sqrt(disc), t1 = fmax(0, (-b - sq) / a), t2 = fmin(1, (-b + sq) / a);
    if (!(t1 <= t2))
        return;
    raise_bound(x, z, x1 + t1 * ex, z1 + t1 * ez, ang);
    raise_bound(x, z, x1 + t2 * ex, z1 + t2 * ez, ang);
}

/* The angles from the vertical, backward and forward (rad), beyond which no ray meets ground
 * within reach of the centre: along a straight segment the angle of its point is monotonic, so
 * the extremes of the ground inside the disc are vertices inside it or the crossings of
 * segments with its circle. The flat extensions beyond the profile's ends count as segments.
 * Each side is walked from its outer end inward, and a segment whose two ends lie within the
 * bounds found so far (each on its side) is passed over: by the same monotony no point of it
 * raises them. On a road that is nearly every segment after the outermost few. */
static void ground_angles(const tirenv_profile *p, double x, double z, double reach,
                          double ang[2])
{
    const double *X = p->x;
    const size_t n = p->n;
    ang[0] = ang[1] = 0;
    /* Segments k = -1 .. n - 1 (segment_bound): k_a to k_b the ones that reach from x - reach
     * to x + reach, k_m the first that ends beyond x. */
    const long k_a = x - reach < X[0] ? -1 : (long)tirenv_profile__segment_at(p, x - reach);
    long k_b = k_a, k_m = k_a;
    while (k_b + 1 < (long)n && X[k_b + 1] <= x + reach)
        ++k_b;
    while (k_m < k_b && k_m + 1 < (long)n && X[k_m + 1] <= x)
        ++k_m;
    for (long k = k_a; k < k_m; ++k) /* backward side, from its outer end */
        segment_bound(p, x, z, reach, k, ang);
    for (long k = k_b; k >= k_m; --k) /* forward side, from its outer end */
        segment_bound(p, x, z, reach, k, ang);
    ang[0] = atan(ang[0]); /* pi/2 from INFINITY */
    ang[1] = atan(ang[1]);
}

/* The nodes j0 .. j1 - 1 outside which the last evaluation of the continuous contact left F
 * and g zero: its window, or, with the shear-coupled tread, the nodes of the points from its
 * solve's first to its last in contact (r->k_first, r->k_last), the only ones it puts forces
 * on. */
static void force_nodes(const tirenv_ring *r, size_t *j0, size_t *j1)
{
    *j0 = r->lo, *j1 = r->lo + r->n;
    if (r->tread && r->n) {
        const int none = r->k_first > r->k_last;
        *j0 = none ? *j1 : r->pts[r->k_first].j;
        *j1 = none ? *j1 : r->pts[r->k_last].j + 2;
    }
}

/* The continuous contact's window: the nodes whose interval holds a point of ground within
 * reach (d > -t_r, as the rays' window), widened to the band solver's smallest size. */
static int cast_window_smooth(tirenv_ring *r, const tirenv_profile *p, double x, double z)
{
    size_t j0, j1; /* the last evaluation's forces cleared */
    force_nodes(r, &j0, &j1);
    for (size_t j = j0; j < j1; ++j)
        r->F[j] = r->g[j] = 0;
    r->n = 0;
    r->n_pts = 0;
    const double reach = r->R0 + r->par.t_r;
    /* The angles of the ground inside reach, two nodes beyond, at most a quarter circle each
     * side: one walk over the ground. Beyond them no ground lies within reach, and no piece
     * takes a point on a line's extension (tirenv_ring__sample cuts at every vertex a ray can
     * pass). (The highest ground of each side, in two more walks, bounded them as well
     * before; these bounds are never wider, up to the one node added here, whose pieces lie
     * out of reach: the same window.) */
    double ang[2];
    ground_angles(p, x, z, reach, ang);
    const size_t m_b = (size_t)fmin((double)(r->M / 4), ang[0] / r->dth + 2);
    const size_t m_f = (size_t)fmin((double)(r->M / 4), ang[1] / r->dth + 2);
    /* Without lugs every point's tread stiffness is the same: computed once, as each
     * point's would be. The points out of reach are marked, and the nodes of the others
     * found, as the points are written. */
    const int lugs = r->par.lug_count > 0;
    const double k_t = lugs ? NAN : tirenv_ring__tread_kappa(r, 0, x) / (r->R * r->dth);
    size_t win[2];
    const int status = tirenv_ring__sample(r, p, x, z, r->i0 - m_b, r->i0 + m_f, k_t, win);
    if (status)
        return status;
    size_t first = win[0], last = win[1];
    if (first > last) {
        r->n_pts = 0; /* no ground within reach */
        return 0;
    }
    while (last - first + 1 < RING_MIN_WINDOW) {
        --first;
        if (last - first + 1 < RING_MIN_WINDOW)
            ++last;
    }
    tirenv_ring_carcass law;
    if (r->tread && tirenv_ring__carcass_law(&r->par, 0, &law)) {
        /* A carcass that softens beyond w_0 (docs/models.md 5.1): the belt's rigid
         * translation presses the whole lower half in, so the window is that half, whose
         * exterior (the upper half, pulled out) stays in the carcass's linear range as its
         * condensation needs; ring_shear.c solves the nodes in contact and those beyond w_0. */
        const size_t h = r->M / 4 - 2;
        first = first < r->i0 - h ? first : r->i0 - h;
        last = last > r->i0 + h ? last : r->i0 + h;
    }
    r->lo = first;
    r->n = last - first + 1;
    return 0;
}

/* The continuous contact's length: from the first to the last point of positive compression,
 * each end extended to where the compression interpolated towards its free neighbour point
 * crosses zero. */
static double patch_length_smooth(const tirenv_ring *r)
{
    const tirenv_ring_point *q = r->pts;
    size_t k1 = r->n_pts, k2 = 0;
    if (r->tread) { /* the shear-coupled tread's solve found them */
        k1 = r->k_first;
        k2 = r->k_last;
    } else {
        for (size_t k = 0; k < r->n_pts; ++k)
            if (q[k].st != 0) {
                k1 = k < k1 ? k : k1;
                k2 = k;
            }
    }
    if (k1 > k2)
        return 0;
    double len = q[k2].X - q[k1].X;
    if (k1 > 0 && q[k1 - 1].d > -INFINITY && q[k1 - 1].e <= 0)
        len += q[k1].e / (q[k1].e - q[k1 - 1].e) * (q[k1].X - q[k1 - 1].X);
    if (k2 + 1 < r->n_pts && q[k2 + 1].d > -INFINITY && q[k2 + 1].e <= 0)
        len += q[k2].e / (q[k2].e - q[k2 + 1].e) * (q[k2 + 1].X - q[k2].X);
    return len;
}

/* The contact counts (over force_nodes) and, for the Winkler tread (with_max), its largest
 * compression; the shear-coupled tread's is its solve's (ring_shear.c), so its points are not
 * walked. */
static void summarise_smooth(tirenv_ring *r, int with_max)
{
    r->n_contact = r->n_belt = 0;
    size_t j0, j1;
    force_nodes(r, &j0, &j1);
    for (size_t j = j0; j < j1; ++j) {
        r->n_contact += r->F[j] > 0;
        r->n_belt += r->g[j] > 0;
    }
    if (!with_max)
        return;
    r->tread_max = 0;
    for (size_t k = 0; k < r->n_pts; ++k)
        if (r->pts[k].st != 0)
            r->tread_max = fmax(r->tread_max, fmin(r->pts[k].e, r->par.t_r));
}

static int forces_smooth(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                         double *fx, double *fz, double *dfz_dz, size_t *contacts,
                         tirenv_diag *diag)
{
    if (r->tread && r->n) /* the last answer's points, before the sampling replaces them */
        tirenv_ring__tread_new_x(r, x);
    int status = cast_window_smooth(r, p, x, z);
    if (status)
        return tirenv_error(diag, status, "", 0, "ring", "out of memory for the contact of "
                            "%zu ground points", r->n_pts);
    *fx = *fz = 0;
    if (dfz_dz)
        *dfz_dz = 0;
    if (r->n && r->tread)
        status = tirenv_ring__solve_shear(r, x, z, fx, fz, dfz_dz, diag);
    else if (r->n)
        status = tirenv_ring__solve_smooth(r, fx, fz, dfz_dz, diag);
    if (status) {
        r->n = 0;
        r->n_pts = 0;
        r->warm_n = 0; /* nothing of a failed solve is reported or reused */
        return status;
    }
    if (r->tread) { /* the contact counts; tread_max is the solve's */
        if (!r->n)
            r->tread_max = 0;
        summarise_smooth(r, 0);
    } else {
        summarise_smooth(r, 1);
    }
    if (contacts)
        *contacts = r->n_contact;
    r->patch = r->n ? patch_length_smooth(r) : 0;
    return 0;
}

/* Contact length: first to last node with a ground force, each edge extended to where the
 * interpolated tread compression between the edge node and its free neighbour crosses zero. */
static double patch_length(const tirenv_ring *r)
{
    size_t j1 = r->M, j2 = 0;
    for (size_t j = r->lo; j < r->lo + r->n; ++j)
        if (r->state[j] != FREE) {
            j1 = j < j1 ? j : j1;
            j2 = j;
        }
    if (j1 > j2)
        return 0;
    double len = r->X[j2] - r->X[j1];
    const double e1 = r->d[j1] - r->w[j1], e2 = r->d[j2] - r->w[j2];
    if (j1 > r->lo && r->d[j1 - 1] > -INFINITY && r->d[j1] > -INFINITY) {
        const double e0 = r->d[j1 - 1] - r->w[j1 - 1];
        if (e1 > 0 && e0 <= 0)
            len += e1 / (e1 - e0) * (r->X[j1] - r->X[j1 - 1]);
    }
    if (j2 + 1 < r->lo + r->n && r->d[j2 + 1] > -INFINITY && r->d[j2] > -INFINITY) {
        const double e3 = r->d[j2 + 1] - r->w[j2 + 1];
        if (e2 > 0 && e3 <= 0)
            len += e2 / (e2 - e3) * (r->X[j2 + 1] - r->X[j2]);
    }
    return len;
}

/* The last evaluation's contact counts and largest tread compression. */
static void summarise(tirenv_ring *r)
{
    r->n_contact = r->n_belt = 0;
    r->tread_max = 0;
    for (size_t j = r->lo; j < r->lo + r->n; ++j) {
        double e = 0;
        if (r->state[j] & T_BASIC) /* on the belt d - w = t_r - (b - d) >= 0 here */
            e = r->d[j] - r->w[j];
        r->n_contact += r->state[j] != FREE;
        r->n_belt += (r->state[j] & B_BASIC) != 0;
        r->tread_max = fmax(r->tread_max, e);
    }
}

int tirenv_ring_forces(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                       double *fx, double *fz, double *dfz_dz, size_t *contacts,
                       tirenv_diag *diag)
{
    if (r->par.contact == TIRENV_RING_CONTINUOUS)
        return forces_smooth(r, p, x, z, fx, fz, dfz_dz, contacts, diag);
    cast_window(r, p, x, z);
    const int status = r->n ? tirenv_ring__solve_contact(r, diag) : 0;
    for (size_t j = r->warm_lo; j < r->warm_lo + r->warm_n; ++j)
        r->warm[j] = FREE;
    r->warm_lo = r->warm_n = 0;
    if (status) {
        clear_window(r); /* nothing of a failed solve is reported */
        return status;
    }
    double sum_c = 0, sum_s = 0;
    for (size_t j = r->lo; j < r->lo + r->n; ++j) {
        if (r->state[j] == FREE)
            continue;
        sum_c += r->F[j] * r->cos_t[j];
        sum_s += r->F[j] * r->sin_t[j];
    }
    memcpy(r->warm + r->lo, r->state + r->lo, r->n);
    r->warm_lo = r->lo;
    r->warm_n = r->n;
    *fz = sum_c;
    *fx = -sum_s;
    summarise(r);
    if (contacts)
        *contacts = r->n_contact;
    r->patch = patch_length(r);
    if (dfz_dz)
        *dfz_dz = r->n ? tirenv_ring__dfz_dz(r) : 0;
    return 0;
}

int tirenv_ring__slope(tirenv_ring *r, double *dfz_dz)
{
    if (!r->n) { /* no ground within reach: solved with none, the slope 0 */
        *dfz_dz = 0;
        return 0;
    }
    return tirenv_ring__shear_slope(r, dfz_dz);
}

void tirenv_ring_state(const tirenv_ring *r, double w[], double f[])
{
    const size_t lo = r->lo, hi = r->lo + r->n;
    /* The compliance at its first use (compute_compliance): r is the caller's workspace,
     * allocated writable; what is filled in once depends only on the tire. */
    if (w && !r->tread && !r->c_ready && !compute_compliance((tirenv_ring *)r)) {
        for (size_t j = 0; j < r->M; ++j)  /* no memory for it: as the tread's exterior */
            w[j] = j >= lo && j < hi ? r->w[j] : NAN;
        w = NULL;
    }
    if (r->tread && w) {
        /* Outside the window the unloaded belt is held by its tread as well as its ends. */
        if (tirenv_ring__tread_exterior(r, w, NULL))
            for (size_t j = 0; j < r->M; ++j)
                w[j] = NAN;
        for (size_t j = lo; j < hi; ++j)
            w[j] = r->w[j];
        w = NULL;
    }
    /* The window's forces: with continuous contact every node's, with rays those of the nodes
     * not free. */
    const int all = r->par.contact == TIRENV_RING_CONTINUOUS;
    for (size_t j = 0; j < r->M; ++j) {
        const int inside = j >= lo && j < hi;
        if (w && inside) {
            w[j] = r->w[j];
        } else if (w) {
            w[j] = 0;
            for (size_t k = lo; k < hi; ++k)
                if (all || r->state[k] != FREE)
                    w[j] += r->c[j > k ? j - k : k - j] * r->F[k];
        }
        if (f)
            f[j] = inside && (all || r->state[j] != FREE) ? r->F[j] : 0;
    }
}

void tirenv_ring_contact(const tirenv_ring *r, double d[], double b[], double g[])
{
    const size_t lo = r->lo, hi = r->lo + r->n;
    if (r->par.contact == TIRENV_RING_CONTINUOUS) {
        /* d: the node's own ray (the larger of its one-sided values), b: the deepest point
         * its two intervals hold, g: the belt layer's share of its force. */
        for (size_t j = 0; j < r->M; ++j) {
            if (d)
                d[j] = -INFINITY;
            if (b)
                b[j] = -INFINITY;
            if (g)
                g[j] = j >= lo && j < hi ? r->g[j] : 0;
        }
        for (size_t k = 0; k < r->n_pts; ++k) {
            const tirenv_ring_point *q = &r->pts[k];
            if (q->d == -INFINITY)
                continue;
            /* A point at node j + 1 joining two pieces (tirenv_ring__sample) lies in interval
             * j + 1 too. */
            const size_t jn[3] = {q->j, q->j + 1, q->j + 2};
            const int ne = q->ends == 3 && q->s == 1 ? 3 : 2;
            for (int e = 0; e < ne; ++e) {
                if (b)
                    b[jn[e]] = fmax(b[jn[e]], q->d);
                if (d && q->s == (double)e)
                    d[jn[e]] = fmax(d[jn[e]], q->d);
            }
        }
        return;
    }
    for (size_t j = 0; j < r->M; ++j) {
        const int inside = j >= lo && j < hi;
        if (d)
            d[j] = inside ? r->d[j] : -INFINITY;
        if (b)
            b[j] = inside ? r->b[j] : -INFINITY;
        if (g) {
            g[j] = 0;
            if (inside && r->state[j] & B_BASIC)
                g[j] = r->state[j] & T_BASIC ? r->F[j] - r->kappa[j] * (r->d[j] - r->w[j])
                                             : r->F[j];
        }
    }
}

/* What the next contact solve starts from: the node states of the rays' contact, and the
 * continuous contact's w (and the shear-coupled tread's u) over the last window, zero
 * elsewhere. Without w a restored ring would start Newton elsewhere; its answer is the same
 * minimum, but where a line search stalls only to round-off. */
static size_t warm_fields(const tirenv_ring *r)
{
    return r->par.contact != TIRENV_RING_CONTINUOUS ? 0 : r->tread ? 2 : 1;
}

/* The shear-coupled tread's doubles after w: u, the slopes in z that the next start
 * follows, and the nodes of the last contact, which its first sub-window holds
 * (ring_shear.c). */
static size_t tread_doubles(const tirenv_ring *r)
{
    return warm_fields(r) == 2 ? tirenv_ring__tread_warm_size(r->tread) : 0;
}

/* The shear-coupled tread's step in z (ring_root.c): its curvatures, saved after the tread's
 * doubles. */
static size_t root_bytes(const tirenv_ring *r)
{
    return warm_fields(r) == 2 ? sizeof r->root : 0;
}

size_t tirenv_ring__state_size(const tirenv_ring *r)
{
    return 2 * sizeof(size_t) + r->M + (warm_fields(r) >= 1) * r->M * sizeof(double) +
           tread_doubles(r) * sizeof(double) + root_bytes(r);
}

void tirenv_ring__state_save(const tirenv_ring *r, unsigned char *buf)
{
    const size_t M = r->M;
    memcpy(buf, &r->warm_lo, sizeof r->warm_lo);
    memcpy(buf + sizeof r->warm_lo, &r->warm_n, sizeof r->warm_n);
    buf += 2 * sizeof(size_t);
    memcpy(buf, r->warm, M);
    buf += M;
    if (warm_fields(r) >= 1)
        memcpy(buf, r->w, M * sizeof *r->w);
    if (warm_fields(r) == 2)
        memcpy(buf + M * sizeof *r->w, tirenv_ring__tread_u(r->tread),
               tread_doubles(r) * sizeof *r->w);
    if (root_bytes(r))
        memcpy(buf + (M + tread_doubles(r)) * sizeof *r->w, &r->root, sizeof r->root);
}

void tirenv_ring__state_restore(tirenv_ring *r, const unsigned char *buf)
{
    const size_t M = r->M;
    memcpy(&r->warm_lo, buf, sizeof r->warm_lo);
    memcpy(&r->warm_n, buf + sizeof r->warm_lo, sizeof r->warm_n);
    buf += 2 * sizeof(size_t);
    memcpy(r->warm, buf, M);
    buf += M;
    if (warm_fields(r) >= 1)
        memcpy(r->w, buf, M * sizeof *r->w);
    if (warm_fields(r) == 2)
        memcpy(tirenv_ring__tread_u(r->tread), buf + M * sizeof *r->w,
               tread_doubles(r) * sizeof *r->w);
    if (root_bytes(r))
        memcpy(&r->root, buf + (M + tread_doubles(r)) * sizeof *r->w, sizeof r->root);
    /* Damaged bytes (a host's: docs/models.md section 1.7): no warm start rather than a NaN
     * one, or one whose node states are none of the four. A state byte with other bits set
     * passed the pivoting's checks as a tread in contact while its system left the node free:
     * the rays' answer came out a centimetre off, as if converged. Outside the window every
     * node is FREE, as the rays' solve leaves them (the continuous contact, all of them). */
    int ok = r->warm_lo <= M && r->warm_n <= M - r->warm_lo;
    if (ok) { /* the bits no state has, or'ed over the nodes (one loop each, no branches) */
        const size_t w0 = r->warm_lo, w1 = w0 + r->warm_n;
        unsigned char stray = 0;
        for (size_t j = 0; j < w0; ++j)
            stray |= r->warm[j];
        for (size_t j = w0; j < w1; ++j)
            stray |= r->warm[j] & (unsigned char)~(T_BASIC | B_BASIC);
        for (size_t j = w1; j < M; ++j)
            stray |= r->warm[j];
        ok = !stray;
    }
    const double *u = warm_fields(r) == 2 ? tirenv_ring__tread_u(r->tread) : NULL;
    for (size_t j = 0; j < M && warm_fields(r) >= 1; ++j)
        ok &= isfinite(r->w[j]);
    for (size_t j = 0; u && j < tread_doubles(r); ++j)
        ok &= isfinite(u[j]);
    if (!ok) {
        r->warm_lo = r->warm_n = 0;
        memset(r->warm, FREE, M);
        for (size_t j = 0; j < M; ++j)
            r->w[j] = 0;
        if (r->tread)
            memset(tirenv_ring__tread_u(r->tread), 0,
                   tirenv_ring__tread_warm_size(r->tread) * sizeof(double));
    }
    /* Damaged curvatures: none, and Newton's linear steps. */
    const double *rd = (const double *)&r->root;
    int root_ok = 1;
    for (size_t i = 0; i < sizeof r->root / sizeof *rd; ++i)
        root_ok &= isfinite(rd[i]);
    root_ok &= r->root.n[0] >= 0 && r->root.n[0] <= TIRENV_RING_ROOT_KEEP &&
               r->root.n[1] >= 0 && r->root.n[1] <= TIRENV_RING_ROOT_KEEP &&
               r->root.eq_n >= 0 && r->root.eq_n <= TIRENV_RING_START_KEEP;
    if (!root_ok)
        tirenv_ring__root_clear(r);
}
