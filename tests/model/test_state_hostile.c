/* A state whose bytes were changed and its checksum made again (a hostile host handing it back
 * through fmi2DeSerializeFMUstate, or a bug in one) passes every check of
 * tirenv_model_state_restore but the type's own. Each model's restore must refuse it, saying
 * why, or restore something that evaluates safely: never index the ground, its elements,
 * rows or nodes out of their bounds (the sanitizer build finds a read past them; an index far
 * out of them faults in any build), never hang, and never give a NaN or an infinity as a
 * result. docs/models.md section 1.7.
 *
 * After each restore the model is evaluated on the obstacle (two positions, the second a step
 * on from the first), on level ground (the flat-ground point the state holds, answered
 * without a force evaluation) and, after a new load (the flat-ground twin's warm start), on
 * level ground again; an evaluation may fail on nonsense restored, saying why, never fault,
 * and what it returns is finite. Where the word fell wholly within a warm start (what only
 * says where a solve begins), a state taken gives the answers of the state as saved to the
 * solver's tolerances: each answer is unique, whatever the start.
 *
 * Every layout a save writes: the springs model with continuous contact (its carry), with
 * rays, with a sidewall in series; the ring with the shear-coupled tread, the Winkler tread
 * and rays, with lugs and with a softening carcass; the rigid disc, the point, the cam, the
 * network over a cleat and over a road; a model set on several tracks (no state), an unset
 * one after a streamed sweep; and the head's load and flat-ground height against each type's
 * own copies.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "model/ring_impl.h"
#include "model/springs_impl.h"
#include "tirenv/tirenv.h"

/* The bytes of the model's head (magic, size, name, tire, load, z_flat, ready). */
enum { HEAD = 8 + 8 + 16 + 8 + 2 * 8 + 1 };

/* The new load after a restore, of the load G: NEW_LOAD G. */
static const double NEW_LOAD = 1.0173;

static const uint64_t FNV_PRIME = 0x100000001b3ull;

/* FNV-1a, 64 bits, from h on over b[0 .. n): eight zero bytes multiply h by the prime to the
 * eighth (a state is mostly zeros; the byte at a time made the resealing most of the test's
 * time). Checked against tirenv_test_fnv1a on every state the test takes. */
static uint64_t fnv_on(uint64_t h, const unsigned char *b, size_t n)
{
    const uint64_t p8 = FNV_PRIME * FNV_PRIME * FNV_PRIME * FNV_PRIME * FNV_PRIME * FNV_PRIME *
                        FNV_PRIME * FNV_PRIME;
    for (size_t i = 0; i < n;) {
        uint64_t w;
        if (i + sizeof w <= n && (memcpy(&w, b + i, sizeof w), w == 0)) {
            h *= p8;
            i += sizeof w;
            continue;
        }
        h ^= b[i++];
        h *= FNV_PRIME;
    }
    return h;
}

static uint64_t bits_of(double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    return b;
}

static double double_of(uint64_t b)
{
    double v;
    memcpy(&v, &b, sizeof v);
    return v;
}

/* A model, the ground it was set on at load G, its state saved and what the test counts. */
typedef struct {
    tirenv_model *m;
    const tirenv_profile *p;
    double G, l_c;      /* the load, from the contact length l_c (N, m) */
    size_t size;
    unsigned char *saved, *buf;
    uint64_t *pre;      /* pre[at]: FNV-1a of saved[0 .. at) */
    double x_on[2];     /* on the obstacle, m */
    double x_level;     /* on level ground, m */
    unsigned what;      /* what follows a restore: ON | LEVEL | LOAD */
    /* same[k][0] .. same[k][1] - 1: bytes that hold only where solves start (a warm start),
     * so that a state with a word written wholly within them, restored, gives the answers on
     * the obstacle of the state as saved, ref, and on level ground after the new load,
     * ref_load, to the solver's tolerances (each answer is unique) */
    size_t same[4][2];
    tirenv_point ref[2], ref_load;
    double dz_max, dfx_max;
    size_t changed, refused, failed;
} hostile;

/* After a restore: evaluations on the obstacle; on level ground; a new load, then level
 * ground. A part of a state that only one of them reads (the flat-ground twin of a deformable
 * model: only a new load solves on it) is followed by that one alone. */
enum { ON = 1, LEVEL = 2, LOAD = 4, ALL = ON | LEVEL | LOAD };

static void hostile_save(hostile *h, tirenv_model *m, const tirenv_profile *p, double G,
                         double l_c, double x0, double x1, double x_level)
{
    tirenv_diag d;
    *h = (hostile){.m = m,
                   .p = p,
                   .G = G,
                   .l_c = l_c,
                   .x_on = {x0, x1},
                   .x_level = x_level,
                   .what = ALL};
    h->size = tirenv_model_state_size(m);
    h->saved = malloc(h->size);
    h->buf = malloc(h->size);
    h->pre = malloc(h->size * sizeof *h->pre);
    assert_true(h->saved && h->buf && h->pre);
    assert_int_equal(tirenv_model_state_save(m, h->saved, h->size, &d), TIRENV_OK);
    uint64_t f = 0xcbf29ce484222325ull;
    for (size_t at = 0; at < h->size; ++at) {
        h->pre[at] = f;
        f = (f ^ h->saved[at]) * FNV_PRIME;
    }
    const size_t n = h->size - sizeof f;
    uint64_t sum;
    memcpy(&sum, h->saved + n, sizeof sum);
    assert_true(sum == tirenv_test_fnv1a(h->saved, n));
    assert_true(fnv_on(h->pre[0], h->saved, n) == sum);
    for (size_t i = 0; i < 2; ++i)
        assert_int_equal(tirenv_model_eval(m, h->x_on[i], &h->ref[i], &d), TIRENV_OK);
    assert_int_equal(tirenv_model_state_restore(m, h->saved, h->size, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set_load(m, NEW_LOAD * G, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, x_level, &h->ref_load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_state_restore(m, h->saved, h->size, &d), TIRENV_OK);
}

static void hostile_free(hostile *h)
{
    free(h->saved);
    free(h->buf);
    free(h->pre);
}

/* The answers from a warm start restored against those from the state as saved: ten times
 * the equilibrium's tolerances eps_z and eps_F (the rays' node states with stray bits gave
 * z 11 mm and F_x 1 kN off, as if converged). */
static const double DZ_SAME = 1e-9, DFX_SAME = 1e-3;

static int finite_point(const tirenv_point *pt)
{
    return isfinite(pt->x) && isfinite(pt->z) && isfinite(pt->h) && isfinite(pt->slope) &&
           isfinite(pt->fx) && isfinite(pt->fz);
}

static void eval_at(hostile *h, double x, uint64_t word, size_t at, const tirenv_point *ref)
{
    tirenv_diag d;
    tirenv_point pt;
    if (tirenv_model_eval(h->m, x, &pt, &d) != TIRENV_OK) {
        ++h->failed;
        assert_true(d.message[0] != '\0');
        return;
    }
    if (!finite_point(&pt))
        fail_msg("%s: the word %#llx at byte %zu of %zu: at x = %g a point that is not finite "
                 "(z %g, h %g, fx %g, fz %g)",
                 tirenv_model_name(h->m), (unsigned long long)word, at, h->size, x, pt.z, pt.h,
                 pt.fx, pt.fz);
    if (ref) {
        const double dz = fabs(pt.z - ref->z), dfx = fabs(pt.fx - ref->fx);
        h->dz_max = dz > h->dz_max ? dz : h->dz_max;
        h->dfx_max = dfx > h->dfx_max ? dfx : h->dfx_max;
        if (!(dz <= DZ_SAME && dfx <= DFX_SAME))
            fail_msg("%s: the word %#llx at byte %zu of %zu: at x = %g z %.17g m, F_x %.17g N; "
                     "from the state as saved %.17g m, %.17g N",
                     tirenv_model_name(h->m), (unsigned long long)word, at, h->size, x, pt.z,
                     pt.fx, ref->z, ref->fx);
    }
}

/* The state saved with word at byte at, resealed, restored and evaluated from. */
static void try_word(hostile *h, size_t at, uint64_t word)
{
    tirenv_diag d;
    const size_t n = h->size - sizeof word;
    memcpy(h->buf, h->saved, h->size);
    memcpy(h->buf + at, &word, sizeof word);
    const uint64_t sum = fnv_on(h->pre[at], h->buf + at, n - at);
    memcpy(h->buf + n, &sum, sizeof sum);
    ++h->changed;
    const int taken = tirenv_model_state_restore(h->m, h->buf, h->size, &d) == TIRENV_OK;
    int same = 0;
    for (size_t k = 0; taken && k < 4; ++k)
        same |= at >= h->same[k][0] && at + sizeof word <= h->same[k][1];
    if (!taken) {
        ++h->refused;
        assert_true(d.message[0] != '\0');
        /* a model a restore unset is set again and goes on; the network's pinned pair of
         * load and contact length (which its state holds, and the set takes) made again
         * where it fails */
        if (tirenv_model_set(h->m, h->p, h->G, &d) != TIRENV_OK) {
            assert_true(d.message[0] != '\0');
            double G;
            assert_int_equal(tirenv_model_load_for_contact_length(h->m, h->l_c, &G, &d),
                             TIRENV_OK);
            assert_true(G == h->G);
            assert_int_equal(tirenv_model_set(h->m, h->p, h->G, &d), TIRENV_OK);
        }
    }
    if (h->what & ON) {
        eval_at(h, h->x_on[0], word, at, same ? &h->ref[0] : NULL);
        eval_at(h, h->x_on[1], word, at, same ? &h->ref[1] : NULL);
    }
    if (h->what & LEVEL)
        eval_at(h, h->x_level, word, at, NULL);
    if (!(h->what & LOAD))
        return;
    if (tirenv_model_set_load(h->m, NEW_LOAD * h->G, &d) == TIRENV_OK)
        eval_at(h, h->x_level, word, at, same ? &h->ref_load : NULL);
    else
        assert_true(d.message[0] != '\0');
}

/* The words written over was: as a size or an index, large, -1 and half the address space;
 * as a double NaN, the infinities, huge, and was +- 1 (a node index saved as a double) and
 * -was; and was +- 1 as an integer. At a place that straddles two fields only the first two
 * (each makes the two fields' bytes garbage). */
static void try_place(hostile *h, size_t at, int aligned)
{
    uint64_t was;
    memcpy(&was, h->saved + at, sizeof was);
    const double v = double_of(was);
    const uint64_t words[] = {(uint64_t)1 << 40, (uint64_t)-1, (uint64_t)1 << 63, was + 1,
                              was - 1, bits_of(NAN), bits_of(INFINITY), bits_of(-INFINITY),
                              bits_of(1e300), bits_of(-1e300), bits_of(v + 1), bits_of(v - 1),
                              bits_of(-v)};
    const size_t n = aligned ? sizeof words / sizeof words[0] : 2;
    for (size_t k = 0; k < n; ++k)
        if (words[k] != was)
            try_word(h, at, words[k]);
}

/* Every place in [a, b), the fields 8-byte words from a; none past the checksum. */
static void every_place(hostile *h, size_t a, size_t b, int straddle)
{
    const size_t end = h->size - 2 * sizeof(uint64_t) + 1;
    for (size_t at = a; at < b && at < end; ++at)
        if ((at - a) % 8 == 0 || straddle)
            try_place(h, at, (at - a) % 8 == 0);
}

/* n places of the array in [a, b) of doubles (stride 8) or bytes (stride 1), drawn from those
 * whose word is not zero, and its first that is zero (if any). */
static void sample_places(hostile *h, size_t a, size_t b, size_t stride, size_t n,
                          uint64_t *seed)
{
    size_t *nz = malloc(((b - a) / stride + 1) * sizeof *nz), n_nz = 0, zero = (size_t)-1;
    assert_non_null(nz);
    for (size_t at = a; at + 8 <= b; at += stride) {
        uint64_t was;
        memcpy(&was, h->saved + at, sizeof was);
        if (was)
            nz[n_nz++] = at;
        else if (zero == (size_t)-1)
            zero = at;
    }
    for (size_t i = 0; i < n && n_nz; ++i)
        try_place(h, nz[(size_t)(tirenv_test_uniform(seed) * (double)n_nz)], stride == 8);
    if (zero != (size_t)-1)
        try_place(h, zero, stride == 8);
    free(nz);
}

/* The bytes of deformable.c's record (the load, the flat-ground point, the history of
 * equilibria), which the springs model's state and the ring's hold after the head: a ring's
 * state less its head, checksum and two ring states. */
static size_t deformable_record(void)
{
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_type_find("ring"), &tire);
    tirenv_ring *twin = tirenv_ring_alloc(tire.springs.R0, &tire.ring);
    assert_true(m && twin);
    const size_t size = tirenv_model_state_size(m), ring_bytes = tirenv_ring__state_size(twin);
    assert_true(size > HEAD + 2 * ring_bytes + 8);
    const size_t record = size - HEAD - 2 * ring_bytes - 8;
    assert_true(record >= 8 && record < 512);
    tirenv_ring_free(twin);
    tirenv_model_free(m);
    return record;
}

/* The springs model's state taken on the bench cleat's edge: the driver's head, deformable.c's
 * record, then two springs states (the model's and its flat-ground twin's), each the window
 * a, b (two size_t), the active set (N bytes), whether a row between elements worked and at
 * which height (1 byte and a double), and with continuous contact the model's carry of the
 * QP's working set and the rays' memos (springs_carry.c). The contact is unique whatever the
 * start, so past deformable.c's record all of it is warm start. */
typedef enum {
    SPRINGS_EVERY, /* -1 and a large index at every place of the type's bytes not zero */
    SPRINGS_PARTS  /* every place of the head, the record and the small fields, every place
                    * within a word of a boundary; a seeded sample of the arrays' places */
} springs_cover;

static void springs_hostile(const tirenv_tire *tire, const char *label, springs_cover cover,
                            uint64_t seed)
{
    tirenv_profile *p = tirenv_profile_cleat(0.30, 0.10);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, tire);
    tirenv_springs *twin = tirenv_springs_alloc(&tire->springs);
    assert_true(p && m && twin);
    tirenv_diag d;
    double G;
    tirenv_point pt;
    assert_int_equal(tirenv_model_load_for_contact_length(m, 0.38, &G, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
    /* on the cleat's edge, the held elements' rays ending on its vertices, rows between
     * elements working; the state taken after a repeat at the same x too */
    const double xs[] = {-0.200, -0.199, -0.198, -0.198};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i)
        assert_int_equal(tirenv_model_eval(m, xs[i], &pt, &d), TIRENV_OK);
    hostile h;
    hostile_save(&h, m, p, G, 0.38, -0.198, -0.197, -1.0);
    const size_t record = deformable_record(), N = tirenv_springs_size(twin),
                 flat_bytes = tirenv_springs__state_size(twin, 1);
    assert_true(h.size >= HEAD + record + 2 * flat_bytes + 8);
    const size_t model_bytes = h.size - HEAD - record - flat_bytes - 8;
    const int cont = tire->springs.contact == TIRENV_SPRINGS_CONTINUOUS;
    assert_int_equal(flat_bytes, 2 * sizeof(size_t) + N + 1 + sizeof(double));
    assert_true(cont ? model_bytes > flat_bytes : model_bytes == flat_bytes);
    /* the history of equilibria and its flags (deformable.c's record: a last height where
     * the tire barely touches, 0.779 m, gave 1.006 mm and 143 N off at the repeated x while
     * a memo moved across a vertex kept its old walk's proof, springs_ray.c's
     * memo_across); the window, active set, carry and memos */
    const size_t same[4][2] = {{HEAD + 16, HEAD + 48}, {HEAD + 104, HEAD + 112},
                               {HEAD + record, h.size}};
    memcpy(h.same, same, sizeof same);
    if (cover == SPRINGS_EVERY) {
        for (size_t at = HEAD; at + 2 * sizeof(uint64_t) <= h.size; ++at) {
            uint64_t was;
            memcpy(&was, h.saved + at, sizeof was);
            if (was)
                try_place(&h, at, 0);
        }
    } else {
        every_place(&h, 0, HEAD, 1);
        every_place(&h, HEAD, HEAD + record, 1);
        for (size_t e = 0; e < 2; ++e) {
            const size_t b = HEAD + record + e * model_bytes, active = b + 2 * sizeof(size_t),
                         between = active + N, carry = between + 1 + sizeof(double),
                         end = e ? h.size - 8 : b + model_bytes;
            h.what = e ? LOAD : ALL; /* the flat twin: only a new load solves on it */
            every_place(&h, b - 7, active, 1);
            sample_places(&h, active, between, 1, 24, &seed);
            every_place(&h, between - 7, carry, 1);
            if (carry < end)
                sample_places(&h, carry, end, 1, 48, &seed);
        }
    }
    print_message("springs (%s): %zu bytes, %zu hostile states, %zu refused, %zu evaluations "
                  "failed; from a warm start restored, z and F_x within %.3g m and %.3g N\n",
                  label, h.size, h.changed, h.refused, h.failed, h.dz_max, h.dfx_max);
    assert_true(h.changed > 100);
    assert_true(h.refused > 0);
    /* the state as saved is still taken */
    assert_int_equal(tirenv_model_state_restore(m, h.saved, h.size, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, -0.197, &pt, &d), TIRENV_OK);
    hostile_free(&h);
    tirenv_springs_free(twin);
    tirenv_model_free(m);
    tirenv_profile_free(p);
}

/* The default: continuous contact, its carry of the QP's working set and the rays' memos. */
static void test_springs_carry_hostile(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    assert_int_equal(tire.springs.contact, TIRENV_SPRINGS_CONTINUOUS);
    springs_hostile(&tire, "continuous", SPRINGS_EVERY, 0);
}

/* The paper's rays: no carry; and a sidewall in series, whose deflection u puts the hub's
 * flat-ground height (the head's) u below the elements' centre's (the record's). */
static void test_springs_configurations_hostile(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.springs.contact = TIRENV_SPRINGS_RAYS;
    springs_hostile(&tire, "rays", SPRINGS_PARTS, 0x5113);
    tire = tirenv_tire_default();
    tire.springs.k_s = 1.7321e6;
    tire.springs.F_s0 = 9876.5;
    springs_hostile(&tire, "continuous, sidewall in series", SPRINGS_PARTS, 0x6029);
}

/* The ring's state taken on the bench cleat after a few evaluations (the warm start's window,
 * w, the tread surface u and the slopes in z, the contact's span and the root's curvatures
 * all set). Its parts, as deformable.c and ring.c write them: the driver's head, the
 * deformable record, then two ring states (the model's and its flat-ground twin's), each the
 * window (two size_t), the node states (M bytes), and with the continuous contact w (M
 * doubles), with the shear-coupled tread u, dw, du (3 M doubles), the prediction's and the
 * span's 7 doubles and the root's record. Every place of the head, the record and the window,
 * every place within a word of a boundary between parts, every field of the 7 doubles and the
 * root; in the arrays a seeded sample of places: their entries are read alike (a loop over the
 * window, the checks of restore over every entry), so that a few hit every kind of value
 * their fields hold, where all of their places would take some 40 times as many states. The
 * rays' contact (its state the window and the node states alone, which only it reads) with
 * more of the node states. */
typedef enum {
    RING_HEAD,   /* and every place of the head and deformable.c's record */
    RING_ARRAYS, /* the ring states' parts alone */
    RING_FEW     /* the model's ring state alone: its window and a place of each array, of the
                  * 7 doubles and of the root record: the default's layout (RING_HEAD covers
                  * its every field) on a costlier solve */
} ring_cover;

static void ring_hostile(tirenv_tire tire, const char *label, ring_cover cover, uint64_t seed)
{
    tire.ring.dtheta = M_PI / 180; /* nodes a degree apart: the same layout, the test a
                                    * seventh of its time with the default's 0.25 degree */
    const tirenv_ring_contact_kind contact = tire.ring.contact;
    tirenv_diag d;
    assert_int_equal(tirenv_tire_check(&tire, &d), TIRENV_OK);
    tirenv_profile *p = tirenv_profile_cleat(0.30, 0.10);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_type_find("ring"), &tire);
    tirenv_ring *twin = tirenv_ring_alloc(tire.springs.R0, &tire.ring);
    assert_true(p && m && twin);
    double G;
    tirenv_point pt;
    assert_int_equal(tirenv_model_load_for_contact_length(m, 0.38, &G, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
    /* the cleat inside the patch, the root's curvatures on both sides */
    const double xs[] = {-0.240, -0.235, -0.230, -0.225, -0.220};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i)
        assert_int_equal(tirenv_model_eval(m, xs[i], &pt, &d), TIRENV_OK);
    assert_true(pt.contacts > 0);
    hostile h;
    /* the next positions within the warm start's reach of the last (ring_shear.c, WARM_DX) */
    hostile_save(&h, m, p, G, 0.38, -0.219, -0.218, -1.0);
    const int cont = contact == TIRENV_RING_CONTINUOUS, shear = cont && twin->tread;
    const size_t M = twin->M, ring_bytes = tirenv_ring__state_size(twin),
                 tread = shear ? tirenv_ring__tread_warm_size(twin->tread) : 0;
    assert_int_equal(ring_bytes, 2 * sizeof(size_t) + M + (cont * M + tread) * sizeof(double) +
                                     shear * sizeof(tirenv_ring_root));
    assert_true(h.size > HEAD + 2 * ring_bytes + 8);
    const size_t record = h.size - HEAD - 2 * ring_bytes - 8; /* deformable.c's */
    assert_true(record >= 8 && record < 512);
    /* deformable.c's record: G, z_flat, then the history's z_prev, x_prev, x_prev2,
     * z_prev2, the flat-ground point (an equilibrium point of 56 bytes) and the history's
     * two flags; the history and the model's ring state are warm starts */
    assert_int_equal(record, 112);
    const size_t same[4][2] = {{HEAD + 16, HEAD + 48}, {HEAD + 104, HEAD + 112},
                               {HEAD + record, HEAD + record + 2 * ring_bytes}};
    memcpy(h.same, same, sizeof same);
    if (cover == RING_HEAD) { /* the head and record, the same in every configuration */
        every_place(&h, 0, HEAD, 1);
        every_place(&h, HEAD, HEAD + record, 1);
    }
    for (size_t e = 0; e < (cover == RING_FEW ? 1u : 2u); ++e) {
        const size_t b = HEAD + record + e * ring_bytes, states = b + 2 * sizeof(size_t),
                     w = states + M, u = w + cont * M * sizeof(double),
                     small = u + (shear ? 3 * M * sizeof(double) : 0),
                     root = small + (shear ? 7 * sizeof(double) : 0),
                     end = b + ring_bytes;
        if (cover == RING_FEW) {
            h.what = ON;
            every_place(&h, b, states, 0);
            sample_places(&h, states, w, 1, 1, &seed);
            sample_places(&h, w, u, 8, 1, &seed);
            if (shear) {
                sample_places(&h, u, small, 8, 1, &seed);
                sample_places(&h, small, root, 8, 1, &seed);
                sample_places(&h, root, end, 8, 1, &seed);
            }
            continue;
        }
        h.what = e ? ON | LOAD : ALL; /* the part before and this one */
        every_place(&h, b - 7, b, 1);
        h.what = e ? LOAD : ON;
        every_place(&h, b, states, 1);
        sample_places(&h, states, w, 1, cont ? 6 : 24, &seed);
        every_place(&h, w - 7, w, 1);
        if (!cont)
            continue;
        sample_places(&h, w, u, 8, 6, &seed);
        if (!shear)
            continue;
        every_place(&h, u - 7, u, 1);
        sample_places(&h, u, small, 8, 12, &seed);
        every_place(&h, small - 7, small, 1);
        every_place(&h, small, root, 0);
        every_place(&h, root - 7, root, 1);
        h.what = e ? 0 : ON; /* the twin's solves never defer their slope (ring_root.c) */
        every_place(&h, root, end, 0);
    }
    print_message("ring (%s): %zu bytes, %zu hostile states, %zu refused, %zu "
                  "evaluations failed; from a warm start restored, z and F_x within %.3g m "
                  "and %.3g N\n", label, h.size, h.changed,
                  h.refused, h.failed, h.dz_max, h.dfx_max);
    assert_true(h.refused > 0 || cover == RING_FEW); /* (its parts drop, never refuse) */
    /* the state as saved is still taken, and gives the answer it gave */
    tirenv_point a, b;
    assert_int_equal(tirenv_model_state_restore(m, h.saved, h.size, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, -0.219, &a, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_state_restore(m, h.saved, h.size, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, -0.219, &b, &d), TIRENV_OK);
    assert_bits_equal(a.z, b.z);
    assert_bits_equal(a.fx, b.fx);
    hostile_free(&h);
    tirenv_ring_free(twin);
    tirenv_model_free(m);
    tirenv_profile_free(p);
}

static void test_ring_hostile(void **state)
{
    (void)state;
    ring_hostile(tirenv_tire_default(), "continuous contact", RING_HEAD, 0x2385);
}

static void test_ring_rays_hostile(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.ring.contact = TIRENV_RING_RAYS;
    ring_hostile(tire, "rays", RING_ARRAYS, 0x4471);
}

/* The ring's other configurations: the Winkler tread (no shear: the state has w but not the
 * tread's u, its slopes and the root's record), lugs on the shear-coupled tread and the
 * softening carcass (the default's layout; other paths through the solve that follows). */
static void test_ring_configurations_hostile(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.ring.G_t = 0;
    ring_hostile(tire, "continuous contact, Winkler tread", RING_ARRAYS, 0x7733);
    tire = tirenv_tire_default();
    tire.ring.lug_count = 23;
    tire.ring.lug_ratio = 0.3;
    ring_hostile(tire, "continuous contact, lugs", RING_FEW, 0x1871);
    tire = tirenv_tire_default();
    tire.ring.k_c = 8.13e5; /* softening beyond 12.5 mm over 9.7 mm */
    tire.ring.w_cs = 0.0097;
    tire.ring.w_c0 = 0.0125;
    ring_hostile(tire, "continuous contact, softening carcass", RING_FEW, 0x2917);
}

/* A model of type name on the tire, set on p at the load of contact length l_c (the network
 * nn given where the type needs one) and evaluated at x. */
static tirenv_model *set_model(const char *name, const tirenv_tire *tire, const tirenv_nn *nn,
                               const tirenv_profile *p, double l_c, double x, double *G)
{
    const tirenv_model_type *t = tirenv_model_type_find(name);
    assert_non_null(t);
    tirenv_model *m = tirenv_model_alloc(t, tire);
    assert_non_null(m);
    tirenv_diag d;
    tirenv_point pt;
    if (tirenv_model_type_flags(t) & TIRENV_MODEL_NEEDS_NETWORK)
        assert_int_equal(tirenv_model_set_network(m, nn, tire->springs.R0, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, G, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(m, p, *G, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, x, &pt, &d), TIRENV_OK);
    return m;
}

/* The state's bytes resealed: its checksum made again over them. */
static void reseal(unsigned char *buf, size_t size)
{
    const uint64_t sum = tirenv_test_fnv1a(buf, size - sizeof sum);
    memcpy(buf + size - sizeof sum, &sum, sizeof sum);
}

/* The rigid disc, the point contact, the cam and the network: states of a few doubles (the
 * load, the flat-ground height, the cam's base, the network's contact length), every place;
 * on a cleat within the made-up network's range, and the network also on a road of two
 * obstacles (its restore then sets the decomposition's contact length). */
static void test_small_states_hostile(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    const double xr[] = {-1.5, -0.61, -0.61, -0.47, -0.47, 0.31, 0.31, 0.43, 0.43, 1.5},
                 zr[] = {0, 0, 0.0513, 0.0513, 0, 0, 0.0387, 0.0387, 0, 0};
    tirenv_profile *cleat = tirenv_profile_cleat(0.2117, 0.0513),
                   *road = tirenv_profile_alloc(sizeof xr / sizeof xr[0], xr, zr);
    tirenv_nn *nn = tirenv_test_made_up_network(2385, 97);
    assert_true(cleat && road && nn);
    const char *const names[] = {"rigid", "point", "cam", "nn", "nn"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
        const tirenv_profile *p = i < 4 ? cleat : road;
        double G;
        tirenv_model *m = set_model(names[i], &tire, nn, p, 0.3371, -0.2, &G);
        hostile h;
        hostile_save(&h, m, p, G, 0.3371, -0.19, -0.18, -1.0);
        every_place(&h, 0, HEAD, 1);
        every_place(&h, HEAD, h.size - sizeof(uint64_t), 1);
        print_message("%s%s: %zu bytes, %zu hostile states, %zu refused, %zu evaluations "
                      "failed\n", names[i], i < 4 ? "" : " on a road", h.size, h.changed,
                      h.refused, h.failed);
        assert_true(h.refused > 0);
        hostile_free(&h);
        tirenv_model_free(m);
    }
    tirenv_nn_free(nn);
    tirenv_profile_free(road);
    tirenv_profile_free(cleat);
}

/* The head's load and flat-ground height and the type's own copies (or what they follow
 * from) are one quantity: a state where the head's is moved by an ulp, resealed, is refused,
 * saying which disagrees; the state as saved is still taken. Every type and every layout of
 * the deformable record (a sidewall in series puts the hub's height below the record's). */
static void test_head_and_type_agree(void **state)
{
    (void)state;
    tirenv_profile *p = tirenv_profile_cleat(0.2117, 0.0513);
    tirenv_nn *nn = tirenv_test_made_up_network(2385, 97);
    assert_true(p && nn);
    tirenv_tire sidewall = tirenv_tire_default();
    sidewall.springs.k_s = 1.7321e6;
    sidewall.springs.F_s0 = 9876.5;
    tirenv_tire coarse = tirenv_tire_default();
    coarse.ring.dtheta = M_PI / 180;
    const struct {
        const char *name;
        const tirenv_tire tire;
    } cases[] = {{"rigid", tirenv_tire_default()}, {"point", tirenv_tire_default()},
                 {"cam", tirenv_tire_default()},   {"nn", tirenv_tire_default()},
                 {"springs", tirenv_tire_default()}, {"springs", sidewall},
                 {"ring", coarse}};
    /* the head's load and z_flat after magic, size, name and tire */
    const size_t at_load = 8 + 8 + 16 + 8, at[2] = {at_load, at_load + 8};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        double G;
        tirenv_model *m = set_model(cases[i].name, &cases[i].tire, nn, p, 0.3371, -0.2, &G);
        tirenv_diag d;
        const size_t size = tirenv_model_state_size(m);
        unsigned char *saved = malloc(size), *buf = malloc(size);
        assert_true(saved && buf);
        assert_int_equal(tirenv_model_state_save(m, saved, size, &d), TIRENV_OK);
        for (size_t k = 0; k < 2; ++k)
            for (int up = 0; up < 2; ++up) {
                double v;
                memcpy(buf, saved, size);
                memcpy(&v, buf + at[k], sizeof v);
                v = nextafter(v, up ? INFINITY : 0);
                memcpy(buf + at[k], &v, sizeof v);
                reseal(buf, size);
                assert_int_equal(tirenv_model_state_restore(m, buf, size, &d), TIRENV_EINVAL);
                if (up && (k || i < 4)) /* the deformable record's messages: both */
                    print_message("%s, head's %s an ulp up: %s\n", cases[i].name,
                                  k ? "z_flat" : "load", d.message);
                assert_non_null(strstr(d.message, "head's"));
                assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
            }
        assert_int_equal(tirenv_model_state_restore(m, saved, size, &d), TIRENV_OK);
        free(saved);
        free(buf);
        tirenv_model_free(m);
    }
    tirenv_nn_free(nn);
    tirenv_profile_free(p);
}

/* A model set on several tracks has one type state a track: its state is neither saved nor
 * restored (a state is that of one track), each refused saying so and the model left as it
 * was; set on one track again, a state of it is taken. */
static void test_tracks_state(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_profile *a = tirenv_profile_cleat(0.30, 0.10), *b = tirenv_profile_cleat(0.20, 0.07);
    assert_true(a && b);
    const tirenv_profile *const tracks[2] = {a, b};
    const char *const names[] = {"springs", "rigid", "cam"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
        double G;
        tirenv_model *m = set_model(names[i], &tire, NULL, a, 0.38, -0.2, &G);
        tirenv_diag d;
        tirenv_point was, now;
        const size_t size = tirenv_model_state_size(m);
        unsigned char *one = malloc(size), *buf = malloc(size);
        assert_true(one && buf);
        assert_int_equal(tirenv_model_state_save(m, one, size, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set_tracks(m, 2, tracks, NULL, G, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_tracks(m), 2);
        assert_int_equal(tirenv_model_eval(m, -0.21, &was, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set_tracks(m, 2, tracks, NULL, G, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_state_save(m, buf, size, &d), TIRENV_EINVAL);
        assert_non_null(strstr(d.message, "tracks"));
        assert_int_equal(tirenv_model_state_restore(m, one, size, &d), TIRENV_EINVAL);
        assert_non_null(strstr(d.message, "tracks"));
        assert_int_equal(tirenv_model_eval(m, -0.21, &now, &d), TIRENV_OK);
        assert_bits_equal(now.z, was.z);
        assert_bits_equal(now.fx, was.fx);
        assert_int_equal(tirenv_model_set(m, a, G, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_state_restore(m, one, size, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, -0.21, &now, &d), TIRENV_OK);
        free(one);
        free(buf);
        tirenv_model_free(m);
    }
    tirenv_profile_free(a);
    tirenv_profile_free(b);
}

/* A source over a bumpy road in memory: vertex k of n, then the end. */
typedef struct {
    size_t k, n;
} bumps;

static int bumps_next(void *ctx, double *x, double *z, int *got, tirenv_diag *diag)
{
    (void)diag;
    bumps *s = ctx;
    *got = s->k < s->n;
    if (*got) {
        *x = -2.0 + 0.011 * (double)s->k;
        *z = 0.013 * sin(3.1 * *x) + 0.0047 * sin(13.7 * *x + 0.4);
        ++s->k;
    }
    return TIRENV_OK;
}

/* After a streamed sweep the model is unset, its type still holding the last window, which
 * the stream freed: a state saved then is an unset model's (its type's bytes are not the
 * window's, which the sanitizer build would find read after the free), restored it leaves
 * the model unset; changed at any place of its head and resealed it is refused or does the
 * same, and the evaluation that follows fails saying why; set again, the model takes a state
 * of its own. */
static void test_streamed_state(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    const char *const names[] = {"springs", "ring", "cam"};
    tirenv_profile *p = tirenv_profile_cleat(0.30, 0.10);
    assert_non_null(p);
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
        tirenv_tire t = tire;
        t.ring.dtheta = M_PI / 180;
        tirenv_model *m = tirenv_model_alloc(tirenv_model_type_find(names[i]), &t);
        assert_non_null(m);
        tirenv_diag d;
        double G;
        tirenv_point pt;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G, &d), TIRENV_OK);
        bumps src = {0, 400};
        tirenv_test_points c = {0};
        assert_int_equal(tirenv_model_stream(m, bumps_next, &src, -1.0, 1.0, 0.05, G,
                                             tirenv_test_keep_point, &c, NULL, &d),
                         TIRENV_OK);
        assert_int_equal(c.n, 41);
        free(c.pt);
        const size_t size = tirenv_model_state_size(m);
        unsigned char *saved = malloc(size), *buf = malloc(size);
        assert_true(saved && buf);
        assert_int_equal(tirenv_model_state_save(m, saved, size, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_state_restore(m, saved, size, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, 0, &pt, &d), TIRENV_EINVAL);
        size_t refused = 0;
        for (size_t at = 0; at < HEAD; ++at) {
            const uint64_t words[] = {(uint64_t)1 << 40, (uint64_t)-1, 1};
            for (size_t k = 0; k < 3; ++k) {
                memcpy(buf, saved, size);
                memcpy(buf + at, &words[k], sizeof words[k]);
                reseal(buf, size);
                if (tirenv_model_state_restore(m, buf, size, &d) != TIRENV_OK) {
                    assert_true(d.message[0] != '\0');
                    ++refused;
                }
                assert_int_equal(tirenv_model_eval(m, 0, &pt, &d), TIRENV_EINVAL);
                assert_true(d.message[0] != '\0');
            }
        }
        print_message("%s streamed: a state of %zu bytes, %zu of %d changed ones refused\n",
                      names[i], size, refused, 3 * HEAD);
        assert_true(refused > 0);
        /* set again, on the same ground as whole: its own state is taken */
        assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_eval(m, -0.2, &pt, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_state_save(m, saved, size, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_state_restore(m, saved, size, &d), TIRENV_OK);
        free(saved);
        free(buf);
        tirenv_model_free(m);
    }
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_springs_carry_hostile),
        cmocka_unit_test(test_springs_configurations_hostile),
        cmocka_unit_test(test_ring_hostile),
        cmocka_unit_test(test_ring_rays_hostile),
        cmocka_unit_test(test_ring_configurations_hostile),
        cmocka_unit_test(test_small_states_hostile),
        cmocka_unit_test(test_head_and_type_agree),
        cmocka_unit_test(test_tracks_state),
        cmocka_unit_test(test_streamed_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
