/* tirenv train: the empirical model's network trained on a data set (docs/models.md section 6).
 * SPDX-License-Identifier: Apache-2.0 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "tirenv/dataset.h"
#include "tirenv/nn_file.h"
#include "tirenv/study.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv train --data DIR [--trainer backprop|rprop|lm] [--seed S]\n"
          "                    [--restarts N] [--epochs N] [--patience N] [--hidden N[,N...]]\n"
          "                    [--learning-rate ETA] [--momentum A] [--batch]\n"
          "                    [--lm-solver cholesky] [--ensemble K] [--input paper|even]\n"
          "                    [--even-width A] [--target h|h/H] [--loss points|curves]\n"
          "                    [--paper] [--seeds N] [-o MODEL.json] [--jobs N]\n"
          "                    [--tire FILE] [--set KEY=VALUE]...\n"
          "\n"
          "Trains the empirical model's network (inputs x_N, contact length, obstacle height,\n"
          "obstacle length; output h) on the cases of a data set: the manifest's train split\n"
          "trains it, the control split stops it early (the weights of least control error\n"
          "are kept), the validation split is only reported. Prints RMS and maximum error in\n"
          "mm per split, epochs and wall time; writes the model file with -o. Runs are\n"
          "reproducible bit for bit for a given --seed. A progress bar is drawn on a terminal.\n"
          "\n"
          "options:\n"
          "  --data DIR           data set directory with cases.csv\n"
          "  --trainer NAME       lm (default): Levenberg-Marquardt; rprop: iRprop-;\n"
          "                       backprop: the paper's back-propagation with momentum\n"
          "  --seed S             seed of the initial weights (and online order), default 1\n"
          "  --restarts N         independent starts M, at most 100000 (default: lm 8,\n"
          "                       rprop 4, backprop 1)\n"
          "  --ensemble K         the model is the mean of the K restarts best on control\n"
          "                       (default 4, or M if fewer; given, at most M; 1: the best\n"
          "                       restart alone)\n"
          "  --input FORM         even (default): the network sees the distance from the\n"
          "                       obstacle centre, rounded: sqrt((1 - x_N)^2 + A^2) - A, so\n"
          "                       the mirrored curve is smooth over the centre; paper: x_N\n"
          "                       itself, as in the paper\n"
          "  --even-width A       the rounding A of the even input, in x_N (default 0.2)\n"
          "  --target T           h/H (default): the network learns h/H (the loss is on h/H)\n"
          "                       and its output times H is h; h: it outputs h\n"
          "  --loss L             curves (default): the mean over curves of each curve's RMS\n"
          "                       error; points: the squared error summed over all points\n"
          "  --paper              start from the paper's network: --input paper --target h\n"
          "                       --loss points --ensemble 1 (those options, given, override)\n"
          "  --seeds N            train with seeds S to S+N-1 and print the median and\n"
          "                       quartiles of the validation error (the mean over the\n"
          "                       validation cases of each case's RMS); -o writes the\n"
          "                       model of the seed nearest the median\n"
          "  --epochs N           epochs per restart (default: lm 1000, rprop 5000,\n"
          "                       backprop 200000, the paper's cycles)\n"
          "  --patience N         stop after N epochs without a better control error; 0 never\n"
          "                       (default: lm 60, rprop 500, backprop 0)\n"
          "  --hidden N[,N...]    hidden layer sizes (default 8: the paper's 4-8-1)\n"
          "  --learning-rate ETA  backprop: learning rate (default 0.01)\n"
          "  --momentum A         backprop: momentum in [0, 1) (default 0.9)\n"
          "  --batch              backprop: one update per epoch instead of per sample\n"
          "  --lm-solver NAME     lm: cholesky (the one solver)\n"
          "  -o, --output FILE    write the model (JSON), complete or not at all; without it\n"
          "                       the network is not saved\n"
          "  --tire FILE, --set KEY=VALUE\n"
          "                       the tire (default: the one the data set's source.txt names,\n"
          "                       a sweep's tire.tir when it set no tire key, else\n"
          "                       tires/default.tir in the data directory), whose\n"
          "                       UNLOADED_RADIUS imports raw logs and defines x_N\n",
          fp);
    cli_help_jobs(fp);
    fputs("  -h, --help           show this help\n", fp);
}

/* The bar on standard error, redrawn at most ten times a second. */
typedef struct {
    const char *trainer;
    double last;           /* s, when drawn last */
    int drawn;
    int over_H;            /* the errors are of h/H, not of h in m */
} bar;

static int draw(const tirenv_train_progress *p, void *data)
{
    bar *b = data;
    const double t = cli_wall_seconds();
    if (b->drawn && t - b->last < 0.1)
        return 0;
    b->last = t;
    b->drawn = 1;
    static const char hashes[] = "##############################";
    const int width = (int)sizeof hashes - 1;
    const int filled = (int)((double)width * (double)p->epoch / (double)p->max_epochs);
    const double unit = b->over_H ? 1e2 : 1e3;
    fprintf(stderr, "\rtirenv: train: %s restart %zu/%zu [%-*.*s] epoch %zu/%zu, control RMS "
            "%.3f %s (best %.3f at %zu)\033[K",
            b->trainer, p->restart + 1, p->restarts, width, filled, hashes, p->epoch,
            p->max_epochs, p->control_rms * unit, b->over_H ? "% of H" : "mm",
            p->best_rms * unit, p->best_epoch);
    return 0;
}

static int parse_hidden(const char *s, tirenv_nn_topology *t)
{
    size_t n = 0;
    const char *p = s;
    for (;;) {
        char buf[32];
        const size_t len = strcspn(p, ",");
        long v;
        if (len == 0 || len >= sizeof buf || n >= TIRENV_NN_MAX_LAYERS - 2)
            return -1;
        memcpy(buf, p, len);
        buf[len] = '\0';
        if (cli_parse_count(buf, 1, TIRENV_NN_MAX_WIDTH, &v))
            return -1;
        t->size[1 + n++] = (size_t)v;
        if (p[len] == '\0')
            break;
        p += len + 1;
    }
    t->n_layers = n + 2;
    t->size[0] = TIRENV_NN_INPUTS;
    t->size[n + 1] = 1;
    return 0;
}

/* What the options asked for; a field left at -1 (or NaN) keeps the trainer's default. */
typedef struct {
    const char *data;
    const tirenv_trainer_type *type;
    long seed, restarts, epochs, patience, ensemble, seeds;
    int have_hidden, batch, have_solver, paper;
    int input, target, loss;   /* -1: the default */
    double learning_rate, momentum, even_width;
    tirenv_lm_solver solver;
    tirenv_nn_topology topology;
} train_options;

static int parse_trainer(void *dst, const char *arg)
{
    const tirenv_trainer_type **type = dst;
    if (!(*type = tirenv_trainer_type_find(arg))) {
        cli_error("--trainer: expected backprop, rprop or lm, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static int parse_hidden_opt(void *dst, const char *arg)
{
    train_options *t = dst;
    if (parse_hidden(arg, &t->topology)) {
        cli_error("--hidden: expected 1 to %d comma-separated layer sizes from 1 to %d, got "
                  "'%s'", TIRENV_NN_MAX_LAYERS - 2, TIRENV_NN_MAX_WIDTH, arg);
        return CLI_EXIT_USAGE;
    }
    t->have_hidden = 1;
    return CLI_EXIT_OK;
}

static int parse_momentum(void *dst, const char *arg)
{
    double *v = dst;
    if (cli_parse_double(arg, v) || !(*v >= 0 && *v < 1)) {
        cli_error("--momentum: expected a number in [0, 1), got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static int parse_solver(void *dst, const char *arg)
{
    train_options *t = dst;
    if (strcmp(arg, "cholesky") == 0)
        t->solver = TIRENV_LM_CHOLESKY;
    else {
        cli_error("--lm-solver: expected cholesky, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    t->have_solver = 1;
    return CLI_EXIT_OK;
}

static int parse_input(void *dst, const char *arg)
{
    if ((*(int *)dst = tirenv_nn_input_form_find(arg)) < 0) {
        cli_error("--input: expected paper or even, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static int parse_target(void *dst, const char *arg)
{
    if ((*(int *)dst = tirenv_nn_target_form_find(arg)) < 0) {
        cli_error("--target: expected h or h/H, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static int parse_loss(void *dst, const char *arg)
{
    if ((*(int *)dst = tirenv_train_loss_find(arg)) < 0) {
        cli_error("--loss: expected points or curves, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* Parses the options; returns an exit code, or CLI_GO_ON. */
static int parse(int argc, char *argv[], cli_options *o, train_options *t)
{
    const cli_opt own[] = {
        {.name = "data", .kind = CLI_STRING, .dst = &t->data, .input = CLI_INPUT_DIR},
        {.name = "trainer", .kind = CLI_CUSTOM, .dst = &t->type, .parse = parse_trainer},
        {.name = "seed", .kind = CLI_COUNT, .dst = &t->seed, .min = 0, .max = LONG_MAX,
         .what = "an integer >= 0"},
        /* Bounded as --seeds is: a record per restart is allocated before the first runs,
         * and 1e9 of them was an unnamed "out of memory". */
        {.name = "restarts", .kind = CLI_COUNT, .dst = &t->restarts, .min = 1,
         .max = 100000, .what = "an integer from 1 to 100000"},
        {.name = "epochs", .kind = CLI_COUNT, .dst = &t->epochs, .min = 1, .max = LONG_MAX,
         .what = "an integer >= 1"},
        {.name = "patience", .kind = CLI_COUNT, .dst = &t->patience, .min = 0,
         .max = LONG_MAX, .what = "an integer >= 0"},
        {.name = "hidden", .kind = CLI_CUSTOM, .dst = t, .parse = parse_hidden_opt},
        {.name = "learning-rate", .kind = CLI_POSITIVE, .dst = &t->learning_rate,
         .what = "a number > 0"},
        {.name = "momentum", .kind = CLI_CUSTOM, .dst = &t->momentum, .parse = parse_momentum},
        {.name = "batch", .kind = CLI_FLAG, .dst = &t->batch},
        {.name = "lm-solver", .kind = CLI_CUSTOM, .dst = t, .parse = parse_solver},
        {.name = "ensemble", .kind = CLI_COUNT, .dst = &t->ensemble, .min = 1,
         .max = TIRENV_NN_MAX_MEMBERS, .what = "an integer from 1 to 64"},
        {.name = "input", .kind = CLI_CUSTOM, .dst = &t->input, .parse = parse_input},
        {.name = "even-width", .kind = CLI_POSITIVE, .dst = &t->even_width,
         .what = "a width > 0 in x_N"},
        {.name = "target", .kind = CLI_CUSTOM, .dst = &t->target, .parse = parse_target},
        {.name = "loss", .kind = CLI_CUSTOM, .dst = &t->loss, .parse = parse_loss},
        {.name = "paper", .kind = CLI_FLAG, .dst = &t->paper},
        {.name = "seeds", .kind = CLI_COUNT, .dst = &t->seeds, .min = 1, .max = 100000,
         .what = "an integer from 1 to 100000"},
        {.name = NULL},
    };
    const cli_parser p = {.name = "train", .usage = usage, .opts = own,
                          .groups = CLI_TIRE | CLI_OUTPUT | CLI_JOBS};
    const int code = cli_parse(&p, argc, argv, o);
    if (code != CLI_GO_ON)
        return code;
    if (!t->data) {
        cli_error("train: expected --data DIR; 'tirenv train --help' shows the options");
        return CLI_EXIT_USAGE;
    }
    return CLI_GO_ON;
}

static tirenv_train_settings settings_from(const train_options *t)
{
    tirenv_train_settings s = t->paper ? tirenv_train_paper(t->type)
                                       : tirenv_train_default(t->type);
    if (t->ensemble > 0)
        s.ensemble = (size_t)t->ensemble;
    if (t->input >= 0)
        s.input = (tirenv_nn_input_form)t->input;
    if (!isnan(t->even_width))
        s.even_width = t->even_width;
    if (t->target >= 0)
        s.target = (tirenv_nn_target_form)t->target;
    if (t->loss >= 0)
        s.loss = (tirenv_train_loss)t->loss;
    if (t->seed >= 0)
        s.seed = (unsigned long)t->seed;
    if (t->restarts >= 0)
        s.restarts = (size_t)t->restarts;
    if (t->epochs >= 0)
        s.max_epochs = (size_t)t->epochs;
    if (t->patience >= 0)
        s.patience = (size_t)t->patience;
    if (t->have_hidden)
        s.topology = t->topology;
    if (!isnan(t->learning_rate))
        s.backprop.learning_rate = t->learning_rate;
    if (!isnan(t->momentum))
        s.backprop.momentum = t->momentum;
    if (t->batch)
        s.backprop.online = 0;
    if (t->have_solver)
        s.lm.solver = t->solver;
    return s;
}

static void print_report(const char *data, const tirenv_dataset *ds,
                         const tirenv_train_settings *s, const char *trainer,
                         const tirenv_train_report *r)
{
    size_t cases[3] = {0, 0, 0};
    for (size_t k = 0; k < ds->n; ++k)
        ++cases[ds->cases[k].split];
    printf("tirenv train: %s on %s: %zu train, %zu control, %zu validation cases; network ",
           trainer, data, cases[0], cases[1], cases[2]);
    for (size_t l = 0; l < s->topology.n_layers; ++l)
        printf("%s%zu", l ? "-" : "", s->topology.size[l]);
    printf(", seed %lu\n", s->seed);
    printf("  input %s", tirenv_nn_input_form_name(s->input));
    if (s->input == TIRENV_NN_INPUT_EVEN)
        printf(" (width %g)", s->even_width);
    printf(", target %s, loss over %s; ", tirenv_nn_target_form_name(s->target),
           tirenv_train_loss_name(s->loss));
    /* Without control cases tirenv_train selects on the training error: say which. */
    const char *on = cases[TIRENV_SPLIT_CONTROL] ? "control" : "the training error";
    if (r->members > 1) {
        printf("the mean of the %zu restarts best on %s (", r->members, on);
        for (size_t k = 0; k < r->members; ++k)
            printf("%s%zu", k ? ", " : "", r->member_restart[k] + 1);
        printf(" of %zu)\n", s->restarts);
    } else {
        printf("the restart best on %s alone\n", on);
    }
    if (!cases[TIRENV_SPLIT_CONTROL])
        printf("  no control cases: the training error, not a held-out one, chooses the weights "
               "and stops the training\n");
    printf("  best restart %zu of %zu: least %s error at epoch %zu of %zu (stopped: %s, "
           "%.3f s in)\n", r->restart + 1, s->restarts,
           cases[TIRENV_SPLIT_CONTROL] ? "control" : "training", r->best_epoch, r->epochs,
           tirenv_train_stop_name(r->stop), r->best_time);
    printf("  %zu epochs in all, wall time %.3f s\n", r->total_epochs, r->wall_time);
    printf("  %-12s %8s %10s %10s\n", "split", "points", "RMS mm", "max mm");
    for (int sp = TIRENV_SPLIT_TRAIN; sp <= TIRENV_SPLIT_VALIDATION; ++sp) {
        if (r->error[sp].n == 0) {  /* an error over no points is no number */
            printf("  %-12s %8zu %10s %10s\n", tirenv_split_name((tirenv_split)sp), (size_t)0,
                   "-", "-");
            continue;
        }
        printf("  %-12s %8zu %10.4f %10.4f\n", tirenv_split_name((tirenv_split)sp),
               r->error[sp].n, r->error[sp].rms * 1e3, r->error[sp].max * 1e3);
    }
}

/* --seeds: one line per seed, then the spread. */
static void print_seeds(const tirenv_dataset *ds, const tirenv_nn_seeds *r)
{
    printf("  %6s %10s", "seed", "mean mm");
    for (size_t c = 0; c < r->n_cases; ++c)
        printf(" %8s", ds->cases[r->case_index[c]].name);
    printf("   (validation RMS per case, mm)\n");
    for (size_t k = 0; k < r->n_seeds; ++k) {
        printf("  %6lu %10.4f", r->seed[k], 1e3 * r->mean_rms[k]);
        for (size_t c = 0; c < r->n_cases; ++c)
            printf(" %8.4f", 1e3 * r->rms[k * r->n_cases + c]);
        printf("%s\n", k == r->median_seed ? "   <- nearest the median" : "");
    }
    printf("  over %zu seeds (%.2f s): median %.4f mm, quartiles %.4f to %.4f mm (IQR %.4f), "
           "range %.4f to %.4f mm\n", r->n_seeds, r->seconds, 1e3 * r->median, 1e3 * r->q1,
           1e3 * r->q3, 1e3 * (r->q3 - r->q1), 1e3 * r->min, 1e3 * r->max);
    if (isnan(r->control_median)) /* tirenv_nn_seeds: NaN without control cases */
        printf("  control cases, the same measure: none in the data set\n");
    else
        printf("  control cases, the same measure: median %.4f mm, quartiles %.4f to %.4f mm\n",
               1e3 * r->control_median, 1e3 * r->control_q1, 1e3 * r->control_q3);
}

/* The ensemble is of restarts: more members than restarts would be fewer than asked, as the
 * default's 4 of 1 backprop restart are, silently; asked for, that is a misuse. */
static int check_ensemble(const train_options *t)
{
    const tirenv_train_settings asked = settings_from(t);
    if (t->ensemble > 0 && asked.ensemble > asked.restarts) {
        cli_error("train: --ensemble %ld: the mean of more networks than the %zu restarts "
                  "(--restarts%s) train; expected at most %zu, or more restarts",
                  t->ensemble, asked.restarts, t->restarts > 0 ? "" : ", the trainer's default",
                  asked.restarts);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* The data set's samples by split (tirenv_samples_from_dataset), and the arrays they own. */
typedef struct {
    tirenv_samples s[3];
    double *x[3], *y[3];
} split_samples;

static void free_samples(split_samples *sm)
{
    for (int sp = 0; sp < 3; ++sp) {
        free(sm->x[sp]);
        free(sm->y[sp]);
    }
}

static int read_samples(const tirenv_dataset *ds, const char *data, split_samples *sm,
                        tirenv_diag *diag)
{
    int status = TIRENV_OK;
    for (int sp = 0; sp < 3 && !status; ++sp)
        status = tirenv_samples_from_dataset(ds, (tirenv_split)sp, &sm->s[sp], &sm->x[sp],
                                             &sm->y[sp], diag);
    if (!status && sm->s[TIRENV_SPLIT_TRAIN].n == 0)
        status = tirenv_error(diag, TIRENV_EINVAL, data, 0, "split",
                              "no training cases in the manifest (split 'train')");
    return status;
}

/* The relation between load and contact length of the tire the data came from (what), which
 * the file records so that the network, driven by the contact length, takes a load as that
 * tire would. */
typedef struct {
    tirenv_contact_law law;
    char what[80];
} data_law;

/* The network trained as t asks (with --seeds, over several seeds, the median's kept) into
 * *nn, its report and the settings it was trained with; the bar drawn on a terminal. */
static int train(const train_options *t, const cli_options *o, const tirenv_dataset *ds,
                 const tirenv_tire *tire, const split_samples *sm, tirenv_train_settings *set,
                 bar *b, tirenv_nn **nn, tirenv_train_report *rep, tirenv_diag *diag)
{
    *set = settings_from(t);
    set->jobs = o->jobs;
    *b = (bar){.trainer = tirenv_trainer_type_name(t->type), .last = 0, .drawn = 0,
               .over_H = set->target == TIRENV_NN_TARGET_H_OVER_H};
    if (isatty(STDERR_FILENO) && t->seeds < 0) {
        set->progress = draw;
        set->progress_data = b;
    }
    tirenv_nn_seeds spread;
    memset(&spread, 0, sizeof spread);
    int status;
    if (t->seeds > 0) {
        status = tirenv_nn_train_seeds(t->type, set, ds, ds, tire->springs.R0, (size_t)t->seeds,
                                       &spread, nn, rep, diag);
        if (!status)
            set->seed = spread.seed[spread.median_seed];
    } else {
        status = tirenv_train(t->type, set, &sm->s[0], &sm->s[1], &sm->s[2], nn, rep, diag);
    }
    if (b->drawn)
        fputs("\r\033[K", stderr);
    if (!status) {
        print_report(t->data, ds, set, b->trainer, rep);
        if (t->seeds > 0)
            print_seeds(ds, &spread);
    }
    tirenv_nn_seeds_free(&spread);
    return status;
}

/* The network written to -o with the record of its training (tirenv_nn_write_json). */
static int write_model(const char *path, const tirenv_nn *nn, const train_options *t,
                       const tirenv_train_settings *set, const char *trainer,
                       const tirenv_train_report *rep, const split_samples *sm,
                       const tirenv_tire *tire, const data_law *law, tirenv_diag *diag)
{
    tirenv_train_record rec;
    memset(&rec, 0, sizeof rec);
    snprintf(rec.trainer, sizeof rec.trainer, "%s", trainer);
    rec.settings = *set;
    rec.settings.progress = NULL;
    rec.settings.progress_data = NULL;
    rec.report = *rep;
    uint64_t h = TIRENV_FNV1A64_OFFSET;
    for (int sp = 0; sp < 3; ++sp)
        h = tirenv_samples_fingerprint(&sm->s[sp], h);
    rec.fingerprint = h;
    rec.R0 = tire->springs.R0;
    rec.law = law->law;
    snprintf(rec.law_source, sizeof rec.law_source, "%s", law->what);
    snprintf(rec.data, sizeof rec.data, "%s", t->data);
    return tirenv_nn_write_json(path, nn, &rec, diag);
}

int cli_train_main(int argc, char *argv[])
{
    cli_options o;
    train_options t;
    memset(&t, 0, sizeof t);
    t.type = tirenv_trainer_lm;
    t.seed = t.restarts = t.epochs = t.patience = t.ensemble = t.seeds = -1;
    t.input = t.target = t.loss = -1;
    t.learning_rate = t.momentum = t.even_width = NAN;
    int code = parse(argc, argv, &o, &t);
    if (code != CLI_GO_ON)
        return code;
    if ((code = check_ensemble(&t)))
        return code;
    /* The radius x_N refers to: the tire that simulated the data, if the data set says. */
    tirenv_dataset_source src;
    char tire_buf[1024];
    tirenv_tire tire;
    tirenv_dataset ds;
    if ((code = cli_data_and_tire(t.data, &o, &src, tire_buf, sizeof tire_buf, &tire, &ds)))
        return code;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    split_samples sm = {.x = {NULL, NULL, NULL}, .y = {NULL, NULL, NULL}};
    tirenv_nn *nn = NULL;
    int status = read_samples(&ds, t.data, &sm, &diag);
    /* The law found before the training, so that a data set that gives none costs none. */
    data_law law = {.what = ""};
    if (!status && o.output) {
        const tirenv_model_type *source = src.model[0] ? tirenv_model_type_find(src.model) : NULL;
        status = tirenv_contact_law_of_data(&ds, source, &tire, &law.law, law.what,
                                            sizeof law.what, &diag);
    }
    tirenv_train_settings set;
    bar b;
    tirenv_train_report rep;
    if (!status)
        status = train(&t, &o, &ds, &tire, &sm, &set, &b, &nn, &rep, &diag);
    if (!status && o.output)
        status = write_model(o.output, nn, &t, &set, b.trainer, &rep, &sm, &tire, &law, &diag);
    if (status)
        code = cli_fail(status, &diag);
    else if (o.output)
        printf("  model written to %s\n", o.output);
    else
        printf("  model not saved (no -o FILE)\n");
    tirenv_nn_free(nn);
    free_samples(&sm);
    tirenv_dataset_free(&ds);
    return code;
}
