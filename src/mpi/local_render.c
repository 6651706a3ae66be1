/* local_render.c - a rank's share of the render on a thread of its own,
 * its tiles timed (local_render.h). */
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "core/error.h"
#include "mpi/local_render.h"

/* The tile a render thread took and when: one tile at a time per thread. */
static _Thread_local uint64_t taken_ns;

static uint64_t now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

static int timed_next(void *user)
{
    local_render *r = user;
    int tile = r->caller.next(r->caller.user);
    taken_ns = now_ns();
    return tile;
}

static void timed_done(void *user, int tile, const float *pixels, size_t stride)
{
    local_render *r = user;
    if (r->caller.done)
        r->caller.done(r->caller.user, tile, pixels, stride);
    atomic_fetch_add(&r->busy_ns, now_ns() - taken_ns);
}

static void *render_thread(void *arg)
{
    local_render *r = arg;
    r->status = render_tiles(r->scene, &r->options, &r->timed, &r->image, &r->stats, &r->err);
    atomic_store(&r->finished, true);
    return NULL;
}

bool local_render_start(local_render *r, const glint_scene *scene, const glint_render_options *options,
                        const render_feed *feed)
{
    r->scene = scene;
    r->options = *options;
    r->caller = *feed;
    r->timed = (render_feed){.next = timed_next, .done = timed_done, .user = r, .pixels = feed->pixels};
    atomic_init(&r->finished, false);
    atomic_init(&r->busy_ns, 0);
    r->status = GLINT_OK;
    memset(&r->err, 0, sizeof r->err);
    memset(&r->stats, 0, sizeof r->stats);
    r->image = (glint_image){0};
    int e = pthread_create(&r->thread, NULL, render_thread, r);
    if (e) {
        r->status = error_set(&r->err, GLINT_ERR_NOMEM, "cannot start the render thread: %s", strerror(e));
        return false;
    }
    return true;
}

bool local_render_finished(local_render *r)
{
    return atomic_load(&r->finished);
}

void local_render_join(local_render *r)
{
    pthread_join(r->thread, NULL);
}

rank_report local_render_report(local_render *r)
{
    rank_report rep = {.stats = {.rays = r->stats.rays,
                                 .samples = r->stats.samples,
                                 .nan_samples = r->stats.nan_samples,
                                 .seconds = r->stats.seconds,
                                 .busy = atomic_load(&r->busy_ns) * 1e-9,
                                 .tiles = r->stats.tiles_done,
                                 .threads = r->options.threads},
                       .status = r->status};
    if (r->status)
        snprintf(rep.message, sizeof rep.message, "%s", r->err.message);
    return rep;
}
