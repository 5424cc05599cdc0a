/* SPDX-License-Identifier: Apache-2.0 */
/* The dataset module's interface to the auxiliary modules after it (sweep), as io/io.h is
 * io's: what a sweep writes and the data-set reader checks of it must count alike. Not the
 * user's: internal tirenv_<object>__ names. */
#ifndef TIRENV_DATASET_DATASET_H
#define TIRENV_DATASET_DATASET_H

#include <stddef.h>

/* The rows of shard k of n (0 <= k < n) of a sweep of m cases: the cases i < m with
 * i mod n = k, none when k >= m. */
static inline size_t tirenv_dataset__shard_rows(size_t m, size_t k, size_t n)
{
    return m > k ? (m - k - 1) / n + 1 : 0;
}

#endif
