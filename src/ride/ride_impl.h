/* Private to src/ride: the checks of ride_checks.c that the vehicle and the ride run use
 * (docs/models.md section 9.5). SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TIRENV_RIDE_IMPL_H
#define TIRENV_RIDE_IMPL_H

#include <stddef.h>
#include "tirenv/ride.h"
#include "tirenv/vehicle.h"

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
