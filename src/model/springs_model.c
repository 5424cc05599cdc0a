/* The springs model as a tirenv_model_type (docs/models.md section 4). */
#include <math.h>
#include "model/deformable.h"
#include "tirenv/springs.h"

static void *springs_alloc(const tirenv_tire *tire)
{
    return tirenv_springs_alloc(&tire->springs);
}

static void springs_free(void *elem) { tirenv_springs_free(elem); }

/* The force callback carries no diagnostic, so why an evaluation was refused (ground the
 * rays cannot see) travels from the callback to springs_eval, on the same thread, here. */
static _Thread_local struct {
    int set;
    tirenv_diag diag;
} refusal;

static int springs_forces(void *elem, const tirenv_profile *p, double x, double z, double *fx,
                          double *fz, double *dfz_dz, size_t *contacts)
{
    const int status = tirenv_springs_forces(elem, p, x, z, fx, fz, dfz_dz, contacts);
    if (status == TIRENV_ERANGE) {
        tirenv_springs_refusal(elem, &refusal.diag);
        refusal.set = 1;
    }
    return status;
}

/* docs/models.md section 1: the springs model's contact length is the chord of the free circle at
 * the centre height, so z_flat follows from l_c in closed form. */
static double springs_R0(void *elem) { return tirenv_springs_params_of(elem)->R0; }

static int springs_contact_length(void *elem, const tirenv_profile *flat, double z, double *l_c)
{
    (void)flat;
    const double R0 = springs_R0(elem);
    *l_c = z < R0 ? 2 * sqrt(R0 * R0 - z * z) : 0;
    return 0;
}

static int springs_z_for_contact_length(void *elem, const tirenv_profile *flat, double l_c,
                                        double *z, tirenv_diag *diag)
{
    (void)flat;
    (void)diag;
    const double R0 = springs_R0(elem);
    *z = sqrt(R0 * R0 - 0.25 * l_c * l_c);
    return 0;
}

static const tirenv_deformable_ops springs_ops = {
    .alloc = springs_alloc,
    .free = springs_free,
    .forces = springs_forces,
    .contact_length = springs_contact_length,
    .z_for_contact_length = springs_z_for_contact_length,
};

static void *springs_model_alloc(const tirenv_tire *tire)
{
    return tirenv_deformable_alloc(tire, &springs_ops);
}

static int springs_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag)
{
    refusal.set = 0;
    const int status = tirenv_deformable_eval(state, x, out, diag);
    if (status == TIRENV_ERANGE && refusal.set && diag)
        *diag = refusal.diag;
    return status;
}

/* TIRENV_DEFORMABLE_TYPE with its own eval, for the message above. */
static const tirenv_model_type springs_type = {
    .name = "springs", .alloc = springs_model_alloc, .free = tirenv_deformable_free,
    .flat = tirenv_deformable_flat,
    .load_for_contact_length = tirenv_deformable_load_for_contact_length,
    .set = tirenv_deformable_set, .eval = springs_eval,
    .set_profile = tirenv_deformable_set_profile,
};
const tirenv_model_type *tirenv_model_springs = &springs_type;
