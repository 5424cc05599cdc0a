/* The OpenCRG header: sections ($CT, $ROAD_CRG, $ROAD_CRG_MPRO, $KD_DEFINITION,
 * $ROAD_CRG_OPTS, $ROAD_CRG_MODS), "KEY = value" records, the data definition's "#:" format
 * and "D:" channels, '*' comment lines, '!' comments, and the "$$$$" line that ends the header
 * (docs/formats.md section 5). Written from the ASAM OpenCRG specification, section 6.
 * SPDX-License-Identifier: Apache-2.0 */
#include "formats/crg_impl.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "formats/propfile.h"

/* Header records are at most 72 characters; the specification says anything beyond is
 * ignored. */
enum { RECORD = 72 };

static const char *const road_names[CRG_ROAD_KEYS] = {
    "REFERENCE_LINE_START_U", "REFERENCE_LINE_END_U", "REFERENCE_LINE_INCREMENT",
    "LONG_SECTION_V_RIGHT", "LONG_SECTION_V_LEFT", "LONG_SECTION_V_INCREMENT",
    "REFERENCE_LINE_START_S", "REFERENCE_LINE_END_S", "REFERENCE_LINE_START_B",
    "REFERENCE_LINE_END_B", "REFERENCE_LINE_START_X", "REFERENCE_LINE_START_Y",
    "REFERENCE_LINE_END_X", "REFERENCE_LINE_END_Y", "REFERENCE_LINE_OFFSET_X",
    "REFERENCE_LINE_OFFSET_Y", "REFERENCE_LINE_START_PHI", "REFERENCE_LINE_END_PHI",
    "REFERENCE_LINE_OFFSET_PHI", "REFERENCE_LINE_START_Z", "REFERENCE_LINE_END_Z",
    "REFERENCE_LINE_OFFSET_Z", "REFERENCE_LINE_START_LON", "REFERENCE_LINE_START_LAT",
    "REFERENCE_LINE_END_LON", "REFERENCE_LINE_END_LAT", "REFERENCE_LINE_START_ALT",
    "REFERENCE_LINE_END_ALT",
};

/* Every option of the specification. Those with used >= 0 change a track; the others steer
 * OpenCRG's own run time (messages, checks, the search of x/y positions, the reference line
 * beyond its ends, heights beyond u's ends) and have no effect on a track over the grid's
 * rows, so they are accepted and left alone. Integer options are checked to be integers. */
typedef struct {
    const char *name;
    int used;              /* index into c->opts, or -1 */
    int integer_max;       /* > 0: an integer in [lo, integer_max]; 0: any number */
    int lo;
} opt_def;

static const opt_def opt_defs[] = {
    {"BORDER_MODE_U", -1, 4, 0},
    {"BORDER_MODE_V", CRG_OPT_BORDER_MODE_V, 4, 0},
    {"BORDER_OFFSET_U", -1, 0, 0},
    {"BORDER_OFFSET_V", CRG_OPT_BORDER_OFFSET_V, 0, 0},
    {"BORDER_SMOOTH_UBEG", CRG_OPT_BORDER_SMOOTH_UBEG, 0, 0},
    {"BORDER_SMOOTH_UEND", CRG_OPT_BORDER_SMOOTH_UEND, 0, 0},
    {"REFLINE_CONTINUATION", -1, 1, 0},
    {"REFLINE_SEARCH_FAR", -1, 0, 0},
    {"REFLINE_SEARCH_CLOSE", -1, 0, 0},
    {"WARN_MSGS", -1, 0, 0},
    {"WARN_CURV_LOCAL", -1, 0, 0},
    {"WARN_CURV_GLOBAL", -1, 0, 0},
    {"LOG_MSGS", -1, 0, 0},
    {"LOG_EVAL", -1, 0, 0},
    {"LOG_EVAL_FREQ", -1, 0, 0},
    {"LOG_HIST", -1, 0, 0},
    {"LOG_HIST_FREQ", -1, 0, 0},
    {"LOG_STAT", -1, 0, 0},
    {"LOG_STAT_FREQ", -1, 0, 0},
    {"CHECK_EPS", -1, 0, 0},
    {"CHECK_INC", -1, 0, 0},
    {"CHECK_TOL", -1, 0, 0},
    {"CHECK_PRO", -1, 0, 0},
    {"CHECK_WGS", -1, 0, 0},
};

/* Every modifier of the specification. Those with used >= 0 are applied (they shift or scale
 * heights, fill border NaNs, or move the reference line in x/y, by offsets or by a reference
 * point); the SCALE_* others re-shape the road in ways tirenv does not implement, and are
 * refused rather than ignored. */
typedef struct {
    const char *name;
    int used;              /* index into c->mods, or -1 (refused) */
} mod_def;

static const mod_def mod_defs[] = {
    {"GRID_NAN_MODE", CRG_MOD_GRID_NAN_MODE},
    {"GRID_NAN_OFFSET", CRG_MOD_GRID_NAN_OFFSET},
    {"SCALE_Z_GRID", CRG_MOD_SCALE_Z_GRID},
    {"REFLINE_ROTCENTER_X", CRG_MOD_REFLINE_ROTCENTER_X},
    {"REFLINE_ROTCENTER_Y", CRG_MOD_REFLINE_ROTCENTER_Y},
    {"REFLINE_OFFSET_PHI", CRG_MOD_REFLINE_OFFSET_PHI},
    {"REFLINE_OFFSET_X", CRG_MOD_REFLINE_OFFSET_X},
    {"REFLINE_OFFSET_Y", CRG_MOD_REFLINE_OFFSET_Y},
    {"REFLINE_OFFSET_Z", CRG_MOD_REFLINE_OFFSET_Z},
    {"REFPOINT_U", CRG_MOD_REFPOINT_U},
    {"REFPOINT_V", CRG_MOD_REFPOINT_V},
    {"REFPOINT_U_FRACTION", CRG_MOD_REFPOINT_U_FRACTION},
    {"REFPOINT_U_OFFSET", CRG_MOD_REFPOINT_U_OFFSET},
    {"REFPOINT_V_FRACTION", CRG_MOD_REFPOINT_V_FRACTION},
    {"REFPOINT_V_OFFSET", CRG_MOD_REFPOINT_V_OFFSET},
    {"REFPOINT_X", CRG_MOD_REFPOINT_X},
    {"REFPOINT_Y", CRG_MOD_REFPOINT_Y},
    {"REFPOINT_Z", CRG_MOD_REFPOINT_Z},
    {"REFPOINT_PHI", CRG_MOD_REFPOINT_PHI},
    {"SCALE_SLOPE", -1},
    {"SCALE_BANKING", -1},
    {"SCALE_LENGTH", -1},
    {"SCALE_WIDTH", -1},
    {"SCALE_CURVATURE", -1},
};

typedef enum {
    SEC_NONE, SEC_CT, SEC_ROAD, SEC_MPRO, SEC_KD, SEC_OPTS, SEC_MODS, SEC_FILE, SEC_COUNT
} section;

static const char *const section_names[SEC_COUNT] = {
    "", "CT", "ROAD_CRG", "ROAD_CRG_MPRO", "KD_DEFINITION", "ROAD_CRG_OPTS",
    "ROAD_CRG_MODS", "ROAD_CRG_FILE",
};

/* A long section as its D: line names it. */
typedef struct {
    int numbered;          /* "long section N" (1) or "long section at v = X" (0) */
    double v;              /* X */
    unsigned long n;       /* N */
} section_name;

/* What the parse gathers besides c's fields. */
typedef struct {
    tirenv_crg *c;
    tirenv_propfile__where at; /* the file's name, the line being read */
    size_t seen[SEC_COUNT];    /* line of each section's start, 0 if absent */
    size_t format_line;        /* the #: line */
    section_name *names;       /* per long section */
    size_t cap;
} parse;

#define fail(p, ...) tirenv_propfile__fail(&(p)->at, __VA_ARGS__)

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t'))
        s[--n] = '\0';
    return s;
}

/* '!' starts a comment anywhere in a header record. */
static void strip_comment(char *s)
{
    char *bang = strchr(s, '!');
    if (bang)
        *bang = '\0';
}

/* A keyword: a letter, then letters, digits and underscores, at most 31 characters. */
static size_t keyword_length(const char *s)
{
    if (!isalpha((unsigned char)s[0]))
        return 0;
    size_t n = 1;
    while (isalnum((unsigned char)s[n]) || s[n] == '_')
        n++;
    return n;
}

/* Stores a key's value; a key given twice must give the same value (a repeated option line
 * is harmless, a contradiction is not). */
static int store(const parse *p, tirenv_crg__value *slot, const char *key, const char *at,
                 double v)
{
    if (slot->line && slot->value != v)
        return fail(p, at, key, "set twice: %.17g here, %.17g on line %zu; expected one value",
                    v, slot->value, slot->line);
    if (!slot->line) {
        slot->value = v;
        slot->line = p->at.line;
    }
    return TIRENV_OK;
}

/* "KEY = value" in $ROAD_CRG, $ROAD_CRG_OPTS or $ROAD_CRG_MODS. */
static int key_line(parse *p, section sec, char *text)
{
    char *eq = strchr(text, '=');
    const char *secname = section_names[sec];
    if (!eq) {
        char *gap = text + strcspn(text, " \t");
        *gap = '\0';
        return fail(p, text, text, "missing '='; expected KEY = value in $%s", secname);
    }
    *eq = '\0';
    char *key = trim(text);
    char *value = trim(eq + 1);
    if (!*key)
        return fail(p, eq, "", "missing key before '='; expected KEY = value");
    if (keyword_length(key) != strlen(key) || strlen(key) > 31)
        return fail(p, key, key, "'%.40s' is not a keyword; expected letters, digits and "
                    "'_', starting with a letter, at most 31 characters", key);
    double v;
    int status;
    tirenv_crg *c = p->c;
    if (sec == SEC_ROAD) {
        for (size_t i = 0; i < CRG_ROAD_KEYS; i++)
            if (strcasecmp(key, road_names[i]) == 0) {
                if ((status = tirenv_propfile__real(&p->at, road_names[i], value, &v)))
                    return status;
                return store(p, &c->road[i], road_names[i], value, v);
            }
        return fail(p, key, key, "unknown key in $ROAD_CRG; expected a REFERENCE_LINE_* or "
                    "LONG_SECTION_* key of the OpenCRG specification");
    }
    if (sec == SEC_OPTS) {
        for (size_t i = 0; i < sizeof opt_defs / sizeof opt_defs[0]; i++) {
            const opt_def *d = &opt_defs[i];
            if (strcasecmp(key, d->name) != 0)
                continue;
            if ((status = tirenv_propfile__real(&p->at, d->name, value, &v)))
                return status;
            if (d->integer_max > 0 && !(v == floor(v) && v >= d->lo && v <= d->integer_max))
                return fail(p, value, d->name, "expected a whole number from %d to %d, got "
                            "%.17g", d->lo, d->integer_max, v);
            if ((d->used == CRG_OPT_BORDER_SMOOTH_UBEG || d->used == CRG_OPT_BORDER_SMOOTH_UEND)
                && v < 0)
                return fail(p, value, d->name, "expected a length >= 0 m, got %.17g", v);
            return d->used >= 0 ? store(p, &c->opts[d->used], d->name, value, v) : TIRENV_OK;
        }
        return fail(p, key, key, "unknown option in $ROAD_CRG_OPTS; expected an option of the "
                    "OpenCRG specification (BORDER_MODE_V, BORDER_OFFSET_V, ...)");
    }
    for (size_t i = 0; i < sizeof mod_defs / sizeof mod_defs[0]; i++) {
        const mod_def *d = &mod_defs[i];
        if (strcasecmp(key, d->name) != 0)
            continue;
        if ((status = tirenv_propfile__real(&p->at, d->name, value, &v)))
            return status;
        if (d->used < 0)
            return fail(p, key, d->name, "modifier not supported by tirenv (it re-scales or "
                        "re-shapes the road); supported are GRID_NAN_MODE, GRID_NAN_OFFSET, "
                        "SCALE_Z_GRID, the REFLINE_* offsets and the REFPOINT_* placement");
        if (d->used == CRG_MOD_GRID_NAN_MODE && !(v == 0 || v == 1 || v == 2))
            return fail(p, value, d->name, "expected 0, 1 or 2, got %.17g", v);
        return store(p, &c->mods[d->used], d->name, value, v);
    }
    return fail(p, key, key, "unknown modifier in $ROAD_CRG_MODS; expected a modifier of the "
                "OpenCRG specification");
}

/* Lower-case with runs of blanks as one space: channel names are compared this way. */
static void normalise(char *s)
{
    char *w = s;
    int blank = 1;
    for (const char *r = s; *r; r++) {
        if (*r == ' ' || *r == '\t') {
            if (!blank)
                *w++ = ' ';
            blank = 1;
        } else {
            *w++ = (char)tolower((unsigned char)*r);
            blank = 0;
        }
    }
    if (w > s && w[-1] == ' ')
        w--;
    *w = '\0';
}

static int add_long_section(parse *p, const section_name *n)
{
    tirenv_crg *c = p->c;
    if (c->nv == p->cap) {
        const size_t cap = p->cap ? 2 * p->cap : 16;
        section_name *names = realloc(p->names, cap * sizeof *names);
        if (names)
            p->names = names;
        size_t *ch = names ? realloc(c->ch_z, cap * sizeof *ch) : NULL;
        if (ch)
            c->ch_z = ch;
        size_t *ln = ch ? realloc(c->kd_line_z, cap * sizeof *ln) : NULL;
        if (ln)
            c->kd_line_z = ln;
        if (!ln)
            return tirenv_error(p->at.diag, TIRENV_ENOMEM, c->src.name, p->at.line, "",
                                "out of memory");
        p->cap = cap;
    }
    p->names[c->nv] = *n;
    c->ch_z[c->nv] = c->nch;
    c->kd_line_z[c->nv] = p->at.line;
    c->nv++;
    return TIRENV_OK;
}

/* "long section at v = X" or "long section N" after "long section". */
static int long_section_name(parse *p, const char *full, const char *rest, section_name *n)
{
    while (*rest == ' ')
        rest++;
    if (strncmp(rest, "at", 2) == 0) {
        rest += 2;
        while (*rest == ' ')
            rest++;
        if (*rest != 'v')
            goto bad;
        rest++;
        while (*rest == ' ')
            rest++;
        if (*rest != '=')
            goto bad;
        rest++;
        char *end;
        const double v = strtod(rest, &end);
        if (end == rest || *end || !isfinite(v))
            return fail(p, NULL, "D", "channel '%.60s': expected a number after 'v ='", full);
        n->numbered = 0;
        n->v = v;
        return TIRENV_OK;
    }
    if (isdigit((unsigned char)*rest)) {
        char *end;
        const unsigned long k = strtoul(rest, &end, 10);
        if (*end || k == 0 || k > 100000)
            return fail(p, NULL, "D", "channel '%.60s': expected a section number from 1",
                        full);
        n->numbered = 1;
        n->n = k;
        return TIRENV_OK;
    }
bad:
    return fail(p, NULL, "D", "channel '%.60s': expected 'long section at v = X' or "
                "'long section N'", full);
}

/* "D:name,unit": one column of the road data. */
static int channel_line(parse *p, char *text)
{
    tirenv_crg *c = p->c;
    char *def = text + 2;
    char *comma = strchr(def, ',');
    if (!comma)
        return fail(p, def, "D", "channel '%.60s' has no unit; expected D:name,unit", def);
    *comma = '\0';
    char *unit = trim(comma + 1);
    char *more = strchr(unit, ',');
    if (more)
        *more = '\0';
    unit = trim(unit);
    char name[RECORD + 1];
    snprintf(name, sizeof name, "%s", trim(def));
    normalise(name);
    const char *want_unit = "m";
    size_t *slot = NULL, *slot_line = NULL;
    if (strcmp(name, "reference line phi") == 0) {
        slot = &c->ch_phi;
        slot_line = &c->kd_line_phi;
        want_unit = "rad";
    } else if (strcmp(name, "reference line slope") == 0) {
        slot = &c->ch_slope;
        slot_line = &c->kd_line_slope;
        want_unit = "m/m";
    } else if (strcmp(name, "reference line banking") == 0) {
        slot = &c->ch_bank;
        slot_line = &c->kd_line_bank;
        want_unit = "m/m";
    } else if (strncmp(name, "long section", 12) != 0) {
        return fail(p, def, "D", "unknown channel '%.60s'; expected 'reference line phi', "
                    "'reference line slope', 'reference line banking', 'long section at v = "
                    "X' or 'long section N'", name);
    }
    if (strcasecmp(unit, want_unit) != 0)
        return fail(p, unit, "D", "channel '%.60s' in '%.20s'; expected the unit '%s'%s", name,
                    unit, want_unit, slot ? "" : " (tirenv reads elevations)");
    int status;
    if (slot) {
        if (*slot != TIRENV_CRG__NONE)
            return fail(p, def, "D", "channel '%s' defined twice (first on line %zu)", name,
                        *slot_line);
        *slot = c->nch;
        *slot_line = p->at.line;
    } else {
        section_name n;
        if ((status = long_section_name(p, name, name + 12, &n)) ||
            (status = add_long_section(p, &n)))
            return status;
    }
    if (c->nch >= 100000)
        return fail(p, def, "D", "more than 100000 channels; expected fewer");
    c->nch++;
    return TIRENV_OK;
}

static int kd_line(parse *p, char *text)
{
    tirenv_crg *c = p->c;
    if (strncmp(text, "#:", 2) == 0) {
        char *fmt = trim(text + 2);
        if (p->format_line)
            return fail(p, text, "#:", "data format given twice (first on line %zu)",
                        p->format_line);
        tirenv_crg_encoding e;
        if (tirenv_crg_encoding_find(fmt, &e) != TIRENV_OK)
            return fail(p, fmt, "#:", "unknown data format '%.20s'; expected LRFI, LDFI, KRBI "
                        "or KDBI", fmt);
        c->enc = e;
        p->format_line = p->at.line;
        return TIRENV_OK;
    }
    if (strncasecmp(text, "D:", 2) == 0)
        return channel_line(p, text);
    if (strncasecmp(text, "U:", 2) == 0)
        return TIRENV_OK; /* a virtual channel: no column in the data */
    return fail(p, text, "", "unexpected '%.40s' in $KD_DEFINITION; expected '#:FORMAT', "
                "'D:name,unit' or 'U:...'", text);
}

/* A line that starts with one '$': a section starts, or (a bare '$') the current one ends. */
static int section_line(parse *p, char *text, section *sec)
{
    strip_comment(text);
    char *kw = trim(text + 1);
    if (!*kw) {
        *sec = SEC_NONE;
        return TIRENV_OK;
    }
    const size_t n = keyword_length(kw);
    if (n == 0 || trim(kw + n)[0])
        return fail(p, kw, "", "'$%.40s' is not a section keyword; expected $CT, $ROAD_CRG, "
                    "$KD_DEFINITION, ... or a bare '$' to end a section", kw);
    kw[n] = '\0';
    for (int s = SEC_CT; s < SEC_COUNT; s++) {
        if (strcasecmp(kw, section_names[s]) != 0)
            continue;
        if (p->seen[s])
            return fail(p, kw, section_names[s], "section given twice (first on line %zu); "
                        "expected each section once", p->seen[s]);
        if (s == SEC_FILE)
            return fail(p, kw, section_names[s], "file references are not supported; open "
                        "the referenced OpenCRG file itself");
        p->seen[s] = p->at.line;
        if (s == SEC_MODS)
            p->c->has_mods = 1;  /* even empty: OpenCRG then drops its default modifiers */
        *sec = (section)s;
        return TIRENV_OK;
    }
    return fail(p, kw, kw, "unknown section; expected $CT, $ROAD_CRG, $ROAD_CRG_MPRO, "
                "$KD_DEFINITION, $ROAD_CRG_OPTS or $ROAD_CRG_MODS");
}

static int header_line(parse *p, char *text, section *sec)
{
    if (text[0] == '*')
        return TIRENV_OK;
    if (text[0] == '$')
        return section_line(p, text, sec);
    switch (*sec) {
    case SEC_CT:
    case SEC_MPRO:
        return TIRENV_OK; /* free text; map projection data does not change heights */
    case SEC_NONE:
    case SEC_COUNT:
    case SEC_FILE:
        strip_comment(text);
        if (*trim(text))
            return fail(p, text, "", "text outside a section; expected a '$SECTION' line");
        return TIRENV_OK;
    case SEC_KD:
        strip_comment(text);
        text = trim(text);
        return *text ? kd_line(p, text) : TIRENV_OK;
    case SEC_ROAD:
    case SEC_OPTS:
    case SEC_MODS:
        strip_comment(text);
        text = trim(text);
        return *text ? key_line(p, *sec, text) : TIRENV_OK;
    }
    return TIRENV_OK;
}

static double tolerance(double a, double b)
{
    return 1e-6 * (1 + fabs(a) + fabs(b));
}

/* Lateral positions of numbered long sections from LONG_SECTION_V_RIGHT / _LEFT / _INCREMENT,
 * which the specification requires for them. With only the increment the first long section
 * is at v = 0 and the road lies to the left of the reference line, as OpenCRG's C API places
 * it (its loader starts at V_RIGHT, 0 when not given; the centring it once had is commented
 * out), so that a minimalist file is evaluated where OpenCRG and Chrono evaluate it. */
static int numbered_positions(parse *p)
{
    tirenv_crg *c = p->c;
    const tirenv_crg__value *right = &c->road[CRG_LS_V_RIGHT], *left = &c->road[CRG_LS_V_LEFT],
                            *inc = &c->road[CRG_LS_V_INCREMENT];
    const double span = (double)(c->nv - 1);
    double first, step;
    if (inc->line) {
        step = inc->value;
        first = right->line ? right->value
                : left->line ? left->value - span * step : 0;
        if (right->line && left->line) {
            const double last = first + span * step;
            if (fabs(last - left->value) > tolerance(last, left->value)) {
                p->at.line = left->line;
                return fail(p, NULL, road_names[CRG_LS_V_LEFT], "with LONG_SECTION_V_RIGHT = "
                            "%.17g and LONG_SECTION_V_INCREMENT = %.17g, the %zu long sections "
                            "end at v = %.17g, not at %.17g", first, step, c->nv, last,
                            left->value);
            }
        }
    } else if (right->line && left->line) {
        first = right->value;
        step = (left->value - right->value) / span;
    } else {
        p->at.line = c->kd_line_z[0];
        return fail(p, NULL, road_names[CRG_LS_V_INCREMENT], "numbered long sections need "
                    "LONG_SECTION_V_INCREMENT (or both LONG_SECTION_V_RIGHT and _LEFT) in "
                    "$ROAD_CRG");
    }
    for (size_t j = 0; j < c->nv; j++) {
        if (p->names[j].n != j + 1) {
            p->at.line = c->kd_line_z[j];
            return fail(p, NULL, "D", "long section %lu where %zu was expected; numbered long "
                        "sections go 1, 2, ... from right to left", p->names[j].n, j + 1);
        }
        c->v[j] = first + (double)j * step;
    }
    return TIRENV_OK;
}

/* Positions given in the channel names: ascending, and agreeing with the header's. */
static int explicit_positions(parse *p)
{
    tirenv_crg *c = p->c;
    for (size_t j = 0; j < c->nv; j++) {
        c->v[j] = p->names[j].v;
        if (j > 0 && !(c->v[j] > c->v[j - 1])) {
            p->at.line = c->kd_line_z[j];
            return fail(p, NULL, "D", "long section at v = %.17g after v = %.17g; expected "
                        "ascending v (right to left)", c->v[j], c->v[j - 1]);
        }
    }
    const struct { int key; double v; } ends[] = {
        {CRG_LS_V_RIGHT, c->v[0]}, {CRG_LS_V_LEFT, c->v[c->nv - 1]},
    };
    for (size_t k = 0; k < 2; k++) {
        const tirenv_crg__value *h = &c->road[ends[k].key];
        if (h->line && fabs(h->value - ends[k].v) > tolerance(h->value, ends[k].v)) {
            p->at.line = h->line;
            return fail(p, NULL, road_names[ends[k].key], "%.17g, but the long sections of "
                        "$KD_DEFINITION %s at v = %.17g", h->value, k ? "end" : "start",
                        ends[k].v);
        }
    }
    const tirenv_crg__value *inc = &c->road[CRG_LS_V_INCREMENT];
    for (size_t j = 1; inc->line && j < c->nv; j++) {
        const double d = c->v[j] - c->v[j - 1];
        if (fabs(d - inc->value) > tolerance(d, inc->value)) {
            p->at.line = inc->line;
            return fail(p, NULL, road_names[CRG_LS_V_INCREMENT], "%.17g, but long sections "
                        "%zu and %zu are %.17g m apart", inc->value, j, j + 1, d);
        }
    }
    return TIRENV_OK;
}

/* Lateral positions within a road's coordinates (TIRENV_PROFILE_MAX_COORDINATE), as its
 * heights and reference line are (crg_rows.c): LONG_SECTION_V_RIGHT = -1e308 and _LEFT =
 * 1e308 spanned an infinite width, and the first section came out at NaN, refused as the
 * reference point's ("REFPOINT: (u, v) = (0, -nan)"), a key the file did not have. The keys
 * themselves are checked with the header (finish); this is the sections' positions, from an
 * increment or the channels' names. */
static int lateral_within(parse *p)
{
    const tirenv_crg *c = p->c;
    for (size_t j = 0; j < c->nv; j++)
        if (!(fabs(c->v[j]) <= TIRENV_PROFILE_MAX_COORDINATE)) {
            p->at.line = c->kd_line_z[j];
            return fail(p, NULL, "D", "long section %zu lies at v = %.17g m%s, beyond +-%g m; "
                        "expected a road's lateral position (in m?)", j + 1, c->v[j],
                        c->v_numbered ? " (from LONG_SECTION_V_RIGHT, _LEFT, _INCREMENT)" : "",
                        TIRENV_PROFILE_MAX_COORDINATE);
        }
    return TIRENV_OK;
}

/* What the whole header must say, checked once it is read. */
static int finish(parse *p, size_t last_line)
{
    tirenv_crg *c = p->c;
    p->at.base = NULL;
    p->at.line = last_line;
    if (!p->seen[SEC_ROAD])
        return fail(p, NULL, "ROAD_CRG", "no $ROAD_CRG section; expected the road parameters "
                    "(REFERENCE_LINE_INCREMENT at least)");
    if (!p->seen[SEC_KD])
        return fail(p, NULL, "KD_DEFINITION", "no $KD_DEFINITION section; expected the data "
                    "format and channels");
    const tirenv_crg__value *inc = &c->road[CRG_RL_INCREMENT];
    if (!inc->line) {
        p->at.line = p->seen[SEC_ROAD];
        return fail(p, NULL, road_names[CRG_RL_INCREMENT], "missing in $ROAD_CRG; expected "
                    "the distance between cross sections, m (the one mandatory key)");
    }
    if (!(inc->value > 0)) {
        p->at.line = inc->line;
        return fail(p, NULL, road_names[CRG_RL_INCREMENT], "%.17g; expected a positive "
                    "length, m", inc->value);
    }
    /* A track's vertices are an increment apart: no farther than a road's segment may be
     * (which convert wrote into a CSV tirenv then refused, and a streamed sweep reported as
     * "out of memory"). */
    if (inc->value > TIRENV_PROFILE_MAX_SEGMENT) {
        p->at.line = inc->line;
        return fail(p, NULL, road_names[CRG_RL_INCREMENT], "%.17g m; expected at most %g m "
                    "between cross sections, a road's longest segment (docs/models.md "
                    "section 2.1)", inc->value, TIRENV_PROFILE_MAX_SEGMENT);
    }
    const tirenv_crg__value *u0 = &c->road[CRG_RL_START_U], *u1 = &c->road[CRG_RL_END_U];
    if (u0->line && u1->line && !(u1->value > u0->value)) {
        p->at.line = u1->line;
        return fail(p, NULL, road_names[CRG_RL_END_U], "%.17g is not beyond "
                    "REFERENCE_LINE_START_U = %.17g", u1->value, u0->value);
    }
    const tirenv_crg__value *vinc = &c->road[CRG_LS_V_INCREMENT];
    if (vinc->line && !(vinc->value > 0)) {
        p->at.line = vinc->line;
        return fail(p, NULL, road_names[CRG_LS_V_INCREMENT], "%.17g; expected a positive "
                    "length, m", vinc->value);
    }
    const tirenv_crg__value *vr = &c->road[CRG_LS_V_RIGHT], *vl = &c->road[CRG_LS_V_LEFT];
    const int v_keys[2] = {CRG_LS_V_RIGHT, CRG_LS_V_LEFT};
    for (size_t k = 0; k < 2; k++) {
        const tirenv_crg__value *h = &c->road[v_keys[k]];
        if (h->line && !(fabs(h->value) <= TIRENV_PROFILE_MAX_COORDINATE)) {
            p->at.line = h->line;
            return fail(p, NULL, road_names[v_keys[k]], "%.17g m is beyond +-%g m; expected "
                        "a road's lateral position (in m?)", h->value,
                        TIRENV_PROFILE_MAX_COORDINATE);
        }
    }
    if (vr->line && vl->line && !(vl->value > vr->value)) {
        p->at.line = vl->line;
        return fail(p, NULL, road_names[CRG_LS_V_LEFT], "%.17g is not left of "
                    "LONG_SECTION_V_RIGHT = %.17g; expected V_RIGHT < V_LEFT", vl->value,
                    vr->value);
    }
    if (c->nv < 2) {
        p->at.line = p->seen[SEC_KD];
        return fail(p, NULL, "D", "%zu long section%s; expected at least two (a road has a "
                    "width)", c->nv, c->nv == 1 ? "" : "s");
    }
    for (size_t j = 1; j < c->nv; j++)
        if (p->names[j].numbered != p->names[0].numbered) {
            p->at.line = c->kd_line_z[j];
            return fail(p, NULL, "D", "long sections both numbered and at given v; expected "
                        "one way for all");
        }
    if (!(c->v = malloc(c->nv * sizeof *c->v)))
        return tirenv_error(p->at.diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    p->c->v_numbered = p->names[0].numbered;
    const int status = p->names[0].numbered ? numbered_positions(p) : explicit_positions(p);
    return status ? status : lateral_within(p);
}

int tirenv_crg__parse_header(tirenv_crg *c, tirenv_diag *diag)
{
    parse p = {.c = c, .at = {.file = c->src.name, .diag = diag}};
    c->enc = TIRENV_CRG_KRBI; /* the specification's default when no #: line is given */
    c->ch_phi = c->ch_slope = c->ch_bank = TIRENV_CRG__NONE;
    tirenv_lines r;
    int status = tirenv_lines__init(&r, &c->src, 0, 1, diag);
    if (status)
        return status;
    section sec = SEC_NONE;
    char text[RECORD + 1];
    int got, ended = 0;
    while (!ended && (got = tirenv_lines__next(&r, diag)) > 0) {
        p.at.line = r.line;
        const char *line = r.text;
        if (r.line == 1 && strncmp(line, "\xEF\xBB\xBF", 3) == 0)
            line += 3; /* a UTF-8 byte-order mark */
        snprintf(text, sizeof text, "%s", line);
        p.at.base = text;
        if (text[0] == '$' && text[1] == '$') {
            ended = 1;
            c->header_lines = r.line;
            c->data_offset = r.pos;
        } else if ((status = header_line(&p, text, &sec))) {
            break;
        }
    }
    if (!status && got < 0)
        status = -got;
    if (!status && !ended) {
        p.at.base = NULL;
        p.at.line = r.line;
        status = fail(&p, NULL, "$$$$", "no end of header (a '$$$$' line) by the end of the "
                      "file; expected the header, a '$$$$' line, then the road data");
    }
    tirenv_lines__free(&r);
    if (!status)
        status = finish(&p, r.line);
    free(p.names);
    return status;
}
