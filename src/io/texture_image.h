/* texture_image.h - decoding PNG and JPEG images into linear float RGB for
 * image textures. */
#ifndef GLINT_IO_TEXTURE_IMAGE_H
#define GLINT_IO_TEXTURE_IMAGE_H

#include <stddef.h>
#include "glint.h"

/* A decoded image: rgb[3 * (y * width + x) + c], top row first, linear. */
typedef struct texture_image {
    int width, height;
    float *rgb;
} texture_image;

/* Decodes the PNG or JPEG file at path, told apart by its first bytes, not
 * its name. Alpha is ignored. On failure *out is left empty and err names
 * the file: GLINT_ERR_IO when it cannot be read, GLINT_ERR_INVALID when it
 * is not a PNG or JPEG, is corrupt or is too large, GLINT_ERR_NOMEM. */
glint_status texture_image_load_file(texture_image *out, const char *path, glint_error *err);

/* As texture_image_load_file, from size bytes at data; `what` names the
 * source in messages. */
glint_status texture_image_load_memory(texture_image *out, const void *data, size_t size,
                                       const char *what, glint_error *err);

/* Frees the pixels and empties the image. NULL is allowed. */
void texture_image_free(texture_image *img);

#endif
