/* Constant-load equilibrium in z (docs/models.md section 11): the default safeguarded Newton,
 * the paper's secant (eq. 2), and GSL's Brent as a derivative-free baseline. */
#include "core/equilibrium.h"

#include <math.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

/* F_z never increases with z and is 0 above first contact, so with f = F - G the bracket
 * [lo, hi] keeps f(lo) >= 0 > f(hi). Newton on the exact dF/dz is taken when it stays inside
 * and converges; otherwise the step falls back to bisection. Converged when the residual and
 * the next correction are both within tolerance, or when the bracket is narrower than eps_z: F_z can jump (a ray sweeping over a convex corner changes the face it
 * hits, so its length jumps), and then the equilibrium is the jump, located to eps_z. */
static int solve_newton(const tirenv_eq_settings *eq, tirenv_eq_force_fn force, void *ctx,
                        double G, const tirenv_eq_problem *prob, tirenv_eq_result *res,
                        tirenv_diag *diag)
{
    double lo = prob->z_lo, hi = prob->z_hi, f_lo = NAN, f_hi = -G;
    int lo_checked = 0;
    double z = fmin(fmax(prob->z0, lo), hi);
    double down = prob->dz_hint;   /* step from a guess with no contact; grows each time */
    double dz_old = INFINITY, last_dz = INFINITY; /* the steps before, to see Newton stall */
    for (size_t it = 1; it <= eq->max_iter; ++it) {
        double F, dF;
        const int status = force(ctx, z, &F, &dF);
        if (status)
            return status;
        res->evals = it;
        const double f = F - G;
        if (f >= 0) {
            lo = z;
            f_lo = f;
            lo_checked = 1;
        } else {
            hi = z;
            f_hi = f;
        }
        const double step = dF < 0 ? -f / dF : INFINITY;
        if (fabs(f) <= eq->eps_F && fabs(step) <= eq->eps_z) {
            *res = (tirenv_eq_result){z, F, dF, it};
            return TIRENV_OK;
        }
        if (lo_checked && hi - lo <= eq->eps_z) {
            const double z_best = fabs(f_lo) <= fabs(f_hi) ? lo : hi;
            if (z_best != z) { /* leave the model's state at the reported point */
                const int s = force(ctx, z_best, &F, &dF);
                if (s)
                    return s;
                ++it;
            }
            *res = (tirenv_eq_result){z_best, F, dF, it};
            return TIRENV_OK;
        }
        double z_next = z + step;
        /* Newton that leaves the bracket, or does not halve the step from the step before
         * last (it oscillates across a jump of F_z), gives way to bisection, as in Numerical
         * Recipes' rtsafe. */
        const int stalled = fabs(2 * step) > dz_old;
        if (!(z_next > lo && z_next < hi) || (stalled && lo_checked)) {
            if (dF >= 0 && f < 0) {
                /* No contact yet: the discrete elements can miss a corner that the rigid
                 * disc (z_hi) touches, so the first contact may lie well below. */
                z_next = fmax(z - down, 0.5 * (lo + hi));
                down *= 4;
            } else if (lo_checked) {
                z_next = 0.5 * (lo + hi);
            } else {
                /* Verify the bracket's lower end before relying on it. */
                lo_checked = 1;
                double F_lo, dF_lo;
                const int s = force(ctx, lo, &F_lo, &dF_lo);
                if (s)
                    return s;
                res->evals = ++it;
                if (F_lo < G)
                    return tirenv_error(diag, TIRENV_ENOBRACKET, "", 0, "load",
                                        "load %.6g N exceeds the %.6g N the tire carries with "
                                        "its centre at the ground (z = %.6g m)",
                                        G, F_lo, lo);
                f_lo = F_lo - G;
                z_next = lo + f_lo * (hi - lo) / (f_lo - f_hi); /* one false-position step */
            }
        }
        dz_old = last_dz;
        last_dz = fabs(z_next - z);
        z = z_next;
    }
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                        "newton: no convergence in %zu evaluations (z in [%.9g, %.9g] m)",
                        eq->max_iter, lo, hi);
}

/* The paper's eq. 2, as published: plain secant from z0 and z0 - secant_dz, no bracket. */
static int solve_secant(const tirenv_eq_settings *eq, tirenv_eq_force_fn force, void *ctx,
                        double G, const tirenv_eq_problem *prob, tirenv_eq_result *res,
                        tirenv_diag *diag)
{
    double z_prev = prob->z0, F_prev, dF;
    int status = force(ctx, z_prev, &F_prev, &dF);
    if (status)
        return status;
    double z = z_prev - eq->secant_dz;
    for (size_t it = 2; it <= eq->max_iter; ++it) {
        double F;
        status = force(ctx, z, &F, &dF);
        if (status)
            return status;
        res->evals = it;
        if (F == F_prev)
            return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                                "secant: equal forces %.6g N at z = %.9g and %.9g m "
                                "(division by zero in eq. 2)", F, z_prev, z);
        const double z_next = z - (F - G) * (z - z_prev) / (F - F_prev);
        if (fabs(F - G) <= eq->eps_F && fabs(z_next - z) <= eq->eps_z) {
            *res = (tirenv_eq_result){z, F, NAN, it};
            return TIRENV_OK;
        }
        if (!isfinite(z_next) || z_next < prob->z_lo)
            return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                                "secant: step left the admissible range (z = %.9g m)", z_next);
        z_prev = z;
        F_prev = F;
        z = z_next;
    }
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                        "secant: no convergence in %zu evaluations (last z = %.9g m)",
                        eq->max_iter, z);
}

typedef struct {
    tirenv_eq_force_fn force;
    void *ctx;
    double G;
    size_t evals;
    int status;
    double last_z, last_f;       /* the last evaluation, so the loop need not repeat it */
} brent_ctx;

static double brent_f(double z, void *p)
{
    brent_ctx *b = p;
    double F, dF;
    ++b->evals;
    const int s = b->force(b->ctx, z, &F, &dF);
    if (s && !b->status)
        b->status = s;
    b->last_z = z;
    b->last_f = s ? NAN : F - b->G;
    return b->last_f;
}

/* GSL's Brent-Dekker on the bracket, started from a bracket around the warm start. */
static int solve_brent(const tirenv_eq_settings *eq, tirenv_eq_force_fn force, void *ctx,
                       double G, const tirenv_eq_problem *prob, tirenv_eq_result *res,
                       tirenv_diag *diag)
{
    brent_ctx b = {force, ctx, G, 0, 0, NAN, NAN};
    gsl_function fn = {brent_f, &b};
    double lo = prob->z_lo, hi = prob->z_hi;
    if (brent_f(lo, &b) < 0)
        return b.status ? b.status
                        : tirenv_error(diag, TIRENV_ENOBRACKET, "", 0, "load",
                                       "load %.6g N exceeds what the tire carries with its "
                                       "centre at the ground (z = %.6g m)", G, lo);
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "equilibrium", "out of memory");
    int status = gsl_root_fsolver_set(s, &fn, lo, hi);
    while (!status && b.evals < eq->max_iter) {
        status = gsl_root_fsolver_iterate(s);
        if (status)
            break;
        const double z = gsl_root_fsolver_root(s);
        lo = gsl_root_fsolver_x_lower(s);
        hi = gsl_root_fsolver_x_upper(s);
        /* Brent keeps a bracket, so a bracket within eps_z also locates the root, or a jump of
         * F_z (see solve_newton). */
        if (hi - lo <= eq->eps_z ||
            (b.last_z == z && fabs(b.last_f) <= eq->eps_F &&
             gsl_root_test_interval(lo, hi, eq->eps_z, 0) == GSL_SUCCESS))
            break;
    }
    const double z = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    if (b.status)
        return b.status;
    /* Leave the model's state at the reported point. */
    const double f = b.last_z == z ? b.last_f : brent_f(z, &b);
    if (!status && (fabs(f) <= eq->eps_F || hi - lo <= eq->eps_z)) {
        *res = (tirenv_eq_result){z, f + G, NAN, b.evals};
        return TIRENV_OK;
    }
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                        "brent: no convergence in %zu evaluations (%s)", b.evals,
                        status ? gsl_strerror(status) : "tolerance not met");
}

int tirenv_eq_solve(const tirenv_eq_settings *eq, tirenv_eq_force_fn force, void *ctx,
                    double G, const tirenv_eq_problem *prob, tirenv_eq_result *res,
                    tirenv_diag *diag)
{
    *res = (tirenv_eq_result){NAN, NAN, NAN, 0};
    switch (eq->method) {
    case TIRENV_EQ_SECANT: return solve_secant(eq, force, ctx, G, prob, res, diag);
    case TIRENV_EQ_BRENT: return solve_brent(eq, force, ctx, G, prob, res, diag);
    case TIRENV_EQ_NEWTON:
    default: return solve_newton(eq, force, ctx, G, prob, res, diag);
    }
}
