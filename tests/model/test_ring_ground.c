/* SPDX-License-Identifier: Apache-2.0 */
/* The ring's sampling of the ground (src/model/ring_ground.c, docs/models.md section 5.3):
 * where two pieces meet at a node on one ray, their two quadrature points are one point
 * weighted by both halves. Against the sampling that keeps them apart (r->apart, as it was
 * before), over seeded cleats, blades, steps and class C roads with vertices 10 mm and 1 mm
 * apart, with the default tire's shear-coupled tread and with the Winkler tread: the same
 * ground (the diagnostics' d and b per node, the same bits; the weights' sum) and contact
 * (--detail's counts, tread compression, the patch), the same equilibrium to round-off (h
 * within 1e-9 m and F_x within 1e-3 N, the limits the join was allowed; measured 6.3e-11 m,
 * the equilibria's own tolerance here, and 2.6e-6 N), and fewer points. The points of the
 * pieces between two nodes, written by their own writer, against the general one's, bit for
 * bit. And the vertices' angles, taken without atan2, against atan2. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testutil.h"
#include "tirenv/tirenv.h"
#include "tirenv/rng.h"
#include "model/ring_impl.h"
#include "profile/profile_impl.h"

/* A seeded obstacle: cleat, 5 mm blade or step (as test_ring_continuity.c draws them), or a
 * 3 m class C road with vertices 10 mm or 1 mm apart. */
static tirenv_profile *random_ground(tirenv_rng *rng, int kind)
{
    if (kind == 0)
        return tirenv_profile_cleat(0.02 + 0.28 * tirenv_rng_uniform(rng),
                                    0.01 + 0.11 * tirenv_rng_uniform(rng));
    if (kind == 1)
        return tirenv_profile_cleat(0.005, 0.05 + 0.15 * tirenv_rng_uniform(rng));
    if (kind == 2)
        return tirenv_profile_step(0, (tirenv_rng_uniform(rng) < 0.5 ? -1 : 1) *
                                          (0.02 + 0.1 * tirenv_rng_uniform(rng)));
    tirenv_road_settings s = tirenv_road_default();
    s.length = 3;
    s.dx = kind == 3 ? 0.01 : 0.001;
    s.seed = (unsigned long)(1000 * tirenv_rng_uniform(rng));
    tirenv_profile *p = NULL;
    tirenv_diag diag;
    assert_int_equal(tirenv_road_iso8608(&s, &p, &diag), TIRENV_OK);
    return p;
}

/* The centre height at x where the ring carries load G (N), by Newton's method on F_z(z) with
 * its exact dF_z/dz, from z (m); its F_x into *fx. */
static double equilibrium(tirenv_ring *r, const tirenv_profile *p, double x, double z,
                          double G, double *fx)
{
    for (int it = 0; it < 60; ++it) {
        double fz, dfz;
        assert_int_equal(tirenv_ring_forces(r, p, x, z, fx, &fz, &dfz, NULL, NULL), 0);
        if (fabs(fz - G) < 1e-9 * G) /* 2e-5 N at most: within 1e-10 m of the root */
            return z;
        if (fz == 0) { /* above the ground: down */
            z -= 0.02;
            continue;
        }
        assert_true(dfz < 0);
        const double step = (fz - G) / dfz;
        z -= fmax(-0.02, fmin(0.02, step)); /* from far above or below, a bounded step */
    }
    fail_msg("no equilibrium at x = %g m", x);
    return NAN;
}

/* Two rings' last evaluations at the same centre give the same diagnostics (--detail's
 * contacts, belt contacts, tread compression, the patch) and the same window. The tolerances
 * are round-off's (the joined points sum their weights first): measured over both tests'
 * 520 evaluations, the tread compression within 3.9e-13 m, the patch within 4.1e-12 m. */
static void same_diagnostics(tirenv_ring *const r[2], const size_t contacts[2])
{
    assert_int_equal(contacts[0], contacts[1]);
    assert_int_equal(tirenv_ring_belt_contacts(r[0]), tirenv_ring_belt_contacts(r[1]));
    assert_near(tirenv_ring_tread_max(r[0]), tirenv_ring_tread_max(r[1]), 1e-12, 0);
    assert_near(tirenv_ring_patch_length(r[0]), tirenv_ring_patch_length(r[1]), 1e-9, 0);
    assert_int_equal(r[0]->lo, r[1]->lo);
    assert_int_equal(r[0]->n, r[1]->n);
}

static void test_joined_points_as_apart(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(25);
    assert_non_null(rng);
    double dh_max = 0, dfx_max = 0;
    size_t compared = 0, fewer = 0;
    for (int tread = 0; tread < 2; ++tread) {
        tirenv_tire t = tirenv_tire_default();
        if (tread)
            t.ring.G_t = 0; /* the Winkler tread */
        const double M = 2 * M_PI / t.ring.dtheta;
        double *d[2], *b[2];
        for (int k = 0; k < 2; ++k) {
            d[k] = malloc((size_t)(M + 0.5) * sizeof(double));
            b[k] = malloc((size_t)(M + 0.5) * sizeof(double));
            assert_true(d[k] && b[k]);
        }
        for (int kind = 0; kind < 5; ++kind) {
            tirenv_profile *p = random_ground(rng, kind);
            tirenv_ring *r[2];
            for (int k = 0; k < 2; ++k) {
                r[k] = tirenv_ring_alloc(t.springs.R0, &t.ring);
                assert_non_null(r[k]);
            }
            r[1]->apart = 1;
            r[0]->whole_ground = r[1]->whole_ground = 1; /* every point (test_gaps_as_whole) */
            const double G = 8000 + 16000 * tirenv_rng_uniform(rng);
            const double x0 = kind >= 3 ? 0.5 : -0.45;
            for (int i = 0; i < 12; ++i) {
                const double x = x0 + (kind >= 3 ? 2.0 : 0.9) * tirenv_rng_uniform(rng);
                const double z0 = tirenv_profile_max_height(p, x - 0.3, x + 0.3) + 0.62;
                double fx[2], h[2];
                for (int k = 0; k < 2; ++k)
                    h[k] = equilibrium(r[k], p, x, z0, G, &fx[k]);
                dh_max = fmax(dh_max, fabs(h[0] - h[1]));
                dfx_max = fmax(dfx_max, fabs(fx[0] - fx[1]));
                assert_near(h[0], h[1], 1e-9, 0);
                assert_near(fx[0], fx[1], 1e-3, 0);
                /* The same ground at the same centre: d, b per node, the weights' sum; and
                 * the same diagnostics (--detail's contacts, belt contacts, tread compression,
                 * the patch). */
                double fz, om[2] = {0, 0};
                size_t contacts[2];
                for (int k = 0; k < 2; ++k) {
                    assert_int_equal(tirenv_ring_forces(r[k], p, x, h[0], &fx[k], &fz, NULL,
                                                        &contacts[k], NULL), 0);
                    tirenv_ring_contact(r[k], d[k], b[k], NULL);
                    for (size_t q = 0; q < r[k]->n_pts; ++q)
                        if (r[k]->pts[q].d > -INFINITY)
                            om[k] += r[k]->pts[q].omega;
                }
                same_diagnostics(r, contacts);
                assert_true(tirenv_ring__same_bits(d[0], d[1], (size_t)(M + 0.5)));
                assert_true(tirenv_ring__same_bits(b[0], b[1], (size_t)(M + 0.5)));
                assert_near(om[0], om[1], 1e-12, 0); /* measured 5.2e-15 rad */
                assert_true(r[0]->n_pts <= r[1]->n_pts);
                fewer += r[0]->n_pts < r[1]->n_pts;
                ++compared;
            }
            for (int k = 0; k < 2; ++k)
                tirenv_ring_free(r[k]);
            tirenv_profile_free(p);
        }
        for (int k = 0; k < 2; ++k) {
            free(d[k]);
            free(b[k]);
        }
    }
    print_message("joined against apart at %zu equilibria (%zu with fewer points): |dh| <= "
                  "%.3g m, |dF_x| <= %.3g N\n", compared, fewer, dh_max, dfx_max);
    assert_int_equal(compared, 120);
    assert_true(fewer == compared); /* every window holds some ground along one line */
    tirenv_rng_free(rng);
}

/* The window's far stretches left unsampled (ring_ground.c far_intervals), their ground
 * bounded instead, against every point sampled (whole_ground), with the shear-coupled tread:
 * over seeded cleats, blades, steps and class C roads, sweeps of 1 mm steps (the last
 * sub-window guides the next sampling), at each x the equilibrium and then one evaluation at
 * it; the same equilibrium (h within 1e-9 m, F_x within 1e-3 N; measured: the same bits), the
 * same window, diagnostics and patch; gaps left at most evaluations over the obstacles (none
 * over the roads, whose vertices are too many: ring_ground.c SKIP_CUTS), and the points of the
 * sampled intervals those of the whole sampling. */
static void test_gaps_as_whole(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(31);
    assert_non_null(rng);
    const tirenv_tire t = tirenv_tire_default();
    double dh_max = 0, dfx_max = 0;
    size_t compared = 0, same = 0, gapped = 0, evals = 0, regap = 0;
    for (int kind = 0; kind < 5; ++kind) {
        for (int rep = 0; rep < 2; ++rep) {
            tirenv_profile *p = random_ground(rng, kind);
            tirenv_ring *r[2];
            for (int k = 0; k < 2; ++k) {
                r[k] = tirenv_ring_alloc(t.springs.R0, &t.ring);
                assert_non_null(r[k]);
            }
            r[1]->whole_ground = 1;
            const double G = 12000 + 18000 * tirenv_rng_uniform(rng);
            const double x0 = (kind >= 3 ? 0.6 : -0.5) + 0.6 * tirenv_rng_uniform(rng);
            double z = tirenv_profile_max_height(p, x0 - 0.3, x0 + 0.3) + 0.62;
            for (int i = 0; i < 40; ++i) {
                const double x = x0 + 0.001 * i;
                double fx[2], h[2];
                const size_t e0 = r[0]->n_gapped;
                for (int k = 0; k < 2; ++k)
                    h[k] = equilibrium(r[k], p, x, z, G, &fx[k]);
                z = h[0];
                dh_max = fmax(dh_max, fabs(h[0] - h[1]));
                dfx_max = fmax(dfx_max, fabs(fx[0] - fx[1]));
                assert_near(h[0], h[1], 1e-9, 0);
                assert_near(fx[0], fx[1], 1e-3, 0);
                same += h[0] == h[1] && fx[0] == fx[1];
                double fz[2];
                size_t contacts[2];
                for (int k = 0; k < 2; ++k)
                    assert_int_equal(tirenv_ring_forces(r[k], p, x, h[0], &fx[k], &fz[k], NULL,
                                                        &contacts[k], NULL), 0);
                if (kind < 3) {
                    gapped += r[0]->n_gapped > e0;
                    ++evals;
                }
                assert_near(fz[0], fz[1], 1e-6, 0); /* measured: the same bits */
                same_diagnostics(r, contacts);
                /* Each point of the gapped sampling is the whole one's, but at a gap's edge
                 * (a node's point there not joined with the gap's); none lies in a gap. */
                size_t q1 = 0;
                for (size_t q = 0; q < r[0]->n_pts; ++q) {
                    const tirenv_ring_point *a = &r[0]->pts[q];
                    assert_false(r[0]->n_gaps && r[0]->gap_on[a->j]);
                    while (q1 < r[1]->n_pts && !(r[1]->pts[q1].phi == a->phi &&
                                                 r[1]->pts[q1].d == a->d))
                        ++q1;
                    assert_true(q1 < r[1]->n_pts);
                }
                ++compared;
            }
            regap += r[0]->n_regap;
            for (int k = 0; k < 2; ++k)
                tirenv_ring_free(r[k]);
            tirenv_profile_free(p);
        }
    }
    print_message("gaps against whole at %zu equilibria (%zu the same bits): |dh| <= %.3g m, "
                  "|dF_x| <= %.3g N; over the obstacles %zu of %zu evaluations left gaps, %zu "
                  "sampled whole again\n", compared, same, dh_max, dfx_max, gapped, evals, regap);
    assert_int_equal(compared, 400);
    assert_int_equal(evals, 240);
    assert_true(gapped > evals * 3 / 4);
    tirenv_rng_free(rng);
}

/* The points of a piece between two nodes are written by piece_point specialised to such
 * pieces (ring_ground.c write_points): against the general writer's (r->nodes_general), bit
 * for bit, every field a point's solve reads (its d, place, weight, stiffness within reach,
 * interval, ends, angle, sine, cosine, d(d)/dz, d(phi)/dz, d(d)/dz along the cut, ground
 * abscissa) and both forces, over seeded cleats, blades, steps and class C roads with vertices
 * 10 mm and 1 mm apart: sweeps of 1 mm steps, each at a height pressing the tread some 1 to 3
 * cm and 3.7e-6 m above it (a Newton step's), and centres exactly on a vertex of the ground.
 * The two rings evaluate the same sequence, so their warm starts and kept samplings match. */
static void test_node_pieces_as_general(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(27);
    assert_non_null(rng);
    const tirenv_tire t = tirenv_tire_default();
    size_t evals = 0, points = 0, node_pieces = 0;
    for (int kind = 0; kind < 5; ++kind) {
        tirenv_profile *p = random_ground(rng, kind);
        tirenv_ring *r[2];
        for (int k = 0; k < 2; ++k) {
            r[k] = tirenv_ring_alloc(t.springs.R0, &t.ring);
            assert_non_null(r[k]);
        }
        r[1]->nodes_general = 1;
        const double x0 = (kind >= 3 ? 0.6 : -0.35) + 0.5 * tirenv_rng_uniform(rng);
        for (int i = 0; i < 24; ++i) {
            double x = x0 + 0.001 * i;
            if (i % 8 == 7) { /* on a vertex: the nearest at or after x */
                size_t v = 0;
                while (v + 1 < p->n && p->x[v] < x)
                    ++v;
                x = p->x[v];
            }
            const double zt = tirenv_profile_max_height(p, x - 0.3, x + 0.3) + t.springs.R0 -
                              0.01 - 0.02 * tirenv_rng_uniform(rng);
            for (int dz = 0; dz < 2; ++dz) {
                const double z = zt + 3.7e-6 * dz;
                double fx[2], fz[2];
                for (int k = 0; k < 2; ++k)
                    assert_int_equal(tirenv_ring_forces(r[k], p, x, z, &fx[k], &fz[k], NULL,
                                                        NULL, NULL), 0);
                assert_true(tirenv_ring__same_bits(fx, fx + 1, 1));
                assert_true(tirenv_ring__same_bits(fz, fz + 1, 1));
                assert_int_equal(r[0]->n_pts, r[1]->n_pts);
                for (size_t q = 0; q < r[0]->n_pts; ++q) {
                    const tirenv_ring_point *a = &r[0]->pts[q], *b = &r[1]->pts[q];
                    assert_true(tirenv_ring__same_bits(&a->d, &b->d, 1));
                    assert_true(tirenv_ring__same_bits(&a->s, &b->s, 1));
                    assert_true(tirenv_ring__same_bits(&a->omega, &b->omega, 1));
                    assert_true(a->d == -INFINITY || tirenv_ring__same_bits(&a->k_t, &b->k_t, 1));
                    assert_int_equal(a->j, b->j);
                    assert_int_equal(a->ends, b->ends);
                    assert_true(tirenv_ring__same_bits(&a->phi, &b->phi, 3)); /* phi, sn, cs */
                    assert_true(tirenv_ring__same_bits(&a->dd, &b->dd, 4)); /* to X */
                }
                points += r[0]->n_pts;
                for (size_t c = 0; c < r[0]->pc_jb - r[0]->pc_ja + r[0]->pc_nv; ++c)
                    node_pieces += r[0]->pc_valid && r[0]->pc_nv < r[0]->pc_jb - r[0]->pc_ja &&
                                   r[0]->lines[c].nodes && r[0]->lines[c].hit;
                ++evals;
            }
        }
        for (int k = 0; k < 2; ++k)
            tirenv_ring_free(r[k]);
        tirenv_profile_free(p);
    }
    print_message("node pieces' writer against the general one: %zu evaluations, %zu points, "
                  "%zu pieces between two nodes by their own writer\n", evals, points,
                  node_pieces);
    assert_int_equal(evals, 240);
    assert_true(node_pieces > 1000);
    tirenv_rng_free(rng);
}

/* A ground vertex's angle seen from the centre (a cut's) is taken from the nearest node's by
 * atan's series, not by atan2 (ring_ground.c cut_angle): against atan2 of the cut's own sine
 * and cosine (themselves rounded), within 4.5e-16 rad (measured 2.2e-16, two ulps at 0.5
 * rad), over the seeded grounds above at random centres (30,333 vertex cuts, some 1,000 an
 * evaluation on a 1 mm road); and the points in angle order. */
static void test_cut_angles(void **state)
{
    (void)state;
    tirenv_rng *rng = tirenv_rng_alloc(26);
    const tirenv_tire t = tirenv_tire_default();
    tirenv_ring *r = tirenv_ring_alloc(t.springs.R0, &t.ring);
    assert_true(rng && r);
    size_t cuts = 0;
    double err = 0;
    for (int kind = 0; kind < 5; ++kind) {
        tirenv_profile *p = random_ground(rng, kind);
        for (int i = 0; i < 20; ++i) {
            const double x = (kind >= 3 ? 0.5 : -0.45) + (kind >= 3 ? 2.0 : 0.9) *
                                                             tirenv_rng_uniform(rng);
            const double z = tirenv_profile_max_height(p, x - 0.3, x + 0.3) + 0.58 +
                             0.1 * tirenv_rng_uniform(rng);
            double fx, fz;
            assert_int_equal(tirenv_ring_forces(r, p, x, z, &fx, &fz, NULL, NULL, NULL), 0);
            double last = -INFINITY;
            for (size_t k = 0; k < r->n_pts; ++k) {
                const tirenv_ring_point *q = &r->pts[k];
                assert_true(q->phi >= last);
                last = q->phi;
                if (q->dphi == 0)
                    continue; /* a node's */
                const double e = fabs(q->phi - atan2(q->sn, q->cs));
                err = fmax(err, e);
                assert_true(e <= 4.5e-16);
                ++cuts;
            }
        }
        tirenv_profile_free(p);
    }
    print_message("%zu vertex cuts: |phi - atan2| <= %.3g rad\n", cuts, err);
    assert_true(cuts > 10000);
    tirenv_ring_free(r);
    tirenv_rng_free(rng);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_joined_points_as_apart),
        cmocka_unit_test(test_gaps_as_whole),
        cmocka_unit_test(test_node_pieces_as_general),
        cmocka_unit_test(test_cut_angles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
