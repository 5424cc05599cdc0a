/* The equilibrium solvers (src/core/equilibrium.c, docs/models.md section 4) on their own, in
 * the manner of GSL's roots/test.c: a table of force laws with known answers (smooth, kinked,
 * a jump in F_z, a plateau, no bracket) and cases that must fail with the right status and
 * stop reason, looped over every method, with the jump each measures across its final
 * bracket. Each solve also checks that the reported point is one
 * of the force function's own evaluations, bit for bit, and that the budget of evaluations
 * holds, whatever the force function does. SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"

#include <math.h>
#include <string.h>

#include "core/equilibrium.h"

/* ---- force laws: F_z(z) never increasing, 0 above first contact ---------------------------- */

typedef enum { SMOOTH, KINKED, JUMP, PLATEAU } law_kind;

typedef struct {
    law_kind kind;
    double a;              /* first contact, m */
    double b;              /* kink, jump or plateau's lower end, m */
    double k1, k2;         /* stiffnesses (SMOOTH: k1 in N/m^1.5), N/m */
    double J;              /* JUMP: the jump, N; PLATEAU: its force, N */
    double z_fail;         /* in [z_fail - BAND, z_fail) the force function fails */
    double z_nan;          /* in [z_nan - BAND, z_nan) F is NaN (-INFINITY: never) */
    double z_unsettled;    /* below it the force does not converge (TIRENV_ENOCONV), as the
                            * ring's contact crushed by a radius; 0: never in these ranges */
} law;

static void law_eval(const law *L, double z, double *F, double *dF)
{
    const double u = L->a - z;
    *F = *dF = 0;
    switch (L->kind) {
    case SMOOTH:  /* Hertz-like: k1 u^1.5 */
        if (u > 0) {
            *F = L->k1 * u * sqrt(u);
            *dF = -1.5 * L->k1 * sqrt(u);
        }
        break;
    case KINKED:  /* stiffer below the kink b */
        if (z < L->b) {
            *F = L->k1 * (L->a - L->b) + L->k2 * (L->b - z);
            *dF = -L->k2;
        } else if (u > 0) {
            *F = L->k1 * u;
            *dF = -L->k1;
        }
        break;
    case JUMP:    /* F jumps by J where z passes below b (a ray switching faces) */
        if (u > 0) {
            *F = L->k1 * u + (z < L->b ? L->J : 0);
            *dF = -L->k1;
        }
        break;
    case PLATEAU: /* constant J on [b, a), stiff below b */
        if (z < L->b) {
            *F = L->J + L->k2 * (L->b - z);
            *dF = -L->k2;
        } else if (u > 0) {
            *F = L->J;
            *dF = 0;
        }
        break;
    }
}

/* The force function records every evaluation, so that the reported point can be checked
 * against them. F_x and the contacts are made-up functions of z (high entropy) whose only
 * purpose is to come from the same evaluation as F. */
enum { LOG_MAX = 512 };
static const double BAND = 0.0035;  /* m */
typedef struct {
    const law *L;
    size_t calls;          /* every call, failed ones too */
    size_t n;
    tirenv_eq_point log[LOG_MAX];
} recorder;

static int force(void *ctx, double z, tirenv_eq_point *out, tirenv_diag *diag)
{
    recorder *r = ctx;
    ++r->calls;
    if (z >= r->L->z_fail - BAND && z < r->L->z_fail)
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "test", "refused at z = %.6g m", z);
    if (z < r->L->z_unsettled)
        return tirenv_error(diag, TIRENV_ENOCONV, "", 0, "test", "did not settle at z = %.6g m",
                            z);
    double F, dF;
    law_eval(r->L, z, &F, &dF);
    if (z >= r->L->z_nan - BAND && z < r->L->z_nan)
        F = NAN;
    *out = (tirenv_eq_point){.z = z, .F = F, .dF_dz = dF, .fx = -0.137 * F * sin(41.3 * z),
                             .contacts = (size_t)(fabs(F) / 997.0)};
    if (r->n < LOG_MAX)
        r->log[r->n++] = *out;
    return TIRENV_OK;
}

/* ---- the table -------------------------------------------------------------------------- */

/* What a method must do on a case. */
typedef struct {
    int status;            /* TIRENV_OK or the failure */
    tirenv_eq_stop stop;   /* why it stops; TIRENV_EQ_RUNNING: residual or bracket, either */
} expect;

typedef struct {
    const char *name;
    law L;
    double G;              /* load, N */
    tirenv_eq_problem prob;
    double root;           /* z where F = G, or the jump's z; NaN if none */
    size_t max_iter;       /* 0: the default */
    expect e[3];           /* newton, secant, brent */
} eq_case;

#define OK_ANY {TIRENV_OK, TIRENV_EQ_RUNNING}
#define NEVER (-INFINITY)

/* The smooth law's root: a - (G/k)^(2/3). */
static const double smooth_a = 0.6817, smooth_k = 3.137e7;
#define SMOOTH_LAW {SMOOTH, 0.6817, 0, 3.137e7, 0, 0, NEVER, NEVER, 0}

static const eq_case cases[] = {
    {"smooth, warm start below the root", SMOOTH_LAW, 12345.6,
     {0.0, 0.6817, 0.62, 0.03, NULL, NULL}, NAN, 0, {OK_ANY, OK_ANY, OK_ANY}},
    {"smooth, cold start at first contact", SMOOTH_LAW, 12345.6,
     {0.0, 0.6817, 0.6817 - 0.0413, 0.0413, NULL, NULL}, NAN, 0, {OK_ANY, OK_ANY, OK_ANY}},
    /* k1 (a - b) = 11152 N at the kink; the root is 0.0123 m below it. */
    {"kinked, the root below a stiffening kink",
     {KINKED, 0.6793, 0.6521, 4.1e5, 1.7e6, 0, NEVER, NEVER, 0}, 4.1e5 * (0.6793 - 0.6521) +
     1.7e6 * 0.0123, {0.0, 0.6793, 0.6701, 0.02, NULL, NULL}, 0.6521 - 0.0123, 0,
     {OK_ANY, OK_ANY, OK_ANY}},
    /* k (a - b) = 17264 N just above the jump, 19664 N just below: G = 18000 N has no root,
     * the equilibrium is the jump. The plain secant has no bracket and cannot find it. */
    {"a jump in F_z across the load",
     {JUMP, 0.6911, 0.6703, 8.3e5, 0, 2400, NEVER, NEVER, 0}, 18000,
     {0.0, 0.6911, 0.6811, 0.02, NULL, NULL}, 0.6703, 0,
     {{TIRENV_OK, TIRENV_EQ_BRACKET}, {TIRENV_ENOCONV, TIRENV_EQ_MAX_EVALS},
      {TIRENV_OK, TIRENV_EQ_BRACKET}}},
    /* F = 9876.5 N on [0.66, 0.70): the secant's first two points see equal forces. */
    {"a plateau of F_z above the root",
     {PLATEAU, 0.70, 0.66, 0, 2.3e6, 9876.5, NEVER, NEVER, 0}, 15234.5,
     {0.0, 0.70, 0.69, 0.02, NULL, NULL}, 0.66 - (15234.5 - 9876.5) / 2.3e6, 0,
     {OK_ANY, {TIRENV_ENOCONV, TIRENV_EQ_BREAKDOWN}, OK_ANY}},
    /* F(z_lo = 0.5) = 2.43e6 N < G: no equilibrium above z_lo. */
    {"no bracket: the load exceeds what the tire carries", SMOOTH_LAW, 3.0e6,
     {0.5, 0.6817, 0.62, 0.03, NULL, NULL}, NAN, 0,
     {{TIRENV_ENOBRACKET, TIRENV_EQ_NO_BRACKET}, {TIRENV_ENOCONV, TIRENV_EQ_BREAKDOWN},
      {TIRENV_ENOBRACKET, TIRENV_EQ_NO_BRACKET}}},
    /* The root is at 0.67633 m: every method has to look in [0.6745, 0.678) m, Brent only
     * after it has taken steps of its own. */
    {"the force function fails near the root",
     {SMOOTH, 0.6817, 0, 3.137e7, 0, 0, 0.678, NEVER, 0}, 12345.6,
     {0.0, 0.6817, 0.68, 0.03, NULL, NULL}, NAN, 0,
     {{TIRENV_ERANGE, TIRENV_EQ_FORCE_FAILED}, {TIRENV_ERANGE, TIRENV_EQ_FORCE_FAILED},
      {TIRENV_ERANGE, TIRENV_EQ_FORCE_FAILED}}},
    {"the force function returns NaN near the root",
     {SMOOTH, 0.6817, 0, 3.137e7, 0, 0, NEVER, 0.678, 0}, 12345.6,
     {0.0, 0.6817, 0.68, 0.03, NULL, NULL}, NAN, 0,
     {{TIRENV_ENOCONV, TIRENV_EQ_FORCE_FAILED}, {TIRENV_ENOCONV, TIRENV_EQ_FORCE_FAILED},
      {TIRENV_ENOCONV, TIRENV_EQ_FORCE_FAILED}}},
    {"two evaluations allowed", SMOOTH_LAW, 12345.6,
     {0.0, 0.6817, 0.62, 0.03, NULL, NULL}, NAN, 2,
     {{TIRENV_ENOCONV, TIRENV_EQ_MAX_EVALS}, {TIRENV_ENOCONV, TIRENV_EQ_MAX_EVALS},
      {TIRENV_ENOCONV, TIRENV_EQ_MAX_EVALS}}},
    /* A start at z_lo inside a plateau below the load (a new load's warm start clamped to the
     * ground, where the springs model's force is flat): Newton took dF/dz = 0 for "no contact
     * yet" and stepped down to z_lo again until its evaluations ran out; the secant took its
     * second point below z_lo. */
    {"a start at z_lo on a plateau below the load",
     {PLATEAU, 0.70, 0.66, 0, 2.3e6, 9876.5, NEVER, NEVER, 0}, 15234.5,
     {0.67, 0.70, 0.67, 0.02, NULL, NULL}, NAN, 0,
     {{TIRENV_ENOBRACKET, TIRENV_EQ_NO_BRACKET}, {TIRENV_ENOCONV, TIRENV_EQ_BREAKDOWN},
      {TIRENV_ENOBRACKET, TIRENV_EQ_NO_BRACKET}}},
    /* z0 - SECANT_STEP lies below z_lo: the secant's second point is taken above (it
     * refused before, though the root lies in range). */
    {"smooth, a start within SECANT_STEP above z_lo", SMOOTH_LAW, 12345.6,
     {0.6, 0.6817, 0.6005, 0.03, NULL, NULL}, NAN, 0, {OK_ANY, OK_ANY, OK_ANY}},
    /* The force does not settle at z_lo, the hub at the ground (the ring crushed by a radius
     * over Horstwalde.crg, docs/models.md section 11.1): Brent failed at its lower end, where
     * Newton and the secant never look; its end moves halfway up, where the force settles. */
    {"the force does not settle near z_lo",
     {SMOOTH, 0.6817, 0, 3.137e7, 0, 0, NEVER, NEVER, 0.45}, 12345.6,
     {0.0, 0.6817, 0.62, 0.03, NULL, NULL}, NAN, 0, {OK_ANY, OK_ANY, OK_ANY}},
    /* ... up to 4.3 mm below the root (0.67633 m): the halving passes the root (an upper end
     * below z_hi), then finds the lower end between. */
    {"the force does not settle up to just below the root",
     {SMOOTH, 0.6817, 0, 3.137e7, 0, 0, NEVER, NEVER, 0.672}, 12345.6,
     {0.0, 0.6817, 0.68, 0.03, NULL, NULL}, NAN, 0, {OK_ANY, OK_ANY, OK_ANY}},
    /* ... and anywhere below 0.678 m, the root too: every method fails with the force's
     * words, Brent once its search has closed to eps_z. */
    {"the force does not settle at the root",
     {SMOOTH, 0.6817, 0, 3.137e7, 0, 0, NEVER, NEVER, 0.678}, 12345.6,
     {0.0, 0.6817, 0.68, 0.03, NULL, NULL}, NAN, 0,
     {{TIRENV_ENOCONV, TIRENV_EQ_FORCE_FAILED}, {TIRENV_ENOCONV, TIRENV_EQ_FORCE_FAILED},
      {TIRENV_ENOCONV, TIRENV_EQ_FORCE_FAILED}}},
};

static const tirenv_eq_solver_type *const *methods(void)
{
    static const tirenv_eq_solver_type *list[3];
    list[0] = tirenv_eq__newton;
    list[1] = tirenv_eq__secant;
    list[2] = tirenv_eq__brent;
    return list;
}

static void run_case(const eq_case *c, size_t m)
{
    const tirenv_eq_solver_type *T = methods()[m];
    tirenv_eq_settings eq = tirenv_eq_default();
    if (c->max_iter)
        eq.max_iter = c->max_iter;
    tirenv_eq_solver *s = tirenv_eq__solver_alloc(T);
    assert_non_null(s);
    recorder rec = {.L = &c->L, .n = 0};
    tirenv_diag diag;
    tirenv_diag_clear(&diag);
    tirenv_eq_result res;
    const int status = tirenv_eq__solve(s, &eq, force, &rec, c->G, &c->prob, &res, &diag);
    print_message("%-8s %-52s -> %s, stop %s, %zu evaluations, z %.12g\n", T->name, c->name,
                  tirenv_strerror(status), tirenv_eq__stop_name(res.stop), res.evals,
                  res.point.z);
    const expect *e = &c->e[m];
    assert_int_equal(status, e->status);
    assert_int_equal(res.evals, rec.calls);       /* every evaluation counted */
    assert_true(res.evals <= eq.max_iter);        /* and the budget kept */
    for (size_t k = 1; k < rec.n; ++k)            /* no height evaluated twice in a row: */
        assert_true(rec.log[k].z != rec.log[k - 1].z);  /* the force gives nothing new */
    for (size_t k = 0; k < rec.n; ++k)            /* none below the admissible range */
        assert_true(rec.log[k].z >= c->prob.z_lo);
    if (status) {
        assert_int_equal(res.stop, e->stop);
        assert_true(diag.message[0] != '\0');     /* every failure says why */
        assert_true(isnan(res.point.z));
        if (e->stop == TIRENV_EQ_FORCE_FAILED && c->L.z_fail > NEVER)
            assert_non_null(strstr(diag.message, "refused"));  /* the force's own words */
        if (e->stop == TIRENV_EQ_FORCE_FAILED && c->L.z_unsettled > 0)
            assert_non_null(strstr(diag.message, "did not settle"));
        tirenv_eq__solver_free(s);
        return;
    }
    if (e->stop != TIRENV_EQ_RUNNING)
        assert_int_equal(res.stop, e->stop);
    else
        assert_true(res.stop == TIRENV_EQ_RESIDUAL || res.stop == TIRENV_EQ_BRACKET);
    /* The reported point is one of the evaluations, bit for bit. */
    size_t k = 0;
    while (k < rec.n && memcmp(&rec.log[k], &res.point, sizeof res.point) != 0)
        ++k;
    assert_true(k < rec.n);
    /* Where it is: the known root (or the jump) within eps_z, or, for a smooth law, the root
     * the residual implies: |dz| <= eps_F/|dF| + eps_z. */
    double root = c->root;
    if (isnan(root) && c->L.kind == SMOOTH)
        root = smooth_a - pow(c->G / smooth_k, 2.0 / 3.0);
    /* The jump across the final bracket (what the continuous models refuse): the law's own
     * where it has one, to its slope times eps_z; else none beyond the force tolerance (a
     * kink's two slopes account for its bend). */
    if (c->L.kind == JUMP)
        assert_near(res.jump, c->L.J, c->L.k1 * eq.eps_z + 1e-6, 0);
    else
        assert_true(res.jump <= eq.eps_F);
    if (res.stop == TIRENV_EQ_RESIDUAL) {
        assert_true(fabs(res.point.F - c->G) <= eq.eps_F);
        assert_near(res.point.z, root, eq.eps_z + eq.eps_F / fabs(res.point.dF_dz), 0);
    } else {
        assert_near(res.point.z, root, eq.eps_z, 0);
    }
    tirenv_eq__solver_free(s);
}

static void test_table_every_method(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        for (size_t m = 0; m < 3; ++m)
            run_case(&cases[i], m);
}

/* The driver is nothing but set, then test and iterate: done by hand, the steps give the same
 * point and the same count; and test before convergence says "running". */
static void test_steps_by_hand(void **state)
{
    (void)state;
    const eq_case *c = &cases[2];  /* kinked */
    for (size_t m = 0; m < 3; ++m) {
        const tirenv_eq_settings eq = tirenv_eq_default();
        tirenv_eq_solver *s = tirenv_eq__solver_alloc(methods()[m]);
        assert_non_null(s);
        recorder r1 = {.L = &c->L}, r2 = {.L = &c->L};
        tirenv_eq_result res;
        assert_int_equal(tirenv_eq__solve(s, &eq, force, &r1, c->G, &c->prob, &res, NULL),
                         TIRENV_OK);
        tirenv_eq_stop stop;
        const tirenv_eq_point *p = NULL;
        assert_int_equal(tirenv_eq__solver_set(s, &eq, force, &r2, c->G, &c->prob, &stop, NULL),
                         TIRENV_OK);
        size_t steps = 0;
        while (tirenv_eq__solver_test(s, &p) == TIRENV_EQ_RUNNING) {
            assert_null(p);
            assert_int_equal(tirenv_eq__solver_iterate(s, &stop, NULL), TIRENV_OK);
            ++steps;
        }
        assert_true(steps >= 1);  /* the kink is not found from the first guess */
        assert_non_null(p);
        assert_int_equal(memcmp(p, &res.point, sizeof *p), 0);
        assert_int_equal(r2.calls, res.evals);
        tirenv_eq__solver_free(s);
    }
}

/* dF/dz on request (tirenv_eq_problem.slope): a force function that leaves it out and gives
 * it when asked leads Newton through the same evaluations to the same point as one that gives
 * it at once, on the smooth, kinked and plateau laws from the table's starts, and is asked fewer
 * times than it is evaluated: not at the accepted iterate, whose correction the slope before
 * bounds. */
typedef struct {
    recorder rec;
    double z_last;         /* the latest evaluation's height, m */
    size_t asked;
} lazy_recorder;

static int lazy_force(void *ctx, double z, tirenv_eq_point *out, tirenv_diag *diag)
{
    lazy_recorder *l = ctx;
    const int status = force(&l->rec, z, out, diag);
    out->dF_dz = NAN;
    l->z_last = z;
    return status;
}

static int lazy_slope(void *ctx, double *dF_dz)
{
    lazy_recorder *l = ctx;
    double F;
    ++l->asked;
    law_eval(l->rec.L, l->z_last, &F, dF_dz);
    return 0;
}

static void test_slope_on_request(void **state)
{
    (void)state;
    static const size_t which[] = {0, 1, 2, 4}; /* smooth twice, kinked, plateau */
    size_t spared = 0;
    for (size_t i = 0; i < sizeof which / sizeof which[0]; ++i) {
        const eq_case *c = &cases[which[i]];
        const tirenv_eq_settings eq = tirenv_eq_default();
        tirenv_eq_solver *s = tirenv_eq__solver_alloc(tirenv_eq__newton);
        assert_non_null(s);
        recorder eager = {.L = &c->L};
        lazy_recorder lazy = {.rec = {.L = &c->L}};
        tirenv_eq_problem prob = c->prob;
        tirenv_eq_result a, b;
        assert_int_equal(tirenv_eq__solve(s, &eq, force, &eager, c->G, &prob, &a, NULL),
                         TIRENV_OK);
        prob.slope = lazy_slope;
        assert_int_equal(tirenv_eq__solve(s, &eq, lazy_force, &lazy, c->G, &prob, &b, NULL),
                         TIRENV_OK);
        assert_int_equal(a.evals, b.evals);
        assert_int_equal(a.stop, b.stop);
        for (size_t k = 0; k < a.evals; ++k)
            assert_int_equal(memcmp(&eager.log[k].z, &lazy.rec.log[k].z, sizeof(double)), 0);
        assert_int_equal(memcmp(&a.point.z, &b.point.z, sizeof(double)), 0);
        assert_int_equal(memcmp(&a.point.F, &b.point.F, sizeof(double)), 0);
        assert_true(lazy.asked <= b.evals);
        spared += b.evals - lazy.asked;
        tirenv_eq__solver_free(s);
    }
    assert_true(spared >= 2);
}

/* A solver is reused position after position: a solve after a failure starts clean. */
static void test_reuse_after_failure(void **state)
{
    (void)state;
    for (size_t m = 0; m < 3; ++m) {
        tirenv_eq_solver *s = tirenv_eq__solver_alloc(methods()[m]);
        const tirenv_eq_settings eq = tirenv_eq_default();
        recorder bad = {.L = &cases[6].L}, good = {.L = &cases[0].L};
        tirenv_eq_result res;
        assert_int_equal(tirenv_eq__solve(s, &eq, force, &bad, cases[6].G, &cases[6].prob, &res,
                                         NULL),
                         TIRENV_ERANGE);
        assert_int_equal(tirenv_eq__solve(s, &eq, force, &good, cases[0].G, &cases[0].prob,
                                         &res, NULL),
                         TIRENV_OK);
        assert_int_equal(res.evals, good.calls);
        tirenv_eq__solver_free(s);
    }
}

/* The model's first iterate (tirenv_eq_problem's start): Newton evaluates there instead of
 * at z0 where it lies inside the bracket, so that a start at the root is the whole solve (one
 * evaluation, the residual's stop); one outside the bracket, or a model proposing none, leaves
 * the solve as it was, evaluation for evaluation. The smooth law of the table, its root
 * known. */
typedef struct {
    double z;              /* the start proposed, m */
    int has;               /* whether one is proposed */
    double z0_seen;        /* the z0 it was asked from, m */
} proposal;

static proposal the_proposal;

static int propose(void *ctx, double z0, double *z)
{
    (void)ctx;
    the_proposal.z0_seen = z0;
    *z = the_proposal.z;
    return the_proposal.has;
}

static void test_model_start(void **state)
{
    (void)state;
    const eq_case *c = &cases[0]; /* smooth, warm start below the root */
    const double G = c->G, root = smooth_a - pow(G / smooth_k, 2.0 / 3.0);
    const tirenv_eq_settings eq = tirenv_eq_default();
    tirenv_eq_solver *s = tirenv_eq__solver_alloc(tirenv_eq__newton);
    assert_non_null(s);
    tirenv_eq_result plain, res;
    recorder r0 = {.L = &c->L, .n = 0};
    assert_int_equal(tirenv_eq__solve(s, &eq, force, &r0, G, &c->prob, &plain, NULL), 0);
    assert_true(plain.evals > 1);
    const struct {
        double z;
        int has;
        int taken;
    } starts[] = {{root, 1, 1}, {c->prob.z_hi + 0.0137, 1, 0}, {c->prob.z_lo - 0.21, 1, 0},
                  {root, 0, 0}};
    for (size_t k = 0; k < sizeof starts / sizeof starts[0]; ++k) {
        the_proposal = (proposal){.z = starts[k].z, .has = starts[k].has, .z0_seen = NAN};
        tirenv_eq_problem prob = c->prob;
        prob.start = propose;
        recorder r = {.L = &c->L, .n = 0};
        assert_int_equal(tirenv_eq__solve(s, &eq, force, &r, G, &prob, &res, NULL), 0);
        assert_true(the_proposal.z0_seen == c->prob.z0); /* asked from the warm start */
        if (starts[k].taken) {
            assert_int_equal(res.evals, 1);
            assert_true(r.log[0].z == root);
            assert_int_equal(res.stop, TIRENV_EQ_RESIDUAL);
        } else {
            assert_int_equal(res.evals, plain.evals);
            assert_true(r.log[0].z == c->prob.z0);
            assert_memory_equal(&res.point.z, &plain.point.z, sizeof res.point.z);
        }
    }
    tirenv_eq__solver_free(s);
}

static void test_names(void **state)
{
    (void)state;
    assert_string_equal(tirenv_eq__newton->name, "newton");
    assert_string_equal(tirenv_eq__secant->name, "secant");
    assert_string_equal(tirenv_eq__brent->name, "brent");
    assert_ptr_equal(tirenv_eq__solver_type_of(TIRENV_EQ_NEWTON), tirenv_eq__newton);
    assert_ptr_equal(tirenv_eq__solver_type_of(TIRENV_EQ_SECANT), tirenv_eq__secant);
    assert_ptr_equal(tirenv_eq__solver_type_of(TIRENV_EQ_BRENT), tirenv_eq__brent);
    const tirenv_eq_stop stops[] = {TIRENV_EQ_RUNNING, TIRENV_EQ_RESIDUAL, TIRENV_EQ_BRACKET,
                                    TIRENV_EQ_NO_BRACKET, TIRENV_EQ_MAX_EVALS,
                                    TIRENV_EQ_BREAKDOWN, TIRENV_EQ_FORCE_FAILED};
    for (size_t i = 0; i < sizeof stops / sizeof stops[0]; ++i) {
        assert_string_not_equal(tirenv_eq__stop_name(stops[i]), "unknown");
        for (size_t j = 0; j < i; ++j)
            assert_string_not_equal(tirenv_eq__stop_name(stops[i]),
                                    tirenv_eq__stop_name(stops[j]));
    }
    assert_string_equal(tirenv_eq__stop_name((tirenv_eq_stop)99), "unknown");
    tirenv_eq__solver_free(NULL);
    assert_null(tirenv_eq__solver_alloc(NULL));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table_every_method),
        cmocka_unit_test(test_steps_by_hand),
        cmocka_unit_test(test_reuse_after_failure),
        cmocka_unit_test(test_slope_on_request),
        cmocka_unit_test(test_model_start),
        cmocka_unit_test(test_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
