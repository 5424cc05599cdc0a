/* TNO / Adams 2-D road files (TeimOrbit: [BLOCK]s of KEY = value, (SUB_BLOCK)s, {table}
 * headers, '$' and '!' comments): 'poly_line', 'plank' and 'flat' roads read as a profile
 * (docs/formats.md section 5). SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/rdf.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "formats/propfile.h"
#include "formats/rdf_impl.h"
#include "formats/road_file_impl.h"
#include "formats/units.h"
#include "io/io.h"

static const char *const side_names[] = {"mean", "left", "right"};

const char *tirenv_rdf_side_name(tirenv_rdf_side side)
{
    return (unsigned)side < 3 ? side_names[side] : NULL;
}

int tirenv_rdf_side_find(const char *name, tirenv_rdf_side *side)
{
    for (int k = 0; k < 3; k++)
        if (name && strcasecmp(name, side_names[k]) == 0) {
            *side = (tirenv_rdf_side)k;
            return TIRENV_OK;
        }
    return TIRENV_EINVAL;
}

/* The numeric road keys, read from [PARAMETERS] or [MODEL] (files put a plank's keys in
 * either). */
enum { K_OFFSET, K_ROTATION, K_MU, K_HEIGHT, K_START, K_LENGTH, K_BEVEL, K_DIRECTION,
       K_EDGE_ROUNDED, K_MU_CLEAT, N_KEYS };
static const char *const key_names[N_KEYS] = {
    "OFFSET", "ROTATION_ANGLE_XY_PLANE", "MU", "HEIGHT", "START", "LENGTH",
    "BEVEL_EDGE_LENGTH", "DIRECTION", "EDGE_ROUNDED", "MU_FACTOR_CLEAT",
};

typedef struct {
    double value;
    size_t line;
} setting;

typedef enum { B_OTHER, B_HEADER, B_UNITS, B_MODEL, B_PARAMETERS } block;

/* A whole read's rows in file units, x and the side's z (before OFFSET), in blocks that are
 * freed as the profile's arrays take them, so that a road whole takes 32 bytes a row at its
 * peak (the blocks or the arrays, then the arrays and the profile), not a growing array's up
 * to 48 and a second reading of the file. */
enum { BLOCK_ROWS = 32768 };
struct block {
    struct block *next;
    size_t n;
    double x[BLOCK_ROWS], zs[BLOCK_ROWS];
};

typedef struct {
    tirenv_propfile__where at; /* the source's name, the line being read */
    block blk;
    int in_xz;                 /* rows of (XZ_DATA) follow */
    int in_table;              /* rows of another sub-block's table follow: (COMMENTS)... */
    size_t xz_line;
    setting keys[N_KEYS];
    setting unit[TIRENV_UNIT_KINDS]; /* value: factor to SI */
    char method[16], road_type[24];
    size_t method_line, road_type_line;
    size_t next_offset;        /* byte offset of the line after the one being read */
    size_t xz_offset;          /* ... after (XZ_DATA)'s: where its rows start */
    tirenv_rdf__check check;   /* the rows as the scan meets them */
    int gather;                /* keep the rows of gather_side as they pass (a whole read) */
    tirenv_rdf_side gather_side;
    struct block *blocks, *last_block;
} rdf;

#define fail(r, ...) tirenv_propfile__fail(&(r)->at, __VA_ARGS__)

/* '$' and '!' start a comment, except inside a quoted string. */
static void strip_comment(char *s)
{
    int quoted = 0;
    for (; *s; s++) {
        if (*s == '\'')
            quoted = !quoted;
        else if ((*s == '$' || *s == '!') && !quoted) {
            *s = '\0';
            return;
        }
    }
}

/* A quoted string's contents, or a bare word; *out points into value (modified). */
static int string_value(const rdf *r, char *value, const char *key, char **out)
{
    if (value[0] == '\'') {
        char *close = strchr(value + 1, '\'');
        if (!close)
            return fail(r, value, key, "unterminated string; expected a closing '");
        if (*tirenv_propfile__trim(close + 1))
            return fail(r, close + 1, key, "unexpected '%.40s' after the string", close + 1);
        *close = '\0';
        *out = tirenv_propfile__trim(value + 1);
        return TIRENV_OK;
    }
    if (!*value)
        return fail(r, value, key, "missing value after '='");
    *out = value;
    return TIRENV_OK;
}

static int set_once(const rdf *r, setting *s, const char *key, const char *at, double v)
{
    if (s->line)
        return fail(r, at, key, "set twice (first on line %zu); expected each key once",
                    s->line);
    s->value = v;
    s->line = r->at.line;
    return TIRENV_OK;
}

static int units_key(rdf *r, const char *key, char *value)
{
    for (int k = 0; k < TIRENV_UNIT_KINDS; k++) {
        if (strcasecmp(key, tirenv_units__key((tirenv_unit_kind)k)) != 0)
            continue;
        char *name = NULL;
        int status = string_value(r, value, key, &name);
        if (status)
            return status;
        double f;
        if (tirenv_units__factor((tirenv_unit_kind)k, name, &f) != TIRENV_OK) {
            char list[512];
            return fail(r, name, tirenv_units__key((tirenv_unit_kind)k), "unknown unit "
                        "'%.30s'; expected one of %s", name,
                        tirenv_units__list((tirenv_unit_kind)k, list, sizeof list));
        }
        return set_once(r, &r->unit[k], tirenv_units__key((tirenv_unit_kind)k), name, f);
    }
    return fail(r, key, key, "unknown key in [UNITS]; expected LENGTH, FORCE, ANGLE, MASS, "
                "TIME or PRESSURE");
}

static int copy_name(const rdf *r, char *value, const char *key, char *dst, size_t n,
                     size_t *line)
{
    char *s = NULL;
    const int status = string_value(r, value, key, &s);
    if (status)
        return status;
    if (*line)
        return fail(r, value, key, "set twice (first on line %zu); expected each key once",
                    *line);
    snprintf(dst, n, "%s", s);
    *line = r->at.line;
    return TIRENV_OK;
}

static int key_line(rdf *r, char *text)
{
    char *eq = strchr(text, '=');
    if (!eq)
        return fail(r, text, "", "unexpected '%.40s'; expected KEY = value, a [BLOCK] or a "
                    "(SUB_BLOCK)", text);
    *eq = '\0';
    char *key = tirenv_propfile__trim(text), *value = tirenv_propfile__trim(eq + 1);
    if (!*key)
        return fail(r, eq, "", "missing key before '='");
    switch (r->blk) {
    case B_OTHER:
        return TIRENV_OK;
    case B_HEADER:
        if (strcasecmp(key, "FILE_TYPE") == 0) {
            char *type;
            const int status = string_value(r, value, key, &type);
            if (status)
                return status;
            if (strcasecmp(type, "rdf") != 0)
                return fail(r, type, "FILE_TYPE", "'%.20s' is not a road file; expected "
                            "'rdf'", type);
        }
        return TIRENV_OK;
    case B_UNITS:
        return units_key(r, key, value);
    case B_MODEL:
        if (strcasecmp(key, "METHOD") == 0)
            return copy_name(r, value, "METHOD", r->method, sizeof r->method, &r->method_line);
        if (strcasecmp(key, "ROAD_TYPE") == 0)
            return copy_name(r, value, "ROAD_TYPE", r->road_type, sizeof r->road_type,
                             &r->road_type_line);
        break;
    case B_PARAMETERS:
        if (r->in_xz)
            return fail(r, key, key, "KEY = value inside (XZ_DATA); expected rows of x, z_left "
                        "and z_right");
        break;
    }
    for (int k = 0; k < N_KEYS; k++)
        if (strcasecmp(key, key_names[k]) == 0) {
            double v = 0;
            const int status = tirenv_propfile__real(&r->at, key_names[k], value, &v);
            return status ? status : set_once(r, &r->keys[k], key_names[k], key, v);
        }
    if (r->blk == B_MODEL)
        return TIRENV_OK; /* other programs' model settings */
    return fail(r, key, key, "unknown key in [PARAMETERS]; expected OFFSET, "
                "ROTATION_ANGLE_XY_PLANE, MU, the plank's HEIGHT, START, LENGTH, "
                "BEVEL_EDGE_LENGTH, DIRECTION, or the (XZ_DATA) table");
}

/* One row of (XZ_DATA): x, z_left and z_right in file units. */
static int xz_parse(const tirenv_propfile__where *at, char *text, double v[3])
{
    char *p = text;
    for (int k = 0; k < 4; k++) {
        while (*p == ' ' || *p == '\t' || *p == ',')
            p++;
        if (k == 3) {
            if (*p)
                return tirenv_propfile__fail(at, p, "XZ_DATA", "unexpected '%.40s' after three "
                                             "numbers; expected rows of x, z_left, z_right", p);
            break;
        }
        static const char *const col[3] = {"x", "z_left", "z_right"};
        if (!*p)
            return tirenv_propfile__fail(at, p, "XZ_DATA", "missing %s; expected rows of x, "
                                         "z_left, z_right", col[k]);
        char *end;
        v[k] = strtod(p, &end);
        if (end == p || !isfinite(v[k]) || (*end && !strchr(" \t,", *end)))
            return tirenv_propfile__fail(at, p, "XZ_DATA", "%s: expected a finite number, got "
                                         "'%.*s'", col[k], (int)(strcspn(p, " \t,") < 30
                                                                 ? strcspn(p, " \t,") : 30), p);
        p = end;
    }
    return TIRENV_OK;
}

/* The height of a row on side in file units, before OFFSET. */
static double side_zs(tirenv_rdf_side side, const double v[3])
{
    return side == TIRENV_RDF_LEFT ? v[1] : side == TIRENV_RDF_RIGHT ? v[2] : 0.5 * (v[1] + v[2]);
}

/* ... in m: f (zs + offset), as the whole read always took it. */
static double side_z(tirenv_rdf_side side, const double v[3], double f, double offset)
{
    return f * (side_zs(side, v) + offset);
}

/* tirenv_profile_validate's checks (tirenv_profile_check_vertex) on the row just read, for the
 * three sides at once, so that a road's rows are checked as they pass, without being kept: the
 * first failure of each side is kept (its line and words), and reported as the whole read
 * reported it, after the file's other checks (tirenv_rdf__side). */
static void check_row(tirenv_rdf__check *c, const double v[3], double f, double offset,
                      size_t line)
{
    const size_t k = c->n++;
    const double x = f * v[0];
    /* The sides, then their mean, which is made of both: where the mean passes and a side is
     * refused at this row, the mean is refused with it, so that 1e308 on one side and -1e308
     * on the other is no mean of 0. */
    static const tirenv_rdf_side order[3] = {TIRENV_RDF_LEFT, TIRENV_RDF_RIGHT, TIRENV_RDF_MEAN};
    for (int i = 0; i < 3; i++) {
        const tirenv_rdf_side s = order[i];
        tirenv_rdf__bad *b = &c->bad[s];
        tirenv_diag d;
        if (b->line || tirenv_profile_check_vertex(k, x, side_z(s, v, f, offset), c->x1, c->x2,
                                                   &d) == TIRENV_OK) {
            const tirenv_rdf__bad *l = &c->bad[TIRENV_RDF_LEFT], *r = &c->bad[TIRENV_RDF_RIGHT];
            if (s == TIRENV_RDF_MEAN && !b->line && (l->line == line || r->line == line))
                *b = l->line == line ? *l : *r;
            continue;
        }
        snprintf(b->message, sizeof b->message, "%s", d.message);
        b->line = line;
    }
    c->x2 = c->x1;
    c->x1 = x;
    if (k == 0)
        c->x_first = v[0];
    c->x_last = v[0];
}

static int xz_row(rdf *r, char *text)
{
    double v[3];
    const int status = xz_parse(&r->at, text, v);
    if (status)
        return status;
    tirenv_rdf__check *c = &r->check;
    if (c->n == 0)
        c->first_line = r->at.line;
    /* Checked now where the length unit is known; where it comes after the rows, the rows
     * are checked again once it is (tirenv_rdf__open), as is every row read before a late
     * OFFSET. */
    if (!r->unit[TIRENV_UNIT_LENGTH].line)
        c->deferred = 1;
    check_row(c, v, r->unit[TIRENV_UNIT_LENGTH].value, r->keys[K_OFFSET].value, r->at.line);
    if (!r->gather)
        return TIRENV_OK;
    struct block *b = r->last_block;
    if (!b || b->n == BLOCK_ROWS) {
        if (!(b = malloc(sizeof *b)))
            return tirenv_error(r->at.diag, TIRENV_ENOMEM, r->at.file, r->at.line, "",
                                "out of memory");
        b->next = NULL;
        b->n = 0;
        *(r->last_block ? &r->last_block->next : &r->blocks) = b;
        r->last_block = b;
    }
    b->x[b->n] = v[0];
    b->zs[b->n] = side_zs(r->gather_side, v);  /* f (zs + offset) at the end: side_z's */
    b->n++;
    return TIRENV_OK;
}

static void free_blocks(struct block *b)
{
    while (b) {
        struct block *next = b->next;
        free(b);
        b = next;
    }
}

static block block_of(const char *name)
{
    return strcasecmp(name, "MDI_HEADER") == 0   ? B_HEADER
           : strcasecmp(name, "UNITS") == 0      ? B_UNITS
           : strcasecmp(name, "MODEL") == 0      ? B_MODEL
           : strcasecmp(name, "PARAMETERS") == 0 ? B_PARAMETERS
                                                  : B_OTHER;
}

static int bracketed(rdf *r, char *text, char close, char **name)
{
    char *end = strchr(text, close);
    if (!end)
        return fail(r, text, "", "unterminated '%c'; expected '%c'", text[0], close);
    const char *rest = tirenv_propfile__trim(end + 1);
    if (*rest)
        return fail(r, rest, "", "unexpected '%.40s' after '%c'", rest, close);
    *end = '\0';
    *name = tirenv_propfile__trim(text + 1);
    return TIRENV_OK;
}

static int line_of(rdf *r, char *text)
{
    strip_comment(text);
    text = tirenv_propfile__trim(text);
    if (!*text)
        return TIRENV_OK;
    char *name = NULL;
    int status;
    if (text[0] == '[') {
        if ((status = bracketed(r, text, ']', &name)))
            return status;
        r->blk = block_of(name);
        r->in_xz = r->in_table = 0;
        return TIRENV_OK;
    }
    if (text[0] == '(') {
        if ((status = bracketed(r, text, ')', &name)))
            return status;
        r->in_xz = r->blk == B_PARAMETERS && strcasecmp(name, "XZ_DATA") == 0;
        r->in_table = !r->in_xz;
        if (r->in_xz && r->xz_line)
            return fail(r, name, "XZ_DATA", "(XZ_DATA) given twice (first on line %zu)",
                        r->xz_line);
        if (r->in_xz) {
            r->xz_line = r->at.line;
            r->xz_offset = r->next_offset;
        }
        return TIRENV_OK;
    }
    if (text[0] == '{' || r->blk == B_OTHER)
        return TIRENV_OK; /* a table's column names; another program's block */
    if (r->in_xz && !strchr(text, '='))
        return xz_row(r, text);
    /* A row of another table, such as the quoted lines of [MDI_HEADER] (COMMENTS) that
     * Adams files carry: not tirenv's to read. */
    if (r->in_table && (text[0] == '\'' || !strchr(text, '=')))
        return TIRENV_OK;
    return key_line(r, text);
}

/* ---- the road ------------------------------------------------------------------------- */

struct tirenv_rdf__road {
    const tirenv_source *src;  /* the file's bytes (the caller's, outliving the road) */
    double f;                  /* [UNITS] LENGTH: m per file unit */
    double offset;             /* [PARAMETERS] OFFSET, file units */
    size_t xz_offset, xz_line; /* where (XZ_DATA)'s rows start: byte offset, line before */
    tirenv_rdf__check check;   /* the rows: how many, their ends, each side's first failure */
    tirenv_profile *small;     /* a 'plank' or 'flat' road whole; NULL for a 'poly_line' */
};

static int need_unit(rdf *r, tirenv_unit_kind kind, const char *why, double *f)
{
    if (r->unit[kind].line) {
        *f = r->unit[kind].value;
        return TIRENV_OK;
    }
    r->at.line = 0;
    return fail(r, NULL, tirenv_units__key(kind), "no [UNITS] %s; expected it for %s",
                tirenv_units__key(kind), why);
}

static int profile_of(rdf *r, size_t n, const double x[], const double z[],
                      tirenv_profile **out)
{
    tirenv_diag d;
    tirenv_diag_clear(&d);
    if (tirenv_profile_validate(n, x, z, &d) != TIRENV_OK) {
        r->at.line = r->road_type_line;  /* its vertices are the road type's keys' */
        return fail(r, NULL, "ROAD_TYPE", "the '%s' road its keys describe is no profile: %s",
                    r->road_type, d.message);
    }
    if (!(*out = tirenv_profile_alloc(n, x, z)))
        return tirenv_error(r->at.diag, TIRENV_ENOMEM, r->at.file, 0, "", "out of memory");
    return TIRENV_OK;
}

/* A poly_line road's rows are read as they are wanted (tirenv_rdf__rows); here, only that
 * there are some. Their checks were made as the scan passed them (check_row). */
static int poly_line(rdf *r)
{
    if (!r->xz_line || r->check.n == 0) {
        r->at.line = r->xz_line ? r->xz_line : r->road_type_line;
        return fail(r, NULL, "XZ_DATA", "ROAD_TYPE 'poly_line' without %s; expected rows of "
                    "x, z_left, z_right in [PARAMETERS] (XZ_DATA)",
                    r->xz_line ? "rows in (XZ_DATA)" : "an (XZ_DATA) table");
    }
    return TIRENV_OK;
}

/* A plank across the road (DIRECTION 0) from START, LENGTH long along x including its 45-degree
 * bevel edges of BEVEL_EDGE_LENGTH along x at its top corners; a negative HEIGHT mirrors it
 * into a depression. */
static int plank(rdf *r, double f, double offset, tirenv_profile **out)
{
    const int req[] = {K_HEIGHT, K_START, K_LENGTH};
    for (size_t k = 0; k < 3; k++)
        if (!r->keys[req[k]].line) {
            r->at.line = r->road_type_line;
            return fail(r, NULL, key_names[req[k]], "ROAD_TYPE 'plank' needs %s in "
                        "[PARAMETERS]; expected HEIGHT, START and LENGTH", key_names[req[k]]);
        }
    const double H = r->keys[K_HEIGHT].value, S = r->keys[K_START].value;
    const double L = r->keys[K_LENGTH].value, b = r->keys[K_BEVEL].value;
    if (r->keys[K_DIRECTION].value != 0) {
        r->at.line = r->keys[K_DIRECTION].line;
        return fail(r, NULL, "DIRECTION", "%.17g: an oblique plank meets each wheel track at "
                    "another x, and a 2-D profile is one track; expected 0 (a plank across "
                    "the road)", r->keys[K_DIRECTION].value);
    }
    if (r->keys[K_EDGE_ROUNDED].value != 0) {
        r->at.line = r->keys[K_EDGE_ROUNDED].line;
        return fail(r, NULL, "EDGE_ROUNDED", "rounded plank edges are not supported; expected "
                    "0 (45-degree bevel edges)");
    }
    /* The corners in m must make a profile (tirenv_profile_validate), checked here at the
     * key that breaks it: a START of 1e300 or a LENGTH of 1e-300 at x = 1 was refused as
     * "vertex 1: x = 1e+300 m" or "vertex 3: x = 1 is shared by three vertices", vertices the
     * file does not have. What these miss (a bevel too short to tell from a corner where its
     * heights differ) profile_of says at ROAD_TYPE. */
    const double x0 = f * S, x1 = f * (S + L), top = f * (fabs(H) + fabs(offset));
    /* A bound, where a check has one, is printed from its constant (bound 0: none). */
    const double c_max = TIRENV_PROFILE_MAX_COORDINATE, seg_max = TIRENV_PROFILE_MAX_SEGMENT;
    const struct { int key; int bad; const char *want; double bound; const char *why; } checks[] = {
        {K_LENGTH, !(L > 0), "a positive length", 0, ""},
        {K_BEVEL, !(b >= 0), "a length >= 0", 0, ""},
        {K_BEVEL, !(2 * b <= L), "at most half of LENGTH (a bevel at each edge)", 0, ""},
        {K_BEVEL, !(b <= fabs(H)), "at most |HEIGHT| (a 45-degree bevel cannot rise higher)", 0,
         ""},
        {K_START, !(fabs(x0) <= c_max), "a position within +-", c_max, ", a road's coordinates"},
        {K_LENGTH, !(fabs(x1) <= c_max), "a plank ending within +-", c_max,
         " of x = 0, a road's coordinates"},
        {K_LENGTH, !(x1 - x0 <= seg_max), "at most ", seg_max, ", a road's longest segment"},
        {K_OFFSET, !(fabs(f * offset) <= c_max), "a height within +-", c_max,
         ", a road's coordinates"},
        {K_HEIGHT, !(top <= c_max), "a height (with OFFSET) within +-", c_max,
         ", a road's coordinates"},
        {K_LENGTH, !(x1 > x0), "a plank long enough that its ends differ at START in double "
         "precision", 0, ""},
    };
    for (size_t k = 0; k < sizeof checks / sizeof checks[0]; k++)
        if (checks[k].bad) {
            r->at.line = r->keys[checks[k].key].line;
            const double v = r->keys[checks[k].key].value;
            const char *name = key_names[checks[k].key];
            if (checks[k].bound > 0)
                return fail(r, NULL, name, "%.17g; expected %s%g m%s", v, checks[k].want,
                            checks[k].bound, checks[k].why);
            return fail(r, NULL, name, "%.17g; expected %s", v, checks[k].want);
        }
    const double s = H < 0 ? -1 : 1, shoulder = s * (fabs(H) - b);
    const double px[] = {S, S, S + b, S + L - b, S + L, S + L};
    const double pz[] = {0, shoulder, H, H, shoulder, 0};
    double x[6], z[6];
    size_t n = 0;
    for (size_t k = 0; k < 6; k++) {
        if (n > 0 && px[k] == px[k - 1] && pz[k] == pz[k - 1])
            continue; /* a corner that a zero bevel or a full bevel removes */
        x[n] = f * px[k];
        z[n] = f * (pz[k] + offset);
        n++;
    }
    return profile_of(r, n, x, z, out);
}

/* The file's checks after its last line, for every side; *small is a plank's or a flat
 * road's profile, NULL for a poly_line. */
static int road(rdf *r, tirenv_profile **small)
{
    *small = NULL;
    r->at.base = NULL;
    if (!r->method_line || !r->road_type_line) {
        r->at.line = r->method_line ? r->method_line : r->road_type_line;
        return fail(r, NULL, r->method_line ? "ROAD_TYPE" : "METHOD", "missing in [MODEL]; "
                    "expected METHOD = '2D' and ROAD_TYPE");
    }
    if (strcasecmp(r->method, "2D") != 0) {
        r->at.line = r->method_line;
        return fail(r, NULL, "METHOD", "'%s': tirenv reads 2-D roads; expected '2D'",
                    r->method);
    }
    double f = 1;
    const int status = need_unit(r, TIRENV_UNIT_LENGTH, "the road's lengths", &f);
    if (status)
        return status;
    const double offset = r->keys[K_OFFSET].value;
    if (strcasecmp(r->road_type, "poly_line") == 0)
        return poly_line(r);
    if (strcasecmp(r->road_type, "plank") == 0)
        return plank(r, f, offset, small);
    if (strcasecmp(r->road_type, "flat") == 0) {
        const double x = 0, z = f * offset;
        return profile_of(r, 1, &x, &z, small);
    }
    r->at.line = r->road_type_line;
    return fail(r, NULL, "ROAD_TYPE", "'%s' is not supported; expected 'poly_line', 'plank' "
                "or 'flat'", r->road_type);
}

/* ---- a poly_line's rows, one at a time ------------------------------------------------- */

struct tirenv_rdf__rows {
    const tirenv_rdf__road *road;
    tirenv_rdf_side side;
    tirenv_lines lines;        /* poly_line: from the line after (XZ_DATA)'s */
    tirenv_propfile__where at;
    size_t k;                  /* rows (vertices of a small road) given */
};

/* The next row in file units (*got 0 after the last of the scan's rows). The rows were
 * checked by the scan; a row that does not parse now, or rows that end early, mean that the
 * file changed under the reader. */
static int raw_next(tirenv_rdf__rows *w, double v[3], int *got, tirenv_diag *diag)
{
    *got = 0;
    if (w->k >= w->road->check.n)
        return TIRENV_OK;
    w->at.diag = diag;
    for (;;) {
        const int more = tirenv_lines__next(&w->lines, diag);
        if (more < 0)
            return -more;
        char *text = more ? w->lines.text : NULL;
        if (text) {
            strip_comment(text);
            text = tirenv_propfile__trim(text);
            if (!*text || text[0] == '{')
                continue;  /* a blank or comment line, a table's column names */
        }
        if (!text || text[0] == '[' || text[0] == '(' || strchr(text, '='))
            return tirenv_error(diag, TIRENV_EIO, w->at.file, w->lines.line, "XZ_DATA",
                                "%zu rows of (XZ_DATA) where %zu were read before; did the "
                                "file change while being read?", w->k, w->road->check.n);
        w->at.line = w->lines.line;
        w->at.base = w->lines.text;
        const int status = xz_parse(&w->at, text, v);
        if (status)
            return status;
        w->k++;
        *got = 1;
        return TIRENV_OK;
    }
}

int tirenv_rdf__rows_open(const tirenv_rdf__road *road, tirenv_rdf_side side,
                          tirenv_rdf__rows **out, tirenv_diag *diag)
{
    *out = NULL;
    tirenv_rdf__rows *w = calloc(1, sizeof *w);
    if (!w)
        return tirenv_error(diag, TIRENV_ENOMEM, road->src->name, 0, "", "out of memory");
    *w = (tirenv_rdf__rows){.road = road, .side = side, .at = {.file = road->src->name}};
    if (!road->small) {
        const int status = tirenv_lines__init(&w->lines, road->src, road->xz_offset,
                                              road->xz_line + 1, diag);
        if (status) {
            free(w);
            return status;
        }
    }
    *out = w;
    return TIRENV_OK;
}

int tirenv_rdf__rows_next(tirenv_rdf__rows *w, double *x, double *z, int *got,
                          tirenv_diag *diag)
{
    *got = 0;
    const tirenv_rdf__road *road = w->road;
    if (road->small) {
        if (w->k < tirenv_profile_size(road->small)) {
            *x = tirenv_profile_x(road->small)[w->k];
            *z = tirenv_profile_z(road->small)[w->k];
            w->k++;
            *got = 1;
        }
        return TIRENV_OK;
    }
    double v[3];
    const int status = raw_next(w, v, got, diag);
    if (!status && *got) {
        *x = road->f * v[0];
        *z = side_z(w->side, v, road->f, road->offset);
    }
    return status;
}

void tirenv_rdf__rows_free(tirenv_rdf__rows *w)
{
    if (!w)
        return;
    tirenv_lines__free(&w->lines);
    free(w);
}

/* ---- the scan ---------------------------------------------------------------------------- */

/* The rows checked again with the final unit and OFFSET, where either was set after the
 * first row (xz_row): the scan's checks used what was known at each row. */
static int recheck(tirenv_rdf__road *road, tirenv_diag *diag)
{
    tirenv_rdf__check c = {0};
    tirenv_rdf__rows *w;
    int status = tirenv_rdf__rows_open(road, TIRENV_RDF_MEAN, &w, diag);
    for (int got = 1; !status && got;) {
        double v[3];
        status = raw_next(w, v, &got, diag);
        if (!status && got)
            check_row(&c, v, road->f, road->offset, w->at.line);
    }
    tirenv_rdf__rows_free(w);
    if (!status) {
        c.first_line = road->check.first_line;
        road->check = c;
    }
    return status;
}

void tirenv_rdf__free(tirenv_rdf__road *road)
{
    if (!road)
        return;
    tirenv_profile_free(road->small);
    free(road);
}

/* One pass over the file: its keys, its blocks, and a poly_line's rows checked as they pass
 * and not kept (their count, their first and last x and each side's first failure are), so
 * that the memory a road takes does not grow with its length; r->gather keeps one side's
 * rows (r->blocks) for a whole read. */
static int scan(const tirenv_source *src, rdf *r, tirenv_rdf__road **out)
{
    *out = NULL;
    tirenv_lines lines;
    int status = tirenv_lines__init(&lines, src, 0, 1, r->at.diag);
    if (status)
        return status;
    int got;
    while (!status && (got = tirenv_lines__next(&lines, r->at.diag)) > 0) {
        r->at.line = lines.line;
        r->next_offset = lines.pos;
        char *text = lines.text;
        if (r->at.line == 1 && strncmp(text, "\xEF\xBB\xBF", 3) == 0)
            text += 3;
        r->at.base = text;
        /* The last line, cut maybe: refused when it holds more than blanks or a comment. */
        if (!lines.eol && (status = tirenv_text__check_unterminated(r->at.diag, src->name,
                                                                    lines.line, text, "$!")))
            break;
        status = line_of(r, text);
    }
    if (!status && got < 0)
        status = -got;
    tirenv_lines__free(&lines);
    tirenv_profile *small = NULL;
    if (!status)
        status = road(r, &small);
    tirenv_rdf__road *road = NULL;
    if (!status && !(road = malloc(sizeof *road)))
        status = tirenv_error(r->at.diag, TIRENV_ENOMEM, src->name, 0, "", "out of memory");
    if (!status) {
        *road = (tirenv_rdf__road){.src = src, .f = r->unit[TIRENV_UNIT_LENGTH].value,
                                   .offset = r->keys[K_OFFSET].value,
                                   .xz_offset = r->xz_offset, .xz_line = r->xz_line,
                                   .check = r->check, .small = small};
        small = NULL;
        if (!road->small &&
            (r->check.deferred || r->keys[K_OFFSET].line > r->check.first_line))
            status = recheck(road, r->at.diag);
    }
    tirenv_profile_free(small);
    if (status) {
        tirenv_rdf__free(road);
        return status;
    }
    *out = road;
    return TIRENV_OK;
}

int tirenv_rdf__open(const tirenv_source *src, tirenv_rdf__road **out, tirenv_diag *diag)
{
    rdf r = {.at = {.file = src->name, .diag = diag}};
    return scan(src, &r, out);
}

/* The gathered rows as the profile on side: the blocks freed as the arrays take them. */
static int gathered(const tirenv_rdf__road *road, rdf *r, tirenv_profile **out,
                    tirenv_diag *diag)
{
    const char *name = road->src->name;
    const size_t n = road->check.n;
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    int status = TIRENV_OK;
    if (!x || !z)
        status = tirenv_error(diag, TIRENV_ENOMEM, name, 0, "", "out of memory");
    size_t k = 0;
    while (!status && r->blocks) {
        struct block *b = r->blocks;
        for (size_t i = 0; i < b->n && k < n; ++i, ++k) {
            x[k] = road->f * b->x[i];
            z[k] = road->f * (b->zs[i] + road->offset);
        }
        r->blocks = b->next;
        free(b);
    }
    r->last_block = NULL;
    if (!status && k != n)  /* a recheck found other rows than the scan: the file changed */
        status = tirenv_error(diag, TIRENV_EIO, name, 0, "XZ_DATA", "%zu rows of (XZ_DATA) "
                              "where %zu were read before; did the file change while being "
                              "read?", n, k);
    if (!status && !(*out = tirenv_profile_alloc(n, x, z)))
        status = tirenv_error(diag, TIRENV_ENOMEM, name, 0, "", "out of memory");
    free(x);
    free(z);
    return status;
}

int tirenv_rdf__open_whole(const tirenv_source *src, tirenv_rdf_side side,
                           tirenv_rdf__road **road, tirenv_profile **out, tirenv_diag *diag)
{
    *road = NULL;
    *out = NULL;
    if (!tirenv_rdf_side_name(side))
        return tirenv_error(diag, TIRENV_EINVAL, src->name, 0, "side", "unknown side %d",
                            (int)side);
    rdf r = {.at = {.file = src->name, .diag = diag}, .gather = 1, .gather_side = side};
    int status = scan(src, &r, road);
    if (!status && !(status = tirenv_rdf__side(*road, side, diag)))
        status = (*road)->small ? tirenv_rdf__profile(*road, side, out, diag)
                                : gathered(*road, &r, out, diag);
    free_blocks(r.blocks);
    return status;
}

int tirenv_rdf__side(const tirenv_rdf__road *road, tirenv_rdf_side side, tirenv_diag *diag)
{
    if (!tirenv_rdf_side_name(side))
        return tirenv_error(diag, TIRENV_EINVAL, road->src->name, 0, "side", "unknown side %d",
                            (int)side);
    const tirenv_rdf__bad *b = &road->check.bad[side];
    if (road->small || !b->line)
        return TIRENV_OK;
    const tirenv_propfile__where at = {.file = road->src->name, .line = b->line, .diag = diag};
    return tirenv_propfile__fail(&at, NULL, "XZ_DATA", "%s", b->message);
}

void tirenv_rdf__extent(const tirenv_rdf__road *road, double *first, double *last)
{
    if (road->small) {
        tirenv_profile_extent(road->small, first, last);
        return;
    }
    *first = road->f * road->check.x_first;
    *last = road->f * road->check.x_last;
}

int tirenv_rdf__profile(const tirenv_rdf__road *road, tirenv_rdf_side side,
                        tirenv_profile **out, tirenv_diag *diag)
{
    *out = NULL;
    int status = tirenv_rdf__side(road, side, diag);
    if (status)
        return status;
    const char *name = road->src->name;
    const tirenv_profile *p = road->small;
    if (p) {
        if (!(*out = tirenv_profile_alloc(tirenv_profile_size(p), tirenv_profile_x(p),
                                          tirenv_profile_z(p))))
            return tirenv_error(diag, TIRENV_ENOMEM, name, 0, "", "out of memory");
        return TIRENV_OK;
    }
    const size_t n = road->check.n;
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    tirenv_rdf__rows *w = NULL;
    if (!x || !z)
        status = tirenv_error(diag, TIRENV_ENOMEM, name, 0, "", "out of memory");
    else
        status = tirenv_rdf__rows_open(road, side, &w, diag);
    for (size_t k = 0; !status && k < n; k++) {
        int got = 0;
        status = tirenv_rdf__rows_next(w, &x[k], &z[k], &got, diag);
    }
    tirenv_rdf__rows_free(w);
    if (!status && !(*out = tirenv_profile_alloc(n, x, z)))
        status = tirenv_error(diag, TIRENV_ENOMEM, name, 0, "", "out of memory");
    free(x);
    free(z);
    return status;
}

/* tirenv_rdf_read from a source: the road scanned once, its rows gathered as they pass. */
static int read_source(const tirenv_source *src, tirenv_rdf_side side, tirenv_profile **out,
                       tirenv_diag *diag)
{
    tirenv_rdf__road *road;
    const int status = tirenv_rdf__open_whole(src, side, &road, out, diag);
    tirenv_rdf__free(road);
    return status;
}

int tirenv_rdf_read(const char *path, tirenv_rdf_side side, tirenv_profile **out,
                    tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    tirenv_source src;
    int status = tirenv_source__open_file(&src, path, diag);
    if (status)
        return status;
    status = read_source(&src, side, out, diag);
    tirenv_source__close(&src);
    return status;
}

int tirenv_rdf_read_memory(const void *data, size_t size, const char *name,
                           tirenv_rdf_side side, tirenv_profile **out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    tirenv_source src;
    int status = tirenv_source__open_memory(&src, data, size, name, diag);
    if (status)
        return status;
    status = read_source(&src, side, out, diag);
    tirenv_source__close(&src);
    return status;
}
