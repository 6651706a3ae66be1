/* follow.c - a glint-mpi worker: tiles asked for, rendered and sent back
 * (follow.h). It keeps up to four tiles a thread in hand, asking for more
 * once no more than two a thread are left: the answer can take two of its
 * MPI thread's and rank 0's idle sleeps (backoff.h), about as long as a
 * small tile takes, so its threads do not wait for it. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include "mpi/backoff.h"
#include "mpi/follow.h"
#include "mpi/local_render.h"
#include "mpi/tile_outbox.h"
#include "mpi/tile_queue.h"

/* The most finished tiles on their way to rank 0 at once. */
#define SENDS_IN_FLIGHT 16

typedef struct follower {
    render_layout layout;
    tile_queue queue;
    tile_outbox outbox;
    /* The tiles being sent, each kept until its send completes. */
    MPI_Request sends[SENDS_IN_FLIGHT];
    tile_message *sending[SENDS_IN_FLIGHT]; /* NULL: a free slot */
    int in_flight;
    volatile int stop;        /* the render's cancel flag */
    MPI_Comm comm;
} follower;

static int follow_next(void *user)
{
    return tile_queue_take(&((follower *)user)->queue);
}

static void follow_done(void *user, int tile, const float *pixels, size_t stride)
{
    follower *f = user;
    tile_outbox_put(&f->outbox, &f->layout, tile, pixels, stride);
}

/* Frees the tiles whose sends completed and starts sending the finished
 * tiles waiting, as many as there are free slots; whether anything
 * happened. The sends do not block: OpenMPI's blocking send of a tile
 * spins until rank 0 takes it, which took a worker's core from its render
 * threads for a third of the time (seed room, 2 ranks x 1 thread). */
static bool send_finished(follower *f)
{
    bool busy = false;
    for (int i = 0; i < SENDS_IN_FLIGHT; i++) {
        if (f->sending[i]) {
            int done = 0;
            MPI_Test(&f->sends[i], &done, MPI_STATUS_IGNORE);
            if (!done)
                continue;
            free(f->sending[i]);
            f->sending[i] = NULL;
            f->in_flight--;
            busy = true;
        }
        tile_message *m = tile_outbox_take(&f->outbox);
        if (!m)
            continue;
        f->sending[i] = m;
        f->in_flight++;
        MPI_Isend(m->bytes, (int)m->size, MPI_BYTE, 0, TAG_PIXELS, f->comm, &f->sends[i]);
        busy = true;
    }
    return busy;
}

/* Once the render has returned: sends every finished tile left, waiting
 * without spinning. With none in flight after send_finished, each free
 * slot found the outbox empty, and nothing adds to it any more. */
static void send_rest(follower *f)
{
    backoff b = {0};
    for (;;) {
        bool busy = send_finished(f);
        if (f->in_flight == 0)
            return;
        backoff_after(&b, busy);
    }
}

/* Receives rank 0's answer to this rank's ASK: its tiles into the queue,
 * or the queue closed when there are no more (or they do not fit: a rank 0
 * of another build). */
static void take_tiles(follower *f, const MPI_Status *st)
{
    int n = 0, tiles[MAX_BATCH];
    MPI_Get_count(st, MPI_INT, &n);
    if (n < 0 || n > MAX_BATCH) {
        MPI_Recv(NULL, 0, MPI_INT, 0, TAG_TILES, f->comm, MPI_STATUS_IGNORE);
        n = 0;
    } else {
        MPI_Recv(tiles, n, MPI_INT, 0, TAG_TILES, f->comm, MPI_STATUS_IGNORE);
    }
    if (n == 0 || !tile_queue_put(&f->queue, tiles, n))
        tile_queue_close(&f->queue);
}

/* Whether the render is to stop now: the rank's own signal, or rank 0's
 * STOP, taken in. */
static bool told_to_stop(const follower *f, const glint_render_options *options)
{
    int flag = 0;
    MPI_Iprobe(0, TAG_STOP, f->comm, &flag, MPI_STATUS_IGNORE);
    if (flag)
        MPI_Recv(NULL, 0, MPI_BYTE, 0, TAG_STOP, f->comm, MPI_STATUS_IGNORE);
    return flag || (options->cancel && *options->cancel);
}

rank_report follow_render(MPI_Comm comm, const glint_scene *scene, const glint_render_options *options)
{
    if (!scene) {
        rank_report failed = {.status = GLINT_ERR_INVALID, .message = "it could not load the scene rank 0 loaded"};
        MPI_Send(&failed, sizeof failed, MPI_BYTE, 0, TAG_DONE, comm);
        return failed;
    }
    int threads = options->threads;
    glint_render_options own_options = *options;
    int want = 4 * threads < MAX_BATCH ? 4 * threads : MAX_BATCH;
    follower f = {.comm = comm};
    glint_error err = {0};
    local_render own = {0};
    rank_report report = {0};
    tile_outbox_init(&f.outbox);
    bool ready = !render_layout_for(scene, options->tile_size, &f.layout, &err) &&
                 tile_queue_init(&f.queue, 2 * threads + MAX_BATCH);
    render_feed feed = {.next = follow_next, .done = follow_done, .user = &f};
    own_options.cancel = &f.stop;
    if (ready && local_render_start(&own, scene, &own_options, &feed)) {
        bool asked = false;
        backoff b = {0};
        for (;;) {
            bool busy = send_finished(&f);
            if (local_render_finished(&own))
                break;
            if (!f.stop && told_to_stop(&f, options))
                f.stop = 1;
            if (!asked && !f.queue.closed && tile_queue_count(&f.queue) <= 2 * threads) {
                MPI_Send(&want, 1, MPI_INT, 0, TAG_ASK, comm);
                asked = true;
            }
            int flag = 0;
            MPI_Status st;
            MPI_Iprobe(0, TAG_TILES, comm, &flag, &st);
            if (flag) {
                take_tiles(&f, &st);
                asked = false;
            }
            backoff_after(&b, busy || flag);
        }
        local_render_join(&own);
        send_rest(&f);
        /* A render that failed may leave an answer on its way. */
        if (asked) {
            MPI_Status st;
            MPI_Probe(0, TAG_TILES, comm, &st);
            take_tiles(&f, &st);
        }
        report = local_render_report(&own);
        glint_image_free(&own.image);
        if (!report.status && tile_outbox_failed(&f.outbox))
            report = (rank_report){.status = GLINT_ERR_NOMEM, .message = "out of memory sending a tile"};
    } else {
        report = (rank_report){.status = ready ? own.status : GLINT_ERR_NOMEM};
        snprintf(report.message, sizeof report.message, "%s", ready ? own.err.message : "out of memory");
    }
    MPI_Send(&report, sizeof report, MPI_BYTE, 0, TAG_DONE, comm);
    if (ready)
        tile_queue_free(&f.queue);
    tile_outbox_free(&f.outbox);
    return report;
}
