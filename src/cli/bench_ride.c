/* tirenv bench, the ride: the default tractor over the bench's 1 km road at 10 km/h, each
 * model's inputs for both axles and the integration timed together, against real time (the
 * project's target: 100 times faster with nn or cam, on one core).
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/bench.h"
#include "cli/ride_cli.h"

static const double ride_speed = 10 / 3.6;   /* m/s */
static const double ride_target = 100;       /* times faster than real time */


/* Both axles' inputs on the grid x[] for one model type: at the static loads into w, or
 * (dynamic) tables over loads into table (their arrays allocated: the caller frees them). The
 * network over the road's low bumps extrapolates (docs/models.md section 12), as make demo's
 * road ride allows it: the bench times the same work. */
static int inputs(const tirenv_model_type *type, const tirenv_tire *tire,
                  const tirenv_vehicle *v, const tirenv_profile *road, const tirenv_nn *nn,
                  size_t n, const double x[], int dynamic, double *w[2],
                  tirenv_ride_table table[2], tirenv_diag *diag)
{
    int status = TIRENV_OK;
    for (int axle = 0; axle < 2 && !status; ++axle) {
        const double G0 = tirenv_vehicle_tire_load(v, axle);
        if (dynamic)
            status = ride_cli_axle_table(type, tire, G0, road, nn, tire->springs.R0, 1, x[0],
                                         x[1] - x[0], n, &table[axle], NULL, 0, diag);
        else
            status = ride_cli_axle_input(type, tire, G0, road, nn, tire->springs.R0, 1, x[0],
                                         x[1] - x[0], n, w[axle], NULL, 0, diag);
    }
    return status;
}

static void tables_free(tirenv_ride_table table[2])
{
    for (int axle = 0; axle < 2; ++axle) {
        free((double *)table[axle].load);
        free((double *)table[axle].w);
        memset(&table[axle], 0, sizeof table[axle]);
    }
}

int cli_bench_ride(const tirenv_tire *tire, const tirenv_profile *road, const tirenv_nn *nn,
                   size_t n, const double x[], long repeat, tirenv_diag *diag)
{
    /* The models and the project's targets: 100 times real time with the cam or the
     * network, on one core. */
    const struct {
        const tirenv_model_type *type;
        int targeted;
        int dynamic;   /* the input follows the tire load (tables over loads) */
    } models[] = {{tirenv_model_point, 0, 0},   {tirenv_model_cam, 1, 0},
                  {tirenv_model_nn, 1, 0},      {tirenv_model_springs, 0, 0},
                  {tirenv_model_cam, 1, 1},     {tirenv_model_nn, 1, 1},
                  {tirenv_model_springs, 0, 1}};
    tirenv_vehicle v = tirenv_vehicle_default();
    if (tirenv_vehicle_tires(&v, tire, tire, diag))  /* its springs and dampers this tire's */
        return TIRENV_EINVAL;
    tirenv_ride_settings s = tirenv_ride_default();
    const double l = v.a + v.b, margin = 1.0;  /* m: the interpolation never runs out */
    s.speed = ride_speed;
    s.x_front0 = x[0] + l + margin;
    s.duration = (x[n - 1] - margin - s.x_front0) / s.speed;
    const size_t n_out = tirenv_ride_n_samples(&s);
    double *w[2] = {malloc(n * sizeof(double)), malloc(n * sizeof(double))};
    tirenv_ride_sample *out = malloc(n_out * sizeof *out);
    int status = w[0] && w[1] && out ? TIRENV_OK : TIRENV_ENOMEM;
    cli_bench_say("\nride: the default tractor (data/vehicles/tractor.veh, this tire on both axles) "
           "over the road at\n%.0f km/h, %.1f s simulated at %g ms (RK4); inputs of both axles "
           "+ integration, best of %ld;\n_dynamic: the input follows the tire load, from tables "
           "over 14 loads (--enveloping dynamic)\n", s.speed * 3.6, s.duration, 1e3 * s.dt, repeat);
    cli_bench_figure("ride_simulated_s", s.duration);
    cli_bench_say("  %-16s %10s %10s %10s %10s %8s\n", "model", "inputs_s", "ode_s", "x_real",
           "target", "");
    for (size_t i = 0; i < sizeof models / sizeof models[0] && !status; ++i) {
        const char *name = tirenv_model_type_name(models[i].type);
        if ((tirenv_model_type_flags(models[i].type) & TIRENV_MODEL_NEEDS_NETWORK) && !nn)
            continue;  /* bench_road said why */
        const int dynamic = models[i].dynamic;
        double t_in = INFINITY, t_ode = INFINITY;
        for (long rep = 0; rep < repeat && !status; ++rep) {
            tirenv_ride_table table[2];
            memset(table, 0, sizeof table);
            double t0 = cli_wall_seconds();
            status = inputs(models[i].type, tire, &v, road, nn, n, x, dynamic, w, table, diag);
            t_in = fmin(t_in, cli_wall_seconds() - t0);
            const tirenv_ride_track front = {x[0], x[1] - x[0], n, w[0]};
            const tirenv_ride_track rear = {x[0], x[1] - x[0], n, w[1]};
            t0 = cli_wall_seconds();
            if (!status && dynamic)
                status = tirenv_ride_run_dynamic(&v, &table[0], &table[1], &s, out, diag);
            else if (!status)
                status = tirenv_ride_run(&v, &front, &rear, &s, out, diag);
            t_ode = fmin(t_ode, cli_wall_seconds() - t0);
            tables_free(table);
        }
        if (!status) {
            const double factor = s.duration / (t_in + t_ode);
            const int targeted = models[i].targeted;
            char key[64], label[32];
            snprintf(label, sizeof label, "%s%s", name, dynamic ? "_dynamic" : "");
            snprintf(key, sizeof key, "ride_%s_inputs_s", label);
            cli_bench_figure(key, t_in);
            snprintf(key, sizeof key, "ride_%s_ode_s", label);
            cli_bench_figure(key, t_ode);
            snprintf(key, sizeof key, "ride_%s_x_real", label);
            cli_bench_figure(key, factor);
            cli_bench_say("  %-16s %10.3f %10.3f %10.0f %10s %8s\n", label, t_in, t_ode,
                          factor, targeted ? "100" : "-",
                          !targeted ? "" : factor >= ride_target ? "met" : "missed");
        }
    }
    free(w[0]);
    free(w[1]);
    free(out);
    return status;
}
