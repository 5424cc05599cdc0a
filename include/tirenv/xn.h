/* tirenv: the normalised position x_N of docs/models.md section 1, which puts enveloping curves
 * of different tires, loads and obstacles on one axis (0 at first contact, 1 over the obstacle
 * centre): an equation of the models, used by the network, the import and the study.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_XN_H
#define TIRENV_XN_H

#include "tirenv/decls.h"

TIRENV_BEGIN_DECLS

/* x_0 of docs/models.md section 1 (m, obstacle coordinates): where the free circle of radius R0
 * (m) at the chord height sqrt(R0^2 - (l_c/2)^2) of contact length l_c (m) touches the leading
 * top corner (-L/2, H) of an obstacle of length L and height H (m) centred at x = 0. NaN if an
 * argument is out of range (R0 > 0, 0 < l_c < 2*R0, L >= 0, H >= 0, all finite) or the corner
 * is out of reach. */
double tirenv_xN_origin(double R0, double l_c, double L, double H);

/* x_N = (x - x_0)/(0 - x_0) at centre position x (m) for the obstacle centred at 0. */
double tirenv_xN(double x, double x_0);

TIRENV_END_DECLS
#endif
