/* texture_image.c - decoding PNG (libpng's simplified API) and JPEG
 * (libjpeg-turbo) files or buffers into 8-bit sRGB RGB for image textures,
 * with the table that makes their bytes linear.
 *
 * Texture files may come from anywhere, so a corrupt or truncated file is an
 * error value, never a crash, an exit or a line on stderr, the size in a
 * header is checked before any pixel memory is allocated, and the length of
 * a PNG chunk before libpng allocates room for it. */
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <png.h>
#include <jpeglib.h>
#include <jerror.h>
#include "core/error.h"
#include "image/texture_image.h"

/* Each scan of a progressive JPEG is another pass over the whole image, and
 * a hostile file can hold thousands; libjpeg-turbo advises capping them. */
#define MAX_JPEG_SCANS 1000

static float srgb_byte_to_linear[256];
static pthread_once_t srgb_table_once = PTHREAD_ONCE_INIT;

static void srgb_table_build(void)
{
    for (int i = 0; i < 256; i++)
        srgb_byte_to_linear[i] = (float)glint_srgb_to_linear(i / 255.0);
}

static glint_status corrupt(const char *what, const char *reason, glint_error *err)
{
    return error_set(err, GLINT_ERR_INVALID, "texture '%s' is corrupt: %s", what, reason);
}

static glint_status check_size(unsigned long width, unsigned long height, const char *what,
                               glint_error *err)
{
    if (width > TEXTURE_IMAGE_MAX_SIDE || height > TEXTURE_IMAGE_MAX_SIDE ||
        width * height > TEXTURE_IMAGE_MAX_PIXELS)
        return error_set(err, GLINT_ERR_INVALID,
                         "texture '%s' is too large: %lux%lu (limit %lu a side, %lu pixels)",
                         what, width, height, TEXTURE_IMAGE_MAX_SIDE, TEXTURE_IMAGE_MAX_PIXELS);
    return GLINT_OK;
}

/* Room for `bytes` bytes a pixel; sizes must have passed check_size, which
 * keeps the product in range. */
static glint_status image_alloc(texture_image *img, unsigned long width, unsigned long height, size_t bytes,
                                const char *what, glint_error *err)
{
    img->srgb = img->owned = malloc((size_t)width * height * bytes);
    if (!img->owned)
        return error_set(err, GLINT_ERR_NOMEM, "cannot decode texture '%s': out of memory", what);
    img->width = (int)width;
    img->height = (int)height;
    img->linear = srgb_byte_to_linear;
    return GLINT_OK;
}

/* libpng has decoded RGBA bytes: each pixel moves down to its RGB place,
 * which never lies past its RGBA one, and the room left over is given back. */
static void png_rgba_to_rgb(texture_image *img)
{
    size_t n = (size_t)img->width * img->height;
    unsigned char *p = img->owned;
    for (size_t i = 0; i < n; i++) {
        p[3 * i] = p[4 * i];
        p[3 * i + 1] = p[4 * i + 1];
        p[3 * i + 2] = p[4 * i + 2];
    }
    unsigned char *fit = realloc(p, n ? 3 * n : 1);
    if (fit)
        img->srgb = img->owned = fit;
}

static bool is_letter(unsigned char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

/* Before the image data libpng reads each chunk whole, into a buffer of the
 * length the chunk claims, which it allocates and zeroes before reading
 * (2 GB for the header of a text chunk in a file of 45 bytes; past its own
 * limit it only warns). In memory no chunk is longer than the bytes after
 * its header, so one that claims to be is refused before libpng sees it.
 * The walk ends where libpng stops first: at a type that is not four
 * letters (refused by name, unread), and at the first IDAT, whose data is
 * inflated a piece at a time and after which nothing is read, so a file cut
 * short there keeps libpng's message. */
static glint_status png_check_chunk_lengths(const unsigned char *data, size_t size, const char *what,
                                            glint_error *err)
{
    size_t at = 8; /* past the signature */
    while (size - at >= 8) {
        const unsigned char *p = data + at;
        size_t length = (size_t)p[0] << 24 | (size_t)p[1] << 16 | (size_t)p[2] << 8 | p[3];
        const unsigned char *type = p + 4;
        if (!is_letter(type[0]) || !is_letter(type[1]) || !is_letter(type[2]) || !is_letter(type[3]) ||
            memcmp(type, "IDAT", 4) == 0 || memcmp(type, "IEND", 4) == 0)
            break;
        if (length > size - at - 8)
            return error_set(err, GLINT_ERR_INVALID,
                             "texture '%s' is corrupt: its %.4s chunk claims %zu bytes, but only %zu follow",
                             what, (const char *)type, length, size - at - 8);
        at += 8 + length + 4; /* header, data, CRC */
        if (at > size)
            break;
    }
    return GLINT_OK;
}

static glint_status decode_png(texture_image *out, const void *data, size_t size,
                               const char *what, glint_error *err)
{
    glint_status checked = png_check_chunk_lengths(data, size, what, err);
    if (checked != GLINT_OK)
        return checked;
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, data, size))
        return corrupt(what, png.message, err);
    glint_status st = check_size(png.width, png.height, what, err);
    if (st == GLINT_OK)
        st = image_alloc(out, png.width, png.height, 4, what, err);
    if (st != GLINT_OK) {
        png_image_free(&png);
        return st;
    }
    /* Alpha is read and dropped rather than composited: a texture keeps the
     * colour stored under transparent pixels, not that colour darkened. */
    png.format = PNG_FORMAT_RGBA;
    /* Otherwise libpng takes 16-bit files without gamma information to be
     * linear, when in practice they are sRGB like 8-bit ones. */
    png.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
    if (!png_image_finish_read(&png, NULL, out->owned, 0, NULL)) {
        png_image_free(&png);
        texture_image_free(out);
        return corrupt(what, png.message, err);
    }
    png_rgba_to_rgb(out);
    return GLINT_OK;
}

/* libjpeg reports errors through these callbacks; the struct starts with its
 * error manager so the manager's address is the struct's. */
typedef struct jpeg_failure {
    struct jpeg_error_mgr mgr;
    jmp_buf jump;
    char reason[JMSG_LENGTH_MAX];
} jpeg_failure;

static void jpeg_fail(j_common_ptr cinfo)
{
    jpeg_failure *fail = (jpeg_failure *)cinfo->err;
    cinfo->err->format_message(cinfo, fail->reason);
    longjmp(fail->jump, 1);
}

/* On damaged data libjpeg only warns and invents the missing pixels; a
 * texture that silently turns grey is worse than an error, so only warnings
 * about metadata are let through. Trace messages (level >= 0) are dropped. */
static void jpeg_emit(j_common_ptr cinfo, int level)
{
    int code = cinfo->err->msg_code;
    if (level < 0 && code != JWRN_JFIF_MAJOR && code != JWRN_ADOBE_XFORM && code != JWRN_BOGUS_ICC
        && code != JWRN_EXTRANEOUS_DATA)
        jpeg_fail(cinfo);
}

static void jpeg_output_nothing(j_common_ptr cinfo)
{
    (void)cinfo;
}

static void jpeg_limit_scans(j_common_ptr cinfo)
{
    if (((j_decompress_ptr)cinfo)->input_scan_number > MAX_JPEG_SCANS) {
        jpeg_failure *fail = (jpeg_failure *)cinfo->err;
        snprintf(fail->reason, sizeof fail->reason, "more than %d progressive scans",
                 MAX_JPEG_SCANS);
        longjmp(fail->jump, 1);
    }
}

static glint_status decode_jpeg(texture_image *out, const void *data, size_t size,
                                const char *what, glint_error *err)
{
    struct jpeg_decompress_struct cinfo;
    struct jpeg_progress_mgr progress = {.progress_monitor = jpeg_limit_scans};
    jpeg_failure fail;
    glint_status st;

    cinfo.err = jpeg_std_error(&fail.mgr);
    fail.mgr.error_exit = jpeg_fail;
    fail.mgr.emit_message = jpeg_emit;
    fail.mgr.output_message = jpeg_output_nothing;
    if (setjmp(fail.jump)) {
        jpeg_destroy_decompress(&cinfo);
        texture_image_free(out);
        return corrupt(what, fail.reason, err);
    }
    jpeg_create_decompress(&cinfo);
    cinfo.progress = &progress;
    jpeg_mem_src(&cinfo, data, (unsigned long)size);
    jpeg_read_header(&cinfo, TRUE);
    if (cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK)
        st = error_set(err, GLINT_ERR_INVALID,
                       "texture '%s' is a CMYK JPEG, which is not supported (save it as RGB)",
                       what);
    else
        st = check_size(cinfo.image_width, cinfo.image_height, what, err);
    if (st == GLINT_OK)
        st = image_alloc(out, cinfo.image_width, cinfo.image_height, 3, what, err);
    if (st != GLINT_OK) {
        jpeg_destroy_decompress(&cinfo);
        return st;
    }
    cinfo.out_color_space = JCS_RGB;
    jpeg_start_decompress(&cinfo);
    size_t row_bytes = (size_t)cinfo.output_width * 3;
    while (cinfo.output_scanline < cinfo.output_height) {
        JSAMPROW row = out->owned + row_bytes * cinfo.output_scanline;
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_decompress(&cinfo);
    jpeg_destroy_decompress(&cinfo);
    return GLINT_OK;
}

glint_status texture_image_load_memory(texture_image *out, const void *data, size_t size,
                                       const char *what, glint_error *err)
{
    static const unsigned char png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char jpeg_magic[3] = {0xff, 0xd8, 0xff};

    pthread_once(&srgb_table_once, srgb_table_build);
    *out = (texture_image){0};
    if (!what)
        what = "(memory)";
    if (size >= sizeof png_magic && memcmp(data, png_magic, sizeof png_magic) == 0)
        return decode_png(out, data, size, what, err);
    if (size >= sizeof jpeg_magic && memcmp(data, jpeg_magic, sizeof jpeg_magic) == 0)
        return decode_jpeg(out, data, size, what, err);
    return error_set(err, GLINT_ERR_INVALID, "texture '%s' is not a PNG or JPEG file", what);
}

static glint_status read_error(int fd, void *buf, const char *path, const char *reason,
                               glint_error *err)
{
    close(fd);
    free(buf);
    return error_set(err, GLINT_ERR_IO, "cannot read texture '%s': %s", path, reason);
}

/* Reads a whole regular file: its size bounds the read, which a pipe or a
 * device such as /dev/zero would not. */
static glint_status read_file(const char *path, unsigned char **data, size_t *size,
                              glint_error *err)
{
    struct stat st;
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK); /* a FIFO must not block */
    if (fd < 0)
        return error_set(err, GLINT_ERR_IO, "cannot open texture '%s': %s", path, strerror(errno));
    if (fstat(fd, &st) != 0)
        return read_error(fd, NULL, path, strerror(errno), err);
    if (!S_ISREG(st.st_mode))
        return read_error(fd, NULL, path, "not a regular file", err);
    if ((unsigned long long)st.st_size > TEXTURE_IMAGE_MAX_FILE) {
        close(fd);
        return error_set(err, GLINT_ERR_INVALID, "texture '%s' is too large: %llu bytes (limit %llu)", path,
                         (unsigned long long)st.st_size, (unsigned long long)TEXTURE_IMAGE_MAX_FILE);
    }
    size_t want = (size_t)st.st_size, got = 0;
    unsigned char *buf = malloc(want ? want : 1);
    if (!buf) {
        close(fd);
        return error_set(err, GLINT_ERR_NOMEM, "cannot read texture '%s': out of memory", path);
    }
    while (got < want) {
        ssize_t n = read(fd, buf + got, want - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return read_error(fd, buf, path, strerror(errno), err);
        if (n == 0)
            break; /* the file shrank: the decoder will call it truncated */
        got += (size_t)n;
    }
    close(fd);
    *data = buf;
    *size = got;
    return GLINT_OK;
}

glint_status texture_image_load_file(texture_image *out, const char *path, glint_error *err)
{
    unsigned char *data = NULL;
    size_t size = 0;
    *out = (texture_image){0};
    glint_status st = read_file(path, &data, &size, err);
    if (st != GLINT_OK)
        return st;
    st = texture_image_load_memory(out, data, size, path, err);
    free(data);
    return st;
}

texture_image texture_image_borrow(int width, int height, const unsigned char *srgb)
{
    pthread_once(&srgb_table_once, srgb_table_build);
    return (texture_image){.width = width, .height = height, .srgb = srgb, .linear = srgb_byte_to_linear};
}

void texture_image_free(texture_image *img)
{
    if (!img)
        return;
    free(img->owned);
    *img = (texture_image){0};
}
