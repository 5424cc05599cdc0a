/* SPDX-License-Identifier: Apache-2.0 */
/* Chrono's way in (fmu/README.md, "Chrono's way in"): the effective road of a tire over an
 * OpenCRG road, queried as a Chrono terrain queries its ground, height and normal at a world
 * point (x, y), two ways:
 *   1. through the FMU: the wheel's position along the road goes in as x (u on the road's
 *      reference line; the FMU's track parameter is the wheel's v), terrain_height and
 *      terrain_normal come out (normal in the road's frame: x along u, y to the left);
 *   2. through the effective road tirenv wrote as a .crg (tirenv envelope ... -o EFF.crg), read
 *      with the OpenCRG C API: load, check, apply modifiers (Chrono's CRGTerrain skips this
 *      step, the same for a file with an empty $ROAD_CRG_MODS section such as tirenv writes),
 *      then height = crgEvalxy2z(x, y) and the normal from central differences of it, 1 mm
 *      along and across the road.
 * The world point of each query is the road's point (u, v) as OpenCRG places it. Heights must
 * agree within 2e-8 m (2 x the 1e-8 m a height a few metres high keeps in the CRG's double
 * grid after REFERENCE_LINE_START_Z is added back); the normals are reported (the FMU's is the
 * model's effective slope -fx/fz, the file's the slope of h: they differ where h bends), and
 * must both be unit vectors with no lateral part (the road is 2-D across the tire).
 *
 *   chrono_terrain FMU_DIR ROAD.crg EFF.crg V LOAD U_FROM U_TO DU
 * FMU_DIR is the unpacked FMU (modelDescription.xml, binaries/, resources/). Prints TAP. */
#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crgBaseLib.h"
#include "fmi2.h"

/* The file's normal comes from its heights 1 mm ahead, behind, left and right of the point,
 * each found from world x/y (xy2uv inside OpenCRG): its two long sections carry the same h,
 * so the lateral part is round-off of the projection, far below 1e-6. */
#define LATERAL 1e-6

static int n_checks, n_failed;

static void check(int ok, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("%s %d - ", ok ? "ok" : "not ok", ++n_checks);
    vprintf(fmt, ap);
    putchar('\n');
    va_end(ap);
    n_failed += !ok;
}

static void logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    (void)env, (void)status;
    fprintf(stderr, "# [%s] %s: %s\n", category, instance, message);
}

/* The GUID from modelDescription.xml (the attribute guid="..."). */
static int read_guid(const char *dir, char *guid, size_t n)
{
    char path[1200], buf[4096];
    snprintf(path, sizeof path, "%s/modelDescription.xml", dir);
    FILE *fp = fopen(path, "r");
    const size_t got = fp ? fread(buf, 1, sizeof buf - 1, fp) : 0;
    if (fp)
        fclose(fp);
    buf[got] = '\0';
    const char *p = strstr(buf, " guid=\"");
    if (!p)
        return -1;
    p += 7;
    const size_t len = strcspn(p, "\"");
    snprintf(guid, n, "%.*s", (int)len, p);
    return 0;
}

#define SYM(name) (*(void **)&name##_ = dlsym(so, #name))

int main(int argc, char *argv[])
{
    if (argc != 9) {
        fputs("usage: chrono_terrain FMU_DIR ROAD.crg EFF.crg V LOAD U_FROM U_TO DU\n", stderr);
        return 2;
    }
    const char *dir = argv[1];
    const double v = atof(argv[4]), load = atof(argv[5]), u_from = atof(argv[6]);
    const double u_to = atof(argv[7]), du = atof(argv[8]);
    char path[1200], guid[128], resources[1300];
    snprintf(path, sizeof path, "%s/binaries/linux64/tirenv_effective_road.so", dir);
    void *so = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!so || read_guid(dir, guid, sizeof guid)) {
        fprintf(stderr, "chrono_terrain: cannot load the FMU in %s: %s\n", dir,
                so ? "no GUID" : dlerror());
        return 1;
    }
    fmi2Component (*fmi2Instantiate_)(fmi2String, fmi2Type, fmi2String, fmi2String,
                                      const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean);
    fmi2Status (*fmi2SetupExperiment_)(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real,
                                       fmi2Boolean, fmi2Real);
    fmi2Status (*fmi2EnterInitializationMode_)(fmi2Component);
    fmi2Status (*fmi2ExitInitializationMode_)(fmi2Component);
    fmi2Status (*fmi2SetReal_)(fmi2Component, const fmi2ValueReference[], size_t,
                               const fmi2Real[]);
    fmi2Status (*fmi2GetReal_)(fmi2Component, const fmi2ValueReference[], size_t, fmi2Real[]);
    fmi2Status (*fmi2SetString_)(fmi2Component, const fmi2ValueReference[], size_t,
                                 const fmi2String[]);
    fmi2Status (*fmi2DoStep_)(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
    void (*fmi2FreeInstance_)(fmi2Component);
    SYM(fmi2Instantiate), SYM(fmi2SetupExperiment), SYM(fmi2EnterInitializationMode);
    SYM(fmi2ExitInitializationMode), SYM(fmi2SetReal), SYM(fmi2GetReal), SYM(fmi2SetString);
    SYM(fmi2DoStep), SYM(fmi2FreeInstance);

    /* The value references of modelDescription.xml (fmu/variables.c): model 100, road_file
     * 102, track 0, x 2, load 3, terrain_height 6, terrain_normal.x/.y/.z 7, 8, 9. */
    const fmi2CallbackFunctions cb = {logger, calloc, free, NULL, NULL};
    snprintf(resources, sizeof resources, "file://%s/resources", dir);
    fmi2Component c = fmi2Instantiate_("chrono", fmi2CoSimulation, guid, resources, &cb,
                                       fmi2False, fmi2False);
    const fmi2ValueReference s_vr[2] = {100, 102}, p_vr[3] = {0, 2, 3};
    const fmi2String s_val[2] = {"springs", argv[2]};
    const fmi2Real p_val[3] = {v, u_from, load};
    int ok = c && fmi2SetupExperiment_(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK &&
             fmi2SetString_(c, s_vr, 2, s_val) == fmi2OK &&
             fmi2EnterInitializationMode_(c) == fmi2OK &&
             fmi2SetReal_(c, p_vr, 3, p_val) == fmi2OK && fmi2ExitInitializationMode_(c) == fmi2OK;
    check(ok, "the FMU over %s, track v = %g m, load %g N, in step mode", argv[2], v, load);

    crgMsgSetLevel(dCrgMsgLevelNone);
    const int road = crgLoaderReadFile(argv[2]), eff = crgLoaderReadFile(argv[3]);
    ok = road > 0 && eff > 0 && crgCheck(road) && crgCheck(eff);
    if (ok) {
        crgDataSetModifiersApply(road);
        crgDataSetModifiersApply(eff);
    }
    const int cp_road = ok ? crgContactPointCreate(road) : -1;
    const int cp_eff = ok ? crgContactPointCreate(eff) : -1;
    check(ok, "OpenCRG loads %s and %s as Chrono's CRGTerrain does", argv[2], argv[3]);
    if (!ok || !c)
        return 1;

    size_t n = 0, same_h = 0, unit = 0;
    double worst_h = 0, worst_n = 0, at_worst_n = 0, worst_lat = 0;
    const double d = 1e-3;  /* the normal's central differences, m */
    for (double t = 0, u = u_from; u <= u_to + 1e-9; u = u_from + (double)++n * du, t += 1e-3) {
        /* Chrono's query point: the wheel over the road's point (u, v). */
        double x, y, xa, ya, xb, yb;
        crgEvaluv2xy(cp_road, u, v, &x, &y);
        /* the road's heading there, from its points 1 mm ahead and behind (crgEvaluv2pk
         * answers 0 on a road without a heading channel, whatever START_PHI says) */
        crgEvaluv2xy(cp_road, u + 1e-3, v, &xa, &ya);
        crgEvaluv2xy(cp_road, u - 1e-3, v, &xb, &yb);
        const double phi = atan2(ya - yb, xa - xb);
        /* 1: the FMU */
        const fmi2ValueReference in_vr = 2, out_vr[4] = {6, 7, 8, 9};
        double fmu[4];
        if (fmi2SetReal_(c, &in_vr, 1, &u) != fmi2OK || fmi2DoStep_(c, t, 1e-3, 0) != fmi2OK ||
            fmi2GetReal_(c, out_vr, 4, fmu) != fmi2OK)
            break;
        /* 2: the effective road's file, queried in world x/y: at the point and 1 mm ahead,
         * behind, left and right of it along the road (the road's axes at the point) */
        double z, za, zb, zl, zr;
        const double ex = cos(phi), ey = sin(phi);  /* along the road; left is (-ey, ex) */
        crgEvalxy2z(cp_eff, x, y, &z);
        crgEvalxy2z(cp_eff, x + d * ex, y + d * ey, &za);
        crgEvalxy2z(cp_eff, x - d * ex, y - d * ey, &zb);
        crgEvalxy2z(cp_eff, x - d * ey, y + d * ex, &zl);
        crgEvalxy2z(cp_eff, x + d * ey, y - d * ex, &zr);
        const double gu = (za - zb) / (2 * d), gv = (zl - zr) / (2 * d);
        const double norm = sqrt(1 + gu * gu + gv * gv);
        const double nr[3] = {-gu / norm, -gv / norm, 1 / norm};  /* the road's frame */
        const double dh = fabs(z - fmu[0]);
        worst_h = fmax(worst_h, dh);
        same_h += dh <= 2e-8;
        const double dn = fabs(nr[0] - fmu[1]);
        if (dn > worst_n) {
            worst_n = dn;
            at_worst_n = u;
        }
        worst_lat = fmax(worst_lat, fabs(nr[1]));
        unit += fabs(fmu[1] * fmu[1] + fmu[2] * fmu[2] + fmu[3] * fmu[3] - 1) < 1e-12 &&
                fmu[2] == 0 && fabs(nr[1]) <= LATERAL;
    }
    const size_t want = (size_t)floor((u_to - u_from) / du + 1e-9) + 1;
    check(n == want && same_h == n, "terrain_height of the FMU = OpenCRG's height of EFF.crg at "
          "the query point (%zu of %zu within 2e-8 m; worst %.3g m)", same_h, n, worst_h);
    check(n == want && unit == n, "both normals are unit vectors without a lateral part in the "
          "road's frame (%zu of %zu; the file's largest lateral part %.3g)", unit, n, worst_lat);
    printf("# forward normal components: FMU (-slope, the model's -fx/fz) against the file's "
           "(the slope of h): largest difference %.3g at u = %.4g m\n", worst_n, at_worst_n);
    fmi2FreeInstance_(c);
    dlclose(so);
    printf("1..%d\n%d passed, %d failed\n", n_checks, n_checks - n_failed, n_failed);
    return n_failed ? 1 : 0;
}
