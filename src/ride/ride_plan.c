/* SPDX-License-Identifier: Apache-2.0 */
/* The run plan of tirenv ride and of the Python module's ride (include/tirenv/ride.h,
 * docs/models.md section 9.4): the names of the integrators and of the ways of enveloping,
 * where each run starts and ends, and the grid of the axles' inputs, checked once for both
 * front ends. */
#include <math.h>
#include <string.h>

#include "tirenv/ride.h"

static const char *const method_names[] = {"rk4", "rk8pd"};
static const char *const enveloping_names[TIRENV_RIDE_N_ENVELOPING] = {"static", "dynamic",
                                                                       "direct"};

const char *tirenv_ride_method_name(tirenv_ride_method m)
{
    return (size_t)m < sizeof method_names / sizeof *method_names ? method_names[m]
                                                                   : "unknown";
}

int tirenv_ride_method_parse(const char *name, tirenv_ride_method *m, tirenv_diag *diag)
{
    for (size_t i = 0; name && i < sizeof method_names / sizeof *method_names; ++i)
        if (strcmp(name, method_names[i]) == 0) {
            *m = (tirenv_ride_method)i;
            return TIRENV_OK;
        }
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, "method", "expected rk4 or rk8pd, got '%s'",
                        name ? name : "");
}

const char *tirenv_ride_enveloping_name(tirenv_ride_enveloping e)
{
    return (size_t)e < TIRENV_RIDE_N_ENVELOPING ? enveloping_names[e] : "unknown";
}

int tirenv_ride_enveloping_parse(const char *name, tirenv_ride_enveloping *e,
                                 tirenv_diag *diag)
{
    for (size_t i = 0; name && i < TIRENV_RIDE_N_ENVELOPING; ++i)
        if (strcmp(name, enveloping_names[i]) == 0) {
            *e = (tirenv_ride_enveloping)i;
            return TIRENV_OK;
        }
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, "enveloping",
                        "expected static, dynamic or direct, got '%s'", name ? name : "");
}

/* 1e7 points: a 10 km/h run at 1 ms lasts 2.8 h, a grid at 5 mm spans 50 km. */
tirenv_ride_plan_params tirenv_ride_plan_params_default(void)
{
    const tirenv_ride_settings s = tirenv_ride_default();
    return (tirenv_ride_plan_params){.span = tirenv_ride_span_default(),
                                     .x_from = NAN,
                                     .x_to = NAN,
                                     .dt = s.dt,
                                     .method = s.method,
                                     .tol = s.tol,
                                     .max_points = 1e7};
}

/* Everything is checked before a caller allocates a sample, so that a typo in a speed, dt or
 * dx is named as such, not as "out of memory". The durations are (x_to - x_from)/V and the
 * grid is tirenv_ride_span_grid's up to the furthest end, as tirenv ride has always computed
 * them (its series and comfort figures are unchanged bit for bit). */
int tirenv_ride_plan_make(const tirenv_ride_plan_params *pp, const tirenv_vehicle *v,
                          const tirenv_profile *p, const double speeds[], size_t n_speeds,
                          tirenv_ride_plan *plan, tirenv_diag *diag)
{
    const double dt = pp->dt, dx = pp->span.dx;
    if (!(dt > 0 && isfinite(dt)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dt",
                            "expected an output interval > 0 in s, got %g", dt);
    if (!(1 / dt >= TIRENV_COMFORT_FS_MIN))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dt",
                            "%g s is too coarse for ISO 2631-1's weightings, which reach "
                            "80 Hz: at most %g s", dt, 1 / TIRENV_COMFORT_FS_MIN);
    /* Too fine a one was found only after the run, by the weighting filters (field fs). */
    if (!(1 / dt <= TIRENV_COMFORT_FS_MAX))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dt",
                            "%g s is finer than ISO 2631-1's weighting filters take (their "
                            "0.4 Hz high-pass loses precision above %g Hz): at least %g s",
                            dt, TIRENV_COMFORT_FS_MAX, 1 / TIRENV_COMFORT_FS_MAX);
    if (!(dx > 0 && isfinite(dx)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "expected a grid spacing > 0 in m, got %g", dx);
    if (n_speeds < 1 || n_speeds > TIRENV_RIDE_PLAN_RUNS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "speed",
                            "expected 1 to %d speeds, got %zu", TIRENV_RIDE_PLAN_RUNS,
                            n_speeds);
    if ((size_t)pp->method >= sizeof method_names / sizeof *method_names)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "method",
                            "expected rk4 or rk8pd, got method %d", (int)pp->method);
    double x_first, x_last;
    tirenv_profile_extent(p, &x_first, &x_last);
    const double x_from = isnan(pp->x_from) ? tirenv_ride_span_start(&pp->span, x_first)
                                            : pp->x_from;
    double x_to_max = x_from;
    for (size_t j = 0; j < n_speeds; ++j) {
        const double V = speeds[j];
        if (!(V > 0 && isfinite(V)))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "speed",
                                "expected a speed > 0 in m/s, got %g", V);
        const double x_to = isnan(pp->x_to) ? tirenv_ride_span_end(&pp->span, v, x_last, V)
                                            : pp->x_to;
        if (!(x_to > x_from))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x_to",
                                "the run must end after it starts: from %g m to %g m",
                                x_from, x_to);
        const double duration = (x_to - x_from) / V;
        /* A run shorter than dt is one sample, the start, where the vehicle rests in its
         * static state: every comfort figure came out 0 (the crest factor 0/0), exit 0, from
         * no motion at all. */
        if (!(duration >= dt))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x_to",
                                "the run from %g m to %g m lasts %.3g s at %g m/s, less than "
                                "one output interval dt = %g s: a single sample, the vehicle "
                                "at rest; expected a run of at least V*dt = %.3g m", x_from,
                                x_to, duration, V, dt, V * dt);
        if (!(duration / dt < pp->max_points))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "speed",
                                "%.3g s of run at dt %g s would be %.3g samples; at most "
                                "%.0f: check the speed (%g m/s) and dt", duration, dt,
                                duration / dt, pp->max_points, V);
        tirenv_ride_settings *s = &plan->run[j];
        *s = tirenv_ride_default();
        s->speed = V;
        s->x_front0 = x_from;
        s->duration = duration;
        s->dt = dt;
        s->method = pp->method;
        s->tol = pp->tol;
        x_to_max = fmax(x_to_max, x_to);
    }
    double x0;
    const double n = tirenv_ride_span_grid(&pp->span, v, x_from, x_to_max, &x0);
    if (!(n <= pp->max_points))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "dx",
                            "%.3g input positions (from %g m to %g m every %g m); at most "
                            "%.0f", n, x0, x_to_max + pp->span.grid_margin, dx,
                            pp->max_points);
    plan->x0 = x0;
    plan->dx = dx;
    plan->n = (size_t)n;
    return TIRENV_OK;
}

double tirenv_ride_dx_max(double R0_front, double R0_rear)
{
    return 0.1 * fmin(R0_front, R0_rear);
}
