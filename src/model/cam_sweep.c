/* What a sweep of cam positions keeps between lifts (docs/models.md section 7; the lift itself is
 * cam_lift.c's): the drop floor of the cam's shape, and the tangency memo. None of it changes
 * a bit of any lift, only how fast it is found.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "model/cam_impl.h"

/* The drop at each step's lower end t_i by tirenv_cam__edge, 1e-9 low (see
 * tirenv_cam__floor); 0 on the first step, which stands for all of [0, t_1). The last step
 * ends at t = 1. */
static void floor_set(tirenv_cam__floor *f, const tirenv_cam__geom *g)
{
    f->d[0] = 0.0;
    for (size_t i = 1; i < TIRENV_CAM__FLOOR_N; i++) {
        const uint64_t bits = ((uint64_t)TIRENV_CAM__FLOOR_I0 + i) << TIRENV_CAM__FLOOR_SHIFT;
        double t;
        memcpy(&t, &bits, sizeof t);
        f->d[i] = -tirenv_cam__edge(g, pow(t, g->c_e)) * (1.0 - 1e-9);
    }
}

void tirenv_cam__sweep_init(tirenv_cam__sweep *sw, const tirenv_cam__geom *g)
{
    floor_set(&sw->floor, g);
    tirenv_cam__sweep_forget(sw);
}

void tirenv_cam__sweep_forget(tirenv_cam__sweep *sw)
{
    memset(sw->memo, 0, sizeof sw->memo); /* tag 0: every slot empty */
}

/* Segment k's slope and tangent into its memo slot, by the operations of cam_lift.c's
 * segment_lift, unless it has none (a wall or a flat segment). */
static void memo_fill(tirenv_cam__sweep *sw, const tirenv_cam__geom *g,
                      const tirenv_profile *p, size_t k)
{
    const double *xs = tirenv_profile_x(p), *zs = tirenv_profile_z(p);
    const double x_a = xs[k], x_b = xs[k + 1], z_a = zs[k], z_b = zs[k + 1];
    if (!(x_b > x_a) || z_b == z_a)
        return;
    const double s = (z_b - z_a) / (x_b - x_a);
    double u, rise;
    tirenv_cam__tangent(g, fabs(s) * g->a_over_b, &u, &rise);
    *tirenv_cam__memo_slot(sw, k) =
        (tirenv_cam__tangent_memo){.tag = k + 1, .s = s, .u = u, .rise = rise};
}

/* After a miss on segment k of a sweep that is heading one way (the memo holds the segment
 * behind k that way, not the one ahead), the tangents of the next MEMO_AHEAD - 1 segments
 * ahead, which the sweep is about to need. Their exp/log chains do not depend on each other,
 * so the processor overlaps them, where one at a time each waits for the last (10 % faster
 * over a road, measured). Positions in no order miss with neither neighbour held, and pay
 * for their own tangent only. */
enum { MEMO_AHEAD = 8 };

void tirenv_cam__memo_ahead(tirenv_cam__sweep *sw, const tirenv_cam__geom *g,
                            const tirenv_profile *p, size_t k)
{
    const size_t n = tirenv_profile_size(p);
    const int behind_left = k > 0 && tirenv_cam__memo_slot(sw, k - 1)->tag == k;
    const int behind_right = k + 2 < n && tirenv_cam__memo_slot(sw, k + 1)->tag == k + 2;
    if (behind_left == behind_right)
        return;
    for (size_t i = 1; i < MEMO_AHEAD; i++) {
        if (behind_left ? !(k + i + 1 < n) : !(i <= k))
            return; /* the profile's end */
        const size_t q = behind_left ? k + i : k - i;
        if (tirenv_cam__memo_slot(sw, q)->tag != q + 1)
            memo_fill(sw, g, p, q);
    }
}
