/* Private to src/io and the modules after it: the temporary files and directories that output files and output
 * directories are built in (outfile.c, outdir.c): their names, a registry that a signal
 * handler can empty, removal of whole trees, the sweep of those a killed run left behind,
 * and symbolic-link resolution. SPDX-License-Identifier: Apache-2.0 */
#ifndef TIRENV_DATA_TMPFILES_H
#define TIRENV_DATA_TMPFILES_H

#include <stddef.h>

#include "tirenv/error.h"

/* Longest path handled, with its NUL. */
#define TIRENV_TMP_PATH 4096

/* The marker in every temporary name: ".<name>.tirenv-tmp.<host>.<pid>.<random>" for a file
 * or staging directory being written, ".<name>.tirenv-old.<host>.<pid>.<random>" for an old
 * directory during a non-atomic exchange (outdir.c). <host> is 8 hex digits of a hash of the
 * host name, <pid> the writing process. */
#define TIRENV_TMP_MARK ".tirenv-tmp."
#define TIRENV_OLD_MARK ".tirenv-old."

/* A fresh temporary name beside target (same directory) with the given mark, in buf; a long
 * target name is shortened in the temporary name so that it stays a legal name. 0, or -1 if
 * the result would not fit. */
int tirenv_tmp__name(const char *target, const char *mark, char buf[TIRENV_TMP_PATH]);

/* Registers path (a file, or a directory removed with its contents) for removal by
 * tirenv_cleanup_on_signal; returns the slot, or -1 if every slot is taken (the path is then
 * only swept by a later run). Register before creating it, unregister after renaming it. */
int tirenv_tmp__register(const char *path, int is_dir);

/* Bracket the registration and creation of a temporary entry: _begin returns -1 (create
 * nothing) once a signal is being handled, and the handler waits for brackets under way. */
int tirenv_tmp__create_begin(void);
void tirenv_tmp__create_end(void);
void tirenv_tmp__unregister(int slot);  /* -1 is a no-op */

/* Removes path and, if it is a directory, everything under it (symbolic links are removed,
 * never followed; no other file system is entered). Async-signal-safe. 0, or -1 with errno. */
int tirenv_tmp__rmtree(const char *path);

/* Once per directory and process: removes the temporary files and directories of this host
 * whose writing process is gone (killed by SIGKILL, or by a crash), and puts back an old
 * directory that a killed non-atomic exchange left aside (outdir.c). A temporary entry of a
 * live process, of another user's process or of another host is left alone. dir "" means
 * the current directory. */
void tirenv_tmp__sweep_stale(const char *dir);

/* The directory part of path ("." when there is none) and the last component, in buffers
 * of TIRENV_TMP_PATH. */
void tirenv_tmp__split(const char *path, char *dir, char *base);

/* Follows symbolic links from path to what they finally name (which may not exist: a
 * dangling link names a file to create), into out. If a link, or path itself, names a
 * descriptor of this process (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N), stops
 * there and sets *fd to N; else *fd is -1. TIRENV_EINVAL / TIRENV_EIO with diag on a loop or
 * an overlong result. */
int tirenv_tmp__resolve(const char *path, char out[TIRENV_TMP_PATH], int *fd,
                        tirenv_diag *diag);

#endif
