/* Private to the data sets (src/dataset/dataset*.c): what the manifest's reader and
 * source.txt's share.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_DATASET_IMPL_H
#define TIRENV_DATASET_IMPL_H

/* The most cases a manifest holds: a million (the most tirenv sweep makes), about 1 GB of
 * case records before any curve is read. source.txt's `cases` may declare no more. */
#define TIRENV_DATASET__MAX_CASES 1000000u

#endif
