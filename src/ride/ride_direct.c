/* SPDX-License-Identifier: Apache-2.0 */
/* A model evaluated during the run as an axle's input (tirenv_ride_direct_input, docs/models.md
 * section 9.5, tirenv ride --enveloping direct): at each position and load, the model's
 * effective height and its slope by central differences half a grid spacing either side. */
#include "tirenv/ride.h"

static int direct_eval(void *ctx, double x, double load, double *w, double *dw_dx,
                       tirenv_diag *diag)
{
    tirenv_ride_direct *d = ctx;
    tirenv_point lo, mid, hi;
    const double h = 0.5 * d->dx;
    int status = tirenv_model_set_load(d->m, load, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x - h, &lo, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x, &mid, diag);
    if (!status)
        status = tirenv_model_eval(d->m, x + h, &hi, diag);
    if (status)
        return status;
    *w = mid.h;
    *dw_dx = (hi.h - lo.h) / (2 * h);
    return TIRENV_OK;
}

/* The heaviest and the lightest loads of the tables' the model takes, as the tables end (a
 * load beyond the model's valid range, the network's outside its trained range). Probed on the
 * run's own model, as the run's first flat-ground solve starts from the probe's last: a range
 * found once would start it elsewhere (not the same bits by construction) to save a handful of
 * the run's tens of thousands of load changes. */
int tirenv_ride_direct_input(tirenv_model *m, double G0, double dx, tirenv_ride_direct *d,
                             tirenv_ride_input *in, tirenv_diag *diag)
{
    double load[TIRENV_RIDE_TABLE_LOADS];
    size_t top = TIRENV_RIDE_TABLE_LOADS, lo = 0;
    tirenv_ride_table_loads(G0, load);
    while (top > 1 && load[top - 1] > G0 && tirenv_model_set_load(m, load[top - 1], NULL))
        --top;
    while (lo + 1 < top && load[lo] < G0 && tirenv_model_set_load(m, load[lo], NULL))
        ++lo;
    const int status = tirenv_model_set_load(m, G0, diag);
    *d = (tirenv_ride_direct){.m = m, .dx = dx};
    *in = (tirenv_ride_input){.fn = direct_eval, .ctx = d, .load_min = load[lo],
                              .load_max = load[top - 1], .dx = dx};
    return status;
}
