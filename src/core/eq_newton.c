/* The safeguarded Newton of docs/models.md section 11, the default equilibrium method.
 * SPDX-License-Identifier: Apache-2.0
 *
 * F_z never increases with z and is 0 above first contact, so with f = F - G the bracket
 * [lo, hi] keeps f(lo) >= 0 > f(hi). Newton's step is taken when it stays inside and
 * converges: the model's own where it gives one (has_root: the springs model's root on its
 * QP's working set, docs/models.md section 4.8; the ring's parabola, section 5.3), else
 * -f / dF/dz, with the solve's latest slope at an iterate near the root whose own the model
 * left out (take); otherwise the step falls back to bisection, as in Numerical Recipes'
 * rtsafe. Converged when the residual and that next correction are within eps_F and eps_z
 * (section 11.3), or when the bracket is
 * narrower than eps_z: F_z can jump (a ray sweeping over a convex corner changes the face it
 * hits, so its length jumps), and then the equilibrium is the jump, located to eps_z, and the
 * end of the bracket with the smaller residual is reported as it was evaluated. The first
 * iterate is the model's proposal where it makes one inside the bracket (prob.start: the
 * springs model's root at a new x on the last position's working set), else z0. */
#include "core/equilibrium.h"

#include <math.h>

typedef struct {
    double lo, hi;         /* the bracket, m */
    double f_lo, f_hi;     /* f at its ends, N (f_lo NaN until checked) */
    int lo_checked;        /* f(lo) >= 0 is known, not only expected */
    double down;           /* the step from a guess with no contact, m; grows each time */
    double dz_old, last_dz;/* the steps before, m, to see Newton stall */
    tirenv_eq_point cur;   /* the latest iterate */
    double step;           /* Newton's correction from it, m (INFINITY if dF/dz >= 0) */
    double k;              /* the latest dF/dz of this solve, N/m (NaN: none yet) */
} newton_state;

/* A new iterate: the bracket, and the correction Newton proposes from it (the model's own
 * where it gives one). Where the force function left dF/dz out (prob.slope) it is asked for,
 * but not at an iterate within eps_F of the load whose correction by the solve's latest slope
 * is within half of eps_z: the test accepts it (its own correction is within eps_z unless
 * dF/dz halved since, over a fraction of a micrometre at one x), and the equilibrium is
 * reached without the slope of its last evaluation, which nothing after reads. */
static int take(newton_state *st, tirenv_eq_solver *s, tirenv_eq_point *p,
                tirenv_eq_stop *stop, tirenv_diag *diag)
{
    const double G = s->G, f = p->F - G;
    double est = NAN;
    if (isnan(p->dF_dz) && s->prob.slope) {
        if (fabs(f) <= s->eq.eps_F && st->k < 0 && fabs(f) <= 0.5 * s->eq.eps_z * -st->k)
            est = -f / st->k;
        else {
            const int status = tirenv_eq__slope(s, p, stop, diag);
            if (status)
                return status;
        }
    }
    if (f >= 0) {
        st->lo = p->z;
        st->f_lo = f;
        st->lo_checked = 1;
    } else {
        st->hi = p->z;
        st->f_hi = f;
    }
    st->cur = *p;
    if (!isnan(p->dF_dz))
        st->k = p->dF_dz;
    st->step = !isnan(est)      ? est
               : p->has_root    ? p->z_root - p->z
               : p->dF_dz < 0   ? -f / p->dF_dz
                                : INFINITY;
    return TIRENV_OK;
}

static int newton_set(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop,
                      tirenv_diag *diag)
{
    newton_state *st = state;
    const tirenv_eq_problem *prob = &s->prob;
    *st = (newton_state){.lo = prob->z_lo, .hi = prob->z_hi, .f_lo = NAN, .f_hi = -s->G,
                         .lo_checked = 0, .down = prob->dz_hint, .dz_old = INFINITY,
                         .last_dz = INFINITY, .k = NAN};
    double z = fmin(fmax(prob->z0, st->lo), st->hi), z_start;
    if (prob->start && prob->start(s->ctx, z, &z_start) && z_start > st->lo &&
        z_start < st->hi)
        z = z_start;
    tirenv_eq_point p;
    int status = tirenv_eq__eval(s, z, &p, stop, diag);
    if (!status)
        status = take(st, s, &p, stop, diag);
    return status;
}

static tirenv_eq_stop newton_test(const void *state, const tirenv_eq_solver *s,
                                  const tirenv_eq_point **accepted)
{
    const newton_state *st = state;
    if (fabs(st->cur.F - s->G) <= s->eq.eps_F && fabs(st->step) <= s->eq.eps_z) {
        *accepted = &st->cur;
        return TIRENV_EQ_RESIDUAL;
    }
    if (st->lo_checked && st->hi - st->lo <= s->eq.eps_z) {
        /* The ends of the bracket are the latest evaluations on either side of the root. */
        const int above = s->have_above &&
                          fabs(s->above.F - s->G) < fabs(s->below.F - s->G);
        *accepted = above ? &s->above : &s->below;
        return TIRENV_EQ_BRACKET;
    }
    return TIRENV_EQ_RUNNING;
}

static int newton_iterate(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop,
                          tirenv_diag *diag)
{
    newton_state *st = state;
    const double G = s->G, z = st->cur.z, f = st->cur.F - G, dF = st->cur.dF_dz;
    double z_next = z + st->step;
    /* Newton that leaves the bracket, or does not halve the step from the step before last
     * (it oscillates across a jump of F_z), gives way to bisection. */
    const int stalled = fabs(2 * st->step) > st->dz_old;
    if (!(z_next > st->lo && z_next < st->hi) || (stalled && st->lo_checked)) {
        if (dF >= 0 && f < 0 && z > st->lo) {
            /* No contact yet: the discrete elements can miss a corner that the rigid disc
             * (z_hi) touches, so the first contact may lie well below. Not at the bracket's
             * lower end, where there is no below: a start at z = 0 (a new load's warm start
             * clamped there) met a force flat in z and stepped to 0 again until the
             * evaluations ran out; the end's check below names the load it carries. */
            z_next = fmax(z - st->down, 0.5 * (st->lo + st->hi));
            st->down *= 4;
        } else if (st->lo_checked) {
            z_next = 0.5 * (st->lo + st->hi);
        } else {
            /* Verify the bracket's lower end before relying on it: the iterate itself when it
             * is there, else one more evaluation. */
            st->lo_checked = 1;
            tirenv_eq_point p = st->cur;
            /* (Its slope, not read, asked for as every evaluation's but the last: the model's
             * next start is made from it.) */
            int status = z == st->lo ? 0 : tirenv_eq__eval(s, st->lo, &p, stop, diag);
            if (!status && z != st->lo)
                status = tirenv_eq__slope(s, &p, stop, diag);
            if (status)
                return status;
            if (p.F < G) {
                *stop = TIRENV_EQ_NO_BRACKET;
                return tirenv_error(diag, TIRENV_ENOBRACKET, "", 0, "load",
                                    "load %.6g N exceeds the %.6g N the tire carries with its "
                                    "centre at the ground (z = %.6g m)",
                                    G, p.F, st->lo);
            }
            st->f_lo = p.F - G;
            /* One false-position step. */
            z_next = st->lo + st->f_lo * (st->hi - st->lo) / (st->f_lo - st->f_hi);
        }
    }
    st->dz_old = st->last_dz;
    st->last_dz = fabs(z_next - z);
    tirenv_eq_point p;
    int status = tirenv_eq__eval(s, z_next, &p, stop, diag);
    if (!status)
        status = take(st, s, &p, stop, diag);
    return status;
}

static const tirenv_eq_solver_type newton_type = {
    .name = "newton",
    .size = sizeof(newton_state),
    .alloc = NULL,
    .free = NULL,
    .set = newton_set,
    .iterate = newton_iterate,
    .test = newton_test,
};

const tirenv_eq_solver_type *const tirenv_eq__newton = &newton_type;
