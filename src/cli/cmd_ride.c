/* tirenv ride: the pitch-plane tractor driven over a profile by each axle's effective
 * profile, for several models and speeds, with ISO 2631-1 comfort figures.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/ride_cli.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv ride OBSTACLE --speed V[,V...] [--model M[,M...]]\n"
          "                   [--nn FILE [--extrapolate]]\n"
          "                   [--vehicle FILE] [--set KEY=VALUE]... [--x-from X] [--x-to X]\n"
          "                   [--track V] [--side S] [--crg-nan-mode M]\n"
          "                   [--dx DX] [--dt S] [--solver rk4|rk8pd] [-o FILE]\n"
          "                   [--out-dir DIR [--series]] [--jobs N]\n"
          "                   [--enveloping static|dynamic|direct[,...]]\n"
          "\n"
          "Drives a pitch-plane tractor (body heave and pitch on a front and a rear axle, the\n"
          "tires as vertical spring-dampers, an optional front-axle suspension) over the\n"
          "obstacle at constant speed, each axle's tires following what the chosen model\n"
          "makes of the ground at the load they carry (or at the axle's static tire load, with\n"
          "--enveloping static), and reports ISO 2631-1 comfort figures at the seat: the\n"
          "Wk-weighted r.m.s. vertical acceleration, its crest factor, VDV and MTVV, and the\n"
          "We-weighted pitch acceleration. Steady start: the tractor is\n"
          "at rest vertically in static equilibrium when the run begins. The model and the\n"
          "metrics: docs/models.md sections 9 and 10.\n"
          "\n"
          "Models: every model of 'tirenv envelope' (the same effective profiles), among\n"
          "them point (the classic single-point contact: the tire follows the raw profile\n"
          "under its centre, the baseline) and nn (the trained network of 'tirenv train',\n"
          "--nn FILE).\n"
          "\n"
          "A table with one row per model, way of enveloping and speed goes to standard\n"
          "output (also the run's time against real time). With one model, one way and one\n"
          "speed, -o writes the time series; --out-dir DIR writes comfort.csv, comfort.md and\n"
          "the plots seat (seat acceleration over distance, at most 20,000 points a line),\n"
          "seat-rms (the running r.m.s. over 1 s of its Wk-weighted value, whose maximum is\n"
          "the MTVV) and spectrum (its PSD), each as .dat, .gp, .png and .svg; with --series\n"
          "also every run's full time series as series-MODEL-SPEEDkmh.csv\n"
          "(series-MODEL-WAY-SPEEDkmh.csv with several ways; a 1 km road at 10 km/h: 55 MB a\n"
          "run). Series columns:\n"
          "  t_s,x_front_m,w_front_m,w_rear_m,z_m,theta_rad,z_axle_m,seat_az_m_s2,\n"
          "  seat_awz_m_s2,seat_ax_m_s2,atheta_rad_s2,F_front_N,F_rear_N\n"
          "(w: the axles' inputs; z, theta: body heave at the CG and pitch, nose up, from the\n"
          "static equilibrium; seat_awz: seat_az weighted by Wk).\n"
          "\n"
          "options:\n",
          fp);
    cli_help_obstacle(fp);
    cli_help_road(fp, 0);
    fputs("  --speed V[,V...]     forward speeds, m/s, or km/h with the suffix km/h\n"
          "                       (e.g. 10km/h)\n"
          "  --model M[,M...]     models (default point,springs)\n"
          "  --nn FILE            the network for --model nn\n"
          "  --extrapolate        let the network run outside its trained ranges (over a\n"
          "                       road, bumps lower or longer than its cleats), with a\n"
          "                       warning; without it such input is refused\n"
          "  --vehicle FILE       vehicle property file; default: vehicles/tractor.veh in\n"
          "                       the data directory ($TIRENV_DATA, else the installed data);\n"
          "                       a key it leaves out keeps the default tractor's value, and\n"
          "                       a warning names it\n"
          "  --set KEY=VALUE      override a key of the vehicle file (e.g. MASS=5200);\n"
          "                       repeatable\n"
          "                       Each axle's tires are its TIRE_FILE's: their spring the\n"
          "                       file's vertical law F_z(rho) (its tangent k_t at the\n"
          "                       static load only for the linear checks), their damper\n"
          "                       c_t its VERTICAL_DAMPING, unless the vehicle gives\n"
          "                       TIRE_STIFFNESS (a linear spring) or TIRE_DAMPING (e.g.\n"
          "                       --set FRONT_AXLE.TIRE_STIFFNESS=300000); --out-dir's\n"
          "                       comfort.md says which the run used\n"
          "  --x-from X, --x-to X front-axle positions where the run starts and ends, m;\n"
          "                       default: 1 m before the obstacle's first vertex, and its\n"
          "                       last vertex + wheelbase + max(3 m, 2 s of travel)\n"
          "  --dx DX              grid of the axles' inputs, m (default 0.005; at most a\n"
          "                       tenth of the tires' free radius)\n"
          "  --dt S               output interval, s (default 0.001; 1e-5 to 1/320)\n"
          "  --solver S           rk4 (default; fixed steps of at most half a grid spacing)\n"
          "                       or rk8pd (adaptive, tolerance 1e-10)\n"
          "  --enveloping E[,E...]  how each axle's input follows the tire load\n"
          "                       (docs/models.md section 9.5): dynamic (default), the\n"
          "                       effective road at the load the tires carry at each instant,\n"
          "                       from tables over 14 loads from 0.1 to 3 times the static\n"
          "                       one (a tire that lifts off follows the lightest); static,\n"
          "                       the effective road at the static load, the paper's\n"
          "                       constant-load curve; direct, the model evaluated at the\n"
          "                       load during the integration, the slow reference the tables\n"
          "                       are checked against. Several: one run each, and comfort.md\n"
          "                       compares them with the static run\n"
          "  -o, --output FILE    the time series of the one run, CSV, complete or not at all\n"
          "  --out-dir DIR        the comfort tables and plots into DIR (created if needed;\n"
          "                       replaced as a whole when the run succeeds, files of DIR\n"
          "                       the run does not write are kept)\n"
          "  --series             with --out-dir: also every run's time series\n",
          fp);
    cli_help_jobs(fp);
    fputs("  -h, --help           show this help\n", fp);
}

void ride_cli_speed_name(double V, char *buf, size_t n)
{
    snprintf(buf, n, "%g", V * 3.6);
}

/* --speed V[,V...]: 1 to TIRENV_RIDE_PLAN_RUNS speeds, each as the library reads one (its error
 * names what a speed must be), no two of one name: 5 and 5.00001 m/s were both 18 km/h, and
 * the second run's series file replaced the first's. */
static int parse_speeds(void *dst, const char *arg)
{
    ride_options *r = dst;
    snprintf(r->speed_buf, sizeof r->speed_buf, "%s", arg);
    r->n_speeds = 0;
    for (char *p = r->speed_buf;; ++p) {
        char *comma = strchr(p, ',');
        if (comma)
            *comma = '\0';
        if (!*p || r->n_speeds == TIRENV_RIDE_PLAN_RUNS) {
            cli_error("ride: --speed expects 1 to %d comma-separated speeds, got '%s'",
                      TIRENV_RIDE_PLAN_RUNS, arg);
            return CLI_EXIT_USAGE;
        }
        tirenv_diag d;
        if (tirenv_ride_speed_parse(p, &r->speeds[r->n_speeds++], &d)) {
            cli_error("ride: --speed: %s", d.message);
            return CLI_EXIT_USAGE;
        }
        char name[32], other[32];
        ride_cli_speed_name(r->speeds[r->n_speeds - 1], name, sizeof name);
        for (size_t k = 0; k + 1 < r->n_speeds; ++k) {
            ride_cli_speed_name(r->speeds[k], other, sizeof other);
            if (strcmp(name, other) == 0) {
                cli_error("ride: --speed: '%s' is %s km/h, as speed %zu is, in '%s': the two "
                          "runs would share the series file and the plots' panel named %s "
                          "km/h; expected distinct speeds", p, name, k + 1, arg, name);
                return CLI_EXIT_USAGE;
            }
        }
        if (!comma)
            return CLI_EXIT_OK;
        p = comma;
    }
}

/* --model M[,M...]: 1 to RIDE_MAX_MODELS names from the library's table of model types, each
 * at most once (a model twice ran twice into one series file and one plot column name). */
static int parse_models(void *dst, const char *arg)
{
    ride_options *r = dst;
    const int code = cli_model_list("ride: --model", arg, r->models, RIDE_MAX_MODELS,
                                    &r->n_models);
    for (size_t i = 0; !code && i < r->n_models; ++i)
        for (size_t k = 0; k < i; ++k)
            if (r->models[k] == r->models[i]) {
                cli_error("ride: --model: '%s' given twice in '%s'; expected each model at "
                          "most once", tirenv_model_type_name(r->models[i]), arg);
                return CLI_EXIT_USAGE;
            }
    return code;
}

static int parse_set(void *dst, const char *arg)
{
    ride_options *r = dst;
    if (r->n_sets == CLI_MAX_SETS) {
        cli_error("ride: at most %d --set options", CLI_MAX_SETS);
        return CLI_EXIT_USAGE;
    }
    r->sets[r->n_sets++] = arg;
    return CLI_EXIT_OK;
}

/* --enveloping E[,E...]: static, dynamic, direct, each at most once, each name as the
 * library reads it (its error names the ways). */
static int parse_enveloping(void *dst, const char *arg)
{
    ride_options *r = dst;
    r->n_envelopings = 0;
    const char *p = arg;
    for (;;) {
        const size_t len = strcspn(p, ",");
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)(len < sizeof name ? len : sizeof name - 1),
                 p);
        tirenv_ride_enveloping e;
        tirenv_diag d;
        if (tirenv_ride_enveloping_parse(name, &e, &d)) {
            cli_error("ride: --enveloping: %s", d.message);
            return CLI_EXIT_USAGE;
        }
        for (size_t k = 0; k < r->n_envelopings; ++k)
            if (r->envelopings[k] == e) {
                cli_error("ride: --enveloping: '%s' given twice in '%s'; expected each way at "
                          "most once", name, arg);
                return CLI_EXIT_USAGE;
            }
        r->envelopings[r->n_envelopings++] = e;
        if (!p[len])
            return CLI_EXIT_OK;
        p += len + 1;
    }
}

static int parse_solver(void *dst, const char *arg)
{
    tirenv_diag d;
    if (tirenv_ride_method_parse(arg, dst, &d)) {
        cli_error("ride: --solver: %s", d.message);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

int cli_ride_main(int argc, char *argv[])
{
    ride_options r = {.pp = tirenv_ride_plan_params_default(),
                      .models = {tirenv_model_point, tirenv_model_springs}, .n_models = 2};
    const cli_opt own[] = {
        {.name = "speed", .kind = CLI_CUSTOM, .dst = &r, .parse = parse_speeds},
        {.name = "model", .kind = CLI_CUSTOM, .dst = &r, .parse = parse_models},
        {.name = "vehicle", .kind = CLI_STRING, .dst = &r.vehicle_path, .input = CLI_INPUT_FILE},
        {.name = "set", .kind = CLI_CUSTOM, .dst = &r, .parse = parse_set, .repeatable = 1},
        {.name = "dt", .kind = CLI_POSITIVE, .dst = &r.pp.dt, .what = "a positive number in s"},
        {.name = "solver", .kind = CLI_CUSTOM, .dst = &r.pp.method, .parse = parse_solver},
        {.name = "enveloping", .kind = CLI_CUSTOM, .dst = &r, .parse = parse_enveloping},
        {.name = "out-dir", .kind = CLI_STRING, .dst = &r.out_dir},
        {.name = "series", .kind = CLI_FLAG, .dst = &r.series},
        {.name = NULL},
    };
    const cli_parser p = {.name = "ride", .usage = usage, .opts = own,
                          .groups = CLI_OBSTACLE | CLI_SWEEP | CLI_OUTPUT | CLI_NETWORK |
                                    CLI_EXTRAPOLATE | CLI_JOBS};
    cli_options o;
    const int code = cli_parse(&p, argc, argv, &o);
    if (code != CLI_GO_ON)
        return code;
    r.jobs = o.jobs;
    r.nn_path = o.nn_path;
    r.extrapolate = o.extrapolate;
    r.out_path = o.output;
    if (!isnan(o.dx))
        r.pp.span.dx = o.dx;
    r.pp.x_from = o.x_from;  /* NAN unless given: the span's */
    r.pp.x_to = o.x_to;
    if (!r.n_speeds) {
        cli_error("ride: expected --speed V; 'tirenv ride --help' shows the options");
        return CLI_EXIT_USAGE;
    }
    if (!r.n_envelopings) {
        r.envelopings[0] = TIRENV_RIDE_ENVELOPING_DEFAULT;
        r.n_envelopings = 1;
    }
    if (r.out_path && (r.n_models > 1 || r.n_speeds > 1 || r.n_envelopings > 1)) {
        cli_error("ride: -o writes the series of one run (one model, one speed, one way of "
                  "enveloping); use --out-dir DIR for %zu models x %zu speeds x %zu ways",
                  r.n_models, r.n_speeds, r.n_envelopings);
        return CLI_EXIT_USAGE;
    }
    if (r.series && !r.out_dir) {
        cli_error("ride: --series writes into --out-dir DIR; with one run, -o FILE writes "
                  "its series");
        return CLI_EXIT_USAGE;
    }
    /* The columns of the tables and plots: each model, in each way asked, labelled by the
     * model alone when there is one way. */
    for (size_t i = 0; i < r.n_models; ++i)
        for (size_t e = 0; e < r.n_envelopings; ++e) {
            ride_column *c = &r.cols[r.n_cols++];
            const char *name = tirenv_model_type_name(r.models[i]);
            c->model = i;
            c->enveloping = r.envelopings[e];
            if (r.n_envelopings == 1)
                snprintf(c->label, sizeof c->label, "%s", name);
            else
                snprintf(c->label, sizeof c->label, "%s-%s", name,
                         tirenv_ride_enveloping_name(c->enveloping));
        }
    size_t with_nn = 0;
    for (size_t i = 0; i < r.n_models; ++i)
        if (tirenv_model_type_flags(r.models[i]) & TIRENV_MODEL_NEEDS_NETWORK) {
            ++with_nn;
            if (!r.nn_path) {
                cli_error("ride: --model %s needs the network: --nn FILE (from 'tirenv train')",
                          tirenv_model_type_name(r.models[i]));
                return CLI_EXIT_USAGE;
            }
        }
    /* As envelope's: a network no model evaluates was taken and not even opened, exit 0. */
    if (r.nn_path && !with_nn) {
        cli_error("ride: --nn is for a model that evaluates a network; none of --model's does "
                  "(add nn to --model)");
        return CLI_EXIT_USAGE;
    }
    return ride_cli_run(&o, &r);
}
