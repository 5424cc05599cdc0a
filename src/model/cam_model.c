/* The tandem elliptical cam as a tirenv_model_type: MF-Swift's effective road, a geometric
 * filter with no iteration (docs/models.md section 7). SPDX-License-Identifier: Apache-2.0
 *
 * The cam itself does not deflect: its parameters say how a tire at a given load envelopes,
 * and the load enters through the MF-Tyre contact-patch law alone. So the model reports
 *   h = w, the effective road height of the tandem (0 on flat ground),
 *   z = z_flat + w, with z_flat = R0 - rho0 and rho0 the static deflection of MF-Tyre's
 *       vertical law (G / VERTICAL_STIFFNESS, or with Q_FZ2 or Q_FZ1 its quadratic, times
 *       PFZ1's pressure factor: section 7.3), the
 *       centre height of the vertical spring on the effective road,
 *   fx = -G*tan(beta): the ground force G, normal to the effective road plane of slope
 *       tan(beta), has the longitudinal part -G*tan(beta) when its vertical part is G, so a
 *       road rising in front pushes back, as in the other models,
 *   fz = G, two contacts (the cams) and no iterations.
 *
 * The tandem base. MF-Tyre's contact law gives the half length a of the patch, and
 * l_s = ELLIPS_SHIFT * (a or 2a); public sources do not settle which. tirenv takes
 * l_s = ELLIPS_SHIFT * 2a: the two cams stand for the leading and trailing edges of the
 * contact patch, which are 2a apart, and the bridging they model (the double hump over a
 * cleat shorter than the patch, with its humps where the cleat passes under the patch's ends)
 * needs the humps about one patch length apart. With the public 205/60R15 values at its
 * nominal 4 kN (2a = 0.13 m) this gives l_s = 0.11 m, against 0.055 m for ELLIPS_SHIFT * a,
 * under half the patch. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/cam_impl.h"
#include "model/model_impl.h"

/* MF-Tyre's vertical law at standstill (docs/models.md section 7.3), the load at a static
 * deflection rho and back:
 *   F_z = f*FNOMIN*(Q_FZ1*s + Q_FZ2*s^2),   s = rho/R0,   f = 1 + PFZ1*dp,
 * with the file's Q_FZ1 where it gives one other than 0 and otherwise (MF-Tyre 6.1's rule)
 *   Q_FZ1 = sqrt((VERTICAL_STIFFNESS*R0/FNOMIN)^2 - 4*Q_FZ2),
 * which makes VERTICAL_STIFFNESS the tangent stiffness at FNOMIN (f times it at INFLPRES). */
double tirenv_cam_q_fz1(double c_z, double R0, double fnomin, double q_fz2)
{
    const double k = c_z * R0 / fnomin;
    return sqrt(k * k - 4 * q_fz2);
}

double tirenv_cam_pressure_factor(double pfz1, double p, double p_nom)
{
    if (pfz1 == 0)
        return 1;
    if (!(p_nom > 0))
        return NAN;
    return 1 + pfz1 * (p - p_nom) / p_nom;
}

double tirenv_cam_vertical_q1(const tirenv_cam_vertical *v)
{
    return v->q_fz1 != 0 ? v->q_fz1 : tirenv_cam_q_fz1(v->c_z, v->R0, v->fnomin, v->q_fz2);
}

/* Without Q_FZ1 and Q_FZ2 the law is linear in VERTICAL_STIFFNESS, and FNOMIN may be 0. Each
 * form with f = 1 is bit for bit what the cam computed before f and Q_FZ1 were read:
 * (f*c_z)*rho, (f*FNOMIN)*(...) and load/(f*FNOMIN) with f*x = x. */
static int vertical_linear(const tirenv_cam_vertical *v)
{
    return v->q_fz1 == 0 && v->q_fz2 == 0;
}

double tirenv_cam_vertical_load(const tirenv_cam_vertical *v, double rho)
{
    if (vertical_linear(v))
        return v->factor * v->c_z * rho;
    const double s = rho / v->R0;
    return v->factor * v->fnomin * (tirenv_cam_vertical_q1(v) * s + v->q_fz2 * s * s);
}

double tirenv_cam_vertical_deflection(const tirenv_cam_vertical *v, double load)
{
    if (vertical_linear(v))
        return load / (v->factor * v->c_z);
    return tirenv_cam_vertical_root(v->R0, tirenv_cam_vertical_q1(v), v->q_fz2,
                                    load / (v->factor * v->fnomin));
}

double tirenv_cam_vertical_stiffness(const tirenv_cam_vertical *v, double rho)
{
    if (vertical_linear(v))
        return v->factor * v->c_z;
    return v->factor * v->fnomin / v->R0 *
           (tirenv_cam_vertical_q1(v) + 2 * v->q_fz2 * rho / v->R0);
}

/* Where a law with Q_FZ2 < 0 peaks, s = -Q_FZ1/(2*Q_FZ2) (m); infinite for the others. */
static double vertical_peak(const tirenv_cam_vertical *v)
{
    if (vertical_linear(v) || !(v->q_fz2 < 0))
        return INFINITY;
    return -v->R0 * tirenv_cam_vertical_q1(v) / (2 * v->q_fz2);
}

/* A tire off the ground carries nothing, and one pressed past a Q_FZ2 < 0 law's peak holds
 * the peak: a load falling with the deflection would let it sink without end. */
double tirenv_cam_vertical_contact(const tirenv_cam_vertical *v, double rho)
{
    if (!(rho > 0))
        return 0;
    return tirenv_cam_vertical_load(v, fmin(rho, vertical_peak(v)));
}

/* The law's integral in closed form: f*c_z*rho^2/2, or f*FNOMIN*R0*(Q_FZ1*s^2/2 +
 * Q_FZ2*s^3/3); past a peak, the peak load times the deflection beyond it. */
double tirenv_cam_vertical_work(const tirenv_cam_vertical *v, double rho)
{
    if (!(rho > 0))
        return 0;
    if (vertical_linear(v))
        return 0.5 * v->factor * v->c_z * rho * rho;
    const double rho_p = fmin(rho, vertical_peak(v)), s = rho_p / v->R0;
    const double W = v->factor * v->fnomin * v->R0 *
                     (0.5 * tirenv_cam_vertical_q1(v) * s * s + v->q_fz2 * s * s * s / 3);
    return W + tirenv_cam_vertical_load(v, rho_p) * (rho - rho_p);
}

/* scale*2*g evaluated as (scale*2)*g: the deflection R0*2*g/(...) the cam always computed. */
double tirenv_cam_vertical_root(double scale, double q1, double q2, double g)
{
    if (q2 == 0)
        return scale * g / q1;
    const double disc = q1 * q1 + 4 * q2 * g;
    if (!(disc >= 0))
        return NAN;
    return scale * 2 * g / (q1 + sqrt(disc));
}

/* The least-squares fit of 1 ~ p*u_i + q*v_i over rows (u_i, v_i), by its 2x2 normal
 * equations [A11 A12; A12 A22] (p, q) = (b1, b2): MF-Tyre's vertical and contact-length laws
 * are each linear in their two keys. */
typedef struct {
    double A11, A12, A22, b1, b2;
} normal2;

static void normal2_add(normal2 *e, double u, double v)
{
    e->A11 += u * u;
    e->A12 += u * v;
    e->A22 += v * v;
    e->b1 += u;
    e->b2 += v;
}

/* (p, q) of n rows by Cramer's rule; TIRENV_EINVAL, outputs untouched, where the rows do not
 * separate the two terms: n < 2, the determinant within 1e-12 of A11*A22 of zero, or p, q not
 * finite. */
static int normal2_solve(const normal2 *e, size_t n, double *p, double *q)
{
    const double det = e->A11 * e->A22 - e->A12 * e->A12;
    const double p_ = (e->A22 * e->b1 - e->A12 * e->b2) / det,
                 q_ = (e->A11 * e->b2 - e->A12 * e->b1) / det;
    if (n < 2 || !(fabs(det) > 1e-12 * e->A11 * e->A22) || !isfinite(p_) || !isfinite(q_))
        return TIRENV_EINVAL;
    *p = p_;
    *q = q_;
    return TIRENV_OK;
}

/* The rows (s/g, s^2/g) with g = G_i/FNOMIN make both terms relative to the load. */
int tirenv_cam_fit_vertical_law(double R0, double fnomin, size_t n, const double rho[],
                                const double G[], double *q_fz1, double *q_fz2)
{
    normal2 e = {0};
    for (size_t i = 0; i < n; i++) {
        const double s = rho[i] / R0, g = G[i] / fnomin;
        normal2_add(&e, s / g, s * s / g); /* the rows for Q_FZ1 and Q_FZ2 */
    }
    return normal2_solve(&e, n, q_fz1, q_fz2);
}

/* The rows (w*s^2, w*s) with w = 2*R0/l_i make both terms relative to the contact length. */
int tirenv_cam_fit_contact_law(double R0, size_t n, const double rho[], const double l[],
                               double *q_ra1, double *q_ra2)
{
    normal2 e = {0};
    for (size_t i = 0; i < n; i++) {
        const double s = sqrt(rho[i] / R0), w = 2 * R0 / l[i];
        normal2_add(&e, w * s * s, w * s); /* the rows for Q_RA2 and Q_RA1 */
    }
    return normal2_solve(&e, n, q_ra2, q_ra1);
}

/* The tire's vertical law (tirenv_cam_vertical): its cam keys, R0, and the pressure factor
 * of PFZ1 at the ring's INFLPRES and NOMPRES. */
static tirenv_cam_vertical cam_vertical(const tirenv_tire *t)
{
    return (tirenv_cam_vertical){
        .R0 = t->springs.R0, .fnomin = t->cam.fnomin, .c_z = t->cam.c_z,
        .q_fz1 = t->cam.q_fz1, .q_fz2 = t->cam.q_fz2,
        .factor = tirenv_cam_pressure_factor(t->cam.pfz1, t->ring.p, t->ring.p_nom)};
}

static double cam_q_fz1(const tirenv_tire *t)
{
    const tirenv_cam_vertical v = cam_vertical(t);
    return tirenv_cam_vertical_q1(&v);
}

/* The law's keys, for messages: "VERTICAL_STIFFNESS 371000 N/m and Q_FZ2". */
static const char *cam_law_keys(const tirenv_tire *t, int with_q2, char *buf, size_t n)
{
    const double f = tirenv_cam_pressure_factor(t->cam.pfz1, t->ring.p, t->ring.p_nom);
    int k = t->cam.q_fz1 != 0 ? snprintf(buf, n, "Q_FZ1 %g", t->cam.q_fz1)
                              : snprintf(buf, n, "VERTICAL_STIFFNESS %g N/m", t->cam.c_z);
    if (k >= 0 && (size_t)k < n && with_q2 && t->cam.q_fz2 != 0)
        k += snprintf(buf + k, n - (size_t)k, " and Q_FZ2");
    if (k >= 0 && (size_t)k < n && f != 1)
        snprintf(buf + k, n - (size_t)k, " at PFZ1's pressure factor %g", f);
    return buf;
}

/* Whether the law has a Q_FZ1 (the file's, or Q_FZ2 < (VERTICAL_STIFFNESS*R0/FNOMIN)^2/4) and a
 * positive pressure factor: a property of the cam with its tire's R0 and pressures, checked
 * where the cam meets a load (the tire check sees the cam keys alone, and other models combine
 * them with another tire's R0). */
static int cam_law_check(const tirenv_tire *t, tirenv_diag *diag)
{
    const double f = tirenv_cam_pressure_factor(t->cam.pfz1, t->ring.p, t->ring.p_nom);
    if (!(f > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "PFZ1",
                            "%g at INFLPRES %g Pa, NOMPRES %g Pa gives the vertical law a "
                            "factor 1 + PFZ1*(INFLPRES - NOMPRES)/NOMPRES = %g: positive "
                            "expected", t->cam.pfz1, t->ring.p, t->ring.p_nom, f);
    if (t->cam.q_fz2 == 0 || t->cam.q_fz1 != 0)
        return TIRENV_OK;
    const double k = t->cam.c_z * t->springs.R0 / t->cam.fnomin;
    if (k * k - 4 * t->cam.q_fz2 > 0)
        return TIRENV_OK;
    return tirenv_error(diag, TIRENV_EINVAL, "", 0, "Q_FZ2",
                        "%g leaves no Q_FZ1 = sqrt((VERTICAL_STIFFNESS*R0/FNOMIN)^2 - 4*Q_FZ2) "
                        "(docs/models.md section 7.3): below (%g)^2/4 = %g expected",
                        t->cam.q_fz2, k, k * k / 4);
}

/* The load (N) at deflection rho (m). */
static double cam_load_at(const tirenv_tire *t, double rho)
{
    const tirenv_cam_vertical v = cam_vertical(t);
    return tirenv_cam_vertical_load(&v, rho);
}

/* The deflection (m) at a load (N): the rising root, in the form without cancellation; NAN
 * beyond the largest load a law with Q_FZ2 < 0 carries. */
static double cam_deflection_at(const tirenv_tire *t, double load)
{
    const tirenv_cam_vertical v = cam_vertical(t);
    return tirenv_cam_vertical_deflection(&v, load);
}

/* The tangent stiffness dF_z/drho (N/m) at deflection rho (m). */
static double cam_stiffness_at(const tirenv_tire *t, double rho)
{
    const tirenv_cam_vertical v = cam_vertical(t);
    return tirenv_cam_vertical_stiffness(&v, rho);
}

tirenv_cam_vertical tirenv_tire_vertical_law(const tirenv_tire *t)
{
    return cam_vertical(t);
}

/* The law's own stiffness at its own deflection under the load: one law for the cam's static
 * deflection and the ride's linear checks, so that one tire file is one tire for both. A load
 * the law would carry only with the centre at or below the ground (a deflection of R0 or
 * more) is beyond the tire, as the cam refuses it (cam_patch): no stiffness there, and the
 * ride refuses the vehicle (the stiffening law has a tangent at any load). */
double tirenv_tire_vertical_stiffness(const tirenv_tire *t, double load)
{
    const double rho = cam_deflection_at(t, load);
    return rho < t->springs.R0 ? cam_stiffness_at(t, rho) : NAN;
}

/* The cam's valid range (docs/models.md section 7.3), as the largest relative deflection
 * y_max = rho/R0 and what ends it there, the first of:
 *   - the patch reaching the chord of the free circle at that deflection: a patch longer than
 *     the chord, 2*sqrt(rho*(2*R0 - rho)), would press the ground on tread the undeformed
 *     tire does not reach there, however much it bulged (real patches are shorter; the public
 *     205/60R15's law reaches its chord at 54 % deflection). With y = s^2 the law meets the
 *     chord where Q_RA2*s + Q_RA1 = sqrt(2 - s^2), the positive root of
 *     (1 + Q_RA2^2) s^2 + 2 Q_RA1 Q_RA2 s + Q_RA1^2 - 2 = 0; Q_RA1 >= sqrt(2) puts every
 *     patch past its chord;
 *   - with Q_RA2 < 0, the law's peak at s = Q_RA1/(2|Q_RA2|): past it the patch would shrink
 *     under more load;
 *   - the centre at the ground, rho = R0. */
typedef struct {
    double y_max;       /* rho/R0 at the end of the range */
    char why[160];
} cam_range;

static cam_range cam_valid_range(const tirenv_tire *t)
{
    const double q1 = t->cam.q_ra1, q2 = t->cam.q_ra2;
    cam_range r = {1, "with the centre at the ground"};
    const double disc = 2 * (1 + q2 * q2) - q1 * q1;
    if (q1 >= M_SQRT2) {
        r.y_max = 0;
        snprintf(r.why, sizeof r.why, "none: with Q_RA1 %g >= sqrt(2) every patch is longer "
                 "than the chord of the free circle", q1);
        return r;
    }
    const double s_chord = (-q1 * q2 + sqrt(disc)) / (1 + q2 * q2);
    if (s_chord > 0 && s_chord * s_chord < r.y_max && q2 * s_chord + q1 >= 0) {
        r.y_max = s_chord * s_chord;
        snprintf(r.why, sizeof r.why, "where the patch of Q_RA1 %g, Q_RA2 %g reaches the chord "
                 "of the free circle: a longer patch would press tread the tire does not "
                 "reach there", q1, q2);
    }
    if (q2 < 0) {
        const double s_peak = q1 / (-2 * q2);
        if (s_peak * s_peak < r.y_max) {
            r.y_max = s_peak * s_peak;
            snprintf(r.why, sizeof r.why, "where the contact length of Q_RA1 %g, Q_RA2 %g "
                     "peaks: under more load the patch would shrink", q1, q2);
        }
    }
    if (t->cam.q_fz2 < 0) {
        const double y_peak = cam_q_fz1(t) / (-2 * t->cam.q_fz2);
        if (y_peak < r.y_max) {
            r.y_max = y_peak;
            snprintf(r.why, sizeof r.why, "where the vertical law of Q_FZ2 %g peaks: it "
                     "carries no more load", t->cam.q_fz2);
        }
    }
    return r;
}

typedef struct {
    tirenv_tire tire;
    cam_range range;            /* of the tire, found once: a load change only compares */
    tirenv_cam__geom cam;       /* a_e = ELLIPS_LENGTH*R0, b_e = ELLIPS_HEIGHT*R0, c_e */
    const tirenv_profile *prof;
    double G;                   /* load, N */
    double z_flat;              /* R0 - rho0, m */
    double l_s;                 /* tandem base ELLIPS_SHIFT*2a, m */
    double z_cap;               /* the profile's highest vertex, m: bounds the scan */
    tirenv_cam__sweep sweep;    /* drop floor and tangency memo, shared by the two cams */
    tirenv_cam__track front, rear; /* where each cam was */
    /* tirenv_model_warnings': the first position since the set where a cam touched the
     * ground more than the tire's ELLIPS_MAX_STEP above its lowest point, "" if none. */
    char said[320];
} cam_state;

static void *cam_alloc(const tirenv_model_type *type, const tirenv_tire *tire)
{
    (void)type;
    const double R0 = tire->springs.R0;
    const tirenv_cam_shape shape = {.a_e = tire->cam.length * R0,
                                    .b_e = tire->cam.height * R0,
                                    .c_e = tire->cam.order};
    cam_state *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    st->tire = *tire;
    st->range = cam_valid_range(tire);
    if (tirenv_cam__geom_set(&st->cam, &shape) != TIRENV_OK) {
        free(st);
        return NULL;
    }
    tirenv_cam__sweep_init(&st->sweep, &st->cam);
    return st;
}

static void cam_free(void *state)
{
    free(state);
}

static int out_of_range(const tirenv_tire *t, const cam_range *r, double load, double l_c,
                        tirenv_diag *diag)
{
    const double R0 = t->springs.R0, rho = r->y_max * R0;
    const double a = R0 * (t->cam.q_ra2 * r->y_max + t->cam.q_ra1 * sqrt(r->y_max));
    if (l_c > 0)
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "contact length",
                            "%g m is beyond the cam model's valid range, up to %.4g m (load "
                            "%.6g N, deflection %.4g m), %s", l_c, 2 * a, cam_load_at(t, rho),
                            rho, r->why);
    char keys[128];
    return tirenv_error(diag, TIRENV_ERANGE, "", 0, "load",
                        "%g N (deflection %g m by %s) is beyond the cam model's valid range, "
                        "up to %.6g N (deflection %.4g m, contact length %.4g m), %s", load,
                        cam_deflection_at(t, load), cam_law_keys(t, 1, keys, sizeof keys),
                        cam_load_at(t, rho), rho, 2 * a, r->why);
}

/* The static deflection rho of the vertical law (section 7.3; G / VERTICAL_STIFFNESS without
 * Q_FZ1, Q_FZ2 and PFZ1) and MF-Tyre's contact half length
 * a = R0*(Q_RA2*rho/R0 + Q_RA1*sqrt(rho/R0)), within the valid range. */
static int cam_patch(const tirenv_tire *t, const cam_range *range, double load, double *rho,
                     double *a, tirenv_diag *diag)
{
    const double R0 = t->springs.R0, q_ra1 = t->cam.q_ra1, q_ra2 = t->cam.q_ra2;
    const int status = cam_law_check(t, diag);
    if (status)
        return status;
    *rho = cam_deflection_at(t, load);
    char keys[128];
    if (isnan(*rho)) {
        const double q1 = cam_q_fz1(t);
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "load",
                            "%g N is more than the vertical law of %s, Q_FZ2 %g carries, at "
                            "most %.6g N", load, cam_law_keys(t, 0, keys, sizeof keys),
                            t->cam.q_fz2,
                            tirenv_cam_pressure_factor(t->cam.pfz1, t->ring.p, t->ring.p_nom) *
                                t->cam.fnomin * q1 * q1 / (-4 * t->cam.q_fz2));
    }
    if (!(*rho < R0))
        return tirenv_error(diag, TIRENV_ENOBRACKET, "", 0, "load",
                            "%g N deflects the tire by %g m (%s), beyond its free radius %g m",
                            load, *rho, cam_law_keys(t, 1, keys, sizeof keys), R0);
    if (!(*rho <= range->y_max * R0))
        return out_of_range(t, range, load, 0, diag);
    const double r = *rho / R0, y = sqrt(r);
    *a = R0 * (q_ra2 * r + q_ra1 * y);
    return TIRENV_OK;
}

static int cam_flat(void *state, double load, tirenv_flat *out, tirenv_diag *diag)
{
    const cam_state *st = state;
    double rho = 0, a = 0;
    const int status = cam_patch(&st->tire, &st->range, load, &rho, &a, diag);
    if (status)
        return status;
    *out = (tirenv_flat){.load = load, .z_flat = st->tire.springs.R0 - rho, .deflection = rho,
                         .contact_length = 2 * a,
                         .stiffness = cam_stiffness_at(&st->tire, rho)};
    return TIRENV_OK;
}

/* The contact law inverted in closed form: with y = sqrt(rho/R0) and A = l_c/(2 R0) = a/R0,
 * Q_RA2 y^2 + Q_RA1 y = A, whose root on the rising branch is y = 2A/(Q_RA1 + sqrt(Q_RA1^2 +
 * 4 Q_RA2 A)) (the form without cancellation; it holds for Q_RA2 = 0 and Q_RA2 < 0 too). The
 * load follows by the vertical law at rho = R0*y^2. */
static int cam_load_for_contact_length(void *state, double l_c, double *load,
                                       tirenv_diag *diag)
{
    const cam_state *st = state;
    const double R0 = st->tire.springs.R0, q_ra1 = st->tire.cam.q_ra1;
    const double q_ra2 = st->tire.cam.q_ra2;
    if (!(l_c > 0 && l_c < 2 * R0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "contact length",
                            "must be in (0, 2*R0) = (0, %g) m, got %g", 2 * R0, l_c);
    const int status = cam_law_check(&st->tire, diag);
    if (status)
        return status;
    const double A = l_c / (2 * R0), disc = q_ra1 * q_ra1 + 4 * q_ra2 * A;
    if (disc < 0)
        return tirenv_error(diag, TIRENV_ERANGE, "", 0, "contact length",
                            "%g m is longer than the longest the contact law of Q_RA1 %g, "
                            "Q_RA2 %g gives, %g m", l_c, q_ra1, q_ra2,
                            -R0 * q_ra1 * q_ra1 / (2 * q_ra2));
    const double y = 2 * A / (q_ra1 + sqrt(disc)), rho = R0 * y * y;
    if (!(rho < R0))
        return tirenv_error(diag, TIRENV_ENOBRACKET, "", 0, "contact length",
                            "%g m needs a deflection of %g m, beyond the free radius %g m",
                            l_c, rho, R0);
    if (!(rho <= st->range.y_max * R0))
        return out_of_range(&st->tire, &st->range, 0, l_c, diag);
    *load = cam_load_at(&st->tire, rho);
    return TIRENV_OK;
}

/* What depends on the load: the tandem base through the contact law, and the static
 * deflection. The shape, the drop floor, the memo of tangencies and the scan's bound z_cap
 * depend on the profile alone. */
static int cam_load(cam_state *st, double load, double *z_flat, tirenv_diag *diag)
{
    double rho = 0, a = 0;
    const int status = cam_patch(&st->tire, &st->range, load, &rho, &a, diag);
    if (status)
        return status;
    st->G = load;
    st->z_flat = *z_flat = st->tire.springs.R0 - rho;  /* cam_flat's, bit for bit */
    st->l_s = st->tire.cam.shift * 2 * a;
    return TIRENV_OK;
}

static int cam_set(void *state, const tirenv_profile *p, double load, double z_flat,
                   tirenv_diag *diag)
{
    cam_state *st = state;
    double z_load;
    const int status = cam_load(st, load, &z_load, diag);
    if (status)
        return status;
    st->z_flat = z_flat;  /* the driver's, which is z_load */
    st->prof = p;
    st->z_cap = tirenv_model__profile_top(p);  /* from the block maxima, O(n/16) */
    /* The memo is indexed by segment: a new profile starts it afresh. The tracks may stay
     * as they are (any content gives the same results), but a fresh start is tidier. */
    tirenv_cam__sweep_forget(&st->sweep);
    st->front = st->rear = (tirenv_cam__track){0};
    st->said[0] = '\0';
    return TIRENV_OK;
}

/* Another window of the same road (streaming): its warning, if any, stays. */
static int cam_set_profile(void *state, const tirenv_profile *p, double load, double z_flat,
                           tirenv_diag *diag)
{
    cam_state *st = state;
    char said[sizeof st->said];
    memcpy(said, st->said, sizeof said);
    const int status = cam_set(state, p, load, z_flat, diag);
    memcpy(st->said, said, sizeof said);
    return status;
}

/* MF-Swift's ELLIPS_MAX_STEP is the highest road step a cam shape is meant for: a cam
 * touching the ground higher above its lowest point (pz - Z) rests on a part of its flank
 * that steps of that height never reached. The first such position is kept for the warning;
 * nothing is asked of the lift where the tire declares no limit. */
static void step_check(cam_state *st, double x, double Z_f, double pz_f, double Z_r,
                       double pz_r)
{
    const double dz = fmax(pz_f - Z_f, pz_r - Z_r);
    if (!(dz > st->tire.cam.max_step) || st->said[0])
        return;
    snprintf(st->said, sizeof st->said,
             "at x = %.6g m a cam touches the ground %.4g mm above its lowest point, higher "
             "than the tire's ELLIPS_MAX_STEP (%.4g mm), the highest road step its shape is "
             "meant for: from there on its curve may extrapolate that shape",
             x, 1e3 * dz, 1e3 * st->tire.cam.max_step);
}

/* Positions usually come in order, so each cam keeps a track, and the two share the sweep's
 * memo: the rear cam meets the front one's tangencies l_s later. Results do not depend on
 * either, whatever the order of positions. */
static int cam_eval(void *state, double x, tirenv_point *out, tirenv_diag *diag)
{
    cam_state *st = state;
    if (!isfinite(x))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "x", "must be finite, got %g", x);
    const int check = st->tire.cam.max_step > 0;
    double px, pz_f = 0, pz_r = 0;
    const double Z_f = tirenv_cam__lift(&st->cam, st->prof, x + 0.5 * st->l_s, st->z_cap,
                                        &st->sweep, &st->front, check ? &px : NULL,
                                        check ? &pz_f : NULL);
    const double Z_r = tirenv_cam__lift(&st->cam, st->prof, x - 0.5 * st->l_s, st->z_cap,
                                        &st->sweep, &st->rear, check ? &px : NULL,
                                        check ? &pz_r : NULL);
    if (check)
        step_check(st, x, Z_f, pz_f, Z_r, pz_r);
    const double w = 0.5 * (Z_f + Z_r), tan_beta = (Z_f - Z_r) / st->l_s;
    *out = (tirenv_point){.x = x, .z = st->z_flat + w, .h = w, .fx = -st->G * tan_beta,
                          .fz = st->G, .contacts = 2, .iterations = 0};
    out->slope = tirenv_model__slope(out);
    return TIRENV_OK;
}

/* The two cams sit l_s/2 either side of x and each reads a_e either side of its own centre.
 * Before a load is set, l_s = ELLIPS_SHIFT*2a is bounded with a <= R0. */
static double cam_reach(const void *state, const tirenv_tire *tire)
{
    const cam_state *st = state;
    (void)tire;  /* the state's own copy */
    const double R0 = st->tire.springs.R0;
    const double half_base = st->l_s > 0 ? 0.5 * st->l_s : st->tire.cam.shift * R0;
    return st->tire.cam.length * R0 + half_base;
}

/* O(1): the lifts do not depend on the load, only where the two cams stand. */
static int cam_set_load(void *state, double load, double *z_flat, tirenv_diag *diag)
{
    return cam_load(state, load, z_flat, diag);
}

static const char *cam_warnings(const void *state)
{
    return ((const cam_state *)state)->said;
}

/* The load and what follows from it; the tracks and the memo change no bit of a lift, and
 * the warning is of the evaluations since the set, whatever was restored between. */
static size_t cam_state_size(const void *state)
{
    (void)state;
    return 3 * sizeof(double);
}

static void cam_state_save(const void *state, unsigned char *buf)
{
    const cam_state *st = state;
    buf = tirenv_model__put(buf, &st->G, sizeof st->G);
    buf = tirenv_model__put(buf, &st->z_flat, sizeof st->z_flat);
    tirenv_model__put(buf, &st->l_s, sizeof st->l_s);
}

/* The flat-ground height and the tandem base follow from the load (cam_load, the same bits
 * as every set and load change give them), and the load and height are the head's too: a
 * state where one of them is not what the load gives is refused, naming it. */
static int cam_state_restore(void *state, const unsigned char *buf, double load, double z_flat,
                             tirenv_diag *diag)
{
    cam_state *st = state;
    double G, z_own, l_s;
    buf = tirenv_model__get(buf, &G, sizeof G);
    buf = tirenv_model__get(buf, &z_own, sizeof z_own);
    tirenv_model__get(buf, &l_s, sizeof l_s);
    if (!(l_s > 0 && isfinite(l_s)) || !(G > 0 && isfinite(G)) ||
        !(z_own > 0 && isfinite(z_own)))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a cam state (its load %g N, flat-ground height %g m, tandem "
                            "base %g m)", G, z_own, l_s);
    double rho = 0, a = 0;
    const int status = cam_patch(&st->tire, &st->range, G, &rho, &a, diag);
    if (status)
        return status;
    const double z_G = st->tire.springs.R0 - rho, l_G = st->tire.cam.shift * 2 * a;
    const char *field = G != load       ? "its load is not the head's"
                        : z_own != z_G  ? "its flat-ground height is not its load's"
                        : z_flat != z_G ? "the head's flat-ground height is not its load's"
                        : l_s != l_G    ? "its tandem base is not its load's"
                                        : NULL;
    if (field)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "state",
                            "not a cam state: %s (load %.17g N, head's %.17g N; flat-ground "
                            "height %.17g m, head's %.17g m, the load's %.17g m; tandem base "
                            "%.17g m, the load's %.17g m)",
                            field, G, load, z_own, z_flat, z_G, l_s, l_G);
    st->G = G;
    st->z_flat = z_own;
    st->l_s = l_s;
    return TIRENV_OK;
}

/* The cam's shape and base, which a fit identifies (docs/models.md section 8). Its
 * contact-length keys (Q_RA1, Q_RA2, VERTICAL_STIFFNESS) set where its two cams stand at a load
 * and trade off against ELLIPS_SHIFT, so they are left as the tire file gives them. */
static const tirenv_model_param cam_params[] = {
    {"ELLIPS_SHIFT", offsetof(tirenv_tire, cam.shift), 0},
    {"ELLIPS_LENGTH", offsetof(tirenv_tire, cam.length), 0},
    {"ELLIPS_HEIGHT", offsetof(tirenv_tire, cam.height), 0},
    {"ELLIPS_ORDER", offsetof(tirenv_tire, cam.order), 1},
};

static const tirenv_model_ops cam_ops = {
    .alloc = cam_alloc,
    .free = cam_free,
    .flat = cam_flat,
    .load_for_contact_length = cam_load_for_contact_length,
    .set = cam_set,
    .set_profile = cam_set_profile,
    .set_load = cam_set_load,
    .eval = cam_eval,
    .reach = cam_reach,
    .state_size = cam_state_size,
    .state_save = cam_state_save,
    .state_restore = cam_state_restore,
    .warnings = cam_warnings,
};

enum { CAM_PARAMS = sizeof cam_params / sizeof cam_params[0] };
static const tirenv_model_fit cam_fit = {cam_params, CAM_PARAMS, CAM_PARAMS};

static const tirenv_model_type cam_type = {
    .name = "cam",
    .summary = "MF-Swift's tandem elliptical cam",
    .flags = TIRENV_MODEL_CONTACT_LENGTH | TIRENV_MODEL_STREAMS,
    .tracks = TIRENV_TRACKS_MEAN,
    .ops = &cam_ops,
    .fit = &cam_fit,
};
const tirenv_model_type *tirenv_model_cam = &cam_type;
