/* Private: the constant-load equilibrium F_z(z) = G_T in the centre height z (docs/models.md
 * section 11), shared by every deformable model. */
#ifndef TIRENV_EQUILIBRIUM_H
#define TIRENV_EQUILIBRIUM_H

#include "tirenv/error.h"
#include "tirenv/tire.h"

/* Vertical hub force F (N) at centre height z (m) and its derivative dF/dz (N/m, <= 0);
 * returns a status. */
typedef int (*tirenv_eq_force_fn)(void *ctx, double z, double *F, double *dF_dz);

/* Where the root lies: F(z_lo) >= G is expected but only checked when needed; F(z_hi) < G
 * is known. z0 is the first guess; dz_hint a typical deflection (m) for the first step down
 * from a guess with no contact. */
typedef struct {
    double z_lo;           /* lowest admissible centre height, m */
    double z_hi;           /* centre height with no contact, m */
    double z0;             /* first guess, m */
    double dz_hint;        /* typical deflection, m */
} tirenv_eq_problem;

typedef struct {
    double z;              /* equilibrium centre height, m */
    double F;              /* force there, N */
    double dF_dz;          /* derivative there, N/m (NaN for methods that do not use it) */
    size_t evals;          /* force evaluations spent */
} tirenv_eq_result;

/* Solves F(z) = G with the method in eq. TIRENV_ENOBRACKET if F(z_lo) < G, TIRENV_ENOCONV
 * if the tolerances are not met in eq->max_iter evaluations; diag says why. */
int tirenv_eq_solve(const tirenv_eq_settings *eq, tirenv_eq_force_fn force, void *ctx,
                    double G, const tirenv_eq_problem *prob, tirenv_eq_result *res,
                    tirenv_diag *diag);

#endif
