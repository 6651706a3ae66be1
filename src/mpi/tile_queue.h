/* tile_queue.h - the tiles a glint-mpi worker was given and has not begun:
 * its MPI thread puts the batches rank 0 sends, its render threads take
 * them one at a time (the render feed's next), waiting while it is empty
 * until more come or it is closed. */
#ifndef GLINT_MPI_TILE_QUEUE_H
#define GLINT_MPI_TILE_QUEUE_H

#include <pthread.h>
#include <stdbool.h>

typedef struct tile_queue {
    pthread_mutex_t lock;
    pthread_cond_t changed;
    int *tiles;               /* a ring of `capacity` */
    int capacity, head, count;
    bool closed;              /* no more will come */
} tile_queue;

/* An empty queue holding up to `capacity` tiles; false when memory runs
 * out. */
bool tile_queue_init(tile_queue *q, int capacity);

/* Frees the queue (no thread may be using it). */
void tile_queue_free(tile_queue *q);

/* Adds n tiles, in order; false, adding none, when they do not fit. */
bool tile_queue_put(tile_queue *q, const int *tiles, int n);

/* No tile will be added: takers find the queue's end once it is empty. */
void tile_queue_close(tile_queue *q);

/* The next tile, waiting while the queue is empty and open; -1 once it is
 * empty and closed. */
int tile_queue_take(tile_queue *q);

/* How many tiles wait in the queue. */
int tile_queue_count(tile_queue *q);

#endif
