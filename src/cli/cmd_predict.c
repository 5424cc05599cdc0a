/* tirenv predict (and tirenv envelope --model nn): the enveloping curve of the trained network
 * over a rectangular cleat, or over any profile by the equivalent-cleat decomposition of
 * nn_road.h, in the CSV of the other models. SPDX-License-Identifier: GPL-3.0-or-later */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/csv_row.h"
#include "tirenv/train.h"

/* As tirenv envelope: the default sweep from R0 + 0.02 m before the cleat to as far beyond
 * it, 1 mm apart. */
static const double margin = 0.02;     /* m */
static const double default_dx = 0.001; /* m */

static void usage(FILE *fp, const char *cmd)
{
    const int env = strcmp(cmd, "envelope") == 0;
    fprintf(fp, "usage: tirenv %s --nn MODEL.json OBSTACLE (--load N | --contact-length M)\n"
            "       %*s [--x-from X] [--x-to X] [--dx DX] [-o FILE]\n"
            "       %*s [--tire FILE] [--set KEY=VALUE]... [--method M]\n",
            env ? "envelope --model nn" : "predict", env ? 26 : 14, "", env ? 26 : 14, "");
    fputs("\n"
          "The enveloping curve of the empirical model, the trained network of 'tirenv train'\n"
          "(paper, Tables 1 and 2), in the CSV of 'tirenv envelope':\n"
          "  x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n"
          "Over --cleat L,H (centred at x = 0), h is the network at x_N(x) (docs/models.md\n"
          "section 1) on the approach half, mirrored on the other, and slope is dh/dx of the\n"
          "written curve (central differences). Over any other obstacle or a --profile (a road\n"
          "from 'tirenv road', say) the network, trained on single cleats, is extended beyond the\n"
          "paper by an equivalent-cleat decomposition: the profile's opening by a window 1.5\n"
          "times the longest trained cleat is the baseline; each bump above it becomes the cleat\n"
          "of equal height and area; h is the baseline or the highest of the bumps' network\n"
          "curves added to it (include/tirenv/nn_road.h); slope is its derivative. z = z_flat + h\n"
          "with z_flat = sqrt(R0^2 - (l_c/2)^2), the chord relation; fz is the load; fx, contacts\n"
          "and iterations are 0 (the network knows none of them).\n"
          "An input outside the range the network was trained on draws a warning naming it;\n"
          "over a profile, one warning counts the bumps clamped to the range (bumps lower than\n"
          "the lowest trained cleat scale its curve down instead, and are only counted in the\n"
          "summary). R0 is the one the network's data referred to (from the model file).\n"
          "\n"
          "options:\n"
          "  --nn FILE            the model file written by 'tirenv train -o'\n"
          "  --cleat L,H          rectangular cleat: length and height in m (h is 0 before\n"
          "                       the first x_N the network saw, and never below 0)\n"
          "  --profile FILE       or a ground profile, CSV x_m,z_m (or a generated obstacle:\n"
          "                       --step, --trapezoid, --triangle, --cylinder, --sine as in\n"
          "                       'tirenv envelope --help')\n"
          "  --contact-length M   the working regime, the network's input, in m\n"
          "  --load N             or the load, N, turned into the contact length of the springs\n"
          "                       model of the tire file (--contact-length is turned into the\n"
          "                       fz column the same way)\n"
          "  --x-from X, --x-to X first and last centre position, m; default: from R0 + 0.02 m\n"
          "                       before the obstacle's first vertex to R0 + 0.02 m after its\n"
          "                       last\n"
          "  --dx DX              spacing of the positions, m (default 0.001)\n"
          "  -o, --output FILE    write the CSV to FILE, complete or not at all (default or\n"
          "                       '-': standard output)\n",
          fp);
    cli_help_tire(fp, 1);
    fputs("  -h, --help           show this help\n", fp);
}

/* dh/dx of the written curve at k: central differences inside, one-sided at the ends (the
 * network has no forces to give an effective slope from). */
static double curve_slope(size_t n, const double x[], const double h[], size_t k)
{
    if (n < 2)
        return 0;
    const size_t lo = k > 0 ? k - 1 : 0, hi = k + 1 < n ? k + 1 : n - 1;
    return (h[hi] - h[lo]) / (x[hi] - x[lo]);
}

/* "--model nn" or "--model=nn" among the arguments: tirenv envelope hands itself over. */
int cli_predict_is_nn(int argc, char *argv[])
{
    for (int k = 1; k < argc; ++k) {
        if (strcmp(argv[k], "--") == 0)
            return 0;
        if (strcmp(argv[k], "--model=nn") == 0 ||
            (strcmp(argv[k], "--model") == 0 && k + 1 < argc && strcmp(argv[k + 1], "nn") == 0))
            return 1;
    }
    return 0;
}

typedef struct {
    const char *nn_path, *out_path;
    int have_from, have_to;
    double x_from, x_to, dx;  /* m */
} predict_options;

/* Parses the options; returns an exit code, or -1 to go on. */
static int parse(int argc, char *argv[], cli_options *o, predict_options *p)
{
    enum { OPT_NN = CLI_OPT_FIRST_OWN, OPT_MODEL, OPT_X_FROM, OPT_X_TO, OPT_DX };
    static const struct option longopts[] = {
        CLI_TIRE_LONGOPTS,
        CLI_METHOD_LONGOPTS,
        CLI_LOAD_LONGOPTS,
        CLI_OBSTACLE_LONGOPTS,
        {"nn", required_argument, NULL, OPT_NN},
        {"model", required_argument, NULL, OPT_MODEL},
        {"x-from", required_argument, NULL, OPT_X_FROM},
        {"x-to", required_argument, NULL, OPT_X_TO},
        {"dx", required_argument, NULL, OPT_DX},
        {"output", required_argument, NULL, 'o'},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    const char *cmd = argv[0];
    int c, longindex = 0;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, &longindex)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout, cmd);
            return CLI_EXIT_OK;
        case 'o':
            p->out_path = optarg;
            break;
        case OPT_NN:
            p->nn_path = optarg;
            break;
        case OPT_MODEL:
            if (strcmp(optarg, "nn") != 0) {
                cli_error("%s: --model %s: this command runs the network only (--model nn)",
                          cmd, optarg);
                return CLI_EXIT_USAGE;
            }
            break;
        case OPT_X_FROM:
        case OPT_X_TO:
        case OPT_DX: {
            double *v = c == OPT_X_FROM ? &p->x_from : c == OPT_X_TO ? &p->x_to : &p->dx;
            if (cli_parse_double(optarg, v)) {
                cli_error("--%s: expected a number in m, got '%s'", longopts[longindex].name,
                          optarg);
                return CLI_EXIT_USAGE;
            }
            p->have_from |= c == OPT_X_FROM;
            p->have_to |= c == OPT_X_TO;
            break;
        }
        case '?':
            usage(stderr, cmd);
            return CLI_EXIT_USAGE;
        default:
            if (cli_option(o, c, optarg))
                return CLI_EXIT_USAGE;
        }
    }
    if (optind < argc) {
        cli_error("%s: unexpected argument '%s'", cmd, argv[optind]);
        return CLI_EXIT_USAGE;
    }
    const char *missing = !p->nn_path    ? "--nn MODEL.json"
                          : !o->obstacle ? "--cleat L,H or --profile FILE"
                          : !o->have_load && !o->have_contact_length
                              ? "--load N or --contact-length M"
                              : NULL;
    if (missing) {
        cli_error("%s: expected %s; 'tirenv %s --help' shows the options", cmd, missing,
                  strcmp(cmd, "envelope") == 0 ? "envelope --model nn" : "predict");
        return CLI_EXIT_USAGE;
    }
    if (o->obstacle == CLI_OPT_CLEAT && (!(o->shape[0] > 0) || !(o->shape[1] > 0))) {
        cli_error("--cleat %s: expected a positive length and height in m", o->obstacle_arg);
        return CLI_EXIT_DATA;
    }
    return -1;
}

/* The working regime both ways through the springs model of the tire file: the network takes
 * the contact length, the CSV's fz column the load. */
static int regime(const cli_options *o, const tirenv_tire *tire, double *l_c, double *load)
{
    tirenv_model *m = NULL;
    int code = cli_model(tirenv_model_springs, tire, &m);
    if (code)
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    int status;
    if (o->have_load) {
        tirenv_flat flat;
        *load = o->load;
        status = tirenv_model_flat(m, o->load, &flat, &diag);
        *l_c = flat.contact_length;
    } else {
        *l_c = o->contact_length;
        status = tirenv_model_load_for_contact_length(m, o->contact_length, load, &diag);
    }
    tirenv_model_free(m);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

/* One warning per input the training never saw a value like, among inputs
 * TIRENV_NN_CONTACT_LENGTH .. end - 1. */
static void warn_range(const char *cmd, const tirenv_nn *nn, const double u[], size_t end)
{
    static const char *const what[TIRENV_NN_INPUTS] = {"x_N", "contact length",
                                                       "obstacle height", "obstacle length"};
    double lo[TIRENV_NN_INPUTS], hi[TIRENV_NN_INPUTS];
    tirenv_nn_get_input_range(nn, lo, hi);
    for (size_t i = tirenv_nn_out_of_range(nn, u, TIRENV_NN_CONTACT_LENGTH); i < end;
         i = tirenv_nn_out_of_range(nn, u, i + 1))
        fprintf(stderr, "tirenv: %s: warning: %s %g m is outside the range the network was "
                "trained on (%g to %g m): the prediction is an extrapolation\n", cmd, what[i],
                u[i], lo[i], hi[i]);
}

/* The CSV of tirenv envelope, complete or not at all. */
static int write_curve(const char *path, size_t n, const double x[], const double h[],
                       const double slope[], double z_flat, double load)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_outfile out;
    int status = tirenv_outfile_open(&out, path, &diag);
    if (!status) {
        fputs("x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n", out.fp);
        char load_text[CLI_ROW_FIELD];
        tirenv_fmt_g(load, 9, load_text);
        for (size_t k = 0; k < n; ++k) {  /* as "%.9g,%.9g,%.9g,%.9g,0,%.9g,0,0\n" */
            char row[5 * CLI_ROW_FIELD + 32], *p = row;
            p = cli_row_g(p, x[k], 9, ',');
            p = cli_row_g(p, z_flat + h[k], 9, ',');
            p = cli_row_g(p, h[k], 9, ',');
            p = cli_row_g(p, slope[k], 9, ',');
            p += sprintf(p, "0,%s,0,0\n", load_text);
            fwrite(row, 1, (size_t)(p - row), out.fp);
        }
        status = tirenv_outfile_commit(&out, &diag);  /* it checks the writes */
    }
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

/* How the summary names the obstacle: the file, or the generator as it was asked for. */
static void obstacle_label(const cli_options *o, char *buf, size_t n)
{
    const char *name = o->obstacle == CLI_OPT_STEP        ? "step"
                       : o->obstacle == CLI_OPT_TRAPEZOID ? "trapezoid"
                       : o->obstacle == CLI_OPT_TRIANGLE  ? "triangle"
                       : o->obstacle == CLI_OPT_CYLINDER  ? "cylinder"
                       : o->obstacle == CLI_OPT_SINE      ? "sine"
                                                          : NULL;
    if (name)
        snprintf(buf, n, "--%s %s", name, o->obstacle_arg);
    else
        snprintf(buf, n, "%s", o->obstacle_arg);
}

/* The profile's decomposition (nn_road.h), its warning about clamped bumps, and h and slope
 * at the positions. *what receives a description of the obstacles for the summary. */
static int road_curve(const char *cmd, const cli_options *o, tirenv_nn *nn, double R0,
                      double l_c, const tirenv_profile *prof, size_t n, const double x[],
                      double h[], double slope[], char *what, size_t what_size)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_nn_road *road = NULL;
    int status = tirenv_nn_road_alloc(nn, R0, l_c, prof, NULL, &road, &diag);
    if (!status)
        status = tirenv_nn_road_eval(road, n, x, h, slope, &diag);
    if (status) {
        if (o->obstacle == CLI_OPT_PROFILE && !diag.file[0])
            snprintf(diag.file, sizeof diag.file, "%s", o->obstacle_arg);
        tirenv_nn_road_free(road);
        return cli_fail(status, &diag);
    }
    const tirenv_nn_road_info in = tirenv_nn_road_get_info(road);
    const size_t clamped = in.height_above + in.length_below + in.length_above;
    if (clamped) {
        char detail[256] = "";
        size_t used = 0;
        const struct {
            size_t count;
            const char *text;
            double bound;
        } parts[] = {{in.height_above, "heights above", in.H_max},
                     {in.length_below, "lengths below", in.L_min},
                     {in.length_above, "lengths above", in.L_max}};
        for (size_t i = 0; i < sizeof parts / sizeof parts[0]; ++i)
            if (parts[i].count && used < sizeof detail)
                used += (size_t)snprintf(detail + used, sizeof detail - used, "%s%zu %s %g m",
                                         used ? ", " : "", parts[i].count, parts[i].text,
                                         parts[i].bound);
        fprintf(stderr, "tirenv: %s: warning: %zu of %zu obstacles outside the network's "
                "training range, clamped to it (%s): their curves are the nearest trained "
                "cleat's\n", cmd, clamped, in.obstacles, detail);
    }
    char label[600];
    obstacle_label(o, label, sizeof label);
    snprintf(what, what_size, "%s: %zu obstacles above a baseline of width %.3g m (%zu lower "
             "than the lowest trained cleat, scaled)",
             label, in.obstacles, in.width, in.height_below);
    tirenv_nn_road_free(road);
    return CLI_EXIT_OK;
}

int cli_predict_main(int argc, char *argv[])
{
    cli_options o;
    cli_options_init(&o);
    predict_options p = {.nn_path = NULL, .out_path = "-", .dx = default_dx};
    const char *cmd = argv[0];
    int code = parse(argc, argv, &o, &p);
    if (code >= 0)
        return code;
    const int cleat = o.obstacle == CLI_OPT_CLEAT;
    const double L = o.shape[0], H = o.shape[1];

    tirenv_tire tire;
    if ((code = cli_tire(&o, &tire)))
        return code;
    tirenv_nn *nn = NULL;
    tirenv_profile *prof = NULL;
    tirenv_train_record rec;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    int status = tirenv_nn_read_json(p.nn_path, &nn, &rec, &diag);
    if (status)
        return cli_fail(status, &diag);
    double *x = NULL, *h = NULL, *slope = NULL;
    if (tirenv_nn_n_inputs(nn) != TIRENV_NN_INPUTS) {
        cli_error("%s: %s: a network of %zu inputs; the enveloping model has %d (x_N, contact "
                  "length, obstacle height, obstacle length)", cmd, p.nn_path,
                  tirenv_nn_n_inputs(nn), TIRENV_NN_INPUTS);
        code = CLI_EXIT_DATA;
        goto done;
    }
    if (!cleat && (code = cli_profile(&o, &prof)))
        goto done;
    double l_c, load;
    if ((code = regime(&o, &tire, &l_c, &load)))
        goto done;
    const double R0 = rec.R0 > 0 ? rec.R0 : tire.springs.R0;
    if (rec.R0 > 0 && fabs(rec.R0 - tire.springs.R0) > 1e-9 * rec.R0)
        fprintf(stderr, "tirenv: %s: warning: the network's data refer to a tire of R0 %g m, "
                "the tire file's is %g m; x_N and z use %g m\n", cmd, rec.R0,
                tire.springs.R0, R0);
    const double u[TIRENV_NN_INPUTS] = {0.5, l_c, H, L};
    warn_range(cmd, nn, u, cleat ? TIRENV_NN_INPUTS : TIRENV_NN_CONTACT_LENGTH + 1);

    double first = -0.5 * L, last = 0.5 * L;
    if (!cleat)
        tirenv_profile_extent(prof, &first, &last);
    if (!p.have_from)
        p.x_from = first - R0 - margin;
    if (!p.have_to)
        p.x_to = last + R0 + margin;
    size_t n = 0;
    if ((code = cli_positions(p.x_from, p.x_to, p.dx, &x, &n)))
        goto done;
    if (!(h = malloc(n * sizeof *h)) || !(slope = malloc(n * sizeof *slope))) {
        code = cli_fail(TIRENV_ENOMEM, NULL);
        goto done;
    }
    char what[900];
    if (cleat) {
        if ((status = tirenv_nn_envelope(nn, R0, l_c, L, H, n, x, h, &diag))) {
            code = cli_fail(status, &diag);
            goto done;
        }
        for (size_t k = 0; k < n; ++k)
            slope[k] = curve_slope(n, x, h, k);
        snprintf(what, sizeof what, "cleat %.4g x %.4g m", L, H);
    } else if ((code = road_curve(cmd, &o, nn, R0, l_c, prof, n, x, h, slope, what,
                                  sizeof what))) {
        goto done;
    }
    const double z_flat = sqrt(R0 * R0 - 0.25 * l_c * l_c);
    if ((code = write_curve(p.out_path, n, x, h, slope, z_flat, load)))
        goto done;
    size_t peak = 0;
    for (size_t k = 1; k < n; ++k)
        if (h[k] > h[peak])
            peak = k;
    fprintf(stderr, "tirenv %s: nn model %s, contact length %.4g m (load %.6g N), %s, %zu "
            "positions: peak h %.3f mm at x = %.4f m\n",
            strcmp(cmd, "envelope") == 0 ? "envelope" : "predict", p.nn_path, l_c, load, what,
            n, h[peak] * 1e3, x[peak]);
    code = CLI_EXIT_OK;
done:
    free(x);
    free(h);
    free(slope);
    tirenv_profile_free(prof);
    tirenv_nn_free(nn);
    return code;
}
