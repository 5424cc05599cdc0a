/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the model files' JSON (src/formats/nn_json.c reads, nn_json_write.c writes): the
 * checksum of the network's numbers and its text, and the largest integer jansson holds. */
#ifndef TIRENV_FORMATS_NN_JSON_IMPL_H
#define TIRENV_FORMATS_NN_JSON_IMPL_H

#include <limits.h>
#include <stddef.h>
#include <stdint.h>
#include <jansson.h>

#include "tirenv/model.h"
#include "tirenv/nn.h"

#if JSON_INTEGER_IS_LONG_LONG
#define NN_JSON_INT_MAX LLONG_MAX
#else
#define NN_JSON_INT_MAX LONG_MAX
#endif

/* FNV-1a 64 over the topology, weights, scaling and ranges, from version 2 on the member
 * count, the two forms and the even width, and from version 3 on law's knot count, loads and
 * lengths (law NULL: no law, a count of 0) (docs/formats.md section 10). */
uint64_t tirenv_nn_json__checksum(const tirenv_nn *nn, const tirenv_contact_law *law,
                                  int version);

/* "fnv1a64:<16 hex>" into buf (n bytes). */
void tirenv_nn_json__hash_text(char *buf, size_t n, uint64_t h);

/* TIRENV_EPARSE naming path and the key's path where an object of root (a file of format
 * version) holds a key the format does not know; else TIRENV_OK (nn_json_keys.c). */
int tirenv_nn_json__check_keys(const char *path, const json_t *root, int version,
                               tirenv_diag *diag);

#endif
