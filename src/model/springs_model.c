/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model as a tirenv_model_type (docs/models.md section 4). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include "model/deformable.h"
#include "model/springs_impl.h"
#include "tirenv/springs.h"

/* The model's workspace: the element-level one and, for the contact length, the tips of an
 * evaluation (tirenv_springs_tips) over the N elements. */
typedef struct {
    tirenv_springs *s;
    double *d, *w, *p;  /* N each: penetration (m), deflection (m), reaction (N) */
} springs_elem;

static void springs_free(void *elem)
{
    springs_elem *e = elem;
    if (!e)
        return;
    tirenv_springs_free(e->s);
    free(e->d);
    free(e);
}

static void *springs_alloc(const tirenv_tire *tire)
{
    springs_elem *e = calloc(1, sizeof *e);
    if (!e)
        return NULL;
    e->s = tirenv_springs_alloc(&tire->springs);
    const size_t N = e->s ? tirenv_springs_size(e->s) : 0;
    e->d = N ? malloc(3 * N * sizeof *e->d) : NULL;
    if (!e->d) {
        springs_free(e);
        return NULL;
    }
    e->w = e->d + N;
    e->p = e->w + N;
    return e;
}

static int springs_forces(void *elem, const tirenv_profile *p, double x, double z,
                          tirenv_eq_point *out, tirenv_diag *diag)
{
    springs_elem *e = elem;
    return tirenv_springs_forces(e->s, p, x, z, &out->fx, &out->F, &out->dF_dz, &out->contacts,
                                 diag);
}

static int springs_root(void *elem, const tirenv_profile *p, double x, double z, double G,
                        const tirenv_eq_point *at, double *z_root)
{
    springs_elem *e = elem;
    return tirenv_springs__root(e->s, p, x, z, G, at->F, at->dF_dz, z_root);
}

static int springs_start(void *elem, const tirenv_profile *p, double x, double z0, double G,
                         double *z)
{
    springs_elem *e = elem;
    return tirenv_springs__start(e->s, p, x, z0, G, z);
}

static void springs_reprofile(void *elem, const tirenv_profile *old, const tirenv_profile *p)
{
    springs_elem *e = elem;
    tirenv_springs__reprofile(e->s, old, p);
}

/* docs/models.md section 1.3: the springs model's contact length is the length of ground its
 * tread touches, as the ring's: from the first to the last element with a positive contact
 * reaction, each end extended towards its free neighbour to where the "compression"
 * e_i = p_i/K_ii + delta_i - w_i, interpolated linearly between them, crosses zero. delta_i =
 * R0 - z/cos(theta_i) is the element's signed penetration of the flat ground (negative where
 * its ray meets the ground beyond its free length), K_ii = k_r + 2 k_ir (k_r + k_ir at the
 * ends) the diagonal of the tips' stiffness (section 4.4): on a touching element
 * (w_i = delta_i) e_i is its reaction over its own stiffness, the tread compression of the
 * ring's Winkler layer; on a free one it is minus its gap. The interradial springs lift the
 * elements at the chord's ends off the ground (their neighbours pull them up), so the length
 * is shorter than the chord of the free circle and depends on c_b/c_r. With the elements'
 * contact along their rays (CONTACT 'rays', the paper's) and continuous contact alike: on
 * flat ground both are the same LCP. */
static int springs_contact_length(void *elem, const tirenv_profile *flat, double z, double *l_c,
                                  tirenv_eq_point *at, tirenv_diag *diag)
{
    springs_elem *e = elem;
    const tirenv_springs_params *par = tirenv_springs_params_of(e->s);
    *l_c = 0;
    if (!(z < par->R0) && !at) /* nothing touches: no evaluation needed */
        return 0;
    tirenv_eq_point p = {.z = z};
    const int status = tirenv_springs_forces(e->s, flat, 0, z, &p.fx, &p.F,
                                             at ? &p.dF_dz : NULL, at ? &p.contacts : NULL,
                                             diag);
    if (at)
        *at = p;
    if (status || !(z < par->R0))
        return status;
    const size_t N = tirenv_springs_size(e->s);
    const double *theta = tirenv_springs_theta(e->s);
    tirenv_springs_tips(e->s, e->d, e->w, e->p);
    size_t k1 = N, k2 = 0;
    for (size_t i = 0; i < N; ++i)
        if (e->p[i] > 0) {
            k1 = i < k1 ? i : k1;
            k2 = i;
        }
    if (k1 > k2)
        return 0;
    tirenv_springs__elements el; /* K_ii is el.diag[i] */
    tirenv_springs__elements_of(e->s, &el);
    const double *cos_t = el.cos_t;
    /* e_i as above, with its ray's crossing of the ground X_i (m from under the centre); 0
     * when the ray does not point below the horizon. */
    double len = z * (tan(theta[k2]) - tan(theta[k1]));
    const size_t ends[2][2] = {{k1, k1 - 1}, {k2, k2 + 1}};
    for (int s = 0; s < 2; ++s) {
        const size_t i = ends[s][0], j = ends[s][1];
        if ((s == 0 && k1 == 0) || (s == 1 && k2 + 1 >= N) || !(cos_t[j] > 0))
            continue;
        const double e_i = e->p[i] / el.diag[i] + (par->R0 - z / cos_t[i]) - e->w[i];
        const double e_j = (e->p[j] > 0 ? e->p[j] / el.diag[j] : 0) +
                           (par->R0 - z / cos_t[j]) - e->w[j];
        if (e_i > 0 && e_j <= 0)
            len += e_i / (e_i - e_j) * z * fabs(tan(theta[j]) - tan(theta[i]));
    }
    *l_c = len;
    return 0;
}

static int springs_bracket(void *elem, const tirenv_profile *p, double x, double *z_lo,
                           double *z_hi)
{
    springs_elem *e = elem;
    tirenv_springs__bracket(e->s, p, x, z_lo, z_hi);
    return 1;
}

static size_t springs_state_size(const void *elem, int level)
{
    const springs_elem *e = elem;
    return tirenv_springs__state_size(e->s, level);
}
static void springs_state_save(const void *elem, const tirenv_profile *p, int level,
                               unsigned char *buf)
{
    const springs_elem *e = elem;
    tirenv_springs__state_save(e->s, p, level, buf);
}
static int springs_state_restore(void *elem, const tirenv_profile *p, int level,
                                 const unsigned char *buf)
{
    springs_elem *e = elem;
    return tirenv_springs__state_restore(e->s, p, level, buf);
}

/* docs/models.md section 4.1: the elements span the tread segment |theta| <= phi/2. With the
 * centre below R0*cos(phi/2) the flat ground would reach past the segment's last element, and
 * the elements the model does not have would carry load: its valid range ends there. The
 * default segment, the lower half (phi = pi), ends only with the centre at the ground. */
static int springs_lowest_z(void *elem, const tirenv_profile *flat, double *z, char *why,
                            size_t n, tirenv_diag *diag)
{
    (void)flat;
    (void)diag;
    const springs_elem *e = elem;
    const tirenv_springs_params *par = tirenv_springs_params_of(e->s);
    *z = 0;
    why[0] = '\0';
    if (par->phi < M_PI) {
        *z = par->R0 * cos(0.5 * par->phi);
        snprintf(why, n, "where the flat contact reaches the ends of the tread segment "
                 "(SEGMENT_ANGLE %g rad): beyond, ground would press elements the model does "
                 "not have", par->phi);
    }
    return 0;
}

/* docs/models.md section 4.9: the sidewall spring between the rim and the elements' centre,
 * rigid up to SIDEWALL_PRELOAD F_s0 and then of stiffness SIDEWALL_STIFFNESS k_s; none with
 * k_s = 0 (the paper's model). */
static double springs_sidewall(const tirenv_tire *tire, double F, double *dU_dF)
{
    const tirenv_springs_params *par = &tire->springs;
    *dU_dF = 0;
    if (!(par->k_s > 0) || !(F > par->F_s0))
        return 0;
    *dU_dF = 1 / par->k_s;
    return (F - par->F_s0) / par->k_s;
}

static int springs_continuous(const tirenv_tire *tire)
{
    return tire->springs.contact == TIRENV_SPRINGS_CONTINUOUS;
}

static const tirenv_deformable springs_deformable = {
    .alloc = springs_alloc,
    .free = springs_free,
    .forces = springs_forces,
    .root = springs_root,
    .start = springs_start,
    .reprofile = springs_reprofile,
    .contact_length = springs_contact_length,
    .lowest_z = springs_lowest_z,
    .bracket = springs_bracket,
    .shift_invariant = tirenv_deformable_invariant,
    .state_size = springs_state_size,
    .state_save = springs_state_save,
    .state_restore = springs_state_restore,
    .series = springs_sidewall,
    .continuous = springs_continuous,
    .level_reach = tirenv_deformable_level_reach_r0,
};

/* The stiffnesses that shape h, which a fit identifies, and the free radius on request
 * (docs/models.md section 8); the discretisation (ELEMENT_ANGLE) is a setting, not fitted. */
static const tirenv_model_param springs_params[] = {
    {"RADIAL_STIFFNESS", offsetof(tirenv_tire, springs.c_r), 0},
    {"INTERRADIAL_STIFFNESS", offsetof(tirenv_tire, springs.c_b), 0},
    {"UNLOADED_RADIUS", offsetof(tirenv_tire, springs.R0), 0},
};
static const tirenv_model_fit springs_fit = {springs_params, 2, 3};

static const tirenv_model_type springs_type = {
    .name = "springs",
    .summary = "the paper's radial + interradial springs",
    .flags = TIRENV_MODEL_CONTACT_LENGTH | TIRENV_MODEL_STREAMS,
    .tracks = TIRENV_TRACKS_EQUILIBRIUM,
    .ops = &tirenv_deformable_ops,
    .fit = &springs_fit,
    .deformable = &springs_deformable,
};
const tirenv_model_type *tirenv_model_springs = &springs_type;
