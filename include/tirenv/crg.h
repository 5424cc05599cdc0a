/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: ASAM OpenCRG road files (the convenience layer): a road surface on a curved regular
 * grid, read as tracks (profiles along the reference line) and written from profiles.
 * What is read and how a track is evaluated: docs/formats.md section 5. */
#ifndef TIRENV_CRG_H
#define TIRENV_CRG_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/error.h"
#include "tirenv/profile.h"

TIRENV_BEGIN_DECLS

/* The four data encodings of the road data block. */
typedef enum {
    TIRENV_CRG_LRFI = 0,   /* text, 10-character numbers, 8 a record */
    TIRENV_CRG_LDFI,       /* text, 20-character numbers, 4 a record */
    TIRENV_CRG_KRBI,       /* binary big-endian float32 (the format's default) */
    TIRENV_CRG_KDBI        /* binary big-endian float64 */
} tirenv_crg_encoding;

/* "LRFI", "LDFI", "KRBI", "KDBI"; NULL for another value. */
const char *tirenv_crg_encoding_name(tirenv_crg_encoding e);
/* The encoding of a name (case-insensitive); TIRENV_EINVAL for another name. */
int tirenv_crg_encoding_find(const char *name, tirenv_crg_encoding *e);

/* An open OpenCRG file: its header, checked, and where its rows are. Immutable once open;
 * every query reads the file where needed, so one handle may serve several threads. */
typedef struct tirenv_crg tirenv_crg;

/* Opens path: parses and checks the header, then reads the road data once to check it (row
 * count against REFERENCE_LINE_END_U, NaN only at the borders of a cross section, the
 * reference line channels) and keeps only what a track needs besides the grid (the reference
 * line's height per row when it has a slope channel, and for the text encodings the file
 * position of every 1024th row). The grid stays in the file. The modifiers' placement by
 * reference point (REFPOINT_*, or OpenCRG's defaults without $ROAD_CRG_MODS) is worked out
 * here, reading the reference line once more if it is curved. Errors name the file and the
 * line (header, text data) or byte offset (binary data) and the key or channel. */
int tirenv_crg_open(const char *path, tirenv_crg **out, tirenv_diag *diag);

/* The same from a buffer of size bytes, which must stay valid until tirenv_crg_free; name
 * labels messages (NULL: "(memory)"). */
int tirenv_crg_open_memory(const void *data, size_t size, const char *name, tirenv_crg **out,
                           tirenv_diag *diag);

/* Closes the file; NULL is a no-op. */
void tirenv_crg_free(tirenv_crg *crg);

/* The grid. Rows (cross sections) are at u_i = u_start + i*u_increment, i = 0..rows-1 (m,
 * arc length along the reference line); long sections at lateral positions v_j, ascending
 * (m, positive to the left of the reference line). */
tirenv_crg_encoding tirenv_crg_encoding_of(const tirenv_crg *crg);
size_t tirenv_crg_rows(const tirenv_crg *crg);
double tirenv_crg_u_start(const tirenv_crg *crg);       /* m */
double tirenv_crg_u_end(const tirenv_crg *crg);         /* m, u of the last row */
double tirenv_crg_u_increment(const tirenv_crg *crg);   /* m */
size_t tirenv_crg_long_sections(const tirenv_crg *crg);
double tirenv_crg_v(const tirenv_crg *crg, size_t j);   /* m; j < long sections */
/* Whether the reference line has a heading channel (curved), a slope or a banking channel. */
int tirenv_crg_is_curved(const tirenv_crg *crg);
int tirenv_crg_has_slope(const tirenv_crg *crg);
int tirenv_crg_has_banking(const tirenv_crg *crg);

/* Which track to take and how its borders are handled. */
typedef struct {
    double v;              /* lateral position, m (0 = the reference line, + to the left) */
    /* Beyond the outer long sections: -1 takes the file's $ROAD_CRG_OPTS BORDER_MODE_V, or 0
     * without one; 0 refuses the track; 1, 2, 3, 4 as OpenCRG (zero, keep the last value,
     * repeat, reflect), plus BORDER_OFFSET_V. */
    int border_mode_v;
    /* A NaN grid value the track needs: -1 takes the file's $ROAD_CRG_MODS GRID_NAN_MODE, or
     * OpenCRG's default 2 in a file without that section, or 0 in one that does not set it;
     * 0 refuses the track naming the row and long section; 1 takes 0, 2 the nearest valid
     * value of the cross section, both plus GRID_NAN_OFFSET. */
    int grid_nan_mode;
    /* With grid_nan_mode 1 or 2 set here (not -1): what is added to the filled value (mode 1:
     * the value itself) instead of the file's GRID_NAN_OFFSET; NaN takes the file's. */
    double grid_nan_offset;
} tirenv_crg_track_spec;

/* v = 0, border_mode_v = -1, grid_nan_mode = -1, grid_nan_offset = NaN. */
tirenv_crg_track_spec tirenv_crg_track_default(void);

/* The track as a profile: x = u of every row (m), z = the road's height there (m): the grid
 * interpolated linearly between the two long sections around v, plus the reference line's
 * height (REFERENCE_LINE_START_Z, the slope channel or REFERENCE_LINE_START_S, and
 * REFERENCE_LINE_OFFSET_Z), plus banking times v, shifted as the modifiers say (REFPOINT_Z,
 * or OpenCRG's default modifiers in a file without $ROAD_CRG_MODS: docs/formats.md section
 * 5). *out is NULL on failure. */
int tirenv_crg_track(const tirenv_crg *crg, const tirenv_crg_track_spec *spec,
                     tirenv_profile **out, tirenv_diag *diag);

/* The same for count rows from row first (first + count <= rows) into u[count], z[count] (m):
 * a window of a long road, read from the file without the rest. */
int tirenv_crg_track_rows(const tirenv_crg *crg, const tirenv_crg_track_spec *spec,
                          size_t first, size_t count, double u[], double z[],
                          tirenv_diag *diag);

/* The row at or before u (m), clamped to 0..rows-1: where a window around u starts. */
size_t tirenv_crg_row_at(const tirenv_crg *crg, double u);

/* Heights at every long section for count rows from row first, row after row, into
 * z[count*long_sections] (m), evaluated as a track at v_j; a NaN grid value stays NaN unless
 * the file's GRID_NAN_MODE fills it. For copying a road grid to another file. */
int tirenv_crg_grid_rows(const tirenv_crg *crg, size_t first, size_t count, double z[],
                         tirenv_diag *diag);

/* The reference line in the file's x/y plane, at every row into x[rows], y[rows] (m), and the
 * heading of the segment that ends at each row into phi[rows] (rad; phi[0] is the first
 * segment's). Integrated from REFERENCE_LINE_START_X/Y with the heading channel, the end
 * position's mismatch (if REFERENCE_LINE_END_X/Y are given) spread linearly along the line as
 * OpenCRG does; REFERENCE_LINE_OFFSET_X/Y/PHI and $ROAD_CRG_MODS REFLINE_* or REFPOINT_*
 * applied (OpenCRG's default REFPOINT_* in a file without that section). Any of x, y, phi
 * may be NULL. */
int tirenv_crg_refline(const tirenv_crg *crg, double x[], double y[], double phi[],
                       tirenv_diag *diag);

/* A track read a block of rows at a time, for roads too long to hold (tirenv_model_stream and
 * the like): the vertices of tirenv_crg_track in order, in memory of one block. */
typedef struct tirenv_crg_track_reader tirenv_crg_track_reader;

/* crg must outlive the reader. */
int tirenv_crg_track_reader_open(const tirenv_crg *crg, const tirenv_crg_track_spec *spec,
                                 tirenv_crg_track_reader **out, tirenv_diag *diag);
/* The next vertex (m) in *u, *z with *got = 1, or *got = 0 after the last row. */
int tirenv_crg_track_reader_next(tirenv_crg_track_reader *r, double *u, double *z, int *got,
                                 tirenv_diag *diag);
void tirenv_crg_track_reader_free(tirenv_crg_track_reader *r);  /* NULL is a no-op */
/* tirenv_crg_track_reader_next in the form of a tirenv_vertex_source (stream.h): reader is
 * the tirenv_crg_track_reader, so that tirenv_model_stream takes a CRG track as it goes. */
int tirenv_crg_track_reader_source(void *reader, double *u, double *z, int *got,
                                   tirenv_diag *diag);

/* ---- writing ------------------------------------------------------------------------- */

/* The grid of a file to write: a straight reference line from (x_start, y_start) with heading
 * phi_start (0, 0, 0: along x from the origin), rows at u_start + i*u_increment, long sections
 * at v[0] < v[1] < ... (m). The header states the placement and a $ROAD_CRG_MODS section
 * without modifiers, so that OpenCRG (and Chrono, which applies OpenCRG's default modifiers
 * to a file that states none) evaluates the road where the file puts it and at the heights
 * written (docs/formats.md section 5). */
typedef struct {
    tirenv_crg_encoding encoding;
    double x_start, y_start;   /* the reference line at u_start in the x/y plane, m */
    double phi_start;          /* its heading, rad from the x axis */
    double z_start;            /* its height (REFERENCE_LINE_START_Z), m: the rows' heights
                                * are written less it, so that a road high above z = 0 keeps
                                * its detail in OpenCRG's single-precision grid */
    double u_start;            /* m */
    double u_increment;        /* m, > 0 */
    size_t rows;               /* rows that will follow, >= 2 */
    size_t long_sections;      /* >= 2: OpenCRG needs a width */
    const double *v;           /* long_sections lateral positions, ascending, m */
    const char *comment;       /* $CT text (lines of at most 72 characters); NULL for none */
} tirenv_crg_layout;

/* A file being written row after row (all or nothing: tirenv_outfile). */
typedef struct tirenv_crg_writer tirenv_crg_writer;

/* Checks the layout, opens path and writes the header. */
int tirenv_crg_writer_open(const char *path, const tirenv_crg_layout *layout,
                           tirenv_crg_writer **out, tirenv_diag *diag);
/* One row: z[long_sections] heights, m (absolute: the file holds z - z_start, read back as
 * z_start plus it, the same to round-off). NaN is written as missing and allowed only at the
 * borders of a row with at least one number (the format's rule); infinities are refused. */
int tirenv_crg_writer_row(tirenv_crg_writer *w, const double z[], tirenv_diag *diag);
/* Checks that all rows came, pads the last binary record with NaN, renames the file into
 * place and frees w (also on failure). */
int tirenv_crg_writer_commit(tirenv_crg_writer *w, tirenv_diag *diag);
/* Removes the temporary file and frees w; NULL is a no-op. */
void tirenv_crg_writer_abort(tirenv_crg_writer *w);

/* Writes n profiles as the long sections at v[0] < ... < v[n-1] (m), n >= 2. The rows are at
 * the vertices of the profiles when they share one evenly spaced x (u_increment 0), else at
 * x_first + i*u_increment over the common extent, the last at its end or the first past it,
 * where each profile's height is taken (tirenv_profile_height, level beyond a profile's end; a
 * vertical wall becomes a ramp one increment long). */
int tirenv_crg_write_profiles(const char *path, tirenv_crg_encoding encoding, size_t n,
                              const double v[], const tirenv_profile *const tracks[],
                              double u_increment, const char *comment, tirenv_diag *diag);

TIRENV_END_DECLS
#endif
