/* The virtual rig: the paper's Figure 2 cart, run on a model instead of a tire. */
#include "tirenv/rig.h"

#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include "tirenv/io.h"

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

int tirenv_rig_simulate(tirenv_model *m, const tirenv_profile *p, const tirenv_rig_settings *s,
                        tirenv_rig_log *out, tirenv_diag *diag)
{
    *out = (tirenv_rig_log){0};
    if (!(s->speed > 0 && s->rate > 0 && s->noise_x >= 0 && s->noise_z >= 0 && s->run_up >= 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "rig",
                            "speed and rate must be positive, noise and run-up not negative");
    /* The whole passage: flat ground, the tire's reach R0, the obstacle, back to flat. */
    double x_first, x_last;
    tirenv_profile_extent(p, &x_first, &x_last);
    const double reach = tirenv_model_tire(m)->springs.R0 + s->run_up;
    const double x0 = x_first - reach, x1 = x_last + reach, dx = s->speed / s->rate;
    const size_t n = (size_t)floor((x1 - x0) / dx) + 1;
    if (n > 100000000)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "rig", "%zu samples is too many", n);
    double *buf = malloc(3 * n * sizeof *buf);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    if (!buf || !rng) {
        free(buf);
        gsl_rng_free(rng);
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "rig", "out of memory");
    }
    gsl_rng_set(rng, s->seed);
    *out = (tirenv_rig_log){n, buf, buf + n, buf + 2 * n};
    for (size_t k = 0; k < n; ++k) {
        const double x = x0 + (double)k * dx;
        tirenv_point pt;
        const int status = tirenv_model_eval(m, x, &pt, diag);
        if (status) {
            tirenv_rig_log_free(out);
            gsl_rng_free(rng);
            return status;
        }
        out->t[k] = (double)k / s->rate;
        out->x[k] = x + s->x_offset + gsl_ran_gaussian_ziggurat(rng, s->noise_x);
        out->z[k] = pt.z + s->z_offset + gsl_ran_gaussian_ziggurat(rng, s->noise_z);
    }
    gsl_rng_free(rng);
    return TIRENV_OK;
}

int tirenv_rig_write_log(const char *path, const tirenv_rig_log *log, const char *comment,
                         tirenv_diag *diag)
{
    tirenv_outfile f;
    int status = tirenv_outfile_open(&f, path, diag);
    if (status)
        return status;
    tirenv_outfile_comment(&f, comment);
    fputs("t_s,x_m,z_m\n", f.fp);
    /* Resolution 1 microsecond and 1 micrometre: more digits would only store noise. */
    for (size_t k = 0; k < log->n; ++k)
        fprintf(f.fp, "%.6f,%.6f,%.6f\n", log->t[k], log->x[k], log->z[k]);
    return tirenv_outfile_commit(&f, diag);
}
