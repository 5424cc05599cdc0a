/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the ring's shear-coupled tread (docs/models.md section 5.3): its state, which the
 * equilibrium (ring_shear.c), its storage (ring_tread.c), its sub-windows (ring_subwin.c), its
 * warm start at a new x (ring_warm.c), the condensation of the window's exterior (ring_exterior.c), the knots
 * (ring_knots.c) and the tests' hooks (ring_shear_probe.c) share, and what each calls of the
 * others. */
#ifndef TIRENV_RING_SHEAR_IMPL_H
#define TIRENV_RING_SHEAR_IMPL_H

#include <stddef.h>
#include "model/ring_impl.h"
#include "model/ring_tband.h"

enum { NB = 6, SPAN = 4 };

/* What a deferred dF_z/dz needs of its evaluation (tirenv_ring__shear_slope): the nodes a .. b
 * and points k0 .. k1 solved, whether a sub-window (sub), and the centre (m). */
typedef struct {
    size_t a, b, k0, k1;
    int sub;
    double z, x_c;
} deferred_window;

struct tirenv_ring_tread {
    size_t M;
    double s[3];        /* the belt's stencil, N/m */
    double k_sh;        /* shear between neighbouring nodes, k_s / (R dtheta), N/m */
    double k_g;         /* contact layer per unit belt length, N/m^2 */
    double kap0;        /* the tread's compression k_c R dtheta of a node without lugs, N/m */
    int lugs;           /* kap differs between nodes: the ends cached for one x, lo, n */
    double lug_x;       /* the centre's abscissa of the cached lugged ends (m) */
    size_t lug_lo, lug_n; /* their window; lug_n = 0: none cached */
    double *kap;        /* per node (global): compression stiffness k_c R dtheta, N/m */
    double *u;          /* per node (global): the tread surface's displacement, m; then,
                         * contiguous with it (the warm start a state saves), dw and du */
    double *dw, *du;    /* per node (global): dw/dz, du/dz at the last evaluation's
                         * equilibrium (0 outside its window or without dF_z/dz) */
    double *pred;       /* 3: that evaluation's z (m), x (m), and 1 if dw, du hold */
    double *dn;         /* M: per node dn_a .. dn_b of the last answer's contact, the ground's
                         * penetration d at the node's ray where it touched the tread surface
                         * (-INFINITY elsewhere), at abscissa dn_x and height dn_z (dn_ok 0:
                         * none; tirenv_ring__tread_new_x) */
    double *dn2, *ddn;  /* M each: this sampling's d and d(d)/dz at the nodes dn_a .. dn_b
                         * (warm_shift) */
    double dn_x, dn_z;
    size_t dn_a, dn_b;
    int dn_ok;
    double last_x, last_z; /* the last answer's centre (last_ok), m; with r->pts, r->k_first
                            * and r->k_last, which a state does not save, its contact's ground
                            * (tirenv_ring__tread_new_x) */
    int last_ok;
    unsigned skip;      /* positions warm_shift leaves out: its last pass moved nothing */
    double *span;       /* 4, after pred (a state saves them): 1 if the last answer had a
                         * contact, the nodes of its first and last point's intervals, and
                         * the centre's abscissa (m) (warm_span): the nodes dn_a, dn_b and
                         * last_x that tirenv_ring__tread_new_x takes, kept apart from them
                         * because a state saves these doubles and not the points */
    double (*end)[NB][NB]; /* per window length: the exterior's correction, N/m */
    unsigned char *have;
    tband ext, win;     /* the exterior's factor (exterior_factor); the window's (band_refactor) */
    int ext_all;        /* ext holds the factor of the longest exterior, M - 1 nodes, and ey
                         * (2 M x 4, by rows) its forward substitutions U^-1 e_a of the first
                         * three unit vectors, the fourth of each row +0 */
    double *ey;
    tband as, ap;       /* the window's system as assemble writes it, and the one before it,
                         * whose factor win holds if ap_ok (band_refactor) */
    int ap_ok;
    double *ck;         /* band_factor_from's accumulators of win, every CKS-th column */
    double *col;        /* 2 M: a right-hand side of the exterior */
    double *x, *xn, *xt, *g; /* 2 M + cap_k each: iterate, Newton point, trial, gradient */
    double *kp;         /* 2 M + cap_k: the driver's workspace */
    /* The knots of the last solve (vertex cuts inside node intervals), m of them, in angle
     * order; per point of r->pts its knot (-1: at a node). */
    size_t m, cap_k;
    size_t *kj;         /* the knot's interval, as its first node's window index */
    double *kd, *ko;    /* the knots' own stiffness: diagonal, and to the next knot (0 if the
                         * next is in another interval), N/m */
    double *dd, *doff;  /* with the points in contact: the knots' block and its Cholesky factor */
    double *c0, *c1;    /* with the points in contact: the coupling of knot to u_j, u_j+1 */
    double *z0, *z1;    /* workspace: D^-1 c0, D^-1 c1 */
    double *kphi, *kdphi; /* the knots' angles (rad) and their d/dz (rad/m): they move with
                           * the centre, as their vertices do */
    double *lc, *la, *lb; /* the line search's terms (line_cb), cap_l each */
    size_t cap_l;
    /* The sub-window of the nodes in contact (solve_shear): per length n' of it, the six
     * columns of the exterior's inverse K_EE^-1 at its six coupled unknowns (NB x 2 (M - n')
     * each, NULL until that length is first a sub-window's), which give the free nodes' (w, u)
     * from the sub-window's ends; the whole window's (w, u) and their d/dz (2 M each). */
    double **cols;
    double *xw, *dxw;
    size_t n_sub;       /* evaluations answered on a sub-window (the tests count them) */
    int whole;          /* nonzero: always the whole window (the tests' reference) */
    int no_peel;        /* nonzero: Newton without peel_cb (the tests' reference) */
    size_t n_peel;      /* points peel_cb freed so far (the tests count them) */
    int poison;         /* nonzero: NaN in what no solve wrote yet (tirenv_ring__tread_poison) */
    /* The softening carcass (CARCASS_SOFTENING_DEFLECTION > 0, docs/models.md 5.1): its
     * parameters, and the window's w at the iterate whose states were set last (the Newton
     * system is linearised there). */
    int soft;
    tirenv_ring_carcass law;
    double *wc;         /* M */
    size_t n_newton;    /* Newton steps so far (the tests and the report count them) */
    /* dF_z/dz on request (tirenv_ring__shear_slope): an evaluation asked to defer it keeps
     * what its slope needs, the last solve_on's window and whether its Newton factorised
     * the final states, until the next evaluation. */
    int defer, deferred, fin_factored;
    /* The right-hand side factor_cb left for solve_cb (NULL: none), knots eliminated and, if
     * fwd_fused, forward-substituted with the factorisation. */
    double *fwd;
    int fwd_fused;
    const double (*fin_Q)[NB];
    deferred_window dfr;
};

/* The window's ends in the interleaved unknowns. */
static inline void end_index(size_t n, size_t b[NB])
{
    b[0] = 0, b[1] = 1, b[2] = 2, b[3] = 2 * n - 4, b[4] = 2 * n - 2, b[5] = 2 * n - 1;
}

/* How compute_end solves the columns: by the processor (ext_columns_avx2 where it has AVX2),
 * in pairs of lanes in the baseline build, or one at a time (ext_columns_each); the last two
 * the tests' references. */
enum { EXT_AUTO, EXT_BASE, EXT_EACH };

/* The exterior (ring_exterior.c). */
/* The belt's and the tread's stiffness of the open arc of count nodes from node j0 (mod M),
 * (w, u) interleaved, added into A. */
void tirenv_ring__add_arc(tband *A, const tirenv_ring_tread *T, size_t j0, size_t count);
/* The exterior's coupled unknowns in its Ne interleaved unknowns. */
void tirenv_ring__ext_index(size_t Ne, size_t e[NB]);
/* The end correction Q of a window of n nodes from lo, and (cols not NULL) the six columns of
 * K_EE^-1 at the exterior's coupled unknowns, Ne each; how: EXT_AUTO, or a tests' reference. */
void tirenv_ring__compute_end_by(tirenv_ring_tread *T, size_t lo, size_t n, double Q[NB][NB],
                                 double *cols, int how);
/* The end correction of r's window at the centre's x_c, kept per window length. */
const double (*tirenv_ring__window_end(tirenv_ring *r, double x_c))[NB];
/* The exterior's columns for a sub-window of n nodes from lo (kept); NULL if out of memory. */
const double *tirenv_ring__sub_cols(tirenv_ring_tread *T, size_t lo, size_t n);
/* The free nodes' (w, u) of r's window outside the sub-window a .. b, into v, from the
 * sub-window's there. */
void tirenv_ring__fill_free(const tirenv_ring *r, size_t a, size_t b, double v[]);
/* The largest w (m) outside the sub-window a .. b, and outside the whole window, of the
 * window's xw; *j_out its node. */
double tirenv_ring__outside_sub(const tirenv_ring *r, size_t a, size_t b, const double xw[],
                                size_t *j_out);
double tirenv_ring__outside_whole(tirenv_ring *r, const double xw[], size_t *j_out);

/* The knots (ring_knots.c). */
/* The knots of r's window's points: T->m, each point's knot, their intervals and stiffness.
 * Nonzero if out of memory. */
int tirenv_ring__find_knots(tirenv_ring *r);
/* The knots condensed out of the assembled system (T->as): nonzero if their block is not
 * positive definite. */
int tirenv_ring__condense_knots(tirenv_ring_tread *T);
/* The knots' right-hand side eliminated from the band's rows of x (2 n + m entries). */
void tirenv_ring__knots_eliminate(tirenv_ring *r, double x[]);
/* The full system's solve after that: the band's (its forward substitution done with the
 * factorisation if fused), then the knots'. */
void tirenv_ring__solve_after(tirenv_ring *r, double x[], int fused);
/* The full system's solve, x (2 n + m entries) overwritten. */
void tirenv_ring__solve_full(tirenv_ring *r, double x[]);
/* rhs -= (dK_knots/dz) a at the solution x: the knots' stiffness moving with them. */
void tirenv_ring__knots_moving(const tirenv_ring *r, const double x[], double rhs[]);

/* The warm start at a new abscissa (ring_warm.c). */
/* The last answer's contact guides an evaluation's warm start within WARM_DX (m) of its
 * abscissa: its nodes, which the first sub-window holds (warm_span), and its ground, along
 * which the tread surface moves (warm_shift). Inside the patch the tread surface lies within
 * the contact layer's compression, some 1e-7 m, of the ground, so wherever the ground moved
 * away from it with x (a road's slope over the step: 1e-5 m and more) the warm start's points
 * read as free or deep in. The nodes in contact move by a node spacing over some 3 mm of
 * travel, so the last contact's nodes are nearly this one's. */
static const double WARM_DX = 2e-3;
/* The shift of each node of the last contact that lies in r's window (m), applied to the
 * warm start xw at centre (x_c, z) (m), after tirenv_ring__tread_new_x. */
void tirenv_ring__warm_shift(tirenv_ring *r, double x_c, double z, double xw[]);

/* The sub-windows of the nodes in contact (ring_subwin.c): SUB_PAD nodes beyond the contact
 * on each side, ends at multiples of SUB_QUANT, at least SUB_MIN nodes and SUB_MIN_FREE free
 * ones left; SUB_TRIES sub-windows at most before the whole window. */
enum { SUB_PAD = 2, SUB_QUANT = 8, SUB_MIN_FREE = 16, SUB_MIN = 8, SUB_TRIES = 3 };
/* The first and the last point of pts[k0 .. k1) in contact, by their states (warm: as the
 * window's xw leaves them); 0 if none. */
int tirenv_ring__contact_span(const tirenv_ring *r, size_t k0, size_t k1, const double xw[],
                              int warm, size_t *kf, size_t *kl);
/* The sub-window a .. b for the points pts[kf .. kl] and the nodes beyond[0] .. beyond[1],
 * and the points pts[k0 .. k1) of its intervals; 0 where it would leave too few free nodes. */
int tirenv_ring__sub_window(const tirenv_ring *r, size_t kf, size_t kl, const size_t beyond[2],
                            size_t *a, size_t *b, size_t *k0, size_t *k1);
/* The window nodes beyond the softening carcass's linear range in xw, into beyond (beyond[0] >
 * beyond[1]: none); returns beyond. */
const size_t *tirenv_ring__beyond_span(const tirenv_ring *r, const double xw[],
                                       size_t beyond[2]);
/* Those and, within WARM_DX of the last answer's centre, that answer's contact nodes (m). */
const size_t *tirenv_ring__warm_span(const tirenv_ring *r, double x_c, const double xw[],
                                     size_t beyond[2]);
/* No point of the window's outside pts[k0 .. k1) touches at xw; those found clear written as
 * free points of the answer. */
int tirenv_ring__free_clear(tirenv_ring *r, size_t k0, size_t k1, const double xw[]);

/* The tread's storage and its window's assembly (ring_tread.c, ring_shear.c). */
/* Room for m knots (the driver's vectors, 2 M + m each, and the knots' arrays); nonzero if out
 * of memory. */
int tirenv_ring__reserve_knots(tirenv_ring_tread *T, size_t m);
/* NaN in the driver's vectors past the N + m unknowns and in the knots' arrays past the m
 * knots of the solve about to start (T->poison: the tests'). */
void tirenv_ring__poison_past(tirenv_ring_tread *T, size_t N, size_t m);
/* The window's arc of n nodes from lo as tirenv_ring__add_arc gives it on a zeroed matrix,
 * written into A (its tail's fresh columns left unset), and rhs's 2 n entries zeroed. */
void tirenv_ring__fill_window(tband *A, const tirenv_ring_tread *T, size_t lo, size_t n,
                              double rhs[]);

#endif
