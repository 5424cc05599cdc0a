/* SPDX-License-Identifier: Apache-2.0 */
/* Private: the road window's fields (road_window.c), which the serial stream (stream.c) reads
 * beyond the public API: where the window sits in the road for the network
 * (tirenv_model__stream_window) and the counts of its statistics. */
#ifndef TIRENV_ROAD_WINDOW_IMPL_H
#define TIRENV_ROAD_WINDOW_IMPL_H

#include <stddef.h>

#include "tirenv/stream.h"

struct tirenv_road_window {
    tirenv_row_source next;
    void *ctx;
    size_t tracks;         /* heights per row */
    double *row;           /* [tracks]: one row as the source gives it, m */
    double *x;             /* [cap]: the rows held, m */
    double **z;            /* z[k][i]: track k's height at x[i], m */
    size_t n, cap;
    int bof;               /* x[0] is the source's first row */
    int eof;               /* the source's last row has been read */
    size_t read;           /* rows read from the source */
    size_t max;            /* largest n so far */
    double x_last;         /* the last row taken, m */
    double x_first;        /* the source's first row, m */
    size_t same_x;         /* rows taken at x_last */
    double keep;           /* the last fill's x_keep, m (-INFINITY before any) */
};

#endif
