/* SPDX-License-Identifier: Apache-2.0 */
/* The embedded data sets (docs/models.md section 5.8): 28 cleat runs each on the virtual rig,
 * shaped like the paper's (Table 2: 28 obstacles, 19 train / 5 control / 4 validation;
 * Table 3): the tractor's, by the ring reference tire, and the 205/60R15 car tire's, by TNO's
 * MF-Swift cam of that tire. */
#include "tirenv/dataset.h"

#include <stdio.h>
#include <string.h>
#include "tirenv/outfile.h"
#include "tirenv/parallel.h"
#include "tirenv/rig.h"
#include "tirenv/tir.h"
#include "io/io.h"

/* Obstacle lengths 0.05 to 0.30 m, heights 0.025 to 0.10 m, contact lengths 0.28 to 0.43 m,
 * spread so that every value of each appears in training, and the validation cases are the
 * paper's F, J, R plus one case (AB) inside the training ranges. Fixed: changing it changes the
 * data set. */
static const tirenv_case_design tractor[] = {
    {"A", TIRENV_SPLIT_TRAIN, 0.28, 0.05, 0.025},
    {"B", TIRENV_SPLIT_TRAIN, 0.28, 0.15, 0.050},
    {"C", TIRENV_SPLIT_TRAIN, 0.28, 0.20, 0.100},
    {"D", TIRENV_SPLIT_TRAIN, 0.28, 0.30, 0.075},
    {"E", TIRENV_SPLIT_CONTROL, 0.28, 0.30, 0.025},
    {"F", TIRENV_SPLIT_VALIDATION, 0.38, 0.30, 0.100},
    {"G", TIRENV_SPLIT_TRAIN, 0.33, 0.05, 0.050},
    {"H", TIRENV_SPLIT_TRAIN, 0.33, 0.10, 0.075},
    {"I", TIRENV_SPLIT_TRAIN, 0.33, 0.15, 0.100},
    {"J", TIRENV_SPLIT_VALIDATION, 0.33, 0.30, 0.050},
    {"K", TIRENV_SPLIT_TRAIN, 0.33, 0.20, 0.025},
    {"L", TIRENV_SPLIT_CONTROL, 0.33, 0.10, 0.025},
    {"M", TIRENV_SPLIT_TRAIN, 0.38, 0.05, 0.075},
    {"N", TIRENV_SPLIT_TRAIN, 0.38, 0.10, 0.050},
    {"O", TIRENV_SPLIT_TRAIN, 0.38, 0.15, 0.025},
    {"P", TIRENV_SPLIT_TRAIN, 0.38, 0.20, 0.075},
    {"Q", TIRENV_SPLIT_CONTROL, 0.38, 0.05, 0.100},
    {"R", TIRENV_SPLIT_VALIDATION, 0.28, 0.10, 0.100},
    {"S", TIRENV_SPLIT_TRAIN, 0.43, 0.05, 0.100},
    {"T", TIRENV_SPLIT_TRAIN, 0.43, 0.10, 0.025},
    {"U", TIRENV_SPLIT_TRAIN, 0.43, 0.15, 0.075},
    {"V", TIRENV_SPLIT_TRAIN, 0.43, 0.20, 0.050},
    {"W", TIRENV_SPLIT_TRAIN, 0.43, 0.30, 0.100},
    {"X", TIRENV_SPLIT_CONTROL, 0.43, 0.30, 0.050},
    {"Y", TIRENV_SPLIT_TRAIN, 0.28, 0.10, 0.050},
    {"Z", TIRENV_SPLIT_TRAIN, 0.33, 0.30, 0.100},
    {"AA", TIRENV_SPLIT_CONTROL, 0.38, 0.20, 0.100},
    {"AB", TIRENV_SPLIT_VALIDATION, 0.43, 0.15, 0.050},
};

/* The 205/60R15 set: the tractor's design shape on a car tire. Heights 0.010 to 0.025 m: no
 * higher than ELLIPS_MAX_STEP, 0.025 m, the largest step TNO identified the cam on (the
 * tire file says so); lengths 0.01 to 0.10 m, the tractor's 0.05 to 0.30 m against its
 * 0.28-0.43 m patch scaled to the car's 0.11-0.15 m one; contact lengths 0.11, 0.13 and
 * 0.15 m, which the cam's contact law (Q_RA1, Q_RA2, VERTICAL_STIFFNESS) gives at 2.97, 3.93
 * and 4.96 kN, about 0.75, 1 and 1.25 times the file's nominal load FNOMIN = 4 kN. Case by
 * case the tractor's: each length, height and contact length mapped in order onto the car's
 * (the tractor's 0.43 m cases spread over the three), so every value of each factor is in
 * training and the validation cases F, J, R and AB lie inside the training ranges, R the
 * short tall cleat at the lightest load as in the paper. */
static const tirenv_case_design car_205[] = {
    {"A", TIRENV_SPLIT_TRAIN, 0.11, 0.01, 0.010},
    {"B", TIRENV_SPLIT_TRAIN, 0.11, 0.04, 0.015},
    {"C", TIRENV_SPLIT_TRAIN, 0.11, 0.06, 0.025},
    {"D", TIRENV_SPLIT_TRAIN, 0.11, 0.10, 0.020},
    {"E", TIRENV_SPLIT_CONTROL, 0.11, 0.10, 0.010},
    {"F", TIRENV_SPLIT_VALIDATION, 0.15, 0.10, 0.025},
    {"G", TIRENV_SPLIT_TRAIN, 0.13, 0.01, 0.015},
    {"H", TIRENV_SPLIT_TRAIN, 0.13, 0.02, 0.020},
    {"I", TIRENV_SPLIT_TRAIN, 0.13, 0.04, 0.025},
    {"J", TIRENV_SPLIT_VALIDATION, 0.13, 0.10, 0.015},
    {"K", TIRENV_SPLIT_TRAIN, 0.13, 0.06, 0.010},
    {"L", TIRENV_SPLIT_CONTROL, 0.13, 0.02, 0.010},
    {"M", TIRENV_SPLIT_TRAIN, 0.15, 0.01, 0.020},
    {"N", TIRENV_SPLIT_TRAIN, 0.15, 0.02, 0.015},
    {"O", TIRENV_SPLIT_TRAIN, 0.15, 0.04, 0.010},
    {"P", TIRENV_SPLIT_TRAIN, 0.15, 0.06, 0.020},
    {"Q", TIRENV_SPLIT_CONTROL, 0.15, 0.01, 0.025},
    {"R", TIRENV_SPLIT_VALIDATION, 0.11, 0.02, 0.025},
    {"S", TIRENV_SPLIT_TRAIN, 0.11, 0.01, 0.025},
    {"T", TIRENV_SPLIT_TRAIN, 0.15, 0.02, 0.010},
    {"U", TIRENV_SPLIT_TRAIN, 0.11, 0.04, 0.020},
    {"V", TIRENV_SPLIT_TRAIN, 0.13, 0.06, 0.015},
    {"W", TIRENV_SPLIT_TRAIN, 0.11, 0.10, 0.025},
    {"X", TIRENV_SPLIT_CONTROL, 0.15, 0.10, 0.015},
    {"Y", TIRENV_SPLIT_TRAIN, 0.11, 0.02, 0.015},
    {"Z", TIRENV_SPLIT_TRAIN, 0.13, 0.10, 0.025},
    {"AA", TIRENV_SPLIT_CONTROL, 0.15, 0.06, 0.025},
    {"AB", TIRENV_SPLIT_VALIDATION, 0.13, 0.04, 0.015},
};

#define N_OF(a) (sizeof(a) / sizeof(a)[0])

/* A design and how its files name what simulated them (the tractor's words are those its
 * shipped files have always had). */
typedef struct {
    tirenv_design d;
    const char *rig_note;     /* in each log's and curve's first comment line */
    const char *made_by;      /* in the manifest's */
} design_record;

static const design_record records[] = {
    {{.name = "14.9R28",
      .summary = "a 14.9R28 tractor tire, simulated by tirenv's flexible-ring reference tire",
      .model = "ring",
      .tire_file = "tires/default.tir",
      .dir = "dataset",
      .cases = tractor,
      .n_cases = N_OF(tractor),
      .seed = 20261123},
     "flexible-ring reference tire",
     "tirenv's flexible-ring reference tire"},
    {{.name = "205-60R15",
      .summary = "a 205/60R15 car tire, simulated by TNO's MF-Swift tandem cam of it",
      .model = "cam",
      .tire_file = "tires/205-60R15-mfswift.tir",
      .dir = "dataset-205-60R15",
      .cases = car_205,
      .n_cases = N_OF(car_205),
      .seed = 20261205},
     "MF-Swift tandem cam of the 205/60R15 car tire",
     "TNO's MF-Swift tandem cam of the 205/60R15 car tire"},
};

static const tirenv_design *const designs[] = {&records[0].d, &records[1].d, NULL};

const tirenv_design *const *tirenv_designs(void)
{
    return designs;
}

const tirenv_design *tirenv_design_find(const char *name)
{
    for (size_t k = 0; name && designs[k]; ++k)
        if (strcmp(designs[k]->name, name) == 0)
            return designs[k];
    return NULL;
}

static const design_record *record_of(const tirenv_design *d)
{
    for (size_t k = 0; k < N_OF(records); ++k)
        if (d == &records[k].d)
            return &records[k];
    return NULL;
}

const tirenv_case_design *tirenv_dataset_design(size_t *n)
{
    if (n)  /* NULL: the caller wants the cases alone (it was written unchecked) */
        *n = N_OF(tractor);
    return tractor;
}

/* One case: load the model to the contact length, run the rig, write the log, import it.
 * The model is the case's own (a fresh instance), so that the case's bytes depend on the case
 * alone, whichever thread runs it and whatever ran before. */
static int build_case(const char *dir, const design_record *r, size_t i,
                      const tirenv_model_type *type, const tirenv_tire *tire, double *load,
                      tirenv_diag *diag)
{
    const tirenv_design *d = &r->d;
    const tirenv_case_design *c = &d->cases[i];
    tirenv_model *m = tirenv_model_alloc(type, tire);
    if (!m)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tire",
                            "the %s model cannot be built from these parameters", d->model);
    int status = tirenv_model_load_for_contact_length(m, c->contact_length, load, diag);
    tirenv_profile *cleat = tirenv_profile_cleat(c->L, c->H);
    if (!cleat) {
        tirenv_model_free(m);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    if (!status)
        status = tirenv_model_set(m, cleat, *load, diag);
    /* Each run has its own noise and its own rig zero, as separate runs of a real rig do. */
    tirenv_rig_settings rig = tirenv_rig_default();
    rig.seed = d->seed + i;
    rig.x_offset = 1.5 + 0.1 * (double)i;
    rig.z_offset = 0.35 + 0.01 * (double)i;
    tirenv_rig_log log = {0};
    if (!status)
        status = tirenv_rig_simulate(m, cleat, &rig, &log, diag);
    char path[1024], comment[1024];
    snprintf(path, sizeof path, "%s/logs/%s.csv", dir, c->name);
    snprintf(comment, sizeof comment,
             "SIMULATED rig data (tirenv virtual rig, %s), not a measurement.\ncase %s: "
             "contact length %.2f m, load %.2f N, cleat %.3f x %.3f m; speed %g m/s, %g Hz, "
             "noise sigma x %g m, z %g m, seed %lu",
             r->rig_note, c->name, c->contact_length, *load, c->L, c->H, rig.speed, rig.rate,
             rig.noise_x, rig.noise_z, rig.seed);
    if (!status)
        status = tirenv_rig_write_log(path, &log, comment, diag);
    tirenv_import_settings imp = tirenv_import_default();
    imp.L = c->L;
    imp.H = c->H;
    imp.R0 = tirenv_model_tire(m)->springs.R0;
    imp.contact_length = c->contact_length;
    tirenv_curve curve = {0};
    if (!status)
        status = tirenv_rig_import_samples(log.n, log.t, log.x, log.z, &imp, &curve, diag);
    snprintf(path, sizeof path, "%s/curves/%s.csv", dir, c->name);
    if (!status)
        status = tirenv_curve_write_csv(path, &curve, comment, diag);
    tirenv_curve_free(&curve);
    tirenv_rig_log_free(&log);
    tirenv_profile_free(cleat);
    tirenv_model_free(m);
    return status;
}

tirenv_dataset_build_settings tirenv_dataset_build_default(void)
{
    TIRENV_NUMERIC_C();
    return (tirenv_dataset_build_settings){.jobs = 1, .progress = NULL, .progress_ctx = NULL};
}

/* What the parallel loop's items share: read-only but for load, each item its own slot. */
typedef struct {
    const char *dir;
    const design_record *r;
    const tirenv_model_type *type;
    const tirenv_tire *tire;
    const tirenv_dataset_build_settings *s;
    double *load;             /* N, by case */
} build_ctx;

static int build_item(void *ctx, size_t i, size_t worker, tirenv_diag *diag)
{
    const build_ctx *b = ctx;
    (void)worker;
    return build_case(b->dir, b->r, i, b->type, b->tire, &b->load[i], diag);
}

static void build_done(void *ctx, size_t i, size_t n_done)
{
    const build_ctx *b = ctx;
    (void)i;
    if (b->s->progress)
        b->s->progress(b->s->progress_ctx, n_done, b->r->d.n_cases);
}

/* source.txt (docs/formats.md section 9): what a study needs to know about the data, and how
 * many cases the manifest holds, so that a manifest cut at a line end is refused. */
static int write_source(const char *dir, const tirenv_design *d, const char *note,
                        tirenv_diag *diag)
{
    char path[1024];
    tirenv_outfile *f;
    snprintf(path, sizeof path, "%s/source.txt", dir);
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    tirenv_outfile_comment(f, note);
    fprintf(tirenv_outfile_stream(f),
            "format = tirenv-dataset 1\ndesign = %s\nmodel = %s\ntire = tire.tir\ncases = %zu\n",
            d->name, d->model, d->n_cases);
    return tirenv_outfile_commit(f, diag);
}

/* The data set of design d (whose record r and model type are known good) into dir. */
static int build_into(const char *dir, const tirenv_design *d, const design_record *r,
                      const tirenv_model_type *type, const tirenv_tire *tire,
                      const tirenv_dataset_build_settings *s, tirenv_diag *diag)
{
    double load[N_OF(car_205) > N_OF(tractor) ? N_OF(car_205) : N_OF(tractor)];
    if (d->n_cases > N_OF(load))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "design",
                            "%zu cases; at most %zu", d->n_cases, N_OF(load));
    char path[1024];
    int status = tirenv_mkdir_p(dir, diag);
    snprintf(path, sizeof path, "%s/logs", dir);
    if (!status)
        status = tirenv_mkdir_p(path, diag);
    snprintf(path, sizeof path, "%s/curves", dir);
    if (!status)
        status = tirenv_mkdir_p(path, diag);
    if (status)
        return status;
    build_ctx b = {.dir = dir, .r = r, .type = type, .tire = tire, .s = s, .load = load};
    status = tirenv_parallel_for(d->n_cases, s->jobs, build_item, build_done, &b, diag);
    char note[512];
    snprintf(note, sizeof note, "SIMULATED data set: %s, on the virtual rig; not measurements "
                                "of a real tire.\nWritten by: tirenv dataset build%s%s",
             d->summary, d == designs[0] ? "" : " --design ", d == designs[0] ? "" : d->name);
    snprintf(path, sizeof path, "%s/tire.tir", dir);
    if (!status)
        status = tirenv_tir_write_noted(path, tire, note, diag);
    if (!status)
        status = write_source(dir, d, note, diag);
    if (status)
        return status;
    /* The manifest last: a data set with a manifest is a whole one. */
    tirenv_outfile *f;
    snprintf(path, sizeof path, "%s/cases.csv", dir);
    if ((status = tirenv_outfile_open(&f, path, diag)))
        return status;
    char comment[512];
    snprintf(comment, sizeof comment,
             "SIMULATED data set: %zu cleat runs of %s on the virtual rig,\nnot measurements of "
             "a real tire. Regenerate with: tirenv dataset build%s%s",
             d->n_cases, r->made_by, d == designs[0] ? "" : " --design ",
             d == designs[0] ? "" : d->name);
    FILE *fp = tirenv_outfile_stream(f);
    fputs("case,split,contact_length_m,load_N,obstacle_length_m,obstacle_height_m,log,curve\n",
          fp);
    tirenv_outfile_comment(f, comment);
    for (size_t i = 0; i < d->n_cases; ++i) {
        const tirenv_case_design *c = &d->cases[i];
        fprintf(fp, "%s,%s,%.2f,%.2f,%.3f,%.3f,logs/%s.csv,curves/%s.csv\n", c->name,
                tirenv_split_name(c->split), c->contact_length, load[i], c->L, c->H, c->name,
                c->name);
    }
    return tirenv_outfile_commit(f, diag);
}

/* The data set is written as a whole (tirenv_outdir): a failed or killed build leaves the
 * previous one as it was. */
int tirenv_dataset_build_design(const char *dir, const tirenv_design *d,
                                const tirenv_tire *tire,
                                const tirenv_dataset_build_settings *settings,
                                tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    const tirenv_dataset_build_settings defaults = tirenv_dataset_build_default();
    const tirenv_dataset_build_settings *s = settings ? settings : &defaults;
    const design_record *r = d ? record_of(d) : NULL;
    const tirenv_model_type *type = r ? tirenv_model_type_find(d->model) : NULL;
    if (!type)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "design",
                            "not one of the designs of tirenv_designs()");
    if (type == tirenv_model_cam && tirenv_tire_check_cam_keys(tire, diag))
        return TIRENV_EINVAL;
    tirenv_outdir *out;
    int status = tirenv_outdir_begin(dir, &out, diag);
    if (status)
        return status;
    status = build_into(tirenv_outdir_path(out), d, r, type, tire, s, diag);
    if (status) {
        tirenv_outdir_abort(out);
        return status;
    }
    return tirenv_outdir_commit(out, diag);
}

int tirenv_dataset_build(const char *dir, const tirenv_tire *tire,
                         const tirenv_dataset_build_settings *s, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_dataset_build_design(dir, designs[0], tire, s, diag);
}
