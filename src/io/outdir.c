/* Output directories written as a whole (include/tirenv/io.h): a staging directory beside
 * the target, filled by the run, then swapped with the target in one step.
 *
 * Why a swap and not a marker: a reader of a report directory (a person, a script, a web
 * server) sees either the old report or the new one, each whole, at every moment, without
 * having to know about a marker. renameat2(RENAME_EXCHANGE) swaps two directories atomically
 * (ext4, xfs, btrfs, tmpfs); where the file system refuses it, the old directory is first
 * renamed aside under a name the next run recognises (".<name>.tirenv-old.<host>.<pid>.<r>")
 * and then the new one into place: a kill between those two renames leaves the target
 * missing for a moment, and the next run in that directory puts the old one back
 * (tmpfiles.c).
 *
 * Why carry the old files over: users keep inputs in output directories (make demo kept the
 * road profile beside the ride's plots); replacing the directory must not destroy what the
 * run does not write. Hard links cost no copy, and every writer of the library replaces a
 * file by renaming a new one over it, never writing into it, so a link shared with the old
 * directory is never changed through the new one.
 * SPDX-License-Identifier: Apache-2.0 */
#define _GNU_SOURCE  /* renameat2, RENAME_EXCHANGE */
#include "tirenv/outfile.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "io/tmpfiles.h"
#include "io/umask.h"

/* More entries than this in an existing target is not a report directory but a mistake
 * (-o ~), which must not be copied and swapped. */
enum { CARRY_MAX = 100000 };

struct tirenv_outdir {
    char path[TIRENV_TMP_PATH];     /* the target as given, for messages */
    char target[TIRENV_TMP_PATH];   /* with its symbolic links followed */
    char staging[TIRENV_TMP_PATH];
    int exists;                     /* the target existed at begin */
    int slot;                       /* registration for tirenv_cleanup_on_signal */
    size_t made_from;               /* parents begin created: target[0..made_from) existed */
    int made;
};

const char *tirenv_outdir_path(const tirenv_outdir *d)
{
    return d->staging;
}

/* ---- begin ------------------------------------------------------------------------------ */

/* mkdir -p of target's parent, remembering where creation started (for abort). */
static int make_parents(tirenv_outdir *d, tirenv_diag *diag)
{
    char buf[TIRENV_TMP_PATH];
    strcpy(buf, d->target);
    char *last = strrchr(buf, '/');
    if (!last || last == buf)
        return TIRENV_OK;
    *last = '\0';
    struct stat st;
    if (stat(buf, &st) == 0)
        return S_ISDIR(st.st_mode) ? TIRENV_OK
                                   : tirenv_error(diag, TIRENV_EIO, buf, 0, "",
                                                  "exists and is not a directory");
    for (char *p = buf + 1; *p; ++p) {
        if (*p != '/')
            continue;
        *p = '\0';
        const int made = mkdir(buf, 0777) == 0;
        if (!made && errno != EEXIST)
            return tirenv_error(diag, TIRENV_EIO, buf, 0, "", "cannot create directory: %s",
                                strerror(errno));
        if (made && !d->made) {
            d->made = 1;
            d->made_from = (size_t)(p - buf);
        }
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        return tirenv_error(diag, TIRENV_EIO, buf, 0, "", "cannot create directory: %s",
                            strerror(errno));
    if (!d->made) {
        d->made = 1;
        d->made_from = strlen(buf);
    }
    return TIRENV_OK;
}

/* rmdir of the parents make_parents created, deepest first, as long as they are empty. */
static void remove_parents(const tirenv_outdir *d)
{
    if (!d->made)
        return;
    char buf[TIRENV_TMP_PATH];
    strcpy(buf, d->target);
    for (;;) {
        char *last = strrchr(buf, '/');
        if (!last || (size_t)(last - buf) < d->made_from)
            return;
        *last = '\0';
        if ((size_t)(last - buf) < d->made_from || rmdir(buf) != 0)
            return;
    }
}

/* A copy of a file where a hard link is refused (another file system cannot happen beside
 * the target; protected_hardlinks or FAT can). */
static int copy_file(int from_dir, int to_dir, const char *name, mode_t mode)
{
    const int in = openat(from_dir, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (in < 0)
        return -1;
    const int out = openat(to_dir, name, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode & 07777);
    int failed = out < 0;
    char buf[65536];
    ssize_t n;
    while (!failed && (n = read(in, buf, sizeof buf)) != 0) {
        if (n < 0) {
            if (errno == EINTR)
                continue;
            failed = 1;
            break;
        }
        for (ssize_t done = 0; done < n && !failed;) {
            const ssize_t w = write(out, buf + done, (size_t)(n - done));
            if (w < 0 && errno != EINTR)
                failed = 1;
            done += w > 0 ? w : 0;
        }
    }
    const int e = errno;
    close(in);
    if (out >= 0 && close(out) != 0)
        failed = 1;
    errno = e;
    return failed ? -1 : 0;
}

/* Carries the entries of the open directory from into to (both open), recursively: links
 * for files, new symbolic links for links, new directories for directories. Our own
 * temporary entries are not carried. */
static int carry(int from, int to, dev_t dev, const char *where, size_t *count, int depth,
                 tirenv_diag *diag)
{
    const int dup_fd = fcntl(from, F_DUPFD_CLOEXEC, 3);
    DIR *dp = dup_fd >= 0 ? fdopendir(dup_fd) : NULL;
    if (!dp) {
        if (dup_fd >= 0)
            close(dup_fd);
        return tirenv_error(diag, TIRENV_EIO, where, 0, "", "cannot read the directory: %s",
                            strerror(errno));
    }
    int status = TIRENV_OK;
    const struct dirent *e;
    while (!status && (e = readdir(dp))) {
        const char *name = e->d_name;
        if (strcmp(name, ".") == 0 || strcmp(name, "..") == 0 ||
            strstr(name, TIRENV_TMP_MARK) || strstr(name, TIRENV_OLD_MARK))
            continue;
        char entry[TIRENV_TMP_PATH];
        snprintf(entry, sizeof entry, "%s/%s", where, name);
        if (++*count > CARRY_MAX) {
            status = tirenv_error(diag, TIRENV_EINVAL, where, 0, "",
                                  "holds more than %d entries: not an output directory of "
                                  "tirenv, which would copy them all; choose a new or an "
                                  "empty directory", CARRY_MAX);
            break;
        }
        struct stat st;
        if (fstatat(from, name, &st, AT_SYMLINK_NOFOLLOW) != 0) {
            status = tirenv_error(diag, TIRENV_EIO, entry, 0, "", "cannot read: %s",
                                  strerror(errno));
        } else if (S_ISREG(st.st_mode)) {
            if (linkat(from, name, to, name, 0) != 0 && copy_file(from, to, name, st.st_mode))
                status = tirenv_error(diag, TIRENV_EIO, entry, 0, "",
                                      "cannot carry it into the new output: %s",
                                      strerror(errno));
        } else if (S_ISLNK(st.st_mode)) {
            char link[TIRENV_TMP_PATH];
            const ssize_t n = readlinkat(from, name, link, sizeof link - 1);
            if (n >= 0)
                link[n] = '\0';
            if (n < 0 || symlinkat(link, to, name) != 0)
                status = tirenv_error(diag, TIRENV_EIO, entry, 0, "",
                                      "cannot carry the link into the new output: %s",
                                      strerror(errno));
        } else if (S_ISDIR(st.st_mode) && st.st_dev == dev && depth < 64) {
            int sub_from = -1, sub_to = -1;
            if (mkdirat(to, name, st.st_mode & 07777) != 0 ||
                (sub_from = openat(from, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW |
                                                   O_CLOEXEC)) < 0 ||
                (sub_to = openat(to, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC)) < 0)
                status = tirenv_error(diag, TIRENV_EIO, entry, 0, "",
                                      "cannot carry the directory into the new output: %s",
                                      strerror(errno));
            else
                status = carry(sub_from, sub_to, dev, entry, count, depth + 1, diag);
            if (sub_from >= 0)
                close(sub_from);
            if (sub_to >= 0)
                close(sub_to);
        } else {
            status = tirenv_error(diag, TIRENV_EINVAL, entry, 0, "",
                                  "%s: tirenv cannot carry it into the new output directory; "
                                  "move it out, or choose a new or an empty directory",
                                  S_ISDIR(st.st_mode) ? "a mount point (another file system)"
                                                      : "a device, FIFO or socket");
        }
    }
    closedir(dp);
    return status;
}

static int carry_old(tirenv_outdir *d, tirenv_diag *diag)
{
    const int from = open(d->target, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    const int to = open(d->staging, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    struct stat st;
    int status;
    if (from < 0 || to < 0 || fstat(from, &st) != 0)
        status = tirenv_error(diag, TIRENV_EIO, d->path, 0, "", "cannot read the directory: %s",
                              strerror(errno));
    else {
        size_t count = 0;
        status = carry(from, to, st.st_dev, d->path, &count, 0, diag);
    }
    if (from >= 0)
        close(from);
    if (to >= 0)
        close(to);
    return status;
}

int tirenv_outdir_begin(const char *target, tirenv_outdir **out, tirenv_diag *diag)
{
    *out = NULL;
    if (!target || !*target)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "out_dir", "empty output directory");
    if (strlen(target) >= TIRENV_TMP_PATH - 64)
        return tirenv_error(diag, TIRENV_EINVAL, target, 0, "out_dir",
                            "output directory name is too long");
    tirenv_outdir *d = calloc(1, sizeof *d);
    if (!d)
        return tirenv_error(diag, TIRENV_ENOMEM, target, 0, "", "out of memory");
    d->slot = -1;
    snprintf(d->path, sizeof d->path, "%s", target);
    /* "out/" and "out" are one directory; the staging one goes beside it, not inside. */
    size_t n = strlen(d->path);
    while (n > 1 && d->path[n - 1] == '/')
        d->path[--n] = '\0';
    int fd;
    int status = tirenv_tmp__resolve(d->path, d->target, &fd, diag);
    n = strlen(d->target);
    while (!status && n > 1 && d->target[n - 1] == '/')
        d->target[--n] = '\0';
    struct stat st;
    mode_t mode = 0;
    const char *tail = strrchr(d->target, '/');
    tail = tail ? tail + 1 : d->target;
    if (!status && (strcmp(tail, ".") == 0 || strcmp(tail, "..") == 0 || !*tail))
        status = tirenv_error(diag, TIRENV_EINVAL, d->path, 0, "out_dir",
                              "a directory that holds the current one cannot be replaced as "
                              "a whole; name a directory inside it (e.g. ./report)");
    if (!status && fd >= 0)
        status = tirenv_error(diag, TIRENV_EINVAL, d->path, 0, "out_dir",
                              "names a file descriptor; expected a directory");
    if (!status && lstat(d->target, &st) == 0) {
        if (!S_ISDIR(st.st_mode))
            status = tirenv_error(diag, TIRENV_EINVAL, d->path, 0, "out_dir",
                                  "exists and is not a directory");
        d->exists = 1;
        mode = st.st_mode & 07777;
    } else if (!status && errno != ENOENT) {
        status = tirenv_error(diag, TIRENV_EIO, d->path, 0, "out_dir", "cannot use it: %s",
                              strerror(errno));
    } else if (!status) {
        mode = 0777 & ~tirenv_data__umask(); /* read without setting it: other threads may
                                                * be creating files (tirenv/parallel.h) */
    }
    if (!status)
        status = make_parents(d, diag);
    if (!status) {
        char dir[TIRENV_TMP_PATH], base[TIRENV_TMP_PATH];
        tirenv_tmp__split(d->target, dir, base);
        tirenv_tmp__sweep_stale(dir);
        int made = 0, e = 0;
        for (int attempt = 0; attempt < 100 && !made; ++attempt) {
            if (tirenv_tmp__name(d->target, TIRENV_TMP_MARK, d->staging)) {
                e = ENAMETOOLONG;
                break;
            }
            if (tirenv_tmp__create_begin()) {
                e = EINTR;  /* a signal is ending the program */
                break;
            }
            d->slot = tirenv_tmp__register(d->staging, 1);
            made = mkdir(d->staging, 0700) == 0;
            e = errno;
            tirenv_tmp__create_end();
            if (!made) {
                tirenv_tmp__unregister(d->slot);
                d->slot = -1;
                if (e != EEXIST)
                    break;
            }
        }
        if (!made) {
            d->staging[0] = '\0';
            status = tirenv_error(diag, TIRENV_EIO, d->path, 0, "",
                                  "cannot create a staging directory beside it: %s",
                                  strerror(e));
        } else {
            (void)chmod(d->staging, mode);
        }
    }
    if (!status && d->exists)
        status = carry_old(d, diag);
    if (status) {
        tirenv_outdir_abort(d);
        return status;
    }
    *out = d;
    return TIRENV_OK;
}

/* ---- commit and abort ----------------------------------------------------------------- */

static void sync_dir(const char *path)
{
    const int fd = open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        (void)fsync(fd);
        close(fd);
    }
}

/* Where renameat2 cannot exchange: the old directory aside, the new one in, the old one
 * removed; undone if the second rename fails. */
static int swap_by_renames(tirenv_outdir *d, tirenv_diag *diag)
{
    char old[TIRENV_TMP_PATH];
    if (tirenv_tmp__name(d->target, TIRENV_OLD_MARK, old))
        return tirenv_error(diag, TIRENV_EINVAL, d->path, 0, "", "path is too long");
    if (rename(d->target, old) != 0)
        return tirenv_error(diag, TIRENV_EIO, d->path, 0, "",
                            "cannot move the old directory aside: %s", strerror(errno));
    if (rename(d->staging, d->target) != 0) {
        const int e = errno;
        rename(old, d->target);
        return tirenv_error(diag, TIRENV_EIO, d->path, 0, "",
                            "cannot move the new directory into place: %s", strerror(e));
    }
    tirenv_tmp__rmtree(old);
    return TIRENV_OK;
}

int tirenv_outdir_commit(tirenv_outdir *d, tirenv_diag *diag)
{
    if (!d)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "", "no output directory to commit");
    sync_dir(d->staging);
    int status = TIRENV_OK, swapped = 0;
#ifdef RENAME_EXCHANGE
    if (d->exists) {
        if (renameat2(AT_FDCWD, d->staging, AT_FDCWD, d->target, RENAME_EXCHANGE) == 0)
            swapped = 1;
        else if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP)
            status = tirenv_error(diag, TIRENV_EIO, d->path, 0, "",
                                  "cannot move the new directory into place: %s",
                                  strerror(errno));
    } else if (renameat2(AT_FDCWD, d->staging, AT_FDCWD, d->target, RENAME_NOREPLACE) == 0) {
        d->staging[0] = '\0';
    } else if (errno == EEXIST || errno == ENOTEMPTY) {
        status = tirenv_error(diag, TIRENV_EIO, d->path, 0, "",
                              "was created by another program while tirenv wrote it; "
                              "nothing replaced");
    } else if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) {
        status = tirenv_error(diag, TIRENV_EIO, d->path, 0, "",
                              "cannot move the new directory into place: %s", strerror(errno));
    }
#endif
    if (!status && !swapped && d->staging[0]) {
        if (d->exists)
            status = swap_by_renames(d, diag);
        else if (rename(d->staging, d->target) == 0)
            d->staging[0] = '\0';
        else
            status = tirenv_error(diag, TIRENV_EIO, d->path, 0, "",
                                  "cannot move the new directory into place: %s",
                                  strerror(errno));
        if (!status)
            d->staging[0] = '\0';
    }
    if (!status) {
        char dir[TIRENV_TMP_PATH], base[TIRENV_TMP_PATH];
        tirenv_tmp__split(d->target, dir, base);
        sync_dir(dir);
        d->made = 0;  /* the parents now hold the output */
    }
    /* After an exchange the staging name holds the old directory: removed like a failed
     * run's staging directory. */
    tirenv_outdir_abort(d);
    return status;
}

void tirenv_outdir_abort(tirenv_outdir *d)
{
    if (!d)
        return;
    if (d->staging[0])
        tirenv_tmp__rmtree(d->staging);
    tirenv_tmp__unregister(d->slot);
    remove_parents(d);
    free(d);
}
