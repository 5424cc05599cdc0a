/* SPDX-License-Identifier: Apache-2.0 */
/* Private: the pieces of the springs model (docs/models.md section 4), one file each. */
#ifndef TIRENV_SPRINGS_IMPL_H
#define TIRENV_SPRINGS_IMPL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include "tirenv/profile.h"
#include "tirenv/springs.h"

/* key is among v[0 .. n) (ascending): a binary search. */
int tirenv_springs__long_in(const long *v, size_t n, long key);

/* The contact state the next force evaluation starts from (springs.c), as bytes: their
 * number for a model, its bytes on profile p (what was carried on another is not), and
 * those bytes back into a model of the same parameters on p: TIRENV_OK, or TIRENV_ENOMEM /
 * TIRENV_EINVAL (then nothing is carried to the next position). level: a model that
 * evaluates at one x on level ground only (the flat-ground workspace), whose contact is the
 * closed form's throughout: its warm start alone, nothing carried from one x to the next. */
size_t tirenv_springs__state_size(const tirenv_springs *s, int level);
void tirenv_springs__state_save(const tirenv_springs *s, const tirenv_profile *p, int level,
                                unsigned char *buf);
int tirenv_springs__state_restore(tirenv_springs *s, const tirenv_profile *p, int level,
                                  const unsigned char *buf);

/* Whether a continuous-contact evaluation at centre height z (m) goes straight to the QP,
 * without trying the elements' own rows first: the last evaluation's solution had a row
 * between elements working and z is within 0.05 R0 of its height (docs/models.md section
 * 11.2). */
int tirenv_springs__qp_first(const tirenv_springs *s, double z);

/* Right after tirenv_springs_forces at (x, z) on prof gave F (N) and dF_z/dz (N/m): the
 * height *z_root (m) where F_z = G (N) on its QP's working set (tirenv_springs__cc_root),
 * where the next evaluation is the update's; 1, or 0 where there is none (rays, the closed
 * form, an update). */
int tirenv_springs__root(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                         double G, double F, double dfz_dz, double *z_root);
/* Before the first evaluation at a new x on prof, from z0 (m, the last position's height):
 * the height *z (m) where F_z = G (N) at x on the last QP solve's working set
 * (tirenv_springs__cc_root_at, with the fan at (x, z0)), where the evaluation is the
 * update's check of that working set; 1, or 0 where there is none (rays, no QP solve kept,
 * an element held on a ground vertex, the same x). */
int tirenv_springs__start(tirenv_springs *s, const tirenv_profile *prof, double x, double z0,
                          double G, double *z);
/* The profile the model evaluates on is now p, not old (a streamed road's next window, the
 * same ground): what tirenv_springs__start carries from the last position is moved onto p's
 * vertices, where p has them (nothing is carried where p is other ground). old NULL: a new
 * sweep on p, nothing carried. */
void tirenv_springs__reprofile(tirenv_springs *s, const tirenv_profile *old,
                               const tirenv_profile *p);

/* The roots tirenv_springs__start found so far, and the updates accepted at them (for the
 * tests). */
void tirenv_springs__start_counts(const tirenv_springs *s, size_t *starts, size_t *updates);
/* The starts refused because a working row's vertex left its sector at the new x and could
 * not move into the next (for the tests). */
size_t tirenv_springs__start_sector(const tirenv_springs *s);
/* The starts whose working rows moved into the next sector, the working rows they let go for
 * a reaction below 0 at the root, and the rows they entered where a ground vertex crossed a
 * held element's ray (for the tests). */
void tirenv_springs__start_moves(const tirenv_springs *s, size_t *across, size_t *released,
                                 size_t *entered);
/* d[i] = R0 - rho[i] where that is > 0 (exactly where rho[i] < R0), else 0 (rho = INFINITY
 * too), for i in [a, b] (m): bit for bit the select v > 0 ? v : 0 on v = R0 - rho[i]. */
void tirenv_springs__penetrations(double R0, const double rho[], double d[], size_t a, size_t b);

/* The evaluations so far that tirenv_springs__cc_update gave (for the tests). */
size_t tirenv_springs__updates(const tirenv_springs *s);
/* The rays' d(rho)/dz taken from the face kept from an earlier x so far, and the faces
 * forgotten (for the tests: the same bits either way). */
size_t tirenv_springs__face_hits(const tirenv_springs *s);
void tirenv_springs__faces_forget(tirenv_springs *s);

/* What the model's contact length (springs_model.c) needs of the elements: their stiffnesses
 * k_r and k_ir (N/m), the diagonal of the tips' stiffness K (N/m: k_r + k_ir per neighbour)
 * and cos(theta_i), N entries each, owned by s. */
typedef struct {
    double k_r, k_ir;
    const double *diag, *cos_t;
} tirenv_springs__elements;
void tirenv_springs__elements_of(const tirenv_springs *s, tirenv_springs__elements *el);

/* The equilibrium's bracket at x (m) on p: the ground height under the centre (*z_lo) and R0
 * above the highest ground within R0 either side (*z_hi), where no element can reach the
 * ground; both from the rays' origin, which the force evaluations at x then reuse. */
void tirenv_springs__bracket(tirenv_springs *s, const tirenv_profile *p, double x,
                             double *z_lo, double *z_hi);

/* Ray casting: distance rho (m) from the centre (x, z) along u = (sin_t, -cos_t) to the first
 * crossing of the ground boundary, or INFINITY if there is none within rho_max. drho_dz is
 * d(rho)/dz with the hit segment fixed (0 on a vertical wall). A centre on or below the ground
 * gives rho = 0. */
double tirenv_springs__ray(const tirenv_profile *p, double x, double z, double sin_t,
                           double cos_t, double rho_max, double *drho_dz);

/* The same, given k = tirenv_profile__segment_at(p, x) and g = tirenv_profile_height(p, x)
 * (m), which do not depend on the ray: bit for bit the result of tirenv_springs__ray. */
double tirenv_springs__ray_at(const tirenv_profile *p, double x, size_t k, double g, double z,
                              double sin_t, double cos_t, double rho_max, double *drho_dz);

/* What one ray of a fan found, kept so that the next cast from the same x at another height
 * can reuse it (tirenv_springs__fan_reuse). */
typedef struct {
    long j;         /* the vertex that ended the walk (-1 or n: it ran off the profile) */
    int kind;       /* how it ended (springs_ray.c) */
    double z_low;   /* the walk's path holds for every centre height above this, m */
    double drho;    /* d(rho)/dz on the face it ends on, m/m; NAN until asked for */
} tirenv_springs__ray_memo;

/* Everything a fan of rays needs of its centre's x, found once per x. */
typedef struct {
    double x;       /* m */
    double g;       /* ground height at x, m (at a wall its top) */
    double g_side[2]; /* where a walk behind [0] and ahead [1] starts: g, or at a wall
                       * under x the wall's end on that side, m */
    long first[2];  /* first vertex strictly ahead of x backward [0] and forward [1] */
    double tol;     /* rounding allowance of the reuse test (without the |z| part), m */
    double z_max[2];  /* bounds of the ground within rho_max behind [0] and ahead [1], m */
    long n_reach;     /* about the vertices within rho_max of x: how finely the ground is
                       * sampled there (the first beyond on either side, and blocks, count) */
    size_t k;       /* tirenv_profile__segment_at(p, x) */
} tirenv_springs__fan_origin;

/* The origin at x; k_hint is any vertex index below p->n, near x for speed (the last
 * origin's k on the same profile: an exponential search from it, not a binary search over a
 * whole road). */
void tirenv_springs__fan_origin_at(const tirenv_profile *p, double x, double rho_max,
                                   size_t k_hint, tirenv_springs__fan_origin *o);

/* A fan's rays: ray i points along (sin_t[i], -cos_t[i]); i0 straight down, the others' angles
 * growing monotonically away from it on either side; inv_s, drop and reach from
 * tirenv_springs__fan_rays_fill, the per-ray constants of the walk. */
typedef struct {
    size_t i0;
    double rho_max;  /* m */
    const double *sin_t, *cos_t, *inv_s, *drop, *reach;
    int ordered;     /* tirenv_springs__fan_rays_ordered: 1 lets a fresh fan take the rays
                      * that end alike as runs; 0 (unknown) walks every ray */
} tirenv_springs__fan_rays;

/* With s = |sin_t|: inv_s = 1 / s (a ray's length per metre of walk along the ground: a
 * multiplication where there was a division per ray), drop = cos_t / s, reach = rho_max s,
 * for n rays. */
void tirenv_springs__fan_rays_fill(size_t n, const double sin_t[], const double cos_t[],
                                   double rho_max, double inv_s[], double drop[],
                                   double reach[]);

/* Whether the n rays of r have, outward from i0 on each side, drops that never grow and
 * reaches that never shrink (as computed): what a fan's resumption asks of each ray, then
 * known once for the tire. */
int tirenv_springs__fan_rays_ordered(const tirenv_springs__fan_rays *r, size_t n);

/* Casts the rays a..b (a <= i0 <= b) from (o->x, z): rho[i] as tirenv_springs__ray_at gives
 * it, bit for bit. Each ray's walk resumes where the previous ray's stopped (a ray turned
 * further from the vertical lies above its neighbour at every distance along the ground, so
 * it cannot cross the ground before where the neighbour did), so a fan costs O(rays +
 * vertices) instead of O(rays x vertices). memo[a..b] records each walk, for
 * tirenv_springs__fan_drho and tirenv_springs__fan_reuse. */
void tirenv_springs__fan(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                         const tirenv_springs__fan_rays *r, double z, size_t a, size_t b,
                         double rho[], tirenv_springs__ray_memo memo[]);

/* d(rho)/dz of ray i with a finite rho, from its memo: what tirenv_springs__ray_at gives
 * (computed once per memo, kept in it). */
double tirenv_springs__fan_drho(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                                size_t i, tirenv_springs__ray_memo *m);

/* The ground a streamed road's window holds around x in any case, its vertices k_lo .. k_hi
 * (from the last at or before x_lo = x - reach to the first after x_hi = x + reach): what
 * the start at a new x may read of the faces the last position's rays found (springs.c), so
 * that a whole sweep and a streamed one read the same. */
typedef struct {
    long k_lo, k_hi;
    double x_lo, x_hi;  /* m */
} tirenv_springs__face_window;
void tirenv_springs__face_window_at(const tirenv_profile *p, double x_lo, double x_hi,
                                    tirenv_springs__face_window *w);
/* Whether vertex id lies within w. */
int tirenv_springs__face_window_has(const tirenv_springs__face_window *w, long id);

/* For each ray i = rays[0..n) (ascending): its rho (m) from the origin o's centre at height
 * z to the face that memo[i]'s walk ended on (from any origin on the same profile), extended
 * as a line, into rho[i]: what the ray finds where it still crosses that face first (not
 * checked); its d(rho)/dz there into drho[i] (as tirenv_springs__fan_drho gives it, kept in
 * the memo; from kept[i], the face ray i last had one computed on, where it is that face,
 * else into it), and the memo into faces[i]. On a segment rho is the face's height below the
 * centre times d(rho)/dz, the height once for the rays on one face. Returns 0 at a memo with
 * no face, or one whose face is not within w (tirenv_springs__face_window_at). O(1) a ray: the
 * held rays at a new x before any fan is cast there (springs.c). */
int tirenv_springs__faces_rho(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                              const tirenv_springs__fan_rays *r, const size_t rays[], size_t n,
                              tirenv_springs__ray_memo memo[], tirenv_springs__ray_memo kept[],
                              double z, const tirenv_springs__face_window *w, double rho[],
                              double drho[], tirenv_springs__ray_memo faces[]);

/* Memo m of ray i from o's centre at height z (m) on the face at ground vertex v that the ray
 * crosses there (a working row's vertex that crossed the ray since m was walked,
 * springs_root.c): the face into v or out of it, as the walk would end near v: 1, or 0 where
 * neither is crossed (m then names no face: tirenv_springs__face_rho gives NAN and
 * tirenv_springs__faces_rho 0 for it). It holds no proof of reuse (z_low infinite): the
 * evaluation's fan walks the ray again. */
int tirenv_springs__memo_across(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                const tirenv_springs__fan_rays *r, size_t i, long v, double z,
                                tirenv_springs__ray_memo *m);

/* Whether memo m (bytes a state brought, springs.c) names only what profile p has: a kind a
 * walk ends with and, where the kind reads it, a vertex of p; with o's centre known (o not
 * NULL), a segment's other end too, for ray i of r (the one before its vertex on the ray's
 * side, or none where the vertex is the side's first). What the reuse of a memo indexes by. */
int tirenv_springs__memo_fits(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                              const tirenv_springs__fan_rays *r, size_t i,
                              const tirenv_springs__ray_memo *m);

/* The vertex at the far end of the segment memo m of ray i ended on, where the ray from o's
 * centre at height z (m) now passes above it (the vertex crossed the ray since the walk), else
 * -1. */
long tirenv_springs__memo_passed(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                 const tirenv_springs__fan_rays *r, size_t i, double z,
                                 const tirenv_springs__ray_memo *m);

/* The same for one ray i: its rho, or NAN where memo m has no face. */
double tirenv_springs__face_rho(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                const tirenv_springs__fan_rays *r, size_t i,
                                const tirenv_springs__ray_memo *m, double z,
                                const tirenv_springs__face_window *w);
/* Memo m of a walk on profile old as one on p, whose vertex k + off is old's k (a streamed
 * road's next window): its vertex moved by off where p has it, else no face (j = -2). */
void tirenv_springs__memo_reprofile(const tirenv_profile *old, const tirenv_profile *p,
                                    long off, tirenv_springs__ray_memo *m);

/* dd[i] = -d(rho)/dz for the rays i in [first, last] with mask[i] set (each with a finite
 * rho), as tirenv_springs__fan_drho gives it: one call for the pinned elements of an
 * evaluation. */
void tirenv_springs__fan_drho_neg(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                                  size_t first, size_t last, const unsigned char mask[],
                                  tirenv_springs__ray_memo memo[], double dd[]);

/* Recomputes rho[a..b] at a new centre height z from the walks recorded in memo[a..b] (from
 * the same profile and origin), where each ray provably still ends on the same face: its new
 * first crossing is found by the same arithmetic, so the result equals a fresh
 * tirenv_springs__fan bit for bit, and the memos stay valid. Returns 0, with nothing
 * guaranteed in rho, if some ray may have changed face; then call tirenv_springs__fan. */
int tirenv_springs__fan_reuse(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                              const tirenv_springs__fan_rays *r, double z, size_t a, size_t b,
                              double rho[], const tirenv_springs__ray_memo memo[]);

/* rho[a..b] at a new centre height z from the same origin: each ray whose memo provably
 * still holds as tirenv_springs__fan_reuse would give it, each other one walked again alone
 * (from where its inner neighbour ends), its memo made anew; a fresh fan where the centre
 * is on or below the ground or the straight-down ray's memo fails. Bit for bit
 * tirenv_springs__fan's rho; returns the number of rays walked again (b - a + 1 for a fresh
 * fan). The memos must cover [a, b] (from a fan or update of at least that span). */
size_t tirenv_springs__fan_update(const tirenv_profile *p, const tirenv_springs__fan_origin *o,
                                  const tirenv_springs__fan_rays *r, double z, size_t a,
                                  size_t b, double rho[], tirenv_springs__ray_memo memo[]);

/* A feature of the ground narrower than the ray spacing (springs_feature.c). */
typedef struct {
    double X, Z;      /* its highest point, m */
    double width;     /* its width where it is inside the tread, m */
    double rise;      /* how far it stands above that line, m */
    double depth;     /* how far it reaches into the tread, m */
    double distance;  /* from the centre, m */
    double spacing;   /* the rays' spacing at that distance, m */
} tirenv_springs__feature;

/* Ground that pokes into the tread between two rays a..b of a fan from (x, z) while neither
 * ray meets it, nor only the one ray between two others (on one side, or the straight-down
 * ray between its neighbours): a feature narrower than the ray spacing, which the elements cannot see (a real, continuous tread rests on it). rho[i] is
 * ray i's first crossing (INFINITY: none within rho_max), tread[i] the tread's distance from
 * the centre along ray i (m). A feature counts if it rises from and falls back to the line
 * joining what the rays on either side of it see (a crossing, or the ground under the tip of
 * a ray that meets none within rho_max) between them, stands more than tol above that line
 * and reaches deeper into the tread than the rays' spacing there (and than tol): shallower
 * ones change the answer by less than the model's own discretisation error, a ray missing a
 * corner by up to about a spacing. Returns 1 with *f describing the first one
 * found, else 0. O(rays + vertices between them). Usable by any model casting a fan of rays
 * (the ring: its belt's radius along each ray as tread). */
int tirenv_springs__unseen_feature(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                                   double x, double z, size_t a, size_t b, const double rho[],
                                   const double tread[], double tol,
                                   tirenv_springs__feature *f);

/* The pairs of rays (k, m) = (pairs[2q], pairs[2q+1]) that tirenv_springs__unseen_feature
 * must look between, given the walks of a fan (memo[a..b]): neighbours or rays two apart on
 * one side whose anchors may have three vertices or more between them (fewer cannot hold a
 * feature). pairs
 * has room for 2 (b - a + 1) pairs; returns their number. O(rays); the same for every height
 * the memo is reused at. */
size_t tirenv_springs__fan_pairs(const tirenv_springs__fan_origin *o,
                                 const tirenv_springs__fan_rays *r, size_t a, size_t b,
                                 const tirenv_springs__ray_memo memo[], size_t pairs[]);

/* tirenv_springs__unseen_feature over those pairs only. */
int tirenv_springs__unseen_pairs(const tirenv_profile *p, const tirenv_springs__fan_rays *r,
                                 double x, double z, const double rho[], const double tread[],
                                 const size_t pairs[], size_t n_pairs, double tol,
                                 tirenv_springs__feature *f);

/* A tridiagonal obstacle problem K w = p, w >= d, p >= 0, p.(w - d) = 0 with K given by its
 * diagonal diag[0..n-1] and constant off-diagonal -k_ir, solved by the primal-dual active
 * set method. active[] holds the starting guess (1 = w_i = d_i) and returns the final set.
 * work holds 2*n doubles (the factorisation of the last pass). */
int tirenv_springs__lcp(size_t n, const double diag[], double k_ir, const double d[],
                        double w[], double p[], unsigned char active[], double work[],
                        size_t max_passes, size_t *passes);

/* The tip LCP of a whole tire of N elements (k_r on the diagonal plus k_ir per neighbour,
 * -k_ir between neighbours) solved in closed form between pinned tips: a free element's
 * deflection follows from the two nearest pinned tips (or one pinned tip and a free end)
 * alone, so each pass of the active-set method is a few multiplications per element with no
 * division and no serial chain. The tables depend only on N, k_r and k_ir. */
typedef struct {
    size_t N;
    double k_ir;
    const double *diag;  /* N: the diagonal of K, N/m */
    const double *lq;    /* N: w_j = lq[j] w_{j+1} when 0..j are free */
    const double *rq;    /* N: w_j = rq[j] w_{j-1} when j..N-1 are free */
    const double *ce;    /* N+2: exp(-k mu), cosh(mu) = 1 + k_r / (2 k_ir) */
    const double *cm;    /* N+2: 1 - exp(-2 k mu) */
    const double *cmi;   /* N+2: 1 / cm[k] (k >= 1) */
} tirenv_springs__chains;

/* Fills the tables ce, cm, cmi (N+2 entries each) for tirenv_springs__chains. */
void tirenv_springs__chain_tables(size_t N, double k_r, double k_ir, double ce[], double cm[],
                                  double cmi[]);

/* An active set over [f0, f1]: count pinned elements from first to last, and the n_gaps
 * pairs of neighbouring pins gap[2k] < gap[2k+1] with free elements between them. gap holds
 * room for N pairs. */
typedef struct {
    size_t count, first, last, n_gaps;
    size_t *gap;
} tirenv_springs__pins;

/* The LCP with d[i] = 0 outside [f0, f1] (d[f0] > 0 and d[f1] > 0): only elements in
 * [f0, f1] can touch, so the active set lives there. Arrays are indexed by element over the
 * whole tire; only [f0, f1] of d, p and active and [f0 - 1, f1 + 1] of w are read or written
 * (w must have room for w[-1] and w[N]). active[] holds the starting guess and returns the
 * final set, also described in *P. */
int tirenv_springs__lcp_pinned(const tirenv_springs__chains *c, size_t f0, size_t f1,
                               const double d[], double w[], double p[],
                               unsigned char active[], tirenv_springs__pins *P,
                               size_t max_passes, size_t *passes);

/* The deflections over [f0, f1] for values v[] on the pinned elements of P (the same closed
 * form as the LCP's; v is read over [P->first, P->last]): dw for a change dd of the obstacle
 * when v = dd. */
void tirenv_springs__pinned_solve(const tirenv_springs__chains *c, size_t f0, size_t f1,
                                  const tirenv_springs__pins *P, const double v[], double w[]);


/* Continuous contact (springs_contact.c, docs/models.md section 4.8): the tread between
 * neighbouring elements i and i + 1 is the curve at distance R0 - (a(t) w_i + b(t) w_(i+1))
 * from the centre, t the parameter along the chord joining the two elements' unit directions
 * (tirenv_springs__cc_weights). Every ground vertex under the tread and every element's ray
 * crossing gives a row a w_i + b w_(i+1) + c lambda >= h (c the tread's own compliance at a
 * vertex between elements, 0 on an element; lambda the row's reaction); the tip problem
 * min 1/2 w^T K w + sum u^2 / (2 c) over the rows G w + u >= h is a strictly convex QP,
 * solved exactly by a primal active set method on banded KKT systems. */

/* What the contact needs of the tire: its elements and the tridiagonal K (diag, -k_ir off the
 * diagonal) with the free chains beyond the rows' span eliminated by lq and rq. */
typedef struct {
    size_t N, i0;
    double R0, k_r, k_ir;
    const double *sin_t, *cos_t, *diag, *lq, *rq;
    /* Filled by tirenv_springs__cc_tire_shape from k_r and k_ir: the tread's interpolation
     * (tirenv_springs__cc_weights), and bounds that let most ground vertices be dropped
     * before their weights: a(t) + b(t) >= 1 + ab_lo t (1 - t), |tau(t) - t| <= tau_dev;
     * c0 the compliance of an element of an endless free chain, 1/sqrt(k_r^2 + 4 k_r k_ir)
     * (m/N), which a row between elements adds (a + b - 1) times of its own
     * (tirenv_springs__cc_weights). */
    double gamma, sin_gamma, cot_gamma, ab_lo, tau_dev, c0;
    /* The largest 1 / sin(theta_(i+1) - theta_i) over neighbouring elements (with a margin
     * of 1e-9 of itself): a bound on dt/dpsi within a sector (springs_rows.c). */
    double inv_sin_step;
} tirenv_springs__cc_tire;

/* Element e's stiffness in the span f0 .. f1: K's diagonal with the free chains beyond the
 * span folded in at its ends (what the banded KKT system and the Schur factor both take). */
static inline double tirenv_springs__cc_k_diag(const tirenv_springs__cc_tire *T, size_t f0,
                                               size_t f1, size_t e)
{
    double d = T->diag[e];
    if (e == f0 && f0 > 0)
        d -= T->k_ir * T->lq[f0 - 1];
    if (e == f1 && f1 + 1 < T->N)
        d -= T->k_ir * T->rq[f1 + 1];
    return d;
}

/* Fills the shape fields of T (gamma, sin_gamma, cot_gamma, ab_lo, tau_dev, c0) from its
 * k_r, k_ir. */
void tirenv_springs__cc_tire_shape(tirenv_springs__cc_tire *T);

/* gamma for a tire of element stiffnesses k_r and k_ir: acos(exp(-mu)), cosh(mu) =
 * 1 + k_r / (2 k_ir), exp(-mu) the ratio of a neighbour's deflection to the loaded element's
 * under a point load on an element (pi/2 with k_ir = 0). */
double tirenv_springs__cc_gamma(double k_r, double k_ir);

/* The tread's weights at t in [0, 1] between two elements: a = sin((1 - t) gamma) /
 * sin(gamma), b = sin(t gamma) / sin(gamma) (and their derivatives in t). With a neighbour's
 * deflection exp(-mu) = cos(gamma) times the loaded element's, a^2 + b^2 + 2 a b cos(gamma) =
 * 1: a point load anywhere between the elements deflects the tread there as much as on an
 * element (linear weights would make the tread 2 t (1 - t) (1 - cos(gamma)) stiffer between
 * them, a ripple of h at the element spacing). The tips then carry (a + b) times the load to
 * the hub; the row's own compliance (a + b - 1) c0 (tirenv_springs__cc_tire) makes the
 * hub's stiffness to a lone point load the same anywhere along the tread (docs/models.md
 * section 4.8). */
void tirenv_springs__cc_weights(const tirenv_springs__cc_tire *T, double t, double *a,
                                double *b, double *da_dt, double *db_dt);
/* A row between elements' own compliance (a + b - 1) c0 (m/N; >= 0, a + b >= 1 but for
 * round-off) at its weights a and b, above; inline, the same bits wherever the rows are made
 * or moved in z (springs_rows.c, springs_update.c, springs_root.c). a + b - 1 is never -0
 * (x - 1 is +0 where x is 1), so its larger with 0 is the select below, NaN to 0 as fmax
 * has it: fmax's call sat on the root's secant's chain of dependent operations. */
static inline double tirenv_springs__cc_compliance(const tirenv_springs__cc_tire *T, double a,
                                                   double b)
{
    const double s = a + b - 1;
    return T->c0 * (s > 0 ? s : 0);
}

/* A row's t closer than this to 0 or 1 is taken as the element itself (springs_rows.c's snap);
 * a row between elements that springs_root.c carries in z must stay inside it. */
#define TIRENV_SPRINGS__T_SNAP 1e-6

/* One constraint row: ga w_i + gb w_j >= h, j = i + 1 for a row between two elements (t in
 * (0, 1): ga, gb the weights at t), t = 0 (ga = 1, gb = 0, j = i) for a row on element i
 * alone (its ray, or a vertex on it). */
typedef struct {
    size_t i, j;
    double t, tau;    /* chord parameter; tau = gb / (ga + gb), the hull's abscissa */
    double ga, gb, h; /* h: m */
    double dga_dz, dgb_dz; /* with the ground point fixed, 1/m */
    double dh_dz;     /* dh/dz, m/m; unused for a ray's row (the ray's memo gives it) */
    /* the tread's own compliance at the row's point, m/N (0 on an element), and its
     * derivative in z, m/N per m: the row reads ga w_i + gb w_j + cmp lambda >= h */
    double cmp, dcmp_dz;
    long id;          /* the ground vertex, or -1 - i for element i's ray */
} tirenv_springs__cc_row;

/* A row's identity in the layout: its id and i + j (tirenv_springs__cc's keys). */
typedef struct {
    long id;
    size_t ij;
} tirenv_springs__cc_key;

/* What the vertex scan (springs_rows.c) proved of one ground vertex at the first height z_r
 * it ran at for an x: that its row between the elements of sector i was dropped (at or below
 * the chord of the rays' penetrations times the tread's bow), with what it takes to prove
 * that again at another height of the same x without computing the row (docs/models.md
 * section 4.8, The later heights at one x). */
typedef struct {
    double margin;  /* the chord times the bow less h at z_r, m (its allowance is taken off
                     * where it is checked) */
    double m_t;     /* how far t may move: min(t, 1 - t) at z_r; 0: nothing proven (the
                     * bound on |dt/dz|, the least chord and the least depth are the
                     * sector's, springs_rows.c) */
    size_t i;       /* the sector */
} tirenv_springs__cc_seen;

/* The most working rows between elements solved through their Schur complement. */
#define TIRENV_SPRINGS__SCHUR_MAX 4

/* The working rows' columns of K_FF^-1 at their free elements (springs_root.c), for the
 * factor at counts (-1: none), the rows' k and elements el and the free chains' shares beyond
 * the span S (N/m): Y[s][r] at slot r's element, phi[s] f . the column, ylo and yhi at its
 * chain's ends. They depend on nothing else. */
typedef struct {
    unsigned long long at;
    size_t k, el[2 * TIRENV_SPRINGS__SCHUR_MAX];
    double S[2];
    double Y[2 * TIRENV_SPRINGS__SCHUR_MAX][2 * TIRENV_SPRINGS__SCHUR_MAX]; /* m/N */
    double phi[2 * TIRENV_SPRINGS__SCHUR_MAX];                              /* N/N */
    double ylo[2 * TIRENV_SPRINGS__SCHUR_MAX], yhi[2 * TIRENV_SPRINGS__SCHUR_MAX]; /* m/N */
} tirenv_springs__cc_cols;

/* The workspace: rows, the active set, the banded KKT factors, the warm start. Grows (once)
 * to the largest number of rows met. */
typedef struct {
    size_t cap_rows, cap_band;
    /* written by the layout alone (springs_rows.c), which keeps a ray's row it finds in place */
    tirenv_springs__cc_row *rows;
    size_t n_rows;
    /* the ground vertices' rows before the layout (each sector's hull is taken from them),
     * n_vrows of room for cap_vrows */
    tirenv_springs__cc_row *vrows;
    size_t n_vrows, cap_vrows;
    /* The vertex scan at the last x, seen_x, on the profile of serial seen_serial: the scans
     * there so far (seen_scans, counted up to springs_rows.c's scans_unproven), and whether
     * its proofs are made (seen_made), at the height seen_z, one for each vertex seen_j0 ..
     * seen_j0 + seen_n - 1 (room for cap_seen); the sectors seen_lo .. seen_hi hold them;
     * per sector (7 N, allocated with seen) the chord's P_l - slack and P_r - P_l at seen_z,
     * bounds on a proven vertex's |dt/dz| and on its depth, and room for what a later height
     * needs of them, which the guessing scan uses for its sectors' penetrations and slack
     * (springs_rows.c); per vertex the scan's list of vertices to compute (cap_seen); the
     * vertices the last scan skipped by the proofs and those whose sector its guess missed
     * (scan_prove; what the tests count);
     * scan_plain, set only by the tests: no proofs, every vertex computed by the plain scan
     * (what the proving loop and the proofs must give bit for bit); scan_blind, set only by
     * the tests: the proving scan guesses every vertex in the first sector in reach, so that
     * the walk from a missed guess takes nearly every vertex; scan_eager, set only by the
     * tests: the first scan at an x makes the proofs */
    tirenv_springs__cc_seen *seen;
    unsigned long long seen_serial;
    double seen_x, seen_z;
    size_t seen_j0, seen_n, cap_seen, seen_lo, seen_hi, scan_skipped, scan_missed;
    size_t seen_scans;
    int seen_made;
    int scan_plain, scan_blind, scan_eager;
    size_t scan_i;  /* the plain scan's sector of its first vertex within reach, where the
                     * next one's walk starts (any sector gives the same rows) */
    double *seen_sec;
    size_t *seen_todo;
    unsigned char *in_w;   /* per row: in the working set */
    double *lambda;        /* per row: reaction, N */
    size_t *order;         /* KKT unknowns: element (< N) or N + row */
    size_t *pos;           /* scratch of tirenv_springs__cc_rows' layout, cap rows */
    double *band, *rhs;
    /* per KKT unknown: the first column of its row's envelope (the first nonzero of the
     * system's row), and the last row whose envelope reaches its column */
    size_t *env_first, *env_last;
    size_t n_kkt, bw;
    /* with at most TIRENV_SPRINGS__SCHUR_MAX working rows between elements, the system is
     * solved by the tridiagonal K_FF and the rows' Schur complement (springs_schur.c):
     * per element the Thomas pivots and multipliers, the rows' columns of K_FF^-1 G^T
     * (N + 2 each); S's LDL^T factors; the rows' KKT positions */
    int use_schur;
    size_t n_schur, schur_pos[TIRENV_SPRINGS__SCHUR_MAX];
    size_t chain_lo[TIRENV_SPRINGS__SCHUR_MAX], chain_hi[TIRENV_SPRINGS__SCHUR_MAX];
    double *tri_piv, *tri_mul, *tri_y;
    size_t *chains, n_chains; /* the chains of free elements: first and last of each */
    /* tri_piv, tri_mul and chains hold K_FF's factor for the span tri_f0..tri_f1 and the
     * held elements wpos marks (tri_ok): the next layout with the same span and held
     * elements (the confirming evaluation, the next position) reuses it */
    int tri_ok;
    int factor_kept; /* the last factorisation kept K_FF's factor (what the tests count) */
    size_t tri_f0, tri_f1;
    double schur[TIRENV_SPRINGS__SCHUR_MAX * TIRENV_SPRINGS__SCHUR_MAX];
    /* per element (N): the pin row (or SIZE_MAX), first sector row and count (written for
     * the sectors in hull_sec alone: no other sector has rows), KKT position of w, scratch */
    size_t *pin_row, *sec_first, *sec_count, *wpos;
    size_t *held, n_held;  /* the held elements of wpos' layout, ascending (N of room) */
    /* per element: the vertex row in vrows that is its pin (SIZE_MAX: its ray), and its
     * sector's weighted vertex rows in vrows, the hull's candidates (cand_count of them from
     * cand_first, for the n_hull_sec sectors in hull_sec, ascending); the span laid out */
    size_t *pin_src, *cand_first, *cand_count, *hull_sec, n_hull_sec, lay_lo, lay_hi;
    /* per vertex row (cap_vrows): kept whether on the hull or not, because a solve of this
     * evaluation found it violated (tirenv_springs__cc_add_dropped); n_forced of them, and
     * the flags read only while n_forced > 0 (cleared over the vertex rows when the first is
     * set) */
    unsigned char *vforce;
    size_t n_forced;
    double *pin_h, *w_try, *step, *raise;
    /* warm start: the vertices of the last solution's active rows, ascending; pinned elements */
    long *warm_ids;
    size_t n_warm, cap_warm;
    unsigned char *warm_pin;
    size_t held_vertex;    /* the last solve's final set's elements held on ground vertices */
    size_t f0, f1;         /* the rows' element span (f0 > f1: no rows) */
    /* Each row's key as laid out (keys: its id, and i + j: 2 i on element i alone, 2 i + 1
     * between i and i + 1), and those of the last solve (last_keys, n_last of them) with its
     * span, while last_ok: rows laid out the same again (the confirming evaluation) find
     * in_w already holding the warm start and the KKT layout of its first eqp unchanged. */
    tirenv_springs__cc_key *keys, *last_keys;
    size_t n_last, last_f0, last_f1;
    int last_ok;
    size_t iterations;     /* of the last solve */
    /* the last evaluation's solution had a row between elements working: the next one within
     * a typical deflection of its centre height (between_z, m) goes to the QP without trying
     * the elements' own rows first (section 4.8, Cost) */
    int between;
    double between_z;
    /* The state of the last QP solve as tirenv_springs__cc_update's base, while base_ok: its
     * rows (rows, in_w, lambda, layout), its w over [f0 - 1, f1 + 1] (base_w[e + 1], m), the
     * derivative of each working row's reaction in z with the working set fixed (dlambda,
     * N/m; written by tirenv_springs__cc_slope for every row, cap_dl of room), and its centre
     * height (base_z, m). The caller sets base_ok once it has the slope and base_w. */
    int base_ok;
    int base_pins;         /* the base is the closed form's (tirenv_springs__cc_base_pins) */
    double base_z;
    double *base_w, *upd_w;  /* N + 2 each; upd_w is the update's scratch, indexed the same */
    double *dlambda;       /* per row, cap_dl of room */
    long *upd_pin;         /* per element: the id of its own row at the update's height */
    size_t cap_dl;
    /* The base's working set carried to where F_z meets the load (tirenv_springs__cc_root,
     * or at another x tirenv_springs__cc_root_at), while pred_ok: its position and height
     * (pred_x, pred_z, m), w on [f0, f1] (pred_w[e], m) and the working rows between
     * elements' reactions (pred_lam, N, in schur_pos' order), the update's start there;
     * pred_w N + 2; root_y its scratch, two columns of N + 2. */
    int pred_ok;
    double pred_x, pred_z;
    double *pred_w, *root_y;
    /* (tirenv_springs__cc_root_at) pred_w holds the held elements' rows at pred_z - pred_dz
     * (m), each element's w at the root pred_w + pred_dz root_du, read where asked (the
     * update sets the held ones to the fresh rays' rows itself); pred_held 0 where pred_w
     * is w at pred_z throughout (tirenv_springs__cc_root) */
    int pred_held;
    double pred_dz;
    double *root_du;       /* N + 2: tirenv_springs__cc_root_at's held rows' dh/dz */
    /* K_FF^-1 f (f the hub's weights, root_v: N + 2) for the factor n_factors counts, while
     * root_v_at is that count (tirenv_springs__cc_schur_factor counts each new factor) */
    double *root_v;
    unsigned long long n_factors, root_v_at;
    /* (tirenv_springs__cc_schur_flip) the factor's count before the last flip mended it, and
     * the elements whose chains the flip changed: a K_FF^-1 f solved for mend_at holds on the
     * other chains, which the flip left as they were */
    unsigned long long mend_at;
    size_t mend_lo, mend_hi;
    double pred_lam[TIRENV_SPRINGS__SCHUR_MAX];
    /* (tirenv_springs__cc_root_at) each working row's two elements and its load on each,
     * lambda g (N), for the check of the held elements' reactions */
    size_t pred_el[2 * TIRENV_SPRINGS__SCHUR_MAX];
    double pred_gl[2 * TIRENV_SPRINGS__SCHUR_MAX];
    /* (springs_root.c) the working rows' columns of K_FF^-1; the next x's root takes them
     * while their factor and rows stay, and reads them in place. */
    tirenv_springs__cc_cols cols;
} tirenv_springs__cc;

int tirenv_springs__cc_init(tirenv_springs__cc *c, size_t N);
void tirenv_springs__cc_free(tirenv_springs__cc *c);
void tirenv_springs__cc_forget(tirenv_springs__cc *c);  /* drop the warm start */
/* springs_schur.c: factor the KKT system laid out by the banded path (wpos, order, the
 * n_schur working rows between elements at schur_pos), K_FF's factor kept as it stands if
 * same (the span and the held elements those of the factor kept, tri_ok); 1 if the rows are
 * dependent. Then
 * solve it by element: x[e] on the free elements (the chains) holds the right-hand side of
 * K's rows and returns w_e; lam[q] holds that of the q-th working row between elements and
 * returns its reaction lambda (N). */
int tirenv_springs__cc_schur_factor(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                   int same);
/* The same after element e's row alone entered or left the working set (c->wpos[e] flipped
 * since K_FF was last factorised, the span the same): K_FF's factor kept but on e's chain
 * from e on, where it changed, and the chains mended; the bits schur_factor gives. */
int tirenv_springs__cc_schur_flip(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                  size_t e);
void tirenv_springs__cc_schur_solve_at(const tirenv_springs__cc *c,
                                       const tirenv_springs__cc_tire *T, double x[],
                                       double lam[]);
/* x := K_FF^-1 x on one chain [lo, hi] of free elements of the factor kept, x zero on
 * [lo, from). */
void tirenv_springs__cc_chain_solve(const tirenv_springs__cc *c, double x[], size_t lo,
                                    size_t from, size_t hi);
/* x1 := K_FF^-1 x1 on chain [lo1, hi1] and x2 := K_FF^-1 x2 on [lo2, hi2], each zero on
 * [lo, from), interleaved: the bits of a chain_solve on each. x1 and x2 one array only where
 * the chains are apart. */
void tirenv_springs__cc_chain_solve_pair(const tirenv_springs__cc *c, double x1[], size_t lo1,
                                         size_t from1, size_t hi1, double x2[], size_t lo2,
                                         size_t from2, size_t hi2);
/* x, y and z := K_FF^-1 of each on one chain [lo, hi] of the factor kept, x whole, y zero on
 * [lo, from_y), z on [lo, from_z), from_y <= from_z; three arrays apart: the bits of a
 * chain_solve on each. */
void tirenv_springs__cc_chain_solve_three(const tirenv_springs__cc *c, double x[], double y[],
                                          size_t from_y, double z[], size_t from_z, size_t lo,
                                          size_t hi);
/* x := K_FF^-1 x on every chain of the factor kept: the bits of a chain_solve on each. */
void tirenv_springs__cc_chains_solve(const tirenv_springs__cc *c, double x[]);

/* The rows of the tip problem at centre (x, z) over p given each element's ray penetration
 * d[a..b] (> 0, else +0 where the ray meets no ground within R0: never negative, -0 or NaN;
 * elements outside [a, b] cannot reach the ground): c->rows, their span c->f0..c->f1 (f0 >
 * f1: nothing touches), c->pin_h[e] (each element's own row's h, 0 if none) and
 * c->pin_row[e]. TIRENV_ENOMEM with diag. */
int tirenv_springs__cc_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                            const tirenv_profile *p, double x, double z, size_t a, size_t b,
                            const double d[], tirenv_diag *diag);

/* After a solve at w: the vertex rows the sectors' hulls dropped (below the hull, but a
 * working row's own compliance lets the tread in under it) that w violates (slack < -tol,
 * m) are kept as rows from now on and the rows laid out again (c->rows, the span as before).
 * Returns 1 if it added some (solve again), 0 if w violates none. Only sectors with a row
 * working are looked at: elsewhere the hull's rows provably hold the tread above them. */
int tirenv_springs__cc_add_dropped(tirenv_springs__cc *c, const double w[], double tol);

/* Whether every row between two elements holds (slack >= -tol, m) at w (over c->f0..c->f1):
 * then the solution of the elements' own rows alone (section 4.4's LCP with obstacle pin_h)
 * is the QP's, the rows between elements inactive. */
int tirenv_springs__cc_pins_hold(const tirenv_springs__cc *c, const double w[], double tol);

/* Solves the tip problem on the rows built at (x, z) (for the messages). Writes w over
 * [f0 - 1, f1 + 1] (free chains carried one element out) and pe[f0..f1] (each element's net
 * contact reaction, N), obstacle[f0..f1] (pin_h, m). Returns TIRENV_ENOMEM or TIRENV_ENOCONV
 * (with diag) on failure. */
int tirenv_springs__cc_solve(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                             double x, double z, double w[], double pe[], double obstacle[],
                             tirenv_diag *diag);

/* dw/dz over [f0, f1] (written to dw) of the last solution with its active set fixed; dd[i]
 * must hold d(d_i)/dz = -d(rho_i)/dz for every element i whose own ray row (id < 0, its
 * pin_row) is in the working set. With dd NULL, dw must hold on entry, over [f0, f1], each
 * held element's row's dh/dz (that d(d_i)/dz for a ray's, dh_dz for a vertex's; the held
 * elements: c->wpos[e] == SIZE_MAX) and 0 on the others: the caller's pass over the
 * elements does it (springs.c). Also each working row's d(lambda)/dz into c->dlambda;
 * returns TIRENV_ENOMEM if there was no room for them (dw is written all the same). */
int tirenv_springs__cc_slope(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                             const double w[], const double dd[], double dw[]);

/* The scan's forward walk (springs_rows.c) for a vertex at (dx, dz) from the centre (m,
 * dz > 0) over the rays (st, ct) = (sin, cos theta_k), k < N, |theta_k| <= pi/2: from ray i,
 * the ray before the first one past i where sigma_k = dx ct_k - dz st_k >= 0 fails, and
 * *s_n = -sigma_k there (N - 1 and 0 if none fails): bit for bit a walk a ray at a time. */
size_t tirenv_springs__walk_ahead(const double st[], const double ct[], size_t N, double dx,
                                  double dz, size_t i, double *s_n);

/* The vertex rows at (x, z) as tirenv_springs__cc_rows finds them before its hulls, into
 * c->vrows (c->n_vrows of them, in order of vertex): what the update checks against. It
 * overwrites the candidates the last layout kept (tirenv_springs__cc_add_dropped), so the
 * next solve must follow new rows. TIRENV_ENOMEM if there was no room. */
int tirenv_springs__cc_vertex_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                   const tirenv_profile *p, double x, double z, size_t a,
                                   size_t b, const double d[]);

/* The state at centre height z of the last QP solve's working set, had by its tangent from
 * the solve's height (springs_update.c, docs/models.md section 4.8, The confirming
 * evaluation): w = w_0 + (z - z_0) dw/dz on the free elements (dw from the solve's
 * tirenv_springs__cc_slope; the tangent only at the base's x, which the caller checks, and never
 * from the closed form's pins; at (c->pred_x, c->pred_z), while c->pred_ok, the state
 * tirenv_springs__cc_root or _root_at solved for, on the working set as the start left it), w_e = h
 * on the held ones, the rows between elements' reactions likewise, the held ones' from K w =
 * G^T lambda; then the QP's KKT conditions checked at z on every row there is at z (the rays'
 * penetrations d[a..b] >= 0 from (x, z), never NaN or -0; every ground vertex in reach): the working rows hold as
 * equalities and K w = G^T lambda to round-off, every reaction >= 0, every other row holds
 * (to 1e-12 R0, as the solve's). Returns 1 with w over [f0 - 1, f1 + 1], pe and obstacle
 * over [f0, f1] as tirenv_springs__cc_solve gives them and *contacts the elements of [f0, f1]
 * with pe > 0; 0 if a condition fails (or the base is not usable: then solve at z), w and pe
 * over [f0, f1] then written or not, obstacle not. */
int tirenv_springs__cc_update(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                              const tirenv_profile *p, double x, double z, size_t a, size_t b,
                              const double d[], const double dw[], double w[], double pe[],
                              double obstacle[], size_t *contacts);

/* springs_root.c: after a QP solve at (x, c->base_z) whose slope made it the update's base,
 * with hub force F0 (N) and dF_z/dz dF0 (N/m) there: the height *z_root (m) where F_z = G (N)
 * with its working set fixed (the rows' weights and heights at each height, the held rays'
 * rows linear in z), F_z = k_r sum cos(theta_e) w_e + S_l w_f0 + S_r w_f1 (the hub's sum,
 * S_l and S_r the free chains' beyond the span); its state kept as the update's start there
 * (c->pred_ok). Returns 1, or 0 where the working set does not allow it (a held element on a
 * vertex, a row leaving its sector, a negative reaction) or the base is not usable. dw is
 * the base's dw/dz over [f0, f1] (tirenv_springs__cc_slope's). docs/models.md section 4.8,
 * Newton's step on the working set. */
int tirenv_springs__cc_root(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                            const tirenv_profile *p, double x, double G, double F0, double dF0,
                            double S_l, double S_r, const double dw[], double *z_root);

/* springs_root.c: the same at another x, from the base's working set alone (its rows between
 * elements by ground vertex, its held elements on their rays' rows, K_FF's factor): given
 * each held element's ray at (x, z_a), rho[e] (m) and d(rho)/dz drho[e] (both finite), the
 * height *z_root where F_z = G with that working set at x, the secant's first step by slope
 * (N/m, < 0: the last dF_z/dz known); its state kept as the update's start at (x, *z_root)
 * (c->pred_ok). The update there (which checks every row at x) decides whether it is the QP's
 * solution.
 * Returns 1, or 0 as tirenv_springs__cc_root does, with *q_neg the working row whose reaction
 * was below 0 at the root found (else SIZE_MAX). docs/models.md section 4.8, A start at a
 * new x. */
int tirenv_springs__cc_root_at(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                               const tirenv_profile *p, double x, double z_a,
                               const double rho[], const double drho[], double G,
                               double slope, double S_l, double S_r, double *z_root,
                               size_t *q_neg);

/* springs_root.c: whether each working row between elements of the base (a ground vertex's)
 * still lies inside its sector at (x, z) (m), as tirenv_springs__cc_root_at first asks at
 * z_a: 0 where one does not (it would return 0 there), read before the held rays' faces
 * are found for it. The rows' vertices must lie in p. */
int tirenv_springs__cc_rows_inside(const tirenv_springs__cc *c,
                                   const tirenv_springs__cc_tire *T, const tirenv_profile *p,
                                   double x, double z);

/* springs_root.c: each working row between elements whose vertex left its sector at (x, z)
 * (m) across one of its elements' rays moved into the sector beyond, where both its elements
 * are free in the base's span, the rows' Schur complement formed again on K_FF's kept factor;
 * each crossed element and its row's vertex into crossed[] and vertex[] (up to
 * TIRENV_SPRINGS__SCHUR_MAX), their count into *n_crossed: 1, or 0 where a row cannot move (the base's rows are then no longer its own: the caller
 * drops the base). */
int tirenv_springs__cc_rows_across(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                   const tirenv_profile *p, double x, double z,
                                   size_t crossed[], long vertex[], size_t *n_crossed);

/* springs_root.c: the element whose own row the state tirenv_springs__cc_root_at kept
 * (pred_w at pred_z, its reactions pred_lam) violates most, looked for where the working set
 * changes with x (the ends of the chains of free elements and the held elements beside them,
 * the working rows' elements): a free element below its ray's row h[e] (m, read at the
 * chains' ends; NAN: none) by more than tol (m), else a held one whose reaction (K w - G^T
 * lambda, N) is below -tol_f (N); *e and 1 (*hold: 1 to hold it, 0 to release), or 0 where
 * none does. */
int tirenv_springs__cc_pred_worst(const tirenv_springs__cc *c,
                                  const tirenv_springs__cc_tire *T, const double h[],
                                  double tol, double tol_f, size_t *e, int *hold);
/* The base's working set with element e held on its ray's row (hold) or released, K_FF
 * factorised again: 0, or 1 (the base is then dropped: base_ok 0) where it cannot be. */
int tirenv_springs__cc_pred_flip(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                 size_t e, int hold);

/* Held element e let go where ground vertex v crossed its ray at (x, z) (m): v's row between e
 * and its neighbour on v's side, found among the base's rows (not working), enters the working
 * set (the span grown by the element beyond its end where needed), K_FF factorised again: 1, or
 * 0 where it cannot (the base is then dropped where it changed: base_ok 0). */
int tirenv_springs__cc_row_enter(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                 const tirenv_profile *p, double x, double z, size_t e, long v);

/* The base's working row q (between elements) out of the set, where the root at a new x
 * found its reaction below 0 (tirenv_springs__cc_root_at's q_neg), the rows' Schur complement
 * formed again: 0, or 1 (the base dropped) where it cannot be. */
int tirenv_springs__cc_pred_release(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                    size_t q);

/* After the closed form's evaluation at centre height z (m) held the elements pinned[e] of
 * [f0, f1] on their own rows with no row between elements working: that state as the base of
 * tirenv_springs__start at the next x (c->f0, f1, wpos, held, K_FF's factor; base_pins, so
 * that neither the update's tangent nor tirenv_springs__cc_root takes it). 1, or 0 where an
 * element is pinned on a ground vertex (or the factor fails): no base. */
int tirenv_springs__cc_base_pins(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                 size_t f0, size_t f1, const unsigned char pinned[],
                                 double z);

/* springs_rows.c: room for n rows (and their KKT unknowns alongside N elements). */
int tirenv_springs__cc_reserve_rows(tirenv_springs__cc *c, size_t n, size_t N);

/* springs_carry.c: the base the start at the next x and the update at this one take up
 * (while base_ok: its working set, the root's state, and where tangent (the base is the last
 * QP solve's at the x last evaluated, as it left it) its w and dw/dz dw[f0..f1] over its span
 * and its rows' reactions), as tirenv_springs__cc_carry_size(N) bytes: saved, with the
 * ray memos of the elements memo_a .. memo_b (the vertices their rays last ended on) and
 * whether one of the closed form's pins is on a ground vertex (pins_vertex); restored into a
 * workspace of the same tire (its warm start dropped, the base made again with K_FF's
 * factor), memo the restored memos, n_v the ground's vertices (0: none), dw written over
 * the span, *pins_vertex the flag: TIRENV_OK, TIRENV_ENOMEM, or TIRENV_EINVAL for bytes no
 * save wrote (an element, a row or a vertex out of range). docs/models.md
 * section 1.7. */
size_t tirenv_springs__cc_carry_size(size_t N);
void tirenv_springs__cc_carry_save(const tirenv_springs__cc *c, size_t N,
                                   const tirenv_springs__ray_memo memo[], size_t memo_a,
                                   size_t memo_b, const double dw[], int tangent,
                                   int pins_vertex, unsigned char *buf);
int tirenv_springs__cc_carry_restore(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                     const tirenv_springs__ray_memo memo[],
                                     const unsigned char *buf, size_t n_v, double dw[],
                                     int *pins_vertex);

/* ---- Identification on flat ground (springs_identify.c, springs_minmax.c) ---- */

/* The springs model par with c_b = beta*c_r and no sidewall at the n deflections d[] (m):
 * its load per unit c_r f[] (N per N/m/rad) and contact length l[] (m), one force
 * evaluation each. The model's errors. */
int tirenv_springs__unit_load(const tirenv_springs_params *par, double beta, size_t n,
                              const double d[], double f[], double l[], tirenv_diag *diag);

/* The elements' flat ground at one beta per unit c_r (springs_table.c), at `points`
 * deflections spaced geometrically from d_lo to d_hi (at most 0.9 R0): the logs of the load,
 * deflection and contact length where the load rises, n of them, ascending. Read at any load
 * and c_r: the elements' load at a deflection is proportional to c_r, their contact length
 * does not depend on it. d, f, l are the force evaluations' own arrays. */
typedef struct {
    size_t points, n;
    double *log_f, *log_d, *log_l, *d, *f, *l;
} tirenv_springs__table;
/* A table of points points in store, 6 * points doubles the caller keeps. */
void tirenv_springs__table_init(tirenv_springs__table *tb, double *store, size_t points);
/* Tabulates tb (points >= 2) for par with c_b = beta*c_r; the model's errors. */
int tirenv_springs__table_of(const tirenv_springs_params *par, double beta, double d_lo,
                             double d_hi, tirenv_springs__table *tb, tirenv_diag *diag);
/* The elements' deflection *d and contact length *l (m) at unit load f, linear in the logs
 * between the table's points: 1, or 0 outside the table. */
int tirenv_springs__table_at(const tirenv_springs__table *tb, double f, double *d, double *l);

#endif
