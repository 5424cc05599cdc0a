/* The keys a model file's objects may hold (docs/formats.md section 10). Every key the format
 * knows is read, so a key outside these lists is a typo or a key in the wrong object: read
 * past, it would leave a member the file meant to set at its default (a "contact_law"
 * misspelt in a version 2 file gave curves from another contact law, exit 0). It is refused,
 * naming the file and the key's path. Objects of the wrong type are left to the readers,
 * which say what they expected. SPDX-License-Identifier: Apache-2.0 */
#include <stdio.h>
#include <string.h>
#include <jansson.h>

#include "formats/nn_json_impl.h"

typedef struct {
    const char *path;
    tirenv_diag *diag;
} kctx;

static int listed(const char *key, const char *const keys[])
{
    for (size_t k = 0; keys[k]; ++k)
        if (strcmp(key, keys[k]) == 0)
            return 1;
    return 0;
}

/* where: the object's path ("" at the top); keys: NULL-terminated. */
static int only(const kctx *c, const json_t *obj, const char *where, const char *const keys[])
{
    const char *key;
    const json_t *v;
    if (!json_is_object(obj))
        return TIRENV_OK;
    json_object_foreach((json_t *)obj, key, v) {
        if (listed(key, keys))
            continue;
        char field[160], expected[400] = "";
        snprintf(field, sizeof field, "%s%s%s", where, where[0] ? "." : "", key);
        for (size_t k = 0; keys[k]; ++k)
            snprintf(expected + strlen(expected), sizeof expected - strlen(expected), "%s%s",
                     k ? ", " : "", keys[k]);
        return tirenv_error(c->diag, TIRENV_EPARSE, c->path, 0, field,
                            "unknown key in %s; expected one of %s",
                            where[0] ? where : "the top-level object", expected);
    }
    return TIRENV_OK;
}

/* Each object of a "layers" array: a layer's bias and weights. */
static int layers_keys(const kctx *c, const json_t *layers, const char *where)
{
    static const char *const layer[] = {"bias", "weights", NULL};
    for (size_t l = 0; l < json_array_size(layers); ++l) {
        char at[96];
        snprintf(at, sizeof at, "%s[%zu]", where, l);
        const int status = only(c, json_array_get(layers, l), at, layer);
        if (status)
            return status;
    }
    return TIRENV_OK;
}

/* The networks: "layers" at the top (version 1) or in each of "members". */
static int network_keys(const kctx *c, const json_t *root, int version)
{
    static const char *const member[] = {"layers", NULL};
    if (version < 2)
        return layers_keys(c, json_object_get(root, "layers"), "layers");
    const json_t *members = json_object_get(root, "members");
    for (size_t k = 0; k < json_array_size(members); ++k) {
        const json_t *m = json_array_get(members, k);
        char at[64];
        snprintf(at, sizeof at, "members[%zu]", k);
        int status = only(c, m, at, member);
        snprintf(at, sizeof at, "members[%zu].layers", k);
        if (status || (status = layers_keys(c, json_object_get(m, "layers"), at)))
            return status;
    }
    return TIRENV_OK;
}

static int training_keys(const kctx *c, const json_t *t, int version)
{
    static const char *const training1[] = {"trainer", "seed", "restarts", "max_epochs",
        "patience", "settings", "data", "result", "errors_m", NULL};
    static const char *const training2[] = {"trainer", "seed", "restarts", "ensemble", "loss",
        "max_epochs", "patience", "settings", "data", "result", "errors_m", NULL};
    static const char *const settings[] = {"backprop", "rprop", "lm", NULL};
    static const char *const backprop[] = {"learning_rate", "momentum", "online", NULL};
    static const char *const rprop[] = {"delta0", "delta_min", "delta_max", "eta_plus",
        "eta_minus", NULL};
    static const char *const lm[] = {"solver", "tau", "mu_max", NULL};
    static const char *const data[] = {"dir", "fingerprint", "tire_R0_m", "contact_law", NULL};
    static const char *const law[] = {"load_N", "contact_length_m", "source", NULL};
    static const char *const result1[] = {"restart", "epochs", "best_epoch", "best_time_s",
        "total_epochs", "wall_time_s", "stop", NULL};
    static const char *const result2[] = {"restart", "members", "epochs", "best_epoch",
        "best_time_s", "total_epochs", "wall_time_s", "stop", NULL};
    static const char *const errors[] = {"train", "control", "validation", NULL};
    static const char *const error[] = {"n", "rms", "max", NULL};
    const json_t *set = json_object_get(t, "settings"), *d = json_object_get(t, "data"),
                 *e = json_object_get(t, "errors_m");
    int status;
    if ((status = only(c, t, "training", version < 2 ? training1 : training2)) ||
        (status = only(c, set, "training.settings", settings)) ||
        (status = only(c, json_object_get(set, "backprop"), "training.settings.backprop",
                       backprop)) ||
        (status = only(c, json_object_get(set, "rprop"), "training.settings.rprop", rprop)) ||
        (status = only(c, json_object_get(set, "lm"), "training.settings.lm", lm)) ||
        (status = only(c, d, "training.data", data)) ||
        (status = only(c, json_object_get(d, "contact_law"), "training.data.contact_law",
                       law)) ||
        (status = only(c, json_object_get(t, "result"), "training.result",
                       version < 2 ? result1 : result2)) ||
        (status = only(c, e, "training.errors_m", errors)))
        return status;
    for (size_t k = 0; errors[k]; ++k) {
        char at[64];
        snprintf(at, sizeof at, "training.errors_m.%s", errors[k]);
        if ((status = only(c, json_object_get(e, errors[k]), at, error)))
            return status;
    }
    return TIRENV_OK;
}

int tirenv_nn_json__check_keys(const char *path, const json_t *root, int version,
                               tirenv_diag *diag)
{
    static const char *const top1[] = {"format", "version", "inputs", "output", "topology",
        "activation", "scaling", "input_range", "layers", "checksum", "training", NULL};
    static const char *const top2[] = {"format", "version", "inputs", "output", "topology",
        "activation", "input_form", "even_width", "target", "scaling", "input_range",
        "members", "checksum", "training", NULL};
    static const char *const activation[] = {"hidden", "output", NULL};
    static const char *const scaling[] = {"input_mean", "input_std", "output_mean",
        "output_std", NULL};
    static const char *const range[] = {"min", "max", NULL};
    const kctx c = {.path = path, .diag = diag};
    int status;
    if ((status = only(&c, root, "", version < 2 ? top1 : top2)) ||
        (status = only(&c, json_object_get(root, "activation"), "activation", activation)) ||
        (status = only(&c, json_object_get(root, "scaling"), "scaling", scaling)) ||
        (status = only(&c, json_object_get(root, "input_range"), "input_range", range)) ||
        (status = network_keys(&c, root, version)))
        return status;
    return training_keys(&c, json_object_get(root, "training"), version);
}
