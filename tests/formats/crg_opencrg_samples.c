/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv's reading of OpenCRG files against the ASAM OpenCRG C API's own (vendored under
 * tests/third_party/opencrg, built for the tests only), used in OpenCRG's sequence: load,
 * check, apply the data set's modifiers (the file's $ROAD_CRG_MODS, or OpenCRG's defaults
 * without one), evaluate.
 *
 *   crg_opencrg_samples FILE.crg...
 *   crg_opencrg_samples --same ROAD.crg COPY.crg
 *
 * For each file, at every row u_i and halfway between rows, on 9 tracks from the rightmost
 * to the leftmost long section (and every long section's own v):
 *  - u/v: tirenv's track height (tirenv_crg_track; between rows linear, as a profile is)
 *    against crgEvaluv2z;
 *  - x/y: tirenv's reference line (tirenv_crg_refline) at every row against crgEvaluv2xy
 *    (u_i, 0) and its heading against OpenCRG's chords; then OpenCRG's height at tirenv's point
 *    of the road (x_i - v sin phi_i, y_i + v cos phi_i) on a straight line, and at the
 *    reference line itself on a curved one, against tirenv's track height there.
 * Tolerances: OpenCRG keeps the grid in single precision, so heights agree to half a float32
 * ulp of the largest grid value (2^-24 max|g|) plus 1e-9 m for the sums in double (the
 * reference line's integrated slope); positions to 1e-9 m plus 1e-12 of the line's length
 * (both integrate the same headings in double); headings to 1e-9 rad (a chord of 1e-2 m
 * between points 1e-12 m apart). A file tirenv refuses
 * fails unless OpenCRG refuses it too.
 * With --same: COPY.crg ('tirenv convert' of ROAD.crg to a .crg) lies where ROAD.crg lies
 * and has its heights: OpenCRG's point (u, v) of ROAD.crg at every row and 9 tracks is
 * OpenCRG's point (u, v) of COPY.crg, and OpenCRG's heights of both there agree (tolerances
 * as above, the grid's float32 rounding counted for both files).
 * Prints TAP; exits 1 on a failure. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crgBaseLib.h"
#include "tirenv/crg.h"

#include "../lib/opencrg_open.h"
#include "../lib/tap.h"

static const char *base(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* The largest |grid value| as tirenv reads it: heights less the reference line's, bounded
 * by the heights themselves plus the reference line's height range; a bound is enough. */
static double max_abs(const double *z, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(z[i]))
            m = fmax(m, fabs(z[i]));
    return m;
}

static void compare(const char *path)
{
    const char *name = base(path);
    tirenv_diag diag = {0};
    tirenv_crg *crg = NULL;
    const int status = tirenv_crg_open(path, &crg, &diag);
    int id;
    const int cp = opencrg_open(path, &id);
    const int opencrg_ok = cp >= 0;
    if (status || !opencrg_ok) {
        check(status && !opencrg_ok, "%s: tirenv %s it, OpenCRG %s it%s%s", name,
              status ? "refuses" : "reads", opencrg_ok ? "reads" : "refuses",
              status ? ": " : "", status ? diag.message : "");
        if (opencrg_ok)
            crgContactPointDelete(cp);
        if (id > 0)
            crgDataSetRelease(id);
        tirenv_crg_free(crg);
        return;
    }
    const size_t nu = tirenv_crg_rows(crg), nv = tirenv_crg_long_sections(crg);
    const double v_r = tirenv_crg_v(crg, 0), v_l = tirenv_crg_v(crg, nv - 1);
    const double du = tirenv_crg_u_increment(crg), len = tirenv_crg_u_end(crg) -
                                                          tirenv_crg_u_start(crg);
    const int curved = tirenv_crg_is_curved(crg);
    double *x = malloc(nu * sizeof *x), *y = malloc(nu * sizeof *y), *phi = malloc(nu * sizeof *phi);
    if (tirenv_crg_refline(crg, x, y, phi, &diag)) {
        check(0, "%s: tirenv's reference line: %s", name, diag.message);
        goto done;
    }
    /* The reference line in x/y, and its heading: that of OpenCRG's chord from row to row
     * (OpenCRG's own heading query gives a straight line's END_PHI, or 0 without it, away
     * from its start). */
    double worst_xy = 0, worst_phi = 0, ox_prev = 0, oy_prev = 0;
    for (size_t i = 0; i < nu; i++) {
        double ox, oy;
        const double u = tirenv_crg_u_start(crg) + (double)i * du;
        crgEvaluv2xy(cp, u, 0, &ox, &oy);
        worst_xy = fmax(worst_xy, fmax(fabs(ox - x[i]), fabs(oy - y[i])));
        if (i > 0) {
            const double d = remainder(atan2(oy - oy_prev, ox - ox_prev) - phi[i], 2 * M_PI);
            worst_phi = fmax(worst_phi, fabs(d));
        }
        ox_prev = ox;
        oy_prev = oy;
    }
    const double tol_xy = 1e-9 + 1e-12 * len;
    check(worst_xy <= tol_xy, "%s: the reference line at each of %zu rows is OpenCRG's point "
          "(u, 0) (worst %.3g m, tolerance %.3g m)", name, nu, worst_xy, tol_xy);
    check(worst_phi <= 1e-9, "%s: its heading at each row is that of OpenCRG's chord (worst "
          "%.3g rad, tolerance 1e-9 rad)", name, worst_phi);
    /* Rows with a missing grid value (after the file's GRID_NAN_MODE): around them OpenCRG's
     * bilinear form gives NaN even where the missing value's weight is 0. */
    double *g = malloc(nu * nv * sizeof *g);
    char *row_nan = calloc(nu, 1);
    if (tirenv_crg_grid_rows(crg, 0, nu, g, &diag)) {
        check(0, "%s: tirenv's grid: %s", name, diag.message);
        free(g);
        free(row_nan);
        goto done;
    }
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++)
            row_nan[i] |= (char)isnan(g[i * nv + j]);
    free(g);
    /* Tracks: 9 across the road and every long section. */
    size_t nt = 9 + nv, tracks = 0, refused = 0, refused_nan = 0, points = 0, bad = 0;
    size_t spread = 0;
    double worst_uv = 0, worst_xyz = 0, tol_used = 0;
    size_t xy_points = 0, xy_bad = 0;
    for (size_t t = 0; t < nt; t++) {
        const double v = t < 9 ? v_r + (v_l - v_r) * (double)t / 8 : tirenv_crg_v(crg, t - 9);
        tirenv_crg_track_spec spec = tirenv_crg_track_default();
        spec.v = v;
        tirenv_profile *p = NULL;
        if (tirenv_crg_track(crg, &spec, &p, &diag)) {
            /* A track tirenv refuses (a missing value without GRID_NAN_MODE) must be one
             * where OpenCRG has no number either. */
            ++refused;
            int nan_seen = 0;
            for (size_t i = 0; i < nu && !nan_seen; i++) {
                double oz;
                crgEvaluv2z(cp, tirenv_crg_u_start(crg) + (double)i * du, v, &oz);
                nan_seen = isnan(oz);
            }
            refused_nan += nan_seen;
            continue;
        }
        ++tracks;
        const double *pu = tirenv_profile_x(p), *pz = tirenv_profile_z(p);
        const double tol = ldexp(max_abs(pz, nu), -24) + 1e-9;
        tol_used = fmax(tol_used, tol);
        for (size_t i = 0; i < nu; i++) {
            for (int half = 0; half < 2 && (half == 0 || i + 1 < nu); half++) {
                const double u = pu[i] + 0.5 * half * du;
                const double z = half ? 0.5 * (pz[i] + pz[i + 1]) : pz[i];
                double oz;
                crgEvaluv2z(cp, u, v, &oz);
                ++points;
                if (isnan(oz) && (row_nan[i] || (i + 1 < nu && row_nan[i + 1]))) {
                    ++spread;
                    continue;
                }
                const double d = fabs(oz - z);
                worst_uv = isnan(d) ? INFINITY : fmax(worst_uv, d);
                bad += !(d <= tol);
            }
            /* x/y: tirenv's point of the road at row i. */
            if (curved && v != 0)
                continue;
            double oz;
            crgEvalxy2z(cp, x[i] - v * sin(phi[i]), y[i] + v * cos(phi[i]), &oz);
            if (isnan(oz) && (row_nan[i] || (i + 1 < nu && row_nan[i + 1])))
                continue;
            const double d = fabs(oz - pz[i]);
            worst_xyz = isnan(d) ? INFINITY : fmax(worst_xyz, d);
            ++xy_points;
            xy_bad += !(d <= tol);
        }
        tirenv_profile_free(p);
    }
    free(row_nan);
    check(refused == refused_nan, "%s: %zu tracks read, %zu refused by tirenv for a missing "
          "value (OpenCRG has none there either on %zu of them)", name, tracks, refused,
          refused_nan);
    check(tracks > 0 && bad == 0, "%s: heights in u/v are OpenCRG's at %zu points (%zu beyond "
          "%.3g m; worst %.3g m; %zu NaN in OpenCRG beside a missing value only)", name, points,
          bad, tol_used, worst_uv, spread);
    check(tracks > 0 && xy_points > 0 && xy_bad == 0, "%s: heights in x/y at tirenv's points "
          "of the road are OpenCRG's at %zu points (%zu beyond %.3g m; worst %.3g m)", name,
          xy_points, xy_bad, tol_used, worst_xyz);
done:
    free(x);
    free(y);
    free(phi);
    crgContactPointDelete(cp);
    crgDataSetRelease(id);
    tirenv_crg_free(crg);
}

static void same(const char *road, const char *copy)
{
    int ida, idb;
    const int a = opencrg_open(road, &ida), b = opencrg_open(copy, &idb);
    check(a >= 0 && b >= 0, "OpenCRG reads %s and tirenv's copy %s", base(road), base(copy));
    if (a < 0 || b < 0)
        return;
    double ub, ue, vr, vl, uinc, vinc;
    crgDataSetGetURange(ida, &ub, &ue);
    crgDataSetGetVRange(ida, &vr, &vl);
    crgDataSetGetIncrements(ida, &uinc, &vinc);
    const size_t nu = (size_t)floor((ue - ub) / uinc + 0.5) + 1;
    double worst_uv = 0, worst_z = 0, zmax = 0;
    size_t points = 0, nan_a = 0, nan_mismatch = 0;
    for (int pass = 0; pass < 2; pass++)
        for (size_t i = 0; i < nu; i++)
            for (int t = 0; t < 9; t++) {
                const double u = ub + (double)i * uinc, v = vr + (vl - vr) * t / 8;
                double x, y, ub2, vb2, za, zb;
                crgEvaluv2xy(a, u, v, &x, &y);
                crgEvaluv2z(a, u, v, &za);
                if (pass == 0) {
                    if (isfinite(za))
                        zmax = fmax(zmax, fabs(za));
                    continue;
                }
                crgEvalxy2uv(b, x, y, &ub2, &vb2);
                crgEvalxy2z(b, x, y, &zb);
                worst_uv = fmax(worst_uv, fmax(fabs(ub2 - u), fabs(vb2 - v)));
                ++points;
                if (isnan(za)) {
                    ++nan_a;
                    nan_mismatch += !isnan(zb);
                    continue;
                }
                worst_z = isnan(zb) ? INFINITY : fmax(worst_z, fabs(za - zb));
            }
    const double tol_z = 2 * ldexp(zmax, -24) + 1e-9, tol_xy = 1e-9 + 1e-12 * (ue - ub);
    check(worst_uv <= tol_xy, "%s: every point (u, v) of the road is the copy's point (u, v) "
          "in OpenCRG's x/y (%zu points, worst %.3g m, tolerance %.3g m)", base(copy), points,
          worst_uv, tol_xy);
    check(worst_z <= tol_z && nan_mismatch == 0, "%s: OpenCRG's heights of road and copy "
          "there agree (worst %.3g m, tolerance %.3g m; %zu missing in both)", base(copy),
          worst_z, tol_z, nan_a - nan_mismatch);
}

int main(int argc, char *argv[])
{
    if (argc < 2 || (strcmp(argv[1], "--same") == 0 && argc != 4)) {
        fputs("usage: crg_opencrg_samples FILE.crg...\n"
              "       crg_opencrg_samples --same ROAD.crg COPY.crg\n", stderr);
        return 2;
    }
    crgMsgSetLevel(dCrgMsgLevelNone);
    if (strcmp(argv[1], "--same") == 0)
        same(argv[2], argv[3]);
    else
        for (int k = 1; k < argc; k++)
            compare(argv[k]);
    return tap_done();
}
