/* libFuzzer harness: the vehicle file reader (tirenv_vehicle_read, and with the keys it left
 * out, tirenv_vehicle_read_unset, which must read the same vehicle), its check, and its tires'
 * springs and dampers set from a tire (tirenv_vehicle_tires).
 * SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/vehicle.h"
#include "tirenv/vehicle_file.h"

#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".veh");
    tirenv_vehicle v = tirenv_vehicle_default();
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_vehicle u = v;
    char unset[64];
    const int read = tirenv_vehicle_read(path, &v, &diag);
    if ((tirenv_vehicle_read_unset(path, &u, unset, sizeof unset, &diag) == TIRENV_OK) !=
            (read == TIRENV_OK) ||
        memcmp(&u, &v, sizeof v) != 0)
        __builtin_trap(); /* the two reads disagree */
    if (read == TIRENV_OK && tirenv_vehicle_check(&v, &diag) == TIRENV_OK) {
        /* Its tires' springs and dampers from the default tire where it gives none. */
        const tirenv_tire tire = tirenv_tire_default();
        if (tirenv_vehicle_tires(&v, &tire, &tire, &diag) == TIRENV_OK)
            (void)tirenv_vehicle_check(&v, &diag);
    }
    return 0;
}
