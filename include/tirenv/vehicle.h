/* tirenv: the pitch-plane tractor of the ride simulation (docs/models.md section 9); its
 * property file (docs/formats.md section 3), a file format, is in vehicle_file.h.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_VEHICLE_H
#define TIRENV_VEHICLE_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/cam.h"
#include "tirenv/error.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

/* One axle: its tires as vertical springs and dampers in parallel (Kelvin-Voigt) acting on
 * the axle's effective profile, each spring its tire file's vertical law or a linear k_t, and,
 * for the front axle, an optional suspension between the body and an unsprung axle mass.
 * Tires may lift off: a tire never pulls. */
typedef struct {
    char tire_file[512];   /* the .tir file of the axle's tires (for the enveloping models),
                            * as fopen takes it (in a vehicle file a relative path is relative
                            * to that file; the reader puts the file's directory before it);
                            * "" = the built-in default tire */
    double tires;          /* tires on the axle (usually 2; 4 for duals) */
    double k_t;            /* vertical stiffness of one tire, N/m, its linear spring; NAN:
                            * its tire file's vertical law (tirenv_vehicle_tires sets law, and
                            * k_t the law's tangent at the static load, which the ride's linear
                            * checks use) */
    double c_t;            /* vertical damping of one tire, N*s/m; NAN: its tire file's
                            * VERTICAL_DAMPING (tirenv_vehicle_tires sets it) */
    tirenv_cam_vertical law; /* the tire's vertical law F_z(rho) the ride's tire force
                            * follows (docs/models.md section 9.3) where law.factor > 0, set by
                            * tirenv_vehicle_tires; law.factor = 0 (as the default and a
                            * vehicle file leave it): none, the linear spring k_t */
    double k_s;            /* suspension stiffness of the axle, N/m; 0 = rigid axle (the axle
                            * moves with the body and its mass is part of the body's) */
    double c_s;            /* suspension damping of the axle, N*s/m */
    double m_a;            /* unsprung axle mass with wheels, kg (used only if k_s > 0) */
} tirenv_axle;

/* A tractor in the pitch plane: a rigid body (heave z, pitch theta nose-up) on a front and
 * a rear axle, CG between them. Tractors usually have no rear suspension, so the rear axle
 * is rigid (its k_s must be 0); the front axle may be suspended. */
typedef struct {
    double m;              /* body mass: everything above the tires except a suspended front
                            * axle, kg */
    double I_y;            /* body pitch moment of inertia about the CG, kg*m^2 */
    double a;              /* CG to front axle, horizontal, m */
    double b;              /* CG to rear axle, horizontal, m (wheelbase a + b) */
    double seat_x;         /* seat reference point ahead of the CG (negative: behind), m */
    double seat_h;         /* seat reference point above the CG, m */
    tirenv_axle front, rear;
    double g;              /* gravitational acceleration, m/s^2 */
} tirenv_vehicle;

/* The documented default: a mid-size 4.5 t tractor, data/vehicles/tractor.veh, whose tires'
 * k_t and c_t are their tire file's (NAN until tirenv_vehicle_tires). */
tirenv_vehicle tirenv_vehicle_default(void);

/* Gives each axle whose k_t is NAN, or that already follows a law, its tire's vertical law
 * (front, rear: the tires of its TIRE_FILE, read by the caller): law =
 * tirenv_tire_vertical_law, k_t = tirenv_tire_vertical_stiffness at the axle's static tire
 * load (tirenv_vehicle_tire_load), its tangent there; and each c_t that is NAN the tire's
 * VERTICAL_DAMPING (k_z). A k_t or c_t the vehicle gives is kept (and its axle's law stays
 * none). TIRENV_EINVAL naming the axle's key ("FRONT_AXLE.TIRE_DAMPING") where the tire has no
 * VERTICAL_DAMPING either, or its vertical law no positive stiffness at that load; that axle
 * is then left as it was. The ride refuses a vehicle with a NAN left (tirenv_ride_run). */
int tirenv_vehicle_tires(tirenv_vehicle *v, const tirenv_tire *front, const tirenv_tire *rear,
                         tirenv_diag *diag);

/* Physical sanity: positive masses, inertia, lengths, tire stiffnesses and g; a whole
 * number of tires; non-negative damping and suspension stiffness (a NAN k_t or c_t passes:
 * the tire file's, not yet set); no suspension damping on a rigid axle; m_a > 0 on a
 * suspended axle; rear k_s = 0. TIRENV_EINVAL naming the field otherwise by its file key
 * ("MASS"; "FRONT_AXLE.TIRES" for the axles' keys, as --set takes them). */
int tirenv_vehicle_check(const tirenv_vehicle *v, tirenv_diag *diag);

/* Static load of one tire of the front (axle 0) or rear (axle 1) axle on flat ground, N:
 * front (m*g*b/(a+b) + (k_s > 0 ? m_a*g : 0)) / front.tires, rear m*g*a/(a+b) / rear.tires;
 * NAN for another axle. */
double tirenv_vehicle_tire_load(const tirenv_vehicle *v, int axle);

TIRENV_END_DECLS
#endif
