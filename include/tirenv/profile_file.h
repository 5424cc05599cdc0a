/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: a ground profile from or to any road file tirenv knows (the convenience layer): CSV
 * ("x_m,z_m"), ASAM OpenCRG (.crg) and TNO / Adams 2-D roads (.rdf), told apart by their
 * content when read and by the file name's extension when written (docs/formats.md
 * section 5). */
#ifndef TIRENV_PROFILE_FILE_H
#define TIRENV_PROFILE_FILE_H

#include "tirenv/decls.h"
#include <stddef.h>
#include "tirenv/crg.h"
#include "tirenv/error.h"
#include "tirenv/profile.h"
#include "tirenv/rdf.h"

TIRENV_BEGIN_DECLS

typedef enum {
    TIRENV_PROFILE_CSV = 0,
    TIRENV_PROFILE_CRG,
    TIRENV_PROFILE_RDF
} tirenv_profile_format;

/* "csv", "crg", "rdf"; NULL for another value. */
const char *tirenv_profile_format_name(tirenv_profile_format f);

/* Which profile to take from a road file that holds more than one. */
typedef struct {
    tirenv_crg_track_spec crg;   /* OpenCRG: the track (v, m) and its border handling */
    tirenv_rdf_side rdf_side;    /* RDF poly_line: left, right or their mean */
} tirenv_profile_source;

/* The reference line of a CRG (v = 0, the file's border options), the mean of an RDF. */
tirenv_profile_source tirenv_profile_source_default(void);

/* The format of size bytes of a file's start, by content: a CRG header ('*' comment lines,
 * then $CT, $ROAD_CRG...), a TeimOrbit file ('$' / '!' comment lines, then a [BLOCK]), or
 * else CSV. */
tirenv_profile_format tirenv_profile_detect_memory(const void *data, size_t size);

/* The format a file name's extension names (.csv, .crg, .rdf, any case); TIRENV_EINVAL for
 * another name. */
int tirenv_profile_format_of_name(const char *path, tirenv_profile_format *f);

/* ---- the one road reader -------------------------------------------------------------- */

/* Bytes of a pipe or a device (not a regular file) that an open road file keeps in memory:
 * it can be read only once, so what is read of it is kept for every reader (256 MiB). */
#define TIRENV_ROAD_FILE_PIPE_MAX 268435456

/* A road file opened once, its format told once by its first 64 KB
 * (tirenv_profile_detect_memory), from which any number of profiles and row readers are then
 * taken: the commands that take --profile, the FMU and the Python module read roads through
 * it. A regular file is read where asked, each reader at its own position; a pipe or a
 * device (a FIFO, /dev/stdin) is read as far as a reader asks and kept (at most
 * TIRENV_ROAD_FILE_PIPE_MAX bytes; an OpenCRG or RDF road is read to its end at once). An
 * OpenCRG road's pass at open and an RDF road's poly_line are read once, kept by the file
 * until it is freed and shared by its readers, tirenv_road_file_extent and the effective
 * road's placement (tirenv_road_writer_layout.on_crg). */
typedef struct tirenv_road_file tirenv_road_file;

/* Opens path and tells its format; TIRENV_EIO if it cannot be opened or read or is a
 * directory. *out is NULL on failure. */
int tirenv_road_file_open(const char *path, tirenv_road_file **out, tirenv_diag *diag);
/* The format its content shows. */
tirenv_profile_format tirenv_road_file_format(const tirenv_road_file *f);
/* The path it was opened by (owned by f). */
const char *tirenv_road_file_name(const tirenv_road_file *f);
void tirenv_road_file_free(tirenv_road_file *f);  /* NULL is a no-op */

/* The format of the file at path, by content (its first 64 KB): tirenv_road_file_open's. */
int tirenv_profile_detect(const char *path, tirenv_profile_format *f, tirenv_diag *diag);

/* Reads n >= 1 tracks of f at the lateral positions v[n] (m) into out[n] (each the caller's
 * to free): a CRG's tracks as tirenv_crg_track with src->crg but v[i]; a CSV or an RDF road
 * (src->rdf_side) is 2-D, the same on every track, so out[i] are copies of one profile. v
 * NULL: every track at src->crg.v; src NULL means the defaults. Errors name file, line and
 * field; on failure every out[i] is NULL. */
int tirenv_road_file_read(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                          const double v[], tirenv_profile *out[], tirenv_diag *diag);

/* The OpenCRG road in f (a .crg by content), as tirenv_crg_open reads it: opened at the first
 * call (or the first reader's, read or extent) and shared with them, so that its pass at
 * open is made once; owned by f (never tirenv_crg_free it), valid until tirenv_road_file_free. */
int tirenv_road_file_crg(tirenv_road_file *f, const tirenv_crg **out, tirenv_diag *diag);

/* tirenv_road_file_read of a file opened for this one read: one track (src NULL: the
 * defaults), or n. */
int tirenv_profile_read_file(const char *path, const tirenv_profile_source *src,
                             tirenv_profile **out, tirenv_diag *diag);
int tirenv_profile_read_tracks(const char *path, const tirenv_profile_source *src, size_t n,
                               const double v[], tirenv_profile *out[], tirenv_diag *diag);

/* A road file read a row at a time, whatever its format, for a streamed sweep
 * (tirenv_model_stream_tracks, or tirenv_model_stream for one track): each row is an x (m) and
 * the heights (m) of n tracks there. A CSV is read row by row, a CRG a block of rows at a time
 * (each block once for every track: memory of a few blocks, whatever the road's length), an
 * RDF road's poly_line a line at a time (a 64 KB window of the file, after a scan at the first
 * reader that checks its rows and keeps none). A CSV or RDF road is 2-D: every track gets its
 * height. */
typedef struct tirenv_profile_file_reader tirenv_profile_file_reader;

/* A reader of f from its start for n >= 1 tracks at v[n] (m; v NULL: every track at
 * src->crg.v); src NULL means the defaults. f must outlive it; several may be open at once. */
int tirenv_road_file_reader(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                            const double v[], tirenv_profile_file_reader **out,
                            tirenv_diag *diag);
/* The same on path, opened for this reader alone (freed with it). */
int tirenv_profile_file_reader_open(const char *path, const tirenv_profile_source *src,
                                    size_t n, const double v[],
                                    tirenv_profile_file_reader **out, tirenv_diag *diag);
/* The next row: *x and z[n] with *got = 1, or *got = 0 after the last. */
int tirenv_profile_file_reader_next(tirenv_profile_file_reader *r, double *x, double z[],
                                    int *got, tirenv_diag *diag);
/* tirenv_profile_file_reader_next in the form of a tirenv_row_source (stream.h). */
int tirenv_profile_file_reader_source(void *reader, double *x, double z[], int *got,
                                      tirenv_diag *diag);
/* The first and last x (m) of the road in f as a reader of n tracks at v reads it (the same
 * arguments as tirenv_road_file_reader), the ends of a sweep over it. every_row nonzero: every
 * row of every track read and checked, so that a bad row anywhere fails here. Zero: read
 * without the rows, which are then a reader's to read and check: a CSV's header, first row and
 * last row (found from the file's end; where it cannot be told so, every row); an OpenCRG
 * road's first and last u from its pass at open (which checks its rows, not the tracks'
 * heights), an RDF road's first and last x from its scan (which checks its rows and keeps
 * none), each kept by f and shared with its readers, so that neither is made again. Errors
 * name file, line and field. */
int tirenv_road_file_extent(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                            const double v[], int every_row, double *first, double *last,
                            tirenv_diag *diag);
/* The format the reader found. */
tirenv_profile_format tirenv_profile_file_reader_format(const tirenv_profile_file_reader *r);
void tirenv_profile_file_reader_free(tirenv_profile_file_reader *r);  /* NULL is a no-op */

/* Writes a profile as CSV: "x_m,z_m" and one row per vertex in the shortest form that reads
 * back to the same doubles; comment (NULL for none) first as '#' lines. All or nothing. */
int tirenv_profile_write_csv(const char *path, const tirenv_profile *p, const char *comment,
                             tirenv_diag *diag);

/* How tirenv_profile_write_file writes what the format leaves open. */
typedef struct {
    tirenv_crg_encoding crg_encoding;  /* default KDBI: binary doubles, exact */
    double crg_u_increment;            /* m; 0: the profile's own even spacing */
    double crg_half_width;             /* m: the profile is the long sections at -w and +w */
    const char *comment;               /* NULL for none */
} tirenv_profile_write_options;

/* KDBI, increment 0, half width 0.5 m, no comment. */
tirenv_profile_write_options tirenv_profile_write_default(void);

/* Writes p in the format path's extension names (o NULL: the defaults): CSV, an RDF
 * 'poly_line' road, or a CRG road whose width is uniform (two equal long sections at v =
 * -crg_half_width and +crg_half_width). A path written through without one ("-",
 * /dev/null, a FIFO: tirenv_outfile_path_is_through) gets CSV. */
int tirenv_profile_write_file(const char *path, const tirenv_profile *p,
                              const tirenv_profile_write_options *o, tirenv_diag *diag);

/* A road written a position at a time (tirenv envelope -o X.crg|X.rdf: the effective road,
 * docs/formats.md section 6): OpenCRG rows streamed to the file, an RDF poly_line kept (16
 * bytes a position) and written at the commit; all or nothing, as every output file. */
typedef struct {
    double x_from, dx;             /* the positions x_k = x_from + k*dx, m */
    size_t n;                      /* how many */
    double half_width;             /* .crg: long sections at v = v_track -+ half_width, m */
    double v_track;                /* .crg: the track's lateral position on the input road, m */
    double x_start, y_start;       /* .crg: the reference line at x_from in the x/y plane, m */
    double phi_start;              /* .crg: its heading, rad */
    double z_start;                /* .crg: the road's height at x_from on the track, m */
    tirenv_road_file *on_crg;      /* .crg: the open OpenCRG road (tirenv_road_file_open) the
                                    * positions run along, or NULL; open then takes x_start,
                                    * y_start, phi_start and z_start from it (its straight
                                    * reference line at u = x_from, its heading, its height on
                                    * the track v_track there). A curved road (a heading
                                    * channel) is refused: its effective road on a straight
                                    * line would lie beside it. */
    tirenv_crg_encoding encoding;  /* .crg */
    const char *comment;           /* what it is, lines of at most 72 characters (copied) */
} tirenv_road_writer_layout;

typedef struct tirenv_road_writer tirenv_road_writer;

/* Opens path in format f (TIRENV_PROFILE_CRG or _RDF) for the n positions of the layout into
 * *out (NULL on failure); a CRG needs n >= 2. */
int tirenv_road_writer_open(const char *path, tirenv_profile_format f,
                            const tirenv_road_writer_layout *l, tirenv_road_writer **out,
                            tirenv_diag *diag);
/* The next position's height h (m) at x (m), in order; more than n is TIRENV_EINVAL. */
int tirenv_road_writer_add(tirenv_road_writer *w, double x, double h, tirenv_diag *diag);
/* Checks that all n came and puts the file in place (all or nothing); frees w. */
int tirenv_road_writer_commit(tirenv_road_writer *w, tirenv_diag *diag);
/* Removes what was written and frees w; NULL is a no-op. */
void tirenv_road_writer_abort(tirenv_road_writer *w);

TIRENV_END_DECLS
#endif
