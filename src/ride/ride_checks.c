/* What the ride checks before and while it integrates (docs/models.md section 9.6): that the
 * fixed RK4 step resolves the stiffest mode of the vehicle, that the static loads leave the
 * dynamic tire forces resolvable in double precision, and that every sample is finite.
 * SPDX-License-Identifier: Apache-2.0 */
#include "ride/ride_impl.h"

#include <float.h>
#include <math.h>
#include "core/eigen.h"

/* The largest |lambda| of the linear system with every tire on the ground (lift-off only
 * removes stiffness and damping), linearised at the static loads: a tire file's spring, whose
 * force follows its vertical law (ride_tire.c), enters as that law's tangent k_t there.
 * Generalised coordinates q = (z, theta[, z_a]), mass matrix M, and each spring-damper adds
 * k*e*e^T to K and c*e*e^T to C, with e the change of its length per unit q: a rigid front
 * axle's tires e = (1, a), the rear's (1, -b); a suspended front axle's tires e = (0, 0, 1)
 * and its suspension (1, a, -1). The state matrix is A = [[0, I], [-M^-1 K, -M^-1 C]]. */
int tirenv_ride__fastest_mode(const tirenv_vehicle *v, double *lambda_max, tirenv_diag *diag)
{
    const int suspended = v->front.k_s > 0;
    const size_t n = suspended ? 3 : 2, N = 2 * n;
    double K[3][3] = {{0}}, C[3][3] = {{0}};
    const double mass[3] = {v->m, v->I_y, v->front.m_a};
    struct {
        double e[3], k, c;
    } springs[3] = {
        {{1, -v->b, 0}, v->rear.tires * v->rear.k_t, v->rear.tires * v->rear.c_t},
        {{1, v->a, 0}, v->front.tires * v->front.k_t, v->front.tires * v->front.c_t},
        {{1, v->a, -1}, v->front.k_s, v->front.c_s},
    };
    if (suspended)
        springs[1].e[0] = 0, springs[1].e[1] = 0, springs[1].e[2] = 1;
    for (size_t s = 0; s < (suspended ? 3u : 2u); ++s)
        for (size_t i = 0; i < n; ++i)
            for (size_t j = 0; j < n; ++j) {
                K[i][j] += springs[s].k * springs[s].e[i] * springs[s].e[j];
                C[i][j] += springs[s].c * springs[s].e[i] * springs[s].e[j];
            }
    double A[6 * 6] = {0};
    for (size_t i = 0; i < n; ++i) {
        A[i * N + n + i] = 1;
        for (size_t j = 0; j < n; ++j) {
            A[(n + i) * N + j] = -K[i][j] / mass[i];
            A[(n + i) * N + n + j] = -C[i][j] / mass[i];
        }
    }
    double complex eval[6];
    const int rc = tirenv_core__eigenvalues(N, A, eval);
    if (rc == 1)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "the vehicle's modes are not "
                            "finite: its stiffnesses, dampings and masses overflow");
    if (rc)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "", "the vehicle's modes could not "
                            "be found: the QR iteration did not converge");
    *lambda_max = 0;
    for (size_t i = 0; i < N; ++i)
        *lambda_max = fmax(*lambda_max, cabs(eval[i]));
    if (!isfinite(*lambda_max))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "the vehicle's modes are not "
                            "finite: its stiffnesses, dampings and masses overflow");
    return TIRENV_OK;
}

/* RK4's amplification per step on a mode e^(lambda t) is the Taylor polynomial of e^(h
 * lambda) to the fourth power, in error by about |h lambda|^5/120 of the mode each step;
 * past |h lambda| = 2.785 (the real axis; 2.828 on the imaginary) it grows without bound.
 * At |h lambda| <= RK4_MAX_H_LAMBDA = 0.5 the error is 2.6e-4 per step, and over a 0.30 x
 * 0.05 m cleat at 10 km/h with point contact a_wz agreed with RK8PD's within 0.6 % at 0.57
 * (3.5 % at 0.99, 13 % at 1.8): a margin of 5.6 under the stability limit. The default
 * tractor at dt 1 ms runs at 0.01. */
int tirenv_ride__rk4_check(const tirenv_vehicle *v, double h, double dt, size_t n_sub,
                           tirenv_diag *diag)
{
    double lambda = 0;
    const int status = tirenv_ride__fastest_mode(v, &lambda, diag);
    if (status || !(h * lambda > RK4_MAX_H_LAMBDA))
        return status;
    return tirenv_error(diag, TIRENV_ERANGE, "", 0, "dt",
                        "RK4's step %g s (dt %g s in %zu substeps) is too long for the "
                        "vehicle's fastest mode (linear, each tire's spring its tangent at the "
                        "static load), |lambda| = %.4g 1/s (%.4g Hz): h*|lambda| = "
                        "%.3g exceeds %g, where RK4 stays within about 1 %% (it is unstable "
                        "past 2.8); use the adaptive rk8pd solver, or dt of at most %.3g s",
                        h, dt, n_sub, lambda, lambda / (2 * M_PI), h * lambda,
                        RK4_MAX_H_LAMBDA, RK4_MAX_H_LAMBDA / lambda);
}

/* The tire forces are F0 + n*k_t*(w - z), to first order under a tire file's law (k_t its
 * tangent at the static load): a static load F0 is rounded to F0*DBL_EPSILON, the force of a
 * deflection of d0*DBL_EPSILON with d0 = F0/(n*k_t) the static deflection. Beyond
 * RESOLUTION_M (1 um, finer than any road input) the dynamic forces drown in the rounding of
 * the static ones: MASS = 1e30 left every seat acceleration exactly 0 (a crest factor of
 * 0/0). Such a vehicle, whose tires would sink d0 > 4.5e9 m, is refused. */
static const double RESOLUTION_M = 1e-6;

int tirenv_ride__static_check(const tirenv_vehicle *v, tirenv_diag *diag)
{
    for (int axle = 0; axle < 2; ++axle) {
        const tirenv_axle *ax = axle ? &v->rear : &v->front;
        const double F0 = tirenv_vehicle_tire_load(v, axle);             /* N */
        const double d0 = F0 / ax->k_t;                                    /* m */
        if (isnan(ax->k_t) && isfinite(F0))
            continue;  /* the tire file's, checked once tirenv_vehicle_tires has set it */
        if (isnan(ax->k_t))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "MASS",
                                "the %s tires' static load (from MASS) is %g N: expected a "
                                "finite load", axle ? "rear" : "front", F0);
        /* A load that overflows is MASS's (1e308 kg), not the tire stiffness's. */
        const char *field = !isfinite(F0) ? "MASS"
                            : axle        ? "REAR_AXLE.TIRE_STIFFNESS"
                                          : "FRONT_AXLE.TIRE_STIFFNESS";
        if (!(d0 * DBL_EPSILON <= RESOLUTION_M))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, field,
                                "the %s tires' static deflection, their load %g N (from MASS) "
                                "over TIRE_STIFFNESS %g N/m, is %g m: unphysical, and in double "
                                "precision it leaves the dynamic tire forces unresolved below "
                                "%g m of deflection; expected at most %g m", axle ? "rear" : "front",
                                tirenv_vehicle_tire_load(v, axle), ax->k_t, d0,
                                d0 * DBL_EPSILON, RESOLUTION_M / DBL_EPSILON);
    }
    return TIRENV_OK;
}

int tirenv_ride__finite_sample(const tirenv_ride_sample *s, tirenv_diag *diag)
{
    const double v[] = {s->z,      s->vz,      s->az,      s->theta,   s->vtheta, s->atheta,
                        s->z_a,    s->vz_a,    s->seat_az, s->seat_ax, s->F_front, s->F_rear};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; ++i)
        if (!isfinite(v[i]))
            return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "",
                                "the ride's state is not finite at t = %.6g s (x_front = "
                                "%.6g m): the integration diverged", s->t, s->x_front);
    return TIRENV_OK;
}
