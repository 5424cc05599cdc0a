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

/* Hub forces (N) with the centre at (x, z) (m): rays, then the contact of the tread with the
 * ground solved exactly by an active set on the belt's compliance; dfz_dz (N/m, may be NULL)
 * is exact for the current active set. TIRENV_ENOCONV if the active set does not settle or
 * its Cholesky factorisation breaks down, diag (may be NULL) saying which. */
int tirenv_ring_forces(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                       double *fx, double *fz, double *dfz_dz, size_t *contacts,
                       tirenv_diag *diag);

/* Length (m) of ground in contact at the last evaluation: from the first to the last point of
 * positive tread pressure, edges interpolated between nodes. */
double tirenv_ring_patch_length(const tirenv_ring *r);

/* Belt inward displacement w_j (m, negative where it bulges out) and tread force per node
 * f_j (N) of the last evaluation, into arrays of tirenv_ring_size() entries (may be NULL). */
void tirenv_ring_state(const tirenv_ring *r, double w[], double f[]);

TIRENV_END_DECLS
#endif
