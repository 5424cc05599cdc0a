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

TIRENV_END_DECLS
#endif
