/* SPDX-License-Identifier: Apache-2.0 */
/* The rigid disc as a tirenv_model_type: no deflection, no iteration (docs/models.md section 3). */
#include <math.h>
#include <stdlib.h>
#include "model/model_impl.h"
#include "model/rigid_impl.h"
#include "tirenv/rigid.h"

typedef struct {
    tirenv_tire tire;
    const tirenv_profile *prof;
    double G;
    tirenv_model *springs;   /* only to translate a contact length into a load */
    size_t hint;             /* segment of the last position: a sweep's next is near it */
} rigid_state;

static void *rigid_alloc(const tirenv_model_type *type, const tirenv_tire *tire)
{
    (void)type;
    rigid_state *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    st->tire = *tire;
    return st;
}

static void rigid_free(void *state)
{
    rigid_state *st = state;
    tirenv_model_free(st->springs);
    free(st);
}

static int rigid_flat(void *state, double load, tirenv_flat *out, tirenv_diag *diag)
{
    const rigid_state *st = state;
    (void)diag;
    *out = (tirenv_flat){.load = load, .z_flat = st->tire.springs.R0, .deflection = 0,
                         .contact_length = 0, .stiffness = INFINITY};
    return TIRENV_OK;
}

/* A rigid disc has no contact length; its curve does not depend on the load, which only
 * scales its hub forces. So a contact length stands for a load: the one at which the springs
 * model of the same tire sinks until the disc's chord at its centre height is that long (the
 * disc does not deflect, so its contact length is geometric: docs/models.md section 1.3). */
static int rigid_load_for_contact_length(void *state, double l_c, double *load,
                                         tirenv_diag *diag)
{
    rigid_state *st = state;
    return tirenv_model__load_at_chord(&st->springs, &st->tire, l_c, load, diag);
}

static int rigid_set(void *state, const tirenv_profile *p, double load, double z_flat,
                     tirenv_diag *diag)
{
    rigid_state *st = state;
    (void)z_flat;
    (void)diag;
    st->prof = p;
    st->G = load;
    return TIRENV_OK;
}

/* The ground pushes along the line from the touching point to the centre, so carrying G
 * vertically takes G*(x - p_x)/(z - p_z) horizontally. */
static int rigid_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag)
{
    rigid_state *st = state;
    const double R0 = st->tire.springs.R0;
    double px, pz;
    (void)diag;
    const double z = tirenv_rigid__height_hint(st->prof, R0, x, &st->hint, &px, &pz);
    *out = (tirenv_point){.x = x, .z = z, .h = z - R0, .fz = st->G,
                          .fx = st->G * (x - px) / (z - pz), .contacts = 1, .iterations = 0};
    out->slope = tirenv_model__slope(out);
    return TIRENV_OK;
}

/* The load scales the hub forces only: nothing of the profile to redo. */
static int rigid_set_load(void *state, double load, double *z_flat, tirenv_diag *diag)
{
    rigid_state *st = state;
    (void)diag;
    st->G = load;
    *z_flat = st->tire.springs.R0;
    return TIRENV_OK;
}

/* The load is all it carries (the search hint changes no result). */
static size_t rigid_state_size(const void *state)
{
    (void)state;
    return sizeof(double);
}

static void rigid_state_save(const void *state, unsigned char *buf)
{
    tirenv_model__put(buf, &((const rigid_state *)state)->G, sizeof(double));
}

/* Its flat-ground height is R0 at every load (rigid_flat). */
static int rigid_state_restore(void *state, const unsigned char *buf, double load,
                               double z_flat, tirenv_diag *diag)
{
    rigid_state *st = state;
    return tirenv_model__restore_load(buf, "rigid", load, z_flat, st->tire.springs.R0, &st->G,
                                      diag);
}

static const tirenv_model_ops rigid_ops = {
    .alloc = rigid_alloc,
    .free = rigid_free,
    .flat = rigid_flat,
    .load_for_contact_length = rigid_load_for_contact_length,
    .set = rigid_set,
    .set_profile = rigid_set,
    .set_load = rigid_set_load,
    .eval = rigid_eval,
    .reach = tirenv_model__default_reach,
    .state_size = rigid_state_size,
    .state_save = rigid_state_save,
    .state_restore = rigid_state_restore,
};

static const tirenv_model_type rigid_type = {
    .name = "rigid",
    .summary = "the rigid disc: the geometric limit",
    .flags = TIRENV_MODEL_STREAMS,
    .tracks = TIRENV_TRACKS_HIGHEST,
    .ops = &rigid_ops,
};
const tirenv_model_type *tirenv_model_rigid = &rigid_type;
