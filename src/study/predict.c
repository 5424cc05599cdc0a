/* Each model's curve for one case of a data set, at the case's own points, driven the way the
 * paper drives it (docs/models.md section 1): the physical models by the applied load, the network
 * by the measured contact length. SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/study.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tirenv/nn.h"

/* Puts "case NAME: " in front of the message the failing call left in diag, so that a failure
 * inside a 28-case fit or comparison says which case it was. */
static int case_failed(const tirenv_case *c, int status, tirenv_diag *diag)
{
    if (diag) {
        char msg[sizeof diag->message];
        snprintf(msg, sizeof msg, "case %s: %.470s", c->name, diag->message);
        memcpy(diag->message, msg, sizeof msg);
    }
    return status;
}

/* The rig holds the load constant and pushes the cart forward, so the model is set once on
 * the cleat and swept in x order: each equilibrium then starts from its neighbour's (the warm
 * start of tirenv_model_eval), which is what makes a sweep cheap. tirenv_model_set measures h
 * from the model's own flat-ground height at this load, as the rig import measures the data
 * from the rig's flat baseline. The cleat lives only for this call: the model is left set
 * on it, so a caller must tirenv_model_set it again before using it directly. A case with
 * its own profile (another shape) is run over that instead. */
int tirenv_case_predict_model(tirenv_model *m, const tirenv_case *c, double h[],
                              tirenv_diag *diag)
{
    const tirenv_curve *cv = &c->curve;
    if (cv->n == 0 || !cv->x)
        return case_failed(c, tirenv_error(diag, TIRENV_EINVAL, "", 0, "curve",
                                           "no curve points to predict"), diag);
    for (size_t k = 0; k < cv->n; ++k)
        if (!isfinite(cv->x[k]) || (k > 0 && !(cv->x[k] > cv->x[k - 1])))
            return case_failed(c, tirenv_error(diag, TIRENV_EINVAL, "", k + 1, "x_m",
                                               "curve positions must be finite and increase; "
                                               "point %zu is at %g m",
                                               k + 1, cv->x[k]), diag);
    tirenv_profile *cleat = c->profile ? NULL : tirenv_profile_cleat(c->L, c->H);
    if (!c->profile && !cleat)
        return case_failed(c, tirenv_error(diag, TIRENV_EINVAL, "", 0, "obstacle",
                                           "expected a positive, finite obstacle length and "
                                           "height, got %g x %g m", c->L, c->H), diag);
    int status = tirenv_model_set(m, c->profile ? c->profile : cleat, c->load, diag);
    for (size_t k = 0; k < cv->n && status == TIRENV_OK; ++k) {
        tirenv_point pt;
        status = tirenv_model_eval(m, cv->x[k], &pt, diag);
        h[k] = status == TIRENV_OK ? pt.h : NAN;
    }
    tirenv_profile_free(cleat);
    return status ? case_failed(c, status, diag) : TIRENV_OK;
}

/* The network reads x_N from x with the tire's R0 and the case's measured contact length,
 * the same convention the import used to put the curve on its x_N grid. */
int tirenv_case_predict_nn(tirenv_nn *nn, double R0, const tirenv_case *c, double h[],
                           tirenv_diag *diag)
{
    const int status = tirenv_nn_envelope(nn, R0, c->contact_length, c->L, c->H, c->curve.n,
                                          c->curve.x, h, diag);
    return status ? case_failed(c, status, diag) : TIRENV_OK;
}
