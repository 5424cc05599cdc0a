/* SPDX-License-Identifier: Apache-2.0 */
/* Private: a deformable model is a hub-force function F(x, z) plus its own definition of the
 * flat-ground contact length; the constant-load equilibrium around it is shared
 * (deformable.c). */
#ifndef TIRENV_DEFORMABLE_H
#define TIRENV_DEFORMABLE_H

#include "core/equilibrium.h"
#include "model/model_impl.h"

/* What a deformable model is besides its type record: its own workspace with the hub-force
 * function and the flat-ground contact length, the end of its valid range, and the contact
 * state it carries. Every member set (the defaults below where a model has nothing of its
 * own); the type record points here (tirenv_model_type's deformable) and names
 * tirenv_deformable_ops as its functions. */
struct tirenv_deformable {
    void *(*alloc)(const tirenv_tire *tire);
    void (*free)(void *elem);
    /* Hub forces with the centre at (x, z) (m): F_z (N), dF_z/dz (N/m; NaN where
     * defer_slope has it left out), F_x (N) and the contacts, all of one evaluation, in *out;
     * a failure says what failed in diag. */
    int (*forces)(void *elem, const tirenv_profile *p, double x, double z,
                  tirenv_eq_point *out, tirenv_diag *diag);
    /* Right after forces() at (x, z) on p: the centre height *z_root (m) where F_z = G (N)
     * with the evaluation's contact state carried along (Newton's step on the model's own
     * piece, more exact than the linear one), returning 1; 0 where it has none. at is what
     * forces() gave, its dF_z/dz filled in (slope()) where it was left out. NULL: no model
     * step (Newton's own). */
    int (*root)(void *elem, const tirenv_profile *p, double x, double z, double G,
                const tirenv_eq_point *at, double *z_root);
    /* Before the first evaluation of the equilibrium at x (m) on p, whose start is z0 (m):
     * a first iterate *z (m) of the model's own where it knows one better (the springs
     * model's root at x on the last position's working set, docs/models.md section 4.8,
     * A start at a new x), returning 1; 0 where it has none. Newton's alone
     * (tirenv_eq_problem's start). NULL: none. */
    int (*start)(void *elem, const tirenv_profile *p, double x, double z0, double G,
                 double *z);
    /* The profile the workspace evaluates on changes from old to p (a streamed road's next
     * window: the same ground), so that what it carries from one position to the next
     * follows; old NULL: a new sweep on p (tirenv_model_set), nothing carried. NULL: the
     * workspace carries nothing. */
    void (*reprofile)(void *elem, const tirenv_profile *old, const tirenv_profile *p);
    /* Flat-ground contact length (m) with the centre at height z (m): the length of ground
     * the tread touches, which grows continuously as the centre comes down to the lowest
     * height of the valid range (lowest_z), so that deformable.c finds the height of a
     * contact length by one search for every model (docs/models.md section 1.3). It is one
     * force evaluation: with at not NULL, its hub forces as forces() gives them (at->z = z),
     * so that a caller needing both evaluates once. */
    int (*contact_length)(void *elem, const tirenv_profile *flat, double z, double *l_c,
                          tirenv_eq_point *at, tirenv_diag *diag);
    /* The lowest flat-ground centre height z (m) of the model's valid range and why the range
     * ends there (a phrase for messages, into why[n]); z = 0 and "" when it ends only where
     * the centre meets the ground. docs/models.md section 1.3. */
    int (*lowest_z)(void *elem, const tirenv_profile *flat, double *z, char *why, size_t n,
                    tirenv_diag *diag);
    /* The bracket of a warm Newton's equilibrium at x (m) where the model knows one more
     * cheaply than the rigid disc's height (the springs model has it from the rays' origin):
     * z_lo the ground height under the centre, z_hi a height from which up nothing of the
     * tire touches the ground; returns 1. tirenv_deformable_no_bracket: returns 0, and the
     * rigid disc's bracket is taken, the tightest for any tire within its free circle. */
    int (*bracket)(void *elem, const tirenv_profile *p, double x, double *z_lo, double *z_hi);
    /* Whether the tire looks the same at every x (no lugs turning with it), so that on level
     * ground the equilibrium is the flat one; tirenv_deformable_invariant: always. */
    int (*shift_invariant)(const tirenv_tire *tire);
    /* The contact state a workspace starts its next solve from, as bytes (a fixed number for
     * a tire and level): saved on profile p, and restored into a workspace of the same tire on
     * p (the same ground; NULL: none set); TIRENV_OK, or an error status, the workspace then
     * carrying nothing to its next solve. level: the flat-ground workspace, which evaluates
     * at one x on level ground only (what a model carries from one x to the next is not
     * its). */
    size_t (*state_size)(const void *elem, int level);
    void (*state_save)(const void *elem, const tirenv_profile *p, int level,
                       unsigned char *buf);
    int (*state_restore)(void *elem, const tirenv_profile *p, int level,
                         const unsigned char *buf);
    /* A spring in series between the hub and the force function's centre, or NULL (none):
     * its deflection u (m) at a force F (N) and its compliance du/dF (m/N, into *dU_dF),
     * u = 0 at F = 0 and non-decreasing in F. The forces above are then those of the centre
     * u above the hub (docs/models.md section 4.9): at a constant load u is a constant, so
     * the equilibria are solved for the centre and the hub reported u below it. */
    double (*series)(const tirenv_tire *tire, double F, double *dU_dF);
    /* Nonzero where the tire's contact makes F_z continuous in z and x (the continuous
     * contacts of docs/models.md 4.8 and 5.3): an equilibrium that the solver locates on a
     * jump of F_z is then a defect, refused (tirenv_deformable_check_jump); NULL: F_z may
     * jump (the paper's rays), and the jump is the equilibrium (section 11.3). */
    int (*continuous)(const tirenv_tire *tire);
    /* Nonzero: the warm start of a position is the line through the last two equilibria
     * (deformable.c's predict), for a model whose Newton converges slowly; else the last. */
    int extrapolate;
    /* dF_z/dz on request, for Newton's equilibrium at a position (NULL: forces() always gives
     * it): defer_slope(elem, 1) has the evaluations that follow leave it out (NaN) where the
     * model can, and returns whether it does; slope() then gives the last evaluation's, the
     * same bits as forces() would have given; defer_slope(elem, 0) ends it. */
    int (*defer_slope)(void *elem, int on);
    int (*slope)(void *elem, double *dF_dz);
    /* What the tire can touch at its flat-ground equilibrium with its centre dz (m) above
     * level ground, for the shortcut of clear ground (deformable.c, docs/models.md section
     * 11.4): *r (m), a radius about the centre beyond which no ground carries force there,
     * and *tan_cut, the tangent of the angle from the vertical within which a vertex below
     * the centre would change how the level ground is sampled (0: no vertex does). NULL: only
     * ground level over the whole reach is short-cut. deformable_clear.c has the models'. */
    void (*level_reach)(const tirenv_tire *tire, double dz, double *r, double *tan_cut);
};

/* The functions of every deformable model's type record (deformable.c): the constant-load
 * equilibrium around the type's deformable record. */
extern const tirenv_model_ops tirenv_deformable_ops;

/* struct tirenv_deformable's level_reach (deformable_clear.c): the free circle R0 of a tire
 * whose tread never stands out of it (the springs model), and R0 + t_r, the farthest ground a
 * ring's ray samples, with its nodes' spacing (the ring). */
void tirenv_deformable_level_reach_r0(const tirenv_tire *tire, double dz, double *r,
                                      double *tan_cut);
void tirenv_deformable_level_reach_tread(const tirenv_tire *tire, double dz, double *r,
                                         double *tan_cut);

/* The defaults of struct tirenv_deformable's bracket and shift_invariant. */
int tirenv_deformable_no_bracket(void *elem, const tirenv_profile *p, double x, double *z_lo,
                                   double *z_hi);
int tirenv_deformable_invariant(const tirenv_tire *tire);

/* TIRENV_ENOCONV, saying so, where res located the equilibrium at load G (N) on a jump of F_z
 * that def's continuous contact for tire should not have (more than eps_F and 1e-6 G beyond
 * the slopes); else TIRENV_OK. */
int tirenv_deformable_check_jump(const tirenv_deformable *def, const tirenv_tire *tire,
                                 const tirenv_eq_result *res, double G, tirenv_diag *diag);

/* The warm start at x (m) from the last two equilibria (x1, z1) and (x2, z2) (m), the last
 * first: z1, or with extrapolate (the model's record's) and have2 the line through both, where
 * x continues their step in its direction at most twice as far. */
double tirenv_deformable_predict(int extrapolate, int have2, double x, double x1, double z1,
                                 double x2, double z2);

/* The warm start's history: the last two equilibria of a sweep, the last first, for
 * tirenv_deformable_predict; deformable.c keeps one per model, tracks.c one per set of tracks.
 * Clearing or restarting it leaves the older entries' values (only the flags say what holds),
 * so a saved state's bytes are what they were. */
typedef struct {
    double x1, z1;               /* the last equilibrium: position and centre height, m */
    double x2, z2;               /* the one before, m */
    int have1, have2;
} tirenv_deformable_history;

/* No equilibrium yet: the next start is cold. */
static inline void tirenv_deformable_history_clear(tirenv_deformable_history *h)
{
    h->have1 = h->have2 = 0;
}

/* The equilibrium at (x, z) (m), after the last. */
static inline void tirenv_deformable_history_push(tirenv_deformable_history *h, double x,
                                                  double z)
{
    h->have2 = h->have1;
    h->x2 = h->x1, h->z2 = h->z1;
    h->x1 = x;
    h->z1 = z;
    h->have1 = 1;
}

/* The equilibrium at (x, z) (m) as the only one: the line through the last two is not
 * continued over it (a level stretch, whose height may end there). */
static inline void tirenv_deformable_history_restart(tirenv_deformable_history *h, double x,
                                                     double z)
{
    h->have2 = 0;
    h->x1 = x;
    h->z1 = z;
    h->have1 = 1;
}

/* Every height held moved by dz (m): a new load's flat-ground height moved so. */
static inline void tirenv_deformable_history_shift(tirenv_deformable_history *h, double dz)
{
    if (h->have1)
        h->z1 += dz;
    if (h->have2)
        h->z2 += dz;
}

/* The start of the equilibrium at x (m): tirenv_deformable_predict of the history (with the
 * model record's extrapolate), z_cold (m) while it is empty. */
static inline double tirenv_deformable_history_start(const tirenv_deformable_history *h,
                                                     int extrapolate, double x, double z_cold)
{
    return h->have1 ? tirenv_deformable_predict(extrapolate, h->have2, x, h->x1, h->z1, h->x2,
                                                h->z2)
                    : z_cold;
}

/* The series spring's deflection (m) at load F (N) of a deformable record for a tire: 0
 * without one (its series NULL). */
double tirenv_deformable_series(const tirenv_deformable *def, const tirenv_tire *tire,
                                double F);

/* The hub forces at (x, z) on the profile set of a state of tirenv_deformable_ops, for the
 * equilibrium over several tracks (tracks.c). */
int tirenv_deformable_forces(void *state, double x, double z, tirenv_eq_point *out,
                             tirenv_diag *diag);

#endif
