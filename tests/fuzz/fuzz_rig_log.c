/* libFuzzer harness: a rig log read and imported (tirenv_rig_import) as the paper's case F
 * (cleat 0.30 x 0.10 m, contact length 0.38 m, R0 0.68 m): the CSV reader, then the import's
 * baseline, obstacle location, smoothing and resampling on whatever it reads.
 * SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/rig.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".csv");
    tirenv_import_settings s = tirenv_import_default();
    s.L = 0.30;
    s.H = 0.10;
    s.R0 = 0.68;
    s.contact_length = 0.38;
    tirenv_curve c = {0};
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    (void)tirenv_rig_import(path, &s, &c, &diag);
    tirenv_curve_free(&c);
    return 0;
}
