/* The normalised position x_N (docs/models.md section 1).
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/xn.h"

#include <math.h>

/* The chord height z_c is where a free circle of radius R0 has a chord of length l_c on flat
 * ground: a convention computable before any simulation. That circle, moved forward, first
 * touches the obstacle's leading top corner (-L/2, H) when the corner is R0 from its centre:
 * horizontally sqrt(R0^2 - (z_c - H)^2) behind the corner. */
double tirenv_xN_origin(double R0, double l_c, double L, double H)
{
    if (!(R0 > 0 && isfinite(R0)) || !(l_c > 0 && l_c < 2 * R0) || !(L >= 0 && isfinite(L))
        || !(H >= 0 && isfinite(H)))
        return NAN;
    const double z_c = sqrt(R0 * R0 - 0.25 * l_c * l_c);
    const double reach2 = R0 * R0 - (z_c - H) * (z_c - H);
    if (!(reach2 >= 0))
        return NAN;
    return -0.5 * L - sqrt(reach2);
}

/* The obstacle centre is x_m = 0, so x_N = (x - x_0)/(0 - x_0). */
double tirenv_xN(double x, double x_0)
{
    return (x - x_0) / (0.0 - x_0);
}
