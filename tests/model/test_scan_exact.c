/* The pruned scans of the rigid disc (block maxima, docs/models.md section 3) and of the elliptical
 * cam (docs/models.md section 7) against the plain scans they replace, on long random polylines and
 * roads: equal bit for bit, contact point included.
 * SPDX-License-Identifier: Apache-2.0
 *
 * Exact equality is the contract, not a tolerance: the pruning only skips candidates strictly
 * below the final best, and ties resolve as in the plain scan's order (the rigid disc keeps
 * that order; the cam ranks its candidates by it), so every candidate the plain scan computes
 * the winner from is computed by the same operations. The cam's sweep state (the floor
 * table, the tangency memo, the track of the last position) must change no bit either, in
 * any order of positions and across changes of profile. */
#include "testutil.h"

#include "tirenv/rng.h"
#include <math.h>
#include <stdlib.h>

#include "tirenv/profile.h"
#include "tirenv/cam.h"
#include "tirenv/rigid.h"
#include "tirenv/road.h"
#include "model/cam_impl.h"
#include "model/rigid_impl.h"
#include "profile/profile_impl.h"

/* The plain scan, as rigid.c had it before the block maxima: every vertex and every sloped
 * segment's tangency within [x - R0, x + R0], left to right, plus the flat extensions. */
static double plain_rigid(size_t n, const double xs[], const double zs[], double R0, double x,
                          double *px, double *pz)
{
    double z_c = -INFINITY, p_x = NAN, p_z = NAN;
#define CONSIDER(Z, X, P)                                                                    \
    do {                                                                                     \
        if ((Z) > z_c) {                                                                     \
            z_c = (Z);                                                                       \
            p_x = (X);                                                                       \
            p_z = (P);                                                                       \
        }                                                                                    \
    } while (0)
    if (x <= xs[0])
        CONSIDER(zs[0] + R0, x, zs[0]);
    if (x >= xs[n - 1])
        CONSIDER(zs[n - 1] + R0, x, zs[n - 1]);
    const double x_lo = x - R0, x_hi = x + R0;
    size_t k0 = 0;
    while (k0 + 1 < n && xs[k0 + 1] <= x_lo)
        k0++;
    for (size_t k = k0; k < n && xs[k] <= x_hi; k++) {
        if (xs[k] >= x_lo) {
            const double u = x - xs[k];
            CONSIDER(zs[k] + sqrt(fmax(0.0, (R0 - u) * (R0 + u))), xs[k], zs[k]);
        }
        if (k + 1 == n || !(xs[k + 1] > xs[k]))
            continue;
        const double dx = xs[k + 1] - xs[k], dz = zs[k + 1] - zs[k];
        const double len = hypot(dx, dz);
        const double P_x = x + R0 * (dz / len);
        if (P_x > xs[k] && P_x < xs[k + 1]) {
            const double P_z = zs[k] + dz * ((P_x - xs[k]) / dx);
            CONSIDER(P_z + R0 * (dx / len), P_x, P_z);
        }
    }
#undef CONSIDER
    *px = p_x;
    *pz = p_z;
    return z_c;
}

/* A random polyline of n vertices: spacing 0 (a wall, never three at one x), 1 mm or up to
 * 30 mm, and with steep set now and then 1e-7 m (a near-vertical segment); heights a random
 * walk with occasional jumps and flat runs, so that ties and walls both occur. */
static tirenv_profile *random_polyline_steep(tirenv_rng *rng, size_t n, int steep, double *x_end)
{
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    assert_non_null(x);
    assert_non_null(z);
    x[0] = -1.379;
    z[0] = 0.0;
    for (size_t k = 1; k < n; k++) {
        const double r = tirenv_rng_uniform(rng);
        const int wall_ok = k < 2 || x[k - 1] != x[k - 2];
        x[k] = x[k - 1] + (r < 0.05 && wall_ok ? 0.0
                           : steep && r < 0.08 ? 1e-7
                           : r < 0.3 ? 0.001 : 0.03 * r);
        const double s = tirenv_rng_uniform(rng);
        z[k] = s < 0.2 ? z[k - 1] : z[k - 1] + (s < 0.25 ? 0.2 : 0.01) * (s - 0.6);
    }
    tirenv_profile *p = tirenv_profile_alloc(n, x, z);
    assert_non_null(p);
    *x_end = x[n - 1];
    free(x);
    free(z);
    return p;
}

static tirenv_profile *random_polyline(tirenv_rng *rng, size_t n, double *x_end)
{
    return random_polyline_steep(rng, n, 0, x_end);
}

/* A smoother random polyline: spacing uniform in (0.1, 1) dx_max, the slope a random walk
 * (steps up to slope_step, now and then a kink), so that convex and concave stretches put
 * the cam's tangency on segments some way from x, not only next to it. */
static tirenv_profile *random_smooth(tirenv_rng *rng, size_t n, double dx_max, double slope_step)
{
    double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z);
    assert_non_null(x);
    assert_non_null(z);
    double slope = 0.0;
    x[0] = -0.9173;
    z[0] = 0.0;
    for (size_t k = 1; k < n; k++) {
        const double r = tirenv_rng_uniform(rng);
        x[k] = x[k - 1] + dx_max * (0.1 + 0.9 * tirenv_rng_uniform(rng));
        slope += slope_step * (2.0 * tirenv_rng_uniform(rng) - 1.0) * (r < 0.03 ? 20.0 : 1.0);
        slope = fmax(-1.5, fmin(1.5, slope));
        z[k] = z[k - 1] + slope * (x[k] - x[k - 1]);
    }
    tirenv_profile *p = tirenv_profile_alloc(n, x, z);
    assert_non_null(p);
    free(x);
    free(z);
    return p;
}

static void test_rigid_equals_plain(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 2385);
    static const double radii[] = {0.6837, 0.0213, 2.385};
    for (size_t trial = 0; trial < 6; trial++) {
        double x_end;
        tirenv_profile *p = random_polyline(rng, 3000 + 1000 * trial, &x_end);
        const size_t n = tirenv_profile_size(p);
        const double *xs = tirenv_profile_x(p), *zs = tirenv_profile_z(p);
        const double R0 = radii[trial % 3];
        size_t hint = n / 2;
        for (size_t i = 0; i < 4000; i++) {
            /* Uniform over the profile and beyond both ends, and exactly at vertices. */
            const double x = i % 4 == 0 ? xs[tirenv_rng_uniform_int(rng, n)]
                                        : xs[0] - 3.0 + (x_end - xs[0] + 6.0) *
                                                            tirenv_rng_uniform(rng);
            double px, pz, px_ref, pz_ref;
            const double z = tirenv_rigid_height(p, R0, x, &px, &pz);
            const double z_ref = plain_rigid(n, xs, zs, R0, x, &px_ref, &pz_ref);
            if (z != z_ref || px != px_ref || pz != pz_ref)
                fail_msg("trial %zu, R0 %g, x = %.17g: z %.17g px %.17g pz %.17g, plain scan "
                         "z %.17g px %.17g pz %.17g", trial, R0, x, z, px, pz, z_ref, px_ref,
                         pz_ref);
            /* The models' hinted search, from the last position's segment (random jumps: a
             * stale hint), must give the same bits. */
            double px_h, pz_h;
            if (tirenv_rigid__height_hint(p, R0, x, &hint, &px_h, &pz_h) != z || px_h != px ||
                pz_h != pz)
                fail_msg("trial %zu, x = %.17g: the hinted search differs", trial, x);
        }
        tirenv_profile_free(p);
    }
    tirenv_rng_free(rng);
}

/* The cam's touching height over a vertex at t = |u|/a_e, and over a sloped segment's
 * tangency point, by the same operations as cam.c, without any pruning. */
static double plain_edge(double b_e, double c_e, double t)
{
    if (t <= 0.0)
        return 0.0;
    const double tc = pow(t, c_e);
    return b_e * (pow(1.0 - tc, 1.0 / c_e) - 1.0);
}

static int plain_tangency(double a_e, double b_e, double c_e, double x, double x_k, double z_k,
                          double x_k1, double s, double *Z, double *p_x)
{
    const double inv_c = 1.0 / c_e, inv_c1 = 1.0 / (c_e - 1.0), p = c_e / (c_e - 1.0);
    const double m = fabs(s) * (a_e / b_e);
    const double lm = log(m);
    double t, rise_m1;
    if (m < 1.0) {
        const double k = exp(lm * inv_c1), j = k * m;
        const double L = log1p(j), P = exp(-inv_c * L);
        t = k * P;
        rise_m1 = j * P + expm1(-inv_c * L);
    } else {
        const double j = exp(-lm * p), L = log1p(j), P = exp(-inv_c * L);
        t = P;
        rise_m1 = m * (1.0 + j) * P - 1.0;
    }
    const double xi = s > 0 ? x + a_e * t : x - a_e * t;
    if (!(xi > x_k && xi < x_k1))
        return 0;
    *Z = z_k + s * (x - x_k) + b_e * rise_m1;
    *p_x = xi;
    return 1;
}

/* The cam's lift as a plain scan in cam.c's order: the ground under x, the vertices within
 * reach nearest first on each side, then every sloped segment between them. */
static double plain_cam(size_t n, const double xs[], const double zs[],
                        const tirenv_cam_shape *cam, double x, double *px, double *pz)
{
    const double a_e = cam->a_e, b_e = cam->b_e, c_e = cam->c_e, inv_a = 1.0 / a_e;
    size_t k_x = 0;
    while (k_x + 1 < n && xs[k_x + 1] <= x)
        k_x++;
    double q_x;
    if (x < xs[0])
        q_x = zs[0];
    else if (x == xs[k_x] && k_x >= 1 && xs[k_x - 1] == x)
        q_x = fmax(zs[k_x - 1], zs[k_x]);
    else if (k_x == n - 1)
        q_x = zs[n - 1];
    else
        q_x = zs[k_x] + (zs[k_x + 1] - zs[k_x]) * ((x - xs[k_x]) / (xs[k_x + 1] - xs[k_x]));
    double z_c = q_x, p_x = x, p_z = q_x;
#define CONSIDER(Z, X, P)                                                                    \
    do {                                                                                     \
        if ((Z) > z_c) {                                                                     \
            z_c = (Z);                                                                       \
            p_x = (X);                                                                       \
            p_z = (P);                                                                       \
        }                                                                                    \
    } while (0)
    size_t k_left = 0, k_right = n - 1;
    for (size_t k = k_x + 1; k-- > 0;) {
        const double t = fabs((x - xs[k]) * inv_a);
        if ((x - xs[k]) * inv_a > 1.0) {
            k_left = k;
            break;
        }
        CONSIDER(zs[k] + plain_edge(b_e, c_e, t), xs[k], zs[k]);
    }
    for (size_t k = k_x + 1; k < n; k++) {
        const double t = (xs[k] - x) * inv_a;
        if (t > 1.0) {
            k_right = k;
            break;
        }
        CONSIDER(zs[k] + plain_edge(b_e, c_e, fabs(t)), xs[k], zs[k]);
    }
    for (size_t k = k_left; k < k_right; k++) {
        const double x_a = xs[k], x_b = xs[k + 1], z_a = zs[k], z_b = zs[k + 1];
        if (!(x_b > x_a) || z_b == z_a)
            continue;
        const double s = (z_b - z_a) / (x_b - x_a);
        if (s > 0 ? !(x_b > x) : !(x_a < x))
            continue;
        double Z, xi;
        if (plain_tangency(a_e, b_e, c_e, x, x_a, z_a, x_b, s, &Z, &xi))
            CONSIDER(Z, xi, z_a + s * (xi - x_a));
    }
#undef CONSIDER
    *px = p_x;
    *pz = p_z;
    return z_c;
}

static void test_cam_equals_plain(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 4357);
    static const tirenv_cam_shape shapes[] = {
        {.a_e = 1.0245, .b_e = 0.6686, .c_e = 1.5257}, /* the default tire's */
        {.a_e = 0.0213, .b_e = 0.0417, .c_e = 1.13},
        {.a_e = 0.385, .b_e = 0.2385, .c_e = 3.7},
    };
    for (size_t trial = 0; trial < 6; trial++) {
        double x_end;
        tirenv_profile *p = random_polyline(rng, 2000 + 500 * trial, &x_end);
        const size_t n = tirenv_profile_size(p);
        const double *xs = tirenv_profile_x(p), *zs = tirenv_profile_z(p);
        const tirenv_cam_shape *cam = &shapes[trial % 3];
        for (size_t i = 0; i < 2000; i++) {
            const double x = i % 4 == 0 ? xs[tirenv_rng_uniform_int(rng, n)]
                                        : xs[0] - 3.0 + (x_end - xs[0] + 6.0) *
                                                            tirenv_rng_uniform(rng);
            double px, pz, px_ref, pz_ref;
            const double z = tirenv_cam_lift(p, cam, x, &px, &pz);
            const double z_ref = plain_cam(n, xs, zs, cam, x, &px_ref, &pz_ref);
            if (z != z_ref || px != px_ref || pz != pz_ref)
                fail_msg("trial %zu, x = %.17g: z %.17g px %.17g pz %.17g, plain scan "
                         "z %.17g px %.17g pz %.17g", trial, x, z, px, pz, z_ref, px_ref,
                         pz_ref);
        }
        tirenv_profile_free(p);
    }
    tirenv_rng_free(rng);
}

/* The shapes of the cam tests: the default tire's, small and pointed ones, squarer ones. */
static const tirenv_cam_shape cam_shapes[] = {
    {.a_e = 1.0245, .b_e = 0.6686, .c_e = 1.5257}, /* the default tire's */
    {.a_e = 0.0213, .b_e = 0.0417, .c_e = 1.13},
    {.a_e = 0.385, .b_e = 0.2385, .c_e = 3.7},
    {.a_e = 0.0917, .b_e = 0.0613, .c_e = 2.0},
    {.a_e = 0.1317, .b_e = 0.0417, .c_e = 6.13},
};
#define N_CAM_SHAPES (sizeof cam_shapes / sizeof cam_shapes[0])

/* The sweep's drop floor never exceeds the drop the lift computes, by the same operations as
 * plain_edge, at any t: on a fine grid in log t, at every step's lower end and the double just
 * below it (where the step changes), and at random t. That is what makes its pruning exact. */
static void test_cam_floor_below_drop(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 2713);
    tirenv_cam__sweep *sw = malloc(sizeof *sw);
    assert_non_null(sw);
    static const tirenv_cam_shape extra[] = {{0.7, 0.3, 1.0001}, {0.7, 0.3, 63.9}};
    for (size_t i = 0; i < N_CAM_SHAPES + 2; i++) {
        const tirenv_cam_shape *shape =
            i < N_CAM_SHAPES ? &cam_shapes[i] : &extra[i - N_CAM_SHAPES];
        tirenv_cam__geom g;
        assert_int_equal(tirenv_cam__geom_set(&g, shape), TIRENV_OK);
        tirenv_cam__sweep_init(sw, &g);
        size_t checked = 0, positive = 0;
        for (size_t j = 0; j < 400000; j++) {
            double t;
            if (j < 100000)
                t = pow(2.0, -40.0 + 40.0 * (double)j / 100000.0);
            else if (j < 100000 + 2 * TIRENV_CAM__FLOOR_N) {
                /* Step i's lower end is the double whose top 17 bits are i + i_0. */
                const size_t step = (j - 100000) / 2;
                const uint64_t bits = (((uint64_t)(1023 - TIRENV_CAM__FLOOR_OCTAVES) << 5) + step)
                                      << 47;
                memcpy(&t, &bits, sizeof t);
                if (j % 2)
                    t = nextafter(t, 0.0);
            } else
                t = tirenv_rng_uniform(rng);
            if (!(t <= 1.0))
                continue;
            const double floor = tirenv_cam__floor_at(&sw->floor, t);
            const double drop = -plain_edge(shape->b_e, shape->c_e, t);
            if (!(floor <= drop))
                fail_msg("c_e %g, t = %.17g: floor %.17g above the drop %.17g", shape->c_e, t,
                         floor, drop);
            checked += drop > 0;
            positive += drop > 0 && floor > 0;
        }
        /* Not vacuous: the floor prunes, and stays close to the drop (within about 2.2 % per
         * unit of c_e, see cam_impl.h; 3.4 % here) where the drop grows like t^c_e and is
         * clear of round-off. */
        assert_true(checked > 10000 && positive > checked - checked / 10);
        for (double t = 0.01; pow(t, shape->c_e) < 0.01; t += 0.0137) {
            if (pow(t, shape->c_e) < 1e-6)
                continue; /* a drop of round-off alone */
            const double drop = -plain_edge(shape->b_e, shape->c_e, t);
            const double floor = tirenv_cam__floor_at(&sw->floor, t);
            if (!(floor >= drop / (1.0 + 0.034 * shape->c_e)))
                fail_msg("c_e %g, t = %.6g: floor %.6g far below the drop %.6g", shape->c_e, t,
                         floor, drop);
        }
    }
    free(sw);
    tirenv_rng_free(rng);
}

/* One lift through the sweep path against the plain scan, bit for bit. */
static void check_sweep_lift(const tirenv_cam__geom *g, const tirenv_cam_shape *shape,
                             const tirenv_profile *p, double z_cap, tirenv_cam__sweep *sw,
                             tirenv_cam__track *tr, double x, const char *what)
{
    const size_t n = tirenv_profile_size(p);
    double px, pz, px_ref, pz_ref;
    const double z = tirenv_cam__lift(g, p, x, z_cap, sw, tr, &px, &pz);
    const double z_ref = plain_cam(n, tirenv_profile_x(p), tirenv_profile_z(p), shape, x,
                                   &px_ref, &pz_ref);
    if (memcmp(&z, &z_ref, sizeof z) || memcmp(&px, &px_ref, sizeof px) ||
        memcmp(&pz, &pz_ref, sizeof pz))
        fail_msg("%s, c_e %g, x = %.17g: z %.17g px %.17g pz %.17g, plain scan z %.17g px "
                 "%.17g pz %.17g", what, shape->c_e, x, z, px, pz, z_ref, px_ref, pz_ref);
}

static double profile_top(const tirenv_profile *p)
{
    const double *z = tirenv_profile_z(p);
    double top = z[0];
    for (size_t k = 1; k < tirenv_profile_size(p); k++)
        top = fmax(top, z[k]);
    return top;
}

/* The sealed profile's largest |z| and steepest slope, which bound the rounding the cam's
 * bar leaves room for (cam_lift.c's slack_of), are what they say. */
static void check_profile_extremes(const tirenv_profile *p)
{
    const double *x = tirenv_profile_x(p), *z = tirenv_profile_z(p);
    double z_abs = fabs(z[0]), slope = 0.0;
    for (size_t k = 1; k < tirenv_profile_size(p); k++) {
        z_abs = fmax(z_abs, fabs(z[k]));
        if (x[k] > x[k - 1])
            slope = fmax(slope, fabs(z[k] - z[k - 1]) / (x[k] - x[k - 1]));
    }
    assert_true(p->z_abs_max == z_abs && p->slope_max == slope);
}

/* The model's path (floor table, memo shared by two tracks, tracks kept between positions)
 * equals the plain scan bit for bit, contact point included (memcmp: -0 and +0 differ too):
 * sweeps forward, as the model runs them, with the two cams of a tandem sharing the memo;
 * backward; in random order and jumps with a stale track; on a profile switched under a
 * track of another one (the memo forgotten, as the model does on a new profile); on roads,
 * random polylines with walls, ties, and near-vertical segments (the slack of the bar), and
 * off both ends of the profile. */
static void test_cam_sweep_equals_plain(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(0);
    tirenv_rng_seed(rng, 8317);
    tirenv_cam__sweep *sw = malloc(sizeof *sw);
    assert_non_null(sw);
    tirenv_road_settings rs = tirenv_road_default();
    rs.length = 23.7;
    enum { N_PROFILES = 9 };
    tirenv_profile *profiles[N_PROFILES];
    assert_int_equal(tirenv_road_iso8608(&rs, &profiles[0], NULL), TIRENV_OK);
    rs.road_class = 'E';
    rs.length = 3.1;
    rs.dx = 0.001;
    rs.seed = 7;
    assert_int_equal(tirenv_road_iso8608(&rs, &profiles[1], NULL), TIRENV_OK);
    double x_end;
    profiles[2] = random_polyline_steep(rng, 1500, 0, &x_end);
    profiles[3] = random_polyline_steep(rng, 1500, 1, &x_end);
    profiles[4] = tirenv_profile_cleat(0.2931, 0.0743);
    profiles[5] = random_polyline_steep(rng, 3, 1, &x_end); /* shorter than any group */
    profiles[6] = random_smooth(rng, 700, 0.004, 0.02);
    profiles[7] = random_smooth(rng, 400, 0.02, 0.01);
    profiles[8] = random_smooth(rng, 300, 0.05, 0.05);
    for (size_t i = 0; i < N_PROFILES; i++) {
        assert_non_null(profiles[i]);
        check_profile_extremes(profiles[i]);
    }
    tirenv_cam__track front = {0}, rear = {0};
    for (size_t s = 0; s < N_CAM_SHAPES; s++) {
        const tirenv_cam_shape *shape = &cam_shapes[s];
        tirenv_cam__geom g;
        assert_int_equal(tirenv_cam__geom_set(&g, shape), TIRENV_OK);
        tirenv_cam__sweep_init(sw, &g);
        for (size_t i = 0; i < N_PROFILES; i++) {
            const tirenv_profile *p = profiles[i];
            const size_t n = tirenv_profile_size(p);
            const double *xs = tirenv_profile_x(p);
            const double x_lo = xs[0] - shape->a_e - 0.1, x_hi = xs[n - 1] + shape->a_e + 0.1;
            const double z_cap = i % 2 ? INFINITY : profile_top(p);
            /* The tracks come from the last profile and shape: stale, as the model's are not
             * (it resets them), to show that they need not be. */
            tirenv_cam__sweep_forget(sw);
            const size_t steps = 1200;
            const double dx = (x_hi - x_lo) / (double)steps, l_s = 0.1173;
            for (size_t k = 0; k <= steps; k++) { /* forward, two cams l_s apart */
                const double x = x_lo + dx * (double)k;
                check_sweep_lift(&g, shape, p, z_cap, sw, &front, x + 0.5 * l_s, "forward");
                check_sweep_lift(&g, shape, p, z_cap, sw, &rear, x - 0.5 * l_s, "forward");
            }
            for (size_t k = steps + 1; k-- > 0;) /* backward */
                check_sweep_lift(&g, shape, p, z_cap, sw, &front, x_lo + dx * (double)k,
                                 "backward");
            for (size_t k = 0; k < 600; k++) { /* random, and at vertices */
                const double x = k % 3 == 0 ? xs[tirenv_rng_uniform_int(rng, n)]
                                            : x_lo + (x_hi - x_lo) * tirenv_rng_uniform(rng);
                check_sweep_lift(&g, shape, p, z_cap, sw, &front, x, "random");
            }
            rear.k_x = (size_t)-1; /* garbage */
            check_sweep_lift(&g, shape, p, z_cap, sw, &rear, 0.5 * (x_lo + x_hi), "garbage");
        }
    }
    for (size_t i = 0; i < N_PROFILES; i++)
        tirenv_profile_free(profiles[i]);
    free(sw);
    tirenv_rng_free(rng);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rigid_equals_plain),
        cmocka_unit_test(test_cam_equals_plain),
        cmocka_unit_test(test_cam_floor_below_drop),
        cmocka_unit_test(test_cam_sweep_equals_plain),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
