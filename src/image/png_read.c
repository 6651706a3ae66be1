/* png_read.c - decoding PNG files for image textures with libpng's
 * simplified API, into 8-bit sRGB RGB. A file may come from anywhere: the
 * length of each chunk before the image data is checked before libpng
 * allocates room for it, and the size in the header before any pixel
 * memory is allocated. */
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <png.h>
#include "core/error.h"
#include "image/image_reader.h"

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

static glint_status decode_png(texture_image *out, const void *data, size_t size, const char *what,
                               glint_error *err)
{
    glint_status checked = png_check_chunk_lengths(data, size, what, err);
    if (checked != GLINT_OK)
        return checked;
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, data, size))
        return image_read_corrupt(what, png.message, err);
    glint_status st = image_read_alloc(out, png.width, png.height, 4, true, what, err);
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
        return image_read_corrupt(what, png.message, err);
    }
    png_rgba_to_rgb(out);
    return GLINT_OK;
}

static const unsigned char png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

const image_reader png_reader = {"PNG", png_signature, sizeof png_signature, decode_png};
