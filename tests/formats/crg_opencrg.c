/* SPDX-License-Identifier: Apache-2.0 */
/* An independent reader of tirenv's OpenCRG files: the ASAM OpenCRG C API (vendored under
 * tests/third_party/opencrg, built for the tests only), used in OpenCRG's own sequence: load,
 * check, apply the data set's modifiers (the file's $ROAD_CRG_MODS, or OpenCRG's defaults if
 * it states none), then evaluate in x/y and u/v. (Project Chrono's CRGTerrain loads and
 * checks but applies no modifiers; a file with a $ROAD_CRG_MODS section that sets none, as
 * every file tirenv writes, is evaluated the same both ways.)
 *
 *   crg_opencrg ROAD.crg EFFECTIVE.crg CURVE.csv V [REACH]
 *
 * CURVE.csv is 'tirenv envelope's curve (x_m, ..., h_m in the third column) over ROAD.crg at
 * the track v = V, and EFFECTIVE.crg the effective road the same run wrote (-o). For every
 * row, the point (u = x_m, v = V) of the road, placed by OpenCRG, is found in the effective
 * road at the same u and v (xy2uv), and OpenCRG's height of the effective road there is the
 * curve's h; where no obstacle is within REACH m (default 1) of u, it is also the road's own
 * height. Tolerances: 1e-9 m in x/y/u/v (both files state the same straight line; round-off
 * of OpenCRG's projection), 2e-8 m in z (the CSV's 9 significant digits of a height of a few
 * metres are 5e-9 m; the effective road's flat parts equal the road to the equilibrium's step
 * tolerance, 1e-10 m). ROAD.crg "-" stands for a road that is no OpenCRG file (a CSV, an RDF, a
 * generated obstacle), whose x is u and y is v: each h must then be where that road's x and y
 * are (the flat rows' check left out). Prints TAP; exits 1 on a failure. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crgBaseLib.h"

#include "../lib/opencrg_open.h"
#include "../lib/tap.h"

int main(int argc, char *argv[])
{
    if (argc < 5) {
        fputs("usage: crg_opencrg ROAD.crg EFFECTIVE.crg CURVE.csv V [REACH]\n", stderr);
        return 2;
    }
    const double v = atof(argv[4]), reach = argc > 5 ? atof(argv[5]) : 1.0;
    crgMsgSetLevel(dCrgMsgLevelNone);
    const int on_axis = strcmp(argv[1], "-") == 0; /* the road's x = u, y = v */
    const int road = on_axis ? 0 : opencrg_open(argv[1], NULL), eff = opencrg_open(argv[2], NULL);
    if (!on_axis)
        check(road >= 0, "OpenCRG loads and checks the road %s", argv[1]);
    check(eff >= 0, "OpenCRG loads and checks tirenv's effective road %s", argv[2]);
    if (road < 0 || eff < 0)
        return 1;
    FILE *fp = fopen(argv[3], "r");
    char line[512];
    if (!fp || !fgets(line, sizeof line, fp)) {
        check(0, "the curve %s opens", argv[3]);
        return 1;
    }
    /* The obstacle's extent: where the road's height along the track is not its first. */
    size_t n = 0, same_place = 0, same_h = 0, flat = 0, same_flat = 0;
    double worst_xy = 0, worst_h = 0, worst_flat = 0;
    double *u = NULL, *h = NULL;
    size_t cap = 0;
    while (fgets(line, sizeof line, fp)) {
        if (n == cap) {
            cap = cap ? 2 * cap : 1024;
            u = realloc(u, cap * sizeof *u);
            h = realloc(h, cap * sizeof *h);
        }
        char *p = line;
        u[n] = strtod(p, &p);
        strtod(p + 1, &p);  /* z_m */
        h[n] = strtod(p + 1, &p);
        ++n;
    }
    fclose(fp);
    double z_first = 0;
    if (!on_axis)
        crgEvaluv2z(road, u[0], v, &z_first);
    for (size_t i = 0; i < n; ++i) {
        double x = u[i], y = v, ue, ve, z_eff, z_road = 0;
        const int ok = (on_axis || crgEvaluv2xy(road, u[i], v, &x, &y)) &&
                       crgEvalxy2uv(eff, x, y, &ue, &ve) && crgEvalxy2z(eff, x, y, &z_eff) &&
                       (on_axis || crgEvalxy2z(road, x, y, &z_road));
        const double dxy = ok ? fmax(fabs(ue - u[i]), fabs(ve - v)) : INFINITY;
        worst_xy = fmax(worst_xy, dxy);
        same_place += dxy <= 1e-9;
        const double dh = ok ? fabs(z_eff - h[i]) : INFINITY;
        worst_h = fmax(worst_h, dh);
        same_h += dh <= 2e-8;
        /* Flat ground around: the road's height is its first all over [u - reach, u + reach]. */
        int is_flat = !on_axis;
        for (double s = -reach; s <= reach && is_flat; s += reach / 50) {
            double z;
            crgEvaluv2z(road, u[i] + s, v, &z);
            is_flat = fabs(z - z_first) <= 1e-12;
        }
        if (is_flat) {
            ++flat;
            const double d = fabs(z_eff - z_road);
            worst_flat = fmax(worst_flat, d);
            same_flat += d <= 2e-8;
        }
    }
    check(n > 0 && same_place == n, "every row's point of the road (u, v = %g) is the effective "
          "road's point at the same u and v in OpenCRG's x/y (%zu of %zu; worst %.3g m)", v,
          same_place, n, worst_xy);
    check(n > 0 && same_h == n, "OpenCRG's height of the effective road there is the curve's h "
          "(%zu of %zu within 2e-8 m; worst %.3g m)", same_h, n, worst_h);
    if (!on_axis)
        check(flat > 0 && same_flat == flat, "away from the obstacle the effective road is the "
              "road (%zu of %zu flat rows within 2e-8 m; worst %.3g m)", same_flat, flat,
              worst_flat);
    free(u);
    free(h);
    return tap_done();
}
