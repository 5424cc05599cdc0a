/* tirenv: the empirical model's file (docs/formats.md): a network (nn.h) and how it was trained
 * (train.h), as JSON. A file format, so it belongs to the auxiliary layer (src/formats/nn_json.c
 * and nn_json_write.c), not to the network or its trainers.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_NN_FILE_H
#define TIRENV_NN_FILE_H

#include "tirenv/decls.h"
#include <stdint.h>
#include "tirenv/error.h"
#include "tirenv/model.h"
#include "tirenv/nn.h"
#include "tirenv/train.h"

TIRENV_BEGIN_DECLS

#define TIRENV_NN_FORMAT "tirenv-nn"
#define TIRENV_NN_FORMAT_VERSION 3  /* 3: the checksum covers the contact law; 2: ensembles
                                     * and forms; versions 1 and 2 still read */

/* What a model file records besides the network. */
typedef struct {
    char trainer[32];                /* trainer name, or "": no record (a file without
                                        one reads so, and is written without one) */
    tirenv_train_settings settings;  /* as used (the callback is not saved) */
    tirenv_train_report report;
    uint64_t fingerprint;            /* tirenv_samples_fingerprint of train, control,
                                        validation in turn */
    double R0;                       /* free radius of the tire the data's x_N refers to, m;
                                        0 if unknown */
    char data[512];                  /* data set directory, or "" */
    /* The load-to-contact-length relation of the tire the data came from (training.data.
     * contact_law, docs/formats.md): law.n = 0 in a file without one (older files). */
    tirenv_contact_law law;
    char law_source[96];             /* what made it: "the ring model's flat ground through the
                                        cases", "the cases: l_c = a*G^b" */
} tirenv_train_record;

/* Writes nn and rec (rec may be NULL) atomically (tirenv_outfile). Non-finite numbers are
 * refused. Reals are written with 17 significant digits, so reading gives the same bits. */
int tirenv_nn_write_json(const char *path, const tirenv_nn *nn, const tirenv_train_record *rec,
                         tirenv_diag *diag);
/* Reads a model file, checking format, version, sizes, finiteness, ranges and the network
 * checksum; errors name the file and the field. *out is NULL on failure; rec may be NULL;
 * TIRENV_EINVAL for a NULL or empty path or a NULL out. */
int tirenv_nn_read_json(const char *path, tirenv_nn **out, tirenv_train_record *rec,
                        tirenv_diag *diag);

TIRENV_END_DECLS
#endif
