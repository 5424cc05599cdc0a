/* SPDX-License-Identifier: Apache-2.0 */
/* The rows of the springs model's continuous contact (docs/models.md section 4.8): the
 * tread's curve between elements (its weights a(t), b(t)), and every ground vertex under it
 * and every ray's pin as a row a w_i + b w_(i+1) >= h, reduced to each sector's upper hull and
 * laid out element by element for the active-set solve of springs_contact.c. */
#include "model/springs_impl.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "core/capacity.h"
#include "profile/profile_impl.h"

/* t closer than this to 0 or 1 is taken as the element itself, and of two rows of a sector
 * closer than this in tau only the higher is kept: two rows on nearly the same point would
 * make the KKT system nearly singular. The tread there moves by at most this fraction of
 * w_(i+1) - w_i (under 1e-8 m). */
static const double t_snap = TIRENV_SPRINGS__T_SNAP;

/* scan_vertex's forward walk goes a ray at a time for this many rays, then gallops. */
enum { scan_steps = 4 };

double tirenv_springs__cc_gamma(double k_r, double k_ir)
{
    if (!(k_ir > 0))
        return 0.5 * M_PI;
    const double ch = 1 + k_r / (2 * k_ir);
    return acos(1 / (ch + sqrt((ch - 1) * (ch + 1)))); /* exp(-mu) without cancellation */
}

void tirenv_springs__cc_weights(const tirenv_springs__cc_tire *T, double t, double *a,
                                double *b, double *da_dt, double *db_dt)
{
    /* sin((1 - t) g) = sin(g) cos(t g) - cos(g) sin(t g): one sine and cosine of t g. */
    const double g = T->gamma, inv = 1 / T->sin_gamma, cot = T->cot_gamma;
    const double sn = sin(t * g), cs = cos(t * g);
    *a = cs - cot * sn;
    *b = sn * inv;
    *da_dt = -g * (sn + cot * cs);
    *db_dt = g * cs * inv;
}

void tirenv_springs__cc_tire_shape(tirenv_springs__cc_tire *T)
{
    T->gamma = tirenv_springs__cc_gamma(T->k_r, T->k_ir);
    T->sin_gamma = sin(T->gamma);
    T->cot_gamma = cos(T->gamma) / T->sin_gamma;
    /* The bounds from 4096 samples, with margins far above the sampling's error (both
     * functions are smooth, their variation between samples below 1e-7 of their range):
     * ab_lo 1 % under the smallest (a + b - 1) / (t (1 - t)) seen, tau_dev 1 % over the
     * largest |tau - t| plus 1e-9. */
    double lo = INFINITY, dev = 0;
    for (int k = 1; k < 4096; ++k) {
        const double t = k / 4096.0;
        double a, b, da, db;
        tirenv_springs__cc_weights(T, t, &a, &b, &da, &db);
        lo = fmin(lo, (a + b - 1) / (t * (1 - t)));
        dev = fmax(dev, fabs(b / (a + b) - t));
    }
    T->ab_lo = lo > 0 ? 0.99 * lo : 0;
    T->tau_dev = 1.01 * dev + 1e-9;
    /* the diagonal of the inverse of the endless chain's K (k_r + 2 k_ir on the diagonal,
     * -k_ir beside it): 1 / sqrt((k_r + 2 k_ir)^2 - 4 k_ir^2) */
    T->c0 = 1 / sqrt(T->k_r * (T->k_r + 4 * T->k_ir));
    /* sin(theta_(i+1) - theta_i) from the unit vectors the scan uses */
    double inv_sin = 0;
    for (size_t i = 0; i + 1 < T->N; ++i)
        inv_sin = fmax(inv_sin, 1 / (T->cos_t[i] * T->sin_t[i + 1] -
                                     T->sin_t[i] * T->cos_t[i + 1]));
    T->inv_sin_step = inv_sin * (1 + 1e-9);
}

/* Room for n rows (and their KKT unknowns alongside N elements). */
static int reserve_rows(tirenv_springs__cc *c, size_t n, size_t N)
{
    if (n <= c->cap_rows)
        return TIRENV_OK;
    const size_t cap = tirenv_core__capacity(c->cap_rows, 64, n);
    tirenv_springs__cc_row *r = realloc(c->rows, cap * sizeof *c->rows);
    if (!r)
        return TIRENV_ENOMEM;
    for (size_t k = c->cap_rows; k < cap; ++k)
        r[k].id = 0; /* no ray's (put_pin reads it) */
    c->rows = r;
    unsigned char *in_w = realloc(c->in_w, cap);
    if (!in_w)
        return TIRENV_ENOMEM;
    c->in_w = in_w;
    double *lambda = realloc(c->lambda, cap * sizeof *lambda);
    if (!lambda)
        return TIRENV_ENOMEM;
    c->lambda = lambda;
    tirenv_springs__cc_key *keys = realloc(c->keys, cap * sizeof *keys);
    if (!keys)
        return TIRENV_ENOMEM;
    c->keys = keys;
    keys = realloc(c->last_keys, cap * sizeof *keys); /* keeps the last solve's */
    if (!keys)
        return TIRENV_ENOMEM;
    c->last_keys = keys;
    size_t *pos = realloc(c->pos, cap * sizeof *pos);
    if (!pos)
        return TIRENV_ENOMEM;
    c->pos = pos;
    size_t *order = realloc(c->order, (cap + N) * sizeof *order);
    if (!order)
        return TIRENV_ENOMEM;
    c->order = order;
    size_t *env_first = realloc(c->env_first, (cap + N) * sizeof *env_first);
    if (!env_first)
        return TIRENV_ENOMEM;
    c->env_first = env_first;
    size_t *env_last = realloc(c->env_last, (cap + N) * sizeof *env_last);
    if (!env_last)
        return TIRENV_ENOMEM;
    c->env_last = env_last;
    double *rhs = realloc(c->rhs, (cap + N) * sizeof *rhs);
    if (!rhs)
        return TIRENV_ENOMEM;
    c->rhs = rhs;
    c->cap_rows = cap;
    return TIRENV_OK;
}

int tirenv_springs__cc_reserve_rows(tirenv_springs__cc *c, size_t n, size_t N)
{
    return reserve_rows(c, n, N);
}

/* Room for n vertex rows in c->vrows. */
static int reserve_vrows(tirenv_springs__cc *c, size_t n)
{
    if (n <= c->cap_vrows)
        return TIRENV_OK;
    const size_t cap = tirenv_core__capacity(c->cap_vrows, 64, n);
    void *r = realloc(c->vrows, cap * sizeof *c->vrows);
    if (!r)
        return TIRENV_ENOMEM;
    c->vrows = r;
    unsigned char *force = realloc(c->vforce, cap);
    if (!force)
        return TIRENV_ENOMEM;
    c->vforce = force;
    c->cap_vrows = cap;
    return TIRENV_OK;
}

/* Room for the scan's proofs of n vertices (c->seen, c->seen_todo) and for the sectors of N
 * elements. */
static int reserve_seen(tirenv_springs__cc *c, size_t n, size_t N)
{
    if (!c->seen_sec && !(c->seen_sec = calloc(7 * N, sizeof *c->seen_sec)))
        return TIRENV_ENOMEM;
    if (n <= c->cap_seen)
        return TIRENV_OK;
    const size_t cap = tirenv_core__capacity(c->cap_seen, 64, n);
    void *e = realloc(c->seen, cap * sizeof *c->seen);
    if (!e)
        return TIRENV_ENOMEM;
    c->seen = e;
    size_t *todo = realloc(c->seen_todo, cap * sizeof *todo);
    if (!todo)
        return TIRENV_ENOMEM;
    c->seen_todo = todo;
    c->cap_seen = cap;
    return TIRENV_OK;
}

/* The scan's loops are each compiled on their own: GCC otherwise inlines them all into
 * vertex_rows, whose registers then go where it sees fit, and a change to one loop moved the
 * others' time by a few per cent. Each starts on a 64-byte boundary: where the code before it
 * ended moved the 10 mm road's time (the plain scan, scan_all) by 2.5 %. */
#if defined(__GNUC__)
#define SCAN_LOOP static __attribute__((noinline, aligned(64)))
#else
#define SCAN_LOOP static
#endif

/* The scans at one x that run without proofs (vertex_rows). */
enum { scans_unproven = 2 };

/* How far the centre may move from the height of a vertex's proof, as a fraction of the
 * vertex's depth dz_r below it: within it rho stays above (1 - seen_reach) rho_r. */
static const double seen_reach = 0.01;

/* Ray e's penetration as the vertex rows take it: 0 outside [a, b] or without a crossing. */
static inline double pen(size_t e, size_t a, size_t b, const double d[])
{
    return e >= a && e <= b && d[e] > 0 ? d[e] : 0;
}

/* The allowance of the proofs at centre height z: far above the rounding of any quantity
 * they bound (each a few operations on numbers below |z| + R0 + max |Z|). */
static double seen_tol(const tirenv_profile *p, double R0, double z)
{
    return 1024 * DBL_EPSILON * (fabs(z) + R0 + p->z_abs_max);
}

/* The scan's vectorised loops (prove_guess, seen_bounds, seen_check) are compiled for
 * AVX-512, AVX2 and the baseline (SSE2) alike, and the loader picks the best the processor
 * has (GCC's target_clones through an ELF ifunc, as the network's evaluation,
 * src/nn/nn_impl.h): with SSE2 alone the guessed sectors cost more time than the walk they
 * replace, with AVX-512 (real gathers, masks, three-operand instructions) much less
 * (docs/models.md section 4.8, The scans at an x). The same bits from every clone: the same
 * IEEE operations, no contraction in ISO C mode. Not under ThreadSanitizer, whose runtime the
 * ifunc resolver would run before. CMakeLists.txt compiles this file without errno, so that
 * the square root vectorises. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__) &&     \
    !defined(__SANITIZE_THREAD__) && !defined(TIRENV_SPRINGS_NO_CLONES)
#define PROVE_CLONES __attribute__((noinline, target_clones("avx512f", "avx2", "default")))
#else
#define PROVE_CLONES
#endif

/* What seen_todo's sectors' bounds take besides each sector's numbers. */
typedef struct {
    double tau_dev, h_rise, B, ab_lo, aD, aD_reach, tol, tol_r, tol4_r, Dp;
} seen_at_z;

/* seen_todo's bounds Qt[q] and Qm[q] of the sectors q < n (seen_todo's comment), from the
 * penetrations at z, Pz[0 .. n], and what the proving scan kept (sA, sD, sT, sZ): a loop the
 * compiler vectorises. Each selection is between values computed on both sides, or adds 0
 * or takes a factor of 1 (the same numbers as the branches they replace: x + 0 and x * 1 are
 * x, and a zero's sign cannot reach a test), so that no operation is left to one side only,
 * which would keep the branch. */
PROVE_CLONES static void seen_bounds(size_t n, const double *restrict Pz,
                                     const double *restrict sA, const double *restrict sD,
                                     const double *restrict sT, const double *restrict sZ,
                                     const seen_at_z *restrict W, double *restrict Qt,
                                     double *restrict Qm)
{
    const double tau_dev = W->tau_dev, h_rise = W->h_rise, B = W->B, ab_lo = W->ab_lo;
    const double aD = W->aD, aD_reach = W->aD_reach, tol = W->tol, tol_r = W->tol_r;
    const double tol4_r = W->tol4_r, Dp = W->Dp;
    for (size_t q = 0; q < n; ++q) {
        const double Pl = Pz[q], Pr = Pz[q + 1];
        const double A = Pl - fabs(Pr - Pl) * tau_dev, D = Pr - Pl;
        const double dA = A - sA[q], dB = dA + (D - sD[q]), mu = dB < dA ? dB : dA;
        /* the largest and the least chord at z_r */
        const double top = sA[q] + (sD[q] > 0 ? sD[q] : 0);
        const double c_lo = sA[q] + (sD[q] < 0 ? sD[q] : 0);
        const double Base = h_rise + -mu * (mu < 0 ? B : 1);
        const double Kq = fabs(D) * B + (top + (mu > 0 ? mu : 0)) * ab_lo;
        const double dt = aD * sT[q];
        /* z within 1 % of every proven vertex's depth, the chord above zero */
        const double chord_holds = c_lo - tol_r + mu - tol >= fabs(D) * dt ? 0 : INFINITY;
        Qt[q] = dt + 2 * t_snap + (aD_reach <= sZ[q] ? chord_holds : INFINITY);
        Qm[q] = Base + dt * Kq + tol4_r - Dp * sZ[q];
    }
}

/* Vertices a seen_check call (seen_todo): their results, a long each, 512 bytes on the
 * stack. */
#define CHECK_BLOCK 64

/* Whether each vertex e[0 .. n - 1] has a proof and it holds at the bounds Qt, Qm
 * (seen_todo), into ok: a loop the compiler vectorises. The bounds of a vertex without a
 * proof are read too (of a sector seen_todo may not have bounded now: seen_sec is zeroed
 * when made, so they are numbers) and not used. */
PROVE_CLONES static void seen_check(size_t n, const tirenv_springs__cc_seen *restrict e,
                                    const double *restrict Qt, const double *restrict Qm,
                                    long *restrict ok)
{
    for (size_t k = 0; k < n; ++k)
        ok[k] = (e[k].m_t > 0) & (Qt[e[k].i] < e[k].m_t) & (e[k].margin >= Qm[e[k].i]);
}

/* At a later height z of the x the proofs were made at (vertex_rows' comment): the vertices
 * j0 .. j_end - 1 (within those proven) with no proof or one that does not hold at z,
 * ascending, into todo; returns their number, *skipped the others'. */
SCAN_LOOP size_t seen_todo(const tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                           const tirenv_profile *p, double z, size_t a, size_t b,
                           const double d[], size_t j0, size_t j_end, size_t todo[],
                           size_t *skipped)
{
    const double ab_lo = T->ab_lo, tau_dev = T->tau_dev;
    const double tol = seen_tol(p, T->R0, z), B = 1 + 0.25 * ab_lo; /* the bow's largest */
    const size_t N = T->N, s0 = c->seen_j0, lo = c->seen_lo;
    const double Delta = z - c->seen_z, aD = fabs(Delta) + tol;
    /* Per sector, from the chords at z_r (sA, sD) and at z: mu, the least change of the
     * chord over t in [0, 1]; what that takes from the margin (times the bow, 1 to B) with
     * h's rise but for its part proportional to the vertex's depth (Base); what the margin
     * loses a unit of t's move (the chord's slope |P_r - P_l| times the bow, the bow's slope
     * ab_lo times the chord: Kq); and |P_r - P_l| at z. A sector's P_r is the next one's
     * P_l. The bound on t's move, dt = aD sT (sT the sector's bound on |dt/dz|), is the
     * same for every vertex of the sector, and so are the chord's fall dt |P_r - P_l| and
     * what the margin must cover, Base + dt Kq: each is computed once a sector. So is all
     * else a proof needs: the chord is at least the sector's least at z_r, and the depth
     * at least the sector's least, sZ (vertex_rows). What a vertex's margin must cover, less
     * the part of h's fall that the sector's least depth gives, and dt with 2 t_snap, go
     * to Qm[q] and Qt[q]; Qt is infinite where the sector's own tests fail. The penetrations
     * at z are taken first (Pz), so that the sectors' loop does not branch on the rays. */
    const double *const sA = c->seen_sec, *const sD = sA + N, *const sT = sD + N;
    const double *const sZ = sT + N;
    double *const Qt = c->seen_sec + 4 * N, *const Qm = Qt + N, *const Pz = Qm + N;
    /* the allowances of the proofs' margin and chord, taken off here (scan_prove) */
    const double tol_r = seen_tol(p, T->R0, c->seen_z), tol4_r = 4 * tol_r;
    /* h rises by at most -Delta + tol if z falls, -Delta dz_r / R0 + tol if it rises */
    const double h_rise = Delta > 0 ? tol : -Delta + tol;
    const double Dp = Delta > 0 ? Delta * ((1 - 1e-12) / T->R0) : 0;
    /* |Delta| <= seen_reach dz_r wherever aD / seen_reach (rounded up) <= dz_r */
    const double aD_reach = aD / seen_reach * (1 + 1e-12);
    const size_t hi = c->seen_hi;
    for (size_t q = lo; q <= hi + 1; ++q)
        Pz[q] = pen(q, a, b, d);
    seen_bounds(hi + 1 - lo, Pz + lo, sA + lo, sD + lo, sT + lo, sZ + lo, &(const seen_at_z){
                    .tau_dev = tau_dev, .h_rise = h_rise, .B = B, .ab_lo = ab_lo, .aD = aD,
                    .aD_reach = aD_reach, .tol = tol, .tol_r = tol_r, .tol4_r = tol4_r,
                    .Dp = Dp}, Qt + lo, Qm + lo);
    /* A proof holds if its sector's tests hold and t stays more than 2 t_snap inside the
     * sector, and the margin covers h's rise, the chord's fall and t's move: both tested for
     * a block of vertices at once (seen_check), then the vertices listed without a branch on
     * the outcome (it follows the road, not a pattern). */
    size_t n = 0;
    long ok[CHECK_BLOCK];
    for (size_t k0 = j0 - s0; k0 < j_end - s0; k0 += CHECK_BLOCK) {
        const size_t m = j_end - s0 - k0 < CHECK_BLOCK ? j_end - s0 - k0 : CHECK_BLOCK;
        seen_check(m, c->seen + k0, Qt, Qm, ok);
        for (size_t k = 0; k < m; ++k) {
            todo[n] = s0 + k0 + k;
            n += !ok[k];
        }
    }
    *skipped = j_end - j0 - n;
    return n;
}

/* What the scan of the vertex rows needs at (x, z): the profile, the tire, the rays'
 * penetrations d over [a, b]. */
typedef struct {
    const double *X, *Z, *st, *ct, *d;
    double x, z, R0, R0sq, ab_lo, tau_dev;
    size_t N, a, b;
} scan_ctx;

/* Along the scan: the last vertex's sector (where the next one's walk starts), sector ci's
 * penetrations and slack, the next row. */
typedef struct {
    size_t i, ci;
    double P_l, P_r, slack_tau;
    tirenv_springs__cc_row *out;
} scan_state;

/* Vertex j's row in sector i at out, the new end returned: h = R0 - rho, dz the vertex's depth
 * below the centre, s_i >= 0 its sigma on ray i and, when s_i > 0, s_n = -sigma_(i+1) > 0,
 * S = s_i + s_n and t = s_i / S. A row on element i (s_i = 0 or t snapped to 0), on element
 * i + 1 (t snapped to 1), or between them at t; the caller has tested a row between elements
 * against the chord (scan_vertex's drop). A row on the element alone (t snapped, or exactly on
 * its ray) keeps t = 0 while z moves within the snap: dt/dz = 0 is the derivative of the rows
 * as used. The weights of a row between elements come later, for the rows that can bind
 * (build_rows); dga_dz holds dt/dz until then. */
static inline tirenv_springs__cc_row *put_row(const double st[], size_t j, size_t i, double s_i,
                                              double s_n, double S, double t, double h,
                                              double dz, double rho,
                                              tirenv_springs__cc_row *out)
{
    size_t r_i = i, r_j = i;
    double r_t = 0, r_dt = 0;
    if (s_i > 0) {
        if (t >= 1 - t_snap) {
            r_i = r_j = i + 1;
        } else if (t > t_snap) {
            r_j = i + 1;
            r_t = t;
            /* d(s_i)/dz = -sin(theta_i), d(s_n)/dz = sin(theta_(i+1)) */
            r_dt = (-st[i] * s_n - s_i * st[i + 1]) / (S * S);
        }
    }
    *out = (tirenv_springs__cc_row){.i = r_i, .j = r_j, .t = r_t, .tau = 0, .ga = 1, .gb = 0,
                                    .h = h, .dga_dz = r_dt, .dgb_dz = 0, .dh_dz = -dz / rho,
                                    .id = (long)j};
    return out + 1;
}

/* walk_ahead past its first scan_steps rays, from ray i with sigma_k >= 0 on (the start, i]:
 * galloping, then bisection. */
static inline size_t gallop(const double st[], const double ct[], size_t N, double dx,
                            double dz, size_t i, double *s_n)
{
    size_t hi = N; /* the first ray past i where sigma_k fails, once found */
    for (size_t step = 2;; step *= 2) {
        const size_t k = i + step;
        if (k >= N)
            break;
        const double u = dx * ct[k] - dz * st[k];
        if (!(u >= 0)) {
            hi = k;
            *s_n = -u;
            break;
        }
        i = k;
    }
    while (hi - i > 1) {
        const size_t k = i + (hi - i) / 2;
        const double u = dx * ct[k] - dz * st[k];
        if (u >= 0) {
            i = k;
        } else {
            hi = k;
            *s_n = -u;
        }
    }
    return i;
}

/* tirenv_springs__walk_ahead: a ray at a time for the first scan_steps rays (a road's next
 * vertex lies a few sectors on), then gallop. sigma_k >= 0 holds for the rays up to the
 * vertex's angle and fails beyond (|theta| <= pi/2 and dz > 0: sin(psi - theta_k) changes
 * sign once, and only one ray can lie within round-off of it), so any search finds the first
 * ray past i where it fails, the walk's, with its sigma: some 2 log2 steps where the walk
 * took one a sector (a cleat's far corner lies some 30 sectors from its near one). */
static inline size_t walk_ahead(const double st[], const double ct[], size_t N, double dx,
                                double dz, size_t i, double *s_n)
{
    *s_n = 0;
    for (size_t n = 0; n < scan_steps; ++n) {
        if (i + 1 >= N)
            return i;
        const double u = dx * ct[i + 1] - dz * st[i + 1];
        if (!(u >= 0)) {
            *s_n = -u;
            return i;
        }
        ++i;
    }
    return i + 1 < N ? gallop(st, ct, N, dx, dz, i, s_n) : i;
}

size_t tirenv_springs__walk_ahead(const double st[], const double ct[], size_t N, double dx,
                                  double dz, size_t i, double *s_n)
{
    return walk_ahead(st, ct, N, dx, dz, i, s_n);
}

/* Vertex j's row at (x, z), if it has one, at sc->out; sc along. scan_prove repeats these
 * operations in a loop of its own: change both (test_springs_scan compares them bit for
 * bit). */
static inline void scan_vertex(const scan_ctx *C, scan_state *sc, size_t j)
{
    const double dx = C->X[j] - C->x, dz = C->z - C->Z[j];
    if (!(dz > 0))
        return; /* at or above the centre's height: outside the lower half */
    const double rr = dx * dx + dz * dz;
    const double *const st = C->st, *const ct = C->ct;
    if (!(rr < C->R0sq))
        return;
    /* sigma_k = rho sin(psi - theta_k): >= 0 at or ahead of ray k. The walk keeps the
     * sigmas it computes: sigma_(i+1) < 0 ends the forward walk, and s_n = -sigma_(i+1)
     * is the same number as dz sin(theta_(i+1)) - dx cos(theta_(i+1)) (the same two
     * products; rounding to nearest is symmetric), never 0. */
    double s_n; /* 0: not known */
    size_t i = walk_ahead(st, ct, C->N, dx, dz, sc->i, &s_n);
    double s_i = dx * ct[i] - dz * st[i];
    while (i > 0 && s_i < 0) {
        --i;
        s_i = dx * ct[i] - dz * st[i];
        s_n = 0;
    }
    sc->i = i;
    if (s_i < 0)
        return; /* behind the first element */
    const double rho = sqrt(rr), h = C->R0 - rho;
    if (!(h > 0))
        return;
    double S = 0, t = 0;
    if (s_i > 0) {
        if (i + 1 >= C->N)
            return; /* beyond the last element's ray */
        if (s_n == 0)
            s_n = dz * st[i + 1] - dx * ct[i + 1]; /* > 0: before ray i + 1 */
        S = s_i + s_n;
        t = s_i / S;
        if (t < 1 - t_snap && t > t_snap) {
            /* Below the hull of the rays' own rows (build_rows' test with the rays'
             * penetrations, which the elements' rows only raise): never binds. */
            if (sc->ci != i) {
                sc->ci = i;
                sc->P_l = pen(i, C->a, C->b, C->d);
                sc->P_r = pen(i + 1, C->a, C->b, C->d);
                sc->slack_tau = fabs(sc->P_r - sc->P_l) * C->tau_dev;
            }
            const double chord = (1 - t) * sc->P_l + t * sc->P_r - sc->slack_tau;
            const double thr = chord * (1 + C->ab_lo * t * (1 - t));
            if (!(h > thr))
                return;
        }
    }
    sc->out = put_row(st, j, i, s_i, s_n, S, t, h, dz, rho, sc->out);
}

/* scan_vertex over the vertices todo[0 .. n - 1], each walk from the sector the proving scan
 * left the vertex in (seen[k].i of vertex s0 + k): its sector at this height is that one or
 * a neighbour, where the last vertex listed may lie sectors away. The walk ends in the same
 * sector from either start (the one between the rays the vertex lies between), with the
 * same numbers. */
SCAN_LOOP void scan_list(const scan_ctx *C, scan_state *sc, const size_t todo[],
                         const tirenv_springs__cc_seen seen[], size_t s0, size_t n)
{
    scan_state S = *sc;
    for (size_t q = 0; q < n; ++q) {
        S.i = seen[todo[q] - s0].i;
        scan_vertex(C, &S, todo[q]);
    }
    *sc = S;
}

/* scan_vertex over the vertices j0 .. j_end - 1. */
SCAN_LOOP void scan_all(const scan_ctx *C, scan_state *sc, size_t j0, size_t j_end,
                        size_t *i_first)
{
    scan_state S = *sc;
    size_t j = j0;
    for (; j < j_end; ++j) { /* up to the first vertex within reach: its walk */
        scan_vertex(C, &S, j);
        const double dx = C->X[j] - C->x, dz = C->z - C->Z[j];
        if (dz > 0 && dx * dx + dz * dz < C->R0sq) {
            *i_first = S.i;
            ++j;
            break;
        }
    }
    for (; j < j_end; ++j)
        scan_vertex(C, &S, j);
    *sc = S;
}

/* A scan at an x without proofs to check: what scan_vertex does, with a proof for every vertex
 * dropped between elements (vertex_rows' comment) or the rows alone, in two passes over blocks of
 * PROVE_BLOCK vertices. scan_vertex finds a vertex's sector by a walk from the last vertex's,
 * which carries from vertex to vertex and branches at each step; prove_guess instead guesses each
 * vertex's sector from its angle (psi = atan(dx / dz) by a polynomial, the rays being dphi apart),
 * then takes the sigmas of the guessed sector's rays, t, h and the drop test with no branch and
 * nothing carried from vertex to vertex: loops the compiler vectorises, the rays' and the sectors'
 * numbers gathered at the guess. Where the sigmas show the guess right (sigma_g > 0 > sigma_(g+1):
 * the walk would end in sector g, the sigmas' signs along the rays changing once) its numbers are
 * the walk's own, the same operations on the same operands (IEEE arithmetic gives a vector's lane
 * what it gives alone, and no FMA is contracted in ISO C mode). The vertices it does not prove
 * dropped (out of reach, rows, and the few whose guess missed: within the polynomial's error of a
 * ray, or on one) are taken again one by one by scan_vertex's walk from the guess (prove_vertex).
 * So the same rows and tests, bit for bit (test_springs_scan). The proofs keep the raw margin,
 * min(t, 1 - t) and the sector; seen_todo takes the allowances and t_snap off once a sector (m_t
 * 0: no proof). */

/* Vertices a block: its scratch (5 doubles a vertex, 2.5 KB) stays in the first-level cache
 * between the passes. */
#define PROVE_BLOCK 64

/* What the guess needs besides scan_ctx: theta_0 and 1 / dphi (rad, 1/rad), the sectors a
 * guess is clamped to [g_lo, g_hi] (g_hi <= N - 2), and each sector q's penetrations and
 * slack at P_l[q], P_r[q], slack[q] over that range. */
typedef struct {
    double theta_0, inv_dphi;
    int g_lo, g_hi;
    const double *P_l, *P_r, *slack;
} prove_guide;

/* One block's results of prove_guess: each vertex's guessed sector, the margin, and m_t (> 0
 * a proof, else 0: the vertex is taken again by prove_vertex). */
typedef struct {
    int g[PROVE_BLOCK];
    double margin[PROVE_BLOCK], m_t[PROVE_BLOCK];
    long open; /* the vertices with m_t 0 */
} prove_block;


/* The proving scan of the vertices j0 .. j0 + m - 1 at their guessed sectors, into B. Two
 * loops: the guess's chain of operations (a division, the polynomial, the conversion) and the
 * test's (the gathers, the sigmas, t's division, the chord) are each long, and one loop of
 * both held too few vertices in flight (26 % slower than the walk with SSE2). */
PROVE_CLONES static void prove_guess(const scan_ctx *C, const prove_guide *G, size_t j0,
                                     size_t m, prove_block *restrict B)
{
    const double *restrict const X = C->X + j0, *restrict const Z = C->Z + j0;
    const double *restrict const st = C->st, *restrict const ct = C->ct;
    const double *restrict const Pl = G->P_l, *restrict const Pr = G->P_r;
    const double *restrict const Sl = G->slack;
    const double x = C->x, z = C->z, R0 = C->R0, R0sq = C->R0sq, ab_lo = C->ab_lo;
    const double theta_0 = G->theta_0, inv_dphi = G->inv_dphi;
    const double g_lo = G->g_lo, g_hi = G->g_hi;
    long open = 0;
    for (size_t k = 0; k < m; ++k) {
        /* atan(r), |r| <= 1, within 1e-5 rad (Abramowitz and Stegun 4.4.47), in Estrin's
         * order: a guess only, checked below (a sector is some 0.02 rad: one vertex in a
         * thousand lies within the error of a ray); NaN or far off where dz <= 0, then
         * clamped */
        const double r = (X[k] - x) / (z - Z[k]), r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
        const double p01 = 0.9998660 - 0.3302995 * r2;
        const double p23 = 0.1801410 - 0.0851330 * r2;
        const double psi = r * ((p01 + p23 * r4) + 0.0208351 * r8);
        double f = (psi - theta_0) * inv_dphi;
        f = f >= g_lo ? f : g_lo; /* NaN too */
        f = f <= g_hi ? f : g_hi;
        B->g[k] = (int)f;
    }
    for (size_t k = 0; k < m; ++k) {
        const double dx = X[k] - x, dz = z - Z[k], rr = dx * dx + dz * dz;
        const double in = ((dz > 0) & (rr < R0sq)) ? 1 : 0; /* a double: the lanes' width */
        /* scan_vertex's numbers in sector g */
        const int g = B->g[k];
        const double s_i = dx * ct[g] - dz * st[g], u = dx * ct[g + 1] - dz * st[g + 1];
        const double S = s_i - u, t = s_i / S;
        const double rho = sqrt(rr), h = R0 - rho;
        const double omt = 1 - t;
        const double chord = omt * Pl[g] + t * Pr[g] - Sl[g];
        const double thr = chord * (1 + ab_lo * t * omt);
        /* the guess held (sigma_g > 0 > sigma_(g+1): the walk would end in sector g, the
         * sigmas' signs along the rays changing once) and the test drops the vertex */
        const int drop = (in > 0) & (s_i > 0) & (u < 0) & (h > 0) & (t < 1 - t_snap) &
                         (t > t_snap) & !(h > thr);
        B->m_t[k] = drop ? (t < omt ? t : omt) : 0;
        B->margin[k] = thr - h;
        open += !drop;
    }
    B->open = open;
}

/* Vertex j, which the guess did not prove dropped (out of reach, a row, or its sector
 * missed): its row at out as scan_vertex takes it, the new end returned, or its proof into
 * *e if it is dropped between elements; its walk from sector g (the guess: the walk ends in
 * the same sector from any start, scan_list). *e's sector: the walk's, or g for a vertex out
 * of reach (where a later scan's walk starts). [*v_lo, *v_hi] take in the sectors the walk
 * visits; *missed counts the vertices within reach whose sector is not g. */
static tirenv_springs__cc_row *prove_vertex(const scan_ctx *C, size_t g, size_t j,
                                            tirenv_springs__cc_seen *e,
                                            tirenv_springs__cc_row *out, size_t *v_lo,
                                            size_t *v_hi, size_t *missed)
{
    const double *const st = C->st, *const ct = C->ct;
    const double dx = C->X[j] - C->x, dz = C->z - C->Z[j];
    const size_t N = C->N;
    *e = (tirenv_springs__cc_seen){.margin = 0, .m_t = 0, .i = g};
    if (!(dz > 0 && dx * dx + dz * dz < C->R0sq))
        return out;
    size_t i = g;
    while (i + 1 < N && dx * ct[i + 1] - dz * st[i + 1] >= 0)
        ++i;
    *v_hi = i > *v_hi ? i : *v_hi;
    while (i > 0 && dx * ct[i] - dz * st[i] < 0)
        --i;
    *v_lo = i < *v_lo ? i : *v_lo;
    *missed += i != g;
    e->i = i;
    const double s_i = dx * ct[i] - dz * st[i];
    if (s_i < 0 || (s_i > 0 && i + 1 >= N))
        return out; /* behind the first ray, beyond the last */
    const double rho = sqrt(dx * dx + dz * dz), h = C->R0 - rho;
    if (!(h > 0))
        return out;
    double s_n = 0, S = 0, t = 0;
    if (s_i > 0) {
        s_n = dz * st[i + 1] - dx * ct[i + 1]; /* -sigma_(i+1), the same number (scan_vertex) */
        S = s_i + s_n;
        t = s_i / S;
        if (t < 1 - t_snap && t > t_snap) {
            const double P_l = pen(i, C->a, C->b, C->d), P_r = pen(i + 1, C->a, C->b, C->d);
            const double slack_tau = fabs(P_r - P_l) * C->tau_dev;
            const double omt = 1 - t;
            const double chord = omt * P_l + t * P_r - slack_tau;
            const double thr = chord * (1 + C->ab_lo * t * omt);
            if (!(h > thr)) {
                *e = (tirenv_springs__cc_seen){.margin = thr - h, .m_t = t < omt ? t : omt,
                                               .i = i};
                return out;
            }
        }
    }
    return put_row(st, j, i, s_i, s_n, S, t, h, dz, rho, out);
}

/* The vertices j0 .. j0 + n - 1 (with proofs: their proofs at seen[0 .. n - 1]; else their
 * rows alone), in the sectors' range [a1, b1] (vertex_rows); sec: room for 3 N doubles;
 * blind: every guess the range's first sector (the tests' scan_blind). The rows go to out,
 * the new end returned; [*lo, *hi]: the sectors of every proof among them, within
 * [0, N - 2]; *missed: the vertices within reach whose sector the guess missed. */
SCAN_LOOP tirenv_springs__cc_row *scan_prove(const scan_ctx *C, size_t a1, size_t b1,
                                             int blind, int proofs, double *sec, size_t j0,
                                             size_t n, tirenv_springs__cc_seen seen[],
                                             tirenv_springs__cc_row *out, size_t *lo,
                                             size_t *hi, size_t *missed)
{
    const size_t N = C->N;
    const double *const st = C->st, *const ct = C->ct;
    const size_t g_lo = a1 < N - 2 ? a1 : N - 2, g_hi = b1 < N - 2 ? b1 : N - 2;
    /* each sector's penetrations and slack, as the walk takes them (pen): sector q's P_r is
     * sector q + 1's P_l, so one array read at q and at q + 1 */
    double *const P_l = sec, *const P_r = sec + 1, *const slack = sec + 2 * N;
    for (size_t q = g_lo; q <= g_hi + 1; ++q)
        P_l[q] = pen(q, C->a, C->b, C->d);
    for (size_t q = g_lo; q <= g_hi; ++q)
        slack[q] = fabs(P_r[q] - P_l[q]) * C->tau_dev;
    /* the rays are dphi apart: theta_0 and dphi from the first two */
    const double dphi = atan2(ct[0] * st[1] - st[0] * ct[1], ct[0] * ct[1] + st[0] * st[1]);
    const prove_guide G = {.theta_0 = atan2(st[0], ct[0]), .inv_dphi = blind ? 0 : 1 / dphi,
                           .g_lo = (int)g_lo, .g_hi = (int)g_hi, .P_l = P_l, .P_r = P_r,
                           .slack = slack};
    size_t v_lo = g_lo, v_hi = g_hi;
    prove_block B;
    for (size_t q0 = 0; q0 < n; q0 += PROVE_BLOCK) {
        const size_t m = n - q0 < PROVE_BLOCK ? n - q0 : PROVE_BLOCK;
        prove_guess(C, &G, j0 + q0, m, &B);
        /* the proofs, and the few vertices the guess did not prove dropped */
        if (proofs) {
            tirenv_springs__cc_seen *const e = seen + q0;
            for (size_t k = 0; k < m; ++k) {
                e[k] = (tirenv_springs__cc_seen){.margin = B.margin[k], .m_t = B.m_t[k],
                                                 .i = (size_t)B.g[k]};
                if (!(B.m_t[k] > 0))
                    out = prove_vertex(C, (size_t)B.g[k], j0 + q0 + k, &e[k], out, &v_lo,
                                       &v_hi, missed);
            }
        } else {
            /* only the rows: the walk over the block's results ends at the last vertex
             * not proven dropped (most blocks under the patch have none) */
            tirenv_springs__cc_seen none;
            for (size_t k = 0, open = (size_t)B.open; open > 0; ++k)
                if (!(B.m_t[k] > 0)) {
                    out = prove_vertex(C, (size_t)B.g[k], j0 + q0 + k, &none, out, &v_lo,
                                       &v_hi, missed);
                    --open;
                }
        }
    }
    *lo = v_lo;
    *hi = v_hi < N - 2 ? v_hi : N - 2;
    return out;
}

/* The sectors' numbers of the proofs made at z_r = c->seen_z with the span [a, b] and the
 * penetrations d there: the chords (sA, sD), the bounds on a proven vertex's |dt/dz| (sT)
 * and on its depth (sZ) over the sectors c->seen_lo .. c->seen_hi (vertex_rows' comment). */
static void seen_sectors(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                         const tirenv_profile *p, size_t a, size_t b, const double d[])
{
    const size_t N = T->N, seen_lo = c->seen_lo, seen_hi = c->seen_hi;
    const double R0 = T->R0, ab_lo = T->ab_lo, tau_dev = T->tau_dev;
    const double *const st = T->sin_t, *const ct = T->cos_t;
    const double tol = seen_tol(p, R0, c->seen_z);
    const double dt_dz_of = T->inv_sin_step / ((1 - seen_reach) * (1 - seen_reach));
    double *const sA = c->seen_sec, *const sD = sA + N, *const sT = sD + N;
    double *const sZ = sT + N;
    const double B = 1 + 0.25 * ab_lo; /* the bow's largest */
    double Pl = pen(seen_lo, a, b, d);
    for (size_t q = seen_lo; q <= seen_hi; ++q) {
        const double Pr = pen(q + 1, a, b, d);
        sA[q] = Pl - fabs(Pr - Pl) * tau_dev;
        sD[q] = Pr - Pl;
        /* A vertex proven in sector q was dropped: h <= thr <= max(P_l, P_r) B, so
         * rho >= rho_lo = R0 - max(P_l, P_r) B (less an allowance), and its angle psi
         * lies between the sector's rays and below the centre, in (-pi/2, pi/2), where
         * |sin(psi)| is at most the larger of the rays' (if both point below the
         * horizontal; else 1): the vertex's |dx| / rr = |sin(psi)| / rho is at most
         * s_max / rho_lo, the same for the whole sector and with no division a vertex.
         * Rounding far inside 1e-12. No bound (infinite: nothing proven) if rho_lo <= 0. */
        const double rho_lo = (R0 - (Pl > Pr ? Pl : Pr) * B) * (1 - 1e-12) - tol;
        const double s_l = fabs(st[q]), s_r = fabs(st[q + 1]); /* fmax's, no call */
        const double s_max = ct[q] > 0 && ct[q + 1] > 0 ? (s_l > s_r ? s_l : s_r) : 1;
        sT[q] = rho_lo > 0 ? dt_dz_of * s_max / rho_lo * (1 + 1e-12) : INFINITY;
        /* its depth rho cos(psi) at least rho_lo times the smaller of the rays' cosines
         * (cos is concave there); 0 (nothing proven) where a ray is not below the
         * horizontal or rho_lo <= 0 */
        const double c_min = ct[q] < ct[q + 1] ? ct[q] : ct[q + 1];
        sZ[q] = rho_lo > 0 && c_min > 0 ? rho_lo * c_min * (1 - 1e-12) : 0;
        Pl = Pr;
    }
}

/* The vertex rows: every ground vertex below the centre's height, within
 * R0 of the centre and inside the tread segment's angle, as a row on the sector of elements it
 * lies in (or on one element, if it lies on its ray), into c->vrows; their number in
 * c->n_vrows.
 *
 * The proving scan at an x (height z_r) proves, for each vertex whose row it drops between
 * two elements (below the chord of the rays' penetrations times the tread's bow, the test
 * below), that the test drops it at every height z the later evaluations at that x take
 * while these bounds hold (docs/models.md section 4.8, The later heights at one x): with
 * Delta = z - z_r and |Delta| <= seen_reach dz_r, h = R0 - rho is concave in z (rho =
 * sqrt(dx^2 + dz^2) is
 * convex) with dh/dz = -dz / rho in [-1, -dz / R0], so h <= h_r - Delta dz_r / R0 if
 * Delta > 0 and h <= h_r - Delta if not; the vertex's angle psi = atan2(dx, dz) moves by at
 * most |Delta| |dx| / rho_min^2 (rho_min >= (1 - seen_reach) rho_r), and within a sector
 * dt/dpsi = sin(dtheta) / (sin(psi - theta_i) + sin(theta_(i+1) - psi))^2 <= 1 / sin(dtheta),
 * so t moves by at most dt = |Delta| dt_dz; while [t_r - dt, t_r + dt] stays inside (t_snap,
 * 1 - t_snap) the vertex stays between the elements of sector i. There the chord at z,
 * A + t D (A = P_l - slack, D = P_r - P_l, the rays' penetrations at z), is at least the
 * chord at z_r at t_r plus mu, the least of its change over t in [0, 1], less |D| dt, and
 * the bow 1 + ab_lo t (1 - t) at least its value at t_r less ab_lo dt; their product, the
 * test's threshold, is then at least the threshold at z_r less Lambda (mu times the bow,
 * which lies between 1 and B = 1 + ab_lo / 4) and less dt K (K = |D| B + ab_lo times the
 * largest chord). Where the margin at z_r (threshold less h) covers h's rise, Lambda and
 * dt K, the test drops the vertex at z. What a proof keeps of its vertex is the margin,
 * min(t_r, 1 - t_r) and the sector: the chord at t_r is at least the sector's least chord
 * at z_r, and dz_r at least rho_lo times the smaller cosine of the sector's rays (sZ), so
 * the tests on the chord and the depth, and the depth's share of h's fall, are the
 * sector's. Every bound carries an allowance (tol) far above the
 * rounding of what it stands for, so the rows, and their order, are the full scan's bit for
 * bit; a vertex not proven is computed as before. On a road at 1 mm nearly every vertex
 * under the patch is dropped by the bow's margin, and the evaluations after the first at an
 * x move the centre by much less than that margin. */
static int vertex_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                       const tirenv_profile *p, double x, double z, size_t a, size_t b,
                       const double d[])
{
    const double *X = p->x, *Z = p->z, R0 = T->R0, R0sq = R0 * R0;
    const double *st = T->sin_t, *ct = T->cos_t;
    const size_t n = p->n, N = T->N;
    /* A vertex within R0 of the centre lies within the angles of the elements that can reach
     * the ground, [a, b], and one more either side (section 4.8): X - x = rho sin(psi). */
    const size_t a1 = a > 0 ? a - 1 : 0, b1 = b + 1 < N ? b + 1 : N - 1;
    const double lo = x + fmin(0, R0 * (ct[a1] >= 0 ? st[a1] : -1));
    const double hi = x + fmax(0, R0 * (ct[b1] >= 0 ? st[b1] : 1));
    size_t j0 = tirenv_profile__segment_at(p, lo);
    while (j0 < n && X[j0] < lo)
        ++j0;
    /* The end of the run from a search, not a walk over it: a road at 1 mm has hundreds of
     * vertices under the patch. */
    size_t j_end = j0;
    if (j0 < n && X[j0] <= hi) {
        j_end = tirenv_profile__segment_near(p, j0, hi);
        j_end = j_end < j0 ? j0 : j_end;
        while (j_end < n && X[j_end] <= hi)
            ++j_end;
    }
    if (reserve_vrows(c, j_end - j0))
        return TIRENV_ENOMEM;
    /* Where the vertices outnumber the sectors (a road sampled finely) the scan guesses their
     * sectors (scan_prove), and the scans at one x after the first scans_unproven there use
     * proofs, made by the scan that follows those, where they cover its run; elsewhere the
     * scan walks as it did (the same rows every way). The proofs cost a few sectors' work
     * and a pass over the vertices to make, and pay only over the scans after: most x
     * see one or two scans (the later evaluations there take the tangent's update). */
    const int same_x = c->seen_serial == p->serial && c->seen_x == x;
    if (!same_x) {
        c->seen_serial = p->serial;
        c->seen_x = x;
        c->seen_scans = 0;
        c->seen_made = 0; /* no proofs at this x, unless made below */
    }
    const int guess = j_end - j0 >= 2 * (b1 - a1 + 1) && !c->scan_plain;
    const int reuse = c->seen_made && c->seen_j0 <= j0 && j_end <= c->seen_j0 + c->seen_n;
    const int prove = guess && !c->seen_made &&
                      (c->scan_eager || c->seen_scans >= scans_unproven);
    c->seen_scans += c->seen_scans < scans_unproven;
    if (guess && !reuse && reserve_seen(c, j_end - j0, N))
        return TIRENV_ENOMEM;
    if (prove) {
        c->seen_z = z;
        c->seen_j0 = j0;
        c->seen_n = j_end - j0;
    }
    tirenv_springs__cc_seen *const seen = c->seen;
    /* the vertices to compute: todo[0 .. n_todo - 1] when reusing (j0 .. j_end - 1 but for
     * those proven dropped at z, *skipped), else j0 .. j_end - 1 */
    size_t skipped = 0;
    size_t *const todo = c->seen_todo;
    size_t n_todo = j_end - j0;
    if (reuse)
        n_todo = seen_todo(c, T, p, z, a, b, d, j0, j_end, todo, &skipped);

    const double ab_lo = T->ab_lo, tau_dev = T->tau_dev;
    const scan_ctx C = {.X = X, .Z = Z, .st = st, .ct = ct, .d = d, .x = x, .z = z, .R0 = R0,
                        .R0sq = R0sq, .ab_lo = ab_lo, .tau_dev = tau_dev, .N = N, .a = a,
                        .b = b};
    /* i: a walk from the last vertex's sector is O(1) on a road; the first from where the
     * last plain scan's first walk ended (a few sectors from where this one's ends, where
     * the walk from i0 crossed half the span over a cleat) */
    scan_state S = {.i = c->scan_i < N ? c->scan_i : T->i0, .ci = SIZE_MAX, .out = c->vrows};
    size_t seen_lo = N, seen_hi = 0, missed = 0;
    if (reuse)
        scan_list(&C, &S, todo, seen, c->seen_j0, n_todo);
    else if (guess)
        S.out = scan_prove(&C, a1, b1, c->scan_blind, prove, c->seen_sec + 4 * N, j0, n_todo,
                           seen, S.out, &seen_lo, &seen_hi, &missed);
    else
        scan_all(&C, &S, j0, j_end, &c->scan_i);
    tirenv_springs__cc_row *const out = S.out; /* NULL while nothing was reserved */
    c->n_vrows = out ? (size_t)(out - c->vrows) : 0;
    c->scan_skipped = skipped;
    c->scan_missed = missed;
    if (prove) {
        c->seen_lo = seen_lo;
        c->seen_hi = seen_hi;
        seen_sectors(c, T, p, a, b, d);
        c->seen_made = 1;
    }
    return TIRENV_OK;
}

/* The weights of a row between elements at its t (dga_dz holding dt/dz). */
static void row_weights(const tirenv_springs__cc_tire *T, tirenv_springs__cc_row *r)
{
    const double dt_dz = r->dga_dz;
    double da, db;
    tirenv_springs__cc_weights(T, r->t, &r->ga, &r->gb, &da, &db);
    r->tau = r->gb / (r->ga + r->gb);
    r->dga_dz = da * dt_dz;
    r->dgb_dz = db * dt_dz;
    /* The tips carry (a + b) lambda to the hub, which deflects them by lambda c0 (a^2 + b^2 +
     * 2 a b cos(gamma)) = lambda c0 on an endless free chain: in series with them the row's
     * own (a + b - 1) c0 (>= 0: a + b >= 1) makes the hub's stiffness to a lone point load
     * 1 / c0 at every t, as on an element (section 4.8). */
    r->cmp = tirenv_springs__cc_compliance(T, r->ga, r->gb);
    r->dcmp_dz = r->cmp > 0 ? T->c0 * (da + db) * dt_dz : 0;
}

/* Rows ordered by sector, then t, then h: insertion sort (the walk gives nearly that order). */
static void sort_rows(tirenv_springs__cc_row *r, size_t n)
{
    for (size_t k = 1; k < n; ++k) {
        const tirenv_springs__cc_row v = r[k];
        size_t m = k;
        while (m > 0 && (r[m - 1].i > v.i ||
                         (r[m - 1].i == v.i && (r[m - 1].t > v.t ||
                                                (r[m - 1].t == v.t && r[m - 1].h > v.h))))) {
            r[m] = r[m - 1];
            --m;
        }
        r[m] = v;
    }
}

/* Upper hull of the sector's points (0, P_l), the rows' (tau, h / (ga + gb)) for the vertex
 * rows [first, first + m) and (1, P_r): a row reads (1 - tau) w_i + tau w_j >= h / (ga + gb), so
 * where no row of the sector works (reaction 0) only rows on the hull can bind (a line over
 * [0, 1] above the hull's vertices is above every point), and keeping only them keeps the KKT
 * systems nonsingular. A working row's tread stands its own compliance times its reaction
 * below its h, so a row under the hull may still bind there: the solve checks the rows
 * dropped here against its w and has them kept (c->vforce, tirenv_springs__cc_add_dropped).
 * The kept rows, and the forced ones in their order of tau, are appended at c->rows[out];
 * returns the new end. stack has room for m + 2. */
static size_t hull_only(tirenv_springs__cc *c, size_t first, size_t m, double P_l, double P_r,
                        size_t *stack, size_t out)
{
    const tirenv_springs__cc_row *r = c->vrows + first;
    size_t top = 0;
    /* point k: 0 the left end, 1..m the rows, m + 1 the right end */
#define PT_T(k) ((k) == 0 ? 0.0 : (k) == m + 1 ? 1.0 : r[(k) - 1].tau)
#define PT_H(k) ((k) == 0 ? P_l : (k) == m + 1 ? P_r : r[(k) - 1].h / (r[(k) - 1].ga + r[(k) - 1].gb))
    for (size_t k = 0; k <= m + 1; ++k) {
        while (top >= 2) {
            const size_t o = stack[top - 2], a = stack[top - 1];
            const double cross = (PT_T(a) - PT_T(o)) * (PT_H(k) - PT_H(o)) -
                                 (PT_H(a) - PT_H(o)) * (PT_T(k) - PT_T(o));
            if (cross < 0)
                break; /* a strictly above the line o-k: a right turn */
            --top;
        }
        stack[top++] = k;
    }
    /* Of two hull vertices within t_snap of each other in tau only the higher is kept (a
     * vertex that near an end was made the element's own row: tau < t_snap needs t < tau). */
    size_t kept = 0;
    double tau_prev = 0, y_prev = 0;
    for (size_t q = 1; q + 1 < top; ++q) {
        const size_t k = stack[q];
        const double y = PT_H(k);
        if (kept > 0 && PT_T(k) - tau_prev < t_snap) {
            if (y > y_prev) {
                c->rows[out - 1] = r[k - 1];
                tau_prev = PT_T(k);
                y_prev = y;
            }
            continue;
        }
        c->rows[out++] = r[k - 1];
        ++kept;
        tau_prev = PT_T(k);
        y_prev = y;
    }
#undef PT_T
#undef PT_H
    if (c->n_forced == 0)
        return out;
    /* The rows the last solve found violated, merged into the hull's rows by tau (the rows
     * are in order of t, hence of tau): each is a row of its own, whatever its neighbours. */
    const unsigned char *force = c->vforce + first;
    size_t n_force = 0;
    for (size_t q = 0; q < m; ++q)
        n_force += force[q] != 0;
    if (n_force == 0)
        return out;
    tirenv_springs__cc_row *hull = c->rows + (out - kept);
    /* the hull's rows move up by n_force from the end, the forced ones fill in */
    size_t src = kept, dst = kept + n_force;
    for (size_t q = m; q-- > 0;) {
        if (!force[q])
            continue;
        while (src > 0 && hull[src - 1].tau > r[q].tau)
            hull[--dst] = hull[--src];
        hull[--dst] = r[q];
    }
    return out + n_force;
}

/* hull_only, and the keys of the rows it appended. */
static size_t hull_rows(tirenv_springs__cc *c, size_t first, size_t m, double P_l, double P_r,
                        size_t *stack, size_t out)
{
    const size_t start = out;
    out = hull_only(c, first, m, P_l, P_r, stack, out);
    for (size_t q = start; q < out; ++q)
        c->keys[q] = (tirenv_springs__cc_key){c->rows[q].id, c->rows[q].i + c->rows[q].j};
    return out;
}

/* Element e's own row at R[out] (its pin: the vertex row pin_src[e] of V, or its ray's row)
 * and its key if it has one (pin_h[e] > 0), and pin_row[e] (SIZE_MAX: none); returns the new
 * end. */
static inline size_t put_pin(const double pin_h[], const size_t pin_src[], size_t pin_row[],
                             const tirenv_springs__cc_row V[], tirenv_springs__cc_row R[],
                             tirenv_springs__cc_key keys[], size_t e, size_t out)
{
    if (!(pin_h[e] > 0)) {
        pin_row[e] = SIZE_MAX;
        return out;
    }
    const size_t src = pin_src[e];
    pin_row[e] = out;
    if (src != SIZE_MAX) {
        R[out] = V[src];
        keys[out] = (tirenv_springs__cc_key){V[src].id, 2 * e};
        return out + 1;
    }
    /* A ray's row. A row laid out here before with its id is that row already, all but its
     * h (nothing writes the rows but the layout; reserve_rows gives new ones id 0). */
    const long id = -1 - (long)e;
    if (R[out].id == id)
        R[out].h = pin_h[e];
    else
        R[out] = (tirenv_springs__cc_row){.i = e, .j = e, .t = 0, .tau = 0, .ga = 1, .gb = 0,
                                          .h = pin_h[e], .dga_dz = 0, .dgb_dz = 0,
                                          .dh_dz = NAN, .cmp = 0, .dcmp_dz = 0, .id = id};
    keys[out] = (tirenv_springs__cc_key){id, 2 * e};
    return out + 1;
}

/* Lays the rows out element by element over [lay_lo, lay_hi]: each element's own row (its
 * pin), then its sector's rows kept. The vertex rows that provably cannot bind are dropped,
 * the others' weights computed and recorded per sector (cand_first, cand_count; the
 * sectors that have some in hull_sec) for tirenv_springs__cc_add_dropped. Sets the span f0,
 * f1. */
static void lay_out(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T)
{
    const size_t lo = c->lay_lo, hi = c->lay_hi, nv = c->n_vrows;
    tirenv_springs__cc_row *R = c->rows, *V = c->vrows;
    /* The workspace's arrays in locals: the rows written below could alias them. */
    const double *pin_h = c->pin_h;
    const size_t *pin_src = c->pin_src;
    size_t *pin_row = c->pin_row, *sec_first = c->sec_first, *sec_count = c->sec_count;
    size_t *cand_first = c->cand_first, *cand_count = c->cand_count, *hull_sec = c->hull_sec;
    tirenv_springs__cc_key *keys = c->keys;
    size_t out = 0, k = 0, f0 = SIZE_MAX, f1 = 0, n_hull = 0;
    size_t *stack = c->pos;
    for (size_t e = lo; e <= hi; ++e) {
        if (pin_h[e] > 0) { /* e ascends: the first e to set f0 is the least */
            out = put_pin(pin_h, pin_src, pin_row, V, R, keys, e, out);
            if (f0 == SIZE_MAX)
                f0 = e;
            f1 = e;
        } else {
            pin_row[e] = SIZE_MAX;
        }
        if (!(k < nv && V[k].i <= e)) /* no vertex row on sector e: nearly every one */
            continue;
        while (k < nv && V[k].i < e)
            ++k;
        size_t first = k, m = 0;
        while (k < nv && V[k].i == e) {
            if (V[k].t > 0) {
                if (m == 0)
                    first = k;
                ++m;
            }
            ++k;
        }
        if (m > 0 && e + 1 <= hi) {
            const double P_r = pin_h[e + 1] > 0 ? pin_h[e + 1] : 0;
            const double P_l = pin_h[e] > 0 ? pin_h[e] : 0;
            /* A row lies below the hull if h / (ga + gb) is at most the chord between the
             * ends at its tau: with ga + gb >= 1 + ab_lo t (1 - t) and |tau - t| <=
             * tau_dev, if h / (1 + ab_lo t (1 - t)) <= (1 - t) P_l + t P_r - |P_r - P_l|
             * tau_dev. Such rows (nearly every vertex of a smooth road: the tread bows out
             * between its tips) are dropped before their weights are computed: the
             * elements' own rows (no compliance) hold the tread above them. */
            const double slack_tau = fabs(P_r - P_l) * T->tau_dev;
            size_t kept = 0;
            for (size_t q = first; q < first + m; ++q) {
                const double t = V[q].t;
                const double chord = (1 - t) * P_l + t * P_r - slack_tau;
                if (V[q].h > chord * (1 + T->ab_lo * t * (1 - t))) {
                    V[first + kept] = V[q];
                    row_weights(T, &V[first + kept]);
                    ++kept;
                }
            }
            if (kept > 0) { /* a sector with rows (none, if the hull keeps none of them) */
                cand_first[e] = first;
                cand_count[e] = kept;
                hull_sec[n_hull++] = e;
                sec_first[e] = out;
                out = hull_rows(c, first, kept, P_l, P_r, stack, out);
                sec_count[e] = out - sec_first[e];
                if (sec_count[e] > 0) {
                    if (f0 == SIZE_MAX)
                        f0 = e;
                    f1 = e + 1;
                }
            }
        }
    }
    c->n_hull_sec = n_hull;
    c->n_rows = out;
    c->f0 = f0;
    c->f1 = f1;
    if (f0 == SIZE_MAX) {
        c->f0 = 1;
        c->f1 = 0;
    }
}

/* Lays the rows out again as lay_out did, the hulls taken from the candidates it recorded
 * and the rows forced since kept with them (tirenv_springs__cc_add_dropped). The span stays:
 * a forced row lies in a sector that had rows. */
static void lay_out_again(tirenv_springs__cc *c)
{
    const size_t lo = c->lay_lo, hi = c->lay_hi;
    tirenv_springs__cc_row *R = c->rows, *V = c->vrows;
    const double *pin_h = c->pin_h;
    const size_t *pin_src = c->pin_src;
    size_t *pin_row = c->pin_row, *sec_first = c->sec_first, *sec_count = c->sec_count;
    tirenv_springs__cc_key *keys = c->keys;
    size_t out = 0, q = 0;
    for (size_t e = lo; e <= hi; ++e) {
        out = put_pin(pin_h, pin_src, pin_row, V, R, keys, e, out);
        if (q < c->n_hull_sec && c->hull_sec[q] == e) {
            ++q;
            sec_first[e] = out;
            out = hull_rows(c, c->cand_first[e], c->cand_count[e], pin_h[e] > 0 ? pin_h[e] : 0,
                            pin_h[e + 1] > 0 ? pin_h[e + 1] : 0, c->pos, out);
            sec_count[e] = out - sec_first[e];
        }
    }
    c->n_rows = out;
}

/* The rows of the problem at (x, z): vertex rows and the rays' pins, reduced to each sector's
 * upper hull, laid out element by element; sets f0, f1. */
static int build_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                      const tirenv_profile *p, double x, double z, size_t a, size_t b,
                      const double d[])
{
    const size_t N = T->N;
    c->n_rows = 0;
    c->n_hull_sec = 0;
    if (vertex_rows(c, T, p, x, z, a <= b ? a : 0, a <= b ? b : N - 1, d))
        return TIRENV_ENOMEM;
    /* the laid-out rows: at most a pin per element and the vertex rows kept; pos, the
     * hulls' stack, needs nv + 2 */
    const size_t nv = c->n_vrows;
    if (reserve_rows(c, nv + N + 2, N))
        return TIRENV_ENOMEM;
    tirenv_springs__cc_row *V = c->vrows;
    sort_rows(V, nv);
    /* The elements any row can touch: the rays' that meet the ground, the vertices'. */
    size_t lo = N, hi = 0;
    for (size_t e = a; a <= b && e <= b; ++e)
        if (d[e] > 0) {
            lo = e;
            break;
        }
    for (size_t e = b + 1; a <= b && e-- > lo;)
        if (d[e] > 0) {
            hi = e;
            break;
        }
    if (nv > 0) {
        lo = V[0].i < lo ? V[0].i : lo;
        const size_t top = V[nv - 1].t > 0 ? V[nv - 1].i + 1 : V[nv - 1].i;
        hi = top > hi ? top : hi;
    }
    if (lo > hi) {
        c->f0 = 1;
        c->f1 = 0;
        return TIRENV_OK;
    }
    /* Pins: the ray's penetration, or a vertex on the ray standing higher. pin_src holds
     * the vertex row (SIZE_MAX: the ray) for the layout. */
    double *pin_h = c->pin_h;
    size_t *pin_src = c->pin_src;
    /* the rays' penetrations on [a, b] (within [lo, hi]: lo <= the first ray with d > 0 and
     * hi >= the last), 0 beyond */
    const size_t ra = a > lo ? a : lo, rb = b < hi ? b : hi;
    memset(pin_src + lo, 0xff, (hi - lo + 1) * sizeof *pin_src); /* SIZE_MAX: all ones */
    /* one pass over pin_h in three pieces: 0, the rays' d (> 0 or +0: what max(d, 0)
     * gives, copied), 0 */
    const size_t r0 = a <= b && ra <= rb ? ra : hi + 1, r1 = a <= b && ra <= rb ? rb : hi;
    memset(pin_h + lo, 0, (r0 - lo) * sizeof *pin_h);
    if (r0 <= r1)
        memcpy(pin_h + r0, d + r0, (r1 - r0 + 1) * sizeof *pin_h);
    memset(pin_h + r1 + 1, 0, (hi - r1) * sizeof *pin_h);
    for (size_t k = 0; k < nv; ++k)
        if (V[k].t == 0 && V[k].h > pin_h[V[k].i]) {
            pin_h[V[k].i] = V[k].h;
            pin_src[V[k].i] = k;
        }
    c->n_forced = 0; /* vforce is read only while some are (tirenv_springs__cc_add_dropped) */
    c->lay_lo = lo;
    c->lay_hi = hi;
    lay_out(c, T);
    return TIRENV_OK;
}

int tirenv_springs__cc_vertex_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                                   const tirenv_profile *p, double x, double z, size_t a,
                                   size_t b, const double d[])
{
    const size_t N = T->N;
    return vertex_rows(c, T, p, x, z, a <= b ? a : 0, a <= b ? b : N - 1, d);
}

int tirenv_springs__cc_rows(tirenv_springs__cc *c, const tirenv_springs__cc_tire *T,
                            const tirenv_profile *p, double x, double z, size_t a, size_t b,
                            const double d[], tirenv_diag *diag)
{
    if (build_rows(c, T, p, x, z, a, b, d))
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory for the contact "
                            "rows of the springs model");
    return TIRENV_OK;
}

int tirenv_springs__cc_add_dropped(tirenv_springs__cc *c, const double w[], double tol)
{
    const tirenv_springs__cc_row *R = c->rows, *V = c->vrows;
    size_t added = 0;
    for (size_t s = 0; s < c->n_hull_sec; ++s) {
        const size_t e = c->hull_sec[s], r0 = c->sec_first[e], nr = c->sec_count[e];
        /* Only a row with a reaction lets the tread under the hull (its own compliance):
         * where none works, the hull's rows hold the tread above every row dropped. */
        int works = 0;
        for (size_t r = r0; r < r0 + nr && !works; ++r)
            works = c->in_w[r] && c->lambda[r] > 0;
        if (!works)
            continue;
        for (size_t q = c->cand_first[e], n = q + c->cand_count[e]; q < n; ++q) {
            if (c->n_forced > 0 && c->vforce[q])
                continue; /* a row already */
            int kept = 0;
            for (size_t r = r0; r < r0 + nr && !kept; ++r)
                kept = R[r].id == V[q].id;
            if (kept || !(V[q].ga * w[V[q].i] + V[q].gb * w[V[q].j] - V[q].h < -tol))
                continue;
            if (c->n_forced == 0 && added == 0) /* the first of this evaluation */
                memset(c->vforce, 0, c->n_vrows);
            c->vforce[q] = 1;
            ++added;
        }
    }
    if (added == 0)
        return 0;
    c->n_forced += added;
    lay_out_again(c);
    return 1;
}
