# SPDX-License-Identifier: Apache-2.0
"""The C side of the tirenv Python module: cffi in API mode, compiled against tirenv's public
headers and linked with libtirenv.so.

API mode, not ABI mode, because the compiler then checks every declaration below against the
real headers: a struct field that changes type or disappears, or a function whose signature
changes, fails the build (the flags below make pointer mismatches errors), and the struct
layouts the module relies on (tirenv_point, tirenv_ride_sample) come from the compiler, not
from a hand-kept mirror.

Used three ways:
  * by 'make python' (CMake): python3 tirenv_build.py --out DIR --include DIR --libdir DIR
    builds the package in place under DIR (build/python);
  * by setup.py (pip install ./python): the attribute ffibuilder, located through
    TIRENV_INCLUDE_DIR / TIRENV_LIBRARY_DIR if set, else pkg-config tirenv;
  * by make_wheel.py (make wheel), which imports make_builder;
  * by nothing else: the module has no run-time dependency on cffi's compiler parts.
"""
import argparse
import os
import shutil
import subprocess
import sys

import cffi

CDEF = r"""
/* error.h */
typedef enum {
    TIRENV_OK = 0, TIRENV_EINVAL, TIRENV_ENOMEM, TIRENV_EIO, TIRENV_EPARSE,
    TIRENV_ENOBRACKET, TIRENV_ENOCONV, TIRENV_ECONTINUE, TIRENV_ERANGE
} tirenv_status;
typedef struct {
    char file[...];
    size_t line;
    size_t column;
    char field[...];
    char message[...];
} tirenv_diag;
const char *tirenv_strerror(int status);
void tirenv_diag_clear(tirenv_diag *diag);
char *tirenv_diag_format(const tirenv_diag *diag, char *buf, size_t n);

/* tire.h */
typedef enum { TIRENV_EQ_NEWTON = 0, TIRENV_EQ_SECANT, TIRENV_EQ_BRENT } tirenv_eq_method;
typedef enum { TIRENV_SPRINGS_CONTINUOUS = 0, TIRENV_SPRINGS_RAYS = 1 } tirenv_springs_contact;
typedef struct { double R0; double c_r; double c_b; double phi; double dphi;
                 tirenv_springs_contact contact; double k_s; double F_s0; } tirenv_springs_params;
typedef struct { tirenv_springs_params springs; ...; } tirenv_tire;
tirenv_tire tirenv_tire_default(void);
int tirenv_tire_check(const tirenv_tire *tire, tirenv_diag *diag);
int tirenv_tire_check_cam_keys(const tirenv_tire *tire, tirenv_diag *diag);

/* tir.h */
int tirenv_tir_set(tirenv_tire *tire, const char *assignment, tirenv_diag *diag);
int tirenv_tir_write(const char *path, const tirenv_tire *tire, tirenv_diag *diag);
typedef enum { TIRENV_TIR_REAL, TIRENV_TIR_COUNT, TIRENV_TIR_NAME } tirenv_tir_kind;
const char *tirenv_tir_key(size_t i, const char **section);
int tirenv_tir_get(const tirenv_tire *tire, const char *key, char *buf, size_t n,
                   tirenv_tir_kind *kind, tirenv_diag *diag);
static const unsigned int TIRENV_TIR_SPRINGS;
static const unsigned int TIRENV_TIR_RING;
static const unsigned int TIRENV_TIR_CAM;
static const unsigned int TIRENV_TIR_VERTICAL;
typedef struct { double fnomin; double rho_nominal; unsigned own; unsigned derived;
                 double pretension_ratio; double cam_ring_deflection;
                 double cam_ring_contact_length; char note[1024]; ...; } tirenv_tir_origin;
int tirenv_tir_read_derive(const char *path, tirenv_tire *tire, unsigned need,
                           tirenv_tir_origin *origin, tirenv_diag *diag);

/* version.h: the headers' version, the project's */
#define TIRENV_VERSION_MAJOR ...
#define TIRENV_VERSION_MINOR ...
#define TIRENV_VERSION_PATCH ...

/* profile.h */
typedef struct tirenv_profile tirenv_profile;
int tirenv_profile_validate(size_t n, const double x[], const double z[], tirenv_diag *diag);
tirenv_profile *tirenv_profile_alloc(size_t n, const double x[], const double z[]);
void tirenv_profile_free(tirenv_profile *p);
size_t tirenv_profile_size(const tirenv_profile *p);
const double *tirenv_profile_x(const tirenv_profile *p);
const double *tirenv_profile_z(const tirenv_profile *p);
double tirenv_profile_height(const tirenv_profile *p, double x);
void tirenv_profile_extent(const tirenv_profile *p, double *x_first, double *x_last);
tirenv_profile *tirenv_profile_cleat(double L, double H);
tirenv_profile *tirenv_profile_step(double x0, double H);
tirenv_profile *tirenv_profile_trapezoid(double L_top, double L_base, double H);
tirenv_profile *tirenv_profile_triangle(double L_base, double H);
tirenv_profile *tirenv_profile_half_cylinder(double r, size_t segments);
tirenv_profile *tirenv_profile_sine(double amplitude, double wavelength, double periods,
                                    size_t points_per_period);
typedef struct { size_t cylinder_segments; size_t sine_points_per_period; }
    tirenv_profile_resolution;
tirenv_profile_resolution tirenv_profile_resolution_default(void);

/* crg.h, rdf.h, profile_file.h: a road file of any format, opened once (the library's one
 * road reader), one track of it */
typedef struct { double v; int border_mode_v; int grid_nan_mode; ...; } tirenv_crg_track_spec;
typedef enum { TIRENV_RDF_MEAN = 0, TIRENV_RDF_LEFT, TIRENV_RDF_RIGHT } tirenv_rdf_side;
int tirenv_rdf_side_find(const char *name, tirenv_rdf_side *side);
typedef struct { tirenv_crg_track_spec crg; tirenv_rdf_side rdf_side; ...; }
    tirenv_profile_source;
tirenv_profile_source tirenv_profile_source_default(void);
int tirenv_profile_read_file(const char *path, const tirenv_profile_source *src,
                             tirenv_profile **out, tirenv_diag *diag);
typedef enum { TIRENV_PROFILE_CSV = 0, TIRENV_PROFILE_CRG, TIRENV_PROFILE_RDF }
    tirenv_profile_format;
typedef struct tirenv_road_file tirenv_road_file;
int tirenv_road_file_open(const char *path, tirenv_road_file **out, tirenv_diag *diag);
tirenv_profile_format tirenv_road_file_format(const tirenv_road_file *f);
void tirenv_road_file_free(tirenv_road_file *f);
int tirenv_road_file_read(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                          const double v[], tirenv_profile *out[], tirenv_diag *diag);

/* road.h */
typedef struct {
    char road_class;
    double length;
    double dx;
    unsigned long seed;
    double n_min, n_max;
    double waviness;
} tirenv_road_settings;
tirenv_road_settings tirenv_road_default(void);
int tirenv_road_iso8608(const tirenv_road_settings *s, tirenv_profile **out,
                        tirenv_diag *diag);

/* model.h */
typedef struct {
    double x; double z; double h; double slope; double fx; double fz;
    size_t contacts; size_t iterations;
} tirenv_point;
typedef struct {
    double load; double z_flat; double deflection; double contact_length; double stiffness;
} tirenv_flat;
typedef struct tirenv_model_type tirenv_model_type;
typedef struct tirenv_model tirenv_model;
const tirenv_model_type *tirenv_model_type_find(const char *name);
const char *tirenv_model_type_name(const tirenv_model_type *type);
unsigned tirenv_tir_need(const tirenv_model_type *type, int alone);
const tirenv_model_type *const *tirenv_model_types(void);
#define TIRENV_MODEL_NEEDS_NETWORK ...
#define TIRENV_MODEL_CONTACT_LENGTH ...
unsigned tirenv_model_type_flags(const tirenv_model_type *type);
tirenv_model *tirenv_model_alloc(const tirenv_model_type *type, const tirenv_tire *tire);
void tirenv_model_free(tirenv_model *m);
const char *tirenv_model_name(const tirenv_model *m);
struct tirenv_nn;
int tirenv_model_set_network(tirenv_model *m, const struct tirenv_nn *nn, double R0,
                             tirenv_diag *diag);
void tirenv_model_set_extrapolate(tirenv_model *m, int allow);
int tirenv_model_flat(tirenv_model *m, double load, tirenv_flat *out, tirenv_diag *diag);
int tirenv_model_load_for_contact_length(tirenv_model *m, double l_c, double *load,
                                         tirenv_diag *diag);
int tirenv_model_set(tirenv_model *m, const tirenv_profile *profile, double load,
                     tirenv_diag *diag);
const char *tirenv_model_warnings(const tirenv_model *m);

/* tracks.h: tracks across the tire's width */
int tirenv_tracks_spread(size_t n, double v, double width, double v_out[], tirenv_diag *diag);
int tirenv_model_set_tracks(tirenv_model *m, size_t n, const tirenv_profile *const profiles[],
                            const double weights[], double load, tirenv_diag *diag);
double tirenv_model_reach(const tirenv_model *m);
int tirenv_model_envelope(tirenv_model *m, size_t n, const double x[], tirenv_point out[],
                          size_t *failed, tirenv_diag *diag);

/* stream.h */
size_t tirenv_positions_count(double x_from, double x_to, double dx);
typedef struct { double x_from; double x_to; double dx; } tirenv_positions;
tirenv_positions tirenv_positions_default(double x_first, double x_last, double R0);

/* nn.h, the network's model file */
typedef struct tirenv_nn tirenv_nn;
void tirenv_nn_free(tirenv_nn *nn);
size_t tirenv_nn_n_inputs(const tirenv_nn *nn);
void tirenv_nn_input_range(const tirenv_nn *nn, double lo[], double hi[]);
void tirenv_nn_run_batch(tirenv_nn *nn, size_t n, const double x[], double y[]);
int tirenv_nn_envelope(tirenv_nn *nn, double R0, double l_c, double L, double H, size_t n,
                       const double x[], double h[], tirenv_diag *diag);
typedef struct { size_t n; double load[32]; double l_c[32]; } tirenv_contact_law;
int tirenv_model_set_contact_law(tirenv_model *m, const tirenv_contact_law *law,
                                 tirenv_diag *diag);
typedef struct { double R0; tirenv_contact_law law; ...; } tirenv_train_record;
int tirenv_nn_read_json(const char *path, tirenv_nn **out, tirenv_train_record *rec,
                        tirenv_diag *diag);

/* nn_road.h */
typedef struct tirenv_nn_road tirenv_nn_road;
typedef struct {
    size_t obstacles; size_t height_below; size_t height_above; size_t length_below;
    size_t length_above; ...;
} tirenv_nn_road_info;
typedef struct { ...; } tirenv_nn_road_settings;
int tirenv_nn_road_alloc(const tirenv_nn *nn, double R0, double l_c, const tirenv_profile *p,
                         const tirenv_nn_road_settings *s, tirenv_nn_road **out,
                         tirenv_diag *diag);
void tirenv_nn_road_free(tirenv_nn_road *r);
int tirenv_nn_road_eval(tirenv_nn_road *r, size_t n, const double x[], double h[],
                        double slope[], tirenv_diag *diag);
tirenv_nn_road_info tirenv_nn_road_info_of(const tirenv_nn_road *r);

/* vehicle.h */
typedef struct {
    char tire_file[...];
    double tires; double k_t; double c_t; double k_s; double c_s; double m_a; ...;
} tirenv_axle;
typedef struct {
    double m; double I_y; double a; double b; double seat_x; double seat_h;
    tirenv_axle front, rear;
    double g;
} tirenv_vehicle;
tirenv_vehicle tirenv_vehicle_default(void);
int tirenv_vehicle_check(const tirenv_vehicle *v, tirenv_diag *diag);
double tirenv_vehicle_tire_load(const tirenv_vehicle *v, int axle);
int tirenv_vehicle_tires(tirenv_vehicle *v, const tirenv_tire *front, const tirenv_tire *rear,
                         tirenv_diag *diag);
int tirenv_vehicle_read(const char *path, tirenv_vehicle *v, tirenv_diag *diag);
int tirenv_vehicle_set(tirenv_vehicle *v, const char *assignment, tirenv_diag *diag);

/* ride.h */
typedef struct { double x0; double dx; size_t n; const double *w; } tirenv_ride_track;
typedef enum { TIRENV_RIDE_RK4, TIRENV_RIDE_RK8PD } tirenv_ride_method;
typedef struct {
    double speed; double x_front0; double duration; double dt;
    tirenv_ride_method method; double tol;
} tirenv_ride_settings;
typedef struct {
    double t; double x_front; double z, vz, az; double theta, vtheta, atheta;
    double z_a, vz_a; double w_front, w_rear; double seat_az; double seat_ax;
    double F_front, F_rear;
} tirenv_ride_sample;
int tirenv_ride_method_parse(const char *name, tirenv_ride_method *m, tirenv_diag *diag);
typedef enum {
    TIRENV_RIDE_STATIC = 0, TIRENV_RIDE_DYNAMIC, TIRENV_RIDE_DIRECT, TIRENV_RIDE_N_ENVELOPING
} tirenv_ride_enveloping;
#define TIRENV_RIDE_ENVELOPING_DEFAULT ...
int tirenv_ride_enveloping_parse(const char *name, tirenv_ride_enveloping *e,
                                 tirenv_diag *diag);
typedef struct {
    double run_in; double settle_min; double settle_time; double grid_margin; double dx;
} tirenv_ride_span;
tirenv_ride_span tirenv_ride_span_default(void);
double tirenv_ride_span_start(const tirenv_ride_span *s, double x_first);
typedef struct {
    tirenv_ride_span span; double x_from; double x_to; double dt; tirenv_ride_method method;
    double tol; double max_points;
} tirenv_ride_plan_params;
tirenv_ride_plan_params tirenv_ride_plan_params_default(void);
#define TIRENV_RIDE_PLAN_RUNS ...
typedef struct {
    double x0; double dx; size_t n;
    tirenv_ride_settings run[...];
} tirenv_ride_plan;
int tirenv_ride_plan_make(const tirenv_ride_plan_params *pp, const tirenv_vehicle *v,
                          const tirenv_profile *p, const double speeds[], size_t n_speeds,
                          tirenv_ride_plan *plan, tirenv_diag *diag);
double tirenv_ride_dx_max(double R0_front, double R0_rear);
int tirenv_ride_effective(tirenv_model *m, const tirenv_profile *p, double load, double x0,
                          double dx, size_t n, double w[], tirenv_diag *diag);
size_t tirenv_ride_n_samples(const tirenv_ride_settings *s);
int tirenv_ride_run(const tirenv_vehicle *v, const tirenv_ride_track *front,
                    const tirenv_ride_track *rear, const tirenv_ride_settings *s,
                    tirenv_ride_sample out[], tirenv_diag *diag);
typedef struct {
    double x0; double dx; size_t n; size_t m; const double *load; const double *w;
} tirenv_ride_table;
#define TIRENV_RIDE_TABLE_LOADS ...
int tirenv_ride_table_build(tirenv_model *model, const tirenv_profile *p, double G0, double x0,
                            double dx, size_t n, double load[], double w[], size_t *rows,
                            char *warnings, size_t warnings_size, tirenv_diag *diag);
int tirenv_ride_run_dynamic(const tirenv_vehicle *v, const tirenv_ride_table *front,
                            const tirenv_ride_table *rear, const tirenv_ride_settings *s,
                            tirenv_ride_sample out[], tirenv_diag *diag);

/* comfort.h */
static const double TIRENV_COMFORT_FS_MIN;
typedef enum { TIRENV_WK = 0, TIRENV_WD, TIRENV_WE } tirenv_weighting;
typedef struct {
    double duration; double rms; double peak; double crest; double vdv; double mtvv;
} tirenv_comfort_metrics;
int tirenv_weighting_parse(const char *name, tirenv_weighting *w, tirenv_diag *diag);
int tirenv_comfort_evaluate(tirenv_weighting w, double fs, const double a[], double a_w[],
                            size_t n, tirenv_comfort_metrics *m, tirenv_diag *diag);
int tirenv_comfort_total_value(const double k[], const double a_w[], size_t n, double *a_v,
                               tirenv_diag *diag);
typedef struct {
    tirenv_comfort_metrics seat, pitch;
    double a_v, peak_az, lift_off;
} tirenv_ride_comfort;
int tirenv_ride_speed_parse(const char *text, double *v, tirenv_diag *diag);
int tirenv_ride_comfort_measure(const tirenv_ride_sample s[], size_t n, double dt,
                                double seat_awz[], tirenv_ride_comfort *c, tirenv_diag *diag);
"""

SOURCE = r"""
#include <tirenv/tirenv.h>
#include <tirenv/nn.h>
#include <tirenv/nn_road.h>
#include <tirenv/train.h>
"""

# Pointer and integer mismatches between the declarations above and the headers are errors.
STRICT = ["-Werror=incompatible-pointer-types", "-Werror=int-conversion",
          "-Werror=implicit-function-declaration"]

SYSTEM_LIBDIRS = {"/usr/lib", "/usr/lib64", "/usr/lib/x86_64-linux-gnu", "/lib",
                  "/lib/x86_64-linux-gnu"}


def make_builder(include_dirs, library_dirs, rpath=None):
    """An FFI builder for tirenv._native against headers in include_dirs and libtirenv.so in
    library_dirs, its run path (RUNPATH) rpath if given (make_wheel.py: $ORIGIN), else the
    library directories that are not system directories."""
    ffi = cffi.FFI()
    ffi.cdef(CDEF)
    if rpath is None:
        rpath = [d for d in library_dirs if os.path.realpath(d) not in SYSTEM_LIBDIRS]
    ffi.set_source("tirenv._native", SOURCE, include_dirs=list(include_dirs),
                   library_dirs=list(library_dirs), libraries=["tirenv", "m"],
                   extra_compile_args=STRICT,
                   extra_link_args=(["-Wl,--enable-new-dtags"] if rpath else []) +
                   ["-Wl,-rpath," + d for d in rpath])
    return ffi


def _pkgconfig(flag):
    out = subprocess.run(["pkg-config", flag, "tirenv"], check=True, capture_output=True,
                         text=True).stdout.split()
    return [w[2:] for w in out if w[:2] in ("-I", "-L")]


def locate():
    """Where an installed libtirenv is: TIRENV_INCLUDE_DIR / TIRENV_LIBRARY_DIR, else
    pkg-config tirenv (PKG_CONFIG_PATH for a prefix of your own)."""
    inc, lib = os.environ.get("TIRENV_INCLUDE_DIR"), os.environ.get("TIRENV_LIBRARY_DIR")
    if inc and lib:
        return [inc], [lib]
    try:
        return _pkgconfig("--cflags-only-I"), _pkgconfig("--libs-only-L")
    except (OSError, subprocess.CalledProcessError) as e:
        sys.exit("tirenv_build: cannot find libtirenv: set TIRENV_INCLUDE_DIR and "
                 "TIRENV_LIBRARY_DIR, or PKG_CONFIG_PATH so that 'pkg-config tirenv' works "
                 f"({e})")


def build_in_place(out, include_dirs, library_dirs, work):
    """The package under out/tirenv: its Python files copied, the extension compiled."""
    here = os.path.dirname(os.path.abspath(__file__))
    pkg = os.path.join(out, "tirenv")
    os.makedirs(pkg, exist_ok=True)
    for name in sorted(os.listdir(os.path.join(here, "tirenv"))):
        if name.endswith(".py"):
            shutil.copyfile(os.path.join(here, "tirenv", name), os.path.join(pkg, name))
    built = make_builder(include_dirs, library_dirs).compile(tmpdir=work, verbose=False)
    target = os.path.join(pkg, os.path.basename(built))
    shutil.copyfile(built, target + ".tmp")
    os.replace(target + ".tmp", target)


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True, help="directory that receives the package")
    ap.add_argument("--include", action="append", required=True, help="tirenv's headers")
    ap.add_argument("--libdir", action="append", required=True, help="libtirenv.so's dir")
    ap.add_argument("--work", required=True, help="scratch directory of the compiler")
    a = ap.parse_args()
    build_in_place(a.out, a.include, a.libdir, a.work)
elif __name__ == "__cffi__":  # setup.py's cffi_modules runs this file under that name
    ffibuilder = make_builder(*locate())
