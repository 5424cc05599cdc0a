/* Private to tirenv ride: its options, and the runs they ask for.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CLI_RIDE_H
#define TIRENV_CLI_RIDE_H

#include "cli/cli.h"
#include "tirenv/comfort.h"
#include "tirenv/nn.h"
#include "tirenv/ride.h"

enum { RIDE_MAX_MODELS = 8 };

/* One column of the tables and plots: a model with one way of enveloping. */
typedef struct {
    size_t model;                    /* index into models */
    tirenv_ride_enveloping enveloping;
    char label[48];                  /* "cam", or "cam-dynamic" when several are asked */
} ride_column;

typedef struct {
    const char *vehicle_path;        /* --vehicle, or NULL for the default file */
    const char *sets[CLI_MAX_SETS];  /* --set KEY=VALUE on the vehicle */
    size_t n_sets;
    const char *nn_path;             /* --nn */
    int extrapolate;                 /* --extrapolate: the network outside its ranges */
    const char *out_path;            /* -o: the one run's series */
    const char *out_dir;             /* --out-dir */
    int series;                      /* --series: every run's series into out_dir */
    char speed_buf[256];
    const tirenv_model_type *models[RIDE_MAX_MODELS];
    size_t n_models;
    double speeds[TIRENV_RIDE_PLAN_RUNS];  /* m/s */
    size_t n_speeds;
    tirenv_ride_enveloping envelopings[TIRENV_RIDE_N_ENVELOPING];  /* --enveloping, in order */
    size_t n_envelopings;
    ride_column cols[RIDE_MAX_MODELS * TIRENV_RIDE_N_ENVELOPING];  /* models x envelopings */
    size_t n_cols;
    tirenv_ride_plan_params pp;      /* --x-from, --x-to, --dx, --dt, --solver over the
                                      * library's span and defaults */
    size_t jobs;                     /* --jobs: model inputs and runs at once */
} ride_options;

/* One run's figures. */
typedef struct {
    const char *model;
    const char *label;             /* its column's label */
    tirenv_ride_enveloping enveloping;
    double speed;                  /* m/s */
    double duration;               /* simulated time, s */
    double seconds;                /* CPU time of the model's inputs and the integration, s */
    tirenv_ride_comfort c;         /* what the driver feels (tirenv_ride_comfort_measure) */
} ride_result;

/* One run's samples and the weighted seat acceleration, kept for the plots. */
typedef struct {
    tirenv_ride_sample *samples;
    double *a_w;                   /* Wk-weighted seat_az, m/s^2 */
    size_t n;
} ride_series;

/* The load-to-contact-length relation the network file records (law->n = 0: none, said once
 * on standard error), which ride_cli_axle_model gives every network model it makes. Set
 * before the models are made; read-only while they are. */
void ride_cli_set_nn_law(const char *nn_path, const tirenv_contact_law *law);

/* A model of this type for one axle's tire into *m (free it, also on failure; NULL if not
 * made): a cam only with the tire's cam data, a type that needs a network with nn (x_N
 * referred to R0_nn, m; 0: the tire's), evaluated outside its trained ranges only if
 * extrapolate is set. */
int ride_cli_axle_model(const tirenv_model_type *type, const tirenv_tire *tire,
                        const tirenv_nn *nn, double R0_nn, int extrapolate, tirenv_model **m,
                        tirenv_diag *diag);

/* What one axle's tires follow on the grid x0 + k*dx (k < n), into w[]: the effective height
 * of a model of this type at the load of one tire (N), the same for every type (the point
 * contact: the profile itself). A type that needs a network gets nn (x_N referred to R0_nn,
 * m; 0: the tire's), evaluated outside its trained ranges only if extrapolate is set. The
 * model's warnings, if any, are copied into warnings (may be NULL). */
int ride_cli_axle_input(const tirenv_model_type *type, const tirenv_tire *tire, double load,
                        const tirenv_profile *p, const tirenv_nn *nn, double R0_nn,
                        int extrapolate, double x0,
                        double dx, size_t n, double w[], char *warnings, size_t warnings_size,
                        tirenv_diag *diag);

/* What one axle's tires follow at every load of tirenv_ride_table_loads
 * (tirenv_ride_table_build for a model of this type, extrapolate as ride_cli_axle_input's:
 * without it the rows the network refuses are left out), into *table (loads and heights
 * allocated: free table->load and table->w). Warnings as tirenv_ride_table_build's. */
int ride_cli_axle_table(const tirenv_model_type *type, const tirenv_tire *tire, double G0,
                        const tirenv_profile *p, const tirenv_nn *nn, double R0_nn,
                        int extrapolate, double x0, double dx, size_t n,
                        tirenv_ride_table *table, char *warnings, size_t warnings_size,
                        tirenv_diag *diag);

/* A speed V (m/s) as the ride names it in km/h (%g), in its series files
 * (series-MODEL-18kmh.csv) and its plots' panels: two speeds of one name are refused. */
void ride_cli_speed_name(double V, char *buf, size_t n);

/* Loads the vehicle, its tires and the obstacle, runs every model at every speed and writes
 * what the options ask for; returns an exit code after printing any error. */
int ride_cli_run(const cli_options *o, const ride_options *r);

/* Writes comfort.csv, comfort.md and the seat and spectrum plots into r->out_dir, for the
 * runs res[j*n_cols + c] (speed j, column c of r->cols) of the vehicle v (its k_t and c_t
 * set), given as the vehicle file and --set gave it (NAN: the tire file's), its axles' tire
 * files tire_path and static tire loads load (N); returns an exit code after printing any
 * error. */
int ride_cli_report(const ride_options *r, const ride_result res[], const ride_series series[],
                    const tirenv_vehicle *v, const tirenv_vehicle *given,
                    const char tire_path[2][1024], const double load[2]);

#endif
