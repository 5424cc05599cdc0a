/* What the libFuzzer harnesses share: the readers take file names, so each input is written
 * to one temporary file (made once, rewritten in place for every input) and read back.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_FUZZ_INPUT_H
#define TIRENV_FUZZ_INPUT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The input as the file at the returned path (suffix: the extension a reader may expect).
 * The file lives in a private directory under $TMPDIR, else /dev/shm (memory: no disk in
 * the loop), else /tmp, removed at exit. */
static inline const char *fuzz_input_file(const uint8_t *data, size_t size, const char *suffix);

static char fuzz_dir[256], fuzz_path[320];

static inline void fuzz_cleanup(void)
{
    if (fuzz_path[0])
        unlink(fuzz_path);
    if (fuzz_dir[0])
        rmdir(fuzz_dir);
}

/* The private directory, made on first use (a harness may put more files in it; it removes
 * them itself). */
static inline const char *fuzz_input_dir(void)
{
    if (!fuzz_dir[0]) {
        const char *tmp = getenv("TMPDIR");
        if (!tmp || !*tmp)
            tmp = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
        snprintf(fuzz_dir, sizeof fuzz_dir, "%s/tirenv-fuzz-XXXXXX", tmp);
        if (!mkdtemp(fuzz_dir))
            abort();
        atexit(fuzz_cleanup);
    }
    return fuzz_dir;
}

static inline const char *fuzz_input_file(const uint8_t *data, size_t size, const char *suffix)
{
    if (!fuzz_path[0])
        snprintf(fuzz_path, sizeof fuzz_path, "%s/input%s", fuzz_input_dir(), suffix);
    FILE *fp = fopen(fuzz_path, "wb");
    if (!fp || (size && fwrite(data, 1, size, fp) != size) || fclose(fp) != 0)
        abort();
    return fuzz_path;
}

#endif
