/* Private to the OpenCRG reader: the open file's parsed header and where its rows are, shared
 * by the header parser (crg_header.c), the row reader (crg_rows.c) and the evaluation of
 * tracks (crg.c). SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_CRG_IMPL_H
#define TIRENV_CRG_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "io/io.h"
#include "tirenv/crg.h"

/* No such channel. */
#define TIRENV_CRG__NONE SIZE_MAX

/* Text data: the file position of every TIRENV_CRG__CHECKPOINT-th row, so that a window of
 * rows is found without parsing the rows before it. */
#define TIRENV_CRG__CHECKPOINT 1024

/* The keys of $ROAD_CRG (the specification's table, in its order). */
enum {
    CRG_RL_START_U, CRG_RL_END_U, CRG_RL_INCREMENT,
    CRG_LS_V_RIGHT, CRG_LS_V_LEFT, CRG_LS_V_INCREMENT,
    CRG_RL_START_S, CRG_RL_END_S, CRG_RL_START_B, CRG_RL_END_B,
    CRG_RL_START_X, CRG_RL_START_Y, CRG_RL_END_X, CRG_RL_END_Y,
    CRG_RL_OFFSET_X, CRG_RL_OFFSET_Y,
    CRG_RL_START_PHI, CRG_RL_END_PHI, CRG_RL_OFFSET_PHI,
    CRG_RL_START_Z, CRG_RL_END_Z, CRG_RL_OFFSET_Z,
    CRG_RL_START_LON, CRG_RL_START_LAT, CRG_RL_END_LON, CRG_RL_END_LAT,
    CRG_RL_START_ALT, CRG_RL_END_ALT,
    CRG_ROAD_KEYS
};

/* The keys of $ROAD_CRG_OPTS that tirenv applies; every other option of the specification is
 * accepted and has no effect on a track (see crg_header.c). */
enum {
    CRG_OPT_BORDER_MODE_V, CRG_OPT_BORDER_OFFSET_V,
    CRG_OPT_BORDER_SMOOTH_UBEG, CRG_OPT_BORDER_SMOOTH_UEND,
    CRG_OPTS_USED
};

/* The keys of $ROAD_CRG_MODS that tirenv applies; the others are refused. */
enum {
    CRG_MOD_GRID_NAN_MODE, CRG_MOD_GRID_NAN_OFFSET, CRG_MOD_SCALE_Z_GRID,
    CRG_MOD_REFLINE_ROTCENTER_X, CRG_MOD_REFLINE_ROTCENTER_Y, CRG_MOD_REFLINE_OFFSET_PHI,
    CRG_MOD_REFLINE_OFFSET_X, CRG_MOD_REFLINE_OFFSET_Y, CRG_MOD_REFLINE_OFFSET_Z,
    CRG_MOD_REFPOINT_U, CRG_MOD_REFPOINT_U_FRACTION, CRG_MOD_REFPOINT_U_OFFSET,
    CRG_MOD_REFPOINT_V, CRG_MOD_REFPOINT_V_FRACTION, CRG_MOD_REFPOINT_V_OFFSET,
    CRG_MOD_REFPOINT_X, CRG_MOD_REFPOINT_Y, CRG_MOD_REFPOINT_Z, CRG_MOD_REFPOINT_PHI,
    CRG_MODS_USED
};

/* A key's value and the line that set it (0: not set). */
typedef struct {
    double value;
    size_t line;
} tirenv_crg__value;

struct tirenv_crg {
    tirenv_source src;
    tirenv_crg_encoding enc;
    size_t header_lines;      /* lines up to and including the $$$$ line */
    size_t data_offset;       /* byte offset of the road data */

    tirenv_crg__value road[CRG_ROAD_KEYS];
    tirenv_crg__value opts[CRG_OPTS_USED];
    tirenv_crg__value mods[CRG_MODS_USED];
    int has_mods;             /* a $ROAD_CRG_MODS section was present; without one OpenCRG's
                               * default modifiers apply: GRID_NAN_MODE 2 and REFPOINT_X, _Y,
                               * _Z, _PHI = 0 (crg_place.c) */

    /* The placement by reference point (REFPOINT_*, given or OpenCRG's defaults): the line
     * is turned by rp_rot about the reference point (rp_from_x, rp_from_y) as the header
     * places it, then moved so that that point lies at (rp_x, rp_y); heights move by the
     * difference between REFPOINT_Z and the road's height there (in z_offset). */
    int refpoint;
    double rp_from_x, rp_from_y; /* m */
    double rp_rot;               /* rad */
    double rp_x, rp_y;           /* m */

    /* Channels: columns of a data row. */
    size_t nch;
    size_t ch_phi, ch_slope, ch_bank;  /* column, or TIRENV_CRG__NONE */
    size_t kd_line_phi, kd_line_slope, kd_line_bank; /* their D: lines */
    size_t nv;                /* long sections */
    size_t *ch_z;             /* column of long section j */
    size_t *kd_line_z;        /* its D: line */
    double *v;                /* its lateral position, ascending, m */
    int v_numbered;           /* long sections numbered (else at given v) */

    /* Rows. */
    size_t nu;
    double u0, du;            /* u of row i = u0 + i*du, m */
    size_t values_per_record; /* 20/10 binary, 8/4 text */
    size_t value_size;        /* binary: 4 or 8 bytes */
    size_t records_per_row;   /* text */
    size_t *ckpt_off;         /* text: byte offset of row k*CHECKPOINT */
    size_t *ckpt_line;        /* and its line */

    /* The reference line's height at each row when it has a slope channel (else z0 + (u - u0)
     * * s0), m; its banking when it has no banking channel. */
    double *rz;
    double z0, s0, b0;
    double z_offset;          /* REFERENCE_LINE_OFFSET_Z + REFLINE_OFFSET_Z, or the shift of
                               * the placement by reference point, m */
};

/* Parses the header from the start of c->src: sections, keys, channels, the end of header;
 * fills everything above the rows. */
int tirenv_crg__parse_header(tirenv_crg *c, tirenv_diag *diag);

/* tirenv_crg_open on a source another owns (an open road file's, tirenv_road_file), which
 * must outlive the handle. */
int tirenv_crg__open_source(const tirenv_source *from, tirenv_crg **out, tirenv_diag *diag);

/* Works out the row count from the data block, checks every row once and fills the rows part
 * (count, checkpoints, rz). Needs the header. */
int tirenv_crg__scan(tirenv_crg *c, tirenv_diag *diag);

/* TIRENV_OK where rows first to first + count - 1 are in the file, else TIRENV_EINVAL naming
 * them (count 0 at the end is in it). */
int tirenv_crg__rows_asked(const tirenv_crg *c, size_t first, size_t count, tirenv_diag *diag);

/* The raw values of count rows from row first, nch per row, into vals (NaN where missing). */
int tirenv_crg__read_rows(const tirenv_crg *c, size_t first, size_t count, double vals[],
                          tirenv_diag *diag);

/* OpenCRG's placement by reference point (crg_place.c), once the rows are scanned: works out
 * the rp_* fields and the height shift from REFPOINT_* or OpenCRG's defaults. */
int tirenv_crg__place(tirenv_crg *c, tirenv_diag *diag);

/* The reference line as tirenv_crg_refline gives it, without (refpoint 0) or with (1) the
 * placement by reference point. */
int tirenv_crg__refline(const tirenv_crg *c, int refpoint, double x[], double y[],
                        double phi[], tirenv_diag *diag);

/* Rows first .. first + count - 1 of a straight reference line (no heading channel) as
 * tirenv_crg__refline gives them, without the whole line: TIRENV_EINVAL for a curved one. */
int tirenv_crg__refline_rows(const tirenv_crg *c, int refpoint, size_t first, size_t count,
                             double x[], double y[], double phi[]);

/* The GRID_NAN_MODE in effect when a track asks for the file's: the file's, else OpenCRG's
 * default 2 without a $ROAD_CRG_MODS section, else 0. */
int tirenv_crg__nan_mode(const tirenv_crg *c);

/* The name a message gives channel col ("long section 3 (v = -0.5 m)", "slope"). */
const char *tirenv_crg__channel_name(const tirenv_crg *c, size_t col, char *buf, size_t n);

/* Several tracks of one file read together, a block of rows at a time (crg.c), for the
 * profile-file reader of any format (profile_reader.c): tracks at v[n] (v NULL: spec->v), the
 * rest of spec for each; the rows as tirenv_crg_track_reader gives them, with n heights. */
typedef struct tirenv_crg__tracks_reader tirenv_crg__tracks_reader;
int tirenv_crg__tracks_reader_open(const tirenv_crg *c, const tirenv_crg_track_spec *spec,
                                   size_t n, const double v[],
                                   tirenv_crg__tracks_reader **out, tirenv_diag *diag);
int tirenv_crg__tracks_reader_next(tirenv_crg__tracks_reader *r, double *u, double z[],
                                   int *got, tirenv_diag *diag);
void tirenv_crg__tracks_reader_free(tirenv_crg__tracks_reader *r);

#endif
