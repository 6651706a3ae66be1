/* tile_outbox.h - a worker's finished tiles waiting to go to rank 0: its
 * render threads pack each tile's pixels into a PIXELS message as the tile
 * is finished (protocol.h), its MPI thread takes the messages and sends
 * them, waking as each comes. */
#ifndef GLINT_MPI_TILE_OUTBOX_H
#define GLINT_MPI_TILE_OUTBOX_H

#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>
#include "render/render_tiles.h"

/* One PIXELS message: a tile_header and the pixels, `size` bytes. */
typedef struct tile_message {
    struct tile_message *next;
    size_t size;
    unsigned char bytes[];
} tile_message;

typedef struct tile_outbox {
    pthread_mutex_t lock;
    pthread_cond_t filled;    /* signalled as each message is put */
    tile_message *first, *last;
    bool failed;              /* memory ran out packing a tile */
} tile_outbox;

/* An empty outbox. */
void tile_outbox_init(tile_outbox *b);

/* Frees the outbox and any message left in it. */
void tile_outbox_free(tile_outbox *b);

/* Packs finished tile `tile` of layout l, its pixels as the render feed's
 * done gives them, into a message at the end of the outbox. When memory
 * runs out the tile is lost and the outbox marked failed. */
void tile_outbox_put(tile_outbox *b, const render_layout *l, int tile, const float *pixels, size_t stride);

/* The oldest message, now the caller's to free; NULL when there is none. */
tile_message *tile_outbox_take(tile_outbox *b);

/* Waits until the outbox holds a message or `timeout_ns` has passed: the
 * MPI thread sleeps until a render thread finishes a tile. */
void tile_outbox_wait(tile_outbox *b, long timeout_ns);

/* Whether memory ran out packing a tile. */
bool tile_outbox_failed(tile_outbox *b);

#endif
