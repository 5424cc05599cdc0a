/* The FMU's variables: one table from which the binary serves values (fmu.c) and
 * describe.c writes modelDescription.xml, so the two cannot disagree. Value references are
 * unique over all types. Names follow Project Chrono's tire FMU where it takes the road from
 * a terrain: terrain_height and terrain_normal.x/.y/.z (fmu/README.md).
 * SPDX-License-Identifier: Apache-2.0 */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "fmu_impl.h"

#define REAL(field) offsetof(fmu_values, field), sizeof(double)
#define STRING(field) offsetof(fmu_values, field), sizeof(((fmu_values *)0)->field)

static const fmu_variable variables[] = {
    {"model", 100, FMU_STRING, FMU_PARAMETER, NULL,
     "enveloping model: rigid, springs, ring or cam; point passes the road's own height and "
     "slope on (nn, which needs a network file, is refused)", STRING(model)},
    {"tire_file", 101, FMU_STRING, FMU_PARAMETER, NULL,
     "tire property file (.tir); relative to the FMU's resources unless absolute; empty: "
     "the built-in default tire", STRING(tire_file)},
    {"road_file", 102, FMU_STRING, FMU_PARAMETER, NULL,
     "road file (CSV x_m,z_m, OpenCRG .crg or TNO/Adams .rdf); relative to the FMU's "
     "resources unless absolute",
     STRING(road_file)},
    {"track", 0, FMU_REAL, FMU_PARAMETER, "m",
     "lateral position of the wheel on an OpenCRG road, + left (a 2-D road's only track)",
     REAL(track)},
    {"width", 1, FMU_REAL, FMU_PARAMETER, "m",
     "tire width over which tracks are combined: 0 (a 2-D road is the same across it; an "
     "OpenCRG road is evaluated on one track)",
     REAL(width)},
    {"x", 2, FMU_REAL, FMU_INPUT, "m", "wheel-centre position along the road", REAL(x)},
    {"load", 3, FMU_REAL, FMU_INPUT, "N", "vertical load on the tire (> 0)", REAL(load)},
    {"h", 4, FMU_REAL, FMU_OUTPUT, "m",
     "effective height of the road: wheel-centre height over flat ground, z - z_flat", REAL(h)},
    {"slope", 5, FMU_REAL, FMU_OUTPUT, NULL,
     "effective slope tan(beta) = -fx/fz (positive uphill in x)", REAL(slope)},
    {"terrain_height", 6, FMU_REAL, FMU_OUTPUT, "m",
     "the effective road under the wheel for a single-point-contact tire (road frame, z up)",
     REAL(terrain_height)},
    {"terrain_normal.x", 7, FMU_REAL, FMU_OUTPUT, NULL,
     "unit normal of the effective road, x (forward) component: -slope/sqrt(1+slope^2)",
     REAL(normal[0])},
    {"terrain_normal.y", 8, FMU_REAL, FMU_OUTPUT, NULL,
     "unit normal of the effective road, y (lateral) component: 0 on a 2-D road",
     REAL(normal[1])},
    {"terrain_normal.z", 9, FMU_REAL, FMU_OUTPUT, NULL,
     "unit normal of the effective road, z (up) component: 1/sqrt(1+slope^2)",
     REAL(normal[2])},
    {"fx", 10, FMU_REAL, FMU_OUTPUT, "N", "longitudinal hub force (positive forward)", REAL(fx)},
    {"fz", 11, FMU_REAL, FMU_OUTPUT, "N", "vertical hub force (the load at equilibrium)",
     REAL(fz)},
};

const fmu_variable *fmu__variables(size_t *n)
{
    *n = sizeof variables / sizeof variables[0];
    return variables;
}

const fmu_variable *fmu__variable_find(fmi2ValueReference vr, fmu_type t)
{
    for (size_t i = 0; i < sizeof variables / sizeof variables[0]; ++i)
        if (variables[i].vr == vr && variables[i].type == t)
            return &variables[i];
    return NULL;
}

fmu_values fmu__start_values(void)
{
    fmu_values v;
    memset(&v, 0, sizeof v);
    snprintf(v.model, sizeof v.model, "springs");
    snprintf(v.tire_file, sizeof v.tire_file, "default.tir");
    snprintf(v.road_file, sizeof v.road_file, "road.csv");
    v.track = 0;
    v.width = 0;
    v.x = 0;
    v.load = 10000;
    return v;
}

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; ++i)
        h = (h ^ p[i]) * UINT64_C(0x100000001b3);
    return h;
}

char *fmu__guid(char *guid, size_t size)
{
    uint64_t h = UINT64_C(0xcbf29ce484222325);
    const fmu_values start = fmu__start_values();
    for (size_t i = 0; i < sizeof variables / sizeof variables[0]; ++i) {
        const fmu_variable *v = &variables[i];
        const int kind[2] = {(int)v->type, (int)v->causality};
        h = fnv1a(h, v->name, strlen(v->name) + 1);
        h = fnv1a(h, &v->vr, sizeof v->vr);
        h = fnv1a(h, kind, sizeof kind);
        h = fnv1a(h, (const char *)&start + v->offset,
                  v->type == FMU_REAL ? sizeof(double) : strlen((const char *)&start + v->offset));
    }
    h = fnv1a(h, TIRENV_VERSION, sizeof TIRENV_VERSION);
    snprintf(guid, size, "{tirenv-effective-road-%016llx}", (unsigned long long)h);
    return guid;
}
