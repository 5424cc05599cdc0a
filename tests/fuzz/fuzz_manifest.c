/* libFuzzer harness: a data set's manifest (cases.csv, tirenv_dataset_read). The input is the
 * manifest of a directory whose curves/ and logs/ hold the repository's data-set files
 * (linked), so that rows naming them go on to read them.
 * SPDX-License-Identifier: Apache-2.0 */
#include "fuzz_input.h"
#include "tirenv/dataset.h"

#include <dirent.h>
#include <sys/stat.h>

#ifndef TIRENV_FUZZ_DATA
#error "TIRENV_FUZZ_DATA must name the repository's data directory"
#endif
#ifndef TIRENV_FUZZ_TEST_DATA
#error "TIRENV_FUZZ_TEST_DATA must name tests/data"
#endif

static char links[2][400];

static void unlink_all(void)
{
    for (int i = 0; i < 2; ++i) {
        DIR *dp = links[i][0] ? opendir(links[i]) : NULL;
        const struct dirent *e;
        while (dp && (e = readdir(dp))) {
            char p[700];
            snprintf(p, sizeof p, "%s/%s", links[i], e->d_name);
            if (e->d_name[0] != '.')
                unlink(p);
        }
        if (dp)
            closedir(dp);
        rmdir(links[i]);
    }
}

/* Each file of src, linked into dst. */
static void link_files(const char *dst, const char *src)
{
    DIR *dp = opendir(src);
    const struct dirent *e;
    while (dp && (e = readdir(dp))) {
        if (e->d_name[0] == '.')
            continue;
        char from[700], to[700];
        snprintf(from, sizeof from, "%s/%s", src, e->d_name);
        snprintf(to, sizeof to, "%s/%s", dst, e->d_name);
        (void)!symlink(from, to);
    }
    if (dp)
        closedir(dp);
}

static void setup(const char *dir)
{
    const char *sub[2] = {"curves", "logs"};
    for (int i = 0; i < 2; ++i) {
        snprintf(links[i], sizeof links[i], "%s/%s", dir, sub[i]);
        mkdir(links[i], 0755);
        char src[600];
        snprintf(src, sizeof src, "%s/dataset/%s", TIRENV_FUZZ_DATA, sub[i]);
        link_files(links[i], src);
        snprintf(src, sizeof src, "%s/dataset_good/%s", TIRENV_FUZZ_TEST_DATA, sub[i]);
        link_files(links[i], src);
    }
    atexit(unlink_all);  /* runs before fuzz_input.h's cleanup, registered earlier */
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *dir = fuzz_input_dir();
    if (!links[0][0])
        setup(dir);
    char path[400];
    snprintf(path, sizeof path, "%s/cases.csv", dir);
    FILE *fp = fopen(path, "wb");
    if (!fp || (size && fwrite(data, 1, size, fp) != size) || fclose(fp) != 0)
        abort();
    tirenv_dataset ds = {0};
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_dataset_read(dir, 0.68, &ds, &diag) == TIRENV_OK)
        tirenv_dataset_free(&ds);
    unlink(path);
    return 0;
}
