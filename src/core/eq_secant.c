/* The paper's eq. 2, as published: the plain secant iteration in z from z0 and
 * z0 - SECANT_STEP, with no bracket; kept to reproduce the paper and to compare against.
 * SPDX-License-Identifier: Apache-2.0 */
#include "core/equilibrium.h"

#include <math.h>

typedef struct {
    double z_prev, F_prev; /* the iterate before, m and N */
    tirenv_eq_point cur;   /* the latest iterate */
    double z_next;         /* eq. 2's next iterate, m */
} secant_state;

/* Eq. 2 from the last two iterates; equal forces leave it undefined. */
static int secant_step(secant_state *st, const tirenv_eq_solver *s, tirenv_eq_stop *stop,
                       tirenv_diag *diag)
{
    const double z = st->cur.z, F = st->cur.F;
    if (F == st->F_prev) {
        *stop = TIRENV_EQ_BREAKDOWN;
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                            "secant: equal forces %.6g N at z = %.9g and %.9g m (division by "
                            "zero in eq. 2)", F, st->z_prev, z);
    }
    st->z_next = z - (F - s->G) * (z - st->z_prev) / (F - st->F_prev);
    return TIRENV_OK;
}

static int secant_set(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop,
                      tirenv_diag *diag)
{
    secant_state *st = state;
    tirenv_eq_point p;
    int status = tirenv_eq__eval(s, s->prob.z0, &p, stop, diag);
    if (status)
        return status;
    st->z_prev = p.z;
    st->F_prev = p.F;
    /* The second point is a step like any other: below the admissible range it is not taken
     * (a new load's warm start clamped to z = 0 evaluated the tire 1 mm under the ground), and
     * the step goes up instead, where the eq. 2 line is as good a start. */
    double z1 = s->prob.z0 - s->eq.secant_dz;
    if (!(z1 >= s->prob.z_lo))
        z1 = s->prob.z0 + s->eq.secant_dz;
    if (!(z1 >= s->prob.z_lo && z1 <= s->prob.z_hi)) {
        *stop = TIRENV_EQ_BREAKDOWN;
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                            "secant: no second starting point within the admissible range "
                            "[%.9g, %.9g] m at z0 -+ SECANT_STEP (z0 = %.9g m)",
                            s->prob.z_lo, s->prob.z_hi, s->prob.z0);
    }
    if ((status = tirenv_eq__eval(s, z1, &st->cur, stop, diag)))
        return status;
    return secant_step(st, s, stop, diag);
}

static tirenv_eq_stop secant_test(const void *state, const tirenv_eq_solver *s,
                                  const tirenv_eq_point **accepted)
{
    const secant_state *st = state;
    if (fabs(st->cur.F - s->G) <= s->eq.eps_F && fabs(st->z_next - st->cur.z) <= s->eq.eps_z) {
        *accepted = &st->cur;
        return TIRENV_EQ_RESIDUAL;
    }
    return TIRENV_EQ_RUNNING;
}

static int secant_iterate(void *state, tirenv_eq_solver *s, tirenv_eq_stop *stop,
                          tirenv_diag *diag)
{
    secant_state *st = state;
    if (!isfinite(st->z_next) || st->z_next < s->prob.z_lo) {
        *stop = TIRENV_EQ_BREAKDOWN;
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                            "secant: step left the admissible range (z = %.9g m)", st->z_next);
    }
    st->z_prev = st->cur.z;
    st->F_prev = st->cur.F;
    const int status = tirenv_eq__eval(s, st->z_next, &st->cur, stop, diag);
    return status ? status : secant_step(st, s, stop, diag);
}

static const tirenv_eq_solver_type secant_type = {
    .name = "secant",
    .size = sizeof(secant_state),
    .alloc = NULL,
    .free = NULL,
    .set = secant_set,
    .iterate = secant_iterate,
    .test = secant_test,
};

const tirenv_eq_solver_type *const tirenv_eq__secant = &secant_type;
