/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: 2-D ground profiles (docs/models.md section 2). */
#ifndef TIRENV_PROFILE_H
#define TIRENV_PROFILE_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"

TIRENV_BEGIN_DECLS

/* A ground profile: a polyline (x_k, z_k), k = 0..n-1, with non-decreasing x. Two consecutive
 * vertices with equal x form a vertical wall. Outside [x_0, x_{n-1}] the ground is flat at the
 * end heights. Immutable once built; shareable between models and threads. */
typedef struct tirenv_profile tirenv_profile;

/* The largest |x| and |z| of a vertex, and the longest segment between two vertices, m:
 * beyond them the models lose their precision (docs/models.md section 2.1). */
#define TIRENV_PROFILE_MAX_COORDINATE 1e9
#define TIRENV_PROFILE_MAX_SEGMENT 1e7

/* Checks vertices for a profile: n >= 1, all finite and within
 * TIRENV_PROFILE_MAX_COORDINATE, no segment longer than TIRENV_PROFILE_MAX_SEGMENT, x
 * non-decreasing, at most two vertices at the same x. Returns TIRENV_OK or TIRENV_EINVAL
 * with the reason in diag (field "x" or "z", line = 1-based vertex index). */
int tirenv_profile_validate(size_t n, const double x[], const double z[], tirenv_diag *diag);

/* tirenv_profile_validate's check of one vertex, for a reader that meets them one at a time:
 * vertex k (0-based) at (x, z), m, after vertices at x_prev (k - 1's, read if k >= 1) and
 * x_prev2 (k - 2's, read if k >= 2). Returns TIRENV_OK or TIRENV_EINVAL with the words
 * tirenv_profile_validate would use (line = k + 1). */
int tirenv_profile_check_vertex(size_t k, double x, double z, double x_prev, double x_prev2,
                                tirenv_diag *diag);

/* Builds a profile from n vertices (copied; x, z in m). NULL if invalid or out of memory. */
tirenv_profile *tirenv_profile_alloc(size_t n, const double x[], const double z[]);

/* As tirenv_profile_alloc, into *out, with the reason in diag: tirenv_profile_validate's
 * (its file name, NULL or not, and no line: the message names the vertex) or TIRENV_ENOMEM.
 * For readers whose rows become a profile. */
int tirenv_profile_make(size_t n, const double x[], const double z[], const char *name,
                        tirenv_profile **out, tirenv_diag *diag);

/* Frees a profile; NULL is a no-op. */
void tirenv_profile_free(tirenv_profile *p);

/* Number of vertices and read-only access to them (m). */
size_t tirenv_profile_size(const tirenv_profile *p);
const double *tirenv_profile_x(const tirenv_profile *p);
const double *tirenv_profile_z(const tirenv_profile *p);

/* Ground height at x (m). At a wall the higher of the two heights is returned. */
double tirenv_profile_height(const tirenv_profile *p, double x);

/* Highest ground (m) over the closed interval [x_lo, x_hi] (m), including flat extensions. */
double tirenv_profile_max_height(const tirenv_profile *p, double x_lo, double x_hi);

/* The road's local level at x (m), docs/models.md section 2.6: the morphological opening of
 * the ground by a level segment of length width (m), i.e. the highest level segment of that
 * length that lies nowhere above the ground and covers x. It follows grades, steps and
 * undulations longer than the segment and passes under obstacles shorter than it: level ground
 * with a cleat shorter than width has the level of the ground. Exact on the polyline;
 * O(log n + vertices within width of x). NAN if width is not positive and finite or x is not
 * finite. */
double tirenv_profile_level(const tirenv_profile *p, double width, double x);

/* x-extent of the non-flat part: first and last vertex x (m). */
void tirenv_profile_extent(const tirenv_profile *p, double *x_first, double *x_last);

/* Generators: obstacles on flat ground z = 0 (steps excepted), centred at x = 0 unless noted.
 * All lengths and heights in m; NULL on invalid arguments (non-positive size, non-finite). */
tirenv_profile *tirenv_profile_cleat(double L, double H);          /* rectangle L x H */
tirenv_profile *tirenv_profile_step(double x0, double H);          /* step of H at x0 (H < 0 down) */
tirenv_profile *tirenv_profile_trapezoid(double L_top, double L_base, double H);
tirenv_profile *tirenv_profile_triangle(double L_base, double H);
/* Inscribed, 2 to 1e9 segments. */
tirenv_profile *tirenv_profile_half_cylinder(double r, size_t segments);
/* A(1-cos(2pi x/wl)), x >= 0; at least 2 points a period, at most 1e9 points in all. */
tirenv_profile *tirenv_profile_sine(double amplitude, double wavelength, double periods,
                                    size_t points_per_period);

/* How finely the curved generators follow their curves. */
typedef struct {
    size_t cylinder_segments;      /* chords of tirenv_profile_half_cylinder */
    size_t sine_points_per_period; /* segments per period of tirenv_profile_sine */
} tirenv_profile_resolution;

/* The CLI's (--cylinder, --sine): 180 chords (1 degree each) and 64 segments a period. */
tirenv_profile_resolution tirenv_profile_resolution_default(void);

TIRENV_END_DECLS
#endif
