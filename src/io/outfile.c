/* All-or-nothing output files (include/tirenv/outfile.h): a regular file is written to a
 * temporary file beside it and renamed over it on success, so a reader (or a plot script)
 * never sees half a file after a failure; what cannot be replaced by a rename (stdout, a
 * device, a FIFO) is written through, and never replaced.
 * SPDX-License-Identifier: Apache-2.0 */
#include "tirenv/outfile.h"
#include "io/umask.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "io/tmpfiles.h"

struct tirenv_outfile {
    FILE *fp;              /* write here between open and commit */
    char path[1024];       /* the path as given, for messages */
    char target[4096];     /* what commit replaces: path with its symbolic links followed */
    char tmp[4096];        /* the temporary file, or "" when written through */
    int through;           /* 1: written straight to the target or descriptor */
    int slot;              /* registration for tirenv_cleanup_on_signal, or -1 */
    char *buf;             /* stdio buffer of a temporary file */
};

static void discard(tirenv_outfile *f);
static int commit(tirenv_outfile *f, tirenv_diag *diag);

/* A temporary file's stdio buffer: large writes cost fewer system calls than 4 KiB ones
 * (a 70 MB CSV took 17,000 writes). */
enum { OUT_BUFFER = 1 << 18 };

static int outfile_is_stdout(const tirenv_outfile *f)
{
    return f->through && f->fp == stdout;
}

/* The temporary file is created with mode 0600, and rename keeps it, whereas fopen would
 * have given 0666 minus the umask. So give it the mode the target already has, or the one
 * fopen would give: the umask read without setting it (the umask(0)/umask(mask) dance would
 * leave it 0 for a moment while other threads create files, tirenv/parallel.h). */
static mode_t new_file_mode(void)
{
    return 0666 & ~tirenv_data__umask();
}

/* Writes through to descriptor fd (a name of it, or "-"): stdout itself for 1, so that its
 * buffer and the program's other output stay in order; a duplicate otherwise. */
static int open_descriptor(tirenv_outfile *f, int fd, tirenv_diag *diag)
{
    f->through = 1;
    if (fd == STDOUT_FILENO) {
        f->fp = stdout;
        return TIRENV_OK;
    }
    const int d = fcntl(fd, F_DUPFD_CLOEXEC, 3);
    if (d < 0)
        return tirenv_error(diag, TIRENV_EIO, f->path, 0, "",
                            "descriptor %d is not open for writing: %s", fd, strerror(errno));
    if (!(f->fp = fdopen(d, "w"))) {
        const int e = errno;
        close(d);
        return tirenv_error(diag, TIRENV_EIO, f->path, 0, "", "cannot write: %s", strerror(e));
    }
    return TIRENV_OK;
}

/* A character device or a FIFO, opened as the shell's '>' would open it but without
 * creating or truncating anything: /dev/null swallows, a terminal shows, a FIFO's reader
 * reads (open waits for one). */
static int open_through(tirenv_outfile *f, tirenv_diag *diag)
{
    const int fd = open(f->target, O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return tirenv_error(diag, TIRENV_EIO, f->path, 0, "", "cannot open for writing: %s",
                            strerror(errno));
    f->through = 1;
    if (!(f->fp = fdopen(fd, "w"))) {
        const int e = errno;
        close(fd);
        return tirenv_error(diag, TIRENV_EIO, f->path, 0, "", "cannot write: %s", strerror(e));
    }
    return TIRENV_OK;
}

/* The temporary file beside the target: registered for the signal handler before it exists,
 * so that there is no moment where a signal would leave it behind. */
static int open_temporary(tirenv_outfile *f, const struct stat *old, tirenv_diag *diag)
{
    char dir[TIRENV_TMP_PATH], base[TIRENV_TMP_PATH];
    tirenv_tmp__split(f->target, dir, base);
    tirenv_tmp__sweep_stale(dir);
    int fd = -1, e = 0;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        if (tirenv_tmp__name(f->target, TIRENV_TMP_MARK, f->tmp))
            return tirenv_error(diag, TIRENV_EINVAL, f->path, 0, "", "path is too long");
        if (tirenv_tmp__create_begin()) {
            e = EINTR;  /* a signal is ending the program */
            break;
        }
        f->slot = tirenv_tmp__register(f->tmp, 0);
        fd = open(f->tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        e = errno;
        tirenv_tmp__create_end();
        if (fd < 0) {
            tirenv_tmp__unregister(f->slot);
            f->slot = -1;
            if (e != EEXIST)
                break;
        }
    }
    if (fd < 0) {
        f->tmp[0] = '\0';
        return tirenv_error(diag, TIRENV_EIO, f->path, 0, "",
                            "cannot create a temporary file beside it: %s", strerror(e));
    }
    /* A file system without modes (FAT) refuses these; the file is still worth writing. The
     * owner only matters when root replaces another user's file. */
    (void)fchmod(fd, old ? old->st_mode & 07777 : new_file_mode());
    if (old && (old->st_uid != geteuid() || old->st_gid != getegid()))
        (void)!fchown(fd, old->st_uid, old->st_gid);
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        e = errno;
        close(fd);
        discard(f);
        return tirenv_error(diag, TIRENV_EIO, f->path, 0, "", "cannot open for writing: %s",
                            strerror(e));
    }
    if ((f->buf = malloc(OUT_BUFFER)))
        setvbuf(f->fp, f->buf, _IOFBF, OUT_BUFFER);
    return TIRENV_OK;
}

static int open_at(tirenv_outfile *f, const char *path, tirenv_diag *diag)
{
    if (!path || !*path)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "",
                            "empty output path; expected a file name or '-'");
    if (strlen(path) >= sizeof f->path)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "",
                            "output path is longer than %zu characters", sizeof f->path - 1);
    strcpy(f->path, path);
    if (strcmp(path, "-") == 0)
        return open_descriptor(f, STDOUT_FILENO, diag);
    int fd;
    int status = tirenv_tmp__resolve(path, f->target, &fd, diag);
    if (status)
        return status;
    if (fd >= 0)
        return open_descriptor(f, fd, diag);
    struct stat st;
    if (lstat(f->target, &st) != 0) {
        if (errno != ENOENT)
            return tirenv_error(diag, TIRENV_EIO, f->path, 0, "", "cannot write there: %s",
                                strerror(errno));
        return open_temporary(f, NULL, diag);
    }
    if (S_ISREG(st.st_mode))
        return open_temporary(f, &st, diag);
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))
        return open_through(f, diag);
    if (S_ISDIR(st.st_mode))
        return tirenv_error(diag, TIRENV_EINVAL, f->path, 0, "",
                            "is a directory; expected a file name");
    if (S_ISBLK(st.st_mode))
        return tirenv_error(diag, TIRENV_EINVAL, f->path, 0, "",
                            "is a block device: tirenv does not write over a disk; write to "
                            "a file, or to '-' and redirect it");
    return tirenv_error(diag, TIRENV_EINVAL, f->path, 0, "",
                        "is a socket or another special file; expected a file name, a "
                        "character device, a FIFO or '-'");
}

int tirenv_outfile_open(tirenv_outfile **out, const char *path, tirenv_diag *diag)
{
    *out = NULL;
    tirenv_outfile *f = malloc(sizeof *f);
    if (!f)
        return tirenv_error(diag, TIRENV_ENOMEM, path ? path : "", 0, "",
                            "out of memory opening an output file");
    f->fp = NULL;
    f->path[0] = f->target[0] = f->tmp[0] = '\0';
    f->through = 0;
    f->slot = -1;
    f->buf = NULL;
    const int status = open_at(f, path, diag);
    if (status) {
        discard(f);
        free(f);
        return status;
    }
    *out = f;
    return TIRENV_OK;
}

FILE *tirenv_outfile_stream(tirenv_outfile *f)
{
    return f->fp;
}

const char *tirenv_outfile_path(const tirenv_outfile *f)
{
    return f->path;
}

int tirenv_outfile_path_is_through(const char *path)
{
    if (!path || !*path)
        return 0;
    if (strcmp(path, "-") == 0)
        return 1;
    char target[TIRENV_TMP_PATH];
    int fd;
    if (tirenv_tmp__resolve(path, target, &fd, NULL) != TIRENV_OK)
        return 0;
    if (fd >= 0)
        return 1;
    struct stat st;
    return stat(target, &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode));
}

int tirenv_outfile_is_atomic(const tirenv_outfile *f)
{
    return !f->through;
}

static void release(tirenv_outfile *f)
{
    tirenv_tmp__unregister(f->slot);
    f->slot = -1;
    f->tmp[0] = '\0';
    free(f->buf);
    f->buf = NULL;
}

int tirenv_outfile_commit(tirenv_outfile *f, tirenv_diag *diag)
{
    if (!f)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "",
                            "output file is not open (commit after a failed open)");
    const int status = commit(f, diag);
    free(f);
    return status;
}

/* fsync before rename: otherwise a crash soon after could leave the new name pointing at an
 * empty file on some file systems, which is the half-written file this module exists to
 * prevent. The rename comes before the unregistration (release): a signal in between removes
 * a name that no longer exists, where the other order could leave the temporary file. */
static int commit(tirenv_outfile *f, tirenv_diag *diag)
{
    const int to_stdout = outfile_is_stdout(f);  /* asked before fp is taken from f */
    FILE *fp = f->fp;
    f->fp = NULL;
    errno = 0;
    if (to_stdout) {
        if (fflush(fp) != 0 || ferror(fp))
            return tirenv_error(diag, TIRENV_EIO, f->path, 0, "",
                                "cannot write to standard output: %s",
                                strerror(errno ? errno : EIO));
        return TIRENV_OK;
    }
    int failed = fflush(fp) != 0 || ferror(fp) || (!f->through && fsync(fileno(fp)) != 0);
    int e = errno;
    if (fclose(fp) != 0 && !failed) {
        failed = 1;
        e = errno;
    }
    if (!failed && !f->through && rename(f->tmp, f->target) != 0) {
        failed = 1;
        e = errno;
    }
    if (failed && !f->through)
        unlink(f->tmp);
    release(f);
    if (failed)  /* ferror does not set errno: an earlier failed fprintf may have left it 0 */
        return tirenv_error(diag, TIRENV_EIO, f->path, 0, "", "cannot write: %s",
                            strerror(e ? e : EIO));
    return TIRENV_OK;
}

static void discard(tirenv_outfile *f)
{
    if (f->fp && !outfile_is_stdout(f))
        fclose(f->fp);
    f->fp = NULL;
    if (f->tmp[0])
        unlink(f->tmp);
    release(f);
}

void tirenv_outfile_abort(tirenv_outfile *f)
{
    if (!f)
        return;
    discard(f);
    free(f);
}

void tirenv_outfile_comment(tirenv_outfile *f, const char *text)
{
    if (!text)
        return;
    fputs("# ", f->fp);
    for (const char *c = text; *c; ++c) {
        fputc(*c, f->fp);
        if (*c == '\n')
            fputs("# ", f->fp);
    }
    fputc('\n', f->fp);
}

/* mkdir -p: an output directory such as out/study usually needs "out" first. */
int tirenv_mkdir_p(const char *path, tirenv_diag *diag)
{
    char buf[TIRENV_TMP_PATH];
    if (!path || !*path)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "out_dir", "empty output directory");
    if (strlen(path) >= sizeof buf - 64)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "out_dir",
                            "output directory name longer than %zu characters",
                            sizeof buf - 65);
    strcpy(buf, path);
    for (char *p = buf + 1; *p; ++p) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            return tirenv_error(diag, TIRENV_EIO, buf, 0, "", "cannot create directory: %s",
                                strerror(errno));
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        return tirenv_error(diag, TIRENV_EIO, buf, 0, "", "cannot create directory: %s",
                            strerror(errno));
    struct stat st;
    if (stat(buf, &st) != 0 || !S_ISDIR(st.st_mode))
        return tirenv_error(diag, TIRENV_EIO, buf, 0, "", "exists and is not a directory");
    return TIRENV_OK;
}
