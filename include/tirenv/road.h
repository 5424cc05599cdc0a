/* tirenv: random road profiles by the road classes of ISO 8608.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_ROAD_H
#define TIRENV_ROAD_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/profile.h"

TIRENV_BEGIN_DECLS

#define TIRENV_ISO8608_N0 0.1            /* reference spatial frequency n0, cycles/m */
#define TIRENV_ROAD_MAX_POINTS 33554432  /* 2^25 vertices, about 1 GB while generating */

/* What tirenv_road_iso8608 generates. */
typedef struct {
    char road_class;       /* 'A'..'H' (or lower case): the class's Gd(n0) */
    double length;         /* road length, m (> 0) */
    double dx;             /* vertex spacing, m (> 0, at most 1/(2*n_max)) */
    unsigned long seed;    /* seed of the phases (tirenv_rng_seed; every value, 0 too, is a seed) */
    double n_min, n_max;   /* band of spatial frequencies generated, cycles/m */
    double waviness;       /* w in Gd(n) = Gd(n0)*(n/n0)^-w */
} tirenv_road_settings;

/* Class C, 100 m at 0.01 m, seed 1, the standard's band 0.011 to 2.83 cycles/m, waviness 2. */
tirenv_road_settings tirenv_road_default(void);

/* Gd(n0) of an ISO 8608 class, m^3 (the geometric mean of the class band: 16e-6 * 4^k for
 * A, B, ... H = k 0..7); NAN for any other character. */
double tirenv_iso8608_gd0(char road_class);

/* The one-sided displacement PSD (m^3, i.e. m^2 per cycle/m) the settings ask for at spatial
 * frequency n (cycles/m): Gd(n0)*(n/n0)^-waviness inside [n_min, n_max], 0 outside; NAN if
 * the class is not A..H. */
double tirenv_road_psd(const tirenv_road_settings *s, double n);

/* Generates a random road of the settings' class: vertices x_j = j*dx, j = 0..N-1 with
 * N = floor(length/dx) + 1, heights a sum of cosines with random phases (see the .c file)
 * shifted so that z_0 = 0, the level of the flat approach. Same settings, same road, bit for
 * bit. *out is NULL on failure: TIRENV_EINVAL (diag names the setting) or TIRENV_ENOMEM. */
int tirenv_road_iso8608(const tirenv_road_settings *s, tirenv_profile **out,
                        tirenv_diag *diag);

TIRENV_END_DECLS
#endif
