/* tile_queue.c - a worker's tiles to render, from its MPI thread to its
 * render threads (tile_queue.h). */
#include <stdlib.h>
#include "mpi/tile_queue.h"

bool tile_queue_init(tile_queue *q, int capacity)
{
    q->tiles = malloc((size_t)capacity * sizeof *q->tiles);
    if (!q->tiles)
        return false;
    q->capacity = capacity;
    q->head = q->count = 0;
    q->closed = false;
    pthread_mutex_init(&q->lock, NULL);
    pthread_cond_init(&q->changed, NULL);
    return true;
}

void tile_queue_free(tile_queue *q)
{
    pthread_cond_destroy(&q->changed);
    pthread_mutex_destroy(&q->lock);
    free(q->tiles);
    q->tiles = NULL;
}

bool tile_queue_put(tile_queue *q, const int *tiles, int n)
{
    pthread_mutex_lock(&q->lock);
    bool fits = n <= q->capacity - q->count;
    for (int i = 0; fits && i < n; i++)
        q->tiles[(q->head + q->count++) % q->capacity] = tiles[i];
    pthread_cond_broadcast(&q->changed);
    pthread_mutex_unlock(&q->lock);
    return fits;
}

void tile_queue_close(tile_queue *q)
{
    pthread_mutex_lock(&q->lock);
    q->closed = true;
    pthread_cond_broadcast(&q->changed);
    pthread_mutex_unlock(&q->lock);
}

int tile_queue_take(tile_queue *q)
{
    pthread_mutex_lock(&q->lock);
    while (q->count == 0 && !q->closed)
        pthread_cond_wait(&q->changed, &q->lock);
    int tile = -1;
    if (q->count > 0) {
        tile = q->tiles[q->head];
        q->head = (q->head + 1) % q->capacity;
        q->count--;
    }
    pthread_mutex_unlock(&q->lock);
    return tile;
}

int tile_queue_count(tile_queue *q)
{
    pthread_mutex_lock(&q->lock);
    int n = q->count;
    pthread_mutex_unlock(&q->lock);
    return n;
}
