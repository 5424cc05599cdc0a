/* SPDX-License-Identifier: Apache-2.0 */
/* The ring reference tire as a tirenv_model_type (docs/models.md section 5). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include "core/golden.h"
#include "model/deformable.h"
#include "model/ring_impl.h"
#include "tirenv/ring.h"

static void *ring_alloc(const tirenv_tire *tire)
{
    return tirenv_ring_alloc(tire->springs.R0, &tire->ring);
}

static void ring_free(void *elem) { tirenv_ring_free(elem); }

static int ring_forces(void *elem, const tirenv_profile *p, double x, double z,
                       tirenv_eq_point *out, tirenv_diag *diag)
{
    const int defer = tirenv_ring__deferring(elem);
    const int status = tirenv_ring_forces(elem, p, x, z, &out->fx, &out->F,
                                          defer ? NULL : &out->dF_dz, &out->contacts, diag);
    if (!status && defer) {
        tirenv_ring__root_seen(elem, x, z, out->F);
        tirenv_ring__root_eval(elem, x, z);
    }
    return status;
}

/* The ring's start at a new x (ring_root.c), where its slope is deferred as for its step. */
static int ring_start(void *elem, const tirenv_profile *p, double x, double z0, double G,
                      double *z)
{
    (void)p, (void)z0, (void)G;
    return tirenv_ring__deferring(elem) && tirenv_ring__root_start(elem, x, z);
}

/* The ring's own step in z (ring_root.c), where its slope is deferred: the shear-coupled
 * tread with the linear carcass under Newton, whose answer does not depend on the path to it
 * (the softening carcass's does, and the Winkler tread's slope leaves the moving cuts out). */
static int ring_root(void *elem, const tirenv_profile *p, double x, double z, double G,
                     const tirenv_eq_point *at, double *z_root)
{
    (void)p;
    return tirenv_ring__deferring(elem) &&
           tirenv_ring__root(elem, x, z, at->F, at->dF_dz, G, z_root);
}

static int ring_defer_slope(void *elem, int on) { return tirenv_ring__defer_slope(elem, on); }

static int ring_slope(void *elem, double *dF_dz) { return tirenv_ring__slope(elem, dF_dz); }

/* The ring's contact length is its real patch, where the tread pressure is positive: shorter
 * than the chord of the free circle, as real tires' are (docs/models.md section 1). It grows
 * continuously as the centre comes down (its edges are interpolated), and deformable.c's
 * search finds the height of a contact length. */
static int ring_contact_length(void *elem, const tirenv_profile *flat, double z, double *l_c,
                               tirenv_eq_point *at, tirenv_diag *diag)
{
    tirenv_eq_point p = {.z = z};
    const int status = tirenv_ring_forces(elem, flat, 0, z, &p.fx, &p.F, at ? &p.dF_dz : NULL,
                                          at ? &p.contacts : NULL, diag);
    if (at)
        *at = p;
    *l_c = tirenv_ring_patch_length(elem);
    return status;
}

/* The ring is a linear model of small belt displacements; pressed far enough, its rays fan
 * out over ground ever farther below the belt and its patch, after growing with the load,
 * shrinks (the default tire's from about 0.83 m at 255 kN down to 0.53 m at 448 kN, where the
 * centre meets the ground). A patch that shrinks under more load is no tire: the valid range
 * ends where the flat-ground patch is longest (docs/models.md section 5.4). It is found on a
 * grid of TIRENV_RING_RANGE_STEPS heights from R0 down, stopping two steps past the longest,
 * then by golden sections between that one's neighbours to RANGE_TOL*R0; about 45 force
 * evaluations, once per model. A force that fails on the way ends the scan: the range ends
 * above it. */
static const double RANGE_TOL = 1e-6;

static int patch_at(void *elem, const tirenv_profile *flat, double z, double *l,
                    tirenv_diag *diag)
{
    return ring_contact_length(elem, flat, z, l, NULL, diag);
}

/* -l at height z for the golden section: its first failure kept, after which nothing is
 * evaluated (and 0 returned). */
typedef struct {
    void *elem;
    const tirenv_profile *flat;
    int status;
    tirenv_diag *diag;
} range_ctx;

static double minus_patch(double z, void *p)
{
    range_ctx *x = p;
    double l = 0;
    if (!x->status)
        x->status = patch_at(x->elem, x->flat, z, &l, x->diag);
    return -l;
}

static int ring_lowest_z(void *elem, const tirenv_profile *flat, double *z, char *why,
                         size_t n, tirenv_diag *diag)
{
    const double R0 = tirenv_ring_free_radius(elem), dz = R0 / TIRENV_RING_RANGE_STEPS;
    double best_l = 0;
    size_t best = 0, k;
    tirenv_diag scan; /* why the scan stopped, said if no patch came before */
    int scan_status = 0;
    tirenv_diag_clear(&scan);
    for (k = 1; k <= TIRENV_RING_RANGE_STEPS; ++k) {
        double l;
        if ((scan_status = patch_at(elem, flat, R0 - (double)k * dz, &l, &scan)))
            break;
        if (l > best_l) {
            best_l = l;
            best = k;
        } else if (k >= best + 2) {
            break;
        }
    }
    const size_t last = k - 1;  /* the lowest height evaluated */
    *z = 0;
    why[0] = '\0';
    if (best == 0 && scan_status)
        return tirenv_error(diag, scan_status, "", 0, scan.field,
                            "no flat-ground patch found below the free radius %g m: %s", R0,
                            scan.message);
    if (best == 0)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                            "no flat-ground patch found below the free radius %g m", R0);
    if (best == last && last == TIRENV_RING_RANGE_STEPS)
        return 0;  /* longest with the centre at the ground: the bracket is the limit */
    /* Golden sections on [a, b] around the longest patch, a below it: the least of -l. */
    double a = R0 - (double)(best + 1) * dz, b = R0 - (double)(best - 1) * dz;
    if (best == last)
        a = R0 - (double)best * dz;  /* the next one down failed */
    range_ctx ctx = {elem, flat, 0, diag};
    tirenv_core__golden g;
    tirenv_core__golden_set(&g, minus_patch, &ctx, a, b, TIRENV_CORE__GOLDEN_TIES_UPPER);
    while (!ctx.status && g.b - g.a > RANGE_TOL * R0)
        tirenv_core__golden_iterate(&g);
    if (ctx.status)
        return ctx.status;
    *z = 0.5 * (g.a + g.b);
    snprintf(why, n, "where its flat-ground contact length peaks: under more load its patch "
             "would shrink, which no tire does");
    return 0;
}

/* Lugs turn with the tread, so a lugged ring is not the same at every x. */
static int ring_shift_invariant(const tirenv_tire *tire) { return !(tire->ring.lug_count > 0); }

static size_t ring_state_size(const void *elem, int level)
{
    (void)level;
    return tirenv_ring__state_size(elem);
}
static void ring_state_save(const void *elem, const tirenv_profile *p, int level,
                            unsigned char *buf)
{
    (void)p;
    (void)level;
    tirenv_ring__state_save(elem, buf);
}
static int ring_state_restore(void *elem, const tirenv_profile *p, int level,
                              const unsigned char *buf)
{
    (void)p;
    (void)level;
    tirenv_ring__state_restore(elem, buf);
    return TIRENV_OK;
}

static int ring_continuous(const tirenv_tire *tire)
{
    return tire->ring.contact == TIRENV_RING_CONTINUOUS;
}

static const tirenv_deformable ring_deformable = {
    .alloc = ring_alloc,
    .free = ring_free,
    .forces = ring_forces,
    .root = ring_root,
    .start = ring_start,
    .contact_length = ring_contact_length,
    .lowest_z = ring_lowest_z,
    .bracket = tirenv_deformable_no_bracket,
    .shift_invariant = ring_shift_invariant,
    .state_size = ring_state_size,
    .state_save = ring_state_save,
    .state_restore = ring_state_restore,
    .continuous = ring_continuous,
    .extrapolate = 1,
    .defer_slope = ring_defer_slope,
    .slope = ring_slope,
    .level_reach = tirenv_deformable_level_reach_tread,
};

/* What tirenv fit identifies on rig data (docs/models.md section 8.4): the carcass's
 * foundation and the tread by default, the belt's bending stiffness and the inflation pressure
 * (which sets the belt's tension and the sidewalls' stiffness) as the optional ones. The
 * thickness and the discretisation are settings. */
static const tirenv_model_param ring_params[] = {
    {"FOUNDATION_STIFFNESS", offsetof(tirenv_tire, ring.k_c), 0},
    {"TREAD_STIFFNESS", offsetof(tirenv_tire, ring.k_t), 0},
    {"BELT_BENDING_STIFFNESS", offsetof(tirenv_tire, ring.EI), 0},
    {"INFLPRES", offsetof(tirenv_tire, ring.p), 0},
};

static const tirenv_model_fit ring_fit = {ring_params, 2, 4};

static const tirenv_model_type ring_type = {
    .name = "ring",
    .summary = "flexible ring and tread: the reference tire",
    .flags = TIRENV_MODEL_CONTACT_LENGTH | TIRENV_MODEL_STREAMS,
    .tracks = TIRENV_TRACKS_EQUILIBRIUM,
    .ops = &tirenv_deformable_ops,
    .fit = &ring_fit,
    .deformable = &ring_deformable,
};
const tirenv_model_type *tirenv_model_ring = &ring_type;
