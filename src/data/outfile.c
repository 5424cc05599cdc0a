/* All-or-nothing output files: write to "<path>.tmp.XXXXXX" beside the target, rename over it
 * on success, so a reader (or a plot script) never sees half a file after a failure.
 * SPDX-License-Identifier: GPL-3.0-or-later */
#include "tirenv/io.h"
#include "data/umask.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

static int outfile_is_stdout(const tirenv_outfile *f)
{
    return strcmp(f->path, "-") == 0;
}

/* mkstemp creates the file with mode 0600 and rename keeps it, whereas fopen would have given
 * 0666 minus the umask. So give the temporary file the mode the target already has, or the
 * one fopen would give (the umask read without setting it: files are written from several
 * threads at once, tirenv/parallel.h). */
static mode_t outfile_mode(const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0)
        return st.st_mode & 0777;
    return 0666 & ~tirenv_data__umask();
}

int tirenv_outfile_open(tirenv_outfile *f, const char *path, tirenv_diag *diag)
{
    f->fp = NULL;
    f->path[0] = '\0';
    f->tmp[0] = '\0';
    if (!path || !*path)
        return tirenv_error(diag, TIRENV_EINVAL, "", 0, "",
                            "empty output path; expected a file name or '-'");
    if (strlen(path) >= sizeof f->path)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "",
                            "output path is longer than %zu characters", sizeof f->path - 1);
    strcpy(f->path, path);
    if (outfile_is_stdout(f)) {
        f->fp = stdout;
        return TIRENV_OK;
    }
    /* Fits: sizeof tmp leaves room for the suffix after the longest accepted path. */
    snprintf(f->tmp, sizeof f->tmp, "%s.tmp.XXXXXX", path);
    const int fd = mkstemp(f->tmp);
    if (fd < 0) {
        const int e = errno;
        f->tmp[0] = '\0';
        return tirenv_error(diag, TIRENV_EIO, path, 0, "",
                            "cannot create a temporary file beside it: %s", strerror(e));
    }
    /* A file system without modes (FAT) refuses this; the file is still worth writing. */
    (void)fchmod(fd, outfile_mode(path));
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        const int e = errno;
        close(fd);
        tirenv_outfile_abort(f);
        return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot open for writing: %s",
                            strerror(e));
    }
    return TIRENV_OK;
}

/* fsync before rename: otherwise a crash soon after could leave the new name pointing at an
 * empty file on some file systems, which is the half-written file this module exists to
 * prevent. */
int tirenv_outfile_commit(tirenv_outfile *f, tirenv_diag *diag)
{
    if (!f->fp)
        return tirenv_error(diag, TIRENV_EINVAL, f->path, 0, "",
                            "output file is not open (commit after abort or a failed open)");
    FILE *fp = f->fp;
    f->fp = NULL;
    errno = 0;
    if (outfile_is_stdout(f)) {
        if (fflush(fp) != 0 || ferror(fp))
            return tirenv_error(diag, TIRENV_EIO, f->path, 0, "",
                                "cannot write to standard output: %s",
                                strerror(errno ? errno : EIO));
        return TIRENV_OK;
    }
    int failed = fflush(fp) != 0 || ferror(fp) || fsync(fileno(fp)) != 0;
    int e = errno;
    if (fclose(fp) != 0 && !failed) {
        failed = 1;
        e = errno;
    }
    if (!failed && rename(f->tmp, f->path) != 0) {
        failed = 1;
        e = errno;
    }
    if (failed) {
        remove(f->tmp);
        f->tmp[0] = '\0';
        /* ferror does not set errno: an earlier failed fprintf may have left it 0. */
        return tirenv_error(diag, TIRENV_EIO, f->path, 0, "", "cannot write: %s",
                            strerror(e ? e : EIO));
    }
    f->tmp[0] = '\0';
    return TIRENV_OK;
}

void tirenv_outfile_abort(tirenv_outfile *f)
{
    if (f->fp && !outfile_is_stdout(f))
        fclose(f->fp);
    f->fp = NULL;
    if (f->tmp[0])
        remove(f->tmp);
    f->tmp[0] = '\0';
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
    char buf[512];
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
