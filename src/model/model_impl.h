/* SPDX-License-Identifier: Apache-2.0 */
/* Private: what a model algorithm provides to the generic driver in model.c: its type record,
 * written out field by field in the algorithm's file as GSL writes gsl_root_fsolver_brent at
 * the end of roots/brent.c. */
#ifndef TIRENV_MODEL_IMPL_H
#define TIRENV_MODEL_IMPL_H

#include <string.h>

#include "core/equilibrium.h"
#include "tirenv/model.h"
#include "tirenv/nn_road.h"
#include "tirenv/tracks.h"

/* What every model does, as functions of its state: all set. A type with nothing of its own
 * to say names the driver's default (tirenv_model__default_reach), or its set where a window
 * of the same ground is as good as a new one. The deformable models share one record,
 * tirenv_deformable_ops (deformable.h), around what is their own. */
typedef struct {
    /* The state for a tire (the type is passed for the records behind it); NULL on
     * failure. */
    void *(*alloc)(const tirenv_model_type *type, const tirenv_tire *tire);
    void (*free)(void *state);
    int (*flat)(void *state, double load, tirenv_flat *out, tirenv_diag *diag);
    int (*load_for_contact_length)(void *state, double l_c, double *load, tirenv_diag *diag);
    /* The flat-ground state with the centre at height z (m); NULL for a model that does not
     * deflect (tirenv_model_flat_at_height then refuses). */
    int (*flat_at_height)(void *state, double z, tirenv_flat *out, tirenv_diag *diag);
    /* New profile and load; z_flat is the model's flat-ground centre height at that load. */
    int (*set)(void *state, const tirenv_profile *p, double load, double z_flat,
               tirenv_diag *diag);
    /* Another window of the same ground at the same load and z_flat (streaming): a type with
     * a warm start keeps it; one without names its set. */
    int (*set_profile)(void *state, const tirenv_profile *p, double load, double z_flat,
                       tirenv_diag *diag);
    /* A new load (N) on the profile already set, at the cost of the work within the tire's
     * reach: what depends on the profile alone is kept, and so is the warm start. The
     * flat-ground centre height at the new load in *z_flat (m). On failure nothing of the
     * state has changed. */
    int (*set_load)(void *state, double load, double *z_flat, tirenv_diag *diag);
    /* One position: every field of *out but x (set by the driver). */
    int (*eval)(void *state, double x, tirenv_point *out, tirenv_diag *diag);
    /* How far from x (m) eval reads the profile at the load set (tirenv_model_reach);
     * tirenv_model__default_reach: TIRENV_MODEL__REACH*R0. */
    double (*reach)(const void *state, const tirenv_tire *tire);
    /* The bytes of what the model carries from one call to the next besides its profile
     * (load, warm start, caches whose content can change a bit of a result), for
     * tirenv_model_state_save / _restore. state_size is fixed for an instance (it may depend
     * on the tire, never on what was evaluated); save writes exactly that many bytes; restore
     * reads them back into an instance of the same type and tire whose profile is set, and
     * may fail with diag filled (then the instance is unset by the driver). load (N) and
     * z_flat (m) are the driver's, from the state's head: a type that keeps its own copy, or
     * what it follows from, refuses a state where the two disagree (docs/models.md section
     * 1.7), so that the driver and the type never answer from two loads. */
    size_t (*state_size)(const void *state);
    void (*state_save)(const void *state, unsigned char *buf);
    int (*state_restore)(void *state, const unsigned char *buf, double load, double z_flat,
                         tirenv_diag *diag);
    /* What a user should hear about the evaluations since the last set (tirenv_model_warnings;
     * a network's are its own, tirenv_model_network); NULL: never anything. */
    const char *(*warnings)(const void *state);
} tirenv_model_ops;

/* The tire parameters a fit identifies (tirenv_model_type_params): the first n by default,
 * n_max with the optional ones. */
typedef struct {
    const tirenv_model_param *params;
    size_t n, n_max;
} tirenv_model_fit;

/* What only a model that evaluates a trained network has (the nn): every member set. */
typedef struct {
    /* The network (to be copied) and the R0 (m) of its x_N. */
    int (*set_network)(void *state, const struct tirenv_nn *nn, double R0, tirenv_diag *diag);
    /* The load-to-contact-length relation of its tire (n = 0: none). */
    void (*set_contact_law)(void *state, const tirenv_contact_law *law);
    /* Whether set may evaluate outside the trained range (tirenv_model_set_extrapolate). */
    void (*set_extrapolate)(void *state, int allow);
    /* The warnings and the note of the last set (tirenv_model_warnings, _note). */
    const char *(*warnings)(const void *state);
    const char *(*note)(const void *state);
    /* A whole sweep at once, through the network's batch path. */
    int (*envelope)(void *state, size_t n, const double x[], tirenv_point out[],
                    size_t *failed, tirenv_diag *diag);
    /* The profiles set from now on are windows of one road (stream.c), w says where (what a
     * model whose results depend on more than the ground within its reach must know: the
     * nn's resampling grid is anchored at the road's first vertex, docs/models.md section
     * 12); NULL: whole profiles again. */
    void (*stream_window)(void *state, const tirenv_nn_road_window *w);
} tirenv_model_network;

typedef struct tirenv_deformable tirenv_deformable;  /* deformable.h */

/* A model algorithm, in the manner of GSL's gsl_root_fsolver_type: its name, what it is, the
 * functions every model has, and one pointer for each thing only some models have (NULL: the
 * model has none of it). The flags that follow from those pointers (FITTABLE, NEEDS_NETWORK,
 * EQUILIBRIUM) are the driver's to add (tirenv_model_type_flags). */
struct tirenv_model_type {
    const char *name;
    const char *summary;       /* what the model is, in 48 characters or fewer */
    unsigned flags;            /* TIRENV_MODEL_CONTACT_LENGTH, TIRENV_MODEL_STREAMS (model.h) */
    /* How several tracks across the width combine (tirenv/tracks.h, docs/models.md section
     * 13); TIRENV_TRACKS_EQUILIBRIUM for a deformable model and only for one. */
    tirenv_tracks_rule tracks;
    const tirenv_model_ops *ops;
    const tirenv_model_fit *fit;             /* what a fit identifies */
    const tirenv_deformable *deformable;     /* a hub force under the shared equilibrium */
    const tirenv_model_network *network;     /* a trained network */
};

/* The default reach: TIRENV_MODEL__REACH*R0 of the tire, whatever the state. */
double tirenv_model__default_reach(const void *state, const tirenv_tire *tire);

struct tirenv_model__tracks;  /* several tracks (tracks.c) */

/* A model instance (model.c, model_state.c, tracks.c): the type's state and what the driver
 * keeps. */
struct tirenv_model {
    const tirenv_model_type *type;
    void *state;
    tirenv_tire tire;
    unsigned long long tire_print; /* fingerprint of the tire, for state restores */
    const tirenv_profile *profile; /* the last profile set (borrowed), NULL if none */
    double load;                   /* N */
    double z_flat;                 /* flat-ground centre height at load, m */
    double reach;                  /* tirenv_model_reach at the load set, m */
    double z_top;                  /* the profile's highest vertex, m */
    int ready;                     /* a profile and load are set */
    size_t n_tracks;               /* distinct tracks set: 1 by tirenv_model_set, 0 before */
    struct tirenv_model__tracks *tracks; /* the other tracks' states, NULL until needed */
    /* What a new track's state must be told that the first one was: the network (a copy) and
     * the R0 of its x_N, and the last contact length given (the network remembers it). */
    struct tirenv_nn *nn;
    double nn_R0;                  /* m */
    tirenv_contact_law law;        /* the network's tire, for further tracks; n = 0: none */
    int have_l_c;
    double l_c;                    /* m */
    int extrapolate;               /* tirenv_model_set_extrapolate's, given to every track */
    int windowed;                  /* profiles are windows of one road (stream.c): */
    tirenv_nn_road_window window;  /* where the current one sits, given to every track */
    int streamed;                  /* a streamed sweep ended: the model is unset, but its
                                    * warnings and note (the windows') stay until a set */
};

/* stream.c: tells every track's state that the profiles set from now on are windows of one
 * road (w), or whole again (NULL); a no-op for a type without a network. */
void tirenv_model__stream_window(tirenv_model *m, const tirenv_nn_road_window *w);

/* tracks.c: the first of the tracks' states' own warnings (ops->warnings) that is not "". */
const char *tirenv_model__tracks_warnings(const tirenv_model *m);

/* Private to model.c and tracks.c: a new type state for a further track, told what the first
 * was told (network, contact length, extrapolation); NULL if out of memory or the network
 * fails. */
void *tirenv_model__track_state(const tirenv_model *m);

/* model.c: a profile's highest vertex (m), and the driver's record of a profile and load
 * just set (profile, load, z_flat, ready, reach; the caller sets z_top). */
double tirenv_model__profile_top(const tirenv_profile *p);
void tirenv_model__took(tirenv_model *m, const tirenv_profile *profile, double load,
                        double z_flat);

/* tracks.c: the driver's hooks for several tracks (m->n_tracks > 1). */
void tirenv_model__tracks_free(tirenv_model *m);  /* and m->tracks = NULL */
/* The contact length just given to the first track's state, given to the others too. */
int tirenv_model__tracks_contact_length(tirenv_model *m, double l_c, tirenv_diag *diag);
/* Whether the model may extrapolate (m->extrapolate), given to the others too. */
void tirenv_model__tracks_extrapolate(tirenv_model *m);
int tirenv_model__tracks_eval(tirenv_model *m, double x, tirenv_point *out,
                              tirenv_diag *diag);
/* A new load on every track (tirenv_model_set_load); the highest ground of the tracks over
 * [x0, x1] (m), for the hub's check. */
int tirenv_model__tracks_set_load(tirenv_model *m, double load, tirenv_diag *diag);
double tirenv_model__tracks_max_height(const tirenv_model *m, double x0, double x1);
int tirenv_model__tracks_envelope(tirenv_model *m, size_t n, const double x[],
                                  tirenv_point out[], size_t *failed, tirenv_diag *diag);

/* Sequential reading and writing of a state's bytes (no alignment assumed): each returns the
 * position after what it moved. */
static inline unsigned char *tirenv_model__put(unsigned char *p, const void *v, size_t n)
{
    memcpy(p, v, n);
    return p + n;
}
static inline const unsigned char *tirenv_model__get(const unsigned char *p, void *v, size_t n)
{
    memcpy(v, p, n);
    return p + n;
}

/* A state that is a load alone (rigid, point): the load at buf into *G, refused (naming the
 * type) unless a positive finite number, since it is the answer's F_z, and unless it is the
 * head's load and the head's z_flat is the type's own, z_own (m) (bytes a host may have
 * changed: docs/models.md section 1.7). */
int tirenv_model__restore_load(const unsigned char *buf, const char *type, double load,
                               double z_flat, double z_own, double *G, tirenv_diag *diag);

/* The default reach in units of R0: a tire of free radius R0 touches no ground farther than
 * R0 from its centre; 5 % covers a tread standing out of the free circle. */
#define TIRENV_MODEL__REACH 1.05

/* The effective road slope of docs/models.md section 1 from a point's forces: the inclination
 * -fx/fz of the resultant ground force (never 0/0: at equilibrium fz is the load). */
static inline double tirenv_model__slope(const tirenv_point *pt)
{
    return pt->fz > 0 ? -pt->fx / pt->fz : 0;
}

/* A converged equilibrium p as the model's point at its x (out->x and out->iterations are the
 * caller's): z, h = z - z_flat, the forces and contacts of that one evaluation, the slope. */
static inline void tirenv_model__eq_point(const tirenv_eq_point *p, double z_flat,
                                          tirenv_point *out)
{
    out->z = p->z;
    out->h = p->z - z_flat;
    out->fz = p->F;
    out->fx = p->fx;
    out->contacts = p->contacts;
    out->slope = tirenv_model__slope(out);
}

/* The load (N) at which the springs model of a tire (*springs, allocated on first need from
 * tire) has its centre at the height whose chord of the free circle is l_c (m),
 * 2*sqrt(R0^2 - z^2) = l_c: the contact length of the models that do not deflect (rigid,
 * point), which stands for the load at which the springs model has that chord, as before the
 * springs model's own contact length became the length its tread touches (docs/models.md
 * section 1.3). */
int tirenv_model__load_at_chord(tirenv_model **springs, const tirenv_tire *tire, double l_c,
                                double *load, tirenv_diag *diag);

#endif
