/* Private to the study (src/study/study.c, findings.c): the facts the report's generated
 * paragraphs are made from. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_STUDY_IMPL_H
#define TIRENV_STUDY_IMPL_H

#include <stdio.h>

#include "tirenv/study.h"

/* The cam shape tirenv starts from (and ships as the default tire's) is TNO's MF-Swift
 * 205/60R15's, identified on steps up to its ELLIPS_MAX_STEP, 0.025 m, with
 * UNLOADED_RADIUS 0.3135 m: beyond that height, scaled by the radius, the shape is an
 * extrapolation. */
#define TIRENV_STUDY_CAM_MAX_STEP_OVER_R0 (0.025 / 0.3135)

typedef struct {
    const tirenv_dataset *ds;              /* the data set */
    const tirenv_compare_result *main;     /* every model on its validation cases */
    const tirenv_compare_settings *main_settings;
    const tirenv_nn_seeds *seeds;          /* the network over seeds (same cases) */
    const tirenv_fit_report *springs_fit, *cam_fit;
    double R0;                             /* the tire's free radius, m */
} tirenv_study__facts;

/* "## What the numbers say": each model's mean and worst error, where it is off, the
 * network over seeds, and whether the paper's case R finding reproduces, all from the
 * numbers. */
void tirenv_study__findings(FILE *fp, const tirenv_study__facts *f);

/* The cam's limits on this data set: cases peaking below H/2, cleats taller than the cam
 * shape's identified range, parameters the fit drove to a bound. */
void tirenv_study__cam_limits(FILE *fp, const tirenv_study__facts *f);

/* The fit's parameters as a Markdown table, a bound flagged in it. */
void tirenv_study__fit_table(FILE *fp, const tirenv_fit_report *fit);

#endif
