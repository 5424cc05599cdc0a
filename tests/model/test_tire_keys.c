/* SPDX-License-Identifier: Apache-2.0 */
/* Every .tir key the models read, set to each of {0, -1, NaN, inf, 1e308, 1e-308}: for every
 * model (the network's aside: it reads no tire key but the radius, which the others cover),
 * either an error that names the key (from --set, the tire check or the model) or a
 * curve over a cleat whose every point is finite and plausible. The keys are those
 * tirenv_tir_write writes, so a key added to the table is swept without editing this test.
 * What would have caught the keys that broke models once (NODE_ANGLE = 1e-20 overflowing the ring,
 * TREAD_STIFFNESS = 1e-308 lifting the ring above the cleat, a cam load of 4.7e-310 N). */
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tirenv/tirenv.h"

enum { MAX_KEYS = 64 };

/* The keys of the default tire as written, "SECTION.KEY" (METHOD and [UNITS] aside: a name,
 * not a number). */
static size_t tire_keys(char keys[][160])
{
    char path[] = "/tmp/tirenv-test-keys-XXXXXX";
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    const tirenv_tire t = tirenv_tire_default();
    tirenv_diag diag;
    assert_int_equal(tirenv_tir_write(path, &t, &diag), TIRENV_OK);
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    char line[512], section[64] = "";
    size_t n = 0;
    while (fgets(line, sizeof line, fp)) {
        if (line[0] == '[') {
            sscanf(line, "[%63[^]]]", section);
            continue;
        }
        char key[64];
        if (strcmp(section, "UNITS") == 0 || !strchr(line, '=') ||
            sscanf(line, " %63[A-Z0-9_] =", key) != 1 || strcmp(key, "METHOD") == 0)
            continue;
        assert_true(n < MAX_KEYS);
        snprintf(keys[n++], 160, "%s.%s", section, key);
    }
    fclose(fp);
    unlink(path);
    return n;
}

/* Plausible over a cleat of height H (m): finite, the centre's rise h within [-1 mm, H +
 * 1 mm] (a tire cannot rise more than the obstacle over flat ground; 1 mm covers the
 * springs' and the ring's solver tolerances, 1e-10 m, many times over, and the ring's tread
 * compression before the cleat), the vertical force the load within 1 %. */
static int plausible(const tirenv_point *p, double H, double load)
{
    return isfinite(p->x) && isfinite(p->z) && isfinite(p->h) && isfinite(p->slope) &&
           isfinite(p->fx) && isfinite(p->fz) && p->h >= -1e-3 && p->h <= H + 1e-3 &&
           fabs(p->fz - load) <= 0.01 * load;
}

static void test_every_key_every_value(void **state)
{
    (void)state;
    static const char *const values[] = {"0", "-1", "nan", "inf", "1e308", "1e-308"};
    static char keys[MAX_KEYS][160];
    const size_t n_keys = tire_keys(keys);
    assert_true(n_keys >= 20);  /* the table's 25 numeric keys, give or take a new one */
    const double L = 0.1, H = 0.05, load = 13000;  /* N: the default tire's working load */
    tirenv_profile *cleat = tirenv_profile_cleat(L, H);
    assert_non_null(cleat);
    enum { N_X = 13 };
    double x[N_X];
    for (size_t k = 0; k < N_X; ++k)
        x[k] = -0.9 + 0.15 * (double)k;  /* -0.9 .. 0.9 m: before, over and past the cleat */
    size_t refused_set = 0, refused_model = 0, curves = 0;
    for (size_t i = 0; i < n_keys; ++i)
        for (size_t v = 0; v < sizeof values / sizeof values[0]; ++v) {
            char assignment[200];
            snprintf(assignment, sizeof assignment, "%s=%s", keys[i], values[v]);
            const char *key = strchr(keys[i], '.') + 1;
            tirenv_tire t = tirenv_tire_default();
            tirenv_diag diag;
            tirenv_diag_clear(&diag);
            int status = tirenv_tir_set(&t, assignment, &diag);
            if (!status)
                status = tirenv_tire_check(&t, &diag);
            if (status) {
                if (!strstr(diag.field, key) && !strstr(diag.message, key))
                    fail_msg("%s refused without naming the key: %s: %s", assignment,
                             diag.field, diag.message);
                ++refused_set;
                continue;
            }
            for (const tirenv_model_type *const *type = tirenv_model_types(); *type; ++type) {
                if (tirenv_model_type_flags(*type) & TIRENV_MODEL_NEEDS_NETWORK)
                    continue;
                tirenv_model *m = tirenv_model_alloc(*type, &t);
                if (!m)
                    fail_msg("%s: the %s model refused a tire the check passed", assignment,
                             tirenv_model_type_name(*type));
                tirenv_point pt[N_X];
                tirenv_diag_clear(&diag);
                status = tirenv_model_set(m, cleat, load, &diag);
                if (!status)
                    status = tirenv_model_envelope(m, N_X, x, pt, NULL, &diag);
                if (status) {
                    if (!diag.message[0])
                        fail_msg("%s: the %s model failed (%d) without a message", assignment,
                                 tirenv_model_type_name(*type), status);
                    ++refused_model;
                } else {
                    for (size_t k = 0; k < N_X; ++k)
                        if (!plausible(&pt[k], H, load))
                            fail_msg("%s: the %s model at x = %g m: z %g h %g fx %g fz %g; "
                                     "expected finite, h in [-1 mm, H + 1 mm], fz the load",
                                     assignment, tirenv_model_type_name(*type), x[k], pt[k].z,
                                     pt[k].h, pt[k].fx, pt[k].fz);
                    ++curves;
                }
                tirenv_model_free(m);
            }
        }
    tirenv_profile_free(cleat);
    printf("# %zu keys x %zu values: %zu refused by --set or the tire check; of the rest, "
           "%zu model runs refused with a message, %zu curves finite and plausible\n",
           n_keys, sizeof values / sizeof values[0], refused_set, refused_model, curves);
    assert_true(curves > 0);  /* the sweep ran models, not only refusals */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_key_every_value),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
