/* tirenv rig: the virtual rig, a cart run over an obstacle written as a raw log.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>

#include "cli/cli.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv rig OBSTACLE (--load N | --contact-length M) -o LOG.csv\n"
          "                  [--model NAME] [--speed M_S] [--rate HZ] [--noise SX,SZ]\n"
          "                  [--offset X,Z] [--seed S] [--track V] [--side S]\n"
          "                  [--crg-nan-mode M] [--tire FILE] [--set KEY=VALUE]...\n"
          "                  [--method M]\n"
          "\n"
          "Simulates the paper's test rig (its Figure 2): a cart rolls the tire over the\n"
          "obstacle at constant speed and vertical load; x(t), z(t) of the tire centre are\n"
          "sampled with Gaussian sensor noise and written as a raw log 't_s,x_m,z_m', the\n"
          "format 'tirenv import' reads. The log is SIMULATED and says so in its header.\n"
          "\n"
          "options:\n",
          fp);
    cli_help_obstacle(fp);
    cli_help_road(fp, 0);
    cli_help_load(fp);
    cli_help_model(fp, 0, TIRENV_MODEL_NEEDS_NETWORK, " (default ring, the reference tire)");
    fputs("  --speed M_S          cart speed, m/s (default 0.1)\n"
          "  --rate HZ            sampling rate, Hz (default 100); speed/rate must leave at\n"
          "                       least 40 samples over L/2 + R0 (what the import needs),\n"
          "                       and the rate at most 1 MHz (the log's 1 us)\n"
          "  --noise SX,SZ        sensor noise sigma on x and z, m (default 5e-5,2e-4)\n"
          "  --offset X,Z         rig readings at obstacle x = 0 and centre z = 0, m (default 0,0);\n"
          "                       readings up to 2.25e9 m, which doubles resolve to the log's\n"
          "                       1 um\n"
          "  --seed S             noise seed (default 1)\n"
          "  -o, --output FILE    the log to write (required; '-' for stdout)\n",
          fp);
    cli_help_tire(fp, 1, "FOUNDATION_STIFFNESS=1.2e5 (the ring's)");
    fputs("  -h, --help           show this help\n", fp);
}

/* --noise SX,SZ and --offset X,Z into two fields of the rig settings. */
static int parse_noise(void *dst, const char *arg)
{
    tirenv_rig_settings *rig = dst;
    double v[2];
    if (cli_parse_doubles(arg, v, 2) || v[0] < 0 || v[1] < 0) {
        cli_error("--noise: expected SX,SZ, two numbers >= 0 in m, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    rig->noise_x = v[0];
    rig->noise_z = v[1];
    return CLI_EXIT_OK;
}

static int parse_offset(void *dst, const char *arg)
{
    tirenv_rig_settings *rig = dst;
    double v[2];
    if (cli_parse_doubles(arg, v, 2)) {
        cli_error("--offset: expected X,Z, two numbers in m, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    rig->x_offset = v[0];
    rig->z_offset = v[1];
    return CLI_EXIT_OK;
}

int cli_rig_main(int argc, char *argv[])
{
    tirenv_rig_settings rig = tirenv_rig_default();
    long seed = (long)rig.seed;
    const cli_opt own[] = {
        {.name = "speed", .kind = CLI_POSITIVE, .dst = &rig.speed, .what = "a speed > 0 in m/s"},
        {.name = "rate", .kind = CLI_POSITIVE, .dst = &rig.rate, .what = "a rate > 0 in Hz"},
        {.name = "noise", .kind = CLI_CUSTOM, .dst = &rig, .parse = parse_noise},
        {.name = "offset", .kind = CLI_CUSTOM, .dst = &rig, .parse = parse_offset},
        {.name = "seed", .kind = CLI_COUNT, .dst = &seed, .min = 0, .max = 2147483647L,
         .what = "a whole number >= 0"},
        {.name = NULL},
    };
    const cli_parser parser = {.name = "rig", .usage = usage, .opts = own,
                               .groups = CLI_TIRE | CLI_METHOD | CLI_LOAD | CLI_OBSTACLE |
                                         CLI_OUTPUT | CLI_MODEL};
    cli_options o;
    const int parsed = cli_parse(&parser, argc, argv, &o);
    if (parsed != CLI_GO_ON)
        return parsed;
    if (!o.output) {
        cli_error("rig: -o LOG.csv is required");
        return CLI_EXIT_USAGE;
    }
    if (!o.have_load && !o.have_contact_length) {
        cli_error("rig: expected --load N or --contact-length M; 'tirenv rig --help' shows "
                  "the options");
        return CLI_EXIT_USAGE;
    }
    rig.seed = (unsigned long)seed;
    const tirenv_model_type *type = o.type ? o.type : tirenv_model_ring;
    o.runs[o.n_runs++] = type;
    const char *out_path = o.output;
    tirenv_tire tire;
    tirenv_model *m = NULL;
    tirenv_profile *p = NULL;
    double load;
    int code = cli_tire(&o, &tire);
    if (!code)
        code = cli_profile(&o, &p);
    if (!code)
        code = cli_model(type, &tire, &o, &m);
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
