/* tirenv envelope --plot FILE.png: the curve just written (-o FILE.csv) over the road under
 * the centre, as a gnuplot script beside it and the PNG and SVG it draws.
 * SPDX-License-Identifier: Apache-2.0 */
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/envelope_plot.h"
#include "tirenv/outfile.h"
#include "tirenv/plot.h"

/* At most this many road vertices drawn (a measured road at 1 mm has a million over 1 km): in
 * bins of equal width beyond it, each bin's lowest and highest vertex, in x order, so that
 * the drawn road keeps every peak and trough. */
enum { ROAD_MAX_POINTS = 20000 };

/* The base of FILE (FILE without a .png or .svg ending) into base, its directory into dir and
 * its name into name; 0 if it does not fit. */
static int split_base(const char *file, char base[PATH_MAX], char dir[PATH_MAX],
                      char name[PATH_MAX])
{
    size_t n = strlen(file);
    if (n >= PATH_MAX)
        return 0;
    if (n > 4 && (strcmp(file + n - 4, ".png") == 0 || strcmp(file + n - 4, ".svg") == 0))
        n -= 4;
    memcpy(base, file, n);
    base[n] = '\0';
    const char *slash = strrchr(base, '/');
    if (slash) {
        snprintf(dir, PATH_MAX, "%.*s", (int)(slash - base) > 0 ? (int)(slash - base) : 1,
                 base);
        snprintf(name, PATH_MAX, "%s", slash + 1);
    } else {
        snprintf(dir, PATH_MAX, ".");
        snprintf(name, PATH_MAX, "%s", base);
    }
    return name[0] != '\0';
}

static void road_point(FILE *fp, double x, double z)
{
    fprintf(fp, "%.9g,%.9g\n", x, z);
}

/* The road under the centre from x_from to x_to: its vertices there and its heights at both
 * ends, thinned as ROAD_MAX_POINTS says. */
static void write_road(FILE *fp, const tirenv_profile *p, double x_from, double x_to)
{
    const size_t n = tirenv_profile_size(p);
    const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
    size_t i0 = 0, i1 = n;
    while (i0 < n && !(x[i0] > x_from))
        ++i0;
    while (i1 > i0 && !(x[i1 - 1] < x_to))
        --i1;
    fputs("# x_m,z_m: the road under the centre\n", fp);
    road_point(fp, x_from, tirenv_profile_height(p, x_from));
    const size_t inside = i1 - i0;
    if (inside <= ROAD_MAX_POINTS) {
        for (size_t i = i0; i < i1; ++i)
            road_point(fp, x[i], z[i]);
    } else {
        const size_t bins = ROAD_MAX_POINTS / 2;
        for (size_t b = 0, i = i0; b < bins; ++b) {
            const double edge = x_from + (x_to - x_from) * (double)(b + 1) / (double)bins;
            size_t lo = SIZE_MAX, hi = SIZE_MAX;
            for (; i < i1 && (x[i] <= edge || b + 1 == bins); ++i) {
                if (lo == SIZE_MAX || z[i] < z[lo])
                    lo = i;
                if (hi == SIZE_MAX || z[i] > z[hi])
                    hi = i;
            }
            if (lo == SIZE_MAX)
                continue;
            road_point(fp, x[lo < hi ? lo : hi], z[lo < hi ? lo : hi]);
            if (hi != lo)
                road_point(fp, x[lo < hi ? hi : lo], z[lo < hi ? hi : lo]);
        }
    }
    road_point(fp, x_to, tirenv_profile_height(p, x_to));
}

int cli_envelope_plot_check(const char *file, tirenv_diag *diag)
{
    char base[PATH_MAX], dir[PATH_MAX], name[PATH_MAX];
    if (!split_base(file, base, dir, name))
        return tirenv_error(diag, TIRENV_EINVAL, file, 0, "--plot", "no file name");
    /* A file where the directory should be passes access(W_OK): the curve would have
     * replaced -o's file before the plot's first file failed. */
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode) || access(dir, W_OK) != 0)
        return tirenv_error(diag, TIRENV_EIO, dir, 0, "--plot",
                            "the plot's directory is not one this process can write into");
    return TIRENV_OK;
}

int cli_envelope_plot(const char *file, const char *csv, const char *model, const char *title,
                      const tirenv_profile *road, double x_from, double x_to, tirenv_diag *diag)
{
    char base[PATH_MAX], dir[PATH_MAX], name[PATH_MAX], path[PATH_MAX + 16], csv_abs[PATH_MAX];
    if (!split_base(file, base, dir, name))
        return tirenv_error(diag, TIRENV_EINVAL, file, 0, "--plot", "no file name");
    /* The script reads the CSV from its own directory, where gnuplot runs. */
    if (!realpath(csv, csv_abs))
        return tirenv_error(diag, TIRENV_EIO, csv, 0, "", "cannot find the curve just written");
    tirenv_outfile *f;
    snprintf(path, sizeof path, "%s-road.dat", base);
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    write_road(tirenv_outfile_stream(f), road, x_from, x_to);
    if ((status = tirenv_outfile_commit(f, diag)))
        return status;
    snprintf(path, sizeof path, "%s.gp", base);
    if ((status = tirenv_outfile_open(&f, path, diag)))
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    const tirenv_plot_style st = tirenv_plot_style_of(model, 0);
    /* Names and the title quoted for gnuplot (cli_plot_quoted): a path may hold anything. */
    fprintf(fp, "# tirenv envelope --plot: the curve of %s over the road under the centre.\n"
                "# Draw by hand from this directory with:  gnuplot %s.gp\n",
            model, name);
    cli_plot_outputs(fp, name);
    fputs("curve = ", fp);
    cli_plot_quoted(fp, csv_abs);
    snprintf(path, sizeof path, "%s-road.dat", name);
    fputs("\nroad = ", fp);
    cli_plot_quoted(fp, path);
    fputc('\n', fp);
    fputs("set title ", fp);
    cli_plot_quoted(fp, title);
    fprintf(fp, " noenhanced\n"
                "set datafile separator ','\n"
                "set encoding utf8\nset grid lc rgb '#d0d0d0'\nset key top left box opaque\n"
                "set xlabel \"x, the wheel centre's position (m)\"\n"
                "set ylabel \"height (mm)\"\n"
                "set autoscale xfix\nset offsets 0, 0, graph 0.05, graph 0.05\n");
    cli_plot_passes(fp, 900, 500);
    fprintf(fp, "    plot road using 1:($2*1e3) with lines lc rgb '#909090' lw 1.5 "
                "title 'the road under the centre', \\\n"
                "         curve every ::1 using 1:($3*1e3) with lines lc rgb '%s' lw %.1f "
                "dt %d title 'h, the effective road (%s)'\n"
                "}\n"
                "unset output\n",
            st.colour, st.width, st.dash, model);
    if ((status = tirenv_outfile_commit(f, diag)))
        return status;
    return tirenv_plot_draw(dir, name, NULL, diag);
}
