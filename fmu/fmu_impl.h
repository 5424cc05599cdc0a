/* tirenv's FMI 2.0 co-simulation FMU: the effective road of a tire at a wheel-centre position
 * and load (fmu/README.md). What fmu.c, fmu_state.c, variables.c and describe.c share: the
 * instance, and the table of variables from which both the binary and its
 * modelDescription.xml are made. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_FMU_IMPL_H
#define TIRENV_FMU_IMPL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <tirenv/tirenv.h>

#include "fmi2.h"

#define FMU_MODEL_IDENTIFIER "tirenv_effective_road"
#define FMU_NAME_MAX 64     /* model name */
#define FMU_PATH_MAX 1024   /* tire_file, road_file, resources */

/* Where an instance is in the co-simulation state machine (FMI 2.0 section 4.2.4). */
typedef enum {
    FMU_INSTANTIATED,
    FMU_INITIALIZATION,
    FMU_STEP,
    FMU_TERMINATED,
    FMU_ERROR           /* a computation failed: only reset, state restore and free help */
} fmu_mode;

/* Everything an FMU state holds: the values of all variables, the time, and what the
 * library's model needs to be rebuilt exactly (see fmu_state.c). Plain data: copied and
 * serialized byte for byte. */
typedef struct {
    /* parameters */
    char model[FMU_NAME_MAX];
    char tire_file[FMU_PATH_MAX];
    char road_file[FMU_PATH_MAX];
    double track;           /* lateral position on the road, m */
    double width;           /* tire width, m */
    /* inputs */
    double x;               /* wheel-centre position along the road, m */
    double load;            /* vertical load, N */
    /* outputs */
    double h;               /* effective height z - z_flat, m */
    double slope;           /* effective slope tan(beta) */
    double terrain_height;  /* the effective road for a single-point-contact tire, m */
    double normal[3];       /* its unit normal (x forward, y left, z up) */
    double fx, fz;          /* hub forces, N */
    /* bookkeeping */
    double time;            /* current communication point, s */
    int evaluated;          /* outputs belong to (x, load) as evaluated last */
    double eval_x, eval_load;
    int model_set;          /* the model is set to the road at load_set */
    double load_set;        /* N */
} fmu_values;

/* One instance of the FMU. */
typedef struct {
    fmi2CallbackFunctions cb;
    char name[256];
    char resources[FMU_PATH_MAX];  /* the resources directory, a local path */
    int logging;
    fmu_mode mode;
    fmu_values v;
    /* The library's objects for the parameters in v (built on leaving initialization). */
    tirenv_tire tire;
    tirenv_profile *road;
    tirenv_model *m;
    int warned;  /* the model's warnings since its last set are logged (a cam's step) */
    double stop_time;  /* s: fmi2SetupExperiment's stop time, NAN where it defined none */
} fmu_instance;

/* ---- the variables (variables.c) ---- */
typedef enum { FMU_REAL, FMU_STRING } fmu_type;
typedef enum { FMU_PARAMETER, FMU_INPUT, FMU_OUTPUT } fmu_causality;

typedef struct {
    const char *name;
    fmi2ValueReference vr;
    fmu_type type;
    fmu_causality causality;
    const char *unit;         /* NULL: dimensionless */
    const char *description;
    size_t offset;            /* of the value in fmu_values */
    size_t size;              /* strings: its buffer's size */
} fmu_variable;

/* The table, n entries; the variable with value reference vr of type t, or NULL. */
const fmu_variable *fmu__variables(size_t *n);
const fmu_variable *fmu__variable_find(fmi2ValueReference vr, fmu_type t);
/* Start values of every variable. */
fmu_values fmu__start_values(void);
/* The GUID into guid (size bytes, 64 suffice): a hash of the table and the start values, so
 * that an FMU and a description made from different tables never match. Returns guid. */
char *fmu__guid(char *guid, size_t size);
/* Writes modelDescription.xml (describe.c's work) to fp; 0 on success. */
int fmu__describe(FILE *fp);

/* ---- shared by fmu.c and fmu_state.c ---- */
void fmu__log(fmu_instance *f, fmi2Status status, const char *category, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
/* Logs the message as an error (category logStatusError) and returns fmi2Error. */
fmi2Status fmu__fail(fmu_instance *f, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
fmi2Status fmu__fail_diag(fmu_instance *f, const char *what, const tirenv_diag *diag);
void *fmu__alloc(const fmu_instance *f, size_t size);
void fmu__free(const fmu_instance *f, void *p);
/* Frees the library's objects of an instance (the model, the road). */
void fmu__teardown(fmu_instance *f);
/* Builds them from the parameters in f->v (tire, road, model); fmi2OK or fmi2Error logged. */
fmi2Status fmu__setup(fmu_instance *f);
/* Sets the model to the road at load (the first time), or moves it to a new load
 * (tirenv_model_set_load); fmi2OK or fmi2Error logged. */
fmi2Status fmu__set_load(fmu_instance *f, double load);
/* Evaluates the model at f->v.x (after setting the load if it changed) into the outputs,
 * fmi2OK or fmi2Error logged. */
fmi2Status fmu__evaluate(fmu_instance *f);

#endif
