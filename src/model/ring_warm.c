/* SPDX-License-Identifier: Apache-2.0 */
/* The shear-coupled tread's warm start at a new abscissa (docs/models.md section 5.3): the
 * last answer's contact, kept by tirenv_ring__tread_new_x, moves the tread surface's start
 * with the ground under each of its nodes (tirenv_ring__warm_shift). The equilibrium that
 * starts from it is ring_shear.c's. */
#include <math.h>
#include <stddef.h>
#include "model/ring_shear_impl.h"
#include "model/ring_impl.h"

/* The warm start at a new abscissa moves the tread surface with the ground (WARM_DX): where
 * the ground under a node moved with x, the last answer's u read its points as free or deep
 * in, and Newton's first steps changed tens of states (with the line search over a road). A
 * node whose ray's ground touched the tread surface in the last answer, within WARM_DX of the
 * last x, starts from u + (d - d_last - dz d(d)/dz) of its ray's ground (dz u/dz already
 * follows the part that moves with z), where that moved by at most WARM_SHIFT_MAX (m; not a
 * cleat's face passing the ray). One pass over the points of the last contact's nodes; the
 * minimum does not depend on the start (its states' system is solved last), so the same
 * bits. */
static const double WARM_SHIFT_MAX = 1e-3;

/* The larger d of the points at each node ja .. jb of r's points from k_lo on (a node's own
 * ray; two one-sided values where a vertex lies at it), of those in contact with the tread
 * surface only with in_contact, into dn (-INFINITY where none), their d(d)/dz into ddn
 * (unless NULL). The points are in node order: the first of interval ja - 1 by bisection. */
static void node_d(const tirenv_ring *r, size_t k_lo, size_t ja, size_t jb, int in_contact,
                   double dn[], double ddn[])
{
    for (size_t j = ja; j <= jb; ++j)
        dn[j] = -INFINITY;
    size_t k0 = k_lo, k1 = r->n_pts;
    while (k0 < k1) {
        const size_t mid = k0 + (k1 - k0) / 2;
        if (r->pts[mid].j + 1 < ja)
            k0 = mid + 1;
        else
            k1 = mid;
    }
    for (size_t k = k0; k < r->n_pts && r->pts[k].j <= jb; ++k) {
        const tirenv_ring_point *q = &r->pts[k];
        if (!(q->s == 0 || q->s == 1) || (in_contact && !(q->st & 1)))
            continue;
        const size_t j = q->j + (q->s == 1);
        if (j >= ja && j <= jb && q->d > dn[j]) {
            dn[j] = q->d;
            if (ddn)
                ddn[j] = q->dd;
        }
    }
}

void tirenv_ring__tread_forget(tirenv_ring_tread *T)
{
    T->span[0] = 0;
    T->last_ok = T->dn_ok = 0;
}

void tirenv_ring__tread_new_x(tirenv_ring *r, double x)
{
    tirenv_ring_tread *T = r->tread;
    T->dn_ok = 0;
    if (T->soft || !T->last_ok || x == T->last_x || !(fabs(x - T->last_x) <= WARM_DX) ||
        r->k_first > r->k_last || r->k_last >= r->n_pts)
        return;
    if (T->skip > 0) {
        --T->skip;
        return;
    }
    T->dn_a = r->pts[r->k_first].j;
    T->dn_b = r->pts[r->k_last].j + 1;
    node_d(r, r->k_first, T->dn_a, T->dn_b, 1, T->dn, NULL);
    T->dn_x = T->last_x, T->dn_z = T->last_z, T->dn_ok = 1;
}

/* After tirenv_ring__tread_new_x: the shift of each node of the last contact that lies in this
 * window, applied to the warm start xw. A pass that moves no node by more than round-off
 * (level ground and a cleat's flat top move along the rays only with z) has the next
 * WARM_SHIFT_SKIP positions left out. */
enum { WARM_SHIFT_SKIP = 16 };

void tirenv_ring__warm_shift(tirenv_ring *r, double x_c, double z, double xw[])
{
    tirenv_ring_tread *T = r->tread;
    const size_t lo = r->lo, hi = lo + r->n - 1;
    const size_t ja = T->dn_a > lo ? T->dn_a : lo, jb = T->dn_b < hi ? T->dn_b : hi;
    if (!T->dn_ok || x_c == T->dn_x || ja > jb)
        return;
    T->dn_ok = 0;
    node_d(r, 0, ja, jb, 0, T->dn2, T->ddn);
    const double dz = z - T->dn_z;
    size_t moved = 0;
    for (size_t j = ja; j <= jb; ++j) {
        if (T->dn[j] == -INFINITY || T->dn2[j] == -INFINITY)
            continue;
        /* The node's point's d(d)/dz: d is linear in z along a ray to one line. */
        const double dd = T->dn2[j] - T->dn[j] - T->ddn[j] * dz;
        if (fabs(dd) <= WARM_SHIFT_MAX) {
            xw[2 * (j - lo) + 1] += dd;
            moved += fabs(dd) > 1e-12;
        }
    }
    if (moved == 0)
        T->skip = WARM_SHIFT_SKIP;
}
