/* The tracks of an open road file (tirenv_road_file) of any format, whole
 * (tirenv_road_file_read) or a row at a time (tirenv_road_file_reader), for the commands that
 * take --profile, the streamed sweeps, the FMU and the Python module; and the path-taking
 * forms, which open the file for one read. A CRG's tracks are read together, each block of
 * rows once for all of them; a CSV or RDF road is 2-D and gives every track the same heights.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/profile_file.h"

#include <stdlib.h>

#include "formats/crg_impl.h"
#include "formats/profile_csv_impl.h"
#include "formats/road_file_impl.h"
#include "io/io.h"

static tirenv_profile_source source_or_default(const tirenv_profile_source *src)
{
    return src ? *src : tirenv_profile_source_default();
}

static void free_all(tirenv_profile *out[], size_t n)
{
    for (size_t k = 0; k < n; ++k) {
        tirenv_profile_free(out[k]);
        out[k] = NULL;
    }
}

int tirenv_road_file_crg(tirenv_road_file *f, const tirenv_crg **out, tirenv_diag *diag)
{
    return tirenv_road_file__crg(f, out, diag);
}

/* One profile of a 2-D road (CSV or RDF). */
static int read_2d(tirenv_road_file *f, tirenv_rdf_side side, tirenv_profile **out,
                   tirenv_diag *diag)
{
    if (tirenv_road_file_format(f) == TIRENV_PROFILE_RDF)
        return tirenv_road_file__rdf_whole(f, side, out, diag);
    FILE *fp = tirenv_road_file__stream(f, diag);
    return fp ? tirenv_profile_csv__read(fp, tirenv_road_file_name(f), out, diag)
              : TIRENV_ENOMEM;
}

int tirenv_road_file_read(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                          const double v[], tirenv_profile *out[], tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    const char *path = tirenv_road_file_name(f);
    for (size_t k = 0; k < n; ++k)
        out[k] = NULL;
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "tracks",
                            "expected at least one track");
    tirenv_profile_source s = source_or_default(src);
    int status;
    if (tirenv_road_file_format(f) == TIRENV_PROFILE_CRG) {
        const tirenv_crg *crg;
        if ((status = tirenv_road_file__crg(f, &crg, diag)))
            return status;
        for (size_t k = 0; k < n && !status; ++k) {
            if (v)
                s.crg.v = v[k];
            status = tirenv_crg_track(crg, &s.crg, &out[k], diag);
        }
    } else {
        status = read_2d(f, s.rdf_side, &out[0], diag);
        for (size_t k = 1; k < n && !status; ++k)
            if (!(out[k] = tirenv_profile_alloc(tirenv_profile_size(out[0]),
                                                tirenv_profile_x(out[0]),
                                                tirenv_profile_z(out[0]))))
                status = tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    }
    if (status)
        free_all(out, n);
    return status;
}

int tirenv_profile_read_tracks(const char *path, const tirenv_profile_source *src, size_t n,
                               const double v[], tirenv_profile *out[], tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    for (size_t k = 0; k < n; ++k)
        out[k] = NULL;
    tirenv_road_file *f;
    int status = tirenv_road_file_open(path, &f, diag);
    if (!status)
        status = tirenv_road_file_read(f, src, n, v, out, diag);
    tirenv_road_file_free(f);
    return status;
}

int tirenv_profile_read_file(const char *path, const tirenv_profile_source *src,
                             tirenv_profile **out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_profile_read_tracks(path, src, 1, NULL, out, diag);
}

/* ---- a row at a time ------------------------------------------------------------------- */

/* An OpenCRG road's open handle and an RDF road's scan are the file's
 * (tirenv_road_file__crg, tirenv_road_file__rdf), shared by its readers: made once whatever
 * the number of readers and tirenv_road_file_extent's calls. Each reader then reads its rows
 * from a window of its own: an OpenCRG road a block of rows, an RDF road a line. */
struct tirenv_profile_file_reader {
    tirenv_profile_format format;
    size_t n;                         /* tracks */
    tirenv_road_file *owned;          /* the file, when the reader opened it itself */
    tirenv_profile_csv__reader *csv;  /* CSV: row by row */
    const tirenv_crg *crg;            /* CRG: the open file (the file's) and its tracks */
    tirenv_crg__tracks_reader *tracks;
    const tirenv_rdf__road *rdf;      /* RDF: the scanned road (the file's) */
    tirenv_rdf__rows *rows;           /* ... and its rows */
};

void tirenv_profile_file_reader_free(tirenv_profile_file_reader *r)
{
    if (!r)
        return;
    tirenv_profile_csv__reader_free(r->csv);
    tirenv_crg__tracks_reader_free(r->tracks);
    tirenv_rdf__rows_free(r->rows);
    tirenv_road_file_free(r->owned);
    free(r);
}

int tirenv_road_file_reader(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                            const double v[], tirenv_profile_file_reader **out,
                            tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    const char *path = tirenv_road_file_name(f);
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "tracks",
                            "expected at least one track");
    const tirenv_profile_source s = source_or_default(src);
    tirenv_profile_file_reader *r = calloc(1, sizeof *r);
    if (!r)
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    r->n = n;
    r->format = tirenv_road_file_format(f);
    int status = TIRENV_OK;
    switch (r->format) {
    case TIRENV_PROFILE_CSV: {
        FILE *fp = tirenv_road_file__stream(f, diag);
        status = fp ? tirenv_profile_csv__reader_open(fp, path, &r->csv, diag) : TIRENV_ENOMEM;
        break;
    }
    case TIRENV_PROFILE_RDF:
        if (!(status = tirenv_road_file__rdf(f, s.rdf_side, &r->rdf, diag)))
            status = tirenv_rdf__rows_open(r->rdf, s.rdf_side, &r->rows, diag);
        break;
    case TIRENV_PROFILE_CRG:
        if (!(status = tirenv_road_file__crg(f, &r->crg, diag)))
            status = tirenv_crg__tracks_reader_open(r->crg, &s.crg, n, v, &r->tracks, diag);
        break;
    }
    if (status) {
        tirenv_profile_file_reader_free(r);
        return status;
    }
    *out = r;
    return TIRENV_OK;
}

int tirenv_profile_file_reader_open(const char *path, const tirenv_profile_source *src,
                                    size_t n, const double v[],
                                    tirenv_profile_file_reader **out, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    tirenv_road_file *f;
    int status = tirenv_road_file_open(path, &f, diag);
    if (!status && !(status = tirenv_road_file_reader(f, src, n, v, out, diag)))
        (*out)->owned = f;
    else
        tirenv_road_file_free(f);
    return status;
}

/* Every row of a reader of f: its first and last x, each row checked. */
static int extent_read(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                       const double v[], double *first, double *last, tirenv_diag *diag)
{
    tirenv_profile_file_reader *r;
    int status = tirenv_road_file_reader(f, src, n, v, &r, diag);
    double *z = status ? NULL : malloc(n * sizeof *z);
    if (!status && !z)
        status = tirenv_error(diag, TIRENV_ENOMEM, tirenv_road_file_name(f), 0, "",
                              "out of memory");
    for (int got = 1, k = 0; !status && got; k = 1) {
        double x;
        status = tirenv_profile_file_reader_next(r, &x, z, &got, diag);
        if (!status && got) {
            if (!k)
                *first = x;
            *last = x;
        }
    }
    free(z);
    tirenv_profile_file_reader_free(r);
    return status;
}

/* The ends of an OpenCRG or RDF road without its rows: a reader's, opened (which checks the
 * tracks' positions against the road) and not read. The OpenCRG road's first and last u are
 * its rows' as the reader gives them (u0 + i du, i = 0 and nu - 1: tirenv_crg_u_end's
 * product), the RDF road's its poly_line's first and last x as its scan found them, both from
 * what the readers of f share (tirenv_road_file__crg, __rdf), so that the rows are read once
 * more, by the reader that follows. */
static int extent_ends(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                       const double v[], double *first, double *last, tirenv_diag *diag)
{
    tirenv_profile_file_reader *r;
    const int status = tirenv_road_file_reader(f, src, n, v, &r, diag);
    if (status)
        return status;
    if (r->format == TIRENV_PROFILE_CRG) {
        *first = tirenv_crg_u_start(r->crg);
        *last = tirenv_crg_u_end(r->crg);
    } else {
        tirenv_rdf__extent(r->rdf, first, last);
    }
    tirenv_profile_file_reader_free(r);
    return TIRENV_OK;
}

/* A CSV's first row comes from a reader (which checks the header and the row), its last from
 * the file's end (tirenv_profile_csv__last_x); where the last cannot be told so, lies before
 * the first (an x decreases somewhere) or beyond the coordinates a road may have (the rows'
 * check, which the tail's parse does not make: 1e308 became a sweep of too many positions, a
 * misuse naming no file), every row is read, and the first bad one named. An OpenCRG or RDF
 * road's come from what its readers share (extent_ends). */
int tirenv_road_file_extent(tirenv_road_file *f, const tirenv_profile_source *src, size_t n,
                            const double v[], int every_row, double *first, double *last,
                            tirenv_diag *diag)
{
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, tirenv_road_file_name(f), 0, "tracks",
                            "expected at least one track");
    if (every_row)
        return extent_read(f, src, n, v, first, last, diag);
    if (tirenv_road_file_format(f) != TIRENV_PROFILE_CSV)
        return extent_ends(f, src, n, v, first, last, diag);
    FILE *fp = tirenv_road_file__stream(f, diag);
    tirenv_profile_csv__reader *r = NULL;
    int status = fp ? tirenv_profile_csv__reader_open(fp, tirenv_road_file_name(f), &r, diag)
                    : TIRENV_ENOMEM;
    int got = 0;
    double z;
    if (!status)
        status = tirenv_profile_csv__reader_next(r, first, &z, &got, diag);
    tirenv_profile_csv__reader_free(r);
    if (status)
        return status;
    const tirenv_source *s;
    if ((status = tirenv_road_file__source(f, &s, diag)))
        return status;
    if (tirenv_profile_csv__last_x(s, last) && *last >= *first &&
        *last <= TIRENV_PROFILE_MAX_COORDINATE)
        return TIRENV_OK;
    return extent_read(f, src, n, v, first, last, diag);
}

int tirenv_profile_file_reader_next(tirenv_profile_file_reader *r, double *x, double z[],
                                    int *got, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *got = 0;
    int status = TIRENV_OK;
    switch (r->format) {
    case TIRENV_PROFILE_CRG:
        return tirenv_crg__tracks_reader_next(r->tracks, x, z, got, diag);
    case TIRENV_PROFILE_CSV:
        status = tirenv_profile_csv__reader_next(r->csv, x, &z[0], got, diag);
        break;
    case TIRENV_PROFILE_RDF:
        status = tirenv_rdf__rows_next(r->rows, x, &z[0], got, diag);
        break;
    }
    for (size_t k = 1; *got && k < r->n; ++k)
        z[k] = z[0];
    return status;
}

int tirenv_profile_file_reader_source(void *reader, double *x, double z[], int *got,
                                      tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    return tirenv_profile_file_reader_next(reader, x, z, got, diag);
}

tirenv_profile_format tirenv_profile_file_reader_format(const tirenv_profile_file_reader *r)
{
    return r->format;
}
