/* Private to the core: the constant-load equilibrium F_z(z) = G_T in the centre height z
 * (docs/models.md section 11), shared by every deformable model. Solvers are types, as GSL's
 * root finders are (gsl_root_fsolver_type): each has set / iterate / test, and one driver runs
 * any of them and says why it stopped. SPDX-License-Identifier: Apache-2.0
 *
 * The force function returns everything the caller reports (F_z, dF_z/dz, F_x, contacts) from
 * one evaluation in one struct, and the solver keeps the evaluations it may accept (the last
 * one on each side of the root, and the latest), so the point a solver reports is an evaluated
 * iterate by construction: nothing depends on what the last call left behind.
 *
 * A model may help Newton three ways, each optional and ignored by the other methods: the
 * point's has_root / z_root (its own step from an evaluation), the problem's start (its own
 * first iterate) and the problem's slope (dF_z/dz left out of an evaluation, NaN, and given
 * on request). slope is the one exception to the rule above: it answers for the latest
 * evaluation, so the solver asks for it before the next (tirenv_eq__slope). */
#ifndef TIRENV_EQUILIBRIUM_H
#define TIRENV_EQUILIBRIUM_H

#include <stddef.h>

#include "tirenv/error.h"
#include "tirenv/tire.h"

/* One evaluation of a model's hub forces with its centre at height z (the position x is the
 * model's business). */
typedef struct {
    double z;              /* centre height evaluated, m */
    double F;              /* vertical hub force F_z, N */
    double dF_dz;          /* dF_z/dz, N/m (<= 0 where the model is monotone; NaN: left out,
                            * given on request through tirenv_eq_problem's slope) */
    double fx;             /* longitudinal hub force F_x, N */
    size_t contacts;       /* elements (or nodes) touching the ground */
    /* The model's own step, where it knows F_z better than its slope does (the springs
     * model's continuous contact: F_z = G on the working set of the evaluation's QP, solved
     * with it, docs/models.md section 4.8, Newton's step on the working set; the ring's
     * parabola through its slope and the curvature measured at the positions before,
     * section 5.3): Newton steps to z_root instead of its linear step. has_root 0 (as every
     * evaluation starts): none. */
    int has_root;
    double z_root;         /* m */
} tirenv_eq_point;

/* Fills *out (out->z = z) or returns a status with diag saying what failed. */
typedef int (*tirenv_eq_force_fn)(void *ctx, double z, tirenv_eq_point *out,
                                  tirenv_diag *diag);

/* Where the root lies: F(z_lo) >= G is expected but only checked when a method needs it;
 * F(z_hi) < G is known. z0 is the first guess; dz_hint a typical deflection (m) for the first
 * step down from a guess with no contact. */
typedef struct {
    double z_lo;           /* lowest admissible centre height, m */
    double z_hi;           /* centre height with no contact, m */
    double z0;             /* first guess, m */
    double dz_hint;        /* typical deflection, m */
    /* dF/dz of the latest evaluation on request, for a force function that leaves it out (NaN)
     * where Newton does not need it (eq_newton.c); NULL: every evaluation gives it. Nonzero
     * if it cannot. */
    int (*slope)(void *ctx, double *dF_dz);
    /* A first iterate the model proposes instead of z0 (the springs model's root at this x
     * on the last position's QP working set, docs/models.md section 4.8, A start at a new
     * x), for Newton (eq_newton.c; the other methods ignore it): returns 1 with *z (m), which
     * Newton takes if it lies inside (z_lo, z_hi), or 0 (z0 is taken). The model's evaluation there
     * decides as any evaluation: the solver's own test accepts it or goes on from it. NULL:
     * none. */
    int (*start)(void *ctx, double z0, double *z);
} tirenv_eq_problem;

/* Why a solve stopped. */
typedef enum {
    TIRENV_EQ_RUNNING = 0, /* not stopped: iterate again */
    TIRENV_EQ_RESIDUAL,    /* |F_z - G| <= eps_F and the next correction within eps_z */
    TIRENV_EQ_BRACKET,     /* a bracket narrower than eps_z: the root, or a jump of F_z where
                            * a ray sweeps over a corner, located to eps_z */
    TIRENV_EQ_NO_BRACKET,  /* F_z(z_lo) < G: the tire cannot carry the load */
    TIRENV_EQ_MAX_EVALS,   /* eps->max_iter force evaluations spent */
    TIRENV_EQ_BREAKDOWN,   /* the method cannot go on (the secant's equal forces or a step
                            * out of range, a failure inside Brent) */
    TIRENV_EQ_FORCE_FAILED /* the force function failed (diag says how) */
} tirenv_eq_stop;

/* "running", "residual", "bracket", "no bracket", "evaluations spent", "breakdown", "force
 * failed". */
const char *tirenv_eq__stop_name(tirenv_eq_stop stop);

typedef struct tirenv_eq_solver tirenv_eq_solver;

/* A method: its name, the size of its state, and its three steps. set evaluates the first
 * point(s); iterate takes one step (one or two evaluations, through tirenv_eq__eval); test
 * says whether the solver has converged (*accepted: the evaluation to report) or must go on
 * (TIRENV_EQ_RUNNING). set and iterate return a status; on failure they fill diag and
 * *stop. */
typedef struct {
    const char *name;
    size_t size;
    int (*alloc)(void *state);               /* NULL, or TIRENV_ENOMEM */
    void (*free)(void *state);               /* NULL, or frees what alloc took */
    int (*set)(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop, tirenv_diag *diag);
    int (*iterate)(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop,
                   tirenv_diag *diag);
    tirenv_eq_stop (*test)(const void *state, const tirenv_eq_solver *s,
                           const tirenv_eq_point **accepted);
} tirenv_eq_solver_type;

/* The safeguarded Newton of docs/models.md section 11 (the default), the paper's secant (its
 * eq. 2), and Brent-Dekker on the bracket (core/brent.c), a derivative-free baseline. */
extern const tirenv_eq_solver_type *const tirenv_eq__newton;
extern const tirenv_eq_solver_type *const tirenv_eq__secant;
extern const tirenv_eq_solver_type *const tirenv_eq__brent;

/* The type of a tirenv_eq_method (tire.h); newton for an unknown one. */
const tirenv_eq_solver_type *tirenv_eq__solver_type_of(tirenv_eq_method method);

/* What every method shares, visible to the methods (src/core/eq_*.c) and to the driver. */
struct tirenv_eq_solver {
    const tirenv_eq_solver_type *type;
    void *state;               /* the method's own, type->size bytes */
    /* The problem of the current solve. */
    tirenv_eq_settings eq;
    tirenv_eq_force_fn force;
    void *ctx;
    double G;                  /* load, N */
    tirenv_eq_problem prob;
    /* The evaluations a method may accept: the latest, and the latest on each side of the
     * root (f = F - G >= 0 below it, < 0 above it; F_z never increases with z). */
    size_t evals;
    tirenv_eq_point last;
    tirenv_eq_point below;     /* latest with F >= G; valid if have_below */
    tirenv_eq_point above;     /* latest with F < G; valid if have_above */
    int have_below, have_above;
};

/* A solver of type T; NULL if out of memory. Allocates once: a solve allocates nothing. */
tirenv_eq_solver *tirenv_eq__solver_alloc(const tirenv_eq_solver_type *T);
void tirenv_eq__solver_free(tirenv_eq_solver *s);  /* NULL is a no-op */

/* Starts a solve of F(z) = G (N) with settings eq (eps_F, eps_z, max_iter, secant_dz) and the
 * force function force(ctx, ...) on prob; evaluates the first point(s). */
int tirenv_eq__solver_set(tirenv_eq_solver *s, const tirenv_eq_settings *eq,
                         tirenv_eq_force_fn force, void *ctx, double G,
                         const tirenv_eq_problem *prob, tirenv_eq_stop *stop,
                         tirenv_diag *diag);
/* One step of the method. */
int tirenv_eq__solver_iterate(tirenv_eq_solver *s, tirenv_eq_stop *stop, tirenv_diag *diag);
/* TIRENV_EQ_RUNNING, or why the solver has converged and, in *accepted, the evaluation it
 * reports. */
tirenv_eq_stop tirenv_eq__solver_test(const tirenv_eq_solver *s,
                                     const tirenv_eq_point **accepted);

/* For the methods: evaluates the force at z through the solver, so that every evaluation is
 * counted, kept and checked against the budget of eq.max_iter evaluations (TIRENV_ENOCONV and
 * TIRENV_EQ_MAX_EVALS once it is spent). *out (may be NULL) receives the evaluation. */
int tirenv_eq__eval(tirenv_eq_solver *s, double z, tirenv_eq_point *out, tirenv_eq_stop *stop,
                    tirenv_diag *diag);

/* For the methods: dF/dz of the latest evaluation *p where it was left out (prob.slope), into
 * *p and the solver's copies of it; nothing where p has one. */
int tirenv_eq__slope(tirenv_eq_solver *s, tirenv_eq_point *p, tirenv_eq_stop *stop,
                     tirenv_diag *diag);

/* What a solve found. */
typedef struct {
    tirenv_eq_point point; /* the accepted evaluation (all NaN / 0 on failure) */
    size_t evals;          /* force evaluations spent */
    tirenv_eq_stop stop;   /* why it stopped */
    double jump;           /* with stop TIRENV_EQ_BRACKET, how far F_z falls across the final
                            * bracket beyond what its ends' slopes account for (N): a jump of
                            * F_z at the root, located to eps_z; 0 otherwise, and where an
                            * evaluation met the load exactly */
} tirenv_eq_result;

/* The driver: set, then test and iterate until the solver converges, fails or spends
 * eq->max_iter evaluations. TIRENV_OK with res->point the accepted evaluation; otherwise
 * TIRENV_ENOBRACKET (the load is too high), TIRENV_ENOCONV (evaluations spent, or the method
 * broke down), or the force function's status, with diag saying which method stopped where
 * and why, and res->stop the reason. */
int tirenv_eq__solve(tirenv_eq_solver *s, const tirenv_eq_settings *eq,
                    tirenv_eq_force_fn force, void *ctx, double G,
                    const tirenv_eq_problem *prob, tirenv_eq_result *res, tirenv_diag *diag);

#endif
