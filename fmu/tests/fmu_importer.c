/* A small FMI 2.0 co-simulation importer of our own for tirenv's FMU: unzips it into a
 * temporary directory, reads the GUID and value references from modelDescription.xml,
 * dlopens the binary and checks it against the CLI:
 *   - stepping along a 0.10 x 0.10 m cleat at one load gives 'tirenv envelope's curve (h,
 *     slope, fx, fz as the CSV writes them, every row), and the Chrono-style outputs agree;
 *   - a load that changes every step gives, at each step, 'tirenv envelope' at that load;
 *   - an FMU state taken mid-cleat, set again (directly and through serialization), repeats
 *     the following steps bit for bit, every output (the model's state holds the working set
 *     the springs model's start at a new x takes up); so do states taken at every 25th step
 *     from 800 to 1,100, and one taken while the load changes every step
 *     (tirenv_model_set_load), and a state's size does not grow with the steps; a state
 *     set into an instance that was only instantiated brings its mode and time and steps on;
 *   - a serialized state with a corrupted mode is refused; NULL categories, NaN and infinite
 *     times and steps give fmi2Error and leave the instance usable;
 *   - wrong value references, a parameter set too late, an unknown model, a missing road
 *     file and a wrong GUID give fmi2Error (or NULL) and a log message saying why;
 *   - the cam on a tire file without its shape keys is refused, naming them;
 *   - with TIR (a tire file whose cam laws are its own), the cam alone derives no ring.
 * Prints TAP lines; exits 1 if a check fails.
 * usage: fmu_importer FMU CLI [TIR]  SPDX-License-Identifier: Apache-2.0 */
#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fmi2.h"

#include "../../tests/lib/tap.h"

/* ---- the logger: keeps the last message, formatted as the standard says ------------------ */
static char last_log[4096];
static int n_logs;

static void logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    (void)env;
    char text[3000];
    va_list ap;
    va_start(ap, message);
    vsnprintf(text, sizeof text, message, ap);
    va_end(ap);
    snprintf(last_log, sizeof last_log, "[%s] %s (status %d): %s", category, instance,
             (int)status, text);
    ++n_logs;
}

static int logged(const char *needle)
{
    return strstr(last_log, needle) != NULL;
}

/* ---- the FMU's functions ---------------------------------------------------------------- */
typedef struct {
    void *so;
    fmi2Component (*instantiate)(fmi2String, fmi2Type, fmi2String, fmi2String,
                                 const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean);
    void (*free_instance)(fmi2Component);
    fmi2Status (*setup)(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real, fmi2Boolean, fmi2Real);
    fmi2Status (*enter_init)(fmi2Component);
    fmi2Status (*exit_init)(fmi2Component);
    fmi2Status (*terminate)(fmi2Component);
    fmi2Status (*get_real)(fmi2Component, const fmi2ValueReference[], size_t, fmi2Real[]);
    fmi2Status (*set_real)(fmi2Component, const fmi2ValueReference[], size_t, const fmi2Real[]);
    fmi2Status (*get_string)(fmi2Component, const fmi2ValueReference[], size_t, fmi2String[]);
    fmi2Status (*set_string)(fmi2Component, const fmi2ValueReference[], size_t,
                             const fmi2String[]);
    fmi2Status (*do_step)(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
    fmi2Status (*get_state)(fmi2Component, fmi2FMUstate *);
    fmi2Status (*set_state)(fmi2Component, fmi2FMUstate);
    fmi2Status (*free_state)(fmi2Component, fmi2FMUstate *);
    fmi2Status (*state_size)(fmi2Component, fmi2FMUstate, size_t *);
    fmi2Status (*serialize)(fmi2Component, fmi2FMUstate, fmi2Byte[], size_t);
    fmi2Status (*deserialize)(fmi2Component, const fmi2Byte[], size_t, fmi2FMUstate *);
    fmi2Status (*set_debug_logging)(fmi2Component, fmi2Boolean, size_t, const fmi2String[]);
} fmu_api;

static void *sym(void *so, const char *name)
{
    void *p = dlsym(so, name);
    if (!p) {
        fprintf(stderr, "fmu_importer: %s missing from the FMU\n", name);
        exit(1);
    }
    return p;
}

#define BIND(field, name) *(void **)&api->field = sym(api->so, name)

static void bind(fmu_api *api)
{
    BIND(instantiate, "fmi2Instantiate");
    BIND(free_instance, "fmi2FreeInstance");
    BIND(setup, "fmi2SetupExperiment");
    BIND(enter_init, "fmi2EnterInitializationMode");
    BIND(exit_init, "fmi2ExitInitializationMode");
    BIND(terminate, "fmi2Terminate");
    BIND(get_real, "fmi2GetReal");
    BIND(set_real, "fmi2SetReal");
    BIND(get_string, "fmi2GetString");
    BIND(set_string, "fmi2SetString");
    BIND(do_step, "fmi2DoStep");
    BIND(get_state, "fmi2GetFMUstate");
    BIND(set_state, "fmi2SetFMUstate");
    BIND(free_state, "fmi2FreeFMUstate");
    BIND(state_size, "fmi2SerializedFMUstateSize");
    BIND(serialize, "fmi2SerializeFMUstate");
    BIND(deserialize, "fmi2DeSerializeFMUstate");
    BIND(set_debug_logging, "fmi2SetDebugLogging");
}

/* ---- modelDescription.xml, read just enough: the GUID and a variable's reference -------- */
static char *xml;

static char *slurp(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    fseek(fp, 0, SEEK_END);
    const long n = ftell(fp);
    rewind(fp);
    char *s = malloc((size_t)n + 1);
    if (s && fread(s, 1, (size_t)n, fp) != (size_t)n) {
        free(s);
        s = NULL;
    }
    if (s)
        s[n] = '\0';
    fclose(fp);
    return s;
}

static void attribute(const char *from, const char *name, char *out, size_t n)
{
    char key[64];
    snprintf(key, sizeof key, " %s=\"", name);
    const char *p = strstr(from, key);
    out[0] = '\0';
    if (!p)
        return;
    p += strlen(key);
    size_t k = 0;
    while (*p && *p != '"' && k + 1 < n)
        out[k++] = *p++;
    out[k] = '\0';
}

/* The value reference of the variable called name; exits if the description has none. */
static fmi2ValueReference vr_of(const char *name)
{
    char key[128], buf[32];
    snprintf(key, sizeof key, "<ScalarVariable name=\"%s\"", name);
    const char *p = strstr(xml, key);
    if (!p) {
        fprintf(stderr, "fmu_importer: no variable '%s' in modelDescription.xml\n", name);
        exit(1);
    }
    attribute(p, "valueReference", buf, sizeof buf);
    return (fmi2ValueReference)strtoul(buf, NULL, 10);
}

/* ---- the CLI's curve -------------------------------------------------------------------- */
typedef struct {
    size_t n;
    char (*row)[256];  /* "x,z,h,slope,fx,fz,contacts,iterations" */
} csv;

static csv read_csv(const char *path)
{
    csv c = {0, NULL};
    FILE *fp = fopen(path, "r");
    char line[256];
    size_t cap = 0;
    if (!fp || !fgets(line, sizeof line, fp))
        return c;
    while (fgets(line, sizeof line, fp)) {
        if (c.n == cap) {
            cap = cap ? 2 * cap : 2048;
            c.row = realloc(c.row, cap * sizeof *c.row);
        }
        line[strcspn(line, "\r\n")] = '\0';
        snprintf(c.row[c.n++], sizeof c.row[0], "%s", line);
    }
    fclose(fp);
    return c;
}

/* Field k (0-based) of a CSV row, into out. */
static void field(const char *row, int k, char *out, size_t n)
{
    for (; k > 0 && row; --k)
        row = strchr(row, ',') ? strchr(row, ',') + 1 : NULL;
    snprintf(out, n, "%.*s", row ? (int)strcspn(row, ",") : 0, row ? row : "");
}

static int run(const char *cmd)
{
    const int rc = system(cmd);
    if (rc != 0)
        fprintf(stderr, "fmu_importer: '%s' failed (%d)\n", cmd, rc);
    return rc;
}

/* ---- driving the FMU ----------------------------------------------------------------------- */
static fmu_api api;
static fmi2CallbackFunctions cb = {logger, calloc, free, NULL, NULL};
static char guid[128], resources[1200], dir[64], cli[1024];
static fmi2ValueReference VR_X, VR_LOAD, VR_H, VR_SLOPE, VR_TH, VR_NX, VR_NY, VR_NZ, VR_FX,
    VR_FZ, VR_MODEL, VR_ROAD, VR_TIRE;

/* An instance in step mode over road with model at x0 and load, of the tire in the file tire
 * (road NULL: the default road; tire NULL: the default tire; a tire needs a road, since the
 * strings are set in the order model, road, tire). */
static fmi2Component start_tire(const char *model, const char *road, const char *tire,
                                double x0, double load, fmi2Status *exit_status)
{
    fmi2Component c = api.instantiate("tire", fmi2CoSimulation, guid, resources, &cb,
                                      fmi2False, fmi2False);
    if (!c)
        return NULL;
    const fmi2ValueReference s_vr[3] = {VR_MODEL, VR_ROAD, VR_TIRE};
    const fmi2String s_val[3] = {model, road, tire};
    const fmi2ValueReference r_vr[2] = {VR_X, VR_LOAD};
    const fmi2Real r_val[2] = {x0, load};
    fmi2Status st = api.setup(c, fmi2False, 0, 0, fmi2False, 0);
    if (st == fmi2OK)
        st = api.set_string(c, s_vr, tire ? 3 : road ? 2 : 1, s_val);
    if (st == fmi2OK)
        st = api.enter_init(c);
    if (st == fmi2OK)
        st = api.set_real(c, r_vr, 2, r_val);
    if (st == fmi2OK)
        st = api.exit_init(c);
    *exit_status = st;
    return c;
}

/* start_tire with the default tire. */
static fmi2Component start(const char *model, const char *road, double x0, double load,
                           fmi2Status *exit_status)
{
    return start_tire(model, road, NULL, x0, load, exit_status);
}

/* One step to x at load; the outputs h, slope, terrain_height, normal xyz, fx, fz in out. */
static fmi2Status step(fmi2Component c, double t, double x, double load, double out[8])
{
    const fmi2ValueReference in_vr[2] = {VR_X, VR_LOAD};
    const double in[2] = {x, load};
    const fmi2ValueReference out_vr[8] = {VR_H, VR_SLOPE, VR_TH, VR_NX, VR_NY, VR_NZ, VR_FX,
                                          VR_FZ};
    fmi2Status st = api.set_real(c, in_vr, 2, in);
    if (st == fmi2OK)
        st = api.do_step(c, t, 1e-3, fmi2False);
    if (st == fmi2OK)
        st = api.get_real(c, out_vr, 8, out);
    return st;
}

static const double X_FROM = -0.8, X_TO = 0.8, DX = 0.001, LOAD = 7500;

/* Serialized bytes an importer corrupted are refused, naming what is wrong, and the argument
 * checks of the entry points hold: bytes is a good serialized state of size
 * bytes from instance d, in step mode; both are left as they were. */
static void test_state_untrusted(fmi2Component d, const fmi2Byte *bytes, size_t size)
{
    /* The header as fmu_state.c lays it out: magic[8], version, values_size (uint32 each),
     * n_model (uint64), mode (int32) at byte 24. */
    const size_t mode_at = 24;
    fmi2Byte *bad = malloc(size);
    memcpy(bad, bytes, size);
    const int32_t modes[3] = {100000000, -1, 5};
    int refused = 0;
    for (int i = 0; i < 3; ++i) {
        memcpy(bad + mode_at, &modes[i], sizeof modes[i]);
        fmi2FMUstate s = NULL;
        n_logs = 0;
        refused += api.deserialize(d, bad, size, &s) == fmi2Error && !s && logged("mode");
    }
    check(refused == 3, "a serialized state whose mode is 1e8, -1 or 5 is refused, naming the "
          "mode (%d of 3; %s)", refused, last_log);
    free(bad);

    n_logs = 0;
    check(api.set_debug_logging(d, fmi2True, 2, NULL) == fmi2Error && logged("NULL"),
          "fmi2SetDebugLogging(c, 1, 2, NULL): fmi2Error, logged (%s)", last_log);
    const fmi2String all = "logAll";
    check(api.set_debug_logging(d, fmi2False, 1, &all) == fmi2OK,
          "and a proper category list after it is taken");
    double t;
    const fmi2ValueReference t_vr = VR_H;
    check(api.do_step(d, 0.9, INFINITY, fmi2False) == fmi2Error &&
          api.do_step(d, 0.9, NAN, fmi2False) == fmi2Error &&
          api.do_step(d, NAN, 1e-3, fmi2False) == fmi2Error,
          "fmi2DoStep with an infinite or NaN step or time: fmi2Error");
    check(api.get_real(d, &t_vr, 1, &t) == fmi2OK && isfinite(t),
          "and the instance is still in step mode, its outputs readable");

    fmi2Component c = api.instantiate("fresh", fmi2CoSimulation, guid, resources, &cb,
                                      fmi2False, fmi2False);
    n_logs = 0;
    check(c && api.setup(c, fmi2False, 0, NAN, fmi2False, 0) == fmi2Error && logged("start"),
          "fmi2SetupExperiment with a NaN start time: fmi2Error, logged (%s)", last_log);
    check(api.setup(c, fmi2False, 0, INFINITY, fmi2False, 0) == fmi2Error &&
          api.setup(c, fmi2False, 0, 0, fmi2True, -1) == fmi2Error &&
          api.setup(c, fmi2True, NAN, 0, fmi2False, 0) == fmi2Error,
          "an infinite start, a stop before the start, a NaN tolerance: fmi2Error");
    check(api.setup(c, fmi2True, 1e-6, 0, fmi2True, 10) == fmi2OK,
          "and the instance takes a proper experiment after them");
    api.free_instance(c);

    /* A stop time defined: a step that ends past it is refused (FMI 2.0 section 4.2.1 lets
     * the FMU, and the Reference FMUs do), one that ends on it is taken; the instance stays
     * in step mode. */
    fmi2Component e = api.instantiate("stop", fmi2CoSimulation, guid, resources, &cb,
                                      fmi2False, fmi2False);
    const fmi2ValueReference m_vr = VR_MODEL;
    const fmi2String rigid = "rigid";
    check(e && api.setup(e, fmi2False, 0, 0, fmi2True, 2e-3) == fmi2OK &&
              api.set_string(e, &m_vr, 1, &rigid) == fmi2OK && api.enter_init(e) == fmi2OK &&
              api.exit_init(e) == fmi2OK && api.do_step(e, 0, 1e-3, fmi2False) == fmi2OK &&
              api.do_step(e, 1e-3, 1e-3, fmi2False) == fmi2OK,
          "with a stop time of 2 ms, two steps of 1 ms: fmi2OK");
    n_logs = 0;
    check(api.do_step(e, 2e-3, 1e-3, fmi2False) == fmi2Error && logged("stop time"),
          "a third step, past the stop time: fmi2Error, logged (%s)", last_log);
    check(api.get_real(e, &t_vr, 1, &t) == fmi2OK && isfinite(t),
          "and the instance is still in step mode, its outputs readable");
    api.free_instance(e);
    api.free_instance(NULL);
    check(1, "fmi2FreeInstance(NULL) returns");
}

static void test_cleat(const char *road)
{
    char cmd[4096], path[256];
    snprintf(path, sizeof path, "%s/envelope.csv", dir);
    snprintf(cmd, sizeof cmd, "'%s' envelope --model springs --profile '%s' --load %.17g "
             "--x-from %.17g --x-to %.17g --dx %.17g -o '%s' 2>/dev/null", cli, road, LOAD,
             X_FROM, X_TO, DX, path);
    if (run(cmd))
        exit(1);
    const csv ref = read_csv(path);
    check(ref.n == 1601, "tirenv envelope wrote %zu rows over the cleat", ref.n);
    fmi2Status st;
    fmi2Component c = start("springs", road, X_FROM, LOAD, &st);
    check(c && st == fmi2OK, "instantiated and initialized over the cleat (status %d)", st);
    if (!c || st != fmi2OK)
        return;
    size_t same = 0, chrono_ok = 0, first_diff = 0;
    int first = 1;
    double *h = malloc(ref.n * sizeof *h);
    for (size_t k = 0; k < ref.n; ++k) {
        const double x = X_FROM + (double)k * DX;  /* the CLI's positions */
        double out[8];
        if (step(c, (double)k * 1e-3, x, LOAD, out) != fmi2OK)
            break;
        h[k] = out[0];
        char got[200], want[4][64];
        for (int j = 0; j < 4; ++j)
            field(ref.row[k], j == 0 ? 2 : j == 1 ? 3 : j + 2, want[j], sizeof want[j]);
        snprintf(got, sizeof got, "%.9g,%.9g,%.9g,%.9g", out[0], out[1], out[6], out[7]);
        char wanted[300];
        snprintf(wanted, sizeof wanted, "%s,%s,%s,%s", want[0], want[1], want[2], want[3]);
        if (strcmp(got, wanted) == 0)
            ++same;
        else if (first) {
            first = 0;
            first_diff = k;
            fprintf(stderr, "# row %zu: FMU %s, CLI %s\n", k, got, wanted);
        }
        const double norm = sqrt(1 + out[1] * out[1]);
        chrono_ok += out[2] == out[0] && out[3] == -out[1] / norm && out[4] == 0 &&
                     out[5] == 1 / norm;
    }
    check(same == ref.n, "h, slope, fx, fz at every step are tirenv envelope's (%zu of %zu "
          "rows; first difference at %zu)", same, ref.n, first_diff);
    check(chrono_ok == ref.n, "terrain_height = h and terrain_normal = (-slope, 0, 1)/|.| at "
          "every step (%zu of %zu)", chrono_ok, ref.n);

    /* The FMU state: taken at step 700 (on the cleat's approach), set back, repeated. */
    fmi2Component d;
    d = start("springs", road, X_FROM, LOAD, &st);
    double out[8];
    const size_t k0 = 700, n_after = 200;
    for (size_t k = 0; k < k0 && st == fmi2OK; ++k)
        st = step(d, (double)k * 1e-3, X_FROM + (double)k * DX, LOAD, out);
    fmi2FMUstate saved = NULL;
    check(st == fmi2OK && api.get_state(d, &saved) == fmi2OK && saved,
          "fmi2GetFMUstate at step %zu", k0);
    double first_pass[200][8], again[200][8], restored[200][8];
    int same_h = 1;
    for (size_t k = k0; k < k0 + n_after; ++k) {
        st = step(d, (double)k * 1e-3, X_FROM + (double)k * DX, LOAD, first_pass[k - k0]);
        same_h &= memcmp(&first_pass[k - k0][0], &h[k], sizeof h[k]) == 0;
    }
    check(st == fmi2OK && same_h, "the run with a state taken is the run without, bit for bit");
    check(api.set_state(d, saved) == fmi2OK, "fmi2SetFMUstate back to step %zu", k0);
    for (size_t k = k0; k < k0 + n_after; ++k)
        st = step(d, (double)k * 1e-3, X_FROM + (double)k * DX, LOAD, again[k - k0]);
    check(st == fmi2OK && memcmp(first_pass, again, sizeof again) == 0,
          "after fmi2SetFMUstate the next %zu steps repeat bit for bit (every output)",
          n_after);
    size_t size = 0;
    fmi2FMUstate copy = NULL;
    st = api.state_size(d, saved, &size);
    check(st == fmi2OK && size > 0, "fmi2SerializedFMUstateSize: %zu bytes", size);
    fmi2Byte *bytes = malloc(size);
    check(api.serialize(d, saved, bytes, size) == fmi2OK &&
          api.deserialize(d, bytes, size, &copy) == fmi2OK && copy,
          "serialized and deserialized");
    /* ... into a fresh instance, which must read the road itself */
    fmi2Component e = start("springs", road, X_FROM, LOAD, &st);
    check(e && api.set_state(e, copy) == fmi2OK, "the deserialized state set in a new instance");
    for (size_t k = k0; k < k0 + n_after; ++k)
        st = step(e, (double)k * 1e-3, X_FROM + (double)k * DX, LOAD, restored[k - k0]);
    check(st == fmi2OK && memcmp(first_pass, restored, sizeof restored) == 0,
          "and the new instance repeats the steps bit for bit");
    /* ... into an instance that was only instantiated (fmusim's way): the state brings the
     * mode (step mode), the parameters and the time with it. */
    fmi2Component g = api.instantiate("bare", fmi2CoSimulation, guid, resources, &cb,
                                      fmi2False, fmi2False);
    n_logs = 0;
    last_log[0] = '\0';
    const fmi2Status set_bare = g ? api.set_state(g, copy) : fmi2Fatal;
    check(set_bare == fmi2OK, "the deserialized state set in an instance that was only "
          "instantiated%s%s", n_logs ? ": " : "", n_logs ? last_log : "");
    st = fmi2OK;
    for (size_t k = k0; k < k0 + n_after && st == fmi2OK; ++k)
        st = step(g, (double)k * 1e-3, X_FROM + (double)k * DX, LOAD, restored[k - k0]);
    check(st == fmi2OK && memcmp(first_pass, restored, sizeof restored) == 0,
          "and it steps on from the state's time, repeating the steps bit for bit");
    api.free_instance(g);
    test_state_untrusted(d, bytes, size);
    bytes[0] ^= 1;
    fmi2FMUstate bad = NULL;
    n_logs = 0;
    check(api.deserialize(d, bytes, size, &bad) == fmi2Error && n_logs && logged("not a serialized"),
          "a corrupted serialized state is refused with a log message");
    check(api.deserialize(d, bytes, size / 2, &bad) == fmi2Error,
          "a truncated serialized state is refused");
    free(bytes);
    api.free_state(d, &saved);
    api.free_state(d, &copy);
    check(saved == NULL && copy == NULL, "fmi2FreeFMUstate clears the pointers");
    api.terminate(c);
    api.free_instance(c);
    api.free_instance(d);
    api.free_instance(e);
    free(h);
    free(ref.row);
}

/* States taken at every 25th step from 800 to 1,100 (over the cleat and down its far side,
 * where the springs model's start at each new x takes up the working set the last position
 * left): after each, 10 steps, the state set back, the 10 steps again, every output bit for
 * bit; the run goes on from there. */
static void test_state_on_cleat(const char *road)
{
    enum { K_FROM = 800, K_TO = 1100, EVERY = 25, N_AFTER = 10 };
    fmi2Status st;
    fmi2Component c = start("springs", road, X_FROM, LOAD, &st);
    double out[8], first[N_AFTER][8], again[N_AFTER][8];
    size_t k = 0, taken = 0, repeated = 0;
#define STEP_AT(k, o) step(c, (double)(k) * 1e-3, X_FROM + (double)(k) * DX, LOAD, o)
    for (size_t k_s = K_FROM; k_s <= K_TO && c && st == fmi2OK; k_s += EVERY) {
        for (; k < k_s && st == fmi2OK; ++k)
            st = STEP_AT(k, out);
        fmi2FMUstate saved = NULL;
        if (st != fmi2OK || api.get_state(c, &saved) != fmi2OK)
            break;
        ++taken;
        for (size_t j = 0; j < N_AFTER && st == fmi2OK; ++j)
            st = STEP_AT(k + j, first[j]);
        if (st == fmi2OK && api.set_state(c, saved) == fmi2OK) {
            for (size_t j = 0; j < N_AFTER && st == fmi2OK; ++j)
                st = STEP_AT(k + j, again[j]);
            repeated += st == fmi2OK && memcmp(first, again, sizeof again) == 0;
        }
        k += N_AFTER;
        api.free_state(c, &saved);
    }
#undef STEP_AT
    check(taken == (K_TO - K_FROM) / EVERY + 1 && repeated == taken,
          "states taken at steps %d to %d over the cleat: the %d steps after each repeat bit "
          "for bit after fmi2SetFMUstate (%zu of %zu)", K_FROM, K_TO, N_AFTER, repeated, taken);
    if (c)
        api.free_instance(c);
}

/* A state taken while the load changes every step, set back after more steps at other loads:
 * the steps repeat bit for bit (the model's load, flat-ground point and warm start are in the
 * state), and the state's size does not grow with the steps taken. */
static void test_state_with_load_changes(const char *road)
{
    enum { K0 = 300, N_AFTER = 100 };
    fmi2Status st;
    fmi2Component c = start("springs", road, X_FROM, LOAD, &st);
    double out[8], first[N_AFTER], again[N_AFTER];
    /* +-20 % about LOAD, a new load at every step */
#define LOAD_AT(k) (LOAD * (1.0 + 0.2 * sin(0.05 * (double)(k))))
    for (size_t k = 0; k < K0 && c && st == fmi2OK; ++k)
        st = step(c, (double)k * 1e-3, X_FROM + (double)k * 2 * DX, LOAD_AT(k), out);
    fmi2FMUstate saved = NULL, later = NULL;
    size_t size0 = 0, size1 = 0;
    const int got0 = c && st == fmi2OK && api.get_state(c, &saved) == fmi2OK &&
                     api.state_size(c, saved, &size0) == fmi2OK;
    check(got0, "fmi2GetFMUstate at step %d with the load changing every step", K0);
    for (size_t k = K0; k < K0 + N_AFTER && st == fmi2OK; ++k) {
        st = step(c, (double)k * 1e-3, X_FROM + (double)k * 2 * DX, LOAD_AT(k), out);
        first[k - K0] = out[0];
    }
    const int got1 = st == fmi2OK && api.get_state(c, &later) == fmi2OK &&
                     api.state_size(c, later, &size1) == fmi2OK;
    check(got1 && size1 == size0, "a state's size does not grow with the steps (%zu bytes at step %d, %zu at %d)",
          size0, K0, size1, K0 + N_AFTER);
    check(api.set_state(c, saved) == fmi2OK, "fmi2SetFMUstate back to step %d", K0);
    for (size_t k = K0; k < K0 + N_AFTER && st == fmi2OK; ++k) {
        st = step(c, (double)k * 1e-3, X_FROM + (double)k * 2 * DX, LOAD_AT(k), out);
        again[k - K0] = out[0];
    }
#undef LOAD_AT
    check(st == fmi2OK && memcmp(first, again, sizeof again) == 0,
          "after fmi2SetFMUstate the next %d steps at changing loads repeat bit for bit",
          N_AFTER);
    api.free_state(c, &saved);
    api.free_state(c, &later);
    api.free_instance(c);
}

/* h as 'tirenv envelope' writes it at one position x (m) and load (N), into want. */
static int cli_h(const char *model, const char *road, double load, double x, char *want,
                 size_t n)
{
    char cmd[4096], path[256];
    snprintf(path, sizeof path, "%s/one.csv", dir);
    snprintf(cmd, sizeof cmd, "'%s' envelope --model %s --profile '%s' --load %.17g "
             "--x-from %.17g --x-to %.17g -o '%s' 2>/dev/null", cli, model, road, load, x, x,
             path);
    if (run(cmd))
        return -1;
    const csv one = read_csv(path);
    if (one.n == 1)
        field(one.row[0], 2, want, n);
    free(one.row);
    return one.n == 1 ? 0 : -1;
}

/* A load that changes every step: at each step the effective road at that load, as the CLI
 * computes one position at that load. */
static void test_load_changes(const char *road)
{
    static const double xs[6] = {-0.35, -0.2, -0.08, -0.03, 0.0, 0.12};
    static const double loads[6] = {7500, 11903.6, 9000, 17860.4, 7500, 12000};
    fmi2Status st;
    fmi2Component c = start("springs", road, xs[0], loads[0], &st);
    size_t same = 0;
    for (int k = 0; k < 6 && c && st == fmi2OK; ++k) {
        double out[8];
        if ((st = step(c, k * 1e-3, xs[k], loads[k], out)) != fmi2OK)
            break;
        char want[64], got[64];
        if (cli_h("springs", road, loads[k], xs[k], want, sizeof want))
            break;
        snprintf(got, sizeof got, "%.9g", out[0]);
        same += strcmp(want, got) == 0;
        if (strcmp(want, got))
            fprintf(stderr, "# x %g load %g: FMU h %s, CLI %s\n", xs[k], loads[k], got, want);
    }
    check(st == fmi2OK && same == 6, "with the load changing every step, h is tirenv "
          "envelope's at that load and position (%zu of 6)", same);
    api.free_instance(c);
}

/* The cam alone, on a tire file whose cam laws are all its own and that has no ring
 * (tests/data/samples/tir/tractor_430_50R38.tir): the FMU derives no ring for it, as tirenv
 * flat --model cam does not (docs/models.md section 14.2), says so, and carries the load;
 * the springs model of the same file is derived, on the ring searched on its laws. */
static void test_cam_alone(const char *road, const char *tir)
{
    static const char *const models[2] = {"cam", "springs"};
    static const char *const said[2] = {"the ring model not derived",
                                        "searched on the file's own vertical and contact laws"};
    for (size_t i = 0; i < 2; i++) {
        last_log[0] = '\0';
        fmi2Status st = fmi2Error;
        fmi2Component c = start_tire(models[i], road, tir, X_FROM, 20000, &st);
        const int note = logged(said[i]);
        double out[8] = {0};
        if (st == fmi2OK)
            st = step(c, 0, X_FROM, 20000, out);
        check(st == fmi2OK && note && fabs(out[7] - 20000) < 1e-3,
              "%s on the 430/50R38 (its own cam laws): '%s' logged, fz %g N of 20000 (%s)",
              models[i], said[i], out[7], last_log);
        if (c)
            api.free_instance(c);
    }
}

/* text written into the file name in the scratch directory, its path into path; whether it
 * was written. */
static int write_in_dir(char *path, size_t n, const char *name, const char *text)
{
    snprintf(path, n, "%s/%s", dir, name);
    FILE *fp = fopen(path, "w");
    const int ok = fp && fputs(text, fp) >= 0;
    return fp && !fclose(fp) && ok;
}

/* The cam on a tire whose ELLIPS_MAX_STEP (25 mm) is lower than the 0.1 m cleat: a warning
 * naming the key is logged once, at the step where a cam first touches the cleat's edge (the
 * first where h rises), however many steps follow. */
static void test_cam_max_step(const char *road)
{
    char tir[256];
    const int wrote = write_in_dir(tir, sizeof tir, "step.tir",
                 "[DIMENSION]\nUNLOADED_RADIUS = 0.3135\n[VERTICAL]\nFNOMIN = 4000\n"
                 "VERTICAL_STIFFNESS = 209651.5\n[CONTACT_PATCH]\nQ_RA1 = 0.6715\n"
                 "Q_RA2 = 0.7308\nELLIPS_SHIFT = 0.8328\nELLIPS_LENGTH = 1.4634\n"
                 "ELLIPS_HEIGHT = 0.9551\nELLIPS_ORDER = 1.5257\nELLIPS_MAX_STEP = 0.025\n");
    fmi2Status st = fmi2Error;
    fmi2Component c = start_tire("cam", road, tir, -0.8, 4000, &st);
    int warned = 0, first = -1, rise = -1;
    for (int k = 0; k <= 800 && st == fmi2OK; ++k) {
        double out[8] = {0};
        last_log[0] = '\0';
        if ((st = step(c, k * 1e-3, -0.8 + 1e-3 * k, 4000, out)) != fmi2OK)
            break;
        if (logged("ELLIPS_MAX_STEP") && warned++ == 0)
            first = k;
        if (out[0] > 0 && rise < 0)
            rise = k;
    }
    check(wrote && st == fmi2OK && warned == 1 && first > 0 && first == rise,
          "cam over a cleat higher than ELLIPS_MAX_STEP: warned %d time(s), at step %d, where "
          "h first rises (step %d)", warned, first, rise);
    if (c)
        api.free_instance(c);
}

/* The cam on a tire file without MF-Swift's cam shape keys: refused at initialization,
 * naming them and the file (it ran with the default tire's shape), as the CLI refuses it; the
 * springs model, which does not need them, runs on the same file. */
static void test_cam_keys(const char *road)
{
    char tir[256];
    const int wrote = write_in_dir(tir, sizeof tir, "nocam.tir",
                 "[DIMENSION]\nUNLOADED_RADIUS = 0.376\n[VERTICAL]\nFNOMIN = 3800\n"
                 "VERTICAL_STIFFNESS = 175000\n");
    fmi2Status st = fmi2OK;
    n_logs = 0;
    fmi2Component c = start_tire("cam", road, tir, 0, 3800, &st);
    check(wrote && c && st == fmi2Error && logged("nocam.tir: ELLIPS_SHIFT") &&
          logged("ELLIPS_SHIFT, ELLIPS_LENGTH, ELLIPS_HEIGHT, ELLIPS_ORDER"),
          "the cam on a tire file without its shape keys: fmi2Error at initialization, "
          "naming them and the file (%s)", last_log);
    if (c)
        api.free_instance(c);
    c = start_tire("springs", road, tir, 0, 3800, &st);
    check(c && st == fmi2OK, "... the springs model on the same file runs");
    if (c)
        api.free_instance(c);
}

static void test_errors(const char *road)
{
    fmi2Status st;
    fmi2Component c = start("springs", road, 0, LOAD, &st);
    double v = 1;
    const fmi2ValueReference bad = 999, string_vr = VR_MODEL, output_vr = VR_H;
    n_logs = 0;
    check(c && api.set_real(c, &bad, 1, &v) == fmi2Error && n_logs && logged("999"),
          "fmi2SetReal of an unknown value reference: fmi2Error, logged (%s)", last_log);
    n_logs = 0;
    check(api.get_real(c, &string_vr, 1, &v) == fmi2Error && n_logs,
          "fmi2GetReal of a String's value reference: fmi2Error, logged");
    n_logs = 0;
    check(api.set_real(c, &output_vr, 1, &v) == fmi2Error && logged("output"),
          "setting an output: fmi2Error, logged (%s)", last_log);
    const fmi2String name = "cam";
    n_logs = 0;
    check(api.set_string(c, &string_vr, 1, &name) == fmi2Error && logged("fixed parameter"),
          "setting a parameter in step mode: fmi2Error, logged (%s)", last_log);
    const fmi2ValueReference load_vr = VR_LOAD;
    v = -5;
    n_logs = 0;
    check(api.set_real(c, &load_vr, 1, &v) == fmi2Error && logged("load"),
          "a negative load: fmi2Error, logged (%s)", last_log);
    api.free_instance(c);

    n_logs = 0;
    c = start("sprongs", road, 0, LOAD, &st);
    check(c && st == fmi2Error && logged("sprongs") && logged("springs"),
          "an unknown model: fmi2Error at initialization, logged (%s)", last_log);
    api.free_instance(c);

    n_logs = 0;
    c = start("nn", road, 0, LOAD, &st);
    check(c && st == fmi2Error && logged("needs a trained network file"),
          "the network, which the FMU has no file for: fmi2Error at initialization, said so "
          "(%s)", last_log);
    api.free_instance(c);

    char missing[256];
    snprintf(missing, sizeof missing, "%s/no-such-road.csv", dir);
    n_logs = 0;
    c = start("springs", missing, 0, LOAD, &st);
    check(c && st == fmi2Error && logged("no-such-road.csv") && logged("cannot open"),
          "a missing road file: fmi2Error at initialization, logged (%s)", last_log);
    double x = 0.1;
    const fmi2ValueReference x_vr = VR_X;
    check(api.set_real(c, &x_vr, 1, &x) == fmi2Error && api.do_step(c, 0, 1e-3, fmi2False) ==
          fmi2Error, "and the instance refuses to step after it");
    api.free_instance(c);

    n_logs = 0;
    c = api.instantiate("tire", fmi2CoSimulation, "{not-this-fmu}", resources, &cb, fmi2False,
                        fmi2False);
    check(!c && n_logs && logged("GUID"), "a wrong GUID: NULL, logged (%s)", last_log);
    n_logs = 0;
    c = api.instantiate("tire", fmi2ModelExchange, guid, resources, &cb, fmi2False, fmi2False);
    check(!c && n_logs && logged("co-simulation"), "model exchange: NULL, logged");

    /* the defaults of the description: the packed tire and road */
    c = start("cam", NULL, 12.3, 10000, &st);
    double h;
    const fmi2ValueReference h_vr = VR_H;
    fmi2String road_name = NULL;
    const fmi2ValueReference road_vr = VR_ROAD;
    const int ok = c && st == fmi2OK && api.get_real(c, &h_vr, 1, &h) == fmi2OK &&
                   api.get_string(c, &road_vr, 1, &road_name) == fmi2OK &&
                   strcmp(road_name, "road.csv") == 0;
    char packed_road[1300], want[64] = "", got[64];
    snprintf(packed_road, sizeof packed_road, "%s/resources/road.csv", dir);
    snprintf(got, sizeof got, "%.9g", ok ? h : NAN);
    check(ok && cli_h("cam", packed_road, 10000, 12.3, want, sizeof want) == 0 &&
          strcmp(got, want) == 0, "the default road and tire from resources/ (cam at x = 12.3 "
          "m: h = %s m; tirenv envelope: %s m)", got, want);
    api.free_instance(c);
}

int main(int argc, char *argv[])
{
    if (argc != 3 && argc != 4) {
        fputs("usage: fmu_importer FMU CLI [TIR]\n", stderr);
        return 2;
    }
    snprintf(cli, sizeof cli, "%s", argv[2]);
    snprintf(dir, sizeof dir, "/tmp/tirenv-fmu-XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    char cmd[2048], path[1200];
    snprintf(cmd, sizeof cmd, "unzip -q '%s' -d '%s'", argv[1], dir);
    if (run(cmd))
        return 1;
    snprintf(path, sizeof path, "%s/modelDescription.xml", dir);
    if (!(xml = slurp(path)))
        return 1;
    attribute(strstr(xml, "<fmiModelDescription"), "guid", guid, sizeof guid);
    VR_X = vr_of("x"), VR_LOAD = vr_of("load"), VR_H = vr_of("h"), VR_SLOPE = vr_of("slope");
    VR_TH = vr_of("terrain_height"), VR_NX = vr_of("terrain_normal.x");
    VR_NY = vr_of("terrain_normal.y"), VR_NZ = vr_of("terrain_normal.z");
    VR_FX = vr_of("fx"), VR_FZ = vr_of("fz"), VR_MODEL = vr_of("model");
    VR_ROAD = vr_of("road_file"), VR_TIRE = vr_of("tire_file");
    snprintf(resources, sizeof resources, "file://%s/resources", dir);
    snprintf(path, sizeof path, "%s/binaries/linux64/tirenv_effective_road.so", dir);
    if (!(api.so = dlopen(path, RTLD_NOW | RTLD_LOCAL))) {
        fprintf(stderr, "fmu_importer: %s\n", dlerror());
        return 1;
    }
    bind(&api);

    /* the cleat of case R, written as a profile file */
    char road[256];
    snprintf(road, sizeof road, "%s/cleat.csv", dir);
    FILE *fp = fopen(road, "w");
    if (!fp)
        return 1;
    fputs("x_m,z_m\n-0.05,0\n-0.05,0.1\n0.05,0.1\n0.05,0\n", fp);
    fclose(fp);

    test_cleat(road);
    test_state_on_cleat(road);
    test_load_changes(road);
    test_state_with_load_changes(road);
    test_errors(road);
    test_cam_keys(road);
    test_cam_max_step(road);
    if (argc > 3)
        test_cam_alone(road, argv[3]);

    dlclose(api.so);
    free(xml);
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    run(cmd);
    return tap_done();
}
