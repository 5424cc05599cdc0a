/* SPDX-License-Identifier: Apache-2.0 */
/* libFuzzer entry point for the FMU (fmu/): the input is a program of FMI 2.0 calls on one
 * instance, in any order and with any arguments (modes out of order, NULL arrays, NaN and
 * infinite times and values, unknown value references, models and files), including states
 * taken, set, freed, serialized, corrupted at offsets the input chooses (a byte, or a word of
 * 8, the model state's checksum made again or not) and deserialized, and raw bytes
 * deserialized as a state. Nothing may crash, leak, read out of
 * bounds or hang whatever the importer does, short of using a freed instance (which FMI 2.0
 * leaves undefined). Seeds: corpus/fmu (runs of springs and cam over the cleat with states
 * taken, corrupted, set and moved; made by fmu_seeds.py).
 * The instance's resources are a private directory holding a 0.10 x 0.10 m cleat (cleat.csv)
 * and a flat road (road.csv), no tire file: the FMU's start value of tire_file (default.tir)
 * is refused there, so an input sets tire_file "" (the built-in tire) to reach a model. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmu_impl.h"
#include "fuzz_input.h"

/* The input, read a piece at a time; past its end every piece reads as zero. */
typedef struct {
    const uint8_t *p;
    size_t n;
} cursor;

static uint8_t byte(cursor *c)
{
    if (!c->n)
        return 0;
    --c->n;
    return *c->p++;
}

/* A number: from a table of the values that break things (one byte), or 8 raw bytes. */
static double number(cursor *c)
{
    static const double table[] = {0,     1,       -1,     0.05,  -0.3,   7500,   1e-3,
                                   1e308, 1e-308,  -1e308, 0.9,   20000,  2.5e-2, 1e9,
                                   NAN,   INFINITY, -INFINITY, 4e-324};
    const uint8_t k = byte(c);
    if (k < 2 * (sizeof table / sizeof table[0]))
        return table[k % (sizeof table / sizeof table[0])];
    double x = 0;
    unsigned char raw[8] = {0};
    for (int i = 0; i < 8; ++i)
        raw[i] = byte(c);
    memcpy(&x, raw, sizeof x);
    return x;
}

static const char *string(cursor *c)
{
    static const char *const table[] = {"springs", "cam",  "ring",   "rigid", "nn",
                                        "point",   "sprongs", "",   "cleat.csv", "road.csv",
                                        "/nonexistent/road.csv", "default.tir", "../cleat.csv"};
    return table[byte(c) % (sizeof table / sizeof table[0])];
}

/* The Real references 0 to 11 and some that are none (12 to 15), the String ones 100 to 102
 * and 103 (none). */
static fmi2ValueReference reference(cursor *c)
{
    const uint8_t b = byte(c);
    return b >= 128 ? 100u + b % 4u : b % 16u;
}

static char resources[400];
static char guid[64];

static void setup_resources(void)
{
    if (resources[0])
        return;
    const char *dir = fuzz_input_dir();
    char path[400];
    snprintf(path, sizeof path, "%s/cleat.csv", dir);
    FILE *fp = fopen(path, "w");
    if (!fp)
        abort();
    fputs("x_m,z_m\n-0.05,0\n-0.05,0.1\n0.05,0.1\n0.05,0\n", fp);
    fclose(fp);
    snprintf(path, sizeof path, "%s/road.csv", dir);
    if (!(fp = fopen(path, "w")))
        abort();
    fputs("x_m,z_m\n-5,0\n5,0.01\n", fp);
    fclose(fp);
    snprintf(resources, sizeof resources, "file://%s", dir);
    fmu__guid(guid, sizeof guid);
}

static void quiet(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                  fmi2String category, fmi2String message, ...)
{
    (void)env, (void)instance, (void)status, (void)category, (void)message;
}

static const fmi2CallbackFunctions callbacks = {quiet, calloc, free, NULL, NULL};

enum { SLOTS = 2, OPS = 48 };

static fmi2Component instantiate(cursor *c)
{
    const uint8_t how = byte(c);
    return fmi2Instantiate(how & 1 ? "" : "fuzz", how & 2 ? fmi2ModelExchange : fmi2CoSimulation,
                           how & 4 ? "{other}" : guid, how & 8 ? "http://x" : resources,
                           &callbacks, fmi2False, (how & 16) != 0);
}

/* The model's state within serialized bytes b (tirenv_model_state_save's: its magic, then
 * its size) given the checksum of its bytes as changed (FNV-1a, 64 bits, over all before
 * it), as a host that means harm would: the model's own checks then meet the changes. */
static void reseal(fmi2Byte *b, size_t size)
{
    static const char magic[8] = {'t', 'i', 'r', 'e', 'n', 'v', 'S', '1'};
    for (size_t at = 0; at + 16 <= size; ++at) {
        if (memcmp(b + at, magic, sizeof magic) != 0)
            continue;
        uint64_t total;
        memcpy(&total, b + at + 8, sizeof total);
        if (total < 16 + sizeof total || total > size - at)
            return;
        uint64_t h = 0xcbf29ce484222325ull;
        for (size_t j = at; j < at + total - sizeof h; ++j) {
            h ^= (unsigned char)b[j];
            h *= 0x100000001b3ull;
        }
        memcpy(b + at + total - sizeof h, &h, sizeof h);
        return;
    }
}

/* A state of slot serialized, bytes of it changed where the input says (8 bytes at a time
 * where it says so, the model's checksum made again where it says so), deserialized into
 * slot (or refused). */
static void corrupt(fmi2Component f, fmi2FMUstate *slot, cursor *c)
{
    size_t size = 0;
    if (fmi2SerializedFMUstateSize(f, *slot, &size) != fmi2OK || !size)
        return;
    fmi2Byte *b = malloc(size);
    if (!b)
        abort();
    if (fmi2SerializeFMUstate(f, *slot, b, size) == fmi2OK) {
        const uint8_t how = byte(c);
        for (uint8_t k = how % 4; k; --k) {
            const size_t at = ((size_t)byte(c) << 8 | byte(c)) % size;
            for (size_t w = 0; w < (how & 4 ? 8u : 1u); ++w)
                b[(at + w) % size] = byte(c);
        }
        if (how & 8)
            reseal(b, size);
        const size_t cut = byte(c) == 255 ? size / 2 : size;
        fmi2DeSerializeFMUstate(f, b, cut, slot);
    }
    free(b);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    setup_resources();
    cursor c = {data, size};
    fmi2Component f = instantiate(&c);
    fmi2FMUstate slot[SLOTS] = {NULL, NULL};
    double t = 0;
    for (int op = 0; op < OPS && c.n && f; ++op) {
        fmi2ValueReference vr[3];
        double v[3];
        fmi2String s[2];
        const uint8_t code = byte(&c);
        const int k = byte(&c) % SLOTS;
        switch (code % 22) {
        case 0: {
            const int tol = byte(&c) & 1, stop = byte(&c) & 1;
            const double a = number(&c), b = number(&c), e = number(&c);
            if (fmi2SetupExperiment(f, tol, a, b, stop, e) == fmi2OK)
                t = b;
            break;
        }
        case 1: fmi2EnterInitializationMode(f); break;
        case 2: fmi2ExitInitializationMode(f); break;
        case 3: fmi2Terminate(f); break;
        case 4: fmi2Reset(f); t = 0; break;
        case 5:
            vr[0] = reference(&c), vr[1] = reference(&c), v[0] = number(&c), v[1] = number(&c);
            fmi2SetReal(f, vr, 1 + (byte(&c) & 1), v);
            break;
        case 6:
            vr[0] = reference(&c), vr[1] = reference(&c), vr[2] = reference(&c);
            fmi2GetReal(f, vr, 3, v);
            break;
        case 7:
            vr[0] = reference(&c), s[0] = string(&c);
            fmi2SetString(f, vr, 1, s);
            break;
        case 8:
            vr[0] = reference(&c);
            fmi2GetString(f, vr, 1, s);
            break;
        case 9: {
            const double dt = byte(&c) & 1 ? number(&c) : 1e-3;
            const double at = byte(&c) & 1 ? number(&c) : t;
            if (fmi2DoStep(f, at, dt, fmi2False) == fmi2OK)
                t = at + dt;
            break;
        }
        case 10: fmi2GetFMUstate(f, &slot[k]); break;
        case 11: fmi2SetFMUstate(f, slot[k]); break;
        case 12: fmi2FreeFMUstate(f, &slot[k]); break;
        case 13: corrupt(f, &slot[k], &c); break;
        case 14: {  /* raw bytes as a serialized state */
            const size_t n = byte(&c) * 16 + byte(&c);
            const size_t m = n < c.n ? n : c.n;
            fmi2DeSerializeFMUstate(f, (const fmi2Byte *)c.p, m, &slot[k]);
            c.p += m, c.n -= m;
            break;
        }
        case 15: {
            const fmi2String cats[2] = {byte(&c) & 1 ? "logAll" : "bogus", NULL};
            fmi2SetDebugLogging(f, byte(&c) & 1, byte(&c) % 3, byte(&c) & 1 ? cats : NULL);
            break;
        }
        case 16: {
            fmi2Status st;
            fmi2Real r;
            fmi2Integer i;
            fmi2Boolean b;
            fmi2String str;
            const fmi2StatusKind kind = (fmi2StatusKind)(byte(&c) % 5);
            fmi2GetStatus(f, kind, &st);
            fmi2GetRealStatus(f, kind, byte(&c) & 1 ? &r : NULL);
            fmi2GetIntegerStatus(f, kind, &i);
            fmi2GetBooleanStatus(f, kind, byte(&c) & 1 ? &b : NULL);
            fmi2GetStringStatus(f, kind, &str);
            break;
        }
        case 17:  /* NULL arrays with counts */
            fmi2GetReal(f, NULL, byte(&c) % 3, NULL);
            fmi2SetReal(f, NULL, byte(&c) % 3, NULL);
            fmi2SetString(f, NULL, byte(&c) % 3, NULL);
            fmi2GetInteger(f, NULL, byte(&c) % 2, NULL);
            fmi2SetBoolean(f, NULL, byte(&c) % 2, NULL);
            break;
        case 18: {  /* a state moved to a new instance, as fmusim does */
            fmi2Component g = instantiate(&c);
            if (g) {
                fmi2SetFMUstate(g, slot[k]);
                fmi2DoStep(g, t, 1e-3, fmi2False);
                vr[0] = reference(&c);
                fmi2GetReal(g, vr, 1, v);
                fmi2FreeInstance(g);
            }
            break;
        }
        case 19: {
            size_t n = 0;
            fmi2SerializedFMUstateSize(f, slot[k], byte(&c) & 1 ? &n : NULL);
            break;
        }
        case 20: fmi2CancelStep(f); break;
        default:
            vr[0] = reference(&c), v[0] = number(&c);
            fmi2SetRealInputDerivatives(f, vr, 1, (const fmi2Integer[]){1}, v);
            fmi2GetDirectionalDerivative(f, vr, 1, vr, 1, v, v + 1);
            break;
        }
    }
    for (int k = 0; k < SLOTS; ++k)
        if (f)
            fmi2FreeFMUstate(f, &slot[k]);
        else
            free(slot[k]);
    fmi2FreeInstance(f);
    return 0;
}
