/* follow.c - a glint-mpi worker: tiles asked for, rendered and sent back
 * (follow.h). It asks for a hand of tiles once, and rank 0 sends one more
 * for each tile it sends back (protocol.h), so that its MPI thread need
 * not poll: it sleeps until its render threads have finished half its
 * hand, and sends those tiles in one message. The hand covers HOLD_NS of
 * rendering at the time its tiles have taken so far (at least four a
 * thread), so that the half left covers rank 0's longest wait to answer
 * (backoff.h) twice; it asks for more when its tiles turn out faster.
 *
 * Waking for each tile, and a message for each, took a worker's core from
 * its render thread 1,500 times in a 0.25 s render of the 1920x1080 bunny
 * (its MPI thread shares its core); 180 times now (bench/README.md). */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "mpi/backoff.h"
#include "mpi/follow.h"
#include "mpi/local_render.h"
#include "mpi/tile_outbox.h"
#include "mpi/tile_queue.h"

/* The rendering a worker's hand covers: four of rank 0's longest sleeps. */
#define HOLD_NS (4 * BACKOFF_MAX_NS)

/* How long the MPI thread sleeps waiting for finished tiles: short while
 * the hand is empty (tiles on their way) or once rank 0 has no more (each
 * tile then goes at once), long otherwise (to see a STOP). Sends in flight
 * move on at the next message: waking every 100 us for them cost the
 * render thread on its core 6% of the time (bunny and seed room, 2 ranks
 * on 2 cores, bench/README.md). */
#define WAIT_SHORT_NS 100000L
#define WAIT_LONG_NS 2000000L

/* The most messages of finished tiles on their way to rank 0 at once. */
#define SENDS_IN_FLIGHT 16

typedef struct follower {
    render_layout layout;
    tile_queue queue;
    tile_outbox outbox;
    /* The messages being sent, each kept until its send completes. */
    MPI_Request sends[SENDS_IN_FLIGHT];
    unsigned char *sending[SENDS_IN_FLIGHT]; /* NULL: a free slot */
    int in_flight;
    int given;                /* tiles rank 0 sent */
    int finished;             /* tiles taken from the outbox to send */
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

/* Frees the messages whose sends completed and starts sending the
 * finished tiles waiting, in one message, if a slot is free; whether
 * anything happened. The sends do not block: OpenMPI's blocking send of a
 * tile spins until rank 0 takes it, which took a worker's core from its
 * render threads for a third of the time (seed room, 2 ranks x 1 thread). */
static bool send_finished(follower *f)
{
    bool busy = false;
    int free_slot = -1;
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
        free_slot = i;
    }
    tile_batch m;
    if (free_slot < 0 || !tile_outbox_take(&f->outbox, &m))
        return busy;
    f->sending[free_slot] = m.bytes;
    f->in_flight++;
    f->finished += m.tiles;
    MPI_Isend(m.bytes, (int)m.size, MPI_BYTE, 0, TAG_PIXELS, f->comm, &f->sends[free_slot]);
    return true;
}

/* Once the render has returned: sends every finished tile left, waiting
 * without spinning long (the rank's cores are idle now). With none in
 * flight after send_finished, a free slot found the outbox empty, and
 * nothing adds to it any more. */
static void send_rest(follower *f)
{
    backoff b = {.max_ns = BACKOFF_IDLE_NS};
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
    else
        f->given += n;
}

/* How many tiles to hold: enough for `threads` threads to render for
 * HOLD_NS at the time a tile has taken so far (`busy_ns`, the threads' time
 * on the tiles finished), at least four a thread, at most MAX_BATCH. */
static int tiles_to_hold(const follower *f, int threads, uint64_t busy_ns)
{
    double tiles = f->finished > 0 && busy_ns > 0 ? (double)HOLD_NS * threads * f->finished / (double)busy_ns : 0;
    int hold = tiles > 4.0 * threads ? (int)tiles + 1 : 4 * threads;
    return hold < MAX_BATCH ? hold : MAX_BATCH;
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
    follower f = {.comm = comm};
    glint_error err = {0};
    local_render own = {0};
    rank_report report = {0};
    tile_outbox_init(&f.outbox);
    bool ready = !render_layout_for(scene, options->tile_size, &f.layout, &err) &&
                 tile_queue_init(&f.queue, 2 * threads + MAX_BATCH);
    render_feed feed = {.next = follow_next, .done = follow_done, .user = &f, .tiles_only = true};
    own_options.cancel = &f.stop;
    own_options.tile_done = NULL; /* rank 0's to call, for every rank's tiles */
    if (ready && local_render_start(&own, scene, &own_options, &feed)) {
        int hand = 0; /* the tiles asked for in all: what rank 0 keeps in this rank's hand */
        for (;;) {
            bool busy = send_finished(&f);
            if (local_render_finished(&own))
                break;
            /* A tile lost for want of memory fails the render at once. */
            if (!f.stop && (told_to_stop(&f, options) || tile_outbox_failed(&f.outbox)))
                f.stop = 1;
            int hold = tiles_to_hold(&f, threads, atomic_load(&own.busy_ns));
            if (!f.queue.closed && hold > hand) {
                int more = hold - hand;
                MPI_Send(&more, 1, MPI_INT, 0, TAG_ASK, comm);
                hand = hold;
            }
            int flag = 0;
            MPI_Status st;
            MPI_Iprobe(0, TAG_TILES, comm, &flag, &st);
            if (flag)
                take_tiles(&f, &st);
            if (busy || flag)
                continue;
            if (f.in_flight == SENDS_IN_FLIGHT) {
                struct timespec ts = {0, WAIT_SHORT_NS};
                nanosleep(&ts, NULL); /* no slot to send from: no wait on the outbox */
            } else if (f.queue.closed || tile_queue_count(&f.queue) == 0) {
                tile_outbox_wait(&f.outbox, 1, WAIT_SHORT_NS);
            } else {
                /* Half the hand, or every tile it still has once rank 0
                 * sends no more (the last of them then go at once). */
                int unsent = f.given - f.finished, half = hand / 2;
                int wanted = half < unsent ? half : unsent;
                tile_outbox_wait(&f.outbox, wanted > 1 ? wanted : 1, WAIT_LONG_NS);
            }
        }
        local_render_join(&own);
        send_rest(&f);
        /* Tiles sent for this rank after a failure or a STOP are left
         * unread: the render is over. */
        report = local_render_report(&own);
        glint_image_free(&own.image);
        if ((!report.status || report.status == GLINT_ERR_CANCELLED) && tile_outbox_failed(&f.outbox))
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
