/* An output that would replace an input (cli_refuse_clobber). Every output file is written
 * beside its target and renamed over it (tirenv/outfile.h), so `-o` naming the road, tire,
 * network or log the command reads leaves a result computed from the whole input, but the
 * input gone: `envelope --profile road.csv -o road.csv` turned the road into its curve.
 * SPDX-License-Identifier: Apache-2.0 */
#define _DEFAULT_SOURCE  /* realpath */
#include "cli/cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* What the rename replaces is the name the path leads to once every symbolic link is
 * followed, so two paths clash when they resolve to the same name: a symbolic link to the
 * input clashes, a hard link (another name of the same file) does not, its name survives. A
 * FIFO or a device is written through and a directory's files are carried over
 * (tirenv/outfile.h), so only a regular file clashes. With inside, output clashes with any
 * regular file below the directory input instead. */
static int clashes(const char *output, const char *input, int inside)
{
    if (!output || !input || strcmp(output, "-") == 0)
        return 0;
    char *const out = realpath(output, NULL);
    char *const in = out ? realpath(input, NULL) : NULL;
    const size_t n = in ? strlen(in) : 0;
    struct stat st;
    const int same = in && (inside ? strncmp(out, in, n) == 0 &&
                                         (out[n] == '/' || in[n - 1] == '/')
                                   : strcmp(out, in) == 0);
    const int clash = same && stat(out, &st) == 0 && S_ISREG(st.st_mode);
    free(out);
    free(in);
    return clash;
}

int cli_refuse_clobber(const char *cmd, const char *output, const char *option,
                       const char *input)
{
    if (!clashes(output, input, 0))
        return CLI_EXIT_OK;
    cli_error("%s: -o %s is the file %s %s reads: the output would replace it; expected "
              "another file", cmd, output, option, input);
    return CLI_EXIT_USAGE;
}

int cli_refuse_clobber_dir(const char *cmd, const char *output, const char *option,
                           const char *dir)
{
    if (!clashes(output, dir, 1))
        return CLI_EXIT_OK;
    cli_error("%s: -o %s is a file of the directory %s %s, whose files it reads: the output "
              "would replace it; expected a file elsewhere or a new name", cmd, output, option,
              dir);
    return CLI_EXIT_USAGE;
}

int cli_same_dir(const char *a, const char *b)
{
    char *const ra = realpath(a, NULL);
    char *const rb = ra ? realpath(b, NULL) : NULL;
    struct stat st;
    const int same = rb && strcmp(ra, rb) == 0 && stat(ra, &st) == 0 && S_ISDIR(st.st_mode);
    free(ra);
    free(rb);
    return same;
}

int cli_refuse_clobber_into(const char *cmd, const char *dir, const char *const names[],
                            const char *option, const char *input)
{
    for (size_t k = 0; input && names[k]; ++k) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, names[k]);
        if (clashes(path, input, 0)) {
            cli_error("%s: -o %s writes %s, which is the file %s %s: the output would "
                      "replace it; expected another directory, or the input elsewhere", cmd,
                      dir, path, option, input);
            return CLI_EXIT_USAGE;
        }
    }
    return CLI_EXIT_OK;
}
