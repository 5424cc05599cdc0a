/* SPDX-License-Identifier: Apache-2.0 */
/* The generic model driver: name lookup, lifecycle, and the sweep over positions. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "profile/profile_impl.h"
#include "model/model_impl.h"
#include "tirenv/nn.h"
#include "model/model_state.h"

/* The table every command looks names up in: the physical models, the network, and the point
 * contact a ride compares them with. The public type pointers are no constant expressions, so
 * the list is filled at run time, once: filled on every call, two threads looking a name up
 * at once both wrote it (a data race, ThreadSanitizer's report). */
static const tirenv_model_type *const *const types[] = {
    &tirenv_model_rigid, &tirenv_model_springs, &tirenv_model_ring,
    &tirenv_model_cam,   &tirenv_model_nn,      &tirenv_model_point};
static const tirenv_model_type *types_list[sizeof types / sizeof types[0] + 1];
static pthread_once_t types_once = PTHREAD_ONCE_INIT;

static void types_fill(void)
{
    for (size_t i = 0; i < sizeof types / sizeof types[0]; ++i)
        types_list[i] = *types[i];
}

const tirenv_model_type *const *tirenv_model_types(void)
{
    pthread_once(&types_once, types_fill);
    return types_list;
}

const tirenv_model_type *tirenv_model_type_find(const char *name)
{
    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t)
        if (name && strcmp((*t)->name, name) == 0)
            return *t;
    return NULL;
}

const char *tirenv_model_type_name(const tirenv_model_type *type) { return type->name; }
const char *tirenv_model_type_summary(const tirenv_model_type *type) { return type->summary; }
/* The record's own flags and those its sub-records imply. */
unsigned tirenv_model_type_flags(const tirenv_model_type *type)
{
    return type->flags | (type->fit ? TIRENV_MODEL_FITTABLE : 0u) |
           (type->network ? TIRENV_MODEL_NEEDS_NETWORK : 0u) |
           (type->deformable ? TIRENV_MODEL_EQUILIBRIUM : 0u);
}

const tirenv_model_param *tirenv_model_type_params(const tirenv_model_type *type, size_t *n,
                                                   size_t *n_max)
{
    if (n)
        *n = type->fit ? type->fit->n : 0;
    if (n_max)
        *n_max = type->fit ? type->fit->n_max : 0;
    return type->fit ? type->fit->params : NULL;
}
const char *tirenv_model_name(const tirenv_model *m) { return m->type->name; }
const tirenv_tire *tirenv_model_tire(const tirenv_model *m) { return &m->tire; }

tirenv_model *tirenv_model_alloc(const tirenv_model_type *type, const tirenv_tire *tire)
{
    if (!type || tirenv_tire_check(tire, NULL))
        return NULL;
    tirenv_model *m = calloc(1, sizeof *m);
    if (!m)
        return NULL;
    m->type = type;
    m->tire = *tire;
    m->tire_print = tirenv_model__tire_print(tire);
    m->load = NAN;
    m->state = type->ops->alloc(type, tire);
    if (!m->state) {
        free(m);
        return NULL;
    }
    return m;
}

void tirenv_model_free(tirenv_model *m)
{
    if (!m)
        return;
    m->type->ops->free(m->state);
    tirenv_model__tracks_free(m);
    tirenv_nn_free(m->nn);
    free(m);
}

int tirenv_model_set_network(tirenv_model *m, const struct tirenv_nn *nn, double R0,
                             tirenv_diag *diag)
{
    m->ready = 0;
    if (!m->type->network)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "network",
                            "the %s model evaluates no network", m->type->name);
    if (!nn || !(R0 >= 0 && isfinite(R0)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "network",
                            "expected a network and R0 >= 0 m, got %s and %g",
                            nn ? "a network" : "none", R0);
    const int status = m->type->network->set_network(m->state, nn, R0, diag);
    if (status)
        return status;
    /* Kept for the states of further tracks (tirenv_model_set_tracks), which are made later;
     * the old tracks' states knew the old network, so they go. */
    tirenv_nn *copy = tirenv_nn_clone(nn);
    if (!copy)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    tirenv_nn_free(m->nn);
    m->nn = copy;
    m->nn_R0 = R0;
    tirenv_model__tracks_free(m);
    m->n_tracks = 0;
    return TIRENV_OK;
}

int tirenv_model_set_contact_law(tirenv_model *m, const tirenv_contact_law *law,
                                 tirenv_diag *diag)
{
    m->ready = 0;
    if (!m->type->network)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact law",
                            "the %s model takes its contact length from its own flat ground",
                            m->type->name);
    const tirenv_contact_law none = {.n = 0};
    if (!law)
        law = &none;
    int status;
    if (law->n && (status = tirenv_contact_law_check(law, diag)))
        return status;
    m->law = *law;
    m->type->network->set_contact_law(m->state, law);
    /* The other tracks' states knew the old law. */
    tirenv_model__tracks_free(m);
    m->n_tracks = 0;
    return TIRENV_OK;
}

void *tirenv_model__track_state(const tirenv_model *m)
{
    const tirenv_model_ops *ops = m->type->ops;
    const tirenv_model_network *net = m->type->network;
    void *state = ops->alloc(m->type, &m->tire);
    double load;
    if (state && m->nn && net->set_network(state, m->nn, m->nn_R0, NULL) != TIRENV_OK) {
        ops->free(state);
        return NULL;
    }
    if (state && m->law.n)  /* a law is only ever set on a model with a network */
        net->set_contact_law(state, &m->law);
    if (state && m->have_l_c &&
        ops->load_for_contact_length(state, m->l_c, &load, NULL) != TIRENV_OK) {
        ops->free(state);
        return NULL;
    }
    if (state && net) {
        net->set_extrapolate(state, m->extrapolate);
        net->stream_window(state, m->windowed ? &m->window : NULL);
    }
    return state;
}

/* Every track's state is told, those that exist and those made later
 * (tirenv_model__track_state). */
void tirenv_model_set_extrapolate(tirenv_model *m, int allow)
{
    m->extrapolate = allow != 0;
    if (m->type->network)
        m->type->network->set_extrapolate(m->state, m->extrapolate);
    tirenv_model__tracks_extrapolate(m);
}

double tirenv_model_load(const tirenv_model *m) { return m->ready ? m->load : NAN; }
const tirenv_profile *tirenv_model_profile(const tirenv_model *m)
{
    return m->ready ? m->profile : NULL;
}

const char *tirenv_model_warnings(const tirenv_model *m)
{
    if (!(m->ready || m->streamed))
        return "";
    if (m->type->network)
        return m->type->network->warnings(m->state);
    return m->type->ops->warnings ? tirenv_model__tracks_warnings(m) : "";
}

const char *tirenv_model_note(const tirenv_model *m)
{
    return (m->ready || m->streamed) && m->type->network ? m->type->network->note(m->state)
                                                          : "";
}

/* The loads a model takes, wherever a load comes in (flat, set, set_load): positive and
 * finite, and above the equilibrium's force tolerance FORCE_TOLERANCE. Within it of none the
 * springs model's flat ground "converged" with F_z 1.1e-5 N at a load of 1e-319 N, and the
 * cam's tandem base underflowed to 0 m (its slope NaN). */
static int load_ok(const tirenv_model *m, double load, tirenv_diag *diag)
{
    if (!(load > 0) || isinf(load))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "load",
                            "must be a positive finite force in N, got %g", load);
    if (!(load > m->tire.eq.eps_F))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "load",
                            "%g N is within the force tolerance FORCE_TOLERANCE (%g N) of no "
                            "load: no equilibrium tells the two apart", load, m->tire.eq.eps_F);
    return TIRENV_OK;
}

int tirenv_model_flat(tirenv_model *m, double load, tirenv_flat *out, tirenv_diag *diag)
{
    const int status = load_ok(m, load, diag);
    return status ? status : m->type->ops->flat(m->state, load, out, diag);
}

int tirenv_model__load_at_chord(tirenv_model **springs, const tirenv_tire *tire, double l_c,
                                double *load, tirenv_diag *diag)
{
    const double R0 = tire->springs.R0;
    if (!(l_c > 0 && l_c < 2 * R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                            "must be in (0, 2*R0) = (0, %g) m, got %g", 2 * R0, l_c);
    if (!*springs && !(*springs = tirenv_model_alloc(tirenv_model_springs, tire)))
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    tirenv_flat f;
    const int status =
        tirenv_model_flat_at_height(*springs, sqrt(R0 * R0 - 0.25 * l_c * l_c), &f, diag);
    if (!status)
        *load = f.load;
    return status;
}

int tirenv_model_flat_at_height(tirenv_model *m, double z, tirenv_flat *out,
                                tirenv_diag *diag)
{
    if (!m->type->ops->flat_at_height)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model",
                            "the %s model does not deflect: it has no load at a centre height",
                            m->type->name);
    return m->type->ops->flat_at_height(m->state, z, out, diag);
}

/* The network remembers the contact length it was given (model.h): a further track's state is
 * told the same (tirenv_model__track_state), and so are those that exist. */
int tirenv_model_load_for_contact_length(tirenv_model *m, double l_c, double *load,
                                         tirenv_diag *diag)
{
    const int status = m->type->ops->load_for_contact_length(m->state, l_c, load, diag);
    if (status)
        return status;
    m->have_l_c = 1;
    m->l_c = l_c;
    return tirenv_model__tracks_contact_length(m, l_c, diag);
}

/* The highest vertex of a profile, from its block maxima. */
double tirenv_model__profile_top(const tirenv_profile *p)
{
    double top = p->z_block[0];
    for (size_t b = 1; b < p->n_block; ++b)
        top = fmax(top, p->z_block[b]);
    return top;
}

/* What the driver keeps of a load just set (O(1)); a new profile's top is the caller's. */
void tirenv_model__took(tirenv_model *m, const tirenv_profile *profile, double load, double z_flat)
{
    m->profile = profile;
    m->load = load;
    m->z_flat = z_flat;
    m->ready = 1;
    m->streamed = 0;
    m->reach = tirenv_model_reach(m);
}

int tirenv_model_set(tirenv_model *m, const tirenv_profile *profile, double load,
                     tirenv_diag *diag)
{
    tirenv_flat flat;
    m->ready = 0;
    m->n_tracks = 0;
    if (!profile)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "profile", "expected a profile, got NULL");
    int status = tirenv_model_flat(m, load, &flat, diag);
    if (!status)
        status = m->type->ops->set(m->state, profile, load, flat.z_flat, diag);
    if (!status) {
        m->z_top = tirenv_model__profile_top(profile);  /* the same address may hold another profile */
        tirenv_model__took(m, profile, load, flat.z_flat);
        m->n_tracks = 1;
    } else {
        m->profile = NULL;  /* the type may hold the new one half-set: nothing to restore on */
    }
    return status;
}

/* The type's own load change on one track; on several, each track's (tracks.c). */
int tirenv_model_set_load(tirenv_model *m, double load, tirenv_diag *diag)
{
    if (!m->ready)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model",
                            "no profile and load set (call tirenv_model_set first)");
    int status = load_ok(m, load, diag);
    if (status || load == m->load)
        return status;
    if (m->n_tracks > 1)  /* every track's state at the new load */
        return tirenv_model__tracks_set_load(m, load, diag);
    double z_flat;
    status = m->type->ops->set_load(m->state, load, &z_flat, diag);
    if (!status)
        tirenv_model__took(m, m->profile, load, z_flat);
    return status;
}

/* The type's set with the load and z_flat already found: no flat-ground solve per window.
 * The warm start is the type's business; the deformable models restart theirs in set. */
int tirenv_model_set_profile(tirenv_model *m, const tirenv_profile *profile, tirenv_diag *diag)
{
    if (!profile) {
        m->ready = 0;
        m->profile = NULL;
        return TIRENV_OK;
    }
    if (!m->ready)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model",
                            "no profile and load set (call tirenv_model_set first)");
    if (m->n_tracks > 1) {
        m->ready = 0;
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model",
                            "set with %zu tracks: use tirenv_model_set_track_profiles",
                            m->n_tracks);
    }
    const int status = m->type->ops->set_profile(m->state, profile, m->load, m->z_flat, diag);
    if (status) {
        m->ready = 0;
        m->profile = NULL;
    } else {
        m->z_top = tirenv_model__profile_top(profile);
        tirenv_model__took(m, profile, m->load, m->z_flat);
    }
    return status;
}

double tirenv_model_reach(const tirenv_model *m)
{
    return m->type->ops->reach(m->state, &m->tire);
}

/* 5 % beyond R0 covers the rigid disc, the springs and the ring, which touch the ground only
 * within R0 of the centre's x. */
double tirenv_model__default_reach(const void *state, const tirenv_tire *tire)
{
    (void)state;
    return TIRENV_MODEL__REACH * tire->springs.R0;
}

/* Names the position: a failure without its x is useless in a 1,500-point sweep. */
static int at_position(const tirenv_model *m, double x, int status, tirenv_diag *diag)
{
    if (status && diag) {
        char msg[sizeof diag->message];  /* the original message is cut at 400 chars */
        snprintf(msg, sizeof msg, "%s model at x = %.6g m, load %.6g N: %.400s", m->type->name, x,
                 m->load, diag->message);
        memcpy(diag->message, msg, sizeof msg);
    }
    return status;
}

static int not_set(tirenv_diag *diag)
{
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model",
                        "no profile and load set (call tirenv_model_set first)");
}

/* The enveloping models assume the hub clears the ground (docs/models.md section 2.5): no
 * ground within the tire's free radius R0 of x (horizontally: where the free circle stands)
 * may rise to the centre's height at x. A tire rolling off a cliff has ground above its hub
 * once it is past the edge, farther than R0 behind: that is not refused. Checked where the
 * model is evaluated, so that a road may climb any height: O(1) when the whole profile is
 * below the centre, else O(log n + the vertices within R0). */
static int clears_ground(const tirenv_model *m, const tirenv_point *pt, tirenv_diag *diag)
{
    if (m->z_top < pt->z)
        return TIRENV_OK;
    const double x = pt->x, R0 = m->tire.springs.R0;
    const double top = m->n_tracks > 1 ? tirenv_model__tracks_max_height(m, x - R0, x + R0)
                                       : tirenv_profile_max_height(m->profile, x - R0, x + R0);
    if (top < pt->z)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_ERANGE, "", 0, "profile",
                        "ground at %.6g m within the tire's radius %.4g m of the centre rises "
                        "to the centre's height %.6g m: the enveloping models assume the hub "
                        "clears the ground", top, R0, pt->z);
}

/* A position that is not a number of metres: refused before any model spends its solver's
 * budget on it (an equilibrium once took 100 evaluations to fail with a bracket of NaNs). */
static int finite_position(double x, tirenv_diag *diag)
{
    return isfinite(x) ? TIRENV_OK
                       : tirenv_error(diag, TIRENV_EINVAL, "", 0, "x",
                                      "a position must be finite, got %g m", x);
}

int tirenv_model_eval(tirenv_model *m, double x, tirenv_point *out, tirenv_diag *diag)
{
    out->x = x;  /* as the header promises, on failure too */
    if (!m->ready)
        return not_set(diag);
    if (finite_position(x, diag))
        return TIRENV_EINVAL;
    int status = m->n_tracks > 1 ? tirenv_model__tracks_eval(m, x, out, diag)
                                       : m->type->ops->eval(m->state, x, out, diag);
    out->x = x;
    if (!status)
        status = clears_ground(m, out, diag);
    return at_position(m, x, status, diag);
}

int tirenv_model_envelope(tirenv_model *m, size_t n, const double x[], tirenv_point out[],
                          size_t *failed, tirenv_diag *diag)
{
    /* Several tracks, or a type with a batched sweep (the network): the whole sweep, then the
     * hub's check position by position. */
    const int tracks = m->ready && m->n_tracks > 1;
    if ((tracks || m->type->network) && n > 0) {
        if (!m->ready) {
            if (failed)
                *failed = 0;
            return not_set(diag);
        }
        size_t k = 0;
        while (k < n && isfinite(x[k]))
            ++k;
        if (k < n) {
            if (failed)
                *failed = k;
            return finite_position(x[k], diag);
        }
        int status = tracks ? tirenv_model__tracks_envelope(m, n, x, out, &k, diag)
                            : m->type->network->envelope(m->state, n, x, out, &k, diag);
        if (!status)
            for (k = 0; k < n && !(status = clears_ground(m, &out[k], diag)); ++k)
                ;
        if (status && failed)
            *failed = k;
        return at_position(m, status ? x[k < n ? k : 0] : 0, status, diag);
    }
    for (size_t k = 0; k < n; ++k) {
        const int status = tirenv_model_eval(m, x[k], &out[k], diag);
        if (status) {
            if (failed)
                *failed = k;
            return status;
        }
    }
    return TIRENV_OK;
}
