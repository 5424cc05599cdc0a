/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model's stiffnesses identified on a reference's flat ground (docs/models.md
 * section 14.1): at each of the reference's loads the springs model deflects as the reference
 * does and touches as much ground. Used by tirenv identify (src/study/identify.c) and by the
 * models derived from an MF-Tyre file (src/formats/tir_derive.c). */
#include "tirenv/springs.h"

#include <math.h>
#include <stddef.h>
#include "core/golden.h"
#include "model/springs_impl.h"
#include "tirenv/model.h"

enum { MAX_LOADS = 64 };

/* The springs model's load at deflection d (m) per unit c_r and its contact length, with
 * c_b = beta*c_r: both from one force evaluation at the centre height R0 - d
 * (tirenv_model_flat_at_height). The load is proportional to (c_r, c_b) together and the
 * contact length, the length of ground the tread touches (section 1.3), depends on their
 * ratio alone; the solve runs at c_r = 1e6 N/m per rad, inside the plausible range
 * (docs/formats.md section 2), and divides the load by it. */
int tirenv_springs__unit_load(const tirenv_springs_params *par, double beta, size_t n,
                              const double d[], double f[], double l[], tirenv_diag *diag)
{
    tirenv_tire t = tirenv_tire_default();
    const double c_unit = 1e6;
    t.springs = *par;
    t.springs.k_s = t.springs.F_s0 = 0; /* the elements alone */
    t.springs.c_r = c_unit;
    t.springs.c_b = beta * c_unit;
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
    if (!m)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "INTERRADIAL_STIFFNESS",
                            "no springs model with c_r %g N/m per rad and c_b %g N*rad/m",
                            c_unit, beta * c_unit);
    const double R0 = t.springs.R0;
    int status = TIRENV_OK;
    for (size_t i = 0; i < n && !status; i++) {
        tirenv_flat fl;
        if (!(status = tirenv_model_flat_at_height(m, R0 - d[i], &fl, diag))) {
            f[i] = fl.load / c_unit;
            l[i] = fl.contact_length;
        }
    }
    tirenv_model_free(m);
    return status;
}

/* For a ratio beta, the least-squares c_r of log(load) at the reference's deflections (into *c_r
 * unless NULL) and the
 * sum of squared residuals: those of log(load), and those of log(contact length) at the same
 * deflections, which c_r does not change. Both relative, so a per cent of either weighs the
 * same. */
static int residual(const tirenv_springs_params *par, double log_beta, size_t n,
                    const double load[], const double d[], const double l_ref[], double *c_r,
                    double *ss, tirenv_diag *diag)
{
    double f[MAX_LOADS], l[MAX_LOADS], r[MAX_LOADS];
    const int status = tirenv_springs__unit_load(par, exp(log_beta), n, d, f, l, diag);
    if (status)
        return status;
    double mean = 0;
    for (size_t i = 0; i < n; i++)
        mean += (r[i] = log(load[i] / f[i])) / (double)n;
    *ss = 0;
    for (size_t i = 0; i < n; i++) {
        const double r_l = l[i] > 0 ? log(l[i] / l_ref[i]) : INFINITY;
        *ss += (r[i] - mean) * (r[i] - mean) + r_l * r_l;
    }
    if (c_r)
        *c_r = exp(mean);
    return TIRENV_OK;
}

/* Steps of the golden sections (tirenv_core__golden_min): 40 narrow the bracket to 1e-8 of
 * its width, 60 to 1e-12. */
enum { GOLDEN = 40 };

/* residual's sum for the golden section: its first failure kept, after which nothing is
 * evaluated. */
typedef struct {
    const tirenv_springs_params *par;
    size_t n;
    const double *load, *d, *l_ref;
    int status;
    tirenv_diag *diag;
} ratio_ctx;

static double ss_of_ratio(double log_beta, void *p)
{
    ratio_ctx *c = p;
    double ss = 0;
    if (!c->status)
        c->status = residual(c->par, log_beta, c->n, c->load, c->d, c->l_ref, NULL, &ss, c->diag);
    return ss;
}

/* Golden section on log(c_b/c_r) over [1e-6, 10] rad^2: the fit is smooth and one-dimensional
 * once c_r is eliminated; 60 steps narrow the bracket to 1e-12 of its width. c_b/c_r sets how
 * far the interradial springs lift the tread off the ground towards the chord's ends, so the
 * contact length, and with c_r the stiffness. */
int tirenv_springs_identify(tirenv_springs_params *par, size_t n, const double load[],
                            const double deflection[], const double contact_length[],
                            tirenv_diag *diag)
{
    if (n < 2 || n > MAX_LOADS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                            "identification needs 2 to %d loads, got %zu", MAX_LOADS, n);
    for (size_t i = 0; i < n; i++)
        if (!(load[i] > 0 && deflection[i] > 0 && deflection[i] < par->R0 &&
              contact_length[i] > 0 && isfinite(load[i]) && isfinite(contact_length[i])))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                                "target %zu: load %g N, deflection %g m, contact length %g m "
                                "is no flat-ground state of a tire of radius %g m", i + 1,
                                load[i], deflection[i], contact_length[i], par->R0);
    ratio_ctx ctx = {par, n, load, deflection, contact_length, TIRENV_OK, diag};
    const double log_beta =
        tirenv_core__golden_min(ss_of_ratio, &ctx, log(1e-6), log(10.0), 60, NULL);
    double c_r, ss;
    int status = ctx.status;
    if (!status)
        status = residual(par, log_beta, n, load, deflection, contact_length, &c_r, &ss, diag);
    if (status)
        return status;
    par->c_b = c_r * exp(log_beta);
    par->c_r = c_r;
    par->k_s = par->F_s0 = 0;
    return TIRENV_OK;
}

/* ---- With the sidewall in series (docs/models.md sections 4.9 and 14.1) ---- */

/* The elements' flat ground a beta (tirenv_springs__table) at TABLE deflections from 0.3 times
 * the smallest target deflection to 1.5 times the largest. */
enum { TABLE = 48 };

/* One identification's targets and the trial values the nested searches share. */
typedef struct {
    size_t n;
    const double *G, *d, *l;      /* targets: N, m, m */
    const tirenv_springs__table *tb;
    double d_el[MAX_LOADS];       /* the elements' deflection at the trial c_r, m */
    double r_el[MAX_LOADS];       /* log(d_el/d): the residual where the sidewall is rigid */
    double ss_l;                  /* sum of the log contact-length residuals' 8th powers */
    double F_s0;                  /* trial preload, N */
} side_ctx;

/* The residuals weigh by their 8th powers, the L^8 norm of scripts/ring-on-laws.py: near the
 * largest, which is what "one tire within 5 %" asks of a pair (docs/models.md 14), and smooth
 * for the golden sections; least squares left the contact length's largest miss 0.4 % higher
 * on the 205/60R15 for the deflection's mean. */
static double pow8(double r)
{
    const double r2 = r * r, r4 = r2 * r2;
    return r4 * r4;
}

/* Sum of the log-deflection residuals' 8th powers with compliance 1/k_s = c (m/N) and preload
 * F_s0. */
static double ss_compliance(double c, void *p)
{
    const side_ctx *x = p;
    double ss = 0;
    for (size_t i = 0; i < x->n; i++) {
        /* At or below the preload the sidewall is rigid: the residual is r_el's. */
        const double r = x->G[i] > x->F_s0
                             ? log((x->d_el[i] + (x->G[i] - x->F_s0) * c) / x->d[i])
                             : x->r_el[i];
        ss += pow8(r);
    }
    return ss;
}

/* For a preload (N): the best compliance (golden section over [0, 2 d_max/(G_max - F_s0)],
 * a sidewall that alone would deflect twice the largest target at most). */
static double ss_preload(double F_s0, void *p)
{
    side_ctx *x = p;
    x->F_s0 = F_s0;
    double ss;
    const double c_hi = 2 * x->d[x->n - 1] / (x->G[x->n - 1] - F_s0);
    tirenv_core__golden_min(ss_compliance, x, 0, c_hi, GOLDEN, &ss);
    return ss;
}

/* For log c_r: the elements' states at the target loads, then the best sidewall. */
static double ss_log_c_r(double log_c_r, void *p)
{
    side_ctx *x = p;
    const double c_r = exp(log_c_r);
    x->ss_l = 0;
    for (size_t i = 0; i < x->n; i++) {
        double d_e, l_e;
        if (!tirenv_springs__table_at(x->tb, x->G[i] / c_r, &d_e, &l_e))
            return 1e6;
        x->d_el[i] = d_e;
        x->r_el[i] = log(d_e / x->d[i]);  /* ss_compliance's with a rigid sidewall */
        const double r = log(l_e / x->l[i]);
        x->ss_l += pow8(r);
    }
    double ss_d;
    tirenv_core__golden_min(ss_preload, x, 0, x->G[x->n - 1], GOLDEN, &ss_d);
    return ss_d + x->ss_l;
}

/* For log beta: its table, then the best c_r (golden section over the c_r that keep every
 * target load within the table). */
typedef struct {
    const tirenv_springs_params *par;
    side_ctx *x;
    int status;
    tirenv_diag *diag;
    double d_lo, d_hi;
} beta_ctx;

static double ss_log_beta(double log_beta, void *p)
{
    beta_ctx *b = p;
    double store[6 * TABLE];
    tirenv_springs__table tb;
    tirenv_springs__table_init(&tb, store, TABLE);
    if (b->status)
        return 1e6;
    if ((b->status = tirenv_springs__table_of(b->par, exp(log_beta), b->d_lo, b->d_hi, &tb,
                                              b->diag)))
        return 1e6;
    if (tb.n < 2)
        return 1e6;
    side_ctx *x = b->x;
    x->tb = &tb;
    const double lo = log(x->G[x->n - 1]) - tb.log_f[tb.n - 1];
    const double hi = log(x->G[0]) - tb.log_f[0];
    if (!(lo < hi))
        return 1e6;
    double ss;
    tirenv_core__golden_min(ss_log_c_r, x, lo, hi, GOLDEN, &ss);
    x->tb = NULL;
    return ss;
}

int tirenv_springs_identify_sidewall(tirenv_springs_params *par, size_t n, const double load[],
                                     const double deflection[],
                                     const double contact_length[], tirenv_diag *diag)
{
    if (n < 3 || n > MAX_LOADS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                            "identification with the sidewall needs 3 to %d loads, got %zu",
                            MAX_LOADS, n);
    for (size_t i = 0; i < n; i++)
        if (!(load[i] > 0 && deflection[i] > 0 && deflection[i] < par->R0 &&
              contact_length[i] > 0 && isfinite(load[i]) && isfinite(contact_length[i]) &&
              (i == 0 || (load[i] > load[i - 1] && deflection[i] > deflection[i - 1]))))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                                "target %zu: load %g N, deflection %g m, contact length %g m "
                                "is no flat-ground state of a tire of radius %g m after the "
                                "last (loads and deflections ascending)", i + 1, load[i],
                                deflection[i], contact_length[i], par->R0);
    side_ctx x = {.n = n, .G = load, .d = deflection, .l = contact_length};
    beta_ctx b = {par, &x, 0, diag, 0.3 * deflection[0], 1.5 * deflection[n - 1]};
    const double log_beta =
        tirenv_core__golden_min(ss_log_beta, &b, log(1e-4), log(1.0), GOLDEN, NULL);
    if (b.status)
        return b.status;
    /* The minimiser's own values, from its table once more. */
    double store[6 * TABLE];
    tirenv_springs__table tb;
    tirenv_springs__table_init(&tb, store, TABLE);
    int status = tirenv_springs__table_of(par, exp(log_beta), b.d_lo, b.d_hi, &tb, diag);
    if (status)
        return status;
    x.tb = &tb;
    const double lo = log(load[n - 1]) - tb.log_f[tb.n - 1], hi = log(load[0]) - tb.log_f[0];
    const double log_c_r = tirenv_core__golden_min(ss_log_c_r, &x, lo, hi, GOLDEN, NULL);
    ss_log_c_r(log_c_r, &x); /* the elements' states at that c_r */
    const double F_s0 = tirenv_core__golden_min(ss_preload, &x, 0, load[n - 1], GOLDEN, NULL);
    x.F_s0 = F_s0;
    const double c = tirenv_core__golden_min(
        ss_compliance, &x, 0, 2 * deflection[n - 1] / (load[n - 1] - F_s0), GOLDEN, NULL);
    par->c_r = exp(log_c_r);
    par->c_b = par->c_r * exp(log_beta);
    par->k_s = 1 / c;
    par->F_s0 = F_s0;
    return TIRENV_OK;
}
