/* libFuzzer harness: the profile CSV reader (tirenv_profile_read_csv), and the extent and
 * sampling of whatever profile it accepts. SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/profile_csv.h"
#include "tirenv/profile.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".csv");
    tirenv_profile *p = NULL;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_profile_read_csv(path, &p, &diag) == TIRENV_OK) {
        double first, last;
        tirenv_profile_extent(p, &first, &last);
        (void)tirenv_profile_height(p, 0.5 * (first + last));
    }
    tirenv_profile_free(p);
    return 0;
}
