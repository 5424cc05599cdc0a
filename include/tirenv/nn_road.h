/* tirenv: the empirical model (nn.h) over any ground profile, by equivalent-cleat
 * decomposition with max-plus superposition (docs/models.md section 12).
 * SPDX-License-Identifier: Apache-2.0
 *
 * A MODEL CHOICE BEYOND THE PAPER. The network of docs/models.md section 6 was trained on single
 * rectangular cleats on flat ground; the paper says nothing about other profiles. This module
 * extends it as follows, and the result is only as good as that extension (it has not been
 * validated against a physical model or a rig over roads):
 *   1. Baseline b: the morphological opening of the profile q (erosion, then dilation) with a
 *      flat structuring element of width W, by default 1.5 times the longest obstacle length
 *      the network was trained on, so that every cleat it knows lies wholly above b. It is
 *      computed on samples of q (a uniform resampling at `spacing`, the vertices, and where
 *      an element ending on a vertex is centred) and interpolated linearly between them.
 *   2. Obstacles: the maximal runs where r = q - b > eps, found exactly on the polyline
 *      through the samples and the vertices (r piecewise linear). Each becomes the
 *      rectangle of the same height and area: H = max r, L = (integral of r dx)/H, centred at
 *      the centroid c of r (exact for a rectangular cleat).
 *   3. Effective height: h(x) = max(b(x), max over obstacles k of min(top_k, b(x) + g_k(x))),
 *      where g_k is tirenv_nn_envelope's curve for the cleat (l_c, H_k, L_k) centred at c_k,
 *      clipped to [0, H_k], and top_k the highest ground point of the obstacle. The tire is
 *      lifted above the baseline under its centre, not above the obstacle's own base, which
 *      keeps h continuous on sloping ground; the cap top_k keeps h below the ground's highest
 *      point. Heights below the trained range use the curve at the smallest trained height
 *      scaled by H/H_min; lengths below or above the range and heights above it are clamped
 *      to it and counted (tirenv_nn_road_info): extrapolations, which the model type nn
 *      refuses unless allowed (tirenv_model_set_extrapolate, docs/models.md section 12).
 * The baseline is followed as is: the network knows no pits, so a hollow narrower than the
 * tire is followed rather than bridged. On a slope an obstacle is measured from the level of
 * its higher foot (where the opening is flat under it). h inherits the network curve's own
 * small step at its first trained x_N (where tirenv_nn_envelope starts); elsewhere it is
 * continuous (at a wall of the profile the baseline rises over one sample spacing). */
#ifndef TIRENV_NN_ROAD_H
#define TIRENV_NN_ROAD_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/nn.h"
#include "tirenv/profile.h"

TIRENV_BEGIN_DECLS

/* How the decomposition is built. */
typedef struct {
    double width_factor;   /* W = width_factor * longest trained obstacle length (> 1) */
    double width;          /* W, m; if > 0 it replaces width_factor (needed for a network
                              without a recorded length range) */
    double spacing;        /* ds, spacing of the baseline's resampling, m (> 0) */
    double eps;            /* a run of r = q - b above eps is an obstacle, m (>= 0) */
    int prune;             /* 1: only obstacles in reach, skipping those whose bound cannot
                              beat the current maximum; 0: every obstacle at every position
                              (the same h, slowly: a check of the pruning) */
} tirenv_nn_road_settings;

/* width_factor 1.5, width 0 (from the factor), spacing 0.005 m, eps 1e-6 m, prune 1. */
tirenv_nn_road_settings tirenv_nn_road_default(void);

/* One obstacle of the decomposition (all m). */
typedef struct {
    double x_lo, x_hi;     /* the run where q - b > eps */
    double c;              /* centroid of q - b over the run */
    double H;              /* height: the largest q - b */
    double L;              /* equivalent length: (integral of q - b)/H */
    double base;           /* mean baseline over the run (reported; h uses b(x), see top) */
    double top;            /* highest ground over the run: the cap of its contribution */
    double H_net, L_net;   /* the cleat the network is evaluated for (H, L clamped to the
                              trained range; H_net = H_min when H < H_min) */
    double reach;          /* the curve acts on centre positions |x - c| <= reach */
} tirenv_nn_obstacle;

/* What the decomposition found: counts, and the geometry it used. */
typedef struct {
    size_t obstacles;      /* number of obstacles */
    size_t height_below;   /* H below the trained range: curve at H_min scaled by H/H_min */
    size_t height_above;   /* H above it: clamped to H_max */
    size_t length_below;   /* L below it: clamped to L_min */
    size_t length_above;   /* L above it: clamped to L_max */
    double H_min, H_max;   /* trained height range, m (+-inf if the network has none) */
    double L_min, L_max;   /* trained length range, m (+-inf if the network has none) */
    double width;          /* W of the opening, m */
    double spacing;        /* ds of the baseline, m */
    double reach;          /* largest distance from a centre position to a ground point of
                              an obstacle acting on it, m (0 without obstacles) */
} tirenv_nn_road_info;

/* The decomposition of one profile at one contact length: opaque, built once. */
typedef struct tirenv_nn_road tirenv_nn_road;

/* Builds the decomposition of profile p (read, not kept) for a tire of free radius R0 (m) at
 * contact length l_c (m), with settings s (NULL: defaults). The network needs 4 inputs
 * (TIRENV_NN_INPUTS) and a finite trained range of x_N; it is copied, so nn may then be
 * freed or used elsewhere. *out is NULL on failure: TIRENV_EINVAL for invalid arguments or
 * settings, TIRENV_ERANGE if an obstacle's cleat reaches the chord height, TIRENV_ENOMEM. */
int tirenv_nn_road_alloc(const tirenv_nn *nn, double R0, double l_c, const tirenv_profile *p,
                         const tirenv_nn_road_settings *s, tirenv_nn_road **out,
                         tirenv_diag *diag);
void tirenv_nn_road_free(tirenv_nn_road *r);  /* NULL is a no-op */

/* Where a window of a longer road sits in it, for a road taken a window at a time
 * (streaming, docs/models.md section 12). */
typedef struct {
    double x_first;        /* the road's first vertex, m: anchors the resampling points */
    int bof;               /* the window's first vertex is the road's first */
    int eof;               /* the window's last vertex is the road's last */
} tirenv_nn_road_window;

/* tirenv_nn_road_alloc over p, a window of a road holding the road's vertices from its first
 * to its last (as tirenv_model_stream's windows): the baseline is the whole road's, bit for
 * bit, farther than tirenv_nn_road_window_margin from a cut end (one that is not bof or eof),
 * the obstacles are those of the whole road whose run lies there, and so h and slope
 * (tirenv_nn_road_eval) at positions at least that margin from a cut end are the whole
 * road's, bit for bit. TIRENV_EINVAL as tirenv_nn_road_alloc, or for a window (NULL, x_first
 * not finite or after p's first vertex). */
int tirenv_nn_road_alloc_window(const tirenv_nn *nn, double R0, double l_c,
                                const tirenv_profile *p, const tirenv_nn_road_settings *s,
                                const tirenv_nn_road_window *w, tirenv_nn_road **out,
                                tirenv_diag *diag);

/* The margin D (m) of tirenv_nn_road_alloc_window for network nn, free radius R0 (m) and
 * settings s (NULL: defaults): 3(a + ds) + 2(a + ds) + 1.01 (L/2 + R0)(1 - x_N_min) + 3 ds
 * with a = W/2 and L the longest network length an obstacle can have (nn_road.c says why).
 * NaN for arguments tirenv_nn_road_alloc would refuse. */
double tirenv_nn_road_window_margin(const tirenv_nn *nn, double R0,
                                    const tirenv_nn_road_settings *s);

/* Changes the contact length (m) of a decomposition, in O(1): the baseline and the obstacles
 * depend on the profile alone; each obstacle's cleat origin x_0 and reach follow when it is
 * next evaluated. The results then equal those of a decomposition built at l_c, bit for bit.
 * TIRENV_EINVAL unless 0 < l_c < 2*R0, TIRENV_ERANGE if an obstacle's cleat reaches the chord
 * height at l_c; on failure r keeps its contact length. */
int tirenv_nn_road_set_contact_length(tirenv_nn_road *r, double l_c, tirenv_diag *diag);

/* h[i] (m) at tire-centre positions x[i] (m), in any order (fastest increasing); slope[i] =
 * dh/dx if slope is not NULL: the derivative of the term that is the maximum (the network's
 * dy/dx_N by a central difference of step 1e-5 in x_N). No allocation; not thread-safe (the
 * network's workspace): one object per thread. TIRENV_EINVAL if x or h is NULL with n > 0,
 * or an x is not finite (diag's line is its 1-based index; nothing is written). */
int tirenv_nn_road_eval(tirenv_nn_road *r, size_t n, const double x[], double h[],
                        double slope[], tirenv_diag *diag);

/* The baseline b(x) (m) at x (m). */
double tirenv_nn_road_baseline(const tirenv_nn_road *r, double x);
/* The obstacles, sorted by c; tirenv_nn_road_info_of(r).obstacles of them (owned by r), their
 * reach at the current contact length (both getters bring every obstacle to it: O(obstacles)). */
const tirenv_nn_obstacle *tirenv_nn_road_obstacles(const tirenv_nn_road *r);
tirenv_nn_road_info tirenv_nn_road_info_of(const tirenv_nn_road *r);
/* tirenv_nn_road_info_of with the counts (obstacles, outside the trained range) of the
 * obstacles whose centre c is beyond x (m) alone: a streamed road's windows counted once. */
tirenv_nn_road_info tirenv_nn_road_info_after(const tirenv_nn_road *r, double x);

TIRENV_END_DECLS
#endif
