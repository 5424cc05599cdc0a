/* tirenv bench: wall time of the models and of the springs model's equilibrium solvers on one
 * fixed sweep, so that figures from different machines and versions can be compared.
 * SPDX-License-Identifier: Apache-2.0 */
#include <errno.h>
#include <jansson.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <unistd.h>

#include "cli/bench.h"
#include "tirenv/nn.h"
#include "tirenv/road.h"
#include "tirenv/train.h"

/* The sweep: the paper's case F (contact length 0.38 m, cleat 0.30 x 0.10 m), 1.5 m at 1 mm. */
static const double bench_l_c = 0.38, cleat_L = 0.30, cleat_H = 0.10;  /* m */
static const double sweep_from = -1.0, sweep_dx = 0.001;                /* m */
enum { SWEEP_N = 1501 };
static double sweep_min_s = 0.2;                        /* s of timed cleat sweeps; 0 quick */
enum { SWEEP_MAX_RUNS = 100000 };

/* The figures of one run, by name, for --json; the table goes to stdout unless --json. */
static json_t *figures;
static int as_json;

void cli_bench_say(const char *fmt, ...)
{
    if (as_json)
        return;
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

void cli_bench_figure(const char *name, double value)
{
    if (figures && isfinite(value))
        json_object_set_new(figures, name, json_real(value));
}

const char *cli_bench_tmpdir(void)
{
    const char *tmp = getenv("TMPDIR");
    return tmp && *tmp ? tmp : "/tmp";
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double cli_bench_median(double v[], size_t n)
{
    qsort(v, n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static const struct {
    const char *label;
    const char *model;
    tirenv_eq_method method;
    const char *key; /* figure names: <key>_cleat_pos_per_s, <key>_evals_per_pos, ... */
} cases[] = {
    {"rigid", "rigid", TIRENV_EQ_NEWTON, "rigid"},
    {"springs newton", "springs", TIRENV_EQ_NEWTON, "springs"},
    {"springs secant", "springs", TIRENV_EQ_SECANT, "springs_secant"},
    {"springs brent", "springs", TIRENV_EQ_BRENT, "springs_brent"},
    {"ring newton", "ring", TIRENV_EQ_NEWTON, "ring"},
};
enum { N_CASES = sizeof cases / sizeof cases[0] };

typedef struct {
    double best;          /* best wall time of a sweep, s */
    double load;          /* N */
    size_t failed;        /* positions without an equilibrium */
    double first_fail_x;  /* m */
    char first_fail[600]; /* its diagnostic */
    double evals_mean;    /* force evaluations per successful position */
    size_t evals_max;
} bench_result;

static void usage(FILE *fp)
{
    fputs("usage: tirenv bench [--repeat N] [--quick] [--memory] [--json] [--tire FILE] "
          "[--set KEY=VALUE]...\n"
          "\n"
          "Times tirenv_model_envelope over a fixed sweep: contact length 0.38 m, cleat\n"
          "0.30 x 0.10 m, centre x from -1.0 to 0.5 m at 1 mm (1501 positions), for the rigid\n"
          "model, the springs model with each equilibrium solver (newton, secant = the\n"
          "paper's eq. 2, brent) and the ring reference tire. Reports the best of N runs\n"
          "(and of as many more as fill 0.2 s: a rigid sweep takes some 50 us),\n"
          "single-threaded. Then the rig-log import of a 10,000-sample log, read from CSV and\n"
          "from memory, and the CSV writers' number formatting against snprintf (10^6\n"
          "numbers, same bytes). Then the road: rigid, cam and springs (contact length 0.33 m) over a\n"
          "1 km ISO 8608 class C road at 10 mm (seed 1), 100,001 positions, against the\n"
          "project's targets; springs' sweep of it in tirenv envelope's chunks on 1 and on 2\n"
          "threads, whole and streamed (--stream, the same points), interleaved (whole:\n"
          "over 2N+1 rounds, the median of the rounds' ratios and the best times'); springs\n"
          "over the same road sampled at 1 mm and 10 mm (a tenth of its length, the same\n"
          "positions; the two sweeps interleaved over 2N+1 rounds: the\n"
          "median of the rounds' ratios, and the best time of each); and nn, the network\n"
          "trained on the embedded data set (lm, seed 1)\n"
          "over the same road by equivalent-cleat decomposition, h and slope, the\n"
          "decomposition's build timed apart, and the network alone on batches of 4096 inputs.\n"
          "Then a load that changes before every position (tirenv_model_set_load, +-20 %\n"
          "over 0.5 m) against a fixed load, per position, for cam, springs and nn.\n"
          "Then the ride: the default tractor over that road at 10 km/h with point contact,\n"
          "cam, nn and springs, against real time (best of at most 3 runs).\n"
          "Last the memory: tirenv envelope --model cam in whole mode over a 10 km class C\n"
          "road at 1 mm (100 m with --quick) into a CSV file, run as a child process (the tire\n"
          "file, without --set), its peak resident set (target at most 400 MB over 10 km),\n"
          "and --stream over the same road written as an RDF file (its rows read as the tire\n"
          "rolls), --jobs 1 and --jobs 2. The road files go to a scratch directory in $TMPDIR\n"
          "(else /tmp), removed at the end or when a signal ends the bench.\n"
          "The ring reference tire runs the cleat sweep too (the solver table's last row).\n"
          "The targets' ratios over the cleat (springs and ring over rigid) are the median of\n"
          "2N+1 rounds' own ratios, each round timing rigid, springs and ring one after the\n"
          "other (best of the sweeps that fill 0.02 s each); the ratio of the best sweeps\n"
          "over the whole run is beside them (_best).\n"
          "\n"
          "options:\n"
          "  --repeat N           runs per method, best kept (default 5)\n"
          "  --quick              one run each and 100 m roads: every figure in seconds,\n"
          "                       rougher\n"
          "  --memory             the memory alone (the last part), the timings skipped\n"
          "  --json               print every figure as one JSON object of name: number\n"
          "                       pairs (positions/s, seconds, ratios) instead of the tables\n",
          fp);
    cli_help_tire(fp, 0, "RADIAL_STIFFNESS=4.5e5 (the springs model's)");
    fputs("  -h, --help           show this help\n", fp);
}


/* Records that a method found no equilibrium even on flat ground (model_set solves it), so
 * that the other methods are still timed. Data errors stop the bench. */
static int setup_failed(int status, const tirenv_diag *diag, bench_result *r)
{
    if (cli_exit_code(status) != CLI_EXIT_NUMERIC)
        return cli_fail(status, diag);
    char msg[sizeof r->first_fail - 16];
    snprintf(r->first_fail, sizeof r->first_fail, "on flat ground: %s",
             tirenv_diag_format(diag, msg, sizeof msg));
    r->failed = SWEEP_N;
    r->first_fail_x = NAN;
    return CLI_EXIT_OK;
}

/* One timed sweep. The whole-sweep call is what users run; when it fails (the plain secant
 * can), the sweep is redone position by position so the failures can be counted. */
static int run_once(tirenv_model *m, const tirenv_profile *prof, const double x[],
                    tirenv_point pt[], unsigned char ok[], bench_result *r, double *seconds)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    memset(ok, 0, SWEEP_N);
    *seconds = 0;
    int status = tirenv_model_set(m, prof, r->load, &diag);  /* resets the warm start */
    if (status)
        return setup_failed(status, &diag, r);
    double t0 = cli_wall_seconds();
    status = tirenv_model_envelope(m, SWEEP_N, x, pt, NULL, &diag);
    double t1 = cli_wall_seconds();
    memset(ok, 1, SWEEP_N);
    r->failed = 0;
    if (status) {
        if ((status = tirenv_model_set(m, prof, r->load, &diag)))
            return setup_failed(status, &diag, r);
        t0 = cli_wall_seconds();
        for (size_t k = 0; k < SWEEP_N; ++k) {
            tirenv_diag d;
            tirenv_diag_clear(&d);
            if (!(ok[k] = tirenv_model_eval(m, x[k], &pt[k], &d) == TIRENV_OK) &&
                r->failed++ == 0) {
                r->first_fail_x = x[k];
                tirenv_diag_format(&d, r->first_fail, sizeof r->first_fail);
            }
        }
        t1 = cli_wall_seconds();
    }
    *seconds = t1 - t0;
    return CLI_EXIT_OK;
}

static int run_case(const tirenv_tire *tire0, size_t i, const tirenv_profile *prof,
                    const double x[], long repeat, bench_result *r)
{
    tirenv_tire tire = *tire0;
    tire.eq.method = cases[i].method;
    const tirenv_model_type *type = tirenv_model_type_find(cases[i].model);
    tirenv_model *m;
    int code = cli_model(type, &tire, NULL, &m);
    if (code)
        return code;
    tirenv_point *pt = malloc(SWEEP_N * sizeof *pt);
    unsigned char *ok = malloc(SWEEP_N);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    int status = pt && ok ? tirenv_model_load_for_contact_length(m, bench_l_c, &r->load, &diag)
                          : TIRENV_ENOMEM;
    if (status)
        code = cli_fail(status, &diag);
    /* A rigid sweep takes some 50 us, too short for the best of 5 to be steady (it moved
     * by 2x between runs, and every "over rigid" ratio with it): the runs go on until they
     * fill sweep_min_s as well. */
    double spent = 0;
    for (long rep = 0; (rep < repeat || (spent < sweep_min_s && rep < SWEEP_MAX_RUNS)) && !code;
         ++rep) {
        double t = 0;
        if (!(code = run_once(m, prof, x, pt, ok, r, &t)) && (rep == 0 || t < r->best))
            r->best = t;
        spent += t;
        /* No equilibrium on flat ground (setup_failed): no sweep ran, none will, and the
         * time spent stays 0, which would run SWEEP_MAX_RUNS failing setups. */
        if (!code && r->failed == SWEEP_N && isnan(r->first_fail_x))
            break;
    }
    if (!code) {
        double sum = 0;
        r->evals_max = 0;
        for (size_t k = 0; k < SWEEP_N; ++k) {
            if (!ok[k])
                continue;
            sum += (double)pt[k].iterations;
            if (pt[k].iterations > r->evals_max)
                r->evals_max = pt[k].iterations;
        }
        r->evals_mean = r->failed < SWEEP_N ? sum / (double)(SWEEP_N - r->failed) : 0;
    }
    free(ok);
    free(pt);
    tirenv_model_free(m);
    return code;
}

/* The targets' ratios over the cleat, rigid's time a position against the springs model's
 * and the ring's, in rounds: in each, the three models' sweeps one after the other (which
 * goes first turns with the round), each repeated until its sweeps fill round_min_s and the
 * best kept; the figure is the median of the rounds' own ratios. The best sweep of each model
 * over the whole bench (print_table's "best over best") set a rigid best of some 4,000 sweeps
 * of 45 us against a springs best of some 60 and a ring best of 5, taken seconds apart, and
 * rigid's best moved by 1.8x between runs of one binary on a shared VM (20.0 M to 36.7 M
 * positions/s), the ratios with it. Within a round the three see the same machine, and the
 * median is not moved by a few rounds that caught a burst of load. */
static double round_min_s = 0.02; /* s of sweeps of each model a round, at least two; 0 quick:
                                   * one (the sanitizer build's cli test runs --quick) */
static const size_t round_cases[3] = {0, 1, 4}; /* rigid, springs newton, ring */

static int cleat_rounds(const tirenv_tire *tire, const tirenv_profile *prof, const double x[],
                        long repeat, const bench_result r[])
{
    const size_t rounds = 2 * (size_t)repeat + 1;
    tirenv_model *m[3] = {NULL, NULL, NULL};
    tirenv_point *pt = malloc(SWEEP_N * sizeof *pt);
    unsigned char *ok = malloc(SWEEP_N);
    double *ratio[2] = {malloc(rounds * sizeof(double)), malloc(rounds * sizeof(double))};
    int code = pt && ok && ratio[0] && ratio[1] ? CLI_EXIT_OK : cli_fail(TIRENV_ENOMEM, NULL);
    for (size_t i = 0; i < 3 && !code; ++i) {
        tirenv_tire t = *tire;
        t.eq.method = cases[round_cases[i]].method;
        code = cli_model(tirenv_model_type_find(cases[round_cases[i]].model), &t, NULL, &m[i]);
    }
    for (size_t q = 0; q < rounds && !code; ++q) {
        double best[3] = {INFINITY, INFINITY, INFINITY};
        for (size_t j = 0; j < 3 && !code; ++j) {
            const size_t i = (q + j) % 3;
            bench_result ri = r[round_cases[i]]; /* its load; run_once counts failures in it */
            double spent = 0, t;
            for (int rep = 0; !code && (rep < (round_min_s > 0 ? 2 : 1) || spent < round_min_s);
                 ++rep) {
                code = run_once(m[i], prof, x, pt, ok, &ri, &t);
                best[i] = fmin(best[i], t);
                spent += t;
            }
        }
        ratio[0][q] = best[1] / best[0];
        ratio[1][q] = best[2] / best[0];
    }
    if (!code) {
        cli_bench_figure("cleat_rounds", (double)rounds);
        const char *name[2] = {"springs_over_rigid_cleat", "ring_over_rigid_cleat"};
        const char *label[2] = {"springs newton", "ring"};
        for (int k = 0; k < 2; ++k) {
            const double mid = cli_bench_median(ratio[k], rounds); /* sorts it */
            cli_bench_figure(name[k], mid);
            cli_bench_say("  %s / rigid time, the median of %zu interleaved rounds: %.1f x "
                          "(from %.1f to %.1f)\n",
                          label[k], rounds, mid, ratio[k][0], ratio[k][rounds - 1]);
        }
    }
    for (size_t i = 0; i < 3; ++i)
        tirenv_model_free(m[i]);
    free(ratio[0]);
    free(ratio[1]);
    free(ok);
    free(pt);
    return code;
}

/* The machine in one line: the kernel's idea of it and, on Linux, the CPU model. */
static void print_machine(void)
{
    struct utsname u;
    char cpu[256] = "unknown CPU";
    FILE *fp = fopen("/proc/cpuinfo", "r");
    if (fp) {
        char line[512];
        while (fgets(line, sizeof line, fp)) {
            const char *colon = strchr(line, ':');
            if (strncmp(line, "model name", 10) == 0 && colon) {
                snprintf(cpu, sizeof cpu, "%s", colon + 2);
                cpu[strcspn(cpu, "\n")] = '\0';
                break;
            }
        }
        fclose(fp);
    }
    if (uname(&u) == 0)
        cli_bench_say("machine: %s %s %s, %s\n", u.sysname, u.release, u.machine, cpu);
    else
        cli_bench_say("machine: %s\n", cpu);
    cli_bench_say("note: one core, one thread; figures are single-threaded wall times "
           "(CLOCK_MONOTONIC), independent of the number of cores\n");
}

static void print_table(long repeat, const bench_result r[])
{
    cli_bench_say("\n%-16s %13s %12s %11s %10s %8s\n", "method", "positions/s", "us/position",
                  "evals mean", "evals max", "failed");
    for (size_t i = 0; i < N_CASES; ++i) {
        char key[64];
        snprintf(key, sizeof key, "%s_cleat_failed", cases[i].key);
        cli_bench_figure(key, (double)r[i].failed);
        if (r[i].failed == SWEEP_N) {
            cli_bench_say("%-16s %13s %12s %11s %10s %8zu\n", cases[i].label, "-", "-", "-",
                          "-", r[i].failed);
            continue;
        }
        snprintf(key, sizeof key, "%s_cleat_pos_per_s", cases[i].key);
        cli_bench_figure(key, SWEEP_N / r[i].best);
        if (strcmp(cases[i].model, "rigid") != 0) {
            snprintf(key, sizeof key, "%s_evals_per_pos", cases[i].key);
            cli_bench_figure(key, r[i].evals_mean);
            snprintf(key, sizeof key, "%s_evals_max", cases[i].key);
            cli_bench_figure(key, (double)r[i].evals_max);
        }
        cli_bench_say("%-16s %13.0f %12.3f %11.2f %10zu %8zu\n", cases[i].label,
                      SWEEP_N / r[i].best, 1e6 * r[i].best / SWEEP_N, r[i].evals_mean,
                      r[i].evals_max, r[i].failed);
    }
    for (size_t i = 0; i < N_CASES; ++i) {
        if (r[i].failed == SWEEP_N)
            cli_bench_say("%s failed everywhere, %s\n", cases[i].label, r[i].first_fail);
        else if (r[i].failed)
            cli_bench_say("%s failed at %zu of %d positions (timed position by position), "
                          "first at x = %.4f m: %s\n",
                          cases[i].label, r[i].failed, SWEEP_N, r[i].first_fail_x,
                          r[i].first_fail);
    }
    /* cases[0] is rigid, [1] springs newton, [2] secant, [4] ring. */
    cli_bench_say("\nratios (best of %ld):\n", repeat);
    if (r[1].evals_mean > 0 && r[2].evals_mean > 0) {
        cli_bench_figure("springs_newton_over_secant_evals", r[1].evals_mean / r[2].evals_mean);
        cli_bench_say("  springs newton / secant evaluations per position: %.3f\n",
                      r[1].evals_mean / r[2].evals_mean);
    }
    if (r[0].best > 0 && r[1].failed < SWEEP_N) {
        cli_bench_figure("springs_over_rigid_cleat_best", r[1].best / r[0].best);
        cli_bench_say("  springs newton / rigid time, best over best: %.1f x\n",
                      r[1].best / r[0].best);
    }
    if (r[0].best > 0 && r[4].failed < SWEEP_N) {
        cli_bench_figure("ring_over_rigid_cleat_best", r[4].best / r[0].best);
        cli_bench_say("  ring / rigid time, best over best: %.0f x\n", r[4].best / r[0].best);
    }
}

/* The rig-log import (target: well under 10 ms at 10,000 samples): a springs-model
 * run over the same cleat sampled to 10,000 samples, written as CSV, then read and imported
 * (and imported alone, from memory), best of repeat. */
static int bench_import(const tirenv_tire *tire, const tirenv_profile *prof, long repeat)
{
    enum { SAMPLES = 10000 };
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, tire);
    double load;
    int status = m ? tirenv_model_load_for_contact_length(m, bench_l_c, &load, &diag)
                   : TIRENV_ENOMEM;
    if (!status)
        status = tirenv_model_set(m, prof, load, &diag);
    tirenv_rig_settings rig = tirenv_rig_default();
    const double passage = cleat_L + 2 * (tire->springs.R0 + rig.run_up);
    rig.rate = rig.speed * (SAMPLES - 1) / passage;
    tirenv_rig_log log = {0};
    if (!status)
        status = tirenv_rig_simulate(m, prof, &rig, &log, &diag);
    char path[PATH_MAX];
    if (!status && snprintf(path, sizeof path, "%s/tirenv-bench-log-XXXXXX", cli_bench_tmpdir())
                       >= (int)sizeof path)
        status = tirenv_error(&diag, TIRENV_EINVAL, "TMPDIR", 0, "", "too long a path: %s",
                              cli_bench_tmpdir());
    const int fd = status ? -1 : mkstemp(path);
    if (fd >= 0)
        close(fd);
    if (!status && fd < 0)
        status = tirenv_error(&diag, TIRENV_EIO, path, 0, "", "cannot make the rig log's "
                              "temporary file: %s", strerror(errno));
    if (!status)
        status = tirenv_rig_write_log(path, &log, NULL, &diag);
    tirenv_import_settings imp = tirenv_import_default();
    imp.L = cleat_L;
    imp.H = cleat_H;
    imp.R0 = tire->springs.R0;
    imp.contact_length = bench_l_c;
    double best_file = INFINITY, best_mem = INFINITY;
    for (long k = 0; k < repeat && !status; ++k) {
        tirenv_curve curve = {0};
        double t0 = cli_wall_seconds();
        status = tirenv_rig_import(path, &imp, &curve, &diag);
        best_file = fmin(best_file, cli_wall_seconds() - t0);
        tirenv_curve_free(&curve);
        t0 = cli_wall_seconds();
        if (!status)
            status = tirenv_rig_import_samples(log.n, log.t, log.x, log.z, &imp, &curve, &diag);
        best_mem = fmin(best_mem, cli_wall_seconds() - t0);
        tirenv_curve_free(&curve);
    }
    if (fd >= 0)
        remove(path);
    if (!status) {
        cli_bench_figure("import_read_ms", 1e3 * best_file);
        cli_bench_figure("import_ms", 1e3 * best_mem);
        cli_bench_say("\nrig-log import of a %zu-sample log (best of %ld): read + import %.2f "
                      "ms, import alone %.2f ms\n", log.n, repeat, 1e3 * best_file,
                      1e3 * best_mem);
    }
    tirenv_rig_log_free(&log);
    tirenv_model_free(m);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

/* The road (speed over roads): a 1 km ISO 8608 class C road at 10 mm, seed 1, and
 * the centre x = 0 .. 1000 m at 10 mm. The targets are the project's, on one core. */
static const double road_l_c = 0.33, road_dx = 0.01; /* m */
static double road_length = 1000.0;                    /* m; 100 with --quick */
static double memory_length = 10000.0; /* m: the memory's road (cli_bench_memory); 100 quick */
static const struct {
    const char *model;
    double target; /* positions/s */
} road_cases[] = {
    {"rigid", 5e6},
    {"cam", 5e6},
    {"springs", 1e5},
};
enum { N_ROAD_CASES = sizeof road_cases / sizeof road_cases[0] };

/* Best of repeat sweeps of tirenv_model_envelope over the road, in *seconds; the model is
 * set (which resets the warm start) before every sweep and outside the timing. */
static int road_time(const tirenv_tire *tire, const char *model, const tirenv_profile *road,
                     size_t n, const double x[], tirenv_point pt[], long repeat,
                     double *seconds, double *evals, tirenv_diag *diag)
{
    tirenv_model *m = tirenv_model_alloc(tirenv_model_type_find(model), tire);
    double load;
    int status = m ? tirenv_model_load_for_contact_length(m, road_l_c, &load, diag)
                   : TIRENV_ENOMEM;
    *seconds = INFINITY;
    for (long rep = 0; rep < repeat && !status; ++rep) {
        if ((status = tirenv_model_set(m, road, load, diag)))
            break;
        const double t0 = cli_wall_seconds();
        status = tirenv_model_envelope(m, n, x, pt, NULL, diag);
        *seconds = fmin(*seconds, cli_wall_seconds() - t0);
    }
    double sum = 0;
    for (size_t k = 0; k < n && !status; ++k)
        sum += (double)pt[k].iterations;
    *evals = sum / (double)n;
    tirenv_model_free(m);
    return status;
}

/* The network of the study (the embedded data set, lm with its defaults, seed 1), or NULL
 * with the reason in diag if the data set cannot be read. *seconds: training time. */
static tirenv_nn *road_network(const tirenv_tire *tire, double *seconds, tirenv_diag *diag)
{
    char dir[600];
    tirenv_dataset ds;
    if (tirenv_dataset_read(cli_data_path("dataset", dir, sizeof dir), tire->springs.R0, &ds, diag))
        return NULL;
    tirenv_samples s[3];
    double *x[3] = {NULL, NULL, NULL}, *y[3] = {NULL, NULL, NULL};
    int status = TIRENV_OK;
    for (int sp = 0; sp < 3 && !status; ++sp)
        status = tirenv_samples_from_dataset(&ds, (tirenv_split)sp, &s[sp], &x[sp], &y[sp],
                                             diag);
    tirenv_nn *nn = NULL;
    const double t0 = cli_wall_seconds();
    if (!status) {
        const tirenv_train_settings set = tirenv_train_default(tirenv_trainer_lm);
        tirenv_train(tirenv_trainer_lm, &set, &s[0], &s[1], &s[2], &nn, NULL, diag);
    }
    *seconds = cli_wall_seconds() - t0;
    for (int sp = 0; sp < 3; ++sp) {
        free(x[sp]);
        free(y[sp]);
    }
    tirenv_dataset_free(&ds);
    return nn;
}

/* nn over the road: the decomposition (built once per profile and contact length, like
 * tirenv_model_set for the models) timed apart from the positions, h and slope as the CLI
 * writes them. A data set that cannot be read skips the row rather than the bench. */
static int bench_road_nn(const tirenv_tire *tire, const tirenv_profile *road, size_t n,
                         const double x[], long repeat, const tirenv_nn *nn, double t_train,
                         const tirenv_diag *why, tirenv_diag *diag)
{
    if (!nn) {
        char msg[1200];
        cli_bench_say("  %-10s %13s %12.0f %8s\nnn: skipped, no network: %s\n", "nn", "-",
                      1e7, "n/a", tirenv_diag_format(why, msg, sizeof msg));
        return TIRENV_OK;
    }
    double *h = malloc(n * sizeof *h), *slope = malloc(n * sizeof *slope);
    int status = h && slope ? TIRENV_OK : TIRENV_ENOMEM;
    double t_build = INFINITY, t_first = 0, t_eval = INFINITY, t_h = INFINITY;
    tirenv_nn_road_info info = {0};
    for (long rep = 0; rep < repeat && !status; ++rep) {
        tirenv_nn_road *r = NULL;
        double t0 = cli_wall_seconds();
        if ((status = tirenv_nn_road_alloc(nn, tire->springs.R0, road_l_c, road, NULL, &r,
                                           diag)))
            break;
        const double t = cli_wall_seconds() - t0;
        t_first = rep == 0 ? t : t_first;
        t_build = fmin(t_build, t);
        info = tirenv_nn_road_info_of(r);
        t0 = cli_wall_seconds();
        status = tirenv_nn_road_eval(r, n, x, h, slope, diag);
        t_eval = fmin(t_eval, cli_wall_seconds() - t0);
        t0 = cli_wall_seconds();
        if (!status)
            status = tirenv_nn_road_eval(r, n, x, h, NULL, diag);
        t_h = fmin(t_h, cli_wall_seconds() - t0);
        tirenv_nn_road_free(r);
    }
    if (!status) {
        cli_bench_figure("nn_road_pos_per_s", (double)n / t_eval);
        cli_bench_figure("nn_road_h_pos_per_s", (double)n / t_h);
        cli_bench_figure("nn_train_s", t_train);
        cli_bench_figure("nn_road_build_ms", 1e3 * t_build);
        cli_bench_figure("nn_road_build_first_ms", 1e3 * t_first);
        cli_bench_say("  %-10s %13.0f %12.0f %8s\n", "nn", (double)n / t_eval, 1e7,
               (double)n / t_eval >= 1e7 ? "met" : "missed");
        cli_bench_say("nn: the network trained on the embedded data set (lm, seed 1) in %.2f s; the "
               "road's equivalent-cleat\ndecomposition (%zu obstacles, opening %.2f m) built "
               "in %.2f ms (first run %.2f ms), not in the rate;\nh and slope as above, h "
               "alone %.0f positions/s\n", t_train, info.obstacles, info.width,
               1e3 * t_build, 1e3 * t_first, (double)n / t_h);
    }
    free(h);
    free(slope);
    return status;
}

/* The network alone on batches (tirenv_nn_run_batch) of 4096 inputs spread over its training
 * ranges, a working set that stays in cache; and one input at a time. Predictions per
 * second, the best of repeat runs of at least 0.2 s each. */
static volatile double nn_sink;

static double nn_rate(tirenv_nn *nn, int batch, const double *x, double *y, size_t n,
                      long repeat)
{
    double best = 0;
    for (long r = 0; r < repeat; ++r) {
        size_t done = 0;
        const double t0 = cli_wall_seconds();
        double t;
        do {
            double acc = 0;
            if (batch) {
                tirenv_nn_run_batch(nn, n, x, y);
                acc = y[n - 1];
            } else {
                for (size_t k = 0; k < n; ++k)
                    acc += tirenv_nn_run(nn, x + 4 * k);
            }
            nn_sink = acc;
            done += n;
            t = cli_wall_seconds() - t0;
        } while (t < 0.2);
        best = fmax(best, (double)done / t);
    }
    return best;
}

static void bench_nn_batch(tirenv_nn *nn, long repeat)
{
    enum { N_IN = 4096 };
    double *x = malloc(4 * N_IN * sizeof *x), *y = malloc(N_IN * sizeof *y);
    if (!x || !y) {
        cli_bench_say("nn batch: skipped, out of memory\n");
    } else {
        double lo[4], hi[4];
        tirenv_nn_input_range(nn, lo, hi);
        unsigned long long state = 0x9e3779b97f4a7c15ull;
        for (size_t k = 0; k < 4 * N_IN; ++k) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const double u = (double)(state >> 11) * 0x1p-53;
            const double a = lo[k % 4], b = hi[k % 4];
            x[k] = isfinite(a) && isfinite(b) ? a + u * (b - a) : u;
        }
        const double batch = nn_rate(nn, 1, x, y, N_IN, repeat);
        const double single = nn_rate(nn, 0, x, y, N_IN, repeat);
        cli_bench_figure("nn_batch_per_s", batch);
        cli_bench_figure("nn_single_per_s", single);
        cli_bench_say("nn alone (the same network, %d inputs over its training ranges, best of "
                      "%ld): batches %.1f M/s, one at a time %.1f M/s\n",
                      N_IN, repeat, batch / 1e6, single / 1e6);
    }
    free(x);
    free(y);
}

/* One timed sweep of m over road (set first, which resets the warm start, outside the
 * timing): its wall time in *seconds. */
static int fine_sweep(tirenv_model *m, const tirenv_profile *road, double load, size_t n,
                      const double x[], tirenv_point pt[], double *seconds, tirenv_diag *diag)
{
    int status = tirenv_model_set(m, road, load, diag);
    if (status)
        return status;
    const double t0 = cli_wall_seconds();
    status = tirenv_model_envelope(m, n, x, pt, NULL, diag);
    *seconds = cli_wall_seconds() - t0;
    return status;
}

/* Finely sampled roads (measured roads come at 1 mm): the springs model over the same ISO 8608
 * class C road (seed 1) generated at 10 mm and at 1 mm, a tenth of the road's length, at the
 * same positions (every 10 mm): the time a position at 1 mm over that at 10 mm. On a shared
 * machine the rate of a sweep moves between runs seconds apart by more than the ratio's own
 * spread, so the two roads' sweeps are interleaved, one of each a round (which goes first
 * alternates), over 2 repeat + 1 rounds: both see the same load. The figure is the median of
 * the rounds' own ratios (each round's 1 mm time over its 10 mm time, sweeps seconds apart),
 * which a burst of load on a few sweeps does not move; the best time at 1 mm over the best at
 * 10 mm is reported beside it, and moves whenever one road's sweeps alone catch a quiet spell
 * (on the loaded 2-core VM, 2.65 and 3.65 in two runs whose medians were 2.91 and 2.92). The
 * rates are the best sweeps'. */
static int bench_fine_road(const tirenv_tire *tire, long repeat, tirenv_diag *diag)
{
    const double length = 0.1 * road_length, dxs[2] = {0.01, 0.001};
    const size_t n = (size_t)floor(length / road_dx + 0.5) + 1;
    const size_t rounds = 2 * (size_t)repeat + 1;
    double *x = malloc(n * sizeof *x), *ratio = malloc(rounds * sizeof *ratio);
    double best[2] = {INFINITY, INFINITY}, load = 0;
    tirenv_point *pt = malloc(n * sizeof *pt);
    tirenv_profile *road[2] = {NULL, NULL};
    tirenv_model *m[2] = {NULL, NULL};
    int status = x && ratio && pt ? TIRENV_OK : TIRENV_ENOMEM;
    for (size_t k = 0; k < n && !status; ++k)
        x[k] = (double)k * road_dx;
    for (int i = 0; i < 2 && !status; ++i) {
        tirenv_road_settings rs = tirenv_road_default();
        rs.length = length;
        rs.dx = dxs[i];
        status = tirenv_road_iso8608(&rs, &road[i], diag);
        if (!status && !(m[i] = tirenv_model_alloc(tirenv_model_springs, tire)))
            status = TIRENV_ENOMEM;
        if (!status)
            status = tirenv_model_load_for_contact_length(m[i], road_l_c, &load, diag);
    }
    for (size_t r = 0; r < rounds && !status; ++r) {
        double t[2] = {0, 0};
        for (int j = 0; j < 2 && !status; ++j) {
            const int i = (int)(r % 2) ^ j;  /* 10 mm first in even rounds, 1 mm in odd */
            status = fine_sweep(m[i], road[i], load, n, x, pt, &t[i], diag);
            best[i] = fmin(best[i], t[i]);
        }
        ratio[r] = t[1] / t[0];
    }
    if (!status) {
        const double mid = cli_bench_median(ratio, rounds);  /* sorts ratio */
        cli_bench_figure("springs_road_10mm_pos_per_s", (double)n / best[0]);
        cli_bench_figure("springs_road_1mm_pos_per_s", (double)n / best[1]);
        cli_bench_figure("springs_fine_over_coarse_road", mid);
        cli_bench_figure("springs_fine_over_coarse_road_best", best[1] / best[0]);
        cli_bench_figure("springs_fine_over_coarse_road_rounds", (double)rounds);
        cli_bench_say("  springs over the same road sampled at 1 mm and at 10 mm (%.0f m, %zu "
                      "positions at 10 mm, %zu rounds interleaved): %.2f x the time (the "
                      "rounds' median ratio, from %.2f to %.2f; best %.0f and %.0f "
                      "positions/s, %.2f x)\n",
                      length, n, rounds, mid, ratio[0], ratio[rounds - 1], (double)n / best[1],
                      (double)n / best[0], best[1] / best[0]);
    }
    for (int i = 0; i < 2; ++i) {
        tirenv_model_free(m[i]);
        tirenv_profile_free(road[i]);
    }
    free(x);
    free(ratio);
    free(pt);
    return status;
}

static int bench_road(const char *tire_path, const tirenv_tire *tire, long repeat)
{
    tirenv_road_settings rs = tirenv_road_default();
    rs.length = road_length;
    rs.dx = road_dx;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_profile *road = NULL;
    int status = tirenv_road_iso8608(&rs, &road, &diag);
    if (status)
        return cli_fail(status, &diag);
    const size_t n = (size_t)floor(road_length / road_dx + 0.5) + 1;
    double *x = malloc(n * sizeof *x);
    tirenv_point *pt = malloc(n * sizeof *pt);
    if (!x || !pt)
        status = TIRENV_ENOMEM;
    for (size_t k = 0; k < n && !status; ++k)
        x[k] = (double)k * road_dx;
    cli_bench_figure("road_positions", (double)n);
    cli_bench_say("\nroad: ISO 8608 class %c, %.0f m at %g mm (seed %lu, %zu vertices), contact "
           "length %.2f m,\n%zu positions x = 0 .. %.0f m at %g mm, best of %ld runs\n",
           rs.road_class, road_length, 1e3 * road_dx, rs.seed, tirenv_profile_size(road),
           road_l_c, n, road_length, 1e3 * road_dx, repeat);
    /* Rows indented, so that they are not mistaken for the solver table's above. */
    cli_bench_say("  %-10s %13s %12s %8s\n", "model", "positions/s", "target", "");
    double rate[N_ROAD_CASES] = {0};
    for (size_t i = 0; i < N_ROAD_CASES && !status; ++i) {
        double t, evals;
        status = road_time(tire, road_cases[i].model, road, n, x, pt, repeat, &t, &evals, &diag);
        if (status)
            break;
        rate[i] = (double)n / t;
        char key[64];
        snprintf(key, sizeof key, "%s_road_pos_per_s", road_cases[i].model);
        cli_bench_figure(key, rate[i]);
        if (strcmp(road_cases[i].model, "springs") == 0)
            cli_bench_figure("springs_road_evals_per_pos", evals);
        cli_bench_say("  %-10s %13.0f %12.0f %8s\n", road_cases[i].model, rate[i],
                      road_cases[i].target, rate[i] >= road_cases[i].target ? "met" : "missed");
    }
    /* road_cases[0] is rigid, [2] springs. */
    if (!status && rate[2] > 0) {
        cli_bench_figure("springs_over_rigid_road", rate[0] / rate[2]);
        cli_bench_say("  springs / rigid time over the road: %.1f x\n", rate[0] / rate[2]);
    }
    if (!status)
        status = cli_bench_jobs(tire, road, road_l_c, 0, road_dx, n, repeat, &diag);
    if (!status)
        status = bench_fine_road(tire, repeat, &diag);
    double t_train = 0;
    tirenv_diag why;
    tirenv_diag_clear(&why);
    tirenv_nn *nn = status ? NULL : road_network(tire, &t_train, &why);
    if (!status)
        status = bench_road_nn(tire, road, n, x, repeat, nn, t_train, &why, &diag);
    if (!status && nn)
        bench_nn_batch(nn, repeat);
    if (!status)
        status = cli_bench_set_load(tire, road, nn, road_l_c, n, x, repeat, &diag);
    if (!status)
        status = cli_bench_ride(tire, road, nn, n, x, repeat < 3 ? repeat : 3, &diag);
    if (!status)
        status = cli_bench_memory_fresh(tire_path, memory_length < 10000, &diag);
    tirenv_nn_free(nn);
    free(pt);
    free(x);
    tirenv_profile_free(road);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

int cli_bench_main(int argc, char *argv[])
{
    long repeat = 0; /* 0: not given */
    int quick = 0, json = 0, memory = 0;
    const cli_opt own[] = {
        {.name = "repeat", .kind = CLI_COUNT, .dst = &repeat, .min = 1, .max = 1000000,
         .what = "a whole number from 1 to 1000000"},
        {.name = "quick", .kind = CLI_FLAG, .dst = &quick},
        {.name = "memory", .kind = CLI_FLAG, .dst = &memory},
        {.name = "json", .kind = CLI_FLAG, .dst = &json},
        {.name = NULL},
    };
    const cli_parser p = {.name = "bench", .usage = usage, .opts = own, .groups = CLI_TIRE};
    cli_options o;
    int code = cli_parse(&p, argc, argv, &o);
    if (code != CLI_GO_ON)
        return code;
    if (quick) {
        road_length = memory_length = 100.0;
        sweep_min_s = round_min_s = 0;
    }
    if (repeat == 0)
        repeat = quick ? 1 : 5;
    tirenv_tire tire;
    char buf[1024];
    const char *path = cli_tire_path(&o, buf, sizeof buf);
    code = cli_refuse_pipe(path, "bench runs itself in child processes that read it again");
    if (!code)
        code = cli_tire(&o, &tire);
    /* Every part runs the cam (the road, the load changes, the ride, the memory's envelope):
     * a tire without its shape keys is refused before any timing, not midway. */
    if (!code)
        code = cli_cam_keys(tirenv_model_cam, &tire, path);
    if (code)
        return code;
    tirenv_profile *prof = tirenv_profile_cleat(cleat_L, cleat_H);
    as_json = json;
    figures = json_object();
    if (!prof || !figures) {
        tirenv_profile_free(prof);
        json_decref(figures);
        figures = NULL;
        return cli_fail(TIRENV_ENOMEM, NULL);
    }
    double x[SWEEP_N];
    for (size_t k = 0; k < SWEEP_N; ++k)
        x[k] = sweep_from + (double)k * sweep_dx;

    bench_result r[N_CASES];
    memset(r, 0, sizeof r);
    for (size_t i = 0; i < N_CASES && !code && !memory; ++i)
        code = run_case(&tire, i, prof, x, repeat, &r[i]);
    if (!code && memory) {  /* the last part alone */
        cli_bench_figure("quick", quick);
        tirenv_diag diag;
        tirenv_diag_clear(&diag);
        const int status = cli_bench_memory(cli_tire_path(&o, buf, sizeof buf), &tire,
                                            memory_length, &diag);
        code = status ? cli_fail(status, &diag) : CLI_EXIT_OK;
    } else if (!code) {
        cli_bench_figure("repeat", (double)repeat);
        cli_bench_figure("quick", quick);
        cli_bench_figure("cleat_positions", SWEEP_N);
        cli_bench_say("tirenv bench: tire %s, contact length %.2f m (load %.6g N), cleat %.2f x "
                      "%.2f m,\n%d positions x = %.3f .. %.3f m at %g mm, best of %ld runs per "
                      "method%s\n",
                      cli_tire_path(&o, buf, sizeof buf), bench_l_c, r[1].load, cleat_L,
                      cleat_H, SWEEP_N, x[0], x[SWEEP_N - 1], sweep_dx * 1e3, repeat,
                      quick ? " (--quick: rough figures)" : "");
        print_machine();
        print_table(repeat, r);
        if (r[0].failed < SWEEP_N && r[1].failed < SWEEP_N && r[4].failed < SWEEP_N)
            code = cleat_rounds(&tire, prof, x, repeat, r);
        if (!code)
            code = bench_import(&tire, prof, repeat);
        if (!code)
            code = cli_bench_fmt(repeat);
    }
    tirenv_profile_free(prof);
    if (!code && !memory)
        code = bench_road(cli_tire_path(&o, buf, sizeof buf), &tire, repeat);
    if (!code && as_json) {
        char *text = json_dumps(figures, JSON_INDENT(2)); /* 17 digits: reads back the same */
        if (!text)
            code = cli_fail(TIRENV_ENOMEM, NULL);
        else
            printf("%s\n", text);
        free(text);
    }
    json_decref(figures);
    figures = NULL;
    return code;
}
