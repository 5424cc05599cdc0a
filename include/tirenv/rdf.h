/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: TNO / Adams 2-D road files (.rdf, TeimOrbit format; the convenience layer): read
 * as a profile, written from profiles. What is read: docs/formats.md section 5. */
#ifndef TIRENV_RDF_H
#define TIRENV_RDF_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/profile.h"

TIRENV_BEGIN_DECLS

/* Which track of a 'poly_line' road, whose (XZ_DATA) rows are x, z_left, z_right. */
typedef enum {
    TIRENV_RDF_MEAN = 0,   /* (z_left + z_right) / 2: the default */
    TIRENV_RDF_LEFT,
    TIRENV_RDF_RIGHT
} tirenv_rdf_side;

/* "mean", "left", "right"; NULL for another value. */
const char *tirenv_rdf_side_name(tirenv_rdf_side side);
/* The side of a name; TIRENV_EINVAL for another name. */
int tirenv_rdf_side_find(const char *name, tirenv_rdf_side *side);

/* Reads a 2-D road (METHOD = '2D') of ROAD_TYPE 'poly_line', 'plank' or 'flat' as a profile in
 * m: [UNITS] LENGTH converted to m, [PARAMETERS] OFFSET added to the heights. Other road
 * types, 3-D roads and an oblique plank (DIRECTION not 0) are refused. Errors name file,
 * line, column and key. *out is NULL on failure. */
int tirenv_rdf_read(const char *path, tirenv_rdf_side side, tirenv_profile **out,
                    tirenv_diag *diag);

/* The same from a buffer of size bytes; name labels messages (NULL: "(memory)"). */
int tirenv_rdf_read_memory(const void *data, size_t size, const char *name,
                           tirenv_rdf_side side, tirenv_profile **out, tirenv_diag *diag);

/* Writes a 'poly_line' road in m from the left and right tracks (right NULL: the same as
 * left), which must share their x; every number in the shortest form that reads back to the
 * same double. A one-vertex profile (flat ground) is written as ROAD_TYPE 'flat' with OFFSET
 * its height. comment (NULL for none) goes in '$' comment lines. All or nothing
 * (tirenv_outfile). */
int tirenv_rdf_write(const char *path, const tirenv_profile *left, const tirenv_profile *right,
                     const char *comment, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
