/* lead.c - rank 0 of glint-mpi: the pull queue of tiles, its own share of
 * the render, and the image the other ranks' tiles are put into (lead.h).
 *
 * Tiles are handed out in order from one counter, to rank 0's own render
 * threads one at a time (the render feed's next) and to the other ranks:
 * a hand of tiles when a rank asks, then one more for each tile it sends
 * back, so that its hand stays full without its asking. A batch is at
 * most what was asked for and at most a 2 x ranks-th of what is left, so
 * that the last tiles are spread thin and no rank is left with a long
 * tail while others wait. */
#include <mpi.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "mpi/backoff.h"
#include "mpi/lead.h"
#include "mpi/local_render.h"
#include "render/film.h"

typedef struct lead {
    MPI_Comm comm;
    render_layout layout;
    int ranks;
    pthread_mutex_t lock;     /* over next_tile and closed */
    int next_tile;            /* the first tile not handed out */
    bool closed;              /* a rank failed: no more tiles are handed out */
    atomic_int local_done;    /* tiles rank 0 finished */
    int remote_done;          /* tiles received from the other ranks */
    volatile int stop;        /* rank 0's render's cancel flag */
    const volatile int *interrupt; /* set when a signal asks the job to stop */
    const glint_render_options *options; /* the caller's: its tile_done told of the others' tiles */
    MPI_Request *stops;       /* the STOP sent to each rank, once stopping */
    bool *closed_for;         /* the ranks told there are no more tiles */
    bool *reported;           /* which ranks sent their DONE */
    float *pixels;            /* the image */
} lead;

/* Up to `want` tiles into tiles[], the next in order; 0 once none are left
 * (or a rank failed). */
static int hand_out(lead *l, int want, int *tiles)
{
    pthread_mutex_lock(&l->lock);
    int left = l->closed ? 0 : l->layout.tiles_total - l->next_tile;
    int spread = left / (2 * l->ranks) > 1 ? left / (2 * l->ranks) : 1;
    int n = want < left ? want : left;
    n = n < spread ? n : spread;
    for (int i = 0; i < n; i++)
        tiles[i] = l->next_tile++;
    pthread_mutex_unlock(&l->lock);
    return n;
}

static void close_queue(lead *l)
{
    pthread_mutex_lock(&l->lock);
    l->closed = true;
    pthread_mutex_unlock(&l->lock);
}

/* Ends the render early, on every rank: no more tiles are handed out,
 * rank 0's own render is cancelled, and every rank still rendering is
 * told to stop (STOP), so that it reports at once. */
static void stop_everyone(lead *l)
{
    if (l->stop)
        return;
    close_queue(l);
    l->stop = 1;
    for (int r = 1; r < l->ranks; r++)
        if (!l->reported[r])
            MPI_Isend(NULL, 0, MPI_BYTE, r, TAG_STOP, l->comm, &l->stops[r]);
}

/* The render feed of rank 0's own threads. */
static int lead_next(void *user)
{
    int tile = -1;
    return hand_out(user, 1, &tile) ? tile : -1;
}

static void lead_done(void *user, int tile, const float *pixels, size_t stride)
{
    lead *l = user;
    atomic_fetch_add(&l->local_done, 1);
}

/* Sends rank `to` up to `want` more tiles; or, once there are none, tells
 * it so, once. */
static void send_tiles(lead *l, int to, int want)
{
    int tiles[MAX_BATCH];
    want = want < 1 ? 1 : want > MAX_BATCH ? MAX_BATCH : want;
    int n = hand_out(l, want, tiles);
    if (n > 0 || !l->closed_for[to])
        MPI_Send(tiles, n, MPI_INT, to, TAG_TILES, l->comm);
    l->closed_for[to] = l->closed_for[to] || n == 0;
}

/* Answers rank `from`'s ASK: the tiles it would like added to its hand. */
static void answer_ask(lead *l, int from)
{
    int want = 0;
    MPI_Recv(&want, 1, MPI_INT, from, TAG_ASK, l->comm, MPI_STATUS_IGNORE);
    send_tiles(l, from, want);
}

/* Where PIXELS messages are received: grown to the largest so far. */
typedef struct pixels_buffer {
    unsigned char *bytes;
    size_t capacity;
} pixels_buffer;

/* Puts the tiles of a PIXELS message of `size` bytes into the image; how
 * many, or -1 when they are not whole tiles of the layout (a rank of
 * another build). */
static int put_tiles(lead *l, const unsigned char *bytes, size_t size)
{
    int tiles = 0;
    for (size_t at = 0; at < size; tiles++) {
        tile_header h;
        if (size - at < sizeof h)
            return -1;
        memcpy(&h, bytes + at, sizeof h);
        at += sizeof h;
        if (h.tile < 0 || h.tile >= l->layout.tiles_total)
            return -1;
        int x0, y0, x1, y1;
        render_tile_bounds(&l->layout, h.tile, &x0, &y0, &x1, &y1);
        size_t row = 3 * (size_t)(x1 - x0) * sizeof(float);
        if ((size - at) / row < (size_t)(y1 - y0))
            return -1;
        size_t stride = 3 * (size_t)l->layout.width;
        float *first = l->pixels + stride * (size_t)y0 + 3 * (size_t)x0;
        for (int y = y0; y < y1; y++, at += row)
            memcpy(first + stride * (size_t)(y - y0), bytes + at, row);
        if (l->options->tile_done)
            l->options->tile_done(l->options->tile_user, x0, y0, x1, y1, first, stride);
    }
    return tiles;
}

/* Takes in a PIXELS message from rank `from` of `size` bytes, into the
 * image; how many tiles it held, or -1 when they are not whole tiles of the
 * layout or more than a worker holds (a rank of another build), or memory
 * ran out. */
static int take_pixels(lead *l, int from, int size, pixels_buffer *in)
{
    size_t most = (size_t)MAX_BATCH * (sizeof(tile_header) + 3 * sizeof(float) * (size_t)l->layout.tile_size *
                                                                (size_t)l->layout.tile_size);
    if ((size_t)size > in->capacity && (size_t)size <= most) {
        unsigned char *bigger = realloc(in->bytes, (size_t)size);
        if (bigger) {
            in->bytes = bigger;
            in->capacity = (size_t)size;
        }
    }
    if ((size_t)size > in->capacity) {
        /* Received all the same, so that it is not left pending. */
        unsigned char *big = malloc((size_t)size);
        MPI_Recv(big, big ? size : 0, MPI_BYTE, from, TAG_PIXELS, l->comm, MPI_STATUS_IGNORE);
        free(big);
        return -1;
    }
    MPI_Recv(in->bytes, size, MPI_BYTE, from, TAG_PIXELS, l->comm, MPI_STATUS_IGNORE);
    int tiles = put_tiles(l, in->bytes, (size_t)size);
    l->remote_done += tiles > 0 ? tiles : 0;
    return tiles;
}

/* Serves the other ranks until they have all reported and rank 0's own
 * render has returned; false if a rank sent what no tile is. */
static bool serve(lead *l, local_render *own, const glint_render_options *options, rank_report *reports)
{
    pixels_buffer in = {0};
    bool sound = true;
    int reported = 0, shown = -1;
    backoff b = {0};
    while (reported < l->ranks - 1 || !local_render_finished(own)) {
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, l->comm, &flag, &st);
        if (flag && st.MPI_TAG == TAG_ASK) {
            answer_ask(l, st.MPI_SOURCE);
        } else if (flag && st.MPI_TAG == TAG_PIXELS) {
            int size = 0;
            MPI_Get_count(&st, MPI_BYTE, &size);
            /* Each tile back is one to send: the rank's hand stays full. */
            int tiles = take_pixels(l, st.MPI_SOURCE, size, &in);
            if (tiles > 0)
                send_tiles(l, st.MPI_SOURCE, tiles);
            else
                sound = false;
        } else if (flag && st.MPI_TAG == TAG_DONE) {
            rank_report *r = &reports[st.MPI_SOURCE];
            MPI_Recv(r, sizeof *r, MPI_BYTE, st.MPI_SOURCE, TAG_DONE, l->comm, MPI_STATUS_IGNORE);
            r->message[sizeof r->message - 1] = '\0';
            l->reported[st.MPI_SOURCE] = true;
            reported++;
            if (r->status)
                stop_everyone(l);
        } else if (flag) {
            /* No tag of the protocol: taken and dropped. */
            MPI_Recv(NULL, 0, MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG, l->comm, MPI_STATUS_IGNORE);
            sound = false;
        }
        /* A signal, a rank sending what is no tile, or rank 0's own render
         * failing (out of memory, Embree) ends the render everywhere. */
        if (*l->interrupt || !sound || (local_render_finished(own) && own->status != GLINT_OK))
            stop_everyone(l);
        int done = atomic_load(&l->local_done) + l->remote_done;
        if (options->progress && done != shown) {
            options->progress(options->progress_user, done, l->layout.tiles_total);
            shown = done;
        }
        b.max_ns = local_render_finished(own) ? BACKOFF_IDLE_NS : 0;
        backoff_after(&b, flag);
    }
    MPI_Waitall(l->ranks, l->stops, MPI_STATUSES_IGNORE);
    free(in.bytes);
    return sound;
}

glint_status lead_render(MPI_Comm comm, const glint_scene *scene, const glint_render_options *options, int ranks,
                         glint_image *out, glint_render_stats *stats, rank_report *reports, glint_error *err)
{
    static const volatile int never = 0;
    double start = MPI_Wtime();
    *out = (glint_image){0};
    lead l = {.comm = comm, .ranks = ranks, .interrupt = options->cancel ? options->cancel : &never,
              .options = options};
    glint_status status = render_layout_for(scene, options->tile_size, &l.layout, err);
    l.stops = malloc((size_t)ranks * sizeof *l.stops);
    l.reported = calloc((size_t)ranks, sizeof *l.reported);
    l.closed_for = calloc((size_t)ranks, sizeof *l.closed_for);
    if (!l.stops || !l.reported || !l.closed_for) {
        /* Not even the others can be told: MPI ends the job. */
        fputs("glint: out of memory for the ranks' state\n", stderr);
        MPI_Abort(comm, 5);
    }
    for (int r = 0; r < ranks; r++)
        l.stops[r] = MPI_REQUEST_NULL;
    l.pixels = status ? NULL : film_pixels_alloc(l.layout.width, l.layout.height, true);
    pthread_mutex_init(&l.lock, NULL);
    atomic_init(&l.local_done, 0);
    if (!l.pixels)
        close_queue(&l); /* the others are told there is nothing to do */
    glint_render_options own_options = *options;
    own_options.cancel = &l.stop;
    own_options.progress = NULL;
    render_feed feed = {.next = lead_next, .done = lead_done, .user = &l, .pixels = l.pixels};
    local_render own = {0}; /* its image, when it returns one, is l.pixels */
    bool started = l.pixels && local_render_start(&own, scene, &own_options, &feed);
    if (!started) {
        close_queue(&l);
        atomic_store(&own.finished, true);
    }
    bool sound = serve(&l, &own, options, reports);
    if (started)
        local_render_join(&own);
    pthread_mutex_destroy(&l.lock);
    free(l.stops);
    free(l.reported);
    free(l.closed_for);
    reports[0] = local_render_report(&own);
    if (!l.pixels && !status)
        reports[0] = (rank_report){.status = GLINT_ERR_NOMEM, .message = "out of memory for the image"};
    /* A rank whose render was cancelled (by a signal, or told to stop)
     * was interrupted, unless a rank failed, which is then what stopped
     * the others: the first rank that failed is the one reported. */
    bool interrupted = *l.interrupt;
    for (int r = 0; r < ranks && !status; r++) {
        if (reports[r].status == GLINT_ERR_CANCELLED)
            interrupted = true;
        else if (reports[r].status)
            status = error_set(err, (glint_status)reports[r].status, "rank %d: %s", r, reports[r].message);
    }
    int done = atomic_load(&l.local_done) + l.remote_done;
    *stats = (glint_render_stats){.seconds = MPI_Wtime() - start, .tiles_done = done,
                                  .tiles_total = l.layout.tiles_total};
    for (int r = 0; r < ranks; r++) {
        stats->rays += reports[r].stats.rays;
        stats->samples += reports[r].stats.samples;
        stats->nan_samples += reports[r].stats.nan_samples;
    }
    if (!status && !sound)
        status = error_set(err, GLINT_ERR_INVALID, "a rank sent a message that is no tile of this image");
    else if (!status && interrupted)
        status = error_set(err, GLINT_ERR_CANCELLED, "render cancelled");
    else if (!status && done != l.layout.tiles_total)
        status = error_set(err, GLINT_ERR_INVALID, "only %d of %d tiles came back", done, l.layout.tiles_total);
    if (status && status != GLINT_ERR_CANCELLED) {
        free(l.pixels);
        return status;
    }
    *out = (glint_image){.width = l.layout.width, .height = l.layout.height, .pixels = l.pixels};
    return status;
}
