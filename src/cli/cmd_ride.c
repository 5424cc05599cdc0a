/* tirenv ride: the pitch-plane tractor driven over a profile by each axle's effective
 * profile, for several models and speeds, with ISO 2631-1 comfort figures.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/ride_cli.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv ride OBSTACLE --speed V[,V...] [--model M[,M...]] [--nn FILE]\n"
          "                   [--vehicle FILE] [--set KEY=VALUE]... [--x-from X] [--x-to X]\n"
          "                   [--dx DX] [--dt S] [--solver rk4|rk8pd] [-o FILE]\n"
          "                   [--out-dir DIR [--series]]\n"
          "\n"
          "Drives a pitch-plane tractor (body heave and pitch on a front and a rear axle, the\n"
          "tires as vertical spring-dampers, an optional front-axle suspension) over the\n"
          "obstacle at constant speed, each axle's tires following what the chosen model\n"
          "makes of the ground at the axle's static tire load, and reports ISO 2631-1 comfort\n"
          "figures at the seat: the Wk-weighted r.m.s. vertical acceleration, its crest factor,\n"
          "VDV and MTVV, and the We-weighted pitch acceleration. Steady start: the tractor is\n"
          "at rest vertically in static equilibrium when the run begins. The model and the\n"
          "metrics: docs/models.md sections 9 and 10.\n"
          "\n"
          "Models: point (the classic single-point contact: the tire follows the raw profile\n"
          "under its centre, the baseline), rigid, springs, ring, cam (effective profiles of\n"
          "'tirenv envelope') and nn (the trained network of 'tirenv train', --nn FILE).\n"
          "\n"
          "A table with one row per model and speed goes to standard output (also the run's\n"
          "time against real time). With one model and one speed, -o writes the time series;\n"
          "--out-dir DIR writes comfort.csv, comfort.md and the plots seat (seat\n"
          "acceleration over distance, at most 20,000 points a line) and spectrum (its PSD),\n"
          "each as .dat, .gp, .png and .svg; with --series also every run's full time series\n"
          "as series-MODEL-SPEEDkmh.csv (a 1 km road at 10 km/h: 55 MB a model). Series\n"
          "columns:\n"
          "  t_s,x_front_m,w_front_m,w_rear_m,z_m,theta_rad,z_axle_m,seat_az_m_s2,\n"
          "  seat_awz_m_s2,seat_ax_m_s2,atheta_rad_s2,F_front_N,F_rear_N\n"
          "(w: the axles' inputs; z, theta: body heave at the CG and pitch, nose up, from the\n"
          "static equilibrium; seat_awz: seat_az weighted by Wk).\n"
          "\n"
          "options:\n",
          fp);
    cli_help_obstacle(fp);
    fputs("  --speed V[,V...]     forward speeds, m/s, or km/h with the suffix km/h\n"
          "                       (e.g. 10km/h)\n"
          "  --model M[,M...]     models (default point,springs)\n"
          "  --nn FILE            the network for --model nn\n"
          "  --vehicle FILE       vehicle property file; default: $TIRENV_DATA/vehicles/\n"
          "                       tractor.veh if TIRENV_DATA is set, else the installed one\n"
          "  --set KEY=VALUE      override a key of the vehicle file (e.g. MASS=5200);\n"
          "                       repeatable\n"
          "  --x-from X, --x-to X front-axle positions where the run starts and ends, m;\n"
          "                       default: 1 m before the obstacle's first vertex, and its\n"
          "                       last vertex + wheelbase + max(3 m, 2 s of travel)\n"
          "  --dx DX              grid of the axles' inputs, m (default 0.005)\n"
          "  --dt S               output interval, s (default 0.001)\n"
          "  --solver S           rk4 (default; fixed steps of at most half a grid spacing)\n"
          "                       or rk8pd (adaptive, tolerance 1e-10)\n"
          "  -o, --output FILE    the time series of the one run, CSV, complete or not at all\n"
          "  --out-dir DIR        the comfort tables and plots into DIR (created if needed;\n"
          "                       replaced as a whole when the run succeeds, files of DIR\n"
          "                       the run does not write are kept)\n"
          "  --series             with --out-dir: also every run's time series\n"
          "  -h, --help           show this help\n",
          fp);
}

/* "10", "2.5m/s" or "10km/h" in m/s; 0 on success. */
static int parse_speed(const char *s, double *v)
{
    char buf[64];
    const size_t n = strlen(s);
    double scale = 1;
    if (n >= sizeof buf)
        return -1;
    memcpy(buf, s, n + 1);
    if (n > 4 && strcmp(buf + n - 4, "km/h") == 0) {
        buf[n - 4] = '\0';
        scale = 1 / 3.6;
    } else if (n > 3 && strcmp(buf + n - 3, "m/s") == 0) {
        buf[n - 3] = '\0';
    }
    if (cli_parse_double(buf, v) || !(*v > 0))
        return -1;
    *v *= scale;
    return 0;
}

/* Splits a comma-separated list in place into 1 to max non-empty items; 0 on success. */
static int split(char *s, const char *items[], size_t max, size_t *n)
{
    for (*n = 0;; s = s + strlen(s) + 1) {
        char *comma = strchr(s, ',');
        if (comma)
            *comma = '\0';
        if (!*s || *n == max)
            return -1;
        items[(*n)++] = s;
        if (!comma)
            return 0;
    }
}

static int known_model(const char *name)
{
    return strcmp(name, "point") == 0 || strcmp(name, "nn") == 0 ||
           tirenv_model_type_find(name) != NULL;
}

/* Parses the options; returns an exit code, or -1 to go on. */
static int parse(int argc, char *argv[], cli_options *o, ride_options *r)
{
    enum { OPT_SPEED = CLI_OPT_FIRST_OWN, OPT_MODEL, OPT_NN, OPT_VEHICLE, OPT_X_FROM, OPT_X_TO,
           OPT_DX, OPT_DT, OPT_SOLVER, OPT_OUT_DIR, OPT_SERIES };
    static const struct option longopts[] = {
        CLI_OBSTACLE_LONGOPTS,
        {"set", required_argument, NULL, CLI_OPT_SET},
        {"speed", required_argument, NULL, OPT_SPEED},
        {"model", required_argument, NULL, OPT_MODEL},
        {"nn", required_argument, NULL, OPT_NN},
        {"vehicle", required_argument, NULL, OPT_VEHICLE},
        {"x-from", required_argument, NULL, OPT_X_FROM},
        {"x-to", required_argument, NULL, OPT_X_TO},
        {"dx", required_argument, NULL, OPT_DX},
        {"dt", required_argument, NULL, OPT_DT},
        {"solver", required_argument, NULL, OPT_SOLVER},
        {"out-dir", required_argument, NULL, OPT_OUT_DIR},
        {"series", no_argument, NULL, OPT_SERIES},
        {"output", required_argument, NULL, 'o'},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    const char *speeds[RIDE_MAX_SPEEDS];
    int c;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, NULL)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return CLI_EXIT_OK;
        case 'o':
            r->out_path = optarg;
            break;
        case OPT_OUT_DIR:
            r->out_dir = optarg;
            break;
        case OPT_SERIES:
            r->series = 1;
            break;
        case OPT_NN:
            r->nn_path = optarg;
            break;
        case OPT_VEHICLE:
            r->vehicle_path = optarg;
            break;
        case CLI_OPT_SET:
            if (r->n_sets == CLI_MAX_SETS) {
                cli_error("ride: at most %d --set options", CLI_MAX_SETS);
                return CLI_EXIT_USAGE;
            }
            r->sets[r->n_sets++] = optarg;
            break;
        case OPT_SPEED: {
            snprintf(r->speed_buf, sizeof r->speed_buf, "%s", optarg);
            if (split(r->speed_buf, speeds, RIDE_MAX_SPEEDS, &r->n_speeds)) {
                cli_error("ride: --speed expects 1 to %d comma-separated speeds, got '%s'",
                          RIDE_MAX_SPEEDS,
                          optarg);
                return CLI_EXIT_USAGE;
            }
            for (size_t i = 0; i < r->n_speeds; ++i)
                if (parse_speed(speeds[i], &r->speeds[i])) {
                    cli_error("ride: --speed expects speeds > 0 in m/s or with the suffix "
                              "km/h, got '%s'", speeds[i]);
                    return CLI_EXIT_USAGE;
                }
            break;
        }
        case OPT_MODEL:
            snprintf(r->model_buf, sizeof r->model_buf, "%s", optarg);
            if (split(r->model_buf, r->models, RIDE_MAX_MODELS, &r->n_models)) {
                cli_error("ride: --model expects 1 to %d comma-separated models, got '%s'",
                          RIDE_MAX_MODELS,
                          optarg);
                return CLI_EXIT_USAGE;
            }
            for (size_t i = 0; i < r->n_models; ++i)
                if (!known_model(r->models[i])) {
                    fputs("tirenv: ride: --model: expected point,", stderr);
                    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t)
                        fprintf(stderr, " %s,", tirenv_model_type_name(*t));
                    fprintf(stderr, " or nn, got '%s'\n", r->models[i]);
                    return CLI_EXIT_USAGE;
                }
            break;
        case OPT_X_FROM:
        case OPT_X_TO:
            if (cli_parse_double(optarg, c == OPT_X_FROM ? &r->x_from : &r->x_to)) {
                cli_error("ride: --%s expects a position in m, got '%s'",
                          c == OPT_X_FROM ? "x-from" : "x-to", optarg);
                return CLI_EXIT_USAGE;
            }
            *(c == OPT_X_FROM ? &r->have_from : &r->have_to) = 1;
            break;
        case OPT_DX:
        case OPT_DT: {
            double *v = c == OPT_DX ? &r->dx : &r->dt;
            if (cli_parse_double(optarg, v) || !(*v > 0)) {
                cli_error("ride: --%s expects a positive number (%s), got '%s'",
                          c == OPT_DX ? "dx" : "dt", c == OPT_DX ? "m" : "s", optarg);
                return CLI_EXIT_USAGE;
            }
            break;
        }
        case OPT_SOLVER:
            if (strcmp(optarg, "rk4") == 0) {
                r->method = TIRENV_RIDE_RK4;
            } else if (strcmp(optarg, "rk8pd") == 0) {
                r->method = TIRENV_RIDE_RK8PD;
            } else {
                cli_error("ride: --solver expects rk4 or rk8pd, got '%s'", optarg);
                return CLI_EXIT_USAGE;
            }
            break;
        default:
            if (c >= CLI_OPT_CLEAT && c <= CLI_OPT_PROFILE) {
                if (cli_option(o, c, optarg))
                    return CLI_EXIT_USAGE;
                break;
            }
            usage(stderr);
            return CLI_EXIT_USAGE;
        }
    }
    if (optind < argc) {
        cli_error("ride: unexpected argument '%s'", argv[optind]);
        return CLI_EXIT_USAGE;
    }
    if (!r->n_speeds) {
        cli_error("ride: expected --speed V; 'tirenv ride --help' shows the options");
        return CLI_EXIT_USAGE;
    }
    if (r->out_path && (r->n_models > 1 || r->n_speeds > 1)) {
        cli_error("ride: -o writes the series of one run (one model, one speed); use "
                  "--out-dir DIR for %zu models x %zu speeds", r->n_models, r->n_speeds);
        return CLI_EXIT_USAGE;
    }
    if (r->series && !r->out_dir) {
        cli_error("ride: --series writes into --out-dir DIR; with one run, -o FILE writes "
                  "its series");
        return CLI_EXIT_USAGE;
    }
    for (size_t i = 0; i < r->n_models; ++i)
        if (strcmp(r->models[i], "nn") == 0 && !r->nn_path) {
            cli_error("ride: --model nn needs the network: --nn FILE (from 'tirenv train')");
            return CLI_EXIT_USAGE;
        }
    return -1;
}

int cli_ride_main(int argc, char *argv[])
{
    cli_options o;
    cli_options_init(&o);
    ride_options r = {.dx = 0.005, .dt = 0.001, .method = TIRENV_RIDE_RK4,
                      .models = {"point", "springs"}, .n_models = 2};
    const int code = parse(argc, argv, &o, &r);
    if (code >= 0)
        return code;
    return ride_cli_run(&o, &r);
}
