/* Default tire, default solver settings, and the physical-parameter check. */
#include "tirenv/tire.h"

#include <math.h>

tirenv_eq_settings tirenv_eq_default(void)
{
    return (tirenv_eq_settings){
        .method = TIRENV_EQ_NEWTON,
        .eps_F = 1e-6,
        .eps_z = 1e-10,
        .max_iter = 100,
        .secant_dz = 1e-3,
    };
}

/* The default tractor tire: a 14.9R28 / 420/85R28-class drive tire at about 1.4 bar.
 * R0 = 0.68 m is half its nominal 1.36 m overall diameter. c_r and c_b are chosen so that the
 * flat-ground contact lengths 0.28 / 0.33 / 0.38 m come at loads a tire of this class carries
 * (see data/tires/default.tir for the figures and reasoning). */
tirenv_tire tirenv_tire_default(void)
{
    return (tirenv_tire){
        .springs = {
            .R0 = 0.68,
            .c_r = 1.6e6,
            .c_b = 1.0e4,
            .phi = M_PI,
            .dphi = M_PI / 360.0,
        },
        .eq = tirenv_eq_default(),
    };
}

int tirenv_tire_check(const tirenv_tire *tire, tirenv_diag *diag)
{
    const tirenv_springs_params *s = &tire->springs;
    const tirenv_eq_settings *eq = &tire->eq;
    if (!(s->R0 > 0 && isfinite(s->R0)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "UNLOADED_RADIUS",
                            "must be a positive length in m, got %g", s->R0);
    if (!(s->c_r > 0 && isfinite(s->c_r)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "RADIAL_STIFFNESS",
                            "must be positive (N/m per rad), got %g", s->c_r);
    if (!(s->c_b >= 0 && isfinite(s->c_b)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "INTERRADIAL_STIFFNESS",
                            "must be zero or positive (N*rad/m), got %g", s->c_b);
    if (!(s->phi > 0 && s->phi <= M_PI * (1 + 1e-12)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "SEGMENT_ANGLE",
                            "must be in (0, pi] rad, got %g", s->phi);
    if (!(s->dphi > 0 && s->dphi <= 0.5 * s->phi * (1 + 1e-12)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ELEMENT_ANGLE",
                            "must be in (0, SEGMENT_ANGLE/2] rad, got %g", s->dphi);
    if (s->phi / s->dphi > 1e6)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ELEMENT_ANGLE",
                            "gives more than a million elements (%g rad)", s->dphi);
    if (!(eq->eps_F > 0) || !(eq->eps_z > 0) || eq->max_iter < 2 || !(eq->secant_dz > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "EQUILIBRIUM",
                            "tolerances must be positive and max_iter >= 2");
    if (eq->method > TIRENV_EQ_BRENT)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "EQUILIBRIUM_METHOD",
                            "unknown method %d", (int)eq->method);
    return TIRENV_OK;
}
