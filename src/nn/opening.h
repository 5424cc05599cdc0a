/* Private to the nn module: the morphological opening of a sampled signal, the baseline of
 * nn_road.c. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_NN_OPENING_H
#define TIRENV_NN_OPENING_H

#include <stddef.h>

/* Opening of n samples s[] at increasing abscissae x[] by a flat element of half-width a:
 * the erosion e_i = min of s_j over |x_j - x_i| <= a, then the dilation b_i = max of e_j
 * over the same window; windows hold only the samples there are (truncated at the ends).
 * e receives the erosion (n doubles); q is a workspace of n indices. O(n) whatever a; no
 * allocation. */
void tirenv_nn__opening(size_t n, const double x[], const double s[], double a, double b[],
                        double e[], size_t q[]);

#endif
