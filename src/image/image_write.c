/* image_write.c - writing a rendered image in the format its path names
 * (image_formats.c), for every format the same safe way: the format's
 * writer fills a new temporary file beside the target, which is synced and
 * renamed over it (over the file a symbolic link leads to, not the link),
 * with the mode, owner and group of the file it replaces, so a failure at
 * any step leaves neither a partial image nor a damaged earlier one, and
 * is reported with the errno text of the step that failed. Writing to a descriptor already open (standard output)
 * goes through the same writers and checks, straight into it. */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "core/error.h"
#include "image/image_format.h"

static glint_status unknown_format(const char *path, glint_error *err)
{
    char known[64];
    return error_set(err, GLINT_ERR_INVALID, "cannot write '%s': unknown image format (use %s)", path,
                     image_writer_extensions(known, sizeof known));
}

glint_status image_write_io_error(const char *path, int errnum, glint_error *err)
{
    return error_set(err, GLINT_ERR_IO, "cannot write '%s': %s", path, strerror(errnum));
}

glint_status image_write_no_memory(const char *path, glint_error *err)
{
    return error_set(err, GLINT_ERR_NOMEM, "cannot write '%s': out of memory", path);
}

glint_status image_write_bytes(int fd, const unsigned char *bytes, size_t size, const char *path,
                               glint_error *err)
{
    while (size > 0) {
        ssize_t n = write(fd, bytes, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return image_write_io_error(path, errno, err);
        bytes += n;
        size -= (size_t)n;
    }
    return GLINT_OK;
}

/* The file that writing `path` replaces: path itself, or where the
 * symbolic links it names lead (a link's target is replaced, never the
 * link), even to a file that does not exist yet. Malloc'd; NULL with errno
 * set on failure (ELOOP past 40 links, as the system counts). */
static char *final_target(const char *path)
{
    char *at = strdup(path);
    for (int hops = 0; at && hops <= 40; hops++) {
        struct stat st;
        if (lstat(at, &st) != 0 || !S_ISLNK(st.st_mode))
            return at;
        char link[PATH_MAX];
        ssize_t n = readlink(at, link, sizeof link - 1);
        if (n < 0) {
            free(at);
            return NULL;
        }
        link[n] = '\0';
        const char *slash = strrchr(at, '/');
        size_t dir = link[0] == '/' || !slash ? 0 : (size_t)(slash - at) + 1;
        char *next = malloc(dir + (size_t)n + 1);
        if (next) {
            memcpy(next, at, dir);
            memcpy(next + dir, link, (size_t)n + 1);
        }
        free(at);
        at = next;
    }
    if (at) {
        free(at);
        errno = ELOOP;
    } else {
        errno = ENOMEM;
    }
    return NULL;
}

/* The longest file name the directory of `path` takes. */
static size_t name_max(const char *path)
{
    const char *slash = strrchr(path, '/');
    char *dir = slash ? strndup(path, slash == path ? 1 : (size_t)(slash - path)) : strdup(".");
    long n = dir ? pathconf(dir, _PC_NAME_MAX) : -1;
    free(dir);
    return n > 0 ? (size_t)n : NAME_MAX;
}

/* Creates a new temporary file beside path, named path.tmp-PID-N, or
 * .glint-PID-N.tmp in its directory when that name would be too long (a
 * legal name of 250 characters has no room for the suffix). Opening with
 * mode 0666 lets the umask decide the mode of a new file, as for any,
 * without touching the process-wide umask. */
static int create_temporary(const char *path, char **tmp_out)
{
    static atomic_uint counter;
    const char *slash = strrchr(path, '/');
    size_t dir = slash ? (size_t)(slash - path) + 1 : 0, size = strlen(path) + 64;
    bool short_name = strlen(path + dir) + sizeof ".tmp-4294967295-4294967295" > name_max(path);
    char *tmp = malloc(size);
    if (!tmp) {
        errno = ENOMEM;
        return -1;
    }
    for (int attempt = 0; attempt < 100; attempt++) {
        unsigned n = atomic_fetch_add(&counter, 1);
        if (short_name)
            snprintf(tmp, size, "%.*s.glint-%ld-%u.tmp", (int)dir, path, (long)getpid(), n);
        else
            snprintf(tmp, size, "%s.tmp-%ld-%u", path, (long)getpid(), n);
        int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) {
            if (fd >= 0)
                *tmp_out = tmp;
            else
                free(tmp);
            return fd;
        }
    }
    free(tmp);
    errno = EEXIST;
    return -1;
}

/* Gives the new file fd what the file it replaces had: its owner and group
 * where the process may set them (each tried, failures kept quiet: a user
 * cannot give a file away), then its mode, last because a change of owner
 * clears the set-user-ID bits. A 0600 image stays private. */
static int keep_mode_of(int fd, const char *target)
{
    struct stat old, now;
    if (stat(target, &old) != 0 || !S_ISREG(old.st_mode) || fstat(fd, &now) != 0)
        return 0;
    if ((old.st_uid != now.st_uid || old.st_gid != now.st_gid) && fchown(fd, old.st_uid, old.st_gid) != 0 &&
        old.st_gid != now.st_gid && fchown(fd, (uid_t)-1, old.st_gid) != 0) {
        /* Neither the owner nor the group could be kept: the mode alone
         * must not hand the group's rights to another group. */
        old.st_mode &= ~(mode_t)(S_IRWXG | S_ISGID);
    }
    return fchmod(fd, old.st_mode & 07777);
}

/* The temporary file sits in the target's directory so that rename() is an
 * atomic replacement on one file system; it is synced first so that after a
 * crash the name points at either the old image or the whole new one. */
static glint_status write_replacing(const image_writer *writer, const glint_image *image,
                                    const glint_image_write_options *options, const char *path, glint_error *err)
{
    char *tmp = NULL, *target = final_target(path);
    if (!target)
        return image_write_io_error(path, errno, err);
    int fd = create_temporary(target, &tmp);
    if (fd < 0) {
        int e = errno;
        free(target);
        return image_write_io_error(path, e, err);
    }
    int e = keep_mode_of(fd, target) != 0 ? errno : 0;
    glint_status st = e ? GLINT_OK : writer->write(fd, image, options, path, err);
    if (st == GLINT_OK && e == 0 && fsync(fd) != 0)
        e = errno;
    if (close(fd) != 0 && e == 0)
        e = errno;
    if (st == GLINT_OK && e == 0 && rename(tmp, target) != 0)
        e = errno;
    if (st == GLINT_OK && e != 0)
        st = image_write_io_error(path, e, err);
    if (st != GLINT_OK)
        unlink(tmp);
    free(tmp);
    free(target);
    return st;
}

glint_status glint_image_write(const glint_image *image, const char *path, glint_error *err)
{
    return glint_image_write_ex(image, path, NULL, err);
}

/* The checks every write makes before its writer runs, with messages that
 * name the destination: an image to write, a known pixel type and bit
 * depth. */
static glint_status check_write(const glint_image *image, const glint_image_write_options *options, const char *name,
                                glint_error *err)
{
    if (!image || !image->pixels || image->width <= 0 || image->height <= 0)
        return error_set(err, GLINT_ERR_INVALID, "cannot write '%s': the image is empty", name);
    if ((size_t)image->width > SIZE_MAX / 3 / (size_t)image->height)
        return image_write_no_memory(name, err);
    if (options->exr_pixel != GLINT_EXR_HALF && options->exr_pixel != GLINT_EXR_FLOAT)
        return error_set(err, GLINT_ERR_INVALID, "cannot write '%s': unknown OpenEXR pixel type %d", name,
                         (int)options->exr_pixel);
    if (options->bit_depth != 0 && options->bit_depth != 8 && options->bit_depth != 16)
        return error_set(err, GLINT_ERR_INVALID, "cannot write '%s': bit depth %d is neither 8 nor 16", name,
                         options->bit_depth);
    return GLINT_OK;
}

static const glint_image_write_options default_options = {.exr_pixel = GLINT_EXR_HALF};

glint_status glint_image_write_ex(const glint_image *image, const char *path,
                                  const glint_image_write_options *options, glint_error *err)
{
    if (!path)
        return error_set(err, GLINT_ERR_INVALID, "cannot write an image without a path");
    const image_writer *writer = image_writer_for_path(path);
    if (!writer)
        return unknown_format(path, err);
    if (!options)
        options = &default_options;
    glint_status st = check_write(image, options, path, err);
    return st ? st : write_replacing(writer, image, options, path, err);
}

glint_status glint_image_write_fd(const glint_image *image, int fd, const glint_image_format *format,
                                  const glint_image_write_options *options, const char *name, glint_error *err)
{
    if (!name)
        name = "<output>";
    const image_writer *writer = format ? image_writer_for_format(format) : NULL;
    if (!writer)
        return error_set(err, GLINT_ERR_INVALID, "cannot write '%s': no such image format", name);
    if (!options)
        options = &default_options;
    glint_status st = check_write(image, options, name, err);
    return st ? st : writer->write(fd, image, options, name, err);
}

glint_status glint_image_check_path(const char *path, glint_error *err)
{
    if (!path)
        return error_set(err, GLINT_ERR_INVALID, "cannot write an image without a path");
    if (!image_writer_for_path(path))
        return unknown_format(path, err);
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return image_write_io_error(path, EISDIR, err);
    char *target = final_target(path);
    if (!target)
        return image_write_io_error(path, errno, err);

    /* The directory keeps its trailing slash, which makes access() fail with
     * ENOTDIR when it names a file rather than pass it as writable. */
    const char *slash = strrchr(target, '/');
    size_t len = slash ? (size_t)(slash - target) + 1 : 0;
    char *dir = malloc(len + 2);
    if (!dir) {
        free(target);
        return image_write_no_memory(path, err);
    }
    if (len > 0) {
        memcpy(dir, target, len);
        dir[len] = '\0';
    } else {
        strcpy(dir, ".");
    }
    free(target);
    int e = access(dir, W_OK | X_OK) != 0 ? errno : 0;
    free(dir);
    return e != 0 ? image_write_io_error(path, e, err) : GLINT_OK;
}

void glint_image_free(glint_image *image)
{
    if (!image)
        return;
    free(image->pixels);
    *image = (glint_image){0};
}
