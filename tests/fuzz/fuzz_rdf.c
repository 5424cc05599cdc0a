/* libFuzzer entry point for the TNO / Adams 2-D road reader: any bytes as an .rdf file, read
 * for each side, and the format detector. Seeds: corpus/rdf.
 * Build by hand: clang -g -O1 -fsanitize=fuzzer,address,undefined -Iinclude -Isrc
 *   tests/fuzz/fuzz_rdf.c <the library's sources> -lcminpack -ljansson -lm
 * SPDX-License-Identifier: Apache-2.0 */
#include <stdint.h>

#include "tirenv/profile_file.h"
#include "tirenv/rdf.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tirenv_profile_detect_memory(data, size);
    for (int side = TIRENV_RDF_MEAN; side <= TIRENV_RDF_RIGHT; side++) {
        tirenv_profile *p = NULL;
        tirenv_diag d;
        if (tirenv_rdf_read_memory(data, size, "fuzz.rdf", (tirenv_rdf_side)side, &p, &d) ==
            TIRENV_OK) {
            tirenv_profile_height(p, 0.5);
            tirenv_profile_free(p);
        }
    }
    return 0;
}
