/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv bench: the peak memory of tirenv envelope's whole mode over a long road sampled as
 * measured roads are (the project's memory target: the cam over a 10 km class C road sampled
 * at 1 mm, 10 M positions, at most 400 MB resident; README, Speed), measured as a user meets
 * it: this program run as a child on a road file it wrote first, its peak resident set from
 * the kernel (wait4's ru_maxrss), so that the bench's own memory does not count. */
#define _GNU_SOURCE /* wait4 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/bench.h"

/* This program's path, from /proc/self/exe. */
static int self_path(char *buf, size_t n)
{
    const ssize_t len = readlink("/proc/self/exe", buf, n - 1);
    if (len <= 0 || (size_t)len >= n - 1)
        return -1;
    buf[len] = '\0';
    return 0;
}

/* Runs argv (argv[0] a path) with its output thrown away; its exit status in *status, its peak
 * resident set in *kb and its wall time in *seconds. 0, or an errno value. */
static int run_child(char *const argv[], int *status, long *kb, double *seconds)
{
    const double t0 = cli_wall_seconds();
    const pid_t pid = fork();
    if (pid < 0)
        return errno;
    if (pid == 0) {
        const int null = open("/dev/null", O_RDWR);
        if (null >= 0) {
            dup2(null, STDIN_FILENO);
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
        }
        execv(argv[0], argv);
        _exit(127);
    }
    struct rusage ru;
    pid_t got;
    while ((got = wait4(pid, status, 0, &ru)) < 0 && errno == EINTR)
        ;
    if (got < 0)
        return errno;
    *seconds = cli_wall_seconds() - t0;
    *kb = ru.ru_maxrss;  /* Linux: kilobytes */
    return 0;
}

int cli_bench_memory(const char *tire_path, const tirenv_tire *tire, double length,
                     tirenv_diag *diag)
{
    char self[PATH_MAX], dir[PATH_MAX - 16], road[PATH_MAX], out[PATH_MAX], len_text[32];
    /* $TMPDIR where set: the 10 km road's CSV is some 250 MB, more than a small /tmp holds */
    const char *tmp = getenv("TMPDIR");
    if (snprintf(dir, sizeof dir, "%s/tirenv-bench-memory-XXXXXX", tmp && *tmp ? tmp : "/tmp") >=
        (int)sizeof dir)
        return tirenv_error(diag, TIRENV_EINVAL, "TMPDIR", 0, "", "too long a path: %s", tmp);
    if (self_path(self, sizeof self) != 0)
        return tirenv_error(diag, TIRENV_EIO, "/proc/self/exe", 0, "",
                            "cannot find this program's path: %s", strerror(errno));
    if (!mkdtemp(dir))
        return tirenv_error(diag, TIRENV_EIO, dir, 0, "", "cannot make a directory: %s",
                            strerror(errno));
    snprintf(road, sizeof road, "%s/road.csv", dir);
    snprintf(out, sizeof out, "%s/curve.csv", dir);
    snprintf(len_text, sizeof len_text, "%.0f", length);
    char *make_road[] = {self, "road", "--class", "C", "--length", len_text, "--dx", "0.001",
                         "-o", road, NULL};
    char *envelope[] = {self, "envelope", "--model", "cam", "--contact-length", "0.33",
                        "--tire", (char *)tire_path, "--profile", road, "-o", out, NULL};
    int st = 0, status = TIRENV_OK;
    long kb = 0, road_kb = 0;
    double seconds = 0, road_s = 0;
    int e = run_child(make_road, &st, &road_kb, &road_s);
    if (!e && !(WIFEXITED(st) && WEXITSTATUS(st) == 0))
        status = tirenv_error(diag, TIRENV_EIO, road, 0, "", "tirenv road failed (status %d)",
                              st);
    if (!e && !status)
        e = run_child(envelope, &st, &kb, &seconds);
    if (!e && !status && !(WIFEXITED(st) && WEXITSTATUS(st) == 0))
        status = tirenv_error(diag, TIRENV_EIO, out, 0, "",
                              "tirenv envelope --model cam over %s failed (status %d)", road,
                              st);
    if (e)
        status = tirenv_error(diag, TIRENV_EIO, dir, 0, "", "cannot run %s: %s", self,
                              strerror(e));
    remove(road);
    remove(out);
    rmdir(dir);
    if (status)
        return status;
    const double mb = 1024.0 * (double)kb / 1e6;  /* ru_maxrss's kilobytes are 1024 bytes */
    const tirenv_positions s = tirenv_positions_default(0, length, tire->springs.R0);
    const size_t positions = tirenv_positions_count(s.x_from, s.x_to, s.dx);
    cli_bench_figure("envelope_whole_road_m", length);
    cli_bench_figure("envelope_whole_positions", (double)positions);
    cli_bench_figure("envelope_whole_peak_mb", mb);
    cli_bench_figure("envelope_whole_s", seconds);
    cli_bench_say("\nmemory: tirenv envelope --model cam (whole mode, --jobs the cores) over a "
                  "%.0f m class C road\nat 1 mm into a CSV file (%zu positions), as a "
                  "child process: %.0f MB peak resident\n(target at most 400 MB over 10 km: "
                  "%s), %.1f s\n",
                  length, positions, mb, length >= 10000 ? (mb <= 400 ? "met" : "missed")
                                                         : "not this road",
                  seconds);
    return TIRENV_OK;
}
