/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: the flexible-ring reference tire, node level (docs/models.md section 5). It drives the
 * virtual rig; tirenv/model.h offers it as the model "ring". */
#ifndef TIRENV_RING_H
#define TIRENV_RING_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/profile.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

/* Workspace of the ring model for one tire: nodes, the belt's compliance, and the state of
 * the last force evaluation. Evaluation never allocates. */
typedef struct tirenv_ring tirenv_ring;

/* NULL if the parameters are unphysical (including a pretension that buckles the belt) or
 * memory runs out. R0 is the free radius (m) at the tread surface. */
tirenv_ring *tirenv_ring_alloc(double R0, const tirenv_ring_params *params);
void tirenv_ring_free(tirenv_ring *r);  /* NULL is a no-op */

/* The free radius R0 (m) at the tread surface. */
double tirenv_ring_free_radius(const tirenv_ring *r);

/* Number of belt nodes around the full circle and their angles (rad, from the downward
 * vertical, positive forward). */
size_t tirenv_ring_size(const tirenv_ring *r);
const double *tirenv_ring_theta(const tirenv_ring *r);

/* Hub forces (N) with the centre at (x, z) (m): rays, then the contact of the tread, and of
 * the belt where the tread is compressed through, with the ground, solved exactly by an active
 * set on the belt's stiffness; dfz_dz (N/m, may be NULL) is exact for the current active set;
 * contacts (may be NULL): nodes with a ground force. TIRENV_ENOCONV if the active set does not
 * settle or its factorisation breaks down, diag (may be NULL) saying which. */
int tirenv_ring_forces(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                       double *fx, double *fz, double *dfz_dz, size_t *contacts,
                       tirenv_diag *diag);

/* Length (m) of ground in contact at the last evaluation: from the first to the last point of
 * positive tread pressure, edges interpolated between nodes. */
double tirenv_ring_patch_length(const tirenv_ring *r);

/* The grid the model "ring" scans for the end of its valid range (docs/models.md section
 * 5.4, where its flat-ground patch is longest): centre heights R0 - k R0 / this from R0
 * down. Public so that a check on the same grid (tirenv_tir_derive's) cannot drift from it. */
enum { TIRENV_RING_RANGE_STEPS = 32 };

/* Belt inward displacement w_j (m, negative where it bulges out) and ground force per node
 * f_j (N: the tread's plus the belt's reaction) of the last evaluation, into arrays of
 * tirenv_ring_size() entries (may be NULL). With the shear-coupled tread (TREAD_SHEAR > 0,
 * the default; docs/models.md section 5.3) w outside the contact window
 * comes from a solve of the unloaded belt and tread there, which allocates (NAN outside the
 * window if memory runs out); with the Winkler tread, from the belt's compliance, computed at
 * the first call that asks for w (allocates likewise, and keeps it in r: const as the state
 * read, but not safe to call on one r from two threads). */
void tirenv_ring_state(const tirenv_ring *r, double w[], double f[]);

/* The contact of the last evaluation per node, into arrays of tirenv_ring_size() entries (may
 * be NULL): d_j = R0 - rho_j, the penetration of the node's ray (m; -INFINITY where it meets
 * no ground within reach); b_j >= d_j, the penetration of the nearest ground in the node's
 * sector of +-dtheta/2 (m; -INFINITY: none), which the belt must stay out of,
 * w_j >= b_j - t_r; g_j >= 0, the belt's own ground reaction (N), zero unless w_j = b_j - t_r.
 * The tread compression is e_j = d_j - w_j <= t_r and the tread force f_j - g_j =
 * kappa_j max(0, e_j) with kappa_j = k_t (R0 - t_r) dtheta (times LUG_GROOVE_RATIO between
 * lugs). With the continuous contact and the shear-coupled tread, d_j = b_j = -INFINITY also
 * at the nodes of the window's far stretches whose ground a bound found clear of the belt, and
 * which were not sampled (docs/models.md 5.3). */
void tirenv_ring_contact(const tirenv_ring *r, double d[], double b[], double g[]);

/* Largest tread compression max_j min(max(0, e_j), t_r) (m; with the shear-coupled tread the
 * largest u - w, the tread surface's displacement less the belt's, capped at t_r) and number
 * of nodes where the belt itself touches (g_j > 0) at the last evaluation. */
double tirenv_ring_tread_max(const tirenv_ring *r);
size_t tirenv_ring_belt_contacts(const tirenv_ring *r);

TIRENV_END_DECLS
#endif
