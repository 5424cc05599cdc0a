/* tirenv bench, a load that changes every step: the cam and the springs model (and the network,
 * when the bench has one) over the bench's road, one position after the other, once at a fixed
 * load and once with tirenv_model_set_load before every position, timed in the same run. The
 * target: a step with a new load costs at most twice a step at a fixed load.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/bench.h"

/* The load swings +-20 % about the base with a wavelength of 0.5 m of travel (a tire's load
 * over a rough road at a few km/h): up to 2.5 % from one 10 mm step to the next. */
static const double swing_amplitude = 0.20, swing_wavelength = 0.5;  /* 1, m */
static const double load_target = 2.0;  /* set_load step / fixed-load step, at most */

static double swing(double G0, double x)
{
    return G0 * (1.0 + swing_amplitude * sin(2.0 * M_PI * x / swing_wavelength));
}

/* One sweep of n positions, each by tirenv_model_eval, with the load changed before each if
 * changing; wall time in *seconds, mean force evaluations in *evals. */
static int sweep(tirenv_model *m, const tirenv_profile *road, double G0, size_t n,
                 const double x[], int changing, double *seconds, double *evals,
                 tirenv_diag *diag)
{
    int status = tirenv_model_set(m, road, G0, diag);  /* resets the warm start */
    double sum = 0;
    const double t0 = cli_wall_seconds();
    for (size_t k = 0; k < n && !status; ++k) {
        tirenv_point pt;
        if (changing)
            status = tirenv_model_set_load(m, swing(G0, x[k]), diag);
        if (!status)
            status = tirenv_model_eval(m, x[k], &pt, diag);
        sum += (double)pt.iterations;
    }
    *seconds = cli_wall_seconds() - t0;
    *evals = sum / (double)n;
    return status;
}

int cli_bench_set_load(const tirenv_tire *tire, const tirenv_profile *road, const tirenv_nn *nn,
                       double l_c, size_t n, const double x[], long repeat, tirenv_diag *diag)
{
    const tirenv_model_type *types[] = {tirenv_model_cam, tirenv_model_springs, tirenv_model_nn};
    cli_bench_say("\nset_load: a load of +-%.0f %% with a wavelength of %.1f m, changed before "
                  "every position by\ntirenv_model_set_load, against a fixed load, over the "
                  "road (per position, best of %ld,\ninterleaved; target: at most %.0f x)\n",
                  100 * swing_amplitude, swing_wavelength, repeat, load_target);
    cli_bench_say("  %-10s %12s %12s %8s %11s %11s %8s\n", "model", "fixed_us", "set_load_us",
                  "ratio", "evals_fixed", "evals_load", "");
    int status = TIRENV_OK;
    for (size_t i = 0; i < sizeof types / sizeof types[0] && !status; ++i) {
        const int needs_nn = (tirenv_model_type_flags(types[i]) & TIRENV_MODEL_NEEDS_NETWORK) != 0;
        if (needs_nn && !nn)
            continue;
        const char *name = tirenv_model_type_name(types[i]);
        tirenv_model *m = tirenv_model_alloc(types[i], tire);
        status = m ? TIRENV_OK : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        /* The network over the road's low bumps extrapolates, as in the bench's ride. */
        if (m)
            tirenv_model_set_extrapolate(m, 1);
        if (!status && needs_nn)
            status = tirenv_model_set_network(m, nn, 0, diag);
        double G0 = 0;
        if (!status)
            status = tirenv_model_load_for_contact_length(m, l_c, &G0, diag);
        double best[2] = {INFINITY, INFINITY}, evals[2] = {0, 0};
        for (long rep = 0; rep < repeat && !status; ++rep)
            for (int changing = 0; changing < 2 && !status; ++changing) {
                double t;
                status = sweep(m, road, G0, n, x, changing, &t, &evals[changing], diag);
                best[changing] = fmin(best[changing], t);
            }
        tirenv_model_free(m);
        if (status)
            break;
        const double fixed_us = 1e6 * best[0] / (double)n, load_us = 1e6 * best[1] / (double)n;
        const double ratio = load_us / fixed_us;
        char key[64];
        snprintf(key, sizeof key, "%s_fixed_load_step_us", name);
        cli_bench_figure(key, fixed_us);
        snprintf(key, sizeof key, "%s_set_load_step_us", name);
        cli_bench_figure(key, load_us);
        snprintf(key, sizeof key, "%s_set_load_over_fixed", name);
        cli_bench_figure(key, ratio);
        if (tirenv_model_type_flags(types[i]) & TIRENV_MODEL_EQUILIBRIUM) {
            snprintf(key, sizeof key, "%s_set_load_evals_per_pos", name);
            cli_bench_figure(key, evals[1]);
        }
        const int targeted = !needs_nn;
        cli_bench_say("  %-10s %12.3f %12.3f %8.2f %11.2f %11.2f %8s\n", name, fixed_us, load_us,
                      ratio, evals[0], evals[1], !targeted ? "" : ratio <= load_target ? "met"
                                                                                  : "missed");
    }
    return status;
}
