/* libFuzzer harness: the streaming profile reader (tirenv_profile_reader_*), to the end of
 * the input or its first error. SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/profile_csv.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".csv");
    tirenv_profile_reader *r = NULL;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_profile_reader_open(path, &r, &diag) == TIRENV_OK) {
        int got = 1;
        double x, z;
        while (got && tirenv_profile_reader_next(r, &x, &z, &got, &diag) == TIRENV_OK)
            ;
    }
    tirenv_profile_reader_free(r);
    return 0;
}
