/* Private to the sweep (src/sweep/sweep_*.c): the grid's arithmetic, the split, the files'
 * names and the description a resumed run and a merge compare.
 * SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_DATA_SWEEP_IMPL_H
#define TIRENV_DATA_SWEEP_IMPL_H

#include <stdio.h>
#include "tirenv/sweep.h"

/* The most cases a sweep takes: a million, a curve file each in one directory (the
 * data-set reader takes as many, src/dataset/dataset_impl.h). 1e8 was accepted, and a run
 * stat-ed every case file (to resume) for minutes before writing the first. */
#define TIRENV_SWEEP__MAX_CASES 1000000u

/* The largest cases.csv or sweep.csv a merge or a finished run reads: 1 GiB, some thousand
 * bytes a row of the most cases. */
#define TIRENV_SWEEP__TABLE_MAX ((size_t)1 << 30)

/* Case i's place in the grid. */
typedef struct {
    size_t variant;          /* index of the tire-key values (mixed radix over the axes) */
    size_t key_index[TIRENV_SWEEP_MAX_KEYS]; /* each axis's value index */
    size_t regime;           /* index into contact_lengths or loads */
    size_t length, height;   /* indices into lengths, heights */
} tirenv_sweep__coords;

void tirenv_sweep__coords_of(const tirenv_sweep_settings *s, size_t i,
                             tirenv_sweep__coords *c);

/* Number of tire variants (product of the axes' value counts) and of regimes. */
size_t tirenv_sweep__variants(const tirenv_sweep_settings *s);
size_t tirenv_sweep__regimes(const tirenv_sweep_settings *s);

/* Case i's name into buf (at least 32 bytes): "c" and i, zero-padded to the width of the
 * grid's last index, at least 4 digits. */
void tirenv_sweep__case_name(const tirenv_sweep_settings *s, size_t i, char buf[32]);

/* The same for case i of a grid of m cases. */
void tirenv_sweep__name_of(size_t m, size_t i, char buf[32]);

/* The tire of variant v: tire with each axis's value applied by tirenv_tir_set. */
int tirenv_sweep__variant_tire(const tirenv_sweep_settings *s, const tirenv_tire *tire,
                               size_t v, tirenv_tire *out, tirenv_diag *diag);

/* The split of every case of the grid (n = tirenv_sweep_count entries), allocated. */
int tirenv_sweep__splits(const tirenv_sweep_settings *s, unsigned char **out,
                         tirenv_diag *diag);

/* The shortest of %.15g, %.16g, %.17g that reads back to the same double, into buf (32). */
void tirenv_sweep__number(double x, char buf[32]);

/* The sweep's description, sweep.txt: the grid and how its cases are made, one "key = value"
 * line each, and "shard = K/N" last in a shard of several. Allocated text (free it). */
char *tirenv_sweep__spec(const tirenv_sweep_settings *s);

/* The line "shard = K/N" of a description, if any: *shard, *shards and where the line
 * starts and ends (so that the rest can be compared); 0 if there is none, -1 if it is
 * malformed. */
int tirenv_sweep__spec_shard(const char *spec, size_t *shard, size_t *shards, size_t *begin,
                             size_t *end);

/* A table's text (len bytes, every line ending in '\n', else TIRENV_EPARSE naming path): the
 * lines that open it, the header and the comment lines around it, *head bytes; then its data
 * rows, each cut at its newline (in place), into *rows (allocated, n_rows of them). */
int tirenv_sweep__split_table(char *text, size_t len, const char *path, size_t *head,
                              char ***rows, size_t *n_rows, tirenv_diag *diag);

/* Whether the rows of dir/table (the first at line head_lines + 1) are those of shard K of N
 * (1 part: the whole sweep) of a sweep of m cases, row j case K + j N, named so; TIRENV_EPARSE
 * naming the file, the line and what is wrong otherwise. */
int tirenv_sweep__check_rows(const char *dir, const char *table, size_t head_lines,
                             char **rows, size_t n_rows, size_t m, size_t shard, size_t shards,
                             tirenv_diag *diag);

/* The log and curve fields (7 and 8) of a manifest row: 0, or -1 where the row does not name
 * them as a sweep writes them (logs/<case>.csv, empty without --rig; curves/<case>.csv). */
int tirenv_sweep__row_files(const char *row, const char **log, size_t *log_len,
                            const char **curve, size_t *curve_len);

/* The '\n' in the len bytes of text. */
size_t tirenv_sweep__lines(const char *text, size_t len);

/* The manifest's comment (the same in a shard as in the whole sweep). Allocated. */
char *tirenv_sweep__manifest_comment(const tirenv_sweep_settings *s, size_t cases);

/* The whole file at path (at most max bytes), NUL-terminated and allocated; its length in
 * *n. TIRENV_EIO naming the file if it cannot be read. */
int tirenv_sweep__read_text(const char *path, size_t max, char **out, size_t *n,
                            tirenv_diag *diag);

/* Writes len bytes of text to path atomically (tirenv_outfile). */
int tirenv_sweep__write_text(const char *path, const char *text, size_t len,
                             tirenv_diag *diag);

/* Whether a case's files are whole, as a run wrote them: the curve a CSV the curve reader
 * takes with the x_N grid's points, and the log (NULL: none) ending with its line's newline.
 * what says where the files came from, for the message ("kept from an interrupted run").
 * A file that is not is TIRENV_EPARSE naming it, the reason and what to do. */
int tirenv_sweep__check_case(const char *curve, const char *log, const char *what,
                             const char *remedy, tirenv_diag *diag);

/* The state of a sweep's target directory dir: 0 absent or empty (write it), 1 already this
 * sweep, complete (sweep.txt and tire.tir equal to spec and tire, cases.csv and sweep.csv
 * with the rows of shard K of N of its m cases), or minus an error status (anything else is
 * there, or a table cut or edited; diag says so). */
int tirenv_sweep__target_state(const char *dir, const char *spec, const char *tire,
                               size_t tire_len, size_t m, size_t shard, size_t shards,
                               tirenv_diag *diag);

#endif
