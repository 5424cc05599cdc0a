/* libFuzzer harness: the enveloping-curve CSV reader (tirenv_curve_read_csv).
 * SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/curve.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".csv");
    tirenv_curve c = {0};
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    (void)tirenv_curve_read_csv(path, &c, &diag);
    tirenv_curve_free(&c);
    return 0;
}
