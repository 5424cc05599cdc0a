/* The equilibrium driver (docs/models.md section 11): solver lifecycle, the one place every
 * force evaluation passes through, and the loop set / test / iterate that says why it stopped,
 * in the manner of GSL's gsl_multifit_nlinear_driver. The methods are in eq_newton.c,
 * eq_secant.c and eq_brent.c. SPDX-License-Identifier: Apache-2.0 */
#include "core/equilibrium.h"

#include <math.h>
#include <stdlib.h>

static const char *const stop_names[] = {
    [TIRENV_EQ_RUNNING] = "running",
    [TIRENV_EQ_RESIDUAL] = "residual",
    [TIRENV_EQ_BRACKET] = "bracket",
    [TIRENV_EQ_NO_BRACKET] = "no bracket",
    [TIRENV_EQ_MAX_EVALS] = "evaluations spent",
    [TIRENV_EQ_BREAKDOWN] = "breakdown",
    [TIRENV_EQ_FORCE_FAILED] = "force failed",
};

const char *tirenv_eq__stop_name(tirenv_eq_stop stop)
{
    return (size_t)stop < sizeof stop_names / sizeof stop_names[0] ? stop_names[stop]
                                                                   : "unknown";
}

const tirenv_eq_solver_type *tirenv_eq__solver_type_of(tirenv_eq_method method)
{
    switch (method) {
    case TIRENV_EQ_SECANT: return tirenv_eq__secant;
    case TIRENV_EQ_BRENT: return tirenv_eq__brent;
    case TIRENV_EQ_NEWTON:
    default: return tirenv_eq__newton;
    }
}

tirenv_eq_solver *tirenv_eq__solver_alloc(const tirenv_eq_solver_type *T)
{
    if (!T)
        return NULL;
    tirenv_eq_solver *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->type = T;
    s->state = calloc(1, T->size ? T->size : 1);
    if (!s->state || (T->alloc && T->alloc(s->state) != TIRENV_OK)) {
        free(s->state);
        free(s);
        return NULL;
    }
    return s;
}

void tirenv_eq__solver_free(tirenv_eq_solver *s)
{
    if (!s)
        return;
    if (s->type->free)
        s->type->free(s->state);
    free(s->state);
    free(s);
}

int tirenv_eq__eval(tirenv_eq_solver *s, double z, tirenv_eq_point *out, tirenv_eq_stop *stop,
                    tirenv_diag *diag)
{
    if (s->evals >= s->eq.max_iter) {
        *stop = TIRENV_EQ_MAX_EVALS;  /* the driver says where the bracket stood */
        return TIRENV_ENOCONV;
    }
    tirenv_eq_point p = {.z = z, .F = NAN, .dF_dz = NAN, .fx = NAN, .contacts = 0};
    ++s->evals;
    int status = s->force(s->ctx, z, &p, diag);
    if (!status && !(isfinite(p.F) && isfinite(p.fx)))
        status = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                              "the force function returned F_z %g N, F_x %g N at z = %.9g m",
                              p.F, p.fx, z);
    if (status) {
        *stop = TIRENV_EQ_FORCE_FAILED;
        return status;
    }
    p.z = z;
    s->last = p;
    if (p.F - s->G >= 0) {
        s->below = p;
        s->have_below = 1;
    } else {
        s->above = p;
        s->have_above = 1;
    }
    if (out)
        *out = p;
    return TIRENV_OK;
}

int tirenv_eq__slope(tirenv_eq_solver *s, tirenv_eq_point *p, tirenv_eq_stop *stop,
                     tirenv_diag *diag)
{
    if (!isnan(p->dF_dz) || !s->prob.slope)
        return TIRENV_OK;
    if (s->prob.slope(s->ctx, &p->dF_dz) || !isfinite(p->dF_dz)) {
        *stop = TIRENV_EQ_FORCE_FAILED;
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                            "the force function gave no dF_z/dz at z = %.9g m", p->z);
    }
    s->last.dF_dz = p->dF_dz;
    (p->F - s->G >= 0 ? &s->below : &s->above)->dF_dz = p->dF_dz;
    return TIRENV_OK;
}

int tirenv_eq__solver_set(tirenv_eq_solver *s, const tirenv_eq_settings *eq,
                         tirenv_eq_force_fn force, void *ctx, double G,
                         const tirenv_eq_problem *prob, tirenv_eq_stop *stop,
                         tirenv_diag *diag)
{
    s->eq = *eq;
    s->force = force;
    s->ctx = ctx;
    s->G = G;
    s->prob = *prob;
    s->evals = 0;
    s->have_below = s->have_above = 0;
    *stop = TIRENV_EQ_RUNNING;
    return s->type->set(s->state, s, stop, diag);
}

int tirenv_eq__solver_iterate(tirenv_eq_solver *s, tirenv_eq_stop *stop, tirenv_diag *diag)
{
    return s->type->iterate(s->state, s, stop, diag);
}

tirenv_eq_stop tirenv_eq__solver_test(const tirenv_eq_solver *s,
                                     const tirenv_eq_point **accepted)
{
    *accepted = NULL;
    return s->type->test(s->state, s, accepted);
}

/* The failure message of the budget, which only the driver can write: the methods stop at
 * tirenv_eq__eval's refusal without knowing more than the solver does. */
static int evals_spent(const tirenv_eq_solver *s, tirenv_diag *diag)
{
    const double lo = s->have_below ? s->below.z : s->prob.z_lo;
    const double hi = s->have_above ? s->above.z : s->prob.z_hi;
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                        "%s: no convergence in %zu evaluations (z in [%.9g, %.9g] m)",
                        s->type->name, s->eq.max_iter, lo, hi);
}

int tirenv_eq__solve(tirenv_eq_solver *s, const tirenv_eq_settings *eq,
                    tirenv_eq_force_fn force, void *ctx, double G,
                    const tirenv_eq_problem *prob, tirenv_eq_result *res, tirenv_diag *diag)
{
    *res = (tirenv_eq_result){
        .point = {.z = NAN, .F = NAN, .dF_dz = NAN, .fx = NAN, .contacts = 0},
        .evals = 0,
        .stop = TIRENV_EQ_RUNNING,
        .jump = 0,
    };
    tirenv_eq_stop stop = TIRENV_EQ_RUNNING;
    const tirenv_eq_point *accepted = NULL;
    int status = tirenv_eq__solver_set(s, eq, force, ctx, G, prob, &stop, diag);
    /* Every iterate evaluates at least once or narrows the bracket to nothing, so the budget
     * ends the loop; the guard only keeps a faulty method from spinning. */
    for (size_t steps = 0; !status; ++steps) {
        stop = tirenv_eq__solver_test(s, &accepted);
        if (stop != TIRENV_EQ_RUNNING)
            break;
        if (steps > 2 * eq->max_iter + 2) {
            stop = TIRENV_EQ_BREAKDOWN;
            status = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                                  "%s: no progress after %zu steps", s->type->name, steps);
            break;
        }
        status = tirenv_eq__solver_iterate(s, &stop, diag);
    }
    if (!status && !accepted) {  /* a test that converged must name its point */
        stop = TIRENV_EQ_BREAKDOWN;
        status = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                              "%s: converged on a point it never evaluated", s->type->name);
    }
    res->evals = s->evals;
    res->stop = stop;
    /* The bracket's ends are the latest evaluations either side of the load, but where one
     * met it exactly (F = G, Brent's bracket shrinks onto it): no jump then. */
    if (stop == TIRENV_EQ_BRACKET && s->have_below && s->have_above) {
        const double w = fabs(s->above.z - s->below.z);
        const double k = fmax(fabs(s->below.dF_dz), fabs(s->above.dF_dz));
        res->jump = w <= eq->eps_z ? fmax(0, s->below.F - s->above.F - k * w) : 0;
    }
    if (status)
        return stop == TIRENV_EQ_MAX_EVALS ? evals_spent(s, diag) : status;
    res->point = *accepted;
    return TIRENV_OK;
}
