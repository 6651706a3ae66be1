/* exr_encode.c - an OpenEXR file's blocks compressed on a thread per
 * processor and written in order. Each thread takes the next block; once
 * compressed, a block waits until the one before it is written, so the file
 * is the same bytes for any number of threads, and memory holds one block a
 * thread. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#include "core/parallel.h"
#include "core/processors.h"
#include "image/exr_encode.h"

/* Points each channel of the block at its samples among the image's
 * interleaved floats, from which OpenEXR converts them to the file's type. */
static void point_channels(exr_encode_pipeline_t *block, const glint_image *image)
{
    const float *row = image->pixels + 3 * (size_t)image->width * (size_t)block->chunk.start_y;
    for (int c = 0; c < block->channel_count; c++) {
        exr_coding_channel_info_t *channel = &block->channels[c];
        const char name = channel->channel_name[0];
        channel->user_data_type = EXR_PIXEL_FLOAT;
        channel->user_bytes_per_element = sizeof(float);
        channel->user_pixel_stride = 3 * sizeof(float);
        channel->user_line_stride = 3 * (int32_t)sizeof(float) * image->width;
        channel->encode_from_ptr = (const uint8_t *)(row + (name == 'R' ? 0 : name == 'G' ? 1 : 2));
    }
}

/* What the threads share. */
typedef struct exr_encoder {
    exr_context_t ctxt;
    int part;
    const glint_image *image;
    int rows, blocks;            /* rows a block, blocks in all */
    atomic_int next;             /* the next block to compress */
    pthread_mutex_t lock;
    pthread_cond_t turn;         /* signalled when a block is written or a thread fails */
    int written;                 /* blocks written so far, under lock */
    _Atomic exr_result_t failed; /* the first failure, else EXR_ERR_SUCCESS */
} exr_encoder;

/* A thread's block, which OpenEXR hands back to wait_turn. */
typedef struct exr_turn {
    exr_encoder *encoder;
    int block;
} exr_turn;

/* OpenEXR calls this between compressing a block and writing it. */
static exr_result_t wait_turn(exr_encode_pipeline_t *pipeline)
{
    const exr_turn *turn = pipeline->encoding_user_data;
    exr_encoder *e = turn->encoder;
    pthread_mutex_lock(&e->lock);
    while (e->written != turn->block && atomic_load(&e->failed) == EXR_ERR_SUCCESS)
        pthread_cond_wait(&e->turn, &e->lock);
    pthread_mutex_unlock(&e->lock);
    return atomic_load(&e->failed);
}

/* After a block: written (rv success), or the whole file failed. */
static void end_turn(exr_encoder *e, exr_result_t rv)
{
    pthread_mutex_lock(&e->lock);
    if (rv == EXR_ERR_SUCCESS)
        e->written++;
    else if (atomic_load(&e->failed) == EXR_ERR_SUCCESS)
        atomic_store(&e->failed, rv);
    pthread_cond_broadcast(&e->turn);
    pthread_mutex_unlock(&e->lock);
}

static void *encode_blocks(void *arg)
{
    exr_encoder *e = arg;
    exr_encode_pipeline_t pipeline = EXR_ENCODE_PIPELINE_INITIALIZER;
    exr_turn turn = {e, 0};
    bool ready = false;
    while (atomic_load(&e->failed) == EXR_ERR_SUCCESS && (turn.block = atomic_fetch_add(&e->next, 1)) < e->blocks) {
        exr_chunk_info_t chunk;
        exr_result_t rv = exr_write_scanline_chunk_info(e->ctxt, e->part, turn.block * e->rows, &chunk);
        if (rv == EXR_ERR_SUCCESS)
            rv = ready ? exr_encoding_update(e->ctxt, e->part, &chunk, &pipeline)
                       : exr_encoding_initialize(e->ctxt, e->part, &chunk, &pipeline);
        if (rv == EXR_ERR_SUCCESS)
            point_channels(&pipeline, e->image);
        if (rv == EXR_ERR_SUCCESS && !ready) {
            rv = exr_encoding_choose_default_routines(e->ctxt, e->part, &pipeline);
            pipeline.yield_until_ready_fn = wait_turn;
            pipeline.encoding_user_data = &turn;
            ready = rv == EXR_ERR_SUCCESS;
        }
        if (rv == EXR_ERR_SUCCESS)
            rv = exr_encoding_run(e->ctxt, e->part, &pipeline);
        end_turn(e, rv);
    }
    exr_encoding_destroy(e->ctxt, &pipeline);
    return NULL;
}

exr_result_t exr_encode_blocks(exr_context_t ctxt, int part, const glint_image *image)
{
    exr_encoder e = {.ctxt = ctxt, .part = part, .image = image};
    exr_result_t rv = exr_get_scanlines_per_chunk(ctxt, part, &e.rows);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    e.blocks = (image->height + e.rows - 1) / e.rows;
    atomic_init(&e.next, 0);
    atomic_init(&e.failed, EXR_ERR_SUCCESS);
    pthread_mutex_init(&e.lock, NULL);
    pthread_cond_init(&e.turn, NULL);
    int threads = processors_online(64);
    parallel_run(threads < e.blocks ? threads : e.blocks, encode_blocks, &e, 0);
    pthread_cond_destroy(&e.turn);
    pthread_mutex_destroy(&e.lock);
    return atomic_load(&e.failed);
}
