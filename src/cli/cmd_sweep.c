/* tirenv sweep: a data set over a grid of cleats x regimes x tire-key values, resumable,
 * in shards for a cluster, and the merge of the shards (tirenv/sweep.h).
 * SPDX-License-Identifier: Apache-2.0 */
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "tirenv/nn_file.h"
#include "tirenv/sweep.h"

static void usage(FILE *fp)
{
    fputs("usage: tirenv sweep --lengths L1,L2,... --heights H1,H2,...\n"
          "                    (--contact-lengths C1,C2,... | --loads G1,G2,...) -o DIR\n"
          "                    [--model NAME] [--rig] [--set KEY=V1,V2,...]...\n"
          "                    [--split NAME | --control-fraction F --validation-fraction F\n"
          "                    [--split-seed S]] [--seed S] [--shard K/N] [--jobs N]\n"
          "                    [--progress] [--tire FILE] [--method NAME]\n"
          "                    [--nn FILE [--extrapolate]]\n"
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
          "  -o, --output DIR     the data set (a part, with --shard) to write\n",
          fp);
    cli_help_model(fp, 0, 0, " (default ring, the reference tire); nn needs\n"
                   "                       --nn FILE");
    fputs("  --rig                through the virtual rig (noise, import); default: the\n"
          "                       model's curve itself\n"
          "  --set KEY=V1,V2,...  sweep a numeric tire key over these values (repeatable,\n"
          "                       one key each; a single value sets it for every case)\n"
          "  --split NAME         every case's split: train (default), control, validation\n"
          "  --control-fraction F, --validation-fraction F\n"
          "                       instead: round(F x cases) cases each, drawn by a seeded\n"
          "                       permutation of the whole grid, the rest train\n"
          "  --split-seed S       the permutation's seed (default 1; with the fractions)\n"
          "  --seed S             rig noise: case i runs with seed S + i (default 1; with\n"
          "                       --rig)\n"
          "  --shard K/N          write part K (0 <= K < N) of N\n"
          "  --nn FILE            the trained network, for --model nn\n"
          "  --extrapolate        with --nn: evaluate the network outside the ranges it was\n"
          "                       trained on (with a warning) instead of refusing the input\n",
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
          "  -o, --output DIR     the merged data set\n",
          fp);
}

enum { MAX_VALUES = 100000 };

/* A list option's destination. */
typedef struct {
    const char *opt;       /* its name, for messages */
    double *v;
    size_t n;
} value_list;

/* "a,b,c" into an allocated array; prints why and returns CLI_EXIT_USAGE if malformed. */
static int parse_values(const char *opt, const char *arg, double **out, size_t *n)
{
    size_t count = 1;
    for (const char *p = arg; *p; ++p)
        count += *p == ',';
    if (count > MAX_VALUES) {
        cli_error("sweep: %s: %zu values; at most %d", opt, count, MAX_VALUES);
        return CLI_EXIT_USAGE;
    }
    double *v = malloc(count * sizeof *v);
    if (!v)
        return cli_fail(TIRENV_ENOMEM, NULL);
    const char *p = arg;
    for (size_t k = 0; k < count; ++k) {
        const size_t len = strcspn(p, ",");
        char field[64];
        if (len == 0 || len >= sizeof field) {
            cli_error("sweep: %s: expected comma-separated numbers, got '%s'", opt, arg);
            free(v);
            return CLI_EXIT_USAGE;
        }
        memcpy(field, p, len);
        field[len] = '\0';
        if (cli_parse_double(field, &v[k])) {
            cli_error("sweep: %s: expected comma-separated numbers, got '%s'", opt, field);
            free(v);
            return CLI_EXIT_USAGE;
        }
        p += len + (p[len] == ',');
    }
    *out = v;
    *n = count;
    return CLI_EXIT_OK;
}

static int parse_list(void *dst, const char *arg)
{
    value_list *l = dst;
    return parse_values(l->opt, arg, &l->v, &l->n);
}

/* --shard K/N */
static int parse_shard(void *dst, const char *arg)
{
    size_t *kn = dst;
    const char *slash = strchr(arg, '/');
    long k, n;
    char left[32];
    if (slash && (size_t)(slash - arg) < sizeof left) {
        memcpy(left, arg, (size_t)(slash - arg));
        left[slash - arg] = '\0';
        if (!cli_parse_count(left, 0, 1000000, &k) &&
            !cli_parse_count(slash + 1, 1, 1000000, &n) && k < n) {
            kn[0] = (size_t)k;
            kn[1] = (size_t)n;
            return CLI_EXIT_OK;
        }
    }
    cli_error("sweep: --shard: expected K/N with 0 <= K < N (e.g. 0/4), got '%s'", arg);
    return CLI_EXIT_USAGE;
}

/* The swept tire keys: --set KEY=V1,V2,... (repeatable). */
typedef struct {
    size_t n;
    char *keys[TIRENV_SWEEP_MAX_KEYS];
    double *values[TIRENV_SWEEP_MAX_KEYS];
    size_t counts[TIRENV_SWEEP_MAX_KEYS];
} sweep_keys;

static int parse_axis(void *dst, const char *arg)
{
    sweep_keys *k = dst;
    const char *eq = strchr(arg, '=');
    if (!eq || eq == arg) {
        cli_error("sweep: --set: expected KEY=V1,V2,..., got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    if (k->n == TIRENV_SWEEP_MAX_KEYS) {
        cli_error("sweep: --set: at most %d keys", TIRENV_SWEEP_MAX_KEYS);
        return CLI_EXIT_USAGE;
    }
    if (!(k->keys[k->n] = strndup(arg, (size_t)(eq - arg))))
        return cli_fail(TIRENV_ENOMEM, NULL);
    char opt[200];
    snprintf(opt, sizeof opt, "--set %s", k->keys[k->n]);
    const int code = parse_values(opt, eq + 1, &k->values[k->n], &k->counts[k->n]);
    if (code)
        return code;
    ++k->n;
    return CLI_EXIT_OK;
}

/* tirenv_tir_set of key=value, the value in full (%.17g). */
static int set_key(tirenv_tire *t, const char *key, double value, tirenv_diag *d)
{
    char assignment[200];
    snprintf(assignment, sizeof assignment, "%.120s=%.17g", key, value);
    return tirenv_tir_set(t, assignment, d);
}

/* The model's curve over the grid's first cleat at its first regime, at 21 positions from R0
 * before the cleat to R0 after it, for the tire with key set to value; 0 if it could not be
 * computed (the sweep itself then says why). */
static int probe_curve(const tirenv_sweep_settings *s, const tirenv_tire *tire, const char *key,
                       double value, tirenv_point out[21])
{
    tirenv_tire t = *tire;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    if (set_key(&t, key, value, &d) || tirenv_tire_check(&t, &d))
        return 0;
    tirenv_model *m = tirenv_model_alloc(s->type, &t);
    tirenv_profile *cleat = tirenv_profile_cleat(s->lengths[0], s->heights[0]);
    double load = s->n_loads ? s->loads[0] : 0;
    int ok = m && cleat &&
             (s->n_loads ||
              !tirenv_model_load_for_contact_length(m, s->contact_lengths[0], &load, &d)) &&
             !tirenv_model_set(m, cleat, load, &d);
    const double R0 = t.springs.R0, half = 0.5 * s->lengths[0] + R0;
    for (size_t i = 0; i < 21 && ok; ++i)
        ok = !tirenv_model_eval(m, -half + (double)i * half / 10, &out[i], &d);
    tirenv_profile_free(cleat);
    tirenv_model_free(m);
    return ok;
}

/* A swept key the model does not read (the springs model's RADIAL_STIFFNESS swept for the
 * ring, as the README's example once did) gives every value the same cases: said when the
 * model's curve over the first cleat is the same, bit for bit, at the key's first two values.
 * A warning, not a refusal: a key may matter only on other cleats or regimes. */
static void warn_unread_keys(const tirenv_sweep_settings *s, const tirenv_tire *tire)
{
    if (tirenv_model_type_flags(s->type) & TIRENV_MODEL_NEEDS_NETWORK)
        return;
    for (size_t k = 0; k < s->n_keys; ++k) {
        tirenv_point a[21], b[21];
        if (s->keys[k].n >= 2 &&
            probe_curve(s, tire, s->keys[k].key, s->keys[k].values[0], a) &&
            probe_curve(s, tire, s->keys[k].key, s->keys[k].values[1], b) &&
            memcmp(a, b, sizeof a) == 0)
            fprintf(stderr, "tirenv: sweep: warning: --set %s: the %s model's curve over the "
                    "first cleat is the same, bit for bit, at %s = %g and %g: the model may "
                    "not read %s, and then every value gives the same cases\n",
                    s->keys[k].key, tirenv_model_type_name(s->type), s->keys[k].key,
                    s->keys[k].values[0], s->keys[k].values[1], s->keys[k].key);
    }
}

/* FNV-1a (64 bit) of a file's bytes: how sweep.txt names the network a sweep evaluated. */
static int file_fingerprint(const char *path, char out[32])
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return -1;
    uint64_t h = UINT64_C(0xcbf29ce484222325);
    int c;
    while ((c = getc(fp)) != EOF) {
        h ^= (uint64_t)(unsigned char)c;
        h *= UINT64_C(0x100000001b3);
    }
    const int failed = ferror(fp);
    fclose(fp);
    snprintf(out, 32, "fnv1a64:%016" PRIx64, h);
    return failed ? -1 : 0;
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

/* "tirenv sweep merge PART... -o DIR": parts are as many as the shards, more than the
 * shared parser's positional arguments, so this small form is parsed here. */
static int merge_main(int argc, char *argv[])
{
    const char *out = NULL;
    const char **parts = calloc((size_t)argc, sizeof *parts);
    size_t n = 0;
    if (!parts)
        return cli_fail(TIRENV_ENOMEM, NULL);
    int code = CLI_EXIT_OK;
    for (int i = 1; i < argc && !code; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            usage(stdout);
            free(parts);
            return CLI_EXIT_OK;
        }
        if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0 ||
            strncmp(a, "--output=", 9) == 0 || (a[0] == '-' && a[1] == 'o' && a[2])) {
            const char *v = a[1] == 'o' && a[2] ? a + 2 : strchr(a, '=') ? strchr(a, '=') + 1
                                                                        : argv[++i];
            if (!v || !*v) {
                cli_error("sweep merge: -o needs a directory, got %s",
                          v ? "an empty path" : "none");
                code = CLI_EXIT_USAGE;
            } else if (out) {
                cli_error("sweep merge: -o given twice; give it once");
                code = CLI_EXIT_USAGE;
            }
            out = v;
        } else if (a[0] == '-' && a[1]) {
            cli_error("sweep merge: unknown option '%s'", a);
            usage(stderr);
            code = CLI_EXIT_USAGE;
        } else {
            parts[n++] = a;
        }
    }
    if (!code && (!out || n == 0)) {
        cli_error("sweep merge: expected the parts and -o DIR");
        usage(stderr);
        code = CLI_EXIT_USAGE;
    }
    /* -o naming a part would merge it into itself: said so, not as "another sweep". */
    for (size_t k = 0; !code && k < n; ++k)
        if (cli_same_dir(out, parts[k])) {
            cli_error("sweep merge: -o %s is the part %s: the merge would replace it; "
                      "expected another directory", out, parts[k]);
            code = CLI_EXIT_USAGE;
        }
    if (code) {
        free(parts);
        return code;
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const double t0 = cli_wall_seconds();
    const int status = tirenv_sweep_merge(out, n, parts, &diag);
    free(parts);
    if (status)
        return cli_fail(status, &diag);
    fprintf(stderr, "tirenv: sweep: %zu parts merged into %s (%.1f s)\n", n, out,
            cli_wall_seconds() - t0);
    return CLI_EXIT_OK;
}

/* The command's own options, as given. */
typedef struct {
    value_list lists[4];   /* --lengths, --heights, --contact-lengths, --loads */
    sweep_keys keys;       /* --set KEY=V1,V2,... */
    const char *split, *tire_path;
    double control, validation;  /* the fractions; NaN if not given */
    long seed, split_seed;  /* -1: not given (the sweep takes 1) */
    size_t shard[2];       /* K, N */
    int rig, want_progress;
} sweep_args;

/* A model that evaluates a network gets it with the radius its x_N refers to; sweep.txt names
 * the model file by its bytes (id). */
typedef struct {
    tirenv_nn *nn;
    tirenv_train_record rec;
    char id[32];
} sweep_network;

/* What cli_sweep_main allocates for the sweep: the value lists, the keys' axes, the network. */
static void free_axes(sweep_args *a, sweep_network *net)
{
    for (size_t k = 0; k < 4; ++k)
        free(a->lists[k].v);
    for (size_t k = 0; k < a->keys.n; ++k) {
        free(a->keys.keys[k]);
        free(a->keys.values[k]);
    }
    tirenv_nn_free(net->nn);
}

static int parse_args(int argc, char *argv[], sweep_args *a, cli_options *o)
{
    const cli_opt own[] = {
        {.name = "lengths", .kind = CLI_CUSTOM, .dst = &a->lists[0], .parse = parse_list},
        {.name = "heights", .kind = CLI_CUSTOM, .dst = &a->lists[1], .parse = parse_list},
        {.name = "contact-lengths", .kind = CLI_CUSTOM, .dst = &a->lists[2],
         .parse = parse_list},
        {.name = "loads", .kind = CLI_CUSTOM, .dst = &a->lists[3], .parse = parse_list},
        {.name = "set", .kind = CLI_CUSTOM, .dst = &a->keys, .parse = parse_axis,
         .repeatable = 1},
        {.name = "tire", .kind = CLI_STRING, .dst = &a->tire_path},
        {.name = "rig", .kind = CLI_FLAG, .dst = &a->rig},
        {.name = "split", .kind = CLI_STRING, .dst = &a->split},
        {.name = "control-fraction", .kind = CLI_NUMBER, .dst = &a->control},
        {.name = "validation-fraction", .kind = CLI_NUMBER, .dst = &a->validation},
        {.name = "split-seed", .kind = CLI_COUNT, .dst = &a->split_seed, .min = 0,
         .max = 2147483647L},
        {.name = "seed", .kind = CLI_COUNT, .dst = &a->seed, .min = 0, .max = 2147483647L},
        {.name = "shard", .kind = CLI_CUSTOM, .dst = a->shard, .parse = parse_shard},
        {.name = "progress", .kind = CLI_FLAG, .dst = &a->want_progress},
        {.name = NULL},
    };
    const cli_parser p = {.name = "sweep", .usage = usage, .opts = own,
                          .groups = CLI_METHOD | CLI_OUTPUT | CLI_MODEL | CLI_NETWORK |
                                    CLI_EXTRAPOLATE | CLI_JOBS};
    return cli_parse(&p, argc, argv, o);
}

/* The options that go together: -o, the grid's lists, one way to split; --split's name into
 * s->split. */
static int check_args(const sweep_args *a, const cli_options *o, tirenv_sweep_settings *s)
{
    const value_list *l = a->lists;
    if (!o->output) {
        cli_error("sweep: -o DIR is required");
        return CLI_EXIT_USAGE;
    }
    if (!l[0].n || !l[1].n || !l[2].n == !l[3].n) {
        cli_error("sweep: expected --lengths, --heights and one of --contact-lengths and "
                  "--loads");
        return CLI_EXIT_USAGE;
    }
    const int fractions = !isnan(a->control) || !isnan(a->validation);
    if (a->split && fractions) {
        cli_error("sweep: --split gives every case one split; the fractions draw them: give "
                  "one or the other");
        return CLI_EXIT_USAGE;
    }
    if (fractions && !((isnan(a->control) || (a->control >= 0 && a->control <= 1)) &&
                       (isnan(a->validation) || (a->validation >= 0 && a->validation <= 1)))) {
        cli_error("sweep: --control-fraction and --validation-fraction: expected numbers in "
                  "[0, 1]");
        return CLI_EXIT_USAGE;
    }
    /* A seed of something the sweep does not draw would change nothing: refused, as envelope
     * refuses its options that change nothing (both were taken and ignored, exit 0). */
    if (a->split_seed >= 0 && !fractions) {
        cli_error("sweep: --split-seed seeds the permutation of --control-fraction and "
                  "--validation-fraction; give one of them, or leave the seed out");
        return CLI_EXIT_USAGE;
    }
    if (a->seed >= 0 && !a->rig) {
        cli_error("sweep: --seed seeds the virtual rig's noise; give --rig, or leave the seed "
                  "out");
        return CLI_EXIT_USAGE;
    }
    if (a->split) {
        size_t k = 0;
        while (k < 3 && strcmp(a->split, tirenv_split_name((tirenv_split)k)) != 0)
            ++k;
        if (k == 3) {
            cli_error("sweep: --split: expected train, control or validation, got '%s'",
                      a->split);
            return CLI_EXIT_USAGE;
        }
        s->split = (tirenv_split)k;
    }
    return CLI_EXIT_OK;
}

/* --nn's network, its record and its bytes' fingerprint. */
static int read_network(const cli_options *o, sweep_network *net)
{
    tirenv_diag d;
    tirenv_diag_clear(&d);
    char tire_buf[1024];
    /* Named in sweep.txt by its bytes, read apart from the network, and checked again by a
     * resumed run: a pipe would give them once. */
    const int code = cli_refuse_pipe(o->nn_path, "sweep reads the network file again to name "
                                     "it by its bytes in sweep.txt");
    if (code)
        return code;
    int st = tirenv_nn_read_json(o->nn_path, &net->nn, &net->rec, &d);
    /* A file without the law of its tire turns loads and contact lengths into each other by
     * the tire file's springs model, as envelope's and predict's network does: refused when
     * the file has none of its own (the default tire's would stand in unsaid). */
    if (!st && !net->rec.law.n)
        st = cli_nn_springs_stand_in(o->nn_path, cli_tire_path(o, tire_buf, sizeof tire_buf),
                                     &cli_tire_origin, &d);
    if (st)
        return cli_fail(st, &d);
    if (!net->rec.law.n)
        fprintf(stderr, "tirenv: warning: %s records no relation between load and contact "
                "length of its tire (training.data.contact_law; a file written before tirenv "
                "recorded it): loads become contact lengths by the springs model of the tire "
                "file, not by the tire the network was trained on; train it again to record "
                "it\n", o->nn_path);
    if (file_fingerprint(o->nn_path, net->id)) {
        cli_error("sweep: %s: cannot read", o->nn_path);
        return CLI_EXIT_DATA;
    }
    return CLI_EXIT_OK;
}

/* The command line parsed and checked, the tire read, and the network where the model
 * evaluates one: CLI_GO_ON, else the exit code. */
static int prepare(int argc, char *argv[], sweep_args *a, cli_options *o, tirenv_tire *tire,
                   tirenv_sweep_settings *s, sweep_network *net)
{
    int code = parse_args(argc, argv, a, o);
    if (code != CLI_GO_ON)
        return code;
    if ((code = check_args(a, o, s)))
        return code;
    o->tire_path = a->tire_path;
    /* Regimes given as contact lengths: the rigid disc's and the point's loads are the springs
     * model's there, which the tire must have (cli_tire). */
    o->have_contact_length = a->lists[2].n > 0;
    if ((code = cli_tire(o, tire)))
        return code;
    if (o->type)
        s->type = o->type;
    if ((tirenv_model_type_flags(s->type) & TIRENV_MODEL_NEEDS_NETWORK) &&
        (code = read_network(o, net)))
        return code;
    return CLI_GO_ON;
}

/* The settings from the options (the lists and keys stay a's, the network net's). */
static void fill_settings(tirenv_sweep_settings *s, const sweep_args *a, const cli_options *o,
                          const sweep_network *net)
{
    s->network = net->nn;
    s->network_R0 = net->rec.R0;
    s->network_law = net->rec.law.n ? &net->rec.law : NULL;
    s->network_id = net->id;
    s->extrapolate = o->extrapolate;
    s->rig = a->rig;
    s->jobs = o->jobs;
    s->seed = a->seed < 0 ? 1ul : (unsigned long)a->seed;
    s->split_seed = a->split_seed < 0 ? 1ul : (unsigned long)a->split_seed;
    s->control_fraction = isnan(a->control) ? 0 : a->control;
    s->validation_fraction = isnan(a->validation) ? 0 : a->validation;
    s->shard = a->shard[0];
    s->shards = a->shard[1];
    s->lengths = a->lists[0].v;
    s->n_lengths = a->lists[0].n;
    s->heights = a->lists[1].v;
    s->n_heights = a->lists[1].n;
    s->contact_lengths = a->lists[2].v;
    s->n_contact_lengths = a->lists[2].n;
    s->loads = a->lists[3].v;
    s->n_loads = a->lists[3].n;
    for (size_t k = 0; k < a->keys.n; ++k)
        s->keys[k] = (tirenv_sweep_axis){a->keys.keys[k], a->keys.counts[k],
                                         a->keys.values[k]};
    s->n_keys = a->keys.n;
}

/* The cam of a tire file without MF-Swift's shape keys, named with the file here (the library
 * refuses it too, without the file); a swept key counts as the tire's own. */
static int refuse_cam_keys(const tirenv_sweep_settings *s, const tirenv_tire *tire,
                           const sweep_keys *keys, const cli_options *o)
{
    if (s->type != tirenv_model_cam)
        return CLI_EXIT_OK;
    tirenv_tire first = *tire;
    tirenv_diag d;
    tirenv_diag_clear(&d);
    for (size_t k = 0; k < keys->n; ++k)  /* a bad key: the library says */
        (void)set_key(&first, keys->keys[k], keys->counts[k] ? keys->values[k][0] : 0.0, &d);
    char path_buf[1024];
    return cli_cam_keys(s->type, &first, cli_tire_path(o, path_buf, sizeof path_buf));
}

/* The sweep run with its progress bar, and what it did said. */
static int run_sweep(const cli_options *o, const tirenv_tire *tire, tirenv_sweep_settings *s,
                     int want_progress)
{
    const int tty = isatty(STDERR_FILENO);
    progress_state ps = {.on = want_progress || tty, .tty = tty, .t0 = cli_wall_seconds(),
                         .first = (size_t)-1, .last_tenth = (size_t)-1};
    s->progress = progress;
    s->progress_ctx = &ps;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_sweep_report rep;
    const int status = tirenv_sweep_run(o->output, tire, s, &rep, &diag);
    if (status) {
        if (tty && ps.first != (size_t)-1)
            fputc('\n', stderr);
        return cli_fail(status, &diag);
    }
    char part[64] = "";
    if (s->shards > 1)
        snprintf(part, sizeof part, " (shard %zu/%zu: %zu cases)", s->shard, s->shards,
                 rep.part_cases);
    if (rep.already_complete)
        fprintf(stderr, "tirenv: sweep: %s already holds this sweep%s, complete; nothing to "
                "do\n", o->output, part);
    else
        fprintf(stderr, "tirenv: sweep: %zu-case grid%s written to %s: %zu cases run, %zu "
                "kept from an interrupted run (%.1f s)\n", rep.cases, part, o->output, rep.run,
                rep.resumed, cli_wall_seconds() - ps.t0);
    return CLI_EXIT_OK;
}

int cli_sweep_main(int argc, char *argv[])
{
    if (argc > 1 && strcmp(argv[1], "merge") == 0)
        return merge_main(argc - 1, argv + 1);
    sweep_args a = {.lists = {{"--lengths", NULL, 0}, {"--heights", NULL, 0},
                              {"--contact-lengths", NULL, 0}, {"--loads", NULL, 0}},
                    .control = NAN, .validation = NAN, .seed = -1, .split_seed = -1,
                    .shard = {0, 1}};
    sweep_network net = {.nn = NULL, .rec = {.R0 = 0}, .id = ""};
    tirenv_sweep_settings s = tirenv_sweep_default();
    cli_options o;
    tirenv_tire tire;
    int code = prepare(argc, argv, &a, &o, &tire, &s, &net);
    if (code == CLI_GO_ON) {
        fill_settings(&s, &a, &o, &net);
        code = refuse_cam_keys(&s, &tire, &a.keys, &o);
        if (!code) {
            warn_unread_keys(&s, &tire);
            code = run_sweep(&o, &tire, &s, a.want_progress);
        }
    }
    free_axes(&a, &net);
    return code;
}
