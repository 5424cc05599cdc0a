/* Model files of the empirical model (docs/models.md section 6; the format: docs/formats.md
 * section 10): the network and how it was trained, as JSON through jansson. Reading trusts
 * nothing: every field is checked for presence, type, finiteness and range, and the network's
 * numbers against a checksum, and a failure names the file and the field. This file reads and
 * holds the checksum; nn_json_keys.c refuses a key the format does not know; nn_json_write.c
 * writes. SPDX-License-Identifier: Apache-2.0
 *
 * Layout (version 3):
 *   format "tirenv-nn", version 3, inputs [names], output "h_m", topology [4, 8, 1],
 *   activation {hidden "logistic", output "identity"},
 *   input_form "paper" | "even", even_width a, target "h" | "h/H"            (nn.h),
 *   scaling {input_mean [], input_std [], output_mean, output_std},
 *   input_range {min [], max []},
 *   members [{layers [{bias [n_out], weights [[n_out] per input neuron]}]}]  (one per network
 *     of the ensemble, each in tirenv_nn_weights order),
 *   checksum "fnv1a64:<16 hex>" over topology, weights, scaling and ranges, then the member
 *     count, the two forms and the even width, then the contact law's knots (training.data.
 *     contact_law: their count, loads and lengths; a count of 0 without one),
 *   training (optional) {trainer, seed, restarts, ensemble, loss, max_epochs, patience,
 *     settings {backprop {}, rprop {}, lm {}}, data {dir, fingerprint, tire_R0_m},
 *     result {restart, members [restarts], epochs, best_epoch, best_time_s, total_epochs,
 *     wall_time_s, stop}, errors_m {train {n, rms, max}, control {}, validation {}}}
 * Version 2 (still read) is version 3 with a checksum that stops before the contact law.
 * Version 1 (still read) had one network: its "layers" at the top level, no forms, no
 * members (the paper's x_N and h), its checksum without the last three, and no ensemble,
 * loss or result.members in the training record. */
#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <jansson.h>

#include "formats/nn_json_impl.h"
#include "tirenv/nn_file.h"
#include "io/io.h"

/* ---- The checksum of the network's numbers ---- */

static uint64_t fnv_u64(uint64_t h, uint64_t v)
{
    for (int b = 0; b < 8; ++b) {
        h ^= (v >> (8 * b)) & 0xff;
        h *= UINT64_C(0x100000001b3);
    }
    return h;
}

static uint64_t fnv_doubles(uint64_t h, size_t n, const double v[])
{
    for (size_t k = 0; k < n; ++k) {
        uint64_t bits;
        memcpy(&bits, &v[k], sizeof bits);
        h = fnv_u64(h, bits);
    }
    return h;
}

uint64_t tirenv_nn_json__checksum(const tirenv_nn *nn, const tirenv_contact_law *law,
                                  int version)
{
    const tirenv_nn_topology *t = tirenv_nn_topology_of(nn);
    const size_t n_in = tirenv_nn_n_inputs(nn);
    double mean[TIRENV_NN_MAX_WIDTH], std[TIRENV_NN_MAX_WIDTH], lo[TIRENV_NN_MAX_WIDTH],
        hi[TIRENV_NN_MAX_WIDTH], out[2];
    tirenv_nn_scaling(nn, mean, std, &out[0], &out[1]);
    tirenv_nn_input_range(nn, lo, hi);
    uint64_t h = fnv_u64(TIRENV_FNV1A64_OFFSET, t->n_layers);
    for (size_t l = 0; l < t->n_layers; ++l)
        h = fnv_u64(h, t->size[l]);
    h = fnv_doubles(h, tirenv_nn_n_weights(nn), tirenv_nn_weights_const(nn));
    h = fnv_doubles(h, n_in, mean);
    h = fnv_doubles(h, n_in, std);
    h = fnv_doubles(h, 2, out);
    h = fnv_doubles(h, n_in, lo);
    h = fnv_doubles(h, n_in, hi);
    if (version < 2)
        return h;
    tirenv_nn_input_form input;
    tirenv_nn_target_form target;
    tirenv_nn_form(nn, &input, &target);
    const double a = tirenv_nn_even_width(nn);
    h = fnv_u64(h, tirenv_nn_n_members(nn));
    h = fnv_u64(h, (uint64_t)input);
    h = fnv_u64(h, (uint64_t)target);
    h = fnv_doubles(h, 1, &a);
    if (version < 3)
        return h;
    /* The law turns the load a model is driven at into the network's contact length: a knot
     * edited by hand would move every curve the network gives, so it is covered too. */
    const size_t n = law ? law->n : 0;
    h = fnv_u64(h, n);
    h = fnv_doubles(h, n, law ? law->load : NULL);
    return fnv_doubles(h, n, law ? law->l_c : NULL);
}

void tirenv_nn_json__hash_text(char *buf, size_t n, uint64_t h)
{
    snprintf(buf, n, "fnv1a64:%016" PRIx64, h);
}

static int hash_parse(const char *s, uint64_t *h)
{
    if (strncmp(s, "fnv1a64:", 8) != 0 || strlen(s) != 8 + 16)
        return -1;
    uint64_t v = 0;
    for (const char *p = s + 8; *p; ++p) {
        const int d = *p >= '0' && *p <= '9' ? *p - '0' : *p >= 'a' && *p <= 'f' ? *p - 'a' + 10 : -1;
        if (d < 0)
            return -1;
        v = v << 4 | (uint64_t)d;
    }
    *h = v;
    return 0;
}

/* ---- Reading ---- */

typedef struct {
    const char *path;
    tirenv_diag *diag;
} rctx;

static int bad(const rctx *c, const char *field, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int bad(const rctx *c, const char *field, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return tirenv_error(c->diag, TIRENV_EPARSE, c->path, 0, field, "%s", msg);
}

static const char *json_kind(const json_t *v)
{
    switch (json_typeof(v)) {
    case JSON_OBJECT: return "an object";
    case JSON_ARRAY: return "an array";
    case JSON_STRING: return "a string";
    case JSON_INTEGER: return "an integer";
    case JSON_REAL: return "a number";
    case JSON_TRUE:
    case JSON_FALSE: return "a boolean";
    case JSON_NULL: return "null";
    }
    return "something else";
}

/* The member key of obj as the given JSON type; field names it in messages. */
static int member(const rctx *c, const json_t *obj, const char *key, const char *field,
                  json_type type, json_t **out)
{
    json_t *v = json_object_get(obj, key);
    *out = v;
    if (!v)
        return bad(c, field, "missing");
    const int ok = json_typeof(v) == type ||
                   (type == JSON_REAL && json_is_integer(v)) ||
                   (type == JSON_TRUE && json_is_boolean(v));
    if (!ok) {
        const char *want = type == JSON_OBJECT   ? "an object"
                           : type == JSON_ARRAY  ? "an array"
                           : type == JSON_STRING ? "a string"
                           : type == JSON_REAL   ? "a number"
                           : type == JSON_TRUE   ? "true or false"
                                                 : "an integer";
        return bad(c, field, "expected %s, found %s", want, json_kind(v));
    }
    return TIRENV_OK;
}

static int get_number(const rctx *c, const json_t *obj, const char *key, const char *field,
                      double *out)
{
    json_t *v;
    const int status = member(c, obj, key, field, JSON_REAL, &v);
    if (status)
        return status;
    *out = json_number_value(v);
    return isfinite(*out) ? TIRENV_OK : bad(c, field, "expected a finite number");
}

static int get_count(const rctx *c, const json_t *obj, const char *key, const char *field,
                     size_t max, size_t *out)
{
    json_t *v;
    const int status = member(c, obj, key, field, JSON_INTEGER, &v);
    if (status)
        return status;
    const json_int_t i = json_integer_value(v);
    if (i < 0 || (unsigned long long)i > max)
        return bad(c, field, "%lld is out of range; expected 0 to %zu", (long long)i, max);
    *out = (size_t)i;
    return TIRENV_OK;
}

static int get_string(const rctx *c, const json_t *obj, const char *key, const char *field,
                      char *buf, size_t n)
{
    json_t *v;
    const int status = member(c, obj, key, field, JSON_STRING, &v);
    if (status)
        return status;
    if (json_string_length(v) >= n)
        return bad(c, field, "longer than %zu characters", n - 1);
    snprintf(buf, n, "%s", json_string_value(v));
    return TIRENV_OK;
}

/* An array of exactly n finite numbers. */
static int number_array(const rctx *c, const json_t *a, const char *field, size_t n,
                        double out[])
{
    if (!json_is_array(a))
        return bad(c, field, "expected an array, found %s", json_kind(a));
    if (json_array_size(a) != n)
        return bad(c, field, "%zu numbers; expected %zu", json_array_size(a), n);
    for (size_t k = 0; k < n; ++k) {
        const json_t *v = json_array_get(a, k);
        if (!json_is_number(v))
            return bad(c, field, "element %zu: expected a number, found %s", k, json_kind(v));
        out[k] = json_number_value(v);
        if (!isfinite(out[k]))
            return bad(c, field, "element %zu: expected a finite number", k);
    }
    return TIRENV_OK;
}

static int get_number_array(const rctx *c, const json_t *obj, const char *key,
                            const char *field, size_t n, double out[])
{
    json_t *v;
    const int status = member(c, obj, key, field, JSON_ARRAY, &v);
    return status ? status : number_array(c, v, field, n, out);
}

static int read_topology(const rctx *c, const json_t *root, tirenv_nn_topology *t)
{
    json_t *top;
    int status = member(c, root, "topology", "topology", JSON_ARRAY, &top);
    if (status)
        return status;
    const size_t n = json_array_size(top);
    if (n < 2 || n > TIRENV_NN_MAX_LAYERS)
        return bad(c, "topology", "%zu layers; expected 2 to %d counting input and output", n,
                   TIRENV_NN_MAX_LAYERS);
    t->n_layers = n;
    for (size_t l = 0; l < n; ++l) {
        const json_t *v = json_array_get(top, l);
        if (!json_is_integer(v) || json_integer_value(v) < 1 ||
            json_integer_value(v) > TIRENV_NN_MAX_WIDTH)
            return bad(c, "topology", "layer %zu: expected an integer from 1 to %d", l,
                       TIRENV_NN_MAX_WIDTH);
        t->size[l] = (size_t)json_integer_value(v);
    }
    if (t->size[n - 1] != 1)
        return bad(c, "topology", "the output layer has %zu neurons; expected 1",
                   t->size[n - 1]);
    return TIRENV_OK;
}

static int read_header(const rctx *c, const json_t *root, int *version)
{
    char buf[64];
    json_t *v;
    int status = get_string(c, root, "format", "format", buf, sizeof buf);
    if (status)
        return status;
    if (strcmp(buf, TIRENV_NN_FORMAT) != 0)
        return bad(c, "format", "'%s'; expected '%s' (not a tirenv network model file)", buf,
                   TIRENV_NN_FORMAT);
    if ((status = member(c, root, "version", "version", JSON_INTEGER, &v)))
        return status;
    if (json_integer_value(v) < 1 || json_integer_value(v) > TIRENV_NN_FORMAT_VERSION)
        return bad(c, "version", "format version %lld; this build reads versions 1 to %d",
                   (long long)json_integer_value(v), TIRENV_NN_FORMAT_VERSION);
    *version = (int)json_integer_value(v);
    return TIRENV_OK;
}

/* Version 2: the forms, and how many networks the "members" array holds. Version 1: one
 * network of the paper's forms. */
static int read_forms(const rctx *c, const json_t *root, int version,
                      tirenv_nn_input_form *input, double *even_width,
                      tirenv_nn_target_form *target, size_t *members)
{
    *input = TIRENV_NN_INPUT_PAPER;
    *even_width = TIRENV_NN_EVEN_WIDTH;
    *target = TIRENV_NN_TARGET_H;
    *members = 1;
    if (version < 2)
        return TIRENV_OK;
    char buf[32];
    json_t *m;
    int status = get_string(c, root, "input_form", "input_form", buf, sizeof buf);
    if (status)
        return status;
    const int in = tirenv_nn_input_form_find(buf);
    if (in < 0)
        return bad(c, "input_form", "'%s'; expected 'paper' (x_N) or 'even' (the distance "
                   "from x_N = 1, rounded)", buf);
    if ((status = get_number(c, root, "even_width", "even_width", even_width)))
        return status;
    if (!(*even_width > 0))
        return bad(c, "even_width", "%g; expected > 0", *even_width);
    if ((status = get_string(c, root, "target", "target", buf, sizeof buf)))
        return status;
    const int out = tirenv_nn_target_form_find(buf);
    if (out < 0)
        return bad(c, "target", "'%s'; expected 'h' or 'h/H'", buf);
    if ((status = member(c, root, "members", "members", JSON_ARRAY, &m)))
        return status;
    if (json_array_size(m) < 1 || json_array_size(m) > TIRENV_NN_MAX_MEMBERS)
        return bad(c, "members", "%zu networks; expected 1 to %d", json_array_size(m),
                   TIRENV_NN_MAX_MEMBERS);
    *input = (tirenv_nn_input_form)in;
    *target = (tirenv_nn_target_form)out;
    *members = json_array_size(m);
    return TIRENV_OK;
}

static int read_inputs(const rctx *c, const json_t *root, size_t n_in)
{
    json_t *names, *act;
    char buf[64];
    int status = member(c, root, "inputs", "inputs", JSON_ARRAY, &names);
    if (status)
        return status;
    if (json_array_size(names) != n_in)
        return bad(c, "inputs", "%zu names for %zu input neurons", json_array_size(names),
                   n_in);
    for (size_t i = 0; i < n_in; ++i) {
        const json_t *v = json_array_get(names, i);
        if (!json_is_string(v))
            return bad(c, "inputs", "element %zu: expected a string", i);
        if (n_in == TIRENV_NN_INPUTS && strcmp(json_string_value(v), tirenv_nn_input_name(i)))
            return bad(c, "inputs", "input %zu is '%s'; expected '%s' (x_N, l_c, H, L in the "
                       "paper's order)", i, json_string_value(v), tirenv_nn_input_name(i));
    }
    if ((status = get_string(c, root, "output", "output", buf, sizeof buf)))
        return status;
    if (strcmp(buf, "h_m") != 0)
        return bad(c, "output", "'%s'; expected 'h_m'", buf);
    if ((status = member(c, root, "activation", "activation", JSON_OBJECT, &act)) ||
        (status = get_string(c, act, "hidden", "activation.hidden", buf, sizeof buf)))
        return status;
    if (strcmp(buf, "logistic") != 0)
        return bad(c, "activation.hidden", "'%s'; only 'logistic' is supported", buf);
    if ((status = get_string(c, act, "output", "activation.output", buf, sizeof buf)))
        return status;
    if (strcmp(buf, "identity") != 0)
        return bad(c, "activation.output", "'%s'; only 'identity' is supported", buf);
    return TIRENV_OK;
}

/* One network's "layers" array into the weights w of one member. */
static int read_layers(const rctx *c, const json_t *layers, const char *prefix,
                       const tirenv_nn *nn, double *w)
{
    const tirenv_nn_topology *t = tirenv_nn_topology_of(nn);
    int status;
    if (json_array_size(layers) != t->n_layers - 1)
        return bad(c, prefix, "%zu layers of weights; the topology needs %zu",
                   json_array_size(layers), t->n_layers - 1);
    for (size_t l = 1; l < t->n_layers; ++l) {
        const size_t n_prev = t->size[l - 1], n_out = t->size[l];
        double *wl = w + tirenv_nn_weight_index(nn, l, 0, 0);
        const json_t *layer = json_array_get(layers, l - 1);
        char field[96];
        json_t *rows;
        snprintf(field, sizeof field, "%s[%zu]", prefix, l - 1);
        if (!json_is_object(layer))
            return bad(c, field, "expected an object, found %s", json_kind(layer));
        snprintf(field, sizeof field, "%s[%zu].bias", prefix, l - 1);
        if ((status = get_number_array(c, layer, "bias", field, n_out, wl)))
            return status;
        snprintf(field, sizeof field, "%s[%zu].weights", prefix, l - 1);
        if ((status = member(c, layer, "weights", field, JSON_ARRAY, &rows)))
            return status;
        if (json_array_size(rows) != n_prev)
            return bad(c, field, "%zu rows; expected one per input neuron, %zu",
                       json_array_size(rows), n_prev);
        for (size_t i = 0; i < n_prev; ++i) {
            snprintf(field, sizeof field, "%s[%zu].weights[%zu]", prefix, l - 1, i);
            if ((status = number_array(c, json_array_get(rows, i), field, n_out,
                                       wl + (1 + i) * n_out)))
                return status;
        }
    }
    return TIRENV_OK;
}

/* training.data.contact_law of data into *law (law->n = 0 without one) and its source into
 * source (n bytes). */
static int read_law(const rctx *c, const json_t *data, tirenv_contact_law *law, char *source,
                    size_t n_source)
{
    law->n = 0;
    source[0] = '\0';
    json_t *o = json_object_get(data, "contact_law"), *G;
    if (!o)
        return TIRENV_OK;
    int status;
    if ((status = member(c, data, "contact_law", "training.data.contact_law", JSON_OBJECT,
                         &o)) ||
        (status = get_string(c, o, "source", "training.data.contact_law.source", source,
                             n_source)) ||
        (status = member(c, o, "load_N", "training.data.contact_law.load_N", JSON_ARRAY, &G)))
        return status;
    const size_t n = json_array_size(G);
    if (n < 2 || n > TIRENV_CONTACT_LAW_MAX)
        return bad(c, "training.data.contact_law.load_N", "%zu points; expected 2 to %d", n,
                   TIRENV_CONTACT_LAW_MAX);
    if ((status = number_array(c, G, "training.data.contact_law.load_N", n, law->load)) ||
        (status = get_number_array(c, o, "contact_length_m",
                                   "training.data.contact_law.contact_length_m", n, law->l_c)))
        return status;
    law->n = n;
    tirenv_diag why;
    tirenv_diag_clear(&why);
    if (tirenv_contact_law_check(law, &why))
        return bad(c, "training.data.contact_law", "%s", why.message);
    return TIRENV_OK;
}

/* The file's checksum against the network's numbers (and, from version 3 on, law's knots). */
static int check_sum(const rctx *c, const json_t *root, int version, const tirenv_nn *nn,
                     const tirenv_contact_law *law)
{
    char sum[64];
    uint64_t h;
    int status;
    if ((status = get_string(c, root, "checksum", "checksum", sum, sizeof sum)))
        return status;
    if (hash_parse(sum, &h))
        return bad(c, "checksum", "'%s'; expected 'fnv1a64:' and 16 lower-case hex digits", sum);
    const uint64_t got = tirenv_nn_json__checksum(nn, law, version);
    if (h != got) {
        char want[32];
        tirenv_nn_json__hash_text(want, sizeof want, got);
        return bad(c, "checksum", "the network's numbers%s give %s, the file says %s: the file "
                   "was altered or corrupted", version < 3 ? "" : " and its contact law "
                   "(training.data.contact_law)", want, sum);
    }
    return TIRENV_OK;
}

static int read_network(const rctx *c, const json_t *root, int version, tirenv_nn *nn)
{
    const size_t n_in = tirenv_nn_n_inputs(nn);
    double *w = tirenv_nn_weights(nn);
    double mean[TIRENV_NN_MAX_WIDTH], std[TIRENV_NN_MAX_WIDTH], lo[TIRENV_NN_MAX_WIDTH],
        hi[TIRENV_NN_MAX_WIDTH], out_mean, out_std;
    json_t *sc, *range, *layers;
    int status;
    if ((status = member(c, root, "scaling", "scaling", JSON_OBJECT, &sc)) ||
        (status = get_number_array(c, sc, "input_mean", "scaling.input_mean", n_in, mean)) ||
        (status = get_number_array(c, sc, "input_std", "scaling.input_std", n_in, std)) ||
        (status = get_number(c, sc, "output_mean", "scaling.output_mean", &out_mean)) ||
        (status = get_number(c, sc, "output_std", "scaling.output_std", &out_std)))
        return status;
    for (size_t i = 0; i < n_in; ++i)
        if (!(std[i] > 0))
            return bad(c, "scaling.input_std", "element %zu is %g; expected > 0", i, std[i]);
    if (!(out_std > 0))
        return bad(c, "scaling.output_std", "%g; expected > 0", out_std);
    if ((status = member(c, root, "input_range", "input_range", JSON_OBJECT, &range)) ||
        (status = get_number_array(c, range, "min", "input_range.min", n_in, lo)) ||
        (status = get_number_array(c, range, "max", "input_range.max", n_in, hi)))
        return status;
    for (size_t i = 0; i < n_in; ++i)
        if (!(lo[i] <= hi[i]))
            return bad(c, "input_range", "input %zu: min %g > max %g", i, lo[i], hi[i]);
    tirenv_nn_set_scaling(nn, mean, std, out_mean, out_std, NULL);
    tirenv_nn_set_input_range(nn, lo, hi, NULL);

    if (version < 2) {
        if ((status = member(c, root, "layers", "layers", JSON_ARRAY, &layers)) ||
            (status = read_layers(c, layers, "layers", nn, w)))
            return status;
    } else {
        json_t *members;
        const size_t K = tirenv_nn_n_members(nn), per = tirenv_nn_n_weights(nn) / K;
        if ((status = member(c, root, "members", "members", JSON_ARRAY, &members)))
            return status;
        for (size_t k = 0; k < K; ++k) {
            char field[64];
            const json_t *m = json_array_get(members, k);
            snprintf(field, sizeof field, "members[%zu]", k);
            if (!json_is_object(m))
                return bad(c, field, "expected an object, found %s", json_kind(m));
            snprintf(field, sizeof field, "members[%zu].layers", k);
            if ((status = member(c, m, "layers", field, JSON_ARRAY, &layers)) ||
                (status = read_layers(c, layers, field, nn, w + k * per)))
                return status;
        }
    }
    if (version < 3)
        return check_sum(c, root, version, nn, NULL);
    /* From version 3 on the checksum covers the contact law of the training record: read
     * here so that the checksum is checked before the record, as in older versions (a file
     * without the record, or whose record is no object, has none: read_training says so). */
    const json_t *t = json_object_get(root, "training");
    const json_t *data = json_is_object(t) ? json_object_get(t, "data") : NULL;
    tirenv_contact_law law = {.n = 0};
    char source[sizeof ((tirenv_train_record *)0)->law_source];
    if (json_is_object(data) && (status = read_law(c, data, &law, source, sizeof source)))
        return status;
    return check_sum(c, root, version, nn, &law);
}

static int read_error(const rctx *c, const json_t *errs, const char *key,
                      tirenv_train_error *e)
{
    char f[64];
    json_t *o;
    snprintf(f, sizeof f, "training.errors_m.%s", key);
    int status = member(c, errs, key, f, JSON_OBJECT, &o);
    if (status)
        return status;
    snprintf(f, sizeof f, "training.errors_m.%s.n", key);
    if ((status = get_count(c, o, "n", f, SIZE_MAX >> 8, &e->n)))
        return status;
    snprintf(f, sizeof f, "training.errors_m.%s.rms", key);
    if ((status = get_number(c, o, "rms", f, &e->rms)))
        return status;
    if (e->rms < 0)
        return bad(c, f, "%g; expected >= 0", e->rms);
    snprintf(f, sizeof f, "training.errors_m.%s.max", key);
    if ((status = get_number(c, o, "max", f, &e->max)))
        return status;
    if (e->max < 0)
        return bad(c, f, "%g; expected >= 0", e->max);
    return TIRENV_OK;
}

/* The training's schedule: trainer, seed, restarts, epochs, patience, and from version 2 on the
 * ensemble and the loss. */
static int read_schedule(const rctx *c, const json_t *t, int version, tirenv_train_record *rec)
{
    tirenv_train_settings *s = &rec->settings;
    const size_t big = SIZE_MAX >> 8;
    char buf[64];
    size_t seed;
    int status;
    if ((status = get_string(c, t, "trainer", "training.trainer", rec->trainer,
                             sizeof rec->trainer)))
        return status;
    if (!tirenv_trainer_type_find(rec->trainer))
        return bad(c, "training.trainer", "unknown trainer '%s'; expected backprop, rprop or "
                   "lm", rec->trainer);
    if ((status = get_count(c, t, "seed", "training.seed", (size_t)NN_JSON_INT_MAX, &seed)) ||
        (status = get_count(c, t, "restarts", "training.restarts", big, &s->restarts)) ||
        (status = get_count(c, t, "max_epochs", "training.max_epochs", big, &s->max_epochs)) ||
        (status = get_count(c, t, "patience", "training.patience", big, &s->patience)))
        return status;
    s->seed = (unsigned long)seed;
    if (version < 2)
        return TIRENV_OK;
    if ((status = get_count(c, t, "ensemble", "training.ensemble", TIRENV_NN_MAX_MEMBERS,
                            &s->ensemble)) ||
        (status = get_string(c, t, "loss", "training.loss", buf, sizeof buf)))
        return status;
    const int loss = tirenv_train_loss_find(buf);
    if (loss < 0)
        return bad(c, "training.loss", "'%s'; expected 'points' or 'curves'", buf);
    s->loss = (tirenv_train_loss)loss;
    return TIRENV_OK;
}

/* The trainers' settings (training.settings), checked as tirenv_train would check them. */
static int read_settings(const rctx *c, const json_t *t, tirenv_train_settings *s)
{
    json_t *set, *b, *rp, *lm, *v;
    char buf[64];
    int status;
    if ((status = member(c, t, "settings", "training.settings", JSON_OBJECT, &set)) ||
        (status = member(c, set, "backprop", "training.settings.backprop", JSON_OBJECT, &b)) ||
        (status = get_number(c, b, "learning_rate",
                             "training.settings.backprop.learning_rate",
                             &s->backprop.learning_rate)) ||
        (status = get_number(c, b, "momentum", "training.settings.backprop.momentum",
                             &s->backprop.momentum)) ||
        (status = member(c, b, "online", "training.settings.backprop.online", JSON_TRUE, &v)))
        return status;
    s->backprop.online = json_is_true(v);
    if ((status = member(c, set, "rprop", "training.settings.rprop", JSON_OBJECT, &rp)) ||
        (status = get_number(c, rp, "delta0", "training.settings.rprop.delta0",
                             &s->rprop.delta0)) ||
        (status = get_number(c, rp, "delta_min", "training.settings.rprop.delta_min",
                             &s->rprop.delta_min)) ||
        (status = get_number(c, rp, "delta_max", "training.settings.rprop.delta_max",
                             &s->rprop.delta_max)) ||
        (status = get_number(c, rp, "eta_plus", "training.settings.rprop.eta_plus",
                             &s->rprop.eta_plus)) ||
        (status = get_number(c, rp, "eta_minus", "training.settings.rprop.eta_minus",
                             &s->rprop.eta_minus)) ||
        (status = member(c, set, "lm", "training.settings.lm", JSON_OBJECT, &lm)) ||
        (status = get_string(c, lm, "solver", "training.settings.lm.solver", buf, sizeof buf)))
        return status;
    if (strcmp(buf, "cholesky") == 0)
        s->lm.solver = TIRENV_LM_CHOLESKY;
    else  /* 'gsl' too: version 0.1's second solver, gone with GSL */
        return bad(c, "training.settings.lm.solver", "'%s'; expected 'cholesky'", buf);
    if ((status = get_number(c, lm, "tau", "training.settings.lm.tau", &s->lm.tau)) ||
        (status = get_number(c, lm, "mu_max", "training.settings.lm.mu_max", &s->lm.mu_max)))
        return status;
    tirenv_diag why;
    tirenv_diag_clear(&why);
    if (tirenv_train_settings_check(s, &why))
        return bad(c, "training.settings", "%s: %s", why.field, why.message);
    return TIRENV_OK;
}

/* What the network was trained on (training.data): the data set, its fingerprint, the tire's
 * radius and its contact law. */
static int read_data(const rctx *c, const json_t *t, tirenv_train_record *rec)
{
    json_t *data;
    char buf[64];
    int status;
    if ((status = member(c, t, "data", "training.data", JSON_OBJECT, &data)) ||
        (status = get_string(c, data, "dir", "training.data.dir", rec->data,
                             sizeof rec->data)) ||
        (status = get_string(c, data, "fingerprint", "training.data.fingerprint", buf,
                             sizeof buf)))
        return status;
    if (hash_parse(buf, &rec->fingerprint))
        return bad(c, "training.data.fingerprint",
                   "'%s'; expected 'fnv1a64:' and 16 lower-case hex digits", buf);
    if ((status = get_number(c, data, "tire_R0_m", "training.data.tire_R0_m", &rec->R0)))
        return status;
    if (rec->R0 < 0)
        return bad(c, "training.data.tire_R0_m", "%g; expected >= 0 (0: unknown)", rec->R0);
    /* Optional: files written before it have none (the model's user is warned). */
    return read_law(c, data, &rec->law, rec->law_source, sizeof rec->law_source);
}

/* The restart each member of the ensemble came from (training.result.members, version 2 on):
 * none listed, or one per network. */
static int read_member_restarts(const rctx *c, const json_t *res, const tirenv_nn *nn,
                                size_t restarts, tirenv_train_report *r)
{
    json_t *mem;
    const int status = member(c, res, "members", "training.result.members", JSON_ARRAY, &mem);
    if (status)
        return status;
    const size_t n = json_array_size(mem);
    if (n != 0 && n != tirenv_nn_n_members(nn))
        return bad(c, "training.result.members", "%zu restarts listed for %zu networks", n,
                   tirenv_nn_n_members(nn));
    for (size_t i = 0; i < n; ++i) {
        const json_t *e = json_array_get(mem, i);
        if (!json_is_integer(e) || json_integer_value(e) < 0 ||
            (unsigned long long)json_integer_value(e) >= restarts)
            return bad(c, "training.result.members", "element %zu: expected a restart "
                       "number from 0 to %zu", i, restarts ? restarts - 1 : 0);
        r->member_restart[i] = (size_t)json_integer_value(e);
    }
    r->members = n;
    return TIRENV_OK;
}

/* How the training ended (training.result), consistent with itself and the settings. */
static int read_result(const rctx *c, const json_t *t, int version, const tirenv_nn *nn,
                       const tirenv_train_settings *s, tirenv_train_report *r)
{
    json_t *res;
    char buf[64];
    const size_t big = SIZE_MAX >> 8;
    int status;
    if ((status = member(c, t, "result", "training.result", JSON_OBJECT, &res)) ||
        (status = get_count(c, res, "restart", "training.result.restart", big, &r->restart)) ||
        (status = get_count(c, res, "epochs", "training.result.epochs", big, &r->epochs)) ||
        (status = get_count(c, res, "best_epoch", "training.result.best_epoch", big,
                            &r->best_epoch)) ||
        (status = get_number(c, res, "best_time_s", "training.result.best_time_s",
                             &r->best_time)) ||
        (status = get_count(c, res, "total_epochs", "training.result.total_epochs", big,
                            &r->total_epochs)) ||
        (status = get_number(c, res, "wall_time_s", "training.result.wall_time_s",
                             &r->wall_time)) ||
        (status = get_string(c, res, "stop", "training.result.stop", buf, sizeof buf)))
        return status;
    r->members = 0;
    if (version < 2) {
        r->members = 1;
        r->member_restart[0] = r->restart;
    } else if ((status = read_member_restarts(c, res, nn, s->restarts, r))) {
        return status;
    }
    if (r->best_epoch > r->epochs || r->epochs > r->total_epochs ||
        (s->restarts && r->restart >= s->restarts) || r->best_time < 0 || r->wall_time < 0)
        return bad(c, "training.result", "inconsistent: restart %zu of %zu, best epoch %zu of "
                   "%zu, %zu in all, times %g and %g s", r->restart, s->restarts,
                   r->best_epoch, r->epochs, r->total_epochs, r->best_time, r->wall_time);
    int found = 0;
    for (int k = TIRENV_TRAIN_MAX_EPOCHS; k <= TIRENV_TRAIN_CANCELLED; ++k)
        if (strcmp(buf, tirenv_train_stop_name((tirenv_train_stop)k)) == 0) {
            r->stop = (tirenv_train_stop)k;
            found = 1;
        }
    if (!found)
        return bad(c, "training.result.stop", "'%s'; expected max-epochs, patience, converged, "
                   "diverged or cancelled", buf);
    return TIRENV_OK;
}

/* The training record (optional): what the network's own shape says, then the file's record
 * of how it was trained, in the file's order. */
static int read_training(const rctx *c, const json_t *root, int version, const tirenv_nn *nn,
                         tirenv_train_record *rec)
{
    json_t *t = json_object_get(root, "training");
    memset(rec, 0, sizeof *rec);
    rec->settings = tirenv_train_paper(NULL);
    rec->settings.topology = *tirenv_nn_topology_of(nn);
    tirenv_nn_form(nn, &rec->settings.input, &rec->settings.target);
    rec->settings.even_width = tirenv_nn_even_width(nn);
    rec->report.members = tirenv_nn_n_members(nn);
    if (!t)
        return TIRENV_OK;  /* a network without its training record: allowed */
    if (!json_is_object(t))
        return bad(c, "training", "expected an object, found %s", json_kind(t));
    tirenv_train_report *r = &rec->report;
    json_t *errs;
    int status;
    if ((status = read_schedule(c, t, version, rec)) ||
        (status = read_settings(c, t, &rec->settings)) ||
        (status = read_data(c, t, rec)) ||
        (status = read_result(c, t, version, nn, &rec->settings, r)) ||
        (status = member(c, t, "errors_m", "training.errors_m", JSON_OBJECT, &errs)) ||
        (status = read_error(c, errs, "train", &r->error[TIRENV_SPLIT_TRAIN])) ||
        (status = read_error(c, errs, "control", &r->error[TIRENV_SPLIT_CONTROL])) ||
        (status = read_error(c, errs, "validation", &r->error[TIRENV_SPLIT_VALIDATION])))
        return status;
    return TIRENV_OK;
}

/* The largest model file read: 64 MiB. The largest network tirenv writes (64 members of six
 * layers 64 wide, 1.3 million weights at about 32 characters each, indentation included) is
 * some 43 MB; jansson holds about ten times the text, so a 100 MB file took 980 MB. */
#define NN_JSON_MAX_BYTES (64u << 20)

/* jansson reads through here, so that a file (or a pipe, or /dev/zero) stops at the cap,
 * after the file's first bytes (head) that are not a UTF-8 byte order mark. */
typedef struct {
    FILE *fp;
    size_t total;
    int too_big, failed;
    unsigned char head[3];
    size_t n_head;
} json_in;

/* A UTF-8 byte order mark is dropped, as every other reader of tirenv drops it (io.h), and as
 * RFC 8259 section 8.1 allows a parser to; other first bytes go to jansson as read. */
static void json_skip_bom(json_in *in)
{
    in->n_head = fread(in->head, 1, sizeof in->head, in->fp);
    in->total = in->n_head;
    if (in->n_head == 3 && memcmp(in->head, "\xEF\xBB\xBF", 3) == 0)
        in->n_head = 0;
}

static size_t json_read(void *buf, size_t n, void *arg)
{
    json_in *in = arg;
    if (in->n_head && n) { /* the first bytes, read to look for a byte order mark */
        const size_t k = n < in->n_head ? n : in->n_head;
        memcpy(buf, in->head, k);
        memmove(in->head, in->head + k, in->n_head - k);
        in->n_head -= k;
        return k;
    }
    if (in->total >= NN_JSON_MAX_BYTES) {
        in->too_big = 1;
        return (size_t)-1;
    }
    const size_t room = NN_JSON_MAX_BYTES - in->total;
    const size_t got = fread(buf, 1, n < room + 1 ? n : room + 1, in->fp);  /* 1 past: over? */
    in->total += got;
    if (in->total > NN_JSON_MAX_BYTES) {
        in->too_big = 1;
        return (size_t)-1;
    }
    if (got == 0 && ferror(in->fp)) {
        in->failed = errno ? errno : EIO;
        return (size_t)-1;
    }
    return got;
}

int tirenv_nn_read_json(const char *path, tirenv_nn **out, tirenv_train_record *rec,
                        tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (!out)
        return tirenv_error(diag, TIRENV_EINVAL, path ? path : "", 0, "",
                            "no place for the network read");
    *out = NULL;
    if (!path || !path[0])
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no model file named");
    const rctx c = {.path = path, .diag = diag};
    json_error_t err;
    json_in in = {.fp = fopen(path, "r")};
    if (!in.fp)
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open the model file: %s",
                            strerror(errno));
    errno = 0;
    json_skip_bom(&in);
    json_t *root = json_load_callback(json_read, &in, JSON_REJECT_DUPLICATES, &err);
    fclose(in.fp);
    if (in.too_big) {
        json_decref(root);
        return tirenv_error(diag, TIRENV_EPARSE, path, 0, "",
                            "larger than %u MiB; a tirenv model file is at most about 43 MB "
                            "(64 members of six layers 64 wide)", NN_JSON_MAX_BYTES >> 20);
    }
    if (in.failed) {
        json_decref(root);
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot read the model file: %s",
                            strerror(in.failed));
    }
    if (!root) {
        const int status = tirenv_error(diag, TIRENV_EPARSE, path,
                                        err.line > 0 ? (size_t)err.line : 0, "",
                                        "not valid JSON (truncated or corrupted?): %s",
                                        err.text);
        if (diag && err.line > 0 && err.column > 0)
            diag->column = (size_t)err.column;
        return status;
    }
    int status = TIRENV_OK, version = 0;
    tirenv_nn_topology t;
    tirenv_nn_input_form input;
    tirenv_nn_target_form target;
    double even_width;
    size_t members = 1;
    tirenv_nn *nn = NULL;
    if (!json_is_object(root))
        status = bad(&c, "", "expected a JSON object at the top, found %s", json_kind(root));
    if (!status)
        status = read_header(&c, root, &version);
    if (!status)
        status = tirenv_nn_json__check_keys(path, root, version, diag);
    if (!status)
        status = read_topology(&c, root, &t);
    if (!status)
        status = read_inputs(&c, root, t.size[0]);
    if (!status)
        status = read_forms(&c, root, version, &input, &even_width, &target, &members);
    if (!status && !(nn = tirenv_nn_alloc_ensemble(&t, members)))
        status = tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    tirenv_diag why;
    tirenv_diag_clear(&why);
    if (!status && tirenv_nn_set_form(nn, input, target, &why))
        status = bad(&c, "input_form", "%s", why.message);
    if (!status)
        tirenv_nn_set_even_width(nn, even_width, NULL);
    if (!status)
        status = read_network(&c, root, version, nn);
    tirenv_train_record scratch;
    if (!status)
        status = read_training(&c, root, version, nn, rec ? rec : &scratch);
    json_decref(root);
    if (status) {
        tirenv_nn_free(nn);
        return status;
    }
    *out = nn;
    return TIRENV_OK;
}
