/* tile_outbox.c - finished tiles packed for rank 0, from a worker's render
 * threads to its MPI thread (tile_outbox.h). */
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "mpi/protocol.h"
#include "mpi/tile_outbox.h"

void tile_outbox_init(tile_outbox *b)
{
    pthread_mutex_init(&b->lock, NULL);
    pthread_cond_init(&b->filled, NULL);
    b->batch = (tile_batch){0};
    b->wanted = 1;
    b->failed = false;
}

void tile_outbox_free(tile_outbox *b)
{
    free(b->batch.bytes);
    pthread_cond_destroy(&b->filled);
    pthread_mutex_destroy(&b->lock);
}

/* Room for `more` bytes at the end of the batch, a new one made for
 * `tiles` such tiles if memory allows; false when memory ran out. */
static bool make_room(tile_batch *t, size_t more, int tiles)
{
    if (t->capacity - t->size >= more)
        return true;
    size_t capacity = t->capacity ? t->capacity : more * (size_t)(tiles > 1 ? tiles : 1);
    while (capacity - t->size < more)
        capacity *= 2;
    unsigned char *bytes = realloc(t->bytes, capacity);
    if (!bytes) /* huge tiles: room for this one is enough */
        bytes = realloc(t->bytes, capacity = t->size + more);
    if (!bytes)
        return false;
    t->bytes = bytes;
    t->capacity = capacity;
    return true;
}

void tile_outbox_put(tile_outbox *b, const render_layout *l, int tile, const float *pixels, size_t stride)
{
    int x0, y0, x1, y1;
    render_tile_bounds(l, tile, &x0, &y0, &x1, &y1);
    size_t row = 3 * (size_t)(x1 - x0), size = sizeof(tile_header) + row * (size_t)(y1 - y0) * sizeof(float);
    /* Packed under the lock: a tile's copy takes a microsecond or two, and
     * a message grows in place rather than being copied again to send. */
    pthread_mutex_lock(&b->lock);
    tile_batch *t = &b->batch;
    if (make_room(t, size, b->wanted)) {
        tile_header h = {.tile = tile};
        memcpy(t->bytes + t->size, &h, sizeof h);
        float *out = (float *)(void *)(t->bytes + t->size + sizeof h);
        for (int y = y0; y < y1; y++)
            memcpy(out + row * (size_t)(y - y0), pixels + stride * (size_t)(y - y0), row * sizeof(float));
        t->size += size;
        t->tiles++;
    } else {
        b->failed = true;
    }
    if (t->tiles >= b->wanted || b->failed)
        pthread_cond_signal(&b->filled);
    pthread_mutex_unlock(&b->lock);
}

bool tile_outbox_take(tile_outbox *b, tile_batch *out)
{
    pthread_mutex_lock(&b->lock);
    bool any = b->batch.tiles > 0;
    if (any) {
        *out = b->batch;
        b->batch = (tile_batch){0};
    }
    pthread_mutex_unlock(&b->lock);
    return any;
}

void tile_outbox_wait(tile_outbox *b, int tiles, long timeout_ns)
{
    struct timespec until;
    clock_gettime(CLOCK_REALTIME, &until);
    until.tv_nsec += timeout_ns;
    until.tv_sec += until.tv_nsec / 1000000000L;
    until.tv_nsec %= 1000000000L;
    pthread_mutex_lock(&b->lock);
    b->wanted = tiles;
    while (b->batch.tiles < tiles && !b->failed)
        if (pthread_cond_timedwait(&b->filled, &b->lock, &until))
            break;
    pthread_mutex_unlock(&b->lock);
}

bool tile_outbox_failed(tile_outbox *b)
{
    pthread_mutex_lock(&b->lock);
    bool failed = b->failed;
    pthread_mutex_unlock(&b->lock);
    return failed;
}
