/* tirenv ride, the work: the vehicle and its tires, each model's inputs for both axles, one
 * run per model and speed, the comfort table and the files. SPDX-License-Identifier:
 * Apache-2.0 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "cli/csv_row.h"
#include "cli/ride_cli.h"
#include "tirenv/nn_file.h"
#include "tirenv/parallel.h"

/* What one model makes of the obstacle for both axles, and what it cost. */
typedef struct {
    const tirenv_model_type *type;
    const char *name;
    double *w[2];          /* front, rear inputs on the grid at the static loads, m (NULL
                            * unless --enveloping static) */
    double seconds;        /* CPU time of the effective profiles, s */
    tirenv_ride_table table[2];  /* front, rear over loads (--enveloping dynamic) */
    double table_seconds;  /* CPU time of the tables, s */
    tirenv_nn *nn;         /* the network the model evaluates, or NULL */
    double R0_nn;          /* the radius its x_N refers to (0: the tire's), m */
} ride_inputs;

typedef struct {
    tirenv_vehicle v;      /* with each axle's k_t and c_t set (tirenv_vehicle_tires) */
    tirenv_vehicle given;  /* as the vehicle file and --set give it: NAN k_t, c_t the tire's */
    tirenv_tire tire[2];   /* front, rear */
    double load[2];        /* static load of one tire, N */
    tirenv_tir_origin origin[2];  /* what tirenv_tir_derive made of each tire file */
    char tire_path[2][1024];
    const tirenv_profile *p;
    tirenv_ride_plan plan; /* each speed's run and the inputs' grid */
} ride_setup;

/* Where the axle's TIRE_FILE was named, for a tire error: the last --set of it, else its line
 * in the vehicle file (a regular file only: a pipe was read once), else nowhere (the default
 * tire file). */
static void tire_named_by(const ride_options *r, const char *vehicle, int axle, int named,
                          char *buf, size_t n)
{
    const char *section = axle ? "REAR_AXLE" : "FRONT_AXLE";
    char field[32];
    snprintf(field, sizeof field, "%s.TIRE_FILE", section);
    if (named)
        snprintf(buf, n, "%s: [%s] TIRE_FILE", vehicle, section);
    else
        snprintf(buf, n, "%s: no [%s] TIRE_FILE: the default tire file", vehicle, section);
    for (size_t i = r->n_sets; i-- > 0;)
        if (strncasecmp(r->sets[i], field, strlen(field)) == 0 &&
            strchr(" \t=", r->sets[i][strlen(field)])) {
            snprintf(buf, n, "--set %s", field);
            return;
        }
    struct stat st;
    FILE *fp = stat(vehicle, &st) == 0 && S_ISREG(st.st_mode) ? fopen(vehicle, "r") : NULL;
    char line[1024];
    int inside = 0;
    for (size_t k = 1; named && fp && fgets(line, sizeof line, fp); ++k) {
        const char *p = line + strspn(line, " \t");
        if (*p == '[')
            inside = strncasecmp(p + 1, section, strlen(section)) == 0 &&
                     p[1 + strlen(section)] == ']';
        else if (inside && strncasecmp(p, "TIRE_FILE", 9) == 0 && strchr(" \t=", p[9])) {
            snprintf(buf, n, "%s:%zu: [%s] TIRE_FILE", vehicle, k, section);
            break;
        }
    }
    if (fp)
        fclose(fp);
}

/* The cam needs MF-Swift's shape keys (ELLIPS_*) of each axle's tire: refused before any run,
 * naming the tire file and where the vehicle names it, as every other tire error does. */
static int cam_keys(const ride_options *r, const ride_setup *s, const char *vehicle)
{
    int cam = 0;
    for (size_t i = 0; i < r->n_models; ++i)
        cam |= r->models[i] == tirenv_model_cam;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    for (int axle = 0; cam && axle < 2; ++axle) {
        if (!tirenv_tire_check_cam_keys(&s->tire[axle], &diag))
            continue;
        char named[700];
        const tirenv_axle *ax = axle ? &s->v.rear : &s->v.front;
        tire_named_by(r, vehicle, axle, ax->tire_file[0] != '\0', named, sizeof named);
        snprintf(diag.file, sizeof diag.file, "%.*s", (int)sizeof diag.file - 1,
                 s->tire_path[axle]);  /* bounded: the TSan build's -Werror saw truncation */
        char msg[1200];
        cli_error("%s (the %s axle's tire, named by %s)",
                  tirenv_diag_format(&diag, msg, sizeof msg), axle ? "rear" : "front", named);
        return cli_exit_code(TIRENV_EINVAL);
    }
    return CLI_EXIT_OK;
}

static int load_vehicle(const ride_options *r, ride_setup *s)
{
    char buf[1024];
    const char *path = r->vehicle_path ? r->vehicle_path
                                       : cli_data_path("vehicles/tractor.veh", buf, sizeof buf);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    s->v = tirenv_vehicle_default();
    /* A user's file that leaves a key out keeps the default tractor's value: said, since a
     * forgotten PITCH_INERTIA would otherwise be the tractor's without a word. */
    char unset[512];
    int status = tirenv_vehicle_read_unset(path, &s->v, unset, sizeof unset, &diag);
    if (!status && r->vehicle_path && unset[0]) {
        char text[700];
        snprintf(text, sizeof text, "%s sets no %s: the default tractor's values", path, unset);
        cli_warnings("ride", text);
    }
    for (size_t i = 0; !status && i < r->n_sets; ++i)
        status = tirenv_vehicle_set(&s->v, r->sets[i], &diag);
    if (!status)
        status = tirenv_vehicle_check(&s->v, &diag);
    if (status)
        return cli_fail(status, &diag);
    for (int axle = 0; axle < 2; ++axle) {
        const tirenv_axle *ax = axle ? &s->v.rear : &s->v.front;
        char tire_buf[1024];
        const char *tire_path = ax->tire_file[0]
                                    ? ax->tire_file
                                    : cli_data_path("tires/default.tir", tire_buf,
                                                    sizeof tire_buf);
        s->tire[axle] = tirenv_tire_default();
        unsigned need = 0;
        for (size_t i = 0; i < r->n_models; ++i)
            need |= tirenv_tir_need(r->models[i], 0);
        /* Both axles on one tire file: read once, which a pipe needs; said for each axle. */
        if (axle && strcmp(tire_path, s->tire_path[0]) == 0) {
            s->tire[1] = s->tire[0];
            s->origin[1] = s->origin[0];
            if (s->origin[1].note[0])
                fprintf(stderr, "tirenv: %s: %s\n", tire_path, s->origin[1].note);
        } else if ((status = cli_tire_read_derive(tire_path, need, &s->tire[axle],
                                                  &s->origin[axle]))) {
            return status;
        }
        snprintf(s->tire_path[axle], sizeof s->tire_path[axle], "%s", tire_path);
        s->load[axle] = tirenv_vehicle_tire_load(&s->v, axle);
    }
    /* The tires' springs and dampers from their tire files where the vehicle gives none. */
    s->given = s->v;
    if ((status = tirenv_vehicle_tires(&s->v, &s->tire[0], &s->tire[1], &diag))) {
        const int axle = strncmp(diag.field, "REAR", 4) == 0;  /* the axle's key is named */
        char named[700], msg[1200];
        tire_named_by(r, path, axle, (axle ? s->v.rear : s->v.front).tire_file[0] != '\0',
                      named, sizeof named);
        cli_error("%s (the %s axle's tire file %s, named by %s)",
                  tirenv_diag_format(&diag, msg, sizeof msg), axle ? "rear" : "front",
                  s->tire_path[axle], named);
        return cli_exit_code(status);
    }
    /* Checked again with the tire file's k_t and c_t (the static deflection, the ranges). */
    if ((status = tirenv_vehicle_check(&s->v, &diag)))
        return cli_fail(status, &diag);
    return cam_keys(r, s, path);
}

/* The model's warnings of one axle, one line each. */
static void axle_warnings(const char *model, int axle, const char *w)
{
    while (*w) {
        const size_t len = strcspn(w, "\n");
        fprintf(stderr, "tirenv: ride: warning: %s model, %s axle: %.*s\n", model,
                axle ? "rear" : "front", (int)len, w);
        w += len + (w[len] == '\n');
    }
}

/* Whether the options ask for a way of enveloping. */
static int asks(const ride_options *r, tirenv_ride_enveloping e)
{
    for (size_t k = 0; k < r->n_envelopings; ++k)
        if (r->envelopings[k] == e)
            return 1;
    return 0;
}

/* The direct evaluation's model of one axle for one run, set on the profile at the static
 * load (a run changes its load as it goes, so no two runs share one). */
static int direct_model(const ride_setup *s, const ride_inputs *in, int axle, int extrapolate,
                        tirenv_model **m, tirenv_diag *diag)
{
    int status = ride_cli_axle_model(in->type, &s->tire[axle], in->nn, in->R0_nn, extrapolate,
                                     m, diag);
    if (!status)
        status = tirenv_model_set(*m, s->p, s->load[axle], diag);
    return status;
}

/* The inputs of every model for both axles: n_models x 2 independent items on --jobs
 * threads, each with model instances of its own (ride_cli_axle_input and _table make them),
 * timed on its own thread's CPU clock; warnings and failures are reported afterwards, in
 * order. */
typedef struct {
    const ride_options *r;
    const ride_setup *s;
    ride_inputs *in;
    double (*seconds)[2];      /* per item: the static inputs', the tables' */
    char (*warnings)[1024];    /* per item */
    int *status;               /* per item */
} inputs_pass;

static int input_item(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    inputs_pass *p = ctx;
    const ride_options *r = p->r;
    const ride_setup *s = p->s;
    ride_inputs *in = &p->in[k / 2];
    const int axle = (int)(k % 2);
    (void)worker;
    int status = TIRENV_OK;
    double t0 = cli_thread_seconds();
    if (asks(r, TIRENV_RIDE_STATIC))
        status = ride_cli_axle_input(in->type, &s->tire[axle], s->load[axle], s->p, in->nn,
                                     in->R0_nn, r->extrapolate, s->plan.x0, s->plan.dx, s->plan.n,
                                     in->w[axle], p->warnings[k], sizeof p->warnings[k], diag);
    p->seconds[k][0] = cli_thread_seconds() - t0;
    t0 = cli_thread_seconds();
    if (!status && asks(r, TIRENV_RIDE_DYNAMIC)) {
        char table_warnings[1024];
        status = ride_cli_axle_table(in->type, &s->tire[axle], s->load[axle], s->p, in->nn,
                                     in->R0_nn, r->extrapolate, s->plan.x0, s->plan.dx, s->plan.n,
                                     &in->table[axle], table_warnings, sizeof table_warnings,
                                     diag);
        if (!asks(r, TIRENV_RIDE_STATIC))
            snprintf(p->warnings[k], sizeof p->warnings[k], "%s", table_warnings);
    }
    p->seconds[k][1] = cli_thread_seconds() - t0;
    /* Direct runs make their models as they go; set this axle's here so that a profile or
     * load the model refuses is named, with its axle, before any run. */
    if (!status && asks(r, TIRENV_RIDE_DIRECT)) {
        tirenv_model *m = NULL;
        status = direct_model(s, in, axle, r->extrapolate, &m, diag);
        tirenv_model_free(m);
    }
    return p->status[k] = status;
}

static int model_inputs(const ride_options *r, const ride_setup *s, ride_inputs in[])
{
    const size_t n_items = 2 * r->n_models;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    double seconds[2 * RIDE_MAX_MODELS][2];
    char warnings[2 * RIDE_MAX_MODELS][1024];
    int item_status[2 * RIDE_MAX_MODELS] = {0};
    inputs_pass pass = {r, s, in, seconds, warnings, item_status};
    int code = CLI_EXIT_OK, status = TIRENV_OK;
    for (size_t i = 0; i < r->n_models && !code; ++i) {
        for (int axle = 0; axle < 2 && asks(r, TIRENV_RIDE_STATIC); ++axle)
            if (!(in[i].w[axle] = malloc(s->plan.n * sizeof *in[i].w[axle])))
                code = cli_fail(TIRENV_ENOMEM, NULL);
        /* x_N refers to the radius of the network's data, when the file records it. */
        tirenv_train_record rec = {.R0 = 0};
        if (!code && (tirenv_model_type_flags(in[i].type) & TIRENV_MODEL_NEEDS_NETWORK)) {
            if ((status = tirenv_nn_read_json(r->nn_path, &in[i].nn, &rec, &diag)))
                code = cli_fail(status, &diag);
            in[i].R0_nn = rec.R0;
            for (int axle = 0; axle < 2 && !code && !rec.law.n; ++axle)
                if ((status = cli_nn_springs_stand_in(r->nn_path, s->tire_path[axle],
                                                      &s->origin[axle], &diag)))
                    code = cli_fail(status, &diag);
            if (!code)
                ride_cli_set_nn_law(r->nn_path, &rec.law);
        }
    }
    for (size_t k = 0; k < n_items; ++k)
        warnings[k][0] = '\0';
    if (!code)
        status = tirenv_parallel_for(n_items, r->jobs, input_item, NULL, &pass, &diag);
    for (size_t k = 0; k < n_items && !code; ++k) {
        const size_t i = k / 2;
        const int axle = (int)(k % 2);
        if (item_status[k]) {
            char msg[1200];
            cli_error("ride: %s model, %s axle (tire load %.6g N): %s", in[i].name,
                      axle ? "rear" : "front", s->load[axle],
                      tirenv_diag_format(&diag, msg, sizeof msg));
            code = cli_exit_code(status);
            break;
        }
        axle_warnings(in[i].name, axle, warnings[k]);
        in[i].seconds += seconds[k][0];  /* in[] starts zeroed */
        in[i].table_seconds += seconds[k][1];
    }
    return code;
}

/* The series into out, left open: -o's file is committed only once --out-dir's report is
 * written too. */
static void series_rows(tirenv_outfile *out, const ride_series *rs, const ride_result *res)
{
    char comment[256];
    snprintf(comment, sizeof comment, "tirenv ride: %s model at %.6g m/s (%.6g km/h), %zu "
             "samples", res->model, res->speed, res->speed * 3.6, rs->n);
    FILE *fp = tirenv_outfile_stream(out);
    fputs("t_s,x_front_m,w_front_m,w_rear_m,z_m,theta_rad,z_axle_m,seat_az_m_s2,seat_awz_m_s2,"
          "seat_ax_m_s2,atheta_rad_s2,F_front_N,F_rear_N\n", fp);
    tirenv_outfile_comment(out, comment);
    for (size_t k = 0; k < rs->n; ++k) {  /* each field as "%.9g" */
        const tirenv_ride_sample *s = &rs->samples[k];
        const double v[13] = {s->t, s->x_front, s->w_front, s->w_rear, s->z, s->theta,
                              s->z_a, s->seat_az, rs->a_w[k], s->seat_ax, s->atheta,
                              s->F_front, s->F_rear};
        char row[13 * CLI_ROW_FIELD], *p = row;
        for (size_t j = 0; j < 13; ++j)
            p = cli_row_g(p, v[j], 9, j + 1 < 13 ? ',' : '\n');
        fwrite(row, 1, (size_t)(p - row), fp);
    }
}

/* A run's series into path, committed (or, failing, what it wrote removed). */
static int write_series(const char *path, const ride_series *rs, const ride_result *res,
                        tirenv_diag *diag)
{
    tirenv_outfile *out;
    const int status = tirenv_outfile_open(&out, path, diag);
    if (status)
        return status;
    series_rows(out, rs, res);
    return tirenv_outfile_commit(out, diag);  /* it checks ferror and removes the file */
}

/* The options a field of tirenv_ride_plan_make's errors comes from. */
static const char *plan_option(const char *field)
{
    static const char *const options[][2] = {
        {"dt", "--dt"}, {"dx", "--dx"}, {"speed", "--speed"}, {"x_to", "--x-from, --x-to"},
        {"method", "--solver"}};
    for (size_t i = 0; i < sizeof options / sizeof *options; ++i)
        if (strcmp(field, options[i][0]) == 0)
            return options[i][1];
    return field;
}

static void print_table(FILE *fp, const ride_result res[], size_t n)
{
    fprintf(fp, "%-16s %7s %9s %6s %9s %9s %10s %9s %9s %8s %8s %9s\n", "run", "km/h",
            "a_wz", "crest", "VDV", "MTVV", "a_w,pitch", "a_v", "peak_az", "liftoff",
            "cpu_s", "x_real");
    fprintf(fp, "%-16s %7s %9s %6s %9s %9s %10s %9s %9s %8s %8s %9s\n", "", "", "m/s^2", "",
            "m/s^1.75", "m/s^2", "rad/s^2", "m/s^2", "m/s^2", "s", "s", "time");
    for (size_t i = 0; i < n; ++i) {
        const ride_result *q = &res[i];
        /* A run without vibration (a level road) has no crest factor (0/0): '-', not nan. */
        char crest[16] = "-";
        if (!isnan(q->c.seat.crest))
            snprintf(crest, sizeof crest, "%.2f", q->c.seat.crest);
        fprintf(fp, "%-16s %7.2f %9.4f %6s %9.4f %9.4f %10.4f %9.4f %9.3f %8.3f %8.3f %9.0f\n",
                q->label, q->speed * 3.6, q->c.seat.rms, crest, q->c.seat.vdv, q->c.seat.mtvv,
                q->c.pitch.rms, q->c.a_v, q->c.peak_az, q->c.lift_off, q->seconds,
                q->duration / fmax(q->seconds, 1e-9));
    }
}

/* One run of one model's inputs, the way of enveloping chosen. */
static int integrate(const ride_options *r, const ride_setup *s, const ride_inputs *in,
                     tirenv_ride_enveloping env, const tirenv_ride_settings *set,
                     tirenv_ride_sample out[], tirenv_diag *diag)
{
    if (env == TIRENV_RIDE_STATIC) {
        const tirenv_ride_track front = {s->plan.x0, s->plan.dx, s->plan.n, in->w[0]};
        const tirenv_ride_track rear = {s->plan.x0, s->plan.dx, s->plan.n, in->w[1]};
        return tirenv_ride_run(&s->v, &front, &rear, set, out, diag);
    }
    if (env == TIRENV_RIDE_DYNAMIC)
        return tirenv_ride_run_dynamic(&s->v, &in->table[0], &in->table[1], set, out, diag);
    /* Direct: the models between the loads the tables span, their positions every half grid
     * spacing apart for dw/dx, as the tables' Steffen slope sees the grid. */
    tirenv_model *m[2] = {NULL, NULL};
    tirenv_ride_direct d[2];
    tirenv_ride_input fn[2];
    int status = TIRENV_OK;
    for (int axle = 0; axle < 2 && !status; ++axle)
        status = direct_model(s, in, axle, r->extrapolate, &m[axle], diag);
    for (int axle = 0; axle < 2 && !status; ++axle)
        status = tirenv_ride_direct_input(m[axle], s->load[axle], s->plan.dx, &d[axle], &fn[axle],
                                          diag);
    if (!status)
        status = tirenv_ride_run_input(&s->v, &fn[0], &fn[1], set, out, diag);
    tirenv_model_free(m[0]);
    tirenv_model_free(m[1]);
    return status;
}

/* Every (speed, column) run: independent items on --jobs threads, each integrating,
 * measuring and writing its own series into --out-dir (-o's, of the one run, is written after
 * them, and committed with --out-dir); the CPU time of a run is its thread's. */
typedef struct {
    const ride_options *r;
    const ride_setup *s;
    const ride_inputs *in;
    ride_result *res;
    ride_series *series;
    int *status;               /* per run */
} ride_runs;

static int run_one(const ride_runs *p, size_t k, tirenv_diag *diag)
{
    const ride_options *r = p->r;
    const size_t j = k / r->n_cols, c = k % r->n_cols;
    const ride_inputs *in = &p->in[r->cols[c].model];
    const tirenv_ride_enveloping env = r->cols[c].enveloping;
    ride_result *q = &p->res[k];
    ride_series *rs = &p->series[k];
    const tirenv_ride_settings set = p->s->plan.run[j];
    *q = (ride_result){.model = in->name, .label = r->cols[c].label, .enveloping = env,
                       .speed = set.speed, .duration = set.duration};
    rs->n = tirenv_ride_n_samples(&set);
    rs->samples = malloc(rs->n * sizeof *rs->samples);
    rs->a_w = malloc(rs->n * sizeof *rs->a_w);
    if (!rs->samples || !rs->a_w)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    const double t0 = cli_thread_seconds();
    int status = integrate(r, p->s, in, env, &set, rs->samples, diag);
    const double inputs = env == TIRENV_RIDE_STATIC    ? in->seconds
                          : env == TIRENV_RIDE_DYNAMIC ? in->table_seconds
                                                : 0;
    q->seconds = inputs + cli_thread_seconds() - t0;
    if (!status)
        status = tirenv_ride_comfort_measure(rs->samples, rs->n, set.dt, rs->a_w, &q->c,
                                             diag);
    if (!status && r->out_dir && r->series) {
        char path[4200], speed[32];
        ride_cli_speed_name(q->speed, speed, sizeof speed);
        snprintf(path, sizeof path, "%s/series-%s-%skmh.csv", r->out_dir, q->label, speed);
        status = write_series(path, rs, q, diag);
    }
    return status;
}

static int run_item(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    ride_runs *p = ctx;
    (void)worker;
    return p->status[k] = run_one(p, k, diag);
}

/* The runs' plan (tirenv_ride_plan_make), checked before allocating, so a typo in --speed,
 * --dt or --dx is named, not "out of memory": a 10 km/h km of road is 0.36 M samples. These
 * are the options' errors. */
static int plan_runs(const ride_options *r, ride_setup *s, tirenv_diag *diag)
{
    if (tirenv_ride_plan_make(&r->pp, &s->v, s->p, r->speeds, r->n_speeds, &s->plan, diag)) {
        cli_error("ride: %s: %s", plan_option(diag->field), diag->message);
        return CLI_EXIT_USAGE;
    }
    const double dx_max = tirenv_ride_dx_max(s->tire[0].springs.R0, s->tire[1].springs.R0);
    if (!(s->plan.dx <= dx_max)) {
        cli_error("ride: --dx: a grid of %g m is coarser than a tenth of the tires' free radius "
                  "(%g m), the least that samples an effective road's features (the tire's "
                  "patch) twice; expected at most %g m (default %g)",
                  s->plan.dx, 10 * dx_max, dx_max, tirenv_ride_span_default().dx);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* -o opened before the inputs and runs, so that a path it cannot write (a directory, a
 * missing directory) is said before the work, not after it. */
static int open_out(const ride_options *r, tirenv_outfile **out, tirenv_diag *diag)
{
    const int status = r->out_path ? tirenv_outfile_open(out, r->out_path, diag) : TIRENV_OK;
    return status ? cli_fail(status, diag) : CLI_EXIT_OK;
}

/* --out-dir is written as a whole (tirenv_outdir): a failed or killed ride leaves the previous
 * directory as it was. The runs write their series into the staging directory: *r becomes
 * staged_r, the options with it as their --out-dir. */
static int stage_out_dir(const ride_options **r, ride_options *staged_r, tirenv_outdir **staged,
                         tirenv_diag *diag)
{
    if (!(*r)->out_dir)
        return CLI_EXIT_OK;
    const int status = tirenv_outdir_begin((*r)->out_dir, staged, diag);
    if (status)
        return cli_fail(status, diag);
    *staged_r = **r;
    staged_r->out_dir = tirenv_outdir_path(*staged);
    *r = staged_r;
    return CLI_EXIT_OK;
}

/* Every run on --jobs threads; the first that failed is said (the one diag is about). */
static int run_all(ride_runs *runs, size_t n_runs, tirenv_diag *diag)
{
    if (!(runs->status = calloc(n_runs, sizeof *runs->status)))
        return cli_fail(TIRENV_ENOMEM, NULL);
    const int status = tirenv_parallel_for(n_runs, runs->r->jobs, run_item, NULL, runs, diag);
    int code = CLI_EXIT_OK;
    for (size_t k = 0; status && k < n_runs; ++k)
        if (runs->status[k]) {
            const ride_result *q = &runs->res[k];
            char msg[1200];
            cli_error("ride: %s model (%s) at %g m/s: %s", q->model,
                      tirenv_ride_enveloping_name(q->enveloping), q->speed,
                      tirenv_diag_format(diag, msg, sizeof msg));
            code = cli_exit_code(status);
            break;
        }
    free(runs->status);
    runs->status = NULL;
    return code;
}

/* What the runs give: -o's series (of the one run: cmd_ride refuses -o with more), the table,
 * and --out-dir's report; -o's file committed only once the report is written (a failing
 * report left it replaced). */
static int write_outputs(const ride_options *r, const ride_setup *s, const ride_result res[],
                         const ride_series series[], size_t n_runs, tirenv_outfile **out,
                         tirenv_outdir **staged, tirenv_diag *diag)
{
    if (*out)  /* one run (cmd_ride refuses -o with more) */
        series_rows(*out, &series[0], &res[0]);
    print_table(stdout, res, n_runs);
    if (r->out_dir) {
        const int code = ride_cli_report(r, res, series, &s->v, &s->given,
                                         (const char(*)[1024])s->tire_path, s->load);
        if (code)
            return code;
    }
    /* -o first: its commit (the data flushed to disk) is the one that can fail for want of
     * room, and then --out-dir's previous directory stays too. */
    if (*out) {
        const int written = tirenv_outfile_commit(*out, diag);
        *out = NULL;
        if (written)
            return cli_fail(written, diag);
    }
    if (!r->out_dir)
        return CLI_EXIT_OK;
    const int committed = tirenv_outdir_commit(*staged, diag);
    *staged = NULL;
    return committed ? cli_fail(committed, diag) : CLI_EXIT_OK;
}

static void free_inputs(ride_inputs in[RIDE_MAX_MODELS])
{
    for (size_t i = 0; i < RIDE_MAX_MODELS; ++i)
        for (int axle = 0; axle < 2; ++axle) {
            free(in[i].w[axle]);
            free((double *)in[i].table[axle].load);
            free((double *)in[i].table[axle].w);
        }
    for (size_t i = 0; i < RIDE_MAX_MODELS; ++i)
        tirenv_nn_free(in[i].nn);
}

static void free_series(ride_series *series, size_t n_runs)
{
    for (size_t k = 0; series && k < n_runs; ++k) {
        free(series[k].samples);
        free(series[k].a_w);
    }
    free(series);
}

int ride_cli_run(const cli_options *o, const ride_options *r)
{
    ride_setup s;
    memset(&s, 0, sizeof s);
    int code = load_vehicle(r, &s);
    tirenv_profile *p = NULL;
    if (code || (code = cli_profile(o, &p)))
        return code;
    s.p = p;
    const size_t n_runs = r->n_cols * r->n_speeds;
    ride_inputs in[RIDE_MAX_MODELS] = {{0}};
    tirenv_outdir *staged = NULL;
    tirenv_outfile *out = NULL;
    ride_result *res = calloc(n_runs, sizeof *res);
    ride_series *series = calloc(n_runs, sizeof *series);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    ride_options staged_r;
    if (!res || !series) {
        code = cli_fail(TIRENV_ENOMEM, NULL);
        goto done;
    }
    if ((code = plan_runs(r, &s, &diag)) || (code = open_out(r, &out, &diag)))
        goto done;
    for (size_t i = 0; i < r->n_models; ++i) {
        in[i].type = r->models[i];
        in[i].name = tirenv_model_type_name(r->models[i]);
    }
    if ((code = model_inputs(r, &s, in)) ||
        (code = stage_out_dir(&r, &staged_r, &staged, &diag)))
        goto done;
    ride_runs runs = {r, &s, in, res, series, NULL};
    if (!(code = run_all(&runs, n_runs, &diag)))
        code = write_outputs(r, &s, res, series, n_runs, &out, &staged, &diag);
done:
    tirenv_outfile_abort(out);
    tirenv_outdir_abort(staged);
    free_inputs(in);
    free_series(series, n_runs);
    free(res);
    tirenv_profile_free(p);
    return code;
}
