/* image_write.c - writing a rendered linear image as an 8-bit sRGB PNG or
 * PPM file.
 *
 * The whole file is encoded in memory first, then written to a temporary
 * file beside the target, synced and renamed over it: a failure at any step
 * leaves neither a partial image nor a damaged earlier one, and every
 * failure, encoding or I/O, is reported with the errno text of the step that
 * failed. */
#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>
#include "core/error.h"
#include "core/processors.h"
#include "image/png_encode.h"
#include "image/srgb.h"

typedef enum image_format { FORMAT_UNKNOWN, FORMAT_PNG, FORMAT_PPM } image_format;

/* The bytes of a whole encoded file. */
typedef struct encoded_file {
    unsigned char *bytes;
    size_t size;
} encoded_file;

static image_format format_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    if (dot && strcasecmp(dot, ".png") == 0)
        return FORMAT_PNG;
    if (dot && strcasecmp(dot, ".ppm") == 0)
        return FORMAT_PPM;
    return FORMAT_UNKNOWN;
}

static glint_status unknown_format(const char *path, glint_error *err)
{
    return error_set(err, GLINT_ERR_INVALID,
                     "cannot write '%s': unknown image format (use .png or .ppm)", path);
}

static glint_status io_error(const char *path, int errnum, glint_error *err)
{
    return error_set(err, GLINT_ERR_IO, "cannot write '%s': %s", path, strerror(errnum));
}

static glint_status no_memory(const char *path, glint_error *err)
{
    return error_set(err, GLINT_ERR_NOMEM, "cannot write '%s': out of memory", path);
}

static size_t sample_count(const glint_image *image)
{
    return (size_t)image->width * (size_t)image->height * 3;
}

static void to_srgb_bytes(unsigned char *dst, const glint_image *image)
{
    srgb_encode(dst, image->pixels, sample_count(image));
}

static glint_status encode_ppm(const glint_image *image, encoded_file *out, const char *path,
                               glint_error *err)
{
    char header[40];
    size_t header_size = (size_t)snprintf(header, sizeof header, "P6\n%d %d\n255\n",
                                          image->width, image->height);
    out->size = header_size + sample_count(image);
    out->bytes = malloc(out->size);
    if (!out->bytes)
        return no_memory(path, err);
    memcpy(out->bytes, header, header_size);
    to_srgb_bytes(out->bytes + header_size, image);
    return GLINT_OK;
}

/* The rows deflate on a thread per processor. */
static glint_status encode_png(const glint_image *image, encoded_file *out, const char *path,
                               glint_error *err)
{
    if (image->width > PNG_ENCODE_MAX_SIDE || image->height > PNG_ENCODE_MAX_SIDE)
        return error_set(err, GLINT_ERR_INVALID,
                         "cannot write '%s': a PNG image is at most %d pixels wide and high, got %dx%d", path,
                         PNG_ENCODE_MAX_SIDE, image->width, image->height);
    if (!png_encode(image, processors_online(64), &out->bytes, &out->size))
        return no_memory(path, err);
    return GLINT_OK;
}

static int write_all(int fd, const unsigned char *bytes, size_t size)
{
    while (size > 0) {
        ssize_t n = write(fd, bytes, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return -1;
        bytes += n;
        size -= (size_t)n;
    }
    return 0;
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
static glint_status write_replacing(const char *path, const encoded_file *file, glint_error *err)
{
    char *tmp = NULL;
    int fd = create_temporary(path, &tmp);
    if (fd < 0)
        return io_error(path, errno, err);
    int e = 0;
    if (write_all(fd, file->bytes, file->size) != 0 || fsync(fd) != 0)
        e = errno;
    if (close(fd) != 0 && e == 0)
        e = errno;
    if (e == 0 && rename(tmp, path) != 0)
        e = errno;
    if (e != 0)
        unlink(tmp);
    free(tmp);
    return e != 0 ? io_error(path, e, err) : GLINT_OK;
}

glint_status glint_image_write(const glint_image *image, const char *path, glint_error *err)
{
    if (!path)
        return error_set(err, GLINT_ERR_INVALID, "cannot write an image without a path");
    image_format format = format_of(path);
    if (format == FORMAT_UNKNOWN)
        return unknown_format(path, err);
    if (!image || !image->pixels || image->width <= 0 || image->height <= 0)
        return error_set(err, GLINT_ERR_INVALID, "cannot write '%s': the image is empty", path);
    if ((size_t)image->width > SIZE_MAX / 3 / (size_t)image->height)
        return no_memory(path, err);

    encoded_file file = {0};
    glint_status st = format == FORMAT_PNG ? encode_png(image, &file, path, err)
                                           : encode_ppm(image, &file, path, err);
    if (st == GLINT_OK)
        st = write_replacing(path, &file, err);
    free(file.bytes);
    return st;
}

glint_status glint_image_check_path(const char *path, glint_error *err)
{
    if (!path)
        return error_set(err, GLINT_ERR_INVALID, "cannot write an image without a path");
    if (format_of(path) == FORMAT_UNKNOWN)
        return unknown_format(path, err);
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return io_error(path, EISDIR, err);

    /* The directory keeps its trailing slash, which makes access() fail with
     * ENOTDIR when it names a file rather than pass it as writable. */
    const char *slash = strrchr(path, '/');
    size_t len = slash ? (size_t)(slash - path) + 1 : 0;
    char *dir = malloc(len + 2);
    if (!dir)
        return no_memory(path, err);
    if (len > 0) {
        memcpy(dir, path, len);
        dir[len] = '\0';
    } else {
        strcpy(dir, ".");
    }
    int e = access(dir, W_OK | X_OK) != 0 ? errno : 0;
    free(dir);
    return e != 0 ? io_error(path, e, err) : GLINT_OK;
}

void glint_image_free(glint_image *image)
{
    if (!image)
        return;
    free(image->pixels);
    *image = (glint_image){0};
}
