/* tirenv-bench-nn: the empirical model's network, timed against FANN (the library users would
 * otherwise pick) in one run: training (every trainer, and FANN's RPROP) on one data set, then
 * inference (single samples and batches) on the same 4-8-1 network.
 *
 * Data: --data DIR reads a data set; by default the embedded one (data/dataset) when it is
 * there. Otherwise, or with --synthetic, the cases of the embedded data set's design
 * (tirenv_dataset_design: 28 cleats, 19 train / 5 control / 4 validation, the paper's F, J, R
 * and case AB validating) are simulated with the springs model of the default tire, through
 * the public model API, at 45 positions x_N = -0.1 .. 1.0 each.
 *
 * Timing: CLOCK_MONOTONIC, one thread; inference rates are the best of --repeats runs of at
 * least 0.2 s each over 4096 samples spread over the training ranges (a working set that stays
 * in cache, as a simulation calling the model at one wheel would). Training is timed once per
 * trainer with one restart and the same seed, so the figures compare algorithms, not luck.
 * SPDX-License-Identifier: Apache-2.0 */
#include <errno.h>
#include <math.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <doublefann.h>

#include "tirenv/dataset.h"
#include "tirenv/model.h"
#include "tirenv/nn.h"
#include "tirenv/profile.h"
#include "tirenv/train.h"

enum { N_BENCH = 4096, POINTS = 45 };

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void die(const char *what, const tirenv_diag *diag)
{
    char buf[1200];
    fprintf(stderr, "tirenv-bench-nn: %s: %s\n", what,
            diag ? tirenv_diag_format(diag, buf, sizeof buf) : "failed");
    exit(2);
}

/* ---- Data ---- */

typedef struct {
    double *x[3], *y[3];
    size_t *start[3];      /* synthetic data: curve offsets (one curve per case) */
    tirenv_samples s[3];   /* by tirenv_split */
    char source[600];
} data_set;

static void add_sample(data_set *d, size_t *cap, int sp, const double u[4], double h)
{
    if (d->s[sp].n == cap[sp]) {
        cap[sp] = cap[sp] ? 2 * cap[sp] : 256;
        d->x[sp] = realloc(d->x[sp], cap[sp] * 4 * sizeof(double));
        d->y[sp] = realloc(d->y[sp], cap[sp] * sizeof(double));
        if (!d->x[sp] || !d->y[sp])
            die("out of memory", NULL);
    }
    memcpy(d->x[sp] + 4 * d->s[sp].n, u, 4 * sizeof(double));
    d->y[sp][d->s[sp].n++] = h;
}

/* The springs model over each designed cleat at the load giving the case's contact length
 * (the length its tread touches), at the x_N grid mapped to positions by docs/models.md
 * section 1. */
static void synthetic_data(data_set *d)
{
    size_t n_cases, cap[3] = {0, 0, 0};
    const tirenv_case_design *des = tirenv_dataset_design(&n_cases);
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (!m)
        die("springs model", NULL);
    const double t0 = now_s();
    for (size_t c = 0; c < n_cases; ++c) {
        double load;
        tirenv_profile *cleat = tirenv_profile_cleat(des[c].L, des[c].H);
        if (!cleat ||
            tirenv_model_load_for_contact_length(m, des[c].contact_length, &load, &diag) ||
            tirenv_model_set(m, cleat, load, &diag))
            die(des[c].name, &diag);
        const double x_0 = tirenv_xN_origin(tire.springs.R0, des[c].contact_length, des[c].L,
                                            des[c].H);
        for (size_t k = 0; k < POINTS; ++k) {
            const double x_N = -0.1 + 1.1 * (double)k / (POINTS - 1);
            tirenv_point pt;
            if (tirenv_model_eval(m, x_0 * (1 - x_N), &pt, &diag))
                die(des[c].name, &diag);
            const double u[4] = {x_N, des[c].contact_length, des[c].H, des[c].L};
            add_sample(d, cap, des[c].split, u, pt.h);
        }
        tirenv_profile_free(cleat);
    }
    /* Every case is one curve of POINTS samples, in the order they were added. */
    for (int sp = 0; sp < 3; ++sp) {
        const size_t n_curves = d->s[sp].n / POINTS;
        if (!(d->start[sp] = malloc((n_curves + 1) * sizeof *d->start[sp])))
            die("out of memory", NULL);
        for (size_t c = 0; c <= n_curves; ++c)
            d->start[sp][c] = c * POINTS;
        d->s[sp] = (tirenv_samples){.n = d->s[sp].n, .n_in = 4, .x = d->x[sp], .y = d->y[sp],
                                    .n_curves = n_curves, .curve_start = d->start[sp]};
    }
    snprintf(d->source, sizeof d->source,
             "synthetic: springs model, default tire (R0 %.3f m), the embedded data set's 28 "
             "cases (19/5/4), %d points each at x_N -0.1..1 (%.2f s to simulate)",
             tire.springs.R0, POINTS, now_s() - t0);
    tirenv_model_free(m);
}

static void read_data(data_set *d, const char *dir)
{
    tirenv_dataset ds;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const tirenv_tire tire = tirenv_tire_default();
    if (tirenv_dataset_read(dir, tire.springs.R0, &ds, &diag))
        die(dir, &diag);
    for (int sp = 0; sp < 3; ++sp) {
        double *x, *y;
        if (tirenv_samples_from_dataset(&ds, (tirenv_split)sp, &d->s[sp], &x, &y, &diag))
            die(dir, &diag);
        d->x[sp] = x;
        d->y[sp] = y;
    }
    snprintf(d->source, sizeof d->source, "data set %s (%zu cases)", dir, ds.n);
    tirenv_dataset_free(&ds);
}

/* ---- Training ---- */

typedef struct {
    const char *name;
    size_t epochs, best_epoch;
    double wall, best_time;    /* s */
    tirenv_train_error e[3];
} train_row;

static void print_row(const train_row *r)
{
    printf("  %-22s %8zu %8zu %9.3f %9.3f %8.4f %8.4f %8.4f %8.3f\n", r->name, r->epochs,
           r->best_epoch, r->wall, r->best_time, r->e[0].rms * 1e3, r->e[1].rms * 1e3,
           r->e[2].rms * 1e3, r->e[2].max * 1e3);
    fflush(stdout);
}

static tirenv_nn *run_trainer(const data_set *d, const char *label,
                              const tirenv_trainer_type *type, const tirenv_train_settings *s,
                              train_row *row)
{
    tirenv_nn *nn;
    tirenv_train_report r;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_train(type, s, &d->s[0], &d->s[1], &d->s[2], &nn, &r, &diag))
        die(label, &diag);
    *row = (train_row){.name = label, .epochs = r.epochs, .best_epoch = r.best_epoch,
                       .wall = r.wall_time, .best_time = r.best_time};
    memcpy(row->e, r.error, sizeof row->e);
    print_row(row);
    return nn;
}

/* FANN on the same data, scaled with the same training-set statistics (FANN has no built-in
 * standardisation), its own Nguyen-Widrow initialisation (fann_init_weights, rand() seeded),
 * iRprop- (FANN_TRAIN_RPROP, its default constants, which are ours), plain squared error.
 * fann_train_on_data calls back after every epoch; the callback tests the control set, keeps
 * the best weights and stops after `patience` epochs without improvement: the same early
 * stopping as tirenv_train. */
typedef struct {
    struct fann_train_data *control;
    fann_type *best;
    double best_mse, t0, best_time;
    unsigned int best_epoch, epochs, patience;
} fann_watch;

static fann_watch watch;

static int FANN_API fann_progress(struct fann *ann, struct fann_train_data *train,
                                  unsigned int max_epochs, unsigned int between,
                                  float desired, unsigned int epochs)
{
    (void)train;
    (void)max_epochs;
    (void)between;
    (void)desired;
    const double mse = fann_test_data(ann, watch.control);
    watch.epochs = epochs;
    if (mse < watch.best_mse) {
        watch.best_mse = mse;
        watch.best_epoch = epochs;
        watch.best_time = now_s() - watch.t0;
        memcpy(watch.best, ann->weights, ann->total_connections * sizeof(fann_type));
    }
    return epochs - watch.best_epoch >= watch.patience ? -1 : 0;
}

static struct fann_train_data *fann_data(const tirenv_samples *s, const double mean[4],
                                         const double std[4], double om, double os)
{
    struct fann_train_data *t = fann_create_train((unsigned)s->n, 4, 1);
    if (!t)
        die("fann_create_train", NULL);
    for (size_t k = 0; k < s->n; ++k) {
        for (int i = 0; i < 4; ++i)
            t->input[k][i] = (s->x[4 * k + i] - mean[i]) / std[i];
        t->output[k][0] = (s->y[k] - om) / os;
    }
    return t;
}

static struct fann *fann_net(void)
{
    struct fann *ann = fann_create_standard(3, 4, 8, 1);
    if (!ann)
        die("fann_create_standard", NULL);
    /* FANN's sigmoid is 1/(1 + exp(-2 s x)): steepness 0.5 is the paper's logistic. */
    fann_set_activation_function_hidden(ann, FANN_SIGMOID);
    fann_set_activation_steepness_hidden(ann, 0.5);
    fann_set_activation_function_output(ann, FANN_LINEAR);
    fann_set_activation_steepness_output(ann, 1.0);
    return ann;
}

static tirenv_train_error fann_errors(struct fann *ann, const tirenv_samples *s,
                                      const double mean[4], const double std[4], double om,
                                      double os)
{
    tirenv_train_error e = {.n = s->n, .rms = 0, .max = 0};
    double sum2 = 0;
    for (size_t k = 0; k < s->n; ++k) {
        fann_type u[4];
        for (int i = 0; i < 4; ++i)
            u[i] = (s->x[4 * k + i] - mean[i]) / std[i];
        const double y = om + os * fann_run(ann, u)[0];
        const double dy = fabs(y - s->y[k]);
        sum2 += dy * dy;
        e.max = fmax(e.max, dy);
    }
    e.rms = s->n ? sqrt(sum2 / (double)s->n) : 0;
    return e;
}

static void fann_train_row(const data_set *d, unsigned long seed, unsigned int max_epochs,
                           unsigned int patience, train_row *row)
{
    tirenv_nn_topology top = tirenv_nn_topology_default();
    tirenv_nn *scaler = tirenv_nn_alloc(&top);
    double mean[4], std[4], om, os;
    tirenv_nn_fit_scaling(scaler, d->s[0].n, d->s[0].x, d->s[0].y, NULL);
    tirenv_nn_scaling(scaler, mean, std, &om, &os);
    tirenv_nn_free(scaler);
    struct fann_train_data *train = fann_data(&d->s[0], mean, std, om, os);
    watch = (fann_watch){.control = fann_data(d->s[1].n ? &d->s[1] : &d->s[0], mean, std, om,
                                              os),
                         .best_mse = INFINITY, .patience = patience};
    struct fann *ann = fann_net();
    watch.best = malloc(ann->total_connections * sizeof(fann_type));
    srand((unsigned)seed);
    fann_init_weights(ann, train);
    fann_set_training_algorithm(ann, FANN_TRAIN_RPROP);
    fann_set_train_error_function(ann, FANN_ERRORFUNC_LINEAR);
    fann_set_callback(ann, fann_progress);
    watch.t0 = now_s();
    fann_train_on_data(ann, train, max_epochs, 1, 0.0f);
    const double wall = now_s() - watch.t0;
    memcpy(ann->weights, watch.best, ann->total_connections * sizeof(fann_type));
    *row = (train_row){.name = "FANN rprop", .epochs = watch.epochs,
                       .best_epoch = watch.best_epoch, .wall = wall,
                       .best_time = watch.best_time};
    for (int sp = 0; sp < 3; ++sp)
        row->e[sp] = fann_errors(ann, &d->s[sp], mean, std, om, os);
    print_row(row);
    free(watch.best);
    fann_destroy_train(watch.control);
    fann_destroy_train(train);
    fann_destroy(ann);
}

/* ---- Inference ---- */

/* Our net in FANN's connections: FANN numbers neurons layer by layer, each layer followed by
 * its bias neuron (value 1), and sees raw inputs, so the input scaling is folded into the
 * first layer (w/std, b - sum w*mean/std) and the output scaling into the last. */
static struct fann *fann_copy_of(const tirenv_nn *nn)
{
    struct fann *ann = fann_net();
    const double *w = tirenv_nn_weights_const(nn);
    double mean[4], std[4], om, os;
    tirenv_nn_scaling(nn, mean, std, &om, &os);
    const unsigned in0 = 0, h0 = 5, out0 = 14;  /* first neuron of each layer; biases 4, 13 */
    for (unsigned j = 0; j < 8; ++j) {
        double b = w[tirenv_nn_weight_index(nn, 1, 0, j)];
        for (unsigned i = 0; i < 4; ++i) {
            const double wij = w[tirenv_nn_weight_index(nn, 1, 1 + i, j)];
            fann_set_weight(ann, in0 + i, h0 + j, wij / std[i]);
            b -= wij * mean[i] / std[i];
        }
        fann_set_weight(ann, in0 + 4, h0 + j, b);
    }
    for (unsigned j = 0; j < 8; ++j)
        fann_set_weight(ann, h0 + j, out0, os * w[tirenv_nn_weight_index(nn, 2, 1 + j, 0)]);
    fann_set_weight(ann, h0 + 8, out0, om + os * w[tirenv_nn_weight_index(nn, 2, 0, 0)]);
    return ann;
}

typedef enum { RUN_SINGLE, RUN_BATCH, RUN_FANN } run_kind;

static volatile double sink;

/* Predictions per second: the best of `repeats` timed runs of at least 0.2 s each. */
static double rate(run_kind kind, tirenv_nn *nn, struct fann *ann, const double *x, double *y,
                   int repeats)
{
    double best = 0;
    for (int r = 0; r < repeats; ++r) {
        size_t done = 0;
        const double t0 = now_s();
        double t;
        do {
            double acc = 0;
            switch (kind) {
            case RUN_SINGLE:
                for (size_t s = 0; s < N_BENCH; ++s)
                    acc += tirenv_nn_run(nn, x + 4 * s);
                break;
            case RUN_BATCH:
                tirenv_nn_run_batch(nn, N_BENCH, x, y);
                acc = y[N_BENCH - 1];
                break;
            case RUN_FANN:
                for (size_t s = 0; s < N_BENCH; ++s)
                    acc += fann_run(ann, (fann_type *)(x + 4 * s))[0];
                break;
            }
            sink = acc;
            done += N_BENCH;
            t = now_s() - t0;
        } while (t < 0.2);
        best = fmax(best, (double)done / t);
    }
    return best;
}

static void usage(FILE *fp)
{
    fputs("usage: tirenv-bench-nn [--data DIR | --synthetic] [--backprop-epochs N]\n"
          "                       [--repeats N] [--seed S] [--lm-seeds N]\n"
          "\n"
          "Times the network's trainers (backprop for the paper's 2e5 cycles by default, rprop,\n"
          "lm, FANN's RPROP) and its inference against FANN's\n"
          "fann_run on the same 4-8-1 network. Data: DIR, else the embedded data set if it is\n"
          "built (" TIRENV_DATA_DIR "/dataset), else (or with --synthetic) the embedded data\n"
          "set's 28 cases simulated with the springs model. lm with its default settings is\n"
          "run for --lm-seeds seeds (default 10) to show the spread of what it reaches.\n",
          fp);
}

static long parse_long(const char *opt, const char *s, long min)
{
    char *end;
    errno = 0;
    const long v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < min) {
        fprintf(stderr, "tirenv-bench-nn: %s: expected an integer >= %ld, got '%s'\n", opt, min,
                s);
        exit(1);
    }
    return v;
}

int main(int argc, char *argv[])
{
    const char *dir = NULL;
    size_t backprop_epochs = 200000;
    int repeats = 5, synthetic = 0;
    unsigned long seed = 1;
    long lm_seeds = 10;
    for (int k = 1; k < argc; ++k) {
        const int more = k + 1 < argc;
        if (strcmp(argv[k], "--help") == 0 || strcmp(argv[k], "-h") == 0) {
            usage(stdout);
            return 0;
        } else if (strcmp(argv[k], "--data") == 0 && more) {
            dir = argv[++k];
        } else if (strcmp(argv[k], "--synthetic") == 0) {
            synthetic = 1;
        } else if (strcmp(argv[k], "--lm-seeds") == 0 && more) {
            lm_seeds = parse_long(argv[k], argv[k + 1], 1);
            ++k;
        } else if (strcmp(argv[k], "--backprop-epochs") == 0 && more) {
            backprop_epochs = (size_t)parse_long(argv[k], argv[k + 1], 1);
            ++k;
        } else if (strcmp(argv[k], "--repeats") == 0 && more) {
            repeats = (int)parse_long(argv[k], argv[k + 1], 1);
            ++k;
        } else if (strcmp(argv[k], "--seed") == 0 && more) {
            seed = (unsigned long)parse_long(argv[k], argv[k + 1], 0);
            ++k;
        } else {
            usage(stderr);
            return 1;
        }
    }

    data_set d;
    memset(&d, 0, sizeof d);
    if (!dir && !synthetic && access(TIRENV_DATA_DIR "/dataset/cases.csv", R_OK) == 0)
        dir = TIRENV_DATA_DIR "/dataset";
    if (dir && !synthetic)
        read_data(&d, dir);
    else
        synthetic_data(&d);
    printf("tirenv-bench-nn: %s\n", d.source);
    printf("samples: train %zu, control %zu, validation %zu; seed %lu; one thread\n\n",
           d.s[0].n, d.s[1].n, d.s[2].n, seed);

    /* Training. */
    printf("training the paper's network (x_N in, h out, loss over points; 1 restart each, "
           "same seed; errors in mm; times in s):\n");
    printf("  %-22s %8s %8s %9s %9s %8s %8s %8s %8s\n", "trainer", "epochs", "best_ep",
           "wall", "to_best", "rms_trn", "rms_ctl", "rms_val", "max_val");
    train_row bp, rp, lm, lm4, lmd, fn;
    tirenv_train_settings s = tirenv_train_paper(tirenv_trainer_backprop);
    s.seed = seed;
    s.max_epochs = backprop_epochs;
    char bp_label[64];
    snprintf(bp_label, sizeof bp_label, "backprop %zu ep", backprop_epochs);
    tirenv_nn_free(run_trainer(&d, bp_label, tirenv_trainer_backprop, &s, &bp));
    s = tirenv_train_paper(tirenv_trainer_rprop);
    s.seed = seed;
    s.restarts = 1;
    tirenv_nn_free(run_trainer(&d, "rprop", tirenv_trainer_rprop, &s, &rp));
    s = tirenv_train_paper(tirenv_trainer_lm);
    s.seed = seed;
    s.restarts = 1;
    tirenv_nn_free(run_trainer(&d, "lm (cholesky)", tirenv_trainer_lm, &s, &lm));
    s = tirenv_train_paper(tirenv_trainer_lm);
    s.seed = seed;
    char lm_label[64], lmd_label[64];
    snprintf(lm_label, sizeof lm_label, "lm paper, best of %zu", s.restarts);
    tirenv_nn *net = run_trainer(&d, lm_label, tirenv_trainer_lm, &s, &lm4);
    s = tirenv_train_default(tirenv_trainer_lm);
    s.seed = seed;
    snprintf(lmd_label, sizeof lmd_label, "lm default, %zu of %zu", s.ensemble, s.restarts);
    tirenv_nn *ens = run_trainer(&d, lmd_label, tirenv_trainer_lm, &s, &lmd);
    const tirenv_train_settings rs = tirenv_train_default(tirenv_trainer_rprop);
    fann_train_row(&d, seed, (unsigned)rs.max_epochs, (unsigned)rs.patience, &fn);


    /* The default lm over several seeds: what a user gets, not one lucky draw. */
    printf("\nlm with its default settings, seeds %lu to %lu (validation RMS mm, wall s):\n",
           seed, seed + (unsigned long)lm_seeds - 1);
    double *val = malloc((size_t)lm_seeds * sizeof *val), t_max = 0;
    long no_worse = 0;
    for (long k = 0; k < lm_seeds; ++k) {
        tirenv_train_settings sk = tirenv_train_default(tirenv_trainer_lm);
        sk.seed = seed + (unsigned long)k;
        tirenv_nn *nk;
        tirenv_train_report rk;
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        if (tirenv_train(tirenv_trainer_lm, &sk, &d.s[0], &d.s[1], &d.s[2], &nk, &rk, &diag))
            die("lm", &diag);
        tirenv_nn_free(nk);
        val[k] = rk.error[2].rms;
        t_max = fmax(t_max, rk.wall_time);
        no_worse += val[k] <= bp.e[2].rms;
        printf("  seed %-4lu %8.4f %7.3f%s\n", sk.seed, val[k] * 1e3, rk.wall_time,
               val[k] <= bp.e[2].rms ? "" : "   (worse than backprop)");
    }
    for (long i = 1; i < lm_seeds; ++i)  /* insertion sort for the median */
        for (long j = i; j > 0 && val[j] < val[j - 1]; --j) {
            const double tmp = val[j];
            val[j] = val[j - 1];
            val[j - 1] = tmp;
        }
    const double median = lm_seeds % 2 ? val[lm_seeds / 2]
                                       : 0.5 * (val[lm_seeds / 2 - 1] + val[lm_seeds / 2]);
    printf("\n  target: lm's validation RMS no worse than backprop's after %zu epochs (%.4f mm, "
           "%.1f s) in at most 1/100 of its time:\n", backprop_epochs, bp.e[2].rms * 1e3,
           bp.wall);
    printf("    lm seed %lu (the paper's network, best restart): %.4f mm in %.3f s = 1/%.0f of the time: %s\n",
           seed, lm4.e[2].rms * 1e3, lm4.wall, bp.wall / lm4.wall,
           lm4.e[2].rms <= bp.e[2].rms && lm4.wall * 100 <= bp.wall ? "met" : "MISSED");
    printf("    over %ld seeds: median %.4f mm, %ld of %ld no worse, slowest %.3f s = 1/%.0f\n\n",
           lm_seeds, median * 1e3, no_worse, lm_seeds, t_max, bp.wall / t_max);
    free(val);

    /* Inference, on the paper's network (the best of the LM restarts), then the default. */
    double lo[4], hi[4];
    tirenv_nn_input_range(net, lo, hi);
    double *x = malloc(N_BENCH * 4 * sizeof *x), *y = malloc(N_BENCH * sizeof *y);
    unsigned long long state = 0x9e3779b97f4a7c15ull ^ seed;
    for (size_t k = 0; k < N_BENCH * 4; ++k) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const double u = (double)(state >> 11) * 0x1p-53;
        x[k] = lo[k % 4] + u * (hi[k % 4] - lo[k % 4]);
    }
    struct fann *ann = fann_copy_of(net);
    double max_diff = 0, max_y = 0;
    tirenv_nn_run_batch(net, N_BENCH, x, y);
    for (size_t k = 0; k < N_BENCH; ++k) {
        max_diff = fmax(max_diff, fabs(fann_run(ann, (fann_type *)(x + 4 * k))[0] - y[k]));
        max_y = fmax(max_y, fabs(y[k]));
    }
    printf("inference, 4-8-1 (predictions per second, best of %d):\n", repeats);
    printf("  FANN copy of our weights: max |difference| %.3g m over %d samples (|h| up to "
           "%.3g m)\n", max_diff, N_BENCH, max_y);
    const double r_single = rate(RUN_SINGLE, net, ann, x, y, repeats);
    const double r_batch = rate(RUN_BATCH, net, ann, x, y, repeats);
    const double r_fann = rate(RUN_FANN, net, ann, x, y, repeats);
    printf("  tirenv_nn_run        %8.1f M/s  (%.1f ns each)\n", r_single / 1e6, 1e9 / r_single);
    printf("  tirenv_nn_run_batch  %8.1f M/s  (%.1f ns each)\n", r_batch / 1e6, 1e9 / r_batch);
    printf("  fann_run (double)    %8.1f M/s  (%.1f ns each; FANN has no batch call)\n",
           r_fann / 1e6, 1e9 / r_fann);
    printf("  targets: single >= 10 M/s %s, batch >= 20 M/s %s, faster than fann_run: single "
           "x%.1f, batch x%.1f\n",
           r_single >= 10e6 ? "met" : "MISSED", r_batch >= 20e6 ? "met" : "MISSED",
           r_single / r_fann, r_batch / r_fann);
    /* The default model: an ensemble of K such networks with the even input and the h/H
     * target, so about K times the work of one. */
    const double e_single = rate(RUN_SINGLE, ens, ann, x, y, repeats);
    const double e_batch = rate(RUN_BATCH, ens, ann, x, y, repeats);
    printf("  default model, the mean of %zu networks (even input, h/H):\n",
           tirenv_nn_n_members(ens));
    printf("  tirenv_nn_run        %8.1f M/s  (%.1f ns each, %.2f times the single network's "
           "time)\n", e_single / 1e6, 1e9 / e_single, r_single / e_single);
    printf("  tirenv_nn_run_batch  %8.1f M/s  (%.1f ns each, %.2f times the single network's "
           "time)\n", e_batch / 1e6, 1e9 / e_batch, r_batch / e_batch);
    tirenv_nn_free(ens);

    fann_destroy(ann);
    tirenv_nn_free(net);
    free(x);
    free(y);
    for (int sp = 0; sp < 3; ++sp) {
        free(d.x[sp]);
        free(d.y[sp]);
        free(d.start[sp]);
    }
    return 0;
}
