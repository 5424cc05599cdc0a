/* The springs model as a tirenv_model_type: constant-load equilibrium per position. */
#include <math.h>
#include <stdlib.h>
#include "core/equilibrium.h"
#include "model/model_impl.h"
#include "tirenv/rigid.h"
#include "tirenv/springs.h"

typedef struct {
    tirenv_springs *s;
    tirenv_tire tire;
    tirenv_profile *flat;        /* flat ground z = 0, for the flat-ground reference */
    const tirenv_profile *prof;  /* current profile (borrowed) */
    double G;                    /* load, N */
    double z_flat;               /* flat-ground centre height at G, m */
    double z_prev;               /* warm start: last equilibrium, m */
    int have_prev;
    /* What the last force evaluation saw, for the output row. */
    const tirenv_profile *eval_prof;
    double eval_x, last_fx;
    size_t last_contacts;
} springs_state;

static int force_at(void *ctx, double z, double *F, double *dF_dz)
{
    springs_state *st = ctx;
    return tirenv_springs_forces(st->s, st->eval_prof, st->eval_x, z, &st->last_fx, F, dF_dz,
                                 &st->last_contacts);
}

static void *springs_alloc(const tirenv_tire *tire)
{
    springs_state *st = calloc(1, sizeof *st);
    const double zero = 0;
    if (!st)
        return NULL;
    st->tire = *tire;
    st->s = tirenv_springs_alloc(&tire->springs);
    st->flat = tirenv_profile_alloc(1, &zero, &zero);
    if (!st->s || !st->flat) {
        tirenv_springs_free(st->s);
        tirenv_profile_free(st->flat);
        free(st);
        return NULL;
    }
    return st;
}

static void springs_free(void *state)
{
    springs_state *st = state;
    tirenv_springs_free(st->s);
    tirenv_profile_free(st->flat);
    free(st);
}

static int springs_flat(void *state, double load, tirenv_flat *out, tirenv_diag *diag)
{
    springs_state *st = state;
    const double R0 = st->tire.springs.R0;
    st->eval_prof = st->flat;
    st->eval_x = 0;
    const tirenv_eq_problem prob = {.z_lo = 0, .z_hi = R0, .z0 = R0, .dz_hint = 0.05 * R0};
    tirenv_eq_result res;
    int status = tirenv_eq_solve(&st->tire.eq, force_at, st, load, &prob, &res, diag);
    if (status)
        return status;
    double F, dF;
    status = force_at(st, res.z, &F, &dF);
    if (status)
        return status;
    *out = (tirenv_flat){
        .load = load,
        .z_flat = res.z,
        .deflection = R0 - res.z,
        .contact_length = 2 * sqrt(R0 * R0 - res.z * res.z),
        .stiffness = -dF,
    };
    return TIRENV_OK;
}

/* MODEL.md section 1: the contact length is the chord of the free circle at z_flat, so z_flat
 * follows from l_c and the load is one force evaluation. */
static int springs_load_for_contact_length(void *state, double l_c, double *load,
                                           tirenv_diag *diag)
{
    springs_state *st = state;
    const double R0 = st->tire.springs.R0;
    if (!(l_c > 0 && l_c < 2 * R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                            "must be in (0, 2*R0) = (0, %g) m, got %g", 2 * R0, l_c);
    st->eval_prof = st->flat;
    st->eval_x = 0;
    double dF;
    return force_at(st, sqrt(R0 * R0 - 0.25 * l_c * l_c), load, &dF);
}

static int springs_set(void *state, const tirenv_profile *p, double load, double z_flat,
                       tirenv_diag *diag)
{
    springs_state *st = state;
    (void)diag;
    st->prof = p;
    st->G = load;
    st->z_flat = z_flat;
    st->have_prev = 0;
    return TIRENV_OK;
}

static int springs_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag)
{
    springs_state *st = state;
    const double R0 = st->tire.springs.R0;
    const double deflection = R0 - st->z_flat;
    const double z_hi = tirenv_rigid_height(st->prof, R0, x, NULL, NULL);
    tirenv_eq_problem prob = {
        .z_lo = tirenv_profile_height(st->prof, x),
        .z_hi = z_hi,
        .z0 = st->have_prev ? st->z_prev : z_hi - deflection,
        .dz_hint = deflection,
    };
    st->eval_prof = st->prof;
    st->eval_x = x;
    tirenv_eq_result res;
    const int status = tirenv_eq_solve(&st->tire.eq, force_at, st, st->G, &prob, &res, diag);
    out->x = x;
    out->iterations = res.evals;
    if (status)
        return status;
    st->z_prev = res.z;
    st->have_prev = 1;
    out->z = res.z;
    out->h = res.z - st->z_flat;
    out->fz = res.F;
    out->fx = st->last_fx;
    out->contacts = st->last_contacts;
    return TIRENV_OK;
}

static const tirenv_model_type springs_type = {
    .name = "springs",
    .alloc = springs_alloc,
    .free = springs_free,
    .flat = springs_flat,
    .load_for_contact_length = springs_load_for_contact_length,
    .set = springs_set,
    .eval = springs_eval,
};
const tirenv_model_type *tirenv_model_springs = &springs_type;
