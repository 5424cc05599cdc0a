/* SPDX-License-Identifier: Apache-2.0 */
/* Private: the cam's geometry with its derived constants, and what a sweep of positions keeps
 * between lifts, shared by cam.c (the cam's formulas), cam_lift.c (the exact lift),
 * cam_sweep.c (the sweep's tables) and cam_model.c (the model type), so that the model
 * computes them once, not per position. */
#ifndef TIRENV_CAM_IMPL_H
#define TIRENV_CAM_IMPL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

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

/* The cam's lower edge above its lowest point (m), negative, at t = |u|/a_e in (0, 1] given
 * tc = t^c_e: b_e*(g(t) - 1) with g(t) = (1 - t^c_e)^(1/c_e). With tc = pow(t, c_e), two pows:
 * accurate to about an ulp of b_e, which is all a comparison of heights needs. Every lift of a
 * vertex, and the drop floor, go through this one function, so they round alike. */
static inline double tirenv_cam__edge(const tirenv_cam__geom *g, double tc)
{
    return g->b_e * (pow(1.0 - tc, g->inv_c) - 1.0);
}

/* The cam's tangency with a straight segment of slope scale m = |slope|*a_e/b_e > 0 (see
 * cam.c): the touching point's distance *u (m) from the cam's bottom and the rise *rise (m)
 * of the lift above the segment's line under the bottom. Five exp/log. */
void tirenv_cam__tangent(const tirenv_cam__geom *g, double m, double *u, double *rise);

/* The drop floor's grid: 2^FLOOR_BITS steps per octave of t (the top FLOOR_BITS bits of the
 * mantissa), from 2^-FLOOR_OCTAVES up to 1; FLOOR_SHIFT drops the rest of a double's bits
 * and FLOOR_I0 is the step index of 2^-FLOOR_OCTAVES in those bits. */
#define TIRENV_CAM__FLOOR_BITS 5
#define TIRENV_CAM__FLOOR_OCTAVES 32
#define TIRENV_CAM__FLOOR_N ((1 << TIRENV_CAM__FLOOR_BITS) * TIRENV_CAM__FLOOR_OCTAVES)
#define TIRENV_CAM__FLOOR_SHIFT (52 - TIRENV_CAM__FLOOR_BITS)
#define TIRENV_CAM__FLOOR_I0 ((int64_t)(1023 - TIRENV_CAM__FLOOR_OCTAVES) << TIRENV_CAM__FLOOR_BITS)

/* A lower bound on the cam's edge drop -tirenv_cam__edge, as a function of t, without a pow:
 * the drop grows with t, so on each step [t_i, t_i+1) it is at least its value d_i at t_i.
 * The grid is even in log t, where the drop grows like t^c_e: a step of 1/32 octave keeps the
 * floor within about 2.2*c_e % of the drop (3 % for c_e = 1.5). d_0 = 0 stands for everything
 * below t_1. Each d_i is stored 1e-9 (relative) low, which covers the rounding of the drop,
 * even next to t = 1 where the cancellation in 1 - t^c_e makes it worst. */
typedef struct {
    double d[TIRENV_CAM__FLOOR_N]; /* m */
} tirenv_cam__floor;

/* The step of t >= 0, whose lower end t_i is the double whose top 17 bits are i + i_0: the
 * bits of a positive double, read as an integer, grow with it, so their top 17 (sign,
 * exponent, 5 bits of mantissa) find t's step at once, without a branch. */
static inline size_t tirenv_cam__floor_step(double t)
{
    uint64_t bits;
    memcpy(&bits, &t, sizeof bits);
    /* & 0xffff: -0 as 0 */
    const int64_t i = (int64_t)((bits >> TIRENV_CAM__FLOOR_SHIFT) & 0xffff) - TIRENV_CAM__FLOOR_I0;
    return (size_t)(i < 0 ? 0 : i < TIRENV_CAM__FLOOR_N ? i : TIRENV_CAM__FLOOR_N - 1);
}

/* The floor at t, 0 <= t <= 1 (m); the walks call it at every vertex. */
static inline double tirenv_cam__floor_at(const tirenv_cam__floor *f, double t)
{
    return f->d[tirenv_cam__floor_step(t)];
}

/* Segments whose tangency a sweep remembers (a power of two); a sweep touches few at once. */
#define TIRENV_CAM__MEMO_N 512

/* A sloped segment's tangency depends on its slope alone, not on where the cam is. */
typedef struct {
    size_t tag;  /* the segment index + 1; 0 for an empty slot */
    double s;    /* the segment's slope */
    double u;    /* tirenv_cam__tangent's *u, m */
    double rise; /* tirenv_cam__tangent's *rise, m */
} tirenv_cam__tangent_memo;

/* What the lifts of one model share, for one cam shape over one profile: the shape's drop
 * floor, and the tangencies met so far (slot k mod MEMO_N), which the rear cam meets again
 * after the front one. */
typedef struct {
    tirenv_cam__floor floor;
    tirenv_cam__tangent_memo memo[TIRENV_CAM__MEMO_N];
} tirenv_cam__sweep;

/* Fills the floor for a geometry, with an empty memo. */
void tirenv_cam__sweep_init(tirenv_cam__sweep *sw, const tirenv_cam__geom *g);

/* Empties the memo: required whenever the profile changes, as it is indexed by segment. */
void tirenv_cam__sweep_forget(tirenv_cam__sweep *sw);

/* Segment k's memo slot (it may hold another segment, or none). */
static inline tirenv_cam__tangent_memo *tirenv_cam__memo_slot(tirenv_cam__sweep *sw, size_t k)
{
    return &sw->memo[k % TIRENV_CAM__MEMO_N];
}

/* After a miss on segment k of p: the tangents of the next few segments the sweep is heading
 * to, if the memo shows it heading one way (see cam_sweep.c). */
void tirenv_cam__memo_ahead(tirenv_cam__sweep *sw, const tirenv_cam__geom *g,
                            const tirenv_profile *p, size_t k);

/* What one cam keeps between positions: where it was. Any content, stale, from another
 * profile, or zero, gives the same lift bit for bit; it only makes the next nearby position
 * faster to find. */
typedef struct {
    size_t k_x; /* the segment under the last position */
} tirenv_cam__track;

/* tirenv_cam_lift for a valid geometry and a finite x; px, pz may be NULL. z_cap (m) is an
 * upper bound on the profile's height within reach (INFINITY if unknown): with it the scan
 * stops where no ground could lift the cam higher than it already is. sweep (made for g, and
 * given the profile p since p last changed) and track may be NULL, for a single lift; with
 * them a sweep of positions prunes more and repeats less. The result does not depend on them,
 * bit for bit. Allocation-free. */
double tirenv_cam__lift(const tirenv_cam__geom *g, const tirenv_profile *p, double x,
                        double z_cap, tirenv_cam__sweep *sweep, tirenv_cam__track *track,
                        double *px, double *pz);

#endif
