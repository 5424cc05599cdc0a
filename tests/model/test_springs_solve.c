/* The springs model's fast paths against the plain ones they replace (docs/models.md
 * section 4): the pinned-chain tip solve against the Thomas active-set solve, the fan of rays
 * (each walk resuming the last) and its reuse across centre heights against one ray at a time,
 * the held rays' faces taken in runs against one ray a call, a workspace's kept state against
 * a fresh workspace, and ground narrower than the rays.
 * SPDX-License-Identifier: Apache-2.0
 *
 * The rays are exact claims (the same operations on the same points, so the same bits); the
 * tip solve is a different formula for the same linear system, so it agrees to round-off: the
 * closed form's factors are table entries accurate to an ulp or two, and exp(-k mu) carries
 * mu's rounding times k, at most ~N eps relative where its weight is e^{-k mu}; in absolute
 * terms every w is within a few hundred eps of max d (the bound used below is 1e-12 max d,
 * ~4500 eps, for up to 721 elements). */
#include "testutil.h"

#include "tirenv/rng.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/profile.h"
#include "tirenv/model.h"
#include "tirenv/road.h"
#include "tirenv/springs.h"
#include "tirenv/tire.h"
#include "model/springs_impl.h"
#include "profile/profile_impl.h"

/* ---- The tip LCP ---- */

typedef struct {
    size_t N;
    double *diag, *L_D, *R_D, *lq, *rq, *ce, *cm, *cmi, *w_buf;
    tirenv_springs__chains c;
} chain_set;

/* The tables as springs.c builds them, for N elements with k_r, k_ir. */
static void chain_set_init(chain_set *cs, size_t N, double k_r, double k_ir)
{
    cs->N = N;
    double **arrays[] = {&cs->diag, &cs->L_D, &cs->R_D, &cs->lq, &cs->rq};
    for (size_t k = 0; k < 5; ++k)
        assert_non_null(*arrays[k] = malloc(N * sizeof(double)));
    double **tables[] = {&cs->ce, &cs->cm, &cs->cmi, &cs->w_buf};
    for (size_t k = 0; k < 4; ++k)
        assert_non_null(*tables[k] = malloc((N + 2) * sizeof(double)));
    for (size_t i = 0; i < N; ++i)
        cs->diag[i] = k_r + (double)((i > 0) + (i + 1 < N)) * k_ir;
    cs->L_D[0] = cs->diag[0];
    for (size_t j = 1; j < N; ++j)
        cs->L_D[j] = cs->diag[j] - k_ir * k_ir / cs->L_D[j - 1];
    cs->R_D[N - 1] = cs->diag[N - 1];
    for (size_t j = N - 1; j-- > 0;)
        cs->R_D[j] = cs->diag[j] - k_ir * k_ir / cs->R_D[j + 1];
    for (size_t j = 0; j < N; ++j) {
        cs->lq[j] = k_ir / cs->L_D[j];
        cs->rq[j] = k_ir / cs->R_D[j];
    }
    tirenv_springs__chain_tables(N, k_r, k_ir, cs->ce, cs->cm, cs->cmi);
    cs->c = (tirenv_springs__chains){.N = N, .k_ir = k_ir, .diag = cs->diag, .lq = cs->lq,
                                     .rq = cs->rq, .ce = cs->ce, .cm = cs->cm, .cmi = cs->cmi};
}

static void chain_set_free(chain_set *cs)
{
    double *arrays[] = {cs->diag, cs->L_D, cs->R_D, cs->lq, cs->rq,
                        cs->ce, cs->cm, cs->cmi, cs->w_buf};
    for (size_t k = 0; k < 9; ++k)
        free(arrays[k]);
}

/* Random obstacles d >= 0 with support in [f0, f1] on random tires (stiffness ratios from
 * 1e-6 to 1e4, interradial stiffness 0 included), solved over the whole tire by the Thomas
 * active-set method and over [f0, f1] by the pinned chains: the same active set, the same w
 * to round-off, and the LCP's conditions on the full-length w. */
static void test_pinned_matches_thomas(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 20261202);
    enum { N_MAX = 721 };
    static double d[N_MAX], w_ref[N_MAX], p_ref[N_MAX], work[2 * N_MAX], p[N_MAX], w_full[N_MAX];
    static unsigned char act_ref[N_MAX], act[N_MAX];
    static size_t gap[2 * N_MAX];
    size_t trials = 0, nontrivial = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const size_t N = 3 + tirenv_rng_uniform_int(rng, N_MAX - 2);
        const double k_r = pow(10, 2 + 5 * tirenv_rng_uniform(rng));
        const double k_ir = trial % 9 == 0 ? 0 : k_r * pow(10, -4 + 8 * tirenv_rng_uniform(rng));
        chain_set cs;
        chain_set_init(&cs, N, k_r, k_ir);
        double *w = cs.w_buf + 1;
        size_t f0 = tirenv_rng_uniform_int(rng, N), f1 = tirenv_rng_uniform_int(rng, N);
        if (f0 > f1) {
            const size_t t = f0;
            f0 = f1;
            f1 = t;
        }
        /* A bump (a tire over a cleat or on the ground) plus noise, zero in places. */
        const double c = 0.5 * (double)(f0 + f1), hw = 0.5 * (double)(f1 - f0) + 1;
        double d_max = 0;
        memset(d, 0, N * sizeof *d);
        for (size_t i = f0; i <= f1; ++i) {
            const double u = ((double)i - c) / hw;
            d[i] = fmax(0, 0.03 * (1 - u * u) + 0.01 * (tirenv_rng_uniform(rng) - 0.3));
            if (tirenv_rng_uniform(rng) < 0.1)
                d[i] = 0;
            d_max = fmax(d_max, d[i]);
        }
        d[f0] = fmax(d[f0], 1e-4);
        d[f1] = fmax(d[f1], 1e-4);
        memset(act_ref, 0, N);
        size_t passes;
        assert_int_equal(tirenv_springs__lcp(N, cs.diag, k_ir, d, w_ref, p_ref, act_ref, work,
                                             1000, &passes),
                         TIRENV_OK);
        /* A random warm start, as a sweep leaves it. */
        for (size_t i = f0; i <= f1; ++i)
            act[i] = tirenv_rng_uniform(rng) < 0.5;
        tirenv_springs__pins P = {.gap = gap};
        assert_int_equal(tirenv_springs__lcp_pinned(&cs.c, f0, f1, d, w, p, act, &P, 1000,
                                                    &passes),
                         TIRENV_OK);
        const double tol = 1e-12 * d_max;
        size_t count = 0;
        for (size_t i = f0; i <= f1; ++i) {
            assert_int_equal(act[i], act_ref[i]);
            assert_near(w[i], w_ref[i], tol, 0);
            count += act[i];
        }
        assert_int_equal(P.count, count);
        for (size_t i = 0; i < N; ++i)
            if (i < f0 || i > f1)
                assert_int_equal(act_ref[i], 0);
        /* The full-length tire: free chains beyond [f0, f1]. */
        for (size_t i = f0; i <= f1; ++i)
            w_full[i] = w[i];
        for (size_t j = f0; j-- > 0;)
            w_full[j] = cs.lq[j] * w_full[j + 1];
        for (size_t j = f1 + 1; j < N; ++j)
            w_full[j] = cs.rq[j] * w_full[j - 1];
        for (size_t i = 0; i < N; ++i) {
            const double w_l = i > 0 ? w_full[i - 1] : 0, w_r = i + 1 < N ? w_full[i + 1] : 0;
            const double r = cs.diag[i] * w_full[i] - k_ir * (w_l + w_r);
            const double scale = (cs.diag[i] + 2 * k_ir) * d_max;
            assert_true(w_full[i] >= d[i] - tol);
            if (act[i] && i >= f0 && i <= f1) {
                assert_true(r >= -1e-12 * scale);
                assert_near(p[i], r, 1e-12 * scale, 0);
            } else {
                assert_near(r, 0, 1e-12 * scale, 0); /* free: no reaction */
            }
        }
        nontrivial += count > 0 && count < f1 - f0 + 1;
        ++trials;
        chain_set_free(&cs);
    }
    assert_true(nontrivial > 100); /* the guard: chains between pins really ran */
    tirenv_rng_free(rng);
}

/* ---- Rays ---- */

/* A random ground: a polyline with walls (two vertices at one x), spikes and flat runs. */
static tirenv_profile *random_ground(tirenv_rng *rng, size_t n)
{
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    double X = -1.5;
    for (size_t k = 0; k < n; ++k) {
        const double r = tirenv_rng_uniform(rng);
        if (k > 0 && r < 0.15 && !(k >= 2 && x[k - 2] == X))
            x[k] = X; /* a wall */
        else
            x[k] = X += 0.002 + 0.05 * tirenv_rng_uniform(rng) * tirenv_rng_uniform(rng);
        z[k] = r < 0.5 ? 0.08 * tirenv_rng_uniform(rng) : k > 0 ? z[k - 1] : 0;
    }
    tirenv_profile *p = tirenv_profile_alloc(n, x, z);
    free(x);
    free(z);
    return p;
}

/* The grounds the fan's tests sweep: the bench cleat, a class C road with vertices 3 mm apart,
 * random grounds of 400 and 60 vertices (walls among them, from rng) and a 0.05 x 0.025 m
 * cleat. */
enum { N_GROUNDS = 5 };

static void seeded_grounds(tirenv_rng *rng, tirenv_profile *g[N_GROUNDS])
{
    tirenv_road_settings rs = tirenv_road_default();
    rs.length = 20;
    rs.dx = 0.003;
    tirenv_diag diag;
    g[0] = tirenv_profile_cleat(0.3, 0.1);
    assert_int_equal(tirenv_road_iso8608(&rs, &g[1], &diag), TIRENV_OK);
    g[2] = random_ground(rng, 400);
    g[3] = random_ground(rng, 60);
    g[4] = tirenv_profile_cleat(0.05, 0.025);
    for (size_t i = 0; i < N_GROUNDS; ++i)
        assert_non_null(g[i]);
}

static void free_grounds(tirenv_profile *g[N_GROUNDS])
{
    for (size_t i = 0; i < N_GROUNDS; ++i)
        tirenv_profile_free(g[i]);
}

enum { FAN_N = 361 };

/* The fans of the tests below: N rays half a degree apart about the straight-down ray
 * i0 = N / 2, for a tire of radius R0 (m), on the arrays given (N each). */
typedef struct {
    double sin_t[FAN_N], cos_t[FAN_N], inv_s[FAN_N], drop[FAN_N], reach[FAN_N];
} fan_arrays;

static tirenv_springs__fan_rays half_degree_fan(fan_arrays *A, double R0)
{
    const size_t i0 = FAN_N / 2;
    for (size_t i = 0; i < FAN_N; ++i) {
        const double th = ((double)i - (double)i0) * M_PI / 360;
        A->sin_t[i] = sin(th);
        A->cos_t[i] = cos(th);
    }
    tirenv_springs__fan_rays_fill(FAN_N, A->sin_t, A->cos_t, R0, A->inv_s, A->drop, A->reach);
    return (tirenv_springs__fan_rays){.i0 = i0, .rho_max = R0, .sin_t = A->sin_t,
                                      .cos_t = A->cos_t, .inv_s = A->inv_s, .drop = A->drop,
                                      .reach = A->reach};
}

/* The fan gives every ray the bits tirenv_springs__ray_at gives it, rho and d(rho)/dz; a reuse
 * at another height either declines or gives the bits a fresh cast gives there. */
static void test_fan_matches_single_rays(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 7);
    const double R0 = 0.6837;
    enum { N = FAN_N };
    static double rho[N];
    static tirenv_springs__ray_memo memo[N];
    const size_t i0 = N / 2;
    static fan_arrays fa;
    const tirenv_springs__fan_rays rays = half_degree_fan(&fa, R0);
    tirenv_profile *grounds[N_GROUNDS];
    seeded_grounds(rng, grounds);
    size_t rays_checked = 0, hits = 0, reused = 0, declined = 0;
    for (size_t gi = 0; gi < 4; ++gi) { /* all but the small cleat */
        const tirenv_profile *p = grounds[gi];
        double x_lo, x_hi;
        tirenv_profile_extent(p, &x_lo, &x_hi);
        for (int trial = 0; trial < 300; ++trial) {
            double x = x_lo - 0.5 + (x_hi - x_lo + 1) * tirenv_rng_uniform(rng);
            if (trial % 5 == 0) /* on a vertex, a wall's x included */
                x = tirenv_profile_x(p)[tirenv_rng_uniform_int(rng, tirenv_profile_size(p))];
            const double g = tirenv_profile_height(p, x);
            const double z = g + 0.02 + 0.8 * tirenv_rng_uniform(rng);
            tirenv_springs__fan_origin o;
            tirenv_springs__fan_origin_at(p, x, R0, 0, &o);
            assert_bits_equal(o.g, g);
            const size_t a = tirenv_rng_uniform_int(rng, i0 + 1);
            const size_t b = i0 + tirenv_rng_uniform_int(rng, N - i0);
            tirenv_springs__fan(p, &o, &rays, z, a, b, rho, memo);
            for (size_t i = a; i <= b; ++i) {
                double drho;
                const double r = tirenv_springs__ray(p, x, z, fa.sin_t[i], fa.cos_t[i], R0, &drho);
                assert_bits_equal(rho[i], r);
                if (isfinite(r)) {
                    assert_bits_equal(tirenv_springs__fan_drho(p, &rays, i, &memo[i]), drho);
                    ++hits;
                }
                ++rays_checked;
            }
            /* Another height: small steps as Newton takes them, and large ones. */
            const double dz = (tirenv_rng_uniform(rng) - 0.5) *
                              (trial % 3 == 0 ? 0.2 : trial % 3 == 1 ? 1e-3 : 1e-8);
            const double z2 = z + dz;
            if (tirenv_springs__fan_reuse(p, &o, &rays, z2, a, b, rho, memo)) {
                for (size_t i = a; i <= b; ++i) {
                    double drho;
                    const double r =
                        tirenv_springs__ray(p, x, z2, fa.sin_t[i], fa.cos_t[i], R0, &drho);
                    assert_bits_equal(rho[i], r);
                    if (isfinite(r))
                        assert_bits_equal(tirenv_springs__fan_drho(p, &rays, i, &memo[i]),
                                          drho);
                }
                ++reused;
            } else {
                ++declined;
            }
        }
    }
    print_message("fan: %zu rays (%zu hits); reuse at another height: %zu taken, %zu "
                  "declined\n", rays_checked, hits, reused, declined);
    assert_true(hits > 10000 && reused > 200 && declined > 50);
    free_grounds(grounds);
    tirenv_rng_free(rng);
}

/* A fresh fan with its rays' resumption order known (fan_rays.ordered) takes the rays that
 * end alike as runs (after a walk past the profile's end, or onto a segment the next rays
 * meet too) without the walk's setup: the same rho and the same memos, bit for bit, as the
 * fan that walks every ray, and the memos so made serve a reuse at another height as well. */
static void test_fan_runs_match_walks(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 11);
    const double R0 = 0.6837;
    enum { N = FAN_N };
    static double rho[N], rho_w[N];
    static tirenv_springs__ray_memo memo[N], memo_w[N];
    const size_t i0 = N / 2;
    static fan_arrays fa;
    tirenv_springs__fan_rays walked = half_degree_fan(&fa, R0);
    tirenv_springs__fan_rays runs = walked;
    runs.ordered = tirenv_springs__fan_rays_ordered(&runs, N);
    assert_int_equal(runs.ordered, 1);
    tirenv_profile *grounds[N_GROUNDS];
    seeded_grounds(rng, grounds);
    size_t rays_checked = 0, past_end = 0, finite = 0, reused = 0;
    for (size_t gi = 0; gi < N_GROUNDS; ++gi) {
        const tirenv_profile *p = grounds[gi];
        const long n = (long)tirenv_profile_size(p);
        double x_lo, x_hi;
        tirenv_profile_extent(p, &x_lo, &x_hi);
        for (int trial = 0; trial < 300; ++trial) {
            double x = x_lo - 0.5 + (x_hi - x_lo + 1) * tirenv_rng_uniform(rng);
            if (trial % 5 == 0) /* on a vertex, a wall's x included */
                x = tirenv_profile_x(p)[tirenv_rng_uniform_int(rng, tirenv_profile_size(p))];
            const double g = tirenv_profile_height(p, x);
            const double z = g + (trial % 2 ? 0.001 : 0.02) + 0.8 * tirenv_rng_uniform(rng);
            tirenv_springs__fan_origin o;
            tirenv_springs__fan_origin_at(p, x, R0, 0, &o);
            const size_t a = tirenv_rng_uniform_int(rng, i0 + 1);
            const size_t b = i0 + tirenv_rng_uniform_int(rng, N - i0);
            tirenv_springs__fan(p, &o, &walked, z, a, b, rho_w, memo_w);
            tirenv_springs__fan(p, &o, &runs, z, a, b, rho, memo);
            for (size_t i = a; i <= b; ++i) {
                assert_bits_equal(rho[i], rho_w[i]);
                assert_int_equal(memo[i].j, memo_w[i].j);
                assert_int_equal(memo[i].kind, memo_w[i].kind);
                assert_bits_equal(memo[i].z_low, memo_w[i].z_low);
                past_end += i != i0 && (memo[i].j < 0 || memo[i].j >= n);
                finite += isfinite(rho[i]);
                ++rays_checked;
            }
            const double z2 = z + (tirenv_rng_uniform(rng) - 0.5) * 1e-4;
            if (tirenv_springs__fan_reuse(p, &o, &runs, z2, a, b, rho, memo)) {
                for (size_t i = a; i <= b; ++i) {
                    double drho;
                    const double r =
                        tirenv_springs__ray(p, x, z2, fa.sin_t[i], fa.cos_t[i], R0, &drho);
                    assert_bits_equal(rho[i], r);
                }
                ++reused;
            }
        }
    }
    print_message("fan runs: %zu rays (%zu finite, %zu past the profile's end); %zu reuses\n",
                  rays_checked, finite, past_end, reused);
    assert_true(finite > 10000 && past_end > 1000 && reused > 100);
    free_grounds(grounds);
    tirenv_rng_free(rng);
}

/* tirenv_springs__faces_rho takes the held rays in runs on one face, deciding once a run how
 * the face gives rho: the same rho, d(rho)/dz, faces and verdict, bit for bit, as the rays
 * taken one at a time, from memos a fan left at another x and height (as the start at a new x
 * reads them), over windows wide and narrow; each rho within round-off of face_rho's crossing
 * on its face (bit for bit on the flat ground past an end and on a wall, a segment's by its
 * line through the face). */
static void test_faces_rho_runs(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 13);
    const double R0 = 0.6837;
    enum { N = FAN_N };
    static double rho_f[N], rho[N], drho[N], rho1[N], drho1[N];
    static tirenv_springs__ray_memo memo[N], m_runs[N], m_one[N], kept_r[N], kept_o[N];
    static tirenv_springs__ray_memo faces[N], faces1[N];
    static size_t rays[N];
    const size_t i0 = N / 2;
    static fan_arrays fa;
    tirenv_springs__fan_rays fan = half_degree_fan(&fa, R0);
    fan.ordered = tirenv_springs__fan_rays_ordered(&fan, N);
    tirenv_profile *grounds[N_GROUNDS];
    seeded_grounds(rng, grounds);
    size_t taken = 0, refused = 0, rays_checked = 0, exact = 0;
    for (size_t gi = 0; gi < N_GROUNDS; ++gi) {
        const tirenv_profile *p = grounds[gi];
        double x_lo, x_hi;
        tirenv_profile_extent(p, &x_lo, &x_hi);
        for (int trial = 0; trial < 300; ++trial) {
            double x1 = x_lo - 0.5 + (x_hi - x_lo + 1) * tirenv_rng_uniform(rng);
            if (trial % 5 == 0) /* on a vertex, a wall's x included */
                x1 = tirenv_profile_x(p)[tirenv_rng_uniform_int(rng, tirenv_profile_size(p))];
            const double z1 =
                tirenv_profile_height(p, x1) + 0.02 + 0.5 * tirenv_rng_uniform(rng);
            tirenv_springs__fan_origin o1, o2;
            tirenv_springs__fan_origin_at(p, x1, R0, 0, &o1);
            const size_t a = tirenv_rng_uniform_int(rng, i0 + 1);
            const size_t b = i0 + tirenv_rng_uniform_int(rng, N - i0);
            tirenv_springs__fan(p, &o1, &fan, z1, a, b, rho_f, memo);
            const double x2 = x1 + 0.004 * (tirenv_rng_uniform(rng) - 0.5);
            const double z2 = z1 + 0.002 * (tirenv_rng_uniform(rng) - 0.5);
            tirenv_springs__fan_origin_at(p, x2, R0, o1.k, &o2);
            const double reach = (trial % 7 == 0 ? 0.2 : 1.5) * R0;
            tirenv_springs__face_window w;
            tirenv_springs__face_window_at(p, x2 - reach, x2 + reach, &w);
            /* the rays in runs with gaps, ascending, as the held ones come */
            size_t n = 0;
            for (size_t i = a; i <= b; ++i)
                if (tirenv_rng_uniform(rng) < 0.8)
                    rays[n++] = i;
            for (size_t i = 0; i < N; ++i) {
                m_runs[i] = m_one[i] = memo[i];
                kept_r[i].kind = kept_o[i].kind = -1;
            }
            const int ok = tirenv_springs__faces_rho(p, &o2, &fan, rays, n, m_runs, kept_r, z2,
                                                     &w, rho, drho, faces);
            int ok1 = 1;
            for (size_t k = 0; k < n && ok1; ++k)
                ok1 = tirenv_springs__faces_rho(p, &o2, &fan, &rays[k], 1, m_one, kept_o, z2, &w,
                                                rho1, drho1, faces1);
            assert_int_equal(ok, ok1);
            if (!ok) {
                ++refused;
                continue;
            }
            ++taken;
            for (size_t k = 0; k < n; ++k) {
                const size_t i = rays[k];
                assert_bits_equal(rho[i], rho1[i]);
                assert_bits_equal(drho[i], drho1[i]);
                assert_int_equal(faces[i].j, memo[i].j);
                assert_int_equal(faces[i].kind, memo[i].kind);
                assert_bits_equal(faces[i].drho, drho[i]);
                const double v =
                    tirenv_springs__face_rho(p, &o2, &fan, i, &memo[i], z2, &w);
                if (isnan(v)) /* (a segment the ray runs along: no crossing, only the line) */
                    continue;
                assert_near(rho[i], v, 1e-12, 1e-12);
                exact += memcmp(&rho[i], &v, sizeof v) == 0;
                ++rays_checked;
            }
        }
    }
    print_message("faces in runs: %zu sets taken, %zu refused; %zu rays, %zu as face_rho's bits\n",
                  taken, refused, rays_checked, exact);
    assert_true(taken > 500 && refused > 50 && rays_checked > 50000 && exact > 5000);
    free_grounds(grounds);
    tirenv_rng_free(rng);
}

/* ---- The workspace's kept state ---- */

/* A workspace that has seen other positions, heights and profiles (a new profile may sit at
 * a freed one's address) gives the forces of a fresh workspace: the rays it keeps are tied to
 * the profile's serial and x, the final active set does not depend on the warm start, and the
 * dF_z/dz it keeps is given again only for the same faces, span and pins (every other height is
 * a hair from the last, where they nearly always recur, as after a Newton step). With rays bit
 * for bit. With continuous contact to round-off: after a state whose solution had a row between
 * elements working the QP is solved without trying the closed form first (docs/models.md
 * section 4.8, The solver), and the two solve the same problem by different arithmetic; 1e-9 of the
 * force (7 uN of 7 kN, against 1e-3 N for 1e-9 m of the tire's stiffness) bounds round-off of
 * solves over tens of elements by orders of magnitude. A height a hair from the last QP
 * solve's at the same x is had by that solve's tangent (tirenv_springs__cc_update), its F_z
 * and F_x to round-off as well, but its dF_z/dz is the base's, the piece's at a height up to
 * 1e-6 m away: off by |d2F/dz2| |dz|, some 5e-9 of it here (1e-9 m, d2F/dz2 about 4.5 per m
 * of dF_z/dz); 1e-6 of dF_z/dz bounds that for every dz the update takes. */
static void kept_state(tirenv_springs_contact contact)
{
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 11);
    tirenv_tire t = tirenv_tire_default();
    t.springs.contact = contact;
    const int exact = contact == TIRENV_SPRINGS_RAYS;
    tirenv_springs *kept = tirenv_springs_alloc(&t.springs);
    assert_non_null(kept);
    const double heights[] = {0.1, 0.05, 0.12, 0.02, 0.08};
    size_t same_address = 0, checked = 0, moved = 0;
    double worst = 0;
    const void *last = NULL;
    double z_last = 0.65;  /* m */
    for (int round = 0; round < 40; ++round) {
        tirenv_profile *p = tirenv_profile_cleat(0.1 + 0.05 * (round % 4), heights[round % 5]);
        assert_non_null(p);
        same_address += (const void *)p == last;
        last = p;
        const double x = round % 2 ? 0.0 : -0.13; /* the same x again and again */
        for (int k = 0; k < 8; ++k) {
            const double z = k % 2 ? z_last + 1e-9 * tirenv_rng_uniform(rng)
                                   : 0.6 + 0.12 * tirenv_rng_uniform(rng);
            z_last = z;
            double fx1, fz1, df1, fx2, fz2, df2;
            size_t c1, c2;
            const int s1 = tirenv_springs_forces(kept, p, x, z, &fx1, &fz1, &df1, &c1, NULL);
            tirenv_springs *fresh = tirenv_springs_alloc(&t.springs);
            const int s2 = tirenv_springs_forces(fresh, p, x, z, &fx2, &fz2, &df2, &c2, NULL);
            tirenv_springs_free(fresh);
            assert_int_equal(s1, s2);
            if (exact) {
                assert_bits_equal(fz1, fz2);
                assert_bits_equal(fx1, fx2);
                assert_bits_equal(df1, df2);
            } else {
                const double rel[] = {fabs(fz1 - fz2) / (fabs(fz2) + 1),
                                      fabs(fx1 - fx2) / (fabs(fz2) + 1),
                                      fabs(df1 - df2) / (fabs(df2) + 1)};
                for (int q = 0; q < 3; ++q) {
                    assert_true(rel[q] <= (q == 2 ? 1e-6 : 1e-9));
                    worst = fmax(worst, rel[q]);
                }
                moved += fz1 != fz2 || fx1 != fx2 || df1 != df2;
            }
            assert_int_equal(c1, c2);
            ++checked;
        }
        tirenv_profile_free(p);
    }
    print_message("%s: %zu evaluations (%zu not bit for bit, largest relative change %.3g); a "
                  "new profile at the freed one's address %zu times\n",
                  exact ? "rays" : "continuous", checked, moved, worst, same_address);
    tirenv_springs_free(kept);
    tirenv_rng_free(rng);
}

static void test_kept_state_is_invisible(void **state)
{
    (void)state;
    kept_state(TIRENV_SPRINGS_RAYS);
    kept_state(TIRENV_SPRINGS_CONTINUOUS);
}

/* ---- Ground narrower than the rays ---- */

/* A needle under the tire: the springs model refuses the position with TIRENV_ERANGE and says
 * where and how wide, through the model API and the element level alike; today's model gave
 * h = 0 there (the needle slipped between two rays). With its centre exactly over the needle
 * the straight-down element stands on its tip: a contact the model does see (the tread rests
 * on the needle, 70 mm up), not refused. */
static void test_needle_refused(void **state)
{
    (void)state;
    tirenv_tire t = tirenv_tire_default();
    t.springs.contact = TIRENV_SPRINGS_RAYS; /* the continuous tread carries it */
    tirenv_profile *needle = tirenv_profile_cleat(1e-9, 0.1);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
    tirenv_diag diag;
    assert_int_equal(tirenv_model_set(m, needle, 13000, &diag), TIRENV_OK);
    tirenv_point pt;
    assert_int_equal(tirenv_model_eval(m, 0.003, &pt, &diag), TIRENV_ERANGE);
    print_message("%s\n", diag.message);
    assert_non_null(strstr(diag.message, "at x = 0.003 m"));
    assert_non_null(strstr(diag.message, "1e-09 m wide"));
    assert_non_null(strstr(diag.message, "rays 0.00"));
    assert_int_equal(tirenv_model_eval(m, 0.0, &pt, &diag), TIRENV_OK);
    assert_true(pt.h > 0.05 && pt.contacts == 1);
    tirenv_model_free(m);

    tirenv_springs *s = tirenv_springs_alloc(&t.springs);
    double fx, fz, dfz;
    size_t c;
    assert_int_equal(tirenv_springs_forces(s, needle, 0.003, 0.66, &fx, &fz, &dfz, &c, NULL),
                     TIRENV_ERANGE);
    tirenv_springs_refusal(s, &diag);
    assert_non_null(strstr(diag.message, "1e-09 m wide"));
    /* Cleared by the next evaluation that succeeds. */
    tirenv_profile *flat = tirenv_test_flat_ground();
    assert_non_null(flat);
    assert_int_equal(tirenv_springs_forces(s, flat, 0.0, 0.66, &fx, &fz, &dfz, &c, NULL), 0);
    tirenv_springs_refusal(s, &diag);
    assert_int_equal(diag.message[0], '\0');
    tirenv_profile_free(flat);
    tirenv_springs_free(s);
    tirenv_profile_free(needle);
}

/* The pairs of rays the springs model looks between (found from the walks, so that most
 * evaluations look at none) miss nothing a look between every pair of neighbours and of rays
 * two apart finds: on random grounds with narrow spikes, at random positions and heights,
 * with the tread at random depths, both find the same feature or none. */
static void test_pairs_miss_nothing(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 5);
    const double R0 = 0.6837;
    enum { N = FAN_N };
    static double rho[N], tread[N];
    static tirenv_springs__ray_memo memo[N];
    static size_t pairs[4 * N];
    const size_t i0 = N / 2;
    static fan_arrays fa;
    const tirenv_springs__fan_rays rays = half_degree_fan(&fa, R0);
    size_t found = 0, trials = 0;
    for (int g = 0; g < 40; ++g) {
        /* Flat ground with spikes 0.5 to 10 mm wide and up to 40 mm tall, some on walls. */
        enum { V = 200 };
        double x[V], z[V];
        double X = -1.0;
        size_t n = 0;
        while (n + 4 < V && X < 1.0) {
            X += 0.005 + 0.05 * tirenv_rng_uniform(rng);
            const double w = 0.0005 + 0.0095 * tirenv_rng_uniform(rng);
            const double h = 0.04 * tirenv_rng_uniform(rng);
            x[n] = X, z[n++] = 0;
            if (tirenv_rng_uniform(rng) < 0.5) {
                x[n] = X, z[n++] = h; /* a wall up */
                x[n] = X + w, z[n++] = h;
            } else {
                x[n] = X + 0.5 * w, z[n++] = h; /* a spike */
            }
            X += w;
            x[n] = X, z[n++] = 0;
        }
        tirenv_profile *p = tirenv_profile_alloc(n, x, z);
        assert_non_null(p);
        for (int k = 0; k < 50; ++k, ++trials) {
            const double xc = -0.6 + 1.2 * tirenv_rng_uniform(rng);
            const double zc = 0.62 + 0.08 * tirenv_rng_uniform(rng);
            tirenv_springs__fan_origin o;
            tirenv_springs__fan_origin_at(p, xc, R0, 0, &o);
            const size_t a = i0 - 100, b = i0 + 100;
            tirenv_springs__fan(p, &o, &rays, zc, a, b, rho, memo);
            for (size_t i = a; i <= b; ++i) /* the tread at or inside the ground, anywhere */
                tread[i] = fmin(R0, isfinite(rho[i]) ? rho[i] : R0) -
                           0.01 * tirenv_rng_uniform(rng);
            tirenv_springs__feature f_all, f_pairs;
            const int all = tirenv_springs__unseen_feature(p, &rays, xc, zc, a, b, rho, tread,
                                                           1e-6, &f_all);
            const size_t np = tirenv_springs__fan_pairs(&o, &rays, a, b, memo, pairs);
            const int some = tirenv_springs__unseen_pairs(p, &rays, xc, zc, rho, tread, pairs,
                                                          np, 1e-6, &f_pairs);
            assert_int_equal(all, some);
            if (all) {
                assert_bits_equal(f_all.X, f_pairs.X);
                assert_bits_equal(f_all.depth, f_pairs.depth);
                assert_true(f_all.depth > f_all.spacing);
                ++found;
            }
        }
        tirenv_profile_free(p);
    }
    print_message("%zu of %zu states with a feature between the rays\n", found, trials);
    assert_true(found > 100 && found < trials);
    tirenv_rng_free(rng);
}

/* ---- K_FF's factor after one element's row enters or leaves ---- */

/* Random spans on random tires, elements held and let go one at a time: the factor mended on
 * the flipped element's chain (tirenv_springs__cc_schur_flip) against one factorised afresh,
 * the same chains and bit for bit the same pivots and multipliers. */
static void test_flip_matches_factor(void **state)
{
    (void)state;
    uint64_t seed = 0x5eed20c0ffeeULL;
    size_t flips = 0, splits = 0, joins = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const size_t N = 20 + (size_t)(200 * tirenv_test_uniform(&seed));
        const double k_r = 1e5 * (0.3 + tirenv_test_uniform(&seed));
        const double k_ir = k_r * pow(10, 4 * tirenv_test_uniform(&seed) - 1);
        chain_set cs;
        chain_set_init(&cs, N, k_r, k_ir);
        const tirenv_springs__cc_tire T = {.N = N, .k_r = k_r, .k_ir = k_ir, .diag = cs.diag,
                                           .lq = cs.lq, .rq = cs.rq};
        tirenv_springs__cc a, b;
        assert_int_equal(tirenv_springs__cc_init(&a, N), 0);
        assert_int_equal(tirenv_springs__cc_init(&b, N), 0);
        const size_t f0 = (size_t)((double)(N / 3) * tirenv_test_uniform(&seed));
        const size_t f1 = N - 1 - (size_t)((double)(N / 3) * tirenv_test_uniform(&seed));
        a.f0 = b.f0 = f0;
        a.f1 = b.f1 = f1;
        a.n_schur = b.n_schur = 0;
        for (size_t e = f0; e <= f1; ++e)
            a.wpos[e] = tirenv_test_uniform(&seed) < 0.3 ? SIZE_MAX : 0;
        assert_int_equal(tirenv_springs__cc_schur_factor(&a, &T, 0), 0);
        for (int step = 0; step < 60; ++step) {
            const size_t e = f0 + (size_t)((double)(f1 - f0 + 1) * tirenv_test_uniform(&seed));
            const int hold = a.wpos[e] != SIZE_MAX;
            a.wpos[e] = hold ? SIZE_MAX : 0;
            const int side = (e > f0 && a.wpos[e - 1] != SIZE_MAX) +
                             (e < f1 && a.wpos[e + 1] != SIZE_MAX);
            splits += hold && side == 2;
            joins += !hold && side == 2;
            assert_int_equal(tirenv_springs__cc_schur_flip(&a, &T, e), 0);
            memcpy(b.wpos + f0, a.wpos + f0, (f1 - f0 + 1) * sizeof *b.wpos);
            assert_int_equal(tirenv_springs__cc_schur_factor(&b, &T, 0), 0);
            assert_int_equal(a.n_chains, b.n_chains);
            for (size_t q = 0; q < 2 * b.n_chains; ++q)
                assert_int_equal(a.chains[q], b.chains[q]);
            for (size_t q = 0; q < b.n_chains; ++q)
                for (size_t m = b.chains[2 * q]; m <= b.chains[2 * q + 1]; ++m) {
                    assert_memory_equal(&a.tri_piv[m], &b.tri_piv[m], sizeof(double));
                    if (m > b.chains[2 * q])
                        assert_memory_equal(&a.tri_mul[m], &b.tri_mul[m], sizeof(double));
                }
            ++flips;
        }
        tirenv_springs__cc_free(&a);
        tirenv_springs__cc_free(&b);
        chain_set_free(&cs);
    }
    print_message("%zu flips, %zu chains split in two, %zu pairs joined\n", flips, splits,
                  joins);
    assert_true(splits > 50 && joins > 50);
}

/* The confirming evaluation's first pass from the root's state (springs_update.c, docs/models.md
 * section 4.8, A start at a new x) takes K w only at the held elements, the chains' ends and the
 * working rows' elements; inside a chain it checks |w| <= R0 instead, which bounds the Thomas
 * solve's residual there below a quarter of the update's tolerance 1e-14 R0 (k_r + 2 k_ir). Over
 * random spans, held sets and tires (k_ir / k_r from 0.1 to 1000), each chain solved as the root
 * solves the state (k_ir h at its ends from the held neighbours, a row's load at a few inner
 * elements, 0 elsewhere), scaled so that max |w| is about R0: every other inner element's
 * residual, by the update's expression, within that quarter (the bound is 0.244 of it). */
static void test_inner_residual_bound(void **state)
{
    (void)state;
    uint64_t seed = 0x1a2b3c4d5e6fULL;
    size_t inner = 0;
    double worst = 0;
    for (int trial = 0; trial < 100; ++trial) {
        const size_t N = 20 + (size_t)(300 * tirenv_test_uniform(&seed));
        const double k_r = 1e5 * (0.3 + tirenv_test_uniform(&seed));
        const double k_ir = k_r * pow(10, 4 * tirenv_test_uniform(&seed) - 1);
        const double R0 = 0.2 + 0.6 * tirenv_test_uniform(&seed);
        const double tol_k = 1e-14 * R0 * (k_r + 2 * k_ir);
        chain_set cs;
        chain_set_init(&cs, N, k_r, k_ir);
        const tirenv_springs__cc_tire T = {.N = N, .R0 = R0, .k_r = k_r, .k_ir = k_ir,
                                           .diag = cs.diag, .lq = cs.lq, .rq = cs.rq};
        tirenv_springs__cc a;
        assert_int_equal(tirenv_springs__cc_init(&a, N), 0);
        const size_t f0 = (size_t)((double)(N / 3) * tirenv_test_uniform(&seed));
        const size_t f1 = N - 1 - (size_t)((double)(N / 3) * tirenv_test_uniform(&seed));
        a.f0 = f0;
        a.f1 = f1;
        a.n_schur = 0;
        for (size_t e = f0; e <= f1; ++e)
            a.wpos[e] = tirenv_test_uniform(&seed) < 0.05 ? SIZE_MAX : 0;
        assert_int_equal(tirenv_springs__cc_schur_factor(&a, &T, 0), 0);
        double *w = calloc(N + 2, sizeof *w), *b = calloc(N + 2, sizeof *b);
        unsigned char *loaded = calloc(N, 1);
        assert_true(w && b && loaded);
        for (size_t q = 0; q < a.n_chains; ++q) {
            const size_t lo = a.chains[2 * q], hi = a.chains[2 * q + 1];
            for (size_t e = lo; e <= hi; ++e)
                b[e] = 0;
            if (lo > f0)
                b[lo] = k_ir * R0 * tirenv_test_uniform(&seed);
            if (hi < f1)
                b[hi] += k_ir * R0 * tirenv_test_uniform(&seed);
            for (int m = 0; m < 2 && hi > lo + 1; ++m) {
                const size_t e = lo + 1 + (size_t)((double)(hi - lo - 1) *
                                                   tirenv_test_uniform(&seed));
                b[e] += k_r * R0 * tirenv_test_uniform(&seed);
                loaded[e] = 1;
            }
            /* solved once for the scale, then again with the right-hand side scaled */
            memcpy(w + lo, b + lo, (hi - lo + 1) * sizeof *w);
            tirenv_springs__cc_chain_solve(&a, w, lo, lo, hi);
            double w_max = 0;
            for (size_t e = lo; e <= hi; ++e)
                w_max = fmax(w_max, fabs(w[e]));
            if (!(w_max > 0))
                continue;
            for (size_t e = lo; e <= hi; ++e)
                w[e] = b[e] * (0.999 * R0 / w_max);
            tirenv_springs__cc_chain_solve(&a, w, lo, lo, hi);
            w_max = 0;
            for (size_t e = lo; e <= hi; ++e)
                w_max = fmax(w_max, fabs(w[e]));
            if (w_max > R0) /* the premise fails: the update takes every residual */
                continue;
            for (size_t e = lo + 1; e < hi; ++e) {
                if (loaded[e])
                    continue;
                const double r = cs.diag[e] * w[e] - k_ir * (w[e - 1] + w[e + 1]);
                worst = fmax(worst, fabs(r) / tol_k);
                assert_true(fabs(r) <= 0.25 * tol_k);
                ++inner;
            }
        }
        free(w);
        free(b);
        free(loaded);
        tirenv_springs__cc_free(&a);
        chain_set_free(&cs);
    }
    print_message("%zu inner elements: the largest residual %.3g of the update's tolerance\n",
                  inner, worst);
    assert_true(inner > 5000); /* 8,581 on these seeds, the largest 0.027 of it */
}

/* K_FF's factor of a random span on a random tire of 5 to 304 elements (cs its tables), a
 * random share of its elements held: its N. */
static size_t random_factor(chain_set *cs, tirenv_springs__cc *a, uint64_t *seed)
{
    const size_t N = 5 + (size_t)(300 * tirenv_test_uniform(seed));
    const double k_r = 1e5 * (0.3 + tirenv_test_uniform(seed));
    const double k_ir = k_r * pow(10, 4 * tirenv_test_uniform(seed) - 1);
    chain_set_init(cs, N, k_r, k_ir);
    const tirenv_springs__cc_tire T = {.N = N, .R0 = 0.3, .k_r = k_r, .k_ir = k_ir,
                                       .diag = cs->diag, .lq = cs->lq, .rq = cs->rq};
    assert_int_equal(tirenv_springs__cc_init(a, N), 0);
    a->f0 = (size_t)((double)(N / 3) * tirenv_test_uniform(seed));
    a->f1 = N - 1 - (size_t)((double)(N / 3) * tirenv_test_uniform(seed));
    a->n_schur = 0;
    const double p_held = 0.02 + 0.4 * tirenv_test_uniform(seed);
    for (size_t e = a->f0; e <= a->f1; ++e)
        a->wpos[e] = tirenv_test_uniform(seed) < p_held ? SIZE_MAX : 0;
    assert_int_equal(tirenv_springs__cc_schur_factor(a, &T, 0), 0);
    return N;
}

/* tirenv_springs__cc_chains_solve (springs_schur.c) solves two chains at a time, interleaved:
 * over random spans, held sets and tires, every element the bits of tirenv_springs__cc_chain_solve
 * on each chain alone. */
static void test_chains_solve_matches(void **state)
{
    (void)state;
    uint64_t seed = 0x7e57c4a1a5ULL;
    size_t chains = 0, elements = 0;
    for (int trial = 0; trial < 60; ++trial) {
        chain_set cs;
        tirenv_springs__cc a;
        const size_t N = random_factor(&cs, &a, &seed);
        double *x = calloc(N + 2, sizeof *x), *y = calloc(N + 2, sizeof *y);
        assert_true(x && y);
        for (size_t e = a.f0; e <= a.f1; ++e)
            x[e] = y[e] = a.wpos[e] == SIZE_MAX ? 0.0 : tirenv_test_uniform(&seed) - 0.3;
        tirenv_springs__cc_chains_solve(&a, x);
        for (size_t q = 0; q < a.n_chains; ++q)
            tirenv_springs__cc_chain_solve(&a, y, a.chains[2 * q], a.chains[2 * q],
                                           a.chains[2 * q + 1]);
        assert_memory_equal(x, y, (N + 2) * sizeof *x);
        chains += a.n_chains;
        elements += a.f1 - a.f0 + 1;
        free(x);
        free(y);
        tirenv_springs__cc_free(&a);
        chain_set_free(&cs);
    }
    print_message("%zu chains over %zu elements, the same bits\n", chains, elements);
    assert_true(chains > 500);
}

/* A chain's right-hand side: x zero on [lo, from), seeded values from there on (a 1 where
 * unit, as the root's columns of K_FF^-1 have). */
static void chain_rhs(double x[], size_t lo, size_t from, size_t hi, int unit, uint64_t *seed)
{
    for (size_t e = lo; e <= hi; ++e)
        x[e] = e < from ? 0.0 : unit && e == from ? 1.0 : tirenv_test_uniform(seed) - 0.3;
}

/* tirenv_springs__cc_chain_solve_pair (two chains, or two columns on one) and _three (a whole
 * vector and two columns on one chain) against tirenv_springs__cc_chain_solve on each, bit
 * for bit, over random spans, held sets, tires, chains and starts. */
static void test_chain_solve_pair_three_match(void **state)
{
    (void)state;
    uint64_t seed = 0x5eedc0105ULL;
    size_t pairs = 0, threes = 0;
    for (int trial = 0; trial < 60; ++trial) {
        chain_set cs;
        tirenv_springs__cc a;
        const size_t N = random_factor(&cs, &a, &seed);
        double *x[3], *y[3];
        for (int i = 0; i < 3; ++i) {
            x[i] = calloc(N + 2, sizeof *x[i]);
            y[i] = calloc(N + 2, sizeof *y[i]);
            assert_true(x[i] && y[i]);
        }
        const size_t n_ch = a.n_chains, *ch = a.chains;
        for (int rep = 0; rep < 20 && n_ch > 0; ++rep) {
            const size_t q1 = (size_t)((double)n_ch * tirenv_test_uniform(&seed));
            const size_t q2 = (size_t)((double)n_ch * tirenv_test_uniform(&seed));
            const size_t lo1 = ch[2 * q1], hi1 = ch[2 * q1 + 1], lo2 = ch[2 * q2],
                         hi2 = ch[2 * q2 + 1];
            const size_t from1 =
                lo1 + (size_t)((double)(hi1 - lo1 + 1) * tirenv_test_uniform(&seed));
            const size_t from2 =
                lo2 + (size_t)((double)(hi2 - lo2 + 1) * tirenv_test_uniform(&seed));
            const int unit = rep % 2;
            /* two chains apart in one array, or any two (the same one too) in two arrays */
            const int apart = q1 != q2 && rep % 3 == 0;
            double *b = apart ? x[0] : x[1], *rb = apart ? y[0] : y[1];
            chain_rhs(x[0], lo1, from1, hi1, unit, &seed);
            chain_rhs(b, lo2, from2, hi2, unit, &seed);
            memcpy(y[0], x[0], (N + 2) * sizeof *x[0]);
            memcpy(y[1], x[1], (N + 2) * sizeof *x[1]);
            tirenv_springs__cc_chain_solve_pair(&a, x[0], lo1, from1, hi1, b, lo2, from2, hi2);
            tirenv_springs__cc_chain_solve(&a, y[0], lo1, from1, hi1);
            tirenv_springs__cc_chain_solve(&a, rb, lo2, from2, hi2);
            assert_memory_equal(x[0], y[0], (N + 2) * sizeof *x[0]);
            assert_memory_equal(x[1], y[1], (N + 2) * sizeof *x[1]);
            ++pairs;
            /* a whole vector and two columns on chain q1 */
            const size_t fy = from1 < from2 && lo1 == lo2 ? from1 : lo1 + (hi1 - lo1) / 3;
            const size_t fz = fy + (size_t)((double)(hi1 - fy + 1) * tirenv_test_uniform(&seed));
            chain_rhs(x[0], lo1, lo1, hi1, 0, &seed);
            chain_rhs(x[1], lo1, fy, hi1, unit, &seed);
            chain_rhs(x[2], lo1, fz, hi1, unit, &seed);
            for (int i = 0; i < 3; ++i)
                memcpy(y[i], x[i], (N + 2) * sizeof *x[i]);
            tirenv_springs__cc_chain_solve_three(&a, x[0], x[1], fy, x[2], fz, lo1, hi1);
            tirenv_springs__cc_chain_solve(&a, y[0], lo1, lo1, hi1);
            tirenv_springs__cc_chain_solve(&a, y[1], lo1, fy, hi1);
            tirenv_springs__cc_chain_solve(&a, y[2], lo1, fz, hi1);
            for (int i = 0; i < 3; ++i)
                assert_memory_equal(x[i], y[i], (N + 2) * sizeof *x[i]);
            ++threes;
        }
        for (int i = 0; i < 3; ++i) {
            free(x[i]);
            free(y[i]);
        }
        tirenv_springs__cc_free(&a);
        chain_set_free(&cs);
    }
    print_message("%zu pairs and %zu threes, the same bits\n", pairs, threes);
    assert_true(pairs > 500 && threes > 500);
}

/* tirenv_springs__penetrations against the select it replaces, bit for bit, over seeded rays
 * (rho near R0 by an ulp, at R0, beyond it, INFINITY, NaN) and spans of every length, empty too;
 * nothing outside [a, b] written. */
static void test_penetrations_match_select(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 20261207);
    enum { N = 61 };
    const double R0 = 0.6837;
    for (int trial = 0; trial < 400; ++trial) {
        double rho[N], d[N], d_ref[N];
        for (size_t i = 0; i < N; ++i) {
            const double u = tirenv_rng_uniform(rng);
            rho[i] = u < 0.1    ? INFINITY
                     : u < 0.15 ? NAN
                     : u < 0.25 ? R0
                     : u < 0.3  ? nextafter(R0, 0)
                     : u < 0.35 ? nextafter(R0, 1)
                                : R0 * (0.8 + 0.4 * tirenv_rng_uniform(rng));
            d[i] = d_ref[i] = -2.385 - (double)i;
        }
        /* a in [1, N - 1], b in [a - 1, N - 1] (b = a - 1: an empty span) */
        const size_t a = 1 + tirenv_rng_uniform_int(rng, N - 1);
        const size_t b = a - 1 + tirenv_rng_uniform_int(rng, N - a + 1);
        for (size_t i = a; i <= b; ++i) {
            const double v = R0 - rho[i];
            d_ref[i] = v > 0 ? v : 0;
        }
        tirenv_springs__penetrations(R0, rho, d, a, b);
        assert_memory_equal(d, d_ref, sizeof d);
    }
    tirenv_rng_free(rng);
}

/* tirenv_springs__walk_ahead against the walk a ray at a time, bit for bit (the ray and its
 * sigma), over seeded vertices anywhere in the lower half, on a ray's angle (sigma within
 * round-off of 0), nearly level with the centre, and from every kind of start. */
static void test_walk_ahead_matches_walk(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 20261208);
    enum { N_MAX = 721 };
    static double st[N_MAX], ct[N_MAX];
    for (int tire = 0; tire < 3; ++tire) {
        const size_t i0 = tire == 0 ? 180 : tire == 1 ? 360 : 37, N = 2 * i0 + 1;
        const double dphi = 0.5 * M_PI / (double)i0;
        for (size_t k = 0; k < N; ++k) {
            st[k] = sin(((double)k - (double)i0) * dphi);
            ct[k] = cos(((double)k - (double)i0) * dphi);
        }
        for (int trial = 0; trial < 4000; ++trial) {
            const double rho = 0.3 * (0.1 + tirenv_rng_uniform(rng));
            const double u = tirenv_rng_uniform(rng);
            const size_t q = tirenv_rng_uniform_int(rng, N);
            const double psi = u < 0.3   ? ((double)q - (double)i0) * dphi /* on a ray */
                               : u < 0.4 ? (q % 2 ? 1 : -1) * (0.5 * M_PI - 1e-9 * u)
                                         : (tirenv_rng_uniform(rng) - 0.5) * M_PI;
            const double dx = rho * sin(psi), dz = rho * cos(psi);
            if (!(dz > 0))
                continue;
            const size_t i = tirenv_rng_uniform(rng) < 0.5 ? tirenv_rng_uniform_int(rng, N)
                                                          : (q + tirenv_rng_uniform_int(rng, 7)) % N;
            size_t ref = i;
            double s_ref = 0;
            while (ref + 1 < N) {
                const double v = dx * ct[ref + 1] - dz * st[ref + 1];
                if (!(v >= 0)) {
                    s_ref = -v;
                    break;
                }
                ++ref;
            }
            double s_n = -2.385;
            const size_t got = tirenv_springs__walk_ahead(st, ct, N, dx, dz, i, &s_n);
            assert_int_equal(got, ref);
            assert_memory_equal(&s_n, &s_ref, sizeof s_n);
        }
    }
    tirenv_rng_free(rng);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pinned_matches_thomas),
        cmocka_unit_test(test_fan_matches_single_rays),
        cmocka_unit_test(test_fan_runs_match_walks),
        cmocka_unit_test(test_faces_rho_runs),
        cmocka_unit_test(test_kept_state_is_invisible),
        cmocka_unit_test(test_needle_refused),
        cmocka_unit_test(test_pairs_miss_nothing),
        cmocka_unit_test(test_flip_matches_factor),
        cmocka_unit_test(test_inner_residual_bound),
        cmocka_unit_test(test_chains_solve_matches),
        cmocka_unit_test(test_chain_solve_pair_three_match),
        cmocka_unit_test(test_penetrations_match_select),
        cmocka_unit_test(test_walk_ahead_matches_walk),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
