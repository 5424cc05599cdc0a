/* tirenv: the empirical enveloping model, a small fully connected feed-forward network
 * (paper, Tables 1 and 2; docs/models.md section 6). Logistic hidden layers, one identity output.
 * Training is in train.h; the model file (the net and how it was trained) in nn_file.h.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_NN_H
#define TIRENV_NN_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/rng.h"
#include "tirenv/error.h"

TIRENV_BEGIN_DECLS

#define TIRENV_NN_MAX_LAYERS 6   /* layers counting input and output: up to 4 hidden */
#define TIRENV_NN_MAX_WIDTH 64   /* neurons in any layer */

/* The inputs of the enveloping model in the paper's order (Table 1: normalised position,
 * working regime, obstacle height, obstacle length); its one output is h, m. */
enum {
    TIRENV_NN_X_N = 0,           /* normalised position x_N (docs/models.md section 1) */
    TIRENV_NN_CONTACT_LENGTH,    /* contact length l_c, m */
    TIRENV_NN_HEIGHT,            /* obstacle height H, m */
    TIRENV_NN_LENGTH,            /* obstacle length L, m */
    TIRENV_NN_INPUTS             /* how many */
};

/* "x_N", "contact_length_m", "obstacle_height_m", "obstacle_length_m"; NULL past the end. */
const char *tirenv_nn_input_name(size_t i);

/* How the enveloping model's inputs and output reach the network (docs/models.md section 6.1).
 * The paper feeds x_N itself; its curve is then mirrored about x_N = 1, where nothing makes
 * the network's slope vanish, so the full curve can have a kink (a notch) over the obstacle
 * centre. The even form feeds the distance from the centre rounded over a width a,
 *     f = sqrt((1 - x_N)^2 + a^2) - a,
 * even about x_N = 1 and smooth there, so dh/dx_N = 0 at the centre by construction; it is
 * monotonic over x_N <= 1, so no two positions of the approach half share a feature. Beyond a
 * it is |1 - x_N| - a, so the network keeps x_N's resolution over the rest of the curve (a
 * large a tends to (1 - x_N)^2 / 2a, which crowds the top of the curve into a small range). */
typedef enum {
    TIRENV_NN_INPUT_PAPER = 0,   /* x_N as is (the paper's Table 1) */
    TIRENV_NN_INPUT_EVEN         /* sqrt((1 - x_N)^2 + a^2) - a in place of x_N */
} tirenv_nn_input_form;

/* The default width a of the even form, in x_N (chosen on the control error over seeds:
 * src/train/train.c says with which figures). */
#define TIRENV_NN_EVEN_WIDTH 0.2

/* The paper's network outputs h; with TIRENV_NN_TARGET_H_OVER_H it learns h/H and its output
 * is H times that, so every obstacle's curve has the same scale to the network. */
typedef enum {
    TIRENV_NN_TARGET_H = 0,      /* the network's output is h, m */
    TIRENV_NN_TARGET_H_OVER_H    /* it is h/H, multiplied by the input H */
} tirenv_nn_target_form;

/* "paper", "even"; "h", "h/H"; NULL for an unknown value. */
const char *tirenv_nn_input_form_name(tirenv_nn_input_form f);
const char *tirenv_nn_target_form_name(tirenv_nn_target_form f);
/* The form of that name; -1 if none. */
int tirenv_nn_input_form_find(const char *name);
int tirenv_nn_target_form_find(const char *name);

/* The most networks an ensemble holds. */
#define TIRENV_NN_MAX_MEMBERS 64

/* Layer sizes, input first, output last. The output layer has exactly one neuron. */
typedef struct {
    size_t n_layers;                     /* 2..TIRENV_NN_MAX_LAYERS */
    size_t size[TIRENV_NN_MAX_LAYERS];   /* neurons per layer, 1..TIRENV_NN_MAX_WIDTH */
} tirenv_nn_topology;

/* The paper's 4-8-1. */
tirenv_nn_topology tirenv_nn_topology_default(void);
/* TIRENV_OK, or TIRENV_EINVAL naming the bad layer in diag. */
int tirenv_nn_topology_check(const tirenv_nn_topology *t, tirenv_diag *diag);

/* A network of fixed shape in one allocation: weights, scaling, input ranges, and the
 * workspace of the evaluations below (which is why they take a non-const pointer: use one
 * network per thread, tirenv_nn_clone makes more).
 *
 * It may be an ensemble: K members of the same topology sharing one input and output
 * scaling, input ranges and forms, whose output is the mean of the members' scaled outputs,
 * y = out_mean + out_std * (o_1 + ... + o_K)/K (times H for TIRENV_NN_TARGET_H_OVER_H). A
 * single network is the ensemble of one; everything below works on either. */
typedef struct tirenv_nn tirenv_nn;

/* NULL if the topology is invalid or memory runs out. Weights 0, identity scaling, input
 * ranges unbounded, the paper's forms (x_N in, h out). */
tirenv_nn *tirenv_nn_alloc(const tirenv_nn_topology *t);
/* The same with `members` networks (1..TIRENV_NN_MAX_MEMBERS); NULL otherwise. */
tirenv_nn *tirenv_nn_alloc_ensemble(const tirenv_nn_topology *t, size_t members);
void tirenv_nn_free(tirenv_nn *nn);                       /* NULL is a no-op */
tirenv_nn *tirenv_nn_clone(const tirenv_nn *nn);          /* NULL on out of memory */
/* Copies weights, scaling, ranges and forms between nets of equal topology and member count;
 * TIRENV_EINVAL if they differ. */
int tirenv_nn_copy(tirenv_nn *dst, const tirenv_nn *src);
/* The ensemble of n single networks (n in 1..TIRENV_NN_MAX_MEMBERS) that share topology,
 * scaling, ranges and forms (training restarts on one data set do): member k is nets[k].
 * NULL if they differ, a net is itself an ensemble, or memory runs out. */
tirenv_nn *tirenv_nn_ensemble(const tirenv_nn *const nets[], size_t n);
/* Member k (0-based) of nn as a single network with nn's scaling, ranges and forms; NULL if
 * k is out of range or memory runs out. */
tirenv_nn *tirenv_nn_member(const tirenv_nn *nn, size_t k);

const tirenv_nn_topology *tirenv_nn_topology_of(const tirenv_nn *nn);
size_t tirenv_nn_n_inputs(const tirenv_nn *nn);
size_t tirenv_nn_n_members(const tirenv_nn *nn);
/* All weights of all members (n_members times those of one). */
size_t tirenv_nn_n_weights(const tirenv_nn *nn);

/* The forms (above); they need the enveloping model's 4 inputs unless both are the paper's:
 * TIRENV_EINVAL otherwise. Set them before tirenv_nn_fit_scaling, which scales the features
 * and the target they define. */
int tirenv_nn_set_form(tirenv_nn *nn, tirenv_nn_input_form input, tirenv_nn_target_form target,
                       tirenv_diag *diag);
void tirenv_nn_form(const tirenv_nn *nn, tirenv_nn_input_form *input,
                    tirenv_nn_target_form *target);
/* The even form's width a (> 0, finite; TIRENV_NN_EVEN_WIDTH when allocated); TIRENV_EINVAL
 * otherwise. Like the forms, set it before tirenv_nn_fit_scaling. */
int tirenv_nn_set_even_width(tirenv_nn *nn, double a, tirenv_diag *diag);
double tirenv_nn_even_width(const tirenv_nn *nn);

/* All weights, member by member, each member's layer by layer; layer l (1-based, fed by
 * layer l-1 of n_in neurons, n_out neurons) is a (1 + n_in) x n_out row-major block: first
 * the n_out biases, then one row per input i holding its weights to each neuron j. Weights
 * act on the scaled features. */
double *tirenv_nn_weights(tirenv_nn *nn);
const double *tirenv_nn_weights_const(const tirenv_nn *nn);
/* Index in that array of the weight from neuron i of layer l-1 (i = 0 for the bias,
 * 1..n_in for the neurons) to neuron j (0-based) of layer l (1..n_layers-1) of member 0;
 * member k's is that plus k*n_weights/n_members. */
size_t tirenv_nn_weight_index(const tirenv_nn *nn, size_t l, size_t i, size_t j);

/* Nguyen-Widrow initialisation of every hidden layer (each neuron's weights uniform in
 * [-0.5, 0.5] rescaled to norm 0.7*n_hidden^(1/n_in), bias uniform in +-that norm), and
 * uniform [-0.5, 0.5] for the output layer; draws from rng neuron by neuron (its n_in
 * weights, then its bias), member after member, so a seed gives the same network on every
 * machine. */
void tirenv_nn_init_weights(tirenv_nn *nn, tirenv_rng *rng);

/* Scaling: the net sees u_i = (f_i - in_mean_i)/in_std_i, with the feature f_i = x_i except
 * f_0 = sqrt((1 - x_N)^2 + a^2) - a under TIRENV_NN_INPUT_EVEN, and outputs y = out_mean +
 * out_std*o (times H under TIRENV_NN_TARGET_H_OVER_H, where out_mean and out_std are those
 * of h/H). Every number finite, stds > 0; else TIRENV_EINVAL. Units of the features and the
 * target. */
int tirenv_nn_set_scaling(tirenv_nn *nn, const double in_mean[], const double in_std[],
                          double out_mean, double out_std, tirenv_diag *diag);
void tirenv_nn_scaling(const tirenv_nn *nn, double in_mean[], double in_std[],
                       double *out_mean, double *out_std);
/* The range of each input seen in training (lo <= hi, finite; or +-inf for unknown). */
int tirenv_nn_set_input_range(tirenv_nn *nn, const double lo[], const double hi[],
                              tirenv_diag *diag);
void tirenv_nn_input_range(const tirenv_nn *nn, double lo[], double hi[]);
/* Sets scaling (mean and population standard deviation of the features and the target of
 * the net's forms; a constant column gets std 1) and input ranges (of the raw inputs) from n
 * samples: x row-major n x n_inputs, y n outputs (h, m). TIRENV_EINVAL if n = 0, a value is
 * not finite, or H <= 0 under TIRENV_NN_TARGET_H_OVER_H. */
int tirenv_nn_fit_scaling(tirenv_nn *nn, size_t n, const double x[], const double y[],
                          tirenv_diag *diag);
/* Index of the first input i >= first outside its training range, or n_inputs if none. */
size_t tirenv_nn_out_of_range(const tirenv_nn *nn, const double x[], size_t first);

/* Output for one sample of n_inputs raw (unscaled) inputs. No allocation. */
double tirenv_nn_run(tirenv_nn *nn, const double x[]);
/* Outputs y[s] for n samples x[s*n_inputs + i]; bit-for-bit what tirenv_nn_run gives. */
void tirenv_nn_run_batch(tirenv_nn *nn, size_t n, const double x[], double y[]);
/* Output for one sample and its exact gradient grad[k] = dy/dw_k over all weights of all
 * members (in the order of tirenv_nn_weights), by back-propagation. */
double tirenv_nn_gradient(tirenv_nn *nn, const double x[], double grad[]);
/* Outputs y[s] (NULL: not wanted) and Jacobian J[s*n_weights + k] = dy_s/dw_k of n samples. */
void tirenv_nn_jacobian(tirenv_nn *nn, size_t n, const double x[], double y[], double J[]);

/* The enveloping model: h (m) at tire-centre positions x[] (m) over a rectangular cleat of
 * length L and height H (m) centred at x = 0, at contact length l_c (m), for a tire of free
 * radius R0 (m). The approach half x <= 0 is the network at x_N(x) (docs/models.md section 1); the
 * other half is its mirror image; h = 0 before the lowest x_N seen in training (the tire is
 * still on flat ground) and where the network says h < 0 (a cleat cannot lower the centre).
 * Needs a 4-input net (TIRENV_NN_INPUTS). TIRENV_EINVAL for non-physical arguments,
 * TIRENV_ERANGE if the cleat reaches the chord height; no allocation. Over any other profile
 * (a road), by equivalent cleats: nn_road.h, an extension beyond the paper. */
int tirenv_nn_envelope(tirenv_nn *nn, double R0, double l_c, double L, double H, size_t n,
                       const double x[], double h[], tirenv_diag *diag);

TIRENV_END_DECLS
#endif
