/* texture_image.c - image textures from files or buffers: the file read
 * whole, its format told by its first bytes from the table of readers (PNG
 * in png_read.c, JPEG in jpeg_read.c), decoded into 8-bit sRGB RGB, with
 * the table that makes those bytes linear.
 *
 * Texture files may come from anywhere, so a corrupt or truncated file is an
 * error value, never a crash, an exit or a line on stderr, and the size in a
 * header is checked before any pixel memory is allocated. */
#include <errno.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "core/big_alloc.h"
#include "core/error.h"
#include "core/open_file.h"
#include "core/word_list.h"
#include "image/image_reader.h"

/* The formats textures are read in, each decoded in a file of its own: the
 * first whose signature the bytes begin with decodes them. */
extern const image_reader png_reader, jpeg_reader, exr_reader;

static const image_reader *const readers[] = {&png_reader, &jpeg_reader, &exr_reader};

#define READER_COUNT ((int)(sizeof readers / sizeof readers[0]))

static float srgb_byte_to_linear[256];
static pthread_once_t srgb_table_once = PTHREAD_ONCE_INIT;
/* Bytes as numbers: byte / 255, for images that hold data. */
static float byte_to_unit[256];

static void srgb_table_build(void)
{
    for (int i = 0; i < 256; i++) {
        srgb_byte_to_linear[i] = (float)glint_srgb_to_linear(i / 255.0);
        byte_to_unit[i] = (float)(i / 255.0);
    }
}

texture_image texture_image_as_data(const texture_image *img)
{
    texture_image data = texture_image_share(img);
    if (data.srgb)
        data.linear = byte_to_unit;
    return data;
}

glint_status image_read_corrupt(const char *what, const char *reason, glint_error *err)
{
    return error_set(err, GLINT_ERR_INVALID, "texture '%s' is corrupt: %s", what, reason);
}

/* Refuses an image of width x height pixels of `bytes` bytes each past the
 * limits; the pixel limit given is the lower of the two the pixels meet. */
static glint_status check_size(unsigned long width, unsigned long height, size_t bytes, const char *what,
                               glint_error *err)
{
    unsigned long max_pixels = TEXTURE_IMAGE_MAX_BYTES / bytes;
    if (max_pixels > TEXTURE_IMAGE_MAX_PIXELS)
        max_pixels = TEXTURE_IMAGE_MAX_PIXELS;
    if (width > TEXTURE_IMAGE_MAX_SIDE || height > TEXTURE_IMAGE_MAX_SIDE || width * height > max_pixels)
        return error_set(err, GLINT_ERR_INVALID,
                         "texture '%s' is too large: %lux%lu (limit %lu a side, %lu pixels)",
                         what, width, height, TEXTURE_IMAGE_MAX_SIDE, max_pixels);
    return GLINT_OK;
}

glint_status image_read_alloc(texture_image *img, unsigned long width, unsigned long height, size_t bytes,
                              bool written_whole, const char *what, glint_error *err)
{
    glint_status st = check_size(width, height, bytes, what, err);
    if (st != GLINT_OK)
        return st;
    /* check_size keeps the product in range. */
    size_t room = (size_t)width * height * bytes + TEXEL_SLACK;
    img->srgb = img->owned = written_whole ? big_alloc(room) : calloc(room, 1);
    if (!img->owned)
        return error_set(err, GLINT_ERR_NOMEM, "cannot decode texture '%s': out of memory", what);
    memset((char *)img->owned + room - TEXEL_SLACK, 0, TEXEL_SLACK);
    img->width = (int)width;
    img->height = (int)height;
    img->linear = srgb_byte_to_linear;
    return GLINT_OK;
}

/* Sets *reader to the reader whose signature the size bytes at data begin
 * with; GLINT_ERR_INVALID naming `what` when there is none. */
static glint_status find_reader(const void *data, size_t size, const char *what, const image_reader **reader,
                                glint_error *err)
{
    for (int i = 0; i < READER_COUNT; i++)
        if (size >= readers[i]->signature_size &&
            memcmp(data, readers[i]->signature, readers[i]->signature_size) == 0) {
            *reader = readers[i];
            return GLINT_OK;
        }
    char names[64] = "";
    for (int i = 0; i < READER_COUNT; i++)
        word_list_append(names, sizeof names, readers[i]->name, i, READER_COUNT);
    return error_set(err, GLINT_ERR_INVALID, "texture '%s' is not a %s file", what, names);
}

glint_status texture_image_load_memory(texture_image *out, const void *data, size_t size,
                                       const char *what, glint_error *err)
{
    pthread_once(&srgb_table_once, srgb_table_build);
    *out = (texture_image){0};
    if (!what)
        what = "(memory)";
    const image_reader *reader;
    glint_status st = find_reader(data, size, what, &reader, err);
    if (!st)
        st = reader->decode(out, data, size, what, err);
    if (!st && (st = texture_image_build_levels(out, err)))
        texture_image_free(out);
    return st;
}

static glint_status read_error(int fd, void *buf, const char *path, const char *reason,
                               glint_error *err)
{
    close(fd);
    free(buf);
    return error_set(err, GLINT_ERR_IO, "cannot read texture '%s': %s", path, reason);
}

/* Opens the texture file at path for reading into *fd, with *st its
 * status: a regular file within TEXTURE_IMAGE_MAX_FILE. */
static glint_status open_texture(const char *path, int *fd, struct stat *st, glint_error *err)
{
    int errnum;
    *fd = open_file_read(path, st, &errnum);
    if (*fd < 0 && (errnum == 0 || errnum == EISDIR))
        return error_set(err, GLINT_ERR_IO, "cannot read texture '%s': %s", path, open_file_reason(errnum));
    if (*fd < 0)
        return error_set(err, GLINT_ERR_IO, "cannot open texture '%s': %s", path, strerror(errnum));
    if ((unsigned long long)st->st_size > TEXTURE_IMAGE_MAX_FILE) {
        close(*fd);
        return error_set(err, GLINT_ERR_INVALID, "texture '%s' is too large: %llu bytes (limit %llu)", path,
                         (unsigned long long)st->st_size, (unsigned long long)TEXTURE_IMAGE_MAX_FILE);
    }
    return GLINT_OK;
}

/* Reads a whole regular file: its size bounds the read, which a pipe or a
 * device such as /dev/zero would not. */
static glint_status read_file(const char *path, unsigned char **data, size_t *size,
                              glint_error *err)
{
    struct stat st;
    int fd;
    glint_status status = open_texture(path, &fd, &st, err);
    if (status)
        return status;
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

glint_status texture_image_check_file(const char *path, glint_error *err)
{
    struct stat st;
    int fd;
    glint_status status = open_texture(path, &fd, &st, err);
    if (status)
        return status;
    unsigned char head[16];
    ssize_t n;
    do
        n = read(fd, head, sizeof head);
    while (n < 0 && errno == EINTR);
    int errnum = errno;
    close(fd);
    if (n < 0)
        return error_set(err, GLINT_ERR_IO, "cannot read texture '%s': %s", path, strerror(errnum));
    const image_reader *reader;
    return find_reader(head, (size_t)n, path, &reader, err);
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
    texture_image_free_levels(img);
    *img = (texture_image){0};
}

void texture_image_free_levels(texture_image *img)
{
    if (img->owns_levels) {
        for (int k = 0; k < img->level_count - 1; k++)
            free(img->levels[k].owned);
        free(img->levels);
    }
    img->levels = NULL;
    img->level_count = 0;
    img->owns_levels = false;
}
