/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: tire parameters and solver settings (the contents of a .tir file, docs/formats.md
 * section 2). */
#ifndef TIRENV_TIRE_H
#define TIRENV_TIRE_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"

TIRENV_BEGIN_DECLS

/* How the constant-load equilibrium F_z(x, z) = G_T is solved in z (docs/models.md section 11). */
typedef enum {
    TIRENV_EQ_NEWTON = 0, /* default: Newton on dF_z/dz inside a bracket, bisection fallback */
    TIRENV_EQ_SECANT,     /* the paper's plain secant iteration (its eq. 2), for comparison */
    TIRENV_EQ_BRENT       /* Brent-Dekker on the bracket, a derivative-free baseline */
} tirenv_eq_method;

/* Tolerances of the equilibrium iteration. Convergence needs both |F_z - G_T| <= eps_F and
 * |dz| <= eps_z, or (bracketing methods) a bracket narrower than eps_z: F_z jumps where a ray
 * sweeps over a convex corner, and then the equilibrium is the jump, located to eps_z. */
typedef struct {
    tirenv_eq_method method;
    double eps_F;          /* force tolerance, N */
    double eps_z;          /* step tolerance, m */
    size_t max_iter;       /* force evaluations allowed per position */
    double secant_dz;      /* secant only: offset of the second starting point, m */
} tirenv_eq_settings;

/* How the springs model's tread meets the ground (docs/models.md sections 4.3 and 4.8):
 * [ENVELOPING_SPRINGS] CONTACT. */
typedef enum {
    TIRENV_SPRINGS_CONTINUOUS = 0, /* 'continuous': the tread between neighbouring elements is a
                                    * curve, every ground vertex under it is a constraint */
    TIRENV_SPRINGS_RAYS = 1        /* 'rays': each element touches only along its ray (the paper) */
} tirenv_springs_contact;

/* Parameters of the radial + interradial springs model (docs/models.md section 4); the rigid model
 * uses R0 only. Stiffnesses are discretisation-independent: k_r = c_r*dphi, k_ir = c_b/dphi. */
typedef struct {
    double R0;             /* [DIMENSION] UNLOADED_RADIUS: free radius, m */
    double c_r;            /* RADIAL_STIFFNESS: radial stiffness per radian, N/m/rad */
    double c_b;            /* INTERRADIAL_STIFFNESS: interradial stiffness, N*rad/m */
    double phi;            /* SEGMENT_ANGLE: width of the tread segment, rad */
    double dphi;           /* ELEMENT_ANGLE: angle between adjacent radial elements, rad */
    tirenv_springs_contact contact; /* CONTACT: 'continuous' (default, 0) or 'rays' */
    double k_s;            /* SIDEWALL_STIFFNESS: a sidewall spring in series between the rim
                            * and the elements' centre, N/m; 0: none, the paper's model
                            * (docs/models.md section 4.9) */
    double F_s0;           /* SIDEWALL_PRELOAD: the load the sidewall carries before it gives,
                            * N: its deflection is max(0, F - F_s0)/k_s; 0: linear */
} tirenv_springs_params;

/* How the ring's tread meets the ground ([ENVELOPING_RING] CONTACT, docs/models.md section
 * 5.3): the tread surface continuous between nodes (the default), or one ray per node as the
 * paper's springs model casts them. */
typedef enum {
    TIRENV_RING_CONTINUOUS = 0, /* 'continuous' */
    TIRENV_RING_RAYS = 1        /* 'rays' */
} tirenv_ring_contact_kind;

/* Parameters of the flexible-ring reference tire (docs/models.md section 5): a belt of radius
 * R = R0 - t_r on a foundation of sidewalls, carried by its inflation pressure p, with a tread
 * layer between belt and ground. Energy per unit belt length: 1/2 EI ((w''+w)/R^2)^2 +
 * 1/2 (T_p/R^2)(w'^2 - w^2) + 1/2 k_f w^2 with the tension T_p = T + p b R (the air's follower
 * load on the crown) and the foundation k_f = k_c + gamma(alpha) p (the sidewalls as membranes
 * under the air, plus the carcass's own k_c); docs/models.md section 5.1. */
typedef struct {
    double t_r;            /* [ENVELOPING_RING] TREAD_THICKNESS, m */
    double EI;             /* BELT_BENDING_STIFFNESS, N*m^2 */
    double T;              /* BELT_PRETENSION: belt tension beyond the air's p*b*R, N */
    double k_c;            /* FOUNDATION_STIFFNESS: the carcass's own radial stiffness, beyond
                            * the air's share of k_f, per unit belt length, N/m^2 */
    double k_t;            /* TREAD_STIFFNESS, per unit belt length, N/m^2 */
    double G_t;            /* TREAD_SHEAR: the tread rubber's shear modulus, Pa, coupling the
                            * tread's neighbouring elements along the arc (section 5.3);
                            * 0 = a Winkler tread; the default 0.25 MPa (5.6) */
    double dtheta;         /* NODE_ANGLE: node spacing around the full circle, rad */
    double lug_count;      /* LUG_COUNT: lugs around the circumference; 0 = smooth tread */
    double lug_fraction;   /* LUG_FRACTION: share of the circumference under lugs, (0, 1) */
    double lug_ratio;      /* LUG_GROOVE_RATIO: tread stiffness between lugs / on lugs, (0, 1] */
    double b_p;            /* BELT_WIDTH: width of the crown the air presses on, m */
    double alpha_s;        /* SIDEWALL_ANGLE: half angle of a sidewall's membrane arc, rad,
                            * in [0.1, pi/2] */
    double w_cs;           /* CARCASS_SOFTENING_DEFLECTION: the carcass's own foundation force
                            * per unit belt length softens beyond w_c0 as k_c (w_c0 + w_cs (1 -
                            * exp(-(w - w_c0)/w_cs))), m; 0 = linear, k_c w (section 5.1) */
    double w_c0;           /* CARCASS_LINEAR_DEFLECTION: the belt deflection up to which the
                            * carcass stays linear, m (with w_cs > 0) */
    double p;              /* [OPERATING_CONDITIONS] INFLPRES: inflation pressure, Pa */
    double p_nom;          /* NOMPRES: MF-Tyre's nominal pressure, Pa (the ring uses INFLPRES;
                            * the cam's vertical law PFZ1 at INFLPRES over NOMPRES) */
    tirenv_ring_contact_kind contact; /* [ENVELOPING_RING] CONTACT */
} tirenv_ring_params;

/* Parameters of the tandem elliptical cam model (docs/models.md section 7), the MF-Tyre keys of
 * the same names, so that an MF-Tyre / MF-Swift property file supplies them unchanged. The cam
 * scales with R0 (springs.R0): a_e = ELLIPS_LENGTH*R0, b_e = ELLIPS_HEIGHT*R0. */
typedef struct {
    double c_z;            /* [VERTICAL] VERTICAL_STIFFNESS: load / static deflection, N/m,
                            * or with Q_FZ2 the tangent stiffness at FNOMIN (docs/models.md
                            * section 7.3) */
    double fnomin;         /* [VERTICAL] FNOMIN: nominal load, N; 0: none (Q_FZ2 needs it) */
    double q_fz2;          /* [VERTICAL] Q_FZ2: quadratic term of MF-Tyre's vertical law
                            * F_z = FNOMIN*(Q_FZ1*rho/R0 + Q_FZ2*(rho/R0)^2); 0: linear */
    double q_fz1;          /* [VERTICAL] Q_FZ1: its linear term; 0 (MF-Tyre's "none"): from
                            * VERTICAL_STIFFNESS, sqrt((c_z*R0/FNOMIN)^2 - 4*Q_FZ2) */
    double pfz1;           /* [VERTICAL] PFZ1: the law times 1 + PFZ1*(INFLPRES - NOMPRES)/
                            * NOMPRES (ring.p, ring.p_nom); 0: no pressure term */
    double q_ra1;          /* [CONTACT_PATCH] Q_RA1: square-root term of the contact length */
    double q_ra2;          /* Q_RA2: linear term of the contact length */
    double shift;          /* ELLIPS_SHIFT: tandem base / contact length 2a */
    double length;         /* ELLIPS_LENGTH: cam half length / R0 */
    double height;         /* ELLIPS_HEIGHT: cam half height / R0 */
    double order;          /* ELLIPS_ORDER: super-ellipse exponent c_e, > 1 */
    unsigned given;        /* TIRENV_CAM_* bits of the keys with a value of this tire's own (a
                            * .tir file read clears the others); the default tire has all */
    double max_step;       /* ELLIPS_MAX_STEP: the highest road step the cam's shape is
                            * declared for, m; where the cam touches the ground higher above
                            * its lowest point, tirenv_model_warnings says so. 0: none
                            * declared, no warning. It changes no result. */
} tirenv_cam_params;

/* Bits of tirenv_cam_params.given, one per cam key. */
enum {
    TIRENV_CAM_C_Z = 1u << 0,     /* [VERTICAL] VERTICAL_STIFFNESS */
    TIRENV_CAM_Q_RA1 = 1u << 1,   /* [CONTACT_PATCH] Q_RA1 */
    TIRENV_CAM_Q_RA2 = 1u << 2,
    TIRENV_CAM_SHIFT = 1u << 3,   /* ELLIPS_SHIFT */
    TIRENV_CAM_LENGTH = 1u << 4,  /* ELLIPS_LENGTH */
    TIRENV_CAM_HEIGHT = 1u << 5,  /* ELLIPS_HEIGHT */
    TIRENV_CAM_ORDER = 1u << 6,   /* ELLIPS_ORDER */
    TIRENV_CAM_ALL = (1u << 7) - 1
};

/* The loads a tire with a nominal load FNOMIN is tabled, identified and compared at (tirenv
 * flat, tirenv identify, tirenv_tir_derive; docs/models.md sections 14.1 and 14.2): these
 * fractions of FNOMIN, 0.5 to 1.5. */
enum { TIRENV_NOMINAL_LOADS = 5 };
extern const double tirenv_nominal_load_fractions[TIRENV_NOMINAL_LOADS];

/* Everything a model needs to know about the tire and how to solve it. */
typedef struct {
    tirenv_springs_params springs;
    tirenv_ring_params ring;
    tirenv_eq_settings eq;
    tirenv_cam_params cam;
    double width;          /* [DIMENSION] WIDTH: the tire's width, m; 0 when a tire file read
                            * gives none (the default tire: 0.38). Where several tracks
                            * across the width are evaluated, their default spread
                            * (docs/models.md section 13) */
    double k_z;            /* [VERTICAL] VERTICAL_DAMPING: the tire's vertical damping, N*s/m,
                            * MF-Tyre's (Pacejka's k_z): the ride's c_t where the vehicle
                            * gives no TIRE_DAMPING (docs/models.md section 9.1); NAN when
                            * a tire file read gives none (the default tire: 3000) */
} tirenv_tire;

/* The equilibrium defaults: Newton, eps_F = 1e-6 N, eps_z = 1e-10 m, 100 evaluations,
 * secant_dz = 1e-3 m. */
tirenv_eq_settings tirenv_eq_default(void);

/* The shipped default tractor tire (same values as data/tires/default.tir). */
tirenv_tire tirenv_tire_default(void);

/* Checks that parameters are physical (R0 > 0, c_r > 0, c_b >= 0, 0 < dphi <= phi/2, width >= 0,
 * phi <= pi, tolerances > 0, the ring's and the cam's keys in range). Returns 0 or
 * TIRENV_EINVAL with the offending key in diag. */
int tirenv_tire_check(const tirenv_tire *tire, tirenv_diag *diag);

/* Whether the tire has its own value for every cam key (cam.given): TIRENV_OK, or
 * TIRENV_EINVAL naming the missing keys, for a tire file without MF-Swift's cam data used with
 * the cam model, which would otherwise take another tire's cam shape. */
int tirenv_tire_check_cam_keys(const tirenv_tire *tire, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
