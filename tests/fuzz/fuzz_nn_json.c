/* libFuzzer harness: the network model file reader (tirenv_nn_read_json), and one prediction
 * with whatever network it accepts. SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/nn.h"
#include "tirenv/nn_file.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_input_file(data, size, ".json");
    tirenv_nn *nn = NULL;
    tirenv_train_record rec;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_nn_read_json(path, &nn, &rec, &diag) == TIRENV_OK) {
        double u[TIRENV_NN_MAX_WIDTH];  /* the first layer is at most this wide */
        for (size_t i = 0; i < TIRENV_NN_MAX_WIDTH; ++i)
            u[i] = 0.1 * (double)(i + 1);
        if (tirenv_nn_n_inputs(nn) <= TIRENV_NN_MAX_WIDTH)
            (void)tirenv_nn_run(nn, u);
    }
    tirenv_nn_free(nn);
    return 0;
}
