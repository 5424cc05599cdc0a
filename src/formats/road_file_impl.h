/* SPDX-License-Identifier: Apache-2.0 */
/* Private to src/formats: what the readers of the formats take from an open road file
 * (tirenv_road_file, road_file.c) instead of a path, so that the file is opened once and its
 * format told once: a stream of its text from the start (the CSV readers) or its bytes at any
 * position (the OpenCRG and RDF readers). */
#ifndef TIRENV_FORMATS_ROAD_FILE_IMPL_H
#define TIRENV_FORMATS_ROAD_FILE_IMPL_H

#include <stdio.h>

#include "formats/rdf_impl.h"
#include "io/io.h"
#include "tirenv/profile_file.h"

/* A new stream of the file's bytes from its start, with a position of its own (several may
 * be open at once; each is the caller's to fclose); NULL with diag set on failure. */
FILE *tirenv_road_file__stream(tirenv_road_file *f, tirenv_diag *diag);

/* The file's bytes at any position, owned by f. A pipe or a device is read to its end first
 * (kept in memory, at most TIRENV_ROAD_FILE_PIPE_MAX bytes). */
int tirenv_road_file__source(tirenv_road_file *f, const tirenv_source **out, tirenv_diag *diag);

/* The OpenCRG road in f, opened (its header parsed, its rows checked in one pass) at the first
 * call and kept by f for every later one: owned by f, shared by its readers. */
int tirenv_road_file__crg(tirenv_road_file *f, const tirenv_crg **out, tirenv_diag *diag);

/* The RDF road in f, scanned at the first call (its keys, its rows checked and not kept:
 * rdf_impl.h) and kept by f for every later one, owned by f, shared by its readers; the
 * error of side, if its rows do not make a profile. */
int tirenv_road_file__rdf(tirenv_road_file *f, tirenv_rdf_side side,
                          const tirenv_rdf__road **out, tirenv_diag *diag);

/* The RDF road in f on side as a profile: gathered in the scan's one pass where f has not
 * been scanned yet (tirenv_rdf__open_whole, the scan then kept by f), else from its rows. */
int tirenv_road_file__rdf_whole(tirenv_road_file *f, tirenv_rdf_side side,
                                tirenv_profile **out, tirenv_diag *diag);

#endif
