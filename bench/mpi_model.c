/* mpi_model.c - glint-mpi past this machine, by simulation: the measured
 * time of every tile of a render (bench_tile_times's output) replayed
 * through glint-mpi's scheduler, as src/mpi/lead.c and src/mpi/follow.c
 * implement it, or through one of two alternatives to it, for 2 to 256
 * ranks over a network of a stated latency and bandwidth. It prints the
 * predicted wall time, speed-up and parallel efficiency, and how busy
 * rank 0's MPI thread is.
 *
 * What is simulated, event by event:
 * - The schedule (--schedule):
 *   pull (the default, glint-mpi's): one shared counter of tiles. Rank 0's
 *   render threads take tiles from it one at a time; a worker asks for a
 *   hand of tiles covering HOLD of rendering at the pace of its tiles so
 *   far (at least 4 x threads, at most MAX_BATCH), and again only for what
 *   its hand should grow by. Rank 0 answers an ASK with at most
 *   min(want, max(1, left / (2 x ranks))) and a PIXELS of k tiles with
 *   min(k, max(1, left / (2 x ranks))) more, so that the worker's hand
 *   stays full; once none are left, a worker is sent an empty TILES, once.
 *   static (Tachyon's): rank r renders tiles r, r + N, r + 2N, ... of N
 *   ranks; no message but the finished tiles and DONE.
 *   steal: rank r starts with the r-th of N contiguous blocks of tiles. A
 *   rank with no tile left to begin asks the rank holding the most (known
 *   to it for free, which favours stealing) for some; that rank's MPI
 *   thread answers on its next turn with the back half, rounded up, of
 *   the tiles it has not begun (none if it has none left by then, and the
 *   thief asks again). A rank that finds no tile left anywhere is done,
 *   and its MPI thread goes on answering asks (with none) until the end.
 * - A worker's finished tiles (tile_outbox.c): its render thread packs
 *   each into the one PIXELS message being filled, and its MPI thread
 *   sends all those packed so far as one message at each turn that finds
 *   any, in every schedule (in static and steal, whose MPI threads wake on
 *   backoff.h's sleeps alone, what was finished since the last turn).
 * - Every rank's MPI thread loop, one message taken a turn, with the idle
 *   sleeps of src/mpi/backoff.h (20 us doubling to 1 ms while its rank
 *   renders, to 50 us once its render threads have all ended; short again
 *   only while a thief awaits its answer), but a pull worker's while it
 *   renders: it sleeps until the message being filled holds half its hand
 *   (the tiles it asked for in all, at least 1), 2 ms at most, or, when it
 *   has no tile left to begin or rank 0 has no more, until it holds one,
 *   100 us at most: one message for half a hand rather than one a tile.
 *   Half a hand that takes longer than 2 ms (a one-thread worker's hand is
 *   its least, 4 tiles, once they take over 1 ms each) goes as it is
 *   finished, a tile or so a message. A worker whose render has ended sends
 *   the rest, waits (backoff.h's sleeps) until its sends are complete, then
 *   sends DONE. Each message an MPI thread sends or takes costs it
 *   --message-us, and pixels are copied at --copy-gbs (twice on rank 0: out
 *   of MPI, then into the image; once on a worker, by the render thread
 *   that finished the tile, into the message).
 * - Messages over links of --latency-us and --gbits: each rank sends and
 *   receives one message at a time at the link's bandwidth, so the tiles
 *   of all workers queue at rank 0's link. A send is complete once its
 *   last byte has left the rank's link (MPI's eager sends). A PIXELS
 *   message is its tiles, each an 8-byte header and 3 floats a pixel.
 * - The start-up (--startup broadcast, the default): rank 0 sends the
 *   scene's files (--file-bytes) down a binomial tree as its load opens
 *   them (at its start, for a scene of one model: the load waits while
 *   rank 0 sends), each rank sending to its children one after the other;
 *   a worker loads as they come, from when MPI_Bcast would return (it has
 *   forwarded the files). Every rank then takes the measured load time,
 *   builds its BVH (the measured set-up) and renders, its MPI loop (asking
 *   for tiles, in the pull queue) running as soon as its load is done. --startup
 *   loaded is the render alone as glint-mpi's summary times it today
 *   (every rank has loaded its scene from a shared folder; each builds its
 *   BVH, then renders); --startup none leaves out loads and BVH builds (the
 *   scheduler, the network and the tail alone). Every schedule has the
 *   same start-up.
 *
 * Not simulated: mpirun's launch, writing the image, MPI's rendezvous for
 * large messages, a worker's limit of 16 messages in flight, and the MPI
 * threads' time taken from the render threads (a rank is taken to have a
 * spare hardware thread for it); every rank's cores are as fast as the
 * measuring machine's.
 *
 *   bench_mpi_model TIMES.txt [--one-core S] [--ranks 2,4,...] [--threads N]
 *       [--schedule pull|static|steal] [--startup broadcast|loaded|none]
 *       [--latency-us 50] [--gbits 10] [--message-us 3] [--copy-gbs 5]
 *       [--file-bytes N]
 *
 * --one-core S scales the tiles so that one core takes S seconds for the
 * frame, load and set-up included (they are not scaled); without it the
 * tiles take what was measured. Prints the assumptions, a Markdown table
 * (ranks, wall s, speed-up, efficiency, rank 0's MPI thread busy, the
 * tiles rank 0 rendered, and the efficiency of --startup none) and, for 64
 * ranks, the longest load + set-up a rank may take for 90% efficiency. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_RANKS 4096
#define MAX_THREADS 256
#define MAX_BATCH 256            /* src/mpi/protocol.h */
#define BACKOFF_MIN 20e-6        /* src/mpi/backoff.h */
#define BACKOFF_MAX 1e-3
#define BACKOFF_IDLE 50e-6       /* backoff.h: the longest sleep once a rank's render is over */
#define HOLD (4 * BACKOFF_MAX)   /* src/mpi/follow.c: the rendering a worker's hand covers */
#define WAIT_SHORT 100e-6        /* follow.c: a worker's wait for finished tiles */
#define WAIT_LONG 2e-3
#define TILE_HEADER_BYTES 8      /* tile_header */
#define TARGET_RANKS 64          /* the target: 90% at 64 ranks */
#define TARGET_EFFICIENCY 0.9
#define REPORT_BYTES 568         /* a DONE message: rank_report */

/* What bench_tile_times measured. */
typedef struct measured {
    int width, height, tile_size, tiles;
    double load, setup;          /* seconds: glint_scene_load_file; the back-end until the first tile */
    double *seconds;             /* per tile */
    int *pixels;                 /* per tile */
} measured;

typedef enum startup { START_BROADCAST, START_LOADED, START_NONE } startup;

/* How the tiles are shared out among the ranks (--schedule). */
typedef enum scheduler { SCHEDULE_PULL, SCHEDULE_STATIC, SCHEDULE_STEAL } scheduler;

/* The assumptions of one simulation. */
typedef struct assumptions {
    int threads;                 /* render threads per rank */
    scheduler plan;              /* pull queue, static interleave or work stealing */
    startup start;
    double tile_scale;           /* each measured tile time is multiplied by it */
    double load, setup;          /* a rank's scene load and BVH set-up, seconds */
    double latency;              /* seconds per message */
    double bandwidth;            /* bytes per second of a link */
    double message_cost;         /* seconds of an MPI thread per message sent or taken */
    double copy_speed;           /* bytes per second of a memory copy */
    double file_bytes;           /* the scene's files, broadcast */
} assumptions;

enum message_kind { ASK, TILES, PIXELS, DONE };

/* A message on its way or waiting to be taken, of `bytes`. `count`: tiles
 * wanted (ASK, to rank 0 or, in work stealing, to any rank), given (TILES,
 * from `first` on), or brought back (PIXELS). */
typedef struct message {
    double arrival, bytes;
    enum message_kind kind;
    int from, count, first;
} message;

/* A first-in first-out list, of messages or of tile numbers. */
typedef struct fifo {
    void *items;
    size_t item_size;
    int head, count, capacity;
} fifo;

typedef struct rank_state {
    fifo inbox;                  /* messages, in the order they arrive */
    fifo queue;                  /* its tiles given and not begun (not rank 0's in the pull queue) */
    int packed;                  /* a worker's finished tiles in the message being filled */
    double packed_bytes;         /* and that message's bytes */
    bool asked, closed;          /* an ASK unanswered; no more tiles will come */
    bool told_none;              /* rank 0 sent it the empty TILES (pull queue) */
    int hand;                    /* a pull worker's tiles asked for in all */
    int rendered;                /* tiles its threads finished */
    double rendering;            /* seconds its threads spent on them */
    bool on_tiles;               /* a pull worker's MPI thread waits for packed tiles, */
    int wanted;                  /* this many */
    int turn;                    /* the MPI thread's turn to come: earlier ones are void */
    bool reported, finished;     /* a worker's DONE sent; the MPI loop ended */
    int waiting, ended;          /* render threads waiting for tiles; render threads ended */
    double sleep;                /* the MPI thread's next idle sleep (backoff.h) */
    double send_free, receive_free; /* when its link is free to send, to receive */
    double busy;                 /* seconds its MPI thread spent on messages */
} rank_state;

enum event_kind { THREAD_FREE, MPI_TURN };

/* A render thread that finished `tile` (-1: none) and takes the next, or
 * an MPI thread's turn number `tile`. `order` keeps events of one time in
 * the order they were made. */
typedef struct event {
    double time;
    long order;
    enum event_kind kind;
    int rank, tile;
} event;

typedef struct simulation {
    const measured *m;
    const assumptions *assumed;
    int ranks;
    rank_state *r;
    int next_tile;               /* the shared counter */
    int lead_tiles;              /* tiles rank 0 rendered */
    int reported;                /* DONE messages rank 0 took */
    double end;                  /* when rank 0's serve loop ended */
    event *heap;
    int events, heap_capacity;
    long order;
} simulation;

typedef struct result {
    double wall, one_core, mpi_busy;
    int lead_tiles;
} result;

/* Says what went wrong and exits with 1. */
_Noreturn static void die(const char *msg)
{
    fprintf(stderr, "bench_mpi_model: %s\n", msg);
    exit(1);
}

/* realloc, or the end of the program when memory runs out. */
static void *grow(void *p, size_t bytes)
{
    p = realloc(p, bytes);
    if (!p)
        die("out of memory");
    return p;
}

/* Adds a copy of *item at the end, growing the list when it is full. */
static void fifo_push(fifo *f, const void *item)
{
    if (f->count == f->capacity) {
        int capacity = f->capacity ? 2 * f->capacity : 16;
        char *items = grow(NULL, (size_t)capacity * f->item_size);
        for (int i = 0; i < f->count; i++)
            memcpy(items + (size_t)i * f->item_size,
                   (char *)f->items + (size_t)((f->head + i) % f->capacity) * f->item_size, f->item_size);
        free(f->items);
        *f = (fifo){.items = items, .item_size = f->item_size, .count = f->count, .capacity = capacity};
    }
    memcpy((char *)f->items + (size_t)((f->head + f->count) % f->capacity) * f->item_size, item, f->item_size);
    f->count++;
}

/* The first item, or NULL when the list is empty. */
static void *fifo_front(const fifo *f)
{
    return f->count ? (char *)f->items + (size_t)f->head * f->item_size : NULL;
}

/* Drops the first item (there is one). */
static void fifo_pop(fifo *f)
{
    f->head = (f->head + 1) % f->capacity;
    f->count--;
}

/* Takes the first tile of a list of tiles (there is one). */
static int pop_tile(fifo *f)
{
    int tile = *(int *)fifo_front(f);
    fifo_pop(f);
    return tile;
}

/* Whether x comes before y. */
static bool before(const event *x, const event *y)
{
    return x->time < y->time || (x->time == y->time && x->order < y->order);
}

/* Adds an event to the heap of those to come. */
static void schedule(simulation *s, double time, enum event_kind kind, int rank, int tile)
{
    if (s->events == s->heap_capacity) {
        s->heap_capacity = s->heap_capacity ? 2 * s->heap_capacity : 1024;
        s->heap = grow(s->heap, (size_t)s->heap_capacity * sizeof *s->heap);
    }
    int i = s->events++;
    s->heap[i] = (event){time, s->order++, kind, rank, tile};
    while (i > 0 && before(&s->heap[i], &s->heap[(i - 1) / 2])) {
        event e = s->heap[i];
        s->heap[i] = s->heap[(i - 1) / 2];
        s->heap[(i - 1) / 2] = e;
        i = (i - 1) / 2;
    }
}

/* Sets `rank`'s MPI thread's next turn at `time`, voiding any set before. */
static void turn_at(simulation *s, int rank, double time)
{
    schedule(s, time, MPI_TURN, rank, ++s->r[rank].turn);
}

/* Takes the earliest event from the heap (there is one). */
static event next_event(simulation *s)
{
    event first = s->heap[0];
    s->heap[0] = s->heap[--s->events];
    for (int i = 0;;) {
        int least = i, l = 2 * i + 1, r = l + 1;
        if (l < s->events && before(&s->heap[l], &s->heap[least]))
            least = l;
        if (r < s->events && before(&s->heap[r], &s->heap[least]))
            least = r;
        if (least == i)
            break;
        event e = s->heap[i];
        s->heap[i] = s->heap[least];
        s->heap[least] = e;
        i = least;
    }
    return first;
}

/* The bytes of a tile in a PIXELS message. */
static double tile_bytes(const simulation *s, int tile)
{
    return TILE_HEADER_BYTES + 12.0 * s->m->pixels[tile];
}

/* Sends `msg` (its arrival ignored) of `bytes` from rank `from` at `time`
 * to rank `to`: it leaves when `from`'s link is free, and is whole at `to`
 * a latency later, or once `to`'s link has taken the messages before it. */
static void send_message(simulation *s, int from, int to, double time, double bytes, message msg)
{
    double wire = bytes / s->assumed->bandwidth;
    rank_state *src = &s->r[from], *dst = &s->r[to];
    double leaves = time > src->send_free ? time : src->send_free;
    src->send_free = leaves + wire;
    double arrives = leaves + s->assumed->latency > dst->receive_free ? leaves + s->assumed->latency : dst->receive_free;
    dst->receive_free = arrives + wire;
    msg.arrival = dst->receive_free;
    msg.bytes = bytes;
    msg.from = from;
    fifo_push(&dst->inbox, &msg);
}

/* lead.c's hand_out: up to `want` tiles from the counter, at most a
 * 2 x ranks-th of what is left (at least one); the first in *first. */
static int hand_out(simulation *s, int want, int *first)
{
    int left = s->m->tiles - s->next_tile;
    int spread = left / (2 * s->ranks) > 1 ? left / (2 * s->ranks) : 1;
    int n = want < left ? want : left;
    n = n < spread ? n : spread;
    *first = s->next_tile;
    s->next_tile += n;
    return n;
}

/* `rank`'s answer to an ASK for `want` tiles, the first in *first: lead.c's
 * hand_out in the pull queue; in work stealing the back half, rounded up,
 * of the tiles it has not begun (a contiguous run: a rank's tiles are one
 * run, its block or what it stole, taken from at both ends). */
static int give_tiles(simulation *s, int rank, int want, int *first)
{
    if (s->assumed->plan == SCHEDULE_PULL)
        return hand_out(s, want, first);
    fifo *q = &s->r[rank].queue;
    int n = (q->count + 1) / 2;
    q->count -= n;
    *first = n ? ((int *)q->items)[(q->head + q->count) % q->capacity] : 0;
    return n;
}

/* lead.c's send_tiles: `rank` sends rank `to` up to `want` (1 to
 * MAX_BATCH) tiles at *time, its work added to *time; in the pull queue
 * an empty answer only once. */
static void send_tiles(simulation *s, int rank, int to, int want, double *time)
{
    message answer = {.kind = TILES};
    want = want < 1 ? 1 : want > MAX_BATCH ? MAX_BATCH : want;
    answer.count = give_tiles(s, rank, want, &answer.first);
    rank_state *dst = &s->r[to];
    if (answer.count == 0 && dst->told_none)
        return;
    dst->told_none = answer.count == 0 && s->assumed->plan == SCHEDULE_PULL;
    *time += s->assumed->message_cost;
    send_message(s, rank, to, *time, 4.0 * answer.count, answer);
}

/* The time a rank's render thread spends on `tile`; a worker's also packs
 * its pixels into the message being filled (tile_outbox.c). */
static double render_time(const simulation *s, int rank, int tile)
{
    double t = s->m->seconds[tile] * s->assumed->tile_scale;
    return rank ? t + tile_bytes(s, tile) / s->assumed->copy_speed : t;
}

/* The tile a free render thread of `rank` begins, -1 when it has none at
 * hand: rank 0's in the pull queue from the shared counter (closed once
 * that is empty), any other from the rank's queue. */
static int next_tile(simulation *s, int rank)
{
    rank_state *r = &s->r[rank];
    int tile = -1;
    if (rank == 0 && s->assumed->plan == SCHEDULE_PULL) {
        r->closed = hand_out(s, 1, &tile) == 0;
        return r->closed ? -1 : tile;
    }
    return r->queue.count ? pop_tile(&r->queue) : -1;
}

/* A render thread of `rank` is free at `time`, having finished `tile`
 * (-1: none yet): the tile goes to rank 0's image or into the worker's
 * message being filled (waking its MPI thread when that holds the tiles it
 * waits for), and the thread takes the next tile, waits for one, or ends. */
static void thread_free(simulation *s, int rank, int tile, double time)
{
    rank_state *r = &s->r[rank];
    if (tile >= 0) {
        r->rendered++;
        r->rendering += render_time(s, rank, tile);
    }
    if (tile >= 0 && rank) {
        r->packed++;
        r->packed_bytes += tile_bytes(s, tile);
    } else if (tile >= 0) {
        s->lead_tiles++;
    }
    if (r->on_tiles && r->packed >= r->wanted) {
        r->on_tiles = false;
        turn_at(s, rank, time);
    }
    int next = next_tile(s, rank);
    if (next >= 0)
        schedule(s, time + render_time(s, rank, next), THREAD_FREE, rank, next);
    else if (r->closed)
        r->ended++;
    else
        r->waiting++;
}

/* backoff.h's backoff_after: the time of `rank`'s MPI thread's next turn,
 * at once when `busy`; the sleeps double up to 1 ms while its render runs,
 * to 50 us once its render threads have all ended (lead.c's serve and
 * follow.c's send_rest), and start short again only while an answer is
 * awaited (a thief's, in work stealing). */
static double after_turn(simulation *s, int rank, double time, bool busy)
{
    rank_state *r = &s->r[rank];
    double most = r->ended == s->assumed->threads ? BACKOFF_IDLE : BACKOFF_MAX;
    r->sleep = r->asked || r->sleep < BACKOFF_MIN ? BACKOFF_MIN : r->sleep > most ? most : r->sleep;
    if (busy)
        return time;
    double wake = time + r->sleep;
    r->sleep = r->sleep * 2 < most ? r->sleep * 2 : most;
    return wake;
}

/* Sets `rank`'s waiting render threads on its queued tiles at `time`, and
 * ends those left waiting once no more tiles will come. */
static void start_waiting(simulation *s, int rank, double time)
{
    rank_state *r = &s->r[rank];
    for (; r->waiting > 0 && r->queue.count; r->waiting--) {
        int tile = pop_tile(&r->queue);
        schedule(s, time + render_time(s, rank, tile), THREAD_FREE, rank, tile);
    }
    if (r->closed) {
        r->ended += r->waiting;
        r->waiting = 0;
    }
}

/* The answer to `rank`'s ASK, taken at `time`: its tiles into the queue
 * (the threads waiting take them at once). None closes a worker of the
 * pull queue; a thief asks again. */
static void take_tiles(simulation *s, int rank, const message *m, double time)
{
    rank_state *r = &s->r[rank];
    for (int i = 0; i < m->count; i++) {
        int tile = m->first + i;
        fifo_push(&r->queue, &tile);
    }
    r->closed = m->count == 0 && s->assumed->plan == SCHEDULE_PULL;
    r->asked = false;
    start_waiting(s, rank, time);
}

/* The rank with the most tiles not begun, -1 when no rank has any. */
static int most_loaded(const simulation *s)
{
    int most = -1;
    for (int i = 0; i < s->ranks; i++)
        if (s->r[i].queue.count && (most < 0 || s->r[i].queue.count > s->r[most].queue.count))
            most = i;
    return most;
}

/* follow.c's tiles_to_hold: the tiles a pull worker's threads render in
 * HOLD at the time its tiles have taken so far, at least 4 x threads, at
 * most MAX_BATCH. */
static int tiles_to_hold(const simulation *s, const rank_state *r)
{
    int threads = s->assumed->threads;
    double tiles = r->rendered ? HOLD * threads * r->rendered / r->rendering : 0;
    int hold = tiles > 4.0 * threads ? (int)tiles + 1 : 4 * threads;
    return hold < MAX_BATCH ? hold : MAX_BATCH;
}

/* How many tiles `rank` asks for now, 0 for none: a worker of the pull
 * queue what its hand should grow by, a rank of work stealing holding none
 * one ask (the victim decides how many) unless one is unanswered; none
 * once no more tiles will come. */
static int tiles_wanted(const simulation *s, int rank)
{
    const rank_state *r = &s->r[rank];
    if (r->closed)
        return 0;
    if (s->assumed->plan == SCHEDULE_PULL)
        return rank && tiles_to_hold(s, r) > r->hand ? tiles_to_hold(s, r) - r->hand : 0;
    return s->assumed->plan == SCHEDULE_STEAL && !r->asked && r->queue.count == 0;
}

/* follow.c's ask, or a thief's: when `rank` wants tiles, an ASK sent at
 * `time` to rank 0 (pull queue) or to the rank holding the most tiles
 * (work stealing); a thief that finds none left anywhere is closed
 * instead. Returns when its MPI thread is done. */
static double ask(simulation *s, int rank, double time)
{
    rank_state *r = &s->r[rank];
    int want = tiles_wanted(s, rank);
    if (!want)
        return time;
    int to = s->assumed->plan == SCHEDULE_STEAL ? most_loaded(s) : 0;
    if (to < 0) {
        r->closed = true;
        start_waiting(s, rank, time);
        return time;
    }
    time += s->assumed->message_cost;
    send_message(s, rank, to, time, 4, (message){.kind = ASK, .count = want});
    r->asked = true;
    r->hand += want;
    return time;
}

/* Takes the first message of `rank`'s inbox if it is there by *time, the
 * MPI thread's work added to *time: an ASK answered, TILES queued, PIXELS
 * copied into rank 0's image (in the pull queue, a tile sent back for each
 * of its tiles), a DONE counted. Whether one was taken. */
static bool take_message(simulation *s, int rank, double *time)
{
    const assumptions *a = s->assumed;
    message *front = fifo_front(&s->r[rank].inbox);
    if (!front || front->arrival > *time)
        return false;
    message m = *front;
    fifo_pop(&s->r[rank].inbox);
    *time += a->message_cost;
    if (m.kind == ASK) {
        send_tiles(s, rank, m.from, m.count, time);
    } else if (m.kind == TILES) {
        take_tiles(s, rank, &m, *time);
    } else if (m.kind == PIXELS) {
        *time += 2 * m.bytes / a->copy_speed;
        if (a->plan == SCHEDULE_PULL)
            send_tiles(s, rank, m.from, m.count, time);
    } else {
        s->reported++;
    }
    return true;
}

/* A turn of lead.c's serve loop at `time`: ends it once every worker has
 * reported and rank 0's render has returned, else (after a thief's ask,
 * in work stealing) takes one message. */
static void lead_turn(simulation *s, double time)
{
    rank_state *r = &s->r[0];
    if (s->reported == s->ranks - 1 && r->ended == s->assumed->threads) {
        s->end = time;
        r->finished = true;
        return;
    }
    double t = ask(s, 0, time);
    bool taken = take_message(s, 0, &t);
    r->busy += t - time;
    turn_at(s, 0, after_turn(s, 0, t, taken));
}

/* follow.c's send_finished: the worker's tiles packed so far, if any,
 * sent at *time as one PIXELS message, its work added to *time; whether
 * there were any. */
static bool send_packed(simulation *s, int rank, double *time)
{
    rank_state *r = &s->r[rank];
    if (!r->packed)
        return false;
    *time += s->assumed->message_cost;
    send_message(s, rank, 0, *time, r->packed_bytes, (message){.kind = PIXELS, .count = r->packed});
    r->packed = 0;
    r->packed_bytes = 0;
    return true;
}

/* A turn of follow.c's loop at `time`: the packed tiles sent; once the
 * render has returned, DONE when the sends are complete (send_rest; the
 * loop then ended, but in work stealing, where it goes on answering asks);
 * an ASK when the rank wants tiles and one message taken when it is
 * there. Then the next turn at once when it sent or took one, else after
 * follow.c's wait for packed tiles (a pull worker rendering) or
 * backoff.h's sleep. */
static void follow_turn(simulation *s, int rank, double time)
{
    rank_state *r = &s->r[rank];
    const assumptions *a = s->assumed;
    double t = time;
    bool sent = send_packed(s, rank, &t);
    bool over = r->ended == a->threads;
    if (over && !r->reported && r->send_free <= t) {
        t += a->message_cost;
        send_message(s, rank, 0, t, REPORT_BYTES, (message){.kind = DONE});
        r->reported = true;
        r->finished = a->plan != SCHEDULE_STEAL;
    }
    t = ask(s, rank, t);
    bool taken = !r->finished && take_message(s, rank, &t);
    r->busy += t - time;
    if (r->finished)
        return;
    r->on_tiles = a->plan == SCHEDULE_PULL && !over && !sent && !taken;
    if (!r->on_tiles) {
        turn_at(s, rank, after_turn(s, rank, t, sent || taken));
        return;
    }
    /* Half its hand, or one tile soon when it has none left to begin. */
    bool soon = r->closed || r->queue.count == 0;
    r->wanted = soon || r->hand / 2 < 1 ? 1 : r->hand / 2;
    turn_at(s, rank, t + (soon ? WAIT_SHORT : WAIT_LONG));
}

/* Each rank's tiles at the start: none in the pull queue (they are asked
 * for); in the static interleave rank r's r, r + N, r + 2N, ... of N
 * ranks, all it gets; in work stealing its r-th of N contiguous blocks. */
static void deal_tiles(simulation *s)
{
    bool interleave = s->assumed->plan == SCHEDULE_STATIC;
    long tiles = s->m->tiles, n = s->ranks;
    for (int r = 0; r < n && s->assumed->plan != SCHEDULE_PULL; r++) {
        int first = interleave ? r : (int)(tiles * r / n);
        int end = interleave ? (int)tiles : (int)(tiles * (r + 1) / n);
        for (int t = first; t < end; t += interleave ? (int)n : 1)
            fifo_push(&s->r[r].queue, &t);
        s->r[r].closed = interleave;
    }
}

/* When each rank's MPI_Bcast of the scene's files returns, from rank 0's
 * start at `start`: a binomial tree, rank r receiving from r - 2^k (2^k
 * its highest bit) and then sending to r + 2^j for each larger j in turn,
 * each transfer a latency and the files' bytes at the link's bandwidth. */
static void broadcast(const assumptions *a, int ranks, double start, double *returns)
{
    double transfer = a->latency + a->file_bytes / a->bandwidth;
    returns[0] = start;
    for (int step = 1; step < ranks; step *= 2)
        for (int r = 0; r < step && r + step < ranks; r++) {
            returns[r] += transfer;
            returns[r + step] = returns[r];
        }
}

/* Runs the render on `ranks` ranks: its wall time from rank 0's start, the
 * time of one core (one thread) for the same work, and rank 0's MPI thread
 * busy share. */
static result simulate(const measured *m, const assumptions *a, int ranks)
{
    simulation s = {.m = m, .assumed = a, .ranks = ranks};
    s.r = grow(NULL, (size_t)ranks * sizeof *s.r);
    for (int i = 0; i < ranks; i++)
        s.r[i] = (rank_state){.inbox.item_size = sizeof(message), .queue.item_size = sizeof(int)};
    deal_tiles(&s);
    double ready[MAX_RANKS];     /* when each rank's MPI loop starts: its load done */
    double load = a->start == START_BROADCAST ? a->load : 0, setup = a->start == START_NONE ? 0 : a->setup;
    for (int i = 0; i < ranks; i++)
        ready[i] = 0;
    if (a->start == START_BROADCAST) {
        /* Rank 0 sends a file as its load opens it (at once, for a scene
         * of one model), its load waiting meanwhile; a worker's load runs
         * as the files come. */
        broadcast(a, ranks, 0, ready);
        s.r[0].send_free = ready[0];
        for (int i = 0; i < ranks; i++) {
            s.r[i].receive_free = i ? ready[i] : 0;
            ready[i] += load;
        }
    }
    /* A rank builds its BVH once it has loaded. */
    for (int i = 0; i < ranks; i++) {
        turn_at(&s, i, ready[i]);
        for (int t = 0; t < a->threads; t++)
            schedule(&s, ready[i] + setup, THREAD_FREE, i, -1);
    }
    while (!s.r[0].finished) {
        if (!s.events)
            die("the simulation stalled: no rank has anything left to do");
        event e = next_event(&s);
        if (e.kind == THREAD_FREE)
            thread_free(&s, e.rank, e.tile, e.time);
        else if (e.tile != s.r[e.rank].turn || s.r[e.rank].finished)
            continue; /* a turn voided, or after the loop ended */
        else if (e.rank == 0)
            lead_turn(&s, e.time);
        else
            follow_turn(&s, e.rank, e.time);
    }
    double work = 0;
    for (int t = 0; t < m->tiles; t++)
        work += m->seconds[t] * a->tile_scale;
    result out = {.wall = s.end, .one_core = load + setup + work, .mpi_busy = s.r[0].busy / s.end,
                  .lead_tiles = s.lead_tiles};
    for (int i = 0; i < ranks; i++) {
        free(s.r[i].inbox.items);
        free(s.r[i].queue.items);
    }
    free(s.r);
    free(s.heap);
    return out;
}

/* The one-core time over the time of all the ranks' threads. */
static double efficiency(const result *r, int ranks, int threads)
{
    return r->one_core / (r->wall * ranks * threads);
}

/* Reads bench_tile_times's output. */
static measured read_times(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        die("cannot open the tile times");
    measured m = {0};
    int capacity = 0, x0, y0;
    double t;
    char line[256];
    while (fgets(line, sizeof line, f)) {
        if (sscanf(line, "image %d %d %d", &m.width, &m.height, &m.tile_size) == 3 ||
            sscanf(line, "load %lf", &m.load) == 1 || sscanf(line, "setup %lf", &m.setup) == 1)
            continue;
        if (sscanf(line, "tile %d %d %lf", &x0, &y0, &t) != 3 || m.tile_size < 4)
            die("the tile times are not bench_tile_times's");
        if (m.tiles == capacity) {
            capacity = capacity ? 2 * capacity : 1024;
            m.seconds = grow(m.seconds, (size_t)capacity * sizeof *m.seconds);
            m.pixels = grow(m.pixels, (size_t)capacity * sizeof *m.pixels);
        }
        int w = m.width - x0 < m.tile_size ? m.width - x0 : m.tile_size;
        int h = m.height - y0 < m.tile_size ? m.height - y0 : m.tile_size;
        m.seconds[m.tiles] = t;
        m.pixels[m.tiles++] = w * h;
    }
    fclose(f);
    if (!m.tiles)
        die("no tiles in the tile times");
    return m;
}

/* The longest load + set-up (both scaled alike, the one-core time kept)
 * for TARGET_EFFICIENCY at TARGET_RANKS, searched up to half the one-core
 * time; negative when even none misses. */
static double startup_for_target(const measured *m, const assumptions *a, double one_core)
{
    double work = 0, lo = 0, hi = one_core / (2 * (a->load + a->setup));
    for (int t = 0; t < m->tiles; t++)
        work += m->seconds[t];
    assumptions b = *a;
    for (int i = 0; i < 30; i++) {
        double k = i ? (lo + hi) / 2 : 0;
        b.load = a->load * k;
        b.setup = a->setup * k;
        b.tile_scale = (one_core - b.load - b.setup) / work;
        result r = simulate(m, &b, TARGET_RANKS);
        bool met = efficiency(&r, TARGET_RANKS, a->threads) >= TARGET_EFFICIENCY;
        if (i == 0 && !met)
            return -1;
        if (i > 0)
            *(met ? &lo : &hi) = k;
    }
    return lo * (a->load + a->setup);
}

static const char *const STARTUPS[] = {"broadcast", "loaded", "none"};
static const char *const SCHEDULES[] = {"pull", "static", "steal"};

/* The place of `name` among the `count` names (STARTUPS, SCHEDULES), or
 * the end of the program with `error`. */
static int named(const char *name, const char *const *names, int count, const char *error)
{
    for (int i = 0; i < count; i++)
        if (strcmp(name, names[i]) == 0)
            return i;
    die(error);
}

int main(int argc, char **argv)
{
    const char *path = NULL, *rank_list = "2,4,8,16,32,64,128,256";
    double one_core = 0, latency_us = 50, gbits = 10, message_us = 3, copy_gbs = 5, file_bytes = 3e6;
    assumptions a = {.threads = 1, .plan = SCHEDULE_PULL, .start = START_BROADCAST};
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        double *number = strcmp(o, "--one-core") == 0    ? &one_core
                         : strcmp(o, "--latency-us") == 0 ? &latency_us
                         : strcmp(o, "--gbits") == 0      ? &gbits
                         : strcmp(o, "--message-us") == 0 ? &message_us
                         : strcmp(o, "--copy-gbs") == 0   ? &copy_gbs
                         : strcmp(o, "--file-bytes") == 0 ? &file_bytes
                                                          : NULL;
        if (number && v) {
            *number = atof(v);
            i++;
        } else if (strcmp(o, "--ranks") == 0 && v) {
            rank_list = argv[++i];
        } else if (strcmp(o, "--threads") == 0 && v) {
            a.threads = atoi(argv[++i]);
        } else if (strcmp(o, "--schedule") == 0 && v) {
            a.plan = (scheduler)named(argv[++i], SCHEDULES, 3, "--schedule is pull, static or steal");
        } else if (strcmp(o, "--startup") == 0 && v) {
            a.start = (startup)named(argv[++i], STARTUPS, 3, "--startup is broadcast, loaded or none");
        } else if (!path && o[0] != '-') {
            path = o;
        } else {
            die("usage: bench_mpi_model TIMES.txt [--one-core S] [--ranks 2,4,...] [--threads N] "
                "[--schedule pull|static|steal] [--startup broadcast|loaded|none] [--latency-us US] [--gbits G] "
                "[--message-us US] [--copy-gbs G] [--file-bytes N]");
        }
    }
    if (!path || a.threads < 1 || a.threads > MAX_THREADS || gbits <= 0 || copy_gbs <= 0 || latency_us < 0 ||
        message_us < 0 || file_bytes < 0 || one_core < 0)
        die("a value is out of range (see the comment at the top of bench/mpi_model.c)");
    measured m = read_times(path);
    double work = 0;
    for (int t = 0; t < m.tiles; t++)
        work += m.seconds[t];
    a.load = m.load;
    a.setup = m.setup;
    a.tile_scale = one_core > 0 ? (one_core - m.load - m.setup) / work : 1;
    if (a.tile_scale <= 0)
        die("--one-core is shorter than the load and set-up alone");
    a.latency = latency_us * 1e-6;
    a.bandwidth = gbits * 1e9 / 8;
    a.message_cost = message_us * 1e-6;
    a.copy_speed = copy_gbs * 1e9;
    a.file_bytes = file_bytes;

    printf("Model: %dx%d in %d tiles of %d px; measured on one core: load %.3f s, set-up %.3f s, tiles %.3f s, "
           "scaled x%.2f (tiles %.2f s); schedule %s; start-up %s; %d render thread%s a rank; "
           "links %.0f us and %.3g Gbit/s; %.3g us of an MPI thread a message; copies at %.3g GB/s; "
           "scene files %.3g MB.\n\n",
           m.width, m.height, m.tiles, m.tile_size, m.load, m.setup, work, a.tile_scale, work * a.tile_scale,
           SCHEDULES[a.plan], STARTUPS[a.start], a.threads, a.threads == 1 ? "" : "s", latency_us, gbits,
           message_us, copy_gbs, file_bytes * 1e-6);
    printf("| ranks | wall s | speed-up | efficiency | rank 0's MPI thread busy | rank 0's tiles "
           "| efficiency, no start-up |\n");
    printf("| --- | --- | --- | --- | --- | --- | --- |\n");
    assumptions bare = a;
    bare.start = START_NONE;
    for (const char *p = rank_list; *p;) {
        char *end;
        long ranks = strtol(p, &end, 10);
        if (end == p || ranks < 2 || ranks > MAX_RANKS || (*end && *end != ','))
            die("--ranks needs numbers of 2..4096 separated by commas");
        p = *end ? end + 1 : end;
        result r = simulate(&m, &a, (int)ranks);
        result alone = simulate(&m, &bare, (int)ranks);
        printf("| %ld | %.3f | %.1f | %.1f%% | %.1f%% | %d | %.1f%% |\n", ranks, r.wall, r.one_core / r.wall,
               100 * efficiency(&r, (int)ranks, a.threads), 100 * r.mpi_busy, r.lead_tiles,
               100 * efficiency(&alone, (int)ranks, a.threads));
    }
    if (a.start == START_BROADCAST && one_core > 0) {
        double most = startup_for_target(&m, &a, one_core);
        if (most < 0)
            printf("\n%.0f%% at %d ranks is out of reach even with no load or set-up.\n", 100 * TARGET_EFFICIENCY,
                   TARGET_RANKS);
        else
            printf("\n%.0f%% at %d ranks needs a rank's load + set-up within %.3f s (measured %.3f s).\n",
                   100 * TARGET_EFFICIENCY, TARGET_RANKS, most, m.load + m.setup);
    }
    free(m.seconds);
    free(m.pixels);
    return 0;
}
