/* SPDX-License-Identifier: Apache-2.0 */
/* tirenv: output files and directories, complete or not at all (docs/formats.md section 1). */
#ifndef TIRENV_OUTFILE_H
#define TIRENV_OUTFILE_H

#include "tirenv/decls.h"
#include <stdio.h>
#include "tirenv/error.h"

TIRENV_BEGIN_DECLS

/* An output file, complete or not at all. Where path names a regular file (or nothing yet),
 * the data go to a temporary file beside it, ".<name>.tirenv-tmp.<host>.<pid>.<random>",
 * renamed over it on commit: a reader never sees half a file, a failure leaves the old one.
 * A symbolic link is followed and its target replaced (the link stays a link). What cannot
 * be replaced is written through instead, never renamed over: "-" and names of this
 * process's descriptors (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N) write to
 * that descriptor; a character device (/dev/null, a terminal) or a FIFO is opened and
 * written (a FIFO waits for its reader); there a failure midway may leave part of the data.
 * A block device, a socket or a directory is refused. The temporary file is removed on
 * failure, by tirenv_cleanup_on_signal on a signal (the tirenv command's SIGINT, SIGTERM,
 * SIGHUP and SIGPIPE), and, after a SIGKILL, by the next
 * output opened in the same directory once the killed process is gone. */
typedef struct tirenv_outfile tirenv_outfile;

/* Opens the output (see above); path "-" writes to stdout. *out is the new handle, NULL on
 * failure; commit or abort frees it. */
int tirenv_outfile_open(tirenv_outfile **out, const char *path, tirenv_diag *diag);
/* Where to write between open and commit (owned by f: never fclose it). */
FILE *tirenv_outfile_stream(tirenv_outfile *f);
/* The path as given to open, for messages. */
const char *tirenv_outfile_path(const tirenv_outfile *f);
/* Flushes, checks every write, closes, renames into place and frees f; on any error removes
 * the temporary file (and still frees f). NULL is TIRENV_EINVAL. */
int tirenv_outfile_commit(tirenv_outfile *f, tirenv_diag *diag);
/* 1 if nothing reaches the target before commit (a temporary file), 0 when written through:
 * a writer that could fail midway may then want to compute everything first. */
int tirenv_outfile_is_atomic(const tirenv_outfile *f);
/* Writes text as '#' comment lines ("# " before each line of it); NULL writes nothing. */
void tirenv_outfile_comment(tirenv_outfile *f, const char *text);
/* Closes and removes the temporary file (after a failure) and frees f; the target is left as
 * it was. NULL is a no-op. */
void tirenv_outfile_abort(tirenv_outfile *f);

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
 * signal handler, which then re-raises the signal (the tirenv command installs one for
 * SIGINT, SIGTERM, SIGHUP and SIGPIPE); a process that carries on afterwards writes no more
 * outputs. */
void tirenv_cleanup_on_signal(void);

/* An output directory written as a whole (tirenv study -o, compare -o, ride --out-dir, dataset
 * build -o, sweep merge -o): the run writes into a staging directory beside the target, which
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

TIRENV_END_DECLS
#endif
