/* OpenCRG files opened as roads: the handle, its queries, and tracks evaluated as OpenCRG
 * evaluates a road at (u, v) (docs/formats.md section 5): the grid interpolated linearly
 * between long sections, plus the reference line's height and banking.
 * SPDX-License-Identifier: Apache-2.0 */
#include "formats/crg_impl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "io/io.h"

static const char *const encoding_names[] = {"LRFI", "LDFI", "KRBI", "KDBI"};

const char *tirenv_crg_encoding_name(tirenv_crg_encoding e)
{
    return (unsigned)e < 4 ? encoding_names[e] : NULL;
}

int tirenv_crg_encoding_find(const char *name, tirenv_crg_encoding *e)
{
    for (int k = 0; k < 4; k++)
        if (name && strcasecmp(name, encoding_names[k]) == 0) {
            *e = (tirenv_crg_encoding)k;
            return TIRENV_OK;
        }
    return TIRENV_EINVAL;
}

void tirenv_crg_free(tirenv_crg *c)
{
    if (!c)
        return;
    tirenv_source__close(&c->src);
    free(c->ch_z);
    free(c->kd_line_z);
    free(c->v);
    free(c->ckpt_off);
    free(c->ckpt_line);
    free(c->rz);
    free(c);
}

static int open_source(tirenv_crg *c, tirenv_crg **out, tirenv_diag *diag)
{
    int status = tirenv_crg__parse_header(c, diag);
    if (!status)
        status = tirenv_crg__scan(c, diag);
    if (status) {
        tirenv_crg_free(c);
        return status;
    }
    c->z_offset = c->road[CRG_RL_OFFSET_Z].value + c->mods[CRG_MOD_REFLINE_OFFSET_Z].value;
    status = tirenv_crg__place(c, diag);
    if (status) {
        tirenv_crg_free(c);
        return status;
    }
    *out = c;
    return TIRENV_OK;
}

int tirenv_crg_open(const char *path, tirenv_crg **out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    tirenv_crg *c = calloc(1, sizeof *c);
    if (!c)
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    const int status = tirenv_source__open_file(&c->src, path, diag);
    if (status) {
        free(c);
        return status;
    }
    return open_source(c, out, diag);
}

int tirenv_crg__open_source(const tirenv_source *from, tirenv_crg **out, tirenv_diag *diag)
{
    *out = NULL;
    tirenv_crg *c = calloc(1, sizeof *c);
    if (!c)
        return tirenv_error(diag, TIRENV_ENOMEM, from->name, 0, "", "out of memory");
    const int status = tirenv_source__share(&c->src, from, diag);
    if (status) {
        free(c);
        return status;
    }
    return open_source(c, out, diag);
}

int tirenv_crg_open_memory(const void *data, size_t size, const char *name, tirenv_crg **out,
                           tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    tirenv_crg *c = calloc(1, sizeof *c);
    if (!c)
        return tirenv_error(diag, TIRENV_ENOMEM, name ? name : "", 0, "", "out of memory");
    const int status = tirenv_source__open_memory(&c->src, data, size, name, diag);
    if (status) {
        free(c);
        return status;
    }
    return open_source(c, out, diag);
}

tirenv_crg_encoding tirenv_crg_encoding_of(const tirenv_crg *c) { return c->enc; }
size_t tirenv_crg_rows(const tirenv_crg *c) { return c->nu; }
double tirenv_crg_u_start(const tirenv_crg *c) { return c->u0; }
double tirenv_crg_u_end(const tirenv_crg *c) { return c->u0 + (double)(c->nu - 1) * c->du; }
double tirenv_crg_u_increment(const tirenv_crg *c) { return c->du; }
size_t tirenv_crg_long_sections(const tirenv_crg *c) { return c->nv; }
double tirenv_crg_v(const tirenv_crg *c, size_t j) { return j < c->nv ? c->v[j] : NAN; }
int tirenv_crg_is_curved(const tirenv_crg *c) { return c->ch_phi != TIRENV_CRG__NONE; }
int tirenv_crg_has_slope(const tirenv_crg *c) { return c->ch_slope != TIRENV_CRG__NONE; }
int tirenv_crg_has_banking(const tirenv_crg *c) { return c->ch_bank != TIRENV_CRG__NONE; }

size_t tirenv_crg_row_at(const tirenv_crg *c, double u)
{
    const double k = floor((u - c->u0) / c->du);
    if (!(k > 0))
        return 0;
    return k >= (double)(c->nu - 1) ? c->nu - 1 : (size_t)k;
}

tirenv_crg_track_spec tirenv_crg_track_default(void)
{
    return (tirenv_crg_track_spec){.v = 0, .border_mode_v = -1, .grid_nan_mode = -1,
                                   .grid_nan_offset = NAN};
}

/* ---- evaluation ------------------------------------------------------------------------- */

/* How heights along one track are formed, worked out once per track. */
typedef struct {
    double v;              /* the track's lateral position as asked, m */
    size_t j;              /* grid: between long sections j and j + 1 */
    double w;              /* at weight w of j + 1 */
    double v_bank;         /* v for banking, clamped to the long sections, m */
    int beyond;            /* 1 beyond the outer long sections with border mode 1 or 2 */
    int border_mode;
    double border_offset;  /* BORDER_OFFSET_V, m */
    int nan_mode;          /* GRID_NAN_MODE in effect */
    double nan_offset;     /* GRID_NAN_OFFSET, m */
    double scale;          /* SCALE_Z_GRID, 1 if none */
    double smooth_beg, smooth_end; /* BORDER_SMOOTH_UBEG / _UEND, m */
} track;

static double opt_or(const tirenv_crg__value *k, double fallback)
{
    return k->line ? k->value : fallback;
}

static void locate_v(const tirenv_crg *c, double v, track *t)
{
    size_t lo = 0, hi = c->nv - 1;
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (c->v[mid] <= v)
            lo = mid;
        else
            hi = mid;
    }
    t->j = lo;
    const double w = (v - c->v[lo]) / (c->v[lo + 1] - c->v[lo]);
    t->w = w < 0 ? 0 : w > 1 ? 1 : w;
}

static int track_setup(const tirenv_crg *c, const tirenv_crg_track_spec *spec, track *t,
                       tirenv_diag *diag)
{
    memset(t, 0, sizeof *t);
    if (!isfinite(spec->v))
        return tirenv_error(diag, TIRENV_EINVAL, c->src.name, 0, "v",
                            "track position %g is not finite", spec->v);
    if (spec->border_mode_v < -1 || spec->border_mode_v > 4 || spec->grid_nan_mode < -1 ||
        spec->grid_nan_mode > 2)
        return tirenv_error(diag, TIRENV_EINVAL, c->src.name, 0, "",
                            "border_mode_v %d or grid_nan_mode %d out of range (-1..4, -1..2)",
                            spec->border_mode_v, spec->grid_nan_mode);
    t->v = spec->v;
    t->border_mode = spec->border_mode_v >= 0
                         ? spec->border_mode_v
                         : (int)opt_or(&c->opts[CRG_OPT_BORDER_MODE_V], 0);
    t->border_offset = c->opts[CRG_OPT_BORDER_OFFSET_V].value;
    t->nan_mode = spec->grid_nan_mode >= 0 ? spec->grid_nan_mode : tirenv_crg__nan_mode(c);
    if (isinf(spec->grid_nan_offset))
        return tirenv_error(diag, TIRENV_EINVAL, c->src.name, 0, "grid_nan_offset",
                            "%g: expected a finite height, or NaN for the file's",
                            spec->grid_nan_offset);
    t->nan_offset = spec->grid_nan_mode >= 0 && !isnan(spec->grid_nan_offset)
                        ? spec->grid_nan_offset
                        : c->mods[CRG_MOD_GRID_NAN_OFFSET].value;
    const double scale = c->mods[CRG_MOD_SCALE_Z_GRID].value;
    t->scale = scale != 0 ? scale : 1; /* OpenCRG: a factor of 0 means no scaling */
    t->smooth_beg = c->opts[CRG_OPT_BORDER_SMOOTH_UBEG].value;
    t->smooth_end = c->opts[CRG_OPT_BORDER_SMOOTH_UEND].value;
    const double vmin = c->v[0], vmax = c->v[c->nv - 1], width = vmax - vmin;
    const double eps = 1e-9 * (1 + fabs(vmin) + fabs(vmax));
    double v = spec->v;
    if (v < vmin - eps || v > vmax + eps) {
        switch (t->border_mode) {
        case 0:
            return tirenv_error(diag, TIRENV_ERANGE, c->src.name, 0, "v",
                                "track at v = %.9g m lies beyond the road's long sections, "
                                "v = %.9g to %.9g m (BORDER_MODE_V 0: refused); expected a v "
                                "on the road", spec->v, vmin, vmax);
        case 1:
        case 2:
            t->beyond = 1;
            break;
        case 3:
            v = vmin + fmod(fmod(v - vmin, width) + width, width);
            break;
        case 4: {
            double p = fmod(fmod(v - vmin, 2 * width) + 2 * width, 2 * width);
            v = vmin + (p > width ? 2 * width - p : p);
            break;
        }
        }
    }
    v = v < vmin ? vmin : v > vmax ? vmax : v;
    t->v_bank = v;
    locate_v(c, v, t);
    return TIRENV_OK;
}

/* Grid value of long section j in row (raw values), with GRID_NAN_MODE applied to a missing
 * one; NaN if it stays missing. */
static double grid_value(const tirenv_crg *c, const double row[], size_t j, int nan_mode,
                         double nan_offset)
{
    const double z = row[c->ch_z[j]];
    if (!isnan(z) || nan_mode == 0)
        return z;
    if (nan_mode == 1)
        return nan_offset;
    /* Mode 2: the nearest valid value of the cross section; missing values lie only at its
     * ends (checked at open), so look inward from j. */
    for (size_t k = j + 1; k < c->nv; k++)
        if (!isnan(row[c->ch_z[k]]))
            return row[c->ch_z[k]] + nan_offset;
    for (size_t k = j; k-- > 0;)
        if (!isnan(row[c->ch_z[k]]))
            return row[c->ch_z[k]] + nan_offset;
    return NAN;
}

/* The reference line's height at row i, m (with the offsets). */
static double refline_z(const tirenv_crg *c, size_t i)
{
    const double rz = c->rz ? c->rz[i] : c->z0 + (double)i * c->du * c->s0;
    return rz + c->z_offset;
}

/* Heights over the first and last BORDER_SMOOTH_U* metres are scaled towards the reference
 * line's height at the ends, as OpenCRG's smoothing zones do. */
static double smooth(const tirenv_crg *c, const track *t, size_t i, double z)
{
    const double u = (double)i * c->du, len = (double)(c->nu - 1) * c->du;
    if (t->smooth_beg > u) {
        const double z_beg = refline_z(c, 0);
        z = u / t->smooth_beg * (z - z_beg) + z_beg;
    }
    if (t->smooth_end > len - u) {
        const double z_end = refline_z(c, c->nu - 1);
        z = (len - u) / t->smooth_end * (z - z_end) + z_end;
    }
    return z;
}

static double banking(const tirenv_crg *c, const double row[])
{
    return c->ch_bank != TIRENV_CRG__NONE ? row[c->ch_bank] : c->b0;
}

/* The track's height at row i from its raw values. */
static int track_z(const tirenv_crg *c, const track *t, size_t i, const double row[], double *z,
                   tirenv_diag *diag)
{
    if (t->beyond && t->border_mode == 1) {
        *z = smooth(c, t, i, t->border_offset);
        return TIRENV_OK;
    }
    const int need_l = t->w < 1, need_r = t->w > 0;
    const double zl = need_l ? grid_value(c, row, t->j, t->nan_mode, t->nan_offset) : 0;
    const double zr = need_r ? grid_value(c, row, t->j + 1, t->nan_mode, t->nan_offset) : 0;
    if (isnan(zl) || isnan(zr)) {
        const size_t j = isnan(zl) ? t->j : t->j + 1;
        return tirenv_error(diag, TIRENV_ERANGE, c->src.name, 0, "v",
                            "the track at v = %.9g m needs long section %zu (v = %.9g m) at "
                            "row %zu (u = %.9g m), where the road data has no value; expected "
                            "a track over the road's valid part (or GRID_NAN_MODE 1 or 2 in "
                            "$ROAD_CRG_MODS to fill missing values)", t->v, j + 1, c->v[j],
                            i + 1, c->u0 + (double)i * c->du);
    }
    const double g = need_l && need_r ? (1 - t->w) * zl + t->w * zr : need_l ? zl : zr;
    double h = t->scale * g + refline_z(c, i) + banking(c, row) * t->v_bank;
    if (t->beyond)
        h += t->border_offset;
    *z = smooth(c, t, i, h);
    return TIRENV_OK;
}

/* Rows per block read from the file: about 2 MB of values. */
static size_t block_rows(const tirenv_crg *c)
{
    const size_t n = 262144 / c->nch;
    return n < 16 ? 16 : n;
}

static int track_rows(const tirenv_crg *c, const track *t, size_t first, size_t count,
                      double u[], double z[], double *vals, size_t block, tirenv_diag *diag)
{
    for (size_t i0 = 0; i0 < count; i0 += block) {
        const size_t n = count - i0 < block ? count - i0 : block;
        int status = tirenv_crg__read_rows(c, first + i0, n, vals, diag);
        for (size_t k = 0; !status && k < n; k++) {
            const size_t i = first + i0 + k;
            u[i0 + k] = c->u0 + (double)i * c->du;
            status = track_z(c, t, i, vals + k * c->nch, &z[i0 + k], diag);
        }
        if (status)
            return status;
    }
    return TIRENV_OK;
}

int tirenv_crg_track_rows(const tirenv_crg *c, const tirenv_crg_track_spec *spec, size_t first,
                          size_t count, double u[], double z[], tirenv_diag *diag)
{
    track t;
    int status = track_setup(c, spec, &t, diag);
    if (status)
        return status;
    if ((status = tirenv_crg__rows_asked(c, first, count, diag)))
        return status;
    const size_t block = count < block_rows(c) ? (count ? count : 1) : block_rows(c);
    double *vals = malloc(block * c->nch * sizeof *vals);
    if (!vals)
        return tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    status = track_rows(c, &t, first, count, u, z, vals, block, diag);
    free(vals);
    return status;
}

int tirenv_crg_track(const tirenv_crg *c, const tirenv_crg_track_spec *spec,
                     tirenv_profile **out, tirenv_diag *diag)
{
    *out = NULL;
    double *u = malloc(c->nu * sizeof *u), *z = malloc(c->nu * sizeof *z);
    int status = u && z ? tirenv_crg_track_rows(c, spec, 0, c->nu, u, z, diag)
                        : tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "",
                                       "out of memory");
    if (!status)
        status = tirenv_profile_make(c->nu, u, z, c->src.name, out, diag);
    free(u);
    free(z);
    return status;
}

int tirenv_crg_grid_rows(const tirenv_crg *c, size_t first, size_t count, double z[],
                         tirenv_diag *diag)
{
    const int asked = tirenv_crg__rows_asked(c, first, count, diag);
    if (asked)
        return asked;
    tirenv_crg_track_spec spec = tirenv_crg_track_default();
    spec.v = c->v[0]; /* on the road: only the file's NaN mode, scale and smoothing matter */
    track t;
    int status = track_setup(c, &spec, &t, diag);
    const size_t block = count < block_rows(c) ? (count ? count : 1) : block_rows(c);
    double *vals = status ? NULL : malloc(block * c->nch * sizeof *vals);
    if (!status && !vals)
        status = tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    for (size_t i0 = 0; !status && i0 < count; i0 += block) {
        const size_t n = count - i0 < block ? count - i0 : block;
        status = tirenv_crg__read_rows(c, first + i0, n, vals, diag);
        for (size_t k = 0; !status && k < n; k++) {
            const size_t i = first + i0 + k;
            const double *row = vals + k * c->nch;
            for (size_t j = 0; j < c->nv; j++) {
                const double g = grid_value(c, row, j, t.nan_mode, t.nan_offset);
                const double h = t.scale * g + refline_z(c, i) + banking(c, row) * c->v[j];
                z[(i0 + k) * c->nv + j] = smooth(c, &t, i, h);
            }
        }
    }
    free(vals);
    return status;
}

/* ---- the reference line in x/y --------------------------------------------------------- */

int tirenv_crg_refline(const tirenv_crg *c, double x[], double y[], double phi[],
                       tirenv_diag *diag)
{
    return tirenv_crg__refline(c, 1, x, y, phi, diag);
}

/* Rows first .. first + count - 1 of the reference line from their positions as integrated
 * (px, py, pp[k] for row first + k): the end position's mismatch spread, the header's global
 * offsets, the REFLINE_* modifiers, and with refpoint the placement by reference point. */
static void refline_finish(const tirenv_crg *c, int refpoint, size_t first, size_t count,
                           double ex, double ey, double px[], double py[], double pp[])
{
    const size_t n = c->nu;
    const double po = c->road[CRG_RL_OFFSET_PHI].value;
    const double xo = c->road[CRG_RL_OFFSET_X].value, yo = c->road[CRG_RL_OFFSET_Y].value;
    const double rot = c->mods[CRG_MOD_REFLINE_OFFSET_PHI].value;
    const double rcx = opt_or(&c->mods[CRG_MOD_REFLINE_ROTCENTER_X], c->road[CRG_RL_START_X].value);
    const double rcy = opt_or(&c->mods[CRG_MOD_REFLINE_ROTCENTER_Y], c->road[CRG_RL_START_Y].value);
    const double mx = c->mods[CRG_MOD_REFLINE_OFFSET_X].value;
    const double my = c->mods[CRG_MOD_REFLINE_OFFSET_Y].value;
    for (size_t k = 0; k < count; k++) {
        const double f = (double)(first + k) / (double)(n - 1);
        const double lx = px[k] + f * ex, ly = py[k] + f * ey;
        const double gx = xo + cos(po) * lx - sin(po) * ly;
        const double gy = yo + sin(po) * lx + cos(po) * ly;
        px[k] = rcx + cos(rot) * (gx - rcx) - sin(rot) * (gy - rcy) + mx;
        py[k] = rcy + sin(rot) * (gx - rcx) + cos(rot) * (gy - rcy) + my;
        pp[k] += po + rot;
    }
    /* The placement by reference point (crg_place.c; never with the REFLINE_OFFSET_*
     * modifiers): turned about the reference point, then moved to where it goes. */
    if (refpoint && c->refpoint) {
        const double cr = cos(c->rp_rot), sr = sin(c->rp_rot);
        const double fx = c->rp_from_x, fy = c->rp_from_y;
        for (size_t k = 0; k < count; k++) {
            const double dx = px[k] - fx, dy = py[k] - fy;
            px[k] = c->rp_x + cr * dx - sr * dy;
            py[k] = c->rp_y + sr * dx + cr * dy;
            pp[k] += c->rp_rot;
        }
    }
}

/* The end position, where given, is more precise than the integrated headings: its mismatch
 * with the last row as integrated (checked at open) is spread linearly along the line. */
static void end_mismatch(const tirenv_crg *c, double x_last, double y_last, double *ex,
                         double *ey)
{
    *ex = c->road[CRG_RL_END_X].line ? c->road[CRG_RL_END_X].value - x_last : 0;
    *ey = c->road[CRG_RL_END_Y].line ? c->road[CRG_RL_END_Y].value - y_last : 0;
}

/* A straight line's row i as integrated: from START_X/Y at START_PHI. */
static void straight_row(const tirenv_crg *c, size_t i, double *x, double *y, double *phi)
{
    const double phi0 = c->road[CRG_RL_START_PHI].value;
    *x = c->road[CRG_RL_START_X].value + (double)i * c->du * cos(phi0);
    *y = c->road[CRG_RL_START_Y].value + (double)i * c->du * sin(phi0);
    *phi = phi0;
}

int tirenv_crg__refline_rows(const tirenv_crg *c, int refpoint, size_t first, size_t count,
                             double x[], double y[], double phi[])
{
    if (c->ch_phi != TIRENV_CRG__NONE || first > c->nu || count > c->nu - first)
        return TIRENV_EINVAL;
    double xl, yl, pl, ex, ey;
    straight_row(c, c->nu - 1, &xl, &yl, &pl);
    end_mismatch(c, xl, yl, &ex, &ey);
    for (size_t k = 0; k < count; k++)
        straight_row(c, first + k, &x[k], &y[k], &phi[k]);
    refline_finish(c, refpoint, first, count, ex, ey, x, y, phi);
    return TIRENV_OK;
}

int tirenv_crg__refline(const tirenv_crg *c, int refpoint, double x[], double y[],
                        double phi[], tirenv_diag *diag)
{
    const size_t n = c->nu;
    double *px = x ? x : malloc(n * sizeof *px), *py = y ? y : malloc(n * sizeof *py);
    double *pp = phi ? phi : malloc(n * sizeof *pp);
    double *vals = NULL;
    const size_t block = n < block_rows(c) ? n : block_rows(c);
    int status = px && py && pp ? TIRENV_OK
                                : tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "",
                                               "out of memory");
    if (!status && c->ch_phi != TIRENV_CRG__NONE) {
        px[0] = c->road[CRG_RL_START_X].value;
        py[0] = c->road[CRG_RL_START_Y].value;
        if (!(vals = malloc(block * c->nch * sizeof *vals)))
            status = tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
        for (size_t i0 = 0; !status && i0 < n; i0 += block) {
            const size_t m = n - i0 < block ? n - i0 : block;
            status = tirenv_crg__read_rows(c, i0, m, vals, diag);
            for (size_t k = 0; !status && k < m; k++)
                if (i0 + k >= 1)
                    pp[i0 + k] = vals[k * c->nch + c->ch_phi];
        }
        if (!status) {
            pp[0] = pp[1];
            for (size_t i = 1; i < n; i++) {
                px[i] = px[i - 1] + c->du * cos(pp[i]);
                py[i] = py[i - 1] + c->du * sin(pp[i]);
            }
        }
    } else if (!status) {
        for (size_t i = 0; i < n; i++)
            straight_row(c, i, &px[i], &py[i], &pp[i]);
    }
    if (!status) {
        double ex, ey;
        end_mismatch(c, px[n - 1], py[n - 1], &ex, &ey);
        refline_finish(c, refpoint, 0, n, ex, ey, px, py, pp);
    }
    free(vals);
    if (!x)
        free(px);
    if (!y)
        free(py);
    if (!phi)
        free(pp);
    return status;
}

/* ---- a track a block at a time ---------------------------------------------------------- */

struct tirenv_crg_track_reader {
    const tirenv_crg *crg;
    track t;
    size_t block;
    size_t next_row;       /* row of buf[pos] */
    size_t pos, len;       /* buffered vertices */
    double *u, *z, *vals;
};

void tirenv_crg_track_reader_free(tirenv_crg_track_reader *r)
{
    if (!r)
        return;
    free(r->u);
    free(r->z);
    free(r->vals);
    free(r);
}

int tirenv_crg_track_reader_open(const tirenv_crg *c, const tirenv_crg_track_spec *spec,
                                 tirenv_crg_track_reader **out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    tirenv_crg_track_reader *r = calloc(1, sizeof *r);
    if (!r)
        return tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    r->crg = c;
    r->block = block_rows(c);
    int status = track_setup(c, spec, &r->t, diag);
    if (!status) {
        r->u = malloc(r->block * sizeof *r->u);
        r->z = malloc(r->block * sizeof *r->z);
        r->vals = malloc(r->block * c->nch * sizeof *r->vals);
        if (!r->u || !r->z || !r->vals)
            status = tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    }
    if (status) {
        tirenv_crg_track_reader_free(r);
        return status;
    }
    *out = r;
    return TIRENV_OK;
}

int tirenv_crg_track_reader_next(tirenv_crg_track_reader *r, double *u, double *z, int *got,
                                 tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *got = 0;
    if (r->pos == r->len) {
        const tirenv_crg *c = r->crg;
        const size_t first = r->next_row + r->len;
        if (first >= c->nu)
            return TIRENV_OK;
        const size_t n = c->nu - first < r->block ? c->nu - first : r->block;
        const int status = track_rows(c, &r->t, first, n, r->u, r->z, r->vals, r->block, diag);
        if (status)
            return status;
        r->next_row = first;
        r->pos = 0;
        r->len = n;
    }
    *u = r->u[r->pos];
    *z = r->z[r->pos];
    r->pos++;
    *got = 1;
    return TIRENV_OK;
}

int tirenv_crg_track_reader_source(void *reader, double *u, double *z, int *got,
                                   tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_crg_track_reader_next(reader, u, z, got, diag);
}

/* ---- several tracks a block at a time ---------------------------------------------------- */

/* Each block of rows is read once for all the tracks: n tracks cost one read of the file. */
struct tirenv_crg__tracks_reader {
    const tirenv_crg *crg;
    size_t n;
    track *t;              /* [n] */
    size_t block;          /* rows per block */
    size_t first, len;     /* rows in vals: first .. first + len - 1 */
    size_t next;           /* the row next returns */
    double *vals;          /* [block * nch] */
};

void tirenv_crg__tracks_reader_free(tirenv_crg__tracks_reader *r)
{
    if (!r)
        return;
    free(r->t);
    free(r->vals);
    free(r);
}

int tirenv_crg__tracks_reader_open(const tirenv_crg *c, const tirenv_crg_track_spec *spec,
                                   size_t n, const double v[],
                                   tirenv_crg__tracks_reader **out, tirenv_diag *diag)
{
    *out = NULL;
    tirenv_crg__tracks_reader *r = calloc(1, sizeof *r);
    if (!r || !(r->t = calloc(n ? n : 1, sizeof *r->t))) {
        free(r);
        return tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    }
    r->crg = c;
    r->n = n;
    r->block = block_rows(c);
    int status = TIRENV_OK;
    for (size_t k = 0; k < n && !status; ++k) {
        tirenv_crg_track_spec sk = *spec;
        if (v)
            sk.v = v[k];
        status = track_setup(c, &sk, &r->t[k], diag);
    }
    if (!status && !(r->vals = malloc(r->block * c->nch * sizeof *r->vals)))
        status = tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    if (status) {
        tirenv_crg__tracks_reader_free(r);
        return status;
    }
    *out = r;
    return TIRENV_OK;
}

int tirenv_crg__tracks_reader_next(tirenv_crg__tracks_reader *r, double *u, double z[],
                                   int *got, tirenv_diag *diag)
{
    const tirenv_crg *c = r->crg;
    *got = 0;
    if (r->next >= c->nu)
        return TIRENV_OK;
    if (r->next >= r->first + r->len) {
        const size_t n = c->nu - r->next < r->block ? c->nu - r->next : r->block;
        const int status = tirenv_crg__read_rows(c, r->next, n, r->vals, diag);
        if (status)
            return status;
        r->first = r->next;
        r->len = n;
    }
    const size_t i = r->next;
    const double *row = r->vals + (i - r->first) * c->nch;
    for (size_t k = 0; k < r->n; ++k) {
        const int status = track_z(c, &r->t[k], i, row, &z[k], diag);
        if (status)
            return status;
    }
    *u = c->u0 + (double)i * c->du;
    r->next++;
    *got = 1;
    return TIRENV_OK;
}
