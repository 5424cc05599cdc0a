/* The tracks of a road file of any format, whole (tirenv_profile_read_tracks) or a row at a
 * time (tirenv_profile_file_reader), for the commands that take --profile and the streamed
 * sweeps. A CRG's tracks are read together, each block of rows once for all of them; a CSV
 * or RDF road is 2-D and gives every track the same heights.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/profile_file.h"

#include <stdlib.h>

#include "formats/crg_impl.h"
#include "formats/profile_csv_impl.h"
#include "tirenv/profile_csv.h"

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

int tirenv_profile_read_tracks(const char *path, const tirenv_profile_source *src, size_t n,
                               const double v[], tirenv_profile *out[], tirenv_diag *diag)
{
    for (size_t k = 0; k < n; ++k)
        out[k] = NULL;
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "tracks",
                            "expected at least one track");
    tirenv_profile_source s = source_or_default(src);
    tirenv_profile_format f;
    int status = tirenv_profile_detect(path, &f, diag);
    if (status)
        return status;
    if (f == TIRENV_PROFILE_CRG) {
        tirenv_crg *crg;
        if ((status = tirenv_crg_open(path, &crg, diag)))
            return status;
        for (size_t k = 0; k < n && !status; ++k) {
            if (v)
                s.crg.v = v[k];
            status = tirenv_crg_track(crg, &s.crg, &out[k], diag);
        }
        tirenv_crg_free(crg);
    } else {
        status = f == TIRENV_PROFILE_RDF ? tirenv_rdf_read(path, s.rdf_side, &out[0], diag)
                                         : tirenv_profile_read_csv(path, &out[0], diag);
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

struct tirenv_profile_file_reader {
    tirenv_profile_format format;
    size_t n;                         /* tracks */
    tirenv_profile_csv__reader *csv;  /* CSV: row by row */
    tirenv_crg *crg;                  /* CRG: the open file and its tracks */
    tirenv_crg__tracks_reader *tracks;
    tirenv_profile *rdf;              /* RDF: the whole road */
    size_t next;                      /* RDF: the vertex next returns */
};

void tirenv_profile_file_reader_free(tirenv_profile_file_reader *r)
{
    if (!r)
        return;
    tirenv_profile_csv__reader_free(r->csv);
    tirenv_crg__tracks_reader_free(r->tracks);
    tirenv_crg_free(r->crg);
    tirenv_profile_free(r->rdf);
    free(r);
}

int tirenv_profile_file_reader_open(const char *path, const tirenv_profile_source *src,
                                    size_t n, const double v[],
                                    tirenv_profile_file_reader **out, tirenv_diag *diag)
{
    *out = NULL;
    if (n == 0)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "tracks",
                            "expected at least one track");
    const tirenv_profile_source s = source_or_default(src);
    tirenv_profile_file_reader *r = calloc(1, sizeof *r);
    if (!r)
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    r->n = n;
    int status = tirenv_profile_detect(path, &r->format, diag);
    if (!status) {
        switch (r->format) {
        case TIRENV_PROFILE_CSV:
            status = tirenv_profile_csv__reader_open(path, &r->csv, diag);
            break;
        case TIRENV_PROFILE_RDF:
            status = tirenv_rdf_read(path, s.rdf_side, &r->rdf, diag);
            break;
        case TIRENV_PROFILE_CRG:
            if (!(status = tirenv_crg_open(path, &r->crg, diag)))
                status = tirenv_crg__tracks_reader_open(r->crg, &s.crg, n, v, &r->tracks, diag);
            break;
        }
    }
    if (status) {
        tirenv_profile_file_reader_free(r);
        return status;
    }
    *out = r;
    return TIRENV_OK;
}

int tirenv_profile_file_reader_next(tirenv_profile_file_reader *r, double *x, double z[],
                                    int *got, tirenv_diag *diag)
{
    *got = 0;
    int status = TIRENV_OK;
    switch (r->format) {
    case TIRENV_PROFILE_CRG:
        return tirenv_crg__tracks_reader_next(r->tracks, x, z, got, diag);
    case TIRENV_PROFILE_CSV:
        status = tirenv_profile_csv__reader_next(r->csv, x, &z[0], got, diag);
        break;
    case TIRENV_PROFILE_RDF:
        if (r->next < tirenv_profile_size(r->rdf)) {
            *x = tirenv_profile_x(r->rdf)[r->next];
            z[0] = tirenv_profile_z(r->rdf)[r->next];
            r->next++;
            *got = 1;
        }
        break;
    }
    for (size_t k = 1; *got && k < r->n; ++k)
        z[k] = z[0];
    return status;
}

int tirenv_profile_file_reader_source(void *reader, double *x, double z[], int *got,
                                      tirenv_diag *diag)
{
    return tirenv_profile_file_reader_next(reader, x, z, got, diag);
}

tirenv_profile_format tirenv_profile_file_reader_format(const tirenv_profile_file_reader *r)
{
    return r->format;
}
