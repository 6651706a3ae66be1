/* png_write.c - the PNG format: 8-bit (or 16) sRGB with an sRGB chunk, the rows
 * deflated on a thread per processor (png_encode.c). */
#include <stdlib.h>
#include "core/error.h"
#include "core/processors.h"
#include "image/image_format.h"
#include "image/png_encode.h"

static glint_status write_png(int fd, const glint_image *image, const glint_image_write_options *options,
                               const char *path, glint_error *err)
{
    if (image->width > PNG_ENCODE_MAX_SIDE || image->height > PNG_ENCODE_MAX_SIDE)
        return error_set(err, GLINT_ERR_INVALID,
                         "cannot write '%s': a PNG image is at most %d pixels wide and high, got %dx%d", path,
                         PNG_ENCODE_MAX_SIDE, image->width, image->height);
    unsigned char *bytes;
    size_t size;
    if (!png_encode(image, options->bit_depth == 16 ? 16 : 8, processors_online(64), &bytes, &size))
        return image_write_no_memory(path, err);
    glint_status st = image_write_bytes(fd, bytes, size, path, err);
    free(bytes);
    return st;
}

static const char *const png_extensions[] = {".png", NULL};

const image_writer png_writer = {{"PNG", png_extensions, "8-bit (or 16) sRGB, clamped to 0..1"}, write_png};
