/* image_reader.h - a texture image format glint reads: the record each
 * format's decoder file defines (its name, the bytes its files begin with
 * and its decode operation), which texture_image.c picks by those bytes
 * from its table, and the checks every decoder shares, so that their limits
 * and messages are the same. */
#ifndef GLINT_IMAGE_IMAGE_READER_H
#define GLINT_IMAGE_IMAGE_READER_H

#include <stddef.h>
#include "glint.h"
#include "image/texture_image.h"

/* Decodes the size bytes at data, which begin with the reader's signature,
 * into *out (empty on entry), as texture_image_load_memory promises: on
 * failure *out is left empty and err names `what`. */
typedef glint_status (*image_decode_fn)(texture_image *out, const void *data, size_t size, const char *what,
                                        glint_error *err);

typedef struct image_reader {
    const char *name;                /* "PNG", for messages */
    const unsigned char *signature;  /* the first bytes of every such file */
    size_t signature_size;
    image_decode_fn decode;
} image_reader;

/* "texture 'WHAT' is corrupt: REASON", as GLINT_ERR_INVALID. */
glint_status image_read_corrupt(const char *what, const char *reason, glint_error *err);

/* Gives img room for width x height pixels of `bytes` bytes each and
 * TEXEL_SLACK bytes more (which floats must keep), and its
 * size and sRGB table, once the size is within TEXTURE_IMAGE_MAX_SIDE,
 * TEXTURE_IMAGE_MAX_PIXELS and TEXTURE_IMAGE_MAX_BYTES: beyond,
 * GLINT_ERR_INVALID naming the limits, before anything is allocated.
 * `written_whole`: the decoder writes every pixel before it succeeds, so
 * the room is left as it comes, on huge pages when large (big_alloc).
 * Otherwise it is zeroed by the system as pages are touched, so a file
 * that claims a large image and ends early costs little memory. */
glint_status image_read_alloc(texture_image *img, unsigned long width, unsigned long height, size_t bytes,
                              bool written_whole, const char *what, glint_error *err);

#endif
