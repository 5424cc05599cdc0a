/* SPDX-License-Identifier: Apache-2.0 */
/* The constant-load equilibrium per position (docs/models.md section 11), shared by every
 * deformable model: it only needs their hub-force function and their contact length. The
 * equilibrium itself is the core's solver (src/core/equilibrium.c), which reports an
 * evaluated point: z, F_z, F_x and the contacts of a row all come from one force evaluation. */
#include "model/deformable.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/brent.h"
#include "core/equilibrium.h"
#include "profile/profile_impl.h"
#include "model/rigid_impl.h"

typedef struct {
    const tirenv_model_type *type;  /* for its name in messages */
    const tirenv_deformable *def;   /* the type's deformable record */
    void *elem;                  /* the model's own workspace, on the profile */
    void *flat_elem;             /* another, on flat ground: a load change solves the flat
                                  * equilibrium there without disturbing the first's warm
                                  * state, and finds its own from the last load's */
    tirenv_tire tire;
    tirenv_eq_solver *solver;    /* of tire.eq.method, allocated once */
    tirenv_profile *flat;        /* flat ground z = 0, for the flat-ground reference */
    const tirenv_profile *prof;  /* current profile (borrowed) */
    double G;                    /* load, N */
    double z_flat;               /* flat-ground centre height at G, m: of the force
                                  * function's centre, u above the hub (series) */
    int has_series;              /* the tire has a series spring (deformable.h's series) */
    tirenv_deformable_history prev; /* warm start: the last two equilibria */
    size_t rigid_hint;           /* profile segment of the last position, for the bracket */
    /* The last flat-ground equilibrium: its load (N) and point, so that tirenv_model_set,
     * which solves it first, does not evaluate it again. */
    int have_flat_point;
    double flat_load;
    tirenv_eq_point flat_point;
    /* The flat-ground equilibrium at the load set (z = z_flat), for level stretches of
     * ground and as the start of the next load's. */
    int shift_invariant;
    tirenv_eq_point flat_at;
    /* What the tire can touch in that state (the record's level_reach at z_flat): a radius
     * (m) about the centre and the tangent of a vertex's cone (deformable_clear.c). */
    double clear_r, clear_tan;
    /* The valid range (docs/models.md section 1.3), found on first need: flat-ground centre
     * heights from z_min up to R0, loads up to G_max (N), contact lengths up to l_max (m). */
    int have_range;
    double z_min, G_max, l_max;
    char range_why[160];
} deformable_state;

/* The force function the solver calls: the model's forces at one position. */
typedef struct {
    deformable_state *st;
    const tirenv_profile *prof;
    double x;                    /* m */
} force_ctx;

static int force_at(void *ctx, double z, tirenv_eq_point *out, tirenv_diag *diag)
{
    const force_ctx *c = ctx;
    const deformable_state *st = c->st;
    const int status = st->def->forces(st->elem, c->prof, c->x, z, out, diag);
    /* The model's own step only where Newton takes a step (the other methods take none):
     * within eps_F of the load the linear one decides convergence as before. It starts from
     * the slope, which Newton asks for there anyway where the model deferred it. */
    if (!status && st->def->root && st->tire.eq.method == TIRENV_EQ_NEWTON &&
        fabs(out->F - st->G) > st->tire.eq.eps_F) {
        if (isnan(out->dF_dz) && st->def->slope &&
            (st->def->slope(st->elem, &out->dF_dz) || !isfinite(out->dF_dz)))
            return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                                "the force function gave no dF_z/dz at z = %.9g m", z);
        out->has_root = st->def->root(st->elem, c->prof, c->x, z, st->G, out, &out->z_root);
    }
    return status;
}

/* The model's first iterate at the position, for Newton (tirenv_eq_problem's start). */
static int start_at(void *ctx, double z0, double *z)
{
    const force_ctx *c = ctx;
    return c->st->def->start(c->st->elem, c->prof, c->x, z0, c->st->G, z);
}

/* The slope of force_at's last evaluation, which left it out (defer_slope). */
static int slope_at(void *ctx, double *dF_dz)
{
    const force_ctx *c = ctx;
    return c->st->def->slope(c->st->elem, dF_dz);
}

/* The same on flat ground, with the flat-ground workspace. */
static int flat_force_at(void *ctx, double z, tirenv_eq_point *out, tirenv_diag *diag)
{
    const force_ctx *c = ctx;
    return c->st->def->forces(c->st->flat_elem, c->st->flat, 0, z, out, diag);
}

static void deformable_free(void *state)
{
    deformable_state *st = state;
    if (st->elem)
        st->def->free(st->elem);
    if (st->flat_elem)
        st->def->free(st->flat_elem);
    tirenv_eq__solver_free(st->solver);
    tirenv_profile_free(st->flat);
    free(st);
}

static void *deformable_alloc(const tirenv_model_type *type, const tirenv_tire *tire)
{
    const tirenv_deformable *def = type->deformable;
    deformable_state *st = calloc(1, sizeof *st);
    const double zero = 0;
    if (!st)
        return NULL;
    st->type = type;
    st->def = def;
    st->tire = *tire;
    st->elem = def->alloc(tire);
    st->flat_elem = def->alloc(tire);
    st->solver = tirenv_eq__solver_alloc(tirenv_eq__solver_type_of(tire->eq.method));
    st->shift_invariant = def->shift_invariant(tire);
    st->has_series = tirenv_deformable_series(def, tire, INFINITY) > 0;
    st->flat = tirenv_profile_alloc(1, &zero, &zero);
    if (!st->elem || !st->flat_elem || !st->solver || !st->flat) {
        deformable_free(st);
        return NULL;
    }
    return st;
}

double tirenv_deformable_series(const tirenv_deformable *def, const tirenv_tire *tire,
                                double F)
{
    double c;
    return def->series ? def->series(tire, F, &c) : 0;
}

/* The hub's stiffness (N/m) from the force function's, k (N/m), and the series spring's
 * compliance c (m/N) at the same force: k itself without one, so that a tire without it keeps
 * its bits. */
static double in_series(double k, double c)
{
    return c > 0 && k > 0 ? 1 / (1 / k + c) : k;
}

/* The series spring's deflection (m) and compliance (m/N, into *c unless NULL) at force F
 * (N). */
static double series_at(const deformable_state *st, double F, double *c)
{
    double c_unused;
    if (!c)
        c = &c_unused;
    *c = 0;
    return st->def->series ? st->def->series(&st->tire, F, c) : 0;
}

/* How far the hub lies below the force function's centre at the load G: the series spring's
 * deflection there, constant while the load is (m; 0 without one). */
static double hub_offset(const deformable_state *st)
{
    return series_at(st, st->G, NULL);
}

/* The valid range, once per model: the load and contact length at the lowest centre height
 * the model's physics allows. Without a limit of the model's own, the centre at the ground
 * bounds the load, which the equilibrium's bracket reports (TIRENV_ENOBRACKET). */
static int valid_range(deformable_state *st, tirenv_diag *diag)
{
    if (st->have_range)
        return TIRENV_OK;
    const double R0 = st->tire.springs.R0;
    double z = 0;
    st->range_why[0] = '\0';
    int status = st->def->lowest_z(st->flat_elem, st->flat, &z, st->range_why,
                                   sizeof st->range_why, diag);
    if (status)
        return status;
    st->z_min = z;
    st->G_max = INFINITY;
    st->l_max = 2 * R0;
    if (z > 0) {
        tirenv_eq_point p;
        if ((status = st->def->contact_length(st->flat_elem, st->flat, z, &st->l_max, &p,
                                              diag)))
            return status;
        st->G_max = p.F;
    }
    st->have_range = 1;
    return TIRENV_OK;
}

/* A failure on flat ground has no position to name; the load is what the user gave. */
static int on_flat_ground(double load, int status, tirenv_diag *diag)
{
    if (status && status != TIRENV_ENOBRACKET && diag) {  /* that one names the load */
        char msg[sizeof diag->message];
        snprintf(msg, sizeof msg, "on flat ground at load %.6g N: %.440s", load, diag->message);
        memcpy(diag->message, msg, sizeof msg);
    }
    return status;
}

/* The flat-ground equilibrium at load from z0 in [0, R0], on the flat-ground workspace. */
static int solve_flat(deformable_state *st, double load, double z0, tirenv_eq_point *out,
                      tirenv_diag *diag)
{
    const double R0 = st->tire.springs.R0;
    const tirenv_eq_problem prob = {.z_lo = 0, .z_hi = R0, .z0 = z0, .dz_hint = 0.05 * R0};
    force_ctx fc = {st, st->flat, 0};
    tirenv_eq_result res;
    const int status = tirenv_eq__solve(st->solver, &st->tire.eq, flat_force_at, &fc, load,
                                        &prob, &res, diag);
    if (status)
        return on_flat_ground(load, status, diag);
    *out = res.point;
    return TIRENV_OK;
}

/* TIRENV_ERANGE for a value of one of the valid range's three quantities beyond the range's
 * end (docs/models.md section 1.3): the value, the end, and the other two quantities there. */
enum { RANGE_LOAD, RANGE_HEIGHT, RANGE_LENGTH };
static int beyond_range(const deformable_state *st, int which, double value,
                        tirenv_diag *diag)
{
    static const char *const field[] = {"load", "centre height", "contact length"};
    char end[3][32], others[128];
    snprintf(end[RANGE_LOAD], sizeof end[0], "%.6g N", st->G_max);
    snprintf(end[RANGE_HEIGHT], sizeof end[0], "%.4g m", st->z_min);
    snprintf(end[RANGE_LENGTH], sizeof end[0], "%.4g m", st->l_max);
    const int a = which == RANGE_LOAD ? RANGE_HEIGHT : RANGE_LOAD;
    const int b = which == RANGE_LENGTH ? RANGE_HEIGHT : RANGE_LENGTH;
    snprintf(others, sizeof others, "%s %s, %s %s", field[a], end[a], field[b], end[b]);
    return tirenv_error(diag, TIRENV_ERANGE, "", 0, field[which],
                        "%g %s is beyond the %s model's valid range, %s %s (%s), %s", value,
                        which == RANGE_LOAD ? "N" : "m", st->type->name,
                        which == RANGE_HEIGHT ? "down to" : "up to", end[which], others,
                        st->range_why);
}

/* TIRENV_ERANGE if the load is beyond the valid range (docs/models.md section 1.3): for a
 * first load (deformable_flat) and a new one (deformable_set_load) alike. */
static int load_in_range(deformable_state *st, double load, tirenv_diag *diag)
{
    int status = valid_range(st, diag);
    if (status)
        return on_flat_ground(load, status, diag);
    if (load > st->G_max)
        return beyond_range(st, RANGE_LOAD, load, diag);
    return TIRENV_OK;
}

static int deformable_flat(void *state, double load, tirenv_flat *out, tirenv_diag *diag)
{
    deformable_state *st = state;
    const double R0 = st->tire.springs.R0;
    int status = load_in_range(st, load, diag);
    if (status)
        return status;
    tirenv_eq_point p;
    if ((status = solve_flat(st, load, R0, &p, diag)))
        return status;
    double l_c;
    if ((status = st->def->contact_length(st->flat_elem, st->flat, p.z, &l_c, NULL, diag)))
        return on_flat_ground(load, status, diag);
    st->have_flat_point = 1;
    st->flat_load = load;
    st->flat_point = p;
    double c;
    const double z_hub = p.z - series_at(st, load, &c);
    *out = (tirenv_flat){
        .load = load,
        .z_flat = z_hub,
        .deflection = R0 - z_hub,
        .contact_length = l_c,
        .stiffness = in_series(-p.dF_dz, c),
    };
    return TIRENV_OK;
}

/* The flat-ground contact length minus the one sought, at a centre height z (m). */
typedef struct {
    const deformable_state *st;
    double l_c;                  /* m */
    int status;                  /* the first failure of the model's contact length */
    tirenv_diag *diag;
} patch_ctx;

static double patch_minus_target(double z, void *p)
{
    patch_ctx *c = p;
    double l = 0;
    const int s =
        c->st->def->contact_length(c->st->flat_elem, c->st->flat, z, &l, NULL, c->diag);
    if (s && !c->status)
        c->status = s;
    return l - c->l_c;
}

/* The flat-ground centre height at which the model's contact length is l_c (m), for every
 * deformable model (docs/models.md section 1.3): each model's contact length is the length of
 * ground its tread touches, which grows continuously (its edges are interpolated) as the
 * centre comes down to the lowest height of the valid range, z_lo, where it is longest; so
 * Brent finds the height: on [R0/2, R0] when the contact length at R0/2 is long enough
 * (every contact length up to 0.69 m for the default tire's ring: the bracket of old, so the
 * data set's loads keep their bits), else on [z_lo, R0/2]. 1e-12 m is far below any contact
 * length's meaning and Brent needs about 40 iterations for it from a 0.34 m bracket, so 200 is
 * only a guard. */
enum { PATCH_MAX_ITER = 200 };
static const double patch_z_tol = 1e-12; /* m */
static int z_for_contact_length(const deformable_state *st, double l_c, double z_lo,
                                double *z, tirenv_diag *diag)
{
    patch_ctx ctx = {st, l_c, 0, diag};
    /* Each end of the bracket evaluated once: f(lo) decides the bracket and starts Brent. */
    double hi = st->tire.springs.R0, lo = fmax(z_lo, 0.5 * hi);
    double f_lo = patch_minus_target(lo, &ctx), f_hi = 0;
    int have_hi = 0;
    if (lo > z_lo && f_lo < 0 && !ctx.status) {
        hi = lo;
        f_hi = f_lo;
        have_hi = 1;
        lo = z_lo;
        f_lo = patch_minus_target(lo, &ctx);
    }
    if (f_lo < 0 || ctx.status)
        return ctx.status ? ctx.status
                          : tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                                         "%g m is beyond the %s tire's reach", l_c,
                                         st->type->name);
    if (!have_hi)
        f_hi = patch_minus_target(hi, &ctx);
    tirenv_core__brent br;
    int status = tirenv_core__brent_set_values(&br, patch_minus_target, &ctx, lo, f_lo, hi,
                                               f_hi);
    for (int it = 0; !status && it < PATCH_MAX_ITER; ++it) {
        status = tirenv_core__brent_iterate(&br);
        if (!status && tirenv_core__brent_converged(&br, patch_z_tol))
            break;
    }
    *z = br.root;
    if (ctx.status)  /* the forces' own message says what failed */
        return ctx.status;
    if (status)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "contact length",
                            "no %s height found for %g m: %s", st->type->name, l_c,
                            tirenv_core__brent_strerror(status));
    return 0;
}

/* The model's own contact-length definition gives z_flat; the load is one force there. */
static int deformable_load_for_contact_length(void *state, double l_c, double *load,
                                              tirenv_diag *diag)
{
    deformable_state *st = state;
    const double R0 = st->tire.springs.R0;
    if (!(l_c > 0 && l_c < 2 * R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                            "must be in (0, 2*R0) = (0, %g) m, got %g", 2 * R0, l_c);
    int status = valid_range(st, diag);
    if (status)
        return status;
    if (l_c > st->l_max)
        return beyond_range(st, RANGE_LENGTH, l_c, diag);
    double z = 0;
    status = z_for_contact_length(st, l_c, st->z_min, &z, diag);
    tirenv_eq_point p;
    if (!status)
        status = st->def->forces(st->flat_elem, st->flat, 0, z, &p, diag);
    if (!status)
        *load = p.F;
    return status;
}

/* With a series spring, the centre height z_c (m) of the force function whose hub is at z
 * (m): the root of g(z_c) = z_c - u(F(z_c)) - z, which grows with z_c (F never increases with
 * the height, u never decreases with F) from g(z) = -u(F(z)) <= 0 to g(R0) = R0 - z > 0,
 * nothing touching at R0; so Brent on [z, R0] finds it, to the contact length's 1e-12 m. */
typedef struct {
    const deformable_state *st;
    double z;                    /* the hub's height, m */
    int status;                  /* the first failure of the model's forces */
    tirenv_diag *diag;
} hub_ctx;

static double hub_minus_target(double z_c, void *p)
{
    hub_ctx *c = p;
    tirenv_eq_point at;
    const int s = c->st->def->forces(c->st->flat_elem, c->st->flat, 0, z_c, &at, c->diag);
    if (s && !c->status)
        c->status = s;
    return z_c - series_at(c->st, s ? 0 : at.F, NULL) - c->z;
}

static int centre_for_hub(const deformable_state *st, double z, double *z_c, tirenv_diag *diag)
{
    const double R0 = st->tire.springs.R0;
    hub_ctx ctx = {st, z, 0, diag};
    const double f_lo = hub_minus_target(z, &ctx);
    *z_c = z;
    if (ctx.status || f_lo == 0)
        return ctx.status;
    tirenv_core__brent br;
    int status = tirenv_core__brent_set_values(&br, hub_minus_target, &ctx, z, f_lo, R0, R0 - z);
    for (int it = 0; !status && !ctx.status && it < PATCH_MAX_ITER; ++it) {
        status = tirenv_core__brent_iterate(&br);
        if (!status && tirenv_core__brent_converged(&br, patch_z_tol))
            break;
    }
    *z_c = br.root;
    if (ctx.status)
        return ctx.status;
    if (status || !tirenv_core__brent_converged(&br, patch_z_tol))
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "centre height",
                            "the %s model's elements found no height with the hub at %g m and "
                            "SIDEWALL_STIFFNESS %g N/m, SIDEWALL_PRELOAD %g N (bracket [%g, %g] "
                            "m): %s", st->type->name, z, st->tire.springs.k_s,
                            st->tire.springs.F_s0, z, R0,
                            status ? tirenv_core__brent_strerror(status)
                                   : "not converged in the iterations allowed");
    return TIRENV_OK;
}

/* One force evaluation at the height: its load and stiffness, and the model's contact length
 * there; with a series spring, the force function's centre found first (centre_for_hub). */
static int deformable_flat_at_height(void *state, double z, tirenv_flat *out,
                                     tirenv_diag *diag)
{
    deformable_state *st = state;
    const double R0 = st->tire.springs.R0;
    if (!(z > 0 && z < R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "centre height",
                            "must be in (0, R0) = (0, %g) m, got %g", R0, z);
    int status = valid_range(st, diag);
    if (status)
        return status;
    if (z < st->z_min)
        return beyond_range(st, RANGE_HEIGHT, z, diag);
    double z_c = z;
    if (st->has_series && (status = centre_for_hub(st, z, &z_c, diag)))
        return status;
    tirenv_eq_point p;
    double l_c, c;
    if ((status = st->def->contact_length(st->flat_elem, st->flat, z_c, &l_c, &p, diag)))
        return status;
    series_at(st, p.F, &c);
    *out = (tirenv_flat){
        .load = p.F,
        .z_flat = z,
        .deflection = R0 - z,
        .contact_length = l_c,
        .stiffness = in_series(-p.dF_dz, c),
    };
    return TIRENV_OK;
}

/* The bound of clear ground at the flat state just set (st->z_flat): without the record's
 * level_reach, none (r infinite), and only level ground is short-cut. */
static void level_reach(deformable_state *st)
{
    st->clear_r = INFINITY;
    st->clear_tan = 0;
    if (st->def->level_reach)
        st->def->level_reach(&st->tire, st->z_flat, &st->clear_r, &st->clear_tan);
}

static int deformable_set(void *state, const tirenv_profile *p, double load, double z_flat,
                          tirenv_diag *diag)
{
    deformable_state *st = state;
    st->prof = p;
    st->G = load;
    const double u = hub_offset(st);
    /* tirenv_model_set has just solved the flat ground at this load: its point is z_flat, the
     * hub's, u below the centre's it was solved for (that centre's own bits kept). */
    tirenv_eq_point flat = st->flat_point;
    const int same = st->have_flat_point && st->flat_load == load && flat.z - u == z_flat;
    const double z_c = same ? flat.z : z_flat + u;
    st->z_flat = z_c;
    tirenv_deformable_history_clear(&st->prev);
    if (st->def->reprofile) /* what the workspace carries from position to position, too */
        st->def->reprofile(st->elem, NULL, p);
    int status = TIRENV_OK;
    if (!(same && flat.z == z_c))
        status = st->def->forces(st->flat_elem, st->flat, 0, z_c, &flat, diag);
    if (status)
        return status;
    flat.z = z_c;
    st->flat_at = flat;
    level_reach(st);
    return TIRENV_OK;
}

/* A new load: the flat-ground equilibrium there, Newton from the last load's flat point
 * stepped along its tangent (z - (G_new - G)/k with k = -dF_z/dz), which on flat ground,
 * with a load that changes by a few per cent, converges in two force evaluations where a
 * start from R0 takes five or more; the profile is not looked at. The warm start moves with
 * the flat-ground height, its best guess of how the tire sinks over any ground. */
static int deformable_set_load(void *state, double load, double *z_flat, tirenv_diag *diag)
{
    deformable_state *st = state;
    const double R0 = st->tire.springs.R0;
    int status = load_in_range(st, load, diag);
    if (status)
        return status;
    const tirenv_eq_point *at = &st->flat_at;
    double z0 = at->dF_dz < 0 ? at->z + (load - st->G) / at->dF_dz : at->z;
    z0 = fmin(fmax(z0, 0.0), R0);
    tirenv_eq_point p;
    if ((status = solve_flat(st, load, z0, &p, diag)))
        return status;
    tirenv_deformable_history_shift(&st->prev, p.z - st->z_flat);
    st->G = load;
    st->z_flat = p.z;
    *z_flat = p.z - hub_offset(st);
    st->flat_at = p;
    level_reach(st);
    return TIRENV_OK;
}

/* What the next evaluations depend on: the load and its flat-ground point, the warm start,
 * and the contact states both workspaces start their next solves from (the model's own, its
 * deformable record's state_*). The rays' caches and the bracket's search hint change no bit
 * of a result. */
typedef struct {
    double G, z_flat, z_prev, x_prev, x_prev2, z_prev2;
    tirenv_eq_point flat_at;
    int have_prev, have_prev2;
} deformable_saved;

static size_t deformable_state_size(const void *state)
{
    const deformable_state *st = state;
    return sizeof(deformable_saved) + st->def->state_size(st->elem, 0) +
           st->def->state_size(st->flat_elem, 1);
}

static void deformable_state_save(const void *state, unsigned char *buf)
{
    const deformable_state *st = state;
    deformable_saved sv;
    memset(&sv, 0, sizeof sv);  /* the padding too: the same state, the same bytes */
    sv.G = st->G;
    sv.z_flat = st->z_flat;
    sv.z_prev = st->prev.z1;
    sv.flat_at = st->flat_at;
    sv.have_prev = st->prev.have1;
    sv.x_prev = st->prev.x1;
    sv.x_prev2 = st->prev.x2;
    sv.z_prev2 = st->prev.z2;
    sv.have_prev2 = st->prev.have2;
    buf = tirenv_model__put(buf, &sv, sizeof sv);
    st->def->state_save(st->elem, st->prof, 0, buf);
    st->def->state_save(st->flat_elem, st->flat, 1, buf + st->def->state_size(st->elem, 0));
}

/* A state's bytes may have been changed by a host (docs/models.md section 1.7). What the
 * answers are made of, the load (within the model's range) and the flat-ground point (level
 * ground's answer), must be finite, or the state is refused; so must the copies of one
 * quantity agree, bit for bit as every set and load change writes them: the load and the
 * head's, the flat-ground point's height and the record's z_flat, the hub's flat-ground
 * height in the head and the record's less the series spring's deflection (deformable_set,
 * _set_load). The history of equilibria only says where the next solve begins: one that is
 * not finite is dropped for the cold start, whose answer meets the same tolerances. */
static int deformable_state_restore(void *state, const unsigned char *buf, double load,
                                    double z_flat, tirenv_diag *diag)
{
    deformable_state *st = state;
    deformable_saved sv;
    buf = tirenv_model__get(buf, &sv, sizeof sv);
    if (!(sv.G > 0 && isfinite(sv.G)) || !(sv.z_flat > 0 && isfinite(sv.z_flat)) ||
        (sv.have_prev != 0 && sv.have_prev != 1) || (sv.have_prev2 != 0 && sv.have_prev2 != 1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a state of the %s model (load %g N, z_flat %g m)",
                            st->type->name, sv.G, sv.z_flat);
    int status = load_in_range(st, sv.G, diag); /* every evaluation would refuse it */
    if (status)
        return status;
    const tirenv_eq_point *f = &sv.flat_at;
    if (!(isfinite(f->z) && isfinite(f->F) && isfinite(f->fx)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a state of the %s model (its flat-ground point: z %g m, F_z "
                            "%g N, F_x %g N)",
                            st->type->name, f->z, f->F, f->fx);
    const double z_hub = sv.z_flat - series_at(st, sv.G, NULL);
    const char *field = sv.G != load      ? "its load is not the head's"
                        : f->z != sv.z_flat ? "its flat-ground point's height is not its z_flat"
                        : z_hub != z_flat   ? "the head's flat-ground height is not its hub's"
                                            : NULL;
    if (field)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a state of the %s model: %s (load %.17g N, head's %.17g N; "
                            "z_flat %.17g m, its flat-ground point's %.17g m; the hub's %.17g "
                            "m, head's %.17g m)",
                            st->type->name, field, sv.G, load, sv.z_flat, f->z, z_hub, z_flat);
    if (!(isfinite(sv.x_prev) && isfinite(sv.z_prev)))
        sv.have_prev = sv.have_prev2 = 0;
    if (!(isfinite(sv.x_prev2) && isfinite(sv.z_prev2)))
        sv.have_prev2 = 0;
    st->G = sv.G;
    st->z_flat = sv.z_flat;
    st->prev.z1 = sv.z_prev;
    st->flat_at = sv.flat_at;
    st->prev.have1 = sv.have_prev;
    st->prev.x1 = sv.x_prev;
    st->prev.x2 = sv.x_prev2;
    st->prev.z2 = sv.z_prev2;
    st->prev.have2 = sv.have_prev2;
    status = st->def->state_restore(st->elem, st->prof, 0, buf);
    if (!status)
        status = st->def->state_restore(st->flat_elem, st->flat, 1,
                                        buf + st->def->state_size(st->elem, 0));
    if (status)
        return tirenv_error(diag, status, "", 0, "state",
                            status == TIRENV_ENOMEM
                                ? "no memory for the %s model's contact state"
                                : "not a state of the %s model (its contact state)",
                            st->type->name);
    level_reach(st);
    return TIRENV_OK;
}

/* The next window of the same ground: the equilibrium of the last position still holds, so the
 * warm start carries over and a stream gives the same iterations as one whole profile. */
static int deformable_set_profile(void *state, const tirenv_profile *p, double load,
                                  double z_flat, tirenv_diag *diag)
{
    deformable_state *st = state;
    (void)load;
    (void)z_flat;
    (void)diag;
    if (st->def->reprofile && st->prof && p)
        st->def->reprofile(st->elem, st->prof, p);
    st->prof = p;
    return TIRENV_OK;
}

int tirenv_deformable_forces(void *state, double x, double z, tirenv_eq_point *out,
                             tirenv_diag *diag)
{
    deformable_state *st = state;
    return st->def->forces(st->elem, st->prof, x, z, out, diag);
}

/* The warm start: for a model whose Newton converges slowly (the ring, whose dF_z/dz leaves
 * out that the cuts at ground vertices move with z, so that every millimetre the start is off
 * costs evaluations) the line through the last two equilibria; the solver clamps it to the
 * bracket. */
double tirenv_deformable_predict(int extrapolate, int have2, double x, double x1, double z1,
                                 double x2, double z2)
{
    if (!(extrapolate && have2))
        return z1;
    const double t = (x - x1) / (x1 - x2);
    if (!(t > 0 && t <= 2))
        return z1;
    return z1 + (z1 - z2) * t;
}

static int deformable_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag)
{
    deformable_state *st = state;
    const double R0 = st->tire.springs.R0;
    /* Level ground under the tire and nothing else within reach that it can touch (the
     * default reach of model_impl.h; docs/models.md section 11.4): the flat-ground
     * equilibrium shifted by the level meets every contact condition there, and is returned
     * with no force evaluation. The solver would land within its tolerance of the same
     * height; a road's run-in and run-out, and an obstacle's approach, cost nothing. */
    double level;
    if (st->shift_invariant &&
        tirenv_profile__level_clear(st->prof, x, TIRENV_MODEL__REACH * R0, st->z_flat,
                                    st->clear_r, st->clear_tan, &level)) {
        /* fx is 0 by symmetry, which the force sum only meets to round-off. */
        const double z_c = st->z_flat + level;
        *out = (tirenv_point){.x = x, .z = z_c - hub_offset(st), .h = level, .fx = 0,
                              .fz = st->flat_at.F, .contacts = st->flat_at.contacts};
        out->slope = tirenv_model__slope(out);
        /* The next start: this height (the level may end there). */
        tirenv_deformable_history_restart(&st->prev, x, z_c);
        return TIRENV_OK;
    }
    const double deflection = R0 - st->z_flat;
    /* Warm, Newton guards each step with the bracket and needs only a valid one, which the
     * model may know more cheaply than the rigid disc's height. A cold start (z_hi less the
     * deflection), the plain secant of eq. 2 (no safeguard: two starts above contact break it
     * down) and Brent (its iterations grow with the bracket) keep the disc's, the tightest. */
    double z_lo, z_hi;
    const int cheap = st->prev.have1 && st->tire.eq.method == TIRENV_EQ_NEWTON &&
                      st->def->bracket(st->elem, st->prof, x, &z_lo, &z_hi);
    if (!cheap)
        tirenv_rigid__bracket(1, &st->prof, R0, x, &st->rigid_hint, &z_lo, &z_hi);
    /* Newton asks for the slope of an evaluation only where it needs it (eq_newton.c):
     * where the model defers it, the position's last evaluation mostly goes without. */
    const int defer = st->def->defer_slope && st->tire.eq.method == TIRENV_EQ_NEWTON &&
                      st->def->defer_slope(st->elem, 1);
    const tirenv_eq_problem prob = {
        .z_lo = z_lo,
        .z_hi = z_hi,
        .z0 = tirenv_deformable_history_start(&st->prev, st->def->extrapolate, x,
                                              z_hi - deflection),
        .dz_hint = deflection,
        .slope = defer ? slope_at : NULL,
        .start = st->def->start && st->tire.eq.method == TIRENV_EQ_NEWTON ? start_at : NULL,
    };
    force_ctx fc = {st, st->prof, x};
    tirenv_eq_result res;
    int status = tirenv_eq__solve(st->solver, &st->tire.eq, force_at, &fc, st->G, &prob,
                                  &res, diag);
    if (defer)
        st->def->defer_slope(st->elem, 0);
    out->x = x;
    out->iterations = res.evals;
    if (!status)
        status = tirenv_deformable_check_jump(st->def, &st->tire, &res, st->G, diag);
    if (status)
        return status;
    tirenv_deformable_history_push(&st->prev, x, res.point.z);
    /* h between the centre's heights (the series spring's u, constant at the load, cancels:
     * the same bits with or without one); the hub u below the centre. */
    tirenv_model__eq_point(&res.point, st->z_flat, out);
    out->z = res.point.z - hub_offset(st);
    return TIRENV_OK;
}

int tirenv_deformable_check_jump(const tirenv_deformable *def, const tirenv_tire *tire,
                                 const tirenv_eq_result *res, double G, tirenv_diag *diag)
{
    if (!(res->jump > tire->eq.eps_F + 1e-6 * G) || !def->continuous || !def->continuous(tire))
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "equilibrium",
                        "F_z jumps by %.3g N across z = %.9g m, where the continuous contact "
                        "has no jump: no equilibrium at this load there (a defect of the "
                        "model's contact, not of the input)", res->jump, res->point.z);
}

int tirenv_deformable_no_bracket(void *elem, const tirenv_profile *p, double x, double *z_lo,
                                   double *z_hi)
{
    (void)elem;
    (void)p;
    (void)x;
    (void)z_lo;
    (void)z_hi;
    return 0;
}

int tirenv_deformable_invariant(const tirenv_tire *tire)
{
    (void)tire;
    return 1;
}

const tirenv_model_ops tirenv_deformable_ops = {
    .alloc = deformable_alloc,
    .free = deformable_free,
    .flat = deformable_flat,
    .load_for_contact_length = deformable_load_for_contact_length,
    .flat_at_height = deformable_flat_at_height,
    .set = deformable_set,
    .set_profile = deformable_set_profile,
    .set_load = deformable_set_load,
    .eval = deformable_eval,
    .reach = tirenv_model__default_reach,
    .state_size = deformable_state_size,
    .state_save = deformable_state_save,
    .state_restore = deformable_state_restore,
};
