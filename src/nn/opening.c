/* The morphological opening (erosion then dilation by a flat element) of a sampled signal:
 * the baseline of the equivalent-cleat decomposition (nn_road.c, docs/models.md section 12).
 * SPDX-License-Identifier: Apache-2.0 */
#include "nn/opening.h"

/* The running minimum (sign +1) or maximum (sign -1, by comparing -s) over the window
 * |x_j - x_i| <= a, by a monotone deque (the "ascending minima" algorithm, here with two
 * pointers because samples need not be evenly spaced): q[head..tail) holds the indices of
 * window samples whose values increase from front to back; a sample entering at the right
 * evicts every larger one from the back, and the front leaves once it is more than a behind
 * x_i. Each index enters and leaves at most once, so the deque never wraps and the cost is
 * O(n) whatever the window. The deque is never empty when read: sample i itself, or a later
 * one in the window no larger than it, is in it. (van Herk and Gil-Werman's algorithm is
 * faster but needs even spacing; the samples include the profile's own vertices.) */
static void running_extremum(size_t n, const double x[], const double s[], double a,
                             double sign, double out[], size_t q[])
{
    size_t head = 0, tail = 0, right = 0;
    for (size_t i = 0; i < n; ++i) {
        for (; right < n && x[right] - x[i] <= a; ++right) {
            const double v = sign * s[right];
            while (tail > head && sign * s[q[tail - 1]] >= v)
                --tail;
            q[tail++] = right;
        }
        while (x[i] - x[q[head]] > a)
            ++head;
        out[i] = s[q[head]];
    }
}

void tirenv_nn__opening(size_t n, const double x[], const double s[], double a, double b[],
                        double e[], size_t q[])
{
    running_extremum(n, x, s, a, 1.0, e, q);
    running_extremum(n, x, e, a, -1.0, b, q);
}
