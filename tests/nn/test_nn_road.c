/* The empirical model over any profile (nn_road.h): the equivalent-cleat decomposition finds
 * a rectangular cleat exactly and reproduces tirenv_nn_envelope's curve for it; far-apart
 * cleats do not interact; the baseline follows plateaus and ramps; flat ground gives 0 and a
 * constant offset shifts h by it; over an ISO 8608 road h is finite, between the baseline and
 * the ground's highest point in reach, and continuous but for the network's own step where a
 * curve begins; pruning changes no bit; bad arguments fail with the right code.
 * SPDX-License-Identifier: Apache-2.0
 *
 * The network is the study's, trained on the embedded (simulated) data set: Levenberg-
 * Marquardt, seed 1, one restart (0.03 s; the curves only need to be a trained network's,
 * not the best one). Its trained ranges: x_N -0.25..1, l_c 0.28..0.43 m, H 0.025..0.1 m,
 * L 0.05..0.3 m; so the default opening is 0.45 m wide.
 *
 * Tolerances.
 *   CURVE_TOL 1e-11 m: h against tirenv_nn_envelope for the same cleat. The two take the same
 *     network inputs up to the round-off of the decomposition: the centroid is a sum of
 *     products (off by a few ulp of the centre, 4e-15 m at 17 m), the equivalent length an
 *     area over a height (a few ulp, 1e-16 m). Through x_N = 1 + |d|/x_0 (|x_0| > 0.17 m) and
 *     the network's slopes (|dy/dx_N| < 1 m, |dy/dL| < 1) that is below 1e-13 m; 1e-11 m
 *     leaves a factor 100.
 *   GEOM_TOL 1e-12 m: the obstacle's centre, ends and length against the cleat's (the same
 *     few ulp, on numbers up to 17 m).
 *   SLOPE_TOL 1e-6: the analytic slope against central differences of h with a 1e-7 m step.
 *     The library's dy/dx_N is a central difference of step 1e-5 in x_N (truncation below
 *     1e-9); the test's own difference has rounding error ulp(h)/1e-7 < 1e-10. Slopes are of
 *     order 0.1 to 1.
 *   Pruning must agree with the exhaustive evaluation bit for bit: memcmp. */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/tirenv.h"
#include "tirenv/train.h"

#define CURVE_TOL 1e-11
#define GEOM_TOL 1e-12
#define SLOPE_TOL 1e-6

static const double R0 = 0.68;  /* m: the data set's tire */

/* ---- fixtures (the network: tirenv_test_nn_setup) ------------------------------------ */

static tirenv_nn_road *build(const tirenv_nn *nn, double l_c, const tirenv_profile *p,
                             const tirenv_nn_road_settings *s)
{
    tirenv_nn_road *r = NULL;
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_nn_road_alloc(nn, R0, l_c, p, s, &r, &diag);
    if (status)
        print_error("tirenv_nn_road_alloc: %s: %s\n", diag.field, diag.message);
    assert_int_equal(status, TIRENV_OK);
    assert_non_null(r);
    return r;
}

static void eval(tirenv_nn_road *r, size_t n, const double x[], double h[], double slope[])
{
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    const int status = tirenv_nn_road_eval(r, n, x, h, slope, &diag);
    if (status)
        print_error("tirenv_nn_road_eval: %s\n", diag.message);
    assert_int_equal(status, TIRENV_OK);
}

/* A profile from vertex lists. */
static tirenv_profile *polyline(size_t n, const double x[], const double z[])
{
    tirenv_profile *p = tirenv_profile_alloc(n, x, z);
    assert_non_null(p);
    return p;
}

/* n positions x0 + i*dx. */
static double *positions(double x0, double dx, size_t n)
{
    double *x = malloc(n * sizeof *x);
    assert_non_null(x);
    for (size_t i = 0; i < n; ++i)
        x[i] = x0 + (double)i * dx;
    return x;
}

/* The single-cleat curve the decomposition must reproduce, for a cleat (L, H) centred at c on
 * ground at level base: base + the envelope, scaled below the trained heights, clipped to
 * [0, H]. L and H are clamped to the trained range as the decomposition does. */
static void cleat_curve(tirenv_nn *nn, double l_c, double L, double H, double c, double base,
                        size_t n, const double x[], double h[])
{
    double lo[TIRENV_NN_INPUTS], hi[TIRENV_NN_INPUTS];
    tirenv_nn_input_range(nn, lo, hi);
    const double H_net = fmin(fmax(H, lo[TIRENV_NN_HEIGHT]), hi[TIRENV_NN_HEIGHT]);
    const double L_net = fmin(fmax(L, lo[TIRENV_NN_LENGTH]), hi[TIRENV_NN_LENGTH]);
    const double scale = H < lo[TIRENV_NN_HEIGHT] ? H / lo[TIRENV_NN_HEIGHT] : 1.0;
    double *d = malloc(n * sizeof *d);
    assert_non_null(d);
    for (size_t i = 0; i < n; ++i)
        d[i] = x[i] - c;
    assert_int_equal(tirenv_nn_envelope(nn, R0, l_c, L_net, H_net, n, d, h, NULL), TIRENV_OK);
    for (size_t i = 0; i < n; ++i)
        h[i] = base + fmin(scale * h[i], H);
    free(d);
}

/* A class C road (tirenv road's generator), length m at dx m, seed. */
static tirenv_profile *iso_road(char road_class, double length, double dx, unsigned long seed)
{
    tirenv_road_settings s = tirenv_road_default();
    s.road_class = road_class;
    s.length = length;
    s.dx = dx;
    s.seed = seed;
    tirenv_profile *p = NULL;
    assert_int_equal(tirenv_road_iso8608(&s, &p, NULL), TIRENV_OK);
    return p;
}

/* ---- one cleat ------------------------------------------------------------------------ */

/* Cleats inside and outside the trained range, centred at 0 and far from it: one obstacle
 * with the cleat's geometry, and h is the single-cleat curve everywhere. */
static void test_single_cleat(void **state)
{
    tirenv_nn *nn = *state;
    static const struct {
        double L, H, l_c, c;        /* m */
        size_t below, above_H, below_L, above_L;  /* expected range counts */
    } cases[] = {
        {0.2385, 0.0615, 0.33, 0.0, 0, 0, 0, 0},    /* walls off the resampling grid */
        {0.1, 0.075, 0.38, 17.3, 0, 0, 0, 0},       /* far from the origin */
        {0.3, 0.1, 0.28, -2.15, 0, 0, 0, 0},        /* longest and highest trained */
        {0.05, 0.025, 0.28, 0.0, 0, 0, 0, 0},       /* shortest and lowest trained */
        {0.1873, 0.0123, 0.33, 0.61, 1, 0, 0, 0},   /* below H_min: scaled */
        {0.1411, 0.1502, 0.33, 0.0, 0, 1, 0, 0},    /* above H_max: clamped */
        {0.0312, 0.0533, 0.38, 0.0, 0, 0, 1, 0},    /* below L_min: clamped */
        {0.3719, 0.0444, 0.38, 3.3, 0, 0, 0, 1},    /* above L_max (< W): clamped */
    };
    enum { N = 2401 };
    for (size_t t = 0; t < sizeof cases / sizeof cases[0]; ++t) {
        const double L = cases[t].L, H = cases[t].H, c = cases[t].c, l_c = cases[t].l_c;
        const double xv[] = {c - L / 2, c - L / 2, c + L / 2, c + L / 2};
        const double zv[] = {0, H, H, 0};
        tirenv_profile *p = polyline(4, xv, zv);
        tirenv_nn_road *r = build(nn, l_c, p, NULL);
        const tirenv_nn_road_info in = tirenv_nn_road_info_of(r);
        assert_int_equal(in.obstacles, 1);
        assert_int_equal(in.height_below, cases[t].below);
        assert_int_equal(in.height_above, cases[t].above_H);
        assert_int_equal(in.length_below, cases[t].below_L);
        assert_int_equal(in.length_above, cases[t].above_L);
        assert_near(in.width, 0.45, 1e-15, 0);
        const tirenv_nn_obstacle *o = tirenv_nn_road_obstacles(r);
        assert_true(o->H == H);         /* q - b with b exactly 0 */
        assert_true(o->top == H);
        assert_true(o->base == 0);
        assert_near(o->L, L, GEOM_TOL, 0);
        assert_near(o->c, c, GEOM_TOL, 0);
        assert_near(o->x_lo, c - L / 2, GEOM_TOL, 0);
        assert_near(o->x_hi, c + L / 2, GEOM_TOL, 0);

        double *x = positions(c - 1.2, 0.001, N);
        double h[N], slope[N], expect[N];
        eval(r, N, x, h, slope);
        cleat_curve(nn, l_c, L, H, c, 0, N, x, expect);
        double peak = 0;
        for (size_t i = 0; i < N; ++i) {
            assert_near(h[i], expect[i], CURVE_TOL, 0);
            peak = fmax(peak, h[i]);
            if (fabs(x[i] - c) > o->reach + 1e-9)
                assert_true(h[i] == 0 && slope[i] == 0);
        }
        print_message("cleat %g x %g m at l_c %g m: peak h %.3f mm\n", L, H, l_c, 1e3 * peak);
        assert_true(peak > 0.1 * H);  /* a curve, not zeros */
        tirenv_nn_road_free(r);
        tirenv_profile_free(p);
        free(x);
    }
    tirenv_nn_road_free(NULL);
}

/* The slope is the derivative of h: against central differences wherever h is smooth (away
 * from the axis of symmetry, where the mirrored curve has a corner, and the start of the
 * curve, where the network's first value is a step). */
static void test_slope(void **state)
{
    tirenv_nn *nn = *state;
    const double L = 0.2385, H = 0.0615, c = 0.4137, l_c = 0.33, dx = 1e-7;
    const double xv[] = {c - L / 2, c - L / 2, c + L / 2, c + L / 2};
    const double zv[] = {0, H, H, 0};
    tirenv_profile *p = polyline(4, xv, zv);
    tirenv_nn_road *r = build(nn, l_c, p, NULL);
    enum { N = 1201 };
    double *x = positions(c - 0.6, 0.001, N);
    double h[N], slope[N], hp[N], hm[N], xp[N], xm[N];
    for (size_t i = 0; i < N; ++i) {
        xp[i] = x[i] + dx;
        xm[i] = x[i] - dx;
    }
    eval(r, N, x, h, slope);
    eval(r, N, xp, hp, NULL);
    eval(r, N, xm, hm, NULL);
    const double reach = tirenv_nn_road_obstacles(r)->reach;
    size_t compared = 0;
    double steepest = 0;
    for (size_t i = 0; i < N; ++i) {
        const double d = fabs(x[i] - c);
        if (d < 1e-3 || fabs(d - reach) < 1e-3 || !(h[i] > 1e-4))
            continue;
        assert_near(slope[i], (hp[i] - hm[i]) / (2 * dx), SLOPE_TOL, 0);
        steepest = fmax(steepest, fabs(slope[i]));
        ++compared;
    }
    assert_true(compared > 300);
    assert_true(steepest > 0.05);  /* not a flat comparison */
    tirenv_nn_road_free(r);
    tirenv_profile_free(p);
    free(x);
}

/* ---- several cleats, plateaus, ramps ---------------------------------------------------- */

/* Two cleats 3.6 m apart, more than twice any reach: two obstacles, and around each h is its
 * own single-cleat curve. */
static void test_two_cleats_far(void **state)
{
    tirenv_nn *nn = *state;
    const double L1 = 0.2385, H1 = 0.0615, c1 = -1.7, L2 = 0.1, H2 = 0.075, c2 = 1.9;
    const double l_c = 0.33;
    const double xv[] = {c1 - L1 / 2, c1 - L1 / 2, c1 + L1 / 2, c1 + L1 / 2,
                         c2 - L2 / 2, c2 - L2 / 2, c2 + L2 / 2, c2 + L2 / 2};
    const double zv[] = {0, H1, H1, 0, 0, H2, H2, 0};
    tirenv_profile *p = polyline(8, xv, zv);
    tirenv_nn_road *r = build(nn, l_c, p, NULL);
    assert_int_equal(tirenv_nn_road_info_of(r).obstacles, 2);
    const tirenv_nn_obstacle *o = tirenv_nn_road_obstacles(r);
    assert_true(o[0].reach + o[1].reach < c2 - c1);
    assert_near(o[0].c, c1, GEOM_TOL, 0);
    assert_near(o[1].c, c2, GEOM_TOL, 0);
    enum { N = 3601 };
    double *x = positions(-1.8 + c1, 0.001, N);  /* -3.5 .. 0.1 */
    double h[N], e[N];
    eval(r, N, x, h, NULL);
    cleat_curve(nn, l_c, L1, H1, c1, 0, N, x, e);
    for (size_t i = 0; i < N; ++i)
        assert_near(h[i], e[i], CURVE_TOL, 0);
    free(x);
    x = positions(0.1, 0.001, N);  /* 0.1 .. 3.7 */
    eval(r, N, x, h, NULL);
    cleat_curve(nn, l_c, L2, H2, c2, 0, N, x, e);
    double peak = 0;
    for (size_t i = 0; i < N; ++i) {
        assert_near(h[i], e[i], CURVE_TOL, 0);
        peak = fmax(peak, h[i]);
    }
    assert_true(peak > 0.3 * H2);
    tirenv_nn_road_free(r);
    tirenv_profile_free(p);
    free(x);
}

/* A cleat on a plateau 4.9987 m long (one wall off the resampling grid): the baseline is the
 * plateau, exactly, and the ground either side; the walls leave no sliver obstacle (the
 * samples include the vertices); h over the cleat is the plateau plus its curve. */
static void test_plateau(void **state)
{
    tirenv_nn *nn = *state;
    const double P = 0.0437, a = -2.5, b = 2.4987, L = 0.15, H = 0.05, c = 0.35, l_c = 0.33;
    const double xv[] = {a, a, c - L / 2, c - L / 2, c + L / 2, c + L / 2, b, b};
    const double zv[] = {0, P, P, P + H, P + H, P, P, 0};
    tirenv_profile *p = polyline(8, xv, zv);
    tirenv_nn_road *r = build(nn, l_c, p, NULL);
    assert_int_equal(tirenv_nn_road_info_of(r).obstacles, 1);
    const tirenv_nn_obstacle *o = tirenv_nn_road_obstacles(r);
    assert_true(o->H == H || fabs(o->H - H) <= 1e-16);  /* (P + H) - P */
    assert_near(o->L, L, GEOM_TOL, 0);
    assert_near(o->c, c, GEOM_TOL, 0);
    assert_near(o->base, P, 1e-15, 0);  /* a mean of P over the run */
    assert_true(o->top == P + H);
    for (double x = a + 0.001; x < b; x += 0.0173)
        assert_true(tirenv_nn_road_baseline(r, x) == P);
    assert_true(tirenv_nn_road_baseline(r, a - 0.01) == 0);
    assert_true(tirenv_nn_road_baseline(r, b + 0.01) == 0);
    enum { N = 2001 };
    double *x = positions(c - 1, 0.001, N);
    double h[N], e[N];
    eval(r, N, x, h, NULL);
    cleat_curve(nn, l_c, L, H, c, P, N, x, e);
    for (size_t i = 0; i < N; ++i)
        assert_near(h[i], e[i], CURVE_TOL, 0);
    tirenv_nn_road_free(r);
    tirenv_profile_free(p);
    free(x);
}

/* A cleat on a 2 % ramp longer than the opening, its top parallel to the ramp. The baseline
 * follows the ramp (the opening of a rising profile is itself) except under the cleat, where
 * the cleat's drop at its higher foot makes the opening flat at that foot's level (within
 * one spacing's rise, s*ds: the samples at a wall carry its top). So the obstacle is the
 * cleat measured from its higher foot: height H (within s*ds), area H*L - s*L^2/2, top
 * exact. Beyond the cleat's reach the tire follows the ramp exactly; in reach h lies
 * between the baseline and the top. */
static void test_ramp(void **state)
{
    tirenv_nn *nn = *state;
    const double s = 0.02, x0 = -3, x1 = 3, L = 0.2, H = 0.06, c = 0.4, l_c = 0.38;
    const double ds = tirenv_nn_road_default().spacing, sampling = s * ds * (1 + 1e-9);
#define RAMP(x) (s * ((x)-x0))
    const double xv[] = {x0, c - L / 2, c - L / 2, c + L / 2, c + L / 2, x1};
    const double zv[] = {0, RAMP(c - L / 2), RAMP(c - L / 2) + H, RAMP(c + L / 2) + H,
                         RAMP(c + L / 2), RAMP(x1)};
    const double top = zv[3];
    tirenv_profile *p = polyline(6, xv, zv);
    tirenv_nn_road *r = build(nn, l_c, p, NULL);
    assert_int_equal(tirenv_nn_road_info_of(r).obstacles, 1);
    const tirenv_nn_obstacle *o = tirenv_nn_road_obstacles(r);
    assert_near(o->H, H, sampling, 0);
    assert_true(o->top == top);
    assert_near(o->L, L - s * L * L / (2 * H), 2 * sampling * L / H, 0);
    assert_near(o->base, RAMP(c + L / 2), sampling, 0);
    for (double x = x0 + 0.001; x < x1; x += 0.0173) {
        const double b = tirenv_nn_road_baseline(r, x);
        if (x < c - L / 2 - ds || x > c + L / 2)
            assert_near(b, RAMP(x), 1e-15, 0);
        else if (x > c - L / 2)
            assert_near(b, RAMP(c + L / 2), sampling, 0);
    }
    enum { N = 5001 };
    double *x = positions(x0 + 0.5, 0.001, N);
    double h[N];
    eval(r, N, x, h, NULL);
    double peak = 0;
    for (size_t i = 0; i < N; ++i) {
        if (fabs(x[i] - o->c) > o->reach) {
            assert_near(h[i], RAMP(x[i]), 1e-15, 0);
        } else {
            assert_true(h[i] >= tirenv_nn_road_baseline(r, x[i]) && h[i] <= top);
            peak = fmax(peak, h[i] - RAMP(x[i]));
        }
    }
    assert_true(peak > 0.3 * H);
#undef RAMP
    tirenv_nn_road_free(r);
    tirenv_profile_free(p);
    free(x);
}

/* ---- flat ground, offsets, roads -------------------------------------------------------- */

/* Flat ground: no obstacle, h = 0 and slope 0 everywhere, inside and beyond the profile. And
 * a single vertex is a valid (flat) profile. */
static void test_flat(void **state)
{
    tirenv_nn *nn = *state;
    const double xv[] = {-5, 5}, zv[] = {0, 0};
    for (size_t nv = 1; nv <= 2; ++nv) {
        tirenv_profile *p = polyline(nv, xv + 2 - nv, zv);
        tirenv_nn_road *r = build(nn, 0.33, p, NULL);
        assert_int_equal(tirenv_nn_road_info_of(r).obstacles, 0);
        assert_true(tirenv_nn_road_info_of(r).reach == 0);
        enum { N = 1001 };
        double *x = positions(-7.3, 0.0147, N);
        double h[N], slope[N];
        eval(r, N, x, h, slope);
        for (size_t i = 0; i < N; ++i)
            assert_true(h[i] == 0 && slope[i] == 0);
        tirenv_nn_road_free(r);
        tirenv_profile_free(p);
        free(x);
    }
}

/* Raising a whole road by 0.8137 m raises h by as much and changes nothing else. */
static void test_offset(void **state)
{
    tirenv_nn *nn = *state;
    const double offset = 0.8137;
    tirenv_profile *p = iso_road('C', 30, 0.01, 5);
    const size_t nv = tirenv_profile_size(p);
    double *zs = malloc(nv * sizeof *zs);
    assert_non_null(zs);
    for (size_t k = 0; k < nv; ++k)
        zs[k] = tirenv_profile_z(p)[k] + offset;
    tirenv_profile *q = polyline(nv, tirenv_profile_x(p), zs);
    tirenv_nn_road *r = build(nn, 0.33, p, NULL), *rq = build(nn, 0.33, q, NULL);
    assert_int_equal(tirenv_nn_road_info_of(r).obstacles,
                     tirenv_nn_road_info_of(rq).obstacles);
    assert_true(tirenv_nn_road_info_of(r).obstacles > 10);
    enum { N = 3301 };
    double *x = positions(-1, 0.01, N);
    double h[N], hq[N], s[N], sq[N];
    eval(r, N, x, h, s);
    eval(rq, N, x, hq, sq);
    for (size_t i = 0; i < N; ++i) {
        assert_near(hq[i], h[i] + offset, 1e-12, 0);
        assert_near(sq[i], s[i], 1e-6, 0);
    }
    tirenv_nn_road_free(r);
    tirenv_nn_road_free(rq);
    tirenv_profile_free(p);
    tirenv_profile_free(q);
    free(zs);
    free(x);
}

/* An ISO 8608 class C road, 200 m at 10 mm, swept at 0.1 mm: h and slope finite; h at or
 * above the baseline and at most the highest ground within the reported reach; and h steps
 * between neighbours by no more than its slope allows plus the network's own first value
 * (where an obstacle's curve begins: h is 0 before x_N_min and y(x_N_min) at it, as in
 * tirenv_nn_envelope), scaled as the obstacle's curve is. */
static void test_iso_road(void **state)
{
    tirenv_nn *nn = *state;
    const double l_c = 0.33, dx = 1e-4;
    tirenv_profile *p = iso_road('C', 200, 0.01, 7);
    tirenv_nn_road *r = build(nn, l_c, p, NULL);
    const tirenv_nn_road_info in = tirenv_nn_road_info_of(r);
    print_message("class C, 200 m: %zu obstacles (%zu below H_min, %zu lengths clamped), "
                  "reach %.3f m\n", in.obstacles, in.height_below,
                  in.length_below + in.length_above, in.reach);
    assert_true(in.obstacles > 100);
    /* The largest step the network's curve starts with, over the obstacles. */
    double lo[TIRENV_NN_INPUTS], hi[TIRENV_NN_INPUTS], edge = 0;
    tirenv_nn_input_range(nn, lo, hi);
    const tirenv_nn_obstacle *ob = tirenv_nn_road_obstacles(r);
    for (size_t k = 0; k < in.obstacles; ++k) {
        const double u[TIRENV_NN_INPUTS] = {lo[TIRENV_NN_X_N], l_c, ob[k].H_net, ob[k].L_net};
        edge = fmax(edge, fmin(ob[k].H, ob[k].H / ob[k].H_net * fmax(0, tirenv_nn_run(nn, u))));
    }
    const size_t n = 2000001;
    double *x = positions(-1, dx, n), *h = malloc(n * sizeof *h), *s = malloc(n * sizeof *s);
    assert_non_null(h);
    assert_non_null(s);
    eval(r, n, x, h, s);
    double s_max = 0, step_max = 0, lift_max = 0;
    for (size_t i = 0; i < n; ++i) {
        assert_true(isfinite(h[i]) && isfinite(s[i]));
        const double b = tirenv_nn_road_baseline(r, x[i]);
        assert_true(h[i] >= b);
        lift_max = fmax(lift_max, h[i] - b);
        s_max = fmax(s_max, fabs(s[i]));
        if (i % 7 == 0) {  /* the ground bound is a search: a seventh of the positions */
            const double w = in.reach + in.spacing;
            assert_true(h[i] <= tirenv_profile_max_height(p, x[i] - w, x[i] + w) + 1e-12);
        }
        if (i > 0)
            step_max = fmax(step_max, fabs(h[i] - h[i - 1]));
    }
    print_message("largest lift above the baseline %.3f mm, slope %.3f, step between 0.1 mm "
                  "neighbours %.4f mm (the network's first value %.4f mm)\n", 1e3 * lift_max,
                  s_max, 1e3 * step_max, 1e3 * edge);
    assert_true(lift_max > 1e-3);  /* the obstacles do lift the tire */
    assert_true(step_max <= 1.01 * s_max * dx + edge);
    tirenv_nn_road_free(r);
    tirenv_profile_free(p);
    free(x);
    free(h);
    free(s);
}

/* Pruning and the window change no bit: against every obstacle at every position, on a
 * class C road at 10 mm and a rougher class E road at 2 mm with eps 0 (many small
 * obstacles per window), positions forwards, backwards and shuffled. */
static void test_pruning_exact(void **state)
{
    tirenv_nn *nn = *state;
    static const struct {
        char road_class;
        double dx, eps;
        unsigned long seed;
    } cases[] = {{'C', 0.01, 1e-6, 11}, {'E', 0.002, 0, 12}};
    for (size_t t = 0; t < sizeof cases / sizeof cases[0]; ++t) {
        tirenv_profile *p = iso_road(cases[t].road_class, 30, cases[t].dx, cases[t].seed);
        tirenv_nn_road_settings s = tirenv_nn_road_default();
        s.eps = cases[t].eps;
        tirenv_nn_road *fast = build(nn, 0.38, p, &s);
        s.prune = 0;
        tirenv_nn_road *slow = build(nn, 0.38, p, &s);
        print_message("class %c at %g mm: %zu obstacles\n", cases[t].road_class,
                      1e3 * cases[t].dx, tirenv_nn_road_info_of(fast).obstacles);
        assert_true(tirenv_nn_road_info_of(fast).obstacles > 20);
        enum { N = 10667 };
        double *x = positions(-1, 0.003, N);
        double h0[N], s0[N], h1[N], s1[N], xr[N], hr[N], sr[N];
        eval(slow, N, x, h0, s0);
        eval(fast, N, x, h1, s1);
        assert_memory_equal(h0, h1, sizeof h0);
        assert_memory_equal(s0, s1, sizeof s0);
        size_t lifted = 0;
        for (size_t i = 0; i < N; ++i)
            lifted += h0[i] > tirenv_nn_road_baseline(slow, x[i]);
        assert_true(lifted > N / 2);  /* obstacles decide most positions */
        /* Backwards, then a fixed shuffle (a full-period LCG modulo N). */
        for (size_t i = 0; i < N; ++i)
            xr[i] = x[N - 1 - i];
        eval(fast, N, xr, hr, sr);
        for (size_t i = 0; i < N; ++i)
            assert_true(hr[i] == h0[N - 1 - i] && sr[i] == s0[N - 1 - i]);
        size_t k = 17;
        for (size_t i = 0; i < N; ++i) {
            k = (k * 7919 + 104729) % N;
            xr[i] = x[k];
            eval(fast, 1, &xr[i], &hr[i], &sr[i]);
            assert_true(hr[i] == h0[k] && sr[i] == s0[k]);
        }
        tirenv_nn_road_free(fast);
        tirenv_nn_road_free(slow);
        tirenv_profile_free(p);
        free(x);
    }
}

/* ---- settings and errors -------------------------------------------------------------- */

static void test_defaults(void **state)
{
    (void)state;
    const tirenv_nn_road_settings s = tirenv_nn_road_default();
    assert_true(s.width_factor == 1.5 && s.width == 0 && s.spacing == 0.005 &&
                s.eps == 1e-6 && s.prune == 1);
}

/* A cleat longer than the opening is part of the baseline, not an obstacle; an explicit
 * width narrower than it makes it one again. */
static void test_width(void **state)
{
    tirenv_nn *nn = *state;
    tirenv_profile *p = tirenv_profile_cleat(0.5, 0.05);
    tirenv_nn_road *r = build(nn, 0.33, p, NULL);
    assert_int_equal(tirenv_nn_road_info_of(r).obstacles, 0);
    assert_true(tirenv_nn_road_baseline(r, 0.1) == 0.05);
    tirenv_nn_road_free(r);
    tirenv_nn_road_settings s = tirenv_nn_road_default();
    s.width = 0.6;
    r = build(nn, 0.33, p, &s);
    assert_int_equal(tirenv_nn_road_info_of(r).obstacles, 1);
    assert_true(tirenv_nn_road_info_of(r).width == 0.6);
    assert_true(tirenv_nn_road_info_of(r).length_above == 1);
    tirenv_nn_road_free(r);
    tirenv_profile_free(p);
}

static void expect_alloc_error(const tirenv_nn *nn, double R0_, double l_c,
                               const tirenv_profile *p, const tirenv_nn_road_settings *s,
                               int status, const char *field)
{
    tirenv_nn_road *r = (tirenv_nn_road *)&r;  /* must come back NULL */
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_road_alloc(nn, R0_, l_c, p, s, &r, &diag), status);
    assert_null(r);
    assert_true(diag.message[0] != '\0');
    if (field)
        assert_string_equal(diag.field, field);
}

static void test_errors(void **state)
{
    tirenv_nn *nn = *state;
    tirenv_profile *p = tirenv_profile_cleat(0.2, 0.05);
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_road_alloc(nn, R0, 0.33, p, NULL, NULL, &diag), TIRENV_EINVAL);
    expect_alloc_error(NULL, R0, 0.33, p, NULL, TIRENV_EINVAL, "network");
    expect_alloc_error(nn, R0, 0.33, NULL, NULL, TIRENV_EINVAL, "profile");
    expect_alloc_error(nn, 0, 0.33, p, NULL, TIRENV_EINVAL, NULL);
    expect_alloc_error(nn, NAN, 0.33, p, NULL, TIRENV_EINVAL, NULL);
    expect_alloc_error(nn, R0, 2 * R0, p, NULL, TIRENV_EINVAL, NULL);
    expect_alloc_error(nn, R0, NAN, p, NULL, TIRENV_EINVAL, NULL);
    expect_alloc_error(nn, R0, -0.1, p, NULL, TIRENV_EINVAL, NULL);
    static const struct {
        double width_factor, width, spacing, eps;
        int prune;
        const char *field;
    } bad[] = {
        {1.5, 0, 0, 1e-6, 1, "spacing"},        {1.5, 0, -0.005, 1e-6, 1, "spacing"},
        {1.5, 0, NAN, 1e-6, 1, "spacing"},      {1.5, 0, 0.005, -1e-6, 1, "eps"},
        {1.5, 0, 0.005, INFINITY, 1, "eps"},    {1.5, -0.4, 0.005, 1e-6, 1, "width"},
        {1.0, 0, 0.005, 1e-6, 1, "width_factor"}, {NAN, 0, 0.005, 1e-6, 1, "width_factor"},
        {1.5, 0, 0.005, 1e-6, 2, "prune"},      {1.5, 0, 1e-12, 1e-6, 1, "spacing"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        tirenv_nn_road_settings s = {.width_factor = bad[k].width_factor,
                                     .width = bad[k].width, .spacing = bad[k].spacing,
                                     .eps = bad[k].eps, .prune = bad[k].prune};
        expect_alloc_error(nn, R0, 0.33, p, &s, TIRENV_EINVAL, bad[k].field);
    }

    /* A network of the wrong input count. */
    tirenv_nn_topology t = tirenv_nn_topology_default();
    t.size[0] = 3;
    tirenv_nn *three = tirenv_nn_alloc(&t);
    assert_non_null(three);
    expect_alloc_error(three, R0, 0.33, p, NULL, TIRENV_EINVAL, "topology");
    tirenv_nn_free(three);

    /* A fresh network has no trained ranges: no x_N range, then no length range. */
    t = tirenv_nn_topology_default();
    tirenv_nn *fresh = tirenv_nn_alloc(&t);
    assert_non_null(fresh);
    expect_alloc_error(fresh, R0, 0.33, p, NULL, TIRENV_EINVAL, "x_N");
    const double lo[] = {-0.25, -INFINITY, -INFINITY, -INFINITY};
    const double hi[] = {1, INFINITY, INFINITY, INFINITY};
    assert_int_equal(tirenv_nn_set_input_range(fresh, lo, hi, NULL), TIRENV_OK);
    expect_alloc_error(fresh, R0, 0.33, p, NULL, TIRENV_EINVAL, "width");
    /* With a width it works; a cleat up to the chord height is then out of the domain. */
    tirenv_nn_road_settings s = tirenv_nn_road_default();
    s.width = 0.45;
    tirenv_nn_road *r = build(fresh, 0.33, p, &s);
    tirenv_nn_road_free(r);
    tirenv_profile *tall = tirenv_profile_cleat(0.2, 0.67);
    expect_alloc_error(fresh, R0, 0.33, tall, &s, TIRENV_ERANGE, "obstacle_height_m");
    tirenv_profile_free(tall);
    tirenv_nn_free(fresh);

    /* Evaluation. */
    r = build(nn, 0.33, p, NULL);
    double x[3] = {0.1, NAN, 0.2}, h[3] = {-1, -1, -1};
    tirenv_diag_clear(&diag);
    assert_int_equal(tirenv_nn_road_eval(r, 3, x, h, NULL, &diag), TIRENV_EINVAL);
    assert_int_equal(diag.line, 2);
    assert_true(h[0] == -1 && h[1] == -1 && h[2] == -1);  /* nothing written */
    x[1] = INFINITY;
    assert_int_equal(tirenv_nn_road_eval(r, 3, x, h, NULL, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_nn_road_eval(r, 1, NULL, h, NULL, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_nn_road_eval(r, 1, x, NULL, NULL, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_nn_road_eval(NULL, 1, x, h, NULL, NULL), TIRENV_EINVAL);
    assert_int_equal(tirenv_nn_road_eval(r, 0, NULL, NULL, NULL, NULL), TIRENV_OK);
    tirenv_nn_road_free(r);
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_single_cleat),
        cmocka_unit_test(test_slope),
        cmocka_unit_test(test_two_cleats_far),
        cmocka_unit_test(test_plateau),
        cmocka_unit_test(test_ramp),
        cmocka_unit_test(test_flat),
        cmocka_unit_test(test_offset),
        cmocka_unit_test(test_iso_road),
        cmocka_unit_test(test_pruning_exact),
        cmocka_unit_test(test_width),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, tirenv_test_nn_setup, tirenv_test_nn_teardown);
}
