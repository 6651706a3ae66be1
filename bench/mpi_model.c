/* mpi_model.c - glint-mpi past this machine, by simulation: the measured
 * time of every tile of a render (bench_tile_times's output) replayed
 * through glint-mpi's scheduler, as src/mpi/lead.c and src/mpi/follow.c
 * implement it, for 2 to 256 ranks over a network of a stated latency and
 * bandwidth. It prints the predicted wall time, speed-up and parallel
 * efficiency, and how busy rank 0's MPI thread is.
 *
 * What is simulated, event by event:
 * - One shared counter of tiles. Rank 0's render threads take tiles from it
 *   one at a time; a worker asks for min(4 x threads, 64) when it holds no
 *   more than 2 x threads, and rank 0 answers with at most
 *   min(want, max(1, left / (2 x ranks))), none when none are left.
 * - Every rank's MPI thread loop, one message a turn on rank 0, with the
 *   idle sleeps of src/mpi/backoff.h (20 us doubling to 1 ms); each message
 *   it sends or takes costs it --message-us, and a tile's pixels are copied
 *   at --copy-gbs (twice on rank 0: out of MPI into the image; once on a
 *   worker, into the message).
 * - Messages over links of --latency-us and --gbits: each rank sends and
 *   receives one message at a time at the link's bandwidth, so the tiles
 *   of all workers queue at rank 0's link. A tile travels as an 8-byte
 *   header and 3 floats a pixel.
 * - The start-up (--startup broadcast, the default): rank 0 loads the
 *   scene (the measured load time), sends its files (--file-bytes) down a
 *   binomial tree, each rank sending to its children one after the other,
 *   and builds its BVH and renders at once; a worker loads the scene once
 *   MPI_Bcast would return (it has forwarded the files), then builds its
 *   BVH (the measured set-up) and renders, asking for tiles as soon as its
 *   load is done. --startup loaded is the render alone as glint-mpi's
 *   summary times it today (every rank has loaded its scene from a shared
 *   folder; each builds its BVH, then renders); --startup none leaves out
 *   loads and BVH builds (the scheduler, the network and the tail alone).
 *
 * Not simulated: mpirun's launch, writing the image, MPI's rendezvous for
 * large messages and its 16 sends in flight per worker, and the MPI
 * threads' time taken from the render threads (a rank is taken to have a
 * spare hardware thread for it); every rank's cores are as fast as the
 * measuring machine's.
 *
 *   bench_mpi_model TIMES.txt [--one-core S] [--ranks 2,4,...] [--threads N]
 *       [--startup broadcast|loaded|none] [--latency-us 50] [--gbits 10]
 *       [--message-us 3] [--copy-gbs 5] [--file-bytes N]
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
#define MAX_BATCH 64             /* src/mpi/protocol.h */
#define BACKOFF_MIN 20e-6        /* src/mpi/backoff.h */
#define BACKOFF_MAX 1e-3
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

/* The assumptions of one simulation. */
typedef struct assumptions {
    int threads;                 /* render threads per rank */
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

/* A message on its way or waiting to be taken. `count`: tiles wanted
 * (ASK), given (TILES, from `first` on), or the tile (PIXELS). */
typedef struct message {
    double arrival;
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
    fifo queue;                  /* a worker's tiles given and not begun */
    fifo outbox;                 /* a worker's finished tiles not yet sent */
    bool asked, closed, finished; /* an ASK unanswered; no more tiles; the MPI loop ended */
    int waiting, ended;          /* render threads waiting for tiles; render threads ended */
    double sleep;                /* the MPI thread's next idle sleep (backoff.h) */
    double send_free, receive_free; /* when its link is free to send, to receive */
    double busy;                 /* seconds its MPI thread spent on messages */
} rank_state;

enum event_kind { THREAD_FREE, MPI_TURN };

/* A render thread that finished `tile` (-1: none) and takes the next, or
 * an MPI thread's next turn. `order` keeps events of one time in the order
 * they were made. */
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

/* The bytes of a tile's PIXELS message. */
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

/* The time a rank's render thread spends on `tile`; a worker's also packs
 * its pixels into a message (tile_outbox.c). */
static double render_time(const simulation *s, int rank, int tile)
{
    double t = s->m->seconds[tile] * s->assumed->tile_scale;
    return rank ? t + tile_bytes(s, tile) / s->assumed->copy_speed : t;
}

/* A render thread of `rank` is free at `time`, having finished `tile`
 * (-1: none yet): the tile goes to rank 0's image or the worker's outbox,
 * and the thread takes the next tile, waits for one, or ends. */
static void thread_free(simulation *s, int rank, int tile, double time)
{
    rank_state *r = &s->r[rank];
    if (tile >= 0 && rank)
        fifo_push(&r->outbox, &tile);
    int next = -1;
    if (rank == 0 && hand_out(s, 1, &next) == 0)
        next = -1;
    else if (rank == 0)
        s->lead_tiles++;
    else if (rank && r->queue.count)
        next = pop_tile(&r->queue);
    else if (rank && !r->closed)
        r->waiting++;
    if (next >= 0)
        schedule(s, time + render_time(s, rank, next), THREAD_FREE, rank, next);
    else if (rank == 0 || r->closed)
        r->ended++;
}

/* backoff.h's backoff_after: the time of the MPI thread's next turn. */
static double after_turn(rank_state *r, double time, bool busy)
{
    if (busy || r->sleep < BACKOFF_MIN) {
        r->sleep = BACKOFF_MIN;
        if (busy)
            return time;
    }
    double wake = time + r->sleep;
    r->sleep = r->sleep * 2 < BACKOFF_MAX ? r->sleep * 2 : BACKOFF_MAX;
    return wake;
}

/* A turn of lead.c's serve loop at `time`: ends it once every worker has
 * reported and rank 0's render has returned, else takes one message. */
static void lead_turn(simulation *s, double time)
{
    rank_state *r = &s->r[0];
    const assumptions *a = s->assumed;
    if (s->reported == s->ranks - 1 && r->ended == a->threads) {
        s->end = time;
        r->finished = true;
        return;
    }
    message *msg = fifo_front(&r->inbox);
    double cost = 0;
    bool taken = msg && msg->arrival <= time;
    if (taken) {
        message m = *msg;
        fifo_pop(&r->inbox);
        cost = a->message_cost;
        if (m.kind == ASK) {
            message answer = {.kind = TILES};
            int want = m.count > MAX_BATCH ? MAX_BATCH : m.count;
            answer.count = hand_out(s, want, &answer.first);
            cost += a->message_cost;
            send_message(s, 0, m.from, time + cost, 4.0 * answer.count, answer);
        } else if (m.kind == PIXELS) {
            cost += 2 * tile_bytes(s, m.count) / a->copy_speed;
        } else {
            s->reported++;
        }
    }
    r->busy += cost;
    schedule(s, after_turn(r, time + cost, taken), MPI_TURN, 0, -1);
}

/* Rank 0's answer to a worker's ASK taken: its tiles into the queue (the
 * threads waiting take them at once), or the queue closed. */
static void take_tiles(simulation *s, int rank, const message *m, double time)
{
    rank_state *r = &s->r[rank];
    for (int i = 0; i < m->count; i++) {
        int tile = m->first + i;
        fifo_push(&r->queue, &tile);
    }
    r->closed = m->count == 0;
    r->asked = false;
    for (; r->waiting > 0 && r->queue.count; r->waiting--) {
        int tile = pop_tile(&r->queue);
        schedule(s, time + render_time(s, rank, tile), THREAD_FREE, rank, tile);
    }
    if (r->closed) {
        r->ended += r->waiting;
        r->waiting = 0;
    }
}

/* A turn of follow.c's loop at `time`: finished tiles sent, the loop ended
 * with DONE once the render has returned, else an ASK when few tiles are
 * left and rank 0's answer taken when it is there. */
static void follow_turn(simulation *s, int rank, double time)
{
    rank_state *r = &s->r[rank];
    const assumptions *a = s->assumed;
    double t = time;
    bool sent = r->outbox.count > 0;
    while (r->outbox.count) {
        int tile = pop_tile(&r->outbox);
        t += a->message_cost;
        send_message(s, rank, 0, t, tile_bytes(s, tile), (message){.kind = PIXELS, .count = tile});
    }
    if (r->ended == a->threads) {
        t += a->message_cost;
        send_message(s, rank, 0, t, REPORT_BYTES, (message){.kind = DONE});
        r->finished = true;
        r->busy += t - time;
        return;
    }
    int want = 4 * a->threads < MAX_BATCH ? 4 * a->threads : MAX_BATCH;
    if (!r->asked && !r->closed && r->queue.count <= 2 * a->threads) {
        t += a->message_cost;
        send_message(s, rank, 0, t, 4, (message){.kind = ASK, .count = want});
        r->asked = true;
    }
    message *answer = fifo_front(&r->inbox);
    bool taken = answer && answer->arrival <= t;
    if (taken) {
        message m = *answer;
        fifo_pop(&r->inbox);
        t += a->message_cost;
        take_tiles(s, rank, &m, t);
    }
    r->busy += t - time;
    schedule(s, after_turn(r, t, sent || taken), MPI_TURN, rank, -1);
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
        s.r[i] = (rank_state){.inbox.item_size = sizeof(message), .queue.item_size = sizeof(int),
                              .outbox.item_size = sizeof(int)};
    double ready[MAX_RANKS];     /* when each rank's MPI loop starts */
    double load = a->start == START_BROADCAST ? a->load : 0, setup = a->start == START_NONE ? 0 : a->setup;
    if (a->start == START_BROADCAST) {
        broadcast(a, ranks, load, ready);
        s.r[0].send_free = ready[0];
        for (int i = 1; i < ranks; i++) {
            s.r[i].receive_free = ready[i];
            ready[i] += load;
        }
    } else {
        for (int i = 0; i < ranks; i++)
            ready[i] = 0;
    }
    /* Rank 0 builds its BVH as soon as it has loaded, beside the
     * broadcast; a worker once its own load is done. */
    for (int i = 0; i < ranks; i++) {
        schedule(&s, ready[i], MPI_TURN, i, -1);
        for (int t = 0; t < a->threads; t++)
            schedule(&s, (i ? ready[i] : load) + setup, THREAD_FREE, i, -1);
    }
    while (!s.r[0].finished) {
        if (!s.events)
            die("the simulation stalled: no rank has anything left to do");
        event e = next_event(&s);
        if (e.kind == THREAD_FREE)
            thread_free(&s, e.rank, e.tile, e.time);
        else if (!s.r[e.rank].finished && e.rank == 0)
            lead_turn(&s, e.time);
        else if (!s.r[e.rank].finished)
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
        free(s.r[i].outbox.items);
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

/* The start-up called `name` (STARTUPS). */
static startup startup_named(const char *name)
{
    for (startup s = START_BROADCAST; s <= START_NONE; s++)
        if (strcmp(name, STARTUPS[s]) == 0)
            return s;
    die("--startup is broadcast, loaded or none");
}

int main(int argc, char **argv)
{
    const char *path = NULL, *rank_list = "2,4,8,16,32,64,128,256";
    double one_core = 0, latency_us = 50, gbits = 10, message_us = 3, copy_gbs = 5, file_bytes = 3e6;
    assumptions a = {.threads = 1, .start = START_BROADCAST};
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
        } else if (strcmp(o, "--startup") == 0 && v) {
            a.start = startup_named(argv[++i]);
        } else if (!path && o[0] != '-') {
            path = o;
        } else {
            die("usage: bench_mpi_model TIMES.txt [--one-core S] [--ranks 2,4,...] [--threads N] "
                "[--startup broadcast|loaded|none] [--latency-us US] [--gbits G] [--message-us US] "
                "[--copy-gbs G] [--file-bytes N]");
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
           "scaled x%.2f (tiles %.2f s); start-up %s; %d render thread%s a rank; links %.0f us and %.3g Gbit/s; "
           "%.3g us of an MPI thread a message; copies at %.3g GB/s; scene files %.3g MB.\n\n",
           m.width, m.height, m.tiles, m.tile_size, m.load, m.setup, work, a.tile_scale, work * a.tile_scale,
           STARTUPS[a.start], a.threads, a.threads == 1 ? "" : "s", latency_us, gbits, message_us, copy_gbs,
           file_bytes * 1e-6);
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
