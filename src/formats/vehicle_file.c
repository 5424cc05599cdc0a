/* The vehicle property file (.veh, docs/formats.md section 3): the .tir syntax through the
 * property-file engine, with the keys of data/vehicles/tractor.veh.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/vehicle_file.h"

#include "formats/propfile.h"
#include "tirenv/version.h"  /* TIRENV_VERSION, written into the file */

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include "io/io.h"

/* Each key's bit (b) in the record of the keys a file sets, which tirenv_vehicle_read_unset
 * keeps (veh_given_schema); tirenv_vehicle_read's schema keeps none. */
#define VEH_REAL(sec, name, member, text, b)                                                   \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_REAL,                            \
     .offset = offsetof(tirenv_vehicle, member), .comment = (text), .given = 1u << (b)}

/* A tire key the file may leave out: then NAN, the tire file's (tirenv_vehicle_tires), and
 * not written back. */
#define VEH_TIRE(sec, name, member, text, b)                                                   \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_REAL,                            \
     .offset = offsetof(tirenv_vehicle, member), .comment = (text), .omit_nan = 1,            \
     .given = 1u << (b)}

/* The same seven keys in each axle's section, bits b to b + 6. */
#define VEH_AXLE(sec, axle, b)                                                                 \
    {.section = (sec), .key = "TIRE_FILE", .kind = TIRENV_PROPFILE_PATH,                       \
     .offset = offsetof(tirenv_vehicle, axle.tire_file),                                       \
     .size = sizeof(((tirenv_vehicle *)NULL)->axle.tire_file),                                 \
     .comment = ".tir file of the tires, relative to this file; '' = built-in default",       \
     .given = 1u << (b)},                                                                      \
    VEH_REAL(sec, "TIRES", axle.tires, "tires on the axle (4 with duals)", (b) + 1),           \
    VEH_TIRE(sec, "TIRE_STIFFNESS", axle.k_t,                                                  \
             "k_t: vertical stiffness of one tire, N/m; absent: the tire file's at its load",  \
             (b) + 2),                                                                         \
    VEH_TIRE(sec, "TIRE_DAMPING", axle.c_t,                                                    \
             "c_t: vertical damping of one tire, N*s/m; absent: its VERTICAL_DAMPING",         \
             (b) + 3),                                                                         \
    VEH_REAL(sec, "SUSPENSION_STIFFNESS", axle.k_s, "k_s: suspension, N/m; 0 = rigid axle",    \
             (b) + 4),                                                                         \
    VEH_REAL(sec, "SUSPENSION_DAMPING", axle.c_s, "c_s: suspension damping, N*s/m", (b) + 5),  \
    VEH_REAL(sec, "AXLE_MASS", axle.m_a, "m_a: unsprung axle mass if suspended, kg", (b) + 6)

/* The keys' bits: the body's and the seat's, then each axle's seven from its first. */
enum {
    B_MASS, B_PITCH_INERTIA, B_CG_TO_FRONT, B_CG_TO_REAR, B_GRAVITY, B_SEAT_AHEAD, B_SEAT_ABOVE,
    B_FRONT_AXLE, B_REAR_AXLE = B_FRONT_AXLE + 7, B_END = B_REAR_AXLE + 7
};
_Static_assert(B_END <= 31, "a key's bit must fit the record (and VEH_ALL an int)");
/* All of them, and those of the optional tire keys (TIRE_STIFFNESS, TIRE_DAMPING: an axle's
 * bits 2 and 3). */
enum {
    VEH_ALL = (int)((1ull << B_END) - 1),
    VEH_OPTIONAL = 3 << (B_FRONT_AXLE + 2) | 3 << (B_REAR_AXLE + 2)
};

/* Every key, in the order written; [UNITS] MASS and [BODY] MASS are told apart by section. */
static const tirenv_propfile__key veh_keys[] = {
    TIRENV_PROPFILE_SI_UNITS,
    VEH_REAL("BODY", "MASS", m, "m: body mass (with a rigid front axle), kg", B_MASS),
    VEH_REAL("BODY", "PITCH_INERTIA", I_y, "I_y: pitch moment of inertia about the CG, kg*m^2",
             B_PITCH_INERTIA),
    VEH_REAL("BODY", "CG_TO_FRONT_AXLE", a, "a: CG to front axle, horizontal, m",
             B_CG_TO_FRONT),
    VEH_REAL("BODY", "CG_TO_REAR_AXLE", b, "b: CG to rear axle, horizontal, m", B_CG_TO_REAR),
    VEH_REAL("BODY", "GRAVITY", g, "g: gravitational acceleration, m/s^2", B_GRAVITY),
    VEH_REAL("SEAT", "SEAT_AHEAD_OF_CG", seat_x, "seat point ahead of the CG (< 0: behind), m",
             B_SEAT_AHEAD),
    VEH_REAL("SEAT", "SEAT_ABOVE_CG", seat_h, "seat point above the CG, m", B_SEAT_ABOVE),
    VEH_AXLE("FRONT_AXLE", front, B_FRONT_AXLE),
    VEH_AXLE("REAR_AXLE", rear, B_REAR_AXLE),
};

/* All tirenv's own: no other program shares this format, so every unknown section or key is
 * a typo. */
static const tirenv_propfile__section veh_sections[] = {
    {"UNITS", 1}, {"BODY", 1}, {"SEAT", 1}, {"FRONT_AXLE", 1}, {"REAR_AXLE", 1},
};

static int veh_check(const void *v, tirenv_diag *diag)
{
    return tirenv_vehicle_check(v, diag);
}

static void veh_preamble(FILE *fp)
{
    fprintf(fp, "! Vehicle property file written by tirenv %s for its ride simulation: a\n"
                "! tractor in the pitch plane. SI units; '$' starts a comment. A relative\n"
                "! TIRE_FILE is relative to this file's directory.\n",
            TIRENV_VERSION);
}

/* The schema's fields but its struct's size and the given bits' place. */
#define VEH_SCHEMA                                                                             \
    .keys = veh_keys, .n_keys = sizeof veh_keys / sizeof veh_keys[0], .sections = veh_sections, \
    .n_sections = sizeof veh_sections / sizeof veh_sections[0], .own_prefix = "",              \
    .first_section = "UNITS", .check = veh_check, .preamble = veh_preamble

static const tirenv_propfile__schema veh_schema = {VEH_SCHEMA, .size = sizeof(tirenv_vehicle)};

/* A vehicle with the record of the keys a file sets (the keys' bits, VEH_ALL). */
typedef struct {
    tirenv_vehicle v;  /* first: the keys' offsets are into it */
    unsigned given;
} vehicle_given;

static const tirenv_propfile__schema veh_given_schema = {
    VEH_SCHEMA, .size = sizeof(vehicle_given), .given_offset = offsetof(vehicle_given, given),
    .given_mask = VEH_ALL};

/* The file read by schema s over obj, whose vehicle is *v. A file without TIRE_STIFFNESS or
 * TIRE_DAMPING leaves them NAN (the tire file's) and no law, not the values of the vehicle it
 * was read over: another TIRE_FILE must not keep the old tire's. */
static int read_over(const tirenv_propfile__schema *s, const char *path, void *obj,
                     tirenv_vehicle *v, tirenv_diag *diag)
{
    const tirenv_axle front = v->front, rear = v->rear;
    v->front.k_t = v->front.c_t = v->rear.k_t = v->rear.c_t = NAN;
    v->front.law = v->rear.law = (tirenv_cam_vertical){0};
    const int status = tirenv_propfile__read(s, path, obj, diag);
    if (status) {
        v->front = front;
        v->rear = rear;
    }
    return status;
}

int tirenv_vehicle_read(const char *path, tirenv_vehicle *v, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (!v)
        return tirenv_propfile__read(&veh_schema, path, v, diag);
    return read_over(&veh_schema, path, v, v, diag);
}

int tirenv_vehicle_read_unset(const char *path, tirenv_vehicle *v, char *unset, size_t n,
                              tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (unset && n)
        unset[0] = '\0';
    if (!v)
        return tirenv_propfile__read(&veh_schema, path, v, diag);
    vehicle_given g = {.v = *v, .given = 0};
    const int status = read_over(&veh_given_schema, path, &g, &g.v, diag);
    if (status)
        return status;
    *v = g.v;
    size_t used = 0;
    for (size_t i = 0; unset && i < veh_given_schema.n_keys; ++i) {
        const tirenv_propfile__key *k = &veh_keys[i];
        if (!k->given || (k->given & (g.given | VEH_OPTIONAL)) || used >= n)
            continue;
        const int w = snprintf(unset + used, n - used, "%s%s.%s", used ? ", " : "", k->section,
                               k->key);
        used = w < 0 ? n : used + (size_t)w;
    }
    if (unset && n && used >= n) /* cut: said so rather than ending mid-name */
        snprintf(unset + (n > 4 ? n - 4 : 0), n > 4 ? 4 : n, "...");
    return TIRENV_OK;
}

int tirenv_vehicle_set(tirenv_vehicle *v, const char *assignment, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_propfile__set(&veh_schema, v, assignment, diag);
}

int tirenv_vehicle_write(const char *path, const tirenv_vehicle *v, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_propfile__write(&veh_schema, path, v, diag);
}
