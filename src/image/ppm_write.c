/* ppm_write.c - the PPM format: binary P6 in sRGB, maxval 255 (8 bits a
 * channel) or, with bit_depth 16, 65535 (two bytes, high first). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/big_alloc.h"
#include "image/image_format.h"
#include "image/srgb.h"

static glint_status write_ppm(int fd, const glint_image *image, const glint_image_write_options *options,
                               const char *path, glint_error *err)
{
    int depth = options->bit_depth == 16 ? 16 : 8;
    char header[40];
    size_t header_size = (size_t)snprintf(header, sizeof header, "P6\n%d %d\n%d\n", image->width, image->height,
                                          depth == 16 ? 65535 : 255);
    size_t samples = (size_t)image->width * (size_t)image->height * 3, sample_bytes = (size_t)depth / 8;
    if (samples > (SIZE_MAX - header_size) / sample_bytes)
        return image_write_no_memory(path, err);
    unsigned char *bytes = big_alloc(header_size + samples * sample_bytes);
    if (!bytes)
        return image_write_no_memory(path, err);
    memcpy(bytes, header, header_size);
    srgb_encode_depth(bytes + header_size, image->pixels, samples, depth);
    glint_status st = image_write_bytes(fd, bytes, header_size + samples * sample_bytes, path, err);
    free(bytes);
    return st;
}

static const char *const ppm_extensions[] = {".ppm", NULL};

const image_writer ppm_writer = {{"PPM", ppm_extensions, "binary P6, 8-bit (or 16) sRGB, clamped to 0..1"}, write_ppm};
