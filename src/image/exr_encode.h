/* exr_encode.h - writing the pixel blocks of an OpenEXR file on every
 * processor, the same bytes for any number of them. */
#ifndef GLINT_IMAGE_EXR_ENCODE_H
#define GLINT_IMAGE_EXR_ENCODE_H

#include <OpenEXR/openexr.h>
#include "glint.h"

/* Encodes every scanline block of part, whose header ctxt has written
 * (R, G and B channels, the image's size), from the image's interleaved
 * floats, converted to the channels' type, and writes them in order. The
 * first failure, else EXR_ERR_SUCCESS. */
exr_result_t exr_encode_blocks(exr_context_t ctxt, int part, const glint_image *image);

#endif
