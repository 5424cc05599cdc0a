/* libFuzzer harness: the .tir reader (tirenv_tir_read) on arbitrary bytes, then the checks
 * and the writer on whatever it accepted. SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/tir.h"
#include "tirenv/tire.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".tir");
    tirenv_tire tire = tirenv_tire_default();
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_tir_read(path, &tire, &diag) == TIRENV_OK &&
        tirenv_tire_check(&tire, &diag) == TIRENV_OK) {
        char out[400];
        snprintf(out, sizeof out, "%s/written.tir", fuzz_input_dir());
        if (tirenv_tir_write(out, &tire, &diag) == TIRENV_OK)
            unlink(out);
    }
    return 0;
}
