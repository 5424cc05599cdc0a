/* Where the CLI finds its data (the default tire, the tractor, the embedded data set): the
 * library itself takes every file by path and knows no data directory.
 * SPDX-License-Identifier: Apache-2.0 */
#include "cli/cli.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef TIRENV_BIN_TO_DATA
#error "TIRENV_BIN_TO_DATA must name the installed data relative to the installed program"
#endif

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* $TIRENV_DATA when set. Else the data are found from where the program is, so that an
 * installed tree works wherever it is moved and the installed program holds no path of the
 * source tree it was built from:
 *   DIR/tirenv-data         in the build tree: the build links it, beside the program, to the
 *                           source tree's data/; the install does not copy it
 *   DIR/TIRENV_BIN_TO_DATA  installed: ../share/tirenv from bin/
 * DIR is the program's directory, from /proc/self/exe (which resolves symbolic links). Where
 * there is no /proc, or neither exists, the installed path is returned all the same, so that
 * an error names the file tirenv looked for. */
const char *cli_data_dir(void)
{
    static char dir[PATH_MAX];
    if (dir[0])
        return dir;
    const char *env = getenv("TIRENV_DATA");
    if (env && env[0]) {
        snprintf(dir, sizeof dir, "%s", env);
        return dir;
    }
    char exe[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) {
        snprintf(dir, sizeof dir, "%s", TIRENV_BIN_TO_DATA);
        return dir;
    }
    exe[n] = '\0';
    char *slash = strrchr(exe, '/');
    if (slash)
        *slash = '\0';
    char path[PATH_MAX];
    int len = snprintf(path, sizeof path, "%s/tirenv-data", exe);
    if (len < 0 || (size_t)len >= sizeof path || !is_dir(path))
        len = snprintf(path, sizeof path, "%s/%s", exe, TIRENV_BIN_TO_DATA);
    if (len < 0 || (size_t)len >= sizeof path)  /* a directory name too long to be real */
        snprintf(path, sizeof path, "%s", TIRENV_BIN_TO_DATA);
    /* Messages name /opt/tirenv/share/tirenv/..., not .../bin/../share/tirenv/... */
    if (!realpath(path, dir))
        snprintf(dir, sizeof dir, "%s", path);
    return dir;
}

const char *cli_data_path(const char *rel, char *buf, size_t n)
{
    snprintf(buf, n, "%s/%s", cli_data_dir(), rel);
    return buf;
}
