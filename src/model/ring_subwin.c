/* SPDX-License-Identifier: Apache-2.0 */
/* The shear-coupled tread's sub-windows: the nodes that can touch (docs/models.md section 5.2,
 * as the Winkler tread's ring_smooth.c does). Of the window (every node whose interval holds
 * ground within R0 + t_r) often half never touches: the ground lies within reach there, but the belt and the tread surface,
 * pressed in by the patch beside it, stay clear of it. The contact is solved on the
 * sub-window of the nodes in contact, SUB_PAD more on each side, its ends moved out to
 * multiples of SUB_QUANT node indices (so that it stays while the patch moves a little, and
 * few lengths, whose exterior corrections are kept, occur); every node outside it condenses
 * out exactly, as the window's exterior does (compute_end, of the sub-window's length). The
 * window's free nodes' (w, u) are then the exterior's unloaded response to the sub-window's
 * ends (fill_free: the six columns of K_EE^-1 that compute_end solves for anyway), and if no
 * point of theirs touches, the sub-window's answer is the minimum of E over the whole window
 * (its gradient vanishes at every unknown; the free points' knots carry nothing, a = 0). The
 * sub-window is first that of the contact the warm start predicts; when the contact found on
 * it asks for another, it is solved again there (Newton from the answer: one step if the
 * states stay); if a free point would touch, on the whole window, then on the sub-window of
 * its contact. So the answer is the sub-window's of its own contact, solved with its final
 * states, whatever the start. Its agreement with the whole window's minimum is round-off.
 * The equilibrium that solves on them is ring_shear.c's. */
#include <math.h>
#include <stddef.h>
#include "model/ring_shear_impl.h"
#include "model/ring_impl.h"

/* A point's tread surface and belt from the whole window's (w, u), xw interleaved from node
 * r->lo, without the knots (zero at the warm start and outside the solved sub-window). */
static double lin_u(const tirenv_ring *r, const tirenv_ring_point *q, const double xw[])
{
    const size_t i = q->j - r->lo;
    return (1 - q->s) * xw[2 * i + 1] + q->s * xw[2 * i + 3];
}

static double lin_w(const tirenv_ring *r, const tirenv_ring_point *q, const double xw[])
{
    const size_t i = q->j - r->lo;
    return (1 - q->s) * xw[2 * i] + q->s * xw[2 * i + 2];
}

static int touches(const tirenv_ring *r, const tirenv_ring_point *q, const double xw[])
{
    return q->d != -INFINITY &&
           (q->d > lin_u(r, q, xw) || q->d - lin_w(r, q, xw) > r->par.t_r);
}

/* The first and the last point of pts[k0 .. k1) in contact, by their states (warm: as the
 * window's xw leaves them); 0 if none. */
int tirenv_ring__contact_span(const tirenv_ring *r, size_t k0, size_t k1, const double xw[],
                              int warm, size_t *kf, size_t *kl)
{
    const tirenv_ring_point *const pts = r->pts;
    size_t k = k0;
    for (; k < k1; ++k)
        if (warm ? touches(r, &pts[k], xw) : pts[k].st != 0)
            break;
    if (k == k1)
        return 0;
    *kf = k;
    for (k = k1; k-- > *kf;)
        if (warm ? touches(r, &pts[k], xw) : pts[k].st != 0)
            break;
    *kl = k;
    return 1;
}

/* The sub-window a .. b of the window for the points pts[kf .. kl] (the first and the last in
 * contact) and the nodes beyond[0] .. beyond[1] (none if beyond[0] > beyond[1]: beyond_span),
 * and the points pts[k0 .. k1) of its intervals; 0 where it would leave fewer than
 * SUB_MIN_FREE free nodes. */
int tirenv_ring__sub_window(const tirenv_ring *r, size_t kf, size_t kl, const size_t beyond[2],
                            size_t *a, size_t *b, size_t *k0, size_t *k1)
{
    const size_t lo = r->lo, hi = r->lo + r->n - 1, Q = SUB_QUANT;
    const tirenv_ring_point *const pts = r->pts;
    size_t j1 = pts[kf].j, j2 = pts[kl].j + 1;
    if (beyond[0] <= beyond[1]) { /* and a softening carcass's nodes beyond its linear range */
        j1 = beyond[0] < j1 ? beyond[0] : j1;
        j2 = beyond[1] > j2 ? beyond[1] : j2;
    }
    size_t first = j1 >= SUB_PAD ? (j1 - SUB_PAD) / Q * Q : 0;
    size_t last = (j2 + SUB_PAD) / Q * Q + Q - 1;
    first = first > lo ? first : lo;
    last = last < hi ? last : hi;
    if ((first - lo) + (hi - last) < SUB_MIN_FREE || last - first + 1 < SUB_MIN)
        return 0;
    *a = first;
    *b = last;
    tirenv_ring__points_of(r, kf, kl, first, last, k0, k1);
    return 1;
}

/* With the softening carcass, the first and the last window node whose w in xw is beyond the
 * carcass's linear range w_0, into beyond (beyond[0] > beyond[1]: none, and always without
 * it): the sub-window must hold them, its exterior being condensed as linear. Returns beyond. */
const size_t *tirenv_ring__beyond_span(const tirenv_ring *r, const double xw[],
                                       size_t beyond[2])
{
    const tirenv_ring_tread *T = r->tread;
    beyond[0] = 1, beyond[1] = 0;
    if (!T->soft)
        return beyond;
    for (size_t i = 0; i < r->n; ++i)
        if (xw[2 * i] > T->law.w_0) {
            if (beyond[0] > beyond[1])
                beyond[0] = r->lo + i;
            beyond[1] = r->lo + i;
        }
    return beyond;
}

/* The nodes the first sub-window must hold besides the warm start's contact: beyond_span's,
 * and, where the last answer was within WARM_DX of x_c (m), the nodes of its contact. Without
 * them the contact the warm start predicts stopped short by tens of nodes: the sub-window then
 * grew by SUB_QUANT a try, and after SUB_TRIES the whole window was solved, then the
 * sub-window of its contact (five solves at a position's first evaluation over a class C
 * road, where one or two do now). */
const size_t *tirenv_ring__warm_span(const tirenv_ring *r, double x_c, const double xw[],
                                     size_t beyond[2])
{
    const tirenv_ring_tread *T = r->tread;
    const double *sp = T->span;
    tirenv_ring__beyond_span(r, xw, beyond);
    if (T->soft || sp[0] != 1 || !(fabs(x_c - sp[3]) <= WARM_DX))
        return beyond;
    /* (Node indices as doubles, exact: what a state saves is doubles. A damaged state's
     * are checked: within the window, or none.) */
    const double lo = (double)r->lo, hi = (double)(r->lo + r->n - 1);
    const double j1 = sp[1] > lo ? sp[1] : lo, j2 = sp[2] < hi ? sp[2] : hi;
    if (j1 <= j2 && j1 == floor(j1) && j2 == floor(j2))
        beyond[0] = (size_t)j1, beyond[1] = (size_t)j2;
    return beyond;
}

/* No point of the window's outside pts[k0 .. k1) touches at xw. Each one found clear is
 * written as a free point of the answer (no force, its overlap from xw): if they all are, the
 * answer is the sub-window's; if not, the window is solved again, which writes them all. */
int tirenv_ring__free_clear(tirenv_ring *r, size_t k0, size_t k1, const double xw[])
{
    /* r's fields in locals: a state's store (a char) may alias them. lin_u, lin_w inline. */
    tirenv_ring_point *const pts = r->pts;
    const size_t n_pts = r->n_pts, lo = r->lo;
    const double t_r = r->par.t_r;
    for (int run = 0; run < 2; ++run)
        for (size_t k = run ? k1 : 0; k < (run ? n_pts : k0); ++k) {
            tirenv_ring_point *q = &pts[k];
            if (q->d == -INFINITY) {
                q->e = -INFINITY;
            } else {
                const size_t i = q->j - lo;
                const double u = (1 - q->s) * xw[2 * i + 1] + q->s * xw[2 * i + 3];
                if (q->d > u || q->d - ((1 - q->s) * xw[2 * i] + q->s * xw[2 * i + 2]) > t_r)
                    return 0; /* touches */
                q->e = q->d - u;
            }
            q->st = 0;
            q->f = 0;
        }
    return 1;
}
