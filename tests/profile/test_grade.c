/* Roads with elevation and grade (docs/models.md sections 2.5 and 2.6): every model runs on a
 * road at any height and on a long straight grade, where its effective height follows the
 * road, h(x) = q(x) + an offset that depends on the grade alone (exactly R0*(sqrt(1 + s^2) - 1)
 * for the rigid disc, the super-ellipse's support function for the cam, 0 for the point
 * contact and the network), tending to the level-ground 0 as s -> 0; streaming over a graded
 * road equals the whole road; and the road's local level (tirenv_profile_level), the exact
 * opening of the ground, against a dense brute force and on the shapes it is defined for.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tirenv/rng.h"

#include "tirenv/tirenv.h"
#include "tirenv/nn.h"
#include "tirenv/profile_file.h"

/* ---- the local level -------------------------------------------------------------------- */

/* E(y) = min of the ground over [y - a, y + a]: its ends and the vertices inside. */
static double window_min(const tirenv_profile *p, double y, double a)
{
    const size_t n = tirenv_profile_size(p);
    const double *xs = tirenv_profile_x(p), *zs = tirenv_profile_z(p);
    double e = fmin(tirenv_profile_height(p, y - a), tirenv_profile_height(p, y + a));
    for (size_t k = 0; k < n; ++k)
        if (xs[k] > y - a && xs[k] < y + a)
            e = fmin(e, zs[k]);
    return e;
}

/* The opening by its definition, on m + 1 window positions: a lower bound on the exact one
 * that falls short by at most the ground's steepest slope times the step (E is that
 * Lipschitz wherever it is continuous, and approached from its continuous side at a wall). */
static double brute_level(const tirenv_profile *p, double width, double x, size_t m)
{
    const double a = 0.5 * width;
    double best = -INFINITY;
    for (size_t j = 0; j <= m; ++j)
        best = fmax(best, window_min(p, x - a + width * (double)j / (double)m, a));
    return best;
}

/* Random polylines with walls, steep and shallow segments, at random positions: the exact
 * level is never below the brute force and exceeds it by at most the slope bound. */
static void test_level_brute_force(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 2718);
    enum { N = 60, M = 4000 };
    for (int trial = 0; trial < 40; ++trial) {
        double x[N], z[N], slope_max = 0;
        x[0] = 0;
        z[0] = 0.1 * tirenv_rng_uniform(rng);
        for (size_t k = 1; k < N; ++k) {
            const int wall = tirenv_rng_uniform(rng) < 0.15 && x[k - 1] != (k >= 2 ? x[k - 2] : -1);
            x[k] = x[k - 1] + (wall ? 0 : 0.005 + 0.12 * tirenv_rng_uniform(rng));
            z[k] = z[k - 1] + 0.08 * (tirenv_rng_uniform(rng) - 0.5);
            if (!wall)
                slope_max = fmax(slope_max, fabs(z[k] - z[k - 1]) / (x[k] - x[k - 1]));
        }
        tirenv_profile *p = tirenv_profile_alloc(N, x, z);
        assert_non_null(p);
        const double width = 0.1 + 0.9 * tirenv_rng_uniform(rng);
        for (int q = 0; q < 15; ++q) {
            const double xq = -0.5 + (x[N - 1] + 1.0) * tirenv_rng_uniform(rng);
            const double exact = tirenv_profile_level(p, width, xq);
            const double brute = brute_level(p, width, xq, M);
            const double step = width / M;
            if (!(exact >= brute - 1e-12 && exact <= brute + slope_max * step + 1e-12))
                fail_msg("trial %d: width %g m at x %g m: exact %.12g, brute force %.12g "
                         "(slack %.3g)", trial, width, xq, exact, brute, slope_max * step);
        }
        tirenv_profile_free(p);
    }
    tirenv_rng_free(rng);
}

/* The shapes the level is for: a grade is its own level; a cleat shorter than the segment
 * lies above the level of the ground around it; a plateau longer than it is followed, a pit
 * is followed down; bad arguments give NaN. */
static void test_level_shapes(void **state)
{
    (void)state;
    const double W = 1.36;
    const double gx[2] = {-10, 10}, gz[2] = {2.1 - 0.7, 2.1 + 0.7};  /* 7 % up, at 2.1 m */
    tirenv_profile *grade = tirenv_profile_alloc(2, gx, gz);
    for (double x = -8; x <= 8; x += 0.37)
        assert_near(tirenv_profile_level(grade, W, x), 2.1 + 0.07 * x, 1e-12, 0);
    /* Off the ends the ground is flat; across the corners of the ramp the level is the ground
     * (a monotone profile is its own opening). */
    assert_near(tirenv_profile_level(grade, W, -10.2), 1.4, 1e-12, 0);
    assert_near(tirenv_profile_level(grade, W, 10.3), 2.8, 1e-12, 0);
    assert_near(tirenv_profile_level(grade, W, 9.9), 2.1 + 0.07 * 9.9, 1e-12, 0);
    tirenv_profile *cleat = tirenv_profile_cleat(0.3, 0.1);
    for (double x = -1; x <= 1; x += 0.05)
        assert_true(tirenv_profile_level(cleat, W, x) == 0);
    const double px[4] = {-1, -1, 1, 1}, pz[4] = {0, 0.1, 0.1, 0};  /* 2 m plateau */
    tirenv_profile *plateau = tirenv_profile_alloc(4, px, pz);
    assert_true(tirenv_profile_level(plateau, W, 0) == 0.1);
    assert_true(tirenv_profile_level(plateau, W, 1 - 0.5 * W) == 0.1);
    assert_true(tirenv_profile_level(plateau, W, 1.01) == 0);
    const double hx[4] = {-0.2, -0.2, 0.2, 0.2}, hz[4] = {0, -0.05, -0.05, 0};  /* a pit */
    tirenv_profile *pit = tirenv_profile_alloc(4, hx, hz);
    assert_true(tirenv_profile_level(pit, W, 0) == -0.05);
    assert_true(isnan(tirenv_profile_level(pit, 0, 0)));
    assert_true(isnan(tirenv_profile_level(pit, -1, 0)));
    assert_true(isnan(tirenv_profile_level(pit, W, NAN)));
    tirenv_profile_free(grade);
    tirenv_profile_free(cleat);
    tirenv_profile_free(plateau);
    tirenv_profile_free(pit);
}

/* ---- models on a grade ------------------------------------------------------------------ */

static tirenv_model *model_named(const char *name, const tirenv_tire *tire, tirenv_nn *nn)
{
    const tirenv_model_type *type = tirenv_model_type_find(name);
    tirenv_model *m = tirenv_model_alloc(type, tire);
    assert_non_null(m);
    tirenv_diag d;
    if (tirenv_model_type_flags(type) & TIRENV_MODEL_NEEDS_NETWORK) {
        assert_int_equal(tirenv_model_set_network(m, nn, 0, &d), TIRENV_OK);
        /* A ramp has no obstacle the made-up network was trained on; the closed forms hold
         * for its extrapolation all the same. */
        tirenv_model_set_extrapolate(m, 1);
    }
    return m;
}

/* Level at e from x = -X to the ramp's foot, the grade s over [-L/2, L/2] (through e at 0),
 * level beyond. */
static tirenv_profile *ramp(double e, double s, double L)
{
    const double x[4] = {-L, -0.5 * L, 0.5 * L, L};
    const double z[4] = {e - 0.5 * s * L, e - 0.5 * s * L, e + 0.5 * s * L, e + 0.5 * s * L};
    tirenv_profile *p = tirenv_profile_alloc(4, x, z);
    assert_non_null(p);
    return p;
}

/* The offset h(x) - q(x) of a model on the grade s at elevation e, at n positions of the
 * ramp's middle (more than the reach from its corners); its spread over them in *spread. */
static double grade_offset(tirenv_model *m, double load, double e, double s, size_t n,
                           double *spread)
{
    const double L = 12.0;
    tirenv_profile *p = ramp(e, s, L);
    tirenv_diag d;
    assert_int_equal(tirenv_model_set(m, p, load, &d), TIRENV_OK);
    const double r = tirenv_model_reach(m), a = -0.5 * L + 1.2 * r, b = 0.5 * L - 1.2 * r;
    double lo = INFINITY, hi = -INFINITY, sum = 0;
    for (size_t k = 0; k < n; ++k) {
        const double x = a + (b - a) * (double)k / (double)(n - 1);
        tirenv_point pt;
        if (tirenv_model_eval(m, x, &pt, &d))
            fail_msg("%s on the grade %g at %g m: %s", tirenv_model_name(m), s, e, d.message);
        const double off = pt.h - tirenv_profile_height(p, x);
        lo = fmin(lo, off);
        hi = fmax(hi, off);
        sum += off;
    }
    tirenv_profile_free(p);
    *spread = hi - lo;
    return sum / (double)n;
}

/* The closed forms: the rigid disc touches the line s at distance R0, so its centre stands
 * R0*sqrt(1 + s^2) above the road under it; the cam's lift over a straight segment is the
 * super-ellipse's support function b_e*((1 + m^p)^(1/p) - 1), m = |s| a_e/b_e, p = c_e/(c_e-1),
 * the same for both cams of the tandem, whose mean height is the road's under x; the point
 * contact and the network (whose baseline, the opening of the road, is the road itself on a
 * straight grade) follow the road. Exact to round-off at 2.1 m and at 250 m elevation. */
static void test_closed_forms(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    tirenv_nn *nn = tirenv_test_made_up_network(4242, 97);
    const double R0 = tire.springs.R0, a_e = tire.cam.length * R0, b_e = tire.cam.height * R0;
    const double c_e = tire.cam.order, p = c_e / (c_e - 1);
    const double grades[] = {-0.12, -0.03, 0.0, 0.0123, 0.05, 0.2};
    const double heights[] = {0.0, 2.1, 250.0};
    const char *names[] = {"rigid", "cam", "point", "nn"};
    for (size_t i = 0; i < 4; ++i) {
        tirenv_model *m = model_named(names[i], &tire, nn);
        tirenv_diag d;
        double G;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G, &d), TIRENV_OK);
        for (size_t g = 0; g < sizeof grades / sizeof grades[0]; ++g)
            for (size_t e = 0; e < sizeof heights / sizeof heights[0]; ++e) {
                const double s = grades[g], m_s = fabs(s) * a_e / b_e;
                double want = 0;
                if (strcmp(names[i], "rigid") == 0)
                    want = R0 * (sqrt(1 + s * s) - 1);
                else if (strcmp(names[i], "cam") == 0)
                    want = b_e * (pow(1 + pow(m_s, p), 1 / p) - 1);
                double spread;
                const double off = grade_offset(m, G, heights[e], s, 25, &spread);
                const double tol = 1e-12 * (1 + heights[e]) + 1e-12;
                if (fabs(off - want) > tol || spread > tol)
                    fail_msg("%s, grade %g at %g m: offset %.15g m, closed form %.15g m, spread "
                             "%.3g m", names[i], s, heights[e], off, want, spread);
            }
        tirenv_model_free(m);
    }
    tirenv_nn_free(nn);
}

/* The springs model and the ring have no closed form on a grade; what they must do: an offset
 * the same all along the ramp (within the equilibrium's tolerance, section 11.3), the same
 * for s and -s (their elements are symmetric), the same at any elevation, and tending to 0 as
 * s -> 0 like s^2 (an even, smooth function of s vanishing at 0). */
static void test_deformable_on_grade(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    const char *names[] = {"springs", "ring"};
    for (size_t i = 0; i < 2; ++i) {
        tirenv_model *m = model_named(names[i], &tire, NULL);
        const size_t n = i ? 5 : 15;
        tirenv_diag d;
        double G;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G, &d), TIRENV_OK);
        double spread, off[4];
        const double s[4] = {0.01, 0.02, 0.04, 0.08};
        for (size_t k = 0; k < 4; ++k) {
            off[k] = grade_offset(m, G, 2.1, s[k], n, &spread);
            assert_true(spread < 2e-9);
            const double down = grade_offset(m, G, 2.1, -s[k], n, &spread);
            assert_true(spread < 2e-9);
            assert_near(down, off[k], 2e-9, 0);
            const double low = grade_offset(m, G, 0.0, s[k], n, &spread);
            assert_near(low, off[k], 2e-9, 0);
            print_message("%s: grade %.2f: offset %.6e m (rigid disc %.6e m)\n", names[i],
                          s[k], off[k], tire.springs.R0 * (sqrt(1 + s[k] * s[k]) - 1));
        }
        assert_true(off[0] > 0);
        for (size_t k = 1; k < 4; ++k) {
            const double ratio = off[k] / off[k - 1];  /* 4 for s^2 */
            assert_true(ratio > 3.5 && ratio < 4.5);
        }
        tirenv_model_free(m);
    }
}

/* ---- streaming a graded road ------------------------------------------------------------ */

typedef struct {
    const tirenv_profile *p;
    size_t k;
} array_source;

static int next_vertex(void *ctx, double *x, double *z, int *got, tirenv_diag *diag)
{
    (void)diag;
    array_source *s = ctx;
    *got = s->k < tirenv_profile_size(s->p);
    if (*got) {
        *x = tirenv_profile_x(s->p)[s->k];
        *z = tirenv_profile_z(s->p)[s->k];
        s->k++;
    }
    return TIRENV_OK;
}

/* A 60 m road climbing 6 m (10 %) in undulations, from 2.1 m: streamed in windows of the
 * reach, it gives the whole road's points bit for bit (rigid, cam, springs). */
static void test_stream_graded(void **state)
{
    (void)state;
    enum { NV = 3001 };
    double *x = malloc(NV * sizeof *x), *z = malloc(NV * sizeof *z);
    assert_true(x && z);
    for (size_t k = 0; k < NV; ++k) {
        x[k] = 0.02 * (double)k;
        z[k] = 2.1 + 0.1 * x[k] + 0.01 * sin(3.1 * x[k]) + 0.004 * sin(17.3 * x[k]);
    }
    tirenv_profile *p = tirenv_profile_alloc(NV, x, z);
    assert_non_null(p);
    const tirenv_tire tire = tirenv_tire_default();
    const char *names[] = {"rigid", "cam", "springs"};
    for (size_t i = 0; i < 3; ++i) {
        tirenv_model *m = model_named(names[i], &tire, NULL);
        tirenv_diag d;
        double G;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G, &d), TIRENV_OK);
        const double from = 1.0, to = 58.0, dx = 0.01;
        const size_t n = tirenv_positions_count(from, to, dx);
        tirenv_point *whole = malloc(n * sizeof *whole);
        tirenv_test_points c = {malloc(n * sizeof *c.pt), 0, n, 0};
        assert_true(whole && c.pt);
        double *xs = malloc(n * sizeof *xs);
        for (size_t k = 0; k < n; ++k)
            xs[k] = from + (double)k * dx;
        assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_envelope(m, n, xs, whole, NULL, &d), TIRENV_OK);
        array_source src = {p, 0};
        tirenv_stream_stats st;
        if (tirenv_model_stream(m, next_vertex, &src, from, to, dx, G, tirenv_test_keep_point, &c, &st, &d))
            fail_msg("%s: %s", names[i], d.message);
        assert_int_equal(c.n, n);
        assert_true(st.window_max < NV / 4);
        for (size_t k = 0; k < n; ++k)
            if (memcmp(&whole[k].z, &c.pt[k].z, sizeof(double)) ||
                memcmp(&whole[k].h, &c.pt[k].h, sizeof(double)) ||
                whole[k].iterations != c.pt[k].iterations)
                fail_msg("%s at x %g m: whole h %.17g, streamed %.17g", names[i], xs[k],
                         whole[k].h, c.pt[k].h);
        free(xs);
        free(whole);
        free(c.pt);
        tirenv_model_free(m);
    }
    tirenv_profile_free(p);
    free(x);
    free(z);
}

/* The check that the hub clears the ground is local: a road 40 m high is no reason to refuse
 * anything, a wall within the reach of a position is. */
static void test_clearance_is_local(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_tire_default();
    const double R0 = tire.springs.R0;
    const double x[6] = {0, 5, 5, 6, 6, 12}, z[6] = {40, 40, 40 + 1.5 * R0, 40 + 1.5 * R0, 40, 40};
    tirenv_profile *p = tirenv_profile_alloc(6, x, z);
    tirenv_model *m = model_named("springs", &tire, NULL);
    tirenv_diag d;
    assert_int_equal(tirenv_model_set(m, p, 10000, &d), TIRENV_OK);
    tirenv_point pt;
    assert_int_equal(tirenv_model_eval(m, 2.0, &pt, &d), TIRENV_OK);
    assert_near(pt.h, 40.0, 1e-9, 0);
    assert_int_equal(tirenv_model_eval(m, 5.0 - 0.9 * R0, &pt, &d), TIRENV_ERANGE);
    assert_string_equal(d.field, "profile");
    assert_non_null(strstr(d.message, "x = "));
    assert_int_equal(tirenv_model_eval(m, 9.0, &pt, &d), TIRENV_OK);
    tirenv_model_free(m);
    tirenv_profile_free(p);
}

/* Chrono's designed twist track Horstwalde (250 m, up to 1.5 m high along its reference line,
 * read by the OpenCRG reader): the rigid disc and the cam run it whole and follow its height,
 * (the disc never below the road under it); relative to the local level what is left are
 * the track's features shorter than the tire (up to 0.15 m away from its drop). The track
 * drops some 0.73 m within 0.1 m at u = 150.2 to 150.3 m: the springs model runs up to it and
 * is refused just past the edge (from 150.82 m), where its hub would pass under it, and runs
 * again beyond R0 from it (docs/models.md section 2.5). */
static void test_horstwalde(void **state)
{
    (void)state;
    char path[600];
    snprintf(path, sizeof path, "%s/crg/Horstwalde.crg", TIRENV_SAMPLES);
    tirenv_profile *p = NULL;
    tirenv_diag d;
    if (tirenv_profile_read_file(path, NULL, &p, &d))
        fail_msg("%s: %s (the sample files beside the repository are needed)", path, d.message);
    double first, last;
    tirenv_profile_extent(p, &first, &last);
    assert_true(last - first > 249);
    const tirenv_tire tire = tirenv_tire_default();
    const double R0 = tire.springs.R0;
    const char *names[] = {"rigid", "cam"};
    for (size_t i = 0; i < 2; ++i) {
        tirenv_model *m = model_named(names[i], &tire, NULL);
        double G;
        assert_int_equal(tirenv_model_load_for_contact_length(m, 0.33, &G, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_set(m, p, G, &d), TIRENV_OK);
        double top = 0, worst_level = 0;
        for (double x = first; x <= last; x += 0.05) {
            tirenv_point pt;
            if (tirenv_model_eval(m, x, &pt, &d))
                fail_msg("%s at %g m: %s", names[i], x, d.message);
            top = fmax(top, pt.h);
            const double q = tirenv_profile_height(p, x);
            if (i == 0)  /* the disc never sinks below the road under its centre */
                assert_true(pt.h >= q - 1e-9);
            const double rel = pt.h - tirenv_profile_level(p, 2 * R0, x);
            if (fabs(x - 150.3) > 2 * R0)  /* away from the drop */
                worst_level = fmax(worst_level, fabs(rel));
        }
        print_message("Horstwalde, %s: highest h %.4f m, |h - level| at most %.4f m away "
                      "from the drop\n",
                      names[i], top, worst_level);
        assert_true(top > 1.4 && top < 1.6);
        tirenv_model_free(m);
    }
    tirenv_model *s = model_named("springs", &tire, NULL);
    double G;
    assert_int_equal(tirenv_model_load_for_contact_length(s, 0.33, &G, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(s, p, G, &d), TIRENV_OK);
    tirenv_point pt;
    for (double x = 120.0; x <= 150.1; x += 0.1)
        if (tirenv_model_eval(s, x, &pt, &d))
            fail_msg("springs at %g m: %s", x, d.message);
    assert_int_equal(tirenv_model_eval(s, 150.85, &pt, &d), TIRENV_ERANGE);
    assert_string_equal(d.field, "profile");
    assert_int_equal(tirenv_model_eval(s, 151.0, &pt, &d), TIRENV_OK);
    tirenv_model_free(s);
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_level_brute_force),
        cmocka_unit_test(test_level_shapes),
        cmocka_unit_test(test_closed_forms),
        cmocka_unit_test(test_deformable_on_grade),
        cmocka_unit_test(test_stream_graded),
        cmocka_unit_test(test_clearance_is_local),
        cmocka_unit_test(test_horstwalde),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
