/* The pitch-plane tractor's equations of motion and their integration with GSL's odeiv2
 * (docs/models.md section 9).
 * SPDX-License-Identifier: GPL-3.0-or-later
 *
 * States, displacements from the static equilibrium on flat ground (small pitch angles):
 *   y = (z, vz, theta, vtheta[, z_a, vz_a])      (the last two with a suspended front axle)
 * Body points above the axles: z_fb = z + a*theta, z_rb = z - b*theta.
 * Tires (n per axle, Kelvin-Voigt, never pulling), with the static axle loads F0:
 *   F_tire = max(0, F0 + n*(k_t*(w - z_axle) + c_t*(dw/dt - dz_axle/dt)))
 * A suspended front axle carries the body through F_s = F_s0 + k_s*(z_a - z_fb) + c_s*(...):
 *   m z'' = F_front_on_body + F_rear - m g,   I theta'' = a F_front_on_body - b F_rear,
 *   m_a z_a'' = F_tire_front - F_s - m_a g.
 * The static loads balance the weights, so gravity only matters once a tire lifts off. */
#include "tirenv/ride.h"
#include "ride/ride_impl.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdlib.h>

typedef struct {
    const tirenv_ride_track *track;
    gsl_interp *interp;
    gsl_interp_accel *acc;
    double *x;             /* the grid, which gsl_interp wants as an array */
} input;

typedef struct {
    const tirenv_vehicle *v;
    double V, x_front0, l;
    double F0_front, F0_rear, F0_susp; /* static loads of the axles' tires and the suspension */
    int suspended;
    input front, rear;
} ride;

/* Height and its time derivative (V * dw/dx) of an axle's input at position x. */
static void input_at(const input *in, double x, double V, double *w, double *w_dot)
{
    const tirenv_ride_track *t = in->track;
    const double x_end = t->x0 + (double)(t->n - 1) * t->dx;
    if (x <= t->x0 || x >= x_end) {
        *w = x <= t->x0 ? t->w[0] : t->w[t->n - 1];
        *w_dot = 0;
        return;
    }
    *w = gsl_interp_eval(in->interp, in->x, t->w, x, in->acc);
    *w_dot = V * gsl_interp_eval_deriv(in->interp, in->x, t->w, x, in->acc);
}

static int input_init(input *in, const tirenv_ride_track *t)
{
    in->track = t;
    in->x = malloc(t->n * sizeof *in->x);
    in->interp = gsl_interp_alloc(gsl_interp_steffen, t->n);
    in->acc = gsl_interp_accel_alloc();
    if (!in->x || !in->interp || !in->acc)
        return TIRENV_ENOMEM;
    for (size_t k = 0; k < t->n; ++k)
        in->x[k] = t->x0 + (double)k * t->dx;
    return gsl_interp_init(in->interp, in->x, t->w, t->n) ? TIRENV_EINVAL : TIRENV_OK;
}

static void input_free(input *in)
{
    free(in->x);
    if (in->interp)
        gsl_interp_free(in->interp);
    if (in->acc)
        gsl_interp_accel_free(in->acc);
}

static double tire_force(const tirenv_axle *ax, double F0, double w, double w_dot, double z,
                         double z_dot)
{
    const double F = F0 + ax->tires * (ax->k_t * (w - z) + ax->c_t * (w_dot - z_dot));
    return F > 0 ? F : 0;
}

/* The right-hand side, and everything a sample reports, at time t and state y. */
static void evaluate(const ride *r, double t, const double y[], double dydt[],
                     tirenv_ride_sample *s)
{
    const tirenv_vehicle *v = r->v;
    const double x_f = r->x_front0 + r->V * t;
    double w_f, wd_f, w_r, wd_r;
    input_at(&r->front, x_f, r->V, &w_f, &wd_f);
    input_at(&r->rear, x_f - r->l, r->V, &w_r, &wd_r);
    const double z = y[0], vz = y[1], th = y[2], vth = y[3];
    const double z_fb = z + v->a * th, vz_fb = vz + v->a * vth;
    const double z_rb = z - v->b * th, vz_rb = vz - v->b * vth;
    const double z_a = r->suspended ? y[4] : z_fb, vz_a = r->suspended ? y[5] : vz_fb;
    const double F_f = tire_force(&v->front, r->F0_front, w_f, wd_f, z_a, vz_a);
    const double F_r = tire_force(&v->rear, r->F0_rear, w_r, wd_r, z_rb, vz_rb);
    double F_body = F_f, az_a = 0;
    if (r->suspended) {
        F_body = r->F0_susp + v->front.k_s * (z_a - z_fb) + v->front.c_s * (vz_a - vz_fb);
        az_a = (F_f - F_body) / v->front.m_a - v->g;
    }
    const double az = (F_body + F_r) / v->m - v->g;
    const double ath = (v->a * F_body - v->b * F_r) / v->I_y;
    if (dydt) {
        dydt[0] = vz;
        dydt[1] = az;
        dydt[2] = vth;
        dydt[3] = ath;
        if (r->suspended) {
            dydt[4] = vz_a;
            dydt[5] = az_a;
        }
    }
    if (s)
        *s = (tirenv_ride_sample){.t = t, .x_front = x_f, .z = z, .vz = vz, .az = az,
                                  .theta = th, .vtheta = vth, .atheta = ath, .z_a = z_a,
                                  .vz_a = vz_a, .w_front = w_f, .w_rear = w_r,
                                  .seat_az = az + v->seat_x * ath,
                                  .seat_ax = -v->seat_h * ath, .F_front = F_f, .F_rear = F_r};
}

static int rhs(double t, const double y[], double dydt[], void *params)
{
    evaluate(params, t, y, dydt, NULL);
    return GSL_SUCCESS;
}

tirenv_ride_settings tirenv_ride_default(void)
{
    return (tirenv_ride_settings){.speed = 1.0, .x_front0 = 0.0, .duration = 10.0, .dt = 1e-3,
                                  .method = TIRENV_RIDE_RK4, .tol = 1e-10};
}

size_t tirenv_ride_n_samples(const tirenv_ride_settings *s)
{
    /* The 1e-9 guards duration = k*dt computed in floating point (10 / 1e-3 = 9999.999...). */
    return (size_t)floor(s->duration / s->dt + 1e-9) + 1;
}

static int check(const tirenv_vehicle *v, const tirenv_ride_track *front,
                 const tirenv_ride_track *rear, const tirenv_ride_settings *s,
                 tirenv_diag *diag)
{
    int status = tirenv_vehicle_check(v, diag);
    if (status)
        return status;
    if (!(s->speed > 0) || !isfinite(s->speed))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "speed", "expected a speed > 0 m/s, "
                            "got %g", s->speed);
    if (!(s->dt > 0) || !(s->duration >= 0) || !isfinite(s->duration) ||
        !isfinite(s->x_front0) || s->duration / s->dt > 1e9)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dt", "expected dt > 0 s, duration "
                            ">= 0 s (at most 1e9 steps) and a finite start; got dt %g, "
                            "duration %g, x_front0 %g", s->dt, s->duration, s->x_front0);
    if (s->method == TIRENV_RIDE_RK8PD && !(s->tol > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tol", "expected tol > 0, got %g",
                            s->tol);
    const tirenv_ride_track *tracks[2] = {front, rear};
    for (int i = 0; i < 2; ++i) {
        const tirenv_ride_track *t = tracks[i];
        if (!t || !t->w || t->n < 2 || !(t->dx > 0) || !isfinite(t->x0))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, i ? "rear" : "front",
                                "an axle's input needs >= 2 heights on a grid of dx > 0");
        for (size_t k = 0; k < t->n; ++k)
            if (!isfinite(t->w[k]))
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, i ? "rear" : "front",
                                    "input height %zu (x = %g m) is not finite", k,
                                    t->x0 + (double)k * t->dx);
    }
    return TIRENV_OK;
}

/* Static equilibrium on the inputs at t = 0: every spring at its static length. */
static size_t steady_start(const ride *r, double y[6])
{
    double w_f, w_r, unused;
    input_at(&r->front, r->x_front0, r->V, &w_f, &unused);
    input_at(&r->rear, r->x_front0 - r->l, r->V, &w_r, &unused);
    const double a = r->v->a, b = r->v->b;
    y[0] = (b * w_f + a * w_r) / r->l;
    y[1] = 0;
    y[2] = (w_f - w_r) / r->l;
    y[3] = 0;
    y[4] = w_f;
    y[5] = 0;
    return r->suspended ? 6 : 4;
}

int tirenv_ride_run(const tirenv_vehicle *v, const tirenv_ride_track *front,
                    const tirenv_ride_track *rear, const tirenv_ride_settings *s,
                    tirenv_ride_sample out[], tirenv_diag *diag)
{
    int status = check(v, front, rear, s, diag);
    if (status)
        return status;
    ride r = {.v = v, .V = s->speed, .x_front0 = s->x_front0, .l = v->a + v->b,
              .suspended = v->front.k_s > 0};
    /* The static loads the effective profiles were computed for (tirenv_vehicle_tire_load);
     * a suspension carries the body's share of the front axle's. */
    r.F0_front = v->front.tires * tirenv_vehicle_tire_load(v, 0);
    r.F0_rear = v->rear.tires * tirenv_vehicle_tire_load(v, 1);
    r.F0_susp = v->m * v->g * v->b / r.l;
    gsl_odeiv2_driver *d = NULL;
    gsl_odeiv2_step *step = NULL;
    if ((status = input_init(&r.front, front)) || (status = input_init(&r.rear, rear))) {
        status = status == TIRENV_ENOMEM
                     ? tirenv_error(diag, status, "", 0, "", "out of memory")
                     : tirenv_error(diag, status, "", 0, "", "GSL cannot interpolate an input");
        goto done;
    }
    double y[6], y_err[6];  /* RK4's error estimate is computed, and unused */
    gsl_odeiv2_system sys = {rhs, NULL, steady_start(&r, y), &r};
    /* RK4 steps on its own (a driver would want an error estimate it does not have); RK8PD
     * goes through the driver, which adapts the step between outputs. */
    if (s->method == TIRENV_RIDE_RK4)
        step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk4, sys.dimension);
    else
        d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, s->dt, s->tol, s->tol);
    if (!step && !d) {
        status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        goto done;
    }
    const size_t n = tirenv_ride_n_samples(s);
    /* RK4 samples the inputs at three points per step, so a step longer than the grid would
     * skip over a cleat's edge: substeps advance at most half a grid spacing. */
    const double dx_min = fmin(front->dx, rear->dx);
    const size_t n_sub = (size_t)fmax(1.0, ceil(2.0 * s->speed * s->dt / dx_min - 1e-9));
    if (step && (status = tirenv_ride__rk4_check(v, s->dt / (double)n_sub, s->dt, n_sub, diag)))
        goto done;
    double t = 0;
    evaluate(&r, t, y, NULL, &out[0]);
    for (size_t k = 1; k < n; ++k) {
        /* Each sample's time is k*dt, not a running sum, so long runs do not drift. */
        const double t_k = (double)k * s->dt;
        int rc = GSL_SUCCESS;
        if (step) {
            const double h = (t_k - t) / (double)n_sub;
            for (size_t j = 0; j < n_sub && rc == GSL_SUCCESS; ++j)
                rc = gsl_odeiv2_step_apply(step, t + (double)j * h, h, y, y_err, NULL, NULL,
                                           &sys);
        } else {
            rc = gsl_odeiv2_driver_apply(d, &t, t_k, y);
        }
        if (rc != GSL_SUCCESS) {
            status = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "", "the ODE solver failed "
                                  "at t = %.6g s (x_front = %.6g m): %s", t,
                                  r.x_front0 + r.V * t, gsl_strerror(rc));
            goto done;
        }
        t = t_k;
        evaluate(&r, t, y, NULL, &out[k]);
        if ((status = tirenv_ride__finite_sample(&out[k], diag)))
            goto done;
    }
done:
    if (d)
        gsl_odeiv2_driver_free(d);
    if (step)
        gsl_odeiv2_step_free(step);
    input_free(&r.front);
    input_free(&r.rear);
    return status;
}

double tirenv_ride_energy(const tirenv_vehicle *v, const tirenv_ride_sample *s)
{
    const double z_fb = s->z + v->a * s->theta, z_rb = s->z - v->b * s->theta;
    const int suspended = v->front.k_s > 0;
    const double d_f = s->w_front - (suspended ? s->z_a : z_fb), d_r = s->w_rear - z_rb;
    double E = 0.5 * v->m * s->vz * s->vz + 0.5 * v->I_y * s->vtheta * s->vtheta +
               0.5 * v->front.tires * v->front.k_t * d_f * d_f +
               0.5 * v->rear.tires * v->rear.k_t * d_r * d_r;
    if (suspended) {
        const double d_s = s->z_a - z_fb;
        E += 0.5 * v->front.m_a * s->vz_a * s->vz_a + 0.5 * v->front.k_s * d_s * d_s;
    }
    return E;
}
