/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: enveloping models over a ground profile at constant vertical load (the core API). */
#ifndef TIRENV_MODEL_H
#define TIRENV_MODEL_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/profile.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

struct tirenv_nn;  /* the network of the empirical model, tirenv/nn.h */

/* One position of the enveloping curve (docs/models.md section 1). */
typedef struct {
    double x;              /* tire-centre longitudinal position, m */
    double z;              /* tire-centre height at equilibrium, m */
    double h;              /* effective profile height z - z_flat, m */
    double slope;          /* effective road slope tan(beta) = -fx/fz, the inclination of the
                            * resultant ground force (MF-Swift's effective slope); for the cam
                            * exactly (Z_f - Z_r)/l_s (docs/models.md section 7); for the
                            * point contact the ground's slope under the centre; for the
                            * network dh/dx of its curve (it knows no forces: fx is 0) */
    double fx;             /* longitudinal hub force (positive forward), N */
    double fz;             /* vertical hub force (equals the load at equilibrium), N */
    size_t contacts;       /* elements (or contact points) touching the ground */
    size_t iterations;     /* force evaluations spent on the equilibrium */
} tirenv_point;

/* The tire's state on flat ground at a given load. */
typedef struct {
    double load;           /* vertical load G_T, N */
    double z_flat;         /* centre height, m */
    double deflection;     /* R0 - z_flat, m */
    double contact_length; /* the model's flat-ground contact length, m */
    double stiffness;      /* vertical stiffness -dF_z/dz at z_flat, N/m */
} tirenv_flat;

/* A model algorithm, chosen by name (GSL style: tirenv_model_springs, tirenv_model_rigid). */
typedef struct tirenv_model_type tirenv_model_type;
extern const tirenv_model_type *tirenv_model_rigid;   /* rigid disc, docs/models.md section 3 */
extern const tirenv_model_type *tirenv_model_springs; /* paper's springs, docs section 4 */
extern const tirenv_model_type *tirenv_model_ring;  /* reference tire, docs/models.md section 5 */
extern const tirenv_model_type *tirenv_model_cam;   /* tandem cam, docs/models.md section 7 */
extern const tirenv_model_type *tirenv_model_nn;    /* trained network, sections 6 and 12 */
extern const tirenv_model_type *tirenv_model_point; /* single-point contact, section 9.2 */

/* The type with this name ("rigid", "springs", "ring", "cam", "nn", "point"), or NULL. */
const tirenv_model_type *tirenv_model_type_find(const char *name);
/* Name of a type; its NULL-terminated list of all types. */
const char *tirenv_model_type_name(const tirenv_model_type *type);
const tirenv_model_type *const *tirenv_model_types(void);
/* What the type is, in 48 characters or fewer, for help texts and reports. */
const char *tirenv_model_type_summary(const tirenv_model_type *type);

/* What a model can do: the flags of its type (tirenv_model_type_flags). */
enum {
    TIRENV_MODEL_FITTABLE = 1u << 0,       /* tirenv_fit identifies its parameters
                                            * (tirenv_model_type_params) */
    TIRENV_MODEL_NEEDS_NETWORK = 1u << 1,  /* it evaluates a trained network, which
                                            * tirenv_model_set_network gives it */
    TIRENV_MODEL_CONTACT_LENGTH = 1u << 2, /* it has a flat-ground contact length of its own;
                                            * without, tirenv_model_load_for_contact_length
                                            * goes through the springs model of the tire */
    TIRENV_MODEL_STREAMS = 1u << 3,        /* it reads the ground only within
                                            * tirenv_model_reach of x (the network: with its
                                            * grid anchored at the road's first vertex, which
                                            * tirenv_model_stream tells it), so
                                            * tirenv_model_stream takes it */
    TIRENV_MODEL_EQUILIBRIUM = 1u << 4     /* it solves the constant-load equilibrium at every
                                            * position, by the tire's equilibrium method */
};
unsigned tirenv_model_type_flags(const tirenv_model_type *type);

/* A tire parameter that shapes a model's curve and that tirenv_fit identifies. */
typedef struct {
    const char *key;       /* its .tir key, e.g. "RADIAL_STIFFNESS" */
    size_t offset;         /* where it lives in tirenv_tire, e.g.
                            * offsetof(tirenv_tire, springs.c_r) */
    double lower;          /* it stays above this (0 for stiffnesses, 1 for ELLIPS_ORDER) */
} tirenv_model_param;

/* The parameters a fit identifies, in order: the first *n by default, *n_max (>= *n) with
 * the optional ones (the springs model's UNLOADED_RADIUS); NULL with 0 and 0 for a type that
 * cannot be fitted. n and n_max may be NULL. */
const tirenv_model_param *tirenv_model_type_params(const tirenv_model_type *type, size_t *n,
                                                   size_t *n_max);

/* A model instance: owns its workspace, so evaluation never allocates. Not thread-safe; use
 * one instance per thread. */
typedef struct tirenv_model tirenv_model;

/* Allocates a model of the given type for a tire (copied). NULL if the tire fails
 * tirenv_tire_check or memory runs out. A type with TIRENV_MODEL_NEEDS_NETWORK needs
 * tirenv_model_set_network before tirenv_model_set. */
tirenv_model *tirenv_model_alloc(const tirenv_model_type *type, const tirenv_tire *tire);
void tirenv_model_free(tirenv_model *m);  /* NULL is a no-op */
const char *tirenv_model_name(const tirenv_model *m);
/* The tire the model was built for (read-only, owned by the model). */
const tirenv_tire *tirenv_model_tire(const tirenv_model *m);

/* The network a TIRENV_MODEL_NEEDS_NETWORK model evaluates (copied: nn may then be freed),
 * and the free radius R0 (m) its inputs x_N refer to (the model file's record; 0: the tire's).
 * TIRENV_EINVAL for a model without a network or a network that does not fit (the enveloping
 * model's 4 inputs). The model is left unset. */
int tirenv_model_set_network(tirenv_model *m, const struct tirenv_nn *nn, double R0,
                             tirenv_diag *diag);

/* A tire's flat-ground relation between load and contact length, as a table of knots: how a
 * model driven by the contact length (the network) turns a load into its input (docs/models.md
 * section 14.3). Between the knots a monotone cubic (Fritsch-Carlson), exact at them; loads
 * outside [load[0], load[n-1]] are refused. */
enum { TIRENV_CONTACT_LAW_MAX = 32 };
typedef struct {
    size_t n;                               /* points, 2 to TIRENV_CONTACT_LAW_MAX; 0: none */
    double load[TIRENV_CONTACT_LAW_MAX];    /* N, strictly ascending, > 0 */
    double l_c[TIRENV_CONTACT_LAW_MAX];     /* m, strictly ascending, > 0 */
} tirenv_contact_law;

/* Checks a law: TIRENV_OK, or TIRENV_EINVAL naming the offending point. */
int tirenv_contact_law_check(const tirenv_contact_law *law, tirenv_diag *diag);

/* The contact length (m) at a load (N) of a checked law: a knot's own value at a knot,
 * monotone between them. TIRENV_ERANGE outside the knots' loads, naming the range. */
int tirenv_contact_law_eval(const tirenv_contact_law *law, double load, double *l_c,
                            tirenv_diag *diag);

/* Its inverse: the load (N) of a contact length (m), a knot's own load at a knot, else the
 * double whose tirenv_contact_law_eval is nearest l_c. TIRENV_ERANGE outside the knots. */
int tirenv_contact_law_inverse(const tirenv_contact_law *law, double l_c, double *load,
                               tirenv_diag *diag);

/* The load-to-contact-length relation of the tire a network's data came from (copied; NULL or
 * n = 0: none, the springs model of the model's tire then gives the contact length, as
 * before). TIRENV_EINVAL for a model without a network or a law that fails
 * tirenv_contact_law_check. The model is left unset. */
int tirenv_model_set_contact_law(tirenv_model *m, const tirenv_contact_law *law,
                                 tirenv_diag *diag);

/* Whether a model with a trained range (the network: its inputs l_c, H, L as trained,
 * docs/models.md sections 6.3 and 12) may be evaluated outside it. 0, the default: such input
 * is refused by tirenv_model_set with TIRENV_ERANGE naming the input, its value and the range.
 * 1: it is evaluated (the network's curve at the value, or over roads the obstacle scaled or
 * clamped to the range) with a warning (tirenv_model_warnings). Kept across sets; the other
 * models have no trained range and ignore it. */
void tirenv_model_set_extrapolate(tirenv_model *m, int allow);

/* Flat-ground state at load G (N). TIRENV_EINVAL unless G is finite and above the tire's
 * force tolerance FORCE_TOLERANCE (an equilibrium cannot tell a smaller load from none);
 * TIRENV_ENOBRACKET if the tire cannot carry G; TIRENV_ERANGE beyond the model's valid load
 * range (docs/models.md section 1.3). */
int tirenv_model_flat(tirenv_model *m, double load, tirenv_flat *out, tirenv_diag *diag);

/* The flat-ground state with the centre at height z (m) above the ground, from one force
 * evaluation there: its load (N), deflection, contact length and stiffness, the inverse of
 * tirenv_model_flat. For the deformable models (springs, ring); TIRENV_EINVAL for the others
 * and for z outside (0, R0), TIRENV_ERANGE for z below the model's valid range. */
int tirenv_model_flat_at_height(tirenv_model *m, double z, tirenv_flat *out,
                                tirenv_diag *diag);

/* Load (N) at which the model's flat-ground contact length is l_c (m); TIRENV_EINVAL if
 * l_c is not in (0, 2*R0), TIRENV_ERANGE if it is beyond the contact lengths of the model's
 * valid load range. A model whose input is the contact length (the network) remembers
 * it: tirenv_model_set at that load then works at exactly l_c. */
int tirenv_model_load_for_contact_length(tirenv_model *m, double l_c, double *load,
                                         tirenv_diag *diag);

/* Sets the ground profile (borrowed: it must outlive its use) and the load (N); computes the
 * flat-ground reference z_flat. The profile may have any elevation and grade: it is checked
 * where it is evaluated (tirenv_model_eval). Resets the warm start. On failure the model is
 * unset (tirenv_model_load NaN, tirenv_model_profile NULL), whatever it was set on before. */
int tirenv_model_set(tirenv_model *m, const tirenv_profile *profile, double load,
                     tirenv_diag *diag);

/* Changes the load (N) of a model already set, keeping its profile and its warm start, at the
 * cost of the work within the tire's reach, not the road's (docs/models.md section 1.7): the
 * next evaluations equal those of a model set at this load with tirenv_model_set, bit for bit
 * for rigid, cam, nn and point, and within the equilibrium's tolerances (section 11.3) for
 * springs and ring, whose flat-ground solve and equilibria start from where they stand.
 * TIRENV_EINVAL if no profile is set; the load errors of tirenv_model_flat. On failure the
 * model is unchanged (still set at its previous load). */
int tirenv_model_set_load(tirenv_model *m, double load, tirenv_diag *diag);

/* The load (N) of the last successful tirenv_model_set or _set_load; NaN before, and after a
 * tirenv_model_set that failed (the model is then unset). */
double tirenv_model_load(const tirenv_model *m);
/* The profile the model is set on (borrowed), or NULL when it is not set. */
const tirenv_profile *tirenv_model_profile(const tirenv_model *m);

/* What a host must keep to rewind the model (a co-simulation's step rejected, a state saved
 * and restored): the load, the flat-ground state, the warm start and every cache that can
 * change a bit of a later result, as opaque bytes for this build and machine (docs/models.md
 * section 1.7). Not the profile, which the model only borrows. The size is fixed for an
 * instance, whatever it has evaluated. */
size_t tirenv_model_state_size(const tirenv_model *m);
/* Writes the state into buf (size bytes); TIRENV_EINVAL if size is not
 * tirenv_model_state_size(m), or if the model is set on several tracks
 * (tirenv_model_set_tracks): a state is that of one track (docs/models.md section 13). */
int tirenv_model_state_save(const tirenv_model *m, void *buf, size_t size, tirenv_diag *diag);
/* Restores a state saved from this instance or from one allocated with the same type and tire
 * (and the same network): the evaluations that follow are bit for bit those that followed the
 * save, given the same calls. The model's profile must be set (tirenv_model_set, with any
 * load) and be the same ground as when the state was saved, which is the caller's to keep.
 * TIRENV_EINVAL, the model left as it was, for a buffer that is not such a state (its size,
 * type or tire differ, or a byte changed since the save: the state ends in a checksum of its
 * bytes), or a state of a set model restored into one without a profile; a type's own restore
 * that fails leaves the model unset. */
int tirenv_model_state_restore(tirenv_model *m, const void *buf, size_t size,
                               tirenv_diag *diag);

/* What a user should hear about the last tirenv_model_set and the evaluations since, one
 * warning per line without a final newline (the network: an input outside its training range,
 * obstacles clamped to it; the cam: the first position where it touched the ground higher
 * above its lowest point than the tire's ELLIPS_MAX_STEP, docs/models.md section 7.5), or ""
 * if nothing; and one line on what the model made of the ground (the network: the equivalent
 * cleats it saw), or "". Owned by the model, valid until the next set or evaluation. After
 * tirenv_model_stream, which leaves the model unset, those of its windows: the obstacles of
 * every window so far, each counted once, and the cam's over all its positions. */
const char *tirenv_model_warnings(const tirenv_model *m);
const char *tirenv_model_note(const tirenv_model *m);

/* Replaces the profile (borrowed) of a model already set, keeping its load and z_flat;
 * for tirenv_model_stream's moving window. TIRENV_EINVAL if tirenv_model_set has not
 * succeeded, or (the model then unset) if it is set on several tracks
 * (tirenv_model_set_track_profiles). NULL unsets the model (tirenv_model_eval then fails until
 * tirenv_model_set). */
int tirenv_model_set_profile(tirenv_model *m, const tirenv_profile *profile, tirenv_diag *diag);

/* A bound (m) on how far from a position x the model reads the profile at the load set
 * (before tirenv_model_set, a bound for usual loads): the profile may be anything beyond
 * [x - reach, x + reach] without changing the result at x. */
double tirenv_model_reach(const tirenv_model *m);

/* Equilibrium at position x (m), warm-started from the previous call. On failure out->x is x
 * and diag says why (x, load, bracket). TIRENV_EINVAL if x is not finite (field "x").
 * TIRENV_ERANGE where ground within R0 of x rises to the centre's height z: the enveloping
 * models assume the hub clears the ground (docs/models.md section 2.5). */
int tirenv_model_eval(tirenv_model *m, double x, tirenv_point *out, tirenv_diag *diag);

/* Evaluates n positions x[] in order into out[]; stops at the first failure (its index in
 * *failed if not NULL). The same points as tirenv_model_eval one after the other, except the
 * network's slope, which over a single cleat is dh/dx of this sweep's curve (central
 * differences, one-sided at its ends). */
int tirenv_model_envelope(tirenv_model *m, size_t n, const double x[], tirenv_point out[],
                          size_t *failed, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
