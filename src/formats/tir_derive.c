/* SPDX-License-Identifier: Apache-2.0 */
/* A tire file's enveloping models derived from its MF-Tyre keys (docs/models.md section 14):
 * the file is read a second time with a schema of the MF-Tyre keys that describe the tire's
 * vertical behaviour, and the springs and ring models a file has no section for are scaled
 * to the file's deflection at its nominal load; a derived ring of a file with a contact law
 * of its own (Q_RA1, Q_RA2) is searched on that law too (derive_on_laws), and the springs
 * model derived on that ring has a sidewall in series (derive_springs_sidewall). */
#include "formats/flat_inverse.h"
#include "formats/propfile.h"
#include "formats/tir_impl.h"
#include "tirenv/cam.h"
#include "tirenv/tir.h"
#include "tirenv/model.h"
#include "tirenv/profile.h"
#include "tirenv/ring.h"
#include "tirenv/springs.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/io.h"

/* What the derivation reads. The enveloping keys are there only to learn whether the file
 * has each section (their values are tirenv_tir_read's). */
typedef struct {
    double R0, width, aspect, rim;           /* m, m, -, m */
    double c_z, fnomin;                      /* N/m, N */
    double inflpres, nompres, pfz1;          /* Pa, Pa, - */
    double q_fz1, q_fz2;                     /* - */
    double unused;                           /* the enveloping keys land here */
    unsigned given;                          /* MF_* bits */
} mf_keys;

enum {
    MF_R0 = 1u << 0, MF_WIDTH = 1u << 1, MF_ASPECT = 1u << 2, MF_RIM = 1u << 3,
    MF_CZ = 1u << 4, MF_FNOMIN = 1u << 5, MF_INFLPRES = 1u << 6, MF_NOMPRES = 1u << 7,
    MF_PFZ1 = 1u << 8, MF_QFZ1 = 1u << 9, MF_QFZ2 = 1u << 10,
    MF_SPRINGS = 1u << 11, MF_RING = 1u << 12,
    MF_ALL = (1u << 13) - 1
};

#define MF(sec, name, member, L, F, P, bit)                                                    \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_REAL,                            \
     .offset = offsetof(mf_keys, member), .comment = "", .dim = {[TIRENV_UNIT_LENGTH] = (L),   \
     [TIRENV_UNIT_FORCE] = (F), [TIRENV_UNIT_PRESSURE] = (P)}, .given = (bit)}
#define OWN(sec, name, bit) MF(sec, name, unused, 0, 0, 0, bit)

static const tirenv_propfile__key mf_table[] = {
    TIRENV_PROPFILE_CONVERTED_UNITS,
    MF("DIMENSION", "UNLOADED_RADIUS", R0, 1, 0, 0, MF_R0),
    MF("DIMENSION", "WIDTH", width, 1, 0, 0, MF_WIDTH),
    MF("DIMENSION", "ASPECT_RATIO", aspect, 0, 0, 0, MF_ASPECT),
    MF("DIMENSION", "RIM_RADIUS", rim, 1, 0, 0, MF_RIM),
    MF("OPERATING_CONDITIONS", "INFLPRES", inflpres, 0, 0, 1, MF_INFLPRES),
    MF("OPERATING_CONDITIONS", "NOMPRES", nompres, 0, 0, 1, MF_NOMPRES),
    MF("VERTICAL", "VERTICAL_STIFFNESS", c_z, -1, 1, 0, MF_CZ),
    MF("VERTICAL", "FNOMIN", fnomin, 0, 1, 0, MF_FNOMIN),
    MF("VERTICAL", "PFZ1", pfz1, 0, 0, 0, MF_PFZ1),
    MF("VERTICAL", "Q_FZ1", q_fz1, 0, 0, 0, MF_QFZ1),
    MF("VERTICAL", "Q_FZ2", q_fz2, 0, 0, 0, MF_QFZ2),
    OWN("ENVELOPING_SPRINGS", "RADIAL_STIFFNESS", MF_SPRINGS),
    OWN("ENVELOPING_SPRINGS", "INTERRADIAL_STIFFNESS", MF_SPRINGS),
    OWN("ENVELOPING_SPRINGS", "SEGMENT_ANGLE", MF_SPRINGS),
    OWN("ENVELOPING_SPRINGS", "ELEMENT_ANGLE", MF_SPRINGS),
    OWN("ENVELOPING_SPRINGS", "SIDEWALL_STIFFNESS", MF_SPRINGS),
    OWN("ENVELOPING_SPRINGS", "SIDEWALL_PRELOAD", MF_SPRINGS),
    OWN("ENVELOPING_RING", "TREAD_THICKNESS", MF_RING),
    OWN("ENVELOPING_RING", "BELT_BENDING_STIFFNESS", MF_RING),
    OWN("ENVELOPING_RING", "BELT_PRETENSION", MF_RING),
    OWN("ENVELOPING_RING", "FOUNDATION_STIFFNESS", MF_RING),
    OWN("ENVELOPING_RING", "TREAD_STIFFNESS", MF_RING),
    OWN("ENVELOPING_RING", "TREAD_SHEAR", MF_RING),
    OWN("ENVELOPING_RING", "CARCASS_SOFTENING_DEFLECTION", MF_RING),
    OWN("ENVELOPING_RING", "CARCASS_LINEAR_DEFLECTION", MF_RING),
    OWN("ENVELOPING_RING", "NODE_ANGLE", MF_RING),
    OWN("ENVELOPING_RING", "LUG_COUNT", MF_RING),
    OWN("ENVELOPING_RING", "LUG_FRACTION", MF_RING),
    OWN("ENVELOPING_RING", "LUG_GROOVE_RATIO", MF_RING),
};

/* Every section lenient: the file was checked by tirenv_tir_read already; this pass only
 * looks the keys up. [OPERATING_CONDITIONS] is MF-Tyre 6's, and [ENVELOPING_SOLVER] is
 * listed so that tirenv's own section is not taken for a typo. */
static const tirenv_propfile__section mf_sections[] = {
    {"UNITS", 0}, {"DIMENSION", 0}, {"OPERATING_CONDITIONS", 0}, {"VERTICAL", 0},
    {"CONTACT_PATCH", 0}, {"ENVELOPING_SPRINGS", 0}, {"ENVELOPING_RING", 0},
    {"ENVELOPING_SOLVER", 0},
};

static int mf_check(const void *obj, tirenv_diag *diag)
{
    (void)obj;
    (void)diag;
    return TIRENV_OK;
}

static const tirenv_propfile__schema mf_schema = {
    .keys = mf_table,
    .n_keys = sizeof mf_table / sizeof mf_table[0],
    .sections = mf_sections,
    .n_sections = sizeof mf_sections / sizeof mf_sections[0],
    .own_prefix = "ENVELOPING_",
    .first_section = "MDI_HEADER",
    .size = sizeof(mf_keys),
    .check = mf_check,
    .given_offset = offsetof(mf_keys, given),
    .given_mask = MF_ALL,
};

/* The file's vertical law with Q_FZ2 q2 at the pressure factor f: the cam's own
 * (tirenv_cam_vertical, docs/models.md section 7.3), with the file's keys,
 *   F_z = f*FNOMIN*(Q_FZ1*rho/R0 + Q_FZ2*(rho/R0)^2),  f = 1 + PFZ1*(p - p0)/p0,
 * Q_FZ1 the file's where not 0, else sqrt((VERTICAL_STIFFNESS*R0/FNOMIN)^2 - 4*Q_FZ2), which
 * makes VERTICAL_STIFFNESS the tangent stiffness at FNOMIN (and, with Q_FZ2 = 0, the law
 * linear: rho = FNOMIN/(f*VERTICAL_STIFFNESS)). Q_V1, Q_V2 are speed terms, and the enveloping
 * models are quasi-static. */
static tirenv_cam_vertical file_law(const mf_keys *k, double q2, double f)
{
    return (tirenv_cam_vertical){.R0 = k->R0, .fnomin = k->fnomin, .c_z = k->c_z,
                                 .q_fz1 = k->q_fz1, .q_fz2 = q2, .factor = f};
}

/* The file's deflection at FNOMIN (m) by that law, with f the cam's: PFZ1 at the tire's
 * INFLPRES and NOMPRES (tirenv_cam_pressure_factor). s = rho/R0 is the law's root at
 * g = 1/f, times R0, the arithmetic the derivation has always used: the cam's
 * tirenv_cam_vertical_deflection(FNOMIN) is the same law to a few ulp (and bit for bit on a
 * law with Q_FZ2 or Q_FZ1), but the derived models' scale, converged to 5e-8, would move
 * within that tolerance with any bit of rho_n. 0 with the missing key in *missing. */
static double nominal_deflection(const mf_keys *k, const tirenv_tire *tire, double *factor,
                                 const char **missing)
{
    *factor = 1;
    *missing = !(k->given & MF_R0) ? "UNLOADED_RADIUS"
               : !(k->given & MF_FNOMIN) ? "FNOMIN"
               : !(k->given & (MF_CZ | MF_QFZ1)) ? "VERTICAL_STIFFNESS" : NULL;
    if (*missing)
        return 0;
    *factor = tirenv_cam_pressure_factor(tire->cam.pfz1, tire->ring.p, tire->ring.p_nom);
    const tirenv_cam_vertical v = file_law(k, k->q_fz2, *factor);
    const double x = tirenv_cam_vertical_root(1, tirenv_cam_vertical_q1(&v), v.q_fz2,
                                              1 / *factor);
    if (!(x > 0 && x < 1 && isfinite(x))) {
        *missing = "VERTICAL_STIFFNESS";
        return 0;
    }
    return x * k->R0;
}

/* The deflection (m) at load G (N) of the file's law with Q_FZ2 q2 at the pressure factor;
 * NAN where the law has no Q_FZ1 or does not reach G. */
static double law_deflection(const mf_keys *k, double q2, double factor, double G)
{
    const tirenv_cam_vertical v = file_law(k, q2, factor);
    return tirenv_cam_vertical_deflection(&v, G);
}

/* The load (N) of a model of *t at deflection rho_n on flat ground. */
static int load_at(const tirenv_model_type *type, const tirenv_tire *t, double rho_n,
                   double guess, double *G, tirenv_diag *diag)
{
    tirenv_model *m = tirenv_model_alloc(type, t);
    if (!m)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, tirenv_model_type_name(type),
                            "the %s model of the derived shape is not a valid tire",
                            tirenv_model_type_name(type));
    const int status = tirenv_flat__load_at_deflection(m, rho_n, guess, G, diag);
    tirenv_model_free(m);
    return status;
}

/* Scales the springs model's stiffnesses stiff[] by one factor c so that it carries FNOMIN
 * at rho_n (a derived ring's: scale_at_height). They make all of its load, so the load is
 * proportional to c and the first step is exact but for rounding; the secant after it is a
 * guard, to 5e-8 of FNOMIN: the load at a fixed deflection, itself a flat inversion to 1e-9 m
 * of deflection, repeats only to a few 1e-8 of it; the tests assert the deflection at FNOMIN
 * to 1e-7. */
static int scale_to(tirenv_tire *t, double *const stiff[], size_t n, double fnomin,
                    double rho_n, tirenv_diag *diag)
{
    const tirenv_model_type *const type = tirenv_model_springs;
    enum { MAX_STIFF = 8, MAX_STEPS = 60 };
    double base[MAX_STIFF];
    for (size_t i = 0; i < n; i++)
        base[i] = *stiff[i];
    double u0 = 0, g0, G;
    int status = load_at(type, t, rho_n, fnomin, &G, diag);
    if (status)
        return status;
    g0 = log(G / fnomin);
    double u1 = -g0;  /* the proportional step */
    for (int step = 0; step < MAX_STEPS; step++) {
        for (size_t i = 0; i < n; i++)
            *stiff[i] = base[i] * exp(u1);
        if ((status = load_at(type, t, rho_n, fnomin, &G, diag)))
            return status;
        const double g1 = log(G / fnomin);
        if (fabs(g1) <= 5e-8)
            return TIRENV_OK;
        /* The secant on G itself against c = e^u: G = G_air + c*G_c is affine in c where
         * the air's share keeps its shape, so this lands at once where the log's secant
         * took six to nine steps from the default's stiffnesses; a step it cannot take (a
         * non-positive c) is the log's. */
        const double c0 = exp(u0), c1 = exp(u1), G0 = fnomin * exp(g0), G1 = fnomin * exp(g1);
        const double c2 = G1 != G0 ? c1 + (fnomin - G1) * (c1 - c0) / (G1 - G0) : 0;
        const double u2 = c2 > 0 && isfinite(c2) ? log(c2)
                          : g1 != g0 ? u1 - g1 * (u1 - u0) / (g1 - g0) : u1 - g1;
        u0 = u1, g0 = g1;
        u1 = fmax(u1 - 5, fmin(u1 + 5, u2));  /* at most a factor e^5 a step */
    }
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "VERTICAL_STIFFNESS",
                        "the %s model's stiffnesses found no scale carrying FNOMIN %g N at "
                        "the file's deflection %g m (its air alone may carry more)",
                        tirenv_model_type_name(type), fnomin, rho_n);
}

/* The loads the derived models are identified and compared at: 0.5 to 1.5 times FNOMIN
 * (tirenv_nominal_load_fractions), as tirenv identify takes them (docs/models.md section
 * 14.1). */
enum { N_LOADS = TIRENV_NOMINAL_LOADS };
enum { I_NOMINAL = 2 };  /* tirenv_nominal_load_fractions[I_NOMINAL] is 1: FNOMIN itself */

/* A model's flat-ground states at those loads. */
typedef struct {
    double G[N_LOADS], defl[N_LOADS], l[N_LOADS];  /* N, m, m */
    double k[N_LOADS];                             /* tangent stiffness, N/m */
} flat_set;

static int flats(const tirenv_model_type *type, const tirenv_tire *t, double fnomin,
                 flat_set *out, tirenv_diag *diag)
{
    tirenv_model *m = tirenv_model_alloc(type, t);
    if (!m)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, tirenv_model_type_name(type),
                            "the %s model of the tire is not valid, so the others cannot be "
                            "identified on it", tirenv_model_type_name(type));
    int status = TIRENV_OK;
    for (size_t i = 0; i < N_LOADS && !status; i++) {
        tirenv_flat f;
        out->G[i] = tirenv_nominal_load_fractions[i] * fnomin;
        status = tirenv_model_flat(m, out->G[i], &f, diag);
        out->defl[i] = f.deflection;
        out->l[i] = f.contact_length;
        out->k[i] = f.stiffness;
    }
    tirenv_model_free(m);
    return status;
}

/* docs/models.md section 14.2: the springs model identified on the tire's ring states (its own
 * ring's or the derived one's) as the default tire is on its own (tirenv_springs_identify): at
 * 0.5 to 1.5 times FNOMIN it deflects as the ring does and touches as much ground; then c_r
 * and c_b, their ratio kept, are scaled to the file's deflection at FNOMIN (the load is
 * proportional to them together: one step). The segment and the elements are the default
 * tire's. */
static int derive_springs(tirenv_tire *t, const mf_keys *k, double rho_n, const flat_set *ring,
                          tirenv_diag *diag)
{
    const tirenv_tire d = tirenv_tire_default();
    t->springs.c_r = d.springs.c_r;
    t->springs.c_b = d.springs.c_b;
    t->springs.phi = d.springs.phi;
    t->springs.dphi = d.springs.dphi;
    int status = tirenv_springs_identify(&t->springs, N_LOADS, ring->G, ring->defl, ring->l,
                                         diag);
    if (status)
        return status;
    double *const stiff[] = {&t->springs.c_r, &t->springs.c_b};
    return scale_to(t, stiff, 2, k->fnomin, rho_n, diag);
}

/* derive_springs with a sidewall in series (docs/models.md sections 4.9 and 14.2), for the
 * ring searched on a file's own laws, which follows their nearly linear vertical law where
 * the elements alone stiffen with the load: c_r, c_b, SIDEWALL_STIFFNESS k_s and
 * SIDEWALL_PRELOAD F_s0 identified on the ring's states (tirenv_springs_identify_sidewall, as
 * tirenv identify --write-springs does), then all four scaled by one factor so that the model
 * carries FNOMIN at rho_n: at a hub deflection the elements deflect d_e(G/c) and the sidewall
 * (G/c - F_s0)/k_s, so the load is proportional to the factor and one step is exact. */
static int derive_springs_sidewall(tirenv_tire *t, const mf_keys *k, double rho_n,
                                   const flat_set *ring, tirenv_diag *diag)
{
    const tirenv_tire d = tirenv_tire_default();
    t->springs.phi = d.springs.phi;
    t->springs.dphi = d.springs.dphi;
    int status = tirenv_springs_identify_sidewall(&t->springs, N_LOADS, ring->G, ring->defl,
                                                  ring->l, diag);
    if (status)
        return status;
    double *const stiff[] = {&t->springs.c_r, &t->springs.c_b, &t->springs.k_s,
                             &t->springs.F_s0};
    return scale_to(t, stiff, 4, k->fnomin, rho_n, diag);
}

/* The ring's load (N) and contact length (m) with its centre at each height R0 - d[i] (m)
 * over flat ground, in that order on one workspace (each evaluation warm-started from the
 * last): tirenv_ring_forces and tirenv_ring_patch_length, what the ring model's
 * tirenv_model_flat_at_height returns, without the model's valid-range scan (about 45 force
 * evaluations down to where the flat-ground patch peaks, which the model makes once before
 * its first evaluation: nine tenths of a table's cost). The derivation's heights are the
 * file's deflections at 0.5 to 1.5 FNOMIN, far above that peak on any ring that carries
 * them; the ring kept is checked to be within its range there once (within_range). */
static int ring_at_heights(const tirenv_tire *t, const tirenv_profile *flat, size_t n,
                           const double d[], double G[], double l[], tirenv_diag *diag)
{
    tirenv_ring *ring = tirenv_ring_alloc(t->springs.R0, &t->ring);
    if (!ring)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ring",
                            "the derived ring is not a valid tire");
    int status = TIRENV_OK;
    for (size_t i = 0; i < n && !status; i++) {
        double fx, fz;
        status = tirenv_ring_forces(ring, flat, 0, t->springs.R0 - d[i], &fx, &fz, NULL, NULL,
                                    diag);
        G[i] = fz;
        if (l)
            l[i] = tirenv_ring_patch_length(ring);
    }
    tirenv_ring_free(ring);
    return status;
}

/* scale_to for a derived ring, by the ring's load at the height R0 - rho_n (one force
 * evaluation a step on a fresh ring workspace, ring_at_heights, where scale_to inverts a flat
 * inversion on a new model, whose valid-range scan costs some 45 evaluations): EI, T, k_f,
 * k_t by one factor c until it carries FNOMIN there to 5e-8, by the secant on the load
 * against c (affine in c but for the air's share), at most MAX_STEPS. */
static int scale_at_height(tirenv_tire *t, const tirenv_profile *flat, double fnomin,
                           double rho_n, tirenv_diag *diag)
{
    enum { MAX_STEPS = 30 };
    double *const stiff[] = {&t->ring.EI, &t->ring.T, &t->ring.k_c, &t->ring.k_t};
    double base[4];
    for (size_t i = 0; i < 4; i++)
        base[i] = *stiff[i];
    double c0 = 1, G0 = 0, G1 = 0;
    int status = ring_at_heights(t, flat, 1, &rho_n, &G0, NULL, diag);
    if (status)
        return status;
    double c1 = fnomin / G0;  /* the proportional step */
    for (int step = 0; step < MAX_STEPS; step++) {
        for (size_t i = 0; i < 4; i++)
            *stiff[i] = base[i] * c1;
        if ((status = ring_at_heights(t, flat, 1, &rho_n, &G1, NULL, diag)))
            return status;
        if (fabs(G1 / fnomin - 1) <= 5e-8)
            return TIRENV_OK;
        double c2 = G1 != G0 ? c1 + (fnomin - G1) * (c1 - c0) / (G1 - G0) : c1 * fnomin / G1;
        if (!(c2 > 0 && isfinite(c2)))
            c2 = c1 * fnomin / G1;
        c0 = c1, G0 = G1;
        c1 = fmax(c1 / 4, fmin(c1 * 4, c2));
    }
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "VERTICAL_STIFFNESS",
                        "the derived ring found no scale carrying FNOMIN "
                        "%g N at the file's deflection %g m", fnomin, rho_n);
}

/* The ring's flat-ground states at 0.5 to 1.5 FNOMIN, as flats takes them from the ring
 * model, for a derived ring: each load's
 * centre height found on one workspace by Newton's method on tirenv_ring_forces (its dF/dz
 * exact for the active set), from the deflection guess[i] (m) and then each from the last,
 * safeguarded by the bracket the evaluations make (bisection where a step leaves it), and
 * converged as the model's equilibrium is (the tire's eq settings: |F - G| <= eps_F and a last
 * step within eps_z, at most max_iter evaluations a load); without the model's valid-range
 * scan, which cost more than the states (ring_at_heights). TIRENV_ENOCONV naming the load and
 * the last bracket where a load does not converge. */
static int ring_flats(const tirenv_tire *t, const tirenv_profile *flat, double fnomin,
                      const double guess[], flat_set *out, tirenv_diag *diag)
{
    tirenv_ring *ring = tirenv_ring_alloc(t->springs.R0, &t->ring);
    if (!ring)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ring",
                            "the derived ring is not a valid tire");
    const double R0 = t->springs.R0;
    const tirenv_eq_settings *eq = &t->eq;
    int status = TIRENV_OK;
    double z = R0 - guess[0];
    for (size_t i = 0; i < N_LOADS && !status; i++) {
        const double G = tirenv_nominal_load_fractions[i] * fnomin;
        double z_lo = 0, z_hi = R0;  /* the load's height lies in [z_lo, z_hi] */
        if (i > 0 && guess[i] > guess[i - 1])
            z -= guess[i] - guess[i - 1];
        z = fmin(fmax(z, z_lo + 1e-3 * R0), z_hi - 1e-3 * R0);
        int done = 0;
        for (size_t it = 0; !done && !status; it++) {
            double fx, F, dF;
            if (it >= eq->max_iter) {
                status = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                                      "the ring's flat ground at %g N did not converge in %zu "
                                      "evaluations (centre height within [%.9g, %.9g] m)",
                                      G, eq->max_iter, z_lo, z_hi);
                break;
            }
            if ((status = tirenv_ring_forces(ring, flat, 0, z, &fx, &F, &dF, NULL, diag)))
                break;
            const double e = F - G;
            if (e < 0)
                z_hi = z;
            else
                z_lo = z;
            double z_new = dF < 0 ? z - e / dF : NAN;
            if (!(z_new > z_lo && z_new < z_hi))
                z_new = 0.5 * (z_lo + z_hi);
            /* Converged, or the bracket within eps_z: the load's force is not resolved to
             * eps_F there (its round-off at 45 kN, a few 1e-6 N, on the 430/50R38's ring). */
            if ((fabs(e) <= eq->eps_F && fabs(z_new - z) <= eq->eps_z) ||
                z_hi - z_lo <= eq->eps_z) {
                out->G[i] = G;
                out->defl[i] = R0 - z;
                out->l[i] = tirenv_ring_patch_length(ring);
                out->k[i] = -dF;
                done = 1;
            } else {
                z = z_new;
            }
        }
    }
    tirenv_ring_free(ring);
    return status;
}

/* TIRENV_OK where the ring of *t is within its valid range (docs/models.md section 1.3: its
 * centre no lower than where its flat-ground patch is longest) down to the deflection rho (m),
 * the largest derived on it; else TIRENV_ERANGE. ring_at_heights and ring_flats evaluate the
 * ring without the model's range, so a derived ring is kept only where this holds. The model
 * finds its range's end on a grid of R0 / TIRENV_RING_RANGE_STEPS steps from R0 down,
 * stopping two steps past the longest patch, then between that one's neighbours; a patch
 * that grows at every step of that grid down to two steps past rho puts the end below rho.
 * That is checked here on one workspace, down to rho only (the model's scan goes on to the
 * end, some 45 evaluations as deep as the patch grows: 0.3 s of CPU on the 430/50R38's ring
 * at 0.25 degrees, more than the rest of the read), and it asks a little more than the model
 * (growth at each step, not only past the longest so far). */
static int within_range(const tirenv_tire *t, const tirenv_profile *flat, double rho,
                        tirenv_diag *diag)
{
    const double R0 = t->springs.R0, dz = R0 / TIRENV_RING_RANGE_STEPS;
    const size_t K = (size_t)ceil(rho / dz) + 2;
    tirenv_ring *ring = tirenv_ring_alloc(R0, &t->ring);
    if (!ring)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ring",
                            "the derived ring is not a valid tire");
    int status = TIRENV_OK;
    double l_last = 0;
    for (size_t k = 1; k <= K && !status && (double)k * dz < R0; k++) {
        double fx, fz;
        status = tirenv_ring_forces(ring, flat, 0, R0 - (double)k * dz, &fx, &fz, NULL, NULL,
                                    diag);
        const double l = tirenv_ring_patch_length(ring);
        if (!status && !(l > l_last))
            status = tirenv_error(diag, TIRENV_ERANGE, "", 0, "ring",
                                  "its flat-ground patch stops growing at a deflection of "
                                  "%.4g m (%.4g m, %.4g m before), above the %.4g m derived "
                                  "on it", (double)k * dz, l, l_last, rho);
        l_last = l;
    }
    tirenv_ring_free(ring);
    return status;
}

/* The section height (m): R0 - RIM_RADIUS, or WIDTH*ASPECT_RATIO, or 0. */
static double section_height(const mf_keys *k)
{
    if ((k->given & MF_RIM) && k->rim > 0 && k->rim < k->R0)
        return k->R0 - k->rim;
    if ((k->given & MF_WIDTH) && (k->given & MF_ASPECT) && k->width > 0 && k->aspect > 0)
        return k->width * k->aspect;
    return 0;
}

/* docs/models.md section 14.2: the default ring made similar: the tread in proportion to the
 * section height, the belt's length scales with R = R0 - t_r, EI/(k_f*R^4) and T/(k_f*R^2)
 * kept, the carcass's pretension raised by tau*k_f*R^2 (tau = 0: the default's shape), then
 * every stiffness scaled to the file's deflection at FNOMIN. */
static int derive_ring(tirenv_tire *t, const mf_keys *k, double rho_n, double tau,
                       const tirenv_profile *flat, tirenv_diag *diag)
{
    const tirenv_tire d = tirenv_tire_default();
    const double H_d = d.springs.R0 - 14 * 0.0254;  /* 380/85R28 on a 28 in rim */
    const double H = section_height(k);
    const double p = t->ring.p, p_nom = t->ring.p_nom;  /* the file's, or the default's */
    t->ring = d.ring;
    t->ring.p = p;
    t->ring.p_nom = p_nom;
    t->ring.t_r = d.ring.t_r * (H > 0 ? H / H_d : k->R0 / d.springs.R0);
    const double s = (k->R0 - t->ring.t_r) / (d.springs.R0 - d.ring.t_r);
    /* The crown the air presses on: the default's share of its 0.38 m section width. */
    t->ring.b_p = (k->given & MF_WIDTH) && k->width > 0 ? d.ring.b_p * k->width / 0.38
                                                        : d.ring.b_p * s;
    t->ring.EI = d.ring.EI * s * s * s * s;
    t->ring.T = d.ring.T * s * s;
    /* The Winkler tread (TREAD_SHEAR 0) at 0.125 degree nodes, the default's before it coupled
     * the tread in shear at 0.25 degrees: derived rings keep what they were derived with
     * (docs/models.md section 14.2); the shear layer's G_t is the default tractor tire's lugs
     * (data/tires/default.tir), not a property to scale to another tire. */
    t->ring.G_t = 0;
    t->ring.dtheta = M_PI / 1440.0;
    if (tau > 0) {
        const double R = k->R0 - t->ring.t_r;
        t->ring.T += tau * d.ring.k_c * R * R;
    }
    return scale_at_height(t, flat, k->fnomin, rho_n, diag);
}

/* docs/models.md section 14.2: Q_FZ2 identified on the ring's states, for a file whose
 * vertical law is VERTICAL_STIFFNESS alone. Q_FZ1 = sqrt(k^2 - 4*Q_FZ2), k =
 * VERTICAL_STIFFNESS*R0/FNOMIN, as MF-Tyre 6.1 derives it for a file without Q_FZ1, keeps
 * VERTICAL_STIFFNESS the law's tangent at FNOMIN whatever Q_FZ2, which leaves Q_FZ2 the one
 * parameter: it minimises the sum of the squared relative differences of the law's deflection
 * (with PFZ1's factor, as rho_n) from the ring's at 0.5 to 1.5 FNOMIN, by golden section over
 * [-k^2/4, k^2/4): above it there is no Q_FZ1, and below it the law softens with the load
 * as steeply as its tangent at FNOMIN allows, where the ring stiffens. A deflection the law
 * does not reach (a Q_FZ2 < 0 whose load peaks below 1.5 FNOMIN) counts as an infinite
 * difference; such Q_FZ2 lie at the lower end, so the search moves away from them.
 * Q_FZ2_STEPS narrow the bracket by 0.618^100, to the last bits of a double. The search is
 * its own: the core's golden section (src/core/golden.c) is internal to the core layer, which
 * the formats may not call. */
static double q_fz2_miss(const mf_keys *k, double factor, const flat_set *ring, double q2)
{
    double sum = 0;
    for (size_t i = 0; i < N_LOADS; i++) {
        const double e = law_deflection(k, q2, factor, ring->G[i]) / ring->defl[i] - 1;
        sum += e * e;
    }
    return isfinite(sum) ? sum : HUGE_VAL;
}

static double q_fz2_on(const mf_keys *k, double factor, const flat_set *ring)
{
    enum { Q_FZ2_STEPS = 100 };
    const double kk = k->c_z * k->R0 / k->fnomin, q_max = kk * kk / 4;
    const double r = (sqrt(5.0) - 1) / 2;
    double a = -q_max, b = q_max * (1 - 1e-9);
    double c = b - r * (b - a), d = a + r * (b - a);
    double fc = q_fz2_miss(k, factor, ring, c), fd = q_fz2_miss(k, factor, ring, d);
    for (int i = 0; i < Q_FZ2_STEPS; i++) {
        if (fc < fd) {
            b = d, d = c, fd = fc;
            c = b - r * (b - a);
            fc = q_fz2_miss(k, factor, ring, c);
        } else {
            a = c, c = d, fc = fd;
            d = a + r * (b - a);
            fd = q_fz2_miss(k, factor, ring, d);
        }
    }
    return fc < fd ? c : d;
}

/* The vertical law the derived ring is scaled to (section 14.2). */
typedef struct {
    double rho_n;     /* the file's deflection at FNOMIN by its own law, m */
    double factor;    /* PFZ1's pressure factor, - */
    int derive_q_fz2; /* the file's law is VERTICAL_STIFFNESS alone: Q_FZ2 identified */
} vertical_law;

/* The ring of *t with its stiffnesses EI, T, k_f, k_t at base[] times c: its states at 0.5 to
 * 1.5 FNOMIN, the Q_FZ2 identified on them, and h, the log of the ratio of that law's
 * deflection at FNOMIN to the ring's. */
static int ring_and_law(tirenv_tire *t, const mf_keys *k, const vertical_law *v,
                        const double base[4], double c, const tirenv_profile *flat,
                        flat_set *ring, double *q2, double *h, tirenv_diag *diag)
{
    t->ring.EI = base[0] * c;
    t->ring.T = base[1] * c;
    t->ring.k_c = base[2] * c;
    t->ring.k_t = base[3] * c;
    double guess[N_LOADS];  /* the last ring's deflections */
    memcpy(guess, ring->defl, sizeof guess);
    const int status = ring_flats(t, flat, k->fnomin, guess, ring, diag);
    if (status)
        return status;
    *q2 = q_fz2_on(k, v->factor, ring);
    const double rho_law = law_deflection(k, *q2, v->factor, k->fnomin);
    if (!(rho_law > 0 && isfinite(rho_law)))
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "Q_FZ2",
                            "the Q_FZ2 = %g identified on the derived ring gives no deflection "
                            "at FNOMIN %g N", *q2, k->fnomin);
    *h = log(rho_law / ring->defl[I_NOMINAL]);
    return TIRENV_OK;
}

/* docs/models.md section 14.2: the derived ring and its states, scaled to the file's vertical
 * law; *rho_n the deflection (m) at which it carries FNOMIN. A file's own law (Q_FZ2 or Q_FZ1
 * given) fixes that deflection, and the ring is scaled to carry FNOMIN there (derive_ring). A
 * law of VERTICAL_STIFFNESS alone gets Q_FZ2 identified on the ring, VERTICAL_STIFFNESS kept
 * its tangent at FNOMIN: the ring stiffens with the load, so the law's secant at FNOMIN falls
 * below VERTICAL_STIFFNESS and its deflection there grows. The ring is then scaled (its four
 * stiffnesses by one factor c, as derive_ring scales them) until it deflects at FNOMIN as the
 * law identified on it does: the root of h(c) = log(the law's deflection / the ring's) at
 * FNOMIN, in log c from the ring that carries FNOMIN at the linear law's deflection (c = 1):
 * the first step takes the ring's tangent at FNOMIN to VERTICAL_STIFFNESS (the ring's
 * stiffness at a deflection grows about as c), which lands within a few per cent of the root
 * where the fixed-point step (the ring scaled to the law's deflection) crept at a per cent a
 * step; then secant steps, and the Illinois method once h changes sign, each step at most
 * MAX_LAW_STEP in log c. To LAW_TOL: the law deflects within 1e-6 of the ring at FNOMIN, far
 * above the ring's repeatability (a flat inversion to 1e-9 m) and far below the differences
 * the tests bound (0.5 % and more); 4 to 5 evaluations of the ring's states on the tests'
 * files. Where h keeps its sign (a ring whose air alone is stiffer at FNOMIN than the law),
 * TIRENV_ENOCONV after MAX_LAW_EVALS, naming Q_FZ2: the caller falls back on the linear
 * law. */
static int ring_on_law(tirenv_tire *t, const mf_keys *k, const vertical_law *v, double tau,
                       const tirenv_profile *flat, flat_set *ring, double *rho_n, double *q2,
                       tirenv_diag *diag)
{
    static const double LAW_TOL = 1e-6, MAX_LAW_STEP = 1;
    enum { MAX_LAW_EVALS = 12 };
    *rho_n = v->rho_n;
    *q2 = 0;
    int status = derive_ring(t, k, v->rho_n, tau, flat, diag);
    if (!status) {
        double guess[N_LOADS];  /* the linear law's */
        for (size_t i = 0; i < N_LOADS; i++)
            guess[i] = tirenv_nominal_load_fractions[i] * v->rho_n;
        status = ring_flats(t, flat, k->fnomin, guess, ring, diag);
    }
    if (status || !v->derive_q_fz2)
        return status;
    if (ring->G[I_NOMINAL] != k->fnomin)  /* the load fractions lost their 1 */
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "FNOMIN",
                            "the derivation's loads do not include FNOMIN itself");
    const double base[4] = {t->ring.EI, t->ring.T, t->ring.k_c, t->ring.k_t};
    /* The states at c = 1 are the ones just computed. */
    *q2 = q_fz2_on(k, v->factor, ring);
    double u = 0, h = log(law_deflection(k, *q2, v->factor, k->fnomin) / ring->defl[I_NOMINAL]);
    double u_a = u, h_a = h, u_b = 0, h_b = 0;  /* the last two, or a bracket */
    int bracket = 0, side = 0;
    for (int ev = 1; !(fabs(h) <= LAW_TOL); ev++) {  /* a NAN h is refused in the loop */
        if (ev >= MAX_LAW_EVALS || !isfinite(h))
            return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "Q_FZ2",
                                "the derived ring and the Q_FZ2 identified on it found no "
                                "common deflection at FNOMIN %g N in %d trials (the law's "
                                "deflection there %g times the ring's at best)", k->fnomin,
                                (int)MAX_LAW_EVALS, exp(fabs(h_a) < fabs(h) ? h_a : h));
        double step;
        if (ev == 1)
            step = log(k->c_z / ring->k[I_NOMINAL]);
        else if (bracket)  /* Illinois within [u_a, u_b] */
            step = (u_a * h_b - u_b * h_a) / (h_b - h_a) - u;
        else
            step = h != h_b ? -h * (u - u_b) / (h - h_b) : -h;
        const double u_new = u + fmax(-MAX_LAW_STEP, fmin(MAX_LAW_STEP, step));
        const double u_old = u, h_old = h;
        if ((status = ring_and_law(t, k, v, base, exp(u_new), flat, ring, q2, &h, diag)))
            return status;
        u = u_new;
        if (bracket) {
            if ((h > 0) == (h_a > 0)) {
                u_a = u, h_a = h;
                if (side == 1)
                    h_b *= 0.5;
                side = 1;
            } else {
                u_b = u, h_b = h;
                if (side == -1)
                    h_a *= 0.5;
                side = -1;
            }
        } else if ((h > 0) != (h_old > 0)) {
            bracket = 1;
            u_a = u_old, h_a = h_old, u_b = u, h_b = h;
        } else {
            u_b = u_old, h_b = h_old;  /* the secant's previous point */
            if (fabs(h) < fabs(h_a))
                u_a = u, h_a = h;      /* the best so far, for the message */
        }
    }
    *rho_n = ring->defl[I_NOMINAL];
    return TIRENV_OK;
}

/* How the springs model's contact length grows with the load against the ring's: the log of
 * their ratio at 0.5 FNOMIN minus that at 1.5 FNOMIN (0: the same growth; > 0: the springs
 * model's grows slower, long at the lowest load and short at the highest). */
static int growth_miss(const tirenv_tire *t, double fnomin, const flat_set *ring, double *e,
                       tirenv_diag *diag)
{
    flat_set sp;
    const int status = flats(tirenv_model_springs, t, fnomin, &sp, diag);
    if (!status)
        *e = log(sp.l[0] / ring->l[0]) - log(sp.l[N_LOADS - 1] / ring->l[N_LOADS - 1]);
    return status;
}

/* The ring and the springs model derived together, for a file with neither (section 14.2).
 * With the default's shape (tau = 0) the springs model identified on the derived ring can
 * touch ground that grows slower with the load than the ring's patch (the 335/65R22.5 and the
 * HMMWV: 7 and 10 % long at 0.5 FNOMIN, 4 and 6 % short at 1.5): c_b/c_r, its one shape
 * parameter, cannot follow both ends. A carcass pretension T = tau*k_f*R^2 on the derived
 * ring slows its patch's growth (and makes its load-deflection more linear, nearer MF-Tyre's
 * law without Q_FZ2), and the springs model identified on it takes a larger c_b/c_r; tau is
 * raised until the two grow alike: the root of growth_miss in tau, bracketed by doubling from
 * TAU_FIRST up to TAU_MAX and narrowed by the Illinois method to E_TOL (half a per cent at
 * each end), at most MAX_EVALS trials, each a ring derivation and a springs identification
 * (about 0.4 s of CPU). TAU_MAX keeps the belt far from buckling on its foundation (the
 * check of section 5.1 refuses tau near 1); where even it leaves the springs model slower,
 * it is taken. A file whose springs model already grows as fast keeps tau = 0: the default's
 * shape and the values derived before. */
typedef struct {
    tirenv_tire t;   /* the tire with both models derived at tau */
    flat_set ring;   /* its ring's states */
    double tau, e;   /* -, growth_miss */
    double rho_n;    /* the deflection at FNOMIN both carry it at, m */
    double q_fz2;    /* Q_FZ2 identified on the ring (ring_on_law), or 0 */
} trial;

static int try_tau(const tirenv_tire *t0, const mf_keys *k, const vertical_law *v, double tau,
                   const tirenv_profile *flat, trial *out, tirenv_diag *diag)
{
    out->t = *t0;
    out->tau = tau;
    int status = ring_on_law(&out->t, k, v, tau, flat, &out->ring, &out->rho_n, &out->q_fz2, diag);
    if (!status)
        status = derive_springs(&out->t, k, out->rho_n, &out->ring, diag);
    if (!status)
        status = growth_miss(&out->t, k->fnomin, &out->ring, &out->e, diag);
    return status;
}

static int derive_ring_springs(tirenv_tire *t, const mf_keys *k, const vertical_law *v,
                               const tirenv_profile *flat, trial *best, tirenv_diag *diag)
{
    static const double TAU_FIRST = 0.1, TAU_MAX = 0.4, E_TOL = 0.01;
    enum { MAX_EVALS = 12 };
    trial lo, hi, x;
    int status = try_tau(t, k, v, 0, flat, &lo, diag);
    int evals = 1;
    if (status)
        return status;
    if (lo.e <= E_TOL) {
        *best = lo;
        return TIRENV_OK;
    }
    /* Bracket: lo grows slower (e > 0); double tau until hi does not. */
    double tau = TAU_FIRST;
    for (;;) {
        if ((status = try_tau(t, k, v, tau, flat, &hi, diag)))
            return status;
        evals++;
        if (hi.e <= E_TOL || tau >= TAU_MAX)
            break;
        lo = hi;
        tau = fmin(2 * tau, TAU_MAX);
    }
    if (hi.e > 0) {  /* within tolerance, or still slower at TAU_MAX */
        *best = hi;
        return TIRENV_OK;
    }
    double fa = lo.e, fb = hi.e;
    int side = 0;
    *best = fabs(lo.e) < fabs(hi.e) ? lo : hi;
    while (evals < MAX_EVALS && fabs(best->e) > E_TOL) {
        tau = (lo.tau * fb - hi.tau * fa) / (fb - fa);
        if ((status = try_tau(t, k, v, tau, flat, &x, diag)))
            return status;
        evals++;
        if (fabs(x.e) < fabs(best->e))
            *best = x;
        if (x.e > 0) {
            lo = x, fa = x.e;
            if (side == 1)
                fb *= 0.5;
            side = 1;
        } else {
            hi = x, fb = x.e;
            if (side == -1)
                fa *= 0.5;
            side = -1;
        }
    }
    return TIRENV_OK;
}

/* docs/models.md section 14.2, "A derived ring on a file's own laws": a file that gives the
 * cam's contact law (Q_RA1, Q_RA2) of its own and no [ENVELOPING_RING] gets a ring that
 * follows that law as well as the vertical law: the ring of section 5.1 whose carcass
 * softens (CARCASS_SOFTENING_DEFLECTION w_s, CARCASS_LINEAR_DEFLECTION w_0 = w_s*W0_RATIO) on
 * the shear-coupled tread (TREAD_SHEAR LAWS_G_T, NODE_ANGLE 0.25 degrees), as the 205/60R15's
 * ring was searched on TNO's laws. Five keys are searched, their logs: FOUNDATION_STIFFNESS
 * k_c, w_s, BELT_BENDING_STIFFNESS EI, TREAD_STIFFNESS k_t and BELT_WIDTH b_p (held within
 * 0.4 to 1.0 times WIDTH, as scripts/ring-on-laws.py holds it), on ten residuals: at each of
 * the cam's deflections d_i at 0.5 to 1.5 FNOMIN the log of the ring's load over G_i and of
 * its contact length over the cam's, from one force evaluation each at the centre height
 * R0 - d_i (tirenv_model_flat_at_height: no inversion). Levenberg and Marquardt's method on
 * their sum of squares, the Jacobian by forward differences at the start and then Broyden's
 * rank-one updates, again by differences when a step fails twice; at most LAWS_MAX_TABLES
 * ring tables. */
enum { N_LAWS = 5, N_H = N_LOADS, N_RES = 2 * N_H, LAWS_MAX_TABLES = 30 };
static const double LAWS_G_T = 5e5, W0_RATIO = 0.02, LAWS_SEARCH_DTHETA = M_PI / 360.0,
                    LAWS_KT_START = 12;

typedef struct {
    tirenv_tire t;                       /* the ring's template */
    const mf_keys *k;
    double G[N_H], d[N_H], l[N_H];       /* the cam's: N, m, m */
    double b_lo, b_hi;                   /* BELT_WIDTH's bounds, m */
    const tirenv_profile *flat;          /* flat ground z = 0 */
    int tables;                          /* ring tables evaluated */
} laws_search;

static void laws_set(const laws_search *s, const double x[N_LAWS], tirenv_tire *t)
{
    *t = s->t;
    t->ring.k_c = exp(x[0]);
    t->ring.w_cs = exp(x[1]);
    t->ring.w_c0 = W0_RATIO * t->ring.w_cs;
    t->ring.EI = exp(x[2]);
    t->ring.k_t = exp(x[3]);
    t->ring.b_p = exp(x[4]);
}

/* The ten residuals of the ring of x; TIRENV_OK or the ring's refusal. */
static int laws_residuals(laws_search *s, const double x[N_LAWS], double r[N_RES],
                          tirenv_diag *diag)
{
    tirenv_tire t;
    laws_set(s, x, &t);
    s->tables++;
    int status = tirenv_tire_check(&t, diag);
    if (status)
        return status;
    double G[N_H], l[N_H];
    if ((status = ring_at_heights(&t, s->flat, N_H, s->d, G, l, diag)))
        return status;
    for (size_t i = 0; i < N_H; i++) {
        if (!(G[i] > 0 && l[i] > 0))
            return tirenv_error(diag, TIRENV_ERANGE, "", 0, "ring",
                                "the ring searched carries no load at %g m", s->d[i]);
        r[i] = log(G[i] / s->G[i]);
        r[N_H + i] = log(l[i] / s->l[i]);
    }
    return TIRENV_OK;
}

static double max_abs(const double r[N_RES])
{
    double m = 0;
    for (size_t i = 0; i < N_RES; i++)
        m = fmax(m, fabs(r[i]));
    return m;
}

static double sum_sq(const double r[N_RES])
{
    double s = 0;
    for (size_t i = 0; i < N_RES; i++)
        s += r[i] * r[i];
    return s;
}

/* BELT_WIDTH within its bounds. */
static void laws_clamp(const laws_search *s, double x[N_LAWS])
{
    x[4] = fmax(log(s->b_lo), fmin(log(s->b_hi), x[4]));
}

/* The Jacobian by forward differences of LAWS_H in each log. */
static int laws_jacobian(laws_search *s, const double x[N_LAWS], const double r[N_RES],
                         double J[N_RES][N_LAWS], tirenv_diag *diag)
{
    static const double LAWS_H = 0.02;
    for (size_t j = 0; j < N_LAWS; j++) {
        double y[N_LAWS], ry[N_RES];
        memcpy(y, x, sizeof y);
        const double h = j == 4 && x[4] + LAWS_H > log(s->b_hi) ? -LAWS_H : LAWS_H;
        y[j] += h;
        const int status = laws_residuals(s, y, ry, diag);
        if (status)
            return status;
        for (size_t i = 0; i < N_RES; i++)
            J[i][j] = (ry[i] - r[i]) / h;
    }
    return TIRENV_OK;
}

/* Solves the n x n system A y = b in place (Gaussian elimination, partial pivoting); 0, or -1
 * for a singular A. */
static int solve_small(size_t n, double A[N_LAWS][N_LAWS], double b[N_LAWS])
{
    for (size_t c = 0; c < n; c++) {
        size_t p = c;
        for (size_t i = c + 1; i < n; i++)
            if (fabs(A[i][c]) > fabs(A[p][c]))
                p = i;
        if (!(fabs(A[p][c]) > 0))
            return -1;
        for (size_t j = 0; j < n; j++) {
            const double a = A[c][j];
            A[c][j] = A[p][j], A[p][j] = a;
        }
        const double bb = b[c];
        b[c] = b[p], b[p] = bb;
        for (size_t i = c + 1; i < n; i++) {
            const double f = A[i][c] / A[c][c];
            for (size_t j = c; j < n; j++)
                A[i][j] -= f * A[c][j];
            b[i] -= f * b[c];
        }
    }
    for (size_t c = n; c-- > 0;) {
        for (size_t j = c + 1; j < n; j++)
            b[c] -= A[c][j] * b[j];
        b[c] /= A[c][c];
    }
    return 0;
}

/* The search from x: x and r become the best ring found and its residuals. Levenberg and
 * Marquardt's damped normal equations (lambda on the diagonal, divided by 3 after a step
 * that lowers the sum of squares, times 4 after one that does not; a step at most 1 in each
 * log), the Jacobian updated along each step taken by Broyden's rank-one formula and made
 * again by differences after two steps in a row that fail (a ring the model refuses fails).
 * It stops when the largest residual is within LAWS_STOP (2.5 %: within the 5 % with
 * room for the shipped resolution and the comparison at fixed loads; at 2 % the tests' two
 * files took 21 and 22 tables for their cam within 2.3 and 1.6 % of the ring, at 2.5 % 10
 * and 20 for 2.3 and 1.7 %), when a step gains less than 1e-3 of the sum, after five
 * failures in a row, or at LAWS_MAX_TABLES tables. A failure of the start or of a Jacobian is
 * returned (the caller keeps the Winkler ring and says why). */
static int laws_search_run(laws_search *s, double x[N_LAWS], double r[N_RES], tirenv_diag *diag)
{
    static const double LAWS_STOP = 0.025, MAX_LOG_STEP = 1;
    double J[N_RES][N_LAWS];
    int status = laws_residuals(s, x, r, diag);
    if (!status)
        status = laws_jacobian(s, x, r, J, diag);
    if (status)
        return status;
    double f = sum_sq(r), lambda = 1e-2;
    int fails = 0;
    while (s->tables < LAWS_MAX_TABLES && max_abs(r) > LAWS_STOP) {
        double A[N_LAWS][N_LAWS], g[N_LAWS], y[N_LAWS], dx[N_LAWS], ry[N_RES], dd = 0;
        for (size_t a = 0; a < N_LAWS; a++) {
            g[a] = 0;
            for (size_t i = 0; i < N_RES; i++)
                g[a] -= J[i][a] * r[i];
            for (size_t b = 0; b < N_LAWS; b++) {
                A[a][b] = 0;
                for (size_t i = 0; i < N_RES; i++)
                    A[a][b] += J[i][a] * J[i][b];
            }
            A[a][a] *= 1 + lambda;
        }
        if (solve_small(N_LAWS, A, g))
            break;
        for (size_t a = 0; a < N_LAWS; a++)
            y[a] = x[a] + fmax(-MAX_LOG_STEP, fmin(MAX_LOG_STEP, g[a]));
        laws_clamp(s, y);
        for (size_t a = 0; a < N_LAWS; a++) {
            dx[a] = y[a] - x[a];
            dd += dx[a] * dx[a];
        }
        if (!(dd > 1e-16))
            break;
        tirenv_diag refused;
        const int st = laws_residuals(s, y, ry, &refused);
        const double fy = st ? HUGE_VAL : sum_sq(ry);
        if (!st) {
            for (size_t i = 0; i < N_RES; i++) {
                double Jdx = 0;
                for (size_t a = 0; a < N_LAWS; a++)
                    Jdx += J[i][a] * dx[a];
                const double u = (ry[i] - r[i] - Jdx) / dd;
                for (size_t a = 0; a < N_LAWS; a++)
                    J[i][a] += u * dx[a];
            }
        }
        if (fy < f) {
            const double gain = f - fy;
            memcpy(x, y, sizeof y);
            memcpy(r, ry, sizeof ry);
            f = fy;
            lambda = fmax(1e-6, lambda / 3);
            fails = 0;
            if (gain < 1e-3 * f)
                break;
        } else {
            lambda *= 4;
            if (++fails == 2 && s->tables + N_LAWS <= LAWS_MAX_TABLES) {
                if ((status = laws_jacobian(s, x, r, J, diag)))
                    return status;
            } else if (fails > 4) {
                break;
            }
        }
    }
    return TIRENV_OK;
}

/* The largest relative differences of two sets of flat states at the same loads. */
static void set_miss(const flat_set *a, const flat_set *b, double *e_defl, double *e_l)
{
    *e_defl = *e_l = 0;
    for (size_t i = 0; i < N_LOADS; i++) {
        *e_defl = fmax(*e_defl, fabs(a->defl[i] - b->defl[i]) / b->defl[i]);
        *e_l = fmax(*e_l, fabs(a->l[i] - b->l[i]) / b->l[i]);
    }
}

/* What the search on the laws did, for the note. */
typedef struct {
    int searched;             /* the ring searched on the laws was kept */
    int tables;               /* ring tables of the search */
    double e_defl, e_l;       /* its cam-ring misses (kept or not) */
    double w_defl, w_l;       /* the Winkler ring's */
    char why[160];            /* why the search's ring could not be made, or "" */
} laws_result;

/* The ring of a file with its own contact law (section 14.2): first the ring on the vertical
 * law as without it (ring_on_law: the Winkler tread; Q_FZ2 identified on it where the file's
 * law is VERTICAL_STIFFNESS alone, and that law kept as the target), then the search above
 * from that ring (its k_c and EI; w_s the law's deflection at FNOMIN, k_t LAWS_KT_START times
 * k_c, as on the 205/60R15's ring and the 430/50R38's best, b_p 0.75 WIDTH) at
 * LAWS_SEARCH_DTHETA, 0.5 degrees; the ring found, at the shipped 0.25 degrees, scaled to
 * carry FNOMIN at the law's deflection there (scale_at_height), tabled (ring_flats) and its
 * range checked (within_range). Every ring of these files, the Winkler ring's scaling and
 * tables included (flat given to ring_on_law), is evaluated on ring workspaces at heights,
 * never through the ring model, whose valid-range scan on each new model cost more than the
 * rest (docs/performance.md 5.3). The search's ring is kept where its largest difference
 * from the cam is below the Winkler ring's, else the Winkler ring (the note says which, and
 * both differences); derive_on_laws then identifies the springs model on the ring kept, with
 * a sidewall in series where it is the search's (derive_springs_sidewall). */
static int laws_ring(const tirenv_tire *t, const mf_keys *k, const vertical_law *v,
                     const tirenv_profile *flat, trial *tr, laws_result *lr, tirenv_diag *diag)
{
    tr->t = *t;
    tr->tau = 0;
    int status = ring_on_law(&tr->t, k, v, 0, flat, &tr->ring, &tr->rho_n, &tr->q_fz2, diag);
    if (status)
        return status;
    tirenv_tire c = tr->t;
    if (v->derive_q_fz2)
        c.cam.q_fz2 = tr->q_fz2;
    flat_set cam;
    if ((status = flats(tirenv_model_cam, &c, k->fnomin, &cam, diag)))
        return status;
    set_miss(&cam, &tr->ring, &lr->w_defl, &lr->w_l);
    laws_search s = {.t = tr->t, .k = k, .flat = flat};
    s.t.ring.G_t = LAWS_G_T;
    s.t.ring.dtheta = LAWS_SEARCH_DTHETA;
    s.t.ring.contact = TIRENV_RING_CONTINUOUS;
    const double width = (k->given & MF_WIDTH) && k->width > 0 ? k->width : tr->t.ring.b_p;
    s.b_lo = 0.4 * width;
    s.b_hi = 1.0 * width;
    for (size_t i = 0; i < N_H; i++) {
        s.G[i] = cam.G[i];
        s.d[i] = cam.defl[i];
        s.l[i] = cam.l[i];
    }
    double x[N_LAWS] = {log(tr->t.ring.k_c), log(tr->rho_n), log(tr->t.ring.EI),
                        log(LAWS_KT_START * tr->t.ring.k_c), log(0.75 * width)};
    laws_clamp(&s, x);
    double r[N_RES];
    tirenv_diag d2;
    status = laws_search_run(&s, x, r, &d2);
    lr->tables = s.tables;
    trial on = *tr;
    if (!status) {
        laws_set(&s, x, &on.t);
        on.t.ring.dtheta = M_PI / 720.0;
        status = scale_at_height(&on.t, flat, k->fnomin, tr->rho_n, &d2);
    }
    if (!status)
        status = ring_flats(&on.t, flat, k->fnomin, cam.defl, &on.ring, &d2);
    if (!status)
        status = within_range(&on.t, flat, on.ring.defl[N_LOADS - 1], &d2);
    if (!status) {
        set_miss(&cam, &on.ring, &lr->e_defl, &lr->e_l);
        lr->searched = fmax(lr->e_defl, lr->e_l) < fmax(lr->w_defl, lr->w_l);
    }
    if (status)
        snprintf(lr->why, sizeof lr->why, "%.40s: %.110s", d2.field, d2.message);
    if (lr->searched)
        *tr = on;
    else  /* the Winkler ring, tabled by ring_flats too */
        return within_range(&tr->t, flat, tr->ring.defl[N_LOADS - 1], diag);
    return TIRENV_OK;
}

static int derive_on_laws(tirenv_tire *t, const mf_keys *k, unsigned lack,
                          const vertical_law *v, const tirenv_profile *flat, trial *tr,
                          laws_result *lr, tirenv_diag *diag)
{
    memset(lr, 0, sizeof *lr);
    const int status = laws_ring(t, k, v, flat, tr, lr, diag);
    if (status || !(lack & TIRENV_TIR_SPRINGS))
        return status;
    return lr->searched ? derive_springs_sidewall(&tr->t, k, tr->rho_n, &tr->ring, diag)
                        : derive_springs(&tr->t, k, tr->rho_n, &tr->ring, diag);
}

/* The largest relative differences of the cam's flat-ground states from the ring's at the
 * same loads: deflection and contact length. */
static int cam_ring_miss(const tirenv_tire *t, double fnomin, const flat_set *ring,
                         double *e_defl, double *e_l, tirenv_diag *diag)
{
    flat_set cam;
    const int status = flats(tirenv_model_cam, t, fnomin, &cam, diag);
    if (status)
        return status;
    *e_defl = *e_l = 0;
    for (size_t i = 0; i < N_LOADS; i++) {
        *e_defl = fmax(*e_defl, fabs(cam.defl[i] - ring->defl[i]) / ring->defl[i]);
        *e_l = fmax(*e_l, fabs(cam.l[i] - ring->l[i]) / ring->l[i]);
    }
    return TIRENV_OK;
}

/* The cam's contact-length law (Q_RA1, Q_RA2) identified on the tire's ring as tirenv identify
 * does (section 14.1): at 0.5 to 1.5 times FNOMIN, at the cam's own deflection there by the
 * file's vertical law, the cam's patch 2a is the ring's contact length. */
static int derive_cam(tirenv_tire *t, double fnomin, const flat_set *ring, tirenv_diag *diag)
{
    flat_set cam;
    int status = flats(tirenv_model_cam, t, fnomin, &cam, diag);
    if (status)
        return status;
    double q_ra1, q_ra2;
    if (tirenv_cam_fit_contact_law(t->springs.R0, N_LOADS, cam.defl, ring->l, &q_ra1, &q_ra2))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "Q_RA1",
                            "the ring's contact lengths at 0.5 to 1.5 FNOMIN do not separate "
                            "the cam's contact law's two terms");
    t->cam.q_ra1 = q_ra1;
    t->cam.q_ra2 = q_ra2;
    t->cam.given |= TIRENV_CAM_Q_RA1 | TIRENV_CAM_Q_RA2;
    return tirenv_tire_check(t, diag);
}

static void note_add(tirenv_tir_origin *o, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void note_add(tirenv_tir_origin *o, const char *fmt, ...)
{
    const size_t n = strlen(o->note);
    if (n + 1 >= sizeof o->note)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(o->note + n, sizeof o->note - n, fmt, ap);
    va_end(ap);
}

/* The cam's part (section 14.2), after the ring and the springs model: where the file lacks
 * Q_RA1 or Q_RA2 they are identified on the tire's ring; where it has them they are kept, and
 * either way, when a model was derived, how far the cam and the ring differ is measured and
 * said. A cam that cannot be derived is not fatal here: without Q_RA1 and Q_RA2 of its own the
 * cam is refused naming them where it is used (tirenv_tire_check_cam_keys). */
static void cam_part(tirenv_tire *t, const mf_keys *k, const flat_set *ring_or_null,
                     int derive, tirenv_tir_origin *origin)
{
    tirenv_diag d;
    flat_set ring;
    int status = TIRENV_OK;
    if (ring_or_null)
        ring = *ring_or_null;
    else
        status = flats(tirenv_model_ring, t, k->fnomin, &ring, &d);
    const char *sep = origin->note[0] ? "; " : "";
    if (!status && derive && !(status = derive_cam(t, k->fnomin, &ring, &d))) {
        origin->derived |= TIRENV_TIR_CAM;
        note_add(origin, "%sno Q_RA1, Q_RA2 of its own: derived on the ring Q_RA1 = %.4g, "
                 "Q_RA2 = %.4g", sep, t->cam.q_ra1, t->cam.q_ra2);
    } else if (!status && !derive) {
        note_add(origin, "%sthe file's own cam contact law kept (Q_RA1 = %.4g, Q_RA2 = %.4g)",
                 sep, t->cam.q_ra1, t->cam.q_ra2);
    }
    double e_defl = 0, e_l = 0;
    if (!status)
        status = cam_ring_miss(t, k->fnomin, &ring, &e_defl, &e_l, &d);
    if (status) {
        note_add(origin, "%sthe cam's contact law could not be %s on the ring (%s: %s)", sep,
                 derive ? "derived" : "compared", d.field, d.message);
        return;
    }
    origin->cam_ring_deflection = e_defl;
    origin->cam_ring_contact_length = e_l;
    note_add(origin, ": cam against ring at 0.5 to 1.5 FNOMIN, deflection up to %.1f %%%s, "
             "contact length up to %.1f %%", 100 * e_defl,
             origin->derived & TIRENV_TIR_VERTICAL ? ""
             : origin->own & TIRENV_TIR_VERTICAL   ? " (the file's own vertical law)"
                                                   : " (the file's linear law)",
             100 * e_l);
}

/* The models the file lacks (lack: TIRENV_TIR_SPRINGS and/or TIRENV_TIR_RING) derived into
 * *t on the law v, the ring first (the springs model is identified on it); *tr holds the
 * ring's states (*have_ring set) and the deflection at FNOMIN and Q_FZ2 they were made on.
 * A derived ring is evaluated on ring workspaces at heights (ring_on_law given the flat
 * ground), never through the ring model, whose valid-range scan on each new model was most
 * of a read (docs/performance.md 5.3), and the ring kept is checked within its range down
 * to its largest deflection (within_range). */
static int derive_models(tirenv_tire *t, const mf_keys *k, unsigned lack, const vertical_law *v,
                         const tirenv_profile *flat, trial *tr, int *have_ring,
                         tirenv_diag *diag)
{
    int status = TIRENV_OK;
    *have_ring = 0;
    tr->rho_n = v->rho_n;
    tr->q_fz2 = 0;
    if (lack == (TIRENV_TIR_SPRINGS | TIRENV_TIR_RING)) {
        status = derive_ring_springs(t, k, v, flat, tr, diag);
        if (!status)
            *t = tr->t;
    } else if (lack == TIRENV_TIR_RING) {
        status = ring_on_law(t, k, v, 0, flat, &tr->ring, &tr->rho_n, &tr->q_fz2, diag);
    } else if (lack == TIRENV_TIR_SPRINGS) {
        status = flats(tirenv_model_ring, t, k->fnomin, &tr->ring, diag);
        if (!status)
            status = derive_springs(t, k, v->rho_n, &tr->ring, diag);
    }
    if (!status && (lack & TIRENV_TIR_RING))
        status = within_range(t, flat, tr->ring.defl[N_LOADS - 1], diag);
    *have_ring = lack != 0 && !status;  /* lack 0: no ring states made here */
    return status;
}

/* derive_models for a file with a contact law of its own (derive_on_laws). */
static int derive_laws_models(tirenv_tire *t, const mf_keys *k, unsigned lack,
                              const vertical_law *v, const tirenv_profile *flat, trial *tr,
                              laws_result *lr, int *have_ring, tirenv_diag *diag)
{
    tr->t = *t;
    const int status = derive_on_laws(t, k, lack, v, flat, tr, lr, diag);
    *have_ring = !status;
    if (!status)
        *t = tr->t;
    return status;
}

/* What of the file's vertical law is not VERTICAL_STIFFNESS at NOMPRES (section 7.3): its own
 * Q_FZ1, and PFZ1's pressure factor at INFLPRES, which the cam and the derivation both take;
 * "" when neither. */
static void law_note(const tirenv_tire *t, char *buf, size_t n)
{
    const double f = tirenv_cam_pressure_factor(t->cam.pfz1, t->ring.p, t->ring.p_nom);
    const tirenv_cam_vertical v = {.R0 = t->springs.R0, .fnomin = t->cam.fnomin,
                                   .c_z = t->cam.c_z, .q_fz1 = t->cam.q_fz1,
                                   .q_fz2 = t->cam.q_fz2, .factor = f};
    int k = 0;
    buf[0] = '\0';
    if (t->cam.q_fz1 != 0)
        k = snprintf(buf, n, "the vertical law takes the file's Q_FZ1 = %.6g, not one from "
                     "VERTICAL_STIFFNESS %.4g kN/m", t->cam.q_fz1, t->cam.c_z / 1e3);
    if (f != 1 && k >= 0 && (size_t)k < n)
        k += snprintf(buf + k, n - (size_t)k, "%sthe vertical law times PFZ1's pressure factor "
                      "1 + %.4g*(INFLPRES %.4g kPa - NOMPRES %.4g kPa)/NOMPRES = %.6g",
                      k ? "; " : "", t->cam.pfz1, t->ring.p / 1e3, t->ring.p_nom / 1e3, f);
    if (k > 0 && (size_t)k < n && t->cam.fnomin > 0)
        snprintf(buf + k, n - (size_t)k, " (deflection %.4g mm at FNOMIN %.6g N)",
                 tirenv_cam_vertical_deflection(&v, t->cam.fnomin) * 1e3, t->cam.fnomin);
}

/* Done: the note on the vertical law (law_note) after the rest. */
static int derived(tirenv_tir_origin *o, const char *law)
{
    if (law[0])
        note_add(o, "%s%s", o->note[0] ? "; " : "", law);
    return TIRENV_OK;
}

/* The enveloping models a file may lack, in the order they are derived (the springs model is
 * identified on the ring). */
static const struct {
    unsigned bit;
    const char *section, *model;
} lackable[] = {
    {TIRENV_TIR_RING, "ENVELOPING_RING", "ring"},
    {TIRENV_TIR_SPRINGS, "ENVELOPING_SPRINGS", "springs"},
};

/* What the file has of its own (origin->own, origin->fnomin), after MF-Tyre's rule that a file
 * without INFLPRES is at its NOMPRES (PFZ1's factor 1), not at the pressure of the tire it was
 * read over. Returns whether the vertical law is the file's own: Q_FZ2, or a Q_FZ1 other than
 * 0 (0 is MF-Tyre's "derive it from VERTICAL_STIFFNESS", nominal_deflection). */
static int take_own(const mf_keys *k, tirenv_tire *tire, tirenv_tir_origin *origin)
{
    if (!(k->given & MF_INFLPRES) && (k->given & MF_NOMPRES)) {
        tire->ring.p = k->nompres;
        note_add(origin, "no INFLPRES: NOMPRES's %.4g kPa", k->nompres / 1e3);
    }
    const int own_law = (k->given & MF_QFZ2) || ((k->given & MF_QFZ1) && k->q_fz1 != 0);
    origin->own = (k->given & MF_SPRINGS ? TIRENV_TIR_SPRINGS : 0u) |
                  (k->given & MF_RING ? TIRENV_TIR_RING : 0u) |
                  (own_law ? TIRENV_TIR_VERTICAL : 0u);
    const unsigned q_ra = TIRENV_CAM_Q_RA1 | TIRENV_CAM_Q_RA2;
    if ((tire->cam.given & q_ra) == q_ra)
        origin->own |= TIRENV_TIR_CAM;
    origin->fnomin = k->given & MF_FNOMIN ? k->fnomin : 0;
    return own_law;
}

/* The cam alone used, its laws the file's own: the models the file lacks said not derived and
 * not this tire's. */
static void note_cam_alone(tirenv_tir_origin *origin, unsigned lack, const tirenv_tire *tire)
{
    for (size_t i = 0; i < 2; i++)
        if (lack & lackable[i].bit)
            note_add(origin, "%sno [%s]: the %s model not derived (the cam alone is used, "
                     "its laws the file's own) and not this tire's",
                     origin->note[0] ? "; " : "", lackable[i].section, lackable[i].model);
    note_add(origin, "; the file's own cam contact law kept (Q_RA1 = %.4g, Q_RA2 = %.4g)",
             tire->cam.q_ra1, tire->cam.q_ra2);
}

/* A file without a key the derivation takes (missing names it): refused where a model it lacks
 * is needed, else each such model said not this tire's. */
static int note_missing(const char *path, unsigned need, unsigned lack, const char *missing,
                        tirenv_tir_origin *origin, tirenv_diag *diag)
{
    for (size_t i = 0; i < 2; i++) {
        if (!(lack & lackable[i].bit))
            continue;
        if (need & lackable[i].bit)
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, missing,
                                "the file has no [%s] and no %s to derive the %s model "
                                "from (docs/models.md section 14)", lackable[i].section,
                                missing, lackable[i].model);
        note_add(origin, "%sno [%s] and no %s: the %s model is not this tire's",
                 origin->note[0] ? "; " : "", lackable[i].section, missing, lackable[i].model);
    }
    return TIRENV_OK;
}

/* One derivation: what the file lacks, what is made of it, on which law, and what came of it
 * (for the notes). */
typedef struct {
    unsigned lack;     /* TIRENV_TIR_SPRINGS and/or TIRENV_TIR_RING: not in the file */
    unsigned unused;   /* of lack, what the caller does not use and is not derived */
    unsigned make;     /* lack & ~unused */
    int on_laws;       /* the ring searched on the file's own contact law (derive_on_laws) */
    vertical_law law;
    trial tr;
    laws_result lr;    /* with on_laws */
    int have_ring;     /* tr.ring holds the ring's states */
    char no_law[sizeof ((tirenv_diag *)0)->message]; /* why no Q_FZ2 was derived, or "" */
} derivation;

/* dv->make derived into *t: on the file's own laws where the ring is searched on them. */
static int make_models(tirenv_tire *t, const mf_keys *k, const tirenv_profile *flat,
                       derivation *dv, tirenv_diag *diag)
{
    return dv->on_laws ? derive_laws_models(t, k, dv->make, &dv->law, flat, &dv->tr, &dv->lr,
                                            &dv->have_ring, diag)
                       : derive_models(t, k, dv->make, &dv->law, flat, &dv->tr, &dv->have_ring,
                                       diag);
}

/* The models dv->make derived into *t (the file's tire, *tire, with what it has), the ring
 * first: the springs model is identified on it. Where no Q_FZ2 identified on the derived ring
 * deflects with it at FNOMIN (a ring whose air alone is stiffer than the law at FNOMIN:
 * test_onetire.c's car-sized ring at a PFZ1 factor of 1.26), the derivation is made again on
 * the file's linear law, as without Q_FZ2, and dv->no_law says why. */
static int run_derivation(const char *path, const tirenv_tire *tire, const mf_keys *k,
                          derivation *dv, tirenv_tire *t, tirenv_diag *diag)
{
    const double zero = 0;
    tirenv_profile *flat = tirenv_profile_alloc(1, &zero, &zero);  /* the ring's ground */
    if (!flat)
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "ring",
                            "no memory for the flat ground the ring is derived on");
    dv->no_law[0] = '\0';
    int status = make_models(t, k, flat, dv, diag);
    if (status && dv->law.derive_q_fz2 && strcmp(diag->field, "Q_FZ2") == 0) {
        snprintf(dv->no_law, sizeof dv->no_law, "%s", diag->message);
        dv->law.derive_q_fz2 = 0;
        *t = *tire;
        status = make_models(t, k, flat, dv, diag);
    }
    tirenv_profile_free(flat);
    if (status && !diag->file[0])
        snprintf(diag->file, sizeof diag->file, "%s", path);
    return status;
}

/* The note on the derived ring: its keys, how it was found, and its air. */
static void note_ring(tirenv_tir_origin *origin, const tirenv_tire *t, const mf_keys *k,
                      const derivation *dv)
{
    if (dv->lack & TIRENV_TIR_RING)
        note_add(origin, "%sno [ENVELOPING_RING]: derived TREAD_THICKNESS = %.4g, "
                 "BELT_BENDING_STIFFNESS = %.4g, BELT_PRETENSION = %.4g, "
                 "FOUNDATION_STIFFNESS = %.4g, TREAD_STIFFNESS = %.4g",
                 origin->note[0] ? "; " : "", t->ring.t_r, t->ring.EI, t->ring.T, t->ring.k_c,
                 t->ring.k_t);
    if (dv->on_laws && dv->lr.searched)
        note_add(origin, ", BELT_WIDTH = %.4g, CARCASS_SOFTENING_DEFLECTION = %.4g, "
                 "CARCASS_LINEAR_DEFLECTION = %.4g, TREAD_SHEAR = %.4g, NODE_ANGLE 0.25 deg: "
                 "searched on the file's own vertical and contact laws (%d ring tables; the "
                 "Winkler ring without them: cam against ring %.1f / %.1f %%)", t->ring.b_p,
                 t->ring.w_cs, t->ring.w_c0, t->ring.G_t, dv->lr.tables, 100 * dv->lr.w_defl,
                 100 * dv->lr.w_l);
    else if (dv->on_laws)
        note_add(origin, ": the Winkler ring, none found nearer the file's own vertical and "
                 "contact laws (%d ring tables searched: %s)", dv->lr.tables,
                 dv->lr.why[0] ? dv->lr.why : "its largest difference from the cam no smaller");
    if ((dv->lack & TIRENV_TIR_RING) && !(k->given & (MF_INFLPRES | MF_NOMPRES)))
        note_add(origin, ", its air at %.4g kPa, the default tire's INFLPRES (the file gives "
                 "no INFLPRES or NOMPRES)", t->ring.p / 1e3);
}

/* The note on the derived springs model (and its sidewall), or on its not being derived. */
static void note_springs(tirenv_tir_origin *origin, const tirenv_tire *t, const derivation *dv)
{
    if (dv->make & TIRENV_TIR_SPRINGS)
        note_add(origin, "%sno [ENVELOPING_SPRINGS]: derived RADIAL_STIFFNESS = %.4g, "
                 "INTERRADIAL_STIFFNESS = %.4g", origin->note[0] ? "; " : "", t->springs.c_r,
                 t->springs.c_b);
    else if (dv->unused)
        note_add(origin, "%sno [ENVELOPING_SPRINGS]: the springs model not derived (not used "
                 "here) and not this tire's", origin->note[0] ? "; " : "");
    if ((dv->make & TIRENV_TIR_SPRINGS) && t->springs.k_s > 0)
        note_add(origin, ", SIDEWALL_STIFFNESS = %.4g, SIDEWALL_PRELOAD = %.4g (a sidewall in "
                 "series, identified with them on the ring)", t->springs.k_s, t->springs.F_s0);
}

/* The note on the vertical law the models were derived on: Q_FZ2 derived or not, and the
 * deflection at FNOMIN. */
static void note_vertical(tirenv_tir_origin *origin, const tirenv_tire *t, const mf_keys *k,
                          const derivation *dv)
{
    if (dv->law.derive_q_fz2)
        note_add(origin, "; no Q_FZ2 of its own: derived on the ring Q_FZ2 = %.4g, "
                 "VERTICAL_STIFFNESS %.4g kN/m its tangent at FNOMIN", t->cam.q_fz2,
                 k->c_z / 1e3);
    if (dv->no_law[0])
        note_add(origin, "; no Q_FZ2 of its own and none derived, the file's linear law kept "
                 "(%s)", dv->no_law);
    if (dv->lack)
        note_add(origin, " (deflection %.4g mm at FNOMIN %.6g N: %sstiffness %.4g kN/m%s)",
                 origin->rho_nominal * 1e3, k->fnomin, dv->law.derive_q_fz2 ? "secant " : "",
                 k->fnomin / origin->rho_nominal / 1e3,
                 dv->law.factor != 1 ? ", PFZ1 at INFLPRES" : "");
}

/* text (len bytes) is the file as tirenv_tir_read read it, or NULL: read path again. */
static int derive(const char *path, const char *text, size_t len, tirenv_tire *tire,
                  unsigned need, tirenv_tir_origin *origin, tirenv_diag *diag)
{
    tirenv_tir_origin unread; /* a caller that does not ask where the values came from */
    if (!origin)
        origin = &unread;
    memset(origin, 0, sizeof *origin);
    origin->cam_ring_deflection = origin->cam_ring_contact_length = NAN;
    mf_keys k;
    memset(&k, 0, sizeof k);
    int status = text ? tirenv_propfile__read_text(&mf_schema, path, text, len, &k, diag)
                      : tirenv_propfile__read(&mf_schema, path, &k, diag);
    if (status)
        return status;
    const int own_law = take_own(&k, tire, origin);
    char law_said[sizeof origin->note / 2];
    law_note(tire, law_said, sizeof law_said);
    derivation dv;
    dv.lack = (TIRENV_TIR_SPRINGS | TIRENV_TIR_RING) & ~origin->own;
    /* A file with both enveloping sections and no cam contact law of its own: the cam's
     * derived on its ring where the file has what it takes; silently not, where it has not
     * (the cam then refuses naming Q_RA1). */
    const int cam_possible = (tire->cam.given & TIRENV_CAM_C_Z) != 0;
    if (!dv.lack && (origin->own & TIRENV_TIR_CAM))
        return derived(origin, law_said);
    const char *missing;
    dv.law.rho_n = origin->rho_nominal = nominal_deflection(&k, tire, &dv.law.factor, &missing);
    /* The cam's Q_FZ2 is identified on the ring where the ring is derived (so the two are
     * scaled together) and the file's law is VERTICAL_STIFFNESS alone (section 14.2). */
    dv.law.derive_q_fz2 = (dv.lack & TIRENV_TIR_RING) && cam_possible && !own_law &&
                          (k.given & MF_CZ);
    if (!dv.lack && (missing || !cam_possible))
        return derived(origin, law_said);
    /* The cam alone used (need TIRENV_TIR_ONLY | TIRENV_TIR_CAM) and every law of it the
     * file's own: nothing of the cam comes from a derived ring (Q_FZ2 is derived on the ring
     * only where the file has no law of its own), so the ring and the springs model the file
     * lacks are not derived (the ring's search on the laws is most of a read), and the note says
     * they are not this tire's. */
    if ((need & TIRENV_TIR_ONLY) && (need & TIRENV_TIR_CAM) && !(need & dv.lack) &&
        (origin->own & TIRENV_TIR_CAM) && !dv.law.derive_q_fz2) {
        note_cam_alone(origin, dv.lack, tire);
        return derived(origin, law_said);
    }
    if (missing) {
        if ((status = note_missing(path, need, dv.lack, missing, origin, diag)))
            return status;
        return derived(origin, law_said);
    }
    /* A file with a contact law of its own gets a ring searched on it (derive_on_laws). */
    dv.on_laws = (dv.lack & TIRENV_TIR_RING) && (origin->own & TIRENV_TIR_CAM);
    /* There the ring is searched on the laws alone, and the springs model then identified on
     * it: a caller that uses neither the springs model nor anything of it (need with
     * TIRENV_TIR_ONLY and without TIRENV_TIR_SPRINGS: the ring or the cam alone) has it not
     * derived, the same ring without the springs model's sidewall identification, which can
     * neither cost that command its time nor fail it. Elsewhere the ring's pretension is
     * chosen with the springs model (derive_ring_springs): both are derived as before. */
    dv.unused = dv.on_laws && (need & TIRENV_TIR_ONLY) && !(need & TIRENV_TIR_SPRINGS)
                    ? dv.lack & TIRENV_TIR_SPRINGS : 0u;
    dv.make = dv.lack & ~dv.unused;
    tirenv_tire t = *tire;
    if ((status = run_derivation(path, tire, &k, &dv, &t, diag)))
        return status;
    origin->derived = dv.make;
    if (dv.make == (TIRENV_TIR_SPRINGS | TIRENV_TIR_RING))
        origin->pretension_ratio = dv.tr.tau;
    if (dv.law.derive_q_fz2) {
        origin->rho_nominal = dv.tr.rho_n;
        t.cam.q_fz2 = dv.tr.q_fz2;
        origin->derived |= TIRENV_TIR_VERTICAL;
    }
    note_ring(origin, &t, &k, &dv);
    note_springs(origin, &t, &dv);
    note_vertical(origin, &t, &k, &dv);
    if (cam_possible)
        cam_part(&t, &k, dv.have_ring ? &dv.tr.ring : NULL, !(origin->own & TIRENV_TIR_CAM),
                 origin);
    *tire = t;
    return derived(origin, law_said);
}

int tirenv_tir_derive(const char *path, tirenv_tire *tire, unsigned need,
                      tirenv_tir_origin *origin, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    const tirenv_tire read = *tire;
    const int status = derive(path, NULL, 0, tire, need, origin, diag);
    if (status)
        *tire = read;
    return status;
}

/* Both passes on the bytes of one read: a pipe, /dev/stdin or a process substitution has no
 * second read to give (the second open of a FIFO waits for a writer that has gone). */
int tirenv_tir_read_derive(const char *path, tirenv_tire *tire, unsigned need,
                           tirenv_tir_origin *origin, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    tirenv_tire t = *tire;
    char *text = NULL;
    size_t len = 0;
    int status = tirenv_tir__read_kept(path, &t, &text, &len, diag);
    if (!status)
        status = derive(path, text, len, &t, need, origin, diag);
    free(text);
    if (!status)
        *tire = t;
    return status;
}

/* The springs model stands in only where a regime is a contact length the model cannot turn
 * into a load itself: the caller knows that, not the type (tir.h). */
unsigned tirenv_tir_need(const tirenv_model_type *type, int alone)
{
    if (type == tirenv_model_ring)
        return TIRENV_TIR_RING | (alone ? TIRENV_TIR_ONLY : 0u);
    if (type == tirenv_model_springs)
        return TIRENV_TIR_SPRINGS;
    if (type == tirenv_model_cam)
        return TIRENV_TIR_CAM | (alone ? TIRENV_TIR_ONLY : 0u);
    return 0;
}
