/* tirenv: sweeps, data sets over a grid of cases (docs/formats.md section 13): rectangular
 * cleats (lengths x heights) x working regimes (contact lengths or loads) x values of tire
 * keys, each case a model's enveloping curve, directly or through the virtual rig, written in
 * the manifest format that tirenv_dataset_read (and so training and the study) reads.
 * A sweep is resumable (cases already written are kept), can be cut into shards run apart
 * (on the nodes of a cluster) and merged, and the result is the same bytes however it ran.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_SWEEP_H
#define TIRENV_SWEEP_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/dataset.h"
#include "tirenv/error.h"
#include "tirenv/model.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

struct tirenv_nn;  /* the network of the empirical model, tirenv/nn.h */

#define TIRENV_SWEEP_MAX_KEYS 8

/* One tire key swept over values (a numeric key of the .tir file, as --set takes it). */
typedef struct {
    const char *key;              /* e.g. "RADIAL_STIFFNESS" */
    size_t n;                     /* values (>= 1) */
    const double *values;         /* SI, borrowed */
} tirenv_sweep_axis;

/* The grid and how to run it. Case i of the grid, in this order (the last list fastest):
 *   tire-key values (axis 0 slowest), regime (contact length or load), length, height;
 * its name is "c" and i zero-padded to at least 4 digits (c0000, c0001, ...). */
typedef struct {
    const tirenv_model_type *type;/* the model that makes every curve (default ring) */
    const struct tirenv_nn *network; /* for a type that needs a network
                                   * (TIRENV_MODEL_NEEDS_NETWORK): the network every case's
                                   * model copies (tirenv_model_set_network); else NULL */
    double network_R0;            /* the radius its x_N refers to, m (0: the tire's) */
    const tirenv_contact_law *network_law; /* the relation between load and contact length
                                   * of the tire its data came from (its model file's record;
                                   * tirenv_model_set_contact_law), which turns a regime's load
                                   * and contact length into each other; NULL (default): the
                                   * tire's springs model stands in */
    const char *network_id;       /* how sweep.txt names that network (e.g. a fingerprint of
                                   * its file), so that a resumed run and a merge can tell */
    int extrapolate;              /* 1: the network may run outside its trained ranges
                                   * (tirenv_model_set_extrapolate); 0 (default): refused */
    int rig;                      /* 1: the model drives the virtual rig, whose noisy log is
                                   * imported (as tirenv_dataset_build does); 0 (default): the
                                   * model's curve at the points of the import's x_N grid */
    const double *lengths;        /* cleat lengths L, m */
    size_t n_lengths;
    const double *heights;        /* cleat heights H, m */
    size_t n_heights;
    const double *contact_lengths;/* working regimes as contact lengths, m ... */
    size_t n_contact_lengths;
    const double *loads;          /* ... or as loads, N: exactly one of the two lists */
    size_t n_loads;
    tirenv_sweep_axis keys[TIRENV_SWEEP_MAX_KEYS];
    size_t n_keys;
    tirenv_split split;           /* every case's split while both fractions are 0 (default
                                   * train) */
    double control_fraction;      /* else round(f * cases) cases each, chosen by a seeded */
    double validation_fraction;   /* permutation of the whole grid (default 0, 0) */
    unsigned long split_seed;     /* the permutation's seed (default 1) */
    unsigned long seed;           /* rig noise: case i runs with seed + i (default 1) */
    size_t shard, shards;         /* this part: the cases i with i mod shards == shard
                                   * (default 0 of 1: the whole grid) */
    size_t jobs;                  /* cases run at once, one thread and one model instance
                                   * each (default 1: no thread; tirenv/parallel.h) */
    void (*progress)(void *ctx, size_t done, size_t total); /* cases of this part written
                                   * (resumed ones first); never overlapping; may be NULL */
    void *progress_ctx;
} tirenv_sweep_settings;

tirenv_sweep_settings tirenv_sweep_default(void);

/* Checks the settings against the tire (every list non-empty, finite, positive, without
 * repeats; every key value accepted by tirenv_tir_set and the tire it makes by
 * tirenv_tire_check; fractions in [0, 1] summing to at most 1; shard < shards); errors name
 * the setting and the value. */
int tirenv_sweep_check(const tirenv_sweep_settings *s, const tirenv_tire *tire,
                       tirenv_diag *diag);

/* Cases in the whole grid (0 if a list is empty or the count overflows). */
size_t tirenv_sweep_count(const tirenv_sweep_settings *s);

/* What a run did. */
typedef struct {
    size_t cases;                 /* in the whole grid */
    size_t part_cases;            /* in this shard */
    size_t resumed;               /* written by an earlier, interrupted run, and kept */
    size_t run;                   /* computed by this run */
    int already_complete;         /* dir already held this very sweep, complete: nothing
                                   * was done */
} tirenv_sweep_report;

/* Runs the sweep (or its shard) into dir. The cases are written into "<dir>.partial" (made
 * if missing), each case's files atomically, and the manifest last; then that directory is
 * renamed to dir, so dir appears whole or not at all. A run that finds "<dir>.partial" of
 * the same sweep (its sweep.txt and tire.tir) keeps the cases it holds and runs the others;
 * of another sweep, it refuses. dir itself must not exist, be empty, or already hold this
 * sweep complete (then nothing is done). Two runs on the same directory at once are refused
 * (a lock on "<dir>.partial"). The bytes written depend on the settings and the tire alone,
 * not on s->jobs, nor on interruptions. report may be NULL. */
int tirenv_sweep_run(const char *dir, const tirenv_tire *tire, const tirenv_sweep_settings *s,
                     tirenv_sweep_report *report, tirenv_diag *diag);

/* Merges the n complete shards parts[] of one sweep (the same sweep.txt apart from the shard,
 * every shard 0 .. N-1 exactly once) into dir, which then holds the bytes the whole sweep run
 * as one part would have written. Case files are hard-linked where the file system allows
 * (else copied). dir (absent, empty, or this sweep already merged: then nothing is done) is
 * written as a whole, like every output directory (tirenv_outdir, tirenv/outfile.h): a failed
 * or killed merge leaves it as it was. */
int tirenv_sweep_merge(const char *dir, size_t n, const char *const parts[],
                       tirenv_diag *diag);

TIRENV_END_DECLS
#endif
