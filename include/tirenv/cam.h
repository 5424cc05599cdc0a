/* tirenv: the tandem elliptical cam, the effective road model of MF-Swift (docs/models.md
 * section 7). The model type is tirenv_model_cam in model.h; these are its geometric parts.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CAM_H
#define TIRENV_CAM_H

#include "tirenv/decls.h"
#include "tirenv/error.h"
#include "tirenv/profile.h"

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
