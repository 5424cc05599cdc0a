/* tirenv predict: the enveloping curve of the trained network, which is tirenv envelope with
 * the model type nn (cmd_envelope.c): over a rectangular cleat the paper's curve, over any
 * profile the equivalent-cleat decomposition of nn_road.h, in the CSV of the other models.
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>

#include "cli/envelope.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv predict --nn MODEL.json OBSTACLE (--load N | --contact-length M)\n"
          "                      [--model NAME] [--extrapolate] [--track V] [--side S]\n"
          "                      [--crg-nan-mode M] [--tracks N] [--width W] [--x-from X]\n"
          "                      [--x-to X] [--dx DX] [--stream]\n"
          "                      [-o FILE.csv|FILE.crg|FILE.rdf]\n"
          "                      [--crg-encoding E] [--relative-to ground|datum]\n"
          "                      [--tire FILE] [--set KEY=VALUE]... [--method M]\n"
          "                      [--jobs N] [--plot FILE.png]\n"
          "\n"
          "The enveloping curve of the empirical model, the trained network of 'tirenv train'\n"
          "(paper, Tables 1 and 2), in the CSV of 'tirenv envelope':\n"
          "  x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations\n"
          "Over a single cleat (--cleat L,H, or a --profile of its four corners, centred at\n"
          "x = 0), h is the network at x_N(x) (docs/models.md section 1) on the approach half,\n"
          "mirrored on the other, and slope is dh/dx of the written curve (central\n"
          "differences). Over any other obstacle or a --profile (a road\n"
          "from 'tirenv road', say) the network, trained on single cleats, is extended beyond the\n"
          "paper by an equivalent-cleat decomposition: the profile's opening by a window 1.5\n"
          "times the longest trained cleat is the baseline; each bump above it becomes the cleat\n"
          "of equal height and area; h is the baseline or the highest of the bumps' network\n"
          "curves added to it (include/tirenv/nn_road.h); slope is its derivative. z = z_flat + h\n"
          "with z_flat = sqrt(R0^2 - (l_c/2)^2), the chord relation; fz is the load; fx, contacts\n"
          "and iterations are 0 (the network knows none of them).\n"
          "An input outside the range the network was trained on (contact length, cleat\n"
          "height or length; over a profile, any bump's equivalent cleat) is refused, naming\n"
          "it, its value and the trained range, unless --extrapolate allows it: the curve is\n"
          "then the network's at that value, or over a profile the bump's clamped to the range\n"
          "(bumps lower than the lowest trained cleat scale its curve down), with a warning\n"
          "counting them. R0 is the one the network's data referred to (from the model file),\n"
          "and so are its input form (x_N, or the even rounded distance from the centre),\n"
          "target (h or h/H) and ensemble size ('tirenv train --input, --target, --ensemble').\n"
          "This command is 'tirenv envelope --model nn'.\n"
          "\n"
          "options:\n"
          "  --nn FILE            the model file written by 'tirenv train -o'\n",
          fp);
    cli_help_model(fp, TIRENV_MODEL_NEEDS_NETWORK, 0,
                   " (the default): this command runs the network;\n"
                   "                       'tirenv envelope --model NAME' runs the others");
    fputs("  --extrapolate        evaluate the network outside its trained ranges (with a\n"
          "                       warning) instead of refusing the input\n"
          "  --cleat L,H          rectangular cleat: length and height in m (h is 0 before\n"
          "                       the first x_N the network saw, and never below 0)\n"
          "  --profile FILE       or a road file: CSV x_m,z_m, OpenCRG .crg or TNO/Adams .rdf\n"
          "  --step X0,H, --trapezoid LTOP,LBASE,H, --triangle L,H, --cylinder R,\n"
          "  --sine A,WAVELENGTH,PERIODS\n"
          "                       or a generated obstacle, as in 'tirenv envelope --help'\n"
          "  --contact-length M   the working regime, the network's input, in m\n"
          "  --load N             or the load, N, turned into the contact length of the tire\n"
          "                       the network's data came from (the relation its file\n"
          "                       records; for an older file, the springs model of the tire\n"
          "                       file) (--contact-length is turned into the fz column the\n"
          "                       same way)\n"
          "  --x-from X, --x-to X first and last centre position, m; default: from R0 + 0.02 m\n"
          "                       before the obstacle's first vertex to R0 + 0.02 m after its\n"
          "                       last\n"
          "  --dx DX              spacing of the positions, m (default 0.001)\n"
          "  --stream             with --profile: read the road as the tire rolls, in memory\n"
          "                       bounded by the network's window whatever the road's\n"
          "                       length, the same bytes as without it ('tirenv envelope\n"
          "                       --help' says how each road format is read); the warnings\n"
          "                       come after the rows\n",
          fp);
    cli_help_road(fp, 1);
    cli_help_envelope_output(fp);
    cli_help_relative_to(fp);
    cli_help_tire(fp, 1, NULL);
    cli_help_jobs(fp);
    fputs("  -h, --help           show this help\n", fp);
}

int cli_predict_main(int argc, char *argv[])
{
    cli_envelope_opts e;
    cli_options o;
    const int code = cli_envelope_parse("predict", usage, argc, argv, &o, &e);
    if (code != CLI_GO_ON)
        return code;
    /* The network is what this command runs: any type that evaluates one. */
    if (o.type && !(tirenv_model_type_flags(o.type) & TIRENV_MODEL_NEEDS_NETWORK)) {
        cli_error("predict: --model %s: this command runs the network only (--model nn)",
                  tirenv_model_type_name(o.type));
        return CLI_EXIT_USAGE;
    }
    if (!o.nn_path) {
        cli_error("predict: expected --nn MODEL.json; 'tirenv predict --help' shows the "
                  "options");
        return CLI_EXIT_USAGE;
    }
    o.runs[o.n_runs++] = o.type ? o.type : tirenv_model_nn;  /* --set's warnings */
    return cli_envelope_run("predict", &o, o.type ? o.type : tirenv_model_nn, &e);
}
