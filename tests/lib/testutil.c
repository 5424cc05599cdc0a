/* SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "tirenv/rng.h"
#include "tirenv/study.h"
#include "tirenv/train.h"
#include "tirenv/xn.h"

#include "tirenv/tir.h"

void tirenv_test_assert_near(double actual, double expected, double abs_tol, double rel_tol,
                             const char *expr, const char *file, int line)
{
    const double tol = abs_tol + rel_tol * fabs(expected);
    if (!(fabs(actual - expected) <= tol)) {
        print_error("%s = %.17g, expected %.17g within %.3g (off by %.3g)\n", expr, actual,
                    expected, tol, actual - expected);
        _fail(file, line);
    }
}

void tirenv_test_check_bits(double a, double b, const char *expr, const char *file, int line)
{
    if (memcmp(&a, &b, sizeof a) != 0) {
        print_error("%s = %.17g (%a), expected exactly %.17g (%a)\n", expr, a, a, b, b);
        _fail(file, line);
    }
}

int tirenv_test_dir_setup(void **state)
{
    tirenv_test_dir *d = calloc(1, sizeof *d);
    if (!d)
        return -1;
    snprintf(d->dir, sizeof d->dir, "/tmp/tirenv_test_XXXXXX");
    if (!mkdtemp(d->dir)) {
        free(d);
        return -1;
    }
    *state = d;
    return 0;
}

int tirenv_test_dir_teardown(void **state)
{
    tirenv_test_dir *d = *state;
    DIR *dir = opendir(d->dir);
    if (dir) {
        const struct dirent *e;
        char path[600];
        while ((e = readdir(dir)) != NULL) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            snprintf(path, sizeof path, "%s/%s", d->dir, e->d_name);
            remove(path);
        }
        closedir(dir);
    }
    const int r = rmdir(d->dir);
    free(d);
    return r;
}

int tirenv_test_dir_teardown_tree(void **state)
{
    const tirenv_test_dir *d = *state;
    char cmd[200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'/*", d->dir);
    if (system(cmd) != 0)
        return -1;
    return tirenv_test_dir_teardown(state);
}

const char *tirenv_test_shell_quote(const char *s, char *buf, size_t size)
{
    size_t n = 0;
    assert_true(size >= 3);
    buf[n++] = '\'';
    for (; *s; ++s) {
        const char *put = *s == '\'' ? "'\\''" : (const char[]){*s, 0};
        for (; *put; ++put) {
            assert_true(n + 2 < size);  /* room for the closing quote and the NUL */
            buf[n++] = *put;
        }
    }
    buf[n++] = '\'';
    buf[n] = 0;
    return buf;
}

const char *tirenv_test_path(const tirenv_test_dir *d, const char *name, char buf[600])
{
    snprintf(buf, 600, "%s/%s", d->dir, name);
    return buf;
}

void tirenv_test_write_text(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    assert_int_equal(fputs(text, fp) >= 0, 1);
    assert_int_equal(fclose(fp), 0);
}

size_t tirenv_test_read_text(const char *path, char *buf, size_t size)
{
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    const size_t n = fread(buf, 1, size - 1, fp);
    assert_int_equal(ferror(fp), 0);
    assert_int_equal(fgetc(fp), EOF);
    assert_int_equal(fclose(fp), 0);
    buf[n] = '\0';
    return n;
}

size_t tirenv_test_count_entries(const tirenv_test_dir *d, const char *containing)
{
    DIR *dir = opendir(d->dir);
    assert_non_null(dir);
    size_t n = 0;
    const struct dirent *e;
    while ((e = readdir(dir)) != NULL)
        if (strstr(e->d_name, containing) && strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            n++;
    closedir(dir);
    return n;
}

tirenv_tire tirenv_test_tire_before_identify(void)
{
    tirenv_tire t = tirenv_tire_default();
    t.springs.c_r = 7.83e5;
    t.springs.c_b = 1.41e4;
    t.cam.q_ra1 = 0.61;
    t.cam.q_ra2 = 0.66;
    t.cam.c_z = 297000;  /* the linear vertical law identified before Q_FZ2 was read */
    t.cam.q_fz2 = 0;
    return t;
}

tirenv_tire tirenv_test_default_tire(void)
{
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_tir_read(TIRENV_DATA_DIR "/tires/default.tir", &t, &d), TIRENV_OK);
    return t;
}

tirenv_model *tirenv_test_nn_model(const tirenv_nn *nn, int extrapolate)
{
    const tirenv_tire t = tirenv_test_default_tire();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_nn, &t);
    assert_non_null(m);
    tirenv_diag d;
    assert_int_equal(tirenv_model_set_network(m, nn, 0, &d), TIRENV_OK);
    if (extrapolate >= 0)
        tirenv_model_set_extrapolate(m, extrapolate);
    return m;
}

tirenv_nn *tirenv_test_made_up_network(unsigned long seed, size_t n_samples)
{
    enum { MAX = 128 };
    assert_true(n_samples <= MAX);
    tirenv_nn_topology t = tirenv_nn_topology_default();
    tirenv_nn *nn = tirenv_nn_alloc(&t);
    assert_non_null(nn);
    tirenv_rng *rng = tirenv_rng_alloc(0);
    assert_non_null(rng);
    tirenv_rng_seed(rng, seed);
    tirenv_nn_init_weights(nn, rng);
    double x[MAX * TIRENV_NN_INPUTS], y[MAX];
    for (size_t k = 0; k < n_samples; ++k) {
        double *u = x + k * TIRENV_NN_INPUTS;
        u[TIRENV_NN_X_N] = -0.25 + 1.25 * tirenv_rng_uniform(rng);
        u[TIRENV_NN_CONTACT_LENGTH] = 0.28 + 0.1 * tirenv_rng_uniform(rng);
        u[TIRENV_NN_HEIGHT] = 0.025 + 0.075 * tirenv_rng_uniform(rng);
        u[TIRENV_NN_LENGTH] = 0.05 + 0.25 * tirenv_rng_uniform(rng);
        y[k] = 0.04 * tirenv_rng_uniform(rng);
    }
    tirenv_diag d;
    assert_int_equal(tirenv_nn_fit_scaling(nn, n_samples, x, y, &d), TIRENV_OK);
    tirenv_rng_free(rng);
    return nn;
}

int tirenv_test_keep_point(void *ctx, const tirenv_point *pt)
{
    tirenv_test_points *c = ctx;
    if (c->stop && c->n == c->stop)
        return TIRENV_EIO;
    if (c->n == c->cap) {
        c->cap = c->cap ? 2 * c->cap : 1024;
        c->pt = realloc(c->pt, c->cap * sizeof *c->pt);
        assert_non_null(c->pt);
    }
    c->pt[c->n++] = *pt;
    return TIRENV_OK;
}

void tirenv_test_expect_diag(size_t i, int status, const tirenv_diag *d, int want,
                             const char *file, size_t line, size_t column, const char *field,
                             const char *says)
{
    char text[1200];
    print_message("case %zu: %s\n", i, tirenv_diag_format(d, text, sizeof text));
    assert_int_equal(status, want);
    assert_string_equal(d->file, file);
    assert_int_equal(d->line, line);
    assert_int_equal(d->column, column);
    assert_string_equal(d->field, field);
    assert_non_null(strstr(d->message, says));
}

void tirenv_test_write_temp(char path[64], const char *what, const char *text)
{
    snprintf(path, 64, "/tmp/tirenv_test_%s_XXXXXX", what);
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *fp = fdopen(fd, "w");
    assert_non_null(fp);
    assert_true(fputs(text, fp) >= 0);
    assert_int_equal(fclose(fp), 0);
}

tirenv_profile *tirenv_test_flat_ground(void)
{
    const double zero = 0;
    tirenv_profile *p = tirenv_profile_alloc(1, &zero, &zero);
    assert_non_null(p);
    return p;
}

int tirenv_test_ring_dfdz(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                          double dz, int *belt)
{
    double fx, F, dF, Fp, Fm, F0;
    assert_int_equal(tirenv_ring_forces(r, p, x, z, &fx, &F, &dF, NULL, NULL), 0);
    *belt = tirenv_ring_belt_contacts(r) > 0;
    if (F < 10)
        return 0;
    tirenv_ring_forces(r, p, x, z + dz, &fx, &Fp, NULL, NULL, NULL);
    tirenv_ring_forces(r, p, x, z - dz, &fx, &Fm, NULL, NULL, NULL);
    tirenv_ring_forces(r, p, x, z, &fx, &F0, NULL, NULL, NULL);
    if (fabs((Fp - F0) - (F0 - Fm)) > 1e-6 * fabs(dF) * dz)
        return 0; /* a kink or jump within dz: one-sided differences disagree */
    assert_near(dF, (Fp - Fm) / (2 * dz), 0, 1e-6);
    return 1;
}

const double tirenv_test_fit_design[6][3] = {{0.28, 0.10, 0.05},  {0.33, 0.30, 0.075},
                                             {0.38, 0.15, 0.10},  {0.43, 0.05, 0.025},
                                             {0.33, 0.20, 0.05},  {0.38, 0.30, 0.025}};

void tirenv_test_model_case(tirenv_model *m, double R0, const double design[3],
                            const char *name, size_t n, tirenv_case *c)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    c->split = TIRENV_SPLIT_TRAIN;
    c->contact_length = design[0];
    c->L = design[1];
    c->H = design[2];
    tirenv_diag diag;
    assert_int_equal(tirenv_model_load_for_contact_length(m, c->contact_length, &c->load,
                                                          &diag), TIRENV_OK);
    assert_int_equal(tirenv_curve_alloc(&c->curve, n), TIRENV_OK);
    const double x_0 = tirenv_xN_origin(R0, c->contact_length, c->L, c->H);
    for (size_t j = 0; j < n; ++j) {
        c->curve.x_N[j] = -0.2 + 1.2 * (double)j / (double)(n - 1);
        c->curve.x[j] = x_0 * (1 - c->curve.x_N[j]);
    }
    assert_int_equal(tirenv_case_predict_model(m, c, c->curve.h, &diag), TIRENV_OK);
}

/* The data set's network, one Levenberg-Marquardt restart on its train and control cases
 * (data/dataset, R0 0.68 m): a cmocka group setup, *state the network. */
int tirenv_test_nn_setup(void **state)
{
    tirenv_dataset ds;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_dataset_read(TIRENV_DATA_DIR "/dataset", 0.68, &ds, &diag)) {
        print_error("data set: %s\n", diag.message);
        return -1;
    }
    tirenv_samples s[3];
    double *x[3] = {NULL, NULL, NULL}, *y[3] = {NULL, NULL, NULL};
    int status = TIRENV_OK;
    for (int sp = 0; sp < 3 && !status; ++sp)
        status = tirenv_samples_from_dataset(&ds, (tirenv_split)sp, &s[sp], &x[sp], &y[sp],
                                             &diag);
    tirenv_nn *nn = NULL;
    tirenv_train_settings set = tirenv_train_default(tirenv_trainer_lm);
    set.restarts = 1;
    if (!status)
        status = tirenv_train(tirenv_trainer_lm, &set, &s[0], &s[1], &s[2], &nn, NULL, &diag);
    for (int sp = 0; sp < 3; ++sp) {
        free(x[sp]);
        free(y[sp]);
    }
    tirenv_dataset_free(&ds);
    if (status) {
        print_error("training: %s\n", diag.message);
        return -1;
    }
    *state = nn;
    return 0;
}

int tirenv_test_nn_teardown(void **state)
{
    tirenv_nn_free(*state);
    return 0;
}

uint64_t tirenv_test_fnv1a(const unsigned char *b, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t j = 0; j < n; ++j) {
        h ^= b[j];
        h *= 0x100000001b3ull;
    }
    return h;
}

double tirenv_test_uniform(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

size_t tirenv_test_jumps(tirenv_model *m, const tirenv_profile *p, tirenv_rng *rng,
                         double *dh_max, double *dfx_max)
{
    tirenv_diag diag;
    const size_t n = tirenv_profile_size(p);
    const double *X = tirenv_profile_x(p);
    size_t checked = 0;
    for (size_t v = 0; v < n; ++v)
        for (int o = 0; o < 3; ++o) {
            /* The vertex itself, and places where a node's ray or the vertex's angle may fall
             * near a node. */
            const double x = X[v] + (o == 0 ? 0 : (o == 1 ? 1 : -1) *
                                                      (0.1 + 0.3 * tirenv_rng_uniform(rng)));
            tirenv_point a, b, c;
            assert_int_equal(tirenv_model_eval(m, x, &a, &diag), TIRENV_OK);
            assert_int_equal(tirenv_model_eval(m, x + 1e-12, &b, &diag), TIRENV_OK);
            assert_int_equal(tirenv_model_eval(m, x - 1e-12, &c, &diag), TIRENV_OK);
            *dh_max = fmax(*dh_max, fmax(fabs(b.h - a.h), fabs(c.h - a.h)));
            *dfx_max = fmax(*dfx_max, fmax(fabs(b.fx - a.fx), fabs(c.fx - a.fx)));
            ++checked;
        }
    return checked;
}
