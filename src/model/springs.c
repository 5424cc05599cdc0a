/* SPDX-License-Identifier: Apache-2.0 */
/* The radial + interradial springs model (docs/models.md section 4, the paper's Figure 4): element
 * layout, stiffness, and the hub forces for a given centre position. */
#include "tirenv/springs.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "model/model_impl.h"
#include "model/springs_impl.h"
#include "profile/profile_impl.h"

/* The active-set iteration on an M-matrix changes its set monotonically, so it settles in at
 * most n passes for n elements that can touch, and one more confirms it (docs/models.md
 * section 4.4). The limit is that bound: a fixed one (200 passes, as before) failed every run
 * with ELEMENT_ANGLE = 2e-4 rad, whose cold start over about 3000 touching elements takes
 * about 530 passes. */
static size_t lcp_max_passes(size_t f0, size_t f1) { return f1 - f0 + 2; }

/* How far (in R0) from the last evaluation's centre height its working row between elements
 * still sends an evaluation straight to the QP: a typical deflection (the equilibrium's
 * dz_hint, 0.05 R0). The flag spares the closed form's pass where the QP's warm start is a
 * step away and the closed form would fail; farther off (Brent's bracket end at the ground,
 * the hub pressed in by the radius), the warm start is stale and the QP would rebuild its
 * working set a row at a time (some 300 steps over the ring) where the closed form holds
 * (docs/models.md section 11.2). Either path gives the same solution to round-off. */
static const double between_reach = 0.05;

struct tirenv_springs {
    tirenv_springs_params par;
    size_t N;              /* number of elements */
    size_t i0;             /* index of the element at theta = 0 */
    double k_r;            /* radial element stiffness c_r*dphi, N/m */
    double k_ir;           /* interradial element stiffness c_b/dphi, N/m */
    double *theta, *sin_t, *cos_t;  /* element angles, rad */
    double *diag;          /* diagonal of K over all elements, N/m */
    /* Elements with d = 0 never touch (p = 0), so the free chains from either end of the
     * tire to the first element that can touch are solved once, by Gaussian elimination from
     * each end: L_D[j] is the eliminated diagonal of element j with 0..j-1 eliminated, R_D[j]
     * the same from the right, lq[j] = k_ir / L_D[j] and rq[j] = k_ir / R_D[j] carry a
     * deflection outward along them. The chains' share of the hub forces is proportional to
     * the end element's deflection: S_lc[a] = sum_{j<a} k_r cos(theta_j) w_j / w_a, and so on. */
    double *L_D, *R_D, *lq, *rq, *S_lc, *S_ls, *S_rc, *S_rs;
    double *ce, *cm, *cmi;  /* the closed form between pinned tips (springs_lcp.c) */
    tirenv_springs__chains chains;
    /* State of the last evaluation: elements [a, b] may touch (d > 0 at both ends; empty if
     * a > b), per-element arrays. */
    size_t a, b;
    size_t span[2];        /* the last side_span walks' ends, back and forward */
    double *d, *w, *p, *dd, *dw;  /* w and dw have a spare entry before 0 and after N - 1 */
    unsigned char *active;
    tirenv_springs__pins pins;
    /* The rays of the last evaluation, kept for the next one at the same x on the same
     * profile (tirenv_springs__fan_reuse): [ray_a, ray_b] were cast from (origin.x, any z). */
    unsigned long long ray_serial;  /* profile serial; 0 = nothing kept */
    tirenv_springs__fan_origin origin;
    size_t ray_a, ray_b;
    size_t *pairs, n_pairs, pairs_a, pairs_b;  /* of rays a..b, for check_unseen */
    double *rho, *ray_inv_s, *ray_drop, *ray_reach, *tread;
    tirenv_springs__fan_rays rays;
    tirenv_springs__ray_memo *memo;
    /* Each ray's last d(rho)/dz computed, with the vertex and kind its walk ended on (face,
     * on the profile ray_serial; kind -1: none). It depends on nothing else, so a fresh fan at
     * the next x whose ray ends on the same face takes it from here: for the QP's slope (most
     * held rays over a cleat, where the division and the face's lookup were some 2 % of the
     * instructions), not the closed form's (a road's rays end on another face at each x: the
     * check and the copy cost more than the hits spared, +1.5 % over the class C road). */
    tirenv_springs__ray_memo *face;
    size_t face_hits;
    /* The rays memo[memo_a..memo_b] were last walked on the profile of serial memo_serial
     * (from any x: set_origin forgets them for reuse, not their faces); pred_face[e], the
     * face tirenv_springs__start took held element e's ray to end on at the new x. */
    size_t memo_a, memo_b;
    unsigned long long memo_serial;
    tirenv_springs__ray_memo *pred_face;
    /* dF_z/dz depends only on the faces the pinned rays end on, the span [f0, f1] and the
     * pins: the last one solved for is kept with them and given again, bit for bit, when they
     * recur (the second evaluation at an x, after Newton's step, nearly always). fans counts
     * the fresh fans cast: the faces are the same while it is. */
    unsigned long long fans;
    /* CONTACT = 'continuous' (springs_contact.c): the tip problem with rows between the
     * elements; its workspace and what it needs of the tire. */
    tirenv_springs__cc cc;
    tirenv_springs__cc_tire cc_tire;
    struct {
        int valid;
        unsigned long long fans;
        size_t f0, f1, count, first, last, n_gaps;
        size_t *gap;       /* N pairs, as in pins */
        double dfz_dz;     /* N/m */
    } slope;
    /* The base of the continuous contact's update (tirenv_springs__cc_update): its x (m),
     * profile and dF_z/dz (N/m). */
    double upd_x, upd_dfz_dz;
    unsigned long long upd_serial;
    size_t updates;        /* evaluations the update gave (what the tests count) */
    /* roots proposed at a new x (tirenv_springs__start), and the updates accepted there;
     * the starts refused because a working row's vertex left its sector; the starts whose
     * rows moved into the next sector, the rows let go at the root, and the rows entered
     * where a vertex crossed a held element's ray (for the tests) */
    size_t starts, start_updates, start_sector, start_across, start_released, start_entered;
    /* the continuous contact's evaluations since the last start was asked for, and whether
     * one accepted its root: what the start from the closed form's pins goes by */
    size_t evals;
    int start_taken;
    /* the last evaluation was the closed form's, at height pins_z (m), its pins in active
     * over [a, b], its x and slope upd_x and upd_dfz_dz */
    int pins_ok;
    double pins_z;
    double eval_x;         /* the x of the last evaluation, m */
    int refused;           /* the last evaluation found ground the rays cannot see */
    tirenv_diag refusal;   /* where, and what (when refused) */
};

static void precompute_chains(tirenv_springs *s)
{
    const size_t N = s->N;
    const double kk = s->k_ir * s->k_ir;
    s->L_D[0] = s->diag[0];
    for (size_t j = 1; j < N; ++j)
        s->L_D[j] = s->diag[j] - kk / s->L_D[j - 1];
    s->R_D[N - 1] = s->diag[N - 1];
    for (size_t j = N - 1; j-- > 0;)
        s->R_D[j] = s->diag[j] - kk / s->R_D[j + 1];
    for (size_t j = 0; j < N; ++j) {
        s->lq[j] = s->k_ir / s->L_D[j];
        s->rq[j] = s->k_ir / s->R_D[j];
    }
    s->S_lc[0] = s->S_ls[0] = 0;
    for (size_t a = 1; a < N; ++a) {
        const double r = s->k_ir / s->L_D[a - 1];
        s->S_lc[a] = r * (s->k_r * s->cos_t[a - 1] + s->S_lc[a - 1]);
        s->S_ls[a] = r * (s->k_r * s->sin_t[a - 1] + s->S_ls[a - 1]);
    }
    s->S_rc[N - 1] = s->S_rs[N - 1] = 0;
    for (size_t b = N - 1; b-- > 0;) {
        const double r = s->k_ir / s->R_D[b + 1];
        s->S_rc[b] = r * (s->k_r * s->cos_t[b + 1] + s->S_rc[b + 1]);
        s->S_rs[b] = r * (s->k_r * s->sin_t[b + 1] + s->S_rs[b + 1]);
    }
}

tirenv_springs *tirenv_springs_alloc(const tirenv_springs_params *par)
{
    tirenv_tire check = tirenv_tire_default();
    check.springs = *par;
    if (tirenv_tire_check(&check, NULL))
        return NULL;
    tirenv_springs *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->par = *par;
    /* Elements at theta_i = i*dphi for every integer i with |theta_i| <= phi/2 (docs/models.md
     * section 4); the relative slack keeps phi/2 itself when it is a multiple of dphi. */
    s->i0 = (size_t)floor(0.5 * par->phi / par->dphi * (1 + 1e-12));
    s->N = 2 * s->i0 + 1;
    s->k_r = par->c_r * par->dphi;
    s->k_ir = par->c_b / par->dphi;
    const size_t N = s->N, n_arrays = 20, n_tables = 5;
    double *buf = calloc(n_arrays * N + n_tables * (N + 2), sizeof *buf);
    s->active = calloc(N, 1);
    s->pins.gap = calloc(2 * N, sizeof *s->pins.gap);
    s->slope.gap = calloc(2 * N, sizeof *s->slope.gap);
    s->memo = calloc(N, sizeof *s->memo);
    s->face = calloc(N, sizeof *s->face);
    s->pred_face = calloc(N, sizeof *s->pred_face);
    s->pairs = calloc(4 * N, sizeof *s->pairs);
    if (!buf || !s->active || !s->pins.gap || !s->slope.gap || !s->memo || !s->face ||
        !s->pred_face || !s->pairs) {
        free(buf);
        tirenv_springs_free(s);
        return NULL;
    }
    double **arrays[] = {&s->theta, &s->sin_t, &s->cos_t, &s->diag, &s->L_D, &s->R_D, &s->lq,
                         &s->rq, &s->S_lc, &s->S_ls, &s->S_rc, &s->S_rs, &s->d, &s->p,
                         &s->dd, &s->rho, &s->ray_inv_s, &s->ray_drop, &s->ray_reach,
                         &s->tread};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; ++k)
        *arrays[k] = buf + k * N;
    double **tables[] = {&s->ce, &s->cm, &s->cmi, &s->w, &s->dw}; /* N + 2 each */
    for (size_t k = 0; k < n_tables; ++k)
        *tables[k] = buf + n_arrays * N + k * (N + 2);
    s->w += 1;
    s->dw += 1;
    for (size_t i = 0; i < N; ++i) {
        s->theta[i] = ((double)i - (double)s->i0) * par->dphi;
        s->sin_t[i] = sin(s->theta[i]);
        s->cos_t[i] = cos(s->theta[i]);
        const double neighbours = (double)((i > 0) + (i + 1 < N));
        s->diag[i] = s->k_r + neighbours * s->k_ir;
    }
    precompute_chains(s);
    /* no face kept yet: calloc's zeros would read as a ray that hit vertex 0 with a zero
     * d(rho)/dz (set_origin forgets them on a new profile too) */
    tirenv_springs__faces_forget(s);
    tirenv_springs__chain_tables(N, s->k_r, s->k_ir, s->ce, s->cm, s->cmi);
    s->chains = (tirenv_springs__chains){.N = N, .k_ir = s->k_ir, .diag = s->diag,
                                         .lq = s->lq, .rq = s->rq, .ce = s->ce, .cm = s->cm,
                                         .cmi = s->cmi};
    tirenv_springs__fan_rays_fill(N, s->sin_t, s->cos_t, par->R0, s->ray_inv_s, s->ray_drop,
                                  s->ray_reach);
    s->rays = (tirenv_springs__fan_rays){.i0 = s->i0, .rho_max = par->R0, .sin_t = s->sin_t,
                                         .cos_t = s->cos_t, .inv_s = s->ray_inv_s,
                                         .drop = s->ray_drop, .reach = s->ray_reach};
    s->rays.ordered = tirenv_springs__fan_rays_ordered(&s->rays, N);
    s->cc_tire = (tirenv_springs__cc_tire){.N = N, .i0 = s->i0, .R0 = par->R0, .k_r = s->k_r,
                                           .k_ir = s->k_ir, .sin_t = s->sin_t,
                                           .cos_t = s->cos_t, .diag = s->diag, .lq = s->lq,
                                           .rq = s->rq};
    tirenv_springs__cc_tire_shape(&s->cc_tire);
    if (par->contact == TIRENV_SPRINGS_CONTINUOUS && tirenv_springs__cc_init(&s->cc, N)) {
        tirenv_springs_free(s);
        return NULL;
    }
    s->a = 1;
    s->b = 0;
    return s;
}

void tirenv_springs_free(tirenv_springs *s)
{
    if (!s)
        return;
    free(s->theta);
    free(s->active);
    free(s->pins.gap);
    free(s->slope.gap);
    free(s->memo);
    free(s->face);
    free(s->pred_face);
    free(s->pairs);
    tirenv_springs__cc_free(&s->cc);
    free(s);
}

const tirenv_springs_params *tirenv_springs_params_of(const tirenv_springs *s)
{
    return &s->par;
}

size_t tirenv_springs_size(const tirenv_springs *s) { return s->N; }

void tirenv_springs__elements_of(const tirenv_springs *s, tirenv_springs__elements *el)
{
    *el = (tirenv_springs__elements){.k_r = s->k_r, .k_ir = s->k_ir, .diag = s->diag,
                                     .cos_t = s->cos_t};
}
const double *tirenv_springs_theta(const tirenv_springs *s) { return s->theta; }

/* Elements that can touch the ground: a ray reaches no lower than its tip z - R0 cos(theta),
 * so it can only meet ground no higher than z_max = (a bound of) the highest ground within R0
 * on its side if R0 cos(theta) >= z - z_max = gap. The largest such |i - i0| is found by
 * walking from the last one found on that side (*m: it moves by an element or two between
 * evaluations, where acos cost 3 % of an evaluation over a road); one extra element
 * absorbs rounding. The two bounds depend on x alone and are kept with the rays' origin. */
static size_t side_span(const tirenv_springs *s, double gap, size_t *m)
{
    const double R0 = s->par.R0;
    const double *cos_t = s->cos_t + s->i0;
    if (gap >= R0)
        return 0;
    if (gap <= 0) /* ground level with the centre: every ray, even one turned upward */
        return s->i0;
    size_t k = *m;
    while (k < s->i0 && R0 * cos_t[k + 1] >= gap)
        ++k;
    while (k > 0 && R0 * cos_t[k] < gap)
        --k;
    *m = k;
    return k < s->i0 ? k + 1 : s->i0;
}

static int candidate_span(tirenv_springs *s, double z, size_t *a, size_t *b)
{
    const double R0 = s->par.R0;
    const double gap_back = z - s->origin.z_max[0], gap_fwd = z - s->origin.z_max[1];
    if (gap_back >= R0 && gap_fwd >= R0)
        return 0;
    *a = s->i0 - side_span(s, gap_back, &s->span[0]);
    *b = s->i0 + side_span(s, gap_fwd, &s->span[1]);
    return 1;
}

/* Everything the rays need of x alone, found when x or the profile changes. */
static void set_origin(tirenv_springs *s, const tirenv_profile *prof, double x)
{
    const double R0 = s->par.R0;
    const int same_ground = s->ray_serial == prof->serial;
    if (same_ground && s->origin.x == x)
        return;
    tirenv_springs__fan_origin_at(prof, x, R0, same_ground ? s->origin.k : 0, &s->origin);
    if (!same_ground)
        tirenv_springs__faces_forget(s);
    s->ray_serial = prof->serial;
    s->ray_a = 1;
    s->ray_b = 0;
}

void tirenv_springs__bracket(tirenv_springs *s, const tirenv_profile *p, double x,
                             double *z_lo, double *z_hi)
{
    set_origin(s, p, x);
    *z_lo = s->origin.g;
    *z_hi = fmax(s->origin.z_max[0], s->origin.z_max[1]) + s->par.R0;
}

/* The ray pairs to look between for ground the rays cannot see, from the walks. */
static void find_pairs(tirenv_springs *s, size_t a, size_t b)
{
    s->n_pairs = tirenv_springs__fan_pairs(&s->origin, &s->rays, a, b, s->memo, s->pairs);
    s->pairs_a = a;
    s->pairs_b = b;
}

/* rho[a..b] and drho[a..b] from (origin.x, z): the rays of the last evaluation again where
 * each provably still ends on the same face (same profile, same x), else a fresh fan. Both give
 * the bits tirenv_springs__ray_at gives. */
static void cast_rays(tirenv_springs *s, const tirenv_profile *prof, double z, size_t a,
                      size_t b)
{
    if (s->ray_a <= a && b <= s->ray_b &&
        tirenv_springs__fan_reuse(prof, &s->origin, &s->rays, z, a, b, s->rho, s->memo)) {
        if (a != s->pairs_a || b != s->pairs_b)
            find_pairs(s, a, b);
        return;
    }
    tirenv_springs__fan(prof, &s->origin, &s->rays, z, a, b, s->rho, s->memo);
    ++s->fans;
    s->ray_a = a;
    s->ray_b = b;
    find_pairs(s, a, b);
}

/* How far (in units of R0) ground must stand above what the rays see before it counts as a
 * feature: far above rounding, far below the ray spacing that decides (springs_feature.c). */
static const double feature_tol = 1e-6;

/* Refuses the state just computed if ground pokes into the tread between rays that cannot see
 * it (tirenv_springs__unseen_feature); the tread along each ray is R0 - w, with w carried
 * out along the free chains beyond [f0, f1]. */
static int check_unseen(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                        size_t a, size_t b, size_t f0, size_t f1, tirenv_diag *diag)
{
    const double R0 = s->par.R0;
    double *tread = s->tread;
    if (s->n_pairs == 0)
        return TIRENV_OK;
    if (f0 <= f1) {
        for (size_t i = f0; i <= f1; ++i)
            tread[i] = R0 - s->w[i];
        double w = s->w[f0];
        for (size_t j = f0; j-- > a;)
            tread[j] = R0 - (w *= s->lq[j]);
        w = s->w[f1];
        for (size_t j = f1 + 1; j <= b; ++j)
            tread[j] = R0 - (w *= s->rq[j]);
    } else {
        for (size_t i = a; i <= b; ++i)
            tread[i] = R0;
    }
    tirenv_springs__feature f;
    if (!tirenv_springs__unseen_pairs(prof, &s->rays, x, z, s->rho, tread, s->pairs,
                                      s->n_pairs, feature_tol * R0, &f))
        return TIRENV_OK;
    s->refused = 1;
    /* The finest element angle that would see it: its angular width, if one is practical. */
    const double angle = f.width / f.distance;
    char remedy[160];
    if (angle >= 1e-4)
        snprintf(remedy, sizeof remedy, "an ELEMENT_ANGLE below %.3g rad would see it",
                 angle);
    else
        snprintf(remedy, sizeof remedy, "no practical ELEMENT_ANGLE sees it; the rigid model "
                 "follows it exactly");
    tirenv_error(&s->refusal, TIRENV_ERANGE, "", 0, "profile",
                 "at x = %.9g m a feature of the ground %.3g m wide (at X = %.6g m, "
                 "%.3g m from the centre) reaches %.3g m into the tread between two "
                 "rays %.3g m apart that do not see it: narrower than the ray spacing, "
                 "the springs model cannot resolve it (a real tread would rest on it); "
                 "%s",
                 x, f.width, f.X, f.distance, f.depth, f.spacing, remedy);
    if (diag)
        *diag = s->refusal;
    return TIRENV_ERANGE;
}

/* Whether the slope kept was solved for these faces, this span and these pins. */
static int same_slope(const tirenv_springs *s, size_t f0, size_t f1)
{
    const tirenv_springs__pins *P = &s->pins;
    return s->slope.valid && s->slope.fans == s->fans && s->slope.f0 == f0 &&
           s->slope.f1 == f1 && s->slope.count == P->count && s->slope.first == P->first &&
           s->slope.last == P->last && s->slope.n_gaps == P->n_gaps &&
           !memcmp(s->slope.gap, P->gap, 2 * P->n_gaps * sizeof *P->gap);
}

/* dF_z/dz (N/m) from dw = dw/dz over [f0, f1], the free chains beyond folded into its ends. */
static double hub_dfz_dz(const tirenv_springs *s, size_t f0, size_t f1)
{
    double sum = s->dw[f0] * s->S_lc[f0] + s->dw[f1] * s->S_rc[f1];
    for (size_t i = f0; i <= f1; ++i)
        sum += s->k_r * s->dw[i] * s->cos_t[i];
    return sum;
}

/* dF_z/dz of the state just solved, over the touching span [f0, f1]: d(d_i)/dz =
 * -d(rho_i)/dz on the pinned elements, and the LCP's closed form carries it to dw. */
static double slope_dfz_dz(tirenv_springs *s, const tirenv_profile *prof, size_t f0, size_t f1)
{
    const tirenv_springs__pins *P = &s->pins;
    if (same_slope(s, f0, f1))
        return s->slope.dfz_dz;
    if (P->count > 0)
        tirenv_springs__fan_drho_neg(prof, &s->rays, P->first, P->last, s->active, s->memo,
                                     s->dd);
    tirenv_springs__pinned_solve(&s->chains, f0, f1, P, s->dd, s->dw);
    const double sum = hub_dfz_dz(s, f0, f1);
    s->slope.valid = 1;
    s->slope.fans = s->fans;
    s->slope.f0 = f0;
    s->slope.f1 = f1;
    s->slope.count = P->count;
    s->slope.first = P->first;
    s->slope.last = P->last;
    s->slope.n_gaps = P->n_gaps;
    memcpy(s->slope.gap, P->gap, 2 * P->n_gaps * sizeof *P->gap);
    s->slope.dfz_dz = sum;
    return sum;
}

/* d(rho)/dz of ray i (a finite rho) as tirenv_springs__fan_drho gives it: kept in its memo,
 * else the face's (s->face) where the walk ended on the same one, else computed. */
static inline double ray_drho(tirenv_springs *s, const tirenv_profile *prof, size_t i)
{
    tirenv_springs__ray_memo *m = &s->memo[i], *f = &s->face[i];
    if (isnan(m->drho)) {
        if (f->j == m->j && f->kind == m->kind) {
            m->drho = f->drho;
            ++s->face_hits;
        } else {
            tirenv_springs__fan_drho(prof, &s->rays, i, m);
            *f = *m;
        }
    }
    return m->drho;
}

/* Whether every held element's ray ends where tirenv_springs__start took it to (its walk
 * ended at the same vertex in the same way: the same face), so that the root's rows were
 * the rays' own. Each such ray's memo takes the face's d(rho)/dz the start found (the next
 * x's start, and ray_drho, read it there instead of looking for it). */
static int same_faces(tirenv_springs *s)
{
    const size_t *held = s->cc.held;
    for (size_t m = 0, n_held = s->cc.n_held; m < n_held; ++m) {
        const size_t e = held[m];
        tirenv_springs__ray_memo *f = &s->memo[e];
        const tirenv_springs__ray_memo *p = &s->pred_face[e];
        if (f->j != p->j || f->kind != p->kind)
            return 0;
        f->drho = p->drho;
    }
    return 1;
}

/* The hub's forces (N) from the continuous contact's w over [f0, f1], the free chains beyond
 * folded into its ends (S_l*, S_r*), and the elements the ground presses, as with rays
 * (counted only where contacts is not NULL: the update counts its own). */
static void hub_forces(const tirenv_springs *s, size_t f0, size_t f1, double *fx,
                       double *fz, size_t *contacts)
{
    const double k_r = s->k_r, *w = s->w, *cos_t = s->cos_t, *sin_t = s->sin_t, *p = s->p;
    double sum_c = w[f0] * s->S_lc[f0] + w[f1] * s->S_rc[f1];
    double sum_s = w[f0] * s->S_ls[f0] + w[f1] * s->S_rs[f1];
    size_t n = 0, i = f0;
    for (; i < f1; i += 2) { /* two at a time, in order (the sums' bits) */
        const double kw0 = k_r * w[i], kw1 = k_r * w[i + 1];
        sum_c += kw0 * cos_t[i];
        sum_s += kw0 * sin_t[i];
        sum_c += kw1 * cos_t[i + 1];
        sum_s += kw1 * sin_t[i + 1];
        if (contacts) /* the loop unswitched */
            n += (p[i] > 0) + (p[i + 1] > 0);
    }
    if (i == f1) {
        sum_c += k_r * w[i] * cos_t[i];
        sum_s += k_r * w[i] * sin_t[i];
        n += p[i] > 0;
    }
    *fz = sum_c;
    *fx = -sum_s;
    if (contacts)
        *contacts = n;
}

/* The select's bits, as maxpd(v, 0) gives them lane by lane (0 where v is 0, -0 or NaN), four
 * elements a step (GCC's own vectorisation of the select took two, with a compare and a mask:
 * some 60 % more instructions). */
void tirenv_springs__penetrations(double R0, const double rho[], double d[], size_t a, size_t b)
{
    size_t i = a;
#if defined(__SSE2__)
    const __m128d r0 = _mm_set1_pd(R0), zero = _mm_setzero_pd();
    for (; i + 3 <= b; i += 4) {
        const __m128d v0 = _mm_sub_pd(r0, _mm_loadu_pd(rho + i));
        const __m128d v1 = _mm_sub_pd(r0, _mm_loadu_pd(rho + i + 2));
        _mm_storeu_pd(d + i, _mm_max_pd(v0, zero));
        _mm_storeu_pd(d + i + 2, _mm_max_pd(v1, zero));
    }
#endif
    for (; i <= b; ++i) {
        const double v = R0 - rho[i];
        d[i] = v > 0 ? v : 0;
    }
}

int tirenv_springs__qp_first(const tirenv_springs *s, double z)
{
    return s->cc.between && fabs(z - s->cc.between_z) <= between_reach * s->par.R0;
}

/* The rays of [a, b] at z: each ray's memo is a proof of its own (springs_ray.c), so the rays
 * whose memos fail at this z are walked again alone, where the last fan covers [a, b]; else
 * the fan cast afresh. Their penetrations into s->d. 1 where no ray was walked (every one on
 * its last face, which the confirming update needs: confirmed). */
static int rays_at(tirenv_springs *s, const tirenv_profile *prof, double z, size_t a,
                   size_t b)
{
    size_t walked = b - a + 1;
    if (s->ray_a <= a && b <= s->ray_b) {
        walked = tirenv_springs__fan_update(prof, &s->origin, &s->rays, z, a, b, s->rho,
                                            s->memo);
    } else {
        tirenv_springs__fan(prof, &s->origin, &s->rays, z, a, b, s->rho, s->memo);
        s->ray_a = a;
        s->ray_b = b;
    }
    s->memo_a = s->ray_a;
    s->memo_b = s->ray_b;
    s->memo_serial = prof->serial;
    tirenv_springs__penetrations(s->par.R0, s->rho, s->d, a, b);
    return walked == 0;
}

/* Newton's confirming evaluation: the last QP solve's state carried along its tangent, where
 * the QP's conditions hold at z (the same x and ground, the rays on the same faces: reused);
 * or at a new x, the state tirenv_springs__start proposed there on the last position's
 * working set, its held rays on the faces it took (from the closed form's pins, whatever
 * faces: on a road sampled at 1 mm a held ray often passes a vertex between the warm start
 * and the root, and the update's corrections, K_FF's own solves there, find the state at z
 * all the same; F_z is then off the load by what that ray's kink moved, and Newton goes on).
 * 1 where it holds, with the forces and dF_z/dz written. */
static int confirmed(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                     size_t a, size_t b, int reused, double *fx, double *fz, double *dfz_dz,
                     size_t *contacts)
{
    const tirenv_springs__cc *c = &s->cc;
    size_t n_contacts;
    if (!(dfz_dz && c->base_ok && s->upd_serial == prof->serial &&
          (s->upd_x == x ? reused
                         : c->pred_ok && c->pred_x == x && c->pred_z == z &&
                               (c->base_pins || same_faces(s))) &&
          tirenv_springs__cc_update(&s->cc, &s->cc_tire, prof, x, z, a, b, s->d, s->dw, s->w,
                                    s->p, s->d, &n_contacts)))
        return 0;
    hub_forces(s, s->cc.f0, s->cc.f1, fx, fz, NULL);
    /* the tips' span: the base's, which the start may have grown by an element */
    s->a = s->cc.f0;
    s->b = s->cc.f1;
    /* the base's working rows (its solve's, none from the closed form's pins), as the solve
     * had them: the next evaluation's path, whichever x it is at */
    s->cc.between = !s->cc.base_pins && s->cc.n_warm > 0;
    s->cc.between_z = z;
    if (contacts)
        *contacts = n_contacts;
    *dfz_dz = s->upd_dfz_dz; /* the piece's, at the base's height */
    ++s->updates;
    s->start_updates += s->upd_x != x;
    return 1;
}

/* The elements with a row of their own within the rows' span [f0, f1] (none: g0 > g1), and
 * the LCP's warm start forgetting the elements outside them, which cannot touch now. */
static void own_span(tirenv_springs *s, size_t f0, size_t f1, size_t *g0_out, size_t *g1_out)
{
    const double *pin_h = s->cc.pin_h;
    size_t g0 = f0, g1 = f1;
    if (f0 <= f1) {
        while (g0 <= f1 && !(pin_h[g0] > 0))
            ++g0;
        while (g1 > g0 && !(pin_h[g1] > 0))
            --g1;
    }
    if (s->a <= s->b) {
        for (size_t i = s->a; i <= s->b && i < g0; ++i)
            s->active[i] = 0;
        for (size_t i = g1 + 1 > s->a ? g1 + 1 : s->a; i <= s->b; ++i)
            s->active[i] = 0;
    }
    *g0_out = g0;
    *g1_out = g1;
}

/* The tips by the closed form between pins (section 4.4) on [g0, g1], where no row between
 * elements is to be taken first (tirenv_springs__qp_first) and every row holds at its answer:
 * 1, with the free chains over the rows' span [f0, f1]; else 0 (the QP's to solve). */
static int pinned_tips(tirenv_springs *s, double z, size_t f0, size_t f1, size_t g0, size_t g1)
{
    const double *pin_h = s->cc.pin_h;
    if (!(g0 <= f1 && !tirenv_springs__qp_first(s, z)))
        return 0;
    for (size_t e = g0; e <= g1; ++e)
        s->d[e] = pin_h[e] > 0 ? pin_h[e] : 0;
    size_t passes;
    if (tirenv_springs__lcp_pinned(&s->chains, g0, g1, s->d, s->w, s->p, s->active, &s->pins,
                                   lcp_max_passes(g0, g1), &passes) != 0)
        return 0;
    for (size_t j = g0; j-- > f0;) /* the free chains, over the rows' span */
        s->w[j] = s->lq[j] * s->w[j + 1];
    for (size_t j = g1 + 1; j <= f1; ++j)
        s->w[j] = s->rq[j] * s->w[j - 1];
    return tirenv_springs__cc_pins_hold(&s->cc, s->w, 1e-12 * s->par.R0);
}

/* dw over [f0, f1] from the closed form's pins: d(d_i)/dz of each pinned element's row (its
 * ray's, or the vertex's on it); the pins are the base of the next x's start where it asks
 * for one (the base is made from them then: s->active holds them until the next
 * evaluation). */
static void slope_pinned(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                         size_t f0, size_t f1)
{
    const tirenv_springs__pins *P = &s->pins;
    for (size_t i = P->first; P->count > 0 && i <= P->last; ++i) {
        if (!s->active[i])
            continue;
        const tirenv_springs__cc_row *R = &s->cc.rows[s->cc.pin_row[i]];
        s->dd[i] = R->id < 0 ? -tirenv_springs__fan_drho(prof, &s->rays, i, &s->memo[i])
                             : R->dh_dz;
    }
    tirenv_springs__pinned_solve(&s->chains, f0, f1, P, s->dd, s->dw);
    s->pins_ok = 1;
    s->pins_z = z;
    s->upd_x = x;
    s->upd_serial = prof->serial;
}

/* dw over the QP's span [f0, f1] as tirenv_springs__cc_slope takes it with no dd: each held
 * element's row's dh/dz (a ray's: -d(rho)/dz), 0 on the free ones; and the state kept as the
 * base of the next evaluation's update at this x. The workspace's arrays in locals (the stores
 * to dw would make them be read again at every element), and a ray's d(rho)/dz as ray_drho
 * keeps it. */
static void slope_qp(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                     size_t f0, size_t f1)
{
    const size_t *pin_row = s->cc.pin_row, *held = s->cc.held;
    const tirenv_springs__cc_row *rows = s->cc.rows;
    double *dw = s->dw;
    /* 0 on the span, then the held elements from the QP's list of them */
    memset(dw + f0, 0, (f1 - f0 + 1) * sizeof *dw);
    for (size_t k = 0, n_held = s->cc.n_held; k < n_held; ++k) {
        const size_t i = held[k];
        const tirenv_springs__cc_row *R = &rows[pin_row[i]];
        dw[i] = R->id < 0 ? -ray_drho(s, prof, i) : R->dh_dz;
    }
    if (tirenv_springs__cc_slope(&s->cc, &s->cc_tire, s->w, NULL, s->dw) == TIRENV_OK) {
        memcpy(s->cc.base_w + f0, s->w + (long)f0 - 1, (f1 - f0 + 3) * sizeof *s->w);
        s->cc.base_z = z;
        s->cc.base_ok = 1;
        s->cc.base_pins = 0;
        s->upd_x = x;
        s->upd_serial = prof->serial;
    }
}

/* CONTACT = 'continuous': the rays give each element's own row, the ground's vertices the
 * rows between elements (springs_contact.c); the hub forces as with rays. Most states have no
 * row between elements active (the tread bows out between its tips, section 4.8): the
 * elements' own rows are solved first by section 4.4's LCP, and if every other row holds
 * there, that is the QP's solution (its KKT conditions hold with those rows' reactions 0);
 * else the QP is solved whole. */
static int forces_continuous(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                             double *fx, double *fz, double *dfz_dz, size_t *contacts,
                             tirenv_diag *diag)
{
    size_t a = 1, b = 0;
    set_origin(s, prof, x);
    const int any = candidate_span(s, z, &a, &b);
    *fx = *fz = 0;
    if (dfz_dz)
        *dfz_dz = 0;
    if (contacts)
        *contacts = 0;
    ++s->evals;
    s->eval_x = x;
    size_t f0 = 1, f1 = 0;
    if (any) {
        const int reused = rays_at(s, prof, z, a, b);
        if (confirmed(s, prof, x, z, a, b, reused, fx, fz, dfz_dz, contacts))
            return TIRENV_OK;
        s->cc.base_ok = 0;
        s->cc.pred_ok = 0;
        s->pins_ok = 0;
        const int status =
            tirenv_springs__cc_rows(&s->cc, &s->cc_tire, prof, x, z, a, b, s->d, diag);
        if (status)
            return status;
        f0 = s->cc.f0;
        f1 = s->cc.f1;
    }
    size_t g0, g1;
    own_span(s, f0, f1, &g0, &g1);
    s->a = 1;
    s->b = 0;
    if (f0 > f1) {
        s->pins.count = 0;
        tirenv_springs__cc_forget(&s->cc);
        return TIRENV_OK;
    }
    const int fast = pinned_tips(s, z, f0, f1, g0, g1);
    if (fast) {
        f0 = g0;
        f1 = g1;
    } else {
        const int status = tirenv_springs__cc_solve(&s->cc, &s->cc_tire, x, z, s->w, s->p,
                                                    s->d, diag);
        if (status)
            return status;
    }
    s->cc.between = !fast && s->cc.n_warm > 0;
    s->cc.between_z = z;
    s->a = f0;
    s->b = f1;
    hub_forces(s, f0, f1, fx, fz, contacts);
    if (!dfz_dz)
        return TIRENV_OK;
    if (fast)
        slope_pinned(s, prof, x, z, f0, f1);
    else
        slope_qp(s, prof, x, z, f0, f1);
    const double sum = hub_dfz_dz(s, f0, f1);
    *dfz_dz = sum;
    s->upd_dfz_dz = sum;
    return TIRENV_OK;
}

size_t tirenv_springs__updates(const tirenv_springs *s)
{
    return s->updates;
}

void tirenv_springs__start_counts(const tirenv_springs *s, size_t *starts, size_t *updates)
{
    *starts = s->starts;
    *updates = s->start_updates;
}

size_t tirenv_springs__start_sector(const tirenv_springs *s)
{
    return s->start_sector;
}

void tirenv_springs__start_moves(const tirenv_springs *s, size_t *across, size_t *released,
                                 size_t *entered)
{
    *across = s->start_across;
    *released = s->start_released;
    *entered = s->start_entered;
}

size_t tirenv_springs__face_hits(const tirenv_springs *s)
{
    return s->face_hits;
}

void tirenv_springs__faces_forget(tirenv_springs *s)
{
    for (size_t i = 0; i < s->N; ++i)
        s->face[i].kind = -1;
}

int tirenv_springs__root(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                         double G, double F, double dfz_dz, double *z_root)
{
    const tirenv_springs__cc *c = &s->cc;
    /* Only right after a full evaluation at (x, z) that left the update's base there. */
    if (s->par.contact != TIRENV_SPRINGS_CONTINUOUS || !c->base_ok || c->base_z != z ||
        s->upd_x != x || s->upd_serial != prof->serial || c->f0 > c->f1)
        return 0;
    return tirenv_springs__cc_root(&s->cc, &s->cc_tire, prof, x, G, F, dfz_dz,
                                   s->S_lc[c->f0], s->S_rc[c->f1], s->dw, z_root);
}

/* Whether ground vertex v and its neighbours lie within w: what the start reads of the ground
 * around a vertex that crossed a ray (the faces on either side), the same in a whole sweep and
 * a streamed one. */
static int faces_near(const tirenv_springs__face_window *w, long v)
{
    return tirenv_springs__face_window_has(w, v - 1) && tirenv_springs__face_window_has(w, v) &&
           tirenv_springs__face_window_has(w, v + 1);
}

/* The working set's changes tirenv_springs__start makes at a new x before it gives up: an
 * element's own row entering or leaving it at the patch's edges, one at a time. */
enum { start_rounds = 3 };

/* Nothing of the last positions for the next one's start (a new sweep, a state restored):
 * its evaluations and whether its start held, the closed form's pins, the QP's base and the
 * root's state. */
static void forget_start(tirenv_springs *s)
{
    s->evals = 0;
    s->start_taken = 0;
    s->pins_ok = 0;
    s->cc.base_ok = 0;
    s->cc.pred_ok = 0;
}

/* Whether a start is tried at x: from the closed form's pins only where the last position
 * (last_evals evaluations, its start taken or not) needed Newton's steps or a start: where it
 * met the load at its warm start (level ground beside an obstacle) the warm start is as good,
 * and the fan the start casts is spent. The base is made from them here, once (the next
 * position's start takes it as it stands). Then only at a new x, after a QP solve at another
 * on this ground whose held elements sit on their rays' rows, and only from a position at
 * most half the model's reach back: only what lies within the reach of x (the deformable
 * models', whose window a streamed road keeps) is read of the ground the last position left
 * (its rows' vertices, its rays' faces), which a streamed road's window holds (the carry
 * moved into it, tirenv_springs__reprofile), so that whole and streamed sweeps start alike. */
static int start_wanted(tirenv_springs *s, const tirenv_profile *prof, double x,
                        size_t last_evals, int last_taken)
{
    tirenv_springs__cc *c = &s->cc;
    if (s->pins_ok && !c->base_ok) {
        if (last_evals < 2 && !last_taken)
            return 0;
        s->pins_ok = 0;
        if (s->par.contact != TIRENV_SPRINGS_CONTINUOUS || s->a > s->b ||
            !tirenv_springs__cc_base_pins(c, &s->cc_tire, s->a, s->b, s->active, s->pins_z))
            return 0;
    }
    if (s->par.contact != TIRENV_SPRINGS_CONTINUOUS || !c->base_ok || s->upd_x == x ||
        s->upd_serial != prof->serial || c->f0 > c->f1 || c->held_vertex > 0 ||
        !c->use_schur)
        return 0;
    if (s->memo_serial != prof->serial)
        return 0;
    return fabs(x - s->eval_x) <= 0.5 * (TIRENV_MODEL__REACH * s->par.R0);
}

/* A working row's vertex that crossed an element's ray (the root's first question, asked
 * before the held rays' faces are found for it): the row moved into the sector beyond, the
 * crossed element's ray onto the vertex's other face (springs_root.c); where a row cannot
 * move, no start (0: the base's rows are no longer its own). */
static int rows_carried(tirenv_springs *s, const tirenv_profile *prof, double x, double z0,
                        const tirenv_springs__face_window *fw)
{
    tirenv_springs__cc *c = &s->cc;
    if (tirenv_springs__cc_rows_inside(c, &s->cc_tire, prof, x, z0))
        return 1;
    size_t crossed[TIRENV_SPRINGS__SCHUR_MAX], n_crossed;
    long vertex[TIRENV_SPRINGS__SCHUR_MAX];
    if (!tirenv_springs__cc_rows_across(c, &s->cc_tire, prof, x, z0, crossed, vertex,
                                        &n_crossed)) {
        c->base_ok = 0;
        ++s->start_sector;
        return 0;
    }
    for (size_t m = 0; m < n_crossed; ++m) {
        const size_t e = crossed[m];
        if (!faces_near(fw, vertex[m])) {
            c->base_ok = 0;
            ++s->start_sector;
            return 0;
        }
        if (e >= s->memo_a && e <= s->memo_b)
            tirenv_springs__memo_across(prof, &s->origin, &s->rays, e, vertex[m], z0,
                                        &s->memo[e]);
    }
    s->upd_x = NAN; /* the base's tangent holds its own rows, no longer these */
    ++s->start_across;
    return 1;
}

/* A ground vertex that crossed the ray of a held element at a run's end (its ray passed the
 * far end of its face): the element is let go and the vertex's row between it and its
 * neighbour enters the set, as for a working row carried across (springs_root.c); at most one
 * a run of free elements (the chains change). Not from the closed form's pins, whose held
 * rays are cast again at the new x by the start's rounds. 0 where the base was lost. */
static int run_end_enters(tirenv_springs *s, const tirenv_profile *prof, double x, double z0,
                          const tirenv_springs__face_window *fw)
{
    tirenv_springs__cc *c = &s->cc;
    for (size_t q = 0; !c->base_pins && c->n_schur < TIRENV_SPRINGS__SCHUR_MAX &&
                       q <= c->n_chains;
         ++q) {
        const size_t ends[2] = {q < c->n_chains ? c->chains[2 * q] - 1 : c->f0,
                                q < c->n_chains ? c->chains[2 * q + 1] + 1 : c->f1};
        for (int m = 0; m < 2; ++m) {
            const size_t e = ends[m];
            if (e < c->f0 || e > c->f1 || c->wpos[e] != SIZE_MAX || e < s->memo_a ||
                e > s->memo_b || !faces_near(fw, s->memo[e].j))
                continue;
            const long v = tirenv_springs__memo_passed(prof, &s->origin, &s->rays, e, z0,
                                                       &s->memo[e]);
            if (v < 0)
                continue;
            if (!tirenv_springs__cc_row_enter(c, &s->cc_tire, prof, x, z0, e, v)) {
                if (!c->base_ok)
                    return 0;
                continue; /* (no row of v's to enter: the update at the root decides) */
            }
            tirenv_springs__memo_across(prof, &s->origin, &s->rays, e, v, z0, &s->memo[e]);
            s->upd_x = NAN;
            ++s->start_entered;
            break; /* (the chains changed) */
        }
    }
    return 1;
}

/* The root at x on the working set, and the working set's changes at the patch's edges
 * (start_rounds at most), into *z; 0 where no start holds. */
static int root_rounds(tirenv_springs *s, const tirenv_profile *prof, double x, double z0,
                       double G, const tirenv_springs__face_window *fw, double *z)
{
    tirenv_springs__cc *c = &s->cc;
    const double R0 = s->par.R0;
    /* after a round's flip: the element whose own row entered the set (the others' rays
     * were found in the rounds before, at the same x and z0), or none where one left */
    size_t e_new = SIZE_MAX;
    for (int round = 0;; ++round) {
        /* Each held element's ray at (x, z0) on the face its last walk ended on, and its
         * d(rho)/dz there (the face's), into rho and dd: no fan is cast (the evaluation at
         * the root casts it, and checks the faces). */
        const size_t n_held = c->n_held;
        if (c->base_pins) {
            /* a road's rays end on other faces at each x: the fan at (x, z0) */
            size_t a = 1, b = 0;
            if (round == 0) {
                if (!candidate_span(s, z0, &a, &b))
                    return 0;
                tirenv_springs__fan(prof, &s->origin, &s->rays, z0, a, b, s->rho, s->memo);
                s->ray_a = s->memo_a = a;
                s->ray_b = s->memo_b = b;
            }
            if (n_held > 0 && (c->held[0] < s->ray_a || c->held[n_held - 1] > s->ray_b))
                return 0;
            for (size_t m = 0; m < n_held; ++m) {
                const size_t e = c->held[m];
                if (!isfinite(s->rho[e]) || !isfinite(s->dd[e] = ray_drho(s, prof, e)))
                    return 0;
                s->pred_face[e] = s->memo[e];
            }
        } else if (round == 0 || e_new != SIZE_MAX) {
            const size_t *rays = round == 0 ? c->held : &e_new, n_rays = round == 0 ? n_held : 1;
            if ((n_rays > 0 && (rays[0] < s->memo_a || rays[n_rays - 1] > s->memo_b)) ||
                !tirenv_springs__faces_rho(prof, &s->origin, &s->rays, rays, n_rays, s->memo,
                                           s->face, z0, fw, s->rho, s->dd, s->pred_face))
                return 0;
        }
        size_t q_neg;
        if (!tirenv_springs__cc_root_at(c, &s->cc_tire, prof, x, z0, s->rho, s->dd, G,
                                        s->upd_dfz_dz, s->S_lc[c->f0], s->S_rc[c->f1], z,
                                        &q_neg)) {
            /* a working row's reaction below 0 there: it leaves the set, as a round */
            if (q_neg == SIZE_MAX || round == start_rounds ||
                tirenv_springs__cc_pred_release(c, &s->cc_tire, q_neg))
                return 0;
            e_new = SIZE_MAX;
            s->upd_x = NAN;
            ++s->start_released;
            continue;
        }
        s->start_taken = 1; /* (a root proposed: the next position asks for one too) */
        /* The free elements' own rays at the root, on their last faces too (h: NAN where
         * none), and the held ones' reactions: where one is violated, the element's row
         * enters or leaves the working set (K_FF factorised again) and the root is found
         * again; the update at the root checks every row as before. */
        double *h = s->tread;
        for (size_t q = 0; q < c->n_chains; ++q)
            for (size_t m = 0; m < 2; ++m) {
                const size_t e = c->chains[2 * q + m];
                h[e] = e >= s->memo_a && e <= s->memo_b
                           ? R0 - tirenv_springs__face_rho(prof, &s->origin, &s->rays, e,
                                                           &s->memo[e], *z, fw)
                           : NAN;
            }
        size_t e;
        int hold;
        if (!tirenv_springs__cc_pred_worst(c, &s->cc_tire, h, 1e-12 * R0, 1e-9 * G, &e,
                                           &hold))
            return 1;
        if (round == start_rounds || tirenv_springs__cc_pred_flip(c, &s->cc_tire, e, hold)) {
            c->pred_ok = 0;
            return 0;
        }
        e_new = hold ? e : SIZE_MAX;
        /* the base's tangent at its x holds its own working set, no longer this one */
        s->upd_x = NAN;
    }
}

int tirenv_springs__start(tirenv_springs *s, const tirenv_profile *prof, double x, double z0,
                          double G, double *z)
{
    const tirenv_springs__cc *c = &s->cc;
    /* The last position's evaluations, and whether its start held. */
    const size_t last_evals = s->evals;
    const int last_taken = s->start_taken;
    s->evals = 0;
    s->start_taken = 0;
    if (!start_wanted(s, prof, x, last_evals, last_taken))
        return 0;
    const double reach = TIRENV_MODEL__REACH * s->par.R0;
    tirenv_springs__face_window fw;
    tirenv_springs__face_window_at(prof, x - reach, x + reach, &fw);
    for (size_t q = 0; q < c->n_schur; ++q)
        if (!tirenv_springs__face_window_has(&fw, c->rows[c->order[c->schur_pos[q]] - s->N].id))
            return 0;
    set_origin(s, prof, x);
    if (!rows_carried(s, prof, x, z0, &fw) || !run_end_enters(s, prof, x, z0, &fw) ||
        !root_rounds(s, prof, x, z0, G, &fw, z))
        return 0;
    ++s->starts;
    return 1;
}

void tirenv_springs__reprofile(tirenv_springs *s, const tirenv_profile *old,
                               const tirenv_profile *p)
{
    tirenv_springs__cc *c = &s->cc;
    if (!old) { /* a new sweep: nothing carried from the last one's positions (nor which
                 * path its first evaluation takes) */
        forget_start(s);
        c->between = 0;
        s->memo_serial = 0;
        return;
    }
    const int carry = s->upd_serial == old->serial || s->memo_serial == old->serial;
    if (!carry || old == p || old->n == 0 || p->n == 0)
        return;
    /* The offset of the vertices: the last vertex at or before the last evaluation's x in
     * old, which the next window keeps (the row left of x - reach stays), found in p. */
    const size_t k = tirenv_profile__segment_at(old, s->eval_x);
    const double X = old->x[k];
    size_t k_new = tirenv_profile__segment_at(p, X);
    if (k + 1 < old->n && old->x[k + 1] == X && k_new > 0) /* the first of a wall's two */
        --k_new;
    const long off = (long)k_new - (long)k;
    if (!(p->x[k_new] == X && p->z[k_new] == old->z[k])) { /* other ground: carry nothing */
        tirenv_springs__reprofile(s, NULL, p);
        return;
    }
    /* Each vertex the carry names moved by off where p has it (else no longer named: the
     * start, which reads only what lies within reach, refuses it as it would the whole
     * road's there). */
    for (size_t r = 0; r < c->n_rows; ++r) {
        const long id = c->rows[r].id, m = id + off;
        if (id >= 0)
            c->rows[r].id = m >= 0 && (size_t)m < p->n && id < (long)old->n &&
                                    p->x[m] == old->x[id] && p->z[m] == old->z[id]
                                ? m
                                : LONG_MAX;
    }
    int warm = 1;
    for (size_t q = 0; q < c->n_warm; ++q) {
        const long id = c->warm_ids[q], m = id + off;
        warm = warm && m >= 0 && (size_t)m < p->n && id < (long)old->n &&
               p->x[m] == old->x[id] && p->z[m] == old->z[id];
        c->warm_ids[q] = m;
    }
    if (!warm)
        c->n_warm = 0; /* (the QP's warm start: how fast, not what it finds) */
    for (size_t i = s->memo_a; i <= s->memo_b && i < s->N; ++i)
        tirenv_springs__memo_reprofile(old, p, off, &s->memo[i]);
    c->last_ok = 0;
    if (s->upd_serial == old->serial)
        s->upd_serial = p->serial;
    if (s->memo_serial == old->serial)
        s->memo_serial = p->serial;
}

int tirenv_springs_forces(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                          double *fx, double *fz, double *dfz_dz, size_t *contacts,
                          tirenv_diag *diag)
{
    s->refused = 0;
    if (s->par.contact == TIRENV_SPRINGS_CONTINUOUS)
        return forces_continuous(s, prof, x, z, fx, fz, dfz_dz, contacts, diag);
    const double R0 = s->par.R0, k_r = s->k_r;
    size_t a = 1, b = 0;
    set_origin(s, prof, x);
    const int any = candidate_span(s, z, &a, &b);
    *fx = *fz = 0;
    if (dfz_dz)
        *dfz_dz = 0;
    if (contacts)
        *contacts = 0;
    size_t f0 = 1, f1 = 0; /* the elements that touch: d > 0 */
    if (any) {
        cast_rays(s, prof, z, a, b);
        double *d = s->d;
        const double *rho = s->rho;
        for (size_t i = a; i <= b; ++i)
            d[i] = rho[i] < R0 ? R0 - rho[i] : 0;
        for (f0 = a; f0 <= b && !(d[f0] > 0); ++f0)
            ;
        for (f1 = b; f1 > f0 && !(d[f1] > 0); --f1)
            ;
        if (f0 > b)
            f1 = 0;
    }
    /* Elements that cannot touch now forget their contact state (the warm start); inside
     * [f0, f1] the LCP does it. */
    if (s->a <= s->b) {
        for (size_t i = s->a; i <= s->b && i < f0; ++i)
            s->active[i] = 0;
        for (size_t i = f1 + 1 > s->a ? f1 + 1 : s->a; i <= s->b; ++i)
            s->active[i] = 0;
    }
    s->a = f0;
    s->b = f1;
    if (f0 > f1) {
        s->pins.count = 0;
        return any ? check_unseen(s, prof, x, z, a, b, f0, f1, diag) : TIRENV_OK;
    }

    size_t passes;
    const size_t max_passes = lcp_max_passes(f0, f1);
    const int status = tirenv_springs__lcp_pinned(&s->chains, f0, f1, s->d, s->w, s->p,
                                                  s->active, &s->pins, max_passes, &passes);
    if (status)
        return tirenv_error(diag, status, "", 0, "ELEMENT_ANGLE",
                            "the tip contact of elements %zu to %zu (the LCP, %zu elements of "
                            "ELEMENT_ANGLE %g rad touching) did not settle in %zu active-set "
                            "passes, the bound for an M-matrix, at z = %.9g m: a round-off "
                            "cycle; a coarser ELEMENT_ANGLE may avoid it", a, b, f1 - f0 + 1,
                            s->par.dphi, max_passes, z);

    /* Eq. 1 and its horizontal counterpart; only the radial springs load the hub. The free
     * chains beyond [f0, f1] carry w[f0] S_lc[f0] and w[f1] S_rc[f1]. */
    double sum_c = s->w[f0] * s->S_lc[f0] + s->w[f1] * s->S_rc[f1];
    double sum_s = s->w[f0] * s->S_ls[f0] + s->w[f1] * s->S_rs[f1];
    for (size_t i = f0; i <= f1; ++i) {
        sum_c += k_r * s->w[i] * s->cos_t[i];
        sum_s += k_r * s->w[i] * s->sin_t[i];
    }
    *fz = sum_c;
    *fx = -sum_s;
    if (contacts)
        *contacts = s->pins.count;
    if (dfz_dz)
        *dfz_dz = slope_dfz_dz(s, prof, f0, f1);
    return check_unseen(s, prof, x, z, a, b, f0, f1, diag);
}

void tirenv_springs_refusal(const tirenv_springs *s, tirenv_diag *diag)
{
    if (!diag)
        return;
    if (s->refused)
        *diag = s->refusal;
    else
        tirenv_diag_clear(diag);
}

void tirenv_springs_tips(const tirenv_springs *s, double d[], double w[], double p[])
{
    const size_t N = s->N, a = s->a, b = s->b;
    const int any = a <= b;
    for (size_t i = 0; i < N; ++i) {
        const int in = any && i >= a && i <= b;
        if (d)
            d[i] = in ? s->d[i] : 0;
        if (p)
            p[i] = in ? s->p[i] : 0;
    }
    if (!w)
        return;
    if (!any) {
        memset(w, 0, N * sizeof *w);
        return;
    }
    memcpy(w + a, s->w + a, (b - a + 1) * sizeof *w);
    for (size_t j = a; j-- > 0;)
        w[j] = s->k_ir / s->L_D[j] * w[j + 1];
    for (size_t j = b + 1; j < N; ++j)
        w[j] = s->k_ir / s->R_D[j] * w[j - 1];
}

/* The warm state of the tip contact: which elements may touch and which were pinned, and
 * whether the continuous contact's last solution had a row between elements working, and at
 * which centre height (they decide whether the closed form is tried first, which moves the
 * last bits). With CONTACT 'continuous' also what the start at the next x and the update at
 * the same x read (tirenv_springs__start, docs/models.md sections 1.7 and 4.8): the last
 * position's evaluations and whether its start held, the closed form's pins, the base's x,
 * profile and dF_z/dz, the x last evaluated, the rays' walks (the faces the held rays ended
 * on) and their range at that x (whether the next evaluation there reuses them decides
 * whether it takes the update), and the base (springs_carry.c); the profiles as whether they
 * were the one given (p), which a twin reads as its own. The QP's warm start, the rays'
 * caches at other x and the faces' d(rho)/dz are dropped on restore; they change no bit of a
 * result, only how fast it is found (tests/model/test_state_rewind.c). */
enum { MEMO_BYTES = sizeof(int64_t) + sizeof(int32_t) + sizeof(double) };

static int carries(const tirenv_springs *s, int level)
{
    return s->par.contact == TIRENV_SPRINGS_CONTINUOUS && !level;
}

static size_t head_bytes(const tirenv_springs *s)
{
    return 2 * sizeof(size_t) + s->N + 1 + sizeof(double);
}

/* the flags; evals, memo_a, memo_b, ray_a, ray_b; pins_z, upd_x, upd_dfz_dz, eval_x, the
 * rays' origin's x; the memos (the vertex and kind their walk ended on, and the height it
 * holds above; not d(rho)/dz, which the face gives again, the same bits) */
static size_t carry_bytes(const tirenv_springs *s)
{
    return 1 + 5 * sizeof(uint64_t) + 5 * sizeof(double) + s->N * MEMO_BYTES;
}

/* The flags: pins_ok, start_taken, and the base, the memos and the rays' cache on p. */
enum { PINS_OK = 1, START_TAKEN = 2, UPD_HERE = 4, MEMO_HERE = 8, RAYS_HERE = 16 };

size_t tirenv_springs__state_size(const tirenv_springs *s, int level)
{
    return head_bytes(s) +
           (carries(s, level) ? carry_bytes(s) + tirenv_springs__cc_carry_size(s->N) : 0);
}

void tirenv_springs__state_save(const tirenv_springs *s, const tirenv_profile *p, int level,
                                unsigned char *buf)
{
    memcpy(buf, &s->a, sizeof s->a);
    memcpy(buf + sizeof s->a, &s->b, sizeof s->b);
    memcpy(buf + 2 * sizeof(size_t), s->active, s->N);
    buf[2 * sizeof(size_t) + s->N] = s->cc.between != 0;
    memcpy(buf + 2 * sizeof(size_t) + s->N + 1, &s->cc.between_z, sizeof(double));
    if (!carries(s, level))
        return;
    unsigned char *q = buf + head_bytes(s);
    memset(q, 0, carry_bytes(s));
    const unsigned long long serial = p ? p->serial : 0;
    /* the rays' cache: the walks over ray_a .. ray_b from origin.x, which the next
     * evaluation at that x reuses where they hold (and then takes the update there) */
    const int rays = serial && s->ray_serial == serial && s->ray_a <= s->ray_b &&
                     s->memo_serial == serial && s->memo_a <= s->ray_a &&
                     s->ray_b <= s->memo_b && s->memo_b < s->N;
    const unsigned char flags =
        (unsigned char)((s->pins_ok ? PINS_OK : 0) | (s->start_taken ? START_TAKEN : 0) |
                        (serial && s->upd_serial == serial ? UPD_HERE : 0) |
                        (serial && s->memo_serial == serial ? MEMO_HERE : 0) |
                        (rays ? RAYS_HERE : 0));
    const uint64_t u[5] = {s->evals, s->memo_a, s->memo_b, rays ? s->ray_a : 1,
                           rays ? s->ray_b : 0};
    const double v[5] = {s->pins_z, s->upd_x, s->upd_dfz_dz, s->eval_x,
                         rays ? s->origin.x : 0};
    q = tirenv_model__put(q, &flags, 1);
    q = tirenv_model__put(q, u, sizeof u);
    q = tirenv_model__put(q, v, sizeof v);
    for (size_t e = s->memo_a; e <= s->memo_b && e < s->N; ++e) {
        const tirenv_springs__ray_memo *m = &s->memo[e];
        const int64_t j = m->j;
        const int32_t kind = m->kind;
        unsigned char *at = q + e * MEMO_BYTES;
        at = tirenv_model__put(at, &j, sizeof j);
        at = tirenv_model__put(at, &kind, sizeof kind);
        tirenv_model__put(at, &m->z_low, sizeof m->z_low);
    }
    q += s->N * MEMO_BYTES;
    /* whether a pin the start would make its base from is a ground vertex's (the rows are
     * the closed form's evaluation's while pins_ok) */
    int pins_vertex = 0;
    for (size_t e = s->a; s->pins_ok && e <= s->b; ++e)
        pins_vertex |= s->active[e] && s->cc.pin_row[e] < s->cc.n_rows &&
                       s->cc.rows[s->cc.pin_row[e]].id >= 0;
    tirenv_springs__cc_carry_save(&s->cc, s->N, s->memo, s->memo_a, s->memo_b, s->dw,
                                  s->upd_x == s->eval_x, pins_vertex, q);
}

int tirenv_springs__state_restore(tirenv_springs *s, const tirenv_profile *p, int level,
                                  const unsigned char *buf)
{
    memcpy(&s->a, buf, sizeof s->a);
    memcpy(&s->b, buf + sizeof s->a, sizeof s->b);
    memcpy(s->active, buf + 2 * sizeof(size_t), s->N);
    if (!(s->a <= s->b && s->b < s->N)) { /* nothing may touch */
        s->a = 1;
        s->b = 0;
    }
    s->ray_serial = 0;
    forget_start(s);
    if (!carries(s, level)) {
        if (s->par.contact == TIRENV_SPRINGS_CONTINUOUS) { /* its warm start is not kept */
            tirenv_springs__cc_forget(&s->cc);
            s->cc.between = buf[2 * sizeof(size_t) + s->N] != 0;
            memcpy(&s->cc.between_z, buf + 2 * sizeof(size_t) + s->N + 1, sizeof(double));
        }
        return TIRENV_OK;
    }
    const unsigned char *q = buf + head_bytes(s);
    unsigned char flags;
    uint64_t u[5];
    double v[5];
    q = tirenv_model__get(q, &flags, 1);
    q = tirenv_model__get(q, u, sizeof u);
    q = tirenv_model__get(q, v, sizeof v);
    const unsigned long long serial = p ? p->serial : 0;
    s->pins_ok = (flags & PINS_OK) != 0;
    s->start_taken = (flags & START_TAKEN) != 0;
    s->upd_serial = flags & UPD_HERE ? serial : 0;
    s->memo_serial = flags & MEMO_HERE ? serial : 0;
    s->evals = u[0];
    s->memo_a = u[1] < s->N ? u[1] : 1;
    s->memo_b = u[2] < s->N ? u[2] : 0;
    s->pins_z = v[0];
    s->upd_x = v[1];
    s->upd_dfz_dz = v[2];
    s->eval_x = v[3];
    for (size_t e = s->memo_a; e <= s->memo_b; ++e) {
        tirenv_springs__ray_memo *m = &s->memo[e];
        int64_t j;
        int32_t kind;
        const unsigned char *at = q + e * MEMO_BYTES;
        at = tirenv_model__get(at, &j, sizeof j);
        at = tirenv_model__get(at, &kind, sizeof kind);
        tirenv_model__get(at, &m->z_low, sizeof m->z_low);
        m->j = (long)j;
        m->kind = kind;
        m->drho = NAN;
    }
    q += s->N * MEMO_BYTES;
    int pins_vertex;
    int status = tirenv_springs__cc_carry_restore(&s->cc, &s->cc_tire, s->memo, q,
                                                  p ? p->n : 0, s->dw, &pins_vertex);
    if (!status && p && (flags & RAYS_HERE) && u[3] <= u[4] && u[3] >= s->memo_a &&
        u[4] <= s->memo_b && isfinite(v[4])) {
        /* the rays' cache at its x: the origin as set_origin finds it (the same bits from
         * any hint), the walks the memos, whose vertices the reuse indexes p by (a state's
         * bytes are not trusted: docs/models.md section 1.7; elsewhere a memo's vertex is
         * read within the start's window of faces, which a streamed road's carry relies on) */
        set_origin(s, p, v[4]);
        for (size_t e = u[3]; e <= u[4] && !status; ++e)
            if (!tirenv_springs__memo_fits(p, &s->origin, &s->rays, e, &s->memo[e]))
                status = TIRENV_EINVAL;
        s->ray_a = u[3];
        s->ray_b = u[4];
    }
    if (status) {
        forget_start(s);
        tirenv_springs__cc_forget(&s->cc);
        s->ray_serial = 0;
        s->memo_serial = 0;
        s->upd_serial = 0;
        s->memo_a = 1;
        s->memo_b = 0;
    }
    /* the faces kept are another ground's or another run's: found again where asked */
    tirenv_springs__faces_forget(s);
    s->cc.between = buf[2 * sizeof(size_t) + s->N] != 0;
    memcpy(&s->cc.between_z, buf + 2 * sizeof(size_t) + s->N + 1, sizeof(double));
    return status;
}
