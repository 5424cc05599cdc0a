/* SPDX-License-Identifier: Apache-2.0 */
/* libFuzzer harness: a data set's source.txt (tirenv_dataset_source_read) on arbitrary bytes;
 * what it accepts must hold terminated strings within their fields, a model it names must be
 * a physical model type, and a count of cases must be one a manifest can hold, given at a line
 * (the reader's promises). */
#include "fuzz_input.h"
#include "tirenv/dataset.h"
#include "tirenv/model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *dir = fuzz_input_dir();
    char path[400];
    snprintf(path, sizeof path, "%s/source.txt", dir);
    FILE *fp = fopen(path, "wb");
    if (!fp || (size && fwrite(data, 1, size, fp) != size) || fclose(fp) != 0)
        abort();
    tirenv_dataset_source src;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_dataset_source_read(dir, &src, &diag) == TIRENV_OK) {
        if (!src.present || !memchr(src.design, '\0', sizeof src.design) ||
            !memchr(src.model, '\0', sizeof src.model) ||
            !memchr(src.tire, '\0', sizeof src.tire))
            abort();
        if (src.cases > 1000000 || !src.cases != !src.cases_line)
            abort();
        if (src.model[0]) {
            const tirenv_model_type *t = tirenv_model_type_find(src.model);
            if (!t || (tirenv_model_type_flags(t) & TIRENV_MODEL_NEEDS_NETWORK))
                abort();
        }
    } else if (!diag.message[0]) {
        abort();  /* every failure says why */
    }
    unlink(path);
    return 0;
}
