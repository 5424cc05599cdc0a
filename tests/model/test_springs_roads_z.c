/* SPDX-License-Identifier: Apache-2.0 */
/* The springs model's F_z is continuous in the centre height z over every sample road of the
 * tests (tests/data/samples: OpenCRG and RDF roads, and the test data's CSV roads) and the
 * embedded data sets' cleats (docs/models.md section 4.8): at seeded positions, random and
 * exactly on vertices, F_z on a fine grid of z around the equilibrium changes between
 * neighbouring heights by no more than its slopes there account for, and on a vertex F_z at
 * x and x +- 1e-12 m agree (a wall under the centre: section 4.3). The paper's rays
 * (CONTACT = 'rays', section 4.6) jump where a ray passes a corner: the same scans find that
 * on the cleats, which shows they can fail. About 1.5 s. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "testutil.h"
#include "tirenv/rng.h"
#include "tirenv/tirenv.h"

/* Heights 2 K + 1 around the equilibrium, DZ apart: a fine grid (5 um, +-0.1 mm) and a wide
 * one (0.1 mm, +-2 mm), each step judged by the slopes at its ends. */
enum { K = 20 };
static const double DZ[2] = {5e-6, 1e-4}; /* m */

typedef struct {
    double worst;          /* the largest change of F_z beyond its slopes', N */
    double x, z;           /* where (the step's lower height), m */
    size_t steps, positions, refused;
    size_t cuts;           /* steps cut in parts (jump_across) */
    double worst_x;        /* on a vertex, the largest |F_z(x +- 1e-12 m) - F_z(x)| at the
                            * equilibrium's z, N */
    double x_x;            /* where, m */
} scan;

/* The change of F_z over one step beyond what its slopes at both ends allow: their mean times
 * dz, up to half their difference (F_z between the tangents at the ends: a kink where an
 * element's contact begins or ends, or any slope that changes one way). */
static double beyond_slopes(double F0, double k0, double F1, double k1, double dz)
{
    return fabs(F1 - F0 - 0.5 * (k0 + k1) * dz) - 0.5 * fabs(k1 - k0) * dz;
}

/* A step over which F_z's slope changes both ways (contacts that begin and end within it, on
 * the wide grid) passes the test of its ends only in parts: the step beyond REFINE N is cut in
 * 8 until each part passes, or is narrower than 1e-9 m, where what is left is a jump. The
 * largest change beyond the slopes of the parts. */
static const double REFINE = 1e-4; /* N */

/* What counts as a jump, N: 1e-3 N is 1e-7 of the loads (4 to 30 kN), 50 times the largest
 * change beyond the slopes measured over every road and cleat (1.95e-5 N, printed by the
 * test), and 1e-5 of the smallest jump the rays make here (97 N). */
static const double JUMP = 1e-3;
static double jump_across(tirenv_springs *s, const tirenv_profile *p, double x, double z0,
                          double F0, double k0, double z1, double F1, double k1, size_t *cuts)
{
    const double b = beyond_slopes(F0, k0, F1, k1, z1 - z0);
    if (b <= REFINE || z1 - z0 < 1e-9)
        return b;
    ++*cuts;
    double worst = 0, Fa = F0, ka = k0, za = z0;
    for (int i = 1; i <= 8; ++i) {
        const double zb = i < 8 ? z0 + (z1 - z0) * i / 8 : z1;
        double fx, Fb = F1, kb = k1;
        tirenv_diag diag;
        if (i < 8 && tirenv_springs_forces(s, p, x, zb, &fx, &Fb, &kb, NULL, &diag))
            fail_msg("x = %.17g m, z = %.17g m: %s", x, zb, diag.message);
        worst = fmax(worst, jump_across(s, p, x, za, Fa, ka, zb, Fb, kb, cuts));
        za = zb, Fa = Fb, ka = kb;
    }
    return worst;
}

/* Scans F_z(z) at x around the model's equilibrium there (the centre u above its hub: the
 * sidewall in series, section 4.9). A position the model refuses (ground that reaches the
 * centre, section 2.5) is counted and skipped. */
static void scan_at(tirenv_model *m, tirenv_springs *s, double u, const tirenv_profile *p,
                    double x, int on_vertex, scan *sc)
{
    tirenv_point eq;
    tirenv_diag diag;
    if (tirenv_model_eval(m, x, &eq, &diag)) {
        ++sc->refused;
        return;
    }
    ++sc->positions;
    const double z_c = eq.z + u;
    if (on_vertex) { /* the vertex's own x against its neighbours' (a wall under x) */
        double F[3];
        for (int i = 0; i < 3; ++i) {
            double fx, kz;
            const double xi = x + (i - 1) * 1e-12;
            if (tirenv_springs_forces(s, p, xi, z_c, &fx, &F[i], &kz, NULL, &diag))
                fail_msg("x = %.17g m, z = %.17g m: %s", xi, z_c, diag.message);
        }
        const double d = fmax(fabs(F[0] - F[1]), fabs(F[2] - F[1]));
        if (d > sc->worst_x)
            sc->worst_x = d, sc->x_x = x;
    }
    for (int g = 0; g < 2; ++g) {
        double F0 = NAN, k0 = NAN, z0 = NAN;
        for (int j = -K; j <= K; ++j) {
            const double z = z_c + DZ[g] * j;
            double fx, fz, kz;
            const int st = tirenv_springs_forces(s, p, x, z, &fx, &fz, &kz, NULL, &diag);
            if (st)
                fail_msg("x = %.17g m, z = %.17g m: %s", x, z, diag.message);
            if (j > -K) {
                const double b = jump_across(s, p, x, z0, F0, k0, z, fz, kz, &sc->cuts);
                if (b > sc->worst)
                    sc->worst = b, sc->x = x, sc->z = z0;
                ++sc->steps;
            }
            F0 = fz;
            k0 = kz;
            z0 = z;
        }
    }
}

/* n_rand positions within R0 of random vertices that are not on level ground, and n_vert
 * exactly on such vertices, drawn with rng. */
static void scan_road(tirenv_model *m, tirenv_springs *s, double u, double R0,
                      const tirenv_profile *p, tirenv_rng *rng, size_t n_rand, size_t n_vert,
                      scan *sc)
{
    const size_t n = tirenv_profile_size(p);
    const double *px = tirenv_profile_x(p), *pz = tirenv_profile_z(p);
    /* The vertices where the ground bends (a wall's ends among them). */
    enum { CAP = 4096 };
    size_t live[CAP], n_live = 0, seen = 0;
    for (size_t k = 1; k + 1 < n; ++k) {
        if ((pz[k] - pz[k - 1]) * (px[k + 1] - px[k]) ==
            (pz[k + 1] - pz[k]) * (px[k] - px[k - 1]))
            continue;  /* no bend */
        const size_t j = seen++ < CAP ? n_live++ : tirenv_rng_uniform_int(rng, seen);
        if (j < CAP)  /* a uniform sample of CAP of them */
            live[j] = k;
    }
    if (n_live == 0)
        return;
    for (size_t i = 0; i < n_rand + n_vert; ++i) {
        const size_t k = live[tirenv_rng_uniform_int(rng, n_live)];
        const double x = i < n_rand ? px[k] + R0 * (2 * tirenv_rng_uniform(rng) - 1) : px[k];
        scan_at(m, s, u, p, x, i >= n_rand, sc);
    }
}

typedef struct {
    tirenv_tire tire;
    tirenv_model *m;
    tirenv_springs *s;
    double u;              /* the sidewall's deflection at the load, m */
} springs_at;

static void springs_set(springs_at *a, const tirenv_tire *t, const tirenv_profile *p,
                        double G)
{
    a->tire = *t;
    a->m = tirenv_model_alloc(tirenv_model_springs, t);
    a->s = tirenv_springs_alloc(&t->springs);
    assert_true(a->m && a->s);
    tirenv_diag d;
    assert_int_equal(tirenv_model_set(a->m, p, G, &d), TIRENV_OK);
    a->u = t->springs.k_s > 0 ? fmax(0, G - t->springs.F_s0) / t->springs.k_s : 0;
}

static void springs_done(springs_at *a)
{
    tirenv_springs_free(a->s);
    tirenv_model_free(a->m);
}

static void report(const char *what, const scan *sc)
{
    print_message("%-44s on vertices: largest |F_z(x +- 1e-12 m) - F_z(x)| %.3g N at "
                  "x = %.17g m\n", what, sc->worst_x, sc->x_x);
    print_message("%-44s %4zu positions (%zu refused), %6zu steps (%zu cut): largest change "
                  "beyond the slopes %.3g N at x = %.17g m, z = %.17g m\n",
                  what, sc->positions, sc->refused, sc->steps, sc->cuts, sc->worst, sc->x,
                  sc->z);
}

static tirenv_tire tire_named(const char *file)
{
    char path[600];
    snprintf(path, sizeof path, "%s/%s", TIRENV_DATA_DIR, file);
    tirenv_tire t = tirenv_tire_default();
    tirenv_diag d;
    if (tirenv_tir_read(path, &t, &d))
        fail_msg("%s: %s", path, d.message);
    return t;
}

/* The sample roads, each with the default tire at 0.33 m of contact and the 205/60R15 at
 * 4000 N. */
static void test_sample_roads(void **state)
{
    (void)state;
    static const char *const roads[] = {
        "samples/crg/Barber.crg", "samples/crg/Horstwalde.crg",
        "samples/crg/halfround_6in.crg", "samples/crg/handmade_arc.crg",
        "samples/crg/handmade_banked.crg", "samples/crg/handmade_circle.crg",
        "samples/crg/handmade_curved.crg", "samples/crg/handmade_curved_banked_sloped.crg",
        "samples/crg/handmade_curved_minimalist.crg", "samples/crg/handmade_sloped.crg",
        "samples/crg/handmade_sloped_opts.crg", "samples/crg/handmade_straight.crg",
        "samples/crg/handmade_straight_double.crg",
        "samples/crg/handmade_straight_minimalist.crg", "samples/crg/handmade_vtest.crg",
        "samples/rdf/plateau.rdf", "placed_bump.crg",
        "profile_good.csv", "profile_crlf.csv"};
    const tirenv_tire tires[2] = {tire_named("tires/default.tir"),
                                  tire_named("tires/205-60R15-mfswift.tir")};
    tirenv_rng *rng = tirenv_rng_alloc(16);
    assert_non_null(rng);
    scan all = {0};
    for (size_t r = 0; r < sizeof roads / sizeof roads[0]; ++r) {
        char path[600];
        snprintf(path, sizeof path, "%s/%s", TIRENV_TEST_DATA, roads[r]);
        tirenv_profile *p = NULL;
        tirenv_diag d;
        if (tirenv_profile_read_file(path, NULL, &p, &d)) {
            print_message("%s: not read (%s)\n", roads[r], d.message);
            continue;
        }
        for (int k = 0; k < 2; ++k) {
            springs_at a;
            double G = 4000;
            if (k == 0) {
                tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tires[0]);
                assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G, &d),
                                 TIRENV_OK);
                tirenv_model_free(m);
            }
            springs_set(&a, &tires[k], p, G);
            scan sc = {0};
            scan_road(a.m, a.s, a.u, tires[k].springs.R0, p, rng, 60, 40, &sc);
            char what[128];
            snprintf(what, sizeof what, "%s, %s", roads[r] + (roads[r][0] == 's' ? 8 : 0),
                     k ? "205/60R15" : "default");
            report(what, &sc);
            if (sc.worst > all.worst)
                all.worst = sc.worst, all.x = sc.x, all.z = sc.z;
            all.positions += sc.positions;
            all.refused += sc.refused;
            all.steps += sc.steps;
            all.cuts += sc.cuts;
            if (sc.worst_x > all.worst_x)
                all.worst_x = sc.worst_x, all.x_x = sc.x_x;
            springs_done(&a);
        }
        tirenv_profile_free(p);
    }
    report("all sample roads", &all);
    assert_true(all.positions > 3000);
    assert_true(all.worst <= JUMP);
    assert_true(all.worst_x <= JUMP);
    tirenv_rng_free(rng);
}

/* The embedded data sets' cleats with each design's tire at each case's contact length, the
 * continuous contact and the paper's rays. */
static void test_dataset_cleats(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(17);
    assert_non_null(rng);
    scan all[2];
    memset(all, 0, sizeof all);
    for (const tirenv_design *const *dz = tirenv_designs(); *dz; ++dz) {
        const tirenv_design *ds = *dz;
        for (int c = 0; c < 2; ++c) {
            tirenv_tire t = tire_named(ds->tire_file);
            t.springs.contact = c ? TIRENV_SPRINGS_RAYS : TIRENV_SPRINGS_CONTINUOUS;
            scan per = {0};
            for (size_t i = 0; i < ds->n_cases; ++i) {
                const tirenv_case_design *cs = &ds->cases[i];
                tirenv_profile *p = tirenv_profile_cleat(cs->L, cs->H);
                assert_non_null(p);
                tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &t);
                double G;
                tirenv_diag d;
                assert_int_equal(tirenv_model_load_for_contact_length(m, cs->contact_length,
                                                                      &G, &d),
                                 TIRENV_OK);
                tirenv_model_free(m);
                springs_at a;
                springs_set(&a, &t, p, G);
                scan_road(a.m, a.s, a.u, t.springs.R0, p, rng, 10, 4, &per);
                springs_done(&a);
                tirenv_profile_free(p);
            }
            char what[128];
            snprintf(what, sizeof what, "data set %s cleats, %s", ds->name,
                     c ? "rays" : "continuous");
            report(what, &per);
            if (per.worst > all[c].worst)
                all[c].worst = per.worst, all[c].x = per.x, all[c].z = per.z;
            all[c].positions += per.positions;
            all[c].steps += per.steps;
            all[c].cuts += per.cuts;
            if (per.worst_x > all[c].worst_x)
                all[c].worst_x = per.worst_x, all[c].x_x = per.x_x;
        }
    }
    assert_true(all[0].positions > 500);
    assert_true(all[0].worst <= JUMP);
    assert_true(all[0].worst_x <= JUMP);
    assert_true(all[1].worst > 1);    /* the rays jump in z, and in x at a wall under the */
    assert_true(all[1].worst_x > 1);  /* centre: the scans can fail */
    tirenv_rng_free(rng);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sample_roads),
        cmocka_unit_test(test_dataset_cleats),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
