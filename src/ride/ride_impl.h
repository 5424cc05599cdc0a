/* Private to the ride module: an axle's input (a track, a table over loads, or a function of
 * position and load) and the tire force it makes, shared by the integrator (ride.c) and
 * the inputs (ride_axle.c), docs/models.md section 9.5; and the checks of ride_checks.c
 * that the vehicle and the ride run use (section 9.6). SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_RIDE_IMPL_H
#define TIRENV_RIDE_IMPL_H

#include <stddef.h>

#include "tirenv/ride.h"
#include "tirenv/vehicle.h"

typedef enum {
    TIRENV_RIDE__TRACK,    /* tirenv_ride_track: the load does not enter */
    TIRENV_RIDE__TABLE,    /* tirenv_ride_table: rows over loads */
    TIRENV_RIDE__FUNCTION  /* tirenv_ride_input: a function of position and load */
} tirenv_ride__kind;

typedef struct {
    tirenv_ride__kind kind;
    const char *name;      /* the axle, "front" or "rear": the field of its errors */
    const tirenv_ride_track *track;
    const tirenv_ride_table *table;
    const tirenv_ride_input *fn;
    /* The grid of a track or a table (a track is one row), and Steffen's slopes on it. */
    double x0, dx;         /* m */
    size_t n, m;           /* grid points, rows */
    const double *w;       /* the rows, m*n heights, m */
    double *slope;         /* the Steffen slopes dw/dx at its m*n points */
    size_t hint;           /* a table's segment of rows where the last load was found */
} tirenv_ride__input;

/* One tire of an axle as the ride's force has it (ride_tire.c, docs/models.md section 9.3):
 * the vehicle's linear spring k_t, or its tire file's vertical law about that law's
 * deflection rho0 under the static load G0. */
typedef struct {
    double n;              /* tires on the axle */
    double G0;             /* static load of one tire, N */
    double k_t, c_t;       /* N/m (the linear spring's), N*s/m */
    tirenv_cam_vertical law;
    int has_law;           /* the law's force, not k_t's */
    double rho0;           /* the law's deflection under G0, m */
    double F_rho0;         /* the law's load there, G0 to round-off, N */
} tirenv_ride__tire;

/* Sets t for the axle ax with static tire load G0 (N); TIRENV_EINVAL, naming the field name,
 * where the axle's law has no positive deflection under G0. */
int tirenv_ride__tire_set(tirenv_ride__tire *t, const tirenv_axle *ax, double G0,
                          const char *name, tirenv_diag *diag);

/* The load of one tire (N, not clamped: <= 0 is off the ground) at the deflection d (m) from
 * the static one, w - z_axle, and its rate d_dot (m/s). */
double tirenv_ride__tire_load(const tirenv_ride__tire *t, double d, double d_dot);

/* The force of all n tires, max(0, ...) of the load (N). */
double tirenv_ride__tire_force(const tirenv_ride__tire *t, double d, double d_dot);

/* The energy all n tires' springs store at deflection d beyond their static state, less the
 * static loads' work (J): 0 at d = 0. */
double tirenv_ride__tire_energy(const tirenv_ride__tire *t, double d);

/* Sets up the input of the axle name (static storage) of one kind from exactly one of track,
 * table, fn (the others NULL);
 * TIRENV_ENOMEM, or TIRENV_EINVAL if the grid has fewer than 2 points. in->slope is
 * then to be freed with tirenv_ride__input_free whatever the status. */
int tirenv_ride__input_init(tirenv_ride__input *in, const char *name,
                            const tirenv_ride_track *track, const tirenv_ride_table *table,
                            const tirenv_ride_input *fn);
void tirenv_ride__input_free(tirenv_ride__input *in);

/* The spacing RK4's substeps must resolve, m. */
double tirenv_ride__input_dx(const tirenv_ride__input *in);

/* The axle's input at position x for the axle's height z_a and its rate zd_a (m, m/s) at
 * speed V, with its tires t: the height w (m), its rate *w_dot (m/s) and the force of all n
 * tires *F (N, >= 0). A track: F = tirenv_ride__tire_force at d = w - z_a; a table or a
 * function: the input at the load the tires carry (tirenv_ride_run_dynamic). A function's
 * failure is returned with diag, and TIRENV_ENOCONV (field: the axle) if a balance is not
 * found within the iteration budget. */
int tirenv_ride__axle(tirenv_ride__input *in, const tirenv_ride__tire *t, double V, double x,
                      double z_a, double zd_a, double *w, double *w_dot, double *F,
                      tirenv_diag *diag);

/* The input's height at x at the static load G0 (N, per tire): the steady start's. */
int tirenv_ride__input_static(tirenv_ride__input *in, double G0, double x, double *w,
                              tirenv_diag *diag);

/* The largest h*|lambda| RK4 is allowed, for the step h and the fastest mode lambda. */
#define RK4_MAX_H_LAMBDA 0.5

/* The largest |lambda| (1/s) of the vehicle's linear modes with every tire on the ground. */
int tirenv_ride__fastest_mode(const tirenv_vehicle *v, double *lambda_max, tirenv_diag *diag);

/* TIRENV_ERANGE, naming dt and the limit, if RK4's step h (s), dt split into n_sub, is too
 * long for the fastest mode. */
int tirenv_ride__rk4_check(const tirenv_vehicle *v, double h, double dt, size_t n_sub,
                           tirenv_diag *diag);

/* TIRENV_EINVAL if a static tire deflection is so large that the dynamic tire forces are
 * lost in its rounding (called by tirenv_vehicle_check). */
int tirenv_ride__static_check(const tirenv_vehicle *v, tirenv_diag *diag);

/* TIRENV_ENOCONV, naming t and x, if any value of the sample is not finite. */
int tirenv_ride__finite_sample(const tirenv_ride_sample *s, tirenv_diag *diag);

#endif
