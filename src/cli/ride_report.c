/* tirenv ride --out-dir: the comfort table as CSV and Markdown, and three gnuplot figures, the
 * seat acceleration over distance, its running r.m.s. and its spectrum, one panel per speed,
 * one line per model.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/ride_cli.h"
#include "tirenv/plot.h"

/* At most this many points per line in the seat plot (a 1 km road at 1 kHz has 360,000); and
 * the longest Welch segment, 4096 samples: 0.24 Hz bins at 1 kHz. */
enum { SEAT_MAX_POINTS = 20000, WELCH_MAX_SEGMENT = 4096 };

/* The spectrum plot's band, Hz: ISO 2631-1's for comfort (Wk). */
static const double SPECTRUM_F_LO = 0.5, SPECTRUM_F_HI = 100;

static int write_csv(const char *path, const ride_options *r, const ride_result res[],
                     tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fputs("model,speed_m_s,speed_km_h,duration_s,a_wz_m_s2,crest,vdv_m_s1.75,mtvv_m_s2,"
          "peak_awz_m_s2,a_w_pitch_rad_s2,vdv_pitch_rad_s1.75,a_v_m_s2,peak_az_m_s2,"
          "lift_off_s,cpu_s,real_time_factor,enveloping\n", fp);
    for (size_t k = 0; k < r->n_cols * r->n_speeds; ++k) {
        const ride_result *q = &res[k];
        fprintf(fp, "%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,"
                "%.6g,%.6g,%s\n", q->model, q->speed, q->speed * 3.6, q->duration, q->c.seat.rms,
                q->c.seat.crest, q->c.seat.vdv, q->c.seat.mtvv, q->c.seat.peak, q->c.pitch.rms,
                q->c.pitch.vdv, q->c.a_v, q->c.peak_az, q->c.lift_off, q->seconds,
                q->duration / fmax(q->seconds, 1e-9), tirenv_ride_enveloping_name(q->enveloping));
    }
    return tirenv_outfile_commit(f, diag);
}

/* The runs of one model at one speed in the other ways of enveloping against its static
 * run: how much following the load changes what the driver feels. */
static void write_differences(FILE *fp, const ride_options *r, const ride_result res[])
{
    int any = 0;
    for (size_t j = 0; j < r->n_speeds; ++j)
        for (size_t c = 0; c < r->n_cols; ++c) {
            const ride_result *q = &res[j * r->n_cols + c];
            if (q->enveloping == TIRENV_RIDE_STATIC)
                continue;
            const ride_result *base = NULL;
            for (size_t b = 0; b < r->n_cols; ++b)
                if (r->cols[b].model == r->cols[c].model &&
                    r->cols[b].enveloping == TIRENV_RIDE_STATIC)
                    base = &res[j * r->n_cols + b];
            if (!base)
                continue;
            if (!any++)
                fputs("\n## Following the load: against the static load's effective road\n\n"
                      "`dynamic`: each axle's input at the load its tires carry at each instant,\n"
                      "from tables over loads; `direct`: the model evaluated at that load during\n"
                      "the integration (the reference of the tables). Differences relative to\n"
                      "the static run (docs/models.md section 9.5).\n\n"
                      "| model | km/h | way | a_wz static | a_wz | Δ a_wz | VDV static | VDV | "
                      "Δ VDV | lift-off static s | lift-off s | CPU s |\n"
                      "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n", fp);
            fprintf(fp, "| %s | %.1f | %s | %.3f | %.3f | %+.1f %% | %.3f | %.3f | %+.1f %% | "
                    "%.3f | %.3f | %.3f |\n", q->model, q->speed * 3.6,
                    tirenv_ride_enveloping_name(q->enveloping), base->c.seat.rms, q->c.seat.rms,
                    100 * (q->c.seat.rms / base->c.seat.rms - 1), base->c.seat.vdv, q->c.seat.vdv,
                    100 * (q->c.seat.vdv / base->c.seat.vdv - 1), base->c.lift_off, q->c.lift_off,
                    q->seconds);
        }
}

/* Each axle's tires as the runs had them, and where their spring and c_t came from: one tire
 * file is one tire, its enveloping and its spring (docs/models.md section 9.1). */
static void write_tires(FILE *fp, const tirenv_vehicle *v, const tirenv_vehicle *given,
                        const char tire_path[2][1024], const double load[2])
{
    fputs("\n## The vehicle's tires\n\n"
          "Each tire a spring and a damper c_t (docs/models.md section 9.1): the tire file's\n"
          "own (its vertical law F_z(rho), whose tangent at the static load is k_t, which\n"
          "the linear checks use; its VERTICAL_DAMPING) unless the vehicle file gives\n"
          "TIRE_STIFFNESS (a linear spring k_t) or TIRE_DAMPING.\n\n"
          "| axle | tire file | tires | static load N | spring | k_t N/m | c_t N*s/m | "
          "c_t from |\n|---|---|---:|---:|---|---:|---:|---|\n", fp);
    for (int axle = 0; axle < 2; ++axle) {
        const tirenv_axle *ax = axle ? &v->rear : &v->front;
        const tirenv_axle *g = axle ? &given->rear : &given->front;
        const char *slash = strrchr(tire_path[axle], '/');  /* the file's name: no local path */
        fprintf(fp, "| %s | %s | %g | %.0f | %s | %.0f | %.0f | %s |\n",
                axle ? "rear" : "front", slash ? slash + 1 : tire_path[axle], ax->tires,
                load[axle],
                ax->law.factor > 0 ? "tire file's vertical law (k_t its tangent at the load)"
                                   : "vehicle file's TIRE_STIFFNESS (linear)",
                ax->k_t, ax->c_t,
                isnan(g->c_t) ? "tire file's VERTICAL_DAMPING" : "vehicle file's TIRE_DAMPING");
    }
}

static int write_md(const char *path, const ride_options *r, const ride_result res[],
                    const tirenv_vehicle *v, const tirenv_vehicle *given,
                    const char tire_path[2][1024], const double load[2], tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fputs("# Ride comfort at the seat (tirenv ride)\n\n"
          "ISO 2631-1:1997 figures of the seat's vertical acceleration (weighting Wk) and the\n"
          "body's pitch acceleration (We); a_v combines the two with k = 1 and 0.4 m/rad.\n"
          "Crest factors above 9 mean the r.m.s. underestimates the shocks: read VDV and MTVV.\n"
          "CPU time covers the model's effective profiles for both axles and the integration.\n"
          "\n"
          "| model | enveloping | km/h | a_wz m/s² | crest | VDV m/s^1.75 | MTVV m/s² | "
          "a_w pitch rad/s² | a_v m/s² | peak a_z m/s² | lift-off s | CPU s | × real time |\n"
          "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n", fp);
    for (size_t k = 0; k < r->n_cols * r->n_speeds; ++k) {
        const ride_result *q = &res[k];
        char crest[16] = "-";  /* no vibration (a level road): no crest factor, 0/0 */
        if (!isnan(q->c.seat.crest))
            snprintf(crest, sizeof crest, "%.1f", q->c.seat.crest);
        fprintf(fp, "| %s | %s | %.1f | %.3f | %s | %.3f | %.3f | %.3f | %.3f | %.2f | "
                "%.3f | %.3f | %.0f |\n", q->model, tirenv_ride_enveloping_name(q->enveloping),
                q->speed * 3.6, q->c.seat.rms, crest, q->c.seat.vdv, q->c.seat.mtvv,
                q->c.pitch.rms, q->c.a_v, q->c.peak_az, q->c.lift_off, q->seconds,
                q->duration / fmax(q->seconds, 1e-9));
    }
    write_differences(fp, r, res);
    write_tires(fp, v, given, tire_path, load);
    return tirenv_outfile_commit(f, diag);
}

/* The gnuplot preamble both figures share: the image names tirenv sets on the command line,
 * and a loop drawing the same multiplot first as PNG, then as SVG. */
static void script_head(FILE *fp, const char *base, const char *what, const ride_options *r)
{
    fprintf(fp,
            "# tirenv ride: %s.\n"
            "# Data: %s.dat in this directory, one block per speed (gnuplot's 'index'), one\n"
            "# column per model. Draw by hand from this directory with:  gnuplot %s.gp\n"
            "# tirenv sets png_out and svg_out itself, to temporary names it renames when\n"
            "# gnuplot has finished.\n",
            what, base, base);
    cli_plot_outputs(fp, base);
    fputs("\nmodels = \"", fp);
    for (size_t i = 0; i < r->n_cols; ++i)
        fprintf(fp, "%s%s", i ? " " : "", r->cols[i].label);
    fputs("\"\nspeeds = \"", fp);
    for (size_t j = 0; j < r->n_speeds; ++j) {
        char speed[32];
        ride_cli_speed_name(r->speeds[j], speed, sizeof speed);
        fprintf(fp, "%s%s", j ? " " : "", speed);
    }
    fputs("\"   # km/h\n", fp);
    for (size_t i = 0; i < r->n_cols; ++i) {
        /* The colours of every tirenv plot: a model looks the same here as in the study; where
         * the run draws a model both ways, the way of enveloping other than the static one is
         * dashed in the model's colour. Alone (the default, dynamic) it keeps the model's own
         * line: dashes over a road's dense oscillation leave it unreadable. */
        const ride_column *c = &r->cols[i];
        const char *name = tirenv_model_type_name(r->models[c->model]);
        const tirenv_plot_style st = tirenv_plot_style_of(name, c->model);
        const int dash = c->enveloping == TIRENV_RIDE_STATIC || r->n_envelopings < 2
                             ? st.dash
                             : 1 + (int)c->enveloping;
        fprintf(fp, "set style line %zu lc rgb '%s' lw %.1f dt %d   # %s\n", i + 1, st.colour,
                st.width, dash, c->label);
    }
    /* The key beside the panels: inside, over a road's dense lines, it hid the right tenth. */
    fputs("set encoding utf8\nset grid lc rgb '#d0d0d0'\nset key outside right top box\n\n", fp);
    cli_plot_passes(fp, 1000, 260 * r->n_speeds + 60);
}

/* <dir>/<base><ext> opened to be written (tirenv_outfile: in place only on commit). */
static int open_in(const char *dir, const char *base, const char *ext, tirenv_outfile **f,
                   tirenv_diag *diag)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s%s", dir, base, ext);
    return tirenv_outfile_open(f, path, diag);
}

/* A data file written in blocks: kept where every block was (status 0), else removed. */
static int close_data(tirenv_outfile *f, int status, tirenv_diag *diag)
{
    if (status) {
        tirenv_outfile_abort(f);
        return status;
    }
    return tirenv_outfile_commit(f, diag);
}

/* Writes <dir>/<base>.gp, one panel per speed drawing every model's column of <base>.dat,
 * with the panel settings 'axes' (gnuplot lines), and draws it as PNG and SVG. */
static int draw(const char *dir, const char *base, const char *what, const char *title,
                const char *axes, const ride_options *r, tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = open_in(dir, base, ".gp", &f, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    script_head(fp, base, what, r);
    fprintf(fp,
            "    set multiplot layout %zu,1 title \"%s\"\n"
            "%s"
            "    do for [j = 1:words(speeds)] {\n"
            "        set title word(speeds, j).\" km/h\"\n"
            "        plot for [i = 1:words(models)] '%s.dat' index (j - 1) using 1:(column(i + 1)) "
            "with lines ls i title word(models, i)\n"
            "    }\n"
            "    unset multiplot\n"
            "}\n"
            "unset output\n",
            r->n_speeds, title, axes, base);
    if ((status = tirenv_outfile_commit(f, diag)))
        return status;
    return tirenv_plot_draw(dir, base, NULL, diag);
}

/* The two figures over the front axle's position, one column per model: seat, the unweighted
 * seat acceleration; seat-rms, the running r.m.s. of the Wk-weighted one (ISO 2631-1 6.3, tau =
 * TIRENV_COMFORT_TAU), whose maximum is the run's MTVV: over a long road the unweighted trace
 * of every model lies on the others', a 1 s mean tells them apart. */
typedef enum { SEAT, SEAT_RMS } over_x;

/* Model i's values of figure kind at the n samples of its run into v. */
static int over_x_values(over_x kind, const ride_options *r, const ride_series *run, size_t n,
                         double v[], tirenv_diag *diag)
{
    if (kind == SEAT_RMS)
        return tirenv_comfort_running_rms(run->a_w, n, 1 / r->pp.dt, TIRENV_COMFORT_TAU, v,
                                          diag);
    for (size_t k = 0; k < n; ++k)
        v[k] = run->samples[k].seat_az;
    return TIRENV_OK;
}

static int over_x_plot(over_x kind, const char *dir, const ride_options *r,
                       const ride_series series[], double wheelbase, tirenv_diag *diag)
{
    const char *base = kind == SEAT ? "seat" : "seat-rms";
    tirenv_outfile *f;
    int status = open_in(dir, base, ".dat", &f, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    for (size_t j = 0; j < r->n_speeds && !status; ++j) {
        /* The runs at one speed share their length, so one x column serves every model. */
        const ride_series *row = &series[j * r->n_cols];
        const size_t n = row[0].n, every = (n + SEAT_MAX_POINTS - 1) / SEAT_MAX_POINTS;
        const size_t cells = r->n_cols * n;
        double *v = malloc((cells > 0 ? cells : 1) * sizeof *v);
        if (!v)
            status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        for (size_t i = 0; i < r->n_cols && !status; ++i)
            status = over_x_values(kind, r, &row[i], n, v + i * n, diag);
        char speed[32];
        ride_cli_speed_name(r->speeds[j], speed, sizeof speed);
        if (!status)
            fprintf(fp, "%s# %s km/h%s: x_front_m", j ? "\n\n" : "", speed,
                    kind == SEAT ? "" : ", running r.m.s. over 1 s");
        for (size_t i = 0; i < r->n_cols && !status; ++i)
            fprintf(fp, kind == SEAT ? " seat_az_%s_m_s2" : " awz_rms_%s_m_s2",
                    r->cols[i].label);
        if (!status)
            fputc('\n', fp);
        /* A row stands for `every` samples by the one of largest magnitude (every k-th sample
         * alone aliased a road's oscillation and missed its peaks): the plotted extremes are
         * the run's, its peak_az and its MTVV. */
        for (size_t k = 0; k < n && !status; k += every) {
            fprintf(fp, "%.6g", row[0].samples[k].x_front);
            for (size_t i = 0; i < r->n_cols; ++i) {
                const double *vi = v + i * n;
                double a = vi[k];
                for (size_t m = k + 1; m < k + every && m < n; ++m)
                    if (fabs(vi[m]) > fabs(a))
                        a = vi[m];
                fprintf(fp, " %.6g", a);
            }
            fputc('\n', fp);
        }
        free(v);
    }
    if ((status = close_data(f, status, diag)))
        return status;
    char axes[300];
    snprintf(axes, sizeof axes,
             "    set xlabel \"front axle position (m); the rear axle follows %.2f m behind\"\n"
             "    set ylabel \"%s\"\n%s"
             "    set autoscale xfix\n", /* the run's span, not the next tics' */
             wheelbase, kind == SEAT ? "seat a_z (m/s²)" : "running r.m.s. of a_wz (m/s²)",
             kind == SEAT ? "" : "    set yrange [0:*]\n");
    if (kind == SEAT)
        return draw(dir, base, "vertical acceleration at the seat over the front axle's "
                    "position, point contact against enveloping",
                    "Seat vertical acceleration (unweighted)", axes, r, diag);
    return draw(dir, base, "running r.m.s. over 1 s of the Wk-weighted vertical acceleration "
                "at the seat (ISO 2631-1 6.3; its maximum is the MTVV), point contact against "
                "enveloping",
                "Seat vertical acceleration, running r.m.s. (Wk, 1 s; its maximum is the MTVV)",
                axes, r, diag);
}

/* The longest power-of-two segment up to WELCH_MAX_SEGMENT giving at least 3 half-overlapping
 * segments, so the estimate averages something. */
static size_t welch_segment(size_t n)
{
    size_t seg = 16;
    while (seg * 2 <= WELCH_MAX_SEGMENT && seg * 2 * 2 <= n)
        seg *= 2;
    return seg;
}

/* spectrum: Welch's PSD of the unweighted seat acceleration. */
static int spectrum_plot(const char *dir, const ride_options *r, const ride_series series[],
                         tirenv_diag *diag)
{
    tirenv_outfile *f;
    int status = open_in(dir, "spectrum", ".dat", &f, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    const double fs = 1 / r->pp.dt;
    double lo = INFINITY, hi = 0;  /* the positive PSD values in the band, over all panels */
    int flat_panel = 0;            /* a panel without one */
    for (size_t j = 0; j < r->n_speeds && !status; ++j) {
        const ride_series *row = &series[j * r->n_cols];
        const size_t seg = welch_segment(row[0].n);
        tirenv_welch *w = NULL;
        double *psd = NULL, *a = malloc(row[0].n * sizeof *a);
        status = a ? tirenv_welch_alloc(seg, &w, diag)
                   : tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        const size_t bins = w ? tirenv_welch_bins(w) : 0;
        if (!status && !(psd = malloc(r->n_cols * bins * sizeof *psd)))
            status = tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
        for (size_t i = 0; i < r->n_cols && !status; ++i) {
            for (size_t k = 0; k < row[i].n; ++k)
                a[k] = row[i].samples[k].seat_az;
            status = tirenv_welch_psd(w, a, row[i].n, fs, psd + i * bins, NULL, diag);
        }
        if (!status) {
            fprintf(fp, "%s# %g km/h, Welch segments of %zu samples: f_Hz", j ? "\n\n" : "",
                    r->speeds[j] * 3.6, seg);
            for (size_t i = 0; i < r->n_cols; ++i)
                fprintf(fp, " psd_%s_m2_s4_Hz", r->cols[i].label);
            fputc('\n', fp);
            double panel_hi = 0;
            for (size_t k = 1; k < bins; ++k) {  /* bin 0 (the mean) has no place on log axes */
                const double freq = (double)k * fs / (double)seg;
                fprintf(fp, "%.6g", freq);
                for (size_t i = 0; i < r->n_cols; ++i) {
                    const double v = psd[i * bins + k];
                    fprintf(fp, " %.6g", v);
                    if (v > 0 && freq >= SPECTRUM_F_LO && freq <= SPECTRUM_F_HI) {
                        lo = fmin(lo, v);
                        panel_hi = fmax(panel_hi, v);
                    }
                }
                fputc('\n', fp);
            }
            hi = fmax(hi, panel_hi);
            flat_panel |= !(panel_hi > 0);
        }
        tirenv_welch_free(w);
        free(psd);
        free(a);
    }
    if ((status = close_data(f, status, diag)))
        return status;
    /* Log axes cannot show a PSD of 0, and a level road leaves the seat still: gnuplot
     * refuses a panel without a positive point ("all points y value undefined"), which failed
     * the whole run after every figure was computed. Such a panel gets the range of the
     * others' values, or a nominal one and a note when no panel has any. */
    char range[200] = "";
    if (flat_panel && hi > 0)
        snprintf(range, sizeof range, "    set yrange [%.6g:%.6g]   # a panel's PSD is 0\n",
                 lo, hi);
    else if (flat_panel)
        snprintf(range, sizeof range, "    set yrange [1e-12:1]\n"
                 "    set label 1 \"the PSD is 0: no vibration at the seat\" at graph 0.5, "
                 "0.5 center\n");
    char axes[800];
    snprintf(axes, sizeof axes,
             "    set logscale xy\n"
             "    set format y '%%.0e'\n"
             "    set xrange [%g:%g]   # ISO 2631-1's band for comfort (Wk)\n"
             "%s"
             "    set xlabel \"frequency (Hz)\"\n"
             "    set ylabel \"PSD of seat a_z ((m/s²)²/Hz)\"\n",
             SPECTRUM_F_LO, SPECTRUM_F_HI, range);
    return draw(dir, "spectrum", "power spectral density of the vertical acceleration at "
                "the seat (Welch, Hann, 50 % overlap), point contact against enveloping",
                "Seat vertical acceleration spectrum", axes, r, diag);
}

int ride_cli_report(const ride_options *r, const ride_result res[], const ride_series series[],
                    const tirenv_vehicle *v, const tirenv_vehicle *given,
                    const char tire_path[2][1024], const double load[2])
{
    const double wheelbase = v->a + v->b;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    char path[1024];
    snprintf(path, sizeof path, "%s/comfort.csv", r->out_dir);
    int status = write_csv(path, r, res, &diag);
    if (!status) {
        snprintf(path, sizeof path, "%s/comfort.md", r->out_dir);
        status = write_md(path, r, res, v, given, tire_path, load, &diag);
    }
    if (!status)
        status = over_x_plot(SEAT, r->out_dir, r, series, wheelbase, &diag);
    if (!status)
        status = over_x_plot(SEAT_RMS, r->out_dir, r, series, wheelbase, &diag);
    if (!status)
        status = spectrum_plot(r->out_dir, r, series, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}
