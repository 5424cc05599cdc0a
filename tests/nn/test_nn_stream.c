/* The network over a road taken a window at a time (tirenv_nn_road_alloc_window, and the nn
 * model under tirenv_model_stream): a window's h and slope are the whole road's bit for bit
 * wherever the margin allows, its obstacles the whole road's; a run is never longer than the
 * bound the margin assumes; a streamed sweep equals the whole-profile sweep point for point
 * (memcmp), over a road with cleats and a plateau longer than the window, a single cleat,
 * and two tracks, with windows far smaller than the road; the refusal of an obstacle outside
 * the trained range names the same obstacle.
 * SPDX-License-Identifier: Apache-2.0
 *
 * The network is the study's (as tests/nn/test_nn_road.c): trained ranges x_N -0.25..1, l_c
 * 0.28..0.43 m, H 0.025..0.1 m, L 0.05..0.3 m; the default opening is 0.45 m wide. Every
 * comparison is exact (memcmp of h, slope, obstacle records, points): no tolerance. */
#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tirenv/stream.h"
#include "tirenv/tirenv.h"
#include "tirenv/train.h"

static const double R0 = 0.68;    /* m: the data set's tire */
static const double l_c = 0.33;   /* m */
enum { CHUNK = TIRENV_ENVELOPE_BLOCK }; /* the CLI's whole-mode chunk (tirenv/stream.h) */


/* ---- roads ----------------------------------------------------------------------------- */

typedef struct {
    double *x, *z;
    size_t n, cap;
} poly;

static void poly_add(poly *p, double x, double z)
{
    if (p->n == p->cap) {
        p->cap = p->cap ? 2 * p->cap : 1024;
        p->x = realloc(p->x, p->cap * sizeof *p->x);
        p->z = realloc(p->z, p->cap * sizeof *p->z);
        assert_non_null(p->x);
        assert_non_null(p->z);
    }
    p->x[p->n] = x;
    p->z[p->n] = z;
    p->n++;
}

/* A class C road (seed 11) of the given length every dx, with rectangular cleats standing on
 * it (walls: two vertices at one x), heights and lengths inside the trained range, two close
 * enough to interact, and a raised plateau 7 m long (longer than any window below): a road
 * with many obstacles, some exactly the network's own case. */
static tirenv_profile *cleat_road(double length, double dx)
{
    tirenv_road_settings s = tirenv_road_default();
    s.road_class = 'C';
    s.length = length;
    s.dx = dx;
    s.seed = 11;
    tirenv_profile *road = NULL;
    assert_int_equal(tirenv_road_iso8608(&s, &road, NULL), TIRENV_OK);
    static const struct {
        double x_lo, x_hi, H;  /* m */
    } bump[] = {{3.1013, 3.2213, 0.0437}, {9.5071, 9.7571, 0.0812}, {9.8207, 9.9107, 0.0301},
                {14.003, 21.003, 0.0625}, {26.4407, 26.5307, 0.0558},
                {33.3333, 33.5833, 0.0966}};
    const size_t n_bump = sizeof bump / sizeof bump[0];
    poly p = {0};
    const size_t n = tirenv_profile_size(road);
    const double *x = tirenv_profile_x(road), *z = tirenv_profile_z(road);
    size_t b = 0;
    int on = 0;  /* on bump b */
    for (size_t k = 0; k < n; ++k) {
        for (;;) {  /* the walls of the bumps that begin or end by x[k] */
            if (b < n_bump && !on && bump[b].x_lo <= x[k]) {
                const double zl = tirenv_profile_height(road, bump[b].x_lo);
                poly_add(&p, bump[b].x_lo, zl);
                poly_add(&p, bump[b].x_lo, zl + bump[b].H);
                on = 1;
            } else if (on && bump[b].x_hi <= x[k]) {
                const double zh = tirenv_profile_height(road, bump[b].x_hi);
                poly_add(&p, bump[b].x_hi, zh + bump[b].H);
                poly_add(&p, bump[b].x_hi, zh);
                on = 0;
                ++b;
            } else {
                break;
            }
        }
        if (p.n == 0 || p.x[p.n - 1] < x[k])  /* not on a wall just drawn */
            poly_add(&p, x[k], z[k] + (on ? bump[b].H : 0));
    }
    tirenv_profile_free(road);
    tirenv_profile *out = tirenv_profile_alloc(p.n, p.x, p.z);
    assert_non_null(out);
    free(p.x);
    free(p.z);
    return out;
}

static tirenv_nn_road *whole_road(const tirenv_nn *nn, const tirenv_profile *p)
{
    tirenv_nn_road *r = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_nn_road_alloc(nn, R0, l_c, p, NULL, &r, &d), TIRENV_OK);
    return r;
}

/* ---- the decomposition of a window ------------------------------------------------------ */

/* Windows [i0, i1] of the road's vertices, of lengths from just over twice the margin to a
 * few times it, at offsets from a fixed generator, the first from the road's first vertex and
 * the last to its end: h, slope and the obstacles of each equal the whole road's where the
 * margin says. */
static void test_window_equals_whole(void **state)
{
    const tirenv_nn *nn = *state;
    tirenv_profile *p = cleat_road(40.0, 0.002);
    tirenv_nn_road *whole = whole_road(nn, p);
    const double D = tirenv_nn_road_window_margin(nn, R0, NULL);
    assert_true(D > 1.05 * R0 && D < 5.0);
    const size_t n_v = tirenv_profile_size(p);
    const double *xv = tirenv_profile_x(p), *zv = tirenv_profile_z(p);
    const tirenv_nn_obstacle *ob_w = tirenv_nn_road_obstacles(whole);
    const size_t n_ob_w = tirenv_nn_road_info_of(whole).obstacles;
    tirenv_rng *rng = tirenv_rng_alloc(2385);
    assert_non_null(rng);
    size_t compared = 0, obstacles = 0;
    enum { N_WIN = 24, N_POS = 1500 };
    double *xs = malloc(N_POS * sizeof *xs), *hw = malloc(N_POS * sizeof *hw),
           *sw = malloc(N_POS * sizeof *sw), *h = malloc(N_POS * sizeof *h),
           *s = malloc(N_POS * sizeof *s);
    assert_true(xs && hw && sw && h && s);
    for (int k = 0; k < N_WIN; ++k) {
        const double len = (2.2 + 2.0 * tirenv_rng_uniform(rng)) * D;
        double x0 = xv[0] + (xv[n_v - 1] - len - xv[0]) * tirenv_rng_uniform(rng);
        if (k == 0)
            x0 = xv[0];
        if (k == N_WIN - 1)
            x0 = xv[n_v - 1] - len;
        size_t i0 = 0, i1 = n_v - 1;
        while (i0 + 1 < n_v && xv[i0 + 1] <= x0)
            ++i0;
        while (i1 > i0 + 1 && xv[i1 - 1] >= x0 + len)
            --i1;
        if (k == 0)
            i0 = 0;
        if (k == N_WIN - 1)
            i1 = n_v - 1;
        tirenv_profile *wp = tirenv_profile_alloc(i1 - i0 + 1, xv + i0, zv + i0);
        assert_non_null(wp);
        const tirenv_nn_road_window win = {.x_first = xv[0], .bof = i0 == 0,
                                           .eof = i1 == n_v - 1};
        tirenv_nn_road *r = NULL;
        tirenv_diag d;
        assert_int_equal(tirenv_nn_road_alloc_window(nn, R0, l_c, wp, NULL, &win, &r, &d),
                         TIRENV_OK);
        /* Positions where the window is exact: beyond the road's ends too at bof and eof. */
        const double a = win.bof ? xv[0] - 1.0 : xv[i0] + D;
        const double b = win.eof ? xv[n_v - 1] + 1.0 : xv[i1] - D;
        assert_true(b > a);
        for (size_t j = 0; j < N_POS; ++j)
            xs[j] = a + (b - a) * ((double)j + 0.5) / N_POS;
        assert_int_equal(tirenv_nn_road_eval(whole, N_POS, xs, hw, sw, &d), TIRENV_OK);
        assert_int_equal(tirenv_nn_road_eval(r, N_POS, xs, h, s, &d), TIRENV_OK);
        assert_memory_equal(h, hw, N_POS * sizeof *h);
        assert_memory_equal(s, sw, N_POS * sizeof *s);
        compared += N_POS;
        /* Each obstacle kept is one of the whole road's, field for field. */
        const tirenv_nn_obstacle *ob = tirenv_nn_road_obstacles(r);
        const size_t n_ob = tirenv_nn_road_info_of(r).obstacles;
        for (size_t i = 0; i < n_ob; ++i) {
            size_t j = 0;
            while (j < n_ob_w && ob_w[j].c != ob[i].c)
                ++j;
            assert_true(j < n_ob_w);
            assert_memory_equal(&ob[i], &ob_w[j], sizeof ob[i]);
        }
        obstacles += n_ob;
        tirenv_nn_road_free(r);
        tirenv_profile_free(wp);
    }
    print_message("margin %.3f m, %zu positions in %d windows, %zu obstacles kept (the road "
                  "has %zu)\n", D, compared, N_WIN, obstacles, n_ob_w);
    assert_true(obstacles > 2 * N_WIN);  /* the windows held obstacles to compare */
    tirenv_rng_free(rng);
    free(xs);
    free(hw);
    free(sw);
    free(h);
    free(s);
    tirenv_nn_road_free(whole);
    tirenv_profile_free(p);
}

/* The margin rests on runs no longer than W + 2 spacings (nn_road.c): over roads of every
 * roughness and the cleat road, the longest run stays within it. */
static void test_runs_bounded(void **state)
{
    const tirenv_nn *nn = *state;
    const tirenv_nn_road_settings s = tirenv_nn_road_default();
    const char classes[] = {'A', 'C', 'E', 'H'};
    for (size_t c = 0; c <= sizeof classes; ++c) {
        tirenv_profile *p;
        if (c < sizeof classes) {
            tirenv_road_settings rs = tirenv_road_default();
            rs.road_class = classes[c];
            rs.length = 200;
            rs.dx = 0.003;
            rs.seed = 5 + c;
            p = NULL;
            assert_int_equal(tirenv_road_iso8608(&rs, &p, NULL), TIRENV_OK);
        } else {
            p = cleat_road(40.0, 0.002);
        }
        tirenv_nn_road *r = whole_road(nn, p);
        const tirenv_nn_road_info in = tirenv_nn_road_info_of(r);
        const tirenv_nn_obstacle *ob = tirenv_nn_road_obstacles(r);
        double longest = 0;
        for (size_t k = 0; k < in.obstacles; ++k)
            longest = fmax(longest, ob[k].x_hi - ob[k].x_lo);
        print_message("%c: %zu obstacles, longest run %.4f m, bound %.4f m\n",
                      c < sizeof classes ? classes[c] : '+', in.obstacles, longest,
                      in.width + 2 * s.spacing);
        assert_true(in.obstacles > 10);
        assert_true(longest <= in.width + 2 * s.spacing);
        tirenv_nn_road_free(r);
        tirenv_profile_free(p);
    }
}

static void test_window_errors(void **state)
{
    const tirenv_nn *nn = *state;
    const double x[] = {1, 2, 3}, z[] = {0, 0.01, 0};
    tirenv_profile *p = tirenv_profile_alloc(3, x, z);
    tirenv_nn_road *r = (tirenv_nn_road *)p;  /* must come back NULL */
    tirenv_diag d;
    assert_int_equal(tirenv_nn_road_alloc_window(nn, R0, l_c, p, NULL, NULL, &r, &d),
                     TIRENV_EINVAL);
    assert_null(r);
    const tirenv_nn_road_window late = {.x_first = 1.5, .bof = 0, .eof = 1};
    assert_int_equal(tirenv_nn_road_alloc_window(nn, R0, l_c, p, NULL, &late, &r, &d),
                     TIRENV_EINVAL);
    assert_null(r);
    assert_non_null(strstr(d.message, "before the road's first vertex"));
    assert_true(isnan(tirenv_nn_road_window_margin(NULL, R0, NULL)));
    assert_true(isnan(tirenv_nn_road_window_margin(nn, -1, NULL)));
    tirenv_nn_road_settings s = tirenv_nn_road_default();
    s.spacing = 0;
    assert_true(isnan(tirenv_nn_road_window_margin(nn, R0, &s)));
    tirenv_profile_free(p);
}

/* ---- the nn model streamed --------------------------------------------------------------- */

typedef struct {
    const tirenv_profile *p[2];
    size_t n_tracks, k;
} rows;

static int next_row(void *ctx, double *x, double z[], int *got, tirenv_diag *diag)
{
    (void)diag;
    rows *r = ctx;
    *got = r->k < tirenv_profile_size(r->p[0]);
    if (*got) {
        *x = tirenv_profile_x(r->p[0])[r->k];
        for (size_t t = 0; t < r->n_tracks; ++t)
            z[t] = tirenv_profile_z(r->p[t])[r->k];
        r->k++;
    }
    return TIRENV_OK;
}

/* The whole-profile sweep as tirenv envelope runs it: set, then chunks of CHUNK positions. */
static tirenv_point *sweep_whole(tirenv_model *m, size_t n_tracks, const tirenv_profile *p[],
                                 double load, double x_from, double dx, size_t n)
{
    tirenv_diag d;
    assert_int_equal(tirenv_model_set_tracks(m, n_tracks, p, NULL, load, &d), TIRENV_OK);
    tirenv_point *pt = malloc(n * sizeof *pt);
    double *x = malloc(CHUNK * sizeof *x);
    assert_true(pt && x);
    for (size_t k0 = 0; k0 < n; k0 += CHUNK) {
        const size_t m_k = n - k0 < CHUNK ? n - k0 : CHUNK;
        for (size_t k = 0; k < m_k; ++k)
            x[k] = x_from + (double)(k0 + k) * dx;
        size_t failed;
        assert_int_equal(tirenv_model_envelope(m, m_k, x, pt + k0, &failed, &d), TIRENV_OK);
    }
    free(x);
    return pt;
}

/* Streamed and whole over n_tracks tracks: the same points, byte for byte, and the same
 * warnings and note. Returns the stats. */
static tirenv_stream_stats check_stream(const tirenv_nn *nn, size_t n_tracks,
                                        const tirenv_profile *p[], double x_from, double x_to,
                                        double dx)
{
    tirenv_model *m = tirenv_test_nn_model(nn, 1);
    double load;
    tirenv_diag d;
    assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &load, &d), TIRENV_OK);
    rows src = {.p = {p[0], p[n_tracks - 1]}, .n_tracks = n_tracks};
    tirenv_test_points c = {0};
    tirenv_stream_stats st;
    assert_int_equal(tirenv_model_stream_tracks(m, n_tracks, NULL, next_row, &src, x_from,
                                                x_to, dx, load, tirenv_test_keep_point, &c,
                                                &st, &d),
                     TIRENV_OK);
    char warnings[2048], note[512];
    snprintf(warnings, sizeof warnings, "%s", tirenv_model_warnings(m));
    snprintf(note, sizeof note, "%s", tirenv_model_note(m));
    const size_t n = tirenv_positions_count(x_from, x_to, dx);
    assert_int_equal(c.n, n);
    tirenv_point *w = sweep_whole(m, n_tracks, p, load, x_from, dx, n);
    assert_memory_equal(c.pt, w, n * sizeof *w);
    assert_string_equal(warnings, tirenv_model_warnings(m));
    assert_string_equal(note, tirenv_model_note(m));
    size_t lifted = 0;
    for (size_t k = 0; k < n; ++k)
        lifted += w[k].h > 1e-3;
    assert_true(lifted > n / 20);  /* the curve has something to compare */
    print_message("%zu positions, %zu windows of at most %zu of %zu vertices; %s\n", n,
                  st.rebuilds, st.window_max, tirenv_profile_size(p[0]), note);
    free(w);
    free(c.pt);
    tirenv_model_free(m);
    return st;
}

/* Over the cleat road, 100 m at 1 mm: windows far smaller than the road (a tenth at most),
 * many of them, the 7 m plateau longer than any. */
static void test_stream_equals_whole(void **state)
{
    const tirenv_nn *nn = *state;
    tirenv_profile *p = cleat_road(100.0, 0.001);
    const tirenv_profile *tracks[1] = {p};
    const tirenv_stream_stats st = check_stream(nn, 1, tracks, -0.8137, 100.7, 0.00071);
    assert_true(st.rebuilds >= 20);
    assert_true(st.window_max < tirenv_profile_size(p) / 10);
    const double D = tirenv_nn_road_window_margin(nn, R0, NULL);
    assert_true(st.window_max * 0.001 < 7.0 + 4 * D);  /* about 4 margins of road */
    tirenv_profile_free(p);
}

/* A single cleat, the network's own case (4 vertices): the window is the whole road, and its
 * sweep's slopes, one-sided at each chunk's ends, fall as in the whole sweep (positions
 * enough for three chunks). */
static void test_stream_cleat(void **state)
{
    const tirenv_nn *nn = *state;
    const double x[] = {-0.06, -0.06, 0.06, 0.06}, z[] = {0, 0.05, 0.05, 0};
    tirenv_profile *p = tirenv_profile_alloc(4, x, z);
    const tirenv_profile *tracks[1] = {p};
    const tirenv_stream_stats st = check_stream(nn, 1, tracks, -0.75, 0.75, 0.00007);
    assert_int_equal(st.rebuilds, 1);
    tirenv_profile_free(p);
}

/* Two tracks (the cleat road and the same with another seed's ground), the mean rule. */
static void test_stream_tracks(void **state)
{
    const tirenv_nn *nn = *state;
    tirenv_profile *a = cleat_road(25.0, 0.002);
    tirenv_road_settings rs = tirenv_road_default();
    rs.road_class = 'D';
    rs.length = 25.0;
    rs.dx = 0.002;
    rs.seed = 12;
    tirenv_profile *other = NULL;
    assert_int_equal(tirenv_road_iso8608(&rs, &other, NULL), TIRENV_OK);
    /* the second track at the first's abscissae (the rows' x) */
    const size_t n = tirenv_profile_size(a);
    double *zb = malloc(n * sizeof *zb);
    assert_non_null(zb);
    for (size_t k = 0; k < n; ++k)
        zb[k] = tirenv_profile_z(a)[k] + tirenv_profile_height(other, tirenv_profile_x(a)[k]);
    tirenv_profile *b = tirenv_profile_alloc(n, tirenv_profile_x(a), zb);
    assert_non_null(b);
    const tirenv_profile *tracks[2] = {a, b};
    const tirenv_stream_stats st = check_stream(nn, 2, tracks, 0.3, 24.9, 0.0013);
    assert_true(st.rebuilds >= 4);
    free(zb);
    tirenv_profile_free(a);
    tirenv_profile_free(b);
    tirenv_profile_free(other);
}

/* Without extrapolation a road whose obstacles leave the trained range is refused, streamed
 * or not, naming the same (first) obstacle. */
static void test_stream_refuses(void **state)
{
    const tirenv_nn *nn = *state;
    tirenv_profile *p = cleat_road(30.0, 0.002);
    tirenv_model *m = tirenv_test_nn_model(nn, 0);
    double load;
    tirenv_diag d, dw;
    assert_int_equal(tirenv_model_load_for_contact_length(m, l_c, &load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(m, p, load, &dw), TIRENV_ERANGE);
    rows src = {.p = {p, p}, .n_tracks = 1};
    tirenv_test_points c = {0};
    assert_int_equal(tirenv_model_stream_tracks(m, 1, NULL, next_row, &src, 0, 30, 0.001, load,
                                                tirenv_test_keep_point, &c, NULL, &d),
                     TIRENV_ERANGE);
    print_message("whole: %.160s\nstreamed: %.160s\n", dw.message, d.message);
    const char *at = strstr(dw.message, "the obstacle at x = ");
    const char *at_s = strstr(d.message, "the obstacle at x = ");
    assert_non_null(at);
    assert_non_null(at_s);
    const size_t len = strcspn(at, "(");  /* its position and extent */
    assert_int_equal(strncmp(at_s, at, len + 40), 0);
    assert_non_null(strstr(d.message, "counts of the streamed window"));
    free(c.pt);
    tirenv_model_free(m);
    tirenv_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_window_equals_whole),
        cmocka_unit_test(test_runs_bounded),
        cmocka_unit_test(test_window_errors),
        cmocka_unit_test(test_stream_equals_whole),
        cmocka_unit_test(test_stream_cleat),
        cmocka_unit_test(test_stream_tracks),
        cmocka_unit_test(test_stream_refuses),
    };
    return cmocka_run_group_tests(tests, tirenv_test_nn_setup, tirenv_test_nn_teardown);
}
