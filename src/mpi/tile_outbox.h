/* tile_outbox.h - a worker's finished tiles waiting to go to rank 0: its
 * render threads pack each tile's pixels into the PIXELS message being
 * filled as the tile is finished (protocol.h), its MPI thread takes the
 * message and sends it, waking when it holds enough tiles to be worth a
 * message. */
#ifndef GLINT_MPI_TILE_OUTBOX_H
#define GLINT_MPI_TILE_OUTBOX_H

#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>
#include "render/render_tiles.h"

/* One PIXELS message: `tiles` tiles, each a tile_header and its pixels,
 * `size` bytes in all. */
typedef struct tile_batch {
    int tiles;
    size_t size, capacity;
    unsigned char *bytes;
} tile_batch;

typedef struct tile_outbox {
    pthread_mutex_t lock;
    pthread_cond_t filled;    /* signalled when the batch reaches `wanted` tiles */
    tile_batch batch;         /* the message being filled */
    int wanted;               /* the tiles the MPI thread waits for */
    bool failed;              /* memory ran out packing a tile */
} tile_outbox;

/* An empty outbox. */
void tile_outbox_init(tile_outbox *b);

/* Frees the outbox and any tiles left in it. */
void tile_outbox_free(tile_outbox *b);

/* Packs finished tile `tile` of layout l, its pixels as the render feed's
 * done gives them, at the end of the message being filled. When memory
 * runs out the tile is lost and the outbox marked failed. */
void tile_outbox_put(tile_outbox *b, const render_layout *l, int tile, const float *pixels, size_t stride);

/* The message filled so far, now the caller's to free (its bytes), the
 * outbox starting a new one; false, taking nothing, when it holds no tile. */
bool tile_outbox_take(tile_outbox *b, tile_batch *out);

/* Waits until the message holds at least `tiles` tiles, memory ran out,
 * or `timeout_ns` has passed: the MPI thread sleeps while the render
 * threads fill a message. */
void tile_outbox_wait(tile_outbox *b, int tiles, long timeout_ns);

/* Whether memory ran out packing a tile. */
bool tile_outbox_failed(tile_outbox *b);

#endif
