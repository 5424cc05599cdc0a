/* What the subcommands share once their options are parsed (parse.c): the tire, the model
 * and its network, the load, the positions, number parsing, and the mapping from library
 * status to exit code. SPDX-License-Identifier: Apache-2.0 */
#include "cli/cli.h"
#include "tirenv/nn_file.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>


void cli_error(const char *fmt, ...)
{
    va_list ap;
    fputs("tirenv: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

int cli_exit_code(int status)
{
    switch (status) {
    case TIRENV_OK:
        return CLI_EXIT_OK;
    case TIRENV_ENOBRACKET:
    case TIRENV_ENOCONV:
    case TIRENV_ECONTINUE:
        return CLI_EXIT_NUMERIC;
    default:  /* EINVAL, EIO, EPARSE, ERANGE, ENOMEM: the input (or the machine) is at fault */
        return CLI_EXIT_DATA;
    }
}

int cli_fail(int status, const tirenv_diag *diag)
{
    char buf[1200];
    if (diag && (diag->message[0] || diag->file[0] || diag->field[0]))
        cli_error("%s", tirenv_diag_format(diag, buf, sizeof buf));
    else
        cli_error("%s", tirenv_strerror(status));
    return cli_exit_code(status);
}

double cli_cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double cli_thread_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double cli_wall_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int cli_mkdir(const char *dir)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_mkdir_p(dir, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

/* strtod's ERANGE is not checked: an overflow is infinite, refused as such, and an underflow
 * is the number rounded to a subnormal or 0, as the file readers take it. */
int cli_parse_double(const char *s, double *v)
{
    char *end;
    const double d = strtod(s, &end);
    if (end == s || *end != '\0' || !isfinite(d))
        return -1;
    *v = d;
    return 0;
}

/* Splits on commas without copying: strtod stops at the comma, which is then required. */
int cli_parse_doubles(const char *s, double v[], size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        char *end;
        v[i] = strtod(s, &end);
        if (end == s || !isfinite(v[i]))
            return -1;
        if (i + 1 < n ? *end != ',' : *end != '\0')
            return -1;
        s = end + 1;
    }
    return 0;
}

int cli_parse_count(const char *s, long min, long max, long *v)
{
    char *end;
    errno = 0;
    const long l = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || l < min || l > max)
        return -1;
    *v = l;
    return 0;
}

int cli_data_source(const char *dir, cli_options *o, tirenv_dataset_source *src, char *buf,
                    size_t n)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_dataset_source_read(dir, src, &diag);
    if (status)
        return cli_fail(status, &diag);
    if (!o->tire_path && src->tire[0]) {
        snprintf(buf, n, "%s", src->tire);
        o->tire_path = buf;
    }
    return CLI_EXIT_OK;
}

int cli_sweep_reference(const char *cmd, const char *dir, const tirenv_dataset_source *src,
                        const char *instead)
{
    if (!src->sweep_model[0] || src->model[0])
        return CLI_EXIT_OK;
    if (src->sweep_key[0])
        cli_error("%s: %s/sweep.txt:%zu: the sweep set %s (each case's value: sweep.csv), so "
                  "its cases are the %s model's with more than its tire.tir, and no one tire "
                  "file is their reference; give %s", cmd, dir, src->sweep_key_line,
                  src->sweep_key, src->sweep_model, instead);
    else
        cli_error("%s: %s/sweep.txt: its cases are the %s model's, which is not a physical "
                  "model to take as their reference; give %s", cmd, dir, src->sweep_model,
                  instead);
    return CLI_EXIT_DATA;
}

int cli_data_and_tire(const char *dir, cli_options *o, tirenv_dataset_source *src, char *buf,
                      size_t n, tirenv_tire *tire, tirenv_dataset *ds)
{
    int code = cli_data_source(dir, o, src, buf, n);
    if (code || (code = cli_tire(o, tire)))
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_dataset_read(dir, tire->springs.R0, ds, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

const char *cli_tire_path(const cli_options *o, char *buf, size_t n)
{
    return o->tire_path ? o->tire_path : cli_data_path("tires/default.tir", buf, n);
}

tirenv_tir_origin cli_tire_origin;

double cli_nominal_load(const tirenv_tire *tire)
{
    const tirenv_tir_origin *o = &cli_tire_origin;
    const double fnomin = o->fnomin;
    if (!(fnomin > 0))
        return 0;
    /* A ring the file lacks and that was not derived though it could be (the cam alone used,
     * tirenv_tir_derive's TIRENV_TIR_ONLY) is not this tire's: its load range. */
    if (!((o->own | o->derived) & TIRENV_TIR_RING) && o->rho_nominal > 0)
        return fnomin;
    tirenv_model *ring = tirenv_model_alloc(tirenv_model_ring, tire);
    double lo = 0, hi = 0;
    const int inside = ring &&
                       tirenv_model_load_for_contact_length(ring, 0.28, &lo, NULL) == 0 &&
                       tirenv_model_load_for_contact_length(ring, 0.38, &hi, NULL) == 0 &&
                       fnomin >= lo && fnomin <= hi;
    tirenv_model_free(ring);
    return inside ? 0 : fnomin;
}

/* One read of the file for both passes: a tire file may be a pipe or /dev/stdin. */
int cli_tire_read_derive(const char *path, unsigned need, tirenv_tire *tire,
                         tirenv_tir_origin *origin)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_tir_read_derive(path, tire, need, origin, &diag);
    if (status)
        return cli_fail(status, &diag);
    if (origin->note[0])
        fprintf(stderr, "tirenv: %s: %s\n", path, origin->note);
    return CLI_EXIT_OK;
}

int cli_refuse_pipe(const char *path, const char *why)
{
    struct stat st;
    if (stat(path, &st) != 0 || !(S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode)))
        return CLI_EXIT_OK;  /* a file, a device or nothing: its reader says what is wrong */
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    return cli_fail(tirenv_error(&diag, TIRENV_EIO, path, 0, "", "a pipe, which can be read "
                                 "only once; %s, expected a regular file", why), &diag);
}

int cli_tire(const cli_options *o, tirenv_tire *tire)
{
    char buf[1024];
    const char *path = cli_tire_path(o, buf, sizeof buf);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    *tire = tirenv_tire_default();
    int status;
    /* A --contact-length is the springs model's load for the models that do not deflect
     * (tirenv_tir_need). */
    const int at_chord = o->have_contact_length &&
                         (o->type == tirenv_model_rigid || o->type == tirenv_model_point);
    const unsigned need = (o->type ? tirenv_tir_need(o->type, o->type_alone)
                                   : TIRENV_TIR_SPRINGS) |  /* every command's default model */
                          (at_chord ? TIRENV_TIR_SPRINGS : 0u);
    if ((status = cli_tire_read_derive(path, need, tire, &cli_tire_origin)))
        return status;
    for (size_t i = 0; i < o->n_sets; ++i) {
        status = tirenv_tir_set(tire, o->sets[i], &diag);
        if (status && diag.file[0])  /* already says "--set: KEY: ..." */
            return cli_fail(status, &diag);
        if (status) {
            char msg[1200];
            cli_error("--set %s: %s", o->sets[i], tirenv_diag_format(&diag, msg, sizeof msg));
            return cli_exit_code(status);
        }
    }
    if (o->have_method)
        tire->eq.method = o->method;
    /* Checked here, not left to tirenv_model_alloc, which can only say NULL. */
    status = tirenv_tire_check(tire, &diag);
    if (status) {
        char msg[1200];
        cli_error("tire from %s%s: %s", path, o->n_sets ? " and --set" : "",
                  tirenv_diag_format(&diag, msg, sizeof msg));
        return cli_exit_code(status);
    }
    /* The models the command runs, to say which --set keys none of them reads. */
    const tirenv_model_type *const *runs = o->n_runs ? o->runs : &o->type;
    const size_t n_runs = o->n_runs ? o->n_runs : o->type != NULL;
    unsigned reads = o->reads_also;
    for (size_t k = 0; k < n_runs; ++k)
        reads |= cli_model_reads(runs[k], o->have_contact_length);
    cli_set_warnings(o->sets, o->n_sets, runs, n_runs, reads);
    if (o->have_method)
        cli_method_warning(runs, n_runs, reads);
    return CLI_EXIT_OK;
}

int cli_model_type(const char *option, const char *name, const tirenv_model_type **type)
{
    *type = tirenv_model_type_find(name);
    if (*type)
        return CLI_EXIT_OK;
    fprintf(stderr, "tirenv: %s: expected one of", option);
    for (const tirenv_model_type *const *t = tirenv_model_types(); *t; ++t)
        fprintf(stderr, " %s", tirenv_model_type_name(*t));
    fprintf(stderr, ", got '%s'\n", name);
    return CLI_EXIT_USAGE;
}

int cli_model_list(const char *option, const char *arg, const tirenv_model_type *types[],
                   size_t max, size_t *n)
{
    *n = 0;
    const char *p = arg;
    for (;;) {
        const size_t len = strcspn(p, ",");
        char name[32];
        if (len == 0 || len >= sizeof name || *n == max) {
            cli_error("%s: expected 1 to %zu comma-separated model names, got '%s'", option,
                      max, arg);
            return CLI_EXIT_USAGE;
        }
        memcpy(name, p, len);
        name[len] = '\0';
        if (cli_model_type(option, name, &types[*n]))
            return CLI_EXIT_USAGE;
        ++*n;
        if (!p[len])
            return CLI_EXIT_OK;
        p += len + 1;
    }
}

/* tirenv_tir_need leaves the springs model to a network whose file records a contact law; an
 * older file's takes the springs model's contact length, which a tire file whose springs model
 * was neither given nor derived does not describe (the default tire's would stand in). */
int cli_nn_springs_stand_in(const char *nn_path, const char *tire_path,
                            const tirenv_tir_origin *origin, tirenv_diag *diag)
{
    if ((origin->own | origin->derived) & TIRENV_TIR_SPRINGS)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, nn_path, 0, "training.data.contact_law",
                        "the file records no relation between load and contact length of its "
                        "tire, and %s has no springs model to stand in for it (no "
                        "[ENVELOPING_SPRINGS], none derived); train the network again to "
                        "record it", tire_path);
}

/* A tire file without MF-Swift's cam data would give the cam another tire's shape: refused,
 * the file named as every other tire error names it. */
int cli_cam_keys(const tirenv_model_type *type, const tirenv_tire *tire, const char *path)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (type != tirenv_model_cam || !tirenv_tire_check_cam_keys(tire, &diag))
        return CLI_EXIT_OK;
    /* The library's refusal serves the FMU and Python too; here the keys can also be set. */
    const size_t n = strlen(diag.message);
    snprintf(diag.message + n, sizeof diag.message - n, " or give them with --set");
    snprintf(diag.file, sizeof diag.file, "%s", path);
    return cli_fail(TIRENV_EINVAL, &diag);
}

/* The network comes with the radius its x_N refers to, recorded in the model file. */
int cli_model(const tirenv_model_type *type, const tirenv_tire *tire, const cli_options *o,
              tirenv_model **out)
{
    char buf[1024];
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    *out = NULL;
    int code = cli_cam_keys(type, tire, o ? cli_tire_path(o, buf, sizeof buf) : "");
    if (code)
        return code;
    *out = tirenv_model_alloc(type, tire);
    if (!*out)  /* the tire was checked: only memory is left */
        return cli_fail(TIRENV_ENOMEM, NULL);
    if (!(tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK))
        return CLI_EXIT_OK;
    tirenv_nn *nn = NULL;
    tirenv_train_record rec;
    int status = o && o->nn_path
                     ? tirenv_nn_read_json(o->nn_path, &nn, &rec, &diag)
                     : tirenv_error(&diag, TIRENV_EINVAL, "", 0, "network",
                                    "the %s model needs a trained network (--nn FILE)",
                                    tirenv_model_type_name(type));
    if (o)
        tirenv_model_set_extrapolate(*out, o->extrapolate);
    if (!status && (status = tirenv_model_set_network(*out, nn, rec.R0, &diag)) &&
        !diag.file[0])
        snprintf(diag.file, sizeof diag.file, "%s", o->nn_path);
    /* The network's own tire turns a load into its contact length; an older file has no
     * record of it, and the springs model of the tire file stands in, as it used to. */
    if (!status && rec.law.n)
        status = tirenv_model_set_contact_law(*out, &rec.law, &diag);
    else if (!status && !(status = cli_nn_springs_stand_in(o->nn_path,
                                                             cli_tire_path(o, buf, sizeof buf),
                                                             &cli_tire_origin, &diag)))
        fprintf(stderr, "tirenv: warning: %s records no relation between load and contact "
                "length of its tire (training.data.contact_law; a file written before tirenv "
                "recorded it): loads become contact lengths by the springs model of the tire "
                "file, not by the tire the network was trained on; train it again to record "
                "it\n", o->nn_path);
    tirenv_nn_free(nn);
    if (status) {
        tirenv_model_free(*out);
        *out = NULL;
        return cli_fail(status, &diag);
    }
    return CLI_EXIT_OK;
}

void cli_model_warnings(const char *cmd, const tirenv_model *m)
{
    cli_warnings(cmd, tirenv_model_warnings(m));
}

void cli_warnings(const char *cmd, const char *w)
{
    while (*w) {
        const size_t len = strcspn(w, "\n");
        fprintf(stderr, "tirenv: %s: warning: %.*s\n", cmd, (int)len, w);
        w += len + (w[len] == '\n');
    }
}

int cli_load(const cli_options *o, tirenv_model *m, double *load)
{
    if (o->have_load) {
        *load = o->load;
        return CLI_EXIT_OK;
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status =
        tirenv_model_load_for_contact_length(m, o->contact_length, load, &diag);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

/* Positions x_k = x_from + k*dx up to x_to (with a 1e-9 dx allowance for round-off), by
 * multiplication so that no error accumulates over thousands of steps. */
int cli_positions_check(double x_from, double x_to, double dx, double max, size_t *n_out)
{
    if (!(dx > 0) || !(x_to >= x_from)) {
        cli_error("expected --dx > 0 and --x-to >= --x-from, got dx %g m from %g to %g m", dx,
                  x_from, x_to);
        return CLI_EXIT_USAGE;
    }
    /* %.3g: a count of 1e300 is not printed as 301 digits. */
    const double steps = floor((x_to + dx * 1e-9 - x_from) / dx);
    if (!(steps < max)) {
        cli_error("%.3g positions from %g to %g m every %g m is too many (at most %.0f); "
                  "raise --dx or narrow --x-from/--x-to", steps + 1, x_from, x_to, dx, max);
        return CLI_EXIT_USAGE;
    }
    if (tirenv_positions_count(x_from, x_to, dx) == 0) {
        cli_error("--dx %g m does not move x at %g m (x + dx == x); expected a larger --dx",
                  dx, fabs(x_from) > fabs(x_to) ? x_from : x_to);
        return CLI_EXIT_USAGE;
    }
    *n_out = tirenv_positions_count(x_from, x_to, dx);
    return CLI_EXIT_OK;
}

int cli_positions(double x_from, double x_to, double dx, double **x_out, size_t *n_out)
{
    size_t n = 0;
    const int code = cli_positions_check(x_from, x_to, dx, CLI_MAX_POSITIONS, &n);
    if (code)
        return code;
    double *x = malloc(n * sizeof *x);
    if (!x)
        return cli_fail(TIRENV_ENOMEM, NULL);
    for (size_t k = 0; k < n; ++k)
        x[k] = x_from + (double)k * dx;
    *x_out = x;
    *n_out = n;
    return CLI_EXIT_OK;
}
