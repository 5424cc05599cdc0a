/* A model's state as bytes (docs/models.md section 1.7): what a host saves to rewind a model
 * and restores into it, or into a twin of the same type and tire. The driver's part (the load
 * and the flat-ground height) comes first, then the type's own (tirenv_model_ops's
 * state_size / _save / _restore). The profile is not in it: the model only borrows that.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "model/model_impl.h"
#include "model/model_state.h"

/* The layout: magic, total size, type name, tire fingerprint, load, z_flat, ready, then the
 * type's bytes, last a checksum of all before it (FNV-1a, 64 bits): a byte changed since the
 * save (a host's storage, a co-simulation master's copy) is refused, not restored as another
 * model's state; the fields' own checks caught only values out of range (a flat-ground height
 * moved within them shifted every h). Native byte order and doubles: a state is for this
 * build and machine. */
static const char magic[8] = {'t', 'i', 'r', 'e', 'n', 'v', 'S', '1'};
enum { NAME_BYTES = 16 };
#define HEAD_BYTES                                                                            \
    (sizeof magic + sizeof(uint64_t) + NAME_BYTES + sizeof(uint64_t) + 2 * sizeof(double) + 1)

/* FNV-1a, 64 bits: fnv(FNV_BASIS, ...) hashes a run of bytes, fnv(h, ...) goes on from h. A
 * zero byte only multiplies h by the prime, so a run of L of them multiplies it by the prime
 * to the L (mod 2^64): the same value in O(log L). A state is mostly such runs (the springs
 * model's and the ring's per element or node outside the contact, some 70 to 99 % of their
 * bytes), which the byte at a time took some 4 ns each. */
static const uint64_t FNV_BASIS = 0xcbf29ce484222325ull, FNV_PRIME = 0x100000001b3ull;

static uint64_t prime_to(size_t n)
{
    uint64_t r = 1, b = FNV_PRIME;
    for (; n; n >>= 1, b *= b)
        if (n & 1)
            r *= b;
    return r;
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n;) {
        if (b[i]) {
            h ^= b[i++];
            h *= FNV_PRIME;
            continue;
        }
        size_t j = i + 1;
        for (uint64_t w; j + sizeof w <= n && (memcpy(&w, b + j, sizeof w), w == 0);)
            j += sizeof w;
        while (j < n && !b[j])
            ++j;
        h *= prime_to(j - i);
        i = j;
    }
    return h;
}

/* The parameter blocks of only doubles are hashed as they lie (no padding in them); the cam's
 * doubles without its given bits (which keys a file set, not their values) and the padding
 * after them, whose bytes are whatever the stack held (a state saved in one instance was
 * refused by another of the same tire in a -O0 build); the solver settings field by field, as
 * their struct may have padding. */
unsigned long long tirenv_model__tire_print(const tirenv_tire *t)
{
    uint64_t h = FNV_BASIS;
    h = fnv(h, &t->springs, sizeof t->springs);
    h = fnv(h, &t->ring, sizeof t->ring);
    h = fnv(h, &t->cam, offsetof(tirenv_cam_params, given));
    const int method = (int)t->eq.method;
    const uint64_t max_iter = t->eq.max_iter;
    h = fnv(h, &method, sizeof method);
    h = fnv(h, &t->eq.eps_F, sizeof t->eq.eps_F);
    h = fnv(h, &t->eq.eps_z, sizeof t->eq.eps_z);
    h = fnv(h, &max_iter, sizeof max_iter);
    h = fnv(h, &t->eq.secant_dz, sizeof t->eq.secant_dz);
    return h;
}

static size_t type_bytes(const tirenv_model *m)
{
    return m->type->ops->state_size(m->state);
}

size_t tirenv_model_state_size(const tirenv_model *m)
{
    return HEAD_BYTES + type_bytes(m) + sizeof(uint64_t);
}

static uint64_t checksum(const void *buf, size_t size)
{
    return fnv(FNV_BASIS, buf, size - sizeof(uint64_t));
}

/* Several tracks hold several type states; the bytes are those of one. */
static int one_track(const tirenv_model *m, tirenv_diag *diag)
{
    if (m->ready && m->n_tracks > 1)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "the %s model is set with %zu tracks: a state is that of one track",
                            m->type->name, m->n_tracks);
    return TIRENV_OK;
}

int tirenv_model_state_save(const tirenv_model *m, void *buf, size_t size, tirenv_diag *diag)
{
    if (one_track(m, diag))
        return TIRENV_EINVAL;
    const size_t need = tirenv_model_state_size(m);
    if (!buf || size != need)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "the %s model's state takes %zu bytes; got a buffer of %zu%s",
                            m->type->name, need, size, buf ? "" : " (NULL)");
    char name[NAME_BYTES] = {0};
    const size_t len = strlen(m->type->name);
    memcpy(name, m->type->name, len < NAME_BYTES ? len : NAME_BYTES - 1);
    const uint64_t total = need, print = m->tire_print;
    const unsigned char ready = (unsigned char)(m->ready != 0);
    unsigned char *p = buf;
    p = tirenv_model__put(p, magic, sizeof magic);
    p = tirenv_model__put(p, &total, sizeof total);
    p = tirenv_model__put(p, name, sizeof name);
    p = tirenv_model__put(p, &print, sizeof print);
    p = tirenv_model__put(p, &m->load, sizeof m->load);
    p = tirenv_model__put(p, &m->z_flat, sizeof m->z_flat);
    p = tirenv_model__put(p, &ready, 1);
    /* An unset model's type bytes are never restored (only its being unset is), and its
     * type may point at ground freed since (a streamed sweep's last window, which the
     * springs model's save read): zeros. */
    if (m->ready)
        m->type->ops->state_save(m->state, p);
    else
        memset(p, 0, type_bytes(m));
    const uint64_t sum = checksum(buf, need);
    memcpy((unsigned char *)buf + need - sizeof sum, &sum, sizeof sum);
    return TIRENV_OK;
}

/* Checks everything before it touches the model, so that a wrong buffer leaves it as it
 * was; only the type's own restore may fail after that, and then the model is unset. */
int tirenv_model_state_restore(tirenv_model *m, const void *buf, size_t size,
                               tirenv_diag *diag)
{
    if (one_track(m, diag))
        return TIRENV_EINVAL;
    const size_t need = tirenv_model_state_size(m);
    if (!buf || size != need)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "a state of the %s model takes %zu bytes; got %zu%s",
                            m->type->name, need, size, buf ? "" : " (NULL)");
    char head[sizeof magic], name[NAME_BYTES];
    uint64_t total, print;
    double load, z_flat;
    unsigned char ready;
    const unsigned char *p = buf;
    p = tirenv_model__get(p, head, sizeof head);
    p = tirenv_model__get(p, &total, sizeof total);
    p = tirenv_model__get(p, name, sizeof name);
    p = tirenv_model__get(p, &print, sizeof print);
    p = tirenv_model__get(p, &load, sizeof load);
    p = tirenv_model__get(p, &z_flat, sizeof z_flat);
    p = tirenv_model__get(p, &ready, 1);
    name[NAME_BYTES - 1] = '\0';
    if (memcmp(head, magic, sizeof magic) != 0 || total != need)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a saved model state (tirenv_model_state_save)");
    uint64_t sum;
    memcpy(&sum, (const unsigned char *)buf + need - sizeof sum, sizeof sum);
    if (sum != checksum(buf, need))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "the state's bytes have changed since it was saved (its checksum "
                            "does not match them)");
    if (strcmp(name, m->type->name) != 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "a state of the %s model cannot be restored into a %s model", name,
                            m->type->name);
    if (print != m->tire_print)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "the state was saved from a model of another tire");
    if (ready > 1 || (ready && !(load > 0 && isfinite(load) && isfinite(z_flat))))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a saved model state (load %g N, z_flat %g m)", load, z_flat);
    if (!ready) {
        m->ready = 0;
        return TIRENV_OK;
    }
    if (!m->profile)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "the %s model has no profile: set it on the ground the state was "
                            "saved on (tirenv_model_set), then restore", m->type->name);
    const int status = m->type->ops->state_restore(m->state, p, load, z_flat, diag);
    if (status) {
        m->ready = 0;
        m->profile = NULL;
        return status;
    }
    m->load = load;
    m->z_flat = z_flat;
    m->ready = 1;
    m->reach = tirenv_model_reach(m);
    return TIRENV_OK;
}

int tirenv_model__restore_load(const unsigned char *buf, const char *type, double load,
                               double z_flat, double z_own, double *G, tirenv_diag *diag)
{
    double g;
    tirenv_model__get(buf, &g, sizeof g);
    if (!(g > 0 && isfinite(g)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state", "not a %s state (its load %g N)",
                            type, g);
    if (g != load || z_flat != z_own)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a %s state: its load %.17g N and flat-ground height %.17g m "
                            "are not the head's %.17g N and %.17g m", type, g, z_own, load,
                            z_flat);
    *G = g;
    return TIRENV_OK;
}
