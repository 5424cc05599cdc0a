/* --jobs N: how many work items a command runs at once (tirenv/parallel.h). The library's
 * default is 1; the command's is every core this process may run on.
 * SPDX-License-Identifier: Apache-2.0 */
#define _GNU_SOURCE  /* sched_getaffinity, CPU_COUNT */
#include <sched.h>
#include <unistd.h>

#include "cli/cli.h"

/* The cores this process may run on, as nproc counts them: the affinity mask (a batch
 * scheduler or taskset may narrow it), else the online cores, at least 1. */
size_t cli_jobs_default(void)
{
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        return (size_t)CPU_COUNT(&set);
    const long online = sysconf(_SC_NPROCESSORS_ONLN);
    return online > 0 ? (size_t)online : 1;
}

int cli_parse_jobs(const char *arg, size_t *jobs)
{
    long n;
    if (cli_parse_count(arg, 1, CLI_MAX_JOBS, &n)) {
        cli_error("--jobs: expected a whole number from 1 to %d, got '%s'", CLI_MAX_JOBS,
                  arg);
        return CLI_EXIT_USAGE;
    }
    *jobs = (size_t)n;
    return CLI_EXIT_OK;
}

void cli_help_jobs(FILE *fp)
{
    fprintf(fp, "  --jobs N             work items run at once, one thread each (default: the\n"
                "                       cores this process may use, here %zu; 1: serial); the\n"
                "                       results are the same, bit for bit, for every N\n",
            cli_jobs_default());
}
