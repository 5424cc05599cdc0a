/* SPDX-License-Identifier: Apache-2.0 */
/* Shared test helpers: cmocka 1.1 has no floating-point comparison. */
#ifndef TIRENV_TESTUTIL_H
#define TIRENV_TESTUTIL_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "tirenv/dataset.h"
#include "tirenv/model.h"
#include "tirenv/nn.h"
#include "tirenv/ring.h"
#include "tirenv/rng.h"
#include "tirenv/tire.h"

/* The next number of a seeded splitmix64 sequence in [0, 1): the tests' own generator, apart
 * from the library's (its state the caller's). */
double tirenv_test_uniform(uint64_t *state);

/* FNV-1a, 64 bits, of b[0..n-1], a byte at a time: the tests' own oracle for the model state's
 * checksum (src/model/model_state.c takes runs of zeros at once). */
uint64_t tirenv_test_fnv1a(const unsigned char *b, size_t n);

/* A model's continuity in x at an obstacle's edges: m set on p, at each vertex of p and at two
 * positions 0.1 to 0.4 m either side of it (drawn from rng), the largest |h(x +- 1e-12) - h(x)|
 * (m) and |F_x(x +- 1e-12) - F_x(x)| (N), raising *dh_max and *dfx_max; returns the positions
 * checked. Fails on an evaluation that does not succeed. */
size_t tirenv_test_jumps(tirenv_model *m, const tirenv_profile *p, tirenv_rng *rng,
                         double *dh_max, double *dfx_max);

/* Fails unless |actual - expected| <= abs_tol + rel_tol*|expected|; prints both values. */
#define assert_near(actual, expected, abs_tol, rel_tol)                                      \
    tirenv_test_assert_near((actual), (expected), (abs_tol), (rel_tol), #actual, __FILE__,   \
                            __LINE__)

void tirenv_test_assert_near(double actual, double expected, double abs_tol, double rel_tol,
                             const char *expr, const char *file, int line);

/* Fails unless a and b are the same double, bit for bit (exactness claims); prints both. */
#define assert_bits_equal(a, b) tirenv_test_check_bits((a), (b), #a, __FILE__, __LINE__)

void tirenv_test_check_bits(double a, double b, const char *expr, const char *file, int line);

/* The repository's data/tires/default.tir over tirenv_tire_default(), asserting it reads. */
/* The default tire with the springs and cam values it had before they were identified on the
 * ring's flat ground (docs/models.md section 14.1): c_r 7.83e5, c_b 1.41e4 (fitted to the
 * embedded data set's curves), Q_RA1 0.61, Q_RA2 0.66 (a law that meets the chord of the
 * free circle below the deflection R0). For the tests of mechanisms that need those
 * properties: lift-off over the ride's cleat, the cam's chord limit, a network's regime. */
tirenv_tire tirenv_test_tire_before_identify(void);
tirenv_tire tirenv_test_default_tire(void);

/* A 4-8-1 network with weights from the seed, scaled to n_samples (at most 128) random
 * inputs over the embedded data set's ranges: no good model of a tire, but a network as the
 * model type sees it. */
tirenv_nn *tirenv_test_made_up_network(unsigned long seed, size_t n_samples);

/* A sink of streamed points (tirenv_model_stream's callback with this as its context): pt
 * NULL or malloc'd with room for cap points, grown by realloc as points come (the caller
 * frees pt, and reads the points there); with stop > 0 the point after the first stop is
 * refused with TIRENV_EIO. */
typedef struct {
    tirenv_point *pt;
    size_t n, cap, stop;
} tirenv_test_points;

int tirenv_test_keep_point(void *ctx, const tirenv_point *pt);

/* A fresh scratch directory per test: cmocka setup and teardown (the teardown removes the
 * files left in it and fails if the directory itself cannot go). */
typedef struct {
    char dir[64];
} tirenv_test_dir;

/* A file that a reader must refuse, with what its diag must say. */
typedef struct {
    const char *text;   /* file contents */
    int status;
    size_t line, column;
    const char *field;
    const char *says;   /* a phrase the message must contain */
} tirenv_test_read_error;

/* Prints case i's message (d), then asserts that the call returned want and that d names
 * file, line, column (0: none), field and, in its message, the phrase says. */
void tirenv_test_expect_diag(size_t i, int status, const tirenv_diag *d, int want,
                             const char *file, size_t line, size_t column, const char *field,
                             const char *says);

int tirenv_test_dir_setup(void **state);
int tirenv_test_dir_teardown(void **state);
/* The same teardown after removing everything in the directory, subdirectories too (a sweep's
 * trees). */
int tirenv_test_dir_teardown_tree(void **state);

/* s in single quotes for a system() command line, each ' in it written '\'' (a path with
 * blanks or quotes stays one word); asserts that it fits in size bytes. Returns buf. */
const char *tirenv_test_shell_quote(const char *s, char *buf, size_t size);

/* dir/name in buf. */
const char *tirenv_test_path(const tirenv_test_dir *d, const char *name, char buf[600]);
/* Writes text to path, asserting success. */
void tirenv_test_write_text(const char *path, const char *text);
/* Reads the whole file at path into buf, NUL-terminated, asserting that it opens and fits in
 * size - 1 bytes (a longer file fails the test rather than being cut); returns its length. */
size_t tirenv_test_read_text(const char *path, char *buf, size_t size);
/* Entries of the directory whose name contains the string. */
size_t tirenv_test_count_entries(const tirenv_test_dir *d, const char *containing);

/* Writes text to a new file /tmp/tirenv_test_<what>_XXXXXX (mkstemp) whose name goes into
 * path, asserting success; the caller removes it. */
void tirenv_test_write_temp(char path[64], const char *what, const char *text);

/* Level ground at height 0 (one vertex at x = 0); free it with tirenv_profile_free. */
tirenv_profile *tirenv_test_flat_ground(void);

/* Ring r's dF_z/dz over p at (x, z) (m) against central differences of step dz (m). Skipped
 * (returns 0) where F_z < 10 N or where the one-sided differences disagree by more than
 * 1e-6 |dF_z/dz| dz (a kink or jump within dz: a contact state changes); else asserts
 * agreement to 1e-6 of the difference quotient and returns 1, with *belt set to whether the
 * belt layer carried at z. */
int tirenv_test_ring_dfdz(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                          double dz, int *belt);

/* The cleats of the fit tests' synthetic data sets: {contact length, L, H}, m. */
extern const double tirenv_test_fit_design[6][3];

/* Case c of a synthetic data set, named name, in the train split: the cleat design[] =
 * {contact length, L, H} (m) at the load m gives that contact length, and m's curve over it
 * on n x_N points from -0.2 to 1 (as the data sets' grid; x from tirenv_xN_origin for a tire
 * of radius R0, m). c->curve is allocated: tirenv_curve_free it. */
void tirenv_test_model_case(tirenv_model *m, double R0, const double design[3],
                            const char *name, size_t n, tirenv_case *c);

/* An nn model of the default tire (tirenv_test_default_tire) evaluating nn at the tire's R0;
 * extrapolation allowed (1), refused (0) or left as the model has it (-1). */
tirenv_model *tirenv_test_nn_model(const tirenv_nn *nn, int extrapolate);

/* A cmocka group setup: *state the network trained on the data set's train and control
 * cases (data/dataset, one Levenberg-Marquardt restart); the teardown frees it. */
int tirenv_test_nn_setup(void **state);
int tirenv_test_nn_teardown(void **state);

#endif
