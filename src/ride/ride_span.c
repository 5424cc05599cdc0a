/* Where tirenv ride drives over an obstacle, and the input grid that covers the run
 * (include/tirenv/ride.h, docs/models.md section 9.4). SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/ride.h"

#include <math.h>

/* A run-in before the obstacle, so the run starts at rest on the level ground before it,
 * and time after it for the body to settle; the grid's margin keeps the interpolation off
 * its ends inside a run. */
tirenv_ride_span tirenv_ride_span_default(void)
{
    return (tirenv_ride_span){.run_in = 1.0, .settle_min = 3.0, .settle_time = 2.0,
                              .grid_margin = 1.0, .dx = 0.005};
}

double tirenv_ride_span_start(const tirenv_ride_span *s, double x_first)
{
    return x_first - s->run_in;
}

/* The sums in this order (not x_last + (a + b)): tirenv ride's ends, bit for bit, as they
 * were before the library had them. */
double tirenv_ride_span_end(const tirenv_ride_span *s, const tirenv_vehicle *v, double x_last,
                            double V)
{
    return x_last + v->a + v->b + fmax(s->settle_min, s->settle_time * V);
}

double tirenv_ride_span_grid(const tirenv_ride_span *s, const tirenv_vehicle *v, double x_from,
                             double x_to, double *x0)
{
    *x0 = x_from - (v->a + v->b) - s->grid_margin;
    return ceil((x_to + s->grid_margin - *x0) / s->dx) + 1;
}
