/* SPDX-License-Identifier: Apache-2.0 */
/* Model files of the empirical model, written (tirenv_nn_write_json; the layout: nn_json.c and
 * docs/formats.md section 10). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <jansson.h>

#include "formats/nn_json_impl.h"
#include "tirenv/outfile.h"
#include "tirenv/nn_file.h"
#include "io/io.h"

/* ---- Writing ---- */

/* jansson's constructors return NULL on out of memory (and json_real on a non-finite
 * number); the set_new / append_new calls take the reference and tolerate NULL by failing,
 * so one flag at the end catches every failure. */
typedef struct {
    int failed;
} wctx;

static json_t *put(wctx *c, json_t *obj, const char *key, json_t *v)
{
    if (!v || json_object_set_new(obj, key, v))
        c->failed = 1;
    return v;
}

static json_t *real_array(wctx *c, size_t n, const double v[], size_t stride)
{
    json_t *a = json_array();
    if (!a) {
        c->failed = 1;
        return NULL;
    }
    for (size_t k = 0; k < n; ++k)
        if (json_array_append_new(a, json_real(v[k * stride])))
            c->failed = 1;
    return a;
}

static json_t *error_json(wctx *c, const tirenv_train_error *e)
{
    json_t *o = json_object();
    if (!o) {
        c->failed = 1;
        return NULL;
    }
    put(c, o, "n", json_integer((json_int_t)e->n));
    put(c, o, "rms", json_real(e->rms));
    put(c, o, "max", json_real(e->max));
    return o;
}

static json_t *training_json(wctx *c, const tirenv_train_record *rec)
{
    const tirenv_train_settings *s = &rec->settings;
    const tirenv_train_report *r = &rec->report;
    json_t *t = json_object();
    if (!t) {
        c->failed = 1;
        return NULL;
    }
    put(c, t, "trainer", json_string(rec->trainer));
    put(c, t, "seed", json_integer((json_int_t)s->seed));
    put(c, t, "restarts", json_integer((json_int_t)s->restarts));
    put(c, t, "ensemble", json_integer((json_int_t)s->ensemble));
    put(c, t, "loss", json_string(tirenv_train_loss_name(s->loss)));
    put(c, t, "max_epochs", json_integer((json_int_t)s->max_epochs));
    put(c, t, "patience", json_integer((json_int_t)s->patience));
    json_t *set = put(c, t, "settings", json_object());
    if (set) {
        json_t *b = put(c, set, "backprop", json_object());
        if (b) {
            put(c, b, "learning_rate", json_real(s->backprop.learning_rate));
            put(c, b, "momentum", json_real(s->backprop.momentum));
            put(c, b, "online", json_boolean(s->backprop.online));
        }
        json_t *rp = put(c, set, "rprop", json_object());
        if (rp) {
            put(c, rp, "delta0", json_real(s->rprop.delta0));
            put(c, rp, "delta_min", json_real(s->rprop.delta_min));
            put(c, rp, "delta_max", json_real(s->rprop.delta_max));
            put(c, rp, "eta_plus", json_real(s->rprop.eta_plus));
            put(c, rp, "eta_minus", json_real(s->rprop.eta_minus));
        }
        json_t *lm = put(c, set, "lm", json_object());
        if (lm) {
            put(c, lm, "solver",
                json_string("cholesky"));
            put(c, lm, "tau", json_real(s->lm.tau));
            put(c, lm, "mu_max", json_real(s->lm.mu_max));
        }
    }
    json_t *data = put(c, t, "data", json_object());
    if (data) {
        char fp[32];
        tirenv_nn_json__hash_text(fp, sizeof fp, rec->fingerprint);
        put(c, data, "dir", json_string(rec->data));
        put(c, data, "fingerprint", json_string(fp));
        put(c, data, "tire_R0_m", json_real(rec->R0));
        if (rec->law.n) {
            json_t *law = put(c, data, "contact_law", json_object());
            json_t *G = law ? put(c, law, "load_N", json_array()) : NULL;
            json_t *l = law ? put(c, law, "contact_length_m", json_array()) : NULL;
            if (law)
                put(c, law, "source", json_string(rec->law_source));
            for (size_t k = 0; G && l && k < rec->law.n; ++k)
                if (json_array_append_new(G, json_real(rec->law.load[k])) ||
                    json_array_append_new(l, json_real(rec->law.l_c[k])))
                    c->failed = 1;
        }
    }
    json_t *res = put(c, t, "result", json_object());
    if (res) {
        put(c, res, "restart", json_integer((json_int_t)r->restart));
        json_t *mem = put(c, res, "members", json_array());
        for (size_t i = 0; mem && i < r->members; ++i)
            if (json_array_append_new(mem, json_integer((json_int_t)r->member_restart[i])))
                c->failed = 1;
        put(c, res, "epochs", json_integer((json_int_t)r->epochs));
        put(c, res, "best_epoch", json_integer((json_int_t)r->best_epoch));
        put(c, res, "best_time_s", json_real(r->best_time));
        put(c, res, "total_epochs", json_integer((json_int_t)r->total_epochs));
        put(c, res, "wall_time_s", json_real(r->wall_time));
        put(c, res, "stop", json_string(tirenv_train_stop_name(r->stop)));
    }
    json_t *err = put(c, t, "errors_m", json_object());
    if (err) {
        put(c, err, "train", error_json(c, &r->error[TIRENV_SPLIT_TRAIN]));
        put(c, err, "control", error_json(c, &r->error[TIRENV_SPLIT_CONTROL]));
        put(c, err, "validation", error_json(c, &r->error[TIRENV_SPLIT_VALIDATION]));
    }
    return t;
}

static json_t *nn_json(wctx *c, const tirenv_nn *nn, const tirenv_contact_law *law)
{
    const tirenv_nn_topology *t = tirenv_nn_topology_of(nn);
    const size_t n_in = tirenv_nn_n_inputs(nn);
    const double *w = tirenv_nn_weights_const(nn);
    double mean[TIRENV_NN_MAX_WIDTH], std[TIRENV_NN_MAX_WIDTH], lo[TIRENV_NN_MAX_WIDTH],
        hi[TIRENV_NN_MAX_WIDTH], out_mean, out_std;
    tirenv_nn_scaling(nn, mean, std, &out_mean, &out_std);
    tirenv_nn_input_range(nn, lo, hi);
    json_t *root = json_object();
    if (!root) {
        c->failed = 1;
        return NULL;
    }
    put(c, root, "format", json_string(TIRENV_NN_FORMAT));
    put(c, root, "version", json_integer(TIRENV_NN_FORMAT_VERSION));
    json_t *names = put(c, root, "inputs", json_array());
    for (size_t i = 0; names && i < n_in; ++i) {
        char buf[32];
        snprintf(buf, sizeof buf, "input_%zu", i);
        if (json_array_append_new(names, json_string(n_in == TIRENV_NN_INPUTS
                                                         ? tirenv_nn_input_name(i)
                                                         : buf)))
            c->failed = 1;
    }
    put(c, root, "output", json_string("h_m"));
    json_t *top = put(c, root, "topology", json_array());
    for (size_t l = 0; top && l < t->n_layers; ++l)
        if (json_array_append_new(top, json_integer((json_int_t)t->size[l])))
            c->failed = 1;
    json_t *act = put(c, root, "activation", json_object());
    if (act) {
        put(c, act, "hidden", json_string("logistic"));
        put(c, act, "output", json_string("identity"));
    }
    tirenv_nn_input_form input;
    tirenv_nn_target_form target;
    tirenv_nn_form(nn, &input, &target);
    put(c, root, "input_form", json_string(tirenv_nn_input_form_name(input)));
    put(c, root, "even_width", json_real(tirenv_nn_even_width(nn)));
    put(c, root, "target", json_string(tirenv_nn_target_form_name(target)));
    json_t *sc = put(c, root, "scaling", json_object());
    if (sc) {
        put(c, sc, "input_mean", real_array(c, n_in, mean, 1));
        put(c, sc, "input_std", real_array(c, n_in, std, 1));
        put(c, sc, "output_mean", json_real(out_mean));
        put(c, sc, "output_std", json_real(out_std));
    }
    json_t *range = put(c, root, "input_range", json_object());
    if (range) {
        put(c, range, "min", real_array(c, n_in, lo, 1));
        put(c, range, "max", real_array(c, n_in, hi, 1));
    }
    json_t *members = put(c, root, "members", json_array());
    const size_t K = tirenv_nn_n_members(nn), per = tirenv_nn_n_weights(nn) / K;
    for (size_t k = 0; members && k < K; ++k) {
        json_t *member = json_object();
        if (!member || json_array_append_new(members, member)) {
            c->failed = 1;
            break;
        }
        json_t *layers = put(c, member, "layers", json_array());
        for (size_t l = 1; layers && l < t->n_layers; ++l) {
            const size_t n_prev = t->size[l - 1], n_out = t->size[l];
            const double *wl = w + k * per + tirenv_nn_weight_index(nn, l, 0, 0);
            json_t *layer = json_object();
            if (!layer || json_array_append_new(layers, layer)) {
                c->failed = 1;
                break;
            }
            put(c, layer, "bias", real_array(c, n_out, wl, 1));
            json_t *rows = put(c, layer, "weights", json_array());
            for (size_t i = 0; rows && i < n_prev; ++i)
                if (json_array_append_new(rows, real_array(c, n_out, wl + (1 + i) * n_out, 1)))
                    c->failed = 1;
        }
    }
    char sum[32];
    tirenv_nn_json__hash_text(sum, sizeof sum,
                              tirenv_nn_json__checksum(nn, law, TIRENV_NN_FORMAT_VERSION));
    put(c, root, "checksum", json_string(sum));
    return root;
}

/* Every number must be finite: JSON has no NaN or infinity, and a model holding one is
 * broken anyway. The input ranges are finite once fitted from data. */
static int check_finite(const tirenv_nn *nn, const tirenv_train_record *rec, tirenv_diag *diag,
                        const char *path)
{
    const size_t n_in = tirenv_nn_n_inputs(nn), p = tirenv_nn_n_weights(nn);
    const double *w = tirenv_nn_weights_const(nn);
    double lo[TIRENV_NN_MAX_WIDTH], hi[TIRENV_NN_MAX_WIDTH];
    tirenv_nn_input_range(nn, lo, hi);
    for (size_t k = 0; k < p; ++k)
        if (!isfinite(w[k]))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "layers",
                                "weight %zu is %g; only finite weights can be saved", k, w[k]);
    for (size_t i = 0; i < n_in; ++i)
        if (!isfinite(lo[i]) || !isfinite(hi[i]))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "input_range",
                                "input %zu range [%g, %g] is not finite; fit the scaling "
                                "from data first (tirenv_nn_fit_scaling)", i, lo[i], hi[i]);
    if (rec) {
        const tirenv_train_report *r = &rec->report;
        const double v[] = {rec->R0, r->best_time, r->wall_time,
                            r->error[0].rms, r->error[0].max, r->error[1].rms,
                            r->error[1].max, r->error[2].rms, r->error[2].max};
        for (size_t k = 0; k < sizeof v / sizeof v[0]; ++k)
            if (!isfinite(v[k]))
                return tirenv_error(diag, TIRENV_EINVAL, path, 0, "training",
                                    "a training figure is %g; expected finite numbers", v[k]);
        if (r->members > TIRENV_NN_MAX_MEMBERS ||
            (r->members && r->members != tirenv_nn_n_members(nn)))
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "training.result.members",
                                "the record lists %zu members; the model has %zu", r->members,
                                tirenv_nn_n_members(nn));
        if (rec->settings.seed > (unsigned long)NN_JSON_INT_MAX)
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "training.seed",
                                "seed %lu is beyond JSON's integers", rec->settings.seed);
        const int status = tirenv_train_settings_check(&rec->settings, diag);
        if (status)
            return status;
    }
    return TIRENV_OK;
}

int tirenv_nn_write_json(const char *path, const tirenv_nn *nn, const tirenv_train_record *rec,
                         tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    /* An empty record, as the reader makes for a file without one, is none: written as such,
     * the file reads back ("trainer": "" would not). */
    if (rec && !rec->trainer[0])
        rec = NULL;
    int status = check_finite(nn, rec, diag, path);
    if (status)
        return status;
    wctx c = {0};
    /* The checksum covers the law the training record writes, and none without a record. */
    json_t *root = nn_json(&c, nn, rec ? &rec->law : NULL);
    if (root && rec)
        put(&c, root, "training", training_json(&c, rec));
    if (c.failed) {
        json_decref(root);
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "",
                            "out of memory building the model file");
    }
    tirenv_outfile *out;
    if ((status = tirenv_outfile_open(&out, path, diag))) {
        json_decref(root);
        return status;
    }
    /* 17 significant digits: every double reads back to the same bits. */
    FILE *fp = tirenv_outfile_stream(out);
    const int failed =
        json_dumpf(root, fp, JSON_INDENT(1) | JSON_REAL_PRECISION(17) | JSON_PRESERVE_ORDER) ||
        fputc('\n', fp) == EOF;
    json_decref(root);
    if (failed) {
        tirenv_outfile_abort(out);
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "write failed");
    }
    return tirenv_outfile_commit(out, diag);
}
