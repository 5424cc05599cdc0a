/* libFuzzer harness: the streaming road reader (tirenv_profile_file_reader_*) over a CSV
 * file, to the end of the input or its first error; CRG and RDF content is detected and read
 * by the same reader. SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/profile_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".csv");
    tirenv_profile_file_reader *r = NULL;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_profile_file_reader_open(path, NULL, 1, NULL, &r, &diag) == TIRENV_OK) {
        int got = 1;
        double x, z;
        while (got && tirenv_profile_file_reader_next(r, &x, &z, &got, &diag) == TIRENV_OK)
            ;
    }
    tirenv_profile_file_reader_free(r);
    return 0;
}
