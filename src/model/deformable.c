/* The constant-load equilibrium per position (docs/models.md section 11), shared by every
 * deformable model: it only needs their hub-force function and their contact length. */
#include "model/deformable.h"

#include <math.h>
#include <stdlib.h>
#include "core/equilibrium.h"
#include "model/rigid_impl.h"
#include "profile/profile_impl.h"

typedef struct {
    const tirenv_deformable_ops *ops;
    void *elem;                  /* the model's own workspace */
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
    size_t rigid_hint;           /* profile segment of the last position, for the bracket */
    /* The flat-ground equilibrium at the load set, for level stretches of ground. */
    int shift_invariant;
    double flat_F;
    size_t flat_contacts;
} deformable_state;

static int force_at(void *ctx, double z, double *F, double *dF_dz)
{
    deformable_state *st = ctx;
    return st->ops->forces(st->elem, st->eval_prof, st->eval_x, z, &st->last_fx, F, dF_dz,
                           &st->last_contacts);
}

void *tirenv_deformable_alloc(const tirenv_tire *tire, const tirenv_deformable_ops *ops)
{
    deformable_state *st = calloc(1, sizeof *st);
    const double zero = 0;
    if (!st)
        return NULL;
    st->ops = ops;
    st->tire = *tire;
    st->elem = ops->alloc(tire);
    st->shift_invariant = !ops->shift_invariant || ops->shift_invariant(tire);
    st->flat = tirenv_profile_alloc(1, &zero, &zero);
    if (!st->elem || !st->flat) {
        tirenv_deformable_free(st);
        return NULL;
    }
    return st;
}

void tirenv_deformable_free(void *state)
{
    deformable_state *st = state;
    if (st->elem)
        st->ops->free(st->elem);
    tirenv_profile_free(st->flat);
    free(st);
}

int tirenv_deformable_flat(void *state, double load, tirenv_flat *out, tirenv_diag *diag)
{
    deformable_state *st = state;
    const double R0 = st->tire.springs.R0;
    st->eval_prof = st->flat;
    st->eval_x = 0;
    const tirenv_eq_problem prob = {.z_lo = 0, .z_hi = R0, .z0 = R0, .dz_hint = 0.05 * R0};
    tirenv_eq_result res;
    int status = tirenv_eq_solve(&st->tire.eq, force_at, st, load, &prob, &res, diag);
    if (status)
        return status;
    double F, dF, l_c;
    status = force_at(st, res.z, &F, &dF);
    if (!status)
        status = st->ops->contact_length(st->elem, st->flat, res.z, &l_c);
    if (status)
        return status;
    *out = (tirenv_flat){
        .load = load,
        .z_flat = res.z,
        .deflection = R0 - res.z,
        .contact_length = l_c,
        .stiffness = -dF,
    };
    return TIRENV_OK;
}

/* The model's own contact-length definition gives z_flat; the load is one force there. */
int tirenv_deformable_load_for_contact_length(void *state, double l_c, double *load,
                                              tirenv_diag *diag)
{
    deformable_state *st = state;
    const double R0 = st->tire.springs.R0;
    if (!(l_c > 0 && l_c < 2 * R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                            "must be in (0, 2*R0) = (0, %g) m, got %g", 2 * R0, l_c);
    double z, dF;
    const int status = st->ops->z_for_contact_length(st->elem, st->flat, l_c, &z, diag);
    if (status)
        return status;
    st->eval_prof = st->flat;
    st->eval_x = 0;
    return force_at(st, z, load, &dF);
}

int tirenv_deformable_set(void *state, const tirenv_profile *p, double load, double z_flat,
                          tirenv_diag *diag)
{
    deformable_state *st = state;
    st->prof = p;
    st->G = load;
    st->z_flat = z_flat;
    st->have_prev = 0;
    st->eval_prof = st->flat;
    st->eval_x = 0;
    double dF;
    const int status = force_at(st, z_flat, &st->flat_F, &dF);
    st->flat_contacts = st->last_contacts;
    return status ? tirenv_error(diag, status, "", 0, "", "the flat-ground forces failed")
                  : TIRENV_OK;
}

/* The next window of the same ground: the equilibrium of the last position still holds, so the
 * warm start carries over and a stream gives the same iterations as one whole profile. */
void tirenv_deformable_set_profile(void *state, const tirenv_profile *p)
{
    deformable_state *st = state;
    st->prof = p;
}

int tirenv_deformable_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag)
{
    deformable_state *st = state;
    const double R0 = st->tire.springs.R0;
    /* Level ground within reach (the default reach of model_impl.h): the flat-ground
     * equilibrium shifted by the level, with no force evaluation. The solver would land
     * within its tolerance of the same height; a road's run-in and run-out cost nothing. */
    double level;
    if (st->shift_invariant &&
        tirenv_profile__level(st->prof, x - TIRENV_MODEL__REACH * R0,
                              x + TIRENV_MODEL__REACH * R0, &level)) {
        /* fx is 0 by symmetry, which the force sum only meets to round-off. */
        *out = (tirenv_point){.x = x, .z = st->z_flat + level, .h = level, .fx = 0,
                              .fz = st->flat_F, .contacts = st->flat_contacts};
        st->z_prev = out->z;
        st->have_prev = 1;
        return TIRENV_OK;
    }
    const double deflection = R0 - st->z_flat;
    const double z_hi = tirenv_rigid__height_hint(st->prof, R0, x, &st->rigid_hint, NULL, NULL);
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
