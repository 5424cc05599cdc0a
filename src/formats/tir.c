/* The .tir tire property file: reading (MF-Tyre files included), --set overrides, writing.
 * The syntax, messages and atomic writing are the property-file engine's (propfile.c); this
 * file says which keys a tire has and where they go.
 * SPDX-License-Identifier: Apache-2.0 */
#include "formats/propfile.h"
#include "formats/tir_impl.h"
#include "tirenv/tir.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include "io/io.h"

/* The engine stores a NAME as an int. */
_Static_assert(sizeof(tirenv_eq_method) == sizeof(int), "tirenv_eq_method must be int-sized");
_Static_assert(sizeof(tirenv_springs_contact) == sizeof(int),
               "tirenv_springs_contact must be int-sized");

/* A real value and its dimension as exponents of length, force and angle (the [UNITS] a
 * file states are converted to SI with them). */
#define TIR_REAL(sec, name, member, L, F, A, text)                                             \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_REAL,                            \
     .offset = offsetof(tirenv_tire, member), .comment = (text), .dim = {L, F, A}}
/* A real value written only where it is not 0 (absent and 0 mean the same: none). */
#define TIR_OPTIONAL(sec, name, member, L, F, A, text)                                         \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_REAL,                            \
     .offset = offsetof(tirenv_tire, member), .omit_zero = 1, .comment = (text),              \
     .dim = {L, F, A}}
/* A cam key: tracked in cam.given, for tirenv_tire_check_cam_keys. */
#define TIR_CAM(sec, name, member, L, F, A, bit, text)                                         \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_REAL,                            \
     .offset = offsetof(tirenv_tire, member), .comment = (text), .dim = {L, F, A},            \
     .given = (bit)}
#define TIR_COUNT(sec, name, member, text)                                                     \
    TIRENV_PROPFILE_KEY(tirenv_tire, sec, name, TIRENV_PROPFILE_COUNT, member, text)
#define TIR_METHOD(sec, name, member, text)                                                    \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_NAME,                            \
     .offset = offsetof(tirenv_tire, member), .comment = (text),                               \
     .names = {[TIRENV_EQ_NEWTON] = "newton", [TIRENV_EQ_SECANT] = "secant",                   \
               [TIRENV_EQ_BRENT] = "brent"},                                                   \
     .noun = "method"}
#define TIR_CONTACT(sec, name, member, text)                                                   \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_NAME,                            \
     .offset = offsetof(tirenv_tire, member), .comment = (text),                               \
     .names = {[TIRENV_SPRINGS_CONTINUOUS] = "continuous", [TIRENV_SPRINGS_RAYS] = "rays"},    \
     .noun = "contact"}

/* Every key tirenv reads, checks, accepts in --set and writes: one table instead of a chain of
 * string comparisons, so the reader, the writer and the error messages cannot drift apart. */
static const tirenv_propfile__key tir_keys[] = {
    TIRENV_PROPFILE_CONVERTED_UNITS,
    TIR_REAL("DIMENSION", "UNLOADED_RADIUS", springs.R0, 1, 0, 0,
             "R0: free (unloaded) tire radius, m"),
    TIR_REAL("DIMENSION", "WIDTH", width, 1, 0, 0,
             "tire width, m: the default spread of tracks across it"),
    TIR_CAM("VERTICAL", "VERTICAL_STIFFNESS", cam.c_z, -1, 1, 0, TIRENV_CAM_C_Z,
             "cam: load / static deflection, N/m; with Q_FZ2 the tangent at FNOMIN"),
    TIR_REAL("VERTICAL", "FNOMIN", cam.fnomin, 0, 1, 0,
             "nominal load, N: the load Q_FZ2 refers to (0: none)"),
    TIR_REAL("VERTICAL", "Q_FZ2", cam.q_fz2, 0, 0, 0,
             "cam: load = FNOMIN*(Q_FZ1*rho/R0 + Q_FZ2*(rho/R0)^2), 0: linear"),
    TIR_OPTIONAL("VERTICAL", "Q_FZ1", cam.q_fz1, 0, 0, 0,
                 "cam: the law's linear term; 0 or absent: from VERTICAL_STIFFNESS"),
    {.section = "VERTICAL", .key = "VERTICAL_DAMPING", .kind = TIRENV_PROPFILE_REAL,
     .offset = offsetof(tirenv_tire, k_z), .omit_nan = 1, .dim = {-1, 1, 0},
     .comment = "k_z: vertical damping, N*s/m: the ride's c_t without the vehicle's"},
    TIR_OPTIONAL("VERTICAL", "PFZ1", cam.pfz1, 0, 0, 0,
                 "cam: load times 1 + PFZ1*(INFLPRES - NOMPRES)/NOMPRES"),
    TIR_CAM("CONTACT_PATCH", "Q_RA1", cam.q_ra1, 0, 0, 0, TIRENV_CAM_Q_RA1,
             "cam: contact half length a = R0*(Q_RA2*rho/R0 + Q_RA1*sqrt(rho/R0))"),
    TIR_CAM("CONTACT_PATCH", "Q_RA2", cam.q_ra2, 0, 0, 0, TIRENV_CAM_Q_RA2,
             "cam: linear term of the contact half length"),
    TIR_CAM("CONTACT_PATCH", "ELLIPS_SHIFT", cam.shift, 0, 0, 0, TIRENV_CAM_SHIFT,
             "cam: tandem base l_s = ELLIPS_SHIFT*2a"),
    TIR_CAM("CONTACT_PATCH", "ELLIPS_LENGTH", cam.length, 0, 0, 0, TIRENV_CAM_LENGTH,
             "cam: half length a_e = ELLIPS_LENGTH*R0"),
    TIR_CAM("CONTACT_PATCH", "ELLIPS_HEIGHT", cam.height, 0, 0, 0, TIRENV_CAM_HEIGHT,
             "cam: half height b_e = ELLIPS_HEIGHT*R0"),
    TIR_CAM("CONTACT_PATCH", "ELLIPS_ORDER", cam.order, 0, 0, 0, TIRENV_CAM_ORDER,
             "cam: super-ellipse exponent c_e, > 1"),
    TIR_OPTIONAL("CONTACT_PATCH", "ELLIPS_MAX_STEP", cam.max_step, 1, 0, 0,
                 "cam: highest road step its shape is meant for, m; above, a warning (0: none)"),
    TIR_REAL("ENVELOPING_SPRINGS", "RADIAL_STIFFNESS", springs.c_r, -1, 1, -1,
             "c_r: radial stiffness per radian of tread, N/m/rad"),
    TIR_REAL("ENVELOPING_SPRINGS", "INTERRADIAL_STIFFNESS", springs.c_b, -1, 1, 1,
             "c_b: interradial (bending) stiffness, N*rad/m"),
    TIR_REAL("ENVELOPING_SPRINGS", "SEGMENT_ANGLE", springs.phi, 0, 0, 1,
             "phi: width of the modelled tread segment, rad"),
    TIR_REAL("ENVELOPING_SPRINGS", "ELEMENT_ANGLE", springs.dphi, 0, 0, 1,
             "dphi: angle between adjacent radial elements, rad"),
    TIR_CONTACT("ENVELOPING_SPRINGS", "CONTACT", springs.contact,
             "'continuous': a tread between the elements; 'rays': the paper's"),
    TIR_OPTIONAL("ENVELOPING_SPRINGS", "SIDEWALL_STIFFNESS", springs.k_s, -1, 1, 0,
                 "k_s: sidewall spring in series with the elements, N/m; 0 or absent: none"),
    TIR_OPTIONAL("ENVELOPING_SPRINGS", "SIDEWALL_PRELOAD", springs.F_s0, 0, 1, 0,
                 "F_s0: load the sidewall carries before it gives, N (0: linear)"),
    TIR_REAL("ENVELOPING_RING", "TREAD_THICKNESS", ring.t_r, 1, 0, 0,
             "t_r: tread layer between belt and ground, m"),
    TIR_REAL("ENVELOPING_RING", "BELT_BENDING_STIFFNESS", ring.EI, 2, 1, 0,
             "EI: bending stiffness of the belt, N*m^2"),
    TIR_REAL("ENVELOPING_RING", "BELT_PRETENSION", ring.T, 0, 1, 0,
             "T: belt tension beyond the air's p*b*R, N"),
    TIR_REAL("ENVELOPING_RING", "FOUNDATION_STIFFNESS", ring.k_c, -2, 1, 0,
             "k_c: the carcass's own foundation per unit belt length (the air's added), N/m^2"),
    TIR_REAL("ENVELOPING_RING", "TREAD_STIFFNESS", ring.k_t, -2, 1, 0,
             "k_t: tread compression stiffness per unit belt length, N/m^2"),
    TIR_REAL("ENVELOPING_RING", "TREAD_SHEAR", ring.G_t, -2, 1, 0,
             "G_t: tread rubber shear modulus, Pa (0: a Winkler tread)"),
    TIR_REAL("ENVELOPING_RING", "NODE_ANGLE", ring.dtheta, 0, 0, 1,
             "dtheta: node spacing around the full circle, rad"),
    TIR_REAL("ENVELOPING_RING", "LUG_COUNT", ring.lug_count, 0, 0, 0,
             "lugs around the circumference; 0 = smooth tread"),
    TIR_REAL("ENVELOPING_RING", "LUG_FRACTION", ring.lug_fraction, 0, 0, 0,
             "share of the circumference under lugs"),
    TIR_REAL("ENVELOPING_RING", "LUG_GROOVE_RATIO", ring.lug_ratio, 0, 0, 0,
             "tread stiffness between lugs / on lugs"),
    TIR_REAL("ENVELOPING_RING", "BELT_WIDTH", ring.b_p, 1, 0, 0,
             "b: width of the crown the air presses on, m"),
    TIR_REAL("ENVELOPING_RING", "SIDEWALL_ANGLE", ring.alpha_s, 0, 0, 1,
             "alpha: half angle of a sidewall's membrane arc, rad"),
    TIR_OPTIONAL("ENVELOPING_RING", "CARCASS_SOFTENING_DEFLECTION", ring.w_cs, 1, 0, 0,
                 "w_s: carcass force k_c*(w_0 + w_s*(1 - exp(-(w - w_0)/w_s))) beyond w_0, m; "
                 "0: linear"),
    TIR_OPTIONAL("ENVELOPING_RING", "CARCASS_LINEAR_DEFLECTION", ring.w_c0, 1, 0, 0,
                 "w_0: belt deflection up to which the carcass is linear, k_c*w, m"),
    {.section = "ENVELOPING_RING", .key = "CONTACT", .kind = TIRENV_PROPFILE_NAME,
     .offset = offsetof(tirenv_tire, ring.contact),
     .comment = "tread on the ground: 'continuous' between nodes, or 'rays' (one per node)",
     .names = {[TIRENV_RING_CONTINUOUS] = "continuous", [TIRENV_RING_RAYS] = "rays"},
     .noun = "contact"},
    TIR_REAL("OPERATING_CONDITIONS", "INFLPRES", ring.p, -2, 1, 0,
             "p: inflation pressure, Pa (the ring reference tire's air)"),
    TIR_REAL("OPERATING_CONDITIONS", "NOMPRES", ring.p_nom, -2, 1, 0,
             "nominal inflation pressure, Pa (MF-Tyre's; the cam's pressure law refers to it)"),
    TIR_METHOD("ENVELOPING_SOLVER", "METHOD", eq.method,
             "equilibrium iteration: 'newton', 'secant' or 'brent'"),
    TIR_REAL("ENVELOPING_SOLVER", "FORCE_TOLERANCE", eq.eps_F, 0, 1, 0,
             "eps_F: converged when |F_z - G_T| <= eps_F, N"),
    TIR_REAL("ENVELOPING_SOLVER", "STEP_TOLERANCE", eq.eps_z, 1, 0, 0,
             "eps_z: converged also needs the last step |dz| <= eps_z, m"),
    TIR_COUNT("ENVELOPING_SOLVER", "MAX_ITERATIONS", eq.max_iter,
             "force evaluations allowed per position"),
    TIR_REAL("ENVELOPING_SOLVER", "SECANT_STEP", eq.secant_dz, 1, 0, 0,
             "secant only: offset of the second starting point, m"),
};

/* The sections tirenv reads. In a strict section an unknown key is a typo and an error; in
 * [DIMENSION], [VERTICAL] and [CONTACT_PATCH], which tirenv shares with MF-Tyre, the keys of
 * the other models (FNOMIN, Q_RB1...) are skipped. Any other section is skipped whole,
 * unless its name starts with ENVELOPING_: those are tirenv's own, and an unknown one is a
 * typo, not MF-Tyre. */
static const tirenv_propfile__section tir_sections[] = {
    {"UNITS", 1},
    {"DIMENSION", 0},
    {"VERTICAL", 0},
    {"CONTACT_PATCH", 0},
    {"OPERATING_CONDITIONS", 0},
    {"ENVELOPING_SPRINGS", 1},
    {"ENVELOPING_RING", 1},
    {"ENVELOPING_SOLVER", 1},
};

static int tir_check(const void *tire, tirenv_diag *diag)
{
    return tirenv_tire_check(tire, diag);
}

static void tir_preamble(FILE *fp)
{
    fprintf(fp, "[MDI_HEADER]\n"
                "FILE_TYPE                = 'tir'\n"
                "FILE_VERSION             = 3.0\n"
                "FILE_FORMAT              = 'ASCII'\n"
                "! Tire property file written by tirenv %s for its enveloping models.\n"
                "! SI units; '$' starts a comment. Sections that tirenv does not know are\n"
                "! skipped, so the MF-Tyre sections of the same tire may be added below\n"
                "! (without the keys written here: each key may appear once).\n",
            TIRENV_VERSION);
}

static const tirenv_propfile__schema tir_schema = {
    .keys = tir_keys,
    .n_keys = sizeof tir_keys / sizeof tir_keys[0],
    .sections = tir_sections,
    .n_sections = sizeof tir_sections / sizeof tir_sections[0],
    .own_prefix = "ENVELOPING_",
    .first_section = "MDI_HEADER",
    .size = sizeof(tirenv_tire),
    .check = tir_check,
    .preamble = tir_preamble,
    .given_offset = offsetof(tirenv_tire, cam.given),
    .given_mask = TIRENV_CAM_ALL,
};

/* A file without WIDTH leaves it 0, not the width of the tire it was read over: a car tire's
 * file must not inherit the tractor's 0.38 m. A file without VERTICAL_DAMPING leaves it NAN
 * (none), not the tractor's 3000 N*s/m: the ride then asks the vehicle for TIRE_DAMPING.
 * Likewise FNOMIN, Q_FZ2, Q_FZ1 and PFZ1: a file without them has a linear vertical law from
 * its VERTICAL_STIFFNESS and no pressure term, not the law of the tire it was read over; and
 * NOMPRES, which only PFZ1's factor reads: a file with PFZ1 and no NOMPRES is refused (tire
 * check), not given the tractor's 1.2 bar. */
int tirenv_tir_read(const char *path, tirenv_tire *tire, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_tir__read_kept(path, tire, NULL, NULL, diag);
}

int tirenv_tir__read_kept(const char *path, tirenv_tire *tire, char **text, size_t *len,
                          tirenv_diag *diag)
{
    const double width = tire->width;
    const tirenv_cam_params cam = tire->cam;
    const double p_nom = tire->ring.p_nom, k_z = tire->k_z;
    tire->width = 0;
    tire->k_z = NAN;
    tire->ring.p_nom = 0;
    tire->cam.fnomin = 0;
    tire->cam.q_fz2 = 0;
    tire->cam.q_fz1 = 0;
    tire->cam.pfz1 = 0;
    const int status = tirenv_propfile__read_kept(&tir_schema, path, tire, text, len, diag);
    if (status) {
        tire->width = width;
        tire->ring.p_nom = p_nom;
        tire->k_z = k_z;
        tire->cam = cam; /* a failed read changed only the fields zeroed above */
    }
    return status;
}

/* "KEY=VALUE" or "SECTION.KEY=VALUE", for the keys that set a parameter (not [UNITS]). */
int tirenv_tir_set(tirenv_tire *tire, const char *assignment, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_propfile__set(&tir_schema, tire, assignment, diag);
}

const char *tirenv_tir_key(size_t i, const char **section)
{
    return tirenv_propfile__key_at(&tir_schema, i, section);
}

int tirenv_tir_get(const tirenv_tire *tire, const char *key, char *buf, size_t n,
                   tirenv_tir_kind *kind, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    tirenv_propfile__kind k = TIRENV_PROPFILE_REAL;
    if (buf && n)
        buf[0] = '\0';  /* a refusal leaves no text a caller might take for the value */
    if (!tire)
        return tirenv_error(diag, TIRENV_EINVAL, "get", 0, key ? key : "", "no tire (NULL)");
    const int status = tirenv_propfile__get(&tir_schema, tire, key, buf, n, &k, diag);
    if (!status && kind)
        *kind = k == TIRENV_PROPFILE_COUNT ? TIRENV_TIR_COUNT
              : k == TIRENV_PROPFILE_NAME  ? TIRENV_TIR_NAME
                                           : TIRENV_TIR_REAL;
    return status;
}

/* A tire that fails tirenv_tire_check is refused: its file could not be read back. */
int tirenv_tir_write(const char *path, const tirenv_tire *tire, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_propfile__write(&tir_schema, path, tire, diag);
}

/* The header names no tirenv version, so that a data set's tire.tir stays the same bytes
 * from one version to the next as long as the tire does. */
int tirenv_tir_write_noted(const char *path, const tirenv_tire *tire, const char *note,
                           tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    char header[2048];
    size_t n = (size_t)snprintf(header, sizeof header,
                                "[MDI_HEADER]\n"
                                "FILE_TYPE                = 'tir'\n"
                                "FILE_VERSION             = 3.0\n"
                                "FILE_FORMAT              = 'ASCII'\n");
    /* Each line of the note as a '!' comment line. */
    for (const char *p = note; p && *p && n < sizeof header;) {
        const char *end = strchr(p, '\n');
        const size_t len = end ? (size_t)(end - p) : strlen(p);
        n += (size_t)snprintf(header + n, sizeof header - n, "! %.*s\n", (int)len, p);
        p = end ? end + 1 : p + len;
    }
    if (n >= sizeof header)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "", "the note is too long");
    return tirenv_propfile__write_headed(&tir_schema, path, tire, header, diag);
}
