/* The .tir tire property file: reading (MF-Tyre files included), --set overrides, writing.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/io.h"
#include "tirenv/tirenv.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/types.h>

/* How a key's value is parsed and where it goes. */
typedef enum {
    TIR_REAL,   /* a finite double at offset */
    TIR_COUNT,  /* a positive integer, stored as size_t at offset */
    TIR_METHOD, /* 'newton' | 'secant' | 'brent', stored as tirenv_eq_method at offset */
    TIR_UNIT    /* one of the accepted SI spellings; stores nothing */
} tir_kind;

typedef struct {
    const char *section;
    const char *key;
    tir_kind kind;
    size_t offset;           /* into tirenv_tire; unused for TIR_UNIT */
    const char *accepted[2]; /* TIR_UNIT: spellings accepted, the first is written */
    const char *comment;     /* unit and meaning, written after the value */
} tir_key;

#define TIR_FIELD(member) offsetof(tirenv_tire, member)

/* Every key tirenv reads, checks, accepts in --set and writes: one table instead of a chain of
 * string comparisons, so the reader, the writer and the error messages cannot drift apart. */
static const tir_key tir_keys[] = {
    {"UNITS", "LENGTH", TIR_UNIT, 0, {"meter", NULL}, "lengths in m"},
    {"UNITS", "FORCE", TIR_UNIT, 0, {"newton", NULL}, "forces in N"},
    {"UNITS", "ANGLE", TIR_UNIT, 0, {"radians", "rad"}, "angles in rad"},
    {"UNITS", "MASS", TIR_UNIT, 0, {"kg", NULL}, "masses in kg"},
    {"UNITS", "TIME", TIR_UNIT, 0, {"second", "sec"}, "times in s"},
    {"DIMENSION", "UNLOADED_RADIUS", TIR_REAL, TIR_FIELD(springs.R0), {NULL, NULL},
     "R0: free (unloaded) tire radius, m"},
    {"VERTICAL", "VERTICAL_STIFFNESS", TIR_REAL, TIR_FIELD(cam.c_z), {NULL, NULL},
     "cam: load / static deflection, N/m"},
    {"CONTACT_PATCH", "Q_RA1", TIR_REAL, TIR_FIELD(cam.q_ra1), {NULL, NULL},
     "cam: contact half length a = R0*(Q_RA2*rho/R0 + Q_RA1*sqrt(rho/R0))"},
    {"CONTACT_PATCH", "Q_RA2", TIR_REAL, TIR_FIELD(cam.q_ra2), {NULL, NULL},
     "cam: linear term of the contact half length"},
    {"CONTACT_PATCH", "ELLIPS_SHIFT", TIR_REAL, TIR_FIELD(cam.shift), {NULL, NULL},
     "cam: tandem base l_s = ELLIPS_SHIFT*2a"},
    {"CONTACT_PATCH", "ELLIPS_LENGTH", TIR_REAL, TIR_FIELD(cam.length), {NULL, NULL},
     "cam: half length a_e = ELLIPS_LENGTH*R0"},
    {"CONTACT_PATCH", "ELLIPS_HEIGHT", TIR_REAL, TIR_FIELD(cam.height), {NULL, NULL},
     "cam: half height b_e = ELLIPS_HEIGHT*R0"},
    {"CONTACT_PATCH", "ELLIPS_ORDER", TIR_REAL, TIR_FIELD(cam.order), {NULL, NULL},
     "cam: super-ellipse exponent c_e, > 1"},
    {"ENVELOPING_SPRINGS", "RADIAL_STIFFNESS", TIR_REAL, TIR_FIELD(springs.c_r), {NULL, NULL},
     "c_r: radial stiffness per radian of tread, N/m/rad"},
    {"ENVELOPING_SPRINGS", "INTERRADIAL_STIFFNESS", TIR_REAL, TIR_FIELD(springs.c_b),
     {NULL, NULL}, "c_b: interradial (bending) stiffness, N*rad/m"},
    {"ENVELOPING_SPRINGS", "SEGMENT_ANGLE", TIR_REAL, TIR_FIELD(springs.phi), {NULL, NULL},
     "phi: width of the modelled tread segment, rad"},
    {"ENVELOPING_SPRINGS", "ELEMENT_ANGLE", TIR_REAL, TIR_FIELD(springs.dphi), {NULL, NULL},
     "dphi: angle between adjacent radial elements, rad"},
    {"ENVELOPING_RING", "TREAD_THICKNESS", TIR_REAL, TIR_FIELD(ring.t_r), {NULL, NULL},
     "t_r: tread layer between belt and ground, m"},
    {"ENVELOPING_RING", "BELT_BENDING_STIFFNESS", TIR_REAL, TIR_FIELD(ring.EI), {NULL, NULL},
     "EI: bending stiffness of the belt, N*m^2"},
    {"ENVELOPING_RING", "BELT_PRETENSION", TIR_REAL, TIR_FIELD(ring.T), {NULL, NULL},
     "T: belt tension from inflation, about p*b*R, N"},
    {"ENVELOPING_RING", "FOUNDATION_STIFFNESS", TIR_REAL, TIR_FIELD(ring.k_f), {NULL, NULL},
     "k_f: sidewall + air foundation per unit belt length, N/m^2"},
    {"ENVELOPING_RING", "TREAD_STIFFNESS", TIR_REAL, TIR_FIELD(ring.k_t), {NULL, NULL},
     "k_t: tread brush stiffness per unit belt length, N/m^2"},
    {"ENVELOPING_RING", "NODE_ANGLE", TIR_REAL, TIR_FIELD(ring.dtheta), {NULL, NULL},
     "dtheta: node spacing around the full circle, rad"},
    {"ENVELOPING_RING", "LUG_COUNT", TIR_REAL, TIR_FIELD(ring.lug_count), {NULL, NULL},
     "lugs around the circumference; 0 = smooth tread"},
    {"ENVELOPING_RING", "LUG_FRACTION", TIR_REAL, TIR_FIELD(ring.lug_fraction), {NULL, NULL},
     "share of the circumference under lugs"},
    {"ENVELOPING_RING", "LUG_GROOVE_RATIO", TIR_REAL, TIR_FIELD(ring.lug_ratio), {NULL, NULL},
     "tread stiffness between lugs / on lugs"},
    {"ENVELOPING_SOLVER", "METHOD", TIR_METHOD, TIR_FIELD(eq.method), {NULL, NULL},
     "equilibrium iteration: 'newton', 'secant' or 'brent'"},
    {"ENVELOPING_SOLVER", "FORCE_TOLERANCE", TIR_REAL, TIR_FIELD(eq.eps_F), {NULL, NULL},
     "eps_F: converged when |F_z - G_T| <= eps_F, N"},
    {"ENVELOPING_SOLVER", "STEP_TOLERANCE", TIR_REAL, TIR_FIELD(eq.eps_z), {NULL, NULL},
     "eps_z: converged also needs the last step |dz| <= eps_z, m"},
    {"ENVELOPING_SOLVER", "MAX_ITERATIONS", TIR_COUNT, TIR_FIELD(eq.max_iter), {NULL, NULL},
     "force evaluations allowed per position"},
    {"ENVELOPING_SOLVER", "SECANT_STEP", TIR_REAL, TIR_FIELD(eq.secant_dz), {NULL, NULL},
     "secant only: offset of the second starting point, m"},
};
#define TIR_NKEYS (sizeof tir_keys / sizeof tir_keys[0])

/* The sections tirenv reads. In a strict section an unknown key is a typo and an error; in
 * [DIMENSION], [VERTICAL] and [CONTACT_PATCH], which tirenv shares with MF-Tyre, the keys of
 * the other models (WIDTH, FNOMIN, Q_RB1...) are skipped. Any other section is skipped whole. */
typedef struct {
    const char *name;
    int strict;
} tir_section;

static const tir_section tir_sections[] = {
    {"UNITS", 1},
    {"DIMENSION", 0},
    {"VERTICAL", 0},
    {"CONTACT_PATCH", 0},
    {"ENVELOPING_SPRINGS", 1},
    {"ENVELOPING_RING", 1},
    {"ENVELOPING_SOLVER", 1},
};
#define TIR_NSECTIONS (sizeof tir_sections / sizeof tir_sections[0])

/* Section names with this prefix are tirenv's own: an unknown one is a typo, not MF-Tyre. */
static const char tir_own_prefix[] = "ENVELOPING_";

static const char *const tir_methods[] = {
    [TIRENV_EQ_NEWTON] = "newton",
    [TIRENV_EQ_SECANT] = "secant",
    [TIRENV_EQ_BRENT] = "brent",
};
#define TIR_NMETHODS (sizeof tir_methods / sizeof tir_methods[0])

/* Where the text being parsed came from, so every error can name file, line and column. */
typedef struct {
    const char *file; /* path, or "--set" */
    size_t line;      /* 1-based, or 0 for --set */
    const char *base; /* start of the line: columns count from here; NULL for no columns */
    tirenv_diag *diag;
} tir_ctx;

/* Records a parse error; 'at' points into the line at the offending character. */
#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static int tir_fail(const tir_ctx *c, const char *at, const char *field, const char *fmt, ...)
{
    char msg[sizeof ((tirenv_diag *)NULL)->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const int status = tirenv_error(c->diag, TIRENV_EPARSE, c->file, c->line, field, "%s", msg);
    if (c->diag && c->base && at)
        c->diag->column = (size_t)(at - c->base) + 1;
    return status;
}

static char *tir_trim(char *s)
{
    while (isspace((unsigned char)*s))
        s++;
    size_t n = strlen(s);
    while (n > 0 && isspace((unsigned char)s[n - 1]))
        s[--n] = '\0';
    return s;
}

/* '$' starts a comment anywhere, except inside a quoted string. */
static void tir_strip_comment(char *s)
{
    int quoted = 0;
    for (; *s; s++) {
        if (*s == '\'')
            quoted = !quoted;
        else if (*s == '$' && !quoted) {
            *s = '\0';
            return;
        }
    }
}

static const tir_section *tir_find_section(const char *name)
{
    for (size_t i = 0; i < TIR_NSECTIONS; i++)
        if (strcasecmp(tir_sections[i].name, name) == 0)
            return &tir_sections[i];
    return NULL;
}

/* The key's index in tir_keys, or TIR_NKEYS. section NULL matches any section. */
static size_t tir_find_key(const char *section, const char *key)
{
    for (size_t i = 0; i < TIR_NKEYS; i++)
        if ((!section || strcasecmp(tir_keys[i].section, section) == 0) &&
            strcasecmp(tir_keys[i].key, key) == 0)
            return i;
    return TIR_NKEYS;
}

/* "A, B, C": the keys of one section (or every settable key if section is NULL). */
static const char *tir_key_list(const char *section, char *buf, size_t n)
{
    size_t k = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < TIR_NKEYS && k < n; i++) {
        const tir_key *e = &tir_keys[i];
        if (section ? strcmp(e->section, section) != 0 : e->kind == TIR_UNIT)
            continue;
        const int r = snprintf(buf + k, n - k, "%s%s", k ? ", " : "", e->key);
        k += r > 0 ? (size_t)r : 0;
    }
    return buf;
}

static int tir_parse_real(const tir_ctx *c, const tir_key *e, const char *text, double *out)
{
    char *end;
    const double v = strtod(text, &end);
    if (end == text)
        return tir_fail(c, text, e->key, "expected a number, got '%.60s'", text);
    if (*end) {
        const char *junk = end + strspn(end, " \t");
        return tir_fail(c, junk, e->key, "unexpected '%.60s' after the number %.*s; expected "
                        "only a number", junk, (int)(end - text), text);
    }
    if (!isfinite(v))
        return tir_fail(c, text, e->key, "expected a finite number, got '%.60s'", text);
    *out = v;
    return TIRENV_OK;
}

static int tir_parse_count(const tir_ctx *c, const tir_key *e, const char *text, size_t *out)
{
    /* strtoull would accept "-3" as a huge count; insist on digits first. */
    if (!isdigit((unsigned char)text[0]))
        return tir_fail(c, text, e->key, "expected a positive integer, got '%.60s'", text);
    char *end;
    errno = 0;
    const unsigned long long v = strtoull(text, &end, 10);
    if (*end) {
        const char *junk = end + strspn(end, " \t");
        return tir_fail(c, junk, e->key, "unexpected '%.60s' after %.*s; expected a positive "
                        "integer", junk, (int)(end - text), text);
    }
    if (errno == ERANGE || v > SIZE_MAX || v == 0)
        return tir_fail(c, text, e->key, "expected a positive integer, got '%.60s'", text);
    *out = (size_t)v;
    return TIRENV_OK;
}

/* Parses value (trimmed, comment removed, in place) for key e and stores it in *tire. */
static int tir_apply(const tir_ctx *c, const tir_key *e, char *value, tirenv_tire *tire)
{
    if (!*value)
        return tir_fail(c, value, e->key, "missing value after '='; expected %s",
                        e->kind == TIR_REAL || e->kind == TIR_COUNT ? "a number" : "a name");
    int quoted = 0;
    if (value[0] == '\'') {
        char *close = strchr(value + 1, '\'');
        if (!close)
            return tir_fail(c, value, e->key, "unterminated string; expected a closing '");
        if (close[1])
            return tir_fail(c, close + 1, e->key, "unexpected '%.60s' after the string",
                            close + 1);
        *close = '\0';
        value++;
        quoted = 1;
    }
    if (quoted && (e->kind == TIR_REAL || e->kind == TIR_COUNT))
        return tir_fail(c, value - 1, e->key, "expected a number, got the string '%.60s'",
                        value);
    unsigned char *field = (unsigned char *)tire + e->offset;
    switch (e->kind) {
    case TIR_REAL: {
        double v = 0;
        const int status = tir_parse_real(c, e, value, &v);
        if (status == TIRENV_OK)
            memcpy(field, &v, sizeof v);
        return status;
    }
    case TIR_COUNT: {
        size_t v = 0;
        const int status = tir_parse_count(c, e, value, &v);
        if (status == TIRENV_OK)
            memcpy(field, &v, sizeof v);
        return status;
    }
    case TIR_METHOD:
        for (size_t m = 0; m < TIR_NMETHODS; m++)
            if (strcasecmp(value, tir_methods[m]) == 0) {
                const tirenv_eq_method v = (tirenv_eq_method)m;
                memcpy(field, &v, sizeof v);
                return TIRENV_OK;
            }
        return tir_fail(c, value, e->key, "unknown method '%.60s'; expected 'newton', "
                        "'secant' or 'brent'", value);
    case TIR_UNIT:
        for (size_t a = 0; a < 2 && e->accepted[a]; a++)
            if (strcasecmp(value, e->accepted[a]) == 0)
                return TIRENV_OK;
        if (e->accepted[1])
            return tir_fail(c, value, e->key, "unit '%.60s' is not supported (tirenv reads SI "
                            "only); expected '%s' or '%s'", value, e->accepted[0],
                            e->accepted[1]);
        return tir_fail(c, value, e->key, "unit '%.60s' is not supported (tirenv reads SI "
                        "only); expected '%s'", value, e->accepted[0]);
    }
    return tir_fail(c, value, e->key, "internal error: unknown key kind");
}

/* Runs the physical check on the parsed tire and points its error at the line where the
 * offending key was set (line 0 if the value did not come from this file). */
static int tir_check(const tirenv_tire *tire, const char *file, const size_t seen[],
                     tirenv_diag *diag)
{
    tirenv_diag d;
    tirenv_diag_clear(&d);
    const int status = tirenv_tire_check(tire, &d);
    if (status == TIRENV_OK)
        return TIRENV_OK;
    const char *key = d.field;
    const size_t i = tir_find_key(NULL, key);
    return tirenv_error(diag, status, file, i < TIR_NKEYS ? seen[i] : 0, key, "%s", d.message);
}

/* Handles a "[SECTION]" line; *sec becomes the section, or NULL if it is to be skipped. */
static int tir_section_line(const tir_ctx *c, char *open, const tir_section **sec)
{
    tir_strip_comment(open);
    char *close = strchr(open, ']');
    if (!close)
        return tir_fail(c, open, "", "unterminated section header; expected ']'");
    char *rest = tir_trim(close + 1);
    if (*rest)
        return tir_fail(c, rest, "", "unexpected '%.60s' after the section header", rest);
    *close = '\0';
    const char *name = tir_trim(open + 1);
    if (!*name)
        return tir_fail(c, open, "", "empty section name; expected [NAME]");
    *sec = tir_find_section(name);
    if (!*sec && strncasecmp(name, tir_own_prefix, sizeof tir_own_prefix - 1) == 0)
        return tir_fail(c, open + 1, name, "unknown section [%.60s]; expected "
                        "[ENVELOPING_SPRINGS], [ENVELOPING_RING] or [ENVELOPING_SOLVER]", name);
    return TIRENV_OK;
}

/* Handles a "KEY = value" line inside section sec. */
static int tir_key_line(const tir_ctx *c, char *text, const tir_section *sec,
                        tirenv_tire *tire, size_t seen[])
{
    tir_strip_comment(text);
    char *eq = strchr(text, '=');
    if (!eq) {
        char *gap = text + strcspn(text, " \t");
        const char saved = *gap;
        *gap = '\0';
        const int status = tir_fail(c, gap, text, "missing '='; expected KEY = value");
        *gap = saved;
        return status;
    }
    *eq = '\0';
    const char *key = tir_trim(text);
    char *value = tir_trim(eq + 1);
    if (!*key)
        return tir_fail(c, eq, "", "missing key before '='; expected KEY = value");
    const size_t i = tir_find_key(sec->name, key);
    if (i == TIR_NKEYS) {
        if (!sec->strict)
            return TIRENV_OK;
        char keys[256];
        return tir_fail(c, key, key, "unknown key in [%s]; expected one of %s", sec->name,
                        tir_key_list(sec->name, keys, sizeof keys));
    }
    if (seen[i])
        return tir_fail(c, key, tir_keys[i].key, "duplicate key (first set on line %zu); "
                        "expected each key once", seen[i]);
    seen[i] = c->line;
    return tir_apply(c, &tir_keys[i], value, tire);
}

/* One line of a .tir file: blank, comment ('!' or '$'), [SECTION] header, or KEY = value. */
static int tir_line(const tir_ctx *c, char *line, const tir_section **sec, int *in_section,
                    tirenv_tire *tire, size_t seen[])
{
    char *p = line;
    while (isspace((unsigned char)*p))
        p++;
    if (*p == '\0' || *p == '!' || *p == '$')
        return TIRENV_OK;
    if (*p == '[') {
        *in_section = 1;
        return tir_section_line(c, p, sec);
    }
    if (!*in_section)
        return tir_fail(c, p, "", "text before the first section; expected a [SECTION] "
                        "header such as [MDI_HEADER]");
    if (!*sec)
        return TIRENV_OK; /* a section of another model (MF-Tyre's [VERTICAL], [SHAPE]...) */
    return tir_key_line(c, p, *sec, tire, seen);
}

int tirenv_tir_read(const char *path, tirenv_tire *tire, tirenv_diag *diag)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open: %s", strerror(errno));
    tirenv_tire copy = *tire;   /* *tire changes only once everything has passed */
    size_t seen[TIR_NKEYS] = {0}; /* line where each key was set, for errors and duplicates */
    const tir_section *sec = NULL;
    int in_section = 0;
    char *buf = NULL;
    size_t cap = 0;
    ssize_t len;
    tir_ctx c = {path, 0, NULL, diag};
    int status = TIRENV_OK;
    while (status == TIRENV_OK && (len = getline(&buf, &cap, fp)) != -1) {
        c.line++;
        char *line = buf;
        if (c.line == 1 && strncmp(line, "\xEF\xBB\xBF", 3) == 0)
            line += 3; /* a UTF-8 byte-order mark some Windows editors add */
        c.base = line;
        status = tir_line(&c, line, &sec, &in_section, &copy, seen);
    }
    if (status == TIRENV_OK && ferror(fp))
        status = tirenv_error(diag, TIRENV_EIO, path, c.line + 1, "", "cannot read: %s",
                              strerror(errno));
    free(buf);
    fclose(fp);
    if (status == TIRENV_OK)
        status = tir_check(&copy, path, seen, diag);
    if (status == TIRENV_OK)
        *tire = copy;
    return status;
}

/* Applies "KEY = VALUE" held in buf (modified in place) to a copy of *tire. */
static int tir_set_buf(tirenv_tire *tire, char *buf, const char *assignment, tirenv_diag *diag)
{
    const tir_ctx c = {"--set", 0, NULL, diag};
    char *eq = strchr(buf, '=');
    if (!eq)
        return tir_fail(&c, NULL, "", "expected KEY=VALUE, got '%.60s'", assignment);
    *eq = '\0';
    char *key = tir_trim(buf);
    const char *section = NULL;
    char *dot = strchr(key, '.');
    if (dot) {
        *dot = '\0';
        section = key;
        key = dot + 1;
    }
    const size_t i = tir_find_key(section, key);
    if (i == TIR_NKEYS || tir_keys[i].kind == TIR_UNIT) {
        char keys[448]; /* every settable key: about 400 characters */
        return tir_fail(&c, NULL, key, "unknown key%s%s; expected one of %s",
                        section ? " in section " : "", section ? section : "",
                        tir_key_list(NULL, keys, sizeof keys));
    }
    tirenv_tire copy = *tire;
    int status = tir_apply(&c, &tir_keys[i], tir_trim(eq + 1), &copy);
    if (status == TIRENV_OK) {
        const size_t seen[TIR_NKEYS] = {0};
        status = tir_check(&copy, "--set", seen, diag);
    }
    if (status == TIRENV_OK)
        *tire = copy;
    return status;
}

/* "KEY=VALUE" or "SECTION.KEY=VALUE", for the keys that set a parameter (not [UNITS]). The
 * value is parsed as in a file. Columns are not reported: with no line number they would
 * be printed as if they were one. */
int tirenv_tir_set(tirenv_tire *tire, const char *assignment, tirenv_diag *diag)
{
    const size_t n = strlen(assignment);
    char *buf = malloc(n + 1);
    if (!buf)
        return tirenv_error(diag, TIRENV_ENOMEM, "--set", 0, "", "out of memory");
    memcpy(buf, assignment, n + 1);
    const int status = tir_set_buf(tire, buf, assignment, diag);
    free(buf);
    return status;
}

/* The shortest "%.*g" that reads back to the same double. Precision 17 always does, but
 * 0.68 then comes out as 0.68000000000000005, which a reader would take for a bug. */
static void tir_format_real(char *buf, size_t n, double v)
{
    for (int prec = 1; prec < 17; prec++) {
        snprintf(buf, n, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            return;
    }
    snprintf(buf, n, "%.17g", v);
}

static void tir_print(FILE *fp, const tirenv_tire *tire)
{
    fprintf(fp, "[MDI_HEADER]\n"
                "FILE_TYPE                = 'tir'\n"
                "FILE_VERSION             = 3.0\n"
                "FILE_FORMAT              = 'ASCII'\n"
                "! Tire property file written by tirenv %s for its enveloping models.\n"
                "! SI units; '$' starts a comment. Sections that tirenv does not know are\n"
                "! skipped, so the MF-Tyre sections of the same tire may be added below\n"
                "! (without the keys written here: each key may appear once).\n",
            TIRENV_VERSION);
    for (size_t s = 0; s < TIR_NSECTIONS; s++) {
        const char *name = tir_sections[s].name;
        fprintf(fp, "$----------------------------------------------------------------%s\n"
                    "[%s]\n", name, name);
        for (size_t i = 0; i < TIR_NKEYS; i++) {
            const tir_key *e = &tir_keys[i];
            if (strcmp(e->section, name) != 0)
                continue;
            const unsigned char *field = (const unsigned char *)tire + e->offset;
            char value[40];
            switch (e->kind) {
            case TIR_REAL: {
                double v;
                memcpy(&v, field, sizeof v);
                tir_format_real(value, sizeof value, v);
                break;
            }
            case TIR_COUNT: {
                size_t v;
                memcpy(&v, field, sizeof v);
                snprintf(value, sizeof value, "%zu", v);
                break;
            }
            case TIR_METHOD: {
                tirenv_eq_method v;
                memcpy(&v, field, sizeof v);
                snprintf(value, sizeof value, "'%s'", tir_methods[v]);
                break;
            }
            case TIR_UNIT:
                snprintf(value, sizeof value, "'%s'", e->accepted[0]);
                break;
            }
            fprintf(fp, "%-24s = %-22s $ %s\n", e->key, value, e->comment);
        }
    }
}

/* A tire that fails tirenv_tire_check is refused: its file could not be read back. */
int tirenv_tir_write(const char *path, const tirenv_tire *tire, tirenv_diag *diag)
{
    int status = tirenv_tire_check(tire, diag);
    if (status != TIRENV_OK)
        return status;
    tirenv_outfile f;
    status = tirenv_outfile_open(&f, path, diag);
    if (status != TIRENV_OK)
        return status;
    tir_print(f.fp, tire);
    return tirenv_outfile_commit(&f, diag);
}
