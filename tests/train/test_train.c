/* Training (docs/models.md section 6): each trainer learns a known smooth function on the embedded
 * data set's 28-case design, early stopping keeps the best control weights, restarts keep the
 * best restart, runs are bit-for-bit reproducible, and model files round-trip exactly and
 * refuse every kind of damage with a message naming file and field.
 * SPDX-License-Identifier: Apache-2.0
 *
 * The known function: h = H * (1 + tanh(5(x_N - 0.55) + 4(L - 0.2) - 6(l_c - 0.355)))/2, a
 * smooth rise to H that depends on all four inputs, sampled like a rig curve at 21 x_N from
 * -0.1 to 1 for each of the 28 designed cases (19 train / 5 control / 4 validation, so the
 * validation cases are unseen combinations of the training values, as in the paper).
 *
 * Tolerances on what a trainer reaches. Training is deterministic, so on this platform each
 * figure is reproduced exactly; the bounds are the measured validation RMS errors (seed 1)
 * times 2 to 3, which absorbs a different libm or compiler nudging the trajectory:
 *   lm        100 epochs    measured 0.033 mm   bound 0.1 mm   (the tightest)
 *   backprop  1000 epochs   measured 0.728 mm   bound 1.5 mm   (learning rate 0.03)
 *   rprop     1000 epochs   measured 0.554 mm   bound 2.0 mm
 * (measured with tirenv's xoshiro256** initialisation; with GSL's mt19937 until version 0.1
 * they were 0.033, 0.466 and 0.947 mm, and backprop's bound 1.0 mm, now only 1.4 times its
 * figure, became 1.5 to keep the factor 2)
 * (H is 25 to 100 mm, so even the loosest bound is a 2 % fit.) Early stopping's kept error is
 * compared with the best one the progress callback saw to 1e-12 relative: the two are the
 * same sum of squares taken in a different order (and units). */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <jansson.h>

#include "tirenv/dataset.h"
#include "tirenv/nn_file.h"

enum { POINTS = 21, MAX_SAMPLES = 28 * POINTS };

static double known_h(double x_N, double l_c, double H, double L)
{
    return H * 0.5 * (1 + tanh(5 * (x_N - 0.55) + 4 * (L - 0.2) - 6 * (l_c - 0.355)));
}

typedef struct {
    double x[3][MAX_SAMPLES * TIRENV_NN_INPUTS];
    double y[3][MAX_SAMPLES];
    size_t start[3][28 + 1];   /* curve offsets: one curve per case */
    tirenv_samples s[3];  /* by tirenv_split */
} synthetic;

static synthetic *make_synthetic(void)
{
    synthetic *d = calloc(1, sizeof *d);
    assert_non_null(d);
    size_t n_cases, n[3] = {0, 0, 0};
    const tirenv_case_design *des = tirenv_dataset_design(&n_cases);
    assert_int_equal(n_cases, 28);
    size_t n_curves[3] = {0, 0, 0};
    for (size_t c = 0; c < n_cases; ++c) {
        const int sp = des[c].split;
        d->start[sp][n_curves[sp]++] = n[sp];
        for (size_t k = 0; k < POINTS; ++k) {
            double *u = d->x[sp] + n[sp] * TIRENV_NN_INPUTS;
            u[TIRENV_NN_X_N] = -0.1 + 1.1 * (double)k / (POINTS - 1);
            u[TIRENV_NN_CONTACT_LENGTH] = des[c].contact_length;
            u[TIRENV_NN_HEIGHT] = des[c].H;
            u[TIRENV_NN_LENGTH] = des[c].L;
            d->y[sp][n[sp]++] = known_h(u[0], u[1], u[2], u[3]);
        }
    }
    assert_int_equal(n[TIRENV_SPLIT_TRAIN], 19 * POINTS);
    assert_int_equal(n[TIRENV_SPLIT_CONTROL], 5 * POINTS);
    assert_int_equal(n[TIRENV_SPLIT_VALIDATION], 4 * POINTS);
    for (int sp = 0; sp < 3; ++sp) {
        d->start[sp][n_curves[sp]] = n[sp];
        d->s[sp] = (tirenv_samples){.n = n[sp], .n_in = TIRENV_NN_INPUTS, .x = d->x[sp],
                                    .y = d->y[sp], .n_curves = n_curves[sp],
                                    .curve_start = d->start[sp]};
    }
    return d;
}

static int setup(void **state)
{
    *state = make_synthetic();
    return 0;
}

static int teardown(void **state)
{
    free(*state);
    return 0;
}

static int train(const synthetic *d, const tirenv_trainer_type *type,
                 const tirenv_train_settings *s, tirenv_nn **nn, tirenv_train_report *r)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_train(type, s, &d->s[0], &d->s[1], &d->s[2], nn, r, &diag);
    if (status)
        print_error("tirenv_train: %s: %s\n", diag.field, diag.message);
    return status;
}

/* Every trainer fits the function to its stated error; the report is consistent. */
static void test_learns(void **state)
{
    const synthetic *d = *state;
    static const struct {
        const char *name;
        size_t epochs;
        double learning_rate;
        double bound;       /* validation RMS, m */
    } cases[] = {
        {"lm", 100, 0, 0.1e-3},
        {"backprop", 1000, 0.03, 1.5e-3},
        {"rprop", 1000, 0, 2.0e-3},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        const tirenv_trainer_type *type = tirenv_trainer_type_find(cases[k].name);
        assert_non_null(type);
        assert_string_equal(tirenv_trainer_type_name(type), cases[k].name);
        /* The paper's network: the known function is not even about x_N = 1. */
        tirenv_train_settings s = tirenv_train_paper(type);
        s.max_epochs = cases[k].epochs;
        s.restarts = 1;
        s.patience = 0;
        if (cases[k].learning_rate > 0)
            s.backprop.learning_rate = cases[k].learning_rate;
        tirenv_nn *nn = NULL;
        tirenv_train_report r;
        assert_int_equal(train(d, type, &s, &nn, &r), TIRENV_OK);
        print_message("%-8s %4zu epochs (best %4zu), %.3f s: RMS train %.4f, control %.4f, "
                      "validation %.4f mm (bound %.1f), max %.3f mm\n",
                      cases[k].name, r.epochs, r.best_epoch, r.wall_time,
                      r.error[0].rms * 1e3, r.error[1].rms * 1e3, r.error[2].rms * 1e3,
                      cases[k].bound * 1e3, r.error[2].max * 1e3);
        assert_true(r.error[TIRENV_SPLIT_VALIDATION].rms < cases[k].bound);
        assert_int_equal(r.epochs, cases[k].epochs);
        assert_int_equal(r.total_epochs, cases[k].epochs);
        assert_true(r.best_epoch >= 1 && r.best_epoch <= r.epochs);
        assert_int_equal(r.stop, TIRENV_TRAIN_MAX_EPOCHS);
        for (int sp = 0; sp < 3; ++sp) {
            assert_int_equal(r.error[sp].n, d->s[sp].n);
            assert_true(r.error[sp].max >= r.error[sp].rms);
            const tirenv_train_error e = tirenv_train_evaluate(nn, &d->s[sp]);
            assert_true(e.rms == r.error[sp].rms && e.max == r.error[sp].max);
        }
        tirenv_nn_free(nn);
    }
    assert_null(tirenv_trainer_type_find("sgd"));
    assert_null(tirenv_trainer_type_find(NULL));
    size_t n = 0;
    for (const tirenv_trainer_type *const *t = tirenv_trainer_types(); *t; ++t)
        ++n;
    assert_int_equal(n, 3);
}

/* Batch back-propagation lowers the error. */
static void test_variants(void **state)
{
    const synthetic *d = *state;
    tirenv_train_settings s = tirenv_train_default(tirenv_trainer_backprop);
    s.max_epochs = 300;
    s.backprop.online = 0;
    s.backprop.learning_rate = 0.002;
    tirenv_nn *nn = NULL, *nn0 = NULL;
    tirenv_train_report r, r0;
    assert_int_equal(train(d, tirenv_trainer_backprop, &s, &nn, &r), TIRENV_OK);
    s.max_epochs = 1;
    assert_int_equal(train(d, tirenv_trainer_backprop, &s, &nn0, &r0), TIRENV_OK);
    assert_true(r.error[0].rms < 0.5 * r0.error[0].rms);
    tirenv_nn_free(nn);
    tirenv_nn_free(nn0);
}

/* What the progress callback saw, per restart and epoch. */
typedef struct {
    size_t calls;
    size_t epochs[8];          /* per restart */
    double best_rms[8];        /* least control RMS per restart */
    size_t best_epoch[8];
    size_t cancel_at;          /* total calls after which to cancel (0: never) */
} trace;

static int record(const tirenv_train_progress *p, void *data)
{
    trace *t = data;
    ++t->calls;
    assert_true(p->restart < 8);
    assert_int_equal(p->epoch, t->epochs[p->restart] + 1);
    t->epochs[p->restart] = p->epoch;
    if (p->epoch == 1 || p->control_rms < t->best_rms[p->restart]) {
        t->best_rms[p->restart] = p->control_rms;
        t->best_epoch[p->restart] = p->epoch;
    }
    assert_true(p->best_rms <= p->control_rms);
    return t->cancel_at && t->calls >= t->cancel_at;
}

/* The kept network is the one of least control error over all epochs of all restarts; a
 * patience stop comes exactly `patience` epochs after the best. LM on this set overfits after
 * a few dozen steps, so the control error does turn up. */
static void test_early_stopping(void **state)
{
    const synthetic *d = *state;
    tirenv_train_settings s = tirenv_train_paper(tirenv_trainer_lm);
    s.restarts = 3;
    s.max_epochs = 400;
    s.patience = 10;
    trace t;
    memset(&t, 0, sizeof t);
    s.progress = record;
    s.progress_data = &t;
    tirenv_nn *nn = NULL;
    tirenv_train_report r;
    assert_int_equal(train(d, tirenv_trainer_lm, &s, &nn, &r), TIRENV_OK);
    size_t total = 0, best_restart = 0;
    for (size_t k = 0; k < 3; ++k) {
        total += t.epochs[k];
        if (t.best_rms[k] < t.best_rms[best_restart])
            best_restart = k;
    }
    assert_int_equal(r.total_epochs, total);
    assert_int_equal(t.calls, total);
    assert_int_equal(r.restart, best_restart);
    assert_int_equal(r.epochs, t.epochs[best_restart]);
    /* The initial weights are never the best here, so the best is an epoch the trace saw. */
    assert_int_equal(r.best_epoch, t.best_epoch[best_restart]);
    assert_near(r.error[TIRENV_SPLIT_CONTROL].rms, t.best_rms[best_restart], 0, 1e-12);
    /* A patience stop comes exactly `patience` epochs after the best, in every restart. */
    size_t patience_stops = 0;
    for (size_t k = 0; k < 3; ++k)
        if (t.epochs[k] < s.max_epochs) {
            assert_int_equal(t.epochs[k], t.best_epoch[k] + s.patience);
            ++patience_stops;
        }
    assert_true(patience_stops > 0);
    assert_int_equal(r.epochs, r.stop == TIRENV_TRAIN_PATIENCE ? r.best_epoch + s.patience
                                                               : s.max_epochs);
    assert_true(r.best_time <= r.wall_time);
    tirenv_nn_free(nn);

    /* Cancelling keeps the best so far and says so. */
    memset(&t, 0, sizeof t);
    t.cancel_at = 5;
    assert_int_equal(train(d, tirenv_trainer_lm, &s, &nn, &r), TIRENV_OK);
    assert_int_equal(r.stop, TIRENV_TRAIN_CANCELLED);
    assert_int_equal(r.epochs, 5);
    assert_int_equal(r.total_epochs, 5);
    assert_near(r.error[TIRENV_SPLIT_CONTROL].rms, t.best_rms[0], 0, 1e-12);
    tirenv_nn_free(nn);
}

/* The same seed gives the same weights to the bit, for every trainer (online backprop's
 * shuffle included); another seed gives other weights. */
static void test_reproducible(void **state)
{
    const synthetic *d = *state;
    for (const tirenv_trainer_type *const *type = tirenv_trainer_types(); *type; ++type) {
        tirenv_train_settings s = tirenv_train_default(*type);
        s.restarts = 2;
        s.max_epochs = 30;
        s.seed = 2385;
        tirenv_nn *a, *b, *c;
        tirenv_train_report ra, rb, rc;
        assert_int_equal(train(d, *type, &s, &a, &ra), TIRENV_OK);
        assert_int_equal(train(d, *type, &s, &b, &rb), TIRENV_OK);
        s.seed = 2386;
        assert_int_equal(train(d, *type, &s, &c, &rc), TIRENV_OK);
        const size_t p = tirenv_nn_n_weights(a);
        assert_memory_equal(tirenv_nn_weights(a), tirenv_nn_weights(b), p * sizeof(double));
        assert_memory_not_equal(tirenv_nn_weights(a), tirenv_nn_weights(c),
                                p * sizeof(double));
        assert_int_equal(ra.restart, rb.restart);
        assert_int_equal(ra.best_epoch, rb.best_epoch);
        assert_true(ra.error[2].rms == rb.error[2].rms);
        tirenv_nn_free(a);
        tirenv_nn_free(b);
        tirenv_nn_free(c);
    }
}

/* _e cases: each bad setting or sample set is refused with EINVAL naming it. */
static void test_refusals(void **state)
{
    const synthetic *d = *state;
    enum { LR, MOMENTUM, ETA_PLUS, DELTA, MU_DEC, MU_INC, EPOCHS, RESTARTS, TOPOLOGY,
           INPUTS, ENSEMBLE, FORM, LOSS, LM_TOO_LARGE, N_BAD };
    static const char *const field[N_BAD] = {"backprop", "backprop", "rprop", "rprop", "lm",
                                             "lm", "settings", "settings", "topology",
                                             "topology", "ensemble", "form", "form",
                                             "topology"};
    for (int k = 0; k < N_BAD; ++k) {
        tirenv_train_settings s = tirenv_train_default(tirenv_trainer_lm);
        switch (k) {
        case LR: s.backprop.learning_rate = 0; break;
        case MOMENTUM: s.backprop.momentum = 1; break;
        case ETA_PLUS: s.rprop.eta_plus = 0.9; break;
        case DELTA: s.rprop.delta0 = s.rprop.delta_max * 2; break;
        case MU_DEC: s.lm.tau = 0; break;
        case MU_INC: s.lm.mu_max = NAN; break;
        case EPOCHS: s.max_epochs = 0; break;
        case RESTARTS: s.restarts = 0; break;
        case TOPOLOGY: s.topology.size[2] = 2; break;
        case INPUTS: s.topology.size[0] = 3; break;
        case ENSEMBLE: s.ensemble = 0; break;
        case FORM: s.input = (tirenv_nn_input_form)7; break;
        case LOSS: s.loss = (tirenv_train_loss)-1; break;
        case LM_TOO_LARGE: /* 4-64-64-64-1: 8,705 weights, LM's two squares 1.2 GB */
            s.topology = (tirenv_nn_topology){.n_layers = 5, .size = {4, 64, 64, 64, 1}};
            break;
        }
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        tirenv_nn *nn = (tirenv_nn *)&diag;  /* must come back NULL */
        assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &d->s[0], &d->s[1], &d->s[2],
                                      &nn, NULL, &diag), TIRENV_EINVAL);
        assert_null(nn);
        assert_string_equal(diag.field, field[k]);
    }
    tirenv_train_settings s = tirenv_train_default(tirenv_trainer_lm);
    tirenv_nn *nn;
    tirenv_diag diag;
    const tirenv_samples empty = {.n = 0, .n_in = 4, .x = NULL, .y = NULL};
    assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &empty, NULL, NULL, &nn, NULL, NULL),
                     TIRENV_EINVAL);
    double x[8], y[2];
    memcpy(x, d->x[0], sizeof x);
    memcpy(y, d->y[0], sizeof y);
    x[6] = NAN;
    const tirenv_samples bad = {.n = 2, .n_in = 4, .x = x, .y = y};
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &d->s[0], &bad, NULL, &nn, NULL,
                                  &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "control");
    assert_int_equal(diag.line, 2);
    /* A solver that is not one: the settings are refused naming lm. */
    s = tirenv_train_paper(tirenv_trainer_lm);
    s.lm.solver = (tirenv_lm_solver)1;
    x[6] = 0.1;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &bad, NULL, NULL, &nn, NULL, &diag),
                     TIRENV_EINVAL);
    assert_string_equal(diag.field, "lm");
}

/* FNV-1a over little-endian IEEE bits: a known answer, computed independently (Python's
 * struct.pack('<dd', 1.0, -2.5) through the FNV-1a 64 loop). */
static void test_fingerprint(void **state)
{
    (void)state;
    const double x[] = {1.0}, y[] = {-2.5};
    const tirenv_samples s = {.n = 1, .n_in = 1, .x = x, .y = y};
    const tirenv_samples none = {.n = 0, .n_in = 1, .x = NULL, .y = NULL};
    assert_true(tirenv_samples_fingerprint(&s, TIRENV_FNV1A64_OFFSET) ==
                UINT64_C(0x2f20b4ea1c69d79c));
    assert_true(tirenv_samples_fingerprint(&none, TIRENV_FNV1A64_OFFSET) ==
                TIRENV_FNV1A64_OFFSET);
    assert_true(tirenv_samples_fingerprint(NULL, 42) == 42);
}

/* Samples of a data set: the points of each case of the split, inputs in Table 1's order. */
static void test_samples_from_dataset(void **state)
{
    (void)state;
    tirenv_case cases[3];
    memset(cases, 0, sizeof cases);
    const tirenv_split split[3] = {TIRENV_SPLIT_TRAIN, TIRENV_SPLIT_CONTROL,
                                   TIRENV_SPLIT_TRAIN};
    for (size_t c = 0; c < 3; ++c) {
        snprintf(cases[c].name, sizeof cases[c].name, "C%zu", c);
        cases[c].split = split[c];
        cases[c].contact_length = 0.28 + 0.05 * (double)c;
        cases[c].L = 0.1 * (double)(c + 1);
        cases[c].H = 0.025 * (double)(c + 1);
        assert_int_equal(tirenv_curve_alloc(&cases[c].curve, 2 + c), TIRENV_OK);
        for (size_t k = 0; k < 2 + c; ++k) {
            cases[c].curve.x_N[k] = 0.25 * (double)k;
            cases[c].curve.h[k] = 1e-3 * (double)(10 * c + k);
        }
    }
    tirenv_dataset ds = {.dir = "synthetic", .n = 3, .cases = cases};
    tirenv_samples s;
    double *x, *y;
    assert_int_equal(tirenv_samples_from_dataset(&ds, TIRENV_SPLIT_TRAIN, &s, &x, &y, NULL),
                     TIRENV_OK);
    assert_int_equal(s.n, 2 + 4);
    assert_int_equal(s.n_in, TIRENV_NN_INPUTS);
    const double *u = s.x + 3 * TIRENV_NN_INPUTS;  /* case 2, point 1 */
    assert_true(u[TIRENV_NN_X_N] == 0.25 && u[TIRENV_NN_CONTACT_LENGTH] == cases[2].contact_length &&
                u[TIRENV_NN_HEIGHT] == cases[2].H && u[TIRENV_NN_LENGTH] == cases[2].L);
    assert_true(s.y[3] == cases[2].curve.h[1]);
    free(x);
    free(y);
    assert_int_equal(tirenv_samples_from_dataset(&ds, TIRENV_SPLIT_VALIDATION, &s, &x, &y,
                                                 NULL), TIRENV_OK);
    assert_int_equal(s.n, 0);
    assert_null(x);
    tirenv_curve_free(&cases[1].curve);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_samples_from_dataset(&ds, TIRENV_SPLIT_CONTROL, &s, &x, &y, &diag),
                     TIRENV_EINVAL);
    assert_non_null(strstr(diag.message, "C1"));
    tirenv_curve_free(&cases[0].curve);
    tirenv_curve_free(&cases[2].curve);
}

/* ---- Model files ---- */

static char *slurp(const char *path, size_t *n)
{
    FILE *fp = fopen(path, "rb");
    assert_non_null(fp);
    fseek(fp, 0, SEEK_END);
    const long len = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *buf = malloc((size_t)len + 1);
    assert_int_equal(fread(buf, 1, (size_t)len, fp), (size_t)len);
    buf[len] = '\0';
    fclose(fp);
    *n = (size_t)len;
    return buf;
}

static void spit(const char *path, const char *buf, size_t n)
{
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite(buf, 1, n, fp), n);
    fclose(fp);
}

typedef struct {
    tirenv_nn *nn;
    tirenv_train_record rec;
    char path[64], bad[64];
} model_file;

static model_file *make_model_file(const synthetic *d)
{
    model_file *m = calloc(1, sizeof *m);
    tirenv_train_settings s = tirenv_train_default(tirenv_trainer_lm);
    s.restarts = 2;
    s.ensemble = 2;
    s.even_width = 0.3;
    s.target = TIRENV_NN_TARGET_H_OVER_H;
    s.loss = TIRENV_TRAIN_LOSS_CURVES;
    s.max_epochs = 20;
    s.seed = 2385;
    assert_int_equal(train(d, tirenv_trainer_lm, &s, &m->nn, &m->rec.report), TIRENV_OK);
    snprintf(m->rec.trainer, sizeof m->rec.trainer, "lm");
    m->rec.settings = s;
    m->rec.settings.progress = NULL;
    uint64_t h = TIRENV_FNV1A64_OFFSET;
    for (int sp = 0; sp < 3; ++sp)
        h = tirenv_samples_fingerprint(&d->s[sp], h);
    m->rec.fingerprint = h;
    m->rec.R0 = 0.68;
    snprintf(m->rec.data, sizeof m->rec.data, "synthetic \"28 cases\"");
    snprintf(m->path, sizeof m->path, "test_train_%ld.json", (long)getpid());
    snprintf(m->bad, sizeof m->bad, "test_train_%ld_bad.json", (long)getpid());
    return m;
}

static void free_model_file(model_file *m)
{
    remove(m->path);
    remove(m->bad);
    tirenv_nn_free(m->nn);
    free(m);
}

/* Write, read: the same bits everywhere; write the read one again: the same bytes. */
static void test_file_round_trip(void **state)
{
    const synthetic *d = *state;
    model_file *m = make_model_file(d);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_write_json(m->path, m->nn, &m->rec, &diag), TIRENV_OK);
    tirenv_nn *nn = NULL;
    tirenv_train_record rec;
    assert_int_equal(tirenv_nn_read_json(m->path, &nn, &rec, &diag), TIRENV_OK);
    assert_non_null(nn);
    const size_t p = tirenv_nn_n_weights(m->nn);
    assert_int_equal(tirenv_nn_n_weights(nn), p);
    assert_memory_equal(tirenv_nn_weights(nn), tirenv_nn_weights(m->nn), p * sizeof(double));
    double a[4], b[4], c[4], e[4], oa[2], ob[2];
    tirenv_nn_scaling(m->nn, a, b, &oa[0], &oa[1]);
    tirenv_nn_scaling(nn, c, e, &ob[0], &ob[1]);
    assert_memory_equal(a, c, sizeof a);
    assert_memory_equal(b, e, sizeof b);
    assert_memory_equal(oa, ob, sizeof oa);
    tirenv_nn_input_range(m->nn, a, b);
    tirenv_nn_input_range(nn, c, e);
    assert_memory_equal(a, c, sizeof a);
    assert_memory_equal(b, e, sizeof b);
    for (size_t k = 0; k < d->s[2].n; ++k) {
        const double ya = tirenv_nn_run(m->nn, d->s[2].x + 4 * k);
        const double yb = tirenv_nn_run(nn, d->s[2].x + 4 * k);
        assert_memory_equal(&ya, &yb, sizeof ya);
    }
    assert_string_equal(rec.trainer, "lm");
    assert_string_equal(rec.data, m->rec.data);
    assert_true(rec.fingerprint == m->rec.fingerprint);
    assert_true(rec.R0 == m->rec.R0);
    assert_true(rec.settings.seed == 2385 && rec.settings.restarts == 2 &&
                rec.settings.max_epochs == 20 && rec.settings.patience == m->rec.settings.patience);
    const tirenv_train_settings *s0 = &m->rec.settings, *s1 = &rec.settings;
    assert_true(s1->backprop.learning_rate == s0->backprop.learning_rate &&
                s1->backprop.momentum == s0->backprop.momentum &&
                s1->backprop.online == s0->backprop.online);
    assert_memory_equal(&s1->rprop, &s0->rprop, sizeof s0->rprop);  /* doubles only */
    assert_true(s1->lm.solver == s0->lm.solver && s1->lm.tau == s0->lm.tau &&
                s1->lm.mu_max == s0->lm.mu_max);
    const tirenv_train_report *r0 = &m->rec.report, *r1 = &rec.report;
    assert_true(r0->restart == r1->restart && r0->epochs == r1->epochs &&
                r0->best_epoch == r1->best_epoch && r0->total_epochs == r1->total_epochs &&
                r0->stop == r1->stop && r0->best_time == r1->best_time &&
                r0->wall_time == r1->wall_time);
    assert_memory_equal(r0->error, r1->error, sizeof r0->error);
    /* An ensemble of two even-input networks, and what made it. */
    assert_int_equal(tirenv_nn_n_members(nn), 2);
    tirenv_nn_input_form in;
    tirenv_nn_target_form out;
    tirenv_nn_form(nn, &in, &out);
    assert_int_equal(in, TIRENV_NN_INPUT_EVEN);
    assert_int_equal(out, TIRENV_NN_TARGET_H_OVER_H);
    assert_true(s1->input == in && s1->target == out && s1->ensemble == s0->ensemble &&
                s1->loss == s0->loss && s1->even_width == 0.3);
    assert_true(tirenv_nn_even_width(nn) == 0.3);
    assert_int_equal(r1->members, 2);
    assert_memory_equal(r1->member_restart, r0->member_restart, 2 * sizeof(size_t));

    /* The record is optional on both sides. */
    tirenv_nn *bare = NULL;
    assert_int_equal(tirenv_nn_read_json(m->path, &bare, NULL, NULL), TIRENV_OK);
    tirenv_nn_free(bare);

    size_t n1, n2;
    char *first = slurp(m->path, &n1);
    assert_int_equal(tirenv_nn_write_json(m->path, nn, &rec, &diag), TIRENV_OK);
    char *second = slurp(m->path, &n2);
    assert_int_equal(n1, n2);
    assert_memory_equal(first, second, n1);
    free(first);
    free(second);

    /* Writing refuses what JSON cannot hold. */
    double *w = tirenv_nn_weights(nn);
    w[3] = INFINITY;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_write_json(m->bad, nn, &rec, &diag), TIRENV_EINVAL);
    assert_string_equal(diag.field, "layers");
    assert_int_equal(access(m->bad, F_OK), -1);  /* nothing written */
    tirenv_nn_free(nn);
    free_model_file(m);
}

/* A damaged copy of the good file made through jansson: mutate(root) edits it. */
static void damaged(const model_file *m, void (*mutate)(json_t *root))
{
    json_error_t err;
    json_t *root = json_load_file(m->path, 0, &err);
    assert_non_null(root);
    mutate(root);
    assert_int_equal(json_dump_file(root, m->bad, JSON_INDENT(1) | JSON_REAL_PRECISION(17) |
                                                      JSON_PRESERVE_ORDER), 0);
    json_decref(root);
}

static json_t *at(json_t *root, const char *a, const char *b)
{
    json_t *v = json_object_get(root, a);
    return b ? json_object_get(v, b) : v;
}

static void m_version(json_t *r) { json_object_set_new(r, "version", json_integer(4)); }
static void m_format(json_t *r) { json_object_set_new(r, "format", json_string("fann")); }
static void m_topology(json_t *r) { json_array_set_new(at(r, "topology", NULL), 1, json_integer(9)); }
static void m_std(json_t *r) { json_array_set_new(at(r, "scaling", "input_std"), 2, json_real(0)); }
/* Layer l of member k. */
static json_t *layer_of(json_t *r, size_t k, size_t l)
{
    json_t *member = json_array_get(at(r, "members", NULL), k);
    return json_array_get(json_object_get(member, "layers"), l);
}
static void m_weight_type(json_t *r)
{
    json_t *rows = json_object_get(layer_of(r, 0, 0), "weights");
    json_array_set_new(json_array_get(rows, 1), 3, json_string("0.5"));
}
static void m_weight_value(json_t *r)
{
    json_t *bias = json_object_get(layer_of(r, 1, 1), "bias");
    json_array_set_new(bias, 0, json_real(json_number_value(json_array_get(bias, 0)) + 1e-9));
}
static void m_form(json_t *r) { json_object_set_new(r, "input_form", json_string("odd")); }
static void m_width(json_t *r) { json_object_set_new(r, "even_width", json_real(-0.1)); }
static void m_target(json_t *r) { json_object_set_new(r, "target", json_string("h/L")); }
static void m_member_count(json_t *r) { json_array_remove(at(r, "members", NULL), 1); }
static void m_loss(json_t *r) { json_object_set_new(at(r, "training", NULL), "loss", json_string("max")); }
static void m_member_restart(json_t *r)
{
    json_array_set_new(json_object_get(at(r, "training", "result"), "members"), 0,
                       json_integer(7));
}
static void m_missing(json_t *r) { json_object_del(r, "scaling"); }
static void m_trainer(json_t *r) { json_object_set_new(at(r, "training", NULL), "trainer", json_string("sgd")); }
static void m_mu_dec(json_t *r)
{
    json_t *lm = json_object_get(at(r, "training", "settings"), "lm");
    json_object_set_new(lm, "tau", json_real(-1.5));
}
static void m_range(json_t *r) { json_array_set_new(at(r, "input_range", "min"), 0, json_real(5.0)); }
static void m_inputs(json_t *r) { json_array_set_new(at(r, "inputs", NULL), 2, json_string("obstacle_length_m")); }
static void m_stop(json_t *r) { json_object_set_new(at(r, "training", "result"), "stop", json_string("bored")); }
static void m_errors(json_t *r)
{
    json_t *e = json_object_get(at(r, "training", "errors_m"), "validation");
    json_object_set_new(e, "rms", json_real(-1e-3));
}
static void m_top(json_t *r) { json_object_set_new(r, "activation", json_string("relu")); }
/* Keys the format does not know: a typo would leave what the key sets at its default. */
static void m_key_top(json_t *r) { json_object_set_new(r, "weigths", json_array()); }
static void m_key_layer(json_t *r) { json_object_set_new(layer_of(r, 1, 0), "bais", json_real(0.5)); }
static void m_key_law(json_t *r) { json_object_set_new(at(r, "training", "data"), "contact_lwa", json_object()); }
static void m_key_error(json_t *r)
{
    json_object_set_new(json_object_get(at(r, "training", "errors_m"), "train"), "mean",
                        json_real(1e-3));
}

/* Every damage refused with EPARSE (EIO for a missing file), the file named, and the field
 * and message saying what is wrong. */
static void test_file_refusals(void **state)
{
    const synthetic *d = *state;
    model_file *m = make_model_file(d);
    assert_int_equal(tirenv_nn_write_json(m->path, m->nn, &m->rec, NULL), TIRENV_OK);
    static const struct {
        void (*mutate)(json_t *root);
        const char *field;
        const char *message;   /* a piece of it */
    } cases[] = {
        {m_version, "version", "this build reads versions 1 to 3"},
        {m_format, "format", "not a tirenv network model file"},
        {m_topology, "members[0].layers[0].bias", "8 numbers; expected 9"},
        {m_std, "scaling.input_std", "element 2 is 0; expected > 0"},
        {m_weight_type, "members[0].layers[0].weights[1]",
         "element 3: expected a number, found a string"},
        {m_weight_value, "checksum", "altered or corrupted"},
        {m_form, "input_form", "'odd'; expected 'paper'"},
        {m_width, "even_width", "expected > 0"},
        {m_target, "target", "'h/L'"},
        {m_member_count, "checksum", "altered or corrupted"},
        {m_loss, "training.loss", "'max'"},
        {m_member_restart, "training.result.members", "expected a restart number"},
        {m_missing, "scaling", "missing"},
        {m_trainer, "training.trainer", "unknown trainer 'sgd'"},
        {m_mu_dec, "training.settings", "lm"},
        {m_range, "input_range", "min 5 > max"},
        {m_inputs, "inputs", "expected 'obstacle_height_m'"},
        {m_stop, "training.result.stop", "'bored'"},
        {m_errors, "training.errors_m.validation.rms", "expected >= 0"},
        {m_top, "activation", "expected an object, found a string"},
        {m_key_top, "weigths", "unknown key in the top-level object"},
        {m_key_layer, "members[1].layers[0].bais", "expected one of bias, weights"},
        {m_key_law, "training.data.contact_lwa", "unknown key in training.data"},
        {m_key_error, "training.errors_m.train.mean", "expected one of n, rms, max"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        damaged(m, cases[k].mutate);
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        tirenv_nn *nn = (tirenv_nn *)&diag;
        assert_int_equal(tirenv_nn_read_json(m->bad, &nn, NULL, &diag), TIRENV_EPARSE);
        assert_null(nn);
        assert_string_equal(diag.file, m->bad);
        assert_string_equal(diag.field, cases[k].field);
        if (!strstr(diag.message, cases[k].message))
            fail_msg("case %zu: message '%s' lacks '%s'", k, diag.message, cases[k].message);
    }

    /* Damage jansson itself catches: truncation, an empty file, a duplicate key, not an
     * object. The line of the error is kept. */
    size_t n;
    char *good = slurp(m->path, &n);
    char dup[] = "{\"format\": \"tirenv-nn\", \"format\": \"tirenv-nn\"}";
    const struct {
        const char *text;
        size_t len;
        const char *message;
        int has_line;
    } raw[] = {
        {good, n / 2, "not valid JSON", 1},
        {good, 0, "not valid JSON", 0},
        {dup, sizeof dup - 1, "duplicate", 1},
        {"[1, 2]", 6, "expected a JSON object", 0},
        {"{\"format\": \"tirenv-nn\", \"version\": 1e999}", 41, "not valid JSON", 1},
    };
    for (size_t k = 0; k < sizeof raw / sizeof raw[0]; ++k) {
        spit(m->bad, raw[k].text, raw[k].len);
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        tirenv_nn *nn = NULL;
        assert_int_equal(tirenv_nn_read_json(m->bad, &nn, NULL, &diag), TIRENV_EPARSE);
        assert_null(nn);
        assert_string_equal(diag.file, m->bad);
        if (!strstr(diag.message, raw[k].message))
            fail_msg("raw case %zu: message '%s' lacks '%s'", k, diag.message,
                     raw[k].message);
        if (raw[k].has_line)
            assert_true(diag.line > 0);
    }
    free(good);

    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_nn *nn = NULL;
    assert_int_equal(tirenv_nn_read_json("no/such/model.json", &nn, NULL, &diag), TIRENV_EIO);
    assert_string_equal(diag.file, "no/such/model.json");
    free_model_file(m);
}


/* The ensemble is the mean of the restarts best on control: ranked by control error, the
 * same networks bit for bit whatever K, and its output the mean of theirs. Each restart
 * depends on its own number only, so asking for more members changes nothing but K. */
static void test_ensemble(void **state)
{
    const synthetic *d = *state;
    tirenv_train_settings s = tirenv_train_paper(tirenv_trainer_lm);
    s.restarts = 4;
    s.max_epochs = 30;
    s.seed = 77;
    tirenv_nn *net[3];
    tirenv_train_report rep[3];
    const size_t K[3] = {4, 2, 1};
    for (int i = 0; i < 3; ++i) {
        s.ensemble = K[i];
        assert_int_equal(train(d, tirenv_trainer_lm, &s, &net[i], &rep[i]), TIRENV_OK);
        assert_int_equal(tirenv_nn_n_members(net[i]), K[i]);
        assert_int_equal(rep[i].members, K[i]);
        assert_int_equal(rep[i].restart, rep[i].member_restart[0]);
    }
    /* All four restarts, ranked by control error, each restart once. */
    int seen[4] = {0, 0, 0, 0};
    double last = 0;
    const size_t p = tirenv_nn_n_weights(net[2]);
    for (size_t k = 0; k < 4; ++k) {
        assert_true(rep[0].member_restart[k] < 4);
        seen[rep[0].member_restart[k]] = 1;
        tirenv_nn *m = tirenv_nn_member(net[0], k);
        assert_non_null(m);
        const double e = tirenv_train_evaluate(m, &d->s[TIRENV_SPLIT_CONTROL]).rms;
        assert_true(e >= last);
        last = e;
        if (k < 2) {  /* the two best are the 2-ensemble's, bit for bit */
            tirenv_nn *m2 = tirenv_nn_member(net[1], k);
            assert_memory_equal(tirenv_nn_weights(m), tirenv_nn_weights(m2),
                                p * sizeof(double));
            assert_int_equal(rep[1].member_restart[k], rep[0].member_restart[k]);
            tirenv_nn_free(m2);
        }
        if (k == 0)   /* the best alone is the single model */
            assert_memory_equal(tirenv_nn_weights(m), tirenv_nn_weights(net[2]),
                                p * sizeof(double));
        tirenv_nn_free(m);
    }
    assert_true(seen[0] && seen[1] && seen[2] && seen[3]);
    /* The model is the mean of its members: the same sums in another order, so to a few
     * ulp of the outputs (~0.1 m): 1e-15 m. */
    tirenv_nn *m0 = tirenv_nn_member(net[1], 0), *m1 = tirenv_nn_member(net[1], 1);
    for (size_t k = 0; k < d->s[2].n; ++k) {
        const double *x = d->s[2].x + 4 * k;
        const double y = tirenv_nn_run(net[1], x);
        assert_near(y, 0.5 * (tirenv_nn_run(m0, x) + tirenv_nn_run(m1, x)), 1e-15, 0);
    }
    assert_true(rep[1].error[2].rms == tirenv_train_evaluate(net[1], &d->s[2]).rms);
    tirenv_nn_free(m0);
    tirenv_nn_free(m1);
    for (int i = 0; i < 3; ++i)
        tirenv_nn_free(net[i]);
}

/* The curves loss: over one curve it is the points loss (every weight stays 1); early
 * stopping keeps the network of least mean per-curve control RMS, as the progress callback
 * saw it; samples without curves are refused. */
static void test_loss_curves(void **state)
{
    const synthetic *d = *state;
    tirenv_train_settings s = tirenv_train_paper(tirenv_trainer_lm);
    s.restarts = 1;
    s.max_epochs = 40;
    size_t one[3][2];
    tirenv_samples whole[3];
    for (int sp = 0; sp < 3; ++sp) {
        one[sp][0] = 0;
        one[sp][1] = d->s[sp].n;
        whole[sp] = d->s[sp];
        whole[sp].n_curves = 1;
        whole[sp].curve_start = one[sp];
    }
    tirenv_nn *a, *b;
    tirenv_train_report ra, rb;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &whole[0], &whole[1], &whole[2], &a,
                                  &ra, &diag), TIRENV_OK);
    s.loss = TIRENV_TRAIN_LOSS_CURVES;
    assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &whole[0], &whole[1], &whole[2], &b,
                                  &rb, &diag), TIRENV_OK);
    assert_near(rb.error[2].rms, ra.error[2].rms, 0, 1e-12);
    tirenv_nn_free(a);
    tirenv_nn_free(b);

    trace t;
    memset(&t, 0, sizeof t);
    s.progress = record;
    s.progress_data = &t;
    s.patience = 10;
    s.max_epochs = 200;
    assert_int_equal(train(d, tirenv_trainer_lm, &s, &a, &ra), TIRENV_OK);
    const tirenv_samples *c = &d->s[TIRENV_SPLIT_CONTROL];
    double y[MAX_SAMPLES], mean = 0;
    tirenv_nn_run_batch(a, c->n, c->x, y);
    for (size_t i = 0; i < c->n_curves; ++i) {
        double sum = 0;
        for (size_t k = c->curve_start[i]; k < c->curve_start[i + 1]; ++k)
            sum += (y[k] - c->y[k]) * (y[k] - c->y[k]);
        mean += sqrt(sum / (double)(c->curve_start[i + 1] - c->curve_start[i]));
    }
    mean /= (double)c->n_curves;
    print_message("curves loss: mean control RMS %.4f mm, best seen %.4f mm\n", mean * 1e3,
                  t.best_rms[0] * 1e3);
    assert_near(mean, t.best_rms[0], 0, 1e-9);
    tirenv_nn_free(a);

    s.progress = NULL;
    tirenv_samples flat = d->s[0];
    flat.n_curves = 0;
    flat.curve_start = NULL;
    tirenv_diag_clear(&diag);
    a = (tirenv_nn *)&diag;
    assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &flat, NULL, NULL, &a, NULL, &diag),
                     TIRENV_EINVAL);
    assert_null(a);
    assert_string_equal(diag.field, "loss");
}

/* The h/H target: the network learns h/H, its output is H times that, and the loss is on
 * h/H, so a curve scaled with its obstacle is learnt the same at every height. On the
 * known function h = H g(x_N, l_c, L), h/H does not depend on H at all: the model's
 * h/H is then nearly the same for two heights, which the h target does not give. */
static void test_target_h_over_H(void **state)
{
    const synthetic *d = *state;
    tirenv_train_settings s = tirenv_train_paper(tirenv_trainer_lm);
    s.restarts = 1;
    s.max_epochs = 100;
    s.patience = 0;
    double spread[2];
    for (int over_H = 0; over_H < 2; ++over_H) {
        s.target = over_H ? TIRENV_NN_TARGET_H_OVER_H : TIRENV_NN_TARGET_H;
        tirenv_nn *nn;
        tirenv_train_report r;
        assert_int_equal(train(d, tirenv_trainer_lm, &s, &nn, &r), TIRENV_OK);
        tirenv_nn_target_form f;
        tirenv_nn_form(nn, NULL, &f);
        assert_int_equal(f, s.target);
        spread[over_H] = 0;
        for (double x_N = 0; x_N <= 1; x_N += 0.125) {
            const double lo[4] = {x_N, 0.33, 0.025, 0.2}, hi[4] = {x_N, 0.33, 0.1, 0.2};
            spread[over_H] = fmax(spread[over_H], fabs(tirenv_nn_run(nn, lo) / 0.025 -
                                                       tirenv_nn_run(nn, hi) / 0.1));
        }
        print_message("target %s: validation RMS %.4f mm; largest |h/H at H = 25 mm - at "
                      "100 mm| %.5f\n", tirenv_nn_target_form_name(s.target),
                      r.error[2].rms * 1e3, spread[over_H]);
        tirenv_nn_free(nn);
    }
    assert_true(spread[1] < 0.5 * spread[0]);
    /* H = 0 cannot scale a target. */
    double x[4 * 2], y[2] = {0.01, 0.02};
    memcpy(x, d->x[0], sizeof x);
    x[TIRENV_NN_HEIGHT] = 0;
    const tirenv_samples bad = {.n = 2, .n_in = 4, .x = x, .y = y};
    s.target = TIRENV_NN_TARGET_H_OVER_H;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_nn *nn = NULL;
    assert_int_equal(tirenv_train(tirenv_trainer_lm, &s, &bad, NULL, NULL, &nn, NULL, &diag),
                     TIRENV_EINVAL);
    assert_string_equal(diag.field, "obstacle_height_m");
}

/* A model file of version 1 (one network, the paper's forms), written by tirenv before
 * ensembles: it still reads, as what it was, and gives the outputs the version that wrote it
 * gave (printed there with %a, so exact); written again it becomes version 3 and reads back
 * to the same bits. */
static void test_file_version1(void **state)
{
    (void)state;
    static const double ref[][5] = {
        {-0.1, 0.28, 0.1, 0.1, 0x1.3ae1a5d0cee2p-11},
        {0.5, 0.33, 0.05, 0.3, 0x1.44545da87e353p-6},
        {1, 0.38, 0.075, 0.2, 0x1.f03d5321d0f65p-5},
        {0.9, 0.43, 0.025, 0.05, 0x1.6622d5b25b8d1p-7},
    };
    tirenv_nn *nn = NULL, *again = NULL;
    tirenv_train_record rec, rec2;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_read_json(TIRENV_TEST_DATA "/nn-v1.json", &nn, &rec, &diag),
                     TIRENV_OK);
    assert_int_equal(tirenv_nn_n_members(nn), 1);
    tirenv_nn_input_form in;
    tirenv_nn_target_form out;
    tirenv_nn_form(nn, &in, &out);
    assert_int_equal(in, TIRENV_NN_INPUT_PAPER);
    assert_int_equal(out, TIRENV_NN_TARGET_H);
    assert_string_equal(rec.data, "data/dataset");
    assert_true(rec.settings.ensemble == 1 && rec.settings.loss == TIRENV_TRAIN_LOSS_POINTS &&
                rec.settings.input == TIRENV_NN_INPUT_PAPER && rec.report.members == 1 &&
                rec.report.member_restart[0] == rec.report.restart);
    for (size_t k = 0; k < sizeof ref / sizeof ref[0]; ++k)
        assert_true(tirenv_nn_run(nn, ref[k]) == ref[k][4]);
    char path[64];
    snprintf(path, sizeof path, "test_train_v1_%ld.json", (long)getpid());
    assert_int_equal(tirenv_nn_write_json(path, nn, &rec, &diag), TIRENV_OK);
    assert_int_equal(tirenv_nn_read_json(path, &again, &rec2, &diag), TIRENV_OK);
    size_t n;
    char *text = slurp(path, &n);
    assert_non_null(strstr(text, "\"version\": 3"));
    free(text);
    assert_memory_equal(tirenv_nn_weights(again), tirenv_nn_weights(nn),
                        tirenv_nn_n_weights(nn) * sizeof(double));
    for (size_t k = 0; k < sizeof ref / sizeof ref[0]; ++k)
        assert_true(tirenv_nn_run(again, ref[k]) == ref[k][4]);
    remove(path);
    tirenv_nn_free(nn);
    tirenv_nn_free(again);
}

/* The first decimal of the first contact-law load in text (after "load_N") changed in place,
 * by 0.1 N or less: the knots stay ascending, a law that reads. */
static void edit_knot(char *text)
{
    char *p = strstr(text, "\"load_N\"");
    assert_non_null(p);
    p = strchr(p, '.');
    assert_non_null(p);
    ++p;
    *p = *p == '9' ? '8' : (char)(*p + 1);
}

/* A version 2 file (written by tirenv before version 3) with a contact law: it still reads,
 * its checksum as before, so a knot edited in it goes unseen, as it always did. Written again
 * it is version 3, whose checksum covers the knots: the same edit is refused, naming the file
 * and the checksum, and the law reads back the same bits. */
static void test_file_version2_law(void **state)
{
    (void)state;
    tirenv_nn *nn = NULL, *again = NULL;
    tirenv_train_record rec, rec2;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    size_t n;
    char *text = slurp(TIRENV_TEST_DATA "/nn-v2-law.json", &n);
    assert_non_null(strstr(text, "\"version\": 2"));
    char v2[64], v3[64];
    snprintf(v2, sizeof v2, "test_train_v2_%ld.json", (long)getpid());
    snprintf(v3, sizeof v3, "test_train_v3_%ld.json", (long)getpid());
    edit_knot(text);
    spit(v2, text, n);
    free(text);
    assert_int_equal(tirenv_nn_read_json(TIRENV_TEST_DATA "/nn-v2-law.json", &nn, &rec, &diag),
                     TIRENV_OK);
    assert_true(rec.law.n >= 2);
    assert_int_equal(tirenv_nn_read_json(v2, &again, &rec2, &diag), TIRENV_OK);
    assert_true(rec2.law.load[0] != rec.law.load[0]);
    tirenv_nn_free(again);
    again = NULL;

    assert_int_equal(tirenv_nn_write_json(v3, nn, &rec, &diag), TIRENV_OK);
    assert_int_equal(tirenv_nn_read_json(v3, &again, &rec2, &diag), TIRENV_OK);
    assert_int_equal(rec2.law.n, rec.law.n);
    assert_memory_equal(rec2.law.load, rec.law.load, rec.law.n * sizeof(double));
    assert_memory_equal(rec2.law.l_c, rec.law.l_c, rec.law.n * sizeof(double));
    tirenv_nn_free(again);
    again = NULL;
    text = slurp(v3, &n);
    assert_non_null(strstr(text, "\"version\": 3"));
    edit_knot(text);
    spit(v3, text, n);
    free(text);
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_read_json(v3, &again, &rec2, &diag), TIRENV_EPARSE);
    assert_null(again);
    assert_string_equal(diag.file, v3);
    assert_string_equal(diag.field, "checksum");
    assert_non_null(strstr(diag.message, "training.data.contact_law"));
    remove(v2);
    remove(v3);
    tirenv_nn_free(nn);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_learns),
        cmocka_unit_test(test_variants),
        cmocka_unit_test(test_early_stopping),
        cmocka_unit_test(test_reproducible),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_fingerprint),
        cmocka_unit_test(test_samples_from_dataset),
        cmocka_unit_test(test_file_round_trip),
        cmocka_unit_test(test_file_refusals),
        cmocka_unit_test(test_ensemble),
        cmocka_unit_test(test_loss_curves),
        cmocka_unit_test(test_target_h_over_H),
        cmocka_unit_test(test_file_version1),
        cmocka_unit_test(test_file_version2_law),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
