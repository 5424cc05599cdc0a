/* Private to the library's file readers: the unit names of the [UNITS] block of TeimOrbit
 * files (MF-Tyre / PAC2002 .tir tire files, Adams .rdf road files) and their factors to SI.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_UNITS_H
#define TIRENV_UNITS_H

/* The quantities a [UNITS] block sets. */
typedef enum {
    TIRENV_UNIT_LENGTH = 0, /* to m */
    TIRENV_UNIT_FORCE,      /* to N */
    TIRENV_UNIT_ANGLE,      /* to rad */
    TIRENV_UNIT_MASS,       /* to kg */
    TIRENV_UNIT_TIME,       /* to s */
    TIRENV_UNIT_PRESSURE,   /* to Pa */
    TIRENV_UNIT_KINDS
} tirenv_unit_kind;

/* The key naming a quantity in [UNITS] ("LENGTH", ...). */
const char *tirenv_units__key(tirenv_unit_kind kind);

/* The factor from the unit called name to SI: 0 (TIRENV_OK) and *factor, or TIRENV_EINVAL
 * if the name is not one of the kind's units. Names are case-insensitive; as in Adams, a
 * unit may be written from its shortest abbreviation up to its full name ('rad', 'radian',
 * 'radians'; 'sec' ... 'seconds'), and common symbols ('m', 'N', 'Pa', 'kPa', 'psi') are
 * accepted too. */
int tirenv_units__factor(tirenv_unit_kind kind, const char *name, double *factor);

/* The accepted names of a kind, "'meter', 'mm', ..." for messages, in buf. */
const char *tirenv_units__list(tirenv_unit_kind kind, char *buf, unsigned long size);

#endif
