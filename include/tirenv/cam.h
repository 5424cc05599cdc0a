/* tirenv: the tandem elliptical cam, the effective road model of MF-Swift (docs/models.md
 * section 7). The model type is tirenv_model_cam in model.h; these are its geometric parts.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CAM_H
#define TIRENV_CAM_H

#include "tirenv/decls.h"
#include "tirenv/error.h"
#include "tirenv/profile.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

/* One cam: the super-ellipse |u/a_e|^c_e + |v/b_e|^c_e = 1 (u along the road, v up). */
typedef struct {
    double a_e;            /* half length, m */
    double b_e;            /* half height, m */
    double c_e;            /* order (exponent), > 1 */
} tirenv_cam_shape;

/* The lift Z(x) (m) of one cam whose lowest point is above x (m), over the profile q:
 * Z(x) = max over |xi - x| <= a_e of q(xi) - b_e + b_e*(1 - |(xi - x)/a_e|^c_e)^(1/c_e),
 * exact on the polyline (no sampling), so 0 on flat ground at z = 0. The touching point of the
 * profile is stored in *px, *pz (m) if not NULL. Allocation-free; O(log n + vertices within
 * a_e). NAN (and a NAN touching point) if the shape is invalid (a_e, b_e not positive and
 * finite, c_e not above 1) or x is not finite. */
double tirenv_cam_lift(const tirenv_profile *p, const tirenv_cam_shape *cam, double x,
                       double *px, double *pz);

/* Two cams a tandem base l_s (m) apart, front at x + l_s/2, rear at x - l_s/2: the effective
 * height w = (Z_f + Z_r)/2 (m) and the effective slope tan(beta) = (Z_f - Z_r)/l_s into
 * *w and *tan_beta. TIRENV_EINVAL if the shape is invalid, l_s is not positive and finite, or
 * x is not finite (outputs untouched). */
int tirenv_cam_tandem(const tirenv_profile *p, const tirenv_cam_shape *cam, double l_s,
                      double x, double *w, double *tan_beta);

/* MF-Tyre's vertical law at standstill (docs/models.md section 7.3),
 * F_z/FNOMIN = Q_FZ1*s + Q_FZ2*s^2 with s = rho/R0, shared by the cam and the .tir reader:
 * _q_fz1 gives Q_FZ1 = sqrt((c_z*R0/FNOMIN)^2 - 4*Q_FZ2) for VERTICAL_STIFFNESS c_z (N/m),
 * R0 (m) and FNOMIN (N), which makes c_z the tangent stiffness at FNOMIN (NAN where Q_FZ2
 * leaves none); _root gives scale*s at the load g = F_z/FNOMIN, the root that grows from 0
 * with the load, as scale*2*g/(q1 + sqrt(q1^2 + 4*q2*g)) (the form without cancellation;
 * scale*g/q1 when q2 = 0), NAN beyond the largest load a q2 < 0 carries. scale is R0 for the
 * deflection in m, 1 for s itself. */
double tirenv_cam_q_fz1(double c_z, double R0, double fnomin, double q_fz2);
double tirenv_cam_vertical_root(double scale, double q1, double q2, double g);

/* The whole of that law as the cam and the .tir derivation both use it (docs/models.md
 * section 7.3), MF-Tyre 6.1's at standstill:
 *   F_z = f*FNOMIN*(Q_FZ1*s + Q_FZ2*s^2),  s = rho/R0,  f = 1 + PFZ1*(p - p_nom)/p_nom,
 * with the file's Q_FZ1 where it is not 0 and otherwise tirenv_cam_q_fz1's, which makes f*c_z
 * the tangent stiffness at FNOMIN; with Q_FZ1 and Q_FZ2 both 0, the linear F_z = f*c_z*rho
 * (FNOMIN not needed). */
typedef struct {
    double R0;       /* UNLOADED_RADIUS, m */
    double fnomin;   /* FNOMIN, N; 0: none (then q_fz1 and q_fz2 are 0) */
    double c_z;      /* VERTICAL_STIFFNESS, N/m */
    double q_fz1;    /* Q_FZ1; 0: from c_z */
    double q_fz2;    /* Q_FZ2 */
    double factor;   /* f, tirenv_cam_pressure_factor; > 0 */
} tirenv_cam_vertical;

/* f = 1 + PFZ1*(p - p_nom)/p_nom for INFLPRES p and NOMPRES p_nom (Pa): exactly 1 where PFZ1
 * is 0; NAN where PFZ1 is not 0 and p_nom is not positive. */
double tirenv_cam_pressure_factor(double pfz1, double p, double p_nom);

/* The law's Q_FZ1: q_fz1 where not 0, else tirenv_cam_q_fz1 (NAN where Q_FZ2 leaves none). */
double tirenv_cam_vertical_q1(const tirenv_cam_vertical *v);

/* The load F_z (N) at deflection rho (m); the deflection (m) at a load (N), the root that grows
 * from 0 with it (NAN beyond the largest load a Q_FZ2 < 0 carries, or where the law has no
 * Q_FZ1); the tangent stiffness dF_z/drho (N/m) at rho. */
double tirenv_cam_vertical_load(const tirenv_cam_vertical *v, double rho);
double tirenv_cam_vertical_deflection(const tirenv_cam_vertical *v, double load);
double tirenv_cam_vertical_stiffness(const tirenv_cam_vertical *v, double rho);

/* The law as a contact (the ride's tire force, docs/models.md section 9.3): the load (N) at
 * deflection rho (m), 0 at rho <= 0 (a tire never pulls), and past the peak of a law with
 * Q_FZ2 < 0 the peak load; _work its integral from 0 to rho (J), the tire's stored energy. */
double tirenv_cam_vertical_contact(const tirenv_cam_vertical *v, double rho);
double tirenv_cam_vertical_work(const tirenv_cam_vertical *v, double rho);

/* The tire's own vertical law: its cam keys, its R0 (UNLOADED_RADIUS) and PFZ1's factor at its
 * INFLPRES and NOMPRES; the law the cam's static deflection and the ride's tire force use. */
tirenv_cam_vertical tirenv_tire_vertical_law(const tirenv_tire *t);

/* The tangent stiffness dF_z/drho (N/m) of the tire's own vertical law above (its cam keys,
 * R0, and PFZ1's factor at its INFLPRES and NOMPRES) at the static deflection under load (N):
 * VERTICAL_STIFFNESS at FNOMIN with INFLPRES = NOMPRES, VERTICAL_STIFFNESS at every load for
 * the linear law. The ride's k_t where the vehicle gives no TIRE_STIFFNESS, for its linear
 * checks (its tire force follows the law itself, docs/models.md section 9.1). NAN where the
 * law carries no such load, has no Q_FZ1 (Q_FZ2 too large), or deflects the tire by its free
 * radius R0 or more under it (the cam refuses that load too). */
double tirenv_tire_vertical_stiffness(const tirenv_tire *t, double load);

/* MF-Tyre's vertical law above, F_z/FNOMIN = Q_FZ1*s + Q_FZ2*s^2 with s = rho/R0, fitted to
 * n >= 2 flat-ground states: rho[i] (m) a reference's deflection at the load G[i] (N), R0 (m),
 * FNOMIN (N), in relative error of the load by the 2x2 normal equations (docs/models.md
 * section 14.1). 0 with Q_FZ1, Q_FZ2 in *q_fz1, *q_fz2; TIRENV_EINVAL, outputs untouched, where
 * the states do not separate the two terms (n < 2, or deflections too alike). */
int tirenv_cam_fit_vertical_law(double R0, double fnomin, size_t n, const double rho[],
                                const double G[], double *q_fz1, double *q_fz2);

/* MF-Tyre's contact-length law a/R0 = Q_RA2*s^2 + Q_RA1*s, s = sqrt(rho/R0) (section 7.3),
 * fitted to n >= 2 flat-ground states of the same tire: rho[i] the cam's own static
 * deflection (m) at a load and l[i] (m) a reference's contact length 2a at that load, in
 * relative error of the contact length by the 2x2 normal equations (docs/models.md sections
 * 14.1, 14.2). 0 with Q_RA1, Q_RA2 in *q_ra1, *q_ra2; TIRENV_EINVAL, outputs untouched, where
 * the states do not separate the two terms (n < 2, or deflections too alike). */
int tirenv_cam_fit_contact_law(double R0, size_t n, const double rho[], const double l[],
                               double *q_ra1, double *q_ra2);

TIRENV_END_DECLS
#endif
