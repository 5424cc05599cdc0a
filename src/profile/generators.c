/* Obstacle generators (docs/models.md section 2): the shapes of the paper's rig and a few more.
 * SPDX-License-Identifier: Apache-2.0 */
#include "profile/profile_impl.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* The most segments the curved generators make (half-cylinder, sine: include/tirenv/profile.h),
 * 16 GB of vertices: a larger request is a mistake, refused before the allocation. */
enum { MAX_CURVE_SEGMENTS = 1000000000 };

/* A size must be a positive, finite length; NaN fails the comparison too. */
static int is_size(double v)
{
    return isfinite(v) && v > 0.0;
}

/* Generated profiles go through the same check as user data, so a generator bug shows up as
 * NULL here rather than as a corrupt profile inside a model. */
static tirenv_profile *checked(tirenv_profile *p)
{
    if (p && tirenv_profile__finish(p, NULL) != TIRENV_OK) {
        tirenv_profile_free(p);
        return NULL;
    }
    return p;
}

/* Two walls and a flat top: the paper's rectangular cleat (case R is 0.10 x 0.10 m). */
tirenv_profile *tirenv_profile_cleat(double L, double H)
{
    if (!is_size(L) || !is_size(H))
        return NULL;
    const double x[] = {-L / 2, -L / 2, L / 2, L / 2};
    const double z[] = {0.0, H, H, 0.0};
    return tirenv_profile_alloc(4, x, z);
}

/* One wall; the flat extensions carry the two levels to infinity on either side. */
tirenv_profile *tirenv_profile_step(double x0, double H)
{
    if (!isfinite(x0) || !isfinite(H) || H == 0.0)
        return NULL;
    const double x[] = {x0, x0};
    const double z[] = {0.0, H};
    return tirenv_profile_alloc(2, x, z);
}

/* Symmetric about x = 0; L_base == L_top degenerates to the cleat (two walls). */
tirenv_profile *tirenv_profile_trapezoid(double L_top, double L_base, double H)
{
    if (!is_size(L_top) || !is_size(L_base) || !is_size(H) || L_base < L_top)
        return NULL;
    const double x[] = {-L_base / 2, -L_top / 2, L_top / 2, L_base / 2};
    const double z[] = {0.0, H, H, 0.0};
    return tirenv_profile_alloc(4, x, z);
}

tirenv_profile *tirenv_profile_triangle(double L_base, double H)
{
    if (!is_size(L_base) || !is_size(H))
        return NULL;
    const double x[] = {-L_base / 2, 0.0, L_base / 2};
    const double z[] = {0.0, H, 0.0};
    return tirenv_profile_alloc(3, x, z);
}

/* Vertices at equal angles theta_i = pi i / n on the circle of radius r about the origin, so
 * the polygon is inscribed: x_i = -r cos(theta_i), z_i = r sin(theta_i). The right half is
 * the mirror image of the left, and the ends and the apex are set exactly, so the polyline
 * is exactly symmetric and meets the ground exactly at x = -r and x = r (sin(pi) in floating
 * point is 1.2e-16, not 0). */
tirenv_profile *tirenv_profile_half_cylinder(double r, size_t segments)
{
    if (!is_size(r) || segments < 2 || segments > MAX_CURVE_SEGMENTS)
        return NULL;
    const size_t n = segments;
    struct tirenv_profile *p = tirenv_profile__new(n + 1);
    if (!p)
        return NULL;
    for (size_t i = 0; 2 * i < n; i++) {
        const double theta = M_PI * (double)i / (double)n;
        p->x[i] = -r * cos(theta);
        p->z[i] = r * sin(theta);
        p->x[n - i] = -p->x[i];
        p->z[n - i] = p->z[i];
    }
    if (n % 2 == 0) {
        p->x[n / 2] = 0.0;
        p->z[n / 2] = r;
    }
    p->z[0] = p->z[n] = 0.0;
    return checked(p);
}

/* Fine enough that the polylines stand for the curves: the chords of a half cylinder stay
 * within 0.004 % of r of the circle (1 - cos(0.5 degree)), those of a sine within 0.061 % of
 * its height 2A. */
tirenv_profile_resolution tirenv_profile_resolution_default(void)
{
    return (tirenv_profile_resolution){.cylinder_segments = 180, .sine_points_per_period = 64};
}

/* z = amplitude (1 - cos(2 pi x / wavelength)) on [0, periods * wavelength]: it starts at
 * z = 0 with zero slope, so it joins the flat ground on the left smoothly. The m segments
 * are equal, m = ceil(periods * points_per_period), so the last vertex lands exactly on
 * periods * wavelength; a fractional number of periods leaves the ground flat at the end
 * height. points_per_period >= 2, since at one point per period every vertex is at z = 0. */
tirenv_profile *tirenv_profile_sine(double amplitude, double wavelength, double periods,
                                    size_t points_per_period)
{
    if (!is_size(amplitude) || !is_size(wavelength) || !is_size(periods) ||
        points_per_period < 2)
        return NULL;
    const double m_real = ceil(periods * (double)points_per_period);
    if (!(m_real <= (double)MAX_CURVE_SEGMENTS)) /* and NaN: a cast to size_t could not */
        return NULL;
    const size_t m = (size_t)m_real;
    const double length = periods * wavelength;
    struct tirenv_profile *p = tirenv_profile__new(m + 1);
    if (!p)
        return NULL;
    for (size_t k = 0; k <= m; k++) {
        const double x = k == m ? length : length * (double)k / (double)m;
        p->x[k] = x;
        p->z[k] = amplitude * (1.0 - cos(2.0 * M_PI * x / wavelength));
    }
    return checked(p);
}
