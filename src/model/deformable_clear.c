/* SPDX-License-Identifier: Apache-2.0 */
/* What each deformable model can touch at its flat-ground equilibrium: the bound behind the
 * shortcut of clear ground (deformable.c; the proofs in docs/models.md section 11.4). Ground
 * beyond it carries no force at that state, so where the ground inside it is the level line
 * the flat state meets every contact condition on the real ground too, and is the answer. */
#include <math.h>

#include "model/deformable.h"

/* The springs model: K is an M-matrix (k_r > 0, k_ir >= 0), so K^-1 >= 0 and the reactions'
 * w = K^-1 G^T lambda >= 0: no tip stands out of R0. The continuous tread between two tips,
 * R0 - (a w_i + b w_(i+1)) with a, b >= 0 on [0, 1], and its own deflection c lambda >= 0 at
 * a vertex, lie within R0 as well; the rays read d = max(0, R0 - rho). A sidewall in series
 * moves the centre, not the elements about it. So ground farther than R0 from the centre
 * gives no row a positive right-hand side; no vertex changes the sampling (rows are cast
 * only within R0). */
void tirenv_deformable_level_reach_r0(const tirenv_tire *tire, double dz, double *r,
                                      double *tan_cut)
{
    (void)dz;
    *r = tire->springs.R0;
    *tan_cut = 0;
}

/* The ring: a point farther than R0 + t_r along its ray is out of reach, d = -infinity, and
 * carries nothing whatever the belt and tread do (src/model/ring_ground.c, piece_point; the
 * rays alike, src/model/ring.c). But every ground vertex below the centre cuts the pieces the
 * tread energy is summed over: one in a node interval holding contact moves the quadrature's
 * weights there. The level ground within R0 + t_r lies within acos(dz/(R0 + t_r)) of the
 * vertical, so a vertex more than two node intervals beyond that angle cuts only intervals
 * whose points are out of reach. */
void tirenv_deformable_level_reach_tread(const tirenv_tire *tire, double dz, double *r,
                                         double *tan_cut)
{
    *r = tire->springs.R0 + tire->ring.t_r;
    const double psi = acos(fmin(1.0, dz / *r)) + 2 * tire->ring.dtheta;
    *tan_cut = psi < 0.5 * M_PI ? tan(psi) : INFINITY;
}
