/* SPDX-License-Identifier: Apache-2.0 */
/* The ride's integrators (docs/models.md section 9.4; the step RK4 may take, 9.6).
 *
 * RK4: the classical fourth-order Runge-Kutta step, summed in the order of its formula
 * (k1 + 2 k2 + 2 k3 + k4) h/6 added term by term as each stage is known.
 *
 * RK8PD: Prince and Dormand's embedded pair RK8(7)13M ("High order embedded Runge-Kutta
 * formulae", J. Comput. Appl. Math. 7, 1981, 67-75; the tableau as printed in Hairer,
 * Norsett and Wanner, Solving Ordinary Differential Equations I, 2nd ed., table II.6.4): 13
 * stages, the eighth-order solution propagated, the seventh-order one for the error estimate
 * (local extrapolation). The published coefficients are rational approximations; the test
 * checks that they meet the order conditions to 1e-15. The step control is the standard one
 * (Hairer et al., section II.4): the error of component i, e_i = |y8_i - y7_i|, against
 * D_i = tol (1 + |y_i|); with r = max e_i/D_i a step is rejected when r > 1.1 and retried with
 * h times max(0.2, 0.9 r^(-1/8)); an accepted step with r < 0.5 lets the next grow by
 * min(5, 0.9 r^(-1/9)) (GSL's gsl_odeiv2_control_standard, which the ride used until version
 * 0.1, takes the same factors). Outputs fall on the integrator's own steps: the last step
 * before an output is shortened to end on it. */
#include "ride/ode.h"

#include <float.h>
#include <math.h>
#include <string.h>

enum { DIM = TIRENV_RIDE__ODE_DIM };

int tirenv_ride__rk4_step(const tirenv_ride__ode *ode, const double t, const double h,
                          double y[])
{
    const size_t n = ode->dim;
    double y0[DIM], k[DIM], y_s[DIM];
    memcpy(y0, y, n * sizeof *y);
    int rc = ode->f(t, y0, k, ode->params);
    if (rc)
        return rc;
    for (size_t i = 0; i < n; ++i) {
        y[i] += h / 6.0 * k[i];
        y_s[i] = y0[i] + 0.5 * h * k[i];
    }
    if ((rc = ode->f(t + 0.5 * h, y_s, k, ode->params)))
        return rc;
    for (size_t i = 0; i < n; ++i) {
        y[i] += h / 3.0 * k[i];
        y_s[i] = y0[i] + 0.5 * h * k[i];
    }
    if ((rc = ode->f(t + 0.5 * h, y_s, k, ode->params)))
        return rc;
    for (size_t i = 0; i < n; ++i) {
        y[i] += h / 3.0 * k[i];
        y_s[i] = y0[i] + h * k[i];
    }
    if ((rc = ode->f(t + h, y_s, k, ode->params)))
        return rc;
    for (size_t i = 0; i < n; ++i)
        y[i] += h / 6.0 * k[i];
    return 0;
}

enum { S = 13 };  /* stages */

/* The nodes c_i and the rows of A (only a_i1 and a_ij for j >= 4 are nonzero past row 4). */
static const double c[S] = {0.0, 1.0 / 18, 1.0 / 12, 1.0 / 8, 5.0 / 16, 3.0 / 8, 59.0 / 400,
                            93.0 / 200, 5490023248.0 / 9719169821.0, 13.0 / 20,
                            1201146811.0 / 1299019798.0, 1.0, 1.0};
static const double a[S][S] = {
    {0},
    {1.0 / 18},
    {1.0 / 48, 1.0 / 16},
    {1.0 / 32, 0, 3.0 / 32},
    {5.0 / 16, 0, -75.0 / 64, 75.0 / 64},
    {3.0 / 80, 0, 0, 3.0 / 16, 3.0 / 20},
    {29443841.0 / 614563906, 0, 0, 77736538.0 / 692538347, -28693883.0 / 1125000000,
     23124283.0 / 1800000000},
    {16016141.0 / 946692911, 0, 0, 61564180.0 / 158732637, 22789713.0 / 633445777,
     545815736.0 / 2771057229, -180193667.0 / 1043307555},
    {39632708.0 / 573591083, 0, 0, -433636366.0 / 683701615, -421739975.0 / 2616292301,
     100302831.0 / 723423059, 790204164.0 / 839813087, 800635310.0 / 3783071287},
    {246121993.0 / 1340847787, 0, 0, -37695042795.0 / 15268766246, -309121744.0 / 1061227803,
     -12992083.0 / 490766935, 6005943493.0 / 2108947869, 393006217.0 / 1396673457,
     123872331.0 / 1001029789},
    {-1028468189.0 / 846180014, 0, 0, 8478235783.0 / 508512852, 1311729495.0 / 1432422823,
     -10304129995.0 / 1701304382, -48777925059.0 / 3047939560, 15336726248.0 / 1032824649,
     -45442868181.0 / 3398467696, 3065993473.0 / 597172653},
    {185892177.0 / 718116043, 0, 0, -3185094517.0 / 667107341, -477755414.0 / 1098053517,
     -703635378.0 / 230739211, 5731566787.0 / 1027545527, 5232866602.0 / 850066563,
     -4093664535.0 / 808688257, 3962137247.0 / 1805957418, 65686358.0 / 487910083},
    {403863854.0 / 491063109, 0, 0, -5068492393.0 / 434740067, -411421997.0 / 543043805,
     652783627.0 / 914296604, 11173962825.0 / 925320556, -13158990841.0 / 6184727034,
     3936647629.0 / 1978049680, -160528059.0 / 685178525, 248638103.0 / 1413531060},
};
/* The eighth-order weights b and the seventh-order ones b_hat. */
static const double b[S] = {14005451.0 / 335480064, 0, 0, 0, 0, -59238493.0 / 1068277825,
                            181606767.0 / 758867731, 561292985.0 / 797845732,
                            -1041891430.0 / 1371343529, 760417239.0 / 1151165299,
                            118820643.0 / 751138087, -528747749.0 / 2220607170, 1.0 / 4};
static const double b_hat[S] = {13451932.0 / 455176623, 0, 0, 0, 0, -808719846.0 / 976000145,
                                1757004468.0 / 5645159321, 656045339.0 / 265891186,
                                -3867574721.0 / 1518517206, 465885868.0 / 322736535,
                                53011238.0 / 667516719, 2.0 / 45, 0};

const double *tirenv_ride__rk8_tableau(const double **c_out, const double **b_out,
                                       const double **b_hat_out)
{
    *c_out = c;
    *b_out = b;
    *b_hat_out = b_hat;
    return &a[0][0];
}

void tirenv_ride__rk8_init(tirenv_ride__rk8 *s, const double h0, const double tol)
{
    *s = (tirenv_ride__rk8){.h = h0, .tol = tol};
}

/* One trial step of h: the eighth-order y_new and the error ratio r. */
static int rk8_try(const tirenv_ride__ode *ode, const double t, const double h,
                   const double y[], const double tol, double y_new[], double *r)
{
    const size_t n = ode->dim;
    double k[S][DIM], y_s[DIM];
    int rc = ode->f(t, y, k[0], ode->params);
    if (rc)
        return rc;
    for (size_t i = 1; i < S; ++i) {
        for (size_t m = 0; m < n; ++m) {
            double sum = 0;
            for (size_t j = 0; j < i; ++j)
                sum += a[i][j] * k[j][m];
            y_s[m] = y[m] + h * sum;
        }
        if ((rc = ode->f(t + c[i] * h, y_s, k[i], ode->params)))
            return rc;
    }
    *r = 0;
    for (size_t m = 0; m < n; ++m) {
        double s8 = 0, s7 = 0;
        for (size_t i = 0; i < S; ++i) {
            s8 += b[i] * k[i][m];
            s7 += b_hat[i] * k[i][m];
        }
        y_new[m] = y[m] + h * s8;
        const double e = fabs(h * (s8 - s7)), D = tol * (1.0 + fabs(y[m]));
        *r = fmax(*r, e / D);
    }
    if (!isfinite(*r))
        *r = HUGE_VAL;
    return 0;
}

int tirenv_ride__rk8_advance(tirenv_ride__rk8 *s, const tirenv_ride__ode *ode, double *t,
                             const double t1, double y[])
{
    double y_new[DIM];
    while (*t < t1) {
        /* The step that ends on t1, also when t1 - t exceeds h by round-off only (outputs
         * k dt apart leave remainders like 1e-17 s otherwise). */
        const int last = t1 - *t <= s->h * (1 + 1e-9);
        const double h = last ? t1 - *t : s->h;
        if (!(h > 8 * DBL_EPSILON * fmax(fabs(*t), fabs(t1))))
            return TIRENV_RIDE__ODE_STEP_UNDERFLOW;
        double r;
        const int rc = rk8_try(ode, *t, h, y, s->tol, y_new, &r);
        if (rc)
            return rc;
        if (r > 1.1) {  /* reject: retry shorter */
            ++s->rejected;
            s->h = h * fmax(0.2, 0.9 * pow(r, -1.0 / 8));
            continue;
        }
        ++s->steps;
        memcpy(y, y_new, ode->dim * sizeof *y);
        *t = last ? t1 : *t + h;
        if (!last)  /* a step shortened to end on t1 says nothing of the next */
            s->h = r < 0.5 ? h * fmin(5.0, 0.9 * pow(fmax(r, 1e-300), -1.0 / 9)) : h;
    }
    return 0;
}
