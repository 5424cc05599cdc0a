/* The FMU state (FMI 2.0 section 2.1.8): get, set, free and serialize. A state records the
 * instance's mode (instantiated, initialization, step, terminated, error), the values of all
 * variables and, with the model set, the model's own state (tirenv_model_state_save: its load,
 * flat-ground point, warm start and contact states), so that setting it leaves the warm start
 * bit for bit where it was at a constant cost; only an instance whose model is not set on the
 * road yet sets it first (once, O(road)). Setting a state restores its mode too, as the FMI
 * Reference FMUs do: an instance that was only instantiated continues the run the state was
 * taken from. A state is not trusted: every field is checked before any is used
 * (state_check), whether it comes from fmi2GetFMUstate or from bytes.
 * SPDX-License-Identifier: Apache-2.0 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fmu_impl.h"

#define STATE_MAGIC "TRNVFMU"   /* 8 bytes with its terminating zero */
#define STATE_VERSION 2u

typedef struct {
    char magic[8];
    uint32_t version;
    uint32_t values_size;   /* sizeof(fmu_values) of the build that wrote it */
    uint64_t n_model;       /* bytes of the model's state (0: the model not set) */
    int32_t mode;
    int32_t pad;
} state_header;

typedef struct {
    state_header hdr;
    fmu_values v;
    unsigned char model[];  /* hdr.n_model bytes: tirenv_model_state_save's */
} fmu_state;

static fmu_state *state_alloc(const fmu_instance *f, size_t n_model)
{
    fmu_state *s = fmu__alloc(f, sizeof *s + n_model);
    if (!s)
        return NULL;
    memcpy(s->hdr.magic, STATE_MAGIC, sizeof s->hdr.magic);
    s->hdr.version = STATE_VERSION;
    s->hdr.values_size = (uint32_t)sizeof(fmu_values);
    s->hdr.n_model = n_model;
    return s;
}

static int state_valid(const fmu_state *s)
{
    return s && memcmp(s->hdr.magic, STATE_MAGIC, sizeof s->hdr.magic) == 0 &&
           s->hdr.version == STATE_VERSION && s->hdr.values_size == sizeof(fmu_values);
}

/* A number field of a state, finite (and > 0 where positive). */
static int finite_field(const char *what, double value, int positive, char *why, size_t n)
{
    if (isfinite(value) && (!positive || value > 0))
        return 0;
    snprintf(why, n, "%s = %g: expected a finite number%s", what, value,
             positive ? " > 0" : "");
    return -1;
}

static int terminated(const char *s, size_t n)
{
    return memchr(s, '\0', n) != NULL;
}

/* Every field of s checked against what fmi2GetFMUstate can have written, so that a state
 * restored from bytes an importer kept (or corrupted) cannot steer a later call out of bounds:
 * the mode is one of fmu_mode's, the strings end within their buffers, the numbers are
 * finite, the flags 0 or 1, and the model's bytes are there exactly when the model was set.
 * 0, or -1 with the reason in why. The model's own bytes are checked by
 * tirenv_model_state_restore when the state is set. */
static int state_check(const fmu_state *s, size_t n_model, char *why, size_t n)
{
    const fmu_values *v = &s->v;
    if (s->hdr.mode < (int32_t)FMU_INSTANTIATED || s->hdr.mode > (int32_t)FMU_ERROR) {
        snprintf(why, n, "mode %d: not one of the FMU's modes (0 to %d)", (int)s->hdr.mode,
                 (int)FMU_ERROR);
        return -1;
    }
    if (s->hdr.pad != 0) {
        snprintf(why, n, "header padding %d: expected 0", (int)s->hdr.pad);
        return -1;
    }
    if (!terminated(v->model, sizeof v->model) || !terminated(v->tire_file, sizeof v->tire_file)
        || !terminated(v->road_file, sizeof v->road_file)) {
        snprintf(why, n, "a string parameter (model, tire_file, road_file) does not end "
                 "within its buffer");
        return -1;
    }
    if (v->evaluated != 0 && v->evaluated != 1) {
        snprintf(why, n, "evaluated = %d: expected 0 or 1", v->evaluated);
        return -1;
    }
    if (v->model_set != 0 && v->model_set != 1) {
        snprintf(why, n, "model_set = %d: expected 0 or 1", v->model_set);
        return -1;
    }
    if ((v->model_set != 0) != (n_model != 0)) {
        snprintf(why, n, "%zu bytes of model state with the model %s", n_model,
                 v->model_set ? "set" : "not set");
        return -1;
    }
    const struct {
        const char *name;
        double value;
        int positive, used;
    } numbers[] = {
        {"track", v->track, 0, 1},
        {"width", v->width, 0, 1},
        {"x", v->x, 0, 1},
        {"load", v->load, 1, 1},
        {"h", v->h, 0, 1},
        {"slope", v->slope, 0, 1},
        {"terrain_height", v->terrain_height, 0, 1},
        {"terrain_normal.x", v->normal[0], 0, 1},
        {"terrain_normal.y", v->normal[1], 0, 1},
        {"terrain_normal.z", v->normal[2], 0, 1},
        {"fx", v->fx, 0, 1},
        {"fz", v->fz, 0, 1},
        {"time", v->time, 0, 1},
        {"the evaluated x", v->eval_x, 0, v->evaluated},
        {"the evaluated load", v->eval_load, 1, v->evaluated},
        {"the model's load", v->load_set, 1, v->model_set},
    };
    for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; ++i)
        if (numbers[i].used &&
            finite_field(numbers[i].name, numbers[i].value, numbers[i].positive, why, n))
            return -1;
    if (!(v->width >= 0)) {
        snprintf(why, n, "width = %g m: expected >= 0", v->width);
        return -1;
    }
    return 0;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    fmu_instance *f = c;
    if (!f || !FMUstate)
        return f ? fmu__fail_diag(f, "fmi2GetFMUstate", &(tirenv_diag){
                                     .message = "NULL state pointer"})
                 : fmi2Error;
    const size_t n = f->v.model_set && f->m ? tirenv_model_state_size(f->m) : 0;
    fmu_state *s = *FMUstate;
    if (!state_valid(s) || s->hdr.n_model != n) {  /* a new one, or one of another size */
        if (state_valid(s))
            fmu__free(f, s);
        if (!(s = state_alloc(f, n)))
            return fmu__fail_diag(f, "fmi2GetFMUstate",
                                  &(tirenv_diag){.message = "out of memory"});
    }
    s->hdr.mode = (int32_t)f->mode;
    s->v = f->v;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    if (n && tirenv_model_state_save(f->m, s->model, n, &diag)) {
        if (s != *FMUstate)
            fmu__free(f, s);
        return fmu__fail_diag(f, "fmi2GetFMUstate", &diag);
    }
    *FMUstate = s;
    return fmi2OK;
}

static int same_parameters(const fmu_values *a, const fmu_values *b)
{
    return strcmp(a->model, b->model) == 0 && strcmp(a->tire_file, b->tire_file) == 0 &&
           strcmp(a->road_file, b->road_file) == 0 && a->track == b->track &&
           a->width == b->width;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    fmu_instance *f = c;
    const fmu_state *s = FMUstate;
    if (!f)
        return fmi2Error;
    char why[256];
    if (!state_valid(s))
        return fmu__fail_diag(f, "fmi2SetFMUstate",
                              &(tirenv_diag){.message = "not a state of this FMU"});
    if (state_check(s, (size_t)s->hdr.n_model, why, sizeof why))
        return fmu__fail(f, "fmi2SetFMUstate: a corrupted state refused (%s); the instance "
                         "is unchanged", why);
    const int rebuild = !f->m || !same_parameters(&f->v, &s->v);
    /* The model on the road already: the state's bytes restore it whatever its load. */
    const int on_road = !rebuild && f->v.model_set && tirenv_model_profile(f->m) == f->road;
    f->v = s->v;
    if (s->v.model_set || s->v.evaluated) {
        /* From here a failure leaves the instance between two states: it is in error
         * (FMI 2.0 section 4.2.4: reset, another state, or free). */
        if (rebuild && fmu__setup(f) != fmi2OK) {
            f->mode = FMU_ERROR;
            return fmi2Error;
        }
        f->v = s->v;
        if (s->v.model_set) {
            tirenv_diag diag;
            tirenv_diag_clear(&diag);
            f->v.model_set = on_road;
            if (!on_road && fmu__set_load(f, s->v.load_set) != fmi2OK) {
                f->mode = FMU_ERROR;
                return fmi2Error;
            }
            if (tirenv_model_state_restore(f->m, s->model, (size_t)s->hdr.n_model, &diag)) {
                f->v.model_set = 0;  /* the model is unset: set anew when next needed */
                f->mode = FMU_ERROR;
                return fmu__fail_diag(f, "fmi2SetFMUstate", &diag);
            }
        }
    } else if (rebuild) {
        fmu__teardown(f);  /* built from the restored parameters when next needed */
    }
    f->v = s->v;
    f->mode = (fmu_mode)s->hdr.mode;
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    fmu_instance *f = c;
    if (!f)
        return fmi2Error;
    if (FMUstate && *FMUstate) {
        fmu__free(f, *FMUstate);
        *FMUstate = NULL;
    }
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size)
{
    fmu_instance *f = c;
    const fmu_state *s = FMUstate;
    if (!f)
        return fmi2Error;
    if (!state_valid(s) || !size)
        return fmu__fail_diag(f, "fmi2SerializedFMUstateSize",
                              &(tirenv_diag){.message = "not a state of this FMU"});
    *size = sizeof *s + (size_t)s->hdr.n_model;
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                 fmi2Byte serializedState[], size_t size)
{
    fmu_instance *f = c;
    const fmu_state *s = FMUstate;
    size_t need;
    if (!f)
        return fmi2Error;
    if (fmi2SerializedFMUstateSize(c, FMUstate, &need) != fmi2OK)
        return fmi2Error;
    if (!serializedState || size < need)
        return fmu__fail_diag(f, "fmi2SerializeFMUstate", &(tirenv_diag){
                                  .message = "buffer smaller than "
                                             "fmi2SerializedFMUstateSize"});
    memcpy(serializedState, s, need);  /* plain data: the same FMU reads it back */
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[],
                                   size_t size, fmi2FMUstate *FMUstate)
{
    fmu_instance *f = c;
    if (!f)
        return fmi2Error;
    state_header hdr;
    if (!serializedState || !FMUstate || size < sizeof(fmu_state))
        return fmu__fail_diag(f, "fmi2DeSerializeFMUstate",
                              &(tirenv_diag){.message = "too short to be a state"});
    memcpy(&hdr, serializedState, sizeof hdr);
    if (memcmp(hdr.magic, STATE_MAGIC, sizeof hdr.magic) != 0 ||
        hdr.version != STATE_VERSION || hdr.values_size != sizeof(fmu_values) ||
        hdr.n_model > SIZE_MAX - sizeof(fmu_state) ||
        size != sizeof(fmu_state) + (size_t)hdr.n_model)
        return fmu__fail_diag(f, "fmi2DeSerializeFMUstate", &(tirenv_diag){
                                  .message = "not a serialized state of this FMU build "
                                             "(magic, version, value layout or size differ)"});
    fmu_state *s = state_alloc(f, (size_t)hdr.n_model);
    if (!s)
        return fmu__fail_diag(f, "fmi2DeSerializeFMUstate",
                              &(tirenv_diag){.message = "out of memory"});
    memcpy(s, serializedState, size);
    char why[256];
    if (state_check(s, (size_t)hdr.n_model, why, sizeof why)) {
        fmu__free(f, s);
        return fmu__fail(f, "fmi2DeSerializeFMUstate: not a state this FMU wrote (%s)", why);
    }
    if (*FMUstate && state_valid(*FMUstate))
        fmu__free(f, *FMUstate);
    *FMUstate = s;
    return fmi2OK;
}
