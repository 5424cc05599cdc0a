/* Private to the comparison (src/study/compare.c and report.c): what the tables and the
 * report share. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_STUDY_COMPARE_IMPL_H
#define TIRENV_STUDY_COMPARE_IMPL_H

#include <stddef.h>
#include <stdio.h>

#include "tirenv/outfile.h"
#include "tirenv/study.h"

/* Model j on the i-th compared case. */
const tirenv_compare_entry *tirenv_compare__entry(const tirenv_compare_result *r, size_t i,
                                                  size_t j);
/* "contact length 380 mm, obstacle 300 x 100 mm". */
void tirenv_compare__caption(const tirenv_case *c, char *buf, size_t size);
/* What model j is in the study ("physical model", "empirical model"...), or NULL. */
const char *tirenv_compare__label(const tirenv_compare_result *r, size_t j);
/* Numbers for people: m as mm ("12.34", "+1.20", "nan"), durations with a unit, ratios. */
void tirenv_compare__mm(char *buf, size_t size, double metres);
void tirenv_compare__signed_mm(char *buf, size_t size, double metres);
void tirenv_compare__duration(char *buf, size_t size, double seconds);
void tirenv_compare__ratio(char *buf, size_t size, double ratio);
/* A fraction as a percentage with one decimal ("1.2"), or "nan". */
void tirenv_compare__percent(char *buf, size_t size, double fraction);
/* Mean of RMS/H of model j over the cases it did not fail on; NaN if none. */
double tirenv_compare__mean_rms_over_H(const tirenv_dataset *ds, const tirenv_compare_result *r,
                                       size_t j);
/* Mean RMS error of model j over the cases it did not fail on (their count in *n_ok, if not
 * NULL), m; NaN if none. */
double tirenv_compare__mean_rms(const tirenv_compare_result *r, size_t j, size_t *n_ok);
/* The Markdown tables of errors.md (errors, mean RMS, timing) at heading level hashes. */
void tirenv_compare__tables(FILE *fp, const char *hashes, const tirenv_dataset *ds,
                            const tirenv_compare_settings *s, const tirenv_compare_result *r);
/* One line: the data set and, when so, that its curves are SIMULATED and by what. */
void tirenv_compare__data_note(FILE *fp, const tirenv_dataset *ds,
                               const tirenv_compare_settings *s);
/* dir/name as an all-or-nothing output file; close checks for write errors and commits. */
int tirenv_compare__open(tirenv_outfile **f, const char *dir, const char *name,
                         tirenv_diag *diag);
int tirenv_compare__close(tirenv_outfile *f, tirenv_diag *diag);

#endif
