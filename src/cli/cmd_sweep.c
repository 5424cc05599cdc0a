/* tirenv sweep: a data set over a grid of cleats x regimes x tire-key values, resumable,
 * in shards for a cluster, and the merge of the shards (tirenv/sweep.h).
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "tirenv/sweep.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv sweep --lengths L1,L2,... --heights H1,H2,...\n"
          "                    (--contact-lengths C1,C2,... | --loads G1,G2,...) -o DIR\n"
          "                    [--model NAME] [--rig] [--set KEY=V1,V2,...]...\n"
          "                    [--split NAME | --control-fraction F --validation-fraction F\n"
          "                    [--split-seed S]] [--seed S] [--shard K/N] [--jobs N]\n"
          "                    [--progress] [--tire FILE] [--method NAME]\n"
          "       tirenv sweep merge PART... -o DIR\n"
          "\n"
          "Writes a data set (cases.csv, curves/, with --rig logs/; what tirenv train,\n"
          "study, compare and fit read with --data) over a grid: every rectangular cleat\n"
          "of --lengths x --heights, at every regime of --contact-lengths (or --loads), for\n"
          "every combination of the --set values. Each case is the model's enveloping\n"
          "curve on the x_N grid of the data sets, or with --rig the model driving the\n"
          "virtual rig, its noisy log imported as dataset build does. The data are\n"
          "SIMULATED. Cases are named c0000, c0001, ... in grid order (heights fastest,\n"
          "then lengths, regimes, --set values); sweep.txt records the grid, tire.tir the\n"
          "tire and sweep.csv each case's --set values.\n"
          "\n"
          "The run writes into DIR.partial and renames it to DIR when every case is there:\n"
          "killed, it is resumed by the same command, which keeps the cases written and\n"
          "runs the others. --shard K/N writes the cases i with i mod N = K only (a part\n"
          "for one node of a cluster; see scripts/slurm/); 'tirenv sweep merge' then\n"
          "joins the N parts into DIR, byte for byte what one run of the whole grid\n"
          "writes. The bytes never depend on --jobs or on interruptions.\n"
          "\n"
          "options:\n"
          "  --lengths L,...      cleat lengths, m\n"
          "  --heights H,...      cleat heights, m\n"
          "  --contact-lengths C,...  regimes as flat-ground contact lengths of the\n"
          "                       model, m (the load is the model's at each)\n"
          "  --loads G,...        regimes as loads, N (the contact length is the model's)\n"
          "  -o DIR               the data set (a part, with --shard) to write\n",
          fp);
    cli_help_model(fp, " (default ring, the reference tire)");
    fputs("  --rig                through the virtual rig (noise, import); default: the\n"
          "                       model's curve itself\n"
          "  --set KEY=V1,V2,...  sweep a numeric tire key over these values (repeatable,\n"
          "                       one key each; a single value sets it for every case)\n"
          "  --split NAME         every case's split: train (default), control, validation\n"
          "  --control-fraction F, --validation-fraction F\n"
          "                       instead: round(F x cases) cases each, drawn by a seeded\n"
          "                       permutation of the whole grid, the rest train\n"
          "  --split-seed S       the permutation's seed (default 1)\n"
          "  --seed S             rig noise: case i runs with seed S + i (default 1)\n"
          "  --shard K/N          write part K (0 <= K < N) of N\n",
          fp);
    cli_help_jobs(fp);
    fputs("  --progress           a progress bar on standard error even when it is not a\n"
          "                       terminal (on a terminal it is always drawn)\n"
          "  --tire FILE          the tire (default: the default tire)\n"
          "  --method NAME        equilibrium solver: newton (default), secant or brent\n"
          "  -h, --help           show this help\n"
          "\n"
          "merge:\n"
          "  PART...              the N complete parts of one sweep, in any order\n"
          "  -o DIR               the merged data set\n",
          fp);
}

enum { MAX_VALUES = 100000 };

/* "a,b,c" into an allocated array; prints why and returns CLI_EXIT_USAGE if malformed. */
static int parse_list(const char *opt, const char *arg, double **out, size_t *n)
{
    size_t count = 1;
    for (const char *p = arg; *p; ++p)
        count += *p == ',';
    if (*n) {
        cli_error("sweep: %s given twice; give all its values in one list", opt);
        return CLI_EXIT_USAGE;
    }
    if (count > MAX_VALUES) {
        cli_error("sweep: %s: %zu values; at most %d", opt, count, MAX_VALUES);
        return CLI_EXIT_USAGE;
    }
    double *v = malloc(count * sizeof *v);
    char *copy = strdup(arg);
    if (!v || !copy) {
        free(v);
        free(copy);
        return cli_fail(TIRENV_ENOMEM, NULL);
    }
    size_t k = 0;
    char *save = NULL;
    for (char *tok = copy; k <= count; tok = NULL) {
        char *t = strtok_r(tok, ",", &save);
        if (!t)
            break;
        if (cli_parse_double(t, &v[k])) {
            cli_error("sweep: %s: expected comma-separated numbers, got '%s'", opt, t);
            free(v);
            free(copy);
            return CLI_EXIT_USAGE;
        }
        ++k;
    }
    free(copy);
    if (k != count) {
        cli_error("sweep: %s: expected comma-separated numbers, got '%s'", opt, arg);
        free(v);
        return CLI_EXIT_USAGE;
    }
    *out = v;
    *n = k;
    return CLI_EXIT_OK;
}

/* --shard K/N */
static int parse_shard(const char *arg, size_t *k, size_t *n)
{
    const char *slash = strchr(arg, '/');
    long kk, nn;
    char left[32];
    if (slash && (size_t)(slash - arg) < sizeof left) {
        memcpy(left, arg, (size_t)(slash - arg));
        left[slash - arg] = '\0';
        if (!cli_parse_count(left, 0, 1000000, &kk) && !cli_parse_count(slash + 1, 1, 1000000, &nn) &&
            kk < nn) {
            *k = (size_t)kk;
            *n = (size_t)nn;
            return CLI_EXIT_OK;
        }
    }
    cli_error("sweep: --shard expects K/N with 0 <= K < N (e.g. 0/4), got '%s'", arg);
    return CLI_EXIT_USAGE;
}

/* The progress bar: redrawn in place on a terminal; elsewhere (a batch job's log) a line at
 * every tenth of the way. */
typedef struct {
    int on, tty;
    double t0;
    size_t first;          /* cases already there when the run started */
    size_t last_tenth;
} progress_state;

static void progress(void *ctx, size_t done, size_t total)
{
    progress_state *p = ctx;
    if (!p->on)
        return;
    const double t = cli_wall_seconds() - p->t0;
    if (p->first == (size_t)-1)
        p->first = done;
    const size_t run = done - p->first, left = total - done;
    char eta[48] = "";
    if (run > 0 && left > 0)
        snprintf(eta, sizeof eta, ", about %.0f s left", t / (double)run * (double)left);
    const double frac = total ? (double)done / (double)total : 1;
    if (p->tty) {
        char bar[31];
        const int fill = (int)(frac * 30);
        for (int k = 0; k < 30; ++k)
            bar[k] = k < fill ? '#' : '.';
        bar[30] = '\0';
        fprintf(stderr, "\r\033[Ktirenv: sweep: [%s] %zu/%zu cases, %.0f s%s", bar, done,
                total, t, eta);
        if (done == total)
            fputc('\n', stderr);
    } else {
        const size_t tenth = total ? done * 10 / total : 10;
        if (tenth == p->last_tenth && done != p->first)
            return;
        p->last_tenth = tenth;
        fprintf(stderr, "tirenv: sweep: %zu/%zu cases (%.0f %%), %.0f s%s\n", done, total,
                100 * frac, t, eta);
    }
    fflush(stderr);
}

static int merge_main(int argc, char *argv[])
{
    static const struct option longopts[] = {
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    const char *out = NULL;
    int c;
    cli_getopt_reset();
    while ((c = getopt_long(argc, argv, "ho:", longopts, NULL)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            return CLI_EXIT_OK;
        case 'o':
            out = optarg;
            break;
        default:
            usage(stderr);
            return CLI_EXIT_USAGE;
        }
    }
    if (!out || optind >= argc) {
        cli_error("sweep merge: expected the parts and -o DIR");
        usage(stderr);
        return CLI_EXIT_USAGE;
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const double t0 = cli_wall_seconds();
    const int status =
        tirenv_sweep_merge(out, (size_t)(argc - optind), (const char *const *)argv + optind,
                           &diag);
    if (status)
        return cli_fail(status, &diag);
    fprintf(stderr, "tirenv: sweep: %d parts merged into %s (%.1f s)\n", argc - optind, out,
            cli_wall_seconds() - t0);
    return CLI_EXIT_OK;
}

typedef struct {
    double *lists[4];      /* lengths, heights, contact lengths, loads */
    size_t counts[4];
    double *values[TIRENV_SWEEP_MAX_KEYS];
    char *keys[TIRENV_SWEEP_MAX_KEYS];
} sweep_lists;

static void lists_free(sweep_lists *l)
{
    for (size_t k = 0; k < 4; ++k)
        free(l->lists[k]);
    for (size_t k = 0; k < TIRENV_SWEEP_MAX_KEYS; ++k) {
        free(l->values[k]);
        free(l->keys[k]);
    }
}

/* --set KEY=V1,V2,... */
static int parse_axis(const char *arg, tirenv_sweep_settings *s, sweep_lists *l)
{
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg) {
        cli_error("sweep: --set expects KEY=V1,V2,..., got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    if (s->n_keys == TIRENV_SWEEP_MAX_KEYS) {
        cli_error("sweep: at most %d --set keys", TIRENV_SWEEP_MAX_KEYS);
        return CLI_EXIT_USAGE;
    }
    const size_t k = s->n_keys;
    l->keys[k] = strndup(arg, (size_t)(eq - arg));
    if (!l->keys[k])
        return cli_fail(TIRENV_ENOMEM, NULL);
    size_t n = 0;
    char opt[200];
    snprintf(opt, sizeof opt, "--set %s", l->keys[k]);
    const int code = parse_list(opt, eq + 1, &l->values[k], &n);
    if (code)
        return code;
    s->keys[k] = (tirenv_sweep_axis){l->keys[k], n, l->values[k]};
    s->n_keys = k + 1;
    return CLI_EXIT_OK;
}

int cli_sweep_main(int argc, char *argv[])
{
    if (argc > 1 && strcmp(argv[1], "merge") == 0)
        return merge_main(argc - 1, argv + 1);
    enum { OPT_LENGTHS = CLI_OPT_FIRST_OWN, OPT_HEIGHTS, OPT_CONTACT_LENGTHS, OPT_LOADS,
           OPT_MODEL, OPT_RIG, OPT_SWEEP_SET, OPT_SPLIT, OPT_CONTROL, OPT_VALIDATION,
           OPT_SPLIT_SEED, OPT_SEED, OPT_SHARD, OPT_PROGRESS };
    static const struct option longopts[] = {
        {"tire", required_argument, NULL, CLI_OPT_TIRE},
        CLI_METHOD_LONGOPTS,
        CLI_JOBS_LONGOPT,
        {"lengths", required_argument, NULL, OPT_LENGTHS},
        {"heights", required_argument, NULL, OPT_HEIGHTS},
        {"contact-lengths", required_argument, NULL, OPT_CONTACT_LENGTHS},
        {"loads", required_argument, NULL, OPT_LOADS},
        {"model", required_argument, NULL, OPT_MODEL},
        {"rig", no_argument, NULL, OPT_RIG},
        {"set", required_argument, NULL, OPT_SWEEP_SET},
        {"split", required_argument, NULL, OPT_SPLIT},
        {"control-fraction", required_argument, NULL, OPT_CONTROL},
        {"validation-fraction", required_argument, NULL, OPT_VALIDATION},
        {"split-seed", required_argument, NULL, OPT_SPLIT_SEED},
        {"seed", required_argument, NULL, OPT_SEED},
        {"shard", required_argument, NULL, OPT_SHARD},
        {"progress", no_argument, NULL, OPT_PROGRESS},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0},
    };
    cli_options o;
    cli_options_init(&o);
    tirenv_sweep_settings s = tirenv_sweep_default();
    s.jobs = cli_jobs_default();
    sweep_lists l;
    memset(&l, 0, sizeof l);
    const char *out = NULL, *split = NULL;
    int have_fraction = 0, want_progress = 0, c, code = CLI_EXIT_OK;
    long count;
    cli_getopt_reset();
    while (!code && (c = getopt_long(argc, argv, "ho:", longopts, NULL)) != -1) {
        switch (c) {
        case 'h':
            usage(stdout);
            lists_free(&l);
            return CLI_EXIT_OK;
        case 'o':
            out = optarg;
            break;
        case OPT_LENGTHS:
        case OPT_HEIGHTS:
        case OPT_CONTACT_LENGTHS:
        case OPT_LOADS: {
            static const char *const names[] = {"--lengths", "--heights", "--contact-lengths",
                                                "--loads"};
            const size_t k = (size_t)(c - OPT_LENGTHS);
            code = parse_list(names[k], optarg, &l.lists[k], &l.counts[k]);
            break;
        }
        case OPT_MODEL:
            code = cli_model_type(optarg, &s.type);
            break;
        case OPT_RIG:
            s.rig = 1;
            break;
        case OPT_SWEEP_SET:
            code = parse_axis(optarg, &s, &l);
            break;
        case OPT_SPLIT:
            split = optarg;
            break;
        case OPT_CONTROL:
        case OPT_VALIDATION: {
            double f;
            if (cli_parse_double(optarg, &f) || !(f >= 0 && f <= 1)) {
                cli_error("sweep: --%s-fraction expects a number in [0, 1], got '%s'",
                          c == OPT_CONTROL ? "control" : "validation", optarg);
                code = CLI_EXIT_USAGE;
            }
            *(c == OPT_CONTROL ? &s.control_fraction : &s.validation_fraction) = f;
            have_fraction = 1;
            break;
        }
        case OPT_SPLIT_SEED:
        case OPT_SEED:
            if (cli_parse_count(optarg, 0, 2147483647L, &count)) {
                cli_error("sweep: --%s expects a whole number >= 0, got '%s'",
                          c == OPT_SEED ? "seed" : "split-seed", optarg);
                code = CLI_EXIT_USAGE;
            }
            *(c == OPT_SEED ? &s.seed : &s.split_seed) = (unsigned long)count;
            break;
        case OPT_SHARD:
            code = parse_shard(optarg, &s.shard, &s.shards);
            break;
        case OPT_PROGRESS:
            want_progress = 1;
            break;
        case CLI_OPT_JOBS:
            code = cli_parse_jobs("sweep", optarg, &s.jobs);
            break;
        case '?':
            usage(stderr);
            code = CLI_EXIT_USAGE;
            break;
        default:
            code = cli_option(&o, c, optarg) ? CLI_EXIT_USAGE : CLI_EXIT_OK;
        }
    }
    if (!code && optind < argc) {
        cli_error("sweep: unexpected argument '%s'", argv[optind]);
        code = CLI_EXIT_USAGE;
    }
    if (!code && !out) {
        cli_error("sweep: -o DIR is required");
        code = CLI_EXIT_USAGE;
    }
    if (!code && (!l.counts[0] || !l.counts[1] || !l.counts[2] == !l.counts[3])) {
        cli_error("sweep: expected --lengths, --heights and one of --contact-lengths and "
                  "--loads");
        code = CLI_EXIT_USAGE;
    }
    if (!code && split && have_fraction) {
        cli_error("sweep: --split gives every case one split; the fractions draw them: give "
                  "one or the other");
        code = CLI_EXIT_USAGE;
    }
    if (!code && split) {
        size_t k = 0;
        while (k < 3 && strcmp(split, tirenv_split_name((tirenv_split)k)) != 0)
            ++k;
        if (k == 3) {
            cli_error("sweep: --split expects train, control or validation, got '%s'", split);
            code = CLI_EXIT_USAGE;
        }
        s.split = (tirenv_split)k;
    }
    tirenv_tire tire;
    if (!code)
        code = cli_tire(&o, &tire);
    if (code) {
        lists_free(&l);
        return code;
    }
    s.lengths = l.lists[0];
    s.n_lengths = l.counts[0];
    s.heights = l.lists[1];
    s.n_heights = l.counts[1];
    s.contact_lengths = l.lists[2];
    s.n_contact_lengths = l.counts[2];
    s.loads = l.lists[3];
    s.n_loads = l.counts[3];
    progress_state ps = {.on = want_progress || isatty(STDERR_FILENO),
                         .tty = isatty(STDERR_FILENO), .t0 = cli_wall_seconds(),
                         .first = (size_t)-1, .last_tenth = (size_t)-1};
    s.progress = progress;
    s.progress_ctx = &ps;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_sweep_report rep;
    const int status = tirenv_sweep_run(out, &tire, &s, &rep, &diag);
    lists_free(&l);
    if (status) {
        if (ps.tty && ps.first != (size_t)-1)
            fputc('\n', stderr);
        return cli_fail(status, &diag);
    }
    char part[64] = "";
    if (s.shards > 1)
        snprintf(part, sizeof part, " (shard %zu/%zu: %zu cases)", s.shard, s.shards,
                 rep.part_cases);
    if (rep.already_complete)
        fprintf(stderr, "tirenv: sweep: %s already holds this sweep%s, complete; nothing to "
                "do\n", out, part);
    else
        fprintf(stderr, "tirenv: sweep: %zu-case grid%s written to %s: %zu cases run, %zu "
                "kept from an interrupted run (%.1f s)\n", rep.cases, part, out, rep.run,
                rep.resumed, cli_wall_seconds() - ps.t0);
    return CLI_EXIT_OK;
}
