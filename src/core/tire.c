/* SPDX-License-Identifier: Apache-2.0 */
/* Default tire, default solver settings, and the physical-parameter check. */
#include "tirenv/tire.h"
#include "tirenv/cam.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

tirenv_eq_settings tirenv_eq_default(void)
{
    return (tirenv_eq_settings){
        .method = TIRENV_EQ_NEWTON,
        /* eps_z binds: 1e-10 m is 2e-5 to 1e-4 N at the models' vertical stiffnesses (2e5 to
         * 1e6 N/m), so eps_F asks for no more (1e-6 N asked for 2e-12 m at the ring's 4.5e5
         * N/m, a confirming force evaluation at some 4 in 10 of the ring's positions over the
         * bench cleat, 17 % of its evaluations, for nothing a curve prints: docs/models.md
         * 11.3). */
        .eps_F = 1e-4,
        .eps_z = 1e-10,
        .max_iter = 100,
        .secant_dz = 1e-3,
    };
}

const double tirenv_nominal_load_fractions[TIRENV_NOMINAL_LOADS] = {0.5, 0.75, 1.0, 1.25, 1.5};

/* The default tractor tire: a 14.9R28 (380/85R28) class drive tire at 1.2 bar.
 * R0 = 0.68 m is half its nominal 1.36 m overall diameter. The ring reference tire's values
 * come from the tire's construction and published data; c_r and c_b, VERTICAL_STIFFNESS and
 * Q_RA1/Q_RA2 are identified on the ring's flat ground by `tirenv identify`, and copied here
 * by scripts/identify-default-tire.sh (data/tires/default.tir gives the figures). */
tirenv_tire tirenv_tire_default(void)
{
    return (tirenv_tire){
        .springs = {
            .R0 = 0.68,
            .c_r = 407000,
            .c_b = 32800,
            .phi = M_PI,
            .dphi = M_PI / 360.0,
        },
        .width = 0.38,  /* 14.9 in section width, the 380 of 380/85R28 */
        .k_z = 3000,    /* a heave damping ratio of 0.08 on the default tractor (default.tir) */
        /* A radial 14.9R28 at 1.2 bar (data/tires/default.tir gives each value's reasoning):
         * 40 mm lugs of rubber, stiff against the foundation (sidewalls + air), which takes
         * the deflection; T = p*b*R = 120 kPa * 0.34 m * 0.64 m. */
        .ring = {
            .t_r = 0.04,
            .EI = 30,
            .T = 0,
            .k_c = 1.1e5,
            .k_t = 1.5e7,
            .G_t = 2.5e5, /* the lugs' effective shear modulus along the arc (5.3, 5.6) */
            .dtheta = M_PI / 720.0, /* 0.25 degrees, converged: docs/models.md section 5.6 */
            .lug_count = 0,
            .lug_fraction = 0.5,
            .lug_ratio = 1,
            .b_p = 0.34,
            .alpha_s = 1.05,
            .p = 1.2e5,
            .p_nom = 1.2e5,
        },
        .eq = tirenv_eq_default(),
        /* The cam (docs/models.md section 7): the dimensionless cam shape of TNO's public 205/60R15
         * (MF-Swift 6.2), which already scales with R0; the deflection and contact-length law
         * identified on the ring reference tire's flat ground (data/tires/default.tir says how). */
        .cam = {
            .c_z = 371000,
            .fnomin = 17900,
            .q_fz2 = 28.7,
            .q_ra1 = 0.461,
            .q_ra2 = 0.892,
            .shift = 0.8328,
            .length = 1.4634,
            .height = 0.9551,
            .order = 1.5257,
            .given = TIRENV_CAM_ALL,
        },
    };
}

/* The cam model's keys (docs/models.md section 7). ELLIPS_ORDER must exceed 1: the exact lift
 * (src/model/cam.c) relies on a strictly convex cam, whose touching height along a straight
 * segment has a single smooth maximum; MF-Swift's fitted orders are about 1.5 to 2. A negative
 * Q_RA2 is accepted (fitted files may have one); the contact length then peaks at some load,
 * and the cam model refuses loads beyond it. */
static int cam_check(const tirenv_cam_params *c, tirenv_diag *diag)
{
    if (!(c->c_z > 0 && isfinite(c->c_z)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "VERTICAL_STIFFNESS",
                            "must be positive (N/m), got %g", c->c_z);
    if (!(c->fnomin >= 0 && isfinite(c->fnomin)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "FNOMIN",
                            "must be zero (none) or positive (N), got %g", c->fnomin);
    if (!isfinite(c->q_fz2) || (c->q_fz2 != 0 && !(c->fnomin > 0)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "Q_FZ2",
                            "must be finite, and needs FNOMIN (the load it refers to) when not "
                            "0, got %g with FNOMIN %g", c->q_fz2, c->fnomin);
    if (!(c->q_fz1 >= 0 && isfinite(c->q_fz1)) || (c->q_fz1 != 0 && !(c->fnomin > 0)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "Q_FZ1",
                            "must be 0 (from VERTICAL_STIFFNESS) or positive, and needs FNOMIN "
                            "(the load it refers to) when not 0, got %g with FNOMIN %g",
                            c->q_fz1, c->fnomin);
    if (!isfinite(c->pfz1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "PFZ1", "must be finite, got %g",
                            c->pfz1);
    if (!(c->q_ra1 >= 0 && isfinite(c->q_ra1)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "Q_RA1",
                            "must be zero or positive, got %g", c->q_ra1);
    if (!isfinite(c->q_ra2) || !(c->q_ra1 > 0 || c->q_ra2 > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "Q_RA2",
                            "must be finite, and positive if Q_RA1 is 0 (no contact length "
                            "otherwise), got %g", c->q_ra2);
    if (!(c->shift > 0 && isfinite(c->shift)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ELLIPS_SHIFT",
                            "must be positive, got %g", c->shift);
    if (!(c->length > 0 && isfinite(c->length)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ELLIPS_LENGTH",
                            "must be positive, got %g", c->length);
    if (!(c->height > 0 && isfinite(c->height)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ELLIPS_HEIGHT",
                            "must be positive, got %g", c->height);
    if (!(c->order > 1 && isfinite(c->order)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ELLIPS_ORDER",
                            "must be greater than 1 (a convex, rounded cam), got %g", c->order);
    return TIRENV_OK;
}

/* Where a value is plausible for a tire, from a scooter's to a mining truck's, as
 * docs/formats.md section 2 lists with each range's reason. A value outside is a typo or a
 * unit slip (1e308, 1e-308, kN for N), which the models would otherwise turn into results
 * that look like numbers (a cam load of 4.7e-310 N, a ring peak above the cleat). */
static int plausible(const char *key, double value, double lo, double hi, const char *unit,
                     tirenv_diag *diag)
{
    if (value >= lo && value <= hi)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, key,
                        "%g %s is outside the plausible range [%g, %g] %s of a tire "
                        "(docs/formats.md section 2)", value, unit, lo, hi, unit);
}

/* Most nodes of the ring (2 round(pi/NODE_ANGLE)): 36,000, a node every 0.01 degree, 50
 * times the default's 720. Each costs memory and time in every evaluation; NODE_ANGLE =
 * 1e-20 overflowed the count. */
#define TIRE_RING_MAX_NODES 36000.0

/* The ranges of docs/formats.md section 2, checked once the signs and relations have been. */
static int tire_plausible(const tirenv_tire *tire, tirenv_diag *diag)
{
    const tirenv_springs_params *s = &tire->springs;
    const tirenv_ring_params *r = &tire->ring;
    const tirenv_cam_params *c = &tire->cam;
    const tirenv_eq_settings *eq = &tire->eq;
    int status;
    if ((status = plausible("UNLOADED_RADIUS", s->R0, 0.05, 5, "m", diag)) ||
        (status = plausible("WIDTH", tire->width, 0, 5, "m", diag)) ||
        (status = plausible("RADIAL_STIFFNESS", s->c_r, 1e3, 1e12, "N/m per rad", diag)) ||
        (status = plausible("INTERRADIAL_STIFFNESS", s->c_b, 0, 1e8, "N*rad/m", diag)) ||
        (status = plausible("SIDEWALL_STIFFNESS", s->k_s, 0, 1e10, "N/m", diag)) ||
        (status = plausible("SIDEWALL_PRELOAD", s->F_s0, 0, 1e7, "N", diag)) ||
        (status = plausible("BELT_BENDING_STIFFNESS", r->EI, 0, 1e5, "N*m^2", diag)) ||
        (status = plausible("BELT_PRETENSION", r->T, 0, 1e7, "N", diag)) ||
        (status = plausible("FOUNDATION_STIFFNESS", r->k_c, 0, 1e10, "N/m^2", diag)) ||
        (status = plausible("TREAD_STIFFNESS", r->k_t, 1e5, 1e13, "N/m^2", diag)) ||
        (status = plausible("TREAD_SHEAR", r->G_t, 0, 1e9, "Pa", diag)) ||
        (status = plausible("CARCASS_SOFTENING_DEFLECTION", r->w_cs, 0, 0.5, "m", diag)) ||
        (status = plausible("CARCASS_LINEAR_DEFLECTION", r->w_c0, 0, 0.5, "m", diag)) ||
        (status = plausible("NODE_ANGLE", r->dtheta, 2 * M_PI / TIRE_RING_MAX_NODES,
                            M_PI / 8, "rad", diag)) ||
        (status = plausible("FORCE_TOLERANCE", eq->eps_F, 0, 100, "N", diag)) ||
        (status = plausible("STEP_TOLERANCE", eq->eps_z, 0, 1e-3, "m", diag)) ||
        (status = plausible("MAX_ITERATIONS", (double)eq->max_iter, 2, 1e6, "evaluations",
                            diag)) ||
        (status = plausible("SECANT_STEP", eq->secant_dz, 0, 0.1, "m", diag)) ||
        (status = plausible("VERTICAL_STIFFNESS", c->c_z, 1e4, 1e8, "N/m", diag)) ||
        (status = isnan(tire->k_z) ? TIRENV_OK
                                   : plausible("VERTICAL_DAMPING", tire->k_z, 0, 1e6, "N*s/m",
                                               diag)) ||
        (status = plausible("Q_RA1", c->q_ra1, 0, 10, "(dimensionless)", diag)) ||
        (status = plausible("Q_RA2", c->q_ra2, -10, 10, "(dimensionless)", diag)) ||
        (status = plausible("ELLIPS_SHIFT", c->shift, 0, 5, "(dimensionless)", diag)) ||
        (status = plausible("ELLIPS_LENGTH", c->length, 0, 10, "(dimensionless)", diag)) ||
        (status = plausible("ELLIPS_HEIGHT", c->height, 0, 10, "(dimensionless)", diag)) ||
        (status = plausible("ELLIPS_ORDER", c->order, 1, 100, "(dimensionless)", diag)) ||
        (status = plausible("ELLIPS_MAX_STEP", c->max_step, 0, s->R0, "m", diag)))
        return status;
    return TIRENV_OK;
}

/* The radius first, and its range before any relation that derives from it (the air's tension
 * p*b*R); the width and the damping. */
static int size_check(const tirenv_tire *tire, tirenv_diag *diag)
{
    const double R0 = tire->springs.R0;
    if (!(R0 > 0 && isfinite(R0)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "UNLOADED_RADIUS",
                            "must be a positive length in m, got %g", R0);
    const int status = plausible("UNLOADED_RADIUS", R0, 0.05, 5, "m", diag);
    if (status)
        return status;
    if (!(tire->width >= 0 && isfinite(tire->width)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "WIDTH",
                            "must be a length >= 0 in m, got %g", tire->width);
    /* NAN is "none given" (the ride then needs the vehicle's TIRE_DAMPING). */
    if (!isnan(tire->k_z) && !(tire->k_z >= 0 && isfinite(tire->k_z)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "VERTICAL_DAMPING",
                            "must be zero or positive (N*s/m), got %g", tire->k_z);
    return TIRENV_OK;
}

/* [ENVELOPING_SPRINGS]. */
static int springs_check(const tirenv_springs_params *s, tirenv_diag *diag)
{
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
    if (s->contact != TIRENV_SPRINGS_CONTINUOUS && s->contact != TIRENV_SPRINGS_RAYS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "CONTACT",
                            "unknown springs contact %d", (int)s->contact);
    if (!(s->k_s >= 0 && isfinite(s->k_s)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "SIDEWALL_STIFFNESS",
                            "must be zero (no sidewall) or positive (N/m), got %g", s->k_s);
    if (!(s->F_s0 >= 0 && isfinite(s->F_s0)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "SIDEWALL_PRELOAD",
                            "must be zero or positive (N), got %g", s->F_s0);
    if (s->F_s0 > 0 && s->k_s == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "SIDEWALL_PRELOAD",
                            "%g N needs a sidewall: SIDEWALL_STIFFNESS is 0 (none)", s->F_s0);
    if (s->phi / s->dphi > 1e6)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "ELEMENT_ANGLE",
                            "gives more than a million elements (%g rad)", s->dphi);
    return TIRENV_OK;
}

/* [ENVELOPING_RING]'s values one by one, and the pressures (R0: the tire's radius, m). */
static int ring_values_check(const tirenv_ring_params *r, double R0, tirenv_diag *diag)
{
    if (!(r->t_r >= 0 && r->t_r < R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "TREAD_THICKNESS",
                            "must be in [0, UNLOADED_RADIUS) m, got %g", r->t_r);
    if (!(r->EI >= 0 && isfinite(r->EI)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "BELT_BENDING_STIFFNESS",
                            "must be zero or positive (N*m^2), got %g", r->EI);
    if (!(r->T >= 0 && isfinite(r->T)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "BELT_PRETENSION",
                            "must be zero or positive (N), got %g", r->T);
    if (!(r->k_c >= 0 && isfinite(r->k_c)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "FOUNDATION_STIFFNESS",
                            "must be zero or positive (N/m^2), got %g", r->k_c);
    if (!(r->p >= 0 && r->p < 1e8))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "INFLPRES",
                            "must be zero or a positive pressure below 1e8 Pa, got %g", r->p);
    if (!(r->p_nom >= 0 && r->p_nom < 1e8))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "NOMPRES",
                            "must be zero or a positive pressure below 1e8 Pa, got %g",
                            r->p_nom);
    if (!(r->b_p >= 0 && r->b_p < 2 * R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "BELT_WIDTH",
                            "must be in [0, 2 UNLOADED_RADIUS) m, got %g", r->b_p);
    if (r->contact != TIRENV_RING_CONTINUOUS && r->contact != TIRENV_RING_RAYS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "CONTACT",
                            "unknown ring contact %d", (int)r->contact);
    if (!(r->alpha_s >= 0.1 && r->alpha_s <= M_PI / 2))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "SIDEWALL_ANGLE",
                            "must be in [0.1, pi/2] rad, got %g", r->alpha_s);
    if (!(r->k_t > 0 && isfinite(r->k_t)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "TREAD_STIFFNESS",
                            "must be positive (N/m^2), got %g", r->k_t);
    if (!(r->G_t >= 0 && isfinite(r->G_t)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "TREAD_SHEAR",
                            "must be zero or a positive shear modulus (Pa), got %g", r->G_t);
    return TIRENV_OK;
}

/* The belt's stiffness per mode is EI s^2/R^4 + T_p s/R^2 + k_f with s = n^2 - 1 >= -1,
 * T_p = T + p b R and k_f = k_c + gamma p (the air's shares, docs/models.md section 5.1;
 * gamma as tirenv_ring__sidewall_gamma); pretension lowers it for n = 0, and too much makes
 * it negative: the belt buckles. s_min is the s of the least. */
typedef struct {
    double R, gamma, T_p, k_f, s_min; /* m, -, N, N/m^2, - */
} belt_modes;

static belt_modes belt_modes_of(const tirenv_ring_params *r, double R0)
{
    belt_modes m;
    const double a = r->alpha_s;
    m.R = R0 - r->t_r;
    m.gamma = (a * sin(a) + cos(a)) / (sin(a) - a * cos(a));
    m.T_p = r->T + r->p * r->b_p * m.R;
    m.k_f = r->k_c + m.gamma * r->p;
    m.s_min = fmax(-1, -m.T_p * m.R * m.R / (2 * fmax(r->EI, 1e-300)));
    return m;
}

/* The least mode's stiffness on a foundation of k_f, N/m^2. */
static double least_mode(const tirenv_ring_params *r, const belt_modes *m, double k_f)
{
    const double R = m->R, s_min = m->s_min;
    return r->EI * s_min * s_min / (R * R * R * R) + m->T_p * s_min / (R * R) + k_f;
}

/* The foundation carries the belt, and the belt does not buckle on it. */
static int foundation_check(const tirenv_ring_params *r, const belt_modes *m,
                            tirenv_diag *diag)
{
    const double e_min = least_mode(r, m, m->k_f);
    /* 1e3 N/m^2: the plausible range's floor for the whole foundation (carcass and air). */
    if (!(m->k_f >= 1e3))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "FOUNDATION_STIFFNESS",
                            "the sidewalls carry almost nothing: FOUNDATION_STIFFNESS %g N/m^2 "
                            "and INFLPRES %g Pa give a foundation of %g N/m^2, below 1e3",
                            r->k_c, r->p, m->k_f);
    if (!(e_min > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "BELT_PRETENSION",
                            "%g N (with the air's) buckles the belt on its foundation "
                            "(%g N/m^2 too soft)", m->T_p, m->k_f);
    return TIRENV_OK;
}

/* The softening carcass (docs/models.md section 5.1): its tangent k_c exp(-(w - w_0)/w_s)
 * falls towards 0 as the belt is pressed in, so the foundation's tangent is at least the air's
 * gamma p and the belt's least mode stiffness at least that bound with k_f = gamma p: the
 * contact energy stays strictly convex, its minimum unique. Only the shear-coupled tread's
 * continuous contact solves it (ring_shear.c), on a smooth tread. */
static int carcass_check(const tirenv_ring_params *r, const belt_modes *m, tirenv_diag *diag)
{
    if (!(r->w_cs >= 0 && isfinite(r->w_cs)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "CARCASS_SOFTENING_DEFLECTION",
                            "must be zero (a linear carcass) or a positive length in m, got %g",
                            r->w_cs);
    if (!(r->w_c0 >= 0 && isfinite(r->w_c0)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "CARCASS_LINEAR_DEFLECTION",
                            "must be a length >= 0 in m, got %g", r->w_c0);
    if (!(r->w_cs > 0))
        return TIRENV_OK;
    if (r->contact != TIRENV_RING_CONTINUOUS || !(r->G_t > 0) || !(r->b_p > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "CARCASS_SOFTENING_DEFLECTION",
                            "needs the shear-coupled tread's continuous contact (CONTACT "
                            "'continuous', TREAD_SHEAR and BELT_WIDTH > 0); got CONTACT "
                            "'%s', TREAD_SHEAR %g Pa, BELT_WIDTH %g m",
                            r->contact == TIRENV_RING_RAYS ? "rays" : "continuous", r->G_t,
                            r->b_p);
    if (r->lug_count > 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "CARCASS_SOFTENING_DEFLECTION",
                            "needs a smooth tread (LUG_COUNT 0), got LUG_COUNT %g",
                            r->lug_count);
    const double k_a = m->gamma * r->p;
    const double e_air = least_mode(r, m, k_a);
    if (!(k_a >= 1e3) || !(e_air > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "CARCASS_SOFTENING_DEFLECTION",
                            "%g m: a carcass that softens leaves the belt's foundation the "
                            "air's %g N/m^2 (INFLPRES %g Pa) when pressed far in, %s",
                            r->w_cs, k_a, r->p,
                            k_a >= 1e3 ? "on which the belt buckles (BELT_PRETENSION and "
                                         "the air's tension)"
                                       : "below 1e3 N/m^2");
    return TIRENV_OK;
}

/* The ring's nodes and its tread's lugs. */
static int tread_check(const tirenv_ring_params *r, tirenv_diag *diag)
{
    if (!(r->dtheta > 0 && r->dtheta <= M_PI / 8))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "NODE_ANGLE",
                            "must be in (0, pi/8] rad, got %g", r->dtheta);
    if (!(r->lug_count >= 0 && r->lug_count == floor(r->lug_count) && r->lug_count < 1000))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "LUG_COUNT",
                            "must be a whole number in [0, 1000), got %g", r->lug_count);
    if (!(r->lug_fraction > 0 && r->lug_fraction < 1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "LUG_FRACTION",
                            "must be in (0, 1), got %g", r->lug_fraction);
    if (!(r->lug_ratio > 0 && r->lug_ratio <= 1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "LUG_GROOVE_RATIO",
                            "must be in (0, 1], got %g", r->lug_ratio);
    return TIRENV_OK;
}

/* [ENVELOPING_SOLVER]. */
static int solver_check(const tirenv_eq_settings *eq, tirenv_diag *diag)
{
    if (!(eq->eps_F > 0 && isfinite(eq->eps_F)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "FORCE_TOLERANCE",
                            "must be a positive force in N, got %g", eq->eps_F);
    if (!(eq->eps_z > 0 && isfinite(eq->eps_z)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "STEP_TOLERANCE",
                            "must be a positive length in m, got %g", eq->eps_z);
    if (eq->max_iter < 2) /* the secant needs two points */
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "MAX_ITERATIONS",
                            "must be at least 2, got %zu", eq->max_iter);
    if (!(eq->secant_dz > 0 && isfinite(eq->secant_dz)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "SECANT_STEP",
                            "must be a positive length in m, got %g", eq->secant_dz);
    if (eq->method > TIRENV_EQ_BRENT)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "METHOD",
                            "unknown equilibrium method %d", (int)eq->method);
    return TIRENV_OK;
}

/* The vertical law's pressure factor (docs/models.md section 7.3) must carry a load. */
static int pressure_factor_check(const tirenv_tire *tire, tirenv_diag *diag)
{
    if (tire->cam.pfz1 != 0 && !(tire->ring.p_nom > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "PFZ1",
                            "%g needs NOMPRES, the pressure it refers to, got NOMPRES %g Pa",
                            tire->cam.pfz1, tire->ring.p_nom);
    if (!(tirenv_cam_pressure_factor(tire->cam.pfz1, tire->ring.p, tire->ring.p_nom) > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "PFZ1",
                            "%g at INFLPRES %g Pa, NOMPRES %g Pa leaves the vertical law no load: "
                            "1 + PFZ1*(INFLPRES - NOMPRES)/NOMPRES = %g, positive expected",
                            tire->cam.pfz1, tire->ring.p, tire->ring.p_nom,
                            tirenv_cam_pressure_factor(tire->cam.pfz1, tire->ring.p,
                                                       tire->ring.p_nom));
    return TIRENV_OK;
}

/* Signs and relations first, the first that fails said, then the plausible ranges. */
int tirenv_tire_check(const tirenv_tire *tire, tirenv_diag *diag)
{
    const double R0 = tire->springs.R0;
    int status;
    if ((status = size_check(tire, diag)) || (status = springs_check(&tire->springs, diag)) ||
        (status = ring_values_check(&tire->ring, R0, diag)))
        return status;
    const belt_modes m = belt_modes_of(&tire->ring, R0);
    if ((status = foundation_check(&tire->ring, &m, diag)) ||
        (status = carcass_check(&tire->ring, &m, diag)) ||
        (status = tread_check(&tire->ring, diag)) || (status = solver_check(&tire->eq, diag)) ||
        (status = cam_check(&tire->cam, diag)) || (status = pressure_factor_check(tire, diag)))
        return status;
    return tire_plausible(tire, diag);
}

int tirenv_tire_check_cam_keys(const tirenv_tire *tire, tirenv_diag *diag)
{
    static const struct { unsigned bit; const char *key; } keys[] = {
        {TIRENV_CAM_C_Z, "VERTICAL_STIFFNESS"}, {TIRENV_CAM_Q_RA1, "Q_RA1"},
        {TIRENV_CAM_Q_RA2, "Q_RA2"}, {TIRENV_CAM_SHIFT, "ELLIPS_SHIFT"},
        {TIRENV_CAM_LENGTH, "ELLIPS_LENGTH"}, {TIRENV_CAM_HEIGHT, "ELLIPS_HEIGHT"},
        {TIRENV_CAM_ORDER, "ELLIPS_ORDER"},
    };
    char missing[160] = "";
    const char *first = NULL;
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        if (!(tire->cam.given & keys[k].bit)) {
            const size_t n = strlen(missing);
            snprintf(missing + n, sizeof missing - n, "%s%s", n ? ", " : "", keys[k].key);
            first = first ? first : keys[k].key;
        }
    if (!first)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, first, "the tire has no value of its own "
                        "for the cam keys %s ([VERTICAL], [CONTACT_PATCH] of an MF-Swift "
                        ".tir file); the cam model needs them: add them to the tire file",
                        missing);
}
