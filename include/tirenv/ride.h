/* tirenv: ride simulation of a pitch-plane tractor driven by each axle's effective profile
 * (docs/models.md section 9). SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_RIDE_H
#define TIRENV_RIDE_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/model.h"
#include "tirenv/profile.h"
#include "tirenv/vehicle.h"

TIRENV_BEGIN_DECLS

/* What an axle's tires follow: heights w (m) on a uniform grid x_k = x0 + k*dx, joined by
 * GSL's Steffen interpolation, which is monotone between samples (no overshoot at a cleat's
 * edges) and has a continuous slope (the tire damper's force c*dw/dt stays continuous, so
 * the integrator keeps its order). Outside the grid the end values continue flat. */
typedef struct {
    double x0;             /* first grid position, m */
    double dx;             /* grid spacing, m */
    size_t n;              /* grid points, >= 2 */
    const double *w;       /* heights, m (borrowed) */
} tirenv_ride_track;

typedef enum {
    TIRENV_RIDE_RK4,       /* classical Runge-Kutta at the fixed step dt (default) */
    TIRENV_RIDE_RK8PD      /* Prince-Dormand 8(9), adaptive, to rel/abs tolerance tol */
} tirenv_ride_method;

typedef struct {
    double speed;          /* forward speed V, m/s (> 0) */
    double x_front0;       /* front-axle position at t = 0, m; the rear axle is a wheelbase
                            * behind */
    double duration;       /* simulated time, s */
    double dt;             /* output interval, s; RK4 steps dt, split into substeps that
                            * advance at most half an input grid spacing (so no edge of a
                            * cleat falls between its samples) */
    tirenv_ride_method method;
    double tol;            /* RK8PD: error tolerance per step (absolute and relative) */
} tirenv_ride_settings;

/* Defaults: 1 m/s, from x = 0, 10 s, dt 1 ms, RK4, tol 1e-10. */
tirenv_ride_settings tirenv_ride_default(void);

/* The state and what the driver feels at one output time. Displacements are from the static
 * equilibrium on flat ground at height 0 (so z = w on a flat road of height w). */
typedef struct {
    double t;              /* s */
    double x_front;        /* front-axle position, m */
    double z, vz, az;      /* body heave at the CG (up), its velocity and acceleration */
    double theta, vtheta, atheta; /* body pitch (nose up), rad, rad/s, rad/s^2 */
    double z_a, vz_a;      /* front axle heave and velocity (equal to the body's at the axle
                            * when it is rigid), m, m/s */
    double w_front, w_rear;/* the axles' inputs, m */
    double seat_az;        /* vertical acceleration at the seat point, m/s^2 */
    double seat_ax;        /* fore-aft acceleration at the seat point from pitch, m/s^2 */
    double F_front, F_rear;/* total tire force of each axle (>= 0: lift-off is 0), N */
} tirenv_ride_sample;

/* What an axle's tires follow over profile p on the grid x_k = x0 + k*dx (k < n), into w[]:
 * the model's effective height h (m) at the load of one tire (N), by tirenv_model_envelope
 * over blocks of the grid; the point contact (tirenv_model_point), or m NULL, gives the
 * profile's own height under the wheel centre. The model is set to p and the load
 * (tirenv_model_set); its errors name the position. */
int tirenv_ride_effective(tirenv_model *m, const tirenv_profile *p, double load, double x0,
                          double dx, size_t n, double w[], tirenv_diag *diag);

/* Number of samples a run writes: floor(duration / dt) + 1 (t = 0 included). */
size_t tirenv_ride_n_samples(const tirenv_ride_settings *s);

/* Runs the simulation from the steady start (static equilibrium on the inputs' heights at
 * t = 0, at rest vertically) and fills out[0 .. tirenv_ride_n_samples(s) - 1].
 * TIRENV_EINVAL for bad settings or vehicle (checked by tirenv_vehicle_check), TIRENV_ENOMEM,
 * TIRENV_ENOCONV if the integrator fails (the time is named). */
int tirenv_ride_run(const tirenv_vehicle *v, const tirenv_ride_track *front,
                    const tirenv_ride_track *rear, const tirenv_ride_settings *s,
                    tirenv_ride_sample out[], tirenv_diag *diag);

/* The vehicle's vertical energy at a sample, J: kinetic + the tire and suspension springs'
 * energy about the static equilibrium (the preloads' work cancels gravity's). Exact for the
 * linear model, i.e. while no tire has lifted off; conserved when all damping is 0 and the
 * inputs are constant. For tests and diagnostics. */
double tirenv_ride_energy(const tirenv_vehicle *v, const tirenv_ride_sample *s);

TIRENV_END_DECLS
#endif
