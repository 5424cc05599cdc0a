/* tirenv: ride simulation of a pitch-plane tractor driven by each axle's effective profile
 * (docs/models.md section 9). SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_RIDE_H
#define TIRENV_RIDE_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/comfort.h"
#include "tirenv/error.h"
#include "tirenv/model.h"
#include "tirenv/profile.h"
#include "tirenv/vehicle.h"

TIRENV_BEGIN_DECLS

/* What an axle's tires follow: heights w (m) on a uniform grid x_k = x0 + k*dx, joined by
 * Steffen's interpolation (1990), which is monotone between samples (no overshoot at a cleat's
 * edges) and has a continuous slope (the tire damper's force c*dw/dt stays continuous, so
 * the integrator keeps its order). Outside the grid the end values continue flat. */
typedef struct {
    double x0;             /* first grid position, m */
    double dx;             /* grid spacing, m */
    size_t n;              /* grid points, >= 2 */
    const double *w;       /* heights, m (borrowed) */
} tirenv_ride_track;

typedef enum {
    TIRENV_RIDE_RK4,       /* classical Runge-Kutta at the fixed step dt (default) */
    TIRENV_RIDE_RK8PD      /* Prince-Dormand RK8(7)13M, adaptive, to rel/abs tolerance tol */
} tirenv_ride_method;

typedef struct {
    double speed;          /* forward speed V, m/s (> 0) */
    double x_front0;       /* front-axle position at t = 0, m; the rear axle is a wheelbase
                            * behind */
    double duration;       /* simulated time, s */
    double dt;             /* output interval, s; RK4 steps dt, split into substeps that
                            * advance at most half an input grid spacing (so no edge of a
                            * cleat falls between its samples) */
    tirenv_ride_method method;
    double tol;            /* RK8PD: error tolerance per step (absolute and relative) */
} tirenv_ride_settings;

/* Defaults: 1 m/s, from x = 0, 10 s, dt 1 ms, RK4, tol 1e-10. */
tirenv_ride_settings tirenv_ride_default(void);

/* The integrators' names, as tirenv ride --solver and the Python module take them: "rk4",
 * "rk8pd". _name gives "unknown" for a value out of range; _parse puts the method named into
 * *m, or returns TIRENV_EINVAL (field "method") listing the names. */
const char *tirenv_ride_method_name(tirenv_ride_method m);
int tirenv_ride_method_parse(const char *name, tirenv_ride_method *m, tirenv_diag *diag);

/* How each axle's input follows the load its tires carry (docs/models.md section 9.5). */
typedef enum {
    TIRENV_RIDE_STATIC = 0, /* the effective road at the axle's static tire load
                             * (tirenv_ride_effective, tirenv_ride_run) */
    TIRENV_RIDE_DYNAMIC,    /* tables over loads, at the load the tires carry
                             * (tirenv_ride_table_build, tirenv_ride_run_dynamic) */
    TIRENV_RIDE_DIRECT,     /* the model evaluated during the integration at that load
                             * (tirenv_ride_direct_input, tirenv_ride_run_input): slow, the
                             * reference the tables are checked against */
    TIRENV_RIDE_N_ENVELOPING
} tirenv_ride_enveloping;

/* The way of enveloping when none is asked: dynamic, since the load of a tire swings by tens
 * of per cent over a cleat and to nothing when it lifts off; static is the paper's
 * constant-load curve. */
#define TIRENV_RIDE_ENVELOPING_DEFAULT TIRENV_RIDE_DYNAMIC

/* "static", "dynamic", "direct": the names tirenv ride --enveloping and the Python module
 * take, and the ones its tables, labels and file names print. _name gives "unknown" out of
 * range; _parse puts the way named into *e, or returns TIRENV_EINVAL (field "enveloping"). */
const char *tirenv_ride_enveloping_name(tirenv_ride_enveloping e);
int tirenv_ride_enveloping_parse(const char *name, tirenv_ride_enveloping *e,
                                 tirenv_diag *diag);

/* A forward speed from text into *v (m/s): "2.5" or "2.5m/s" in m/s, "10km/h" in km/h (times
 * 1/3.6), as tirenv ride --speed takes it. TIRENV_EINVAL (field "speed") unless the number is
 * all of the text before the suffix, finite and > 0. */
int tirenv_ride_speed_parse(const char *text, double *v, tirenv_diag *diag);

/* Where a run drives over ground, and the grid of the axles' inputs (tirenv_ride_track,
 * tirenv_ride_table) that covers it (docs/models.md section 9.4). */
typedef struct {
    double run_in;         /* the front axle starts this far before the first vertex, m */
    double settle_min;     /* the run ends once the rear axle is max(settle_min, */
    double settle_time;    /* settle_time*V) past the last vertex: m, s */
    double grid_margin;    /* the grid reaches this far beyond both axles' travel, m */
    double dx;             /* grid spacing, m */
} tirenv_ride_span;

/* tirenv ride's: run-in 1 m, settling max(3 m, 2 s of travel), grid margin 1 m, dx 5 mm. */
tirenv_ride_span tirenv_ride_span_default(void);

/* The front axle's start (m) over ground whose first vertex is at x_first (m). */
double tirenv_ride_span_start(const tirenv_ride_span *s, double x_first);

/* The front axle's end (m) at speed V (m/s) over ground whose last vertex is at x_last (m):
 * the rear axle of v, a wheelbase behind, is then max(settle_min, settle_time*V) past it. */
double tirenv_ride_span_end(const tirenv_ride_span *s, const tirenv_vehicle *v, double x_last,
                            double V);

/* The grid x_k = x0 + k*s->dx of a run whose front axle goes from x_from to x_to (m; over
 * several speeds, the furthest end of all): from grid_margin behind the rear axle's start to
 * grid_margin beyond the front axle's end. Puts x0 (m) into *x0 and returns the number of
 * points, ceil((x_to + grid_margin - x0)/dx) + 1, as a double for the caller to check
 * against what it can hold before converting (not finite unless dx > 0 and all is finite). */
double tirenv_ride_span_grid(const tirenv_ride_span *s, const tirenv_vehicle *v, double x_from,
                             double x_to, double *x0);

/* What a set of runs over one profile asks for, before tirenv_ride_plan_make checks it and
 * works out where each run starts and ends (docs/models.md section 9.4). */
typedef struct {
    tirenv_ride_span span; /* run-in, settling, grid margin and the grid spacing dx */
    double x_from;         /* the front axle's start, m; NAN: tirenv_ride_span_start's */
    double x_to;           /* its end, m; NAN: tirenv_ride_span_end's at each speed */
    double dt;             /* output interval, s (a sampling rate of TIRENV_COMFORT_FS_MIN at
                            * least, for the comfort weightings) */
    tirenv_ride_method method;
    double tol;            /* RK8PD's tolerance per step */
    double max_points;     /* the most samples one run and points the grid may have: more is
                            * taken for a typo in a speed, dt or dx, not run out of memory on */
} tirenv_ride_plan_params;

/* tirenv ride's: tirenv_ride_span_default, x_from and x_to NAN, dt, method and tol of
 * tirenv_ride_default, max_points 1e7. */
tirenv_ride_plan_params tirenv_ride_plan_params_default(void);

/* The most speeds one plan holds. */
#define TIRENV_RIDE_PLAN_RUNS 16

/* What tirenv ride (and the Python module's ride) drive: one run per speed, all from the same
 * start, and the one grid of the axles' inputs that covers them all: x_k = x0 + k*dx (k < n),
 * from the rear axle's start to the furthest end of the front axle, grid_margin beyond both
 * (tirenv_ride_span_grid). */
typedef struct {
    double x0;             /* the grid's first position, m */
    double dx;             /* the grid's spacing, m */
    size_t n;              /* the grid's points */
    tirenv_ride_settings run[TIRENV_RIDE_PLAN_RUNS]; /* one per speed: speed, x_front0, duration
                            * (to x_to, or the span's end at the speed), dt, method, tol */
} tirenv_ride_plan;

/* The plan of runs of vehicle v over profile p at speeds[] (m/s, n_speeds of them, 1 to
 * TIRENV_RIDE_PLAN_RUNS) into *plan. TIRENV_EINVAL, naming the field: dt not positive or too
 * coarse for the weightings (dt, "80 Hz"); dx not positive or not finite (dx); a speed not
 * positive and finite (speed); a run that ends before it starts (x_to); a run of more than
 * max_points samples (speed: its duration, at dt) or a grid of more (dx). */
int tirenv_ride_plan_make(const tirenv_ride_plan_params *pp, const tirenv_vehicle *v,
                          const tirenv_profile *p, const double speeds[], size_t n_speeds,
                          tirenv_ride_plan *plan, tirenv_diag *diag);

/* The coarsest grid of the axles' inputs (m) that follows tires of free radii R0_front and
 * R0_rear (m): an effective road varies on the scale of a tire's patch, some 0.2 R0 or more,
 * which a tenth of the smaller R0 samples at least twice. tirenv ride and the Python module
 * refuse a coarser dx: a 10 m grid over a 0.3 m cleat never sampled it and the ride printed a
 * still seat (docs/models.md section 9.6). */
double tirenv_ride_dx_max(double R0_front, double R0_rear);

/* The state and what the driver feels at one output time. Displacements are from the static
 * equilibrium on flat ground at height 0 (so z = w on a flat road of height w). */
typedef struct {
    double t;              /* s */
    double x_front;        /* front-axle position, m */
    double z, vz, az;      /* body heave at the CG (up), its velocity and acceleration */
    double theta, vtheta, atheta; /* body pitch (nose up), rad, rad/s, rad/s^2 */
    double z_a, vz_a;      /* front axle heave and velocity (equal to the body's at the axle
                            * when it is rigid), m, m/s */
    double w_front, w_rear;/* the axles' inputs, m */
    double seat_az;        /* vertical acceleration at the seat point, m/s^2 */
    double seat_ax;        /* fore-aft acceleration at the seat point from pitch, m/s^2 */
    double F_front, F_rear;/* total tire force of each axle (>= 0: lift-off is 0), N */
} tirenv_ride_sample;

/* What an axle's tires follow over profile p on the grid x_k = x0 + k*dx (k < n), into w[]:
 * the model's effective height h (m) at the load of one tire (N), by tirenv_model_envelope
 * over blocks of the grid; the point contact (tirenv_model_point), or m NULL, gives the
 * profile's own height under the wheel centre. The model is set to p and the load
 * (tirenv_model_set, or tirenv_model_set_load if it is set on p already: the rows of a
 * table); its errors name the position. */
int tirenv_ride_effective(tirenv_model *m, const tirenv_profile *p, double load, double x0,
                          double dx, size_t n, double w[], tirenv_diag *diag);

/* What the driver feels over one run, as tirenv ride reports it (docs/models.md section 10.4,
 * ISO 2631-1). */
typedef struct {
    tirenv_comfort_metrics seat;   /* Wk-weighted vertical acceleration at the seat, m/s^2 */
    tirenv_comfort_metrics pitch;  /* We-weighted pitch acceleration, rad/s^2 */
    double a_v;            /* vibration total value of the two (k = 1, 0.4 m/rad), m/s^2 */
    double peak_az;        /* largest unweighted seat acceleration, m/s^2 */
    double lift_off;       /* time with a tire off the ground (a sample's dt each), s */
} tirenv_ride_comfort;

/* The comfort figures of a run's n samples s[] taken every dt (s) into *c; the Wk-weighted
 * seat acceleration into seat_awz[] (n, m/s^2) unless it is NULL. TIRENV_EINVAL if dt is not
 * positive and finite or as tirenv_comfort_evaluate (too few samples, dt too coarse for the
 * weightings, a sample not finite); TIRENV_ENOMEM. */
int tirenv_ride_comfort_measure(const tirenv_ride_sample s[], size_t n, double dt,
                                double seat_awz[], tirenv_ride_comfort *c, tirenv_diag *diag);

/* Number of samples a run writes: floor(duration / dt) + 1 (t = 0 included); 0 for settings
 * a run refuses (dt not positive, duration negative or not finite, more than 1e9 steps). */
size_t tirenv_ride_n_samples(const tirenv_ride_settings *s);

/* Runs the simulation from the steady start (static equilibrium on the inputs' heights at
 * t = 0, at rest vertically) and fills out[0 .. tirenv_ride_n_samples(s) - 1].
 * TIRENV_EINVAL for bad settings or vehicle (checked by tirenv_vehicle_check), TIRENV_ENOMEM,
 * TIRENV_ENOCONV if the integrator fails (the time is named). */
int tirenv_ride_run(const tirenv_vehicle *v, const tirenv_ride_track *front,
                    const tirenv_ride_track *rear, const tirenv_ride_settings *s,
                    tirenv_ride_sample out[], tirenv_diag *diag);

/* What an axle's tires follow when it depends on their load (docs/models.md section 9.5):
 * one model's effective heights at m >= 1 loads of one tire on the grid of tirenv_ride_track,
 * w[j*n + k] at load[j] and x_k = x0 + k*dx. In x each row is a tirenv_ride_track (Steffen),
 * in the load linear between rows; below load[0] the input is load[0]'s, above load[m-1]
 * load[m-1]'s (m = 1: an input that does not depend on the load). tirenv_ride_table_build
 * computes one from a model. */
typedef struct {
    double x0;             /* first grid position, m */
    double dx;             /* grid spacing, m */
    size_t n;              /* grid points, >= 2 */
    size_t m;              /* loads, >= 1 */
    const double *load;    /* the loads of one tire, N, increasing, > 0 (borrowed) */
    const double *w;       /* m*n heights, m (borrowed) */
} tirenv_ride_table;

/* The loads of the rows of tirenv ride's tables for a tire of static load G0 (N): G0 times
 * 0.1, 0.2, 0.3, 0.4, 0.55, 0.7, 0.85, 1, 1.2, 1.45, 1.75, 2.1, 2.5 and 3 (docs/models.md
 * section 9.5), into load[TIRENV_RIDE_TABLE_LOADS]. */
#define TIRENV_RIDE_TABLE_LOADS 14
void tirenv_ride_table_loads(double G0, double load[]);

/* tirenv ride's table for a tire of static load G0 (N): rows of model over profile p at the
 * loads of tirenv_ride_table_loads (each row tirenv_ride_effective's), into load[] and w[] (room for
 * TIRENV_RIDE_TABLE_LOADS rows of n), their number in *rows. A load the model refuses ends the
 * rows above G0, or is left out below it; G0's row must succeed (its error is returned). Rows
 * all alike (a model whose road does not depend on the load: rigid, point) become one, at G0.
 * warnings (may be NULL) receives the model's warnings at G0, then those of the lightest and
 * the heaviest rows if they have their own, one per line. */
int tirenv_ride_table_build(tirenv_model *model, const tirenv_profile *p, double G0, double x0,
                            double dx, size_t n, double load[], double w[], size_t *rows,
                            char *warnings, size_t warnings_size, tirenv_diag *diag);

/* An axle's input as a function of position and tire load, for inputs that are neither a
 * track nor a table (a model evaluated during the integration, say): fn puts the height
 * w (m) and dw/dx at position x (m) and tire load (N, in [load_min, load_max]) into *w and
 * *dw_dx, or returns a TIRENV_ code with diag filled, which stops the run. */
typedef int (*tirenv_ride_input_fn)(void *ctx, double x, double load, double *w, double *dw_dx,
                                    tirenv_diag *diag);
typedef struct {
    tirenv_ride_input_fn fn;
    void *ctx;
    double load_min, load_max; /* the loads it is evaluated at (per tire, N, > 0); a load
                                * outside is evaluated at the nearer end */
    double dx;                 /* the input's resolution, m: RK4 substeps advance at most half
                                * of it, as over a grid */
} tirenv_ride_input;

/* A model evaluated during the run as an axle's input (tirenv ride --enveloping direct): at
 * each position and load, tirenv_model_set_load then tirenv_model_eval at x and x -+ dx/2 for
 * dw/dx. The caller owns it; it must outlive the run. */
typedef struct {
    tirenv_model *m;       /* the axle's model, set on the profile (borrowed) */
    double dx;             /* the grid spacing, m: the derivative's step is dx/2 either side */
} tirenv_ride_direct;

/* Makes *in the direct input of model m (set on the profile at G0, the static load of one tire,
 * N) over a grid every dx (m), its state in *d: load_min and load_max the lightest and the
 * heaviest of tirenv_ride_table_loads(G0) that m takes (as the tables end), m left at G0,
 * whose refusal is returned. */
int tirenv_ride_direct_input(tirenv_model *m, double G0, double dx, tirenv_ride_direct *d,
                             tirenv_ride_input *in, tirenv_diag *diag);

/* The simulation with load-dependent inputs (docs/models.md section 9.5): at every evaluation
 * each axle's input is taken at the load its tires then carry, the load G of one tire that
 * balances G = max(0, g(G)), g the tire's load (section 9.3) at the deflection
 * w(x, G) - z_axle from the static one and its rate V*dw/dx(x, G) - dz_axle/dt: with the
 * vehicle's TIRE_STIFFNESS k_t, g = G0 + k_t*(w - z_axle) + c_t*(...) (G0 its static load),
 * solved exactly on a table (linear in G between rows); with the tire file's vertical law by
 * regula falsi on the table's segment; by the same bracketing iteration on a function input.
 * A tire off the ground (G = 0) follows the input at its
 * lightest load (load[0], load_min), which decides where it touches down. A table of one row
 * (or rows all alike) gives tirenv_ride_run's result to round-off. Errors as tirenv_ride_run;
 * an input function's error stops the run, naming the time, and so does a function input's
 * balance not found in 100 iterations (TIRENV_ENOCONV, field the axle, the bracket and the
 * residual reached in the message). */
int tirenv_ride_run_dynamic(const tirenv_vehicle *v, const tirenv_ride_table *front,
                            const tirenv_ride_table *rear, const tirenv_ride_settings *s,
                            tirenv_ride_sample out[], tirenv_diag *diag);
int tirenv_ride_run_input(const tirenv_vehicle *v, const tirenv_ride_input *front,
                          const tirenv_ride_input *rear, const tirenv_ride_settings *s,
                          tirenv_ride_sample out[], tirenv_diag *diag);

/* The vehicle's vertical energy at a sample, J: kinetic + the tire and suspension springs'
 * energy about the static equilibrium (the preloads' work cancels gravity's; a tire file's
 * vertical law by its own integral, a linear k_t as k_t*d^2/2). Exact while no tire has
 * lifted off; conserved when all damping is 0 and the inputs are constant. NAN where an
 * axle's law carries no static load. For tests and diagnostics. */
double tirenv_ride_energy(const tirenv_vehicle *v, const tirenv_ride_sample *s);

TIRENV_END_DECLS
#endif
