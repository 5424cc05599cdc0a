/* Ray casting of the radial elements onto the ground polyline (docs/models.md section 4,
 * "geometric penetration"). */
#include "model/springs_impl.h"

#include <math.h>
#include "core/profile_impl.h"

/* The ground is a graph z = g(X) with vertical walls and the centre lies above it, so walking
 * from the centre along X in the ray's direction, the first vertex where the ray is at or below
 * the ground closes the segment that holds the first crossing: f(X) = ray height - ground is
 * linear between vertices. Most rays hit the segment under the centre, so this is O(1) per ray
 * after one O(log n) search. */
double tirenv_springs__ray(const tirenv_profile *p, double x, double z, double sin_t,
                           double cos_t, double rho_max, double *drho_dz)
{
    return tirenv_springs__ray_at(p, x, tirenv_profile__segment_at(p, x),
                                  tirenv_profile_height(p, x), z, sin_t, cos_t, rho_max,
                                  drho_dz);
}

/* The walk itself; k and g depend on x alone, so a caller casting many rays from one centre
 * finds them once (two binary searches saved per ray). */
double tirenv_springs__ray_at(const tirenv_profile *p, double x, size_t k, double g, double z,
                              double sin_t, double cos_t, double rho_max, double *drho_dz)
{
    const double *X = p->x, *Z = p->z;
    const size_t n = p->n;
    const double f0 = z - g;
    *drho_dz = 0;
    if (f0 <= 0)
        return 0; /* centre on or below the ground */
    if (sin_t == 0) {
        *drho_dz = 1;
        return f0 <= rho_max ? f0 : INFINITY;
    }
    const int dir = sin_t > 0 ? 1 : -1;
    const double s = fabs(sin_t);
    const double drop = cos_t / s;          /* ray descent per metre of walk */
    const double reach = rho_max * s;       /* walk length of the whole ray */

    /* First vertex strictly ahead of x in the walking direction. */
    long j;
    if (dir > 0) {
        j = X[k] <= x ? (long)k + 1 : (long)k;
    } else {
        j = X[k] < x ? (long)k : (long)k - 1;
        while (j >= 0 && X[j] >= x)
            --j;
    }
    double a_prev = 0, f_prev = f0;         /* walk distance and f at the last check point */
    for (; j >= 0 && j < (long)n; j += dir) {
        const double a = dir * (X[j] - x);
        const double f = z - a * drop - Z[j];
        if (f <= 0) {
            if (a == a_prev) {              /* a vertical wall: rho does not depend on z */
                return a <= reach ? a / s : INFINITY;
            }
            const double a_hit = a_prev + f_prev * (a - a_prev) / (f_prev - f);
            if (a_hit > reach)
                return INFINITY;
            const long jp = j - dir;        /* the hit segment is [jp, j]; -1 or n: flat */
            const double slope =
                jp >= 0 && jp < (long)n ? (Z[j] - Z[jp]) / (X[j] - X[jp]) : 0;
            *drho_dz = 1 / (cos_t + sin_t * slope);
            return a_hit / s;
        }
        if (a > reach)
            return INFINITY;
        a_prev = a;
        f_prev = f;
    }
    /* Past the last vertex the ground is flat at the end height, and f > 0 at a_prev. */
    if (cos_t <= 0)
        return INFINITY;
    const double rho = (z - Z[dir > 0 ? n - 1 : 0]) / cos_t;
    if (rho > rho_max)
        return INFINITY;
    *drho_dz = 1 / cos_t;
    return rho;
}
