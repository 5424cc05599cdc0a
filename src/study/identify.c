/* SPDX-License-Identifier: Apache-2.0 */
/* One tire, every model (docs/models.md section 14.1): the springs model's stiffnesses and the
 * cam's vertical and contact-length keys identified on a reference model's flat ground, so
 * that at one load the models of a tire file deflect alike. */
#include "tirenv/study.h"
#include "tirenv/cam.h"
#include "tirenv/springs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/io.h"

enum { MAX_LOADS = 64, MAX_REFS = 4 };

/* The springs model on the reference's deflections and contact lengths
 * (tirenv_springs_identify, src/model/springs_identify.c). */
static int identify_springs(tirenv_tire *t, size_t n, const tirenv_flat_target tg[],
                            tirenv_diag *diag)
{
    double G[MAX_LOADS], d[MAX_LOADS], l[MAX_LOADS];
    for (size_t i = 0; i < n; i++) {
        G[i] = tg[i].load;
        d[i] = tg[i].deflection;
        l[i] = tg[i].contact_length;
    }
    /* A springs model with a sidewall (SIDEWALL_STIFFNESS > 0, docs/models.md section 4.9)
     * has it identified too; without, the paper's model is. */
    return t->springs.k_s > 0 ? tirenv_springs_identify_sidewall(&t->springs, n, G, d, l, diag)
                              : tirenv_springs_identify(&t->springs, n, G, d, l, diag);
}

/* The cam (section 7.3). Without FNOMIN its vertical law is linear, rho = G/VERTICAL_STIFFNESS,
 * and VERTICAL_STIFFNESS is the geometric mean of the reference's load over deflection (least
 * squares in log deflection). With FNOMIN it is MF-Tyre's quadratic
 * G/FNOMIN = Q_FZ1*s + Q_FZ2*s^2 (s = rho/R0), linear in Q_FZ1 and Q_FZ2, fitted in relative
 * load error by the 2x2 normal equations (tirenv_cam_fit_vertical_law); VERTICAL_STIFFNESS is then its tangent at FNOMIN,
 * (FNOMIN/R0)*sqrt(Q_FZ1^2 + 4*Q_FZ2). Then a/R0 = Q_RA2*s^2 + Q_RA1*s with s = sqrt(rho/R0),
 * rho the law's deflection at each load, is linear in the two keys, fitted in relative error
 * of the contact length by the 2x2 normal equations (tirenv_cam_fit_contact_law). */
static int identify_vertical(tirenv_tire *t, size_t n, const tirenv_flat_target tg[],
                             tirenv_diag *diag)
{
    const double R0 = t->springs.R0, F0 = t->cam.fnomin;
    /* PFZ1's pressure factor f scales the whole law (section 7.3): the keys are fitted to the
     * loads over f, and Q_FZ1 is left to VERTICAL_STIFFNESS (0), which the fit sets. */
    const double f = tirenv_cam_pressure_factor(t->cam.pfz1, t->ring.p, t->ring.p_nom);
    if (!(f > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "PFZ1",
                            "the vertical law's pressure factor is %g: positive expected", f);
    t->cam.q_fz1 = 0;
    if (!(F0 > 0)) {
        double mean = 0;
        for (size_t i = 0; i < n; i++)
            mean += log(tg[i].load / tg[i].deflection) / (double)n;
        t->cam.c_z = exp(mean) / f;
        t->cam.q_fz2 = 0;
        return TIRENV_OK;
    }
    double rho[MAX_LOADS], G[MAX_LOADS];
    for (size_t i = 0; i < n; i++) {
        rho[i] = tg[i].deflection;
        G[i] = tg[i].load;
    }
    double q1, q2;
    if (tirenv_cam_fit_vertical_law(R0, f * F0, n, rho, G, &q1, &q2) ||
        !(q1 * q1 + 4 * q2 > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "Q_FZ2",
                            "the loads do not separate the vertical law's two terms (give "
                            "loads further apart)");
    t->cam.c_z = F0 / R0 * sqrt(q1 * q1 + 4 * q2);
    t->cam.q_fz2 = q2;
    return TIRENV_OK;
}

static int identify_cam(tirenv_tire *t, size_t n, const tirenv_flat_target tg[],
                        tirenv_diag *diag)
{
    const double R0 = t->springs.R0;
    int status = identify_vertical(t, n, tg, diag);
    if (!status)
        status = tirenv_tire_check(t, diag); /* model_alloc's NULL would say only "invalid" */
    if (status)
        return status;
    tirenv_model *cam = tirenv_model_alloc(tirenv_model_cam, t);
    if (!cam)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    double rho[MAX_LOADS];
    for (size_t i = 0; i < n && !status; i++) {
        tirenv_flat f;
        status = tirenv_model_flat(cam, tg[i].load, &f, diag);
        rho[i] = f.deflection;
    }
    tirenv_model_free(cam);
    if (status)
        return status;
    double l[MAX_LOADS];
    for (size_t i = 0; i < n; i++)
        l[i] = tg[i].contact_length;
    double q_ra2, q_ra1;
    if (tirenv_cam_fit_contact_law(R0, n, rho, l, &q_ra1, &q_ra2))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "Q_RA1",
                            "the loads do not separate the contact law's two terms (give "
                            "loads further apart)");
    t->cam.q_ra2 = q_ra2;
    t->cam.q_ra1 = q_ra1;
    t->cam.given |= TIRENV_CAM_C_Z | TIRENV_CAM_Q_RA1 | TIRENV_CAM_Q_RA2;
    return TIRENV_OK;
}

/* Each reference's flat ground at the loads: reference j's at tg[j*n + i]. */
static int reference_states(const tirenv_tire *tire, size_t m,
                            const tirenv_model_type *const refs[], size_t n,
                            const double loads[], tirenv_flat_target tg[], tirenv_diag *diag)
{
    int status = TIRENV_OK;
    for (size_t j = 0; j < m && !status; j++) {
        tirenv_model *model = tirenv_model_alloc(refs[j], tire);
        if (!model)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "the tire is not valid for "
                                "the %s model", tirenv_model_type_name(refs[j]));
        for (size_t i = 0; i < n && !status; i++) {
            tirenv_flat f;
            if (!(loads[i] > 0 && isfinite(loads[i])))
                status = tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                                      "load %zu must be a positive force in N, got %g", i + 1,
                                      loads[i]);
            else if (!(status = tirenv_model_flat(model, loads[i], &f, diag)))
                tg[j * n + i] = (tirenv_flat_target){.load = loads[i],
                                                     .deflection = f.deflection,
                                                     .contact_length = f.contact_length};
        }
        tirenv_model_free(model);
    }
    return status;
}

/* The springs model on several references together: min-max (tirenv_springs_identify_minmax,
 * src/model/springs_minmax.c). */
static int identify_springs_minmax(tirenv_tire *t, size_t m, size_t n,
                                   const tirenv_flat_target tg[], tirenv_diag *diag)
{
    double G[MAX_LOADS], d[MAX_REFS * MAX_LOADS], l[MAX_REFS * MAX_LOADS];
    for (size_t i = 0; i < n; i++)
        G[i] = tg[i].load;
    for (size_t k = 0; k < m * n; k++) {
        d[k] = tg[k].deflection;
        l[k] = tg[k].contact_length;
    }
    return tirenv_springs_identify_minmax(&t->springs, n, G, m, d, l, diag);
}

int tirenv_identify_flat_on(const tirenv_tire *tire, size_t m,
                            const tirenv_model_type *const refs[], size_t n,
                            const double loads[], tirenv_tire *out,
                            tirenv_flat_target target[], tirenv_diag *diag)
{
    if (n < 2 || n > MAX_LOADS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                            "identification needs 2 to %d loads, got %zu", MAX_LOADS, n);
    if (m < 1 || m > MAX_REFS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "references",
                            "identification needs 1 to %d reference models, got %zu",
                            MAX_REFS, m);
    int cam_ref = 0;
    for (size_t j = 0; j < m; j++) {
        if (refs[j] == tirenv_model_springs)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "references",
                                "the springs model is identified, not a reference");
        cam_ref |= refs[j] == tirenv_model_cam;
    }
    tirenv_flat_target tg[MAX_REFS * MAX_LOADS];
    int status = reference_states(tire, m, refs, n, loads, tg, diag);
    tirenv_tire t = *tire;
    if (!status)
        status = m == 1 ? identify_springs(&t, n, tg, diag)
                        : identify_springs_minmax(&t, m, n, tg, diag);
    /* A cam that is a reference is the tire's as given; otherwise it is identified on the
     * first reference. */
    if (!status && !cam_ref)
        status = identify_cam(&t, n, tg, diag);
    if (!status && (status = tirenv_tire_check(&t, diag)) == TIRENV_OK) {
        *out = t;
        if (target)
            memcpy(target, tg, m * n * sizeof tg[0]);
    }
    return status;
}

int tirenv_identify_flat(const tirenv_tire *tire, const tirenv_model_type *reference, size_t n,
                         const double loads[], tirenv_tire *out, tirenv_flat_target target[],
                         tirenv_diag *diag)
{
    const tirenv_model_type *const refs[] = {reference};
    return tirenv_identify_flat_on(tire, 1, refs, n, loads, out, target, diag);
}

/* The data set's distinct case loads with their contact lengths, ascending by load, into
 * G[] and l[] (at most cap): *m of them, or TIRENV_EINVAL where one load has two contact
 * lengths or the pairs do not ascend together (no tire's law). */
static int case_knots(const tirenv_dataset *ds, double G[], double l[], size_t cap, size_t *m,
                      tirenv_diag *diag)
{
    size_t k = 0;
    for (size_t i = 0; i < ds->n; i++) {
        const tirenv_case *c = &ds->cases[i];
        if (!(c->load > 0 && c->contact_length > 0))
            continue;
        size_t j = 0;
        while (j < k && G[j] < c->load)
            j++;
        if (j < k && G[j] == c->load) {
            if (l[j] != c->contact_length)
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                                    "case %s: %g m at %g N, where another case has %g m at "
                                    "the same load", c->name, c->contact_length, c->load,
                                    l[j]);
            continue;
        }
        if (k == cap) {
            *m = cap + 1;  /* more than cap: the caller's grid alone */
            return TIRENV_OK;
        }
        memmove(G + j + 1, G + j, (k - j) * sizeof G[0]);
        memmove(l + j + 1, l + j, (k - j) * sizeof l[0]);
        G[j] = c->load;
        l[j] = c->contact_length;
        k++;
    }
    *m = k;
    return TIRENV_OK;
}

/* The geometric grid of a law's loads from lo to hi (N) in n points: load k is
 * lo*exp(k*step), step = log(hi/lo)/(n - 1). */
static double load_grid_step(double lo, double hi, size_t n)
{
    return log(hi / lo) / (double)(n - 1);
}

static double load_grid(double lo, double step, size_t k)
{
    return lo * exp(step * (double)k);
}

/* With a source model, the law's knots are the data set's cases themselves (their loads give
 * back their contact lengths exactly, docs/models.md section 14.3) and, around them, the
 * source model's flat ground on a geometric grid from half the smallest to 1.5 times the
 * largest case load, less the grid points within a third of a grid step of a case (whose
 * round-off difference from the case, 1e-6 m at the embedded data set's loads, would otherwise
 * make a steep, possibly descending, sliver). A data set of more distinct loads than
 * TIRENV_CONTACT_LAW_MAX / 2 has the grid alone. */
int tirenv_contact_law_of_data(const tirenv_dataset *ds, const tirenv_model_type *source,
                               const tirenv_tire *tire, tirenv_contact_law *law, char *what,
                               size_t n, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    double G_min = INFINITY, G_max = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    size_t m = 0;
    for (size_t i = 0; i < ds->n; i++) {
        const tirenv_case *c = &ds->cases[i];
        if (!(c->load > 0 && c->contact_length > 0))
            continue;
        G_min = fmin(G_min, c->load);
        G_max = fmax(G_max, c->load);
        const double x = log(c->load), y = log(c->contact_length);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        m++;
    }
    /* The source model's flat ground gives the relation around a single load; the power law
     * of measured data needs two. */
    if (source ? m < 1 : m < 2 || !(G_max > G_min))
        return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "load",
                            "the data set's cases have %zu positive loads, %s; a relation "
                            "between load and contact length needs %s", m,
                            m ? "all equal" : "none",
                            source ? "one" : "two different ones (measured data: no model "
                                             "that simulated them gives it)");
    const size_t N = TIRENV_CONTACT_LAW_MAX, half = N / 2;
    const double lo = 0.5 * G_min, hi = 1.5 * G_max;
    tirenv_contact_law out = {.n = 0};
    int status = TIRENV_OK;
    if (source) {
        double G_case[TIRENV_CONTACT_LAW_MAX], l_case[TIRENV_CONTACT_LAW_MAX];
        size_t n_case = 0;
        if ((status = case_knots(ds, G_case, l_case, half, &n_case, diag)))
            return status;
        if (n_case > half)
            n_case = 0;
        const size_t n_grid = N - n_case;
        const double step = load_grid_step(lo, hi, n_grid);
        tirenv_model *model = tirenv_model_alloc(source, tire);
        if (!model)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "the tire is not valid for "
                                "the %s model", tirenv_model_type_name(source));
        size_t j = 0;
        for (size_t k = 0; k < n_grid && !status; k++) {
            const double G = load_grid(lo, step, k);
            while (j < n_case && G_case[j] < G) {
                out.load[out.n] = G_case[j];
                out.l_c[out.n++] = l_case[j++];
            }
            const int near_case =
                (j < n_case && log(G_case[j] / G) < step / 3) ||
                (j > 0 && log(G / G_case[j - 1]) < step / 3);
            tirenv_flat f;
            if (near_case)
                continue;
            if (!(status = tirenv_model_flat(model, G, &f, diag))) {
                out.load[out.n] = G;
                out.l_c[out.n++] = f.contact_length;
            }
        }
        while (!status && j < n_case) {
            out.load[out.n] = G_case[j];
            out.l_c[out.n++] = l_case[j++];
        }
        tirenv_model_free(model);
        snprintf(what, n, "the %s model's flat ground%s", tirenv_model_type_name(source),
                 n_case ? " through the cases" : "");
    } else {
        const double b = (m * sxy - sx * sy) / (m * sxx - sx * sx), a = (sy - b * sx) / m;
        const double step = load_grid_step(lo, hi, N);
        out.n = N;
        for (size_t k = 0; k < N; k++) {
            out.load[k] = load_grid(lo, step, k);
            out.l_c[k] = exp(a + b * log(out.load[k]));
        }
        /* A contact length that does not grow with the load is no tire's: cases of several
         * tires (a sweep over tire keys) share contact lengths at different loads. */
        if (!(b > 0) || tirenv_contact_law_check(&out, NULL))
            return tirenv_error(diag, TIRENV_EINVAL, ds->dir, 0, "load",
                                "the power law fitted to the cases' loads and contact lengths, "
                                "l_c = %.4g*G^%.4g, does not grow with the load, which no "
                                "tire's does (cases of several tires, such as a sweep over "
                                "tire keys, share contact lengths at different loads); expected "
                                "the cases of one tire", exp(a), b);
        snprintf(what, n, "the cases: l_c = %.4g*G^%.4f", exp(a), b);
    }
    if (!status && (status = tirenv_contact_law_check(&out, diag)) && source && diag) {
        /* The cases and the source model's flat ground are one tire's only if the tire is the
         * one that simulated the data: another tire's (a --tire of the study) interleaves its
         * contact lengths with the cases', and the law descends. */
        char msg[sizeof diag->message];
        snprintf(msg, sizeof msg, "the %s model of this tire and the data set's cases give no "
                 "one relation between load and contact length (%.300s); expected the tire "
                 "that simulated the data", tirenv_model_type_name(source), diag->message);
        memcpy(diag->message, msg, sizeof msg);
        snprintf(diag->file, sizeof diag->file, "%s", ds->dir);  /* the data set, named */
    }
    if (!status)
        *law = out;
    return status;
}
