/* Output files and directories (include/tirenv/io.h): what each kind of target becomes, the
 * temporary names, the cleanup on a signal, the sweep of what a SIGKILL left, and the
 * output directory written as a whole. SPDX-License-Identifier: Apache-2.0 */
#include "testutil.h"
#include "tirenv/outfile.h"
#include "io/tmpfiles.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* ---- fixture: a scratch directory removed whole -------------------------------------------- */

typedef struct {
    char dir[64];
} scratch;

static int setup(void **state)
{
    scratch *s = calloc(1, sizeof *s);
    if (!s)
        return -1;
    snprintf(s->dir, sizeof s->dir, "/tmp/tirenv_outfile_XXXXXX");
    if (!mkdtemp(s->dir))
        return -1;
    *state = s;
    return 0;
}

static int teardown(void **state)
{
    scratch *s = *state;
    const int r = tirenv_tmp__rmtree(s->dir);
    free(s);
    return r;
}

static const char *at(const scratch *s, const char *name, char buf[700])
{
    snprintf(buf, 700, "%s/%s", s->dir, name);
    return buf;
}

static void write_text(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    fputs(text, fp);
    assert_int_equal(fclose(fp), 0);
}

static void read_text(const char *path, char *buf, size_t n)
{
    FILE *fp = fopen(path, "r");
    assert_non_null(fp);
    buf[fread(buf, 1, n - 1, fp)] = '\0';
    fclose(fp);
}

/* Entries of dir (not recursive) whose name contains the string. */
static size_t count(const char *dir, const char *containing)
{
    DIR *dp = opendir(dir);
    assert_non_null(dp);
    size_t n = 0;
    const struct dirent *e;
    while ((e = readdir(dp)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strstr(e->d_name, containing))
            n++;
    closedir(dp);
    return n;
}

/* Writes text through a tirenv_outfile to path and commits; returns the status. */
static int put(const char *path, const char *text)
{
    tirenv_outfile *f;
    tirenv_diag d;
    int status = tirenv_outfile_open(&f, path, &d);
    if (status)
        return status;
    fputs(text, tirenv_outfile_stream(f));
    return tirenv_outfile_commit(f, &d);
}

/* ---- regular files and symbolic links ------------------------------------------------------- */

static void test_regular_file_temporary_name(void **state)
{
    scratch *s = *state;
    char path[700], text[64];
    at(s, "out.csv", path);
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, path, &d), TIRENV_OK);
    assert_true(tirenv_outfile_is_atomic(f));
    fputs("a,b\n", tirenv_outfile_stream(f));
    /* Until commit the target does not exist; the temporary name says whose it is. */
    assert_int_equal(access(path, F_OK), -1);
    assert_int_equal(count(s->dir, ".out.csv.tirenv-tmp."), 1);
    char pid[32];
    snprintf(pid, sizeof pid, ".%ld.", (long)getpid());
    assert_int_equal(count(s->dir, pid), 1);
    assert_int_equal(tirenv_outfile_commit(f, &d), TIRENV_OK);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "a,b\n");
    assert_int_equal(count(s->dir, ""), 1);
}

static void test_symlink_target_replaced(void **state)
{
    scratch *s = *state;
    char link[700], target[700], sub[700], text[64];
    /* A relative link into a subdirectory, and a link to that link. */
    assert_int_equal(mkdir(at(s, "data", sub), 0755), 0);
    at(s, "data/target.csv", target);
    write_text(target, "old\n");
    assert_int_equal(symlink("data/target.csv", at(s, "link.csv", link)), 0);
    char link2[700];
    assert_int_equal(symlink("link.csv", at(s, "link2.csv", link2)), 0);
    assert_int_equal(put(link2, "new\n"), TIRENV_OK);
    struct stat st;
    assert_int_equal(lstat(link, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_int_equal(lstat(link2, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    read_text(target, text, sizeof text);
    assert_string_equal(text, "new\n");
    assert_int_equal(count(sub, "tirenv-tmp"), 0);
    assert_int_equal(count(s->dir, "tirenv-tmp"), 0);

    /* A dangling link names the file to create; the link stays. */
    char dangling[700], made[700];
    assert_int_equal(symlink("data/made.csv", at(s, "dangling.csv", dangling)), 0);
    assert_int_equal(put(dangling, "made\n"), TIRENV_OK);
    read_text(at(s, "data/made.csv", made), text, sizeof text);
    assert_string_equal(text, "made\n");
    assert_int_equal(lstat(dangling, &st), 0);
    assert_true(S_ISLNK(st.st_mode));

    /* A loop is an error, not a hang. */
    char loop[700];
    assert_int_equal(symlink("loop.csv", at(s, "loop.csv", loop)), 0);
    tirenv_diag d;
    assert_int_equal(put(loop, "x\n") != TIRENV_OK, 1);
    tirenv_outfile *f;
    assert_int_equal(tirenv_outfile_open(&f, loop, &d), TIRENV_EIO);
    assert_null(f);
    assert_non_null(strstr(d.message, "symbolic links"));
}

/* ---- what is not a regular file ----------------------------------------------------------- */

/* A character device stays the same device: /dev/null for anyone, and a node made here
 * (as /dev/null's numbers) when the test runs as root. */
static void check_char_device(const char *path)
{
    struct stat before, after;
    assert_int_equal(stat(path, &before), 0);
    assert_true(S_ISCHR(before.st_mode));
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, path, &d), TIRENV_OK);
    assert_false(tirenv_outfile_is_atomic(f));
    for (int i = 0; i < 10000; ++i)
        fputs("0.123456789,0.987654321\n", tirenv_outfile_stream(f));
    assert_int_equal(tirenv_outfile_commit(f, &d), TIRENV_OK);
    assert_int_equal(lstat(path, &after), 0);
    assert_true(S_ISCHR(after.st_mode));
    assert_true(after.st_rdev == before.st_rdev && after.st_ino == before.st_ino);
}

static void test_character_device_written_through(void **state)
{
    scratch *s = *state;
    check_char_device("/dev/null");
    char node[700];
    if (geteuid() != 0) {
        print_message("NOT TESTED: mknod of a character device needs root; only /dev/null "
                      "was checked\n");
        return;
    }
    assert_int_equal(mknod(at(s, "null", node), S_IFCHR | 0644, makedev(1, 3)), 0);
    check_char_device(node);
    assert_int_equal(count(s->dir, "tirenv-tmp"), 0);
    /* A block device (a loop device's numbers) is refused before anything is opened. */
    char blk[700];
    assert_int_equal(mknod(at(s, "disk", blk), S_IFBLK | 0600, makedev(7, 0)), 0);
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, blk, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "block device"));
    struct stat st;
    assert_int_equal(lstat(blk, &st), 0);
    assert_true(S_ISBLK(st.st_mode));
}

/* A FIFO with a reader (a child process) gets the data and stays a FIFO. */
static void test_fifo_written_through(void **state)
{
    scratch *s = *state;
    char fifo[700];
    assert_int_equal(mkfifo(at(s, "fifo", fifo), 0644), 0);
    int report[2];
    assert_int_equal(pipe(report), 0);
    const pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        close(report[0]);
        const int fd = open(fifo, O_RDONLY);
        char buf[4096], got[64] = "";
        size_t total = 0;
        ssize_t n;
        while ((n = read(fd, buf, sizeof buf)) > 0) {
            if (total == 0)
                memcpy(got, buf, n < 10 ? (size_t)n : 10);
            total += (size_t)n;
        }
        char line[128];
        const int len = snprintf(line, sizeof line, "%zu %s", total, got);
        (void)!write(report[1], line, (size_t)len);
        _exit(0);
    }
    close(report[1]);
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, fifo, &d), TIRENV_OK);
    for (int i = 0; i < 1000; ++i)
        fputs("fifo line\n", tirenv_outfile_stream(f));
    assert_int_equal(tirenv_outfile_commit(f, &d), TIRENV_OK);
    char line[128] = "";
    assert_true(read(report[0], line, sizeof line - 1) > 0);
    close(report[0]);
    int ws;
    waitpid(child, &ws, 0);
    assert_string_equal(line, "10000 fifo line\n");
    struct stat st;
    assert_int_equal(lstat(fifo, &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    assert_int_equal(count(s->dir, ""), 1);
}

/* /dev/fd/N writes to descriptor N (here a pipe), as the shell's >(...) hands it over. */
static void test_descriptor_names(void **state)
{
    (void)state;
    int p[2];
    assert_int_equal(pipe(p), 0);
    char name[64];
    snprintf(name, sizeof name, "/dev/fd/%d", p[1]);
    assert_int_equal(put(name, "through the pipe\n"), TIRENV_OK);
    snprintf(name, sizeof name, "/proc/self/fd/%d", p[1]);
    assert_int_equal(put(name, "again\n"), TIRENV_OK);
    close(p[1]);
    char buf[64] = "";
    assert_true(read(p[0], buf, sizeof buf - 1) > 0);
    close(p[0]);
    assert_string_equal(buf, "through the pipe\nagain\n");
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, "/dev/fd/999", &d), TIRENV_EIO);
    assert_non_null(strstr(d.message, "descriptor 999"));
    assert_int_equal(tirenv_outfile_open(&f, "/dev/stdout", &d), TIRENV_OK);
    assert_ptr_equal(tirenv_outfile_stream(f), stdout);
    assert_int_equal(tirenv_outfile_commit(f, &d), TIRENV_OK);
}

static void test_directory_refused(void **state)
{
    scratch *s = *state;
    tirenv_outfile *f;
    tirenv_diag d;
    assert_int_equal(tirenv_outfile_open(&f, s->dir, &d), TIRENV_EINVAL);
    assert_non_null(strstr(d.message, "directory"));
    assert_null(f);
}

/* ---- signals and stale files ------------------------------------------------------------ */

static void on_term(int sig)
{
    (void)sig;
    tirenv_cleanup_on_signal();
}

static void test_cleanup_on_signal(void **state)
{
    scratch *s = *state;
    char path[700], dir[700];
    /* Called directly, as the CLI's handler calls it; in a child, for afterwards the process
     * makes no temporary entry any more (it is on its way out: a --jobs worker that went on
     * creating files after the cleanup left one behind). The exit code says which check
     * failed. */
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        tirenv_outfile *f;
        tirenv_diag d;
        tirenv_outdir *od;
        if (tirenv_outfile_open(&f, at(s, "a.csv", path), &d) ||
            tirenv_outdir_begin(at(s, "rep", dir), &od, &d))
            _exit(2);
        char inner[800];
        snprintf(inner, sizeof inner, "%s/sub", tirenv_outdir_path(od));
        if (mkdir(inner, 0755) != 0)
            _exit(3);
        strcat(inner, "/deep.txt");
        write_text(inner, "x");
        if (count(s->dir, "tirenv-tmp") != 2)
            _exit(4);
        tirenv_cleanup_on_signal();  /* what the CLI's handler calls */
        if (count(s->dir, "") != 0)
            _exit(5);
        /* The handles are still to be released, as after any failure. */
        tirenv_outfile_abort(f);
        tirenv_outdir_abort(od);
        /* No new output starts: nothing would remove it. */
        tirenv_outfile *g;
        if (tirenv_outfile_open(&g, at(s, "b.csv", path), &d) != TIRENV_EIO ||
            tirenv_outdir_begin(at(s, "rep2", dir), &od, &d) != TIRENV_EIO)
            _exit(6);
        _exit(count(s->dir, "") == 0 ? 0 : 7);
    }
    int status;
    waitpid(child, &status, 0);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 0);

    /* In a child killed by SIGTERM with a handler as the CLI's. */
    child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        struct sigaction sa = {0};
        sa.sa_handler = on_term;
        sigaction(SIGTERM, &sa, NULL);
        tirenv_outfile *g;
        tirenv_diag d;
        if (tirenv_outfile_open(&g, at(s, "a.csv", path), &d))
            _exit(2);
        fputs("half", tirenv_outfile_stream(g));
        raise(SIGTERM);
        _exit(count(s->dir, "tirenv-tmp") == 0 ? 0 : 1);
    }
    int ws;
    waitpid(child, &ws, 0);
    assert_true(WIFEXITED(ws) && WEXITSTATUS(ws) == 0);
    assert_int_equal(count(s->dir, ""), 0);
}

/* A pid that is surely gone: a child that has exited and been waited for. */
static long dead_pid(void)
{
    const pid_t p = fork();
    if (p == 0)
        _exit(0);
    int ws;
    waitpid(p, &ws, 0);
    return (long)p;
}

/* This host's hash, as tirenv_tmp__name writes it. */
static void host_part(char host[9])
{
    char name[TIRENV_TMP_PATH];
    assert_int_equal(tirenv_tmp__name("x", TIRENV_TMP_MARK, name), 0);
    memcpy(host, name + strlen(".x" TIRENV_TMP_MARK), 8);
    host[8] = '\0';
}

static void test_stale_entries_swept(void **state)
{
    scratch *s = *state;
    char host[9], other[9], name[300], path[700], sub[800];
    host_part(host);
    snprintf(other, sizeof other, "%08x", (unsigned)(strtoul(host, NULL, 16) ^ 0x5a5a5a5a));
    const long dead = dead_pid();
    /* A dead process's file and staging directory (with contents): removed. */
    snprintf(name, sizeof name, ".r.csv.tirenv-tmp.%s.%ld.0badf00d", host, dead);
    write_text(at(s, name, path), "stale");
    snprintf(name, sizeof name, ".rep.tirenv-tmp.%s.%ld.0badf00e", host, dead);
    assert_int_equal(mkdir(at(s, name, path), 0700), 0);
    snprintf(sub, sizeof sub, "%s/F.dat", path);
    write_text(sub, "stale");
    /* A live process's (ours), another host's, and a name that only looks alike: kept. */
    snprintf(name, sizeof name, ".r.csv.tirenv-tmp.%s.%ld.0badf00f", host, (long)getpid());
    write_text(at(s, name, path), "live");
    snprintf(name, sizeof name, ".r.csv.tirenv-tmp.%s.%ld.0badf010", other, dead);
    write_text(at(s, name, path), "other host");
    write_text(at(s, "notes.tirenv-tmp.txt", path), "user's");
    /* An old directory put aside by a killed exchange, its target missing: put back. */
    snprintf(name, sizeof name, ".old-report.tirenv-old.%s.%ld.0badf011", host, dead);
    assert_int_equal(mkdir(at(s, name, path), 0755), 0);
    snprintf(sub, sizeof sub, "%s/report.md", path);
    write_text(sub, "the old report");
    assert_int_equal(count(s->dir, ""), 6);

    /* Any output opened in the directory sweeps it. */
    assert_int_equal(put(at(s, "new.csv", path), "new\n"), TIRENV_OK);
    assert_int_equal(count(s->dir, ""), 5);
    assert_int_equal(count(s->dir, "0badf00d"), 0);
    assert_int_equal(count(s->dir, "0badf00e"), 0);
    assert_int_equal(count(s->dir, "0badf00f"), 1);
    assert_int_equal(count(s->dir, "0badf010"), 1);
    assert_int_equal(count(s->dir, "notes.tirenv-tmp.txt"), 1);
    char text[64];
    read_text(at(s, "old-report/report.md", path), text, sizeof text);
    assert_string_equal(text, "the old report");
}

/* ---- output directories ------------------------------------------------------------------ */

static void test_outdir_new(void **state)
{
    scratch *s = *state;
    char target[700], path[900], text[64];
    at(s, "out/study", target);  /* "out" is missing too */
    tirenv_outdir *d;
    tirenv_diag diag;
    assert_int_equal(tirenv_outdir_begin(target, &d, &diag), TIRENV_OK);
    assert_int_equal(access(target, F_OK), -1);  /* nothing there until commit */
    snprintf(path, sizeof path, "%s/report.md", tirenv_outdir_path(d));
    assert_int_equal(put(path, "report\n"), TIRENV_OK);
    assert_int_equal(tirenv_outdir_commit(d, &diag), TIRENV_OK);
    snprintf(path, sizeof path, "%s/report.md", target);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "report\n");
    char out[700];
    assert_int_equal(count(at(s, "out", out), ""), 1);

    /* Aborted on a missing target: no target, and the parents it made are gone too. */
    at(s, "a/b/c", target);
    assert_int_equal(tirenv_outdir_begin(target, &d, &diag), TIRENV_OK);
    tirenv_outdir_abort(d);
    char a[700];
    assert_int_equal(access(at(s, "a", a), F_OK), -1);
    tirenv_outdir_abort(NULL);
}

static void test_outdir_replaces_whole(void **state)
{
    scratch *s = *state;
    char target[700], path[900], text[64];
    at(s, "rep", target);
    assert_int_equal(mkdir(target, 0750), 0);
    snprintf(path, sizeof path, "%s/report.md", target);
    write_text(path, "old report\n");
    snprintf(path, sizeof path, "%s/road.csv", target);  /* the user's own file */
    write_text(path, "x_m,z_m\n");
    snprintf(path, sizeof path, "%s/sub", target);
    assert_int_equal(mkdir(path, 0755), 0);
    snprintf(path, sizeof path, "%s/sub/F.dat", target);
    write_text(path, "old F\n");
    assert_int_equal(symlink("road.csv", (snprintf(path, sizeof path, "%s/link", target), path)),
                     0);
    struct stat road_st;
    snprintf(path, sizeof path, "%s/road.csv", target);
    assert_int_equal(stat(path, &road_st), 0);

    tirenv_outdir *d;
    tirenv_diag diag;
    assert_int_equal(tirenv_outdir_begin(target, &d, &diag), TIRENV_OK);
    const char *st = tirenv_outdir_path(d);
    /* Carried over: the same file (a hard link), the subdirectory, the link. */
    struct stat carried;
    snprintf(path, sizeof path, "%s/road.csv", st);
    assert_int_equal(stat(path, &carried), 0);
    assert_true(carried.st_ino == road_st.st_ino);
    snprintf(path, sizeof path, "%s/link", st);
    assert_int_equal(lstat(path, &carried), 0);
    assert_true(S_ISLNK(carried.st_mode));
    assert_int_equal(stat(st, &carried), 0);
    assert_int_equal(carried.st_mode & 0777, 0750);
    /* The run replaces some files; until commit the old directory is unchanged. */
    snprintf(path, sizeof path, "%s/report.md", st);
    assert_int_equal(put(path, "new report\n"), TIRENV_OK);
    snprintf(path, sizeof path, "%s/sub/F.dat", st);
    assert_int_equal(put(path, "new F\n"), TIRENV_OK);
    snprintf(path, sizeof path, "%s/report.md", target);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "old report\n");
    snprintf(path, sizeof path, "%s/sub/F.dat", target);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "old F\n");
    assert_int_equal(tirenv_outdir_commit(d, &diag), TIRENV_OK);

    snprintf(path, sizeof path, "%s/report.md", target);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "new report\n");
    snprintf(path, sizeof path, "%s/sub/F.dat", target);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "new F\n");
    snprintf(path, sizeof path, "%s/road.csv", target);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "x_m,z_m\n");
    assert_int_equal(count(s->dir, ""), 1);  /* no staging or old directory left */

    /* Aborted: the directory is as it was. */
    assert_int_equal(tirenv_outdir_begin(target, &d, &diag), TIRENV_OK);
    snprintf(path, sizeof path, "%s/report.md", tirenv_outdir_path(d));
    assert_int_equal(put(path, "aborted\n"), TIRENV_OK);
    tirenv_outdir_abort(d);
    snprintf(path, sizeof path, "%s/report.md", target);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "new report\n");
    assert_int_equal(count(s->dir, ""), 1);
}

static void test_outdir_symlink_and_refusals(void **state)
{
    scratch *s = *state;
    char real[700], link[700], path[900], text[64];
    assert_int_equal(mkdir(at(s, "real", real), 0755), 0);
    assert_int_equal(symlink("real", at(s, "link", link)), 0);
    tirenv_outdir *d;
    tirenv_diag diag;
    assert_int_equal(tirenv_outdir_begin(link, &d, &diag), TIRENV_OK);
    snprintf(path, sizeof path, "%s/x.txt", tirenv_outdir_path(d));
    assert_int_equal(put(path, "via link\n"), TIRENV_OK);
    assert_int_equal(tirenv_outdir_commit(d, &diag), TIRENV_OK);
    struct stat st;
    assert_int_equal(lstat(link, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    snprintf(path, sizeof path, "%s/x.txt", real);
    read_text(path, text, sizeof text);
    assert_string_equal(text, "via link\n");

    char file[700];
    write_text(at(s, "file", file), "a file");
    assert_int_equal(tirenv_outdir_begin(file, &d, &diag), TIRENV_EINVAL);
    assert_null(d);
    assert_non_null(strstr(diag.message, "not a directory"));
    assert_int_equal(tirenv_outdir_begin(".", &d, &diag), TIRENV_EINVAL);
    /* A FIFO inside cannot be carried over: refused, the directory untouched. */
    snprintf(path, sizeof path, "%s/fifo", real);
    assert_int_equal(mkfifo(path, 0644), 0);
    assert_int_equal(tirenv_outdir_begin(real, &d, &diag), TIRENV_EINVAL);
    assert_non_null(strstr(diag.message, "FIFO"));
    assert_int_equal(count(s->dir, "tirenv-tmp"), 0);
}

/* The tree removal the signal handler uses: nested directories, links not followed. */
static void test_rmtree(void **state)
{
    scratch *s = *state;
    char top[700], path[1000], keep[700];
    assert_int_equal(mkdir(at(s, "top", top), 0755), 0);
    write_text(at(s, "keep.txt", keep), "keep");
    char dir[800];
    snprintf(dir, sizeof dir, "%s", top);
    for (int i = 0; i < 5; ++i) {
        strcat(dir, "/d");
        assert_int_equal(mkdir(dir, 0755), 0);
        for (int j = 0; j < 300; ++j) {  /* more than one getdents64 batch */
            snprintf(path, sizeof path, "%s/file-with-a-longish-name-%03d", dir, j);
            write_text(path, "x");
        }
    }
    snprintf(path, sizeof path, "%s/link-out", top);
    assert_int_equal(symlink(keep, path), 0);
    assert_int_equal(tirenv_tmp__rmtree(top), 0);
    assert_int_equal(access(top, F_OK), -1);
    assert_int_equal(access(keep, F_OK), 0);
}

int main(void)
{
#define T(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)
    const struct CMUnitTest tests[] = {
        T(test_regular_file_temporary_name),
        T(test_symlink_target_replaced),
        T(test_character_device_written_through),
        T(test_fifo_written_through),
        T(test_descriptor_names),
        T(test_directory_refused),
        T(test_cleanup_on_signal),
        T(test_stale_entries_swept),
        T(test_outdir_new),
        T(test_outdir_replaces_whole),
        T(test_outdir_symlink_and_refusals),
        T(test_rmtree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
