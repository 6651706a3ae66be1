/* local_render.h - a glint-mpi rank's own share of the render: the render
 * back-end (render/render_tiles.h) run on a thread of its own, so that the
 * thread that called MPI_Init_thread stays free to talk to the other ranks
 * while the render threads work (MPI_THREAD_FUNNELED: they never call
 * MPI). It also times how long the render threads spent on tiles. */
#ifndef GLINT_MPI_LOCAL_RENDER_H
#define GLINT_MPI_LOCAL_RENDER_H

#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include "mpi/protocol.h"
#include "render/render_tiles.h"

typedef struct local_render {
    /* Set by local_render_start. */
    const glint_scene *scene;
    glint_render_options options;
    render_feed caller;       /* the feed the rank gave */
    render_feed timed;        /* the feed the render uses: the caller's, timed */
    pthread_t thread;
    atomic_bool finished;     /* render_tiles returned */
    atomic_uint_least64_t busy_ns; /* render threads' time from taking a tile to finishing it */
    /* render_tiles's results, to read once finished. */
    glint_status status;
    glint_error err;
    glint_image image;
    glint_render_stats stats;
} local_render;

/* Starts rendering scene with options, the tiles coming from and going to
 * feed (which, with options, must outlive the render). False, with r->err
 * saying why, when the thread cannot start. */
bool local_render_start(local_render *r, const glint_scene *scene, const glint_render_options *options,
                        const render_feed *feed);

/* Whether the render has returned (its feed gave no more tiles, it failed
 * or it was cancelled). */
bool local_render_finished(local_render *r);

/* Waits for the render to return; then r->status, r->err, r->image (the
 * caller's to free) and r->stats are its results. */
void local_render_join(local_render *r);

/* The rank's report of a joined render (protocol.h). */
rank_report local_render_report(local_render *r);

#endif
