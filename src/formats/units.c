/* Unit names of TeimOrbit [UNITS] blocks and their factors to SI. The names and their
 * shortest abbreviations follow the Adams Tire documentation ("Units supported in tire
 * property files"); the factors are the exact definitions (inch, pound, psi) or standard
 * gravity for the kilogram-force. SPDX-License-Identifier: Apache-2.0 */
#include "formats/units.h"

#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "tirenv/error.h"

/* A unit is matched by any prefix of full that begins with abbrev: 'rad', 'radi', ...,
 * 'radians'. A symbol is its own full name. */
typedef struct {
    tirenv_unit_kind kind;
    const char *abbrev;
    const char *full;
    double factor;
} unit;

#define LB 0.45359237            /* kg, exact */
#define G0 9.80665               /* m/s^2, standard gravity */
#define PI_180 0.017453292519943295

static const unit units[] = {
    {TIRENV_UNIT_LENGTH, "meter", "meters", 1},
    {TIRENV_UNIT_LENGTH, "metre", "metres", 1},
    {TIRENV_UNIT_LENGTH, "m", "m", 1},
    {TIRENV_UNIT_LENGTH, "mm", "mm", 1e-3},
    {TIRENV_UNIT_LENGTH, "millim", "millimeters", 1e-3},
    {TIRENV_UNIT_LENGTH, "cm", "cm", 1e-2},
    {TIRENV_UNIT_LENGTH, "centim", "centimeters", 1e-2},
    {TIRENV_UNIT_LENGTH, "km", "km", 1e3},
    {TIRENV_UNIT_LENGTH, "kilom", "kilometers", 1e3},
    {TIRENV_UNIT_LENGTH, "mile", "miles", 1609.344},
    {TIRENV_UNIT_LENGTH, "foot", "foot", 0.3048},
    {TIRENV_UNIT_LENGTH, "feet", "feet", 0.3048},
    {TIRENV_UNIT_LENGTH, "ft", "ft", 0.3048},
    {TIRENV_UNIT_LENGTH, "in", "inches", 0.0254},
    {TIRENV_UNIT_FORCE, "newton", "newtons", 1},
    {TIRENV_UNIT_FORCE, "n", "n", 1},
    {TIRENV_UNIT_FORCE, "knewton", "knewtons", 1e3},
    {TIRENV_UNIT_FORCE, "kilonewton", "kilonewtons", 1e3},
    {TIRENV_UNIT_FORCE, "kilo_newton", "kilo_newtons", 1e3},
    {TIRENV_UNIT_FORCE, "kn", "kn", 1e3},
    {TIRENV_UNIT_FORCE, "mnewton", "mnewtons", 1e-3},
    {TIRENV_UNIT_FORCE, "millinewton", "millinewtons", 1e-3},
    {TIRENV_UNIT_FORCE, "dyne", "dynes", 1e-5},
    {TIRENV_UNIT_FORCE, "pound_force", "pound_force", LB * G0},
    {TIRENV_UNIT_FORCE, "lbf", "lbf", LB * G0},
    {TIRENV_UNIT_FORCE, "kpound_force", "kpound_force", 1e3 * LB * G0},
    {TIRENV_UNIT_FORCE, "kilogram_force", "kilogram_force", G0},
    {TIRENV_UNIT_FORCE, "kgf", "kgf", G0},
    {TIRENV_UNIT_FORCE, "ounce_force", "ounce_force", LB / 16 * G0},
    {TIRENV_UNIT_ANGLE, "rad", "radians", 1},
    {TIRENV_UNIT_ANGLE, "deg", "degrees", PI_180},
    {TIRENV_UNIT_MASS, "kg", "kg", 1},
    {TIRENV_UNIT_MASS, "kilog", "kilograms", 1},
    {TIRENV_UNIT_MASS, "gram", "grams", 1e-3},
    {TIRENV_UNIT_MASS, "g", "g", 1e-3},
    {TIRENV_UNIT_MASS, "tonne", "tonnes", 1e3},
    {TIRENV_UNIT_MASS, "pound_mass", "pound_mass", LB},
    {TIRENV_UNIT_MASS, "lbm", "lbm", LB},
    {TIRENV_UNIT_MASS, "kpound_mass", "kpound_mass", 1e3 * LB},
    {TIRENV_UNIT_MASS, "slug", "slugs", LB * G0 / 0.3048},
    {TIRENV_UNIT_MASS, "ounce_mass", "ounce_mass", LB / 16},
    {TIRENV_UNIT_TIME, "sec", "seconds", 1},
    {TIRENV_UNIT_TIME, "s", "s", 1},
    {TIRENV_UNIT_TIME, "milli", "milliseconds", 1e-3},
    {TIRENV_UNIT_TIME, "ms", "ms", 1e-3},
    {TIRENV_UNIT_TIME, "min", "minutes", 60},
    {TIRENV_UNIT_TIME, "hour", "hours", 3600},
    {TIRENV_UNIT_TIME, "h", "h", 3600},
    {TIRENV_UNIT_PRESSURE, "pa", "pascals", 1},
    {TIRENV_UNIT_PRESSURE, "kpa", "kpa", 1e3},
    {TIRENV_UNIT_PRESSURE, "kpascal", "kpascals", 1e3},
    {TIRENV_UNIT_PRESSURE, "kilopascal", "kilopascals", 1e3},
    {TIRENV_UNIT_PRESSURE, "mpa", "mpa", 1e6},
    {TIRENV_UNIT_PRESSURE, "megapascal", "megapascals", 1e6},
    {TIRENV_UNIT_PRESSURE, "bar", "bar", 1e5},
    {TIRENV_UNIT_PRESSURE, "mbar", "mbar", 1e2},
    {TIRENV_UNIT_PRESSURE, "psi", "psi", LB * G0 / (0.0254 * 0.0254)},
    {TIRENV_UNIT_PRESSURE, "n/m^2", "n/m^2", 1},
    {TIRENV_UNIT_PRESSURE, "n/m2", "n/m2", 1},
};

static const char *const keys[TIRENV_UNIT_KINDS] = {"LENGTH", "FORCE", "ANGLE",
                                                     "MASS", "TIME", "PRESSURE"};

const char *tirenv_units__key(tirenv_unit_kind kind)
{
    return (unsigned)kind < TIRENV_UNIT_KINDS ? keys[kind] : "";
}

int tirenv_units__factor(tirenv_unit_kind kind, const char *name, double *factor)
{
    const size_t n = strlen(name);
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++) {
        const unit *u = &units[i];
        if (u->kind != kind || n < strlen(u->abbrev) || n > strlen(u->full))
            continue;
        if (strncasecmp(name, u->full, n) == 0) {
            *factor = u->factor;
            return TIRENV_OK;
        }
    }
    return TIRENV_EINVAL;
}

const char *tirenv_units__list(tirenv_unit_kind kind, char *buf, unsigned long size)
{
    size_t k = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < sizeof units / sizeof units[0] && k < size; i++)
        if (units[i].kind == kind) {
            const int r = snprintf(buf + k, size - k, "%s'%s'", k ? ", " : "", units[i].full);
            k += r > 0 ? (size_t)r : 0;
        }
    return buf;
}
