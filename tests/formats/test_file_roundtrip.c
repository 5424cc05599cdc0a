/* What a reader takes, the writer writes back, and the reader takes again (docs/formats.md
 * sections 3 and 10): a .veh TIRE_FILE with quotes was read, then refused by the writer; a
 * network file without its training record was read, written with an empty trainer, and
 * refused on the next read; one with a byte order mark was refused.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include "tirenv/rng.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/tirenv.h"

/* TIRE_FILE = /'x' (unquoted, a quote inside): the reader refuses it as the writer would,
 * naming the line and the key; a quoted path reads, writes and reads back the same. */
static void test_vehicle_tire_file(void **state)
{
    const tirenv_test_dir *d = *state;
    char bad[600], good[600], copy[600];
    tirenv_test_path(d, "bad.veh", bad);
    tirenv_test_write_text(bad, "[FRONT_AXLE]\nTIRES = 2\nTIRE_FILE = /'x'\n");
    tirenv_vehicle v = tirenv_vehicle_default();
    tirenv_diag diag;
    assert_int_equal(tirenv_vehicle_read(bad, &v, &diag), TIRENV_EINVAL);
    assert_int_equal(diag.line, 3);
    assert_string_equal(diag.field, "FRONT_AXLE.TIRE_FILE");
    assert_non_null(strstr(diag.message, "quote"));
    assert_string_equal(v.front.tire_file, tirenv_vehicle_default().front.tire_file);
    /* --set meets the same check. */
    assert_int_equal(tirenv_vehicle_set(&v, "REAR_AXLE.TIRE_FILE=a'b.tir", &diag),
                     TIRENV_EINVAL);

    tirenv_test_path(d, "good.veh", good);
    tirenv_test_write_text(good, "[FRONT_AXLE]\nTIRE_FILE = '/data/front tires.tir'\n");
    assert_int_equal(tirenv_vehicle_read(good, &v, &diag), 0);
    assert_string_equal(v.front.tire_file, "/data/front tires.tir");
    tirenv_test_path(d, "copy.veh", copy);
    assert_int_equal(tirenv_vehicle_write(copy, &v, &diag), 0);
    tirenv_vehicle w = tirenv_vehicle_default();
    assert_int_equal(tirenv_vehicle_read(copy, &w, &diag), 0);
    assert_memory_equal(&v, &w, sizeof v);
}

/* The default topology with random weights from seed, scaled and ranged as the data set's
 * inputs are: a network the writer takes. */
static tirenv_nn *random_network(uint64_t seed)
{
    const tirenv_nn_topology t = tirenv_nn_topology_default();
    tirenv_nn *nn = tirenv_nn_alloc(&t);
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, seed);
    tirenv_nn_init_weights(nn, rng);
    tirenv_rng_free(rng);
    const double mean[4] = {0.5, 0.35, 0.06, 0.17}, std[4] = {0.36, 0.05, 0.027, 0.08};
    const double lo[4] = {-0.25, 0.28, 0.025, 0.05}, hi[4] = {1, 0.43, 0.1, 0.3};
    tirenv_diag diag;
    assert_int_equal(tirenv_nn_set_scaling(nn, mean, std, 0.02, 0.02, &diag), 0);
    assert_int_equal(tirenv_nn_set_input_range(nn, lo, hi, &diag), 0);
    return nn;
}

/* A network written without a record reads back with an empty one (trainer ""), which
 * written again gives a file without a record, which reads: the weights the same bits. */
static void test_network_without_record(void **state)
{
    const tirenv_test_dir *d = *state;
    tirenv_nn *nn = random_network(2385);
    tirenv_diag diag;
    char a[600], b[600];
    tirenv_test_path(d, "a.json", a);
    tirenv_test_path(d, "b.json", b);
    assert_int_equal(tirenv_nn_write_json(a, nn, NULL, &diag), 0);
    tirenv_nn *read1 = NULL, *read2 = NULL;
    tirenv_train_record rec;
    assert_int_equal(tirenv_nn_read_json(a, &read1, &rec, &diag), 0);
    assert_string_equal(rec.trainer, "");
    assert_int_equal(tirenv_nn_write_json(b, read1, &rec, &diag), 0);
    assert_int_equal(tirenv_nn_read_json(b, &read2, &rec, &diag), 0);
    assert_string_equal(rec.trainer, "");
    assert_memory_equal(tirenv_nn_weights(read2), tirenv_nn_weights(nn),
                        tirenv_nn_n_weights(nn) * sizeof(double));
    char text[16384];
    tirenv_test_read_text(b, text, sizeof text);
    assert_null(strstr(text, "\"training\""));
    tirenv_nn_free(read1);
    tirenv_nn_free(read2);
    tirenv_nn_free(nn);
}

/* A network file saved with a UTF-8 byte order mark (as some editors save) reads as the same
 * file without one, as every other file tirenv reads; a mark cut short is invalid JSON. */
static void test_network_with_bom(void **state)
{
    const tirenv_test_dir *d = *state;
    tirenv_nn *nn = random_network(7);
    tirenv_diag diag;
    char a[600], b[600];
    tirenv_test_path(d, "a.json", a);
    tirenv_test_path(d, "bom.json", b);
    assert_int_equal(tirenv_nn_write_json(a, nn, NULL, &diag), 0);
    char text[16384] = "\xEF\xBB\xBF";
    tirenv_test_read_text(a, text + 3, sizeof text - 3);
    tirenv_test_write_text(b, text);
    tirenv_nn *read = NULL;
    tirenv_train_record rec;
    assert_int_equal(tirenv_nn_read_json(b, &read, &rec, &diag), 0);
    assert_memory_equal(tirenv_nn_weights(read), tirenv_nn_weights(nn),
                        tirenv_nn_n_weights(nn) * sizeof(double));
    tirenv_nn_free(read);
    text[2] = ' '; /* EF BB and a blank: not a mark, not JSON */
    tirenv_test_write_text(b, text);
    read = NULL;
    assert_int_equal(tirenv_nn_read_json(b, &read, &rec, &diag), TIRENV_EPARSE);
    assert_null(read);
    assert_string_equal(diag.file, b);
    tirenv_nn_free(nn);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_vehicle_tire_file, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_network_without_record, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
        cmocka_unit_test_setup_teardown(test_network_with_bom, tirenv_test_dir_setup,
                                        tirenv_test_dir_teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
