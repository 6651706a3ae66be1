/* open_file.c - opening a file glint reads, regular files only. A FIFO
 * opened for reading blocks until a writer comes, for ever in a hostile
 * model's buffer URI, so the open is non-blocking and the type checked on
 * the open descriptor (no window between a stat and the open); blocking
 * mode comes back for the reads, which a regular file never makes wait.
 * Opens go through the thread's file log (file_log.h) when it has one.
 * The files of /proc and /sys call themselves regular but have a size of
 * 0 or 4096 whatever they hold: they are refused as not regular. */
#define _GNU_SOURCE /* memfd_create */
#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/sendfile.h>
#include <unistd.h>
#include "core/file_log.h"
#include "core/open_file.h"
#ifdef __linux__
#include <linux/magic.h>
#include <sys/vfs.h>
#endif

/* True when the open file fd lies on a file system of made-up files. */
static bool pseudo_file(int fd)
{
#ifdef __linux__
    struct statfs fs;
    return fstatfs(fd, &fs) == 0 && (fs.f_type == PROC_SUPER_MAGIC || fs.f_type == SYSFS_MAGIC ||
                                     fs.f_type == DEBUGFS_MAGIC || fs.f_type == SECURITYFS_MAGIC);
#else
    (void)fd;
    return false;
#endif
}

/* open_file_read on the file system itself. */
static int open_regular(const char *path, struct stat *st, int *errnum)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    if (fd < 0) {
        *errnum = errno;
        return -1;
    }
    int flags;
    if (fstat(fd, st) != 0 || (flags = fcntl(fd, F_GETFL)) < 0)
        *errnum = errno;
    else if (S_ISDIR(st->st_mode))
        *errnum = EISDIR;
    else if (!S_ISREG(st->st_mode) || pseudo_file(fd))
        *errnum = 0;
    else if (fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0)
        *errnum = errno;
    else
        return fd;
    close(fd);
    return -1;
}

int open_file_read(const char *path, struct stat *st, int *errnum)
{
    int fd;
    if (file_log_replay_open(path, &fd, st, errnum))
        return fd;
    fd = open_regular(path, st, errnum);
    return file_log_note_open(path, fd, st, fd >= 0 ? 0 : *errnum);
}

FILE *open_file_stream(const char *path, struct stat *st, int *errnum)
{
    int fd = open_file_read(path, st, errnum);
    if (fd < 0)
        return NULL;
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        *errnum = errno;
        close(fd);
    }
    return f;
}

const char *open_file_reason(int errnum)
{
    return errnum ? strerror(errnum) : "not a regular file";
}

int open_file_copy(int fd, uint64_t offset, uint64_t size)
{
    int copy = memfd_create("glint-file", MFD_CLOEXEC);
    if (copy < 0)
        return -1;
    off_t from = (off_t)offset;
    for (uint64_t left = size; left > 0;) {
        ssize_t n = sendfile(copy, fd, &from, left < (1u << 30) ? (size_t)left : (1u << 30));
        if (n <= 0) {
            int e = n < 0 ? errno : EIO;
            close(copy);
            errno = e;
            return -1;
        }
        left -= (uint64_t)n;
    }
    if (lseek(copy, 0, SEEK_SET) != 0) {
        int e = errno;
        close(copy);
        errno = e;
        return -1;
    }
    return copy;
}
