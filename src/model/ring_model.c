/* The ring reference tire as a tirenv_model_type (docs/models.md section 5). */
#include <math.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include "model/deformable.h"
#include "tirenv/ring.h"

static void *ring_alloc(const tirenv_tire *tire)
{
    return tirenv_ring_alloc(tire->springs.R0, &tire->ring);
}

static void ring_free(void *elem) { tirenv_ring_free(elem); }

static int ring_forces(void *elem, const tirenv_profile *p, double x, double z,
                       tirenv_eq_point *out, tirenv_diag *diag)
{
    return tirenv_ring_forces(elem, p, x, z, &out->fx, &out->F, &out->dF_dz, &out->contacts,
                              diag);
}

/* The ring's contact length is its real patch, where the tread pressure is positive: shorter
 * than the chord of the free circle, as real tires' are (docs/models.md section 1). */
static int ring_contact_length(void *elem, const tirenv_profile *flat, double z, double *l_c,
                               tirenv_diag *diag)
{
    double fx, fz;
    const int status = tirenv_ring_forces(elem, flat, 0, z, &fx, &fz, NULL, NULL, diag);
    *l_c = tirenv_ring_patch_length(elem);
    return status;
}

typedef struct {
    void *elem;
    const tirenv_profile *flat;
    double l_c;
    int status;
    tirenv_diag *diag;
} patch_ctx;

static double patch_minus_target(double z, void *p)
{
    patch_ctx *c = p;
    double l;
    const int s = ring_contact_length(c->elem, c->flat, z, &l, c->diag);
    if (s && !c->status)
        c->status = s;
    return l - c->l_c;
}

/* The patch grows continuously as the centre comes down (its edges are interpolated), so
 * Brent on [R0/2, R0] finds the height; 1e-12 m is far below any patch length's meaning and
 * Brent needs about 40 iterations for it from a 0.34 m bracket, so 200 is only a guard. */
enum { PATCH_MAX_ITER = 200 };
static const double patch_z_tol = 1e-12; /* m */
static int ring_z_for_contact_length(void *elem, const tirenv_profile *flat, double l_c,
                                     double *z, tirenv_diag *diag)
{
    patch_ctx ctx = {elem, flat, l_c, 0, diag};
    gsl_function fn = {patch_minus_target, &ctx};
    double hi = tirenv_ring_free_radius(elem), lo = 0.5 * hi;
    if (patch_minus_target(lo, &ctx) < 0 || ctx.status)
        return ctx.status ? ctx.status
                          : tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                                         "%g m is beyond the ring tire's reach", l_c);
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    int status = gsl_root_fsolver_set(s, &fn, lo, hi);
    for (int it = 0; !status && it < PATCH_MAX_ITER; ++it) {
        status = gsl_root_fsolver_iterate(s);
        lo = gsl_root_fsolver_x_lower(s);
        hi = gsl_root_fsolver_x_upper(s);
        if (!status && gsl_root_test_interval(lo, hi, patch_z_tol, 0) == GSL_SUCCESS)
            break;
    }
    *z = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    if (ctx.status)  /* the forces' own message says what failed */
        return ctx.status;
    if (status)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "contact length",
                            "no ring height found for %g m: %s", l_c, gsl_strerror(status));
    return 0;
}

/* Lugs turn with the tread, so a lugged ring is not the same at every x. */
static int ring_shift_invariant(const tirenv_tire *tire) { return !(tire->ring.lug_count > 0); }

static const tirenv_deformable_ops ring_ops = {
    .alloc = ring_alloc,
    .free = ring_free,
    .forces = ring_forces,
    .contact_length = ring_contact_length,
    .z_for_contact_length = ring_z_for_contact_length,
    .shift_invariant = ring_shift_invariant,
};

static void *ring_model_alloc(const tirenv_tire *tire)
{
    return tirenv_deformable_alloc(tire, &ring_ops);
}

static const tirenv_model_type ring_type = {
    .name = "ring",
    .summary = "flexible ring and tread: the reference tire",
    .flags = TIRENV_MODEL_CONTACT_LENGTH | TIRENV_MODEL_STREAMS | TIRENV_MODEL_EQUILIBRIUM,
    .params = NULL,
    .n_params = 0,
    .n_params_max = 0,
    .alloc = ring_model_alloc,
    .free = tirenv_deformable_free,
    .flat = tirenv_deformable_flat,
    .load_for_contact_length = tirenv_deformable_load_for_contact_length,
    .set = tirenv_deformable_set,
    .eval = tirenv_deformable_eval,
    .envelope = NULL,
    .set_profile = tirenv_deformable_set_profile,
    .reach = NULL,
    .set_network = NULL,
    .warnings = NULL,
    .note = NULL,
};
const tirenv_model_type *tirenv_model_ring = &ring_type;
