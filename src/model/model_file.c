/* model_file.c - opening and reading a model file and the files it names:
 * only regular files, never for writing, and none larger than half the
 * machine's memory (a model is read whole, or its model built beside it).
 * A model may come from anyone, so the files it names must lie in its
 * folder or below: a buffer URI "../../../etc/passwd" would otherwise be
 * read and shown as vertices. */
#include <errno.h>
#include <limits.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "core/file_log.h"
#include "core/error.h"
#include "core/open_file.h"
#include "model/model_file.h"

uint64_t model_file_memory_limit(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? (uint64_t)pages * (uint64_t)page / 2 : 0;
}

glint_status model_file_open(const char *path, int *fd, size_t *size, glint_error *err)
{
    *size = 0;
    struct stat st;
    int errnum;
    *fd = open_file_read(path, &st, &errnum);
    if (*fd < 0) {
        error_set(err, GLINT_ERR_IO, errnum && errnum != EISDIR ? "%s: cannot open: %s" : "%s: cannot read: %s", path,
                  open_file_reason(errnum));
        errno = errnum;
        return GLINT_ERR_IO;
    }
    glint_status s = GLINT_OK;
    uint64_t limit = model_file_memory_limit();
    if ((uintmax_t)st.st_size >= SIZE_MAX)
        s = error_set(err, GLINT_ERR_NOMEM, "%s: too large to read", path);
    /* The file is read whole and its model built beside it: one larger
     * than half the memory is refused before reading, rather than found
     * out by the system (or its out-of-memory killer) halfway through. */
    else if (limit > 0 && (uint64_t)st.st_size > limit)
        s = error_set(err, GLINT_ERR_INVALID,
                      "%s: too large to import: %llu bytes, more than half of this machine's memory (%llu bytes)", path,
                      (unsigned long long)st.st_size, (unsigned long long)limit * 2);
    if (s) {
        close(*fd);
        *fd = -1;
        return s;
    }
    *size = (size_t)st.st_size;
    return GLINT_OK;
}

glint_status model_file_read_fd(int fd, size_t size, const char *path, unsigned char **data, glint_error *err)
{
    unsigned char *buf = malloc(size ? size : 1);
    size_t got = 0;
    glint_status s = buf ? GLINT_OK : error_set(err, GLINT_ERR_NOMEM, "%s: out of memory reading it", path);
    while (!s && got < size) {
        ssize_t r = read(fd, buf + got, size - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            s = error_set(err, GLINT_ERR_IO, "%s: cannot read: %s", path, r < 0 ? strerror(errno) : "file shrank");
        else
            got += (size_t)r;
    }
    if (s) {
        free(buf);
        buf = NULL;
    }
    *data = buf;
    return s;
}

glint_status model_file_read(const char *path, unsigned char **data, size_t *size, glint_error *err)
{
    int fd;
    *data = NULL;
    glint_status s = model_file_open(path, &fd, size, err);
    if (s)
        return s;
    s = model_file_read_fd(fd, *size, path, data, err);
    close(fd);
    if (s)
        *size = 0;
    return s;
}

char *model_file_path(const char *dir, const char *ref)
{
    size_t len = strlen(dir) + strlen(ref) + 2;
    char *path = malloc(len);
    if (!path)
        return NULL;
    size_t start = 0;
    if (ref[0] != '/' && dir[0] != '\0')
        start = (size_t)snprintf(path, len, "%s/", dir);
    snprintf(path + start, len - start, "%s", ref);
    /* Models made on Windows may separate folders with backslashes. */
    for (char *c = path + start; *c; c++)
        if (*c == '\\')
            *c = '/';
    return path;
}

/* True when `path` (resolved) is `dir` (resolved) or lies below it. */
static bool below(const char *dir, const char *path)
{
    size_t n = strlen(dir);
    if (n == 1) /* "/" */
        return true;
    return strncmp(path, dir, n) == 0 && (path[n] == '/' || path[n] == '\0');
}

glint_status model_file_check_inside(const char *dir, const char *path, const char *file, const char *what,
                                     const char *ref, glint_error *err)
{
    char real_dir[PATH_MAX], real_path[PATH_MAX];
    /* A file that does not resolve is left to the open, which says why. */
    if (!file_realpath(path, real_path))
        return GLINT_OK;
    if (!file_realpath(dir[0] ? dir : ".", real_dir))
        return error_set(err, GLINT_ERR_IO, "%s: cannot resolve its folder: %s", file, strerror(errno));
    if (below(real_dir, real_path))
        return GLINT_OK;
    return error_set(err, GLINT_ERR_INVALID, "%s: %s '%s' lies outside the model's folder (a model may name only files in it or below it)",
                     file, what, ref);
}
