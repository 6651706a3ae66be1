/* exr_read.c - decoding OpenEXR files for image textures with OpenEXR's C
 * library (OpenEXRCore), into linear float RGB: high dynamic range skies
 * and environments. Scanline and tiled single-part images with R, G and B
 * channels (or Y alone, grey) of any pixel type, each channel sampled at
 * every pixel; alpha and other channels are ignored. The file is read from
 * memory, its data window checked against the size limits before any
 * pixel memory is allocated, and every OpenEXR failure reported in its
 * words, never a crash or a message on stderr. */
#include <stdlib.h>
#include <string.h>
#include <openexr.h>
#include "core/error.h"
#include "image/image_reader.h"

typedef struct exr_memory {
    const unsigned char *data;
    size_t size;
} exr_memory;

static int64_t read_memory(exr_const_context_t ctxt, void *user, void *buffer, uint64_t sz, uint64_t offset,
                           exr_stream_error_func_ptr_t error_cb)
{
    (void)ctxt;
    (void)error_cb;
    const exr_memory *m = user;
    if (offset >= m->size)
        return 0;
    uint64_t n = m->size - offset < sz ? m->size - offset : sz;
    memcpy(buffer, m->data + offset, n);
    return (int64_t)n;
}

static int64_t memory_size(exr_const_context_t ctxt, void *user)
{
    (void)ctxt;
    return (int64_t)((const exr_memory *)user)->size;
}

/* OpenEXR's own reports would go to stderr: its reasons are in the codes. */
static void quiet(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    (void)code;
    (void)msg;
}

/* The channel of img's pixel that channel `name` fills: 0, 1, 2 for R, G,
 * B, 3 for Y (grey), -1 for one not read. */
static int channel_slot(const char *name)
{
    static const char *const names[] = {"R", "G", "B", "Y"};
    for (int i = 0; i < 4; i++)
        if (strcmp(name, names[i]) == 0)
            return i;
    return -1;
}

/* Where the channels glint does not read are decoded to. OpenEXR 3.1
 * picks an unpacker for three interleaved channels when the channels it
 * fills happen to be spaced like three (one grey Y among three, its pixel
 * stride three floats) and then writes through the others' pointers even
 * when they are NULL; a skipped channel therefore gets a real plane of its
 * own, reused by every skipped channel and grown as chunks need. */
typedef struct skipped_plane {
    float *values;
    size_t capacity;
} skipped_plane;

/* Points `channel` at plane, grown to the channel's samples in this chunk. */
static exr_result_t skip_channel(exr_coding_channel_info_t *channel, skipped_plane *plane)
{
    size_t columns = channel->width > 0 ? (size_t)channel->width : 1;
    size_t needed = columns * (channel->height > 0 ? (size_t)channel->height : 1);
    if (needed > plane->capacity) {
        float *grown = realloc(plane->values, needed * sizeof(float));
        if (!grown)
            return EXR_ERR_OUT_OF_MEMORY;
        plane->values = grown;
        plane->capacity = needed;
    }
    channel->decode_to_ptr = (uint8_t *)plane->values;
    channel->user_pixel_stride = sizeof(float);
    channel->user_line_stride = (int32_t)(sizeof(float) * columns);
    return EXR_ERR_SUCCESS;
}

/* Decodes chunk `chunk` (covering rows and columns of the data window from
 * (x0, y0)) into img through *decoder. */
static exr_result_t decode_chunk(exr_context_t ctxt, const exr_chunk_info_t *chunk, exr_decode_pipeline_t *decoder,
                                 bool *started, texture_image *img, int x0, int y0, bool grey, skipped_plane *plane)
{
    /* A chunk the file places outside the data window would be decoded
     * outside the pixels. */
    if (chunk->start_x < x0 || chunk->start_y < y0 || chunk->width < 0 || chunk->height < 0 ||
        (int64_t)chunk->start_x - x0 + chunk->width > img->width ||
        (int64_t)chunk->start_y - y0 + chunk->height > img->height)
        return EXR_ERR_CORRUPT_CHUNK;
    exr_result_t rv = *started ? exr_decoding_update(ctxt, 0, chunk, decoder)
                               : exr_decoding_initialize(ctxt, 0, chunk, decoder);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    float *pixels = (float *)img->owned;
    for (int c = 0; c < decoder->channel_count; c++) {
        exr_coding_channel_info_t *channel = &decoder->channels[c];
        channel->user_data_type = EXR_PIXEL_FLOAT;
        channel->user_bytes_per_element = sizeof(float);
        int slot = channel_slot(channel->channel_name);
        if (slot < 0 || (grey && slot != 3) || (!grey && slot == 3)) {
            if ((rv = skip_channel(channel, plane)) != EXR_ERR_SUCCESS)
                return rv;
            continue;
        }
        size_t row = (size_t)(chunk->start_y - y0), col = (size_t)(chunk->start_x - x0);
        channel->decode_to_ptr = (uint8_t *)(pixels + 3 * (row * (size_t)img->width + col) + (grey ? 0 : slot));
        channel->user_pixel_stride = 3 * sizeof(float);
        channel->user_line_stride = 3 * sizeof(float) * img->width;
    }
    if (!*started && (rv = exr_decoding_choose_default_routines(ctxt, 0, decoder)) != EXR_ERR_SUCCESS)
        return rv;
    *started = true;
    return exr_decoding_run(ctxt, 0, decoder);
}

/* Decodes every chunk of the one part of ctxt into img. */
static exr_result_t decode_chunks(exr_context_t ctxt, exr_storage_t storage, texture_image *img, int x0, int y0,
                                  bool grey)
{
    exr_decode_pipeline_t decoder = EXR_DECODE_PIPELINE_INITIALIZER;
    skipped_plane plane = {NULL, 0};
    bool started = false;
    exr_result_t rv = EXR_ERR_SUCCESS;
    if (storage == EXR_STORAGE_SCANLINE) {
        int32_t rows;
        rv = exr_get_scanlines_per_chunk(ctxt, 0, &rows);
        for (int y = y0; rv == EXR_ERR_SUCCESS && y < y0 + img->height; y += rows) {
            exr_chunk_info_t chunk;
            rv = exr_read_scanline_chunk_info(ctxt, 0, y, &chunk);
            if (rv == EXR_ERR_SUCCESS)
                rv = decode_chunk(ctxt, &chunk, &decoder, &started, img, x0, y0, grey, &plane);
        }
    } else {
        int32_t tile_w = 1, tile_h = 1;
        rv = exr_get_tile_sizes(ctxt, 0, 0, 0, &tile_w, &tile_h);
        if (rv == EXR_ERR_SUCCESS && (tile_w <= 0 || tile_h <= 0))
            rv = EXR_ERR_INVALID_ATTR;
        int64_t tiles_x = rv ? 0 : ((int64_t)img->width + tile_w - 1) / tile_w;
        int64_t tiles_y = rv ? 0 : ((int64_t)img->height + tile_h - 1) / tile_h;
        for (int64_t ty = 0; rv == EXR_ERR_SUCCESS && ty < tiles_y; ty++)
            for (int64_t tx = 0; rv == EXR_ERR_SUCCESS && tx < tiles_x; tx++) {
                exr_chunk_info_t chunk;
                rv = exr_read_tile_chunk_info(ctxt, 0, (int)tx, (int)ty, 0, 0, &chunk);
                if (rv == EXR_ERR_SUCCESS)
                    rv = decode_chunk(ctxt, &chunk, &decoder, &started, img, x0, y0, grey, &plane);
            }
    }
    exr_result_t done = exr_decoding_destroy(ctxt, &decoder);
    free(plane.values);
    return rv != EXR_ERR_SUCCESS ? rv : done;
}

/* Which of R, G, B and Y the part has, sampled at every pixel: *grey when
 * it has Y and not all of R, G and B. */
static const char *check_channels(exr_context_t ctxt, bool *grey)
{
    const exr_attr_chlist_t *list;
    if (exr_get_channels(ctxt, 0, &list) != EXR_ERR_SUCCESS)
        return "it has no channel list";
    unsigned found = 0;
    for (int c = 0; c < list->num_channels; c++) {
        int slot = channel_slot(list->entries[c].name.str);
        if (slot < 0)
            continue;
        if (list->entries[c].x_sampling != 1 || list->entries[c].y_sampling != 1)
            return "its colour channels are subsampled";
        found |= 1u << slot;
    }
    *grey = (found & 7) != 7;
    if (*grey && !(found & 8))
        return "it has neither R, G and B channels nor Y";
    return NULL;
}

static glint_status decode_exr(texture_image *out, const void *data, size_t size, const char *what,
                               glint_error *err)
{
    exr_memory m = {data, size};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &m;
    init.read_fn = read_memory;
    init.size_fn = memory_size;
    init.error_handler_fn = quiet;
    exr_context_t ctxt = NULL;
    exr_result_t rv = exr_start_read(&ctxt, what, &init);
    if (rv != EXR_ERR_SUCCESS) {
        exr_finish(&ctxt);
        return image_read_corrupt(what, exr_get_default_error_message(rv), err);
    }
    int parts = 0;
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    exr_attr_box2i_t window;
    bool grey = false;
    const char *problem = NULL;
    if (exr_get_count(ctxt, &parts) != EXR_ERR_SUCCESS || parts != 1)
        problem = "it is not an image of one part";
    else if (exr_get_storage(ctxt, 0, &storage) != EXR_ERR_SUCCESS ||
             (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED))
        problem = "it holds deep data, not an image";
    else if (exr_get_data_window(ctxt, 0, &window) != EXR_ERR_SUCCESS || window.max.x < window.min.x ||
             window.max.y < window.min.y)
        problem = "its data window is empty";
    else
        problem = check_channels(ctxt, &grey);
    if (problem) {
        exr_finish(&ctxt);
        return image_read_corrupt(what, problem, err);
    }
    unsigned long width = (unsigned long)((int64_t)window.max.x - window.min.x + 1);
    unsigned long height = (unsigned long)((int64_t)window.max.y - window.min.y + 1);
    glint_status st = image_read_alloc(out, width, height, 3 * sizeof(float), false, what, err);
    if (st) {
        exr_finish(&ctxt);
        return st;
    }
    out->hdr = out->owned;
    out->srgb = NULL;
    rv = decode_chunks(ctxt, storage, out, window.min.x, window.min.y, grey);
    exr_finish(&ctxt);
    if (rv != EXR_ERR_SUCCESS) {
        texture_image_free(out);
        return image_read_corrupt(what, exr_get_default_error_message(rv), err);
    }
    float *p = out->owned;
    size_t n = 3 * (size_t)width * height;
    for (size_t i = 0; i < n; i++) {
        if (grey && i % 3)
            p[i] = p[i - i % 3];
        /* Glint's colours are finite and not negative. */
        if (!(p[i] >= 0))
            p[i] = 0;
        else if (p[i] > 3.0e38f)
            p[i] = 3.0e38f;
    }
    return GLINT_OK;
}

static const unsigned char exr_signature[] = {0x76, 0x2f, 0x31, 0x01};

const image_reader exr_reader = {"OpenEXR", exr_signature, sizeof exr_signature, decode_exr};
