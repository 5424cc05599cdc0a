/* Private to the data sets (src/dataset/dataset*.c): what the manifest's reader and
 * source.txt's share.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_DATASET_IMPL_H
#define TIRENV_DATASET_IMPL_H

/* The most cases a manifest holds: a million (the most tirenv sweep makes), about 1 GB of
 * case records before any curve is read. source.txt's `cases` may declare no more. */
#define TIRENV_DATASET__MAX_CASES 1000000u

#include <stddef.h>

#include "tirenv/error.h"

/* The number of rows a manifest must hold, and which file declares it. */
typedef struct {
    size_t cases;          /* rows of the manifest; 0: nothing declared */
    size_t line;           /* the declaring line of file */
    char file[1100];       /* source.txt or sweep.txt, with the directory */
    char what[96];         /* the declaration as the message quotes it, "cases = 28" */
    /* sweep.txt's: its `model`, its first `set KEY` and that line (or "", "", 0) */
    char model[32], key[64];
    size_t key_line;
    int raw;               /* `curves = model`: the model's own curves, no rig */
} tirenv_dataset__declared;

/* What dir/sweep.txt, when there is one and it gives `cases = M` (and `shard = K/N`),
 * declares: the shard's rows of the M cases, those i with i mod N = K (dataset_sweep.c), and
 * its model and first tire key set. Nothing (out->cases 0) without the file or the key;
 * TIRENV_EPARSE naming the file, line and key for a count or shard that is not one. */
int tirenv_dataset__sweep_declared(const char *dir, tirenv_dataset__declared *out,
                                   tirenv_diag *diag);

/* TIRENV_EIO naming path when it is a pipe (a FIFO or a socket), else TIRENV_OK (a file, a
 * device such as /dev/zero, whose reader stops at its cap, or nothing, which the reader
 * names). A data set's files are
 * read more than once (source.txt by the command and by tirenv_dataset_read, every file by
 * each stage of a study), and a pipe has no second read: refused before it is opened, where
 * the second open would wait for a writer that has gone. */
int tirenv_dataset__refuse_pipe(const char *path, tirenv_diag *diag);

#endif
