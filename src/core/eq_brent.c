/* GSL's Brent-Dekker on the bracket [z_lo, z_hi], a derivative-free baseline for the
 * equilibrium (docs/models.md section 11). SPDX-License-Identifier: GPL-3.0-or-later
 *
 * GSL evaluates through a plain function returning a double; the evaluation goes through the
 * solver (tirenv_eq__eval) so that it is counted and kept like any other. A failing evaluation
 * hands GSL a finite 0 and is reported after GSL returns, so that GSL never has a reason to
 * signal an error of its own. Brent's root is always an end of its bracket, and the ends are
 * the latest evaluations on either side of the root: the reported point is one of them. */
#include "core/equilibrium.h"

#include <math.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

typedef struct {
    gsl_root_fsolver *gs;  /* allocated once, with the solver */
    gsl_function fn;       /* GSL keeps a pointer to it between set and iterate */
    tirenv_eq_solver *s;   /* for the callback */
    tirenv_diag *diag;
    int status;            /* the first failure inside GSL's calls, and why */
    tirenv_eq_stop stop;
    int iterated;          /* GSL has taken a step since set */
} brent_state;

static int brent_alloc(void *state)
{
    brent_state *st = state;
    st->gs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    return st->gs ? TIRENV_OK : TIRENV_ENOMEM;
}

static void brent_free(void *state)
{
    brent_state *st = state;
    gsl_root_fsolver_free(st->gs);
}

static double brent_f(double z, void *p)
{
    brent_state *st = p;
    if (st->status)
        return 0.0;
    tirenv_eq_point pt;
    st->status = tirenv_eq__eval(st->s, z, &pt, &st->stop, st->diag);
    return st->status ? 0.0 : pt.F - st->s->G;
}

/* What GSL's call left: our failure first, then GSL's own status. */
static int after_gsl(brent_state *st, int gsl_status, tirenv_eq_stop *stop, tirenv_diag *diag)
{
    if (st->status) {
        *stop = st->stop;
        return st->status;
    }
    if (gsl_status) {
        *stop = TIRENV_EQ_BREAKDOWN;
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium", "brent: %s",
                            gsl_strerror(gsl_status));
    }
    return TIRENV_OK;
}

static int brent_set(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop,
                     tirenv_diag *diag)
{
    brent_state *st = state;
    st->s = s;
    st->diag = diag;
    st->status = 0;
    st->iterated = 0;
    const double lo = s->prob.z_lo, hi = s->prob.z_hi;
    tirenv_eq_point p;
    const int status = tirenv_eq__eval(s, lo, &p, stop, diag);
    if (status)
        return status;
    if (p.F < s->G) {
        *stop = TIRENV_EQ_NO_BRACKET;
        return tirenv_error(diag, TIRENV_ENOBRACKET, "", 0, "load",
                            "load %.6g N exceeds what the tire carries with its centre at the "
                            "ground (z = %.6g m)", s->G, lo);
    }
    st->fn = (gsl_function){brent_f, st};
    return after_gsl(st, gsl_root_fsolver_set(st->gs, &st->fn, lo, hi), stop, diag);
}

/* The kept evaluation at z: the latest, or the latest on either side of the root. */
static const tirenv_eq_point *kept(const tirenv_eq_solver *s, double z)
{
    if (s->last.z == z)
        return &s->last;
    if (s->have_below && s->below.z == z)
        return &s->below;
    if (s->have_above && s->above.z == z)
        return &s->above;
    return NULL;
}

/* Brent keeps a bracket, so a bracket within eps_z locates the root (or a jump of F_z, as for
 * Newton); so does a residual within eps_F at the point just evaluated when the bracket also
 * passes GSL's interval test. Once the budget is spent, a root within eps_F is accepted. */
static tirenv_eq_stop brent_test(const void *state, const tirenv_eq_solver *s,
                                 const tirenv_eq_point **accepted)
{
    const brent_state *st = state;
    if (!st->iterated)
        return TIRENV_EQ_RUNNING;
    const double z = gsl_root_fsolver_root(st->gs);
    const double lo = gsl_root_fsolver_x_lower(st->gs), hi = gsl_root_fsolver_x_upper(st->gs);
    const tirenv_eq_point *p = kept(s, z);
    tirenv_eq_stop stop = TIRENV_EQ_RUNNING;
    if (hi - lo <= s->eq.eps_z)
        stop = TIRENV_EQ_BRACKET;
    else if (s->last.z == z && fabs(s->last.F - s->G) <= s->eq.eps_F &&
             gsl_root_test_interval(lo, hi, s->eq.eps_z, 0) == GSL_SUCCESS)
        stop = TIRENV_EQ_RESIDUAL;
    else if (s->evals >= s->eq.max_iter && p && fabs(p->F - s->G) <= s->eq.eps_F)
        stop = TIRENV_EQ_RESIDUAL;
    if (stop == TIRENV_EQ_RUNNING)
        return stop;
    if (!p)
        return TIRENV_EQ_BREAKDOWN;  /* the driver says so: it cannot happen with GSL's Brent */
    *accepted = p;
    return stop;
}

static int brent_iterate(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop,
                         tirenv_diag *diag)
{
    brent_state *st = state;
    (void)s;
    st->diag = diag;
    st->iterated = 1;
    return after_gsl(st, gsl_root_fsolver_iterate(st->gs), stop, diag);
}

static const tirenv_eq_solver_type brent_type = {
    .name = "brent",
    .size = sizeof(brent_state),
    .alloc = brent_alloc,
    .free = brent_free,
    .set = brent_set,
    .iterate = brent_iterate,
    .test = brent_test,
};

const tirenv_eq_solver_type *const tirenv_eq__brent = &brent_type;
