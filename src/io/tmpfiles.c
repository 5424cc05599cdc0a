/* The temporary files and directories outputs are built in: names that say whose they are,
 * a registry that a signal handler empties, tree removal with async-signal-safe calls only,
 * the sweep of what a SIGKILLed run left, and symbolic-link resolution.
 *
 * Why the names carry host and pid: a killed run's temporary file must be removed by a later
 * run, but only when nobody is writing it any more. Two runs may write into one directory at
 * once (two terminals, a job array), and a directory may be shared between hosts (NFS), where
 * a pid means nothing. So a run removes an entry only if it was made on this host (a hash of
 * the host name) by a process that no longer exists (kill(pid, 0) fails with ESRCH); a live
 * process, another user's (EPERM) or another host's keeps its files. A reused pid only delays
 * the removal to a later run. Two runs writing the same target still race for it, as any
 * two writers do; neither sees half a file.
 * SPDX-License-Identifier: Apache-2.0 */
#define _GNU_SOURCE  /* syscall(SYS_getdents64), DT_DIR */
#include "io/tmpfiles.h"
#include "io/io.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

#include "tirenv/outfile.h"

/* ---- names ------------------------------------------------------------------------------ */

/* FNV-1a of the host name: 8 hex digits tell this host's temporary entries from others'. */
static uint32_t host_hash(void)
{
    char host[256] = "";
    gethostname(host, sizeof host - 1);
    uint32_t h = 2166136261u;
    for (const char *c = host; *c; ++c)
        h = (h ^ (unsigned char)*c) * 16777619u;
    return h;
}

static uint64_t splitmix64(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/* Not for secrecy: O_EXCL (or mkdir) refuses a name already taken and the caller draws again. */
static uint32_t random32(void)
{
    static atomic_uint counter;
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    const uint64_t seed = (uint64_t)t.tv_nsec ^ ((uint64_t)t.tv_sec << 30) ^
                          ((uint64_t)getpid() << 40) ^
                          ((uint64_t)atomic_fetch_add(&counter, 1) << 20);
    return (uint32_t)splitmix64(seed);
}

void tirenv_tmp__split(const char *path, char *dir, char *base)
{
    const char *slash = strrchr(path, '/');
    if (!slash) {
        strcpy(dir, ".");
        snprintf(base, TIRENV_TMP_PATH, "%s", path);
        return;
    }
    const size_t n = slash == path ? 1 : (size_t)(slash - path);  /* "/x": the root */
    memcpy(dir, path, n);
    dir[n] = '\0';
    snprintf(base, TIRENV_TMP_PATH, "%s", slash + 1);
}

int tirenv_tmp__name(const char *target, const char *mark, char buf[TIRENV_TMP_PATH])
{
    char dir[TIRENV_TMP_PATH], base[TIRENV_TMP_PATH];
    tirenv_tmp__split(target, dir, base);
    /* NAME_MAX bytes per name: ".", the mark (12), host (8), ".", pid (<= 10), ".", random
     * (8) leave 214 of a long name. */
    const size_t keep = 214;
    if (strlen(base) > keep)
        base[keep] = '\0';
    const int has_dir = strchr(target, '/') != NULL;
    const int n = snprintf(buf, TIRENV_TMP_PATH, "%s%s.%s%s%08x.%ld.%08x",
                           has_dir ? dir : "", has_dir && strcmp(dir, "/") ? "/" : "", base,
                           mark, (unsigned)host_hash(), (long)getpid(), (unsigned)random32());
    return n > 0 && n < TIRENV_TMP_PATH ? 0 : -1;
}

/* ---- the registry ----------------------------------------------------------------------- */

enum { SLOTS = 64 };
enum { SLOT_FREE, SLOT_BUSY, SLOT_LIVE };

_Static_assert(ATOMIC_INT_LOCK_FREE == 2, "the registry needs lock-free atomics: a signal "
                                          "handler reads it");

/* A slot is filled while BUSY and only read by the handler when LIVE, so the handler never
 * sees half a path; pid keeps a forked child (before its exec) from removing its parent's. */
static struct {
    atomic_int state;
    int is_dir;
    pid_t pid;
    char path[TIRENV_TMP_PATH];
} slots[SLOTS];

/* Set by the signal handler before it removes anything; creating counts the threads between
 * tirenv_tmp__create_begin and _end. With --jobs, the other threads run on while one handles
 * the signal: a worker that registered and then created its file after the handler's pass
 * left the file behind (1 run in 60 of 'sweep --jobs 2' under SIGTERM). Now the handler
 * waits for creations under way, and no new one starts. */
static atomic_int dying, creating;

int tirenv_tmp__create_begin(void)
{
    atomic_fetch_add(&creating, 1);
    if (atomic_load(&dying)) {
        atomic_fetch_sub(&creating, 1);
        return -1;
    }
    return 0;
}

void tirenv_tmp__create_end(void)
{
    atomic_fetch_sub(&creating, 1);
}

int tirenv_tmp__register(const char *path, int is_dir)
{
    if (strlen(path) >= TIRENV_TMP_PATH)
        return -1;
    for (int i = 0; i < SLOTS; ++i) {
        int expect = SLOT_FREE;
        if (atomic_compare_exchange_strong(&slots[i].state, &expect, SLOT_BUSY)) {
            strcpy(slots[i].path, path);
            slots[i].is_dir = is_dir;
            slots[i].pid = getpid();
            atomic_store(&slots[i].state, SLOT_LIVE);
            return i;
        }
    }
    return -1;
}

void tirenv_tmp__unregister(int slot)
{
    if (slot >= 0 && slot < SLOTS) {
        atomic_store(&slots[slot].state, SLOT_BUSY);
        atomic_store(&slots[slot].state, SLOT_FREE);
    }
}

/* ---- removal ------------------------------------------------------------------------------ */

/* What getdents64 returns: the kernel's struct linux_dirent64. */
typedef struct {
    uint64_t d_ino;
    int64_t d_off;
    unsigned short d_reclen;
    unsigned char d_type;
    char d_name[];
} tmp_dirent64;

/* Empties the open directory fd: unlinkat for everything, into subdirectories on the same
 * device (a mount point is left, and so is the directory holding it). getdents64 rather than
 * readdir: readdir may allocate, which a signal handler must not. Entries removed while
 * reading may make the kernel skip others, hence a few passes from the start. */
static void empty_dir(int fd, dev_t dev, int depth)
{
    for (int pass = 0; pass < 4; ++pass) {
        int left = 0;
        lseek(fd, 0, SEEK_SET);
        _Alignas(8) char buf[4096];
        long n;
        while ((n = syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0) {
            for (long off = 0; off < n;) {
                const tmp_dirent64 *d = (const tmp_dirent64 *)(buf + off);
                off += d->d_reclen;
                const char *name = d->d_name;
                if (name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0')))
                    continue;
                if (unlinkat(fd, name, 0) == 0)
                    continue;
                if (d->d_type != DT_DIR && d->d_type != DT_UNKNOWN) {
                    left = 1;
                    continue;
                }
                const int sub = openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
                struct stat st;
                if (sub >= 0 && depth < 32 && fstat(sub, &st) == 0 && st.st_dev == dev)
                    empty_dir(sub, dev, depth + 1);
                if (sub >= 0)
                    close(sub);
                if (unlinkat(fd, name, AT_REMOVEDIR) != 0)
                    left = 1;
            }
        }
        if (!left)
            return;
    }
}

int tirenv_tmp__rmtree(const char *path)
{
    if (unlink(path) == 0)
        return 0;
    if (errno != EISDIR && errno != EPERM)
        return -1;
    const int fd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return -1;
    struct stat st;
    if (fstat(fd, &st) == 0)
        empty_dir(fd, st.st_dev, 0);
    close(fd);
    return rmdir(path);
}

void tirenv_cleanup_on_signal(void)
{
    const pid_t self = getpid();
    /* If this thread was itself creating, the count never drops: wait at most 0.2 s. Its
     * file, if made, is registered already (registration comes first). */
    atomic_store(&dying, 1);
    for (int i = 0; i < 2000 && atomic_load(&creating) > 0; ++i) {
        const struct timespec pause = {0, 100000};
        nanosleep(&pause, NULL);
    }
    for (int i = 0; i < SLOTS; ++i)
        if (atomic_load(&slots[i].state) == SLOT_LIVE && slots[i].pid == self) {
            if (slots[i].is_dir)
                tirenv_tmp__rmtree(slots[i].path);
            else
                unlink(slots[i].path);
        }
}

/* ---- the sweep of stale entries ----------------------------------------------------------- */

/* Parses ".<base><mark><host>.<pid>.<random>" from the right; 1 with its parts if name is a
 * temporary name of either mark. */
static int parse_tmp_name(const char *name, int *is_old, size_t *base_len, uint32_t *host,
                          long *pid)
{
    const size_t n = strlen(name);
    const size_t mark_len = sizeof TIRENV_TMP_MARK - 1;
    if (name[0] != '.' || n < 1 + mark_len + 8 + 4)
        return 0;
    const char *r = strrchr(name, '.');  /* before the random part */
    const char *p = r;
    while (p > name && p[-1] != '.')
        --p;                             /* start of the pid */
    if (p <= name + 1 + mark_len + 8 || p == r)
        return 0;
    const char *h = p - 1 - 8;           /* start of the host hash */
    const char *mark = h - mark_len;
    if (memcmp(mark, TIRENV_TMP_MARK, mark_len) == 0)
        *is_old = 0;
    else if (memcmp(mark, TIRENV_OLD_MARK, mark_len) == 0)
        *is_old = 1;
    else
        return 0;
    char *end;
    const unsigned long hv = strtoul(h, &end, 16);
    if (end != p - 1)
        return 0;
    errno = 0;
    const long pv = strtol(p, &end, 10);
    if (end != r || pv <= 0 || errno)
        return 0;
    *base_len = (size_t)(mark - name - 1);
    *host = (uint32_t)hv;
    *pid = pv;
    return 1;
}

int tirenv_tmp__target_of(const char *entry, char *name, size_t n)
{
    int is_old;
    size_t base_len;
    uint32_t host;
    long pid;
    if (!parse_tmp_name(entry, &is_old, &base_len, &host, &pid) || is_old || base_len == 0 ||
        base_len >= n)
        return 0;
    memcpy(name, entry + 1, base_len);
    name[base_len] = '\0';
    return 1;
}

static int process_gone(long pid)
{
    return pid > 0 && pid <= INT_MAX && kill((pid_t)pid, 0) == -1 && errno == ESRCH;
}

/* Directories already swept by this process, in a ring: device, inode and birth time (a
 * directory made later with a freed inode is another one; where the file system records no
 * birth time, it counts as the same). */
enum { SWEPT = 64 };
typedef struct {
    uint32_t dev_major, dev_minor;
    uint64_t ino;
    int64_t btime_s;
    uint32_t btime_ns;
} dir_id;
static dir_id swept[SWEPT];
static size_t n_swept;
static pthread_mutex_t swept_lock = PTHREAD_MUTEX_INITIALIZER;

static int first_visit(const char *dir)
{
    struct statx sx;
    if (statx(AT_FDCWD, dir, 0, STATX_INO | STATX_BTIME, &sx) != 0)
        return 0;
    dir_id id = {sx.stx_dev_major, sx.stx_dev_minor, sx.stx_ino, 0, 0};
    if (sx.stx_mask & STATX_BTIME) {
        id.btime_s = sx.stx_btime.tv_sec;
        id.btime_ns = sx.stx_btime.tv_nsec;
    }
    pthread_mutex_lock(&swept_lock);
    int seen = 0;
    for (size_t i = 0; i < n_swept && i < SWEPT; ++i)
        if (swept[i].dev_major == id.dev_major && swept[i].dev_minor == id.dev_minor &&
            swept[i].ino == id.ino && swept[i].btime_s == id.btime_s &&
            swept[i].btime_ns == id.btime_ns)
            seen = 1;
    if (!seen)
        swept[n_swept++ % SWEPT] = id;
    pthread_mutex_unlock(&swept_lock);
    return !seen;
}

void tirenv_tmp__sweep_stale(const char *dir)
{
    const char *d = dir && *dir ? dir : ".";
    if (!first_visit(d))
        return;
    DIR *dp = opendir(d);
    if (!dp)
        return;
    const uint32_t me = host_hash();
    const struct dirent *e;
    while ((e = readdir(dp))) {
        int is_old;
        size_t base_len;
        uint32_t host;
        long pid;
        if (!parse_tmp_name(e->d_name, &is_old, &base_len, &host, &pid) || host != me ||
            !process_gone(pid))
            continue;
        char path[TIRENV_TMP_PATH], target[TIRENV_TMP_PATH];
        if (snprintf(path, sizeof path, "%s/%s", d, e->d_name) >= (int)sizeof path)
            continue;
        struct stat st;
        /* An old directory aside, whose target is missing: the run was killed between its
         * two renames (outdir.c); the old one goes back. */
        if (is_old && snprintf(target, sizeof target, "%s/%.*s", d, (int)base_len,
                               e->d_name + 1) < (int)sizeof target &&
            lstat(target, &st) != 0 && errno == ENOENT) {
            rename(path, target);
            continue;
        }
        tirenv_tmp__rmtree(path);
    }
    closedir(dp);
}

/* ---- symbolic links ----------------------------------------------------------------------- */

/* N if path names descriptor N of this process, else -1. */
static int fd_name(const char *path)
{
    if (strcmp(path, "/dev/stdin") == 0)
        return 0;
    if (strcmp(path, "/dev/stdout") == 0)
        return 1;
    if (strcmp(path, "/dev/stderr") == 0)
        return 2;
    char self[64];
    snprintf(self, sizeof self, "/proc/%ld/fd/", (long)getpid());
    const char *const prefixes[] = {"/dev/fd/", "/proc/self/fd/", "/proc/thread-self/fd/",
                                    self};
    for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; ++i) {
        const size_t n = strlen(prefixes[i]);
        if (strncmp(path, prefixes[i], n) != 0 || !path[n])
            continue;
        char *end;
        errno = 0;
        const long v = strtol(path + n, &end, 10);
        if (*end == '\0' && !errno && v >= 0 && v <= INT_MAX && path[n] >= '0' &&
            path[n] <= '9')
            return (int)v;
    }
    return -1;
}

int tirenv_tmp__resolve(const char *path, char out[TIRENV_TMP_PATH], int *fd,
                        tirenv_diag *diag)
{
    char cur[TIRENV_TMP_PATH];
    if (snprintf(cur, sizeof cur, "%s", path) >= (int)sizeof cur)
        return tirenv_error(diag, TIRENV_EINVAL, path, 0, "", "path is too long");
    for (int hops = 0;; ++hops) {
        *fd = fd_name(cur);
        struct stat st;
        if (*fd >= 0 || lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode)) {
            strcpy(out, cur);
            return TIRENV_OK;
        }
        if (hops == 40)
            return tirenv_error(diag, TIRENV_EIO, path, 0, "",
                                "too many levels of symbolic links");
        char dir[TIRENV_TMP_PATH], base[TIRENV_TMP_PATH];
        tirenv_tmp__split(cur, dir, base);
        /* The kernel's protected_symlinks rule, which following by hand would bypass: in a
         * sticky world-writable directory (/tmp), a link is followed only by its owner or
         * when it belongs to the directory's owner. Else another user's link there could
         * make this run's output replace a file of ours it points at. */
        struct stat dst;
        if (stat(dir, &dst) != 0)
            return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot examine %s: %s", dir,
                                strerror(errno));
        if ((dst.st_mode & S_ISVTX) && (dst.st_mode & S_IWOTH) && st.st_uid != geteuid() &&
            st.st_uid != dst.st_uid)
            return tirenv_error(diag, TIRENV_EIO, path, 0, "",
                                "refusing to follow the symbolic link %s: it belongs to "
                                "another user (uid %ld) in the sticky world-writable "
                                "directory %s, as the kernel's protected_symlinks would",
                                cur, (long)st.st_uid, dir);
        char link[TIRENV_TMP_PATH];
        const ssize_t n = readlink(cur, link, sizeof link - 1);
        if (n < 0)
            return tirenv_error(diag, TIRENV_EIO, path, 0, "", "cannot read the link %s: %s",
                                cur, strerror(errno));
        link[n] = '\0';
        int w;
        if (link[0] == '/' || !strchr(cur, '/'))
            w = snprintf(cur, sizeof cur, "%s", link);
        else
            w = snprintf(cur, sizeof cur, "%s%s%s", dir, strcmp(dir, "/") ? "/" : "", link);
        if (w < 0 || w >= (int)sizeof cur)
            return tirenv_error(diag, TIRENV_EINVAL, path, 0, "",
                                "the path its symbolic links name is too long");
    }
}
