/* A host that rewinds (a co-simulation master's rejected step, FMI's fmi2SetFMUstate) saves a
 * model's state at one position and restores it later: the evaluations that follow the
 * restore must be those that followed the save, bit for bit (h, z, F_x, F_z, contacts,
 * iterations), in the same instance and in a twin of another history; and taking a state
 * must not change the run. Over seeded sweeps across cleats, a step and class C roads, for
 * the springs model (continuous contact and rays, two tires), the ring and the cam, with the
 * load fixed and changing at every step, and with positions repeated (a vehicle at rest).
 * docs/models.md section 1.7.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/tirenv.h"
#include "tirenv/road.h"
#include "tirenv/tir.h"

static int same_bits(const tirenv_point *a, const tirenv_point *b)
{
    return memcmp(&a->z, &b->z, sizeof a->z) == 0 && memcmp(&a->h, &b->h, sizeof a->h) == 0 &&
           memcmp(&a->slope, &b->slope, sizeof a->slope) == 0 &&
           memcmp(&a->fx, &b->fx, sizeof a->fx) == 0 &&
           memcmp(&a->fz, &b->fz, sizeof a->fz) == 0 && a->contacts == b->contacts &&
           a->iterations == b->iterations;
}

/* A class C road of `length` m sampled every dx m (seeded). */
static tirenv_profile *road_c(double length, double dx, unsigned long seed)
{
    tirenv_road_settings rs = tirenv_road_default();
    rs.road_class = 'C';
    rs.length = length;
    rs.dx = dx;
    rs.seed = seed;
    tirenv_profile *road = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_road_iso8608(&rs, &road, &d), TIRENV_OK);
    return road;
}

/* One sweep: positions x0 + k dx for k < n, or with `rest` each third step at the position
 * of the one before (a vehicle at rest, a master's step repeated); the load G0 or, with
 * swing 1, G0 (1 + 0.2 sin(0.05 k)) set before each step, with swing 2 a load that moves by
 * 1e-6 of itself (its flat-ground height by some 1e-7 m: the flat workspace's next solve
 * starts a hair from where the last one ended). */
typedef struct {
    const char *what;
    const tirenv_profile *p;
    double x0, dx, l_c; /* l_c: the base load's contact length (m), or the load (N) if > 1 */
    size_t n;
    int swing, rest;
} sweep;

static double load_at(const sweep *s, double G0, size_t k)
{
    return s->swing == 1   ? G0 * (1.0 + 0.2 * sin(0.05 * (double)k))
           : s->swing == 2 ? G0 * (1.0 + 1e-6 * (double)(k % 3))
                           : G0;
}

static void step(tirenv_model *m, const sweep *s, double G0, size_t k, tirenv_point *out)
{
    tirenv_diag d;
    const double at = (double)(s->rest ? k - k / 3 : k);
    if ((s->swing && tirenv_model_set_load(m, load_at(s, G0, k), &d)) ||
        tirenv_model_eval(m, s->x0 + at * s->dx, out, &d))
        fail_msg("%s over %s at step %zu: %s", tirenv_model_name(m), s->what, k, d.message);
}

enum { N_AFTER = 6 };

/* Whether a state is taken before step k: every `stride` steps, and every step in
 * [dense_lo, dense_hi). */
typedef struct {
    size_t stride, dense_lo, dense_hi;
} saves;

static int save_before(const saves *v, size_t k)
{
    return k > 0 && (k % v->stride == 0 || (k >= v->dense_lo && k < v->dense_hi));
}

/* The sweep run plain, and again with states taken: before each step the saves name, the
 * state is saved, the next N_AFTER steps run, the state restored into the same instance and
 * the steps run again, then restored into the twin (whose history is other: it was set at
 * another load and restored at other steps) and run once more. Every step of the run with
 * states taken, and every repeat, equals the plain run's bit for bit. Returns the states
 * taken. */
static size_t check_sweep(const tirenv_model_type *type, const tirenv_tire *tire,
                          const sweep *s, const saves *v)
{
    tirenv_diag d;
    tirenv_model *plain = tirenv_model_alloc(type, tire), *m = tirenv_model_alloc(type, tire),
                 *twin = tirenv_model_alloc(type, tire);
    assert_true(plain && m && twin);
    double G0;
    G0 = s->l_c;
    if (s->l_c < 1)
        assert_int_equal(tirenv_model_load_for_contact_length(plain, s->l_c, &G0, &d),
                         TIRENV_OK);
    assert_int_equal(tirenv_model_set(plain, s->p, load_at(s, G0, 0), &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(m, s->p, load_at(s, G0, 0), &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(twin, s->p, 0.9 * G0, &d), TIRENV_OK);
    const size_t size = tirenv_model_state_size(m);
    unsigned char *buf = malloc(size);
    tirenv_point *ref = malloc(s->n * sizeof *ref);
    assert_true(buf && ref);
    for (size_t k = 0; k < s->n; ++k)
        step(plain, s, G0, k, &ref[k]);
    size_t taken = 0;
    tirenv_point pt;
    for (size_t k = 0; k < s->n;) {
        if (!save_before(v, k) || k + N_AFTER > s->n) {
            step(m, s, G0, k, &pt);
            if (!same_bits(&pt, &ref[k]))
                fail_msg("%s over %s: step %zu after a state was taken differs from the plain "
                         "run: h %.17g, %.17g",
                         tirenv_model_type_name(type), s->what, k, pt.h, ref[k].h);
            ++k;
            continue;
        }
        assert_int_equal(tirenv_model_state_save(m, buf, size, &d), TIRENV_OK);
        ++taken;
        for (int pass = 0; pass < 3; ++pass) {
            tirenv_model *r = pass == 2 ? twin : m;
            if (pass > 0)
                assert_int_equal(tirenv_model_state_restore(r, buf, size, &d), TIRENV_OK);
            for (size_t j = k; j < k + N_AFTER; ++j) {
                step(r, s, G0, j, &pt);
                if (!same_bits(&pt, &ref[j]))
                    fail_msg("%s over %s, a state taken before step %zu: step %zu %s differs "
                             "from the plain run: h %.17g, %.17g (dh %.3g m), F_x %.17g, "
                             "%.17g, iterations %zu, %zu",
                             tirenv_model_type_name(type), s->what, k, j,
                             pass == 0 ? "(the run on)" : pass == 1 ? "(restored)"
                                                                   : "(restored in the twin)",
                             pt.h, ref[j].h, pt.h - ref[j].h, pt.fx, ref[j].fx, pt.iterations,
                             ref[j].iterations);
            }
        }
        k += N_AFTER;
    }
    free(ref);
    free(buf);
    tirenv_model_free(plain);
    tirenv_model_free(m);
    tirenv_model_free(twin);
    return taken;
}

/* The grounds: the bench's 0.30 x 0.10 m cleat, the FMU test's 0.10 x 0.10 m one (its steps
 * 800 to 1,100, x from 0 to 0.3 m, failed before the state held the start's carry: a state
 * before each step there but those the repeats take), a 0.05 m step up, a vehicle at rest, a
 * class C road at 1 cm and one at 1 mm; every n_scale-th position (n_scale times the step);
 * the sweeps whose bits are set in mask. */
static void check_model(const char *name, const tirenv_tire *tire, size_t n_scale,
                        unsigned mask)
{
    const tirenv_model_type *type = tirenv_model_type_find(name);
    assert_non_null(type);
    tirenv_profile *bench = tirenv_profile_cleat(0.30, 0.10);
    tirenv_profile *fmu = tirenv_profile_cleat(0.10, 0.10);
    tirenv_profile *up = tirenv_profile_step(0.0, 0.05);
    tirenv_profile *c1 = road_c(4.0, 0.01, 11), *c2 = road_c(1.0, 0.001, 12);
    assert_true(bench && fmu && up && c1 && c2);
    const size_t k = n_scale;
    const sweep sweeps[] = {
        {"the 0.30 x 0.10 m cleat", bench, -0.30, 0.001 * k, 0.38, 400 / k, 0, 0},
        {"the 0.10 x 0.10 m cleat (the FMU test's)", fmu, -0.25, 0.001 * k, 7500, 600 / k, 0,
         0},
        {"the 0.10 x 0.10 m cleat at changing loads", fmu, -0.4, 0.002 * k, 0.33, 400 / k, 1,
         0},
        {"the 0.30 x 0.10 m cleat at rest every third step", bench, -0.35, 0.001 * k, 0.38,
         450 / k, 0, 1},
        {"a 0.05 m step at loads a hair apart", up, -0.3, 0.002 * k, 0.33, 300 / k, 2, 1},
        {"a class C road at 1 cm", c1, 0.5, 0.01 * k, 0.33, 300 / k, 1, 0},
        {"a class C road at 1 mm", c2, 0.3, 0.001 * k, 0.33, 400 / k, 0, 0},
    };
    const saves v[] = {
        {7, 0, 0}, {23, 250 / k, 550 / k}, {5, 0, 0}, {5, 0, 0},
        {5, 0, 0}, {4, 0, 0},               {5, 0, 0},
    };
    size_t taken = 0;
    for (size_t i = 0; i < sizeof sweeps / sizeof sweeps[0]; ++i)
        if (mask >> i & 1)
            taken += check_sweep(type, tire, &sweeps[i], &v[i]);
    assert_true(taken >= 10);
    tirenv_profile_free(bench);
    tirenv_profile_free(fmu);
    tirenv_profile_free(up);
    tirenv_profile_free(c1);
    tirenv_profile_free(c2);
}

enum { ALL = 0x7f, RING = 0x29 };

static void test_springs_continuous(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    assert_int_equal(tire.springs.contact, TIRENV_SPRINGS_CONTINUOUS);
    check_model("springs", &tire, 1, ALL);
}

/* The 205/60R15's springs model (a sidewall in series, another element count), at every
 * third position. */
static void test_springs_205(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tirenv_diag d;
    assert_int_equal(tirenv_tir_read_derive(TIRENV_DATA_DIR "/tires/205-60R15-mfswift.tir",
                                            &tire, TIRENV_TIR_SPRINGS, NULL, &d),
                     TIRENV_OK);
    check_model("springs", &tire, 3, ALL);
}

static void test_springs_rays(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_tire_default();
    tire.springs.contact = TIRENV_SPRINGS_RAYS;
    check_model("springs", &tire, 3, ALL);
}

/* The ring at every tenth position over the bench cleat, at rest and the 1 cm road (its
 * evaluations cost some 15 times the springs'), and at every millimetre onto the cleat's
 * edge, where its sampling of the ground carries pieces from one position to the next. */
static void test_ring(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    check_model("ring", &tire, 10, RING);
    tirenv_profile *bench = tirenv_profile_cleat(0.30, 0.10);
    assert_non_null(bench);
    const sweep edge = {"the 0.30 x 0.10 m cleat's edge at 1 mm", bench, -0.32, 0.001, 0.38,
                        60, 0, 0};
    const saves v = {4, 0, 0};
    assert_true(check_sweep(tirenv_model_type_find("ring"), &tire, &edge, &v) >= 5);
    tirenv_profile_free(bench);
}

static void test_cam(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    check_model("cam", &tire, 2, ALL);
}

/* FNV-1a, 64 bits, a byte at a time: what the state's checksum is (src/model/model_state.c
 * takes runs of zero bytes at once), over the bytes before it. Over states mid-sweep (runs of
 * zeros and not) of the springs model, the ring and the cam. */
static void test_checksum_is_fnv1a(void **state)
{
    (void)state;
    const char *names[] = {"springs", "ring", "cam", "rigid"};
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_profile *p = tirenv_profile_cleat(0.30, 0.10);
    assert_non_null(p);
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
        tirenv_model *m = tirenv_model_alloc(tirenv_model_type_find(names[i]), &tire);
        assert_non_null(m);
        tirenv_diag d;
        double G;
        tirenv_point pt;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.38, &G, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
        const size_t size = tirenv_model_state_size(m);
        unsigned char *buf = malloc(size);
        assert_non_null(buf);
        for (int k = 0; k < 3; ++k) {
            assert_int_equal(tirenv_model_eval(m, -0.4 + 0.2 * k, &pt, &d), TIRENV_OK);
            assert_int_equal(tirenv_model_state_save(m, buf, size, &d), TIRENV_OK);
            uint64_t sum;
            const uint64_t h = tirenv_test_fnv1a(buf, size - sizeof sum);
            memcpy(&sum, buf + size - sizeof sum, sizeof sum);
            if (sum != h)
                fail_msg("%s at x = %g: the state's checksum %016llx is not the FNV-1a of its "
                         "%zu bytes, %016llx", names[i], -0.4 + 0.2 * k,
                         (unsigned long long)sum, size - sizeof sum, (unsigned long long)h);
        }
        free(buf);
        tirenv_model_free(m);
    }
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_springs_continuous),
        cmocka_unit_test(test_springs_205),
        cmocka_unit_test(test_springs_rays),
        cmocka_unit_test(test_ring),
        cmocka_unit_test(test_cam),
        cmocka_unit_test(test_checksum_is_fnv1a),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
