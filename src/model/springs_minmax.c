/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model identified on several references' flat ground together (docs/models.md
 * section 14.1): c_r, c_b and, with a sidewall in series (section 4.9), its preload and
 * stiffness that make the largest relative difference of the deflection and of the contact
 * length from every reference at every load the least. One tire whose springs model is within
 * a few per cent of its ring and of its cam asks exactly that of the pair furthest apart; a sum
 * of squares, or the L^8 norm of tirenv_springs_identify_sidewall, would trade the worst load
 * against the others. Used by tirenv identify --reference ring,cam (src/study/identify.c). */
#include "tirenv/springs.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include "core/golden.h"
#include "model/springs_impl.h"

enum {
    MAX_LOADS = 64,
    MAX_REFS = 4,
    TABLE = 1024, /* the elements' flat ground per beta: deflections 0.26 % apart (205/60R15) */
    SCAN = 97,    /* log beta scanned before its golden section, points 10 % apart */
    SCAN_GOLDEN = 20, /* steps of the scan's inner golden sections: to 7e-5 of the bracket */
    GOLDEN = 40   /* steps of each golden section after it: its bracket to 1e-8 of its width */
};

/* One identification's targets and the trial values the nested searches share. */
typedef struct {
    size_t n, m;                  /* loads, references */
    const double *G;              /* loads, N */
    const double *d, *l;          /* reference j's deflection and contact length (m) at [j*n + i] */
    int sidewall;                 /* whether k_s and F_s0 are identified */
    double d_max;                 /* the largest reference deflection, m */
    int steps;                    /* of the golden sections over c_r, F_s0 and 1/k_s */
    const tirenv_springs__table *tb;
    double d_el[MAX_LOADS];       /* the elements' deflection at the trial c_r, m */
    double F_s0;                  /* trial preload, N */
    double c;                     /* trial compliance, m/N (0: no sidewall) */
} minmax_ctx;

/* The hub's deflection (m) at load i: the elements' plus the sidewall's, compliance c m/N
 * beyond the trial preload. */
static double hub_deflection(const minmax_ctx *x, size_t i, double c)
{
    return x->d_el[i] + (x->G[i] > x->F_s0 ? (x->G[i] - x->F_s0) * c : 0);
}

/* The largest relative difference of the hub's deflection from every reference's. */
static double worst_deflection(const minmax_ctx *x, double c)
{
    double worst = 0;
    for (size_t i = 0; i < x->n; i++)
        for (size_t j = 0; j < x->m; j++)
            worst = fmax(worst, fabs(hub_deflection(x, i, c) / x->d[j * x->n + i] - 1));
    return worst;
}

/* The sum of the 16th powers of those differences: what the sidewall's searches minimise.
 * The largest alone need not fix the sidewall: where it is the smallest load's, below the
 * preload, which the elements alone carry (the 205/60R15's 2 kN), every sidewall that keeps
 * the other loads within it is as good, and the golden sections would stop at any of them
 * (a preload at the smallest load, 2000 N, against the 2703 N shipped). The L^16 norm is near
 * the largest and has one minimum. Convex in c. */
static double ss16_compliance(double c, void *p)
{
    const minmax_ctx *x = p;
    double ss = 0;
    for (size_t i = 0; i < x->n; i++)
        for (size_t j = 0; j < x->m; j++) {
            const double r = hub_deflection(x, i, c) / x->d[j * x->n + i] - 1, r2 = r * r,
                         r4 = r2 * r2, r8 = r4 * r4;
            ss += r8 * r8;
        }
    return ss;
}

/* The compliance bracket at a preload: [0, 2 d_max/(G_max - F_s0)], a sidewall that alone
 * would deflect twice the largest reference deflection at most. */
static double c_max(const minmax_ctx *x)
{
    return 2 * x->d_max / (x->G[x->n - 1] - x->F_s0);
}

/* For a preload (N): the sum at the best compliance. */
static double ss16_preload(double F_s0, void *p)
{
    minmax_ctx *x = p;
    x->F_s0 = F_s0;
    double ss;
    tirenv_core__golden_min(ss16_compliance, x, 0, c_max(x), x->steps, &ss);
    return ss;
}

/* The sidewall that fits the deflection best at the trial c_r (x->d_el): its preload into
 * x->F_s0, its compliance (m/N) returned; none (0) without a sidewall. */
static double best_sidewall(minmax_ctx *x)
{
    if (!x->sidewall) {
        x->F_s0 = 0;
        return 0;
    }
    x->F_s0 = tirenv_core__golden_min(ss16_preload, x, 0, x->G[x->n - 1], x->steps, NULL);
    return tirenv_core__golden_min(ss16_compliance, x, 0, c_max(x), x->steps, NULL);
}

/* For log c_r: the elements' states at the loads, their contact lengths' largest difference
 * (which no sidewall changes), and the deflection's with the sidewall that fits it best (into
 * x->F_s0 and x->c): the larger of the two. */
static double worst_log_c_r(double log_c_r, void *p)
{
    minmax_ctx *x = p;
    const double c_r = exp(log_c_r);
    double worst_l = 0;
    for (size_t i = 0; i < x->n; i++) {
        double d_e, l_e;
        if (!tirenv_springs__table_at(x->tb, x->G[i] / c_r, &d_e, &l_e))
            return INFINITY;
        x->d_el[i] = d_e;
        for (size_t j = 0; j < x->m; j++)
            worst_l = fmax(worst_l, fabs(l_e / x->l[j * x->n + i] - 1));
    }
    x->c = best_sidewall(x);
    return fmax(worst_deflection(x, x->c), worst_l);
}

/* The c_r that keep every load within the table: [*lo, *hi] in log c_r; 0 if none. */
static int c_r_range(const minmax_ctx *x, const tirenv_springs__table *tb, double *lo, double *hi)
{
    if (tb->n < 2)
        return 0;
    *lo = log(x->G[x->n - 1]) - tb->log_f[tb->n - 1];
    *hi = log(x->G[0]) - tb->log_f[0];
    return *lo < *hi;
}

/* For log beta: its table, then the best c_r by golden section. */
typedef struct {
    const tirenv_springs_params *par;
    minmax_ctx *x;
    tirenv_springs__table *tb;
    double d_lo, d_hi;            /* the table's deflections, m */
    int status;
    tirenv_diag *diag;
    double log_c_r;               /* the best c_r at the last beta tried */
} beta_ctx;

static double worst_log_beta(double log_beta, void *p)
{
    beta_ctx *b = p;
    double lo, hi;
    if (b->status)
        return INFINITY;
    if ((b->status = tirenv_springs__table_of(b->par, exp(log_beta), b->d_lo, b->d_hi, b->tb,
                                              b->diag)))
        return INFINITY;
    if (!c_r_range(b->x, b->tb, &lo, &hi))
        return INFINITY;
    b->x->tb = b->tb;
    double worst;
    b->log_c_r = tirenv_core__golden_min(worst_log_c_r, b->x, lo, hi, b->x->steps, &worst);
    b->x->tb = NULL;
    return worst;
}

/* The error where no c_b/c_r and c_r keep every load within the table. */
static int no_model(const beta_ctx *b)
{
    const double *const load = b->x->G;
    return tirenv_error(b->diag, TIRENV_EINVAL, "", 0, "loads",
                        "no springs model carries the loads %g to %g N within the "
                        "deflections %g to %g m", load[0], load[b->x->n - 1], b->d_lo, b->d_hi);
}

/* The search itself (tirenv_springs_identify_minmax's, below), on b's table. */
static int search(tirenv_springs_params *par, beta_ctx *b)
{
    minmax_ctx *const x = b->x;
    const double a = log(1e-4), step = (log(1.0) - a) / (SCAN - 1);
    size_t k_best = 0;
    double best = INFINITY;
    x->steps = SCAN_GOLDEN;
    for (size_t k = 0; k < SCAN; k++) {
        const double worst = worst_log_beta(a + step * (double)k, b);
        if (b->status)
            return b->status;
        if (worst < best)
            best = worst, k_best = k;
    }
    if (!isfinite(best))
        return no_model(b);
    x->steps = GOLDEN;
    const double log_beta = tirenv_core__golden_min(
        worst_log_beta, b, a + step * ((double)k_best - 1), a + step * ((double)k_best + 1),
        GOLDEN, NULL);
    if (b->status)
        return b->status;
    /* The minimiser's own values: its table and best c_r once more, then the elements' states
     * and the sidewall at that c_r. */
    const double worst = worst_log_beta(log_beta, b);
    if (b->status)
        return b->status;
    if (!isfinite(worst))
        return no_model(b);
    x->tb = b->tb;
    const double log_c_r = b->log_c_r;
    worst_log_c_r(log_c_r, x);
    par->c_r = exp(log_c_r);
    par->c_b = par->c_r * exp(log_beta);
    par->k_s = x->sidewall ? 1 / x->c : 0;
    par->F_s0 = x->F_s0;
    return TIRENV_OK;
}

/* c_b/c_r (beta) is scanned at SCAN points spaced geometrically over [1e-4, 1] rad^2, and the
 * golden section runs between the best one's neighbours: the largest difference is not
 * unimodal in it. On a springs model's own flat ground it falls to 0 within 5 % of the true
 * ratio beside a shelf near 1.6 % with a dip of its own, where 25 points 47 % apart stopped
 * (tests/model/test_springs_minmax.c); it also has kinks where another load or reference
 * becomes the worst. The scan's inner searches take SCAN_GOLDEN steps, enough to rank the
 * points, the rest GOLDEN. Inside, golden sections nest over log c_r and the sidewall's F_s0
 * and 1/k_s as in tirenv_springs_identify_sidewall; the innermost objective is convex. No
 * other optimiser is needed: each level is one-dimensional. */
int tirenv_springs_identify_minmax(tirenv_springs_params *par, size_t n, const double load[],
                                   size_t m, const double deflection[],
                                   const double contact_length[], tirenv_diag *diag)
{
    const int sidewall = par->k_s > 0;
    const size_t n_min = sidewall ? 3 : 2;
    if (n < n_min || n > MAX_LOADS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                            "identification %s needs %zu to %d loads, got %zu",
                            sidewall ? "with the sidewall" : "of the springs model", n_min,
                            MAX_LOADS, n);
    if (m < 1 || m > MAX_REFS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "references",
                            "identification needs 1 to %d references, got %zu", MAX_REFS, m);
    double d_min = INFINITY, d_max = 0;
    for (size_t j = 0; j < m; j++)
        for (size_t i = 0; i < n; i++) {
            const double G = load[i], d = deflection[j * n + i], l = contact_length[j * n + i];
            if (!(G > 0 && d > 0 && d < par->R0 && l > 0 && isfinite(G) && isfinite(l) &&
                  (i == 0 || (G > load[i - 1] && d > deflection[j * n + i - 1]))))
                return tirenv_error(diag, TIRENV_EINVAL, "", 0, "loads",
                                    "reference %zu, target %zu: load %g N, deflection %g m, "
                                    "contact length %g m is no flat-ground state of a tire of "
                                    "radius %g m after the last (loads and deflections "
                                    "ascending)", j + 1, i + 1, G, d, l, par->R0);
            d_min = fmin(d_min, d);
            d_max = fmax(d_max, d);
        }
    double *store = malloc(6 * TABLE * sizeof *store);
    if (!store)
        return tirenv_error(diag, TIRENV_ENOMEM, "", 0, "", "out of memory");
    tirenv_springs__table table;
    tirenv_springs__table_init(&table, store, TABLE);
    minmax_ctx x = {.n = n, .m = m, .G = load, .d = deflection, .l = contact_length,
                    .sidewall = sidewall, .d_max = d_max};
    beta_ctx b = {par, &x, &table, 0.3 * d_min, 1.5 * d_max, TIRENV_OK, diag, 0};
    const int status = search(par, &b);
    free(store);
    return status;
}
