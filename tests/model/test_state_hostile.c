/* A state whose bytes were changed and its checksum made again (a hostile host, or a bug in
 * one) passes every check of tirenv_model_state_restore but the type's own: the springs
 * model's must refuse it or restore something it can evaluate from, never index the ground,
 * its elements or its rows out of their bounds (the sanitizer build finds a read past them;
 * an index far out of them faults in any build). Over a springs state (continuous contact,
 * its carry of the QP's working set and the rays' memos) taken on the bench cleat, 64-bit
 * words written at every place of the type's bytes that is not zero: a large vertex or
 * element index, and -1 (every bit set). docs/models.md section 1.7.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/tirenv.h"

/* FNV-1a, 64 bits, of the bytes before the checksum, written in its place. */
static void reseal(unsigned char *buf, size_t size)
{
    const uint64_t h = tirenv_test_fnv1a(buf, size - sizeof h);
    memcpy(buf + size - sizeof h, &h, sizeof h);
}

/* The bytes of the model's head (magic, size, name, tire, load, z_flat, ready): left as
 * saved, so that the type's own restore reads the changed ones. */
enum { HEAD = 8 + 8 + 16 + 8 + 2 * 8 + 1 };

static void test_springs_carry_hostile(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    assert_int_equal(tire.springs.contact, TIRENV_SPRINGS_CONTINUOUS);
    tirenv_profile *p = tirenv_profile_cleat(0.30, 0.10);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_type_find("springs"), &tire);
    assert_true(p && m);
    tirenv_diag d;
    double G;
    tirenv_point pt;
    assert_int_equal(tirenv_model_load_for_contact_length(m, 0.38, &G, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
    const size_t size = tirenv_model_state_size(m);
    unsigned char *saved = malloc(size), *buf = malloc(size);
    assert_true(saved && buf);
    /* on the cleat's edge, the held elements' rays ending on its vertices, rows between
     * elements working; the state taken after a repeat at the same x too */
    const double xs[] = {-0.200, -0.199, -0.198, -0.198};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i)
        assert_int_equal(tirenv_model_eval(m, xs[i], &pt, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_state_save(m, saved, size, &d), TIRENV_OK);
    const uint64_t words[] = {(uint64_t)1 << 40, (uint64_t)-1};
    size_t changed = 0, refused = 0;
    for (size_t at = HEAD; at + 8 + sizeof(uint64_t) <= size; ++at) {
        uint64_t was;
        memcpy(&was, saved + at, sizeof was);
        if (!was)
            continue;
        for (size_t w = 0; w < sizeof words / sizeof words[0]; ++w) {
            memcpy(buf, saved, size);
            memcpy(buf + at, &words[w], sizeof words[w]);
            reseal(buf, size);
            ++changed;
            if (tirenv_model_state_restore(m, buf, size, &d) != TIRENV_OK) {
                ++refused;
                assert_true(d.message[0] != '\0');
                /* a model a restore unset is set again and goes on */
                assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
            }
            /* an evaluation may fail on nonsense restored, never fault */
            (void)tirenv_model_eval(m, -0.198, &pt, &d);
            (void)tirenv_model_eval(m, -0.197, &pt, &d);
        }
    }
    assert_true(changed > 100);
    assert_true(refused > 0);
    /* the state as saved is still taken */
    assert_int_equal(tirenv_model_state_restore(m, saved, size, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, -0.197, &pt, &d), TIRENV_OK);
    free(saved);
    free(buf);
    tirenv_model_free(m);
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_springs_carry_hostile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
