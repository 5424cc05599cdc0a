/* The training driver: trainer lookup and defaults, seeded restarts, early stopping on the
 * control set, errors per split (docs/models.md section 6).
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "train/train_impl.h"
#include "core/clock.h"
#include "tirenv/parallel.h"

extern const struct tirenv_trainer_type tirenv_train__backprop_type;
extern const struct tirenv_trainer_type tirenv_train__rprop_type;
extern const struct tirenv_trainer_type tirenv_train__lm_type;

const tirenv_trainer_type *tirenv_trainer_backprop = &tirenv_train__backprop_type;
const tirenv_trainer_type *tirenv_trainer_rprop = &tirenv_train__rprop_type;
const tirenv_trainer_type *tirenv_trainer_lm = &tirenv_train__lm_type;

const tirenv_trainer_type *const *tirenv_trainer_types(void)
{
    static const tirenv_trainer_type *const list[] = {
        &tirenv_train__backprop_type, &tirenv_train__rprop_type, &tirenv_train__lm_type, NULL};
    return list;
}

const tirenv_trainer_type *tirenv_trainer_type_find(const char *name)
{
    for (const tirenv_trainer_type *const *t = tirenv_trainer_types(); *t; ++t)
        if (name && strcmp((*t)->name, name) == 0)
            return *t;
    return NULL;
}

const char *tirenv_trainer_type_name(const tirenv_trainer_type *type) { return type->name; }

/* The defaults. Constants of the algorithms are their authors' (iRprop-: Igel and Huesken,
 * as in FANN; LM: Nielsen's tau, as in GSL). The rest was chosen on the control error of the
 * embedded data set (seed 1 for backprop, seeds 1 to 10 for LM), never on the validation set:
 *   backprop  learning rate 0.01 with momentum 0.9: control RMS after the paper's 2e5 epochs
 *             1.91 mm, against 3.03 mm at 0.003 and 2.41 mm at 0.03;
 *   lm        8 restarts: mean control RMS 2.42 / 1.98 / 1.92 mm with 4 / 8 / 16, at twice
 *             the time per doubling; patience 60: 1.998 mm with 30, 1.980 with 60, no gain
 *             beyond (one restart of ten improved at its epoch 218).
 * rprop: 5000 epochs, patience 500 (a run of 4 restarts takes about 2 s on that set). */
tirenv_train_settings tirenv_train_default(const tirenv_trainer_type *type)
{
    tirenv_train_settings s = {
        .topology = tirenv_nn_topology_default(),
        .seed = 1,
        .restarts = 8,
        .max_epochs = 1000,
        .patience = 60,
        .backprop = {.learning_rate = 0.01, .momentum = 0.9, .online = 1},
        .rprop = {.delta0 = 0.1, .delta_min = 1e-6, .delta_max = 50, .eta_plus = 1.2,
                  .eta_minus = 0.5},
        .lm = {.solver = TIRENV_LM_CHOLESKY, .tau = 1e-3, .mu_max = 1e10},
        .jobs = 1,
        .progress = NULL,
        .progress_data = NULL,
    };
    if (type == tirenv_trainer_backprop) {
        s.restarts = 1;
        s.max_epochs = 200000;  /* the paper's "about 2e5 training cycles" (Table 2) */
        s.patience = 0;
    } else if (type == tirenv_trainer_rprop) {
        s.restarts = 4;
        s.max_epochs = 5000;
        s.patience = 500;
    }
    return s;
}

const char *tirenv_train_stop_name(tirenv_train_stop stop)
{
    switch (stop) {
    case TIRENV_TRAIN_MAX_EPOCHS: return "max-epochs";
    case TIRENV_TRAIN_PATIENCE: return "patience";
    case TIRENV_TRAIN_CONVERGED: return "converged";
    case TIRENV_TRAIN_DIVERGED: return "diverged";
    case TIRENV_TRAIN_CANCELLED: return "cancelled";
    }
    return "unknown";
}

static double out_std_of(const tirenv_nn *nn)
{
    double out_std;
    tirenv_nn_get_scaling(nn, NULL, NULL, NULL, &out_std);
    return out_std;
}

double tirenv_train__gradient(tirenv_nn *nn, const tirenv_samples *s, double g[],
                              double grad[])
{
    const size_t p = tirenv_nn_n_weights(nn);
    const double inv_std = 1.0 / out_std_of(nn);
    double sse = 0;
    memset(g, 0, p * sizeof g[0]);
    for (size_t k = 0; k < s->n; ++k) {
        const double y = tirenv_nn_gradient(nn, s->x + k * s->n_in, grad);
        const double r = (y - s->y[k]) * inv_std;
        sse += r * r;
        const double c = r * inv_std;
        for (size_t j = 0; j < p; ++j)
            g[j] += c * grad[j];
    }
    return sse;
}

double tirenv_train__sse(tirenv_nn *nn, const tirenv_samples *s, double y[])
{
    const double inv_std = 1.0 / out_std_of(nn);
    double sse = 0;
    tirenv_nn_run_batch(nn, s->n, s->x, y);
    for (size_t k = 0; k < s->n; ++k) {
        const double r = (y[k] - s->y[k]) * inv_std;
        sse += r * r;
    }
    return sse;
}

tirenv_train_error tirenv_train_evaluate(tirenv_nn *nn, const tirenv_samples *s)
{
    tirenv_train_error e = {.n = s ? s->n : 0, .rms = 0, .max = 0};
    if (!s || s->n == 0)
        return e;
    double y[256];
    double sum2 = 0;
    for (size_t k0 = 0; k0 < s->n; k0 += 256) {
        const size_t m = s->n - k0 < 256 ? s->n - k0 : 256;
        tirenv_nn_run_batch(nn, m, s->x + k0 * s->n_in, y);
        for (size_t k = 0; k < m; ++k) {
            const double d = fabs(y[k] - s->y[k0 + k]);
            sum2 += d * d;
            e.max = d > e.max || isnan(d) ? d : e.max;
        }
    }
    e.rms = sqrt(sum2 / (double)s->n);
    return e;
}

static uint64_t fnv1a64_u64(uint64_t h, uint64_t v)
{
    for (int b = 0; b < 8; ++b) {
        h ^= (v >> (8 * b)) & 0xff;
        h *= UINT64_C(0x100000001b3);
    }
    return h;
}

uint64_t tirenv_samples_fingerprint(const tirenv_samples *s, uint64_t h)
{
    if (!s)
        return h;
    const size_t n_x = s->n * s->n_in;
    for (size_t k = 0; k < n_x + s->n; ++k) {
        const double v = k < n_x ? s->x[k] : s->y[k - n_x];
        uint64_t bits;
        memcpy(&bits, &v, sizeof bits);
        h = fnv1a64_u64(h, bits);
    }
    return h;
}

/* splitmix64 (Steele, Lea and Flood 2014): decorrelates the seeds of consecutive restarts, so
 * that restart r is reproducible on its own, whatever the others drew. */
static unsigned long restart_seed(unsigned long seed, size_t r)
{
    uint64_t z = (uint64_t)seed + (uint64_t)r * UINT64_C(0x9e3779b97f4a7c15);
    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    z ^= z >> 31;
    return (unsigned long)(z & 0xffffffffu);  /* mt19937 takes 32 bits */
}

static int check_samples(const tirenv_samples *s, const char *name, size_t n_in,
                         tirenv_diag *diag)
{
    if (!s || s->n == 0)
        return TIRENV_OK;
    if (s->n_in != n_in || !s->x || !s->y)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, name,
                            "%zu inputs per sample; expected %zu (the network's)", s->n_in,
                            n_in);
    for (size_t k = 0; k < s->n; ++k) {
        for (size_t i = 0; i < n_in; ++i)
            if (!isfinite(s->x[k * n_in + i]))
                return tirenv_error(diag, TIRENV_EINVAL, "", k + 1, name,
                                    "sample %zu, input %zu is %g; expected a finite number", k,
                                    i, s->x[k * n_in + i]);
        if (!isfinite(s->y[k]))
            return tirenv_error(diag, TIRENV_EINVAL, "", k + 1, name,
                                "sample %zu, output is %g; expected a finite number", k,
                                s->y[k]);
    }
    return TIRENV_OK;
}

int tirenv_train_settings_check(const tirenv_train_settings *s, tirenv_diag *diag)
{
    const int status = tirenv_nn_topology_check(&s->topology, diag);
    if (status)
        return status;
    if (s->restarts < 1 || s->max_epochs < 1)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "settings",
                            "restarts %zu, max_epochs %zu; expected both >= 1", s->restarts,
                            s->max_epochs);
    const tirenv_backprop_settings *b = &s->backprop;
    if (!(b->learning_rate > 0) || !isfinite(b->learning_rate) || !(b->momentum >= 0) ||
        !(b->momentum < 1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "backprop",
                            "learning rate %g, momentum %g; expected > 0 and in [0, 1)",
                            b->learning_rate, b->momentum);
    const tirenv_rprop_settings *r = &s->rprop;
    if (!(r->delta_min > 0) || !(r->delta0 >= r->delta_min) || !(r->delta_max >= r->delta0) ||
        !isfinite(r->delta_max) || !(r->eta_plus > 1) || !isfinite(r->eta_plus) ||
        !(r->eta_minus > 0) || !(r->eta_minus < 1))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "rprop",
                            "delta0 %g in [%g, %g], eta+ %g, eta- %g; expected 0 < delta_min "
                            "<= delta0 <= delta_max, eta+ > 1, 0 < eta- < 1",
                            r->delta0, r->delta_min, r->delta_max, r->eta_plus, r->eta_minus);
    const tirenv_lm_settings *m = &s->lm;
    if ((m->solver != TIRENV_LM_CHOLESKY && m->solver != TIRENV_LM_GSL) || !(m->tau > 0) ||
        !(m->mu_max >= m->tau) || !isfinite(m->mu_max))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "lm",
                            "solver %d, tau %g, mu_max %g; expected cholesky or gsl, 0 < tau "
                            "<= mu_max < inf", (int)m->solver, m->tau, m->mu_max);
    return TIRENV_OK;
}

/* What a worker holds for its restarts, so that one cleanup frees it: the trainer's state is
 * reset by its set at every restart, the network's weights by tirenv_nn_init_weights and the
 * generator by its seed, so a restart's result is a function of (data, settings, restart)
 * alone, whichever worker runs it. */
typedef struct {
    tirenv_nn *nn, *cand;
    void *state;
    gsl_rng *rng;
    double *y;
} run_state;

static void run_free(const tirenv_trainer_type *type, run_state *r)
{
    tirenv_nn_free(r->nn);
    tirenv_nn_free(r->cand);
    if (r->state)
        type->free(r->state);
    gsl_rng_free(r->rng);
    free(r->y);
    memset(r, 0, sizeof *r);
}

/* What one restart leaves. */
typedef struct {
    tirenv_nn *net;        /* its weights of least control error */
    double best;           /* that error (sum of squares of the scaled residuals) */
    size_t epochs, best_epoch;
    double best_time;      /* s */
    tirenv_train_stop stop;
    int cancelled;         /* the progress callback asked to stop */
} restart_result;

/* The restarts, run on settings->jobs threads. */
typedef struct {
    const tirenv_trainer_type *type;
    const tirenv_train_settings *s;
    const tirenv_samples *train, *sel;
    const tirenv_nn *proto;    /* topology and scaling */
    run_state *workers;        /* one per worker, built on first use */
    restart_result *res;       /* one per restart */
    pthread_mutex_t lock;      /* the progress callback is called by one restart at a time */
    int cancel;                /* set when the callback asks to stop */
} train_pass;

static int worker_state(train_pass *p, size_t w, run_state **out, tirenv_diag *diag)
{
    run_state *r = &p->workers[w];
    *out = r;
    if (r->nn)
        return TIRENV_OK;
    if (!(r->nn = tirenv_nn_clone(p->proto)) || !(r->cand = tirenv_nn_clone(p->proto)) ||
        !(r->rng = gsl_rng_alloc(gsl_rng_mt19937)) ||
        !(r->y = malloc(p->sel->n * sizeof *r->y))) {
        run_free(p->type, r);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    const int status = p->type->alloc(&r->state, r->nn, p->train, p->s, diag);
    if (status) {
        r->state = NULL;
        run_free(p->type, r);
    }
    return status;
}

/* Early stopping (Prechelt, "Early stopping - but when?", 1998) within restart k: train, and
 * keep the weights of least control error; stop when it has not improved for `patience`
 * epochs. */
static int run_restart(void *ctx, size_t k, size_t worker, tirenv_diag *diag)
{
    train_pass *p = ctx;
    const tirenv_train_settings *s = p->s;
    const tirenv_samples *train = p->train, *sel = p->sel;
    restart_result *out = &p->res[k];
    run_state *r;
    int status = worker_state(p, worker, &r, diag);
    if (status)
        return status;
    const double out_std = out_std_of(r->nn);
    gsl_rng_set(r->rng, restart_seed(s->seed, k));
    tirenv_nn_init_weights(r->nn, r->rng);
    if ((status = p->type->set(r->state, r->nn, train, diag)))
        return status;
    const double t_restart = tirenv_core__wall_seconds();
    double best = tirenv_train__sse(r->nn, sel, r->y);
    size_t best_epoch = 0, epoch = 0;
    double best_time = 0;
    tirenv_nn_copy(r->cand, r->nn);
    tirenv_train_stop stop = TIRENV_TRAIN_MAX_EPOCHS;
    while (epoch < s->max_epochs) {
        if (__atomic_load_n(&p->cancel, __ATOMIC_RELAXED)) {
            stop = TIRENV_TRAIN_CANCELLED;
            break;
        }
        double train_sse = 0;
        const int st = p->type->epoch(r->state, r->nn, train, r->rng, &train_sse, diag);
        if (st != TIRENV_OK && st != TIRENV_ECONTINUE)
            return st;
        ++epoch;
        const double e = tirenv_train__sse(r->nn, sel, r->y);
        if (e < best) {
            best = e;
            best_epoch = epoch;
            best_time = tirenv_core__wall_seconds() - t_restart;
            tirenv_nn_copy(r->cand, r->nn);
        }
        if (s->progress) {
            const tirenv_train_progress pr = {
                .restart = k, .restarts = s->restarts, .epoch = epoch,
                .max_epochs = s->max_epochs,
                .train_rms = sqrt(train_sse / (double)train->n) * out_std,
                .control_rms = sqrt(e / (double)sel->n) * out_std,
                .best_rms = sqrt(best / (double)sel->n) * out_std,
                .best_epoch = best_epoch};
            pthread_mutex_lock(&p->lock);
            const int stop_now = s->progress(&pr, s->progress_data);
            pthread_mutex_unlock(&p->lock);
            if (stop_now) {
                __atomic_store_n(&p->cancel, 1, __ATOMIC_RELAXED);
                out->cancelled = 1;
                stop = TIRENV_TRAIN_CANCELLED;
                break;
            }
        }
        if (!isfinite(e) || !isfinite(train_sse)) {
            stop = TIRENV_TRAIN_DIVERGED;
            break;
        }
        if (st == TIRENV_OK) {
            stop = TIRENV_TRAIN_CONVERGED;
            break;
        }
        if (s->patience && epoch - best_epoch >= s->patience) {
            stop = TIRENV_TRAIN_PATIENCE;
            break;
        }
    }
    if (!(out->net = tirenv_nn_clone(r->cand)))
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    out->best = best;
    out->epochs = epoch;
    out->best_epoch = best_epoch;
    out->best_time = best_time;
    out->stop = stop;
    return TIRENV_OK;
}

/* Restarts are independent runs from new initial weights; the one with the least control
 * error wins. They run on settings->jobs threads; the choice among them is made afterwards in
 * restart order, so the network is the same, bit for bit, for every number of jobs. */
int tirenv_train(const tirenv_trainer_type *type, const tirenv_train_settings *settings,
                 const tirenv_samples *train, const tirenv_samples *control,
                 const tirenv_samples *validation, tirenv_nn **out,
                 tirenv_train_report *report, tirenv_diag *diag)
{
    *out = NULL;
    if (!type || !settings || !train)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no trainer, settings or samples");
    if (train->n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "train", "no training samples");
    const tirenv_train_settings *s = settings;
    int status;
    if (s->topology.size[0] != train->n_in)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "topology",
                            "%zu inputs; the samples have %zu", s->topology.size[0],
                            train->n_in);
    if ((status = tirenv_train_settings_check(s, diag)) ||
        (status = check_samples(train, "train", train->n_in, diag)) ||
        (status = check_samples(control, "control", train->n_in, diag)) ||
        (status = check_samples(validation, "validation", train->n_in, diag)))
        return status;
    const tirenv_samples *sel = control && control->n ? control : train;
    const size_t jobs = s->jobs < 1 ? 1 : s->jobs < s->restarts ? s->jobs : s->restarts;

    tirenv_nn *proto = tirenv_nn_alloc(&s->topology);
    train_pass p = {.type = type, .s = s, .train = train, .sel = sel, .proto = proto,
                    .workers = calloc(jobs, sizeof *p.workers),
                    .res = calloc(s->restarts, sizeof *p.res), .cancel = 0};
    if (!proto || !p.workers || !p.res) {
        tirenv_nn_free(proto);
        free(p.workers);
        free(p.res);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    }
    pthread_mutex_init(&p.lock, NULL);
    const double t_start = tirenv_core__wall_seconds();
    status = tirenv_nn_fit_scaling(proto, train->n, train->x, train->y, diag);
    if (!status)
        status = tirenv_parallel_for(s->restarts, jobs, run_restart, NULL, &p, diag);
    tirenv_train_report rep = {0};
    tirenv_nn *best_net = NULL;
    double best_overall = INFINITY;
    /* In restart order, up to the first one cancelled (the restarts after it would not have
     * run one after the other). Strictly better, so the earliest restart wins a tie: the
     * result does not depend on how many restarts were asked for beyond the one that found
     * it. */
    for (size_t k = 0; k < s->restarts && !status && p.res[k].net; ++k) {
        const restart_result *q = &p.res[k];
        rep.total_epochs += q->epochs;
        if (k == 0 || q->best < best_overall) {
            best_overall = q->best;
            best_net = q->net;
            rep.restart = k;
            rep.epochs = q->epochs;
            rep.best_epoch = q->best_epoch;
            rep.best_time = q->best_time;
            rep.stop = q->stop;
        }
        if (q->cancelled)
            break;
    }
    if (!status) {
        rep.wall_time = tirenv_core__wall_seconds() - t_start;
        rep.error[TIRENV_SPLIT_TRAIN] = tirenv_train_evaluate(best_net, train);
        rep.error[TIRENV_SPLIT_CONTROL] = tirenv_train_evaluate(best_net, control);
        rep.error[TIRENV_SPLIT_VALIDATION] = tirenv_train_evaluate(best_net, validation);
        if (report)
            *report = rep;
        *out = best_net;
    }
    for (size_t k = 0; k < s->restarts; ++k)
        if (p.res[k].net != *out)
            tirenv_nn_free(p.res[k].net);
    for (size_t w = 0; w < jobs; ++w)
        run_free(type, &p.workers[w]);
    pthread_mutex_destroy(&p.lock);
    free(p.workers);
    free(p.res);
    tirenv_nn_free(proto);
    return status;
}
