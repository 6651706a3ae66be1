/* ppm_write.c - the PPM format: binary P6, maxval 255, 8-bit sRGB. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/image_format.h"
#include "image/srgb.h"

static glint_status write_ppm(int fd, const glint_image *image, const glint_image_write_options *options,
                               const char *path, glint_error *err)
{
    char header[40];
    size_t header_size = (size_t)snprintf(header, sizeof header, "P6\n%d %d\n255\n", image->width, image->height);
    size_t samples = (size_t)image->width * (size_t)image->height * 3;
    unsigned char *bytes = malloc(header_size + samples);
    if (!bytes)
        return image_write_no_memory(path, err);
    memcpy(bytes, header, header_size);
    srgb_encode(bytes + header_size, image->pixels, samples);
    glint_status st = image_write_bytes(fd, bytes, header_size + samples, path, err);
    free(bytes);
    return st;
}

static const char *const ppm_extensions[] = {".ppm", NULL};

const image_writer ppm_writer = {{"PPM", ppm_extensions, "binary P6, 8-bit sRGB, clamped to 0..1"}, write_ppm};
