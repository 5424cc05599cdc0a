/* The OpenCRG road data block: its rows in the four encodings (KRBI/KDBI big-endian binary
 * records of 80 bytes padded with NaN; LRFI/LDFI fixed-width text records of 80 characters
 * with '*' for a missing value), read a window at a time, and the one pass at open that
 * counts and checks them. SPDX-License-Identifier: Apache-2.0 */
#include "formats/crg_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { RECORD_BYTES = 80 };

static int is_text(tirenv_crg_encoding e)
{
    return e == TIRENV_CRG_LRFI || e == TIRENV_CRG_LDFI;
}

/* Characters per number in a text record. */
static size_t field_width(const tirenv_crg *c)
{
    return c->enc == TIRENV_CRG_LRFI ? 10 : 20;
}

const char *tirenv_crg__channel_name(const tirenv_crg *c, size_t col, char *buf, size_t n)
{
    if (col == c->ch_phi)
        snprintf(buf, n, "reference line phi");
    else if (col == c->ch_slope)
        snprintf(buf, n, "reference line slope");
    else if (col == c->ch_bank)
        snprintf(buf, n, "reference line banking");
    else {
        snprintf(buf, n, "channel %zu", col + 1);
        for (size_t j = 0; j < c->nv; j++)
            if (c->ch_z[j] == col && c->v)
                snprintf(buf, n, "long section %zu (v = %g m)", j + 1, c->v[j]);
    }
    return buf;
}

/* ---- decoding -------------------------------------------------------------------------- */

static double be_value(const unsigned char *b, size_t size)
{
    if (size == 4) {
        const uint32_t w = (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 |
                           (uint32_t)b[3];
        float f;
        memcpy(&f, &w, sizeof f);
        return f;
    }
    uint64_t w = 0;
    for (size_t k = 0; k < 8; k++)
        w = w << 8 | b[k];
    double d;
    memcpy(&d, &w, sizeof d);
    return d;
}

/* Binary values [first, first + count) of the whole data block into out. */
static int read_binary(const tirenv_crg *c, size_t first, size_t count, double out[],
                       tirenv_diag *diag)
{
    enum { CHUNK = 8192 };
    unsigned char buf[CHUNK * 8];
    const size_t vs = c->value_size;
    while (count > 0) {
        const size_t n = count < CHUNK ? count : CHUNK;
        const int status = tirenv_source__read(&c->src, c->data_offset + first * vs, buf,
                                               n * vs, diag);
        if (status)
            return status;
        for (size_t k = 0; k < n; k++)
            out[k] = be_value(buf + k * vs, vs);
        out += n;
        first += n;
        count -= n;
    }
    return TIRENV_OK;
}

/* Where a message points for row i, channel col: the line and column of a text field, or the
 * byte offset of a binary value. row_line is the line of the row's first record (text). */
static void locate(const tirenv_crg *c, size_t i, size_t col, size_t row_line, size_t *line,
                   size_t *column, size_t *offset)
{
    *line = *column = *offset = 0;
    if (is_text(c->enc)) {
        *line = row_line + col / c->values_per_record;
        *column = col % c->values_per_record * field_width(c) + 1;
    } else {
        *offset = c->data_offset + (i * c->nch + col) * c->value_size;
    }
}

#if defined(__GNUC__)
__attribute__((format(printf, 7, 8)))
#endif
static int data_fail(const tirenv_crg *c, size_t i, size_t col, size_t row_line, int status,
                     tirenv_diag *diag, const char *fmt, ...)
{
    char msg[400], ch[96], where[64] = "";
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    size_t line, column, offset;
    locate(c, i, col, row_line, &line, &column, &offset);
    if (offset)
        snprintf(where, sizeof where, " (byte offset %zu)", offset);
    tirenv_crg__channel_name(c, col, ch, sizeof ch);
    const int s = tirenv_error(diag, status, c->src.name, line, ch, "row %zu (u = %.17g m)%s: "
                               "%s", i + 1, c->u0 + (double)i * c->du, where, msg);
    if (diag)
        diag->column = column;
    return s;
}

/* ---- text records ---------------------------------------------------------------------- */

static int all_blank(const char *s, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (s[k] != ' ' && s[k] != '\t')
            return 0;
    return 1;
}

/* nf numbers of one record (the line r->text) into out; a field whose first non-blank
 * character is '*' is missing (NaN). The last field may end early on a line that ends with a
 * line end (its trailing blanks stripped, as OpenCRG's MATLAB reader pads a short line to 80
 * characters); nothing may follow it. A last line the file ends inside, without a line end,
 * must hold its fields whole: the file was cut there, maybe mid-number ("0.12" of
 * "0.1234567"), and a cut number would read as another value. */
static int parse_record(const tirenv_crg *c, const tirenv_lines *r, size_t nf, double out[],
                        tirenv_diag *diag)
{
    const size_t w = field_width(c);
    const char *text = r->text;
    const size_t len = r->len;
    if (!r->eol && len < nf * w && len > (nf - 1) * w) {
        const int s = tirenv_error(diag, TIRENV_EPARSE, c->src.name, r->line, "data",
                                   "truncated data: the file ends %zu characters into the "
                                   "last %zu-character number of the record, without a line "
                                   "end; expected %zu whole numbers (%zu characters)",
                                   len - (nf - 1) * w, w, nf, nf * w);
        if (diag)
            diag->column = len + 1;
        return s;
    }
    for (size_t f = 0; f < nf; f++) {
        const size_t at = f * w;
        if (at >= len || all_blank(text + at, len - at < w ? len - at : w)) {
            const int s = tirenv_error(diag, TIRENV_EPARSE, c->src.name, r->line, "data",
                                       "record of %zu number%s where %zu were expected (%zu "
                                       "characters each); a row of %zu channels goes in "
                                       "records of %zu", f, f == 1 ? "" : "s", nf, w, c->nch,
                                       c->values_per_record);
            if (diag)
                diag->column = at + 1;
            return s;
        }
        char field[24];
        const size_t n = len - at < w ? len - at : w;
        memcpy(field, text + at, n);
        field[n] = '\0';
        char *p = field;
        while (*p == ' ' || *p == '\t')
            p++;
        size_t m = strlen(p);
        while (m > 0 && (p[m - 1] == ' ' || p[m - 1] == '\t'))
            p[--m] = '\0';
        if (p[0] == '*') {
            out[f] = NAN;
            continue;
        }
        char *end;
        const double v = strtod(p, &end);
        if (end == p || *end || !isfinite(v)) {
            const int s = tirenv_error(diag, TIRENV_EPARSE, c->src.name, r->line, "data",
                                       "'%s' is not a number; expected a %zu-character number "
                                       "or a '*' placeholder for a missing value", p, w);
            if (diag)
                diag->column = at + 1;
            return s;
        }
        out[f] = v;
    }
    if (len > nf * w && !all_blank(text + nf * w, len - nf * w)) {
        const int s = tirenv_error(diag, TIRENV_EPARSE, c->src.name, r->line, "data",
                                   "unexpected '%.20s' after %zu numbers; expected at most "
                                   "%zu per record", text + nf * w, nf, nf);
        if (diag)
            diag->column = nf * w + 1;
        return s;
    }
    return TIRENV_OK;
}

/* One row from its records; *row_line gets the line of its first record. */
static int read_text_row(const tirenv_crg *c, tirenv_lines *r, double out[], size_t *row_line,
                         tirenv_diag *diag)
{
    for (size_t k = 0; k < c->records_per_row; k++) {
        const int got = tirenv_lines__next(r, diag);
        if (got < 0)
            return -got;
        if (got == 0)
            return tirenv_error(diag, TIRENV_EIO, c->src.name, r->line, "data",
                                "the road data ended inside a row (did the file change while "
                                "being read?)");
        if (k == 0)
            *row_line = r->line;
        const size_t first = k * c->values_per_record;
        const size_t nf = c->nch - first < c->values_per_record ? c->nch - first
                                                                 : c->values_per_record;
        const int status = parse_record(c, r, nf, out + first, diag);
        if (status)
            return status;
    }
    return TIRENV_OK;
}

int tirenv_crg__rows_asked(const tirenv_crg *c, size_t first, size_t count, tirenv_diag *diag)
{
    if (first > c->nu || count > c->nu - first)
        return tirenv_error(diag, TIRENV_EINVAL, c->src.name, 0, "",
                            "rows %zu to %zu asked for; the file has %zu", first + 1,
                            first + count, c->nu);
    return TIRENV_OK;
}

int tirenv_crg__read_rows(const tirenv_crg *c, size_t first, size_t count, double vals[],
                          tirenv_diag *diag)
{
    const int asked = tirenv_crg__rows_asked(c, first, count, diag);
    if (asked)
        return asked;
    if (!is_text(c->enc))
        return read_binary(c, first * c->nch, count * c->nch, vals, diag);
    const size_t k = first / TIRENV_CRG__CHECKPOINT;
    tirenv_lines r;
    int status = tirenv_lines__init(&r, &c->src, c->ckpt_off[k], c->ckpt_line[k], diag);
    /* Rows between the checkpoint and first are skipped whole, records unparsed. */
    const size_t skip = (first - k * TIRENV_CRG__CHECKPOINT) * c->records_per_row;
    for (size_t s = 0; !status && s < skip; s++) {
        const int got = tirenv_lines__next(&r, diag);
        if (got <= 0)
            status = got < 0 ? -got
                             : tirenv_error(diag, TIRENV_EIO, c->src.name, r.line, "data",
                                            "the road data ended early (did the file change "
                                            "while being read?)");
    }
    size_t row_line;
    for (size_t i = 0; !status && i < count; i++)
        status = read_text_row(c, &r, vals + i * c->nch, &row_line, diag);
    tirenv_lines__free(&r);
    return status;
}

/* ---- the pass at open ------------------------------------------------------------------- */

/* What the pass learns about the reference line channels, for the header checks. */
typedef struct {
    double phi_first, phi_last;    /* heading of the first and last segment, rad */
    double s_first, s_last;        /* slope of the first and last segment */
    double b_first, b_last;        /* banking at the first and last row */
    double x_end, y_end;           /* the heading channel integrated from (0, 0), m */
} pass_sums;

typedef struct {
    size_t cap;                    /* of c->rz */
    size_t ckpt_cap;
    pass_sums sums;
} pass;

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    size_t cap2 = *cap ? *cap : 64;
    while (cap2 < need)
        cap2 *= 2;
    void *q = realloc(*p, cap2 * size);
    if (!q)
        return -1;
    *p = q;
    *cap = cap2;
    return 0;
}

/* Heights (and the banking and slope they are made with) beyond a road's coordinates
 * (TIRENV_PROFILE_MAX_COORDINATE): a typo or a unit slip, refused at its value, where 1e308 in
 * one long section became -1e308 on every row of a converted track (exit 0, a CSV tirenv then
 * refuses) and, streamed, "out of memory". */
static int too_far(double v)
{
    return fabs(v) > TIRENV_PROFILE_MAX_COORDINATE;
}

/* Checks row i and adds it to the pass: NaN only at the ends of the cross section and at
 * least one value; the reference line channels finite where used; the slope integrated into
 * the reference line's height; every value within a road's bound. */
static int pass_row(tirenv_crg *c, pass *ps, size_t i, const double row[], size_t row_line,
                    tirenv_diag *diag)
{
    size_t lo = TIRENV_CRG__NONE, hi = 0;
    for (size_t j = 0; j < c->nv; j++) {
        const double z = row[c->ch_z[j]];
        if (isinf(z))
            return data_fail(c, i, c->ch_z[j], row_line, TIRENV_EPARSE, diag,
                             "infinite value; expected a height in m");
        if (too_far(z))
            return data_fail(c, i, c->ch_z[j], row_line, TIRENV_EPARSE, diag,
                             "%g m is beyond +-%g m; expected a road's height (in m?)", z,
                             TIRENV_PROFILE_MAX_COORDINATE);
        if (!isnan(z)) {
            if (lo == TIRENV_CRG__NONE)
                lo = j;
            hi = j;
        }
    }
    if (lo == TIRENV_CRG__NONE)
        return data_fail(c, i, c->ch_z[0], row_line, TIRENV_EPARSE, diag,
                         "no long section has a value; expected at least one number in every "
                         "cross section");
    for (size_t j = lo; j <= hi; j++)
        if (isnan(row[c->ch_z[j]]))
            return data_fail(c, i, c->ch_z[j], row_line, TIRENV_EPARSE, diag,
                             "missing value between values of the cross section; expected "
                             "missing values only at its left and right ends");
    pass_sums *s = &ps->sums;
    if (c->ch_phi != TIRENV_CRG__NONE && i >= 1) {
        const double phi = row[c->ch_phi];
        if (!isfinite(phi))
            return data_fail(c, i, c->ch_phi, row_line, TIRENV_EPARSE, diag,
                             "missing heading; expected the heading of the segment ending at "
                             "this row, rad (only the first row's is unused)");
        if (i == 1)
            s->phi_first = phi;
        s->phi_last = phi;
        s->x_end += c->du * cos(phi);
        s->y_end += c->du * sin(phi);
    }
    if (c->ch_bank != TIRENV_CRG__NONE) {
        const double b = row[c->ch_bank];
        if (!isfinite(b))
            return data_fail(c, i, c->ch_bank, row_line, TIRENV_EPARSE, diag,
                             "missing banking; expected the cross slope at every row, m/m");
        if (too_far(b))
            return data_fail(c, i, c->ch_bank, row_line, TIRENV_EPARSE, diag,
                             "%g m/m is beyond +-%g; expected a road's cross slope", b,
                             TIRENV_PROFILE_MAX_COORDINATE);
        if (i == 0)
            s->b_first = b;
        s->b_last = b;
    }
    if (c->ch_slope != TIRENV_CRG__NONE) {
        if (grow((void **)&c->rz, &ps->cap, i + 1, sizeof *c->rz))
            return tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
        if (i == 0) {
            c->rz[0] = c->z0;
        } else {
            const double sl = row[c->ch_slope];
            if (!isfinite(sl))
                return data_fail(c, i, c->ch_slope, row_line, TIRENV_EPARSE, diag,
                                 "missing slope; expected the slope of the segment ending at "
                                 "this row, m/m (only the first row's is unused)");
            if (i == 1)
                s->s_first = sl;
            s->s_last = sl;
            c->rz[i] = c->rz[i - 1] + c->du * sl;
            if (too_far(c->rz[i]))
                return data_fail(c, i, c->ch_slope, row_line, TIRENV_EPARSE, diag,
                                 "slope %g takes the reference line to %g m, beyond +-%g m; "
                                 "expected a road's slope, m/m", sl, c->rz[i],
                                 TIRENV_PROFILE_MAX_COORDINATE);
        }
    }
    return TIRENV_OK;
}

/* Rows in a binary block: its whole records hold nu rows and then at most one record's worth
 * of NaN padding. Trailing all-NaN rows inside the last record are that padding (a row of
 * NaN is not a valid cross section anyway). */
static int binary_rows(tirenv_crg *c, tirenv_diag *diag)
{
    const size_t bytes = c->src.size - c->data_offset;
    if (bytes == 0)
        return tirenv_error(diag, TIRENV_EPARSE, c->src.name, c->header_lines, "data",
                            "no road data after the header (byte offset %zu); expected %s "
                            "records", c->data_offset, tirenv_crg_encoding_name(c->enc));
    if (bytes % RECORD_BYTES)
        return tirenv_error(diag, TIRENV_EPARSE, c->src.name, 0, "data",
                            "truncated data: %zu bytes of road data (from byte offset %zu) are "
                            "not a whole number of %d-byte records; the last record starts at "
                            "byte offset %zu", bytes, c->data_offset, RECORD_BYTES,
                            c->data_offset + bytes / RECORD_BYTES * RECORD_BYTES);
    const size_t nvals = bytes / c->value_size, vpr = c->values_per_record;
    double last[RECORD_BYTES / 4];
    int status = read_binary(c, nvals - vpr, vpr, last, diag);
    if (status)
        return status;
    size_t nu = nvals / c->nch;
    /* Values after the last whole row must be padding. */
    for (size_t k = nu * c->nch; k < nvals; k++)
        if (!isnan(last[k - (nvals - vpr)]))
            return tirenv_error(diag, TIRENV_EPARSE, c->src.name, 0, "data",
                                "truncated data: the last %zu values (from byte offset %zu) "
                                "are not a whole row of %zu channels nor NaN padding",
                                nvals - nu * c->nch, c->data_offset + nu * c->nch * c->value_size,
                                c->nch);
    while (nu > 0 && (nu - 1) * c->nch >= nvals - vpr) {
        int all_nan = 1;
        for (size_t k = (nu - 1) * c->nch; k < nu * c->nch; k++)
            all_nan &= isnan(last[k - (nvals - vpr)]) != 0;
        if (!all_nan)
            break;
        nu--;
    }
    if (nvals - nu * c->nch >= vpr)
        return tirenv_error(diag, TIRENV_EPARSE, c->src.name, 0, "data",
                            "truncated data: the road data ends %zu values into a row of %zu "
                            "channels (from byte offset %zu), and NaN padding fills less than "
                            "one record", nvals - nu * c->nch, c->nch,
                            c->data_offset + nu * c->nch * c->value_size);
    c->nu = nu;
    return TIRENV_OK;
}

static int scan_binary(tirenv_crg *c, pass *ps, tirenv_diag *diag)
{
    int status = binary_rows(c, diag);
    if (status || c->nu < 2)
        return status;
    size_t block = 262144 / c->nch;
    block = block < 16 ? 16 : block;
    double *vals = malloc(block * c->nch * sizeof *vals);
    if (!vals)
        return tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    for (size_t i0 = 0; !status && i0 < c->nu; i0 += block) {
        const size_t n = c->nu - i0 < block ? c->nu - i0 : block;
        status = read_binary(c, i0 * c->nch, n * c->nch, vals, diag);
        for (size_t i = 0; !status && i < n; i++)
            status = pass_row(c, ps, i0 + i, vals + i * c->nch, 0, diag);
    }
    free(vals);
    return status;
}

static int scan_text(tirenv_crg *c, pass *ps, tirenv_diag *diag)
{
    double *row = malloc(c->nch * sizeof *row);
    tirenv_lines r;
    int status = row ? tirenv_lines__init(&r, &c->src, c->data_offset, c->header_lines + 1, diag)
                     : tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    if (status) {
        free(row);
        return status;
    }
    size_t i = 0, k = 0, row_line = 0, blank_line = 0;
    int got;
    while (!status && (got = tirenv_lines__next(&r, diag)) > 0) {
        if (all_blank(r.text, r.len)) {
            if (!blank_line)
                blank_line = r.line; /* fine at the end of the file only */
            continue;
        }
        if (blank_line) {
            status = tirenv_error(diag, TIRENV_EPARSE, c->src.name, blank_line, "data",
                                  "blank line inside the road data; expected a record");
            break;
        }
        if (k == 0) {
            row_line = r.line;
            if (i % TIRENV_CRG__CHECKPOINT == 0) {
                const size_t n = i / TIRENV_CRG__CHECKPOINT + 1;
                size_t cap = ps->ckpt_cap;
                if (grow((void **)&c->ckpt_off, &cap, n, sizeof *c->ckpt_off) ||
                    grow((void **)&c->ckpt_line, &ps->ckpt_cap, n, sizeof *c->ckpt_line)) {
                    status = tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "",
                                          "out of memory");
                    break;
                }
                c->ckpt_off[n - 1] = r.start;
                c->ckpt_line[n - 1] = r.line;
            }
        }
        const size_t first = k * c->values_per_record;
        const size_t nf = c->nch - first < c->values_per_record ? c->nch - first
                                                                 : c->values_per_record;
        status = parse_record(c, &r, nf, row + first, diag);
        if (!status && ++k == c->records_per_row) {
            status = pass_row(c, ps, i, row, row_line, diag);
            k = 0;
            i++;
        }
    }
    if (!status && got < 0)
        status = -got;
    if (!status && k != 0)
        status = tirenv_error(diag, TIRENV_EPARSE, c->src.name, row_line, "data",
                              "truncated data: the last row has %zu of its %zu records (a row "
                              "of %zu channels takes %zu records of %zu numbers)", k,
                              c->records_per_row, c->nch, c->records_per_row,
                              c->values_per_record);
    if (!status && i == 0)
        status = tirenv_error(diag, TIRENV_EPARSE, c->src.name, c->header_lines, "data",
                              "no road data after the header; expected %s records",
                              tirenv_crg_encoding_name(c->enc));
    c->nu = i;
    tirenv_lines__free(&r);
    free(row);
    return status;
}

/* ---- header against data --------------------------------------------------------------- */

/* The angle between two headings, rad, in [0, pi]. */
static double angle_gap(double a, double b)
{
    const double d = fmod(fabs(a - b), 2 * M_PI);
    return d > M_PI ? 2 * M_PI - d : d;
}

typedef struct {
    int key;
    const char *name;
    double have;       /* what the data or the rest of the header says */
    double tol;
    int angle;
    const char *what;  /* where `have` comes from */
} agreement;

static int agree(const tirenv_crg *c, const agreement *a, tirenv_diag *diag)
{
    const tirenv_crg__value *k = &c->road[a->key];
    if (!k->line)
        return TIRENV_OK;
    const double gap = a->angle ? angle_gap(k->value, a->have) : fabs(k->value - a->have);
    if (gap <= a->tol)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EPARSE, c->src.name, k->line, a->name,
                        "%.17g, but %s gives %.17g (off by %.3g, more than %.3g)", k->value,
                        a->what, a->have, gap, a->tol);
}

/* The header's reference line keys against the data and each other. Tolerances are
 * OpenCRG's check defaults: 1e-6 relative, 1e-4 m absolute for positions. */
static int check_refline(tirenv_crg *c, const pass_sums *s, tirenv_diag *diag)
{
    const double len = (double)(c->nu - 1) * c->du;
    const double pos_tol = fmax(1e-6 * len, 1e-4);
    const double phi0 = c->road[CRG_RL_START_PHI].value;
    int status = TIRENV_OK;
    if (c->ch_phi != TIRENV_CRG__NONE) {
        const agreement a[] = {
            {CRG_RL_START_PHI, "REFERENCE_LINE_START_PHI", s->phi_first, 1e-5, 1,
             "the heading channel's first segment"},
            {CRG_RL_END_PHI, "REFERENCE_LINE_END_PHI", s->phi_last, 1e-5, 1,
             "the heading channel's last segment"},
        };
        for (size_t k = 0; !status && k < 2; k++)
            status = agree(c, &a[k], diag);
    } else {
        const agreement a = {CRG_RL_END_PHI, "REFERENCE_LINE_END_PHI", phi0, 1e-5, 1,
                             "REFERENCE_LINE_START_PHI without a heading channel"};
        status = agree(c, &a, diag);
    }
    /* The end position: the heading integrated from the start. */
    const double x0 = c->road[CRG_RL_START_X].value, y0 = c->road[CRG_RL_START_Y].value;
    const double xe = c->ch_phi != TIRENV_CRG__NONE ? x0 + s->x_end : x0 + len * cos(phi0);
    const double ye = c->ch_phi != TIRENV_CRG__NONE ? y0 + s->y_end : y0 + len * sin(phi0);
    const agreement ends[] = {
        {CRG_RL_END_X, "REFERENCE_LINE_END_X", xe, pos_tol, 0,
         "the reference line's heading integrated from its start"},
        {CRG_RL_END_Y, "REFERENCE_LINE_END_Y", ye, pos_tol, 0,
         "the reference line's heading integrated from its start"},
    };
    for (size_t k = 0; !status && k < 2; k++)
        status = agree(c, &ends[k], diag);
    if (status)
        return status;
    const double s0 = c->road[CRG_RL_START_S].value, b0 = c->road[CRG_RL_START_B].value;
    const agreement sb[] = {
        {CRG_RL_START_S, "REFERENCE_LINE_START_S", s->s_first, 1e-6, 0,
         "the slope channel's first segment"},
        {CRG_RL_END_S, "REFERENCE_LINE_END_S", s->s_last, 1e-6, 0,
         "the slope channel's last segment"},
        {CRG_RL_END_S, "REFERENCE_LINE_END_S", s0, 1e-6, 0,
         "REFERENCE_LINE_START_S without a slope channel"},
        {CRG_RL_START_B, "REFERENCE_LINE_START_B", s->b_first, 1e-6, 0,
         "the banking channel's first row"},
        {CRG_RL_END_B, "REFERENCE_LINE_END_B", s->b_last, 1e-6, 0,
         "the banking channel's last row"},
        {CRG_RL_END_B, "REFERENCE_LINE_END_B", b0, 1e-6, 0,
         "REFERENCE_LINE_START_B without a banking channel"},
    };
    const int has_s = c->ch_slope != TIRENV_CRG__NONE, has_b = c->ch_bank != TIRENV_CRG__NONE;
    const int use[] = {has_s, has_s, !has_s, has_b, has_b, !has_b};
    for (size_t k = 0; !status && k < 6; k++)
        if (use[k])
            status = agree(c, &sb[k], diag);
    if (status)
        return status;
    /* The end height: with a slope channel, a mismatch within tolerance is spread linearly
     * along the line (OpenCRG's forward/backward integration); beyond it, an error. */
    const tirenv_crg__value *ze = &c->road[CRG_RL_END_Z];
    const double z_end = has_s ? c->rz[c->nu - 1] : c->z0 + len * c->s0;
    const agreement za = {CRG_RL_END_Z, "REFERENCE_LINE_END_Z", z_end, pos_tol, 0,
                          has_s ? "the slope channel integrated from REFERENCE_LINE_START_Z"
                                : "REFERENCE_LINE_START_Z and _START_S"};
    if ((status = agree(c, &za, diag)))
        return status;
    if (has_s && ze->line) {
        const double err = ze->value - c->rz[c->nu - 1];
        for (size_t i = 1; i < c->nu; i++)
            c->rz[i] += err * (double)i / (double)(c->nu - 1);
    }
    return TIRENV_OK;
}

/* The row count against REFERENCE_LINE_END_U. */
static int check_rows(const tirenv_crg *c, tirenv_diag *diag)
{
    if (c->nu < 2)
        return tirenv_error(diag, TIRENV_EPARSE, c->src.name, c->header_lines + 1, "data",
                            "%zu row%s of road data; expected at least two cross sections",
                            c->nu, c->nu == 1 ? "" : "s");
    const tirenv_crg__value *end = &c->road[CRG_RL_END_U];
    if (!end->line)
        return TIRENV_OK;
    const double span = (end->value - c->u0) / c->du;
    const double rows = floor(span + 0.5) + 1;
    if (fabs(span - (rows - 1)) > 1e-3)
        return tirenv_error(diag, TIRENV_EPARSE, c->src.name, end->line,
                            "REFERENCE_LINE_END_U", "%.17g is %.6g increments of %.17g m from "
                            "the start %.17g; expected a whole number", end->value, span,
                            c->du, c->u0);
    if (rows != (double)c->nu)
        return tirenv_error(diag, TIRENV_EPARSE, c->src.name, end->line,
                            /* %.15g: a whole number of rows as digits up to 1e15, beyond
                             * with an exponent (%.0f of 1e308 rows took the whole message) */
                            "REFERENCE_LINE_END_U", "%.17g means %.15g rows from u = %.17g every "
                            "%.17g m, but the road data has %zu rows (truncated data, or a "
                            "wrong header?)", end->value, rows, c->u0, c->du, c->nu);
    return TIRENV_OK;
}

int tirenv_crg__scan(tirenv_crg *c, tirenv_diag *diag)
{
    const int text = is_text(c->enc);
    c->values_per_record = text ? RECORD_BYTES / field_width(c)
                                : RECORD_BYTES / (c->enc == TIRENV_CRG_KRBI ? 4 : 8);
    c->value_size = text ? 0 : (c->enc == TIRENV_CRG_KRBI ? 4 : 8);
    c->records_per_row = (c->nch + c->values_per_record - 1) / c->values_per_record;
    c->u0 = c->road[CRG_RL_START_U].value;
    c->du = c->road[CRG_RL_INCREMENT].value;
    c->z0 = c->road[CRG_RL_START_Z].value;
    c->s0 = c->road[CRG_RL_START_S].value;
    c->b0 = c->road[CRG_RL_START_B].value;
    pass ps = {0};
    int status = text ? scan_text(c, &ps, diag) : scan_binary(c, &ps, diag);
    if (!status)
        status = check_rows(c, diag);
    if (!status)
        status = check_refline(c, &ps.sums, diag);
    return status;
}
