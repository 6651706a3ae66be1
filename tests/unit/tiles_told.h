/* tiles_told.h - a glint_render_options.tile_done for tests: each tile it
 * is told of copied into an image of its own, with a count of how often
 * each pixel was told, so that a test can check the tiles were the image's
 * and each was told once (test_render.c, and tests/mpi_tiles.c under
 * mpirun). */
#ifndef GLINT_TESTS_TILES_TOLD_H
#define GLINT_TESTS_TILES_TOLD_H

#include <pthread.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

typedef struct tiles_told {
    pthread_mutex_t lock;
    int width, height, calls;
    float *pixels;            /* width x height pixels of 3 floats */
    int *told;                /* width x height counts */
} tiles_told;

/* Ready for a width x height image; false when memory ran out. */
static inline bool tiles_told_init(tiles_told *t, int width, int height)
{
    *t = (tiles_told){.width = width, .height = height,
                      .pixels = calloc((size_t)width * height * 3, sizeof(float)),
                      .told = calloc((size_t)width * height, sizeof(int))};
    pthread_mutex_init(&t->lock, NULL);
    return t->pixels && t->told;
}

static inline void tiles_told_free(tiles_told *t)
{
    pthread_mutex_destroy(&t->lock);
    free(t->pixels);
    free(t->told);
}

/* The tile_done: user is a tiles_told. */
static inline void tiles_told_note(void *user, int x0, int y0, int x1, int y1, const float *pixels, size_t stride)
{
    tiles_told *t = user;
    pthread_mutex_lock(&t->lock);
    t->calls++;
    for (int y = y0; y < y1; y++) {
        memcpy(t->pixels + 3 * ((size_t)y * t->width + x0), pixels + stride * (size_t)(y - y0),
               3 * sizeof(float) * (size_t)(x1 - x0));
        for (int x = x0; x < x1; x++)
            t->told[y * t->width + x]++;
    }
    pthread_mutex_unlock(&t->lock);
}

/* Whether every pixel was told of exactly once. */
static inline bool tiles_told_once_each(const tiles_told *t)
{
    for (int i = 0; i < t->width * t->height; i++)
        if (t->told[i] != 1)
            return false;
    return true;
}

#endif
