/* The flexible-ring reference tire (docs/models.md section 5): a belt on an elastic foundation with
 * a tread of radial brush springs, in contact with the ground along rays from the centre. */
#include "tirenv/ring.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include "model/springs_impl.h"
#include "core/profile_impl.h"

/* Passes of the active-set iteration before giving up; it typically needs 2 to 4. */
enum { RING_MAX_PASSES = 100 };

struct tirenv_ring {
    double R0;             /* free radius at the tread surface, m */
    double R;              /* belt radius R0 - t_r, m */
    tirenv_ring_params par;
    size_t M;              /* nodes around the circle */
    size_t i0;             /* node at theta = 0 */
    double dth;            /* node spacing 2*pi/M, rad */
    double *theta, *sin_t, *cos_t;
    double *c;             /* circulant compliance: w_j = sum_k c[|j-k| mod M] f_k, m/N */
    /* The last evaluation: candidate nodes (rays that meet the ground within reach), in
     * ascending node order, and the active ones among them (positive tread force). */
    size_t nc, na;
    size_t *node;          /* node index of candidate k */
    double *d;             /* R0 - rho: tread compression if the belt did not move, m */
    double *drho;          /* d(rho)/dz, 1 */
    double *X;             /* ground point abscissa x + rho sin(theta), m */
    double *kappa;         /* tread stiffness of the node, k_t*R*dtheta, N/m */
    double *gap;           /* d - w: positive where the tread is compressed, m */
    unsigned char *act;    /* per candidate: active */
    unsigned char *warm;   /* per node: active at the last evaluation */
    size_t *ai;            /* candidate index of active a */
    double *S, *f, *rhs;   /* contact system (na x na), tread forces (N), right-hand side */
    double patch;          /* contact length of the last evaluation, m */
};

/* Fourier symbol of the belt per node: for w_j = cos(n theta_j) the energy per unit length
 * 1/2 EI ((w''+w)/R^2)^2 + 1/2 (T/R^2)(w'^2 - w^2) + 1/2 k_f w^2, with w'' the second and w'
 * the forward difference (both give sigma = (2 sin(n dtheta/2)/dtheta)^2 for n^2), times the
 * arc R dtheta of a node. Rigid translations (n = 1, sigma ~ 1) cost only the foundation. */
static double mode_stiffness(const tirenv_ring *r, size_t n)
{
    const double s = 2 * sin(M_PI * (double)n / (double)r->M) / r->dth;
    const double sigma = s * s, R = r->R;
    const double e = r->par.EI * (sigma - 1) * (sigma - 1) / (R * R * R * R) +
                     r->par.T * (sigma - 1) / (R * R) + r->par.k_f;
    return R * r->dth * e;
}

/* The belt's stiffness matrix is circulant (a uniform ring), so its inverse is too: one
 * column, the inverse discrete cosine transform of 1/lambda_n, once per tire. */
static int compute_compliance(tirenv_ring *r)
{
    const size_t M = r->M;
    double *inv_lambda = malloc(M * sizeof *inv_lambda), *cos_tab = malloc(M * sizeof *cos_tab);
    int ok = inv_lambda && cos_tab;
    for (size_t n = 0; ok && n < M; ++n) {
        const double lambda = mode_stiffness(r, n);
        ok = lambda > 0; /* otherwise the pretension buckles the belt */
        inv_lambda[n] = 1 / lambda;
        cos_tab[n] = cos(2 * M_PI * (double)n / (double)M);
    }
    for (size_t m = 0; ok && m < M; ++m) {
        double sum = 0;
        for (size_t n = 0; n < M; ++n)
            sum += cos_tab[(n * m) % M] * inv_lambda[n];
        r->c[m] = sum / (double)M;
    }
    free(inv_lambda);
    free(cos_tab);
    return ok;
}

tirenv_ring *tirenv_ring_alloc(double R0, const tirenv_ring_params *par)
{
    tirenv_tire check = tirenv_tire_default();
    check.springs.R0 = R0;
    check.ring = *par;
    if (tirenv_tire_check(&check, NULL))
        return NULL;
    tirenv_ring *r = calloc(1, sizeof *r);
    if (!r)
        return NULL;
    r->R0 = R0;
    r->R = R0 - par->t_r;
    r->par = *par;
    r->M = 2 * (size_t)round(M_PI / par->dtheta);
    r->i0 = r->M / 2;
    r->dth = 2 * M_PI / (double)r->M;
    const size_t M = r->M;
    r->theta = malloc(10 * M * sizeof(double));
    r->node = malloc(2 * M * sizeof(size_t));
    r->act = calloc(2 * M, 1);
    /* The contact system is at most the lower half of the nodes square. */
    r->S = malloc((M / 2 + 1) * (M / 2 + 1) * sizeof(double));
    if (!r->theta || !r->node || !r->act || !r->S) {
        tirenv_ring_free(r);
        return NULL;
    }
    double **arrays[] = {&r->sin_t, &r->cos_t, &r->c, &r->d, &r->drho, &r->X, &r->kappa,
                         &r->gap, &r->f};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; ++k)
        *arrays[k] = r->theta + (k + 1) * M;
    r->rhs = malloc(M * sizeof(double));
    r->ai = r->node + M;
    r->warm = r->act + M;
    if (!r->rhs) {
        tirenv_ring_free(r);
        return NULL;
    }
    for (size_t j = 0; j < M; ++j) {
        r->theta[j] = ((double)j - (double)r->i0) * r->dth;
        r->sin_t[j] = sin(r->theta[j]);
        r->cos_t[j] = cos(r->theta[j]);
    }
    if (!compute_compliance(r)) {
        tirenv_ring_free(r);
        return NULL;
    }
    return r;
}

void tirenv_ring_free(tirenv_ring *r)
{
    if (!r)
        return;
    free(r->theta);
    free(r->node);
    free(r->act);
    free(r->S);
    free(r->rhs);
    free(r);
}

double tirenv_ring_free_radius(const tirenv_ring *r) { return r->R0; }
size_t tirenv_ring_size(const tirenv_ring *r) { return r->M; }
const double *tirenv_ring_theta(const tirenv_ring *r) { return r->theta; }
double tirenv_ring_patch_length(const tirenv_ring *r) { return r->patch; }

static double compliance(const tirenv_ring *r, size_t j, size_t k)
{
    return r->c[j > k ? j - k : k - j];  /* c is even: c[m] = c[M - m] */
}

/* Tread stiffness per node: lugs move with the tread, which turns by x/R0 as the tire rolls
 * forward, so the node at theta sees the tread point that was at theta + x/R0 at x = 0. */
static double tread_kappa(const tirenv_ring *r, double theta, double x)
{
    const tirenv_ring_params *p = &r->par;
    double k_t = p->k_t;
    if (p->lug_count > 0) {
        const double u = (theta + x / r->R0) * p->lug_count / (2 * M_PI);
        if (u - floor(u) >= p->lug_fraction)
            k_t *= p->lug_ratio;
    }
    return k_t * r->R * r->dth;
}

/* Rays of the lower half that reach the ground within R0 + t_r: the belt bulges outward away
 * from the patch (w < 0), so a ray a little longer than R0 may still touch; the tread
 * thickness bounds the bulge we allow for. */
static void cast_candidates(tirenv_ring *r, const tirenv_profile *p, double x, double z)
{
    const double reach = r->R0 + r->par.t_r;
    const double gap = z - tirenv_profile_max_height(p, x - reach, x + reach);
    r->nc = 0;
    if (gap >= reach)
        return;
    size_t m = r->M / 4; /* up to the horizontal */
    if (gap > 0)
        m = (size_t)fmin((double)m, acos(gap / reach) / r->dth + 1);
    /* What every ray needs of x, found once (the same bits as tirenv_springs__ray). */
    const size_t k_x = tirenv_profile__segment_at(p, x);
    const double g_x = tirenv_profile_height(p, x);
    for (size_t j = r->i0 - m; j <= r->i0 + m; ++j) {
        if (r->cos_t[j] < 0)
            continue;
        double drho;
        const double rho = tirenv_springs__ray_at(p, x, k_x, g_x, z, r->sin_t[j], r->cos_t[j],
                                                  reach, &drho);
        if (!isfinite(rho))
            continue;
        const size_t k = r->nc++;
        r->node[k] = j;
        r->d[k] = r->R0 - rho;
        r->drho[k] = drho;
        r->X[k] = x + rho * r->sin_t[j];
        r->kappa[k] = tread_kappa(r, r->theta[j], x);
    }
}

/* A Cholesky breakdown is its own failure, not a slow convergence: the active-set matrix
 * C_AA + diag(1/kappa_A) is symmetric positive definite in exact arithmetic, so a breakdown
 * means the belt's compliance is numerically singular (a far too stiff or too soft tire). */
static int cholesky_failed(tirenv_diag *diag, size_t na)
{
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                        "Cholesky factorisation of the %zu x %zu tread-contact matrix broke "
                        "down (not numerically positive definite)", na, na);
}

/* With the active set fixed the tread forces f_A solve (C_AA + diag(1/kappa_A)) f_A = d_A: the
 * belt moves by C f and each compressed tread spring carries kappa (d - w). The matrix is SPD
 * (C is), so Cholesky; its factor stays in S for the derivative. */
static int solve_active(tirenv_ring *r, tirenv_diag *diag)
{
    const size_t na = r->na;
    if (na == 0)
        return 0;
    for (size_t a = 0; a < na; ++a) {
        const size_t ka = r->ai[a];
        for (size_t b = 0; b <= a; ++b)
            r->S[a * na + b] = r->S[b * na + a] = compliance(r, r->node[ka], r->node[r->ai[b]]);
        r->S[a * na + a] += 1 / r->kappa[ka];
        r->f[a] = r->d[ka];
    }
    gsl_matrix_view S = gsl_matrix_view_array(r->S, na, na);
    gsl_vector_view f = gsl_vector_view_array(r->f, na);
    if (gsl_linalg_cholesky_decomp1(&S.matrix) || gsl_linalg_cholesky_svx(&S.matrix, &f.vector))
        return cholesky_failed(diag, na);
    return 0;
}

/* Semi-smooth Newton (primal-dual active set) on f = kappa (d - C f)_+: solve with the set
 * fixed, then take as active every node whose tread would be compressed. */
static int solve_contact(tirenv_ring *r, tirenv_diag *diag)
{
    for (size_t k = 0; k < r->nc; ++k)
        r->act[k] = r->d[k] > 0 || r->warm[r->node[k]];
    for (size_t pass = 0; pass < RING_MAX_PASSES; ++pass) {
        r->na = 0;
        for (size_t k = 0; k < r->nc; ++k)
            if (r->act[k])
                r->ai[r->na++] = k;
        const int status = solve_active(r, diag);
        if (status)
            return status;
        int changed = 0;
        for (size_t k = 0, a = 0; k < r->nc; ++k) {
            double w = 0;
            for (size_t b = 0; b < r->na; ++b)
                w += compliance(r, r->node[k], r->node[r->ai[b]]) * r->f[b];
            r->gap[k] = r->d[k] - w;
            /* On the active set gap = f/kappa exactly; use f there to avoid round-off. */
            const int is_active = a < r->na && r->ai[a] == k;
            const unsigned char now = is_active ? r->f[a++] > 0 : r->gap[k] > 0;
            changed |= now != r->act[k];
            r->act[k] = now;
        }
        if (!changed)
            return 0;
    }
    return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "ring",
                        "the tread contact's active set did not settle in %d passes",
                        RING_MAX_PASSES);
}

/* Contact length: first to last active ground point, each edge extended to where the
 * interpolated gap between the edge node and its inactive neighbour crosses zero. */
static double patch_length(const tirenv_ring *r)
{
    if (r->na == 0)
        return 0;
    const size_t k1 = r->ai[0], k2 = r->ai[r->na - 1];
    double len = r->X[k2] - r->X[k1];
    if (k1 > 0 && r->node[k1 - 1] + 1 == r->node[k1])
        len += r->gap[k1] / (r->gap[k1] - r->gap[k1 - 1]) * (r->X[k1] - r->X[k1 - 1]);
    if (k2 + 1 < r->nc && r->node[k2 + 1] == r->node[k2] + 1)
        len += r->gap[k2] / (r->gap[k2] - r->gap[k2 + 1]) * (r->X[k2 + 1] - r->X[k2]);
    return len;
}

int tirenv_ring_forces(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                       double *fx, double *fz, double *dfz_dz, size_t *contacts,
                       tirenv_diag *diag)
{
    cast_candidates(r, p, x, z);
    const int status = solve_contact(r, diag);
    memset(r->warm, 0, r->M);
    if (status)
        return status;
    double sum_c = 0, sum_s = 0;
    for (size_t a = 0; a < r->na; ++a) {
        const size_t j = r->node[r->ai[a]];
        r->warm[j] = 1;
        sum_c += r->f[a] * r->cos_t[j];
        sum_s += r->f[a] * r->sin_t[j];
    }
    *fz = sum_c;
    *fx = -sum_s;
    if (contacts)
        *contacts = r->na;
    r->patch = patch_length(r);
    if (dfz_dz) {
        /* d(d)/dz = -d(rho)/dz on the active nodes, through the same Cholesky factor. */
        *dfz_dz = 0;
        if (r->na > 0) {
            for (size_t a = 0; a < r->na; ++a)
                r->rhs[a] = -r->drho[r->ai[a]];
            gsl_matrix_view S = gsl_matrix_view_array(r->S, r->na, r->na);
            gsl_vector_view v = gsl_vector_view_array(r->rhs, r->na);
            if (gsl_linalg_cholesky_svx(&S.matrix, &v.vector))
                return cholesky_failed(diag, r->na);
            for (size_t a = 0; a < r->na; ++a)
                *dfz_dz += r->rhs[a] * r->cos_t[r->node[r->ai[a]]];
        }
    }
    return 0;
}

void tirenv_ring_state(const tirenv_ring *r, double w[], double f[])
{
    for (size_t j = 0; j < r->M; ++j) {
        if (w) {
            w[j] = 0;
            for (size_t a = 0; a < r->na; ++a)
                w[j] += compliance(r, j, r->node[r->ai[a]]) * r->f[a];
        }
        if (f)
            f[j] = 0;
    }
    if (f)
        for (size_t a = 0; a < r->na; ++a)
            f[r->node[r->ai[a]]] = r->f[a];
}
