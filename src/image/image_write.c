/* image_write.c - writing a rendered image in the format its path names
 * (image_formats.c), for every format the same safe way: the format's
 * writer fills a new temporary file beside the target, which is synced and
 * renamed over it, so a failure at any step leaves neither a partial image
 * nor a damaged earlier one, and is reported with the errno text of the
 * step that failed. Writing to a descriptor already open (standard output)
 * goes through the same writers and checks, straight into it. */
#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
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

/* Creates a new temporary file beside path, named path.tmp-PID-N. Opening
 * with mode 0666 lets the umask decide the final mode, as for any new file,
 * without touching the process-wide umask. */
static int create_temporary(const char *path, char **tmp_out)
{
    static atomic_uint counter;
    size_t size = strlen(path) + 64;
    char *tmp = malloc(size);
    if (!tmp) {
        errno = ENOMEM;
        return -1;
    }
    for (int attempt = 0; attempt < 100; attempt++) {
        snprintf(tmp, size, "%s.tmp-%ld-%u", path, (long)getpid(), atomic_fetch_add(&counter, 1));
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

/* The temporary file sits in the target's directory so that rename() is an
 * atomic replacement on one file system; it is synced first so that after a
 * crash the name points at either the old image or the whole new one. */
static glint_status write_replacing(const image_writer *writer, const glint_image *image,
                                    const glint_image_write_options *options, const char *path, glint_error *err)
{
    char *tmp = NULL;
    int fd = create_temporary(path, &tmp);
    if (fd < 0)
        return image_write_io_error(path, errno, err);
    glint_status st = writer->write(fd, image, options, path, err);
    int e = 0;
    if (st == GLINT_OK && fsync(fd) != 0)
        e = errno;
    if (close(fd) != 0 && e == 0)
        e = errno;
    if (st == GLINT_OK && e == 0 && rename(tmp, path) != 0)
        e = errno;
    if (st == GLINT_OK && e != 0)
        st = image_write_io_error(path, e, err);
    if (st != GLINT_OK)
        unlink(tmp);
    free(tmp);
    return st;
}

glint_status glint_image_write(const glint_image *image, const char *path, glint_error *err)
{
    return glint_image_write_ex(image, path, NULL, err);
}

/* The checks every write makes before its writer runs, with messages that
 * name the destination: an image to write and a known pixel type. */
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

    /* The directory keeps its trailing slash, which makes access() fail with
     * ENOTDIR when it names a file rather than pass it as writable. */
    const char *slash = strrchr(path, '/');
    size_t len = slash ? (size_t)(slash - path) + 1 : 0;
    char *dir = malloc(len + 2);
    if (!dir)
        return image_write_no_memory(path, err);
    if (len > 0) {
        memcpy(dir, path, len);
        dir[len] = '\0';
    } else {
        strcpy(dir, ".");
    }
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
