/* tirenv rig: the virtual rig, a cart run over an obstacle written as a raw log.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdio.h>

#include "cli/cli.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv rig OBSTACLE (--load N | --contact-length M) -o LOG.csv\n"
          "                  [--model NAME] [--speed M_S] [--rate HZ] [--noise SX,SZ]\n"
          "                  [--offset X,Z] [--seed S] [--tire FILE] [--set KEY=VALUE]...\n"
          "\n"
          "Simulates the paper's test rig (its Figure 2): a cart rolls the tire over the\n"
          "obstacle at constant speed and vertical load; x(t), z(t) of the tire centre are\n"
          "sampled with Gaussian sensor noise and written as a raw log 't_s,x_m,z_m', the\n"
          "format 'tirenv import' reads. The log is SIMULATED and says so in its header.\n"
          "\n"
          "options:\n",
          fp);
    cli_help_obstacle(fp);
    cli_help_load(fp);
    cli_help_model(fp, " (default ring, the reference tire)");
    fputs("  --speed M_S          cart speed, m/s (default 0.1)\n"
          "  --rate HZ            sampling rate, Hz (default 100)\n"
          "  --noise SX,SZ        sensor noise sigma on x and z, m (default 5e-5,2e-4)\n"
          "  --offset X,Z         rig readings at obstacle x = 0 and centre z = 0, m (default 0,0)\n"
          "  --seed S             noise seed (default 1)\n"
          "  -o FILE              the log to write (required; '-' for stdout)\n",
          fp);
    cli_help_tire(fp, 1);
    fputs("  -h, --help           show this help\n", fp);
}

int cli_rig_main(int argc, char *argv[])
{
    enum { OPT_MODEL = CLI_OPT_FIRST_OWN, OPT_SPEED, OPT_RATE, OPT_NOISE, OPT_OFFSET, OPT_SEED };
    static const struct option longopts[] = {
        CLI_TIRE_LONGOPTS,
        CLI_METHOD_LONGOPTS,
        CLI_LOAD_LONGOPTS,
        CLI_OBSTACLE_LONGOPTS,
        {"model", required_argument, NULL, OPT_MODEL},
        {"speed", required_argument, NULL, OPT_SPEED},
        {"rate", required_argument, NULL, OPT_RATE},
        {"noise", required_argument, NULL, OPT_NOISE},
        {"offset", required_argument, NULL, OPT_OFFSET},
        {"seed", required_argument, NULL, OPT_SEED},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    cli_options o;
    cli_options_init(&o);
    const tirenv_model_type *type = tirenv_model_ring;
    tirenv_rig_settings rig = tirenv_rig_default();
    const char *out_path = NULL;
    double pair[2];
    long seed;
    int c;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, NULL)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return CLI_EXIT_OK;
        case 'o':
            out_path = optarg;
            break;
        case OPT_MODEL:
            if (cli_model_type(optarg, &type))
                return CLI_EXIT_USAGE;
            break;
        case OPT_SPEED:
        case OPT_RATE:
            if (cli_parse_double(optarg, c == OPT_SPEED ? &rig.speed : &rig.rate) ||
                !((c == OPT_SPEED ? rig.speed : rig.rate) > 0)) {
                cli_error("rig: --%s expects a positive number, got '%s'",
                          c == OPT_SPEED ? "speed" : "rate", optarg);
                return CLI_EXIT_USAGE;
            }
            break;
        case OPT_NOISE:
        case OPT_OFFSET:
            if (cli_parse_doubles(optarg, pair, 2) || (c == OPT_NOISE && (pair[0] < 0 || pair[1] < 0))) {
                cli_error("rig: --%s expects two numbers X,Z%s, got '%s'",
                          c == OPT_NOISE ? "noise" : "offset",
                          c == OPT_NOISE ? " (not negative)" : "", optarg);
                return CLI_EXIT_USAGE;
            }
            if (c == OPT_NOISE) {
                rig.noise_x = pair[0];
                rig.noise_z = pair[1];
            } else {
                rig.x_offset = pair[0];
                rig.z_offset = pair[1];
            }
            break;
        case OPT_SEED:
            if (cli_parse_count(optarg, 0, 2147483647L, &seed)) {
                cli_error("rig: --seed expects a whole number >= 0, got '%s'", optarg);
                return CLI_EXIT_USAGE;
            }
            rig.seed = (unsigned long)seed;
            break;
        case '?':
            usage(stderr);
            return CLI_EXIT_USAGE;
        default:
            if (cli_option(&o, c, optarg))
                return CLI_EXIT_USAGE;
        }
    }
    if (optind < argc || !out_path) {
        cli_error(optind < argc ? "rig: unexpected argument '%s'" : "rig: -o LOG.csv is required%s",
                  optind < argc ? argv[optind] : "");
        return CLI_EXIT_USAGE;
    }
    tirenv_tire tire;
    tirenv_model *m = NULL;
    tirenv_profile *p = NULL;
    double load;
    int code = cli_tire(&o, &tire);
    if (!code)
        code = cli_profile(&o, &p);
    if (!code)
        code = cli_model(type, &tire, &m);
    if (!code)
        code = cli_load(&o, m, &load);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_rig_log log = {0};
    int status = TIRENV_OK;
    if (!code && !(status = tirenv_model_set(m, p, load, &diag)))
        status = tirenv_rig_simulate(m, p, &rig, &log, &diag);
    if (!code && !status) {
        char comment[512];
        snprintf(comment, sizeof comment,
                 "SIMULATED rig log (tirenv virtual rig, %s model), not a measurement.\n"
                 "load %.2f N; speed %g m/s, %g Hz, noise sigma x %g m, z %g m, seed %lu",
                 tirenv_model_type_name(type), load, rig.speed, rig.rate, rig.noise_x,
                 rig.noise_z, rig.seed);
        status = tirenv_rig_write_log(out_path, &log, comment, &diag);
    }
    if (!code && status)
        code = cli_fail(status, &diag);
    if (!code)
        fprintf(stderr, "tirenv: rig: %zu samples written to %s\n", log.n, out_path);
    tirenv_rig_log_free(&log);
    tirenv_model_free(m);
    tirenv_profile_free(p);
    return code;
}
