/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the ride module: the two integrators of tirenv_ride_method (ode.c). */
#ifndef TIRENV_RIDE_ODE_H
#define TIRENV_RIDE_ODE_H

#include <stddef.h>

enum { TIRENV_RIDE__ODE_DIM = 6 };  /* the largest state (a suspended front axle) */

/* dy/dt at (t, y) into dydt; 0, or a nonzero status that stops the integration. */
typedef int (*tirenv_ride__rhs)(double t, const double y[], double dydt[], void *params);

typedef struct {
    tirenv_ride__rhs f;
    void *params;
    size_t dim;            /* <= TIRENV_RIDE__ODE_DIM */
} tirenv_ride__ode;

/* One classical Runge-Kutta step of h from (t, y), y updated; f's status, or 0. */
int tirenv_ride__rk4_step(const tirenv_ride__ode *ode, double t, double h, double y[]);

/* The adaptive Prince-Dormand 8(7) integrator and its step size. */
typedef struct {
    double h;              /* the next step to try, s */
    double tol;            /* per component: |error| <= tol (1 + |y|) */
    size_t steps, rejected;
} tirenv_ride__rk8;

/* Starts with the step h0 > 0 and the tolerance tol > 0. */
void tirenv_ride__rk8_init(tirenv_ride__rk8 *s, double h0, double tol);
/* Advances (t, y) to t1 > t by steps that keep the error estimate within the tolerance,
 * ending exactly at t1; *t = t1 on success. Returns 0, f's status, or
 * TIRENV_RIDE__ODE_STEP_UNDERFLOW when the step needed fell below round-off of t. */
int tirenv_ride__rk8_advance(tirenv_ride__rk8 *s, const tirenv_ride__ode *ode, double *t,
                             double t1, double y[]);
enum { TIRENV_RIDE__ODE_STEP_UNDERFLOW = -1 };

/* The tableau of RK8(7)13M, for the test of its order conditions: returns A (13 x 13,
 * row-major), and c, b (eighth order), b_hat (seventh) through the pointers. */
const double *tirenv_ride__rk8_tableau(const double **c_out, const double **b_out,
                                       const double **b_hat_out);

#endif
