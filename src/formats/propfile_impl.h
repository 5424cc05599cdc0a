/* SPDX-License-Identifier: Apache-2.0 */
/* Private to the property-file engine's own files (propfile.c reads, propfile_write.c
 * writes): the key lookups both sides use. */
#ifndef TIRENV_PROPFILE_IMPL_H
#define TIRENV_PROPFILE_IMPL_H

#include <stddef.h>

#include "formats/propfile.h"

/* The index of the first matching key in s->keys, or s->n_keys. section NULL matches any
 * section; settable leaves out the [UNITS] keys (MASS is both a unit and a vehicle key).
 * *matches, if not NULL, counts the keys that match. */
size_t tirenv_propfile__find_key(const tirenv_propfile__schema *s, const char *section,
                                 const char *key, int settable, size_t *matches);

/* "A, B, C": the keys of one section, or every settable key (each name once) if section is
 * NULL, into buf (n bytes). */
const char *tirenv_propfile__key_list(const tirenv_propfile__schema *s, const char *section,
                                      char *buf, size_t n);

#endif
