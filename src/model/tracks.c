/* Several tracks across the tire's width (docs/models.md section 13): a road that varies
 * across gives each slice of the tire its own profile, and the model's type says how the
 * slices' results make one point. Each distinct track has a type state of its own (the first
 * is the model's), set on its profile at the model's load and z_flat; the tracks' points, or
 * for the equilibrium their forces, are combined with the weights w_i (sum 1):
 *   mean:        z, h, slope, fx, fz = sum_i w_i (z_i, h_i, slope_i, fx_i, fz_i);
 *   highest:     the point of the highest track (ties: the mean of the tied tracks' forces);
 *   equilibrium: sum_i w_i F_z,i(x, z) = G solved in z by the core's equilibrium driver
 *                (docs/models.md section 11) with dF_z/dz and F_x summed alike.
 * One distinct track goes through the ordinary single-track path, so n copies of one profile
 * are tirenv_model_set bit for bit. SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/equilibrium.h"
#include "model/deformable.h"
#include "model/model_impl.h"
#include "model/rigid_impl.h"

/* Positions per block of a batched sweep (the network's envelope) over each track. */
enum { TRACKS_BLOCK = 256 };

struct tirenv_model__tracks {
    size_t cap;                   /* type states held: state[0] is the model's own */
    void **state;
    size_t n_given;               /* profiles of the last set, as the caller gave them */
    size_t *map;                  /* given profile i -> distinct track map[i] */
    size_t n;                     /* distinct tracks */
    const tirenv_profile **prof;  /* [n] */
    double *w;                    /* [n], sum 1 */
    size_t *hint;                 /* [n] profile segment of the last position, per track */
    tirenv_point *pt;             /* [n] one position's points */
    tirenv_point *block;          /* [TRACKS_BLOCK], a batched sweep's points of one track */
    tirenv_eq_solver *solver;     /* the equilibrium's, of the tire's method */
    tirenv_deformable_history prev; /* warm start: the last two equilibria */
};

static const char *const rule_names[] = {"mean", "highest", "equilibrium"};

const char *tirenv_tracks_rule_name(tirenv_tracks_rule rule)
{
    return (unsigned)rule < 3 ? rule_names[rule] : NULL;
}

tirenv_tracks_rule tirenv_model_type_tracks(const tirenv_model_type *type)
{
    return type->tracks;
}

int tirenv_tracks_spread(size_t n, double v, double width, double v_out[], tirenv_diag *diag)
{
    if (n == 0 || !isfinite(v) || !(width >= 0 && isfinite(width)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, n == 0 ? "tracks" : "width",
                            "expected n >= 1 tracks over a finite width >= 0 m around a finite "
                            "position, got %zu over %g m around %g m", n, width, v);
    /* The midpoint rule over the width: slice i is [v - w/2 + i w/n, v - w/2 + (i+1) w/n]. */
    for (size_t i = 0; i < n; ++i)
        v_out[i] = n == 1 ? v : v - 0.5 * width + ((double)i + 0.5) * width / (double)n;
    return TIRENV_OK;
}

/* The further tracks' states belong to the type; the model's own (state[0]) to the model. */
void tirenv_model__tracks_free(tirenv_model *m)
{
    struct tirenv_model__tracks *t = m->tracks;
    if (!t)
        return;
    for (size_t k = 1; k < t->cap; ++k)
        if (t->state[k])
            m->type->ops->free(t->state[k]);
    free(t->state);
    free(t->map);
    free(t->prof);
    free(t->w);
    free(t->hint);
    free(t->pt);
    free(t->block);
    tirenv_eq__solver_free(t->solver);
    free(t);
    m->tracks = NULL;
}

int tirenv_model__tracks_contact_length(tirenv_model *m, double l_c, tirenv_diag *diag)
{
    struct tirenv_model__tracks *t = m->tracks;
    for (size_t k = 1; t && k < t->cap; ++k) {
        double load;
        const int status =
            m->type->ops->load_for_contact_length(t->state[k], l_c, &load, diag);
        if (status)
            return status;
    }
    return TIRENV_OK;
}

void tirenv_model__tracks_extrapolate(tirenv_model *m)
{
    struct tirenv_model__tracks *t = m->tracks;
    for (size_t k = 1; t && m->type->network && k < t->cap; ++k)
        m->type->network->set_extrapolate(t->state[k], m->extrapolate);
}

void tirenv_model__stream_window(tirenv_model *m, const tirenv_nn_road_window *w)
{
    m->streamed = !w && (m->windowed || m->streamed);
    m->windowed = w != NULL;
    if (w)
        m->window = *w;
    const tirenv_model_network *net = m->type->network;
    if (!net)
        return;
    net->stream_window(m->state, w);
    struct tirenv_model__tracks *t = m->tracks;
    for (size_t k = 1; t && k < t->cap; ++k)
        net->stream_window(t->state[k], w);
}

/* The driver's record of tracks just set at load (z_flat in m): the first track stands for
 * the profile, the highest vertex is over them all (the hub's check, model.c). */
static void tracks_took(tirenv_model *m, double load, double z_flat)
{
    const struct tirenv_model__tracks *t = m->tracks;
    double top = -INFINITY;
    for (size_t k = 0; k < t->n; ++k)
        top = fmax(top, tirenv_model__profile_top(t->prof[k]));
    m->z_top = top;
    tirenv_model__took(m, t->prof[0], load, z_flat);
    m->n_tracks = t->n;
}

/* Room for n given profiles (and so at most n distinct tracks) in the arrays. */
static int tracks_arrays(tirenv_model *m, size_t n, tirenv_diag *diag)
{
    struct tirenv_model__tracks *t = m->tracks;
    if (!t) {
        if (!(t = calloc(1, sizeof *t)))
            return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        m->tracks = t;
    }
    size_t *map = realloc(t->map, n * sizeof *map);
    if (map)
        t->map = map;
    const tirenv_profile **prof = map ? realloc(t->prof, n * sizeof *prof) : NULL;
    if (prof)
        t->prof = prof;
    double *w = prof ? realloc(t->w, n * sizeof *w) : NULL;
    if (w)
        t->w = w;
    size_t *hint = w ? realloc(t->hint, n * sizeof *hint) : NULL;
    if (hint)
        t->hint = hint;
    tirenv_point *pt = hint ? realloc(t->pt, n * sizeof *pt) : NULL;
    if (pt)
        t->pt = pt;
    if (pt && !t->block)
        t->block = malloc(TRACKS_BLOCK * sizeof *t->block);
    if (!pt || !t->block)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    return TIRENV_OK;
}

/* A type state for each of n distinct tracks (and the equilibrium's solver). */
static int tracks_states(tirenv_model *m, size_t n, tirenv_diag *diag)
{
    struct tirenv_model__tracks *t = m->tracks;
    if (n > t->cap) {
        void **state = realloc(t->state, n * sizeof *state);
        if (!state)
            return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        t->state = state;
        state[0] = m->state;
        if (t->cap == 0)
            t->cap = 1;
        while (t->cap < n) {
            if (!(state[t->cap] = tirenv_model__track_state(m)))
                return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "",
                                    "out of memory (the state of track %zu)", t->cap + 1);
            t->cap++;
        }
    }
    if (m->type->tracks == TIRENV_TRACKS_EQUILIBRIUM) {
        if (!m->type->deformable)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "model",
                                "the %s model combines tracks by an equilibrium but has no "
                                "force function", m->type->name);
        if (!t->solver &&
            !(t->solver = tirenv_eq__solver_alloc(tirenv_eq__solver_type_of(m->tire.eq.method))))
            return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    return TIRENV_OK;
}

/* The distinct tracks of what the caller gave: a profile given again (the same object) joins
 * its first occurrence, its weight added. Returns how many there are. */
static size_t distinct(size_t n, const tirenv_profile *const profiles[], const double weights[],
                       size_t map[], const tirenv_profile *prof[], double w[])
{
    size_t k = 0;
    for (size_t i = 0; i < n; ++i) {
        const double wi = weights ? weights[i] : 1.0;
        size_t j = 0;
        while (j < k && prof[j] != profiles[i])
            ++j;
        if (j == k) {
            prof[k] = profiles[i];
            w[k++] = wi;
        } else {
            w[j] += wi;
        }
        map[i] = j;
    }
    return k;
}

int tirenv_model_set_tracks(tirenv_model *m, size_t n, const tirenv_profile *const profiles[],
                            const double weights[], double load, tirenv_diag *diag)
{
    m->ready = 0;
    m->n_tracks = 0;
    if (n == 0 || !profiles)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tracks", "expected at least one track");
    double total = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!profiles[i])
            return tirenv_error(diag, TIRENV_EINVAL, "", i + 1, "profile",
                                "track %zu has no profile (NULL)", i + 1);
        if (weights && !(weights[i] > 0 && isfinite(weights[i])))
            return tirenv_error(diag, TIRENV_EINVAL, "", i + 1, "weight",
                                "track %zu: expected a finite weight > 0, got %g", i + 1,
                                weights[i]);
        total += weights ? weights[i] : 1.0;
    }
    if (!isfinite(total))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "weight", "the weights sum to %g",
                            total);
    int status = tracks_arrays(m, n, diag);
    if (status)
        return status;
    struct tirenv_model__tracks *t = m->tracks;
    t->n_given = n;
    t->n = distinct(n, profiles, weights, t->map, t->prof, t->w);
    tirenv_deformable_history_clear(&t->prev);
    if (t->n == 1)  /* one track: the ordinary path, bit for bit */
        return tirenv_model_set(m, t->prof[0], load, diag);
    for (size_t k = 0; k < t->n; ++k)
        t->w[k] /= total;
    if ((status = tracks_states(m, t->n, diag)))
        return status;
    tirenv_flat flat;
    if ((status = tirenv_model_flat(m, load, &flat, diag)))
        return status;
    m->z_flat = flat.z_flat;
    for (size_t k = 0; k < t->n && !status; ++k) {
        status = m->type->ops->set(t->state[k], t->prof[k], load, flat.z_flat, diag);
        if (status && diag && t->n > 1) {
            char msg[sizeof diag->message];
            snprintf(msg, sizeof msg, "track %zu: %.400s", k + 1, diag->message);
            memcpy(diag->message, msg, sizeof msg);
        }
        t->hint[k] = 0;
    }
    if (status)
        return status;
    tracks_took(m, load, flat.z_flat);
    return TIRENV_OK;
}

int tirenv_model_set_track_profiles(tirenv_model *m, size_t n,
                                    const tirenv_profile *const profiles[], tirenv_diag *diag)
{
    struct tirenv_model__tracks *t = m->tracks;
    if (!m->ready || !t || n != t->n_given || !profiles) {
        const size_t was = m->ready && t ? t->n_given : 0;
        m->ready = 0;
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tracks",
                            "expected the %zu tracks of tirenv_model_set_tracks, got %zu", was,
                            n);
    }
    /* The pattern of repeated objects must be the one set (the weights go by it), and the
     * model must still be set with these tracks, not since by tirenv_model_set. */
    size_t d = 0;
    for (size_t i = 0; i < n; ++i) {
        size_t j = 0;
        while (j < i && profiles[j] != profiles[i])
            ++j;
        const int ok = profiles[i] && (j < i ? t->map[i] == t->map[j] : t->map[i] == d++);
        if (!ok || m->n_tracks != t->n) {
            m->ready = 0;
            return tirenv_error(diag, TIRENV_EINVAL, "", i + 1, "profile",
                                "track %zu: not the tracks of tirenv_model_set_tracks (the "
                                "same number, the same profiles repeated)", i + 1);
        }
    }
    if (t->n == 1)
        return tirenv_model_set_profile(m, profiles[0], diag);
    int status = TIRENV_OK;
    for (size_t i = 0; i < n; ++i)
        t->prof[t->map[i]] = profiles[i];
    for (size_t k = 0; k < t->n && !status; ++k)
        status = m->type->ops->set_profile(t->state[k], t->prof[k], m->load, m->z_flat, diag);
    if (status) {
        m->ready = 0;
        m->profile = NULL;
    } else {
        tracks_took(m, m->load, m->z_flat);
    }
    return status;
}

/* Each track's state at the new load, by the type's set_load. A failure leaves the model unset
 * (some tracks may have moved). */
int tirenv_model__tracks_set_load(tirenv_model *m, double load, tirenv_diag *diag)
{
    struct tirenv_model__tracks *t = m->tracks;
    tirenv_flat flat;
    int status = m->type->ops->flat(m->state, load, &flat, diag);
    for (size_t k = 0; k < t->n && !status; ++k) {
        double z_k;  /* the type's own z_flat at the load: flat's, as every track's tire is one */
        status = m->type->ops->set_load(t->state[k], load, &z_k, diag);
    }
    if (status) {
        m->ready = 0;
        m->profile = NULL;
        return status;
    }
    tirenv_deformable_history_clear(&t->prev);
    tracks_took(m, load, flat.z_flat);
    return TIRENV_OK;
}

double tirenv_model__tracks_max_height(const tirenv_model *m, double x0, double x1)
{
    const struct tirenv_model__tracks *t = m->tracks;
    double top = -INFINITY;
    for (size_t k = 0; k < t->n; ++k)
        top = fmax(top, tirenv_profile_max_height(t->prof[k], x0, x1));
    return top;
}

const char *tirenv_model__tracks_warnings(const tirenv_model *m)
{
    const char *(*said)(const void *state) = m->type->ops->warnings;
    const char *w = said(m->state);
    const struct tirenv_model__tracks *t = m->tracks;
    for (size_t k = 1; !w[0] && t && k < m->n_tracks && k < t->cap; ++k)
        w = said(t->state[k]);
    return w;
}

size_t tirenv_model_tracks(const tirenv_model *m)
{
    return m->ready ? m->n_tracks : 0;
}

/* ---- one position ------------------------------------------------------------------------ */

/* The slices' forces at (x, z), weighted and summed. */
typedef struct {
    tirenv_model *m;
    double x;              /* m */
} sum_ctx;

static int sum_forces(void *ctx, double z, tirenv_eq_point *out, tirenv_diag *diag)
{
    const sum_ctx *c = ctx;
    const struct tirenv_model__tracks *t = c->m->tracks;
    *out = (tirenv_eq_point){.z = z};
    for (size_t k = 0; k < t->n; ++k) {
        tirenv_eq_point p;
        const int status = tirenv_deformable_forces(t->state[k], c->x, z, &p, diag);
        if (status)
            return status;
        out->F += t->w[k] * p.F;
        out->dF_dz += t->w[k] * p.dF_dz;
        out->fx += t->w[k] * p.fx;
        out->contacts += p.contacts;
    }
    return TIRENV_OK;
}

/* The bracket of docs/models.md section 11.1 over every track, the rigid disc's, at every
 * position: the cheaper one a warm Newton takes on one track (deformable.c) is the deformable
 * model's own for its one profile. */
static int equilibrium(tirenv_model *m, double x, tirenv_point *out, tirenv_diag *diag)
{
    struct tirenv_model__tracks *t = m->tracks;
    /* The centre of the force function, u above the hub with a series spring (deformable.h):
     * its flat-ground height, which the equilibria are solved for. */
    const double u = tirenv_deformable_series(m->type->deformable, &m->tire, m->load);
    const double R0 = m->tire.springs.R0, z_flat = m->z_flat + u, deflection = R0 - z_flat;
    double z_lo, z_hi;
    tirenv_rigid__bracket(t->n, t->prof, R0, x, t->hint, &z_lo, &z_hi);
    const tirenv_eq_problem prob = {
        .z_lo = z_lo,
        .z_hi = z_hi,
        .z0 = tirenv_deformable_history_start(&t->prev, m->type->deformable->extrapolate, x,
                                              z_hi - deflection),
        .dz_hint = deflection,
    };
    sum_ctx c = {m, x};
    tirenv_eq_result res;
    int status = tirenv_eq__solve(t->solver, &m->tire.eq, sum_forces, &c, m->load, &prob,
                                  &res, diag);
    out->x = x;
    out->iterations = res.evals;
    if (!status)
        status = tirenv_deformable_check_jump(m->type->deformable, &m->tire, &res, m->load,
                                              diag);
    if (status)
        return status;
    tirenv_deformable_history_push(&t->prev, x, res.point.z);
    tirenv_model__eq_point(&res.point, z_flat, out);
    out->z = res.point.z - u;
    return TIRENV_OK;
}

/* o += w p, the mean rule's step: the weighted fields, and the contacts and iterations added
 * up. */
static void add_weighted(tirenv_point *o, double w, const tirenv_point *p)
{
    o->z += w * p->z;
    o->h += w * p->h;
    o->slope += w * p->slope;
    o->fx += w * p->fx;
    o->fz += w * p->fz;
    o->contacts += p->contacts;
    o->iterations += p->iterations;
}

/* The tracks' points pt[n] made one by the mean or the highest rule. */
static void combine(const tirenv_model *m, const tirenv_point pt[], tirenv_point *out)
{
    const struct tirenv_model__tracks *t = m->tracks;
    const double x = out->x;
    *out = (tirenv_point){.x = x};
    if (m->type->tracks != TIRENV_TRACKS_HIGHEST) {
        for (size_t k = 0; k < t->n; ++k)
            add_weighted(out, t->w[k], &pt[k]);
        return;
    }
    for (size_t k = 0; k < t->n; ++k)
        out->iterations += pt[k].iterations;
    double z = pt[0].z;
    for (size_t k = 1; k < t->n; ++k)
        z = fmax(z, pt[k].z);
    double w = 0;
    for (size_t k = 0; k < t->n; ++k)
        if (pt[k].z == z) {
            out->h = pt[k].h;
            out->fx += t->w[k] * pt[k].fx;
            out->fz += t->w[k] * pt[k].fz;
            out->contacts += pt[k].contacts;
            w += t->w[k];
        }
    out->z = z;
    out->fx /= w;
    out->fz /= w;
    out->slope = tirenv_model__slope(out);
}

int tirenv_model__tracks_eval(tirenv_model *m, double x, tirenv_point *out, tirenv_diag *diag)
{
    struct tirenv_model__tracks *t = m->tracks;
    if (m->type->tracks == TIRENV_TRACKS_EQUILIBRIUM)
        return equilibrium(m, x, out, diag);
    for (size_t k = 0; k < t->n; ++k) {
        const int status = m->type->ops->eval(t->state[k], x, &t->pt[k], diag);
        if (status)
            return status;
    }
    out->x = x;
    combine(m, t->pt, out);
    return TIRENV_OK;
}

/* A type with a batched sweep (the network) runs it per track, a block of positions at a
 * time, and the blocks are combined; otherwise position after position. */
int tirenv_model__tracks_envelope(tirenv_model *m, size_t n, const double x[],
                                  tirenv_point out[], size_t *failed, tirenv_diag *diag)
{
    struct tirenv_model__tracks *t = m->tracks;
    if (!m->type->network || m->type->tracks != TIRENV_TRACKS_MEAN) {
        for (size_t i = 0; i < n; ++i) {
            const int status = tirenv_model__tracks_eval(m, x[i], &out[i], diag);
            if (status) {
                *failed = i;
                return status;
            }
        }
        return TIRENV_OK;
    }
    for (size_t i0 = 0; i0 < n; i0 += TRACKS_BLOCK) {
        const size_t nb = n - i0 < TRACKS_BLOCK ? n - i0 : TRACKS_BLOCK;
        /* out[] holds the tracks' weighted sums as they come (the mean rule). */
        for (size_t k = 0; k < t->n; ++k) {
            size_t bad = 0;
            const int status =
                m->type->network->envelope(t->state[k], nb, x + i0, t->block, &bad, diag);
            if (status) {
                *failed = i0 + bad;
                return status;
            }
            for (size_t i = 0; i < nb; ++i) {
                if (k == 0)
                    out[i0 + i] = (tirenv_point){.x = x[i0 + i]};
                add_weighted(&out[i0 + i], t->w[k], &t->block[i]);
            }
        }
    }
    return TIRENV_OK;
}
