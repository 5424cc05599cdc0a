/* libFuzzer harness: what a sweep's sweep.txt declares of the manifest beside it
 * (tirenv_dataset__sweep_declared, src/dataset/dataset_sweep.c) and what simulated it, on
 * arbitrary bytes; what it accepts must be a count a manifest can hold, given at a line, with
 * terminated strings, a key set only with its line, and every failure must say why (the
 * reader's promises).
 * SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "dataset/dataset_impl.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *dir = fuzz_input_dir();
    char path[400];
    snprintf(path, sizeof path, "%s/sweep.txt", dir);
    FILE *fp = fopen(path, "wb");
    if (!fp || (size && fwrite(data, 1, size, fp) != size) || fclose(fp) != 0)
        abort();
    tirenv_dataset__declared d;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_dataset__sweep_declared(dir, &d, &diag) == TIRENV_OK) {
        if (d.cases > TIRENV_DATASET__MAX_CASES || !d.cases != !d.line ||
            !memchr(d.file, '\0', sizeof d.file) || !memchr(d.what, '\0', sizeof d.what))
            abort();
        if (d.cases && (strcmp(d.file, path) != 0 || strncmp(d.what, "cases = ", 8) != 0))
            abort();
        /* the source it gives: terminated, a key only with its line, no blank or '=' in it */
        if (!memchr(d.model, '\0', sizeof d.model) || !memchr(d.key, '\0', sizeof d.key) ||
            !d.key[0] != !d.key_line || strpbrk(d.key, " =") || (d.raw != 0 && d.raw != 1))
            abort();
    } else if (!diag.message[0] || !diag.line) {
        abort();  /* every failure says why, at its line */
    }
    unlink(path);
    return 0;
}
