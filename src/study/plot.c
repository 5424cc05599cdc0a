/* Comparison plots in the manner of the paper's Figure 5: for one case, h in mm over x_N, the
 * measured curve as markers and one line per model. The numbers go to a plain data file and
 * the drawing to a gnuplot script a reader can edit and rerun; tirenv runs that script to
 * draw the PNG for the report and the SVG for print. SPDX-License-Identifier: Apache-2.0 */
#define _GNU_SOURCE  /* pipe2 */
#include "study/plot.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tirenv/outfile.h"
#include "tirenv/plot.h"

/* Image size in pixels: the width of a report column, the paper's aspect ratio. */
enum { PLOT_WIDTH = 900, PLOT_HEIGHT = 600 };
/* More markers than this crowd the lines; a dense rig curve shows every k-th point. */
enum { PLOT_MAX_MARKERS = 80 };

void tirenv_plot__base(const char *case_name, char *base, size_t size)
{
    size_t k = 0;
    for (; case_name[k] && k + 1 < size; ++k) {
        const char ch = case_name[k];
        const int ok = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') ||
                       (ch >= '0' && ch <= '9') || ch == '.' || ch == '_' || ch == '-';
        base[k] = ok ? ch : '_';
    }
    base[k] = '\0';
    /* "." and ".." are names of directories, not of files. */
    if (strcmp(base, ".") == 0 || strcmp(base, "..") == 0 || k == 0)
        snprintf(base, size, "case");
}

/* One line style per model, the same on every plot of tirenv (the study's and the ride's), so a
 * reader learns the colours once: the physical models in cool colours, the network in red,
 * the rigid limit grey and dashed, the point contact (the ride's baseline) orange and thin. */
static const struct {
    const char *name;
    tirenv_plot_style style;
} styles[] = {
    {"rigid", {"#808080", 2, 2.0}},
    {"springs", {"#1f5fbf", 1, 2.5}},
    {"ring", {"#2a9d3a", 4, 2.0}},
    {"cam", {"#9467bd", 1, 2.0}},
    {"nn", {"#d62728", 1, 2.5}},
    {"point", {"#ff7f0e", 1, 1.5}},
};
static const char *const spare_colours[] = {"#8c564b", "#e377c2", "#17becf", "#bcbd22"};

tirenv_plot_style tirenv_plot_style_of(const char *model, size_t i)
{
    for (size_t k = 0; k < sizeof styles / sizeof styles[0]; ++k)
        if (strcmp(styles[k].name, model) == 0)
            return styles[k].style;
    const size_t n_spare = sizeof spare_colours / sizeof spare_colours[0];
    return (tirenv_plot_style){spare_colours[i % n_spare], 1, 2.0};
}

/* A gnuplot double-quoted string: backslash escapes are processed in these, so backslash and
 * the quote are escaped and a newline becomes \n (a line break in a title). */
static void gp_string(FILE *fp, const char *s)
{
    fputc('"', fp);
    for (; *s; ++s) {
        if (*s == '\n')
            fputs("\\n", fp);
        else if (*s == '"' || *s == '\\')
            fprintf(fp, "\\%c", *s);
        else
            fputc(*s, fp);
    }
    fputc('"', fp);
}

/* Lengths on the plot and in the files are in mm, to the precision a rig reports. */
static void mm_text(char *buf, size_t size, double metres)
{
    snprintf(buf, size, "%.4g", metres * 1e3);
}

/* "Case F: contact length 380 mm, obstacle 300 x 100 mm (length x height)", as Table 3 lists
 * the cases. */
static void case_caption(const tirenv_case *c, char *buf, size_t size)
{
    char lc[32], L[32], H[32];
    mm_text(lc, sizeof lc, c->contact_length);
    mm_text(L, sizeof L, c->L);
    mm_text(H, sizeof H, c->H);
    snprintf(buf, size, "Case %s: contact length %s mm, obstacle %s x %s mm (length x height)",
             c->name, lc, L, H);
}

static void simulated_note(const tirenv_plot__settings *ps, char *buf, size_t size)
{
    if (ps->simulated_by)
        snprintf(buf, size, ps->raw ? "SIMULATED data: the %s model's own curves, not "
                                      "measurements of a real tire"
                                    : "SIMULATED data: virtual rig on the %s reference tire, "
                                      "not measurements of a real tire", ps->simulated_by);
    else
        snprintf(buf, size, "SIMULATED data, not measurements of a real tire");
}

static int write_failed(tirenv_outfile *f, tirenv_diag *diag)
{
    const int e = errno;
    const int status = tirenv_error(diag, TIRENV_EIO, tirenv_outfile_path(f), 0, "",
                                    "cannot write: %s", strerror(e ? e : EIO));
    tirenv_outfile_abort(f);
    return status;
}

/* <base>.dat: x_N, then h in mm of the measurement and of each model, whitespace-separated,
 * NaN where a model has no value. */
static int write_data(const char *path, const tirenv_plot__settings *ps, const tirenv_case *c,
                      size_t n_series, const tirenv_plot__series series[], tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    char caption[256], note[256];
    case_caption(c, caption, sizeof caption);
    errno = 0;
    FILE *fp = tirenv_outfile_stream(f);
    fprintf(fp, "# tirenv compare: %s, load %.6g N\n", caption, c->load);
    if (ps->simulated) {
        simulated_note(ps, note, sizeof note);
        fprintf(fp, "# %s\n", note);
    }
    fputs("# x_N: normalised position (0 at first contact, 1 with the tire axis over the "
          "obstacle centre); h: effective profile height, mm; NaN: the model has no value\n"
          "# columns: x_N h_measured_mm",
          fp);
    for (size_t j = 0; j < n_series; ++j)
        fprintf(fp, " h_%s_mm", series[j].name);
    fputc('\n', fp);
    for (size_t j = 0; j < n_series; ++j)
        if (series[j].failure)
            fprintf(fp, "# %s failed on this case: %s\n", series[j].name, series[j].failure);
    const tirenv_curve *cv = &c->curve;
    for (size_t k = 0; k < cv->n; ++k) {
        fprintf(fp, "%.6f %.4f", cv->x_N[k], cv->h[k] * 1e3);
        for (size_t j = 0; j < n_series; ++j) {
            const double h = series[j].h ? series[j].h[k] : NAN;
            if (isfinite(h))
                fprintf(fp, " %.4f", h * 1e3);
            else
                fputs(" NaN", fp);
        }
        fputc('\n', fp);
    }
    if (ferror(fp))
        return write_failed(f, diag);
    return tirenv_outfile_commit(f, diag);
}

/* The x range: the data's, widened to the next 0.05 so the axis ends on a tic. */
static void x_range(const tirenv_curve *cv, double *lo, double *hi)
{
    double a = cv->x_N[0], b = cv->x_N[0];
    for (size_t k = 1; k < cv->n; ++k) {
        a = fmin(a, cv->x_N[k]);
        b = fmax(b, cv->x_N[k]);
    }
    *lo = floor(a * 20 - 1e-9) / 20;
    *hi = ceil(b * 20 + 1e-9) / 20;
    if (!(*hi > *lo))
        *hi = *lo + 0.05;
}

/* <base>.gp: a script meant to be read and rerun by hand ("gnuplot F.gp" in its directory);
 * tirenv sets png_out and svg_out to temporary names on the command line and renames the
 * images when gnuplot has finished, so a report never links a half-drawn image. */
static int write_script(const char *path, const char *base, const tirenv_plot__settings *ps,
                        const tirenv_case *c, size_t n_series,
                        const tirenv_plot__series series[], tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    char caption[256], note[256], title[600];
    case_caption(c, caption, sizeof caption);
    simulated_note(ps, note, sizeof note);
    snprintf(title, sizeof title, "%s%s%s", caption, ps->simulated ? "\n" : "",
             ps->simulated ? note : "");
    double x_lo, x_hi;
    x_range(&c->curve, &x_lo, &x_hi);
    const size_t every = (c->curve.n + PLOT_MAX_MARKERS - 1) / PLOT_MAX_MARKERS;

    errno = 0;
    fprintf(fp,
            "# tirenv compare: the enveloping curve of case %s, measured and modelled, in the\n"
            "# manner of the paper's Figure 5 (Stojic et al.; tirenv docs/models.md section 8).\n"
            "# %s.\n",
            c->name, caption);
    if (ps->simulated)
        fprintf(fp, "# %s.\n", note);
    fprintf(fp,
            "#\n"
            "# Data: %s.dat in this directory (x_N, then h in mm: measured, then each model).\n"
            "# Draw by hand from this directory with:  gnuplot %s.gp\n"
            "# which writes %s.png (for screens and the report) and %s.svg (for print).\n"
            "# tirenv sets png_out and svg_out itself, to temporary names it renames when\n"
            "# gnuplot has finished.\n"
            "if (!exists(\"png_out\")) png_out = '%s.png'\n"
            "if (!exists(\"svg_out\")) svg_out = '%s.svg'\n"
            "\n"
            "set encoding utf8\n"
            "set datafile missing 'NaN'   # a model that failed on this case has NaN columns\n"
            "\n"
            "# Axes as in the paper: h (mm) over the normalised position x_N.\n"
            "set title ",
            base, base, base, base, base, base);
    gp_string(fp, title);
    fprintf(fp,
            "\n"
            "set xlabel \"x_N, normalised position (0: first contact, 1: tire axis over the "
            "obstacle centre)\"\n"
            "set ylabel \"h (mm), effective profile height\"\n"
            "set xrange [%.2f:%.2f]\n"
            "set yrange [*:*]\n"
            "set autoscale yfixmin   # start just below the lowest value, not at a tic\n"
            "set offsets 0, 0, graph 0.1, graph 0.03   # headroom above the peak\n"
            "set xtics 0.1\n"
            "set mxtics 2\n"
            "set grid xtics ytics lc rgb '#d0d0d0' lw 1 dt 1\n"
            "# The curves start low on the left, so the legend sits there.\n"
            "set key top left reverse Left box opaque samplen 2.5 spacing 1.15 width 1\n"
            "\n"
            "# Measured points as markers, each model as a line.\n"
            "set style line 1 lc rgb 'black' pt 7 ps 0.8   # measured\n",
            x_lo, x_hi);
    for (size_t j = 0; j < n_series; ++j) {
        const tirenv_plot_style st = tirenv_plot_style_of(series[j].name, j);
        fprintf(fp, "set style line %zu lc rgb '%s' lw %.1f dt %d   # %s\n", j + 2, st.colour,
                st.width, st.dash, series[j].name);
    }
    for (size_t j = 0; j < n_series; ++j)
        if (series[j].failure)
            fprintf(fp, "# %s is not drawn: it failed on this case (%s)\n", series[j].name,
                    series[j].failure);
    fprintf(fp,
            "\n"
            "# First the PNG, by cairo, for screens and the report...\n"
            "set terminal pngcairo size %d,%d font 'Sans,11' noenhanced\n"
            "set output png_out\n"
            "# Column 1 is x_N, column 2 the measured h, then one column per model.\n",
            PLOT_WIDTH, PLOT_HEIGHT);
    fprintf(fp, "plot '%s.dat' using 1:2 every %zu with points ls 1 title ", base,
            every ? every : 1);
    gp_string(fp, ps->simulated ? "measured (simulated)" : "measured");
    for (size_t j = 0; j < n_series; ++j) {
        if (series[j].failure)
            continue;
        fprintf(fp, ", \\\n     '' using 1:%zu with lines ls %zu title ", j + 3, j + 2);
        gp_string(fp, series[j].label ? series[j].label : series[j].name);
    }
    fprintf(fp,
            "\n"
            "\n"
            "# ...then the same plot as SVG, for print.\n"
            "set terminal svg size %d,%d font 'Sans,11' noenhanced background rgb 'white'\n"
            "set output svg_out\n"
            "replot\n"
            "unset output\n",
            PLOT_WIDTH, PLOT_HEIGHT);
    if (ferror(fp))
        return write_failed(f, diag);
    return tirenv_outfile_commit(f, diag);
}

/* ---- running gnuplot ------------------------------------------------------------------- */

/* What the child writes when exec fails; the parent recognises it. Only async-signal-safe
 * calls are allowed between fork and exec, so the message is fixed text. */
static const char exec_failed[] = "tirenv: cannot execute the program\n";
static const char chdir_failed[] = "tirenv: cannot enter the output directory\n";

/* fork and exec rather than popen: no shell to quote file names for, the output directory as
 * working directory (the script names its files relatively, so the directory can be moved),
 * and gnuplot's messages captured from a pipe instead of going to the user's terminal: the
 * library never prints. */
int tirenv_plot__run(const char *gnuplot, const char *dir, const char *script,
                     const char *assignments, tirenv_diag *diag)
{
    const char *prog = gnuplot && *gnuplot ? gnuplot : "gnuplot";
    char where[1024];  /* the script as messages name it */
    snprintf(where, sizeof where, "%s/%s", dir, script);
    /* Close-on-exec: another thread of a parallel comparison may fork its own gnuplot at the
     * same moment, and a child holding this pipe's write end would keep the read below waiting
     * until that other gnuplot ends too (dup2 in the child clears the flag where it counts). */
    int fd[2];
    if (pipe2(fd, O_CLOEXEC) != 0)
        return tirenv_error(diag, TIRENV_EIO, where, 0, "", "cannot run %s: pipe: %s", prog,
                            strerror(errno));
    const pid_t pid = fork();
    if (pid < 0) {
        const int e = errno;
        close(fd[0]);
        close(fd[1]);
        return tirenv_error(diag, TIRENV_EIO, where, 0, "", "cannot run %s: fork: %s", prog,
                            strerror(e));
    }
    if (pid == 0) {
        close(fd[0]);
        dup2(fd[1], STDOUT_FILENO);
        dup2(fd[1], STDERR_FILENO);
        close(fd[1]);
        /* Nothing to read: a script that waits for input must not hang the comparison. */
        close(STDIN_FILENO);
        if (chdir(dir) != 0) {
            (void)!write(STDERR_FILENO, chdir_failed, sizeof chdir_failed - 1);
            _exit(126);
        }
        char e_opt[] = "-e";
        char *argv[] = {(char *)prog, e_opt, (char *)assignments, (char *)script, NULL};
        execvp(prog, argv);
        (void)!write(STDERR_FILENO, exec_failed, sizeof exec_failed - 1);
        _exit(127);
    }
    close(fd[1]);
    /* Keep the start of what gnuplot says (its first error names the script line); read the
     * rest to the end so it never blocks on a full pipe. */
    char out[400];
    size_t n_out = 0;
    for (;;) {
        char buf[512];
        const ssize_t got = read(fd[0], buf, sizeof buf);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            break;
        for (ssize_t i = 0; i < got && n_out + 1 < sizeof out; ++i)
            out[n_out++] = buf[i];
    }
    close(fd[0]);
    out[n_out] = '\0';
    for (size_t i = 0; i < n_out; ++i)
        if (out[i] == '\n' || out[i] == '\r' || out[i] == '\t')
            out[i] = ' ';
    int wstatus;
    pid_t w;
    while ((w = waitpid(pid, &wstatus, 0)) < 0 && errno == EINTR)
        ;
    if (w < 0)
        return tirenv_error(diag, TIRENV_EIO, where, 0, "", "cannot wait for %s: %s", prog,
                            strerror(errno));
    if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0)
        return TIRENV_OK;
    if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 127 &&
        strncmp(out, exec_failed, sizeof exec_failed - 2) == 0)
        return tirenv_error(diag, TIRENV_EIO, "", 0, "gnuplot", /* no script's fault */
                            "cannot run '%s' to draw the plots: not found or not executable; "
                            "install gnuplot (scripts/deps.sh installs gnuplot-nox)", prog);
    if (WIFEXITED(wstatus))
        return tirenv_error(diag, TIRENV_EIO, where, 0, "gnuplot",
                            "'%s %s' in %s exited with status %d: %s", prog, script, dir,
                            WEXITSTATUS(wstatus), n_out ? out : "(no output)");
    return tirenv_error(diag, TIRENV_EIO, where, 0, "gnuplot",
                        "'%s %s' in %s was killed by signal %d", prog, script, dir,
                        WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : 0);
}

/* gnuplot's single-quoted strings take everything literally except '' for a quote. */
static void gp_single(char *dst, size_t size, const char *s)
{
    size_t k = 0;
    if (k + 1 < size)
        dst[k++] = '\'';
    for (; *s && k + 3 < size; ++s) {
        if (*s == '\'')
            dst[k++] = '\'';
        dst[k++] = *s;
    }
    if (k + 1 < size)
        dst[k++] = '\'';
    dst[k] = '\0';
}

static int join(char *buf, size_t size, const char *dir, const char *base, const char *ext,
                tirenv_diag *diag)
{
    const int n = snprintf(buf, size, "%s/%s%s", dir, base, ext);
    if (n < 0 || (size_t)n >= size)
        return tirenv_error(diag, TIRENV_EINVAL, dir, 0, "", "output path '%s/%s%s' is too "
                            "long (at most %zu characters)", dir, base, ext, size - 1);
    return TIRENV_OK;
}

/* Draws both images under temporary names and renames them into place only when gnuplot has
 * succeeded; on any failure neither temporary file is left behind. The names are the
 * process's and this call's own, and whatever holds one already (a file left by a killed
 * run of a process of the same id, a symbolic link) is removed first: gnuplot opens its
 * output for writing, and would have written through a link, or into a hard link that a
 * staging directory shares with the previous output (tirenv_outdir). */
int tirenv_plot_draw(const char *dir, const char *base, const char *gnuplot,
                     tirenv_diag *diag)
{
    static atomic_uint serial;
    char tmp_ext[2][64], tmp[2][512], final[2][512], script[300];
    const char *ext[2] = {".png", ".svg"};
    const unsigned call = atomic_fetch_add(&serial, 1u);
    int status = TIRENV_OK;
    for (int i = 0; i < 2 && !status; ++i) {
        snprintf(tmp_ext[i], sizeof tmp_ext[i], "%s.tmp.%ld.%u", ext[i], (long)getpid(), call);
        status = join(tmp[i], sizeof tmp[i], dir, base, tmp_ext[i], diag);
        if (!status)
            status = join(final[i], sizeof final[i], dir, base, ext[i], diag);
        if (!status && remove(tmp[i]) != 0 && errno != ENOENT)
            status = tirenv_error(diag, TIRENV_EIO, tmp[i], 0, "gnuplot",
                                  "cannot remove what holds the image's temporary name: %s",
                                  strerror(errno));
    }
    if (status)
        return status;
    char png_q[300], svg_q[300], assign[640];
    char name[300];
    snprintf(name, sizeof name, "%s%s", base, tmp_ext[0]);
    gp_single(png_q, sizeof png_q, name);
    snprintf(name, sizeof name, "%s%s", base, tmp_ext[1]);
    gp_single(svg_q, sizeof svg_q, name);
    snprintf(assign, sizeof assign, "png_out = %s; svg_out = %s", png_q, svg_q);
    snprintf(script, sizeof script, "%s.gp", base);
    status = tirenv_plot__run(gnuplot, dir, script, assign, diag);
    for (int i = 0; i < 2 && !status; ++i)
        if (rename(tmp[i], final[i]) != 0)
            status = tirenv_error(diag, TIRENV_EIO, final[i], 0, "gnuplot",
                                  "gnuplot ran but the image is missing (%s: %s)", tmp[i],
                                  strerror(errno));
    if (status) {
        remove(tmp[0]);
        remove(tmp[1]);
    }
    return status;
}

int tirenv_plot__draw(const tirenv_plot__settings *ps, const char *case_name,
                      tirenv_diag *diag)
{
    char base[64];
    tirenv_plot__base(case_name, base, sizeof base);
    return tirenv_plot_draw(ps->dir, base, ps->gnuplot, diag);
}

int tirenv_plot__case(const tirenv_plot__settings *ps, const tirenv_case *c, size_t n_series,
                      const tirenv_plot__series series[], tirenv_diag *diag)
{
    if (c->curve.n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "curve",
                            "case %s has no curve to plot", c->name);
    char base[64], dat[512], gp[512];
    tirenv_plot__base(c->name, base, sizeof base);
    int status = join(dat, sizeof dat, ps->dir, base, ".dat", diag);
    if (!status)
        status = join(gp, sizeof gp, ps->dir, base, ".gp", diag);
    if (!status)
        status = write_data(dat, ps, c, n_series, series, diag);
    if (!status)
        status = write_script(gp, base, ps, c, n_series, series, diag);
    return status;
}
