/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model's ground scan with its shortcuts against the plain scan it replaces
 * (docs/models.md section 4.8, The later heights at one x): equal bit for bit on seeded random
 * finely sampled roads, the centre exactly over a vertex or anywhere, at the heights an equilibrium
 * visits at one x.
 *
 * Exact equality is the contract, not a tolerance. The vertex rows: a workspace whose scans at
 * an x guess the vertices' sectors, the first two without proofs and the third making them (a
 * vertex dropped there is skipped at a later height where a bound proves it dropped again),
 * and one whose first scan at an x makes the proofs (scan_eager), must give the rows, in
 * their order, and the laid-out rows of a fresh workspace that computes every vertex by the
 * plain scan (scan_plain: no proving loop, no proofs); the proving loop's guessed sectors and
 * the walk where a guess misses both give the plain scan's. The rays: a fan updated ray by
 * ray from its memos (the rays whose memos fail walked again alone) must give the rho of a
 * fresh fan. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "testutil.h"
#include "model/springs_impl.h"
#include "tirenv/tirenv.h"

static uint64_t rng_state;
static double uniform(void) { return tirenv_test_uniform(&rng_state); }

/* A road of n vertices dx apart: a random walk of slopes (like an ISO class C-D road at that
 * spacing), a long wave, and a few spikes and steps. */
static tirenv_profile *random_road(size_t n, double dx, int spikes)
{
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    assert_non_null(x);
    assert_non_null(z);
    double level = 0, slope = 0;
    const double wave = 0.02 * uniform(), k = 2 * M_PI / (0.3 + 2 * uniform());
    for (size_t i = 0; i < n; ++i) {
        x[i] = -0.5 * (double)n * dx + (double)i * dx;
        slope = 0.97 * slope + 0.02 * (uniform() - 0.5);
        level += slope * dx;
        z[i] = level + wave * sin(k * x[i]);
    }
    for (int s = 0; s < spikes; ++s) {
        const size_t i = 1 + (size_t)(uniform() * (double)(n - 2));
        z[i] += (s % 2 ? 0.005 : -0.003) + 0.02 * uniform();
    }
    tirenv_profile *p = tirenv_profile_alloc(n, x, z);
    assert_non_null(p);
    free(x);
    free(z);
    return p;
}

/* The tire as springs.c lays it out (the continuous contact's view of it). */
typedef struct {
    size_t N, i0;
    double *sin_t, *cos_t, *diag, *lq, *rq, *d, *inv_s, *drop, *reach;
    tirenv_springs__cc_tire T;
    tirenv_springs__fan_rays rays;
} tire_setup;

static void setup_tire(tire_setup *S, const tirenv_springs_params *par)
{
    const size_t i0 = (size_t)floor(0.5 * par->phi / par->dphi * (1 + 1e-12));
    const size_t N = 2 * i0 + 1;
    S->N = N;
    S->i0 = i0;
    double **arrays[] = {&S->sin_t, &S->cos_t, &S->diag, &S->lq, &S->rq,
                         &S->d,     &S->inv_s, &S->drop, &S->reach};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; ++k) {
        *arrays[k] = calloc(N, sizeof(double));
        assert_non_null(*arrays[k]);
    }
    const double k_r = par->c_r * par->dphi, k_ir = par->c_b / par->dphi;
    for (size_t i = 0; i < N; ++i) {
        const double theta = ((double)i - (double)i0) * par->dphi;
        S->sin_t[i] = sin(theta);
        S->cos_t[i] = cos(theta);
        S->diag[i] = k_r + (double)((i > 0) + (i + 1 < N)) * k_ir;
    }
    double L = S->diag[0];
    S->lq[0] = k_ir / L;
    for (size_t j = 1; j < N; ++j) {
        L = S->diag[j] - k_ir * k_ir / L;
        S->lq[j] = k_ir / L;
    }
    L = S->diag[N - 1];
    S->rq[N - 1] = k_ir / L;
    for (size_t j = N - 1; j-- > 0;) {
        L = S->diag[j] - k_ir * k_ir / L;
        S->rq[j] = k_ir / L;
    }
    S->T = (tirenv_springs__cc_tire){.N = N, .i0 = i0, .R0 = par->R0, .k_r = k_r,
                                     .k_ir = k_ir, .sin_t = S->sin_t, .cos_t = S->cos_t,
                                     .diag = S->diag, .lq = S->lq, .rq = S->rq};
    tirenv_springs__cc_tire_shape(&S->T);
    tirenv_springs__fan_rays_fill(N, S->sin_t, S->cos_t, par->R0, S->inv_s, S->drop, S->reach);
    S->rays = (tirenv_springs__fan_rays){.i0 = i0, .rho_max = par->R0, .sin_t = S->sin_t,
                                         .cos_t = S->cos_t, .inv_s = S->inv_s,
                                         .drop = S->drop, .reach = S->reach};
}

static void free_tire(tire_setup *S)
{
    double *arrays[] = {S->sin_t, S->cos_t, S->diag, S->lq, S->rq,
                        S->d,     S->inv_s, S->drop, S->reach};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; ++k)
        free(arrays[k]);
}

/* The centre heights one x sees: a first guess, Newton-like steps from it (1e-4 to 1e-3 m),
 * a confirming one 1e-10 m on, and a far one (0.01 m). */
static double height(double z1, int k)
{
    static const double steps[] = {0, 3.7e-4, 3.7e-4 + 1.1e-10, -8.3e-4, -2.9e-5,
                                   -2.9e-5 - 2.3e-10, 0.0113, 1.9e-3};
    return z1 + steps[k];
}
#define N_HEIGHTS 8

/* The penetrations d[a..b] at (x, z) from single rays (the reference caster), and the span
 * [a, b] of the rays that meet the ground, one more either side. */
static int penetrations(const tire_setup *S, const tirenv_profile *p, double x, double z,
                        double R0, size_t *a, size_t *b)
{
    size_t lo = S->N, hi = 0;
    for (size_t i = 0; i < S->N; ++i) {
        double dr;
        const double rho = tirenv_springs__ray(p, x, z, S->sin_t[i], S->cos_t[i], R0, &dr);
        S->d[i] = rho < R0 ? R0 - rho : 0;
        if (S->d[i] > 0) {
            lo = i < lo ? i : lo;
            hi = i;
        }
    }
    if (lo > hi)
        return 0;
    *a = lo > 0 ? lo - 1 : 0;
    *b = hi + 1 < S->N ? hi + 1 : S->N - 1;
    return 1;
}

/* The vertex rows of a (sorted and weighted as the layout left them), the rows the solve gets
 * and their span, bit for bit those of b. */
static void same_rows(const tirenv_springs__cc *a, const tirenv_springs__cc *b)
{
    assert_int_equal(a->n_vrows, b->n_vrows);
    for (size_t r = 0; r < a->n_vrows; ++r)
        assert_memory_equal(&a->vrows[r], &b->vrows[r], sizeof a->vrows[r]);
    assert_int_equal(a->n_rows, b->n_rows);
    assert_int_equal(a->f0, b->f0);
    assert_int_equal(a->f1, b->f1);
    for (size_t r = 0; r < a->n_rows; ++r)
        assert_memory_equal(&a->rows[r], &b->rows[r], sizeof a->rows[r]);
}

static void test_vertex_rows_proven_exact(void **state)
{
    (void)state;
    rng_state = 20261206;
    tirenv_springs_params par = tirenv_tire_default().springs;
    par.contact = TIRENV_SPRINGS_CONTINUOUS;
    tire_setup S;
    setup_tire(&S, &par);
    const size_t N = S.N;
    size_t scans = 0, skipped = 0, rows = 0, on_vertex = 0, missed = 0, missed_blind = 0;
    size_t skipped_up = 0, skipped_down = 0; /* at heights above and below the proofs' */
    size_t skipped_hot = 0; /* by the proofs the third scan at an x makes */
    for (int trial = 0; trial < 24; ++trial) {
        const double dx = 0.0003 + 0.0012 * uniform();
        tirenv_profile *p = random_road((size_t)(4.0 / dx), dx, trial % 4);
        const double *X = tirenv_profile_x(p);
        const size_t n = tirenv_profile_size(p);
        tirenv_springs__cc hot, eager, blind;
        assert_int_equal(tirenv_springs__cc_init(&hot, N), TIRENV_OK);
        assert_int_equal(tirenv_springs__cc_init(&eager, N), TIRENV_OK);
        assert_int_equal(tirenv_springs__cc_init(&blind, N), TIRENV_OK);
        eager.scan_eager = 1; /* the proofs made by the first scan at each x */
        blind.scan_blind = 1; /* every guessed sector wrong but one: the walk takes them */
        blind.scan_eager = trial % 2; /* with and without proofs at the first scan */
        for (int pos = 0; pos < 12; ++pos) {
            /* every other position exactly over a vertex, the others anywhere */
            const size_t v = n / 4 + (size_t)(uniform() * (double)(n / 2));
            const double x = pos % 2 ? X[v] : X[v] + dx * uniform();
            on_vertex += pos % 2;
            const double g = tirenv_profile_height(p, x);
            const double z1 = g + par.R0 - 0.01 - 0.07 * uniform();
            for (int k = 0; k < N_HEIGHTS; ++k) {
                const double z = height(z1, k);
                size_t a = 0, b = 0;
                if (!penetrations(&S, p, x, z, par.R0, &a, &b))
                    continue;
                tirenv_springs__cc cold;
                assert_int_equal(tirenv_springs__cc_init(&cold, N), TIRENV_OK);
                cold.scan_plain = 1; /* every vertex by scan_vertex, no proving loop */
                tirenv_diag diag;
                assert_int_equal(tirenv_springs__cc_rows(&hot, &S.T, p, x, z, a, b, S.d, &diag),
                                 TIRENV_OK);
                assert_int_equal(tirenv_springs__cc_rows(&eager, &S.T, p, x, z, a, b, S.d,
                                                         &diag), TIRENV_OK);
                assert_int_equal(tirenv_springs__cc_rows(&cold, &S.T, p, x, z, a, b, S.d,
                                                         &diag), TIRENV_OK);
                assert_int_equal(tirenv_springs__cc_rows(&blind, &S.T, p, x, z, a, b, S.d,
                                                         &diag), TIRENV_OK);
                ++scans;
                skipped += eager.scan_skipped;
                skipped_hot += hot.scan_skipped;
                missed += eager.scan_missed;
                missed_blind += blind.scan_missed;
                if (z > z1)
                    skipped_up += eager.scan_skipped;
                else if (z < z1)
                    skipped_down += eager.scan_skipped;
                /* the first two scans at an x make no proofs and skip nothing */
                if (k < 2)
                    assert_int_equal(hot.scan_skipped, 0);
                same_rows(&hot, &cold);
                same_rows(&eager, &cold);
                same_rows(&blind, &cold);
                rows += hot.n_rows;
                tirenv_springs__cc_free(&cold);
            }
        }
        tirenv_springs__cc_free(&hot);
        tirenv_springs__cc_free(&eager);
        tirenv_springs__cc_free(&blind);
        tirenv_profile_free(p);
    }
    print_message("%zu scans (%zu positions on a vertex), %zu vertices skipped by proofs made "
                  "at the first scan at an x (%zu with the centre higher than there, %zu "
                  "lower), %zu by those made at the third, %zu whose sector the proving "
                  "scan's guess missed (%zu blind), %zu rows\n",
                  scans, on_vertex, skipped, skipped_up, skipped_down, skipped_hot, missed,
                  missed_blind, rows);
    /* The shortcut taken (most vertices of the later heights skipped), rows compared; the
     * proofs' check both where h may rise (the centre lower) and where it falls; the proving
     * scan's walk for a vertex whose guessed sector is wrong (on a ray or within the guess's
     * error of one) taken too. */
    assert_true(scans > 1000);
    assert_true(skipped > 100 * scans);
    assert_true(skipped_up > 10 * scans);
    assert_true(skipped_down > 10 * scans);
    assert_true(skipped_hot > 50 * scans);
    assert_true(rows > 10 * scans);
    assert_true(missed_blind > 10 * scans); /* a first scan in 8 */
    free_tire(&S);
}

static void test_fan_update_exact(void **state)
{
    (void)state;
    rng_state = 8608;
    tirenv_springs_params par = tirenv_tire_default().springs;
    tire_setup S;
    setup_tire(&S, &par);
    const size_t N = S.N;
    tirenv_springs__ray_memo *memo = calloc(N, sizeof *memo), *fresh = calloc(N, sizeof *fresh);
    double *rho = calloc(N, sizeof *rho), *rho_ref = calloc(N, sizeof *rho_ref);
    assert_non_null(memo);
    assert_non_null(fresh);
    assert_non_null(rho);
    assert_non_null(rho_ref);
    size_t updates = 0, cast = 0, rays = 0;
    for (int trial = 0; trial < 30; ++trial) {
        const double dx = 0.0003 + 0.003 * uniform();
        tirenv_profile *p = random_road((size_t)(4.0 / dx), dx, trial % 5);
        const double *X = tirenv_profile_x(p);
        const size_t n = tirenv_profile_size(p);
        size_t k_hint = 0;
        for (int pos = 0; pos < 20; ++pos) {
            const size_t v = n / 4 + (size_t)(uniform() * (double)(n / 2));
            const double x = pos % 2 ? X[v] : X[v] + dx * uniform();
            tirenv_springs__fan_origin o;
            tirenv_springs__fan_origin_at(p, x, par.R0, k_hint, &o);
            k_hint = o.k;
            const double z1 = o.g + par.R0 - 0.01 - 0.07 * uniform();
            const size_t a = (size_t)(uniform() * (double)(S.i0 / 2));
            const size_t b = N - 1 - (size_t)(uniform() * (double)(S.i0 / 2));
            tirenv_springs__fan(p, &o, &S.rays, z1, a, b, rho, memo);
            /* the heights of one x, then a walk up and down by 1e-4 to 5e-3 m: a memo whose
             * z_low were too low would keep a ray's end past a vertex come up to it */
            double z = z1;
            for (int k = 1; k < N_HEIGHTS + 16; ++k) {
                static const double walk[] = {1e-4, -1e-3, 5e-3, -5e-3, -2.3e-3, 7e-4};
                z = k < N_HEIGHTS ? height(z1, k) : z + walk[(size_t)(6 * uniform())];
                /* a narrower span now and then, as the candidate span moves */
                const size_t a2 = k % 3 ? a : a + 1, b2 = k % 3 ? b : b - 1;
                cast += tirenv_springs__fan_update(p, &o, &S.rays, z, a2, b2, rho, memo);
                tirenv_springs__fan(p, &o, &S.rays, z, a2, b2, rho_ref, fresh);
                ++updates;
                rays += b2 - a2 + 1;
                for (size_t i = a2; i <= b2; ++i) {
                    assert_memory_equal(&rho[i], &rho_ref[i], sizeof rho[i]);
                    /* the memos end where a fresh fan's do */
                    assert_int_equal(memo[i].j, fresh[i].j);
                }
            }
        }
        tirenv_profile_free(p);
    }
    print_message("%zu updates, %zu of %zu rays walked again\n", updates, cast, rays);
    /* Both paths taken: most rays kept, some walked again. */
    assert_true(cast > 0);
    assert_true(cast < rays / 2);
    free(memo);
    free(fresh);
    free(rho);
    free(rho_ref);
    free_tire(&S);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vertex_rows_proven_exact),
        cmocka_unit_test(test_fan_update_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
