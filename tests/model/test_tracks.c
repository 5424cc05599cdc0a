/* Several tracks across the tire's width (tracks.h, docs/models.md section 13): one track is
 * tirenv_model_set bit for bit, a repeated profile is one track, a road flat on one half and
 * raised on the other gives something between, with the equilibrium's closed form on the
 * springs model without interradial springs, and a streamed sweep equals the whole one.
 * SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/tirenv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double load = 11903.6;      /* N: the default tire at its 0.33 m patch */
static const double cleat_L = 0.3, cleat_H = 0.0713;  /* m */

static tirenv_profile *flat_at(double h)
{
    const double x = 0;
    tirenv_profile *p = tirenv_profile_alloc(1, &x, &h);
    assert_non_null(p);
    return p;
}

/* A copy of p: the same vertices in another object. */
static tirenv_profile *copy_of(const tirenv_profile *p)
{
    tirenv_profile *c = tirenv_profile_alloc(tirenv_profile_size(p), tirenv_profile_x(p),
                                             tirenv_profile_z(p));
    assert_non_null(c);
    return c;
}

enum { N_POS = 241 };

/* Positions over the cleat and its run-in: -0.9 to 0.9 m. */
static void positions(double x[N_POS])
{
    for (size_t k = 0; k < N_POS; ++k)
        x[k] = -0.9 + 0.0075 * (double)k;
}

static void assert_points_bits(const tirenv_point *a, const tirenv_point *b)
{
    assert_bits_equal(a->x, b->x);
    assert_bits_equal(a->z, b->z);
    assert_bits_equal(a->h, b->h);
    assert_bits_equal(a->slope, b->slope);
    assert_bits_equal(a->fx, b->fx);
    assert_bits_equal(a->fz, b->fz);
    assert_int_equal(a->contacts, b->contacts);
    assert_int_equal(a->iterations, b->iterations);
}

static const tirenv_model_type *const *physical_types(void)
{
    static const tirenv_model_type *types[6];
    types[0] = tirenv_model_rigid;
    types[1] = tirenv_model_springs;
    types[2] = tirenv_model_ring;
    types[3] = tirenv_model_cam;
    types[4] = tirenv_model_point;
    types[5] = NULL;
    return types;
}

static void curve(tirenv_model *m, const double x[N_POS], tirenv_point out[N_POS])
{
    tirenv_diag d;
    assert_int_equal(tirenv_model_envelope(m, N_POS, x, out, NULL, &d), TIRENV_OK);
}

/* n = 1, and n copies of one pointer (any weights), are tirenv_model_set bit for bit, for
 * every model type: the single-track path. Each sweep on a fresh instance (the ring keeps
 * contact states from one set to the next, which may move its iterations). */
static void test_one_track_is_set(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    tirenv_profile *cleat = tirenv_profile_cleat(cleat_L, cleat_H);
    double x[N_POS];
    positions(x);
    static tirenv_point ref[N_POS], got[N_POS];
    const tirenv_profile *three[3] = {cleat, cleat, cleat};
    const double w[3] = {0.2, 1.7, 3.1};
    for (const tirenv_model_type *const *t = physical_types(); *t; ++t)
        for (int variant = 0; variant < 3; ++variant) {
            tirenv_model *m = tirenv_model_alloc(*t, &tire);
            assert_non_null(m);
            tirenv_diag d;
            if (variant == 0)
                assert_int_equal(tirenv_model_set(m, cleat, load, &d), TIRENV_OK);
            else if (variant == 1)
                assert_int_equal(tirenv_model_set_tracks(m, 1, three, NULL, load, &d),
                                 TIRENV_OK);
            else
                assert_int_equal(tirenv_model_set_tracks(m, 3, three, w, load, &d), TIRENV_OK);
            assert_int_equal(tirenv_model_tracks(m), 1);
            curve(m, x, variant ? got : ref);
            for (size_t k = 0; variant && k < N_POS; ++k)
                assert_points_bits(&got[k], &ref[k]);
            tirenv_model_free(m);
        }
    tirenv_profile_free(cleat);
}

/* How far an equilibrium's F_z may be from the load: the solver stops when |F_z - G| <= eps_F
 * or when its last step is below eps_z (docs/models.md section 11.3), which at a vertical
 * stiffness up to 4e5 N/m (the ring's at these loads) leaves 4e5 * eps_z = 4e-5 N. */
static double eq_F_tol(const tirenv_tire *t) { return fmax(t->eq.eps_F, 4e5 * t->eq.eps_z); }

/* The ring's vertical stiffness dF_z/dz (exact for its contact states, N/m) at each
 * equilibrium of a curve over p, the smallest: how far eps_F leaves an answer from its root. */
static double ring_k_min(const tirenv_tire *tire, const tirenv_profile *p,
                         const tirenv_point pt[N_POS])
{
    tirenv_ring *r = tirenv_ring_alloc(tire->springs.R0, &tire->ring);
    assert_non_null(r);
    double k_min = INFINITY;
    for (size_t k = 0; k < N_POS; ++k) {
        double fx, fz, dfz;
        assert_int_equal(tirenv_ring_forces(r, p, pt[k].x, pt[k].z, &fx, &fz, &dfz, NULL, NULL),
                         0);
        k_min = fmin(k_min, -dfz);
    }
    tirenv_ring_free(r);
    assert_true(k_min > 0);
    return k_min;
}

/* The same for the springs model (its default continuous contact, exact dF_z/dz on the
 * QP's working set, section 4.8). */
static double springs_k_min(const tirenv_tire *tire, const tirenv_profile *p,
                            const tirenv_point pt[N_POS])
{
    tirenv_springs *s = tirenv_springs_alloc(&tire->springs);
    assert_non_null(s);
    double k_min = INFINITY;
    for (size_t k = 0; k < N_POS; ++k) {
        double fx, fz, dfz;
        assert_int_equal(tirenv_springs_forces(s, p, pt[k].x, pt[k].z, &fx, &fz, &dfz, NULL,
                                               NULL), 0);
        if (fz > 0)
            k_min = fmin(k_min, -dfz);
    }
    tirenv_springs_free(s);
    assert_true(k_min > 0);
    return k_min;
}

/* Separate profiles with the same vertices are separate tracks: the combination agrees with
 * one track to round-off. Measured over this cleat at 0.75 mm steps with 2 to 5 copies: h
 * within 1.7e-15 m (cam 1.4e-17, rigid and point exact), the slope within 8.6e-14; two and
 * four copies give h bit for bit (weights that are powers of two sum exactly). Checked here
 * with margins: 1e-12 m, 3e-11. The springs model (1.1e-16 m once) now differs as the ring
 * does, below: one track takes the model's own Newton step (F_z = G on its QP's working set,
 * docs/models.md section 4.8), the sum of tracks the linear one, so their iterates differ;
 * measured 9.9e-11 m against the bound 2 eps_F / k_min, 1.0e-9 m (3.8e-12 m against 1.0e-11 m
 * with eps_F 1e-6 N).
 * The ring (the default tire: its tread coupled in shear, 0.25 MPa at 0.25 degrees) starts each
 * position's Newton from the line through the last two equilibria (src/model/deformable.c),
 * and one track has skipped the level ground before the cleat where three tracks solved it:
 * their z iterates differ, and both stop where |F_z - G| <= eps_F (1e-4 N) and the next step
 * is within eps_z (docs/models.md section 11). With dF_z/dz exact (section 5.3) the next step
 * -(F_z - G)/(dF_z/dz) is each answer's distance from the root to second order, so two
 * answers lie within 2 eps_F / k_min of each other, k_min the smallest vertical stiffness
 * over the curve (2.1e5 N/m here, computed below: 9.6e-10 m). Measured 6.6e-12 m (2.08e-12 m
 * with eps_F 1e-6 N, the default before; the Winkler tread at 0.125 degrees 8.3e-13 m); the
 * slope within 7.5e-12 (2.8e-11 with the Winkler tread, whose F_x sums forces of a belt with
 * stencil entries near 1e11 N/m). Since one track's ring takes its own step in z too (the
 * parabola of its measured curvature, src/model/ring_root.c), its iterates differ as the
 * springs model's do: h within 1.2e-10 m, the slope within 8.9e-11 (measured). The springs
 * model's slope, its iterates 15 times farther apart, within 2.7e-10: both checked within
 * 1e-9, the others' within 3e-11. The cleat
 * and the load are the same for the two, so no summation order is involved: the one track's
 * F_z and the three tracks' sum of three equal slices differ only in the iterate at which
 * each stopped. */
static void test_equal_copies(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    assert_true(tire.ring.G_t > 0); /* the default's shear-coupled tread */
    tirenv_profile *cleat = tirenv_profile_cleat(cleat_L, cleat_H);
    tirenv_profile *c1 = copy_of(cleat), *c2 = copy_of(cleat);
    double x[N_POS];
    positions(x);
    static tirenv_point ref[N_POS], got[N_POS];
    for (const tirenv_model_type *const *t = physical_types(); *t; ++t) {
        tirenv_model *m = tirenv_model_alloc(*t, &tire);
        tirenv_diag d;
        assert_int_equal(tirenv_model_set(m, cleat, load, &d), TIRENV_OK);
        curve(m, x, ref);
        const tirenv_profile *three[3] = {cleat, c1, c2};
        assert_int_equal(tirenv_model_set_tracks(m, 3, three, NULL, load, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_tracks(m), 3);
        curve(m, x, got);
        const int eq = tirenv_model_type_tracks(*t) == TIRENV_TRACKS_EQUILIBRIUM;
        const int ring = *t == tirenv_model_ring;
        const int springs = *t == tirenv_model_springs;
        const double h_tol = ring      ? 2 * tire.eq.eps_F / ring_k_min(&tire, cleat, ref)
                             : springs ? 2 * tire.eq.eps_F / springs_k_min(&tire, cleat, ref)
                                       : 1e-12;
        double dh = 0;
        for (size_t k = 0; k < N_POS; ++k) {
            assert_int_equal(got[k].contacts, 3 * ref[k].contacts);
            assert_near(got[k].h, ref[k].h, h_tol, 0);
            dh = fmax(dh, fabs(got[k].h - ref[k].h));
            assert_near(got[k].slope, ref[k].slope, springs || ring ? 1e-9 : 3e-11, 0);
            assert_near(got[k].fz, ref[k].fz, eq ? eq_F_tol(&tire) : 1e-9, 0);
        }
        if (ring || springs)
            print_message("%s, three copies against one: max |dh| %.3g m, bound %.3g m\n",
                          ring ? "ring" : "springs", dh, h_tol);
        tirenv_model_free(m);
    }
    tirenv_profile_free(c2);
    tirenv_profile_free(c1);
    tirenv_profile_free(cleat);
}

/* The same for the ring with its tread coupled in shear (TREAD_SHEAR 1 MPa, 0.125 degrees;
 * docs/models.md section 5.3), three copies against one. Its Newton solve used to
 * accept the Newton point when the line search stalled (E's round-off hiding the decrease),
 * which left the answer depending on the warm start: h 1.5e-9 m apart, the slope 1.2e-9. It
 * now polishes with full Newton steps to a consistent set of contact states, the unique
 * minimiser: measured 3.9e-11 m and 7.4e-11 (3 stalls, all settled; h 1.8e-11 m since dF_z/dz
 * follows the cuts at ground vertices, so that Newton in z converges quadratically), of the order of the
 * equilibrium's step tolerance eps_z = 1e-10 m and not shrinking with it (1.6e-11 m at
 * eps_z = 1e-12): the round-off of the stiffer belt-and-tread solve, whose contact layer is
 * 1e4 k_t. One track takes the ring's own step in z (src/model/ring_root.c), three the
 * linear one, so they stop at different iterates, each within eps_z of the root: 1.05e-10 m
 * measured; since one track also starts a new x from the mean slope of its last steps where
 * that predicts better (ring_root.c), 1.05e-10 m and the slope (F_x over F_z) 5.3e-10 apart
 * (7.1e-10 with the mean slope always), F_x some 2e-5 N. Checked within 2 eps_z = 2e-10 m
 * and, as test_equal_copies, 1e-9. */
static void test_equal_copies_with_shear(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_test_default_tire();
    tire.ring.G_t = 1.0e6;
    tire.ring.dtheta = M_PI / 1440.0; /* where the figures above were measured */
    tirenv_profile *cleat = tirenv_profile_cleat(cleat_L, cleat_H);
    tirenv_profile *c1 = copy_of(cleat), *c2 = copy_of(cleat);
    double x[N_POS];
    positions(x);
    static tirenv_point ref[N_POS], got[N_POS];
    tirenv_model *m = tirenv_model_alloc(tirenv_model_ring, &tire);
    tirenv_diag d;
    assert_int_equal(tirenv_model_set(m, cleat, load, &d), TIRENV_OK);
    curve(m, x, ref);
    const tirenv_profile *three[3] = {cleat, c1, c2};
    assert_int_equal(tirenv_model_set_tracks(m, 3, three, NULL, load, &d), TIRENV_OK);
    curve(m, x, got);
    double dh = 0, lifted = 0, dslope = 0;
    for (size_t k = 0; k < N_POS; ++k) {
        assert_int_equal(got[k].contacts, 3 * ref[k].contacts);
        assert_near(got[k].h, ref[k].h, 2 * tire.eq.eps_z, 0);
        assert_near(got[k].slope, ref[k].slope, 1e-9, 0);
        dslope = fmax(dslope, fabs(got[k].slope - ref[k].slope));
        assert_near(got[k].fz, ref[k].fz, eq_F_tol(&tire), 0);
        dh = fmax(dh, fabs(got[k].h - ref[k].h));
        lifted = fmax(lifted, ref[k].h);
    }
    print_message("TREAD_SHEAR 1 MPa, three copies against one: max |dh| %.3g m, slope %.3g\n",
                  dh, dslope);
    assert_true(lifted > 0.01); /* the cleat lifts the hub: the comparison can fail */
    tirenv_model_free(m);
    tirenv_profile_free(c2);
    tirenv_profile_free(c1);
    tirenv_profile_free(cleat);
}

/* Flat ground on one half of the width and a cleat on the other: the mean rule gives half the
 * cleat's curve exactly, the highest the cleat's, the equilibrium something between the flat
 * ground's 0 and the cleat's curve (the slices' forces rise with the ground, so the shared
 * centre sits between the two single-track equilibria), strictly between where the cleat
 * lifts the tire. Weights 1:3 give a quarter and three quarters. */
static void test_flat_and_cleat(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    tirenv_profile *cleat = tirenv_profile_cleat(cleat_L, cleat_H);
    tirenv_profile *flat = flat_at(0);
    double x[N_POS];
    positions(x);
    static tirenv_point on_cleat[N_POS], on_flat[N_POS], both[N_POS], weighted[N_POS];
    for (const tirenv_model_type *const *t = physical_types(); *t; ++t) {
        tirenv_model *m = tirenv_model_alloc(*t, &tire);
        tirenv_diag d;
        assert_int_equal(tirenv_model_set(m, cleat, load, &d), TIRENV_OK);
        curve(m, x, on_cleat);
        assert_int_equal(tirenv_model_set(m, flat, load, &d), TIRENV_OK);
        curve(m, x, on_flat);
        const tirenv_profile *two[2] = {flat, cleat};
        assert_int_equal(tirenv_model_set_tracks(m, 2, two, NULL, load, &d), TIRENV_OK);
        curve(m, x, both);
        const double w[2] = {1, 3};
        assert_int_equal(tirenv_model_set_tracks(m, 2, two, w, load, &d), TIRENV_OK);
        curve(m, x, weighted);
        size_t between = 0;
        for (size_t k = 0; k < N_POS; ++k) {
            assert_bits_equal(on_flat[k].h, 0.0);
            switch (tirenv_model_type_tracks(*t)) {
            case TIRENV_TRACKS_MEAN:
                assert_bits_equal(both[k].h, 0.5 * on_cleat[k].h);
                assert_bits_equal(weighted[k].h, 0.75 * on_cleat[k].h);
                break;
            case TIRENV_TRACKS_HIGHEST:
                assert_bits_equal(both[k].h, on_cleat[k].h);
                assert_bits_equal(weighted[k].h, on_cleat[k].h);
                break;
            case TIRENV_TRACKS_EQUILIBRIUM:
                assert_true(both[k].h >= -tire.eq.eps_z);
                assert_true(both[k].h <= on_cleat[k].h + tire.eq.eps_z);
                assert_true(weighted[k].h >= both[k].h - tire.eq.eps_z);
                assert_true(weighted[k].h <= on_cleat[k].h + tire.eq.eps_z);
                assert_near(both[k].fz, load, eq_F_tol(&tire), 0);
                if (on_cleat[k].h > 1e-3) {
                    assert_true(both[k].h > 1e-4 && both[k].h < on_cleat[k].h - 1e-4);
                    ++between;
                }
                break;
            }
        }
        if (tirenv_model_type_tracks(*t) == TIRENV_TRACKS_EQUILIBRIUM)
            assert_true(between > 20);
        tirenv_model_free(m);
    }
    tirenv_profile_free(flat);
    tirenv_profile_free(cleat);
}

/* The springs model without interradial springs (c_b = 0): each element pushes on its own,
 * k_r (R0 cos(theta_i) - (z - H)) on level ground at H where R0 cos(theta_i) > z - H, so the
 * equilibrium of two level tracks at 0 and H with weights w and 1 - w is the root of a
 * piecewise-linear function, found here from that formula alone (bisection to the contact
 * sets, then the linear piece solved exactly), and the model must land on it within eps_z. */
static double closed_form_force(const tirenv_tire *t, double z, double H)
{
    const double R0 = t->springs.R0, dphi = t->springs.dphi, k_r = t->springs.c_r * dphi;
    const long i_max = (long)floor(0.5 * t->springs.phi / dphi * (1 + 1e-12));
    double F = 0;
    for (long i = -i_max; i <= i_max; ++i) {
        const double tip = R0 * cos((double)i * dphi);
        if (tip > z - H)
            F += k_r * (tip - (z - H));
    }
    return F;
}

static double closed_form_z(const tirenv_tire *t, double w, double H, double G)
{
    double lo = 0, hi = t->springs.R0 + H;  /* F(lo) > G > F(hi) */
    for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (w * closed_form_force(t, mid, 0) + (1 - w) * closed_form_force(t, mid, H) > G)
            lo = mid;
        else
            hi = mid;
    }
    /* The linear piece the root lies on: z = (sum of the touching tips - G/k_r) / count. */
    const double z = 0.5 * (lo + hi), R0 = t->springs.R0, dphi = t->springs.dphi;
    const double k_r = t->springs.c_r * dphi;
    const long i_max = (long)floor(0.5 * t->springs.phi / dphi * (1 + 1e-12));
    double sum = 0, count = 0;
    for (long i = -i_max; i <= i_max; ++i) {
        const double tip = R0 * cos((double)i * dphi);
        if (tip > z) {
            sum += w * tip;
            count += w;
        }
        if (tip > z - H) {
            sum += (1 - w) * (tip + H);
            count += 1 - w;
        }
    }
    return (sum - G / k_r) / count;
}

static void test_equilibrium_closed_form(void **state)
{
    (void)state;
    tirenv_tire tire = tirenv_test_default_tire();
    tire.springs.c_b = 0;
    tire.springs.dphi = 0.0123;  /* not a divisor of phi: an uneven layout */
    tirenv_model *m = tirenv_model_alloc(tirenv_model_springs, &tire);
    assert_non_null(m);
    tirenv_profile *low = flat_at(0);
    const double Hs[] = {0.0031, 0.0217, 0.0538};
    const double ws[] = {0.5, 0.3};
    for (size_t i = 0; i < sizeof Hs / sizeof Hs[0]; ++i)
        for (size_t j = 0; j < sizeof ws / sizeof ws[0]; ++j) {
            tirenv_profile *high = flat_at(Hs[i]);
            const tirenv_profile *two[2] = {low, high};
            const double w[2] = {ws[j], 1 - ws[j]};
            tirenv_diag d;
            assert_int_equal(tirenv_model_set_tracks(m, 2, two, w, load, &d), TIRENV_OK);
            tirenv_point pt;
            assert_int_equal(tirenv_model_eval(m, 0.37, &pt, &d), TIRENV_OK);
            const double z = closed_form_z(&tire, ws[j], Hs[i], load);
            assert_near(pt.z, z, 2 * tire.eq.eps_z, 0);
            assert_near(pt.fz, load, tire.eq.eps_F, 0);
            assert_near(pt.slope, 0, 1e-12, 0);
            /* Between the two single tracks: the flat one's h = 0 and the raised one's H. */
            assert_true(pt.h > 0 && pt.h < Hs[i]);
            tirenv_profile_free(high);
        }
    tirenv_profile_free(low);
    tirenv_model_free(m);
}

/* The rigid disc on two cleats of different heights rests on the higher; ties share it. */
static void test_highest_two_cleats(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    tirenv_profile *a = tirenv_profile_cleat(0.2, 0.05), *b = tirenv_profile_cleat(0.1, 0.08);
    tirenv_model *m = tirenv_model_alloc(tirenv_model_rigid, &tire);
    double x[N_POS];
    positions(x);
    static tirenv_point pa[N_POS], pb[N_POS], both[N_POS];
    tirenv_diag d;
    assert_int_equal(tirenv_model_set(m, a, load, &d), TIRENV_OK);
    curve(m, x, pa);
    assert_int_equal(tirenv_model_set(m, b, load, &d), TIRENV_OK);
    curve(m, x, pb);
    const tirenv_profile *two[2] = {a, b};
    assert_int_equal(tirenv_model_set_tracks(m, 2, two, NULL, load, &d), TIRENV_OK);
    curve(m, x, both);
    for (size_t k = 0; k < N_POS; ++k) {
        assert_bits_equal(both[k].z, fmax(pa[k].z, pb[k].z));
        if (pa[k].z > pb[k].z)
            assert_bits_equal(both[k].slope, pa[k].slope);
        else if (pb[k].z > pa[k].z)
            assert_bits_equal(both[k].slope, pb[k].slope);
    }
    tirenv_model_free(m);
    tirenv_profile_free(a);
    tirenv_profile_free(b);
}

/* Rows of two tracks from arrays, for the streamed sweep. */
typedef struct {
    const double *x, *z0, *z1;
    size_t n, next;
} rows;

static int rows_next(void *ctx, double *x, double z[], int *got, tirenv_diag *diag)
{
    (void)diag;
    rows *r = ctx;
    *got = r->next < r->n;
    if (*got) {
        *x = r->x[r->next];
        z[0] = r->z0[r->next];
        z[1] = r->z1[r->next];
        r->next++;
    }
    return TIRENV_OK;
}

/* Two tracks of different ISO 8608 roads, 12 m, streamed: every point as over the whole
 * tracks, bit for bit, for the equilibrium (springs) and the mean (cam); the window stays
 * small. */
static void test_stream_tracks(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    tirenv_road_settings rs = tirenv_road_default();
    rs.road_class = 'D';
    rs.length = 12;
    rs.seed = 11;
    tirenv_profile *r0 = NULL, *r1 = NULL;
    tirenv_diag d;
    assert_int_equal(tirenv_road_iso8608(&rs, &r0, &d), TIRENV_OK);
    rs.seed = 12;
    assert_int_equal(tirenv_road_iso8608(&rs, &r1, &d), TIRENV_OK);
    assert_int_equal(tirenv_profile_size(r0), tirenv_profile_size(r1));
    const double x_from = 0.5, x_to = 11.5, dx = 0.005;
    const size_t n = tirenv_positions_count(x_from, x_to, dx);
    double *x = malloc(n * sizeof *x);
    tirenv_point *whole = malloc(n * sizeof *whole), *streamed = malloc(n * sizeof *streamed);
    for (size_t k = 0; k < n; ++k)
        x[k] = x_from + (double)k * dx;
    const tirenv_model_type *types[] = {tirenv_model_springs, tirenv_model_cam};
    const double w[2] = {0.4, 0.6};
    for (size_t i = 0; i < 2; ++i) {
        tirenv_model *m = tirenv_model_alloc(types[i], &tire);
        const tirenv_profile *two[2] = {r0, r1};
        assert_int_equal(tirenv_model_set_tracks(m, 2, two, w, load, &d), TIRENV_OK);
        assert_int_equal(tirenv_model_envelope(m, n, x, whole, NULL, &d), TIRENV_OK);
        rows src = {tirenv_profile_x(r0), tirenv_profile_z(r0), tirenv_profile_z(r1),
                    tirenv_profile_size(r0), 0};
        tirenv_test_points sb = {streamed, 0, n, 0};
        tirenv_stream_stats st;
        assert_int_equal(tirenv_model_stream_tracks(m, 2, w, rows_next, &src, x_from, x_to, dx,
                                                    load, tirenv_test_keep_point, &sb, &st, &d),
                         TIRENV_OK);
        assert_int_equal(sb.n, n);
        for (size_t k = 0; k < n; ++k)
            assert_points_bits(&streamed[k], &whole[k]);
        assert_true(st.window_max < 700);
        assert_true(st.rebuilds > 3);
        tirenv_model_free(m);
    }
    free(x);
    free(whole);
    free(streamed);
    tirenv_profile_free(r0);
    tirenv_profile_free(r1);
}

static void test_spread(void **state)
{
    (void)state;
    double v[5];
    tirenv_diag d;
    assert_int_equal(tirenv_tracks_spread(1, 0.9, 0.38, v, &d), TIRENV_OK);
    assert_bits_equal(v[0], 0.9);
    assert_int_equal(tirenv_tracks_spread(4, 0.9, 0.38, v, &d), TIRENV_OK);
    for (size_t i = 0; i < 4; ++i)
        assert_near(v[i], 0.9 - 0.19 + (0.095 * (double)i + 0.0475), 1e-15, 0);
    assert_near(v[0] + v[3], 1.8, 1e-15, 0);  /* symmetric about the centre */
    assert_int_equal(tirenv_tracks_spread(0, 0, 1, v, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_tracks_spread(3, 0, -1, v, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_tracks_spread(3, NAN, 1, v, &d), TIRENV_EINVAL);
    assert_string_equal(tirenv_tracks_rule_name(TIRENV_TRACKS_EQUILIBRIUM), "equilibrium");
    assert_null(tirenv_tracks_rule_name((tirenv_tracks_rule)7));
    assert_int_equal(tirenv_model_type_tracks(tirenv_model_springs), TIRENV_TRACKS_EQUILIBRIUM);
    assert_int_equal(tirenv_model_type_tracks(tirenv_model_ring), TIRENV_TRACKS_EQUILIBRIUM);
    assert_int_equal(tirenv_model_type_tracks(tirenv_model_rigid), TIRENV_TRACKS_HIGHEST);
    assert_int_equal(tirenv_model_type_tracks(tirenv_model_cam), TIRENV_TRACKS_MEAN);
    assert_int_equal(tirenv_model_type_tracks(tirenv_model_nn), TIRENV_TRACKS_MEAN);
    assert_int_equal(tirenv_model_type_tracks(tirenv_model_point), TIRENV_TRACKS_MEAN);
}

/* Bad calls: no tracks, a NULL profile, a weight that is not positive, windows that are not
 * the tracks set, windows after a plain set; each leaves the model unset. */
static void test_errors(void **state)
{
    (void)state;
    const tirenv_tire tire = tirenv_test_default_tire();
    tirenv_model *m = tirenv_model_alloc(tirenv_model_cam, &tire);
    tirenv_profile *a = flat_at(0), *b = flat_at(0.01), *c = flat_at(0.02);
    const tirenv_profile *ab[2] = {a, b}, *aa[2] = {a, a}, *cc[2] = {c, c}, *an[2] = {a, NULL};
    tirenv_diag d;
    tirenv_point pt;
    assert_int_equal(tirenv_model_set_tracks(m, 0, ab, NULL, load, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_set_tracks(m, 2, an, NULL, load, &d), TIRENV_EINVAL);
    assert_int_equal(d.line, 2);
    const double bad[2][2] = {{1, 0}, {1, NAN}};
    for (size_t i = 0; i < 2; ++i) {
        assert_int_equal(tirenv_model_set_tracks(m, 2, ab, bad[i], load, &d), TIRENV_EINVAL);
        assert_string_equal(d.field, "weight");
    }
    assert_int_equal(tirenv_model_eval(m, 0, &pt, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_set_tracks(m, 2, ab, NULL, -1, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_tracks(m), 0);

    assert_int_equal(tirenv_model_set_tracks(m, 2, ab, NULL, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_tracks(m), 2);
    assert_int_equal(tirenv_model_set_track_profiles(m, 2, cc, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_eval(m, 0, &pt, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_set_tracks(m, 2, aa, NULL, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set_track_profiles(m, 2, ab, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_set_tracks(m, 2, ab, NULL, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set_track_profiles(m, 1, ab, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_set_tracks(m, 2, ab, NULL, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set_profile(m, c, &d), TIRENV_EINVAL);
    assert_int_equal(tirenv_model_set_tracks(m, 2, ab, NULL, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set(m, c, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set_track_profiles(m, 2, ab, &d), TIRENV_EINVAL);
    /* And a good window: b then a, as new tracks. */
    const tirenv_profile *ba[2] = {b, a};
    assert_int_equal(tirenv_model_set_tracks(m, 2, ab, NULL, load, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_set_track_profiles(m, 2, ba, &d), TIRENV_OK);
    assert_int_equal(tirenv_model_eval(m, 0, &pt, &d), TIRENV_OK);
    assert_near(pt.h, 0.005, 1e-15, 0);
    tirenv_model_free(m);
    tirenv_profile_free(a);
    tirenv_profile_free(b);
    tirenv_profile_free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_track_is_set),
        cmocka_unit_test(test_equal_copies),
        cmocka_unit_test(test_equal_copies_with_shear),
        cmocka_unit_test(test_flat_and_cleat),
        cmocka_unit_test(test_equilibrium_closed_form),
        cmocka_unit_test(test_highest_two_cleats),
        cmocka_unit_test(test_stream_tracks),
        cmocka_unit_test(test_spread),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
