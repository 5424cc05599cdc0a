/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model as a tirenv_model_type (docs/models.md section 4). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include "model/deformable.h"
#include "model/springs_impl.h"
#include "tirenv/springs.h"

static void *springs_alloc(const tirenv_tire *tire)
{
    return tirenv_springs_alloc(&tire->springs);
}

static void springs_free(void *elem) { tirenv_springs_free(elem); }

static int springs_forces(void *elem, const tirenv_profile *p, double x, double z,
                          tirenv_eq_point *out, tirenv_diag *diag)
{
    return tirenv_springs_forces(elem, p, x, z, &out->fx, &out->F, &out->dF_dz, &out->contacts,
                                 diag);
}

/* docs/models.md section 1: the springs model's contact length is the chord of the free circle at
 * the centre height, so z_flat follows from l_c in closed form. */
static double springs_R0(void *elem) { return tirenv_springs_params_of(elem)->R0; }

static int springs_contact_length(void *elem, const tirenv_profile *flat, double z, double *l_c,
                                  tirenv_diag *diag)
{
    (void)flat;
    (void)diag;
    const double R0 = springs_R0(elem);
    *l_c = z < R0 ? 2 * sqrt(R0 * R0 - z * z) : 0;
    return 0;
}

static int springs_z_for_contact_length(void *elem, const tirenv_profile *flat, double l_c,
                                        double z_lo, double *z, tirenv_diag *diag)
{
    (void)flat;
    (void)z_lo;
    (void)diag;
    const double R0 = springs_R0(elem);
    *z = sqrt(R0 * R0 - 0.25 * l_c * l_c);
    return 0;
}

static int springs_bracket(void *elem, const tirenv_profile *p, double x, double *z_lo,
                           double *z_hi)
{
    tirenv_springs__bracket(elem, p, x, z_lo, z_hi);
    return 1;
}

static size_t springs_state_size(const void *elem) { return tirenv_springs__state_size(elem); }
static void springs_state_save(const void *elem, unsigned char *buf)
{
    tirenv_springs__state_save(elem, buf);
}
static void springs_state_restore(void *elem, const unsigned char *buf)
{
    tirenv_springs__state_restore(elem, buf);
}

/* docs/models.md section 4.1: the elements span the tread segment |theta| <= phi/2. With the
 * centre below R0*cos(phi/2) the flat ground would reach past the segment's last element, and
 * the elements the model does not have would carry load: its valid range ends there. The
 * default segment, the lower half (phi = pi), ends only with the centre at the ground. */
static int springs_lowest_z(void *elem, const tirenv_profile *flat, double *z, char *why,
                            size_t n, tirenv_diag *diag)
{
    (void)flat;
    (void)diag;
    const tirenv_springs_params *par = tirenv_springs_params_of(elem);
    *z = 0;
    why[0] = '\0';
    if (par->phi < M_PI) {
        *z = par->R0 * cos(0.5 * par->phi);
        snprintf(why, n, "where the flat contact reaches the ends of the tread segment "
                 "(SEGMENT_ANGLE %g rad): beyond, ground would press elements the model does "
                 "not have", par->phi);
    }
    return 0;
}

static const tirenv_deformable springs_deformable = {
    .alloc = springs_alloc,
    .free = springs_free,
    .forces = springs_forces,
    .contact_length = springs_contact_length,
    .z_for_contact_length = springs_z_for_contact_length,
    .lowest_z = springs_lowest_z,
    .bracket = springs_bracket,
    .shift_invariant = tirenv_deformable_invariant,
    .state_size = springs_state_size,
    .state_save = springs_state_save,
    .state_restore = springs_state_restore,
};

/* The stiffnesses that shape h, which a fit identifies, and the free radius on request
 * (docs/models.md section 8); the discretisation (ELEMENT_ANGLE) is a setting, not fitted. */
static const tirenv_model_param springs_params[] = {
    {"RADIAL_STIFFNESS", offsetof(tirenv_tire, springs.c_r), 0},
    {"INTERRADIAL_STIFFNESS", offsetof(tirenv_tire, springs.c_b), 0},
    {"UNLOADED_RADIUS", offsetof(tirenv_tire, springs.R0), 0},
};
static const tirenv_model_fit springs_fit = {springs_params, 2, 3};

static const tirenv_model_type springs_type = {
    .name = "springs",
    .summary = "the paper's radial + interradial springs",
    .flags = TIRENV_MODEL_CONTACT_LENGTH | TIRENV_MODEL_STREAMS,
    .tracks = TIRENV_TRACKS_EQUILIBRIUM,
    .ops = &tirenv_deformable_ops,
    .fit = &springs_fit,
    .deformable = &springs_deformable,
};
const tirenv_model_type *tirenv_model_springs = &springs_type;
