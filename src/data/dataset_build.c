/* The embedded data set: 28 cleat runs of the ring reference tire on the virtual rig, shaped
 * like the paper's (Table 2: 28 obstacles, 19 train / 5 control / 4 validation; Table 3). */
#include "tirenv/dataset.h"

#include <stdio.h>
#include <string.h>
#include "tirenv/io.h"
#include "tirenv/parallel.h"
#include "tirenv/rig.h"

/* Obstacle lengths 0.05 to 0.30 m, heights 0.025 to 0.10 m, contact lengths 0.28 to 0.43 m,
 * spread so that every value of each appears in training, and the validation cases are the
 * paper's F, J, R plus one case (AB) inside the training ranges. Fixed: changing it changes the
 * data set. */
static const tirenv_case_design design[] = {
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

const tirenv_case_design *tirenv_dataset_design(size_t *n)
{
    *n = sizeof design / sizeof design[0];
    return design;
}


/* One case: load the ring to the contact length, run the rig, write the log, import it.
 * The ring is the case's own (a fresh instance), so that the case's bytes depend on the case
 * alone, whichever thread runs it and whatever ran before. */
static int build_case(const char *dir, size_t i, const tirenv_tire *tire, double *load,
                      tirenv_diag *diag)
{
    const tirenv_case_design *c = &design[i];
    tirenv_model *ring = tirenv_model_alloc(tirenv_model_ring, tire);
    if (!ring)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "tire",
                            "the ring reference tire cannot be built from these parameters");
    int status = tirenv_model_load_for_contact_length(ring, c->contact_length, load, diag);
    tirenv_profile *cleat = tirenv_profile_cleat(c->L, c->H);
    if (!cleat) {
        tirenv_model_free(ring);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    if (!status)
        status = tirenv_model_set(ring, cleat, *load, diag);
    /* Each run has its own noise and its own rig zero, as separate runs of a real rig do. */
    tirenv_rig_settings rig = tirenv_rig_default();
    rig.seed = 20261123 + i;
    rig.x_offset = 1.5 + 0.1 * (double)i;
    rig.z_offset = 0.35 + 0.01 * (double)i;
    tirenv_rig_log log = {0};
    if (!status)
        status = tirenv_rig_simulate(ring, cleat, &rig, &log, diag);
    char path[1024], comment[1024];
    snprintf(path, sizeof path, "%s/logs/%s.csv", dir, c->name);
    snprintf(comment, sizeof comment,
             "SIMULATED rig data (tirenv virtual rig, flexible-ring reference tire), not a "
             "measurement.\ncase %s: contact length %.2f m, load %.2f N, cleat %.3f x %.3f m; "
             "speed %g m/s, %g Hz, noise sigma x %g m, z %g m, seed %lu",
             c->name, c->contact_length, *load, c->L, c->H, rig.speed, rig.rate, rig.noise_x,
             rig.noise_z, rig.seed);
    if (!status)
        status = tirenv_rig_write_log(path, &log, comment, diag);
    tirenv_import_settings imp = tirenv_import_default();
    imp.L = c->L;
    imp.H = c->H;
    imp.R0 = tire->springs.R0;
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
    tirenv_model_free(ring);
    return status;
}

tirenv_dataset_build_settings tirenv_dataset_build_default(void)
{
    return (tirenv_dataset_build_settings){.jobs = 1, .progress = NULL, .progress_ctx = NULL};
}

typedef struct {
    const char *dir;
    const tirenv_tire *tire;
    const tirenv_dataset_build_settings *s;
    double load[sizeof design / sizeof design[0]];  /* N, by case */
} build_ctx;

static int build_item(void *ctx, size_t i, size_t worker, tirenv_diag *diag)
{
    build_ctx *b = ctx;
    (void)worker;
    return build_case(b->dir, i, b->tire, &b->load[i], diag);
}

static void build_done(void *ctx, size_t i, size_t n_done)
{
    const build_ctx *b = ctx;
    (void)i;
    if (b->s->progress)
        b->s->progress(b->s->progress_ctx, n_done, sizeof design / sizeof design[0]);
}

int tirenv_dataset_build(const char *dir, const tirenv_tire *tire,
                         const tirenv_dataset_build_settings *settings, tirenv_diag *diag)
{
    const tirenv_dataset_build_settings defaults = tirenv_dataset_build_default();
    const tirenv_dataset_build_settings *s = settings ? settings : &defaults;
    const size_t n = sizeof design / sizeof design[0];
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
    build_ctx b = {.dir = dir, .tire = tire, .s = s};
    if ((status = tirenv_parallel_for(n, s->jobs, build_item, build_done, &b, diag)))
        return status;
    const double *load = b.load;
    /* The manifest last: a data set with a manifest is a whole one. */
    tirenv_outfile f;
    snprintf(path, sizeof path, "%s/cases.csv", dir);
    if ((status = tirenv_outfile_open(&f, path, diag)))
        return status;
    tirenv_outfile_comment(&f, "SIMULATED data set: 28 cleat runs of tirenv's flexible-ring "
                               "reference tire on the virtual rig,\nnot measurements of a real "
                               "tire. Regenerate with: tirenv dataset build");
    fputs("case,split,contact_length_m,load_N,obstacle_length_m,obstacle_height_m,log,curve\n",
          f.fp);
    for (size_t i = 0; i < n; ++i)
        fprintf(f.fp, "%s,%s,%.2f,%.2f,%.3f,%.3f,logs/%s.csv,curves/%s.csv\n", design[i].name,
                tirenv_split_name(design[i].split), design[i].contact_length, load[i],
                design[i].L, design[i].H, design[i].name, design[i].name);
    return tirenv_outfile_commit(&f, diag);
}
