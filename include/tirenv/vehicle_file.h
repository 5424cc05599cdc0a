/* tirenv: the vehicle property file (.veh, docs/formats.md): the pitch-plane tractor of
 * vehicle.h read, overridden and written in the .tir syntax. A file format, so it belongs to
 * the auxiliary layer (src/formats/vehicle_file.c). SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_VEHICLE_FILE_H
#define TIRENV_VEHICLE_FILE_H

#include "tirenv/decls.h"
#include "tirenv/error.h"
#include "tirenv/vehicle.h"

TIRENV_BEGIN_DECLS

/* Reads a vehicle property file (the .tir syntax: [SECTION]s of KEY = value, '$' comments,
 * SI units; keys in data/vehicles/tractor.veh) over *v, which changes only if the whole
 * file passes (parsing and tirenv_vehicle_check); errors name the file, line, column and
 * key. A relative TIRE_FILE is relative to the vehicle file's directory and is stored with
 * that directory put before it, so that it opens from the working directory. */
int tirenv_vehicle_read(const char *path, tirenv_vehicle *v, tirenv_diag *diag);
/* tirenv_vehicle_read that also names, into unset (n bytes, "" if none), the keys the file
 * does not set, as "SECTION.KEY" separated by ", " (cut with "..." if they do not fit): those
 * keep the values of the vehicle read over. TIRE_STIFFNESS and TIRE_DAMPING, whose absence
 * means the tire file's, are not named. */
int tirenv_vehicle_read_unset(const char *path, tirenv_vehicle *v, char *unset, size_t n,
                              tirenv_diag *diag);

/* Applies one "KEY=VALUE" override (KEY as in the file, e.g. MASS=5200; the axle keys need
 * their section, e.g. FRONT_AXLE.TIRES=4), then checks; *v changes only if both pass, and a
 * refusal's diag names the file "--set" (line 0) and the key as its field. A relative
 * TIRE_FILE given here is relative to the working directory. */
int tirenv_vehicle_set(tirenv_vehicle *v, const char *assignment, tirenv_diag *diag);

/* Writes *v as a vehicle property file (atomically: all or nothing); refuses a vehicle that
 * fails tirenv_vehicle_check. A relative TIRE_FILE is written as an absolute path when the
 * file goes to another directory than the working one, so that it names the same tire. */
int tirenv_vehicle_write(const char *path, const tirenv_vehicle *v, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
