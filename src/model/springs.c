/* The radial + interradial springs model (docs/models.md section 4, the paper's Figure 4): element
 * layout, stiffness, and the hub forces for a given centre position. */
#include "tirenv/springs.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "model/springs_impl.h"
#include "core/profile_impl.h"

/* Passes of the active-set iteration before giving up; it needs at most n in theory. */
enum { LCP_MAX_PASSES = 200 };

struct tirenv_springs {
    tirenv_springs_params par;
    size_t N;              /* number of elements */
    size_t i0;             /* index of the element at theta = 0 */
    double k_r;            /* radial element stiffness c_r*dphi, N/m */
    double k_ir;           /* interradial element stiffness c_b/dphi, N/m */
    double *theta, *sin_t, *cos_t;  /* element angles, rad */
    double *diag;          /* diagonal of K over all elements, N/m */
    /* Elements outside the candidate span [a, b] have d = 0 and p = 0, so they form free chains
     * whose effect on the span is a Schur complement, precomputed by Gaussian elimination from
     * each end: L_D[j] is the eliminated diagonal of element j with 0..j-1 eliminated, R_D[j]
     * the same from the right. The chains' share of the hub forces is proportional to the end
     * element's deflection: S_lc[a] = sum_{j<a} k_r cos(theta_j) w_j / w_a, and so on. */
    double *L_D, *R_D, *S_lc, *S_ls, *S_rc, *S_rs;
    /* State of the last evaluation: span [a, b] (empty if a > b), per-element arrays. */
    size_t a, b;
    double *d, *drho, *w, *p, *red, *work, *dd;
    unsigned char *active;
};

static void precompute_chains(tirenv_springs *s)
{
    const size_t N = s->N;
    const double kk = s->k_ir * s->k_ir;
    s->L_D[0] = s->diag[0];
    for (size_t j = 1; j < N; ++j)
        s->L_D[j] = s->diag[j] - kk / s->L_D[j - 1];
    s->R_D[N - 1] = s->diag[N - 1];
    for (size_t j = N - 1; j-- > 0;)
        s->R_D[j] = s->diag[j] - kk / s->R_D[j + 1];
    s->S_lc[0] = s->S_ls[0] = 0;
    for (size_t a = 1; a < N; ++a) {
        const double r = s->k_ir / s->L_D[a - 1];
        s->S_lc[a] = r * (s->k_r * s->cos_t[a - 1] + s->S_lc[a - 1]);
        s->S_ls[a] = r * (s->k_r * s->sin_t[a - 1] + s->S_ls[a - 1]);
    }
    s->S_rc[N - 1] = s->S_rs[N - 1] = 0;
    for (size_t b = N - 1; b-- > 0;) {
        const double r = s->k_ir / s->R_D[b + 1];
        s->S_rc[b] = r * (s->k_r * s->cos_t[b + 1] + s->S_rc[b + 1]);
        s->S_rs[b] = r * (s->k_r * s->sin_t[b + 1] + s->S_rs[b + 1]);
    }
}

tirenv_springs *tirenv_springs_alloc(const tirenv_springs_params *par)
{
    tirenv_tire check = tirenv_tire_default();
    check.springs = *par;
    if (tirenv_tire_check(&check, NULL))
        return NULL;
    tirenv_springs *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->par = *par;
    /* Elements at theta_i = i*dphi for every integer i with |theta_i| <= phi/2 (docs/models.md
     * section 4); the relative slack keeps phi/2 itself when it is a multiple of dphi. */
    s->i0 = (size_t)floor(0.5 * par->phi / par->dphi * (1 + 1e-12));
    s->N = 2 * s->i0 + 1;
    s->k_r = par->c_r * par->dphi;
    s->k_ir = par->c_b / par->dphi;
    const size_t N = s->N, n_arrays = 19;
    double *buf = calloc(n_arrays * N, sizeof *buf);
    s->active = calloc(N, 1);
    if (!buf || !s->active) {
        free(buf);
        tirenv_springs_free(s);
        return NULL;
    }
    double **arrays[] = {&s->theta, &s->sin_t, &s->cos_t, &s->diag, &s->L_D, &s->R_D,
                         &s->S_lc, &s->S_ls, &s->S_rc, &s->S_rs, &s->d, &s->drho, &s->w,
                         &s->p, &s->red, &s->dd, &s->work};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; ++k)
        *arrays[k] = buf + k * N;  /* work is last and takes the remaining 3*N */
    for (size_t i = 0; i < N; ++i) {
        s->theta[i] = ((double)i - (double)s->i0) * par->dphi;
        s->sin_t[i] = sin(s->theta[i]);
        s->cos_t[i] = cos(s->theta[i]);
        const double neighbours = (double)((i > 0) + (i + 1 < N));
        s->diag[i] = s->k_r + neighbours * s->k_ir;
    }
    precompute_chains(s);
    s->a = 1;
    s->b = 0;
    return s;
}

void tirenv_springs_free(tirenv_springs *s)
{
    if (!s)
        return;
    free(s->theta);
    free(s->active);
    free(s);
}

const tirenv_springs_params *tirenv_springs_params_of(const tirenv_springs *s)
{
    return &s->par;
}

size_t tirenv_springs_size(const tirenv_springs *s) { return s->N; }
const double *tirenv_springs_theta(const tirenv_springs *s) { return s->theta; }

/* Elements that can touch the ground: a ray reaches no lower than its tip z - R0 cos(theta),
 * so it can only meet ground no higher than z_max = the highest ground within R0 if
 * cos(theta) >= (z - z_max)/R0. One extra element on each side absorbs rounding. */
static int candidate_span(const tirenv_springs *s, const tirenv_profile *prof, double x,
                          double z, size_t *a, size_t *b)
{
    const double R0 = s->par.R0;
    const double gap = z - tirenv_profile_max_height(prof, x - R0, x + R0);
    if (gap >= R0)
        return 0;
    size_t m = s->i0;
    if (gap > 0) {
        const double m_real = acos(gap / R0) / s->par.dphi + 1;
        if (m_real < (double)s->i0)
            m = (size_t)m_real;
    }
    *a = s->i0 - m;
    *b = s->i0 + m;
    return 1;
}

int tirenv_springs_forces(tirenv_springs *s, const tirenv_profile *prof, double x, double z,
                          double *fx, double *fz, double *dfz_dz, size_t *contacts,
                          tirenv_diag *diag)
{
    const double R0 = s->par.R0, k_r = s->k_r, k_ir = s->k_ir;
    size_t a = 1, b = 0;
    const int any = candidate_span(s, prof, x, z, &a, &b);
    /* Elements leaving the span forget their contact state (the warm start). */
    for (size_t i = s->a; i <= s->b && i < s->N; ++i)
        if (!any || i < a || i > b)
            s->active[i] = 0;
    s->a = a;
    s->b = b;
    *fx = *fz = 0;
    if (dfz_dz)
        *dfz_dz = 0;
    if (contacts)
        *contacts = 0;
    if (!any)
        return 0;

    const size_t n = b - a + 1;
    const size_t k_x = tirenv_profile__segment_at(prof, x);
    const double g_x = tirenv_profile_height(prof, x);
    for (size_t i = a; i <= b; ++i) {
        const double rho = tirenv_springs__ray_at(prof, x, k_x, g_x, z, s->sin_t[i],
                                                  s->cos_t[i], R0, &s->drho[i]);
        s->d[i] = rho < R0 ? R0 - rho : 0;
        s->red[i - a] = s->diag[i];
    }
    if (a > 0)
        s->red[0] -= k_ir * k_ir / s->L_D[a - 1];
    if (b + 1 < s->N)
        s->red[n - 1] -= k_ir * k_ir / s->R_D[b + 1];

    size_t passes;
    const int status = tirenv_springs__lcp(n, s->red, k_ir, s->d + a, s->w + a, s->p + a,
                                           s->active + a, s->work, LCP_MAX_PASSES, &passes);
    if (status)
        return tirenv_error(diag, status, "", 0, "springs",
                            "the tip contact of elements %zu to %zu (the LCP) did not settle "
                            "in %d active-set passes at z = %.9g m", a, b, LCP_MAX_PASSES, z);

    /* Eq. 1 and its horizontal counterpart; only the radial springs load the hub. */
    double sum_c = s->w[a] * s->S_lc[a] + s->w[b] * s->S_rc[b];
    double sum_s = s->w[a] * s->S_ls[a] + s->w[b] * s->S_rs[b];
    size_t in_contact = 0;
    for (size_t i = a; i <= b; ++i) {
        sum_c += k_r * s->w[i] * s->cos_t[i];
        sum_s += k_r * s->w[i] * s->sin_t[i];
        in_contact += s->active[i];
    }
    *fz = sum_c;
    *fx = -sum_s;
    if (contacts)
        *contacts = in_contact;
    if (dfz_dz) {
        /* d(d_i)/dz = -d(rho_i)/dz on the active elements; the same factorisation gives dw. */
        double *dd = s->dd + a, *dw = s->red; /* red is free again after the LCP */
        for (size_t i = a; i <= b; ++i)
            dd[i - a] = -s->drho[i];
        tirenv_springs__lcp_tangent(n, k_ir, dd, s->active + a, s->work, dw);
        double sum = dw[0] * s->S_lc[a] + dw[n - 1] * s->S_rc[b];
        for (size_t i = a; i <= b; ++i)
            sum += k_r * dw[i - a] * s->cos_t[i];
        *dfz_dz = sum;
    }
    return 0;
}

void tirenv_springs_tips(const tirenv_springs *s, double d[], double w[], double p[])
{
    const size_t N = s->N, a = s->a, b = s->b;
    const int any = a <= b;
    for (size_t i = 0; i < N; ++i) {
        const int in = any && i >= a && i <= b;
        if (d)
            d[i] = in ? s->d[i] : 0;
        if (p)
            p[i] = in ? s->p[i] : 0;
    }
    if (!w)
        return;
    if (!any) {
        memset(w, 0, N * sizeof *w);
        return;
    }
    memcpy(w + a, s->w + a, (b - a + 1) * sizeof *w);
    for (size_t j = a; j-- > 0;)
        w[j] = s->k_ir / s->L_D[j] * w[j + 1];
    for (size_t j = b + 1; j < N; ++j)
        w[j] = s->k_ir / s->R_D[j] * w[j - 1];
}
