/* The FMU state (FMI 2.0 section 2.1.8): get, set, free and serialize. The library has no
 * API yet to save a model's warm start, so a state records what rebuilds it exactly: the
 * values of all variables, the load the model was set at and the positions evaluated since
 * (in order). Setting a state sets the model at that load and evaluates those positions
 * again, which leaves the warm start bit for bit where it was; the cost is one evaluation
 * per step since the last load change. SPDX-License-Identifier: GPL-3.0-or-later */
#include <stdint.h>
#include <string.h>

#include "fmu_impl.h"

#define STATE_MAGIC "TRNVFMU"   /* 8 bytes with its terminating zero */
#define STATE_VERSION 1u

typedef struct {
    char magic[8];
    uint32_t version;
    uint32_t values_size;   /* sizeof(fmu_values) of the build that wrote it */
    uint64_t n_hist;
    int32_t mode;
    int32_t pad;
} state_header;

typedef struct {
    state_header hdr;
    fmu_values v;
    double hist[];          /* hdr.n_hist positions, m */
} fmu_state;

static fmu_state *state_alloc(const fmu_instance *f, size_t n_hist)
{
    fmu_state *s = fmu__alloc(f, sizeof *s + n_hist * sizeof(double));
    if (!s)
        return NULL;
    memcpy(s->hdr.magic, STATE_MAGIC, sizeof s->hdr.magic);
    s->hdr.version = STATE_VERSION;
    s->hdr.values_size = (uint32_t)sizeof(fmu_values);
    s->hdr.n_hist = n_hist;
    return s;
}

static int state_valid(const fmu_state *s)
{
    return s && memcmp(s->hdr.magic, STATE_MAGIC, sizeof s->hdr.magic) == 0 &&
           s->hdr.version == STATE_VERSION && s->hdr.values_size == sizeof(fmu_values);
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    fmu_instance *f = c;
    if (!f || !FMUstate)
        return f ? fmu__fail_diag(f, "fmi2GetFMUstate", &(tirenv_diag){
                                     .message = "NULL state pointer"})
                 : fmi2Error;
    const size_t n = f->v.model_set ? f->n_hist : 0;
    fmu_state *s = *FMUstate;
    if (!state_valid(s) || s->hdr.n_hist != n) {  /* a new one, or one of another size */
        if (state_valid(s))
            fmu__free(f, s);
        if (!(s = state_alloc(f, n)))
            return fmu__fail_diag(f, "fmi2GetFMUstate",
                                  &(tirenv_diag){.message = "out of memory"});
    }
    s->hdr.mode = (int32_t)f->mode;
    s->v = f->v;
    if (n)
        memcpy(s->hist, f->hist, n * sizeof(double));
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
    if (!state_valid(s))
        return fmu__fail_diag(f, "fmi2SetFMUstate",
                              &(tirenv_diag){.message = "not a state of this FMU"});
    const int rebuild = !f->m || !same_parameters(&f->v, &s->v);
    f->v = s->v;
    if (s->v.model_set || s->v.evaluated) {
        if (rebuild && fmu__setup(f) != fmi2OK)
            return fmi2Error;
        f->v = s->v;
        if (s->v.model_set) {
            if (fmu__set_load(f, s->v.load_set) != fmi2OK)
                return fmi2Error;
            f->v.load = s->v.load_set;  /* the inputs of the steps replayed */
            for (size_t k = 0; k < s->hdr.n_hist; ++k) {
                f->v.x = s->hist[k];
                if (fmu__evaluate(f) != fmi2OK)
                    return fmi2Error;
            }
        }
    } else if (rebuild) {
        fmu__teardown(f);  /* built from the restored parameters when next needed */
    }
    f->v = s->v;
    if (f->mode == FMU_ERROR)
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
    *size = sizeof *s + s->hdr.n_hist * sizeof(double);
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
        hdr.n_hist > (SIZE_MAX - sizeof(fmu_state)) / sizeof(double) ||
        size != sizeof(fmu_state) + hdr.n_hist * sizeof(double))
        return fmu__fail_diag(f, "fmi2DeSerializeFMUstate", &(tirenv_diag){
                                  .message = "not a serialized state of this FMU build "
                                             "(magic, version, value layout or size differ)"});
    fmu_state *s = state_alloc(f, (size_t)hdr.n_hist);
    if (!s)
        return fmu__fail_diag(f, "fmi2DeSerializeFMUstate",
                              &(tirenv_diag){.message = "out of memory"});
    memcpy(s, serializedState, size);
    /* Strings must be terminated within their buffers before anything reads them. */
    s->v.model[sizeof s->v.model - 1] = '\0';
    s->v.tire_file[sizeof s->v.tire_file - 1] = '\0';
    s->v.road_file[sizeof s->v.road_file - 1] = '\0';
    if (*FMUstate && state_valid(*FMUstate))
        fmu__free(f, *FMUstate);
    *FMUstate = s;
    return fmi2OK;
}
