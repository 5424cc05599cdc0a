/* SPDX-License-Identifier: Apache-2.0 */
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
 * with R0 (m) as tirenv_rig_import does). A dir/source.txt that gives `cases` (see
 * tirenv_dataset_source_read, which reads it here too) makes a manifest with another number
 * of cases an error; without it, so does the `cases` (and `shard`) of a dir/sweep.txt that
 * tirenv sweep wrote, whose curves must then have the x_N grid's points (docs/formats.md
 * sections 9 and 13). Errors name file, line and column. */
int tirenv_dataset_read(const char *dir, double R0, tirenv_dataset *out, tirenv_diag *diag);
void tirenv_dataset_free(tirenv_dataset *ds);  /* NULL is a no-op */

/* One case of the embedded data set as designed: what the virtual rig is asked to run. */
typedef struct {
    const char *name;
    tirenv_split split;
    double contact_length;    /* m */
    double L, H;              /* obstacle length and height, m */
} tirenv_case_design;

/* The 28 cases of the embedded tractor data set (19 train, 5 control, 4 validation; the
 * paper's Table 3 cases F, J and R among the validation ones); *n receives the count
 * (n may be NULL). */
const tirenv_case_design *tirenv_dataset_design(size_t *n);

/* An embedded data set as designed (docs/models.md section 5.8): its cases, the model the
 * virtual rig runs to simulate them and the tire file it runs with. */
typedef struct {
    const char *name;         /* "14.9R28" (the tractor set, the default), "205-60R15" */
    const char *summary;      /* one line: the tire and the model */
    const char *model;        /* the simulating model's type name ("ring", "cam") */
    const char *tire_file;    /* its tire, relative to the data directory */
    const char *dir;          /* the shipped data set, relative to the data directory */
    const tirenv_case_design *cases;
    size_t n_cases;
    unsigned long seed;       /* case i's rig noise seed is seed + i */
} tirenv_design;

/* The embedded designs, NULL-terminated, the default (the tractor's) first. */
const tirenv_design *const *tirenv_designs(void);
/* The design of this name, or NULL. */
const tirenv_design *tirenv_design_find(const char *name);

/* How a data set is built. */
typedef struct {
    size_t jobs;              /* cases run at once, each on its own thread with its own model
                               * instance (default 1: no thread is started;
                               * tirenv/parallel.h); the bytes written are the same for every
                               * value */
    void (*progress)(void *ctx, size_t done, size_t total); /* after each case (calls never
                               * overlap, may come from any thread); may be NULL */
    void *progress_ctx;
} tirenv_dataset_build_settings;

tirenv_dataset_build_settings tirenv_dataset_build_default(void);

/* Builds a designed data set into dir (created if missing; written as a whole, see
 * tirenv_outdir): for each case a fresh instance of the design's model of `tire` is loaded to
 * the case's contact length, run over the cleat on the virtual rig (seeded), its log written
 * to dir/logs/<case>.csv, imported to dir/curves/<case>.csv; then dir/tire.tir (the tire as
 * simulated), dir/source.txt (what simulated the data, tirenv_dataset_source) and last the
 * manifest dir/cases.csv. Deterministic: the same design and tire give the same bytes,
 * whatever s->jobs. s NULL: the defaults. */
int tirenv_dataset_build_design(const char *dir, const tirenv_design *design,
                                const tirenv_tire *tire,
                                const tirenv_dataset_build_settings *s, tirenv_diag *diag);

/* tirenv_dataset_build_design with the default design (the tractor set, the ring). */
int tirenv_dataset_build(const char *dir, const tirenv_tire *tire,
                         const tirenv_dataset_build_settings *s, tirenv_diag *diag);

/* What a data set says about where its curves came from: dir/source.txt (docs/formats.md
 * section 9), written by tirenv dataset build, or, in a directory tirenv sweep wrote (no
 * source.txt, a sweep.txt: section 13), its sweep.txt. A data set with neither says nothing
 * (measured, or unknown). */
typedef struct {
    int present;              /* 1 if dir/source.txt exists */
    char design[64];          /* the design it was built from, or "" */
    char model[32];           /* the model that simulated it ("ring", "cam"), or "" */
    char tire[512];           /* the tire it was simulated with, full path, or "" */
    size_t cases;             /* the number of cases its manifest holds, or 0 if not given */
    size_t cases_line;        /* the line of source.txt that gives it, or 0 */
    /* From a sweep's sweep.txt: the model that simulated every case, whatever its type ("nn"
     * too), and the first tire key it set (`set KEY = ...`, with its line), or "" and 0.
     * With a physical model and no key set, model and tire above (the sweep's tire.tir) are
     * the data's source as a source.txt would give them; else they stay "": no one physical
     * model of one tire file simulated the cases (each case's key values: sweep.csv). */
    char sweep_model[32];
    char sweep_key[64];
    size_t sweep_key_line;
    int sweep_raw;            /* 1: the sweep's curves are its model's own (`curves = model`),
                               * not through the virtual rig: no noise, no import */
} tirenv_dataset_source;

/* Reads dir/source.txt into *out (present 0 if there is none), or without it dir/sweep.txt
 * (sweep_model "" if there is none either). Errors name file, line and key: an unknown key, a
 * model that is not a physical model type, a number of cases that is not a whole number from
 * 1 to 1,000,000, a malformed line. */
int tirenv_dataset_source_read(const char *dir, tirenv_dataset_source *out, tirenv_diag *diag);

/* The enveloping model's samples from a data set: one per curve point, inputs (x_N, l_c, H,
 * L), output h, one curve per case (out->n_curves, out->curve_start); cases of the given
 * split only. Allocates *x and *y (free them; *x also holds the curve offsets that
 * out->curve_start points to); TIRENV_EINVAL if a case has no curve. */
int tirenv_samples_from_dataset(const tirenv_dataset *ds, tirenv_split split,
                                tirenv_samples *out, double **x, double **y,
                                tirenv_diag *diag);

TIRENV_END_DECLS
#endif
