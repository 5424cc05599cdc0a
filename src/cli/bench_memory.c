/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv bench: the peak memory of tirenv envelope's whole mode over a long road sampled as
 * measured roads are (the project's memory target: the cam over a 10 km class C road sampled
 * at 1 mm, 10 M positions, at most 400 MB resident; README, Speed), and of --stream over the
 * same road as an RDF file (read in bounded memory, docs/formats.md section 5; on one thread
 * and on two, whose chunks hold a window of rows each: envelope_stream.h), measured as a
 * user meets them: this program run as a child on road files it wrote first, its peak
 * resident set from the kernel (wait4's ru_maxrss), so that the bench's own memory does not
 * count, except as a floor: the kernel counts the child's copy of the bench at the fork (its
 * resident set then), which a child that stays smaller (--stream over the RDF road) would
 * report instead of its own. So the full bench takes them from a fresh tirenv bench --memory
 * (cli_bench_memory_fresh), some 4 MB at the fork, not from itself after its timings (13 MB
 * after --quick's). The files (some 250 MB of CSV and 360 MB of RDF over 10 km) are written
 * in a scratch directory made as an output directory's staging one (tirenv_outdir, never
 * committed): a signal that ends the bench ends the child first and removes it (signals.c),
 * and one left by a SIGKILL is removed by the next run. */
#define _GNU_SOURCE /* wait4 */
#include <errno.h>
#include <jansson.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/bench.h"
#include "cli/signals.h"
#include "tirenv/outfile.h"

/* This program's path, from /proc/self/exe; -1 with errno set if there is none. */
static int self_path(char *buf, size_t n)
{
    const ssize_t len = readlink("/proc/self/exe", buf, n - 1);
    if (len <= 0 || (size_t)len >= n - 1) {
        if (len >= 0)  /* readlink succeeded: empty, or (maybe) cut short */
            errno = len == 0 ? ENOENT : ENAMETOOLONG;
        return -1;
    }
    buf[len] = '\0';
    return 0;
}

/* Runs argv (argv[0] a path) with its output thrown away; its exit status in *status, its peak
 * resident set in *kb and its wall time in *seconds. 0, or an errno value. The child is the
 * one a signal ends first (cli_signals_child), known to the handler before a signal can come
 * (they are blocked over the fork), and dies with this program (PR_SET_PDEATHSIG: a SIGKILL
 * of the bench ends the child too, which removes its own temporary file). */
static int run_child(char *const argv[], int out_fd, int *status, long *kb, double *seconds)
{
    const double t0 = cli_wall_seconds();
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigaddset(&block, SIGPIPE);
    sigprocmask(SIG_BLOCK, &block, &old);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid > 0)
        cli_signals_child(pid);
    const int fork_errno = errno;
    if (pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        sigprocmask(SIG_SETMASK, &old, NULL);
        if (getppid() != parent)  /* the bench died before prctl */
            _exit(127);
    } else {
        sigprocmask(SIG_SETMASK, &old, NULL);
    }
    if (pid < 0)
        return fork_errno;
    if (pid == 0) {
        const int null = open("/dev/null", O_RDWR);
        if (null >= 0) {
            dup2(null, STDIN_FILENO);
            dup2(out_fd >= 0 ? out_fd : null, STDOUT_FILENO);
            if (out_fd < 0)
                dup2(null, STDERR_FILENO);
        }
        execv(argv[0], argv);
        _exit(127);
    }
    struct rusage ru;
    pid_t got;
    while ((got = wait4(pid, status, 0, &ru)) < 0 && errno == EINTR)
        ;
    const int wait_errno = errno;
    cli_signals_child(0);
    if (got < 0)
        return wait_errno;
    *seconds = cli_wall_seconds() - t0;
    *kb = ru.ru_maxrss;  /* Linux: kilobytes */
    return 0;
}

/* The memory's figures and its lines of the tables. */
static void report(double length, size_t positions, double mb, double seconds, double rdf_mb,
                   double rdf_s, double rdf2_mb, double rdf2_s)
{
    cli_bench_figure("envelope_whole_road_m", length);
    cli_bench_figure("envelope_whole_positions", (double)positions);
    cli_bench_figure("envelope_whole_peak_mb", mb);
    cli_bench_figure("envelope_whole_s", seconds);
    cli_bench_figure("envelope_stream_rdf_peak_mb", rdf_mb);
    cli_bench_figure("envelope_stream_rdf_s", rdf_s);
    cli_bench_figure("envelope_stream_rdf_jobs2_peak_mb", rdf2_mb);
    cli_bench_figure("envelope_stream_rdf_jobs2_s", rdf2_s);
    cli_bench_say("\nmemory: tirenv envelope --model cam (whole mode, --jobs the cores) over a "
                  "%.0f m class C road\nat 1 mm into a CSV file (%zu positions), as a "
                  "child process: %.0f MB peak resident\n(target at most 400 MB over 10 km: "
                  "%s), %.1f s;\n--stream over the same road as an RDF file: %.1f MB peak "
                  "resident, %.1f s (--jobs 1),\n%.1f MB, %.1f s (--jobs 2)\n",
                  length, positions, mb, length >= 10000 ? (mb <= 400 ? "met" : "missed")
                                                         : "not this road",
                  seconds, rdf_mb, rdf_s, rdf2_mb, rdf2_s);
}

/* How a child that failed ended, from its wait status st: its exit status or its signal (the
 * raw status, 256 for an exit status of 1, reads as neither). */
static const char *child_end(int st, char *buf, size_t n)
{
    if (WIFEXITED(st))
        snprintf(buf, n, "exit status %d", WEXITSTATUS(st));
    else if (WIFSIGNALED(st))
        snprintf(buf, n, "killed by signal %d, %s", WTERMSIG(st), strsignal(WTERMSIG(st)));
    else
        snprintf(buf, n, "wait status %d", st);
    return buf;
}

/* Runs argv as a child (run_child) that must succeed; what failed in diag, naming file. */
static int run_ok(char *const argv[], const char *file, const char *what, long *kb,
                  double *seconds, tirenv_diag *diag)
{
    int st = 0;
    const int e = run_child(argv, -1, &st, kb, seconds);
    if (e)
        return tirenv_error(diag, TIRENV_EIO, file, 0, "", "cannot run %s: %s", argv[0],
                            strerror(e));
    char end[64];
    if (!(WIFEXITED(st) && WEXITSTATUS(st) == 0))
        return tirenv_error(diag, TIRENV_EIO, file, 0, "", "%s failed (%s)", what,
                            child_end(st, end, sizeof end));
    return TIRENV_OK;
}

/* The tire file as a child reads it: by its real path, so that /dev/stdin (or /dev/fd/0)
 * redirected from a file names that file, not the child's own standard input, /dev/null
 * (run_child); a pipe was refused before (cmd_bench.c). */
static const char *child_tire(const char *tire_path, char real[PATH_MAX])
{
    return realpath(tire_path, real) ? real : tire_path;
}

int cli_bench_memory(const char *tire_path, const tirenv_tire *tire, double length,
                     tirenv_diag *diag)
{
    char real[PATH_MAX];
    tire_path = child_tire(tire_path, real);
    char self[PATH_MAX], target[PATH_MAX - 64], road[PATH_MAX], rdf[PATH_MAX], out[PATH_MAX];
    char len_text[32];
    const char *tmp = cli_bench_tmpdir();  /* the 10 km road's files are some 600 MB */
    if (snprintf(target, sizeof target, "%s/tirenv-bench-memory", tmp) >= (int)sizeof target)
        return tirenv_error(diag, TIRENV_EINVAL, "TMPDIR", 0, "", "too long a path: %s", tmp);
    if (self_path(self, sizeof self) != 0)
        return tirenv_error(diag, TIRENV_EIO, "/proc/self/exe", 0, "",
                            "cannot find this program's path: %s", strerror(errno));
    tirenv_outdir *scratch = NULL;
    int status = tirenv_outdir_begin(target, &scratch, diag);
    if (status)
        return status;
    const char *dir = tirenv_outdir_path(scratch);
    snprintf(road, sizeof road, "%s/road.csv", dir);
    snprintf(rdf, sizeof rdf, "%s/road.rdf", dir);
    snprintf(out, sizeof out, "%s/curve.csv", dir);
    snprintf(len_text, sizeof len_text, "%.0f", length);
    char *make_road[] = {self, "road", "--class", "C", "--length", len_text, "--dx", "0.001",
                         "-o", road, NULL};
    char *envelope[] = {self, "envelope", "--model", "cam", "--contact-length", "0.33",
                        "--tire", (char *)tire_path, "--profile", road, "-o", out, NULL};
    char *convert[] = {self, "convert", "--profile", road, "-o", rdf, NULL};
    char jobs[] = "1";  /* then "2" */
    char *stream[] = {self, "envelope", "--model", "cam", "--contact-length", "0.33",
                      "--tire", (char *)tire_path, "--profile", rdf, "--stream", "--jobs", jobs,
                      "-o", out, NULL};
    long kb = 0, rdf_kb = 0, rdf2_kb = 0, setup_kb = 0;
    double seconds = 0, rdf_s = 0, rdf2_s = 0, setup_s = 0;
    status = run_ok(make_road, road, "tirenv road", &setup_kb, &setup_s, diag);
    if (!status)
        status = run_ok(envelope, out, "tirenv envelope --model cam over the CSV road", &kb,
                        &seconds, diag);
    if (!status)
        status = run_ok(convert, rdf, "tirenv convert to RDF", &setup_kb, &setup_s, diag);
    if (!status)
        status = run_ok(stream, out, "tirenv envelope --model cam --stream over the RDF road",
                        &rdf_kb, &rdf_s, diag);
    jobs[0] = '2';
    if (!status)
        status = run_ok(stream, out, "tirenv envelope --model cam --stream --jobs 2 over the "
                        "RDF road", &rdf2_kb, &rdf2_s, diag);
    tirenv_outdir_abort(scratch);
    if (status)
        return status;
    const tirenv_positions s = tirenv_positions_default(0, length, tire->springs.R0);
    /* ru_maxrss's kilobytes are 1024 bytes */
    report(length, tirenv_positions_count(s.x_from, s.x_to, s.dx), 1024.0 * (double)kb / 1e6,
           seconds, 1024.0 * (double)rdf_kb / 1e6, rdf_s, 1024.0 * (double)rdf2_kb / 1e6,
           rdf2_s);
    return TIRENV_OK;
}

/* The figures of a fresh bench --memory --json, in its output text. */
static int fresh_figures(const char *text, tirenv_diag *diag)
{
    static const char *const names[8] = {
        "envelope_whole_road_m",       "envelope_whole_peak_mb",
        "envelope_whole_s",            "envelope_stream_rdf_peak_mb",
        "envelope_stream_rdf_s",       "envelope_whole_positions",
        "envelope_stream_rdf_jobs2_peak_mb", "envelope_stream_rdf_jobs2_s"};
    double v[8];
    json_error_t e;
    json_t *root = json_loads(text, 0, &e);
    int status = root ? TIRENV_OK
                      : tirenv_error(diag, TIRENV_EPARSE, "tirenv bench --memory --json", 0,
                                     "", "its output does not read as JSON: %s", e.text);
    for (size_t k = 0; !status && k < 8; ++k) {
        const json_t *j = json_object_get(root, names[k]);
        if (!json_is_number(j))
            status = tirenv_error(diag, TIRENV_EPARSE, "tirenv bench --memory --json", 0,
                                  names[k], "missing from its output");
        else
            v[k] = json_number_value(j);
    }
    json_decref(root);
    if (!status)
        report(v[0], (size_t)v[5], v[1], v[2], v[3], v[4], v[6], v[7]);
    return status;
}

int cli_bench_memory_fresh(const char *tire_path, int quick, tirenv_diag *diag)
{
    char real[PATH_MAX];
    tire_path = child_tire(tire_path, real);
    char self[PATH_MAX];
    if (self_path(self, sizeof self) != 0)
        return tirenv_error(diag, TIRENV_EIO, "/proc/self/exe", 0, "",
                            "cannot find this program's path: %s", strerror(errno));
    int status = TIRENV_OK;
    char *argv[] = {self, "bench", "--memory", "--json", "--tire", (char *)tire_path,
                    quick ? "--quick" : NULL, NULL};
    FILE *out = tmpfile();  /* its figures: a few hundred bytes */
    if (!out)
        return tirenv_error(diag, TIRENV_EIO, "tmpfile", 0, "", "cannot make a temporary "
                            "file: %s", strerror(errno));
    int st = 0;
    long kb = 0;
    double seconds = 0;
    const int e = run_child(argv, fileno(out), &st, &kb, &seconds);
    char text[8192], end[64];
    size_t n = 0;
    if (e)
        status = tirenv_error(diag, TIRENV_EIO, self, 0, "", "cannot run %s: %s", self,
                              strerror(e));
    else if (!(WIFEXITED(st) && WEXITSTATUS(st) == 0))
        status = tirenv_error(diag, TIRENV_EIO, self, 0, "", "tirenv bench --memory failed "
                              "(%s)", child_end(st, end, sizeof end));
    else if (fseek(out, 0, SEEK_SET) != 0 || (n = fread(text, 1, sizeof text - 1, out)) == 0)
        status = tirenv_error(diag, TIRENV_EIO, "tmpfile", 0, "", "cannot read the figures "
                              "of tirenv bench --memory");
    fclose(out);
    text[n] = '\0';
    return status ? status : fresh_figures(text, diag);
}
