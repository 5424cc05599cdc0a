/* The pitch-plane tractor's equations of motion and their integration (ode.c)
 * (docs/models.md section 9).
 * SPDX-License-Identifier: Apache-2.0
 *
 * States, displacements from the static equilibrium on flat ground (small pitch angles):
 *   y = (z, vz, theta, vtheta[, z_a, vz_a])      (the last two with a suspended front axle)
 * Body points above the axles: z_fb = z + a*theta, z_rb = z - b*theta.
 * Tires (n per axle, Kelvin-Voigt, never pulling; ride_tire.c), with the static tire load G0:
 *   F_tire = n*(F_z(rho0 + w - z_axle) + c_t*(dw/dt - dz_axle/dt)) while rho0 + w - z_axle > 0,
 *            else 0, and never below 0,
 * F_z the tire file's vertical law and rho0 its deflection under G0; or, where the vehicle
 * gives TIRE_STIFFNESS k_t, F_tire = max(0, n*G0 + n*(k_t*(w - z_axle) + c_t*(...))).
 * A suspended front axle carries the body through F_s = F_s0 + k_s*(z_a - z_fb) + c_s*(...):
 *   m z'' = F_front_on_body + F_rear - m g,   I theta'' = a F_front_on_body - b F_rear,
 *   m_a z_a'' = F_tire_front - F_s - m_a g.
 * The static loads balance the weights, so gravity only matters once a tire lifts off. */
#include "tirenv/ride.h"
#include "ride/ode.h"
#include "ride/ride_impl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const tirenv_vehicle *v;
    double V, x_front0, l;
    double G0_front, G0_rear;  /* static load of one tire of each axle, N */
    tirenv_ride__tire tire_front, tire_rear;
    double F0_susp;            /* static load of the suspension, N */
    int suspended;
    tirenv_ride__input front, rear;
    int status;                /* an input function's failure, and why */
    tirenv_diag diag;
} ride;

/* The right-hand side, and everything a sample reports, at time t and state y. */
static int evaluate(ride *r, double t, const double y[], double dydt[], tirenv_ride_sample *s)
{
    const tirenv_vehicle *v = r->v;
    const double x_f = r->x_front0 + r->V * t;
    const double z = y[0], vz = y[1], th = y[2], vth = y[3];
    const double z_fb = z + v->a * th, vz_fb = vz + v->a * vth;
    const double z_rb = z - v->b * th, vz_rb = vz - v->b * vth;
    const double z_a = r->suspended ? y[4] : z_fb, vz_a = r->suspended ? y[5] : vz_fb;
    double w_f, wd_f, w_r, wd_r, F_f, F_r;
    int status = tirenv_ride__axle(&r->front, &r->tire_front, r->V, x_f, z_a, vz_a, &w_f,
                                   &wd_f, &F_f, &r->diag);
    if (!status)
        status = tirenv_ride__axle(&r->rear, &r->tire_rear, r->V, x_f - r->l, z_rb, vz_rb,
                                   &w_r, &wd_r, &F_r, &r->diag);
    if (status)
        return r->status = status;
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
    return TIRENV_OK;
}

static int rhs(double t, const double y[], double dydt[], void *params)
{
    return evaluate(params, t, y, dydt, NULL) ? 1 : 0;
}

tirenv_ride_settings tirenv_ride_default(void)
{
    return (tirenv_ride_settings){.speed = 1.0, .x_front0 = 0.0, .duration = 10.0, .dt = 1e-3,
                                  .method = TIRENV_RIDE_RK4, .tol = 1e-10};
}

size_t tirenv_ride_n_samples(const tirenv_ride_settings *s)
{
    /* The 1e-9 guards duration = k*dt computed in floating point (10 / 1e-3 = 9999.999...).
     * Settings the run refuses (check_settings) count 0, never an overflowing cast. */
    const double steps = floor(s->duration / s->dt + 1e-9);
    if (!(s->dt > 0 && steps >= 0 && steps <= 1e9))
        return 0;
    return (size_t)steps + 1;
}

static int check_settings(const tirenv_vehicle *v, const tirenv_ride_settings *s,
                          tirenv_diag *diag)
{
    int status = tirenv_vehicle_check(v, diag);
    if (status)
        return status;
    for (int axle = 0; axle < 2; ++axle) {
        const tirenv_axle *ax = axle ? &v->rear : &v->front;
        if (!isnan(ax->k_t) && !isnan(ax->c_t))
            continue;
        char field[64];
        snprintf(field, sizeof field, "%s_AXLE.%s", axle ? "REAR" : "FRONT",
                 isnan(ax->k_t) ? "TIRE_STIFFNESS" : "TIRE_DAMPING");
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, field,
                            "is the tire file's and not yet set: expected the vehicle through "
                            "tirenv_vehicle_tires with its axles' tires first");
    }
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
    return TIRENV_OK;
}

/* A grid of heights: n >= 2 finite heights per row on dx > 0 from a finite x0. */
static int check_grid(const char *axle, double x0, double dx, size_t n, size_t m,
                      const double *w, tirenv_diag *diag)
{
    if (!w || n < 2 || m < 1 || !(dx > 0) || !isfinite(x0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, axle,
                            "an axle's input needs >= 2 heights on a grid of dx > 0");
    for (size_t k = 0; k < n * m; ++k)
        if (!isfinite(w[k]))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, axle,
                                "input height %zu (x = %g m) is not finite", k % n,
                                x0 + (double)(k % n) * dx);
    return TIRENV_OK;
}

static int check_table(const char *axle, const tirenv_ride_table *t, tirenv_diag *diag)
{
    if (!t)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, axle, "no input");
    int status = check_grid(axle, t->x0, t->dx, t->n, t->m, t->w, diag);
    for (size_t j = 0; !status && j < t->m; ++j)
        if (!t->load || !(t->load[j] > 0) || !isfinite(t->load[j]) ||
            (j > 0 && !(t->load[j] > t->load[j - 1])))
            status = tirenv_error(diag, TIRENV_EINVAL, "", 0, axle,
                                  "the loads of an input's rows must be positive and "
                                  "increasing; row %zu has %g N", j, t->load ? t->load[j] : 0);
    return status;
}

static int check_fn(const char *axle, const tirenv_ride_input *f, tirenv_diag *diag)
{
    if (!f || !f->fn || !(f->load_min > 0) || !(f->load_max >= f->load_min) ||
        !isfinite(f->load_max) || !(f->dx > 0) || !isfinite(f->dx))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, axle,
                            "an input function needs 0 < load_min <= load_max (N) and a "
                            "resolution dx > 0 m");
    return TIRENV_OK;
}

/* Static equilibrium on the inputs at t = 0 (at the static loads): every spring at its
 * static length. */
static int steady_start(ride *r, double y[6], size_t *dim)
{
    double w_f, w_r;
    int status = tirenv_ride__input_static(&r->front, r->G0_front, r->x_front0, &w_f, &r->diag);
    if (!status)
        status = tirenv_ride__input_static(&r->rear, r->G0_rear, r->x_front0 - r->l, &w_r,
                                           &r->diag);
    if (status)
        return status;
    const double a = r->v->a, b = r->v->b;
    y[0] = (b * w_f + a * w_r) / r->l;
    y[1] = 0;
    y[2] = (w_f - w_r) / r->l;
    y[3] = 0;
    y[4] = w_f;
    y[5] = 0;
    *dim = r->suspended ? 6 : 4;
    return TIRENV_OK;
}

/* The integration, for inputs of any kind (set up by the callers below). */
static int run(const tirenv_vehicle *v, ride *r, const tirenv_ride_settings *s,
               tirenv_ride_sample out[], tirenv_diag *diag)
{
    r->v = v;
    r->V = s->speed;
    r->x_front0 = s->x_front0;
    r->l = v->a + v->b;
    r->suspended = v->front.k_s > 0;
    /* The static loads the effective profiles were computed for (tirenv_vehicle_tire_load);
     * a suspension carries the body's share of the front axle's. */
    r->G0_front = tirenv_vehicle_tire_load(v, 0);
    r->G0_rear = tirenv_vehicle_tire_load(v, 1);
    r->F0_susp = v->m * v->g * v->b / r->l;
    tirenv_diag_clear(&r->diag);
    double y[TIRENV_RIDE__ODE_DIM];
    size_t dim = 4;
    int status = tirenv_ride__tire_set(&r->tire_front, &v->front, r->G0_front,
                                       "FRONT_AXLE.TIRE_FILE", &r->diag);
    if (!status)
        status = tirenv_ride__tire_set(&r->tire_rear, &v->rear, r->G0_rear,
                                       "REAR_AXLE.TIRE_FILE", &r->diag);
    if (!status)
        status = steady_start(r, y, &dim);
    if (status) {
        if (diag)
            *diag = r->diag;
        return status;
    }
    const tirenv_ride__ode sys = {rhs, r, dim};
    const int step = s->method == TIRENV_RIDE_RK4;
    tirenv_ride__rk8 rk8;  /* RK8PD adapts its step between outputs (ode.c) */
    tirenv_ride__rk8_init(&rk8, s->dt, s->tol);
    const size_t n = tirenv_ride_n_samples(s);
    /* RK4 samples the inputs at three points per step, so a step longer than the grid would
     * skip over a cleat's edge: substeps advance at most half a grid spacing. */
    const double dx_min = fmin(tirenv_ride__input_dx(&r->front), tirenv_ride__input_dx(&r->rear));
    const size_t n_sub = (size_t)fmax(1.0, ceil(2.0 * s->speed * s->dt / dx_min - 1e-9));
    if (step && (status = tirenv_ride__rk4_check(v, s->dt / (double)n_sub, s->dt, n_sub, diag)))
        goto done;
    double t = 0;
    if ((status = evaluate(r, t, y, NULL, &out[0])))
        goto failed;
    for (size_t k = 1; k < n; ++k) {
        /* Each sample's time is k*dt, not a running sum, so long runs do not drift. */
        const double t_k = (double)k * s->dt;
        int rc = 0;
        if (step) {
            /* Each substep h is two RK4 steps of h/2: what GSL's rk4 stepper, which the ride
             * used until version 0.1, returned (it took one step of h as well, for an error
             * estimate the ride never read). */
            const double h = (t_k - t) / (double)n_sub;
            for (size_t j = 0; j < n_sub && rc == 0; ++j) {
                const double t_j = t + (double)j * h;
                rc = tirenv_ride__rk4_step(&sys, t_j, 0.5 * h, y);
                if (rc == 0)
                    rc = tirenv_ride__rk4_step(&sys, t_j + 0.5 * h, 0.5 * h, y);
            }
        } else {
            rc = tirenv_ride__rk8_advance(&rk8, &sys, &t, t_k, y);
        }
        if (rc != 0 && r->status) {
            status = r->status;
            goto failed;
        }
        if (rc != 0) {
            status = tirenv_error(diag, TIRENV_ENOCONV, "", 0, "", "the ODE solver failed "
                                  "at t = %.6g s (x_front = %.6g m): the step needed for "
                                  "tolerance %g fell below round-off", t,
                                  r->x_front0 + r->V * t, s->tol);
            goto done;
        }
        t = t_k;
        if ((status = evaluate(r, t, y, NULL, &out[k])))
            goto failed;
        if ((status = tirenv_ride__finite_sample(&out[k], diag)))
            goto done;
    }
    goto done;
failed:  /* an input failed: its own message, with where the run was */
    if (diag) {
        *diag = r->diag;
        char msg[sizeof diag->message];
        snprintf(msg, sizeof msg, "at t = %.6g s (x_front = %.6g m): %.400s", t,
                 r->x_front0 + r->V * t, r->diag.message);
        memcpy(diag->message, msg, sizeof msg);
    }
done:
    return status;
}

/* Sets up both inputs, runs, frees: the three public forms differ in their inputs alone. */
static int run_with(const tirenv_vehicle *v, const tirenv_ride_track *tf,
                    const tirenv_ride_track *tr, const tirenv_ride_table *bf,
                    const tirenv_ride_table *br, const tirenv_ride_input *ff,
                    const tirenv_ride_input *fr, const tirenv_ride_settings *s,
                    tirenv_ride_sample out[], tirenv_diag *diag)
{
    ride r;
    memset(&r, 0, sizeof r);
    int status = tirenv_ride__input_init(&r.front, "front", tf, bf, ff);
    if (!status)
        status = tirenv_ride__input_init(&r.rear, "rear", tr, br, fr);
    if (status)
        status = status == TIRENV_ENOMEM
                     ? tirenv_error(diag, status, "", 0, "", "out of memory")
                     : tirenv_error(diag, status, "", 0, "", "an input has fewer than 2 grid points");
    else
        status = run(v, &r, s, out, diag);
    tirenv_ride__input_free(&r.front);
    tirenv_ride__input_free(&r.rear);
    return status;
}

int tirenv_ride_run(const tirenv_vehicle *v, const tirenv_ride_track *front,
                    const tirenv_ride_track *rear, const tirenv_ride_settings *s,
                    tirenv_ride_sample out[], tirenv_diag *diag)
{
    int status = check_settings(v, s, diag);
    if (!status)
        status = front ? check_grid("front", front->x0, front->dx, front->n, 1, front->w, diag)
                       : tirenv_error(diag, TIRENV_EINVAL, "", 0, "front", "no input");
    if (!status)
        status = rear ? check_grid("rear", rear->x0, rear->dx, rear->n, 1, rear->w, diag)
                      : tirenv_error(diag, TIRENV_EINVAL, "", 0, "rear", "no input");
    return status ? status : run_with(v, front, rear, NULL, NULL, NULL, NULL, s, out, diag);
}

int tirenv_ride_run_dynamic(const tirenv_vehicle *v, const tirenv_ride_table *front,
                            const tirenv_ride_table *rear, const tirenv_ride_settings *s,
                            tirenv_ride_sample out[], tirenv_diag *diag)
{
    int status = check_settings(v, s, diag);
    if (!status)
        status = check_table("front", front, diag);
    if (!status)
        status = check_table("rear", rear, diag);
    return status ? status : run_with(v, NULL, NULL, front, rear, NULL, NULL, s, out, diag);
}

int tirenv_ride_run_input(const tirenv_vehicle *v, const tirenv_ride_input *front,
                          const tirenv_ride_input *rear, const tirenv_ride_settings *s,
                          tirenv_ride_sample out[], tirenv_diag *diag)
{
    int status = check_settings(v, s, diag);
    if (!status)
        status = check_fn("front", front, diag);
    if (!status)
        status = check_fn("rear", rear, diag);
    return status ? status : run_with(v, NULL, NULL, NULL, NULL, front, rear, s, out, diag);
}

/* The springs' energy by tirenv_ride__tire_energy: a law whose deflection under the static
 * load is not found makes it NAN. */
double tirenv_ride_energy(const tirenv_vehicle *v, const tirenv_ride_sample *s)
{
    const double z_fb = s->z + v->a * s->theta, z_rb = s->z - v->b * s->theta;
    const int suspended = v->front.k_s > 0;
    const double d_f = s->w_front - (suspended ? s->z_a : z_fb), d_r = s->w_rear - z_rb;
    tirenv_ride__tire t_f, t_r;
    if (tirenv_ride__tire_set(&t_f, &v->front, tirenv_vehicle_tire_load(v, 0), "", NULL) ||
        tirenv_ride__tire_set(&t_r, &v->rear, tirenv_vehicle_tire_load(v, 1), "", NULL))
        return NAN;
    double E = 0.5 * v->m * s->vz * s->vz + 0.5 * v->I_y * s->vtheta * s->vtheta +
               tirenv_ride__tire_energy(&t_f, d_f) + tirenv_ride__tire_energy(&t_r, d_r);
    if (suspended) {
        const double d_s = s->z_a - z_fb;
        E += 0.5 * v->front.m_a * s->vz_a * s->vz_a + 0.5 * v->front.k_s * d_s * d_s;
    }
    return E;
}
