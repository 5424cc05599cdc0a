/* The force of an axle's tires at their deflection (docs/models.md section 9.3): its tire
 * file's vertical law where the vehicle gives no TIRE_STIFFNESS, or the linear spring k_t it
 * gives. SPDX-License-Identifier: Apache-2.0
 *
 * With the law F_z(rho), per tire at the deflection d = w - z_axle from the static one:
 *     G = G0 + (F_z(rho0 + d) - F_z(rho0)) + c_t*d_dot   while rho0 + d > 0,   G = 0 off it,
 * rho0 the law's deflection under the static load G0. F_z(rho0) is G0 to round-off, and taken
 * out so that G is G0 at rest exactly: the static loads then balance the weights to the bit, and
 * level ground leaves the seat exactly still, as with the linear spring. A
 * tire off the ground carries nothing, its damper included: with the damper alone, a tire
 * still in the air would push as soon as it moved towards the ground. The linear spring is
 *     G = G0 + k_t*d + c_t*d_dot,
 * the ride's tire until the law replaced it, kept bit for bit for vehicles that give k_t;
 * its tire lifts off where that line crosses zero. */
#include "ride/ride_impl.h"

#include <math.h>

int tirenv_ride__tire_set(tirenv_ride__tire *t, const tirenv_axle *ax, double G0,
                          const char *name, tirenv_diag *diag)
{
    *t = (tirenv_ride__tire){.n = ax->tires, .G0 = G0, .k_t = ax->k_t, .c_t = ax->c_t,
                             .law = ax->law, .has_law = ax->law.factor > 0};
    if (!t->has_law)
        return TIRENV_OK;
    t->rho0 = tirenv_cam_vertical_deflection(&ax->law, G0);
    t->F_rho0 = tirenv_cam_vertical_contact(&ax->law, t->rho0);
    if (t->rho0 > 0 && isfinite(t->rho0))
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, name,
                        "the tire's vertical law (FNOMIN %g N, VERTICAL_STIFFNESS %g N/m, "
                        "Q_FZ2 %g, docs/models.md section 7.3) has no deflection under the "
                        "static tire load %g N (got %g m): expected a law that carries it",
                        ax->law.fnomin, ax->law.c_z, ax->law.q_fz2, G0, t->rho0);
}

double tirenv_ride__tire_load(const tirenv_ride__tire *t, double d, double d_dot)
{
    if (!t->has_law)
        return t->G0 + t->k_t * d + t->c_t * d_dot;
    const double rho = t->rho0 + d;
    return rho > 0 ? t->G0 + (tirenv_cam_vertical_contact(&t->law, rho) - t->F_rho0) +
                         t->c_t * d_dot
                   : 0;
}

/* The linear spring's as the ride always computed it, n*G0 + n*(...): other roundings than
 * n times the load of one tire, which old vehicle files keep. */
double tirenv_ride__tire_force(const tirenv_ride__tire *t, double d, double d_dot)
{
    const double F = t->has_law ? t->n * tirenv_ride__tire_load(t, d, d_dot)
                                : t->n * t->G0 + t->n * (t->k_t * d + t->c_t * d_dot);
    return F > 0 ? F : 0;
}

/* The spring's energy above its static state, less the static load's work: the law's
 * integral W(rho0 + d) - W(rho0) - G0*d, or k_t*d^2/2. Its derivative in d is the spring's
 * force less G0, which is what gravity balances. */
double tirenv_ride__tire_energy(const tirenv_ride__tire *t, double d)
{
    if (!t->has_law)
        return t->n * 0.5 * t->k_t * d * d;
    return t->n * (tirenv_cam_vertical_work(&t->law, t->rho0 + d) -
                   tirenv_cam_vertical_work(&t->law, t->rho0) - t->G0 * d);
}
