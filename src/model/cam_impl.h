/* Private: the cam geometry with its derived constants, shared by cam.c (the lift) and
 * cam_model.c (the model type), so that the model computes them once, not per position. */
#ifndef TIRENV_CAM_IMPL_H
#define TIRENV_CAM_IMPL_H

#include "tirenv/cam.h"

typedef struct {
    double a_e, b_e, c_e;  /* the shape: half length m, half height m, order */
    double inv_a;          /* 1/a_e, 1/m */
    double a_over_b;       /* a_e/b_e: turns a road slope into the cam's slope scale */
    double inv_c;          /* 1/c_e */
    double inv_c1;         /* 1/(c_e - 1) */
    double p;              /* c_e/(c_e - 1), the exponent conjugate to c_e */
    double b_over_c;       /* b_e/c_e, m */
    unsigned n_c;          /* ceil(c_e), at most 64: t^n_c <= t^c_e on [0, 1] (pruning) */
} tirenv_cam__geom;

/* Fills *g from a shape; TIRENV_EINVAL (g untouched) unless a_e, b_e are positive and finite
 * and c_e > 1 is finite. */
int tirenv_cam__geom_set(tirenv_cam__geom *g, const tirenv_cam_shape *shape);

/* tirenv_cam_lift for a valid geometry and a finite x; px, pz may be NULL. z_cap (m) is an
 * upper bound on the profile's height within reach (INFINITY if unknown): with it the scan
 * stops where no ground could lift the cam higher than it already is. */
double tirenv_cam__lift(const tirenv_cam__geom *g, const tirenv_profile *p, double x,
                        double z_cap, double *px, double *pz);

#endif
