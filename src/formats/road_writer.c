/* SPDX-License-Identifier: Apache-2.0 */
/* A road written position by position (tirenv_road_writer, profile_file.h), as tirenv
 * envelope -o X.crg|X.rdf writes the effective road: an OpenCRG road with a straight reference
 * line where the input road's is (layout on_crg, place below), whose rows are the positions u
 * and whose long sections (the same height at v_track -+ half_width) carry it across the
 * tire's width, written row by row as they come; or a TNO/Adams poly_line road (x, z_left = z_right = h), written at the end from the
 * heights kept (16 bytes a position). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/crg_impl.h"
#include "formats/road_file_impl.h"
#include "tirenv/crg.h"
#include "tirenv/profile_file.h"
#include "tirenv/rdf.h"
#include "io/io.h"

struct tirenv_road_writer {
    tirenv_profile_format format;
    char path[1024];
    char *comment;
    size_t n, added;
    double x_from, dx;           /* m */
    tirenv_crg_writer *crg;
    double *x, *h;               /* .rdf: the road, kept until commit */
};

void tirenv_road_writer_abort(tirenv_road_writer *w)
{
    if (!w)
        return;
    tirenv_crg_writer_abort(w->crg);
    free(w->x);
    free(w->h);
    free(w->comment);
    free(w);
}

/* Where the effective road of the open OpenCRG road on, read at lateral position v, goes:
 * its straight reference line at u = l->x_from, its heading, its height on the track there
 * and v, into the layout. The road is the one its readers share (tirenv_road_file__crg), so
 * that it is not opened, and its rows checked, once more. */
static int place(tirenv_road_file *on, double v, tirenv_road_writer_layout *l,
                 tirenv_diag *diag)
{
    l->v_track = l->x_start = l->y_start = l->phi_start = l->z_start = 0;
    const char *path = tirenv_road_file_name(on);
    const tirenv_crg *crg = NULL;
    int status = tirenv_road_file__crg(on, &crg, diag);
    if (status)
        return status;
    if (tirenv_crg_is_curved(crg))
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "reference line phi",
                            "a curved reference line: tirenv writes an effective road on a "
                            "straight one, which would lie beside this road; write it as "
                            ".csv or .rdf (along u) instead");
    /* Straight: the reference line at any u from its first row and its one heading (the
     * first row as tirenv_crg_refline gives it, without the whole line). */
    double x0, y0, phi0;
    if (tirenv_crg__refline_rows(crg, 1, 0, 1, &x0, &y0, &phi0))
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "", "no reference line");
    /* The road's height on the track at the row at or before x_from: the written file's
     * reference height, so that its grid holds only the relief (OpenCRG keeps the grid in
     * single precision). */
    tirenv_crg_track_spec spec = tirenv_crg_track_default();
    spec.v = v;
    double u0, z0 = 0;
    status = tirenv_crg_track_rows(crg, &spec, tirenv_crg_row_at(crg, l->x_from), 1, &u0, &z0,
                                   diag);
    if (!status) {
        const double du = l->x_from - tirenv_crg_u_start(crg);
        l->z_start = z0;
        l->phi_start = phi0;
        l->x_start = x0 + cos(phi0) * du;
        l->y_start = y0 + sin(phi0) * du;
        l->v_track = v;
    }
    return status;
}

int tirenv_road_writer_open(const char *path, tirenv_profile_format f,
                            const tirenv_road_writer_layout *l, tirenv_road_writer **out,
                            tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    *out = NULL;
    tirenv_road_writer_layout placed;
    if (f == TIRENV_PROFILE_CRG && l->on_crg) {
        placed = *l;
        const int status = place(l->on_crg, l->v_track, &placed, diag);
        if (status)
            return status;
        l = &placed;
    }
    tirenv_road_writer *w = calloc(1, sizeof *w);
    const size_t len = l->comment ? strlen(l->comment) + 1 : 1;
    if (!w || !(w->comment = malloc(len))) {
        free(w);
        return tirenv_error(diag, TIRENV_ENOMEM, path, 0, "", "out of memory");
    }
    memcpy(w->comment, l->comment ? l->comment : "", len);
    snprintf(w->path, sizeof w->path, "%s", path);
    w->format = f;
    w->n = l->n;
    w->x_from = l->x_from;
    w->dx = l->dx;
    int status = TIRENV_OK;
    if (f == TIRENV_PROFILE_CRG) {
        if (l->n < 2)
            status = tirenv_error(diag, TIRENV_EINVAL, path, 0, "",
                                  "an OpenCRG road needs at least 2 positions, got %zu", l->n);
        const double v[2] = {l->v_track - l->half_width, l->v_track + l->half_width};
        const tirenv_crg_layout layout = {.encoding = l->encoding, .x_start = l->x_start,
                                          .y_start = l->y_start, .phi_start = l->phi_start,
                                          .z_start = l->z_start,
                                          .u_start = l->x_from,
                                          .u_increment = l->dx, .rows = l->n,
                                          .long_sections = 2, .v = v, .comment = w->comment};
        if (!status)
            status = tirenv_crg_writer_open(path, &layout, &w->crg, diag);
    } else if (!(w->x = malloc(l->n * sizeof *w->x)) || !(w->h = malloc(l->n * sizeof *w->h))) {
        status = tirenv_error(diag, TIRENV_ENOMEM, path, 0, "",
                              "out of memory for the %zu heights of the road", l->n);
    }
    if (status) {
        tirenv_road_writer_abort(w);
        return status;
    }
    *out = w;
    return TIRENV_OK;
}

int tirenv_road_writer_add(tirenv_road_writer *w, double x, double h, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    if (w->added == w->n)
        return tirenv_error(diag, TIRENV_EINVAL, w->path, 0, "",
                            "more than the %zu positions announced", w->n);
    int status = TIRENV_OK;
    if (w->crg) {
        const double z[2] = {h, h};
        status = tirenv_crg_writer_row(w->crg, z, diag);
    } else {
        w->x[w->added] = x;
        w->h[w->added] = h;
    }
    if (!status)
        w->added++;
    return status;
}

int tirenv_road_writer_commit(tirenv_road_writer *w, tirenv_diag *diag)
{
    TIRENV_NUMERIC_C();
    int status = TIRENV_OK;
    if (w->added != w->n) {
        status = tirenv_error(diag, TIRENV_EINVAL, w->path, 0, "",
                              "%zu positions of %zu written", w->added, w->n);
    } else if (w->crg) {
        tirenv_crg_writer *crg = w->crg;
        w->crg = NULL;  /* commit frees it, also on failure */
        status = tirenv_crg_writer_commit(crg, diag);
    } else {
        tirenv_profile *p = tirenv_profile_alloc(w->n, w->x, w->h);
        status = p ? tirenv_rdf_write(w->path, p, NULL, w->comment, diag)
                   : tirenv_error(diag, TIRENV_ENOMEM, w->path, 0, "", "out of memory");
        tirenv_profile_free(p);
    }
    tirenv_road_writer_abort(w);
    return status;
}
