/* tirenv: data sets of enveloping curves: a directory with a manifest cases.csv
 * (case,split,contact_length_m,load_N,obstacle_length_m,obstacle_height_m,log,curve). */
#ifndef TIRENV_DATASET_H
#define TIRENV_DATASET_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/curve.h"
#include "tirenv/error.h"
#include "tirenv/profile.h"
#include "tirenv/tire.h"
#include "tirenv/train.h"

TIRENV_BEGIN_DECLS

/* A case's split (tirenv_split, train.h) by its manifest name: */
/* "train", "control", "validation". */
const char *tirenv_split_name(tirenv_split split);

typedef struct {
    char name[32];            /* case label, e.g. "F" */
    tirenv_split split;
    double contact_length;    /* measured l_c, m */
    double load;              /* applied vertical load, N */
    double L, H;              /* obstacle length and height, m */
    char log[512];            /* raw rig log, full path, or "" */
    char curve_path[512];     /* imported curve, full path, or "" */
    tirenv_curve curve;       /* the approach-half curve (read, or imported from the log) */
    const tirenv_profile *profile; /* the obstacle if it is not the cleat L x H (borrowed;
                                    * L, H then give its extent for x_N and the network) */
} tirenv_case;

typedef struct {
    char dir[512];
    size_t n;
    tirenv_case *cases;
} tirenv_dataset;

/* Reads dir/cases.csv and each case's curve (the curve file if given, else the log imported
 * with R0 (m) as tirenv_rig_import does). Errors name file, line and column. */
int tirenv_dataset_read(const char *dir, double R0, tirenv_dataset *out, tirenv_diag *diag);
void tirenv_dataset_free(tirenv_dataset *ds);  /* NULL is a no-op */

/* One case of the embedded data set as designed: what the virtual rig is asked to run. */
typedef struct {
    const char *name;
    tirenv_split split;
    double contact_length;    /* m */
    double L, H;              /* obstacle length and height, m */
} tirenv_case_design;

/* The 28 cases of the embedded data set (19 train, 5 control, 4 validation; the paper's
 * Table 3 cases F, J and R among the validation ones); *n receives the count. */
const tirenv_case_design *tirenv_dataset_design(size_t *n);

/* How tirenv_dataset_build runs. */
typedef struct {
    size_t jobs;              /* cases run at once, each on its own thread with its own ring
                               * (default 1: no thread is started; tirenv/parallel.h); the
                               * bytes written are the same for every value */
    void (*progress)(void *ctx, size_t done, size_t total); /* after each case (calls never
                               * overlap, may come from any thread); may be NULL */
    void *progress_ctx;
} tirenv_dataset_build_settings;

tirenv_dataset_build_settings tirenv_dataset_build_default(void);

/* Builds the embedded data set into dir (created if missing): for each designed case the ring
 * reference tire of `tire` is loaded to the designed contact length, run over the cleat on the
 * virtual rig (seeded), its log written to dir/logs/<case>.csv, imported to dir/curves/<case>.csv,
 * and the manifest dir/cases.csv written last. Deterministic: the same tire gives the same
 * bytes, whatever s->jobs. s NULL: the defaults. */
int tirenv_dataset_build(const char *dir, const tirenv_tire *tire,
                         const tirenv_dataset_build_settings *s, tirenv_diag *diag);

/* The enveloping model's samples from a data set: one per curve point, inputs (x_N, l_c, H,
 * L), output h, one curve per case (out->n_curves, out->curve_start); cases of the given
 * split only. Allocates *x and *y (free them; *x also holds the curve offsets that
 * out->curve_start points to); TIRENV_EINVAL if a case has no curve. */
int tirenv_samples_from_dataset(const tirenv_dataset *ds, tirenv_split split,
                                tirenv_samples *out, double **x, double **y,
                                tirenv_diag *diag);

TIRENV_END_DECLS
#endif
