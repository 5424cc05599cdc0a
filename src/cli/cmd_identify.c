/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv identify: one tire, every model. The springs model's stiffnesses and the cam's
 * vertical and contact-length keys identified on the reference model's flat ground (the
 * ring's), reported model against model, and written into the tire file with how
 * (docs/models.md section 14.1). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli/cli.h"
#include "tirenv/study.h"

enum { MAX_LOADS = 64, MAX_REFS = 2 };

/* Contact lengths (m) at which the reference gives the loads of a tire file without FNOMIN:
 * the span of the paper's working regimes, 0.28 to 0.38 m. A file with FNOMIN gives its own,
 * tirenv_nominal_load_fractions of it (the range `tirenv flat` shows). */
static const double regime_lc[] = {0.28, 0.305, 0.33, 0.355, 0.38};

typedef struct {
    double v[MAX_LOADS];
    size_t n;
} load_list;

static int parse_loads(void *dst, const char *arg)
{
    load_list *l = dst;
    l->n = 0;
    for (const char *p = arg; *p;) {
        char *end;
        const double v = strtod(p, &end);
        if (end == p || !(v > 0 && isfinite(v)) || (*end && *end != ',') ||
            (*end == ',' && !end[1]) || l->n == MAX_LOADS) {
            cli_error("--loads: expected up to %d positive loads in N separated by commas, got "
                      "'%s'", MAX_LOADS, arg);
            return CLI_EXIT_USAGE;
        }
        l->v[l->n++] = v;
        p = *end ? end + 1 : end;
    }
    if (l->n < 2) {
        cli_error("--loads: at least two loads are needed, got '%s'", arg);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* --reference: one model, or several separated by commas, each with a contact length of its
 * own and not the springs model (the ring and the cam), none twice. */
typedef struct {
    const tirenv_model_type *t[MAX_REFS];
    const char *name[MAX_REFS];
    size_t m;
} ref_list;

static int parse_references(ref_list *r, const char *arg)
{
    if (cli_model_list("--reference", arg, r->t, MAX_REFS, &r->m))
        return CLI_EXIT_USAGE; /* said, with the models' names */
    for (size_t k = 0; k < r->m; k++) {
        if (!(tirenv_model_type_flags(r->t[k]) & TIRENV_MODEL_CONTACT_LENGTH) ||
            r->t[k] == tirenv_model_springs)
            goto bad;
        for (size_t j = 0; j < k; j++)
            if (r->t[j] == r->t[k])
                goto bad;
        r->name[k] = tirenv_model_type_name(r->t[k]);
    }
    return CLI_EXIT_OK;
bad:
    cli_error("--reference: expected one or more of the models with a contact length of their "
              "own other than the springs model, identified (ring, cam), separated by commas "
              "and none twice, got '%s'", arg);
    return CLI_EXIT_USAGE;
}

static void usage(FILE *fp)
{
    fputs("usage: tirenv identify [--reference MODEL[,MODEL]] [--loads G1,G2,...] [--write | "
          "--write-springs]\n"
          "                       [--tire FILE] [--set KEY=VALUE]... [--method M]\n"
          "\n"
          "One tire, every model: identifies the springs model's RADIAL_STIFFNESS and\n"
          "INTERRADIAL_STIFFNESS (with SIDEWALL_STIFFNESS and SIDEWALL_PRELOAD when the\n"
          "tire has a sidewall: --set SIDEWALL_STIFFNESS=5e5 asks for one, at least three\n"
          "loads), and the cam's VERTICAL_STIFFNESS, Q_FZ2 (with FNOMIN),\n"
          "Q_RA1 and Q_RA2, on the reference model's flat-ground load-deflection and\n"
          "load-contact-length curves (docs/models.md section 14.1), then tabulates the\n"
          "three models' deflections and contact lengths at each load and their largest\n"
          "relative differences from the reference, all with the values rounded to three\n"
          "significant digits, as written. The loads: 0.5 to 1.5 times the file's FNOMIN,\n"
          "or, for a file without it, the reference's loads at contact lengths 0.28 to\n"
          "0.38 m (the paper's working regimes).\n"
          "\n"
          "options:\n"
          "  --reference MODEL    the model the others are identified on (default ring)\n"
          "  --reference ring,cam the springs model identified on both together: the\n"
          "                       largest relative difference of its deflection and contact\n"
          "                       length from either at any load the least (min-max), the\n"
          "                       values rounded to four significant digits; the cam, a\n"
          "                       reference, is the file's as read, not identified (so too\n"
          "                       with --reference cam). The table then shows each model\n"
          "                       against each reference\n"
          "  --loads G1,G2,...    the loads, N (at least two)\n"
          "  --write              set the identified values in the tire file in place, keeping its\n"
          "                       comments, with a '!' note on how they were identified\n"
          "  --write-springs      the same for the springs model's values alone, the cam's\n"
          "                       laws kept as the file has them (the table then shows the\n"
          "                       file's cam). Both refuse a file whose ring is derived as\n"
          "                       it is read (no [ENVELOPING_RING]) and a --set of a key\n"
          "                       they do not write\n",
          fp);
    cli_help_tire(fp, 1, "FOUNDATION_STIFFNESS=1.2e5 (the ring's)");
    fputs("  -h, --help           show this help\n", fp);
}

/* A model's flat-ground states at the loads. */
static int states(const tirenv_model_type *type, const tirenv_tire *tire, size_t n,
                  const double loads[], tirenv_flat f[])
{
    tirenv_model *m = tirenv_model_alloc(type, tire);
    if (!m)
        return cli_fail(TIRENV_ENOMEM, NULL);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    int status = TIRENV_OK;
    for (size_t i = 0; i < n && !status; i++)
        status = tirenv_model_flat(m, loads[i], &f[i], &diag);
    tirenv_model_free(m);
    return status ? cli_fail(status, &diag) : CLI_EXIT_OK;
}

static double rel(double a, double b) { return fabs(a - b) / b; }

/* Whether --write (all 1) or --write-springs (all 0) sets the key of a --set assignment
 * ("KEY=VALUE" or "SECTION.KEY=VALUE") in the file: the keys it identifies. */
static int written(const char *assignment, int all)
{
    static const char *const keys[] = {"RADIAL_STIFFNESS", "INTERRADIAL_STIFFNESS",
                                       "SIDEWALL_STIFFNESS", "SIDEWALL_PRELOAD",
                                       "VERTICAL_STIFFNESS", "Q_FZ2", "Q_FZ1", "Q_RA1",
                                       "Q_RA2"};
    const char *eq = strchr(assignment, '='), *key = assignment;
    if (!eq)
        return 0;
    for (const char *c = assignment; c < eq; c++)
        if (*c == '.')
            key = c + 1;
    const size_t len = (size_t)(eq - key);
    for (size_t k = 0; k < (all ? sizeof keys / sizeof keys[0] : 4); k++)
        if (strlen(keys[k]) == len && strncasecmp(key, keys[k], len) == 0)
            return 1;
    return 0;
}

/* s with its spaces and newlines turned into line breaks so that no line is longer than
 * width bytes where a word allows. */
static void wrap(char *s, size_t width)
{
    for (char *p = s; *p; p++)
        if (*p == '\n')
            *p = ' ';
    char *line = s, *space = NULL;
    for (char *p = s; *p; p++) {
        if (*p == ' ' && p[1] != '%') /* "4.7 %" kept on one line */
            space = p;
        if ((size_t)(p - line) >= width && space) {
            *space = '\n';
            line = space + 1;
            space = NULL;
        }
    }
}

/* The largest relative differences of a's deflection and contact length from b's over n
 * states. */
static void largest(size_t n, const tirenv_flat a[], const tirenv_flat b[], double *e_d,
                    double *e_l)
{
    *e_d = *e_l = 0;
    for (size_t i = 0; i < n; i++) {
        *e_d = fmax(*e_d, rel(a[i].deflection, b[i].deflection));
        *e_l = fmax(*e_l, rel(a[i].contact_length, b[i].contact_length));
    }
}

/* The identified values (the springs model's four, the cam's four) rounded to digits
 * significant digits, as the file gets them and the table shows them. */
static void round_identified(tirenv_tire *id, int digits)
{
    double *const ids[] = {&id->springs.c_r, &id->springs.c_b, &id->springs.k_s,
                           &id->springs.F_s0, &id->cam.c_z, &id->cam.q_fz2, &id->cam.q_ra1,
                           &id->cam.q_ra2};
    for (size_t k = 0; k < sizeof ids / sizeof ids[0]; k++) {
        char t[32];
        snprintf(t, sizeof t, "%.*g", digits, *ids[k]);
        *ids[k] = strtod(t, NULL);
    }
}

/* What the command line asks, checked: the references, the loads (none: the defaults), and
 * which of the write options. */
typedef struct {
    ref_list refs;
    load_list loads;
    int write, write_springs; /* --write, --write-springs */
    int cam_ref;              /* the cam is one of the references: tabled as read */
} request;

/* A failed identification said with the references and the loads it was made on: an
 * identified value out of its range (a contact law fitted over loads of a few N) names only
 * the value. */
static int identify_failed(int status, tirenv_diag *diag, const char *on, size_t m,
                           const load_list *loads, int why_max)
{
    const size_t n = loads->n;
    char why[sizeof diag->message];
    memcpy(why, diag->message, sizeof why);
    snprintf(diag->message, sizeof diag->message, "identified on the %.40s model%s at %zu "
             "loads %.6g to %.6g N: %.*s", on, m > 1 ? "s" : "", n, loads->v[0],
             loads->v[n - 1], why_max, why);
    return cli_fail(status, diag);
}

/* The identified values against the file's (was); the cam's laws as read where they are kept
 * (cam_kept), else identified (on cam_on, said where not NULL). */
static void print_values(const tirenv_tire *id, const tirenv_tire *was, int cam_kept,
                         const char *cam_on)
{
    printf("  RADIAL_STIFFNESS       %.6g N/m/rad (was %.6g)\n", id->springs.c_r,
           was->springs.c_r);
    printf("  INTERRADIAL_STIFFNESS  %.6g N*rad/m (was %.6g)\n", id->springs.c_b,
           was->springs.c_b);
    if (id->springs.k_s > 0) {
        printf("  SIDEWALL_STIFFNESS     %.6g N/m (was %.6g)\n", id->springs.k_s,
               was->springs.k_s);
        printf("  SIDEWALL_PRELOAD       %.6g N (was %.6g)\n", id->springs.F_s0,
               was->springs.F_s0);
    }
    if (cam_kept) {
        printf("  the cam's laws kept as read: VERTICAL_STIFFNESS %.6g N/m, ", was->cam.c_z);
        if (was->cam.fnomin > 0)
            printf("Q_FZ2 %.6g (FNOMIN %.6g N), ", was->cam.q_fz2, was->cam.fnomin);
        printf("Q_RA1 %.6g, Q_RA2 %.6g\n", was->cam.q_ra1, was->cam.q_ra2);
        return;
    }
    printf("  VERTICAL_STIFFNESS     %.6g N/m (was %.6g)", id->cam.c_z, was->cam.c_z);
    if (cam_on)
        printf(", identified on the %s", cam_on);
    printf("\n");
    if (id->cam.fnomin > 0)
        printf("  Q_FZ2                  %.6g (was %.6g; FNOMIN %.6g N)\n", id->cam.q_fz2,
               was->cam.q_fz2, id->cam.fnomin);
    printf("  Q_RA1                  %.6g (was %.6g)\n", id->cam.q_ra1, was->cam.q_ra1);
    printf("  Q_RA2                  %.6g (was %.6g)\n", id->cam.q_ra2, was->cam.q_ra2);
}

/* Whether the cam's laws as read are (a part of them) derived from the file's MF-Tyre keys as
 * it is read (docs/models.md 14.2), not its own: a note that keeps them says so, as this does
 * not write them. */
static int cam_laws_derived(void)
{
    return (cli_tire_origin.derived & (TIRENV_TIR_CAM | TIRENV_TIR_VERTICAL)) != 0;
}

/* The reference's n states from its targets. */
static void target_states(size_t n, const tirenv_flat_target tg[], tirenv_flat f[])
{
    for (size_t i = 0; i < n; i++)
        f[i] = (tirenv_flat){.load = tg[i].load, .deflection = tg[i].deflection,
                             .contact_length = tg[i].contact_length};
}

/* ---- several references (or the cam) -------------------------------------------------- */

/* The references' names as the output and the note say them: "ring and cam" (on), "the ring's
 * and the cam's" (whose), "ring,cam" (list, as on the command line). */
typedef struct {
    char on[128], whose[128], list[128];
} ref_names;

static void name_references(const ref_list *refs, ref_names *r)
{
    const size_t m = refs->m;
    r->on[0] = r->whose[0] = r->list[0] = '\0';
    for (size_t j = 0; j < m; j++) {
        const char *sep = j == 0 ? "" : j + 1 == m ? " and " : ", ";
        snprintf(r->on + strlen(r->on), sizeof r->on - strlen(r->on), "%s%s", sep,
                 refs->name[j]);
        snprintf(r->whose + strlen(r->whose), sizeof r->whose - strlen(r->whose),
                 "%sthe %s's", sep, refs->name[j]);
        snprintf(r->list + strlen(r->list), sizeof r->list - strlen(r->list), "%s%s",
                 j ? "," : "", refs->name[j]);
    }
}

/* The tabled models' states: the references' (from their targets), then the springs model's
 * and the cam's where it is not a reference; cols lists the rows of f in use, in order. */
enum { SPRINGS = MAX_REFS, CAM, N_MODELS };
typedef struct {
    tirenv_flat f[N_MODELS][MAX_LOADS];
    const char *name[N_MODELS];
    size_t cols[N_MODELS], n_cols;
} model_table;

static int table_models(const request *q, const tirenv_tire *id, const tirenv_flat_target tg[],
                        model_table *t)
{
    const size_t n = q->loads.n;
    t->n_cols = 0;
    for (size_t j = 0; j < q->refs.m; j++) {
        target_states(n, tg + j * n, t->f[j]);
        t->name[j] = q->refs.name[j];
        t->cols[t->n_cols++] = j;
    }
    int code = states(tirenv_model_springs, id, n, q->loads.v, t->f[SPRINGS]);
    t->name[SPRINGS] = "springs";
    t->cols[t->n_cols++] = SPRINGS;
    if (!code && !q->cam_ref) {
        code = states(tirenv_model_cam, id, n, q->loads.v, t->f[CAM]);
        t->name[CAM] = "cam";
        t->cols[t->n_cols++] = CAM;
    }
    return code;
}

/* Deflections then contact lengths, a column per tabled model, a row per load. */
static void print_table(const model_table *t, const load_list *loads)
{
    const size_t n_cols = t->n_cols;
    printf("%10s  %-*s  %s\n", "", (int)(9 * n_cols - 1), "deflection, mm",
           "contact length, m");
    printf("%10s ", "load_N");
    for (size_t k = 0; k < 2 * n_cols; k++)
        printf("%s%8s", k == n_cols ? "  " : " ", t->name[t->cols[k % n_cols]]);
    printf("\n");
    for (size_t i = 0; i < loads->n; i++) {
        printf("%10.1f ", loads->v[i]);
        for (size_t k = 0; k < n_cols; k++)
            printf(" %8.2f", t->f[t->cols[k]][i].deflection * 1e3);
        printf(" ");
        for (size_t k = 0; k < n_cols; k++)
            printf(" %8.4f", t->f[t->cols[k]][i].contact_length);
        printf("\n");
    }
}

/* The identified models against each reference, then each reference against those before it:
 * "springs against ring deflection 4.7 %, contact length 3.9 %; ...", a line each. */
static void pair_differences(const model_table *t, size_t m, size_t n, char *pairs,
                             size_t size)
{
    pairs[0] = '\0';
    for (size_t c = 0; c < t->n_cols; c++) {
        const size_t k = t->cols[(c + m) % t->n_cols];
        for (size_t j = 0; j < m && j < k; j++) {
            double e_d, e_l;
            largest(n, t->f[k], t->f[j], &e_d, &e_l);
            const size_t used = strlen(pairs);
            snprintf(pairs + used, size - used, "%s%s against %s deflection %.1f %%, "
                     "contact length %.1f %%", used ? ";\n" : "", t->name[k], t->name[j],
                     100 * e_d, 100 * e_l);
        }
    }
}

/* The identified values into the file in place, with the note: the file's '!' block
 * (tirenv_tir_update), one paragraph wrapped. */
static int write_several(const request *q, const char *path, const tirenv_tire *tire,
                         const tirenv_tire *id, int cam_kept, const ref_names *r,
                         const char *pairs)
{
    const size_t n = q->loads.n, m = q->refs.m;
    const int sidewall = id->springs.k_s > 0;
    const int cam_derived = cam_laws_derived();
    char note[2048];
    snprintf(note, sizeof note,
             "RADIAL_STIFFNESS, INTERRADIAL_STIFFNESS%s%s below are identified by `tirenv "
             "identify --reference %s %s` (docs/models.md section 14.1) on %s flat ground%s at "
             "%zu loads %.4g to %.4g kN; %s%s. Largest differences over these loads: %s.",
             sidewall ? ", SIDEWALL_STIFFNESS and SIDEWALL_PRELOAD (the sidewall in series, "
                        "section 4.9)" : "",
             cam_kept ? "" : (id->cam.fnomin > 0 ? ", VERTICAL_STIFFNESS, Q_FZ2, Q_RA1, Q_RA2"
                                                 : ", VERTICAL_STIFFNESS, Q_RA1, Q_RA2"),
             r->list, q->write ? "--write" : "--write-springs", r->whose,
             m > 1 ? " together (min-max)" : "", n, q->loads.v[0] / 1e3,
             q->loads.v[n - 1] / 1e3,
             !cam_kept ? "the cam's laws are identified on the "
             : cam_derived ? "the cam's laws are derived from its MF-Tyre keys as it is read "
                             "(section 14.2)"
                           : "the cam's laws are the file's own",
             !cam_kept ? q->refs.name[0] : "", pairs);
    wrap(note, 92);
    tirenv_tir_value values[9];
    size_t n_values = 0;
    values[n_values++] = (tirenv_tir_value){"ENVELOPING_SPRINGS", "RADIAL_STIFFNESS",
                                            id->springs.c_r};
    values[n_values++] = (tirenv_tir_value){"ENVELOPING_SPRINGS", "INTERRADIAL_STIFFNESS",
                                            id->springs.c_b};
    if (sidewall) {
        values[n_values++] = (tirenv_tir_value){"ENVELOPING_SPRINGS", "SIDEWALL_STIFFNESS",
                                                id->springs.k_s};
        values[n_values++] = (tirenv_tir_value){"ENVELOPING_SPRINGS", "SIDEWALL_PRELOAD",
                                                id->springs.F_s0};
    }
    if (!cam_kept) {
        values[n_values++] = (tirenv_tir_value){"VERTICAL", "VERTICAL_STIFFNESS", id->cam.c_z};
        values[n_values++] = (tirenv_tir_value){"CONTACT_PATCH", "Q_RA1", id->cam.q_ra1};
        values[n_values++] = (tirenv_tir_value){"CONTACT_PATCH", "Q_RA2", id->cam.q_ra2};
        if (id->cam.fnomin > 0)
            values[n_values++] = (tirenv_tir_value){"VERTICAL", "Q_FZ2", id->cam.q_fz2};
        if (tire->cam.q_fz1 != 0)
            values[n_values++] = (tirenv_tir_value){"VERTICAL", "Q_FZ1", 0};
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_tir_update(path, n_values, values, note, &diag);
    if (status)
        return cli_fail(status, &diag);
    fprintf(stderr, "tirenv identify: wrote the %zu values into %s\n", n_values, path);
    return CLI_EXIT_OK;
}

/* --reference with several models, or the cam: the springs model identified on them together
 * (min-max, tirenv_identify_flat_on), the cam as read where it is a reference; every model
 * tabled, each against each reference (the models: the references in their order, then the
 * springs model, then the cam where it is not a reference). */
static int identify_several(const tirenv_tire *tire, const char *path, const request *q)
{
    const size_t n = q->loads.n, m = q->refs.m;
    ref_names r;
    name_references(&q->refs, &r);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_tire id;
    tirenv_flat_target tg[MAX_REFS * MAX_LOADS];
    const int status =
        tirenv_identify_flat_on(tire, m, q->refs.t, n, q->loads.v, &id, tg, &diag);
    if (status)
        return identify_failed(status, &diag, r.on, m, &q->loads, 360);
    /* Four significant digits, as written: a min-max optimum sits where several differences
     * are equal, and three digits would move it (docs/models.md section 14.1). */
    round_identified(&id, 4);
    const int cam_kept = q->cam_ref || q->write_springs;
    if (cam_kept)
        id.cam = tire->cam; /* the file's own laws, kept and tabled */
    model_table t;
    const int code = table_models(q, &id, tg, &t);
    if (code)
        return code;

    printf("identified on the %s model%s of %s at %zu loads %.6g to %.6g N\n", r.on,
           m > 1 ? "s together (min-max)" : "", path, n, q->loads.v[0], q->loads.v[n - 1]);
    print_values(&id, tire, cam_kept, q->refs.name[0]);
    print_table(&t, &q->loads);
    char pairs[1024];
    pair_differences(&t, m, n, pairs, sizeof pairs);
    printf("largest differences:\n%s\n", pairs);
    if (!q->write && !q->write_springs)
        return CLI_EXIT_OK;
    return write_several(q, path, tire, &id, cam_kept, &r, pairs);
}

/* ---- one reference other than the cam -------------------------------------------------- */

/* The reference's, the springs model's and the cam's states, and the largest relative
 * differences of the two from the reference: springs (e_sd, e_sl) and cam (e_cd, e_cl),
 * deflection and contact length. */
typedef struct {
    tirenv_flat ref[MAX_LOADS], springs[MAX_LOADS], cam[MAX_LOADS];
    double e_sd, e_sl, e_cd, e_cl;
} one_table;

static void print_one_table(const one_table *t, size_t n, const char *ref_name)
{
    printf("%10s  %-26s  %-26s\n", "", "deflection, mm", "contact length, m");
    printf("%10s  %8s %8s %8s  %8s %8s %8s\n", "load_N", ref_name, "springs", "cam", ref_name,
           "springs", "cam");
    for (size_t i = 0; i < n; i++)
        printf("%10.1f  %8.2f %8.2f %8.2f  %8.4f %8.4f %8.4f\n", t->ref[i].load,
               t->ref[i].deflection * 1e3, t->springs[i].deflection * 1e3,
               t->cam[i].deflection * 1e3, t->ref[i].contact_length,
               t->springs[i].contact_length, t->cam[i].contact_length);
    printf("largest difference from the %s: springs deflection %.1f %%, springs contact length "
           "%.1f %%, cam deflection %.1f %%, cam contact length %.1f %%\n", ref_name,
           100 * t->e_sd, 100 * t->e_sl, 100 * t->e_cd, 100 * t->e_cl);
}

/* --write-springs: the springs model's values alone into the file in place, with the note. */
static int write_springs_one(const char *path, const tirenv_tire *id, const one_table *t,
                             const char *ref_name, const load_list *loads)
{
    const size_t n = loads->n;
    const int sidewall = id->springs.k_s > 0;
    const int cam_derived = cam_laws_derived();
    char note[1024];
    snprintf(note, sizeof note,
             "RADIAL_STIFFNESS and INTERRADIAL_STIFFNESS%s below are identified by `tirenv\n"
             "identify --write-springs` (docs/models.md section 14.1) on the %s model's flat\n"
             "ground at %zu loads %.4g to %.4g kN (deflection %.1f to %.1f mm, contact length\n"
             "%.3f to %.3f m); the cam's laws are %s. Largest differences from the\n"
             "%s over these loads: springs deflection %.1f %%, springs contact length %.1f %%,\n"
             "cam deflection %.1f %%, cam contact length %.1f %%.",
             sidewall ? " (and SIDEWALL_STIFFNESS,\nSIDEWALL_PRELOAD: the sidewall in series, "
                        "section 4.9)"
                      : "",
             ref_name, n, loads->v[0] / 1e3, loads->v[n - 1] / 1e3, t->ref[0].deflection * 1e3,
             t->ref[n - 1].deflection * 1e3, t->ref[0].contact_length,
             t->ref[n - 1].contact_length,
             cam_derived ? "derived\nfrom its MF-Tyre keys as it is read (section 14.2)"
                         : "the file's own",
             ref_name, 100 * t->e_sd, 100 * t->e_sl, 100 * t->e_cd, 100 * t->e_cl);
    const tirenv_tir_value springs[] = {
        {"ENVELOPING_SPRINGS", "RADIAL_STIFFNESS", id->springs.c_r},
        {"ENVELOPING_SPRINGS", "INTERRADIAL_STIFFNESS", id->springs.c_b},
        {"ENVELOPING_SPRINGS", "SIDEWALL_STIFFNESS", id->springs.k_s},
        {"ENVELOPING_SPRINGS", "SIDEWALL_PRELOAD", id->springs.F_s0},
    };
    const size_t n_springs = sidewall ? 4 : 2;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_tir_update(path, n_springs, springs, note, &diag);
    if (status)
        return cli_fail(status, &diag);
    fprintf(stderr, "tirenv identify: wrote the %zu springs values into %s\n", n_springs,
            path);
    return CLI_EXIT_OK;
}

/* --write: the springs model's and the cam's values into the file in place, with the note. */
static int write_one(const char *path, const tirenv_tire *tire, const tirenv_tire *id,
                     const one_table *t, const char *ref_name, const load_list *loads)
{
    const size_t n = loads->n;
    char note[2048];
    snprintf(note, sizeof note,
             "RADIAL_STIFFNESS, INTERRADIAL_STIFFNESS, VERTICAL_STIFFNESS,%s Q_RA1 and Q_RA2 below\n"
             "are identified by `tirenv identify --write` (docs/models.md section 14.1) on the\n"
             "%s model's flat ground at %zu loads %.4g to %.4g kN (deflection %.1f to %.1f mm,\n"
             "contact length %.3f to %.3f m). Largest differences from it over these loads:\n"
             "springs deflection %.1f %%, springs contact length %.1f %% (the length of ground\n"
             "its tread touches), cam deflection %.1f %%, cam contact length %.1f %%.",
             id->cam.fnomin > 0 ? " Q_FZ2," : "", ref_name, n, loads->v[0] / 1e3,
             loads->v[n - 1] / 1e3, t->ref[0].deflection * 1e3, t->ref[n - 1].deflection * 1e3,
             t->ref[0].contact_length, t->ref[n - 1].contact_length, 100 * t->e_sd,
             100 * t->e_sl, 100 * t->e_cd, 100 * t->e_cl);
    tirenv_tir_value values[] = {
        {"VERTICAL", "VERTICAL_STIFFNESS", id->cam.c_z},
        {"CONTACT_PATCH", "Q_RA1", id->cam.q_ra1},
        {"CONTACT_PATCH", "Q_RA2", id->cam.q_ra2},
        {"ENVELOPING_SPRINGS", "RADIAL_STIFFNESS", id->springs.c_r},
        {"ENVELOPING_SPRINGS", "INTERRADIAL_STIFFNESS", id->springs.c_b},
        {"VERTICAL", "Q_FZ2", id->cam.q_fz2},  /* only with FNOMIN, which it refers to */
        {"VERTICAL", "Q_FZ1", 0},              /* only over a file's own: the law is now
                                                * VERTICAL_STIFFNESS's (section 14.1) */
    };
    size_t n_values = sizeof values / sizeof values[0] - 2 + (id->cam.fnomin > 0 ? 1 : 0);
    tirenv_tir_value all[sizeof values / sizeof values[0] + 2];
    memcpy(all, values, n_values * sizeof values[0]);
    if (tire->cam.q_fz1 != 0)
        all[n_values++] = values[sizeof values / sizeof values[0] - 1];
    if (id->springs.k_s > 0) { /* the sidewall identified with the springs model (4.9) */
        all[n_values++] = (tirenv_tir_value){"ENVELOPING_SPRINGS", "SIDEWALL_STIFFNESS",
                                             id->springs.k_s};
        all[n_values++] = (tirenv_tir_value){"ENVELOPING_SPRINGS", "SIDEWALL_PRELOAD",
                                             id->springs.F_s0};
    }
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_tir_update(path, n_values, all, note, &diag);
    if (status)
        return cli_fail(status, &diag);
    fprintf(stderr, "tirenv identify: wrote the %zu values into %s\n", n_values, path);
    return CLI_EXIT_OK;
}

/* One reference other than the cam (ref): the springs model and the cam identified on it
 * (tirenv_identify_flat) and tabled beside it. */
static int identify_one(const tirenv_tire *tire, const char *path,
                        const tirenv_model_type *ref, const request *q)
{
    const load_list *loads = &q->loads;
    const size_t n = loads->n;
    const char *ref_name = q->refs.name[0];
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_tire id;
    tirenv_flat_target tg[MAX_LOADS];
    const int status = tirenv_identify_flat(tire, ref, n, loads->v, &id, tg, &diag);
    if (status)
        return identify_failed(status, &diag, ref_name, 1, loads, 400);
    /* Three significant digits, as written: the table and the note describe the file. */
    round_identified(&id, 3);
    if (q->write_springs)
        id.cam = tire->cam; /* the file's own laws, kept and tabled */
    one_table t;
    int code;
    if ((code = states(tirenv_model_springs, &id, n, loads->v, t.springs)) ||
        (code = states(tirenv_model_cam, &id, n, loads->v, t.cam)))
        return code;
    target_states(n, tg, t.ref);
    largest(n, t.springs, t.ref, &t.e_sd, &t.e_sl);
    largest(n, t.cam, t.ref, &t.e_cd, &t.e_cl);

    printf("identified on the %s model of %s at %zu loads %.6g to %.6g N\n", ref_name, path, n,
           loads->v[0], loads->v[n - 1]);
    print_values(&id, tire, q->write_springs, NULL);
    print_one_table(&t, n, ref_name);
    if (q->write_springs)
        return write_springs_one(path, &id, &t, ref_name, loads);
    if (!q->write)
        return CLI_EXIT_OK;
    return write_one(path, tire, &id, &t, ref_name, loads);
}

/* ---- the command ----------------------------------------------------------------------- */

/* The references, and the write options with the --set keys they allow. */
static int check_request(request *q, const char *ref_name, const cli_options *o)
{
    int code;
    if ((code = parse_references(&q->refs, ref_name)))
        return code;
    if (q->write && q->write_springs) {
        cli_error("--write and --write-springs: expected one of them");
        return CLI_EXIT_USAGE;
    }
    q->cam_ref = 0;
    for (size_t j = 0; j < q->refs.m; j++)
        q->cam_ref |= q->refs.t[j] == tirenv_model_cam;
    /* A --set of a key the file does not get would leave it another tire than the one its
     * identified values and note describe. --write with the cam a reference writes the
     * springs values alone, as --write-springs. */
    const int writes_cam = q->write && !q->cam_ref;
    for (size_t i = 0; (q->write || q->write_springs) && i < o->n_sets; i++)
        if (!written(o->sets[i], writes_cam)) {
            cli_error("--set %s with %s: the file would keep its own value of that key, not the "
                      "one identified on; expected --set only of the keys written (%s), or set "
                      "it in the file first", o->sets[i], q->write ? "--write" : "--write-springs",
                      writes_cam ? "RADIAL_STIFFNESS, INTERRADIAL_STIFFNESS, SIDEWALL_STIFFNESS, "
                              "SIDEWALL_PRELOAD, VERTICAL_STIFFNESS, Q_FZ1, Q_FZ2, Q_RA1, Q_RA2"
                            : "RADIAL_STIFFNESS, INTERRADIAL_STIFFNESS, SIDEWALL_STIFFNESS, "
                              "SIDEWALL_PRELOAD");
            return CLI_EXIT_USAGE;
        }
    return CLI_EXIT_OK;
}

/* The model the tire is read for: the file's ring where it is a reference (derived with the
 * springs model, and checked), else the first reference. */
static const tirenv_model_type *read_for(const ref_list *refs)
{
    const tirenv_model_type *ref = refs->t[0];
    for (size_t j = 1; j < refs->m; j++)
        if (refs->t[j] == tirenv_model_ring)
            ref = refs->t[j];
    return ref;
}

/* The tire, for writing in place where asked. A ring derived as the file is read is derived
 * with its springs model where the file has neither (docs/models.md 14.2): springs values
 * written into it would change the ring the next read derives, and no longer be identified on
 * it (nor on a cam whose laws are derived on that ring: --reference cam). */
static int read_tire(cli_options *o, const request *q, const char *path, tirenv_tire *tire)
{
    const int writes = q->write || q->write_springs;
    int code;
    if (writes && (code = cli_refuse_pipe(path, q->write ? "--write sets its values in place"
                                                         : "--write-springs sets its values "
                                                           "in place")))
        return code;
    if ((code = cli_tire(o, tire)))
        return code;
    if (writes && (cli_tire_origin.derived & TIRENV_TIR_RING)) {
        cli_error("%s %s: its ring is derived from its MF-Tyre keys as it is read (docs/models.md "
                  "section 14.2), and writing the springs values would change the ring derived "
                  "next; expected a file with an [ENVELOPING_RING] of its own (the derived "
                  "values are on standard error)", q->write ? "--write" : "--write-springs", path);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* The loads where --loads gives none: the file's own load range whenever it gives FNOMIN, also
 * for a tire of the paper's class (the default tire: 8.95 to 26.85 kN, whose models then agree
 * within 5 % up to the embedded data set's 38.5 kN too, docs/models.md section 14.1), unlike
 * flat's table; else the reference's at the regimes' contact lengths. */
static int default_loads(const tirenv_model_type *ref, const tirenv_tire *tire,
                         load_list *loads)
{
    const double fnomin = cli_tire_origin.fnomin;
    tirenv_model *m = tirenv_model_alloc(ref, tire);
    if (!m)
        return cli_fail(TIRENV_ENOMEM, NULL);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const size_t n = fnomin > 0 ? TIRENV_NOMINAL_LOADS : sizeof regime_lc / sizeof regime_lc[0];
    int status = TIRENV_OK;
    for (size_t i = 0; i < n && !status; i++)
        status = fnomin > 0
                     ? (loads->v[i] = tirenv_nominal_load_fractions[i] * fnomin, TIRENV_OK)
                     : tirenv_model_load_for_contact_length(m, regime_lc[i], &loads->v[i],
                                                            &diag);
    tirenv_model_free(m);
    if (status)
        return cli_fail(status, &diag);
    loads->n = n;
    return CLI_EXIT_OK;
}

int cli_identify_main(int argc, char *argv[])
{
    const char *ref_name = "ring";
    request q = {.loads = {.n = 0}};
    const cli_opt own[] = {
        {.name = "reference", .kind = CLI_STRING, .dst = &ref_name},
        {.name = "loads", .kind = CLI_CUSTOM, .dst = &q.loads, .parse = parse_loads},
        {.name = "write", .kind = CLI_FLAG, .dst = &q.write},
        {.name = "write-springs", .kind = CLI_FLAG, .dst = &q.write_springs},
        {.name = NULL},
    };
    const cli_parser p = {.name = "identify", .usage = usage, .opts = own,
                          .groups = CLI_TIRE | CLI_METHOD};
    cli_options o;
    int code = cli_parse(&p, argc, argv, &o);
    if (code != CLI_GO_ON)
        return code;
    if ((code = check_request(&q, ref_name, &o)))
        return code;
    const tirenv_model_type *ref = read_for(&q.refs);
    o.type = ref;
    /* Each reference, the springs model identified on them and the cam (--set's warnings). */
    for (size_t j = 0; j < q.refs.m && o.n_runs < CLI_MAX_RUNS; j++)
        o.runs[o.n_runs++] = q.refs.t[j];
    o.runs[o.n_runs++] = tirenv_model_springs;
    if (!q.cam_ref)
        o.runs[o.n_runs++] = tirenv_model_cam;
    char buf[1024];
    const char *path = cli_tire_path(&o, buf, sizeof buf);
    tirenv_tire tire;
    if ((code = read_tire(&o, &q, path, &tire)) ||
        (q.loads.n == 0 && (code = default_loads(ref, &tire, &q.loads))))
        return code;
    /* One reference other than the cam: the cam identified on it and tabled beside it. */
    if (q.refs.m > 1 || q.refs.t[0] == tirenv_model_cam)
        return identify_several(&tire, path, &q);
    return identify_one(&tire, path, ref, &q);
}
