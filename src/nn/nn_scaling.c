/* SPDX-License-Identifier: Apache-2.0 */
/* The network's forms (its input x_N or the even distance, its target h or h/H), the scaling
 * of its inputs and output, and the input ranges it was trained on (docs/models.md section 6). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "nn/nn_impl.h"
#include "tirenv/nn.h"

int tirenv_nn_set_form(tirenv_nn *nn, tirenv_nn_input_form input, tirenv_nn_target_form target,
                       tirenv_diag *diag)
{
    if (!tirenv_nn_input_form_name(input) || !tirenv_nn_target_form_name(target))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "form",
                            "input form %d, target form %d; expected paper or even, h or h/H",
                            (int)input, (int)target);
    if ((input != TIRENV_NN_INPUT_PAPER || target != TIRENV_NN_TARGET_H) &&
        nn->n_in != TIRENV_NN_INPUTS)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "form",
                            "the %s input and the %s target need the enveloping model's %d "
                            "inputs (x_N, l_c, H, L); this network has %zu",
                            tirenv_nn_input_form_name(input), tirenv_nn_target_form_name(target),
                            TIRENV_NN_INPUTS, nn->n_in);
    nn->input_form = input;
    nn->target_form = target;
    return TIRENV_OK;
}

void tirenv_nn_form(const tirenv_nn *nn, tirenv_nn_input_form *input,
                    tirenv_nn_target_form *target)
{
    if (input)
        *input = nn->input_form;
    if (target)
        *target = nn->target_form;
}

int tirenv_nn_set_even_width(tirenv_nn *nn, double a, tirenv_diag *diag)
{
    if (!(a > 0) || !isfinite(a))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "even_width",
                            "%g; expected a finite width > 0 (in x_N)", a);
    nn->even_width = a;
    return TIRENV_OK;
}

double tirenv_nn_even_width(const tirenv_nn *nn) { return nn->even_width; }

int tirenv_nn_set_scaling(tirenv_nn *nn, const double in_mean[], const double in_std[],
                          double out_mean, double out_std, tirenv_diag *diag)
{
    for (size_t i = 0; i < nn->n_in; ++i)
        if (!isfinite(in_mean[i]) || !isfinite(in_std[i]) || !(in_std[i] > 0))
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "scaling",
                                "input %zu: mean %g, std %g; expected finite, std > 0", i,
                                in_mean[i], in_std[i]);
    if (!isfinite(out_mean) || !isfinite(out_std) || !(out_std > 0))
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "scaling",
                            "output: mean %g, std %g; expected finite, std > 0", out_mean,
                            out_std);
    for (size_t i = 0; i < nn->n_in; ++i) {
        nn->in_mean[i] = in_mean[i];
        nn->in_std[i] = in_std[i];
        nn->in_inv_std[i] = 1.0 / in_std[i];
    }
    nn->out_mean = out_mean;
    nn->out_std = out_std;
    return TIRENV_OK;
}

void tirenv_nn_scaling(const tirenv_nn *nn, double in_mean[], double in_std[],
                       double *out_mean, double *out_std)
{
    for (size_t i = 0; i < nn->n_in; ++i) {
        if (in_mean)
            in_mean[i] = nn->in_mean[i];
        if (in_std)
            in_std[i] = nn->in_std[i];
    }
    if (out_mean)
        *out_mean = nn->out_mean;
    if (out_std)
        *out_std = nn->out_std;
}

int tirenv_nn_set_input_range(tirenv_nn *nn, const double lo[], const double hi[],
                              tirenv_diag *diag)
{
    for (size_t i = 0; i < nn->n_in; ++i)
        if (isnan(lo[i]) || isnan(hi[i]) || !(lo[i] <= hi[i]) || lo[i] == INFINITY ||
            hi[i] == -INFINITY)
            return tirenv_error(diag, TIRENV_EINVAL, "", 0, "input_range",
                                "input %zu: [%g, %g]; expected lo <= hi", i, lo[i], hi[i]);
    memcpy(nn->in_lo, lo, nn->n_in * sizeof(double));
    memcpy(nn->in_hi, hi, nn->n_in * sizeof(double));
    return TIRENV_OK;
}

void tirenv_nn_input_range(const tirenv_nn *nn, double lo[], double hi[])
{
    memcpy(lo, nn->in_lo, nn->n_in * sizeof(double));
    memcpy(hi, nn->in_hi, nn->n_in * sizeof(double));
}

/* Two passes (mean, then squared deviations) rather than one running sum of squares, which
 * cancels catastrophically when the spread is small against the mean (l_c ~ 0.33 +- 0.04). */
int tirenv_nn_fit_scaling(tirenv_nn *nn, size_t n, const double x[], const double y[],
                          tirenv_diag *diag)
{
    const size_t n_in = nn->n_in;
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "samples",
                            "no samples to take the scaling from");
    double mean[TIRENV_NN_MAX_WIDTH], std[TIRENV_NN_MAX_WIDTH], lo[TIRENV_NN_MAX_WIDTH],
        hi[TIRENV_NN_MAX_WIDTH];
    double y_mean = 0, y_var = 0;
    for (size_t i = 0; i < n_in; ++i) {
        mean[i] = std[i] = 0;
        lo[i] = INFINITY;
        hi[i] = -INFINITY;
    }
    const int over_H = nn->target_form == TIRENV_NN_TARGET_H_OVER_H;
    for (size_t s = 0; s < n; ++s) {
        for (size_t i = 0; i < n_in; ++i) {
            const double v = x[s * n_in + i];
            if (!isfinite(v))
                return tirenv_error(diag, TIRENV_EINVAL, "", s + 1, tirenv_nn_input_name(i),
                                    "sample %zu: input %zu is %g; expected a finite number", s,
                                    i, v);
            mean[i] += feature(nn, i, v);
            lo[i] = v < lo[i] ? v : lo[i];
            hi[i] = v > hi[i] ? v : hi[i];
        }
        if (!isfinite(y[s]))
            return tirenv_error(diag, TIRENV_EINVAL, "", s + 1, "output",
                                "sample %zu: output is %g; expected a finite number", s, y[s]);
        if (over_H && !(x[s * n_in + TIRENV_NN_HEIGHT] > 0))
            return tirenv_error(diag, TIRENV_EINVAL, "", s + 1, "obstacle_height_m",
                                "sample %zu: H is %g; the h/H target needs H > 0", s,
                                x[s * n_in + TIRENV_NN_HEIGHT]);
        y_mean += over_H ? y[s] / x[s * n_in + TIRENV_NN_HEIGHT] : y[s];
    }
    for (size_t i = 0; i < n_in; ++i)
        mean[i] /= (double)n;
    y_mean /= (double)n;
    for (size_t s = 0; s < n; ++s) {
        for (size_t i = 0; i < n_in; ++i) {
            const double d = feature(nn, i, x[s * n_in + i]) - mean[i];
            std[i] += d * d;
        }
        const double t = over_H ? y[s] / x[s * n_in + TIRENV_NN_HEIGHT] : y[s];
        y_var += (t - y_mean) * (t - y_mean);
    }
    for (size_t i = 0; i < n_in; ++i) {
        std[i] = sqrt(std[i] / (double)n);
        if (!(std[i] > 0))
            std[i] = 1;  /* a constant input: centre it, nothing to scale */
    }
    double y_std = sqrt(y_var / (double)n);
    if (!(y_std > 0))
        y_std = 1;
    const int status = tirenv_nn_set_scaling(nn, mean, std, y_mean, y_std, diag);
    return status ? status : tirenv_nn_set_input_range(nn, lo, hi, diag);
}

size_t tirenv_nn_out_of_range(const tirenv_nn *nn, const double x[], size_t first)
{
    for (size_t i = first; i < nn->n_in; ++i)
        if (!(x[i] >= nn->in_lo[i] && x[i] <= nn->in_hi[i]))
            return i;
    return nn->n_in;
}
