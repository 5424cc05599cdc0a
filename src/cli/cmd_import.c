/* tirenv import: a raw rig log (t, x, z of the tire centre) to an approach-half enveloping
 * curve on an x_N grid, as CSV. SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

static void usage(FILE *fp)
{
    const tirenv_import_settings d = tirenv_import_default();
    fputs("usage: tirenv import --log FILE --cleat L,H (--load N | --contact-length M)\n"
          "                     [--x-n-from A] [--x-n-to B] [--dx-n D] [--smooth W] [-o FILE]\n"
          "                     [--tire FILE] [--set KEY=VALUE]...\n"
          "\n"
          "Imports a rig log, CSV 't_s,x_m,z_m' (tire-centre position over time; any rate,\n"
          "either direction, constant offsets, noise, repeated or missing samples), over a\n"
          "symmetric cleat: removes the flat baseline, finds the obstacle centre, folds the\n"
          "departure half onto the approach half, filters the noise without shifting the\n"
          "curve, and writes the approach half on an x_N grid (docs/models.md section 1):\n"
          "  x_N,x_m,h_m\n"
          "x_m in obstacle coordinates (centre at 0), h_m above the flat ground. A summary\n"
          "(noise, centre, smoothing) goes to standard error. A log that does not hold a\n"
          "whole passage (flat ground, the bump, flat ground) is refused with the reason, as\n"
          "is a curve the tire and obstacle cannot give (h above H + R0, a bump wider than\n"
          "L/2 + 1.05 R0 either side: a log not in metres). The smoothing never exceeds 5 %\n"
          "of |x_0|, which keeps the curve's shape; a log too noisy or sparse for the noise\n"
          "target is smoothed at that cap with a warning, and refused only when the cap's\n"
          "window holds fewer than 8 samples.\n"
          "\n"
          "options:\n"
          "  --log FILE           the raw log\n"
          "  --cleat L,H          the obstacle: length and height in m\n",
          fp);
    fprintf(fp,
            "  --contact-length M   the working regime: contact length in m (fixes x_N)\n"
            "  --load N             or the vertical load in N: the contact length is then the\n"
            "                       ring reference tire's flat-ground patch at that load (the\n"
            "                       tire's, docs/models.md section 14)\n"
            "  --x-n-from A         first grid point (default %g: before first contact)\n"
            "  --x-n-to B           last grid point (default %g: over the centre)\n"
            "  --dx-n D             grid step (default %g)\n"
            "  --smooth W           smoothing half-width in m (default: chosen from the noise)\n"
            "  -o, --output FILE    write the CSV to FILE, complete or not at all (default or\n"
            "                       '-': standard output)\n",
            d.xN_from, d.xN_to, d.dxN);
    cli_help_tire(fp, 0, "FOUNDATION_STIFFNESS=1.2e5 (the ring's)");
    fputs("  -h, --help           show this help\n", fp);
}

/* The working regime: --contact-length as given, or the tire's flat-ground contact length at
 * --load, the ring reference tire's patch (docs/models.md section 14: the tire the rig
 * simulates; the springs model's is identified to follow it within 5 %). */
static int contact_length(const cli_options *o, const tirenv_tire *tire, double *l_c)
{
    if (o->have_contact_length) {
        *l_c = o->contact_length;
        return CLI_EXIT_OK;
    }
    tirenv_model *m;
    int code = cli_model(tirenv_model_ring, tire, NULL, &m);
    if (code)
        return code;
    tirenv_flat flat;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_model_flat(m, o->load, &flat, &diag);
    tirenv_model_free(m);
    if (status)
        return cli_fail(status, &diag);
    *l_c = flat.contact_length;
    return CLI_EXIT_OK;
}

static void summary(const char *log, const tirenv_import_info *in, const tirenv_curve *c)
{
    double peak = 0;
    for (size_t k = 0; k < c->n; k++)
        peak = fmax(peak, c->h[k]);
    fprintf(stderr,
            "tirenv import: %s: %zu samples (%zu repeated dropped), travel towards %sx, noise "
            "%.3g mm, flat z %.6g m, centre at x = %.6g m, x_0 = %.4g m; smoothing half-width "
            "%.3g mm leaves %.2g mm of noise; peak h %.2f mm\n",
            log, in->n_samples, in->n_repeated, in->reversed ? "-" : "+", in->sigma * 1e3,
            in->baseline, in->centre, in->x_0, in->half_width * 1e3, in->noise_se * 1e3,
            peak * 1e3);
    if (in->width_capped)
        fprintf(stderr,
                "tirenv: import: warning: %s: the smoothing half-width stopped at its cap, "
                "%.3g mm (5 %% of |x_0|, which keeps the curve's shape): the noise leaves a "
                "standard error of %.2g mm on h against the %.2g mm aimed at\n",
                log, in->half_width * 1e3, in->noise_se * 1e3, in->target_se * 1e3);
}

/* --cleat L,H: a rig log is folded over a symmetric cleat, the one obstacle import takes. */
static int parse_cleat(void *dst, const char *arg)
{
    if (cli_parse_doubles(arg, dst, 2) == 0)
        return CLI_EXIT_OK;
    cli_error("--cleat: expected L,H: length and height in m, got '%s'", arg);
    return CLI_EXIT_USAGE;
}

int cli_import_main(int argc, char *argv[])
{
    tirenv_import_settings set = tirenv_import_default();
    const char *log = NULL;
    double cleat[2] = {NAN, NAN};  /* L, H, m */
    const cli_opt own[] = {
        {.name = "log", .kind = CLI_STRING, .dst = &log, .input = CLI_INPUT_FILE},
        {.name = "cleat", .kind = CLI_CUSTOM, .dst = cleat, .parse = parse_cleat},
        {.name = "x-n-from", .kind = CLI_NUMBER, .dst = &set.xN_from},
        {.name = "x-n-to", .kind = CLI_NUMBER, .dst = &set.xN_to},
        {.name = "dx-n", .kind = CLI_POSITIVE, .dst = &set.dxN},
        {.name = "smooth", .kind = CLI_POSITIVE, .dst = &set.smooth,
         .what = "a positive length in m"},
        {.name = NULL},
    };
    const cli_parser p = {.name = "import", .usage = usage, .opts = own,
                          .groups = CLI_TIRE | CLI_LOAD | CLI_OUTPUT};
    cli_options o;
    int code = cli_parse(&p, argc, argv, &o);
    if (code != CLI_GO_ON)
        return code;
    const char *missing = !log                         ? "--log FILE"
                          : isnan(cleat[0])            ? "--cleat L,H"
                          : !(o.have_load || o.have_contact_length)
                              ? "--load N or --contact-length M"
                              : NULL;
    if (missing) {
        cli_error("import: %s is required ('tirenv import --help' shows the options)", missing);
        return CLI_EXIT_USAGE;
    }
    /* A reversed or empty grid is a misuse of the options, said in their names (the library
     * refuses it too, as bad data, naming its field). */
    if (!(set.xN_to > set.xN_from)) {
        cli_error("import: --x-n-from, --x-n-to: expected the grid's end after its start, got "
                  "%g to %g", set.xN_from, set.xN_to);
        return CLI_EXIT_USAGE;
    }
    tirenv_tire tire;
    if (o.have_load)
        o.type = tirenv_model_ring;  /* its patch is the regime: derived if the file has none */
    /* Else the tire gives R0 alone, and --set is not warned of: no model runs. */
    if ((code = cli_tire(&o, &tire)))
        return code;
    set.R0 = tire.springs.R0;
    set.L = cleat[0];
    set.H = cleat[1];
    if ((code = contact_length(&o, &tire, &set.contact_length)))
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_curve curve;
    tirenv_import_info info;
    int status = tirenv_rig_import_file(log, &set, &curve, &info, &diag);
    if (status == TIRENV_OK)
        status = tirenv_curve_write_csv(o.output ? o.output : "-", &curve, NULL, &diag);
    if (status == TIRENV_OK)
        summary(log, &info, &curve);
    tirenv_curve_free(&curve);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}
