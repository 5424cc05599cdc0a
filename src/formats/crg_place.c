/* SPDX-License-Identifier: Apache-2.0 */
/* OpenCRG's placement of a road by a reference point (docs/formats.md section 5,
 * *Modifiers*): $ROAD_CRG_MODS REFPOINT_*, or, for a file without a $ROAD_CRG_MODS section,
 * OpenCRG's default modifiers (REFPOINT_X = Y = Z = PHI = 0 with GRID_NAN_MODE 2), applied as
 * the ASAM OpenCRG C API applies them when a data set is checked and its modifiers applied
 * (crgCheck, then crgDataSetModifiersApply): the reference point is the road's point at
 * (u_ref, v_ref), by default the start of the reference line at LONG_SECTION_V_RIGHT;
 * the road is turned about it so that the reference line's heading there becomes REFPOINT_PHI,
 * moved so that it lies at (REFPOINT_X, REFPOINT_Y), and every height shifted so that the
 * road's height there becomes REFPOINT_Z. */
#include "formats/crg_impl.h"

#include <math.h>
#include <stdlib.h>

static int set(const tirenv_crg__value *k) { return k->line != 0; }

int tirenv_crg__nan_mode(const tirenv_crg *c)
{
    const tirenv_crg__value *m = &c->mods[CRG_MOD_GRID_NAN_MODE];
    return m->line ? (int)m->value : c->has_mods ? 0 : 2;
}

/* Two modifiers that OpenCRG's check refuses together: the error names the later one. */
static int exclusive(const tirenv_crg *c, int a, int b, const char *na, const char *nb,
                     tirenv_diag *diag)
{
    if (!set(&c->mods[a]) || !set(&c->mods[b]))
        return TIRENV_OK;
    const int later_b = c->mods[b].line > c->mods[a].line;
    const tirenv_crg__value *first = &c->mods[later_b ? a : b], *second = &c->mods[later_b ? b : a];
    const char *n1 = later_b ? na : nb, *n2 = later_b ? nb : na;
    return tirenv_error(diag, TIRENV_EPARSE, c->src.name, second->line, n2,
                        "%s with %s (line %zu): OpenCRG refuses both; expected one of them "
                        "in $ROAD_CRG_MODS", n2, n1, first->line);
}

/* OpenCRG's point at (u, v) of a reference line given by its rows' x, y (crgDataEvaluv2xy):
 * within the line, between the lateral lines through the rows, each along the normal of
 * the chord from the row before to the row after; beyond its ends, straight on at the end's
 * heading. */
/* Rows base .. base + len - 1 of the reference line: x, y, phi[k] of row base + k. */
typedef struct {
    const double *x, *y, *phi;
    size_t base;
} rows_view;

/* The row index i at or before u of OpenCRG's evaluation (tirenv_crg_row_at) clamped to
 * 0 .. rows - 2, so that rows i and i + 1 exist, and the fraction of a row beyond it (may be
 * < 0 or > 1 beyond the ends). */
static size_t row_of(const tirenv_crg *c, double u, double *frac)
{
    size_t i = tirenv_crg_row_at(c, u);
    if (i >= c->nu - 1)
        i = c->nu - 2;
    if (frac)
        *frac = (u - c->u0) / c->du - (double)i;
    return i;
}

/* Row j of a view. */
#define X(j) (r->x[(j) - r->base])
#define Y(j) (r->y[(j) - r->base])

static void uv2xy(const tirenv_crg *c, const rows_view *r, double phi_first, double phi_last,
                  double u, double v, double *ox, double *oy)
{
    const size_t n = c->nu;
    double f;
    const size_t i = row_of(c, u, &f);
    if (f < 0) {
        const double d = f * c->du;
        *ox = X(0) + d * cos(phi_first) - v * sin(phi_first);
        *oy = Y(0) + d * sin(phi_first) + v * cos(phi_first);
        return;
    }
    if (f > 1) {
        const double d = (f - 1) * c->du;
        *ox = X(n - 1) + d * cos(phi_last) - v * sin(phi_last);
        *oy = Y(n - 1) + d * sin(phi_last) + v * cos(phi_last);
        return;
    }
    double n12[2] = {-(Y(i + 1) - Y(i)), X(i + 1) - X(i)};
    const double l12 = hypot(n12[0], n12[1]);
    n12[0] /= l12;
    n12[1] /= l12;
    double n1[2] = {n12[0], n12[1]}, n2[2] = {n12[0], n12[1]};
    if (i > 0) {
        n1[0] = -(Y(i + 1) - Y(i - 1));
        n1[1] = X(i + 1) - X(i - 1);
        const double l = hypot(n1[0], n1[1]);
        n1[0] /= l;
        n1[1] /= l;
    }
    if (i < n - 2) {
        n2[0] = -(Y(i + 2) - Y(i));
        n2[1] = X(i + 2) - X(i);
        const double l = hypot(n2[0], n2[1]);
        n2[0] /= l;
        n2[1] /= l;
    }
    /* The lateral lines meet the chord's normal so that a track keeps its offset v. */
    const double d1 = n1[0] * n12[0] + n1[1] * n12[1], d2 = n2[0] * n12[0] + n2[1] * n12[1];
    if (fabs(d1) > 1e-10) {
        n1[0] /= d1;
        n1[1] /= d1;
    }
    if (fabs(d2) > 1e-10) {
        n2[0] /= d2;
        n2[1] /= d2;
    }
    const double ax = X(i) + v * n1[0], ay = Y(i) + v * n1[1];
    const double bx = X(i + 1) + v * n2[0], by = Y(i + 1) + v * n2[1];
    *ox = ax + f * (bx - ax);
    *oy = ay + f * (by - ay);
}
#undef X
#undef Y

/* OpenCRG's heading at u (crgDataEvaluv2pk): that of the segment ending at the row at or
 * before u, not interpolated; within half a metre (at least a row) of either end the line's
 * first or last heading. */
static double heading_at(const tirenv_crg *c, const rows_view *r, double phi_first,
                         double phi_last, double u)
{
    const size_t n = c->nu, i = row_of(c, u, NULL);
    size_t nu = (size_t)(0.5 / c->du);
    if (nu < 1)
        nu = 1;
    if (nu > i)
        return phi_first;
    if (i + nu >= n)
        return phi_last;
    return r->phi[i - r->base];
}

/* The road's height at (u, v) before the placement: the track at v (OpenCRG's default border
 * mode beyond the long sections is 2, keep the last value, unless the file says otherwise)
 * between the rows around u, linear in u as OpenCRG's bilinear evaluation is; u beyond the
 * rows takes the end row's. */
static int height_at(const tirenv_crg *c, double u, double v, double *z, tirenv_diag *diag)
{
    tirenv_crg_track_spec spec = tirenv_crg_track_default();
    spec.v = v;
    if (!set(&c->opts[CRG_OPT_BORDER_MODE_V]))
        spec.border_mode_v = 2;
    double f;
    const size_t i = row_of(c, u, &f);
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    double uu[2], zz[2];
    const int status = tirenv_crg_track_rows(c, &spec, i, 2, uu, zz, diag);
    if (status)
        return status;
    *z = zz[0] + f * (zz[1] - zz[0]);
    return TIRENV_OK;
}

int tirenv_crg__place(tirenv_crg *c, tirenv_diag *diag)
{
    const tirenv_crg__value *m = c->mods;
    int status = exclusive(c, CRG_MOD_REFPOINT_U, CRG_MOD_REFPOINT_U_FRACTION, "REFPOINT_U",
                           "REFPOINT_U_FRACTION", diag);
    if (!status)
        status = exclusive(c, CRG_MOD_REFPOINT_V, CRG_MOD_REFPOINT_V_FRACTION, "REFPOINT_V",
                           "REFPOINT_V_FRACTION", diag);
    if (status)
        return status;
    int by_point = !c->has_mods;
    for (int k = CRG_MOD_REFPOINT_U; k <= CRG_MOD_REFPOINT_PHI; k++)
        by_point |= set(&m[k]);
    if (!by_point)
        return TIRENV_OK;
    static const char *const offsets[] = {"REFLINE_OFFSET_PHI", "REFLINE_OFFSET_X",
                                           "REFLINE_OFFSET_Y", "REFLINE_OFFSET_Z"};
    for (int k = CRG_MOD_REFLINE_OFFSET_PHI; k <= CRG_MOD_REFLINE_OFFSET_Z; k++)
        if (set(&m[k]))
            return tirenv_error(diag, TIRENV_EPARSE, c->src.name, m[k].line,
                                offsets[k - CRG_MOD_REFLINE_OFFSET_PHI],
                                "a REFLINE_OFFSET_* modifier with REFPOINT_* ones: OpenCRG "
                                "refuses placing a road both by offset and by reference "
                                "point; expected one of the two in $ROAD_CRG_MODS");
    /* The reference point in (u, v): REFPOINT_U, or START_U + U_FRACTION * length +
     * U_OFFSET; REFPOINT_V, or v_right + V_FRACTION * (v_left - v_right) + V_OFFSET (OpenCRG's
     * check sets the fractions to 0 when neither is given). OpenCRG's v_right and v_left are
     * LONG_SECTION_V_RIGHT and _LEFT as the header states them, 0 without them, except that
     * long sections at given, evenly spaced v (within 1e-3 of the spacing) start v_right at
     * the first of them: its loader sets no other. */
    const double u_end = tirenv_crg_u_end(c);
    double v_right = c->road[CRG_LS_V_RIGHT].value, v_left = c->road[CRG_LS_V_LEFT].value;
    if (!set(&c->road[CRG_LS_V_RIGHT]) && !c->v_numbered) {
        double dv_min = INFINITY, dv_max = 0;
        for (size_t j = 0; j + 1 < c->nv; j++) {
            dv_min = fmin(dv_min, c->v[j + 1] - c->v[j]);
            dv_max = fmax(dv_max, c->v[j + 1] - c->v[j]);
        }
        if ((dv_max - dv_min) / dv_min < 1e-3)
            v_right = c->v[0];
    }
    const double u = set(&m[CRG_MOD_REFPOINT_U])
                         ? m[CRG_MOD_REFPOINT_U].value
                         : c->u0 + m[CRG_MOD_REFPOINT_U_FRACTION].value * (u_end - c->u0) +
                               m[CRG_MOD_REFPOINT_U_OFFSET].value;
    const double v = set(&m[CRG_MOD_REFPOINT_V])
                         ? m[CRG_MOD_REFPOINT_V].value
                         : v_right + m[CRG_MOD_REFPOINT_V_FRACTION].value * (v_left - v_right) +
                               m[CRG_MOD_REFPOINT_V_OFFSET].value;
    if (!isfinite(u) || !isfinite(v))
        return tirenv_error(diag, TIRENV_EPARSE, c->src.name, 0, "REFPOINT",
                            "the reference point (u, v) = (%g, %g) m is not finite", u, v);
    double z_from;
    if ((status = height_at(c, u, v, &z_from, diag)))
        return status;
    /* The line as the header places it around u (rows i - 1 .. i + 2) and at its end: a
     * straight one from its start, a curved one integrated whole. */
    const size_t n = c->nu, i = row_of(c, u, NULL);
    const size_t lo = i > 0 ? i - 1 : 0, hi = i + 2 < n ? i + 2 : n - 1;
    const int curved = tirenv_crg_is_curved(c);
    const size_t len = curved ? n : hi - lo + 1;
    double *x = malloc(len * sizeof *x), *y = malloc(len * sizeof *y);
    double *phi = malloc(len * sizeof *phi);
    double last[3];
    if (!x || !y || !phi)
        status = tirenv_error(diag, TIRENV_ENOMEM, c->src.name, 0, "", "out of memory");
    else if (curved)
        status = tirenv_crg__refline(c, 0, x, y, phi, diag);
    else if ((status = tirenv_crg__refline_rows(c, 0, lo, len, x, y, phi)) == TIRENV_OK)
        status = tirenv_crg__refline_rows(c, 0, n - 1, 1, &last[0], &last[1], &last[2]);
    if (!status) {
        const rows_view r = {x, y, phi, curved ? 0 : lo};
        /* OpenCRG's first heading is REFERENCE_LINE_START_PHI as given (0 without it), its
         * last the line's last; the header's global offsets turn both. */
        const double po = c->road[CRG_RL_OFFSET_PHI].value;
        const double phi_first = c->road[CRG_RL_START_PHI].value + po;
        const double phi_last = curved ? phi[n - 1] : last[2];
        uv2xy(c, &r, phi_first, phi_last, u, v, &c->rp_from_x, &c->rp_from_y);
        c->rp_rot = m[CRG_MOD_REFPOINT_PHI].value - heading_at(c, &r, phi_first, phi_last, u);
        c->rp_x = m[CRG_MOD_REFPOINT_X].value;
        c->rp_y = m[CRG_MOD_REFPOINT_Y].value;
        c->z_offset += m[CRG_MOD_REFPOINT_Z].value - z_from;
        c->refpoint = 1;
    }
    free(x);
    free(y);
    free(phi);
    return status;
}
