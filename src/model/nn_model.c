/* The empirical model, the paper's trained network (docs/models.md section 6), as a
 * tirenv_model_type, so that every command runs it as it runs the physical models.
 * SPDX-License-Identifier: Apache-2.0
 *
 * The network's inputs are the working regime (the contact length l_c), the obstacle's
 * height and length, and the normalised position x_N; its output is h. So the model
 *   - turns a load into l_c through the contact law of the tire its data came from (the
 *     network file's record, a monotone cubic exact at its knots: model.h), else, for an
 *     older file, through the springs model of the same tire (its flat-ground contact
 *     length), and remembers the pair tirenv_model_load_for_contact_length made, so that a
 *     regime given as a contact length reaches the network exactly;
 *   - over a single rectangular cleat centred at x = 0 on level ground (a profile of exactly
 *     the four corners) evaluates the paper's curve (tirenv_nn_envelope); over any other
 *     profile, the equivalent-cleat decomposition of nn_road.h (docs/models.md section 12), an
 *     extension beyond the paper;
 *   - reports z = z_flat + h with z_flat = sqrt(R0^2 - (l_c/2)^2), the chord height, fz the
 *     load, and fx, contacts and iterations 0: the network knows none of them. Its slope is
 *     dh/dx of its curve: over a cleat, central differences of the sweep's own curve (one-sided
 *     at its ends), or of a step of 1e-5 in x_N at a single position; over a road, the
 *     decomposition's own derivative.
 * Over a road it reads the ground within tirenv_nn_road_window_margin of x, with the
 * decomposition's grid anchored at the road's first vertex, so it streams: stream.c tells it
 * where each window sits (nn_model_stream_window), and a window's decomposition is the whole
 * road's where it is evaluated. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model_impl.h"
#include "tirenv/nn.h"
#include "tirenv/nn_road.h"
#include "tirenv/xn.h"

/* Positions per block of a sweep: the network's batch path, on the stack. */
enum { NN_MODEL_BLOCK = 256 };
/* The x_N step of the slope at a single position over a cleat. */
static const double slope_step_xN = 1e-5;

typedef struct {
    tirenv_tire tire;
    tirenv_model *springs;     /* the working regime: load <-> contact length */
    tirenv_nn *nn;             /* owned copy; NULL until tirenv_model_set_network */
    double R0;                 /* the free radius x_N refers to, m */
    char r0_warning[256];      /* the network's R0 is not the tire's, or "" */
    int extrapolate;           /* evaluate outside the trained ranges (with warnings) */
    tirenv_contact_law law;    /* the network's tire: load -> l_c; n = 0: the springs model's flat-ground contact length */
    int pinned;                /* the last load_for_contact_length's pair: */
    double pin_load, pin_l_c;  /* N, m */
    /* The set: */
    const tirenv_profile *prof;
    double load, l_c, z_flat;  /* N, m, m */
    int cleat;                 /* the profile is a single cleat L x H */
    double L, H, x_0;          /* m; x_0 the x_N origin */
    tirenv_nn_road *road;      /* otherwise its decomposition */
    /* Streaming (stream.c): the profiles set are windows of one road, win says where; the
     * obstacles of the windows so far, each counted once (those centred beyond counted_to
     * are new), for the warnings and the note. */
    int windowed;
    tirenv_nn_road_window win;
    double counted_to;         /* m */
    tirenv_nn_road_info seen;
    char clamped[512];         /* the decomposition's obstacles outside the training range */
    char warnings[1024];
    char note[256];
} nn_state;

static void nn_model_free(void *state)
{
    nn_state *st = state;
    tirenv_model_free(st->springs);
    tirenv_nn_free(st->nn);
    tirenv_nn_road_free(st->road);
    free(st);
}

static void *nn_model_alloc(const tirenv_model_type *type, const tirenv_tire *tire)
{
    (void)type;
    nn_state *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    st->tire = *tire;
    st->R0 = tire->springs.R0;
    if (!(st->springs = tirenv_model_alloc(tirenv_model_springs, tire))) {
        nn_model_free(st);
        return NULL;
    }
    return st;
}

static int nn_model_set_network(void *state, const struct tirenv_nn *nn, double R0,
                                tirenv_diag *diag)
{
    nn_state *st = state;
    if (tirenv_nn_n_inputs(nn) != TIRENV_NN_INPUTS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "network",
                            "a network of %zu inputs; the enveloping model has %d (x_N, "
                            "contact length, obstacle height, obstacle length)",
                            tirenv_nn_n_inputs(nn), TIRENV_NN_INPUTS);
    tirenv_nn *copy = tirenv_nn_clone(nn);
    if (!copy)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    tirenv_nn_free(st->nn);
    st->nn = copy;
    const double R0_tire = st->tire.springs.R0;
    st->R0 = R0 > 0 ? R0 : R0_tire;
    st->r0_warning[0] = '\0';
    if (R0 > 0 && fabs(R0 - R0_tire) > 1e-9 * R0)
        snprintf(st->r0_warning, sizeof st->r0_warning,
                 "the network's data refer to a tire of R0 %g m, the tire file's is %g m; x_N "
                 "and z use %g m", R0, R0_tire, st->R0);
    return TIRENV_OK;
}

static void nn_model_set_contact_law(void *state, const tirenv_contact_law *law)
{
    nn_state *st = state;
    st->law = *law;
}

/* How far (m) a contact length the law makes from a load may lie outside the network's trained
 * range and still be taken as the range's end: 1e-6 m. A data set records its cases' loads to
 * 0.01 N, and its loads were solved for its contact lengths, so a load found again from a case's
 * contact length (tirenv flat --contact-length, another build) can differ from the recorded one
 * by about that; at the ring's 1e-5 m/kN (the embedded data set) that is 1e-7 m of contact
 * length, and 1e-6 m covers ten times it, while it is 1/280 000 of the smallest trained contact
 * length and 1/700 of the network's own validation error (0.76 mm), so no prediction changes
 * measurably. */
static const double l_c_range_tol = 1e-6;

/* The law's contact length at a load, taken to the trained range's end within
 * l_c_range_tol of it (the range itself is checked later, where it is refused or warned). */
static int law_contact_length(const nn_state *st, double load, double *l_c, tirenv_diag *diag)
{
    const int status = tirenv_contact_law_eval(&st->law, load, l_c, diag);
    if (status || !st->nn)
        return status;
    double lo[TIRENV_NN_INPUTS], hi[TIRENV_NN_INPUTS];
    tirenv_nn_input_range(st->nn, lo, hi);
    const size_t i = TIRENV_NN_CONTACT_LENGTH;
    if (*l_c < lo[i] && *l_c >= lo[i] - l_c_range_tol)
        *l_c = lo[i];
    else if (*l_c > hi[i] && *l_c <= hi[i] + l_c_range_tol)
        *l_c = hi[i];
    return TIRENV_OK;
}

/* The network's regime at a load: the contact length of the network's own tire (the law its
 * file records), else the springs model's, or exactly the one the load was made from. flat
 * may be NULL; with a law its stiffness is the springs model's where that has one, else 0. */
static int regime(nn_state *st, double load, double *l_c, tirenv_flat *flat, tirenv_diag *diag)
{
    tirenv_flat f = {.stiffness = 0};
    int status;
    if (st->law.n) {
        if (st->pinned && load == st->pin_load)
            *l_c = st->pin_l_c;
        else if ((status = law_contact_length(st, load, l_c, diag)))
            return status;
        tirenv_flat s;
        if (flat && tirenv_model_flat(st->springs, load, &s, NULL) == TIRENV_OK)
            f.stiffness = s.stiffness;
    } else {
        if ((status = tirenv_model_flat(st->springs, load, &f, diag)))
            return status;
        *l_c = st->pinned && load == st->pin_load ? st->pin_l_c : f.contact_length;
    }
    if (flat)
        *flat = f;
    return TIRENV_OK;
}

/* The chord height of docs/models.md section 1: where the network's z is measured from. */
static int chord_height(const nn_state *st, double l_c, double *z_c, tirenv_diag *diag)
{
    if (!(l_c > 0 && l_c < 2 * st->R0))
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "contact length",
                            "%g m is no chord of a tire of radius %g m", l_c, st->R0);
    *z_c = sqrt(st->R0 * st->R0 - 0.25 * l_c * l_c);
    return TIRENV_OK;
}

static int nn_model_flat(void *state, double load, tirenv_flat *out, tirenv_diag *diag)
{
    nn_state *st = state;
    tirenv_flat f;
    double l_c = NAN, z_c = NAN;
    int status = regime(st, load, &l_c, &f, diag);
    if (!status)
        status = chord_height(st, l_c, &z_c, diag);
    if (status)
        return status;
    *out = (tirenv_flat){.load = load, .z_flat = z_c, .deflection = st->R0 - z_c,
                         .contact_length = l_c, .stiffness = f.stiffness};
    return TIRENV_OK;
}

static int nn_model_load_for_contact_length(void *state, double l_c, double *load,
                                            tirenv_diag *diag)
{
    nn_state *st = state;
    const int status =
        st->law.n ? tirenv_contact_law_inverse(&st->law, l_c, load, diag)
                  : tirenv_model_load_for_contact_length(st->springs, l_c, load, diag);
    st->pinned = status == TIRENV_OK;
    st->pin_load = *load;
    st->pin_l_c = l_c;
    return status;
}

/* A single rectangular cleat centred at x = 0 on level ground 0: the network's own case. */
static int single_cleat(const tirenv_profile *p, double *L, double *H)
{
    if (tirenv_profile_size(p) != 4)
        return 0;
    const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
    if (!(x[0] == x[1] && x[2] == x[3] && x[0] < 0 && x[3] == -x[0] && z[0] == 0 &&
          z[3] == 0 && z[1] == z[2] && z[1] > 0))
        return 0;
    *L = x[3] - x[0];
    *H = z[1];
    return 1;
}

/* Appends one line to the warnings. */
static void warn(nn_state *st, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static void warn(nn_state *st, const char *fmt, ...)
{
    size_t used = strlen(st->warnings);
    if (used && used + 1 < sizeof st->warnings) {
        st->warnings[used++] = '\n';
        st->warnings[used] = '\0';
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(st->warnings + used, sizeof st->warnings - used, fmt, ap);
    va_end(ap);
}

/* Among the inputs from the contact length up to end - 1 (the cleat's all three; over a road
 * only the contact length, obstacles_in_range checks the obstacles), each the training never
 * saw a value like: refused, or with extrapolation allowed one warning each. */
static int check_range(nn_state *st, size_t end, tirenv_diag *diag)
{
    static const char *const what[TIRENV_NN_INPUTS] = {"x_N", "contact length",
                                                       "obstacle height", "obstacle length"};
    const double u[TIRENV_NN_INPUTS] = {0.5, st->l_c, st->H, st->L};
    double lo[TIRENV_NN_INPUTS], hi[TIRENV_NN_INPUTS];
    tirenv_nn_input_range(st->nn, lo, hi);
    for (size_t i = tirenv_nn_out_of_range(st->nn, u, TIRENV_NN_CONTACT_LENGTH); i < end;
         i = tirenv_nn_out_of_range(st->nn, u, i + 1)) {
        if (!st->extrapolate)
            return tirenv_error(diag, TIRENV_ERANGE, "", 0, what[i],
                                "%g m is outside the range the network was trained on, %g to "
                                "%g m: the network would extrapolate, which is refused unless "
                                "allowed (--extrapolate; tirenv_model_set_extrapolate)", u[i],
                                lo[i], hi[i]);
        warn(st, "%s %g m is outside the range the network was trained on (%g to %g m): the "
             "prediction is an extrapolation", what[i], u[i], lo[i], hi[i]);
    }
    return TIRENV_OK;
}

/* Over a road, the first equivalent cleat (docs/models.md section 12) outside the trained
 * heights or lengths, unless extrapolation is allowed: below the trained heights its curve
 * would be the lowest trained one scaled, beyond the ranges clamped to them, curves the
 * network never learned. */
static int obstacles_in_range(const nn_state *st, tirenv_diag *diag)
{
    const tirenv_nn_road_info in = tirenv_nn_road_info_of(st->road);
    if (st->extrapolate)
        return TIRENV_OK;
    const tirenv_nn_obstacle *ob = tirenv_nn_road_obstacles(st->road);
    size_t out = 0, first = 0;
    for (size_t k = 0; k < in.obstacles; ++k)
        if (!(ob[k].H >= in.H_min && ob[k].H <= in.H_max && ob[k].L >= in.L_min &&
              ob[k].L <= in.L_max) && out++ == 0)
            first = k;
    if (out == 0)
        return TIRENV_OK;
    const tirenv_nn_obstacle *o = &ob[first];
    return tirenv_error(diag, TIRENV_ERANGE, "", 0,
                        o->H >= in.H_min && o->H <= in.H_max ? "obstacle length"
                                                             : "obstacle height",
                        "the obstacle at x = %.6g m (%.6g to %.6g m, %.4g m high, %.4g m long "
                        "as a cleat) is outside the range the network was trained on, heights "
                        "%g to %g m, lengths %g to %g m (%zu of %zu obstacles are): the network "
                        "would extrapolate (scale or clamp its curves), which is refused unless "
                        "allowed (--extrapolate; tirenv_model_set_extrapolate)%s", o->c,
                        o->x_lo, o->x_hi, o->H, o->L, in.H_min, in.H_max, in.L_min, in.L_max,
                        out, in.obstacles,
                        st->windowed ? "; counts of the streamed window of the road around it"
                                     : "");
}

/* The decomposition's obstacles outside the training range, in one warning into
 * st->clamped (a property of the profile, kept for the warnings of a new load). */
static void warn_clamped(nn_state *st, const tirenv_nn_road_info *in)
{
    st->clamped[0] = '\0';
    const size_t clamped = in->height_above + in->length_below + in->length_above;
    if (!clamped)
        return;
    char detail[256] = "";
    size_t used = 0;
    const struct {
        size_t count;
        const char *text;
        double bound;
    } parts[] = {{in->height_above, "heights above", in->H_max},
                 {in->length_below, "lengths below", in->L_min},
                 {in->length_above, "lengths above", in->L_max}};
    for (size_t i = 0; i < sizeof parts / sizeof parts[0]; ++i)
        if (parts[i].count && used < sizeof detail)
            used += (size_t)snprintf(detail + used, sizeof detail - used, "%s%zu %s %g m",
                                     used ? ", " : "", parts[i].count, parts[i].text,
                                     parts[i].bound);
    snprintf(st->clamped, sizeof st->clamped, "%zu of %zu obstacles outside the network's "
             "training range, clamped to it (%s): their curves are the nearest trained "
             "cleat's", clamped, in->obstacles, detail);
}

/* The inputs the regime set checks: the cleat's three, or the contact length over a road. */
static size_t checked_inputs(const nn_state *st)
{
    return st->cleat ? TIRENV_NN_INPUTS : TIRENV_NN_CONTACT_LENGTH + 1;
}

/* The warnings of the regime set: the network's R0, its inputs outside the training range
 * (refused unless extrapolation is allowed: check_range), the obstacles clamped. */
static int warnings_build(nn_state *st, tirenv_diag *diag)
{
    st->warnings[0] = '\0';
    if (st->r0_warning[0])
        warn(st, "%s", st->r0_warning);
    const int status = check_range(st, checked_inputs(st), diag);
    if (status)
        return status;
    if (!st->cleat && st->clamped[0])
        warn(st, "%s", st->clamped);
    return TIRENV_OK;
}

/* The network's forms after the note: what the model file says it was trained as. */
static void note_forms(nn_state *st)
{
    tirenv_nn_input_form input;
    tirenv_nn_target_form target;
    tirenv_nn_form(st->nn, &input, &target);
    const size_t used = strlen(st->note), K = tirenv_nn_n_members(st->nn);
    snprintf(st->note + used, sizeof st->note - used,
             "; network: input %s, target %s, mean of %zu network%s",
             tirenv_nn_input_form_name(input), tirenv_nn_target_form_name(target), K,
             K == 1 ? "" : "s");
}

/* A streamed window's obstacles not counted yet appended to the road's so far (st->seen),
 * which the warnings and the note then report: the whole road's once the last window is set.
 * The counts add up; the geometry (trained ranges, W, ds, reach) is the window's. */
static tirenv_nn_road_info seen_add(nn_state *st)
{
    tirenv_nn_road_info add = tirenv_nn_road_info_after(st->road, st->counted_to);
    if (add.obstacles) {
        const tirenv_nn_obstacle *ob = tirenv_nn_road_obstacles(st->road);
        st->counted_to = ob[tirenv_nn_road_info_of(st->road).obstacles - 1].c;
    }
    add.obstacles += st->seen.obstacles;
    add.height_below += st->seen.height_below;
    add.height_above += st->seen.height_above;
    add.length_below += st->seen.length_below;
    add.length_above += st->seen.length_above;
    return st->seen = add;
}

static int nn_model_set(void *state, const tirenv_profile *p, double load, double z_flat,
                        tirenv_diag *diag)
{
    nn_state *st = state;
    st->warnings[0] = st->note[0] = st->clamped[0] = '\0';
    tirenv_nn_road_free(st->road);
    st->road = NULL;
    if (!st->nn)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "network",
                            "the nn model has no network (tirenv_model_set_network)");
    const int status = regime(st, load, &st->l_c, NULL, diag);
    if (status)
        return status;
    st->prof = p;
    st->load = load;
    st->z_flat = z_flat;
    /* A window is the cleat only if it is the whole road. */
    st->cleat = (!st->windowed || (st->win.bof && st->win.eof)) && single_cleat(p, &st->L, &st->H);
    if (st->cleat) {
        const int s = warnings_build(st, diag);
        if (s)
            return s;
        st->x_0 = tirenv_xN_origin(st->R0, st->l_c, st->L, st->H);
        snprintf(st->note, sizeof st->note, "cleat %.4g x %.4g m", st->L, st->H);
        note_forms(st);
        /* No positions: only the checks of the arguments, so that set says what is wrong. */
        return tirenv_nn_envelope(st->nn, st->R0, st->l_c, st->L, st->H, 0, NULL, NULL, diag);
    }
    int s = check_range(st, TIRENV_NN_CONTACT_LENGTH + 1, diag);
    if (s ||
        (s = st->windowed ? tirenv_nn_road_alloc_window(st->nn, st->R0, st->l_c, p, NULL,
                                                        &st->win, &st->road, diag)
                          : tirenv_nn_road_alloc(st->nn, st->R0, st->l_c, p, NULL, &st->road,
                                                 diag)) ||
        (s = obstacles_in_range(st, diag)))
        return s;
    const tirenv_nn_road_info in = st->windowed ? seen_add(st) : tirenv_nn_road_info_of(st->road);
    warn_clamped(st, &in);
    if ((s = warnings_build(st, diag)))
        return s;
    snprintf(st->note, sizeof st->note, "%zu obstacles above a baseline of width %.3g m (%zu "
             "lower than the lowest trained cleat, scaled)", in.obstacles, in.width,
             in.height_below);
    if (in.height_below)
        warn(st, "%zu of %zu obstacles lower than the lowest trained cleat (%g m): their "
             "curves are its curve scaled down, an extrapolation", in.height_below,
             in.obstacles, in.H_min);
    note_forms(st);
    return TIRENV_OK;
}

/* A contact length on the profile set: over a cleat its x_N origin, over a road the
 * decomposition's (O(1), tirenv_nn_road_set_contact_length). Checked before anything changes;
 * then the warnings follow. */
static int nn_model_apply(nn_state *st, double load, double l_c, double z_flat,
                          tirenv_diag *diag)
{
    /* The new contact length within the trained range first (extrapolation allowed, it can
     * only warn: warnings_build below). */
    int status = TIRENV_OK;
    if (!st->extrapolate) {
        const double l_c_was = st->l_c;
        st->l_c = l_c;
        status = check_range(st, checked_inputs(st), diag);
        st->l_c = l_c_was;
        if (status)
            return status;
    }
    status = st->cleat
                     ? tirenv_nn_envelope(st->nn, st->R0, l_c, st->L, st->H, 0, NULL, NULL, diag)
                     : tirenv_nn_road_set_contact_length(st->road, l_c, diag);
    if (status)
        return status;
    st->load = load;
    st->l_c = l_c;
    st->z_flat = z_flat;
    if (st->cleat)
        st->x_0 = tirenv_xN_origin(st->R0, l_c, st->L, st->H);
    return warnings_build(st, diag);  /* the range is checked: it adds the warnings */
}

/* The regime at the new load, as tirenv_model_set finds it (the same flat-ground solve, so the
 * same bits), without the decomposition of the road, which does not depend on it. */
static int nn_model_set_load(void *state, double load, double *z_flat, tirenv_diag *diag)
{
    nn_state *st = state;
    double l_c = NAN, z_c = NAN;
    int status = regime(st, load, &l_c, NULL, diag);
    if (!status)
        status = chord_height(st, l_c, &z_c, diag);
    if (!status)
        status = nn_model_apply(st, load, l_c, z_c, diag);
    if (!status)
        *z_flat = z_c;
    return status;
}

/* The regime and the pair load_for_contact_length made; the network, the profile and its
 * decomposition are the instance's. */
typedef struct {
    double load, l_c, z_flat, pin_load, pin_l_c;
    int pinned;
} nn_saved;

static size_t nn_model_state_size(const void *state)
{
    (void)state;
    return sizeof(nn_saved);
}

static void nn_model_state_save(const void *state, unsigned char *buf)
{
    const nn_state *st = state;
    nn_saved sv;
    memset(&sv, 0, sizeof sv);
    sv.load = st->load;
    sv.l_c = st->l_c;
    sv.z_flat = st->z_flat;
    sv.pin_load = st->pin_load;
    sv.pin_l_c = st->pin_l_c;
    sv.pinned = st->pinned;
    tirenv_model__put(buf, &sv, sizeof sv);
}

/* How far (m) a state's flat-ground height may lie from its contact length's chord height:
 * a load change gives the chord's bits, a set the flat-ground solve's, which finds the
 * contact length again (two solves of the springs model's flat ground at one load, not
 * shown to give the same last bits); 1e-9 m, ten times the equilibrium's eps_z. */
static const double z_chord_tol = 1e-9;

/* The load is the answer's F_z and the flat-ground height its z: a state whose bytes a host
 * changed into values no set could give (not finite, not positive) is refused, and so is a
 * pinned contact length (which a set at its load takes in place of the regime's); so is one
 * whose load or flat-ground height is not the head's, or whose height is not its contact
 * length's chord height (chord_height) within z_chord_tol. The network then checks the
 * contact length as it would a new one. */
static int nn_model_state_restore(void *state, const unsigned char *buf, double load,
                                  double z_flat, tirenv_diag *diag)
{
    nn_state *st = state;
    nn_saved sv;
    tirenv_model__get(buf, &sv, sizeof sv);
    if (!st->nn || !(st->cleat || st->road))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "the nn model has no network and profile to restore onto");
    if (!(sv.load > 0 && isfinite(sv.load)) || !(sv.l_c > 0 && isfinite(sv.l_c)) ||
        !(sv.z_flat > 0 && isfinite(sv.z_flat)) ||
        (sv.pinned && !(sv.pin_l_c > 0 && isfinite(sv.pin_l_c))))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a state of the nn model (its load %g N, contact length %g m, "
                            "flat-ground height %g m, pinned contact length %g m)",
                            sv.load, sv.l_c, sv.z_flat, sv.pin_l_c);
    double z_c = NAN;
    int status = chord_height(st, sv.l_c, &z_c, diag);
    if (status)
        return status;
    const int off_chord = !(fabs(sv.z_flat - z_c) <= z_chord_tol);
    const char *field = sv.load != load       ? "its load is not the head's"
                        : sv.z_flat != z_flat ? "its flat-ground height is not the head's"
                        : off_chord ? "its flat-ground height is not its contact length's chord's"
                                    : NULL;
    if (field)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a state of the nn model: %s (load %.17g N, head's %.17g N; "
                            "flat-ground height %.17g m, head's %.17g m, the chord's %.17g m "
                            "at contact length %.17g m)",
                            field, sv.load, load, sv.z_flat, z_flat, z_c, sv.l_c);
    status = nn_model_apply(st, sv.load, sv.l_c, sv.z_flat, diag);
    if (status)
        return status;
    st->pinned = sv.pinned != 0;
    st->pin_load = sv.pin_load;
    st->pin_l_c = sv.pin_l_c;
    return TIRENV_OK;
}

static void fill(const nn_state *st, double x, double h, double slope, tirenv_point *out)
{
    *out = (tirenv_point){.x = x, .z = st->z_flat + h, .h = h, .slope = slope, .fx = 0,
                          .fz = st->load, .contacts = 0, .iterations = 0};
}

static int nn_model_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag)
{
    nn_state *st = state;
    if (!isfinite(x))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x", "must be finite, got %g", x);
    double h, slope;
    int status;
    if (st->cleat) {
        const double d = slope_step_xN * fabs(st->x_0);
        const double xs[3] = {x - d, x, x + d};
        double hs[3];
        status = tirenv_nn_envelope(st->nn, st->R0, st->l_c, st->L, st->H, 3, xs, hs, diag);
        h = hs[1];
        slope = (hs[2] - hs[0]) / (xs[2] - xs[0]);
    } else {
        status = tirenv_nn_road_eval(st->road, 1, &x, &h, &slope, diag);
    }
    if (!status)
        fill(st, x, h, slope, out);
    return status;
}

/* The sweep in blocks through the network's batch path; over a cleat the slope is the sweep's
 * own curve's, as 'tirenv predict' has always written it. */
static int nn_model_envelope(void *state, size_t n, const double x[], tirenv_point out[],
                             size_t *failed, tirenv_diag *diag)
{
    nn_state *st = state;
    double h[NN_MODEL_BLOCK], slope[NN_MODEL_BLOCK];
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(x[k])) {
            *failed = k;
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x", "must be finite, got %g",
                                x[k]);
        }
    for (size_t k0 = 0; k0 < n; k0 += NN_MODEL_BLOCK) {
        const size_t m = n - k0 < NN_MODEL_BLOCK ? n - k0 : NN_MODEL_BLOCK;
        const int status =
            st->cleat ? tirenv_nn_envelope(st->nn, st->R0, st->l_c, st->L, st->H, m, x + k0, h,
                                           diag)
                      : tirenv_nn_road_eval(st->road, m, x + k0, h, slope, diag);
        if (status) {
            *failed = k0;
            return status;
        }
        for (size_t k = 0; k < m; ++k)
            fill(st, x[k0 + k], h[k], st->cleat ? 0 : slope[k], &out[k0 + k]);
    }
    if (st->cleat && n > 1)
        for (size_t k = 0; k < n; ++k) {
            const size_t lo = k > 0 ? k - 1 : 0, hi = k + 1 < n ? k + 1 : n - 1;
            out[k].slope = (out[hi].h - out[lo].h) / (x[hi] - x[lo]);
        }
    return TIRENV_OK;
}

static void nn_model_stream_window(void *state, const tirenv_nn_road_window *w)
{
    nn_state *st = state;
    if (w && !st->windowed) {  /* a new road */
        st->counted_to = -INFINITY;
        st->seen = (tirenv_nn_road_info){0};
    }
    st->windowed = w != NULL;
    if (w)
        st->win = *w;
}

/* Over a road the decomposition reads the ground farther than the tire reaches: the
 * opening's element, the runs, the reach of their cleats (tirenv_nn_road_window_margin), with
 * the resampling grid anchored at the road's first vertex (stream.c tells the windows). */
static double nn_model_reach(const void *state, const tirenv_tire *tire)
{
    const nn_state *st = state;
    const double r = tirenv_model__default_reach(state, tire);
    if (!st->nn)
        return r;
    const double D = tirenv_nn_road_window_margin(st->nn, st->R0, NULL);
    return D > r ? D : r;
}

static void nn_model_set_extrapolate(void *state, int allow)
{
    ((nn_state *)state)->extrapolate = allow;
}

static const char *nn_model_warnings(const void *state)
{
    return ((const nn_state *)state)->warnings;
}

static const char *nn_model_note(const void *state)
{
    return ((const nn_state *)state)->note;
}

static const tirenv_model_ops nn_ops = {
    .alloc = nn_model_alloc,
    .free = nn_model_free,
    .flat = nn_model_flat,
    .load_for_contact_length = nn_model_load_for_contact_length,
    .set = nn_model_set,
    .set_profile = nn_model_set,
    .set_load = nn_model_set_load,
    .eval = nn_model_eval,
    .reach = nn_model_reach,
    .state_size = nn_model_state_size,
    .state_save = nn_model_state_save,
    .state_restore = nn_model_state_restore,
};

static const tirenv_model_network nn_network = {
    .set_network = nn_model_set_network,
    .set_contact_law = nn_model_set_contact_law,
    .set_extrapolate = nn_model_set_extrapolate,
    .warnings = nn_model_warnings,
    .note = nn_model_note,
    .envelope = nn_model_envelope,
    .stream_window = nn_model_stream_window,
};

static const tirenv_model_type nn_type = {
    .name = "nn",
    .summary = "the paper's trained network (--nn FILE)",
    .flags = TIRENV_MODEL_STREAMS,
    .tracks = TIRENV_TRACKS_MEAN,
    .ops = &nn_ops,
    .network = &nn_network,
};
const tirenv_model_type *tirenv_model_nn = &nn_type;
