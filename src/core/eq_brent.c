/* Brent-Dekker on the bracket [z_lo, z_hi] (core/brent.c), a derivative-free baseline for
 * the equilibrium (docs/models.md section 11). SPDX-License-Identifier: Apache-2.0
 *
 * Brent evaluates through a plain function returning a double; the evaluation goes through the
 * solver (tirenv_eq__eval) so that it is counted and kept like any other. A failing evaluation
 * hands Brent a finite 0 and is reported after Brent returns, so that Brent never has a reason
 * to fail on its own. Brent's root is always an end of its bracket, and the ends are the latest
 * evaluations on either side of the root: the reported point is one of them. */
#include "core/equilibrium.h"

#include <math.h>
#include "core/brent.h"

typedef struct {
    tirenv_core__brent br;
    tirenv_eq_solver *s;   /* for the callback */
    tirenv_diag *diag;
    int status;            /* the first failure inside Brent's calls, and why */
    tirenv_eq_stop stop;
    int iterated;          /* Brent has taken a step since set */
} brent_state;

static int brent_alloc(void *state)
{
    (void)state;
    return TIRENV_OK;
}

static void brent_free(void *state)
{
    (void)state;
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

/* What Brent's call left: our failure first, then Brent's own status. */
static int after_brent(brent_state *st, int br_status, tirenv_eq_stop *stop, tirenv_diag *diag)
{
    if (st->status) {
        *stop = st->stop;
        return st->status;
    }
    if (br_status) {
        *stop = TIRENV_EQ_BREAKDOWN;
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium", "brent: %s",
                            tirenv_core__brent_strerror(br_status));
    }
    return TIRENV_OK;
}

/* The bracket's lower end: z_lo, the hub at the ground (docs/models.md section 11.1), where
 * the force settles there. A deformable model crushed by a whole radius can fail to settle
 * (the ring's contact over Horstwalde.crg: 1,420 points on 719 nodes, 200 Newton steps from
 * the warm start and from rest) though its equilibrium lies centimetres below z_hi; there the
 * end moves halfway toward the upper one while the force keeps failing (TIRENV_ENOCONV), an
 * evaluation below the load on the way becomes the upper end (*hi, *f_hi) and the search goes
 * on below it, until an evaluation carries the load. The failure is reported once the ends
 * close to eps_z or the budget is spent. Every solve whose lower end settles is as before:
 * only a position that failed is searched. *p: the lower end's evaluation. */
static int unsettled(int status, tirenv_eq_stop stop)
{
    return status == TIRENV_ENOCONV && stop == TIRENV_EQ_FORCE_FAILED;
}

static int lower_end(tirenv_eq_solver *s, tirenv_eq_point *p, double *hi, double *f_hi,
                     tirenv_eq_stop *stop, tirenv_diag *diag)
{
    double a = s->prob.z_lo;
    int status = tirenv_eq__eval(s, a, p, stop, diag);
    while (unsettled(status, *stop) && *hi - a > s->eq.eps_z) {
        const double z = a + 0.5 * (*hi - a);
        const int status_z = tirenv_eq__eval(s, z, p, stop, diag);
        if (unsettled(status_z, *stop)) {
            a = z;
        } else if (status_z || p->F >= s->G) {
            return status_z;  /* the budget spent, another failure, or the lower end */
        } else {
            *hi = z;
            *f_hi = p->F - s->G;
        }
    }
    return status;  /* z_lo's evaluation, or the last failure (*stop still says so) */
}

static int brent_set(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop,
                     tirenv_diag *diag)
{
    brent_state *st = state;
    st->s = s;
    st->diag = diag;
    st->status = 0;
    st->iterated = 0;
    double hi = s->prob.z_hi, f_hi = NAN;
    tirenv_eq_point p;
    const int status = lower_end(s, &p, &hi, &f_hi, stop, diag);
    if (status)
        return status;
    if (p.F < s->G) {
        *stop = TIRENV_EQ_NO_BRACKET;
        return tirenv_error(diag, TIRENV_ENOBRACKET, "", 0, "load",
                            "load %.6g N exceeds what the tire carries with its centre at the "
                            "ground (z = %.6g m)", s->G, s->prob.z_lo);
    }
    /* Brent starts from f(lo) as evaluated here (evaluating it again would cost an evaluation
     * and give the same value) and f(hi), unless the search for lo has evaluated a lower hi */
    if (isnan(f_hi))
        f_hi = brent_f(hi, st);
    return after_brent(st, tirenv_core__brent_set_values(&st->br, brent_f, st, p.z,
                                                         p.F - s->G, hi, f_hi),
                       stop, diag);
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
 * passes the interval test |hi - lo| < eps_z. Once the budget is spent, a root within eps_F is accepted. */
static tirenv_eq_stop brent_test(const void *state, const tirenv_eq_solver *s,
                                 const tirenv_eq_point **accepted)
{
    const brent_state *st = state;
    if (!st->iterated)
        return TIRENV_EQ_RUNNING;
    const double z = st->br.root;
    const double lo = st->br.lo, hi = st->br.hi;
    const tirenv_eq_point *p = kept(s, z);
    tirenv_eq_stop stop = TIRENV_EQ_RUNNING;
    if (hi - lo <= s->eq.eps_z)
        stop = TIRENV_EQ_BRACKET;
    else if (s->last.z == z && fabs(s->last.F - s->G) <= s->eq.eps_F &&
             tirenv_core__brent_converged(&st->br, s->eq.eps_z))
        stop = TIRENV_EQ_RESIDUAL;
    else if (s->evals >= s->eq.max_iter && p && fabs(p->F - s->G) <= s->eq.eps_F)
        stop = TIRENV_EQ_RESIDUAL;
    if (stop == TIRENV_EQ_RUNNING)
        return stop;
    if (!p)
        return TIRENV_EQ_BREAKDOWN;  /* the driver says so: it cannot happen with Brent */
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
    return after_brent(st, tirenv_core__brent_iterate(&st->br), stop, diag);
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
