/* exr_write.c - the OpenEXR format, through OpenEXR's C library
 * (OpenEXRCore): the linear image as it is, neither sRGB-encoded nor
 * clamped, as R, G and B channels of half (the default) or 32-bit float, in
 * scanline blocks of 16 rows compressed with ZIP (deflate: lossless, and
 * Blender's default) on every processor (exr_encode.c). The header holds only the attributes every OpenEXR
 * file must have; without a chromaticities attribute, readers take the
 * primaries to be Rec. 709's, which are linear sRGB's, glint's own.
 *
 * OpenEXR goes back to fill in the table of block offsets after the
 * blocks, which a pipe cannot do, so the file is made in memory and then
 * written in one pass, as PNG and PPM are: the same code for a file and
 * for standard output (glint_image_write_fd). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <OpenEXR/openexr.h>
#include "core/array.h"
#include "core/error.h"
#include "image/exr_encode.h"
#include "image/image_format.h"

/* The widest image written: OpenEXR steps from row to row of the caller's
 * pixels by a 32-bit count of bytes, 12 a pixel here. */
#define EXR_MAX_WIDTH (INT32_MAX / 12)

/* Deflate's level 4, the C++ library's default since OpenEXR 3.1.3: the C
 * library of Debian's 3.1.5 deflates at zlib's 6, in half again the time
 * for files of rendered half floats a tenth smaller. */
#define ZIP_LEVEL 4

/* The file as OpenEXR makes it, and what stopped it. */
typedef struct exr_sink {
    unsigned char *bytes;
    size_t size, cap;  /* bytes made (the furthest end written), room */
    bool no_memory;    /* the file outgrew the memory */
    char message[256]; /* OpenEXR's first error message, else empty */
} exr_sink;

/* OpenEXR writes the header, the blocks, then goes back to fill in the
 * table of block offsets: each write names its place in the file. */
static int64_t sink_write(exr_const_context_t ctxt, void *user, const void *buffer, uint64_t size, uint64_t offset,
                          exr_stream_error_func_ptr_t error_cb)
{
    exr_sink *sink = user;
    if (offset > SIZE_MAX - size || !array_reserve((void **)&sink->bytes, &sink->cap, (size_t)(offset + size), 1)) {
        sink->no_memory = true;
        return -1;
    }
    /* Nothing skips ahead, but a gap would be zeros, never old memory. */
    if (offset > sink->size)
        memset(sink->bytes + sink->size, 0, (size_t)offset - sink->size);
    memcpy(sink->bytes + offset, buffer, (size_t)size);
    if (offset + size > sink->size)
        sink->size = (size_t)(offset + size);
    return (int64_t)size;
}

/* OpenEXR would print its messages on stderr; the library prints nothing,
 * so the first is kept for the error. */
static void keep_message(exr_const_context_t ctxt, exr_result_t code, const char *message)
{
    void *user = NULL;
    exr_sink *sink;
    if (exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && (sink = user) != NULL && sink->message[0] == '\0')
        snprintf(sink->message, sizeof sink->message, "%s", message);
}

/* Defines the file's one part, *part, and writes the header. */
static exr_result_t define_header(exr_context_t ctxt, const glint_image *image, glint_exr_pixel pixel, int *part)
{
    static const char *const channels[] = {"R", "G", "B"};
    exr_pixel_type_t type = pixel == GLINT_EXR_FLOAT ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF;
    exr_result_t rv = exr_add_part(ctxt, NULL, EXR_STORAGE_SCANLINE, part);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_initialize_required_attr_simple(ctxt, *part, image->width, image->height, EXR_COMPRESSION_ZIP);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_set_zip_compression_level(ctxt, *part, ZIP_LEVEL);
    for (int c = 0; c < 3 && rv == EXR_ERR_SUCCESS; c++)
        rv = exr_add_channel(ctxt, *part, channels[c], type, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    return rv == EXR_ERR_SUCCESS ? exr_write_header(ctxt) : rv;
}

static glint_status failure(const exr_sink *sink, exr_result_t rv, const char *path, glint_error *err)
{
    if (sink->no_memory || rv == EXR_ERR_OUT_OF_MEMORY)
        return image_write_no_memory(path, err);
    return error_set(err, GLINT_ERR_IO, "cannot write '%s': OpenEXR: %s", path,
                     sink->message[0] ? sink->message : exr_get_default_error_message(rv));
}

static glint_status write_exr(int fd, const glint_image *image, const glint_image_write_options *options,
                              const char *path, glint_error *err)
{
    if (image->width > EXR_MAX_WIDTH)
        return error_set(err, GLINT_ERR_INVALID, "cannot write '%s': an OpenEXR image is at most %d pixels wide, got %d",
                         path, EXR_MAX_WIDTH, image->width);
    exr_sink sink = {0};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &sink;
    init.write_fn = sink_write;
    init.error_handler_fn = keep_message;
    exr_context_t ctxt = NULL;
    int part = 0;
    /* With a write function of its own, OpenEXR names the file in messages
     * only, and creates, replaces and removes nothing. */
    exr_result_t rv = exr_start_write(&ctxt, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS)
        rv = define_header(ctxt, image, options->exr_pixel, &part);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_encode_blocks(ctxt, part, image);
    /* Finishing writes the table of block offsets, and frees the context
     * whether or not the rest went well. */
    exr_result_t finished = ctxt ? exr_finish(&ctxt) : EXR_ERR_SUCCESS;
    if (rv == EXR_ERR_SUCCESS)
        rv = finished;
    glint_status st = rv == EXR_ERR_SUCCESS ? image_write_bytes(fd, sink.bytes, sink.size, path, err)
                                            : failure(&sink, rv, path, err);
    free(sink.bytes);
    return st;
}

static const char *const exr_extensions[] = {".exr", NULL};

const image_writer exr_writer = {
    {"OpenEXR", exr_extensions, "linear RGB, half or 32-bit float, unclamped, ZIP-compressed"}, write_exr};
