/* SPDX-License-Identifier: Apache-2.0 */
/* Private: the ring reference tire's pieces (docs/models.md section 5), one file each: the belt
 * as a stiffness matrix condensed onto a window of nodes and the banded solver of its contact
 * system (ring_belt.c), the contact solve (ring_contact.c), rays and the public API
 * (ring.c). */
#ifndef TIRENV_RING_IMPL_H
#define TIRENV_RING_IMPL_H

#include <stddef.h>
#include <string.h>
#include "tirenv/ring.h"
#include "tirenv/tire.h"

/* The belt's stiffness K per node around the full circle of M nodes is the circulant
 * pentadiagonal matrix with K[j][j] = s[0], K[j][j+-1] = s[1], K[j][j+-2] = s[2] (N/m): the
 * finite-difference form of the belt energy (section 5), whose Fourier symbol is the mode
 * stiffness R dtheta [EI (sigma - 1)^2 / R^4 + T (sigma - 1) / R^2 + k_f]. Nodes outside a
 * window of contiguous nodes carry no load, so they condense out exactly: the window's
 * stiffness is K_WW - K_WE K_EE^-1 K_EW, which differs from K_WW only on the two nodes at
 * each end of the window (K is pentadiagonal). That correction depends on the window's length
 * alone (the ring is uniform); tirenv_ring__belt_alloc keeps a table of them, filled when a
 * length is first needed. */
typedef struct tirenv_ring_belt tirenv_ring_belt;

/* Equal bits (not ==, which equates 0 and -0): n doubles. The ring reuses work where its
 * inputs are the same bits as last time (ring_ground.c's points, ring_tband.c's factor). */
static inline int tirenv_ring__same_bits(const double *a, const double *b, size_t n)
{
    return memcmp(a, b, n * sizeof *a) == 0;
}

/* Curvatures the ring's step in z keeps per side (ring_root.c). */
#define TIRENV_RING_ROOT_KEEP 3

/* Equilibria the ring's start at a new x keeps (ring_root.c): the mean slope over the last
 * TIRENV_RING_START_KEEP - 1 steps. */
#define TIRENV_RING_START_KEEP 4

/* k_g / k_t: the contact layer between the ground and the shear-coupled tread's surface
 * (ring_shear.c, docs/models.md 5.3); the tests' closed forms use it too. */
#define TIRENV_RING_GROUND_LAYER 1e4

/* k_b / k_t: the belt and carcass under the tread, in compression (ring_smooth.c,
 * ring_shear.c, docs/models.md 5.3). */
#define TIRENV_RING_BELT_LAYER 1e3

/* The tread coupled in shear along the arc (ring_shear.c, docs/models.md section 5.3): its
 * constants, the exterior's condensation per window length, the banded system of the window's
 * belt and tread surface, and the tread surface's displacement per node. */
typedef struct tirenv_ring_tread tirenv_ring_tread;

/* NULL if out of memory. R: belt radius (m), dtheta = 2 pi / M (rad). The caller has checked
 * the parameters (tirenv_tire_check: K is positive definite). */
tirenv_ring_belt *tirenv_ring__belt_alloc(size_t M, double R, const tirenv_ring_params *par);
void tirenv_ring__belt_free(tirenv_ring_belt *b);

/* The pressure's share of the belt (docs/models.md section 5.1): gamma(alpha), the two
 * sidewalls' radial stiffness per unit pressure (dimensionless); the foundation k_c +
 * gamma p (N/m^2); the belt's tension energy c1 sum (w[j+1] - w[j])^2 + c0 sum w[j]^2 (N/m)
 * of the carcass's pretension and the air's follower load. */
double tirenv_ring__sidewall_gamma(double alpha);
double tirenv_ring__foundation(const tirenv_ring_params *par);
void tirenv_ring__tension(size_t M, double R, const tirenv_ring_params *par, double *c1,
                          double *c0);

/* Stencil s[0..2] of K (N/m). */
const double *tirenv_ring__belt_stencil(const tirenv_ring_belt *b);

/* The condensed window stiffness's end correction for a window of n >= 6 nodes (n <= M - 6):
 * q[0..3][0..3] (N/m) over the window nodes 0, 1, n-2, n-1, to be subtracted from K_WW. */
const double (*tirenv_ring__belt_end(tirenv_ring_belt *b, size_t n))[4];

/* A symmetric positive definite n x n matrix (n >= 6) that is pentadiagonal but for a coupling
 * of its first two rows with its last two, and its Cholesky factor A = L L^T in place of it.
 * Each row of the contact system is one window node (section 5): the condensed belt plus the
 * tread on the nodes in tread contact, or an identity row where the belt itself is held. */
typedef struct {
    size_t n;
    double *a0, *a1, *a2;  /* A[i][i], A[i][i+1], A[i][i+2] (N/m); then L[i][i], L[i+1][i],
                            * L[i+2][i] for the band rows i < n-2 */
    double c[2][2];        /* A[i][n-2+k] for i, k in {0, 1}, on top of the band */
    double *bm[2];         /* factor: L[n-2+k][i], i < n-2 (the last two rows) */
    double t[3];           /* factor: L[n-2][n-2], L[n-1][n-2], L[n-1][n-1] */
} tirenv_ring_band;

/* A's band: n nodes of the unloaded belt in a row, its stencil on every row but where it
 * would pass the last (the corner c untouched). */
void tirenv_ring__band_belt(tirenv_ring_band *A, const tirenv_ring_belt *b, size_t n);

/* Takes the belt's condensed ends q (tirenv_ring__belt_end, over rows 0, 1, n-2, n-1) off A's
 * band and sets the corner coupling c from them. */
void tirenv_ring__band_less_ends(tirenv_ring_band *A, const double (*q)[4]);

/* Factorises A in place; nonzero if A is not positive definite. O(n). */
int tirenv_ring__band_factor(tirenv_ring_band *A);

/* Solves A x = b with the factor, x overwriting b (n entries). O(n). */
void tirenv_ring__band_solve(const tirenv_ring_band *A, double b[]);

/* A node's state: which of its two complementarity pairs (ring_contact.c) are basic. FREE: no
 * force; TREAD: the tread carries kappa (d - w); with B_BASIC the belt is held at b - t_r, and
 * with T_BASIC too the tread carries kappa (d - w) of its force, without it none. */
enum { TIRENV_RING_FREE = 0, TIRENV_RING_T_BASIC = 1, TIRENV_RING_B_BASIC = 2 };

/* A quadrature point of the continuous contact (ring_ground.c, ring_smooth.c): an end of a
 * piece of the window along which the ground is one segment (or the ends of two pieces on one
 * ray, joined), in node interval j. Aligned to 64
 * bytes (128 in all on 64-bit targets; ring_ground.c allocates the array so): what the contact
 * solve's passes over the points read at every Newton step (their states, energy, line search
 * and system) lies in its first 64, one cache line a point; what an evaluation reads once (the
 * forces, dF_z/dz) in the rest. */
typedef struct {
    _Alignas(64) double d; /* penetration R0 - rho (m; -INFINITY: none) */
    double s;              /* place in the interval: the tread there is (1 - s) w_j + s w_j+1 */
    double omega;          /* weight: half its piece's angle, rad */
    double k_t;            /* tread stiffness there, N/m^2 (lugs included) */
    size_t j;              /* the interval's first node */
    long knot;             /* the shear-coupled tread's knot at the point in the last solve's
                            * knots (ring_knots.c), -1: none (a point at a node) */
    unsigned char st;      /* 0 free, 1 tread, 2 tread and the belt beneath it */
    unsigned char ends;    /* the pieces it ends: 1 it begins the piece to pts[k + 1], 2 it
                            * ends the one from pts[k - 1], 3 both (two pieces' ends on one
                            * ray, joined: tirenv_ring__sample) */
    double e;              /* last evaluation: tread compression, m (the shear-coupled
                            * tread: at the patch and beside it) */
    double phi, sn, cs;    /* angle (rad) and its sine and cosine */
    double dd;             /* d(d)/dz, m/m */
    double dphi;           /* d(phi)/dz: a ground vertex's cut moves with the centre (rad/m),
                            * 0 at a node */
    double ddt;            /* d(d)/dz along the moving cut, dd + (dd/dphi)*dphi */
    double X;              /* ground abscissa, m */
    double f;              /* last evaluation: ground force, N */
} tirenv_ring_point;

/* A piece of the window between two cuts (nodes or ground vertices), and the ground line its
 * middle ray meets (hit = 0: none within reach). */
typedef struct {
    double pa, sa, ca, pb, sb, cb; /* its ends' angles (rad), sines and cosines */
    size_t j;                      /* its node interval */
    int hit;
    int contig;                    /* its first cut is the piece before's second, the same
                                    * bits (no zero-length piece left out between them) */
    double L[4];                   /* the line (X1, Z1) - (X2, Z2), m */
    double da, db;                 /* its ends' d(angle)/dz, rad/m (0 at a node) */
    /* Its last sampling, for the next at the same x or a new one (ring_ground.c, shift_whole):
     * the cursor its line's walk ended at, the index of its first point (the point it joined,
     * if it joined the piece before's last) and whether it joined. */
    long vk;
    size_t q0;
    int joined;
    int nodes; /* both its ends are nodes (no vertex cut in its interval) */
} tirenv_ring_piece;

/* The ring's own step in z (ring_root.c): F_z's curvature in z, measured at the positions
 * before, by the sign of the step (0 up, 1 down), newest first; and the evaluation it stepped
 * from at this x. Saved with the warm start (a chunk's first position starts without it);
 * every field a double, counts and flag too, so that ring.c's state_restore checks the saved
 * bytes as one array of doubles (finite, counts in range). */
typedef struct {
    double c[2][TIRENV_RING_ROOT_KEEP]; /* d^2 F_z/dz^2, N/m^2 */
    double n[2];           /* how many of c[s] hold one */
    double x, z, F, k;     /* the step's evaluation: m, m, N, N/m */
    double have;           /* 1: x .. k hold it */
    double ex, ez;         /* the last evaluation: m, m */
    double eq_x[TIRENV_RING_START_KEEP], eq_z[TIRENV_RING_START_KEEP]; /* the equilibria
                            * before, newest first: m, m */
    double eq_n;           /* how many of eq_x, eq_z hold one */
    double e_have;         /* 1: ex, ez hold an evaluation */
    double s_mean, s_line; /* the two starts' decayed squared misses, m^2 (0, 0: none yet) */
} tirenv_ring_root;

struct tirenv_ring {
    double R0;             /* free radius at the tread surface, m */
    double R;              /* belt radius R0 - t_r, m */
    tirenv_ring_params par;
    size_t M;              /* nodes around the circle */
    size_t i0;             /* node at theta = 0 */
    double dth;            /* node spacing 2*pi/M, rad */
    double *theta, *sin_t, *cos_t;
    double *c;             /* circulant compliance: w_j = sum_k c[|j-k| mod M] F_k, m/N */
    int c_ready;           /* c computed (at the first tirenv_ring_state that needs it) */
    tirenv_ring_belt *belt;
    /* Per node (global index), over the last window: */
    double *d, *dd;        /* ray penetration R0 - rho (m, -INFINITY: no ground) and d(d)/dz */
    double *b, *db;        /* belt-limit penetration b >= d (m, -INFINITY: none), d(b)/dz */
    double *X;             /* ground point abscissa of the ray (or vertex), m */
    double *kappa;         /* tread stiffness of the node, k_t*R*dtheta, N/m */
    double *w;             /* belt inward displacement, m */
    double *F;             /* ground force on the node, N */
    unsigned char *state;  /* TIRENV_RING_FREE, or T_BASIC and/or B_BASIC */
    unsigned char *warm;   /* the states of the last evaluation, FREE outside its window */
    unsigned char *flip;   /* the violated pairs of a pass */
    double *pn_w, *pn_p, *pn_t, *pn_g; /* projected Newton: iterate, step, trial, gradient */
    size_t lo, n;          /* the window: nodes lo .. lo + n - 1 (n = 0: no ground in reach) */
    size_t warm_lo, warm_n;
    tirenv_ring_band A;    /* the window's contact system and its factor */
    tirenv_ring_band B;    /* the continuous contact's free ends of the window (ring_smooth.c):
                            * the belt there given the nodes that can touch */
    double *rhs;           /* right-hand side, then solution, of the window system */
    double patch;          /* contact length of the last evaluation, m */
    double tread_max;      /* largest tread compression of the last evaluation, m */
    size_t n_contact, n_belt;
    /* The continuous contact's workspace (grown to the largest window met): */
    tirenv_ring_point *pts;
    size_t n_pts, cap_pts;
    void *cuts;
    size_t cap_cuts;
    tirenv_ring_piece *lines;
    size_t cap_lines;
    /* The last sampling's pieces, kept for the next (ring_ground.c): its nodes ja .. jb, and
     * its vertex cuts in angle order (the profile's vertex and the node interval it cuts);
     * valid only if no piece had zero length. */
    int pc_valid;
    size_t pc_ja, pc_jb, pc_nv, cap_pc;
    size_t *pc_vk, *pc_vj;
    size_t n_kept;         /* samplings that kept the last one's pieces (the tests count them) */
    /* The last sampling's pieces (r->lines) with their rays backward, pc_back, and whether they
     * are its first ones (pc_ordered); both known if pc_back_ok. For tests: back_check also
     * counts them by the whole pass where they are carried (ring_ground.c, back_carried),
     * n_back_carried the samplings that carried them and n_back_bad those where the two
     * disagreed. */
    size_t pc_back;
    int pc_ordered, pc_back_ok, back_check;
    size_t n_back_carried, n_back_bad;
    int apart;             /* for tests: a node's two points on one ray kept apart, not joined
                            * (ring_ground.c), as the sampling did before */
    int nodes_general;     /* for tests: the points of pieces between two nodes written by the
                            * general writer (ring_ground.c: no piece marked nodes) */
    /* The window's stretches left unsampled (ring_ground.c): node intervals far from the last
     * sub-window, their ground bounded instead. near_ok: near_a .. near_b is the last solve's
     * sub-window (set by ring_shear.c, where its solve may skip). gaps: n_gaps entries of
     * skipped intervals, each its first and last interval, gap_d at its first an upper bound
     * of d over them (m); gap_on: per node, interval j skipped. The last sampling's
     * arguments, to sample it whole when a solve needs every point. */
    int near_ok, whole_ground; /* whole_ground: for tests, never skip */
    size_t near_a, near_b;
    double *gap_d;
    unsigned char *gap_on; /* per node: interval j is in a gap */
    size_t *gaps, n_gaps;
    size_t n_gapped, n_regap; /* samplings that left gaps, and those sampled whole again after
                               * (the tests count them) */
    const tirenv_profile *smp_p;
    double smp_x, smp_z, smp_kt;
    size_t smp_ja, smp_jb;
    /* A sampling from the last one's points (ring_ground.c, shift_whole): shift_ok, the last
     * fresh sampling's points and its pieces' records are whole; its points' count and window;
     * its gaps (gaps_prev, n_gaps_prev intervals); n_shifted: samplings made so (the tests
     * count them). */
    int shift_ok;
    size_t shift_n_pts, shift_win[2];
    size_t shift_back;   /* its pieces with their rays backward */
    long shift_cur[2];   /* its first vertex behind the centre and ahead of it (-1, n: none) */
    size_t *gaps_prev, n_gaps_prev;
    size_t n_shifted;
    double *g;             /* per node: the belt layer's share of F, N */
    /* The Winkler tread's last factorised system (ring_smooth.c), by what makes its matrix:
     * the window and, of each point in contact, its interval, place, weight, stiffness and
     * state. The next system with the same has the same factor. */
    void *key;
    size_t n_key, cap_key, key_lo, key_n;
    int key_valid;
    size_t n_factor;       /* the Winkler tread's factorisations so far (the tests count them) */
    size_t n_sub;          /* its evaluations answered on the sub-window of their contact
                            * (ring_smooth.c; the tests count them) */
    tirenv_ring_tread *tread; /* TREAD_SHEAR > 0 and the continuous contact; else NULL */
    size_t k_first, k_last;   /* the shear-coupled tread's last solve: its first and last
                               * point in contact (k_first > k_last: none) */
    tirenv_ring_root root;    /* the shear-coupled tread's step in z (ring_root.c) */
};

/* After an evaluation at (x, z) (m) with hub force F (N): F_z's curvature in z from it and the
 * evaluation the last step went from, where that was at the same x. */
void tirenv_ring__root_seen(tirenv_ring *r, double x, double z, double F);

/* Right after an evaluation at (x, z) (m) with F_z = F (N) and dF_z/dz = k (N/m): the height
 * *z_root (m) where F_z = G (N) on the parabola of that slope and the curvature measured at
 * the positions before, returning 1; 0 where there is none (no curvature yet, or a step the
 * curvature would change by more than a tenth), and Newton takes its linear step. */
int tirenv_ring__root(tirenv_ring *r, double x, double z, double F, double k, double G,
                      double *z_root);

/* The root's measurements forgotten (a cold start). */
void tirenv_ring__root_clear(tirenv_ring *r);

/* The quadrature points of the continuous contact over nodes ja .. jb (ring_ground.c):
 * r->pts, r->n_pts; those out of reach (d <= -t_r) with d = -INFINITY, the others with the
 * tread stiffness k_t (N/m^2; NAN: each its own, lugs) and within the nodes win[0] ..
 * win[1] (win[0] > win[1]: none). TIRENV_ENOMEM if its workspace cannot grow. */
int tirenv_ring__sample(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                        size_t ja, size_t jb, double k_t, size_t win[2]);

/* The last sampling again, every interval sampled (its gaps filled): r->pts, r->n_pts, and
 * the same window. TIRENV_ENOMEM if its workspace cannot grow. */
int tirenv_ring__sample_whole(tirenv_ring *r);

/* Whether the last sampling's gaps (r->gaps) are clear of the belt and tread surface xw (the
 * window's (w, u) interleaved from node r->lo, without knots): every point they would hold
 * free, certified by their bounds. 1 if there are none. */
int tirenv_ring__gaps_clear(const tirenv_ring *r, const double xw[]);

/* Whether the intervals a - 1 .. b of the last sampling were all sampled (its points there
 * those of a whole sampling: a sub-window a .. b may be solved on them). */
int tirenv_ring__sampled_over(const tirenv_ring *r, size_t a, size_t b);

/* The points pts[*k0 .. *k1) of the intervals of nodes first .. last, from pts[kf .. kl] in
 * them: the sub-windows of the nodes in contact (ring_smooth.c, ring_shear.c). */
static inline void tirenv_ring__points_of(const tirenv_ring *r, size_t kf, size_t kl,
                                          size_t first, size_t last, size_t *k0, size_t *k1)
{
    size_t k = kf;
    while (k > 0 && r->pts[k - 1].j >= first)
        --k;
    *k0 = k;
    k = kl + 1;
    while (k < r->n_pts && r->pts[k].j < last)
        ++k;
    *k1 = k;
}

/* The continuous contact on the window r->lo, r->n (ring_smooth.c): w, F, g per node and e, f
 * per point; TIRENV_ENOCONV with diag if Newton does not settle. dfz_dz (may be NULL). */
int tirenv_ring__solve_smooth(tirenv_ring *r, double *fx, double *fz, double *dfz_dz,
                              tirenv_diag *diag);

/* The continuous contact's Newton driver (ring_newton.c) on N unknowns, the callbacks a
 * tread's: factor assembles the system of the points' current states and factorises it, its
 * right-hand side into rhs (nonzero: the factorisation broke down); solve applies the factor
 * in place; set_states sets every point's state from x and returns how many changed. The
 * energy E(x) = 1/2 x.K x + P(x): apply writes y = K x; points returns P(x) and, if grad is
 * not NULL, subtracts the points' forces from it (K x there: the gradient of E). K: the
 * window's end correction; kp: N entries of workspace. */
typedef struct {
    size_t N;
    const void *K;
    int (*factor)(tirenv_ring *r, const void *K, double rhs[]);
    void (*solve)(tirenv_ring *r, double x[]);
    size_t (*set_states)(tirenv_ring *r, const double x[]);
    void (*apply)(tirenv_ring *r, const void *K, const double x[], double y[]);
    double (*points)(tirenv_ring *r, const double x[], double grad[]);
    double *kp;
    /* Optional (NULL: backtracking alone): the points' share of E along x + alpha p as terms
     * 1/2 c_i max(0, a_i - alpha b_i)^2, written to arrays of its own (*c, *a, *b); returns
     * their count, or (size_t)-1 if out of memory. */
    size_t (*line)(tirenv_ring *r, const double x[], const double p[], const double **c,
                   const double **a, const double **b);
    /* 0: E is piecewise quadratic, settled when a step leaves the states. Else E has a smooth
     * nonlinear part too (the softening carcass), which factor linearises at the iterate:
     * settled when the states stay and the step is at most nl_tol (m). */
    double nl_tol;
    size_t *steps; /* may be NULL: Newton steps (factorisations) counted into it */
    /* May be NULL: the smooth part of E's slope and curvature along p at x, added to the
     * line's quadratic before its exact minimiser is sought. */
    void (*smooth)(tirenv_ring *r, const double x[], const double p[], double *d1, double *d2);
    /* May be NULL (not used with nl_tol > 0): after the second full step, from x to the
     * Newton point xn (the states set there), the start x0: the points that entered since x0
     * and leave now free the grazing runs beside them that entered with them; returns how many
     * it freed (ring_newton.c, the peel). */
    size_t (*peel)(tirenv_ring *r, const double x0[], const double x[], const double xn[]);
} tirenv_ring_newton;

enum { TIRENV_RING_NEWTON_OK = 0, TIRENV_RING_NEWTON_BREAKDOWN, TIRENV_RING_NEWTON_NOCONV };
enum { TIRENV_RING_NEWTON_MAX_ITER = 200 }; /* Newton steps before _NOCONV */

/* Minimises the contact energy from x (N entries, overwritten with the minimum; the points'
 * states are its). xn, xt, g: N entries of workspace. *factored: the factor left by the last
 * Newton step is that of the final states. TIRENV_RING_NEWTON_OK, _BREAKDOWN or _NOCONV (after
 * TIRENV_RING_NEWTON_MAX_ITER steps). */
int tirenv_ring__newton(tirenv_ring *r, const tirenv_ring_newton *nw, double x[], double xn[],
                        double xt[], double g[], int *factored);

/* The error of a failed solve on n nodes: st a _BREAKDOWN (of the factorisation of the
 * "<system> system") or _NOCONV (the "<contact> contact" of r's points not settled). */
int tirenv_ring__newton_error(const tirenv_ring *r, int st, size_t n, const char *system,
                              const char *contact, tirenv_diag *diag);

/* The tread's shear stiffness k_s = G_t t_r b per unit belt length (N): TREAD_SHEAR times the
 * tread depth and BELT_WIDTH. Zero: a Winkler tread (ring_smooth.c). */
double tirenv_ring__tread_shear(const tirenv_ring_params *par);

/* The carcass's own foundation (docs/models.md section 5.1) per node: k w up to w_0, beyond
 * it k (w_0 + w_s (1 - exp(-(w - w_0)/w_s))), k = k_c R dtheta (N/m), w_0, w_s in m. */
typedef struct {
    double k, w_0, w_s;
} tirenv_ring_carcass;

/* The law of par on nodes of arc length arc = R dtheta (m); nonzero if it softens
 * (CARCASS_SOFTENING_DEFLECTION > 0 and a carcass k_c > 0). */
int tirenv_ring__carcass_law(const tirenv_ring_params *par, double arc, tirenv_ring_carcass *law);

/* The law's departure from the linear k w at w (m): returns its energy (J), *g1 its force
 * (N) and *g2 its tangent (N/m), all zero for w <= w_0; g1 <= 0, -k < g2 <= 0. */
double tirenv_ring__carcass(const tirenv_ring_carcass *law, double w, double *g1, double *g2);

/* Newton steps of the shear-coupled tread's contact solves so far. */
size_t tirenv_ring__tread_newton_steps(const tirenv_ring_tread *T);

/* NULL if out of memory. stencil: the belt's (tirenv_ring__belt_stencil). */
tirenv_ring_tread *tirenv_ring__tread_alloc(size_t M, double R, const tirenv_ring_params *par,
                                            const double stencil[3]);
void tirenv_ring__tread_free(tirenv_ring_tread *T);

/* Per node (global index): the tread surface's inward displacement u over the last window, m. */
double *tirenv_ring__tread_u(tirenv_ring_tread *T);
/* The evaluations answered on the sub-window of the nodes in contact (ring_shear.c), and, with
 * whole nonzero, every later one on the whole window instead (the tests' reference). */
size_t tirenv_ring__tread_n_sub(const tirenv_ring_tread *T);
void tirenv_ring__tread_whole(tirenv_ring_tread *T, int whole);
/* With no_peel nonzero, the contact's Newton without its peel (ring_newton.c): the tests'
 * reference, the same answers in more steps; and the points the peel freed so far. */
void tirenv_ring__tread_no_peel(tirenv_ring_tread *T, int no_peel);
size_t tirenv_ring__tread_peeled(const tirenv_ring_tread *T);
/* For tests: from now on NaN in the Newton driver's vectors and the knots' arrays wherever no
 * solve has written yet, and, before each solve, past the unknowns and knots it writes; a
 * read of an entry it did not write then shows (a NaN answer, a Newton that does not settle),
 * as garbage in reused heap memory would. */
void tirenv_ring__tread_poison(tirenv_ring_tread *T);

/* The doubles of the warm start from tirenv_ring__tread_u on (u, its and w's slopes in z, the
 * z they were found at, the last contact's nodes): what a state saves. */
size_t tirenv_ring__tread_warm_size(const tirenv_ring_tread *T);

/* The shear-coupled tread's contact on the window r->lo, r->n, the centre at abscissa x_c (m,
 * for the lugs): w, u, F, g per node, f per point, e (the ground's overlap with the tread
 * surface) at the points in contact and the two beside them (r->k_first, r->k_last: the
 * patch's), r->tread_max; TIRENV_ENOCONV with diag if Newton does not settle. */
int tirenv_ring__solve_shear(tirenv_ring *r, double x_c, double z, double *fx, double *fz,
                             double *dfz_dz, tirenv_diag *diag);

/* Before the ground is sampled for an evaluation at abscissa x (m): where it is not the last
 * answer's, the ground's penetration at the nodes of that answer's contact, kept from its
 * points for the warm start's shift (ring_warm.c). */
void tirenv_ring__tread_new_x(tirenv_ring *r, double x);

/* For tests: the next evaluation's warm start without the last answer's contact (its nodes
 * for the first sub-window, its ground for the shift), as before either was kept. */
void tirenv_ring__tread_forget(tirenv_ring_tread *T);

/* w and u (m) of the nodes outside the last window, from the exterior's exact solve
 * (allocates; diagnostics only); u_out may be NULL. Nonzero if out of memory. */
int tirenv_ring__tread_exterior(const tirenv_ring *r, double w_out[], double u_out[]);

/* The last window's belt-and-tread stiffness, dense ((2 n)^2 entries, lower triangle), as
 * ring_shear.c's assembly writes it (by_arc 0) or as its exterior's arc does (by_arc 1), for
 * the test that they agree (allocates); nonzero if out of memory, n < 2 or the assembly's
 * right-hand side was not zeroed with the band. */
int tirenv_ring__tread_window(const tirenv_ring *r, int by_arc, double K[]);

/* For tests: the last factorisation's system (m band rows), its diagonal changed from column c
 * on, factorised again by ring_tband.c's restart from a checkpoint and from the start; 0 if the
 * same bits, 1 if not, -1 if it cannot. *q the restart's column, *moved 1 if column c moved. */
int tirenv_ring__tread_refactor(tirenv_ring *r, size_t c, size_t *m, size_t *q, int *moved);

/* For tests: the last factorised system factorised by ring_tband.c's baseline and AVX2 builds;
 * 0 if the same bits, 1 if not, -1 if it cannot. *avx2 1 if the AVX2 build ran. */
int tirenv_ring__tread_factor_isa(const tirenv_ring *r, int *avx2);

/* For tests: the last factorised system's solve with its forward substitution in the
 * factorisation's pass (ring_tband.c's band_factor_x), whole and restarted at each checkpoint,
 * against its factorisation and then its solve, for a pseudo-random right-hand side from seed
 * with lead leading +0 rows and its tail entry neg0 (< 4; else none) -0; 0 if the same bits,
 * 1 if not, -1 if it cannot. *fused 1 if the fused pass ran, *n_restarts the restarts. */
int tirenv_ring__tread_fused_solve(const tirenv_ring *r, unsigned long seed, size_t lead,
                                   size_t neg0, int *fused, size_t *n_restarts);

/* For tests: the last factorised system solved with its factor for a pseudo-random right-hand
 * side from seed: the residual max |b - A x| / (max row sum of |A| * max |x|); -1 if it cannot. */
double tirenv_ring__tread_solve_residual(const tirenv_ring *r, unsigned long seed);

/* For tests: the last factor's solve (ring_tband.c's band_solve, which starts the forward
 * substitution at the first row that is not +0) of a right-hand side with lead leading +0 rows,
 * pseudo-random from seed, its tail entry neg0 (< 4; else none) and with lead_neg0 its row lead
 * -0, against the forward substitution from row 0; 0 if the same bits, 1 if not, -1 if it
 * cannot. */
int tirenv_ring__tread_solve_zeros(const tirenv_ring *r, unsigned long seed, size_t lead,
                                   size_t neg0, int lead_neg0);

/* For tests: the exterior's six columns for a window of n nodes from ring_exterior.c's shared
 * factor of the longest exterior, solved in lanes, against that exterior's own factorisation
 * and full solves, the baseline build's lanes and the columns one at a time, and its end
 * correction from each and without the columns; 0 if the same bits, 1 if not, -1 if it cannot
 * (lugs, n out of range, out of memory). */
int tirenv_ring__tread_end_check(tirenv_ring *r, size_t n);

/* A node's tread stiffness k_t R dtheta (N/m) at angle theta (rad) with the centre at x (m):
 * LUG_GROOVE_RATIO between lugs, which turn with the tire (ring.c). */
double tirenv_ring__tread_kappa(const tirenv_ring *r, double theta, double x);

/* (S w)_i: the belt force holding window node i at w (ring_contact.c). */
double tirenv_ring__belt_force(const tirenv_ring *r, const double (*q)[4], const double w[],
                               size_t i);

/* The contact on the window lo .. lo + n - 1 (n >= 6) of the rays cast: states, w and F of
 * every window node, from the states in warm. TIRENV_ENOCONV, diag saying which, if no method
 * settles or the banded Cholesky breaks down. */
int tirenv_ring__solve_contact(tirenv_ring *r, tirenv_diag *diag);

/* The node states the next contact solve starts from (ring.c), as bytes: their number for a
 * ring, its bytes, and those bytes back into a ring of the same parameters. */
size_t tirenv_ring__state_size(const tirenv_ring *r);
void tirenv_ring__state_save(const tirenv_ring *r, unsigned char *buf);
void tirenv_ring__state_restore(tirenv_ring *r, const unsigned char *buf);

/* dF_z/dz (N/m) with the states of the last tirenv_ring__solve_contact fixed. */
double tirenv_ring__dfz_dz(tirenv_ring *r);

/* dF_z/dz on request, for the equilibrium's Newton (the shear-coupled tread only): with on,
 * the evaluations that follow leave it out (their dfz_dz NULL), each keeping what it needs
 * until the next, and tirenv_ring__slope gives the last one's, the same bits as computed
 * with it. Returns whether it defers (0 without the tread, with the softening carcass, or
 * off). */
int tirenv_ring__defer_slope(tirenv_ring *r, int on);
int tirenv_ring__deferring(const tirenv_ring *r);
int tirenv_ring__shear_slope(tirenv_ring *r, double *dfz_dz);
int tirenv_ring__slope(tirenv_ring *r, double *dfz_dz);

/* The ring's start at a new x (ring_root.c): every evaluation at (x, z) (m) is recorded
 * (tirenv_ring__root_eval); before the first at a new x, the last evaluation at the x before
 * is taken as its equilibrium, and where the last TIRENV_RING_START_KEEP equilibria lie a
 * step apart up to x, and their mean slope has predicted the equilibria before better than
 * the line through the last two, *z (m) is the last one continued by that slope (returns 1). */
void tirenv_ring__root_eval(tirenv_ring *r, double x, double z);
int tirenv_ring__root_start(tirenv_ring *r, double x, double *z);

#endif
