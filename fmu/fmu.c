/* tirenv's FMI 2.0 co-simulation FMU: instances, variables, initialization and steps. At every
 * step the outputs are the model's equilibrium at the input position x and load, warm-started
 * from the previous step, exactly as 'tirenv envelope' sweeps positions at one load.
 * A load that changes moves the model to it (tirenv_model_set_load: the work within the tire's
 * reach, not the road's); the FMU state is in fmu_state.c. SPDX-License-Identifier: Apache-2.0 */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmu_impl.h"

/* ---- logging and memory ------------------------------------------------------------- */

void fmu__log(fmu_instance *f, fmi2Status status, const char *category, const char *fmt, ...)
{
    if (!f || !f->cb.logger || (status == fmi2OK && !f->logging))
        return;
    char raw[2048], msg[4200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(raw, sizeof raw, fmt, ap);
    va_end(ap);
    /* The importer formats the message printf-style, and '#' starts a variable reference
     * (FMI 2.0 section 2.1.5): both are doubled to stand for themselves. */
    size_t j = 0;
    for (size_t i = 0; raw[i] && j + 2 < sizeof msg; ++i) {
        if (raw[i] == '%' || raw[i] == '#')
            msg[j++] = raw[i];
        msg[j++] = raw[i];
    }
    msg[j] = '\0';
    f->cb.logger(f->cb.componentEnvironment, f->name, status, category, msg);
}

fmi2Status fmu__fail(fmu_instance *f, const char *fmt, ...)
{
    char msg[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    fmu__log(f, fmi2Error, "logStatusError", "%s", msg);
    return fmi2Error;
}

fmi2Status fmu__fail_diag(fmu_instance *f, const char *what, const tirenv_diag *diag)
{
    char buf[1600];
    return fmu__fail(f, "%s: %s", what, tirenv_diag_format(diag, buf, sizeof buf));
}

void *fmu__alloc(const fmu_instance *f, size_t size)
{
    return f->cb.allocateMemory(1, size);
}

void fmu__free(const fmu_instance *f, void *p)
{
    if (p)
        f->cb.freeMemory(p);
}

static const char *mode_name(fmu_mode m)
{
    static const char *const names[] = {"instantiated", "initialization mode", "step mode",
                                        "terminated", "error"};
    /* Only fmu_mode's values reach here (a restored state's mode is checked), but a name
     * must never be read out of the table. */
    return (unsigned)m < sizeof names / sizeof names[0] ? names[m] : "an unknown mode";
}

/* ---- the library's objects ------------------------------------------------------------ */

void fmu__teardown(fmu_instance *f)
{
    tirenv_model_free(f->m);
    tirenv_profile_free(f->road);
    f->m = NULL;
    f->road = NULL;
    f->v.model_set = 0;
    f->v.evaluated = 0;
}

/* A file parameter: absolute as given, else relative to the resources directory. */
static int resolve(const fmu_instance *f, const char *name, char *out, size_t n)
{
    const int len = name[0] == '/' ? snprintf(out, n, "%s", name)
                                   : snprintf(out, n, "%s/%s", f->resources, name);
    return len < 0 || (size_t)len >= n ? -1 : 0;
}

static void model_names(char *buf, size_t n)
{
    const tirenv_model_type *const *t = tirenv_model_types();
    size_t used = 0;
    buf[0] = '\0';
    for (; *t && used < n; ++t) {
        const int k = snprintf(buf + used, n - used, "%s%s", used ? ", " : "",
                               tirenv_model_type_name(*t));
        used += k > 0 ? (size_t)k : 0;
    }
}

fmi2Status fmu__setup(fmu_instance *f)
{
    fmu__teardown(f);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    char path[FMU_PATH_MAX + 64];
    const fmu_values *v = &f->v;

    const tirenv_model_type *type = tirenv_model_type_find(v->model);
    if (!type) {
        char names[256];
        model_names(names, sizeof names);
        return fmu__fail(f, "model: unknown model '%s'; expected one of %s", v->model, names);
    }
    /* Said in the FMU's terms: the library's own refusal, at the first load, named
     * tirenv_model_set_network. */
    if (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK)
        return fmu__fail(f, "model: '%s' needs a trained network file, for which the FMU has "
                         "no parameter; expected rigid, springs, ring, cam or point",
                         v->model);
    if (!isfinite(v->track))
        return fmu__fail(f, "track: expected a finite lateral position, got %g m", v->track);
    if (!(v->width >= 0) || !isfinite(v->width))
        return fmu__fail(f, "width: expected a finite width >= 0 m, got %g m", v->width);

    f->tire = tirenv_tire_default();
    if (v->tire_file[0]) {
        if (resolve(f, v->tire_file, path, sizeof path))
            return fmu__fail(f, "tire_file: path too long: %s", v->tire_file);
        /* A file without tirenv's sections: the springs and ring models of its own tire,
         * derived from its MF-Tyre keys (docs/models.md section 14.2), logged. The FMU runs
         * the one model named, so the cam is used alone, as by tirenv flat --model cam: a
         * file whose cam laws are all its own has no ring searched for nothing. One read of
         * the file for both passes (a pipe has no second). */
        tirenv_tir_origin origin;
        if (tirenv_tir_read_derive(path, &f->tire, tirenv_tir_need(type, 1), &origin, &diag))
            return fmu__fail_diag(f, "tire_file", &diag);
        if (origin.note[0])
            fmu__log(f, fmi2Warning, "logAll", "%s: %s", path, origin.note);
        /* A file without MF-Swift's cam shape (which, unlike its laws, is never derived) would
         * give the cam the default tire's: refused, as the CLI refuses it. */
        if (type == tirenv_model_cam && tirenv_tire_check_cam_keys(&f->tire, &diag)) {
            char buf[1600];
            return fmu__fail(f, "tire_file: %s: %s", path,
                             tirenv_diag_format(&diag, buf, sizeof buf));
        }
    }
    if (tirenv_tire_check(&f->tire, &diag))
        return fmu__fail_diag(f, "tire_file", &diag);

    if (!v->road_file[0])
        return fmu__fail(f, "road_file: empty; expected a road profile file");
    if (resolve(f, v->road_file, path, sizeof path))
        return fmu__fail(f, "road_file: path too long: %s", v->road_file);
    /* Any road file the CLI's --profile reads: a CSV or RDF road is 2-D, the same on every
     * track and across the tire's width, so track and width select nothing in it; an OpenCRG
     * road's track is the long section at v = track. Several tracks across a width are the
     * CLI's (tirenv envelope --tracks, which can write the effective road for this FMU as a
     * road file): the FMU evaluates one. */
    tirenv_road_file *road;
    if (tirenv_road_file_open(path, &road, &diag))
        return fmu__fail_diag(f, "road_file", &diag);
    if (tirenv_road_file_format(road) == TIRENV_PROFILE_CRG && v->width > 0) {
        tirenv_road_file_free(road);
        return fmu__fail(f, "width: %g m over the OpenCRG road %s: the FMU evaluates one "
                         "track (width 0); for the tire's width run 'tirenv envelope --tracks N' "
                         "and give its effective road (-o ROAD.crg) as road_file", v->width,
                         v->road_file);
    }
    tirenv_profile_source src = tirenv_profile_source_default();
    src.crg.v = v->track;
    const int status = tirenv_road_file_read(road, &src, 1, NULL, &f->road, &diag);
    tirenv_road_file_free(road);
    if (status)
        return fmu__fail_diag(f, "road_file", &diag);

    if (!(f->m = tirenv_model_alloc(type, &f->tire)))
        return fmu__fail(f, "model: out of memory allocating the %s model", v->model);
    fmu__log(f, fmi2OK, "logAll", "%s model, tire %s, road %s (%zu vertices)", v->model,
             v->tire_file[0] ? v->tire_file : "(built-in default)", v->road_file,
             tirenv_profile_size(f->road));
    return fmi2OK;
}

fmi2Status fmu__set_load(fmu_instance *f, double load)
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    /* Set on the road once; a new load after that keeps the profile and the warm start. A
     * load refused leaves the model at its last (tirenv_model_set_load). */
    const int on_road = f->v.model_set && tirenv_model_profile(f->m) == f->road;
    if (on_road ? tirenv_model_set_load(f->m, load, &diag)
                : tirenv_model_set(f->m, f->road, load, &diag)) {
        f->v.model_set = on_road && tirenv_model_profile(f->m) == f->road;
        char what[96];
        snprintf(what, sizeof what, "load %.9g N", load);
        return fmu__fail_diag(f, what, &diag);
    }
    if (!on_road)
        f->warned = 0;  /* a new set: its warnings are new */
    f->v.model_set = 1;
    f->v.load_set = load;
    return fmi2OK;
}

fmi2Status fmu__evaluate(fmu_instance *f)
{
    fmu_values *v = &f->v;
    if (!f->m && fmu__setup(f) != fmi2OK)
        return fmi2Error;
    if ((!v->model_set || v->load != v->load_set) && fmu__set_load(f, v->load) != fmi2OK)
        return fmi2Error;
    tirenv_point p;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (tirenv_model_eval(f->m, v->x, &p, &diag)) {
        /* The warm start after a failed evaluation is the model's business: set it anew. */
        v->model_set = 0;
        char what[128];
        snprintf(what, sizeof what, "%s model at x = %.9g m, load %.9g N", v->model, v->x,
                 v->load);
        return fmu__fail_diag(f, what, &diag);
    }
    const char *said = tirenv_model_warnings(f->m);
    if (said[0] && !f->warned) {  /* once: it stays until the next set */
        fmu__log(f, fmi2Warning, "logAll", "%s model at x = %.9g m: %s", v->model, v->x, said);
        f->warned = 1;
    }
    v->h = p.h;
    v->slope = p.slope;
    v->terrain_height = p.h;  /* the flat ground's level is z = 0 of the road's frame */
    const double norm = sqrt(1 + p.slope * p.slope);
    v->normal[0] = -p.slope / norm;
    v->normal[1] = 0;
    v->normal[2] = 1 / norm;
    v->fx = p.fx;
    v->fz = p.fz;
    v->evaluated = 1;
    v->eval_x = v->x;
    v->eval_load = v->load;
    return fmi2OK;
}

/* The outputs for the inputs as they stand: evaluated once per change of the inputs, so that
 * reading them twice, or reading them and stepping, leaves the warm start as one evaluation
 * does. */
static fmi2Status outputs_current(fmu_instance *f)
{
    const fmu_values *v = &f->v;
    if (v->evaluated && v->eval_x == v->x && v->eval_load == v->load && v->model_set &&
        v->load_set == v->load)
        return fmi2OK;
    return fmu__evaluate(f);
}

/* ---- 2.1.4, 2.1.5: platform, instances ------------------------------------------------ */

const char *fmi2GetTypesPlatform(void)
{
    return fmi2TypesPlatform;
}

const char *fmi2GetVersion(void)
{
    return fmi2Version;
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[])
{
    fmu_instance *f = c;
    if (!f)
        return fmi2Error;
    if (nCategories && !categories)
        return fmu__fail(f, "fmi2SetDebugLogging: %zu categories but a NULL array", nCategories);
    for (size_t i = 0; i < nCategories; ++i)
        if (!categories[i] || (strcmp(categories[i], "logStatusError") != 0 &&
                               strcmp(categories[i], "logAll") != 0))
            return fmu__fail(f, "fmi2SetDebugLogging: unknown log category '%s'; expected "
                             "logStatusError or logAll", categories[i] ? categories[i] : "(null)");
    f->logging = loggingOn != fmi2False;
    return fmi2OK;
}

/* "file:///dir", "file:/dir" or "file://localhost/dir", %XX escapes decoded, into out. */
static int resource_dir(const char *uri, char *out, size_t n)
{
    const char *p;
    if (strncmp(uri, "file://localhost/", 17) == 0)
        p = uri + 16;
    else if (strncmp(uri, "file:///", 8) == 0)
        p = uri + 7;
    else if (strncmp(uri, "file:/", 6) == 0)
        p = uri + 5;
    else
        return -1;
    size_t j = 0;
    for (; *p && j + 1 < n; ++p) {
        if (*p == '%' && isxdigit((unsigned char)p[1]) && isxdigit((unsigned char)p[2])) {
            const char hex[3] = {p[1], p[2], '\0'};
            out[j++] = (char)strtol(hex, NULL, 16);
            p += 2;
        } else {
            out[j++] = *p;
        }
    }
    if (*p)
        return -1;
    while (j > 1 && out[j - 1] == '/')
        --j;
    out[j] = '\0';
    return 0;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn)
{
    (void)visible;
    if (!functions || !functions->allocateMemory || !functions->freeMemory)
        return NULL;  /* nowhere to put an instance, nor to say so */
    fmu_instance tmp;
    memset(&tmp, 0, sizeof tmp);
    tmp.cb = *functions;
    snprintf(tmp.name, sizeof tmp.name, "%s", instanceName ? instanceName : "");
    char guid[64];
    fmu__guid(guid, sizeof guid);
    if (!instanceName || !instanceName[0]) {
        fmu__fail(&tmp, "fmi2Instantiate: an instance name is required");
        return NULL;
    }
    if (fmuType != fmi2CoSimulation) {
        fmu__fail(&tmp, "fmi2Instantiate: this FMU supports co-simulation only (fmi2CoSimulation)");
        return NULL;
    }
    if (!fmuGUID || strcmp(fmuGUID, guid) != 0) {
        fmu__fail(&tmp, "fmi2Instantiate: GUID '%s' is not this FMU's %s (a modelDescription.xml "
                  "of another build?)", fmuGUID ? fmuGUID : "(null)", guid);
        return NULL;
    }
    if (!fmuResourceLocation || resource_dir(fmuResourceLocation, tmp.resources,
                                             sizeof tmp.resources)) {
        fmu__fail(&tmp, "fmi2Instantiate: expected the resources as a file: URI, got '%s'",
                  fmuResourceLocation ? fmuResourceLocation : "(null)");
        return NULL;
    }
    fmu_instance *f = fmu__alloc(&tmp, sizeof *f);
    if (!f) {
        fmu__fail(&tmp, "fmi2Instantiate: out of memory");
        return NULL;
    }
    *f = tmp;
    f->logging = loggingOn != fmi2False;
    f->mode = FMU_INSTANTIATED;
    f->v = fmu__start_values();
    f->stop_time = NAN;
    fmu__log(f, fmi2OK, "logAll", "instantiated, resources in %s", f->resources);
    return f;
}

/* FMI 2.0 (section 2.1.5) ends the component's life here: a NULL component is ignored, but
 * freeing the same component twice, or calling anything with it afterwards, is the importer's
 * error and cannot be detected (the memory is the importer's allocator's again); fmu/README.md
 * says so. */
void fmi2FreeInstance(fmi2Component c)
{
    fmu_instance *f = c;
    if (!f)
        return;
    fmu__teardown(f);
    const fmi2CallbackFreeMemory release = f->cb.freeMemory;
    release(f);
}

/* ---- 2.1.6: initialization, termination, reset ---------------------------------------- */

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    fmu_instance *f = c;
    if (!f)
        return fmi2Error;
    if (f->mode != FMU_INSTANTIATED)
        return fmu__fail(f, "fmi2SetupExperiment: only after fmi2Instantiate, not in %s",
                         mode_name(f->mode));
    /* The tolerance is not used (a static map has no error to control), but a value given
     * must be a number; a time that is not finite would leave no step possible. */
    if (toleranceDefined && !(tolerance >= 0 && isfinite(tolerance)))
        return fmu__fail(f, "fmi2SetupExperiment: tolerance %g: expected a finite number >= 0",
                         tolerance);
    if (!isfinite(startTime))
        return fmu__fail(f, "fmi2SetupExperiment: start time %g s: expected a finite time",
                         startTime);
    if (stopTimeDefined && !(stopTime >= startTime && isfinite(stopTime)))
        return fmu__fail(f, "fmi2SetupExperiment: stop time %g s: expected a finite time >= "
                         "the start time %.17g s", stopTime, startTime);
    f->v.time = startTime;
    f->stop_time = stopTimeDefined ? stopTime : NAN;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    fmu_instance *f = c;
    if (!f)
        return fmi2Error;
    if (f->mode != FMU_INSTANTIATED)
        return fmu__fail(f, "fmi2EnterInitializationMode: only after fmi2Instantiate, not in %s",
                         mode_name(f->mode));
    f->mode = FMU_INITIALIZATION;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    fmu_instance *f = c;
    if (!f)
        return fmi2Error;
    if (f->mode != FMU_INITIALIZATION)
        return fmu__fail(f, "fmi2ExitInitializationMode: not in initialization mode but in %s",
                         mode_name(f->mode));
    if (outputs_current(f) != fmi2OK) {
        f->mode = FMU_ERROR;
        return fmi2Error;
    }
    f->mode = FMU_STEP;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    fmu_instance *f = c;
    if (!f)
        return fmi2Error;
    if (f->mode != FMU_STEP && f->mode != FMU_ERROR)
        return fmu__fail(f, "fmi2Terminate: not in step mode but in %s", mode_name(f->mode));
    f->mode = FMU_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c)
{
    fmu_instance *f = c;
    if (!f)
        return fmi2Error;
    fmu__teardown(f);
    f->v = fmu__start_values();
    f->stop_time = NAN;
    f->mode = FMU_INSTANTIATED;
    return fmi2OK;
}

/* ---- 2.1.7: values ------------------------------------------------------------------------ */

static const char *type_name(fmu_type t)
{
    return t == FMU_REAL ? "Real" : "String";
}

/* The variable vr of type t, or an error logged naming the call. */
static const fmu_variable *lookup(fmu_instance *f, const char *call, fmi2ValueReference vr,
                                  fmu_type t)
{
    const fmu_variable *var = fmu__variable_find(vr, t);
    if (!var)
        fmu__fail(f, "%s: no %s variable has value reference %u (see modelDescription.xml)", call,
                  type_name(t), vr);
    return var;
}

/* Whether var may be set now (FMI 2.0 section 4.2.4: fixed parameters before the end of
 * initialization, inputs until termination, outputs never). */
static fmi2Status settable(fmu_instance *f, const char *call, const fmu_variable *var)
{
    if (var->causality == FMU_OUTPUT)
        return fmu__fail(f, "%s: %s is an output; it cannot be set", call, var->name);
    if (f->mode == FMU_TERMINATED || f->mode == FMU_ERROR)
        return fmu__fail(f, "%s: %s cannot be set in %s", call, var->name, mode_name(f->mode));
    if (var->causality == FMU_PARAMETER && f->mode == FMU_STEP)
        return fmu__fail(f, "%s: %s is a fixed parameter: set it before "
                         "fmi2ExitInitializationMode", call, var->name);
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[])
{
    fmu_instance *f = c;
    if (!f || (nvr && (!vr || !value)))
        return f ? fmu__fail(f, "fmi2GetReal: NULL arrays") : fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        const fmu_variable *var = lookup(f, "fmi2GetReal", vr[i], FMU_REAL);
        if (!var)
            return fmi2Error;
        if (var->causality == FMU_OUTPUT) {
            if (f->mode == FMU_INSTANTIATED)
                return fmu__fail(f, "fmi2GetReal: output %s is computed from "
                                 "fmi2EnterInitializationMode on", var->name);
            if ((f->mode == FMU_INITIALIZATION || f->mode == FMU_STEP) &&
                outputs_current(f) != fmi2OK)
                return fmi2Error;
        }
        memcpy(&value[i], (const char *)&f->v + var->offset, sizeof(double));
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[])
{
    fmu_instance *f = c;
    if (!f || (nvr && (!vr || !value)))
        return f ? fmu__fail(f, "fmi2SetReal: NULL arrays") : fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        const fmu_variable *var = lookup(f, "fmi2SetReal", vr[i], FMU_REAL);
        if (!var || settable(f, "fmi2SetReal", var) != fmi2OK)
            return fmi2Error;
        if (!isfinite(value[i]))
            return fmu__fail(f, "fmi2SetReal: %s = %g: expected a finite number", var->name,
                             value[i]);
        if (strcmp(var->name, "load") == 0 && !(value[i] > 0))
            return fmu__fail(f, "fmi2SetReal: load = %g N: expected a load > 0", value[i]);
        if (strcmp(var->name, "width") == 0 && !(value[i] >= 0))
            return fmu__fail(f, "fmi2SetReal: width = %g m: expected a width >= 0", value[i]);
        if (var->causality == FMU_PARAMETER)
            fmu__teardown(f);  /* built again from the new value when next needed */
        memcpy((char *)&f->v + var->offset, &value[i], sizeof(double));
    }
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[])
{
    fmu_instance *f = c;
    if (!f || (nvr && (!vr || !value)))
        return f ? fmu__fail(f, "fmi2GetString: NULL arrays") : fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        const fmu_variable *var = lookup(f, "fmi2GetString", vr[i], FMU_STRING);
        if (!var)
            return fmi2Error;
        value[i] = (const char *)&f->v + var->offset;  /* valid until the next call */
    }
    return fmi2OK;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[])
{
    fmu_instance *f = c;
    if (!f || (nvr && (!vr || !value)))
        return f ? fmu__fail(f, "fmi2SetString: NULL arrays") : fmi2Error;
    for (size_t i = 0; i < nvr; ++i) {
        const fmu_variable *var = lookup(f, "fmi2SetString", vr[i], FMU_STRING);
        if (!var || settable(f, "fmi2SetString", var) != fmi2OK)
            return fmi2Error;
        if (!value[i])
            return fmu__fail(f, "fmi2SetString: %s: NULL string", var->name);
        if (strlen(value[i]) >= var->size)
            return fmu__fail(f, "fmi2SetString: %s: longer than %zu bytes", var->name,
                             var->size - 1);
        fmu__teardown(f);
        snprintf((char *)&f->v + var->offset, var->size, "%s", value[i]);
    }
    return fmi2OK;
}

/* No Integer or Boolean variables: an empty request succeeds, any reference is an error. */
static fmi2Status none(fmu_instance *f, const char *call, const char *type,
                       const fmi2ValueReference vr[], size_t nvr)
{
    if (!f)
        return fmi2Error;
    if (!nvr)
        return fmi2OK;
    return fmu__fail(f, "%s: this FMU has no %s variables (value reference %u)", call, type,
                     vr ? vr[0] : 0);
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[])
{
    (void)value;
    return none(c, "fmi2GetInteger", "Integer", vr, nvr);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[])
{
    (void)value;
    return none(c, "fmi2GetBoolean", "Boolean", vr, nvr);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[])
{
    (void)value;
    return none(c, "fmi2SetInteger", "Integer", vr, nvr);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[])
{
    (void)value;
    return none(c, "fmi2SetBoolean", "Boolean", vr, nvr);
}

/* ---- 2.1.9, 4.2: derivatives, stepping, status -------------------------------------------- */

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[])
{
    (void)vUnknown_ref, (void)nUnknown, (void)vKnown_ref, (void)nKnown, (void)dvKnown;
    (void)dvUnknown;
    return c ? fmu__fail(c, "fmi2GetDirectionalDerivative: not provided "
                         "(providesDirectionalDerivative = false)")
             : fmi2Error;
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[])
{
    (void)vr, (void)nvr, (void)order, (void)value;
    return c ? fmu__fail(c, "fmi2SetRealInputDerivatives: inputs are not interpolated "
                         "(canInterpolateInputs = false): the outputs follow the inputs' values")
             : fmi2Error;
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[],
                                        fmi2Real value[])
{
    (void)vr, (void)nvr, (void)order, (void)value;
    return c ? fmu__fail(c, "fmi2GetRealOutputDerivatives: not provided "
                         "(maxOutputDerivativeOrder = 0)")
             : fmi2Error;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    fmu_instance *f = c;
    (void)noSetFMUStatePriorToCurrentPoint;
    if (!f)
        return fmi2Error;
    if (f->mode != FMU_STEP)
        return fmu__fail(f, "fmi2DoStep: not in step mode but in %s", mode_name(f->mode));
    if (!(communicationStepSize > 0) || !isfinite(communicationStepSize))
        return fmu__fail(f, "fmi2DoStep: step size %g s: expected a finite step > 0",
                         communicationStepSize);
    const double t = f->v.time;
    if (!isfinite(currentCommunicationPoint + communicationStepSize))
        return fmu__fail(f, "fmi2DoStep: the step from %.17g s by %.17g s ends at no finite "
                         "time", currentCommunicationPoint, communicationStepSize);
    if (!(fabs(currentCommunicationPoint - t) <= 1e-9 * fmax(1, fabs(t))))
        return fmu__fail(f, "fmi2DoStep: the communication point %.17g s is not the FMU's time "
                         "%.17g s (restore an FMU state to go back)", currentCommunicationPoint, t);
    /* FMI 2.0 (4.2.1): with a stop time defined the master must not step beyond it, and the
     * FMU may refuse, as the Reference FMUs do; the same round-off allowance as above. */
    const double end = currentCommunicationPoint + communicationStepSize, stop = f->stop_time;
    if (end > stop + 1e-9 * fmax(1, fabs(stop)))
        return fmu__fail(f, "fmi2DoStep: the step from %.17g s by %.17g s ends past the stop "
                         "time %.17g s of fmi2SetupExperiment", currentCommunicationPoint,
                         communicationStepSize, stop);
    /* A static map: the outputs at the end of the step are the equilibrium at the inputs
     * as they stand (set before this call). */
    if (outputs_current(f) != fmi2OK) {
        f->mode = FMU_ERROR;
        return fmi2Error;
    }
    f->v.time = currentCommunicationPoint + communicationStepSize;
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    return c ? fmu__fail(c, "fmi2CancelStep: fmi2DoStep never returns fmi2Pending "
                         "(canRunAsynchronuously = false): nothing to cancel")
             : fmi2Error;
}

static fmi2Status no_status(fmu_instance *f, const char *call, fmi2StatusKind s)
{
    if (!f)
        return fmi2Error;
    fmu__log(f, fmi2Discard, "logStatusError", "%s: status kind %d is not available: "
             "fmi2DoStep never returns fmi2Pending", call, (int)s);
    return fmi2Discard;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value)
{
    (void)value;
    return no_status(c, "fmi2GetStatus", s);
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value)
{
    fmu_instance *f = c;
    if (f && s == fmi2LastSuccessfulTime && value) {
        *value = f->v.time;
        return fmi2OK;
    }
    return no_status(f, "fmi2GetRealStatus", s);
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value)
{
    (void)value;
    return no_status(c, "fmi2GetIntegerStatus", s);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value)
{
    fmu_instance *f = c;
    if (f && s == fmi2Terminated && value) {
        *value = fmi2False;  /* the slave never asks to end the simulation */
        return fmi2OK;
    }
    return no_status(f, "fmi2GetBooleanStatus", s);
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value)
{
    (void)value;
    return no_status(c, "fmi2GetStringStatus", s);
}
