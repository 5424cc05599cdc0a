/* Private: the capacity of a buffer that grows with what it holds.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CORE_CAPACITY_H
#define TIRENV_CORE_CAPACITY_H

#include <stddef.h>

/* The capacity to hold n: cap (first while it is 0) doubled until it does, so that a buffer
 * sized anew at each position settles at its largest need after O(log n) reallocations. */
static inline size_t tirenv_core__capacity(size_t cap, size_t first, size_t n)
{
    cap = cap ? cap : first;
    while (cap < n)
        cap *= 2;
    return cap;
}

#endif
