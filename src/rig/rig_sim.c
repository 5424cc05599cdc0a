/* SPDX-License-Identifier: Apache-2.0 */
/* The virtual rig: the paper's Figure 2 cart, run on a model instead of a tire. */
#include "tirenv/rig.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include "tirenv/rng.h"
#include "tirenv/outfile.h"
#include "io/io.h"

tirenv_rig_settings tirenv_rig_default(void)
{
    /* 0.1 m/s is quasi-static for a tire (no damping force worth a sample's noise); 100 Hz
     * gives one sample per millimetre; the noise is that of a good draw-wire encoder (x) and a
     * laser distance sensor (z). */
    return (tirenv_rig_settings){.speed = 0.1, .rate = 100, .noise_x = 5e-5, .noise_z = 2e-4,
                                 .x_offset = 0, .z_offset = 0, .run_up = 0.3, .seed = 1};
}

void tirenv_rig_log_free(tirenv_rig_log *log)
{
    if (!log)
        return;
    free(log->t);
    *log = (tirenv_rig_log){0};
}

/* What a log must resolve to be imported (docs/models.md section 5.7). The import smooths
 * with a half-width of at most 5 % of |x_0|, the distance from first contact to the obstacle's
 * centre, and fits a parabola to at least 8 samples of both halves folded in that window: one
 * sample every 2.5 % of |x_0| at the least, MIN_APPROACH_SAMPLES over the approach. |x_0| is
 * at most L/2 + R0 (the free circle's first contact), so a log with fewer samples over
 * L/2 + R0 cannot be imported whatever the load; the import states its own reasons for the
 * rest. The log is written to LOG_RESOLUTION (1 us and 1 um, %.6f): a sampling interval below
 * it repeats times, and an offset at which doubles are spaced wider than half of it cannot
 * carry the differences between samples (--offset 1e300,1e300 wrote every x and z alike). */
enum { MIN_APPROACH_SAMPLES = 40 };
static const double LOG_RESOLUTION = 1e-6; /* s and m */

/* The largest reading of one axis: the passage's own, the offset and six sigmas of noise.
 * Refused naming the setting that makes it large (--noise 1e300,0 was said to be the
 * offset, which was 0). */
static int resolvable(const char *what, double passage, double offset, double sigma,
                      const char *noise_field, tirenv_diag *diag)
{
    const double largest = passage + fabs(offset) + 6 * sigma;
    if (largest * DBL_EPSILON <= 0.5 * LOG_RESOLUTION)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_ERANGE, "", 0, 6 * sigma > fabs(offset) ? noise_field
                                                                            : "offset",
                        "%s readings up to %g m are spaced %g m apart in double precision, "
                        "coarser than the log's resolution of %g m: the samples' differences "
                        "would be lost; expected readings within %g m", what, largest,
                        largest * DBL_EPSILON, LOG_RESOLUTION,
                        0.5 * LOG_RESOLUTION / DBL_EPSILON);
}

static int check_sampling(const tirenv_rig_settings *s, double L, double R0, double x0,
                          double x1, double z_max, tirenv_diag *diag)
{
    const double dx = s->speed / s->rate, approach = 0.5 * L + R0;
    if (!(approach / dx >= MIN_APPROACH_SAMPLES))
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "rig",
                            "a sample every %g m (speed %g m/s at %g Hz) gives %.3g samples "
                            "over the approach to the obstacle's centre, L/2 + R0 = %g m; the "
                            "import needs at least %d there (8 in a smoothing window of at most "
                            "5 %% of it, both halves folded): sample faster or drive slower",
                            dx, s->speed, s->rate, approach / dx, approach,
                            MIN_APPROACH_SAMPLES);
    if (!(1 / s->rate >= LOG_RESOLUTION))
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "rate",
                            "%g Hz samples every %g s, finer than the log's time resolution "
                            "of %g s: times would repeat", s->rate, 1 / s->rate,
                            LOG_RESOLUTION);
    const int status = resolvable("x", fmax(fabs(x0), fabs(x1)), s->x_offset, s->noise_x,
                                  "noise_x", diag);
    return status ? status
                  : resolvable("z", z_max, s->z_offset, s->noise_z, "noise_z", diag);
}

int tirenv_rig_simulate(tirenv_model *m, const tirenv_profile *p, const tirenv_rig_settings *s,
                        tirenv_rig_log *out, tirenv_diag *diag)
{
    *out = (tirenv_rig_log){0};
    if (!m || !p || !s)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "rig",
                            "no model, profile or rig settings given");
    /* Each refusal names its setting and value (one sentence for all of them named none). */
    const struct {
        const char *name;
        double value;
        int ok;
        const char *expected;
    } set[] = {
        {"speed", s->speed, s->speed > 0 && isfinite(s->speed), "a finite speed > 0 m/s"},
        {"rate", s->rate, s->rate > 0 && isfinite(s->rate), "a finite rate > 0 Hz"},
        {"noise_x", s->noise_x, s->noise_x >= 0, "a sigma >= 0 m"},
        {"noise_z", s->noise_z, s->noise_z >= 0, "a sigma >= 0 m"},
        {"run_up", s->run_up, s->run_up >= 0, "a length >= 0 m"},
        {"x_offset", s->x_offset, isfinite(s->x_offset), "a finite offset in m"},
        {"z_offset", s->z_offset, isfinite(s->z_offset), "a finite offset in m"},
    };
    for (size_t i = 0; i < sizeof set / sizeof set[0]; ++i)
        if (!set[i].ok)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, set[i].name,
                                "rig setting %s is %g; expected %s", set[i].name, set[i].value,
                                set[i].expected);
    /* The whole passage: flat ground, the tire's reach R0, the obstacle, back to flat. */
    double x_first, x_last;
    tirenv_profile_extent(p, &x_first, &x_last);
    const double R0 = tirenv_model_tire(m)->springs.R0, reach = R0 + s->run_up;
    const double x0 = x_first - reach, x1 = x_last + reach, dx = s->speed / s->rate;
    double z_max = 0;  /* the centre stays below the highest ground plus R0 */
    for (size_t k = 0; k < tirenv_profile_size(p); ++k)
        z_max = fmax(z_max, fabs(tirenv_profile_z(p)[k]));
    int status = check_sampling(s, x_last - x_first, R0, x0, x1, z_max + R0, diag);
    if (status)
        return status;
    /* Counted as a double first: a speed of 1e-300 m/s made the cast overflow (undefined;
     * it gave one sample and exit 0). */
    const double steps = floor((x1 - x0) / dx);
    if (!(steps < 1e8))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "rig",
                            "%.3g samples (%g m every %g m: speed %g m/s at %g Hz) is too many; "
                            "expected at most 1e8: drive faster or sample slower", steps + 1,
                            x1 - x0, dx, s->speed, s->rate);
    const size_t n = (size_t)steps + 1;
    double *buf = malloc(3 * n * sizeof *buf);
    tirenv_rng *rng = tirenv_rng_alloc(s->seed);
    if (!buf || !rng) {
        free(buf);
        tirenv_rng_free(rng);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "rig", "out of memory");
    }
    *out = (tirenv_rig_log){n, buf, buf + n, buf + 2 * n};
    for (size_t k = 0; k < n; ++k) {
        const double x = x0 + (double)k * dx;
        tirenv_point pt;
        status = tirenv_model_eval(m, x, &pt, diag);
        if (status) {
            tirenv_rig_log_free(out);
            tirenv_rng_free(rng);
            return status;
        }
        out->t[k] = (double)k / s->rate;
        out->x[k] = x + s->x_offset + tirenv_rng_gaussian(rng, s->noise_x);
        out->z[k] = pt.z + s->z_offset + tirenv_rng_gaussian(rng, s->noise_z);
    }
    tirenv_rng_free(rng);
    return TIRENV_OK;
}

int tirenv_rig_write_log(const char *path, const tirenv_rig_log *log, const char *comment,
                         tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    tirenv_outfile *f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    FILE *fp = tirenv_outfile_stream(f);
    fputs("t_s,x_m,z_m\n", fp);
    tirenv_outfile_comment(f, comment);
    /* Resolution 1 microsecond and 1 micrometre: more digits would only store noise. */
    for (size_t k = 0; k < log->n; ++k)
        fprintf(fp, "%.6f,%.6f,%.6f\n", log->t[k], log->x[k], log->z[k]);
    return tirenv_outfile_commit(f, diag);
}
