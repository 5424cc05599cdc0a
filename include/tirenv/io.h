/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: file formats (the convenience layer): .tir tire property files, profile CSV,
 * and all-or-nothing output files. */
#ifndef TIRENV_IO_H
#define TIRENV_IO_H

#include "tirenv/decls.h"
#include <stdio.h>
#include "tirenv/error.h"
#include "tirenv/profile.h"
#include "tirenv/tire.h"

TIRENV_BEGIN_DECLS

/* Reads a .tir file (sections in brackets, KEY = value, '$' comments, [UNITS] in SI) into
 * *tire, overriding only the keys present. Keys this library knows (see data/tires/default.tir)
 * are checked; sections it does not know are skipped so that MF-Tyre files load unchanged.
 * Errors name file, line and key. On failure *tire is unchanged. */
int tirenv_tir_read(const char *path, tirenv_tire *tire, tirenv_diag *diag);

/* Applies one "KEY=VALUE" override (KEY as in the .tir file, e.g. RADIAL_STIFFNESS=1.6e6),
 * as the --set option does. On failure *tire is unchanged. */
int tirenv_tir_set(tirenv_tire *tire, const char *assignment, tirenv_diag *diag);

/* Writes *tire as a .tir file (atomically: all or nothing). */
int tirenv_tir_write(const char *path, const tirenv_tire *tire, tirenv_diag *diag);

/* What a tire key holds: a real number (SI), a count, or a name (METHOD). */
typedef enum { TIRENV_TIR_REAL, TIRENV_TIR_COUNT, TIRENV_TIR_NAME } tirenv_tir_kind;

/* The keys tirenv_tir_set and tirenv_tir_get take, in the order a .tir file is written: the
 * i-th key's name (and, if section is not NULL, its [SECTION]); NULL past the last. Static
 * strings. */
const char *tirenv_tir_key(size_t i, const char **section);

/* The value of key ("KEY" or "SECTION.KEY", as tirenv_tir_set takes it) in *tire as text into
 * buf (n bytes, 64 always suffice), exactly as tirenv_tir_write writes it: the shortest text
 * that reads back to the same double (SI units), a count, or a name unquoted; *kind (if not
 * NULL) says which. An unknown key is TIRENV_EINVAL with the known keys in the message. */
int tirenv_tir_get(const tirenv_tire *tire, const char *key, char *buf, size_t n,
                   tirenv_tir_kind *kind, tirenv_diag *diag);

/* The models of a tire file that tirenv_tir_derive may derive (docs/models.md section 14). */
enum {
    TIRENV_TIR_SPRINGS = 1u << 0, /* [ENVELOPING_SPRINGS]: c_r and c_b */
    TIRENV_TIR_RING = 1u << 1     /* [ENVELOPING_RING]: t_r, EI, T, k_f, k_t */
};

/* What a tire file says of its own tire besides tirenv's keys, and what tirenv_tir_derive
 * made of it. */
typedef struct {
    double fnomin;         /* [VERTICAL] FNOMIN: nominal load, N; 0 if the file has none */
    double rho_nominal;    /* the file's deflection at FNOMIN and INFLPRES, m; 0 if unknown */
    unsigned own;          /* TIRENV_TIR_* of the enveloping sections the file has */
    unsigned derived;      /* TIRENV_TIR_* of the models derived from its MF-Tyre keys */
    char note[1024];       /* which values were derived from which keys, or why a model
                            * could not be; "" when the file has every section */
} tirenv_tir_origin;

/* After tirenv_tir_read(path, tire): for each enveloping model whose section the file lacks,
 * derives its parameters from the file's MF-Tyre keys (UNLOADED_RADIUS, FNOMIN,
 * VERTICAL_STIFFNESS, PFZ1/INFLPRES/NOMPRES, Q_FZ1/Q_FZ2, RIM_RADIUS or WIDTH and
 * ASPECT_RATIO) so that its flat-ground deflection at FNOMIN is the file's, and says so in
 * origin->note. need (TIRENV_TIR_* bits): the models that must describe this tire; one that
 * can be neither read nor derived is TIRENV_EINVAL naming the missing key, where the others
 * keep *tire's values with a note. On failure *tire is unchanged. */
int tirenv_tir_derive(const char *path, tirenv_tire *tire, unsigned need,
                      tirenv_tir_origin *origin, tirenv_diag *diag);

/* One key of a .tir file to set by tirenv_tir_update. */
typedef struct {
    const char *section;   /* e.g. "ENVELOPING_SPRINGS" */
    const char *key;       /* e.g. "RADIAL_STIFFNESS" */
    double value;          /* SI; written with 6 significant digits */
} tirenv_tir_value;

/* Sets the n values[] in the .tir file at path in place, keeping every other line, comment
 * and column (the file must state its [UNITS] in SI or not at all: its values are not
 * converted): a key present has its value replaced, a missing one is added after its
 * section's header, a missing section at the end. note (lines separated by '\n') replaces
 * the '!' block between "! tirenv identify: begin" and "! tirenv identify: end" lines, or
 * is added with them after the [MDI_HEADER] keys. The file is replaced atomically (or not
 * at all) and must then read back with tirenv_tir_read. */
int tirenv_tir_update(const char *path, size_t n, const tirenv_tir_value values[],
                      const char *note, tirenv_diag *diag);

/* Reads a profile CSV: header "x_m,z_m", one vertex per line, '#' comment lines and blank
 * lines allowed. Errors name file, line and column. *out is NULL on failure. */
int tirenv_profile_read_csv(const char *path, tirenv_profile **out, tirenv_diag *diag);

/* A profile CSV ("x_m,z_m", as tirenv_profile_read_csv) read one vertex at a time, for
 * tirenv_model_stream (stream.h) over a road longer than memory. */
typedef struct tirenv_profile_reader tirenv_profile_reader;

/* Opens path and checks its header; *out is NULL on failure (diag names file and line). */
int tirenv_profile_reader_open(const char *path, tirenv_profile_reader **out,
                               tirenv_diag *diag);

/* The next vertex (m) in *x, *z with *got = 1, or *got = 0 at the end of the file. Applies
 * the checks of tirenv_profile_read_csv (numbers, x non-decreasing, at most two vertices at
 * one x, at least one row) and names file, line and column on failure. */
int tirenv_profile_reader_next(tirenv_profile_reader *r, double *x, double *z, int *got,
                               tirenv_diag *diag);

/* Closes the file; NULL is a no-op. */
void tirenv_profile_reader_free(tirenv_profile_reader *r);

/* tirenv_profile_reader_next in the form of a tirenv_vertex_source (stream.h): ctx is the
 * reader. */
int tirenv_profile_reader_source(void *reader, double *x, double *z, int *got,
                                 tirenv_diag *diag);

/* An output file, complete or not at all. Where path names a regular file (or nothing yet),
 * the data go to a temporary file beside it, ".<name>.tirenv-tmp.<host>.<pid>.<random>",
 * renamed over it on commit: a reader never sees half a file, a failure leaves the old one.
 * A symbolic link is followed and its target replaced (the link stays a link). What cannot
 * be replaced is written through instead, never renamed over: "-" and names of this
 * process's descriptors (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N) write to
 * that descriptor; a character device (/dev/null, a terminal) or a FIFO is opened and
 * written (a FIFO waits for its reader); there a failure midway may leave part of the data.
 * A block device, a socket or a directory is refused. The temporary file is removed on
 * failure, by tirenv_cleanup_on_signal on SIGINT/SIGTERM, and, after a SIGKILL, by the next
 * output opened in the same directory once the killed process is gone. */
typedef struct {
    FILE *fp;              /* write here between open and commit */
    char path[1024];       /* the path as given, for messages */
    /* private: */
    char target[4096];     /* what commit replaces: path with its symbolic links followed */
    char tmp[4096];        /* the temporary file, or "" when written through */
    int through;           /* 1: written straight to the target or descriptor */
    int slot;              /* registration for tirenv_cleanup_on_signal, or -1 */
    char *buf;             /* stdio buffer of a temporary file */
} tirenv_outfile;

/* Opens the output (see above); path "-" writes to stdout. */
int tirenv_outfile_open(tirenv_outfile *f, const char *path, tirenv_diag *diag);
/* Flushes, checks every write, closes and renames into place; on any error removes the
 * temporary file. */
int tirenv_outfile_commit(tirenv_outfile *f, tirenv_diag *diag);
/* 1 if nothing reaches the target before commit (a temporary file), 0 when written through:
 * a writer that could fail midway may then want to compute everything first. */
int tirenv_outfile_is_atomic(const tirenv_outfile *f);
/* 1 if tirenv_outfile_open would write PATH through rather than replace it: "-", a
 * descriptor's name (/dev/stdout, /dev/fd/N, /proc/self/fd/N), or what exists there, links
 * followed, as a character device (/dev/null, a terminal) or a FIFO; 0 otherwise (a regular
 * file, a name not yet taken, or what opening refuses). A writer that picks its format by
 * the name's extension writes CSV to such a path when the name has none, as it does to "-". */
int tirenv_outfile_path_is_through(const char *path);
/* Creates a directory and its missing parents (mkdir -p); an existing one is fine. */
int tirenv_mkdir_p(const char *path, tirenv_diag *diag);

/* Removes the temporary files and staging directories of every output this process has
 * open (tirenv_outfile, tirenv_outdir), after waiting (at most 0.2 s) for other threads
 * creating one; from then on the process creates none (opening an output fails with
 * TIRENV_EIO), so a thread still running cannot leave one behind. Async-signal-safe: for a
 * SIGINT or SIGTERM handler, which then re-raises the signal (the tirenv command installs
 * one); a process that carries on afterwards writes no more outputs. */
void tirenv_cleanup_on_signal(void);

/* An output directory written as a whole (tirenv study -o, compare -o, ride --out-dir,
 * dataset build -o): the run writes into a staging directory beside the target, which
 * commit moves into place at once (on Linux an atomic exchange, renameat2 RENAME_EXCHANGE),
 * then removes the old one. A killed or failed run leaves the old directory as it was; a
 * completed one leaves the new one whole, never a mixture. Files of the old directory that
 * the run does not write are kept: begin carries them into the staging directory as hard
 * links (copies where a link is refused), so the run's files replace theirs all at once.
 * A symbolic link to a directory is followed (the link stays). */
typedef struct tirenv_outdir tirenv_outdir;

/* Starts writing target (created with its missing parents if need be; an existing one must
 * be a directory of at most 100,000 entries, all on its file system, without devices,
 * FIFOs or sockets). *out is NULL on failure. */
int tirenv_outdir_begin(const char *target, tirenv_outdir **out, tirenv_diag *diag);
/* Where to write: the staging directory. */
const char *tirenv_outdir_path(const tirenv_outdir *d);
/* Moves the staging directory into place and frees d (also on failure, after which the old
 * directory is unchanged and the staging one removed). */
int tirenv_outdir_commit(tirenv_outdir *d, tirenv_diag *diag);
/* Removes the staging directory (and the parents begin created, if empty) and frees d; the
 * target is left as it was. NULL is a no-op. */
void tirenv_outdir_abort(tirenv_outdir *d);

/* Room for any number tirenv_fmt_g writes, with its NUL ("-1.2345678901234567e-308"). */
#define TIRENV_FMT_G_SIZE 32

/* Writes x into buf exactly as snprintf(buf, TIRENV_FMT_G_SIZE, "%.*g", precision, x) does
 * (the same bytes, ties rounded as glibc rounds them, "-0", "inf", "-nan") and returns the
 * length; precision 1 to 17 (otherwise writes "" and returns 0). buf must have
 * TIRENV_FMT_G_SIZE bytes, all of which may be written (what follows the NUL is scratch).
 * Several times faster than printf: exact integer arithmetic with a proven error bound, and
 * snprintf only in the rare cases the bound cannot decide. For CSV rows in a buffer with
 * that much room left before each number: p += tirenv_fmt_g(v, 9, p). */
size_t tirenv_fmt_g(double x, int precision, char *buf);

/* Writes into buf (TIRENV_FMT_G_SIZE bytes, all of which may be written) the shortest text
 * that strtod reads back to exactly x, and returns its length: the shortest "%.*g", or plain
 * decimals where they are at most 4 characters longer (0.1, -10000, 250.2 rather than
 * -1e+04; 1e-07, 6.02e+23 stay). Never longer than "%.17g"; -0 keeps its sign; inf and nan
 * are written as "%g" writes them (a nan reads back as a nan, not its bits). */
size_t tirenv_fmt_shortest(double x, char *buf);

/* Writes text as '#' comment lines ("# " before each line of it); NULL writes nothing. */
void tirenv_outfile_comment(tirenv_outfile *f, const char *text);
/* Closes and removes the temporary file (after a failure); safe to call twice. */
void tirenv_outfile_abort(tirenv_outfile *f);

TIRENV_END_DECLS
#endif
