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
    b->first = b->last = NULL;
    b->failed = false;
}

void tile_outbox_free(tile_outbox *b)
{
    tile_message *m;
    while ((m = tile_outbox_take(b)) != NULL)
        free(m);
    pthread_cond_destroy(&b->filled);
    pthread_mutex_destroy(&b->lock);
}

void tile_outbox_put(tile_outbox *b, const render_layout *l, int tile, const float *pixels, size_t stride)
{
    int x0, y0, x1, y1;
    render_tile_bounds(l, tile, &x0, &y0, &x1, &y1);
    size_t row = 3 * (size_t)(x1 - x0), size = sizeof(tile_header) + row * (size_t)(y1 - y0) * sizeof(float);
    tile_message *m = malloc(sizeof *m + size);
    if (m) {
        m->next = NULL;
        m->size = size;
        tile_header h = {.tile = tile};
        memcpy(m->bytes, &h, sizeof h);
        float *out = (float *)(void *)(m->bytes + sizeof h);
        for (int y = y0; y < y1; y++)
            memcpy(out + row * (size_t)(y - y0), pixels + stride * (size_t)(y - y0), row * sizeof(float));
    }
    pthread_mutex_lock(&b->lock);
    if (!m)
        b->failed = true;
    else if (b->last)
        b->last->next = m;
    else
        b->first = m;
    if (m)
        b->last = m;
    pthread_cond_signal(&b->filled);
    pthread_mutex_unlock(&b->lock);
}

tile_message *tile_outbox_take(tile_outbox *b)
{
    pthread_mutex_lock(&b->lock);
    tile_message *m = b->first;
    if (m) {
        b->first = m->next;
        if (!b->first)
            b->last = NULL;
    }
    pthread_mutex_unlock(&b->lock);
    return m;
}

void tile_outbox_wait(tile_outbox *b, long timeout_ns)
{
    struct timespec until;
    clock_gettime(CLOCK_REALTIME, &until);
    until.tv_nsec += timeout_ns;
    until.tv_sec += until.tv_nsec / 1000000000L;
    until.tv_nsec %= 1000000000L;
    pthread_mutex_lock(&b->lock);
    if (!b->first && !b->failed)
        pthread_cond_timedwait(&b->filled, &b->lock, &until);
    pthread_mutex_unlock(&b->lock);
}

bool tile_outbox_failed(tile_outbox *b)
{
    pthread_mutex_lock(&b->lock);
    bool failed = b->failed;
    pthread_mutex_unlock(&b->lock);
    return failed;
}
