/* What the CLI's own gnuplot scripts share (tirenv ride --out-dir, tirenv envelope --plot): the
 * image names tirenv_plot_draw sets, strings quoted for gnuplot, and the two passes that draw
 * the PNG and then the SVG. SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>

#include "cli/cli.h"

void cli_plot_quoted(FILE *fp, const char *s)
{
    fputc('\'', fp);
    for (; *s; ++s) {
        if (*s == '\'')
            fputc('\'', fp);
        fputc(*s, fp);
    }
    fputc('\'', fp);
}

void cli_plot_outputs(FILE *fp, const char *name)
{
    static const char *const ext[2] = {"png", "svg"};
    for (int k = 0; k < 2; ++k) {
        char file[1100];
        snprintf(file, sizeof file, "%s.%s", name, ext[k]);
        fprintf(fp, "if (!exists(\"%s_out\")) %s_out = ", ext[k], ext[k]);
        cli_plot_quoted(fp, file);
        fputc('\n', fp);
    }
}

void cli_plot_passes(FILE *fp, size_t width, size_t height)
{
    fprintf(fp,
            "do for [pass = 1:2] {\n"
            "    if (pass == 1) {\n"
            "        set terminal pngcairo size %zu,%zu font 'Sans,10' noenhanced\n"
            "        set output png_out\n"
            "    } else {\n"
            "        set terminal svg size %zu,%zu font 'Sans,10' noenhanced background "
            "rgb 'white'\n"
            "        set output svg_out\n"
            "    }\n",
            width, height, width, height);
}
