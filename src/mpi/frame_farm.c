/* frame_farm.c - a sequence's frames spread over the ranks, a whole frame
 * to a rank (frame_farm.h; the messages in protocol.h).
 *
 * A frame takes a rank seconds, against a millisecond for rank 0 to
 * answer: one frame in hand is enough, and the only waits are the last
 * frames, each rendered by one rank while the others are done. Rank 0's
 * own frames are rendered on a thread of its own; what they give waits in
 * a list for its MPI thread, which alone takes frames in (writes them and
 * prints), so that takes never run at once. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "mpi/backoff.h"
#include "mpi/frame_farm.h"
#include "mpi/protocol.h"

/* How long a worker's MPI thread sleeps between looks for a STOP while its
 * frame renders: a frame takes far longer, and its threads want the core. */
#define WATCH_NS 2000000L

/* A frame's render on a thread of the rank's own. */
typedef struct frame_thread {
    const farm_job *job;
    farm_frame *frame;
    const volatile int *cancel;
    pthread_t thread;
    atomic_bool finished;
} frame_thread;

static void *render_frame(void *arg)
{
    frame_thread *t = arg;
    t->job->render(t->job->user, t->frame, t->cancel);
    atomic_store(&t->finished, true);
    return NULL;
}

/* ---- rank 0 ---- */

typedef struct farm {
    MPI_Comm comm;
    int ranks;
    const farm_job *job;
    MPI_Datatype pixel;
    pthread_mutex_t lock;     /* over next, closed and the own list */
    int next;                 /* the first frame not handed out */
    bool closed;              /* stopping: no more frames are handed out */
    volatile int stop;        /* rank 0's own render's cancel flag */
    MPI_Request *stops;       /* the STOP sent to each rank, once stopping */
    int *rendering;           /* the frame each rank has in hand; -1: none, and none to come */
    farm_frame *own;          /* rank 0's frames rendered, in order, and how many */
    int own_count, own_taken;
    bool own_finished;        /* its thread has no more frames to render */
    bool interrupted;
    glint_status failed;      /* the first failure, said in err */
    glint_error err;
    int taken;
    farm_rank_stats *per_rank;
} farm;

/* The next frame to hand out, or -1. */
static int hand_out(farm *l)
{
    pthread_mutex_lock(&l->lock);
    int frame = l->closed || l->next >= l->job->count ? -1 : l->job->frames[l->next++];
    pthread_mutex_unlock(&l->lock);
    return frame;
}

/* Ends the farm early: no more frames, rank 0's own render cancelled, and
 * each rank with a frame in hand told to stop it. */
static void stop_everyone(farm *l)
{
    if (l->stop)
        return;
    pthread_mutex_lock(&l->lock);
    l->closed = true;
    pthread_mutex_unlock(&l->lock);
    l->stop = 1;
    for (int r = 1; r < l->ranks; r++)
        if (l->rendering[r] >= 0)
            MPI_Isend(NULL, 0, MPI_BYTE, r, TAG_STOP, l->comm, &l->stops[r]);
}

/* Stops the farm for the failure e, the first one said. */
static void fail(farm *l, const glint_error *e)
{
    if (!l->failed) {
        l->failed = e->status;
        l->err = *e;
    }
    stop_everyone(l);
}

/* Gives rank `to` its next frame, or -1. */
static void send_frame(farm *l, int to)
{
    int frame = hand_out(l);
    l->rendering[to] = frame;
    MPI_Send(&frame, 1, MPI_INT, to, TAG_FRAME, l->comm);
}

/* What becomes of a frame rendered: counted, and taken in when whole or
 * cancelled; a failure or a cancel stops every rank. */
static void settle(farm *l, farm_frame *f)
{
    farm_rank_stats *s = &l->per_rank[f->rank];
    s->frames++;
    s->busy += f->seconds;
    s->samples += f->stats.samples;
    s->rays += f->stats.rays;
    s->nan_samples += f->stats.nan_samples;
    if (f->status == GLINT_ERR_CANCELLED) {
        l->interrupted = true;
        stop_everyone(l);
    } else if (f->status) {
        glint_error e;
        error_set(&e, f->status, "rank %d, frame %d: %s", f->rank, f->frame, f->err.message);
        fail(l, &e);
    }
    glint_error err = {0};
    if ((!f->status || f->status == GLINT_ERR_CANCELLED) && l->job->take(l->job->user, f, &err))
        fail(l, &err);
    else if (!f->status)
        l->taken++;
    glint_image_free(&f->image);
}

/* Takes in rank `from`'s FRAME_DONE (and its pixels) into *f; false when
 * it is no frame this rank was given, of this image. */
static bool receive_frame(farm *l, int from, const MPI_Status *st, farm_frame *f)
{
    frame_header h;
    int size = 0;
    MPI_Get_count(st, MPI_BYTE, &size);
    if (size != (int)sizeof h) {
        MPI_Recv(NULL, 0, MPI_BYTE, from, TAG_FRAME_DONE, l->comm, MPI_STATUS_IGNORE);
        return false;
    }
    MPI_Recv(&h, sizeof h, MPI_BYTE, from, TAG_FRAME_DONE, l->comm, MPI_STATUS_IGNORE);
    h.message[sizeof h.message - 1] = '\0';
    *f = (farm_frame){.frame = h.frame, .rank = from, .status = (glint_status)h.status, .stats = h.stats,
                      .seconds = h.seconds};
    snprintf(f->err.message, sizeof f->err.message, "%s", h.message);
    f->err.status = f->status;
    bool with_pixels = h.width > 0;
    if (h.frame != l->rendering[from] || (with_pixels && (h.width != l->job->width || h.height != l->job->height)))
        return false; /* its pixels, if any, are left unread: the farm stops */
    if (!with_pixels)
        return true;
    MPI_Status pst;
    MPI_Probe(from, TAG_FRAME_PIXELS, l->comm, &pst);
    int pixels = 0;
    MPI_Get_count(&pst, l->pixel, &pixels);
    size_t count = (size_t)h.width * (size_t)h.height;
    float *image = pixels == (int)count ? malloc(count * 3 * sizeof *image) : NULL;
    if (!image && pixels == (int)count) {
        /* It cannot be taken in, nor left: MPI ends the job. */
        fputs("glint-mpi: out of memory for a frame from another rank\n", stderr);
        MPI_Abort(l->comm, 5);
    }
    if (!image)
        return false;
    MPI_Recv(image, pixels, l->pixel, from, TAG_FRAME_PIXELS, l->comm, MPI_STATUS_IGNORE);
    f->image = (glint_image){.width = h.width, .height = h.height, .pixels = image};
    return true;
}

/* Rank 0's own frames, on a thread of their own. */
static void *render_own(void *arg)
{
    farm *l = arg;
    for (int frame; (frame = hand_out(l)) >= 0;) {
        farm_frame f = {.frame = frame};
        l->job->render(l->job->user, &f, &l->stop);
        pthread_mutex_lock(&l->lock);
        l->own[l->own_count++] = f;
        pthread_mutex_unlock(&l->lock);
    }
    pthread_mutex_lock(&l->lock);
    l->own_finished = true;
    pthread_mutex_unlock(&l->lock);
    return NULL;
}

/* Takes in rank 0's own frames rendered so far; whether its thread is
 * finished and every frame it rendered taken. */
static bool take_own(farm *l, bool *busy)
{
    pthread_mutex_lock(&l->lock);
    while (l->own_taken < l->own_count) {
        farm_frame f = l->own[l->own_taken++];
        pthread_mutex_unlock(&l->lock);
        settle(l, &f);
        *busy = true;
        pthread_mutex_lock(&l->lock);
    }
    bool over = l->own_finished && l->own_taken == l->own_count;
    pthread_mutex_unlock(&l->lock);
    return over;
}

/* A rank sent what the farm does not send (another build): it stops. */
static void unsound(farm *l, int rank)
{
    glint_error e;
    error_set(&e, GLINT_ERR_INVALID, "rank %d sent what is no frame it was given", rank);
    fail(l, &e);
}

/* Serves the other ranks until each has been told there are no more
 * frames and rank 0's own are all taken in. */
static void serve(farm *l)
{
    int busy_ranks = 0;
    for (int r = 1; r < l->ranks; r++) {
        send_frame(l, r);
        busy_ranks += l->rendering[r] >= 0;
    }
    int shown = -1;
    backoff b = {0};
    for (bool own_over = false; busy_ranks > 0 || !own_over;) {
        bool busy = false;
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, l->comm, &flag, &st);
        if (flag && st.MPI_TAG == TAG_FRAME_DONE) {
            farm_frame f;
            bool sound = receive_frame(l, st.MPI_SOURCE, &st, &f);
            if (!sound)
                unsound(l, st.MPI_SOURCE);
            /* The rank's next frame first: it waits, rank 0 need not. */
            send_frame(l, st.MPI_SOURCE);
            busy_ranks -= l->rendering[st.MPI_SOURCE] < 0;
            if (sound)
                settle(l, &f);
            busy = true;
        } else if (flag) {
            /* No message of the farm: taken and dropped. */
            MPI_Recv(NULL, 0, MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG, l->comm, MPI_STATUS_IGNORE);
            unsound(l, st.MPI_SOURCE);
        }
        own_over = take_own(l, &busy);
        if (l->job->cancel && *l->job->cancel) {
            l->interrupted = true;
            stop_everyone(l);
        }
        if (l->job->progress && l->taken != shown) {
            l->job->progress(l->job->progress_user, l->taken, l->job->count);
            shown = l->taken;
        }
        b.max_ns = own_over ? BACKOFF_IDLE_NS : 0;
        backoff_after(&b, busy);
    }
}

glint_status farm_lead(MPI_Comm comm, const farm_job *job, farm_rank_stats *per_rank, int *taken, glint_error *err)
{
    int ranks;
    MPI_Comm_size(comm, &ranks);
    farm l = {.comm = comm, .ranks = ranks, .job = job, .per_rank = per_rank};
    l.stops = malloc((size_t)ranks * sizeof *l.stops);
    l.rendering = malloc((size_t)ranks * sizeof *l.rendering);
    l.own = malloc(((size_t)job->count + 1) * sizeof *l.own);
    if (!l.stops || !l.rendering || !l.own) {
        /* Not even the others can be told: MPI ends the job. */
        fputs("glint-mpi: out of memory for the frames' state\n", stderr);
        MPI_Abort(comm, 5);
    }
    for (int r = 0; r < ranks; r++) {
        l.stops[r] = MPI_REQUEST_NULL;
        l.rendering[r] = -1;
        per_rank[r] = (farm_rank_stats){0};
    }
    MPI_Type_contiguous(3, MPI_FLOAT, &l.pixel);
    MPI_Type_commit(&l.pixel);
    pthread_mutex_init(&l.lock, NULL);
    pthread_t own;
    bool own_started = pthread_create(&own, NULL, render_own, &l) == 0;
    l.own_finished = !own_started; /* without it, the others render every frame */
    serve(&l);
    if (own_started)
        pthread_join(own, NULL);
    MPI_Waitall(ranks, l.stops, MPI_STATUSES_IGNORE);
    MPI_Type_free(&l.pixel);
    pthread_mutex_destroy(&l.lock);
    free(l.stops);
    free(l.rendering);
    free(l.own);
    *taken = l.taken;
    if (l.failed) {
        *err = l.err;
        return l.failed;
    }
    if (l.interrupted)
        return error_set(err, GLINT_ERR_CANCELLED, "render cancelled");
    if (l.taken != job->count)
        return error_set(err, GLINT_ERR_INVALID, "only %d of %d frames came back", l.taken, job->count);
    return GLINT_OK;
}

/* ---- every other rank ---- */

/* Whether rank 0 sent a STOP, taken in. */
static bool stop_came(MPI_Comm comm)
{
    int flag = 0;
    MPI_Iprobe(0, TAG_STOP, comm, &flag, MPI_STATUS_IGNORE);
    if (flag)
        MPI_Recv(NULL, 0, MPI_BYTE, 0, TAG_STOP, comm, MPI_STATUS_IGNORE);
    return flag;
}

/* Rank 0's next FRAME, waited for without spinning; a STOP meanwhile sets
 * *stop. */
static int next_frame(MPI_Comm comm, volatile int *stop)
{
    backoff b = {.max_ns = BACKOFF_IDLE_NS};
    for (;;) {
        if (stop_came(comm))
            *stop = 1;
        int flag = 0;
        MPI_Iprobe(0, TAG_FRAME, comm, &flag, MPI_STATUS_IGNORE);
        if (flag) {
            int frame = -1;
            MPI_Recv(&frame, 1, MPI_INT, 0, TAG_FRAME, comm, MPI_STATUS_IGNORE);
            return frame;
        }
        backoff_after(&b, false);
    }
}

/* Sends rank 0 how frame f went, and its image when it has one. */
static void send_back(MPI_Comm comm, const farm_frame *f, MPI_Datatype pixel)
{
    frame_header h = {.frame = f->frame, .status = (int32_t)f->status, .width = f->image.pixels ? f->image.width : 0,
                      .height = f->image.pixels ? f->image.height : 0, .seconds = f->seconds, .stats = f->stats};
    snprintf(h.message, sizeof h.message, "%s", f->status ? f->err.message : "");
    MPI_Send(&h, sizeof h, MPI_BYTE, 0, TAG_FRAME_DONE, comm);
    if (h.width > 0)
        MPI_Send(f->image.pixels, h.width * h.height, pixel, 0, TAG_FRAME_PIXELS, comm);
}

void farm_follow(MPI_Comm comm, const farm_job *job)
{
    int rank;
    MPI_Comm_rank(comm, &rank);
    MPI_Datatype pixel;
    MPI_Type_contiguous(3, MPI_FLOAT, &pixel);
    MPI_Type_commit(&pixel);
    volatile int stop = 0;
    for (int frame; (frame = next_frame(comm, &stop)) >= 0;) {
        farm_frame f = {.frame = frame, .rank = rank};
        frame_thread t = {.job = job, .frame = &f, .cancel = &stop};
        atomic_init(&t.finished, false);
        if (pthread_create(&t.thread, NULL, render_frame, &t) != 0) {
            f.status = error_set(&f.err, GLINT_ERR_NOMEM, "out of memory for a thread to render it");
        } else {
            while (!atomic_load(&t.finished)) {
                if (stop_came(comm) || (job->cancel && *job->cancel))
                    stop = 1;
                struct timespec ts = {0, WATCH_NS};
                nanosleep(&ts, NULL);
            }
            pthread_join(t.thread, NULL);
        }
        send_back(comm, &f, pixel);
        glint_image_free(&f.image);
    }
    MPI_Type_free(&pixel);
}
