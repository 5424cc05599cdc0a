/* SPDX-License-Identifier: Apache-2.0 */
/* A tire file's enveloping models derived from its MF-Tyre keys (docs/models.md section 14):
 * the file is read a second time with a schema of the MF-Tyre keys that describe the tire's
 * vertical behaviour, and the springs and ring models a file has no section for are scaled
 * to the file's deflection at its nominal load. */
#include "formats/flat_inverse.h"
#include "formats/propfile.h"
#include "tirenv/cam.h"
#include "tirenv/tir.h"
#include "tirenv/model.h"
#include "tirenv/springs.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

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
    OWN("ENVELOPING_RING", "TREAD_THICKNESS", MF_RING),
    OWN("ENVELOPING_RING", "BELT_BENDING_STIFFNESS", MF_RING),
    OWN("ENVELOPING_RING", "BELT_PRETENSION", MF_RING),
    OWN("ENVELOPING_RING", "FOUNDATION_STIFFNESS", MF_RING),
    OWN("ENVELOPING_RING", "TREAD_STIFFNESS", MF_RING),
    OWN("ENVELOPING_RING", "TREAD_SHEAR", MF_RING),
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

/* The file's deflection at FNOMIN (m), by MF-Tyre's vertical law at standstill,
 *   F_z = (1 + PFZ1*dp) * (Q_FZ1*rho/R0 + Q_FZ2*(rho/R0)^2) * FNOMIN,  dp = (p - p0)/p0,
 * with Q_FZ1 = sqrt((VERTICAL_STIFFNESS*R0/FNOMIN)^2 - 4*Q_FZ2) where the file gives none,
 * which makes VERTICAL_STIFFNESS the tangent stiffness at FNOMIN (and, with Q_FZ2 = 0, the
 * law linear: rho = FNOMIN/VERTICAL_STIFFNESS). Q_V1, Q_V2 are speed terms, and the enveloping
 * models are quasi-static. 0 with the missing key in *missing. */
static double nominal_deflection(const mf_keys *k, double *factor, const char **missing)
{
    *factor = 1;
    *missing = !(k->given & MF_R0) ? "UNLOADED_RADIUS"
               : !(k->given & MF_FNOMIN) ? "FNOMIN"
               : !(k->given & (MF_CZ | MF_QFZ1)) ? "VERTICAL_STIFFNESS" : NULL;
    if (*missing)
        return 0;
    if ((k->given & MF_PFZ1) && (k->given & MF_INFLPRES) && (k->given & MF_NOMPRES) &&
        k->nompres > 0)
        *factor = 1 + k->pfz1 * (k->inflpres - k->nompres) / k->nompres;
    const double q2 = k->given & MF_QFZ2 ? k->q_fz2 : 0;
    const double q1 = (k->given & MF_QFZ1) && k->q_fz1 != 0
                          ? k->q_fz1
                          : tirenv_cam_q_fz1(k->c_z, k->R0, k->fnomin, q2);
    /* q2 x^2 + q1 x = 1/factor, the root that grows from 0 with the load. */
    const double x = tirenv_cam_vertical_root(1, q1, q2, 1 / *factor);
    if (!(x > 0 && x < 1 && isfinite(x))) {
        *missing = "VERTICAL_STIFFNESS";
        return 0;
    }
    return x * k->R0;
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

/* Scales the stiffnesses stiff[] by one factor c so that the model carries FNOMIN at rho_n.
 * Where they make all of the load (springs) the load is proportional to c and one step is
 * exact; the ring's air (INFLPRES) carries a share that c does not scale, so c is found by a
 * secant on log c (the load grows monotonically with c), to 1e-8 of FNOMIN (ten times the flat
 * inversion's own tolerance on the deflection, 1e-9; the tests assert 1e-7). */
static int scale_to(const tirenv_model_type *type, tirenv_tire *t, double *const stiff[],
                    size_t n, double fnomin, double rho_n, tirenv_diag *diag)
{
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
        if (fabs(g1) <= 1e-8)
            return TIRENV_OK;
        const double u2 = g1 != g0 ? u1 - g1 * (u1 - u0) / (g1 - g0) : u1 - g1;
        u0 = u1, g0 = g1;
        u1 = fmax(u1 - 5, fmin(u1 + 5, u2));  /* at most a factor e^5 a step */
    }
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "VERTICAL_STIFFNESS",
                        "the %s model's stiffnesses found no scale carrying FNOMIN %g N at "
                        "the file's deflection %g m (its air alone may carry more)",
                        tirenv_model_type_name(type), fnomin, rho_n);
}

/* docs/models.md section 14.2: the springs model identified on the tire's ring (its own or the
 * derived one) as the default tire is on its own (tirenv_springs_identify): at 0.5 to 1.5
 * times FNOMIN it deflects as the ring does and touches as much ground; then c_r and c_b,
 * their ratio kept, are scaled to the file's deflection at FNOMIN (the load is proportional to
 * them together: one step). The segment and the elements are the default tire's. */
static int derive_springs(tirenv_tire *t, const mf_keys *k, double rho_n, tirenv_diag *diag)
{
    static const double fractions[] = {0.5, 0.75, 1.0, 1.25, 1.5};
    enum { N = sizeof fractions / sizeof fractions[0] };
    const tirenv_tire d = tirenv_tire_default();
    t->springs.c_r = d.springs.c_r;
    t->springs.c_b = d.springs.c_b;
    t->springs.phi = d.springs.phi;
    t->springs.dphi = d.springs.dphi;
    tirenv_model *ring = tirenv_model_alloc(tirenv_model_ring, t);
    if (!ring)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ring",
                            "the ring model of the tire is not valid, so the springs model "
                            "cannot be identified on it");
    double G[N], defl[N], l[N];
    int status = TIRENV_OK;
    for (size_t i = 0; i < N && !status; i++) {
        tirenv_flat f;
        G[i] = fractions[i] * k->fnomin;
        status = tirenv_model_flat(ring, G[i], &f, diag);
        defl[i] = f.deflection;
        l[i] = f.contact_length;
    }
    tirenv_model_free(ring);
    if (!status)
        status = tirenv_springs_identify(&t->springs, N, G, defl, l, diag);
    if (status)
        return status;
    double *const stiff[] = {&t->springs.c_r, &t->springs.c_b};
    return scale_to(tirenv_model_springs, t, stiff, 2, k->fnomin, rho_n, diag);
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

/* docs/models.md section 14.3: the default ring made similar: the tread in proportion to the
 * section height, the belt's length scales with R = R0 - t_r, EI/(k_f*R^4) and T/(k_f*R^2)
 * kept, then every stiffness scaled to the file's deflection at FNOMIN. */
static int derive_ring(tirenv_tire *t, const mf_keys *k, double rho_n, tirenv_diag *diag)
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
    double *const stiff[] = {&t->ring.EI, &t->ring.T, &t->ring.k_f, &t->ring.k_t};
    return scale_to(tirenv_model_ring, t, stiff, 4, k->fnomin, rho_n, diag);
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

int tirenv_tir_derive(const char *path, tirenv_tire *tire, unsigned need,
                      tirenv_tir_origin *origin, tirenv_diag *diag)
{
    memset(origin, 0, sizeof *origin);
    mf_keys k;
    memset(&k, 0, sizeof k);
    int status = tirenv_propfile__read(&mf_schema, path, &k, diag);
    if (status)
        return status;
    origin->own = (k.given & MF_SPRINGS ? TIRENV_TIR_SPRINGS : 0u) |
                  (k.given & MF_RING ? TIRENV_TIR_RING : 0u);
    origin->fnomin = k.given & MF_FNOMIN ? k.fnomin : 0;
    const unsigned lack = (TIRENV_TIR_SPRINGS | TIRENV_TIR_RING) & ~origin->own;
    if (!lack)
        return TIRENV_OK;
    double factor;
    const char *missing;
    const double rho_n = nominal_deflection(&k, &factor, &missing);
    origin->rho_nominal = rho_n;
    tirenv_tire t = *tire;
    /* The ring first: the springs model is identified on it. */
    static const struct { unsigned bit; const char *section, *model; } models[] = {
        {TIRENV_TIR_RING, "ENVELOPING_RING", "ring"},
        {TIRENV_TIR_SPRINGS, "ENVELOPING_SPRINGS", "springs"},
    };
    for (size_t i = 0; i < 2; i++) {
        if (!(lack & models[i].bit))
            continue;
        if (missing) {
            if (need & models[i].bit)
                return tirenv_error(diag, TIRENV_EINVAL, path, 0, missing,
                                    "the file has no [%s] and no %s to derive the %s model "
                                    "from (docs/models.md section 14)", models[i].section,
                                    missing, models[i].model);
            note_add(origin, "%sno [%s] and no %s: the %s model is not this tire's",
                     origin->note[0] ? "; " : "", models[i].section, missing, models[i].model);
            continue;
        }
        status = models[i].bit == TIRENV_TIR_SPRINGS ? derive_springs(&t, &k, rho_n, diag)
                                                      : derive_ring(&t, &k, rho_n, diag);
        if (status) {
            if (!diag->file[0])
                snprintf(diag->file, sizeof diag->file, "%s", path);
            return status;
        }
        origin->derived |= models[i].bit;
        if (models[i].bit == TIRENV_TIR_SPRINGS)
            note_add(origin, "%sno [ENVELOPING_SPRINGS]: derived RADIAL_STIFFNESS = %.4g, "
                     "INTERRADIAL_STIFFNESS = %.4g", origin->note[0] ? "; " : "",
                     t.springs.c_r, t.springs.c_b);
        else
            note_add(origin, "%sno [ENVELOPING_RING]: derived TREAD_THICKNESS = %.4g, "
                     "BELT_BENDING_STIFFNESS = %.4g, BELT_PRETENSION = %.4g, "
                     "FOUNDATION_STIFFNESS = %.4g, TREAD_STIFFNESS = %.4g",
                     origin->note[0] ? "; " : "", t.ring.t_r, t.ring.EI, t.ring.T, t.ring.k_f,
                     t.ring.k_t);
    }
    if (origin->derived)
        note_add(origin, " (deflection %.4g mm at FNOMIN %.6g N: stiffness %.4g kN/m%s)",
                 rho_n * 1e3, k.fnomin, k.fnomin / rho_n / 1e3,
                 factor != 1 ? ", PFZ1 at INFLPRES" : "");
    *tire = t;
    return TIRENV_OK;
}
