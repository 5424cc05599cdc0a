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

#define VEH_REAL(sec, name, member, text)                                                      \
    TIRENV_PROPFILE_KEY(tirenv_vehicle, sec, name, TIRENV_PROPFILE_REAL, member, text)

/* A tire key the file may leave out: then NAN, the tire file's (tirenv_vehicle_tires), and
 * not written back. */
#define VEH_TIRE(sec, name, member, text)                                                      \
    {.section = (sec), .key = (name), .kind = TIRENV_PROPFILE_REAL,                            \
     .offset = offsetof(tirenv_vehicle, member), .comment = (text), .omit_nan = 1}

/* The same seven keys in each axle's section. */
#define VEH_AXLE(sec, axle)                                                                    \
    {.section = (sec), .key = "TIRE_FILE", .kind = TIRENV_PROPFILE_PATH,                       \
     .offset = offsetof(tirenv_vehicle, axle.tire_file),                                       \
     .size = sizeof(((tirenv_vehicle *)NULL)->axle.tire_file),                                 \
     .comment = ".tir file of the tires, relative to this file; '' = built-in default"},       \
    VEH_REAL(sec, "TIRES", axle.tires, "tires on the axle (4 with duals)"),                    \
    VEH_TIRE(sec, "TIRE_STIFFNESS", axle.k_t,                                                  \
             "k_t: vertical stiffness of one tire, N/m; absent: the tire file's at its load"), \
    VEH_TIRE(sec, "TIRE_DAMPING", axle.c_t,                                                    \
             "c_t: vertical damping of one tire, N*s/m; absent: its VERTICAL_DAMPING"),        \
    VEH_REAL(sec, "SUSPENSION_STIFFNESS", axle.k_s, "k_s: suspension, N/m; 0 = rigid axle"),   \
    VEH_REAL(sec, "SUSPENSION_DAMPING", axle.c_s, "c_s: suspension damping, N*s/m"),           \
    VEH_REAL(sec, "AXLE_MASS", axle.m_a, "m_a: unsprung axle mass if suspended, kg")

/* Every key, in the order written; [UNITS] MASS and [BODY] MASS are told apart by section. */
static const tirenv_propfile__key veh_keys[] = {
    TIRENV_PROPFILE_SI_UNITS,
    VEH_REAL("BODY", "MASS", m, "m: body mass (with a rigid front axle), kg"),
    VEH_REAL("BODY", "PITCH_INERTIA", I_y, "I_y: pitch moment of inertia about the CG, kg*m^2"),
    VEH_REAL("BODY", "CG_TO_FRONT_AXLE", a, "a: CG to front axle, horizontal, m"),
    VEH_REAL("BODY", "CG_TO_REAR_AXLE", b, "b: CG to rear axle, horizontal, m"),
    VEH_REAL("BODY", "GRAVITY", g, "g: gravitational acceleration, m/s^2"),
    VEH_REAL("SEAT", "SEAT_AHEAD_OF_CG", seat_x, "seat point ahead of the CG (< 0: behind), m"),
    VEH_REAL("SEAT", "SEAT_ABOVE_CG", seat_h, "seat point above the CG, m"),
    VEH_AXLE("FRONT_AXLE", front),
    VEH_AXLE("REAR_AXLE", rear),
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

static const tirenv_propfile__schema veh_schema = {
    .keys = veh_keys,
    .n_keys = sizeof veh_keys / sizeof veh_keys[0],
    .sections = veh_sections,
    .n_sections = sizeof veh_sections / sizeof veh_sections[0],
    .own_prefix = "",
    .first_section = "UNITS",
    .size = sizeof(tirenv_vehicle),
    .check = veh_check,
    .preamble = veh_preamble,
};

/* A file without TIRE_STIFFNESS or TIRE_DAMPING leaves them NAN (the tire file's) and no
 * law, not the values of the vehicle it was read over: another TIRE_FILE must not keep the
 * old tire's. */
int tirenv_vehicle_read(const char *path, tirenv_vehicle *v, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (!v)
        return tirenv_propfile__read(&veh_schema, path, v, diag);
    const tirenv_axle front = v->front, rear = v->rear;
    v->front.k_t = v->front.c_t = v->rear.k_t = v->rear.c_t = NAN;
    v->front.law = v->rear.law = (tirenv_cam_vertical){0};
    const int status = tirenv_propfile__read(&veh_schema, path, v, diag);
    if (status) {
        v->front = front;
        v->rear = rear;
    }
    return status;
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
