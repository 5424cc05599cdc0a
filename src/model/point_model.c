/* The classic single-point contact as a tirenv_model_type: the tire touches the ground at one
 * point under its centre and follows the raw profile, with no enveloping at all. It is what
 * vehicle models without a tire model assume, and the baseline a ride compares the enveloping
 * models with (docs/models.md section 9.2). SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdlib.h>

#include "profile/profile_impl.h"
#include "model/model_impl.h"

typedef struct {
    tirenv_tire tire;
    const tirenv_profile *prof;
    double G;                /* load, N */
    size_t hint;             /* segment of the last position: a sweep's next is near it */
    tirenv_model *springs;   /* only to translate a contact length into a load */
} point_state;

static void *point_alloc(const tirenv_model_type *type, const tirenv_tire *tire)
{
    (void)type;
    point_state *st = calloc(1, sizeof *st);
    if (st)
        st->tire = *tire;
    return st;
}

static void point_free(void *state)
{
    point_state *st = state;
    tirenv_model_free(st->springs);
    free(st);
}

/* The point does not deflect: the spring of a vehicle model carries the load. */
static int point_flat(void *state, double load, tirenv_flat *out, tirenv_diag *diag)
{
    const point_state *st = state;
    (void)diag;
    *out = (tirenv_flat){.load = load, .z_flat = st->tire.springs.R0, .deflection = 0,
                         .contact_length = 0, .stiffness = INFINITY};
    return TIRENV_OK;
}

/* No contact length of its own: as for the rigid disc, the springs model's load at that
 * chord. */
static int point_load_for_contact_length(void *state, double l_c, double *load,
                                         tirenv_diag *diag)
{
    point_state *st = state;
    return tirenv_model__load_at_chord(&st->springs, &st->tire, l_c, load, diag);
}

static int point_set(void *state, const tirenv_profile *p, double load, double z_flat,
                     tirenv_diag *diag)
{
    point_state *st = state;
    (void)z_flat;
    (void)diag;
    st->prof = p;
    st->G = load;
    st->hint = 0;
    return TIRENV_OK;
}

/* h is the ground under the centre (the higher side of a wall, as tirenv_profile_height
 * says), and the ground force is normal to the ground there: its slope is the segment's
 * (0 on the flat extensions, and on the segment after a wall where x is the wall's). */
static int point_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag)
{
    point_state *st = state;
    if (!isfinite(x))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x", "must be finite, got %g", x);
    const tirenv_profile *p = st->prof;
    const size_t k = st->hint = tirenv_profile__segment_near(p, st->hint, x);
    const double slope = x >= p->x[0] && k + 1 < p->n && p->x[k + 1] > p->x[k]
                             ? (p->z[k + 1] - p->z[k]) / (p->x[k + 1] - p->x[k])
                             : 0;
    const double h = tirenv_profile_height(p, x);
    /* fx = -G*slope, with level ground's 0 written as 0, not -0. */
    const double fx = slope != 0 ? -st->G * slope : 0;
    *out = (tirenv_point){.x = x, .z = st->tire.springs.R0 + h, .h = h, .slope = slope,
                          .fx = fx, .fz = st->G, .contacts = 1, .iterations = 0};
    return TIRENV_OK;
}

/* The load scales the hub forces only: nothing of the profile to redo. */
static int point_set_load(void *state, double load, double *z_flat, tirenv_diag *diag)
{
    point_state *st = state;
    (void)diag;
    st->G = load;
    *z_flat = st->tire.springs.R0;
    return TIRENV_OK;
}

/* The load is all it carries (the search hint changes no result). */
static size_t point_state_size(const void *state)
{
    (void)state;
    return sizeof(double);
}

static void point_state_save(const void *state, unsigned char *buf)
{
    tirenv_model__put(buf, &((const point_state *)state)->G, sizeof(double));
}

/* Its flat-ground height is R0 at every load (point_flat). */
static int point_state_restore(void *state, const unsigned char *buf, double load,
                               double z_flat, tirenv_diag *diag)
{
    point_state *st = state;
    return tirenv_model__restore_load(buf, "point", load, z_flat, st->tire.springs.R0, &st->G,
                                      diag);
}

static const tirenv_model_ops point_ops = {
    .alloc = point_alloc,
    .free = point_free,
    .flat = point_flat,
    .load_for_contact_length = point_load_for_contact_length,
    .set = point_set,
    .set_profile = point_set,
    .set_load = point_set_load,
    .eval = point_eval,
    .reach = tirenv_model__default_reach,  /* it reads the ground at x alone; the default keeps
                                            * windows long */
    .state_size = point_state_size,
    .state_save = point_state_save,
    .state_restore = point_state_restore,
};

static const tirenv_model_type point_type = {
    .name = "point",
    .summary = "single-point contact on the raw profile",
    .flags = TIRENV_MODEL_STREAMS,
    .tracks = TIRENV_TRACKS_MEAN,
    .ops = &point_ops,
};
const tirenv_model_type *tirenv_model_point = &point_type;
