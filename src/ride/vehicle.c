/* The pitch-plane tractor of the ride simulation (docs/models.md section 9): its default, its
 * physical check and its static tire loads. The file format is in vehicle_file.c.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/vehicle.h"
#include "ride/ride_impl.h"
#include "tirenv/cam.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The values of data/vehicles/tractor.veh, where each is explained; a test keeps them equal.
 * Its tires are springs and dampers of their own tire file (tirenv_vehicle_tires). */
tirenv_vehicle tirenv_vehicle_default(void)
{
    const tirenv_axle axle = {.tire_file = "", .tires = 2, .k_t = NAN, .c_t = NAN,
                              .k_s = 0, .c_s = 0, .m_a = 400};
    return (tirenv_vehicle){.m = 4500, .I_y = 5000, .a = 1.45, .b = 0.95, .seat_x = -0.75,
                            .seat_h = 1.2, .front = axle, .rear = axle, .g = 9.81};
}

/* value > 0 (or >= 0 if zero_ok), and finite; the error names field and unit. */
static int vehicle_require(const char *field, double value, int zero_ok, const char *unit,
                           tirenv_diag *diag)
{
    if (isfinite(value) && (value > 0 || (zero_ok && value == 0)))
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, field, "must be %s (%s), got %g",
                        zero_ok ? "zero or positive" : "positive", unit, value);
}

/* Where a value is plausible for a vehicle, from a garden tractor's to a mining truck's, as
 * docs/formats.md section 3 lists with each range's reason: a value outside is a typo or a
 * unit slip (MASS = 1e9 gave seat accelerations of 2.4e9 m/s^2). */
static int vehicle_plausible(const char *field, double value, double lo, double hi,
                             const char *unit, tirenv_diag *diag)
{
    if (value >= lo && value <= hi)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, field,
                        "%g %s is outside the plausible range [%g, %g] %s of a vehicle "
                        "(docs/formats.md section 3)", value, unit, lo, hi, unit);
}

/* An axle's field is named SECTION.KEY, as --set accepts it: the bare key is in both axle
 * sections. */
static const char *axle_field(char f[64], const char *section, const char *key)
{
    snprintf(f, 64, "%s.%s", section, key);
    return f;
}

static int vehicle_check_axle(const tirenv_axle *ax, const char *section, int rear,
                              tirenv_diag *diag)
{
    char f[64];
#define FIELD(key) axle_field(f, section, key)
    if (!memchr(ax->tire_file, '\0', sizeof ax->tire_file))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, FIELD("TIRE_FILE"),
                            "is not terminated within its %zu bytes", sizeof ax->tire_file);
    /* The file format has no escapes (docs/formats.md section 3): a path holding a quote or a
     * line break could be read, but never written back. */
    if (strpbrk(ax->tire_file, "'\n\r"))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, FIELD("TIRE_FILE"),
                            "path \"%.60s\" holds a quote or a line break, which a vehicle "
                            "file cannot hold; expected a path in single quotes, such as "
                            "'tires/default.tir'", ax->tire_file);
    int status;
    if (!(ax->tires >= 1 && ax->tires == floor(ax->tires) && isfinite(ax->tires)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, FIELD("TIRES"),
                            "must be a whole number of tires, at least 1, got %g", ax->tires);
    /* NAN: the tire file's, which tirenv_vehicle_tires sets. */
    if ((!isnan(ax->k_t) &&
         (status = vehicle_require(FIELD("TIRE_STIFFNESS"), ax->k_t, 0, "N/m", diag))) ||
        (!isnan(ax->c_t) &&
         (status = vehicle_require(FIELD("TIRE_DAMPING"), ax->c_t, 1, "N*s/m", diag))))
        return status;
    /* The ride model has no rear suspension: a value here would be silently ignored. */
    if (rear && ax->k_s != 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, FIELD("SUSPENSION_STIFFNESS"),
                            "must be 0: a tractor's rear axle is rigid here (the ride model "
                            "has no rear suspension), got %g", ax->k_s);
    if ((status = vehicle_require(FIELD("SUSPENSION_STIFFNESS"), ax->k_s, 1, "N/m", diag)) ||
        (status = vehicle_require(FIELD("SUSPENSION_DAMPING"), ax->c_s, 1, "N*s/m", diag)))
        return status;
    /* A damper alone cannot carry the axle's static load, and the model would ignore it. */
    if (ax->k_s == 0 && ax->c_s != 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, FIELD("SUSPENSION_DAMPING"),
                            "must be 0 on a rigid axle (SUSPENSION_STIFFNESS 0), got %g",
                            ax->c_s);
    /* A suspended axle's mass is a state of its own and divides by it; a rigid axle's is
     * part of the body's and unused. */
    return vehicle_require(FIELD("AXLE_MASS"), ax->m_a, ax->k_s == 0, "kg", diag);
#undef FIELD
}

static int axle_plausible(const tirenv_axle *ax, const char *section, tirenv_diag *diag)
{
    char f[64];
#define FIELD(key) axle_field(f, section, key)
    int status;
    if ((status = vehicle_plausible(FIELD("TIRES"), ax->tires, 1, 16, "tires", diag)) ||
        (!isnan(ax->k_t) && (status = vehicle_plausible(FIELD("TIRE_STIFFNESS"), ax->k_t, 1e4,
                                                        1e10, "N/m", diag))) ||
        (!isnan(ax->c_t) &&
         (status = vehicle_plausible(FIELD("TIRE_DAMPING"), ax->c_t, 0, 1e6, "N*s/m", diag))) ||
        (status = vehicle_plausible(FIELD("SUSPENSION_STIFFNESS"), ax->k_s, 0, 1e9, "N/m",
                                    diag)) ||
        (status = vehicle_plausible(FIELD("SUSPENSION_DAMPING"), ax->c_s, 0, 1e7, "N*s/m",
                                    diag)) ||
        (status = vehicle_plausible(FIELD("AXLE_MASS"), ax->m_a, 0, 1e5, "kg", diag)))
        return status;
    return TIRENV_OK;
#undef FIELD
}

/* The ranges of docs/formats.md section 3, once the signs, the relations and the static
 * loads have passed (their messages say more where they apply). */
static int vehicle_plausible_all(const tirenv_vehicle *v, tirenv_diag *diag)
{
    int status;
    if ((status = vehicle_plausible("MASS", v->m, 50, 1e6, "kg", diag)) ||
        (status = vehicle_plausible("PITCH_INERTIA", v->I_y, 1, 1e8, "kg*m^2", diag)) ||
        (status = vehicle_plausible("CG_TO_FRONT_AXLE", v->a, 0, 20, "m", diag)) ||
        (status = vehicle_plausible("CG_TO_REAR_AXLE", v->b, 0, 20, "m", diag)) ||
        (status = vehicle_plausible("GRAVITY", v->g, 1, 30, "m/s^2", diag)) ||
        (status = vehicle_plausible("SEAT_AHEAD_OF_CG", v->seat_x, -20, 20, "m", diag)) ||
        (status = vehicle_plausible("SEAT_ABOVE_CG", v->seat_h, -10, 10, "m", diag)) ||
        (status = axle_plausible(&v->front, "FRONT_AXLE", diag)) ||
        (status = axle_plausible(&v->rear, "REAR_AXLE", diag)))
        return status;
    return TIRENV_OK;
}

int tirenv_vehicle_check(const tirenv_vehicle *v, tirenv_diag *diag)
{
    int status;
    if ((status = vehicle_require("MASS", v->m, 0, "kg", diag)) ||
        (status = vehicle_require("PITCH_INERTIA", v->I_y, 0, "kg*m^2", diag)) ||
        (status = vehicle_require("CG_TO_FRONT_AXLE", v->a, 0, "m", diag)) ||
        (status = vehicle_require("CG_TO_REAR_AXLE", v->b, 0, "m", diag)) ||
        (status = vehicle_require("GRAVITY", v->g, 0, "m/s^2", diag)))
        return status;
    if (!isfinite(v->seat_x))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "SEAT_AHEAD_OF_CG",
                            "must be a finite length in m, got %g", v->seat_x);
    if (!isfinite(v->seat_h))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "SEAT_ABOVE_CG",
                            "must be a finite length in m, got %g", v->seat_h);
    if ((status = vehicle_check_axle(&v->front, "FRONT_AXLE", 0, diag)) ||
        (status = vehicle_check_axle(&v->rear, "REAR_AXLE", 1, diag)) ||
        (status = tirenv_ride__static_check(v, diag)))
        return status;
    return vehicle_plausible_all(v, diag);
}

/* Moments about the axles split the body's weight m*g in the ratio b : a; a suspended front
 * axle adds its own weight to the front tires (a rigid one's is inside m already). */
double tirenv_vehicle_tire_load(const tirenv_vehicle *v, int axle)
{
    const double l = v->a + v->b;
    if (axle == 0)
        return (v->m * v->g * v->b / l + (v->front.k_s > 0 ? v->front.m_a * v->g : 0)) /
               v->front.tires;
    if (axle == 1)
        return v->m * v->g * v->a / l / v->rear.tires;
    return NAN;
}

/* One axle's spring and damper from its tire where the vehicle gives none (NAN): the tire's
 * vertical law, which the ride's force follows, with k_t its tangent at the static load for
 * the ride's linear checks (docs/models.md section 9.1); the damping MF-Tyre's
 * VERTICAL_DAMPING. An axle that follows a law takes the new tire's, at the load it now has. */
static int axle_tires(tirenv_axle *ax, const char *section, const tirenv_tire *t, double G0,
                      tirenv_diag *diag)
{
    char f[64];
    const int own = isnan(ax->k_t) || ax->law.factor > 0;
    const double k_t = own ? tirenv_tire_vertical_stiffness(t, G0) : ax->k_t;
    const double c_t = isnan(ax->c_t) ? t->k_z : ax->c_t;
    if (isnan(c_t))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, axle_field(f, section, "TIRE_DAMPING"),
                            "not given, and its tire file has no [VERTICAL] VERTICAL_DAMPING "
                            "either: the %s axle's tires need a vertical damping (N*s/m); "
                            "expected TIRE_DAMPING in [%s] or VERTICAL_DAMPING in the tire file",
                            section[0] == 'R' ? "rear" : "front", section);
    if (!(k_t > 0 && isfinite(k_t)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0,
                            axle_field(f, section, "TIRE_STIFFNESS"),
                            "not given, and its tire file's vertical law (VERTICAL_STIFFNESS "
                            "%g N/m, FNOMIN %g N, Q_FZ2 %g, docs/models.md section 7.3) has no "
                            "positive stiffness at the static tire load %g N (got %g N/m: a "
                            "law that carries no such load, or only deflected by the tire's "
                            "free radius %g m or more); expected TIRE_STIFFNESS in [%s], or a "
                            "law that carries the load", t->cam.c_z, t->cam.fnomin,
                            t->cam.q_fz2, G0, k_t, t->springs.R0, section);
    ax->k_t = k_t;
    ax->c_t = c_t;
    if (own)
        ax->law = tirenv_tire_vertical_law(t);
    return TIRENV_OK;
}

int tirenv_vehicle_tires(tirenv_vehicle *v, const tirenv_tire *front, const tirenv_tire *rear,
                         tirenv_diag *diag)
{
    if (!v || !front || !rear)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no vehicle or tire (NULL)");
    int status = axle_tires(&v->front, "FRONT_AXLE", front, tirenv_vehicle_tire_load(v, 0),
                            diag);
    if (!status)
        status = axle_tires(&v->rear, "REAR_AXLE", rear, tirenv_vehicle_tire_load(v, 1), diag);
    return status;
}
