/* sequence.c - glint-mpi rendering an animation's frames (sequence.h).
 *
 * Rank 0 picks the frames (--resume leaving out those whose files are
 * whole) and checks their file names before any is rendered; the list goes
 * to every rank. A rank loads each frame it renders at the frame's time
 * from the files rank 0 sent at the start (load_again), never from files
 * of its own, with the frame's number in its settings, as glint loads it:
 * a frame is the same bytes on any rank, alone or in the sequence. With at
 * least as many frames as ranks, whole frames go to the ranks
 * (frame_farm.c): no messages within a frame, and a frame's scene load
 * and file write overlap the other ranks' renders. With fewer, every rank
 * renders each frame, by tiles (render_across.c). */
#define _GNU_SOURCE /* open_memstream */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "core/error.h"
#include "mpi/agree.h"
#include "mpi/frame_farm.h"
#include "mpi/load_everywhere.h"
#include "mpi/rank_threads.h"
#include "mpi/render_across.h"
#include "mpi/sequence.h"

typedef struct sequence {
    const cli_options *o;
    cli_frames frames;
    file_log *log;
    int rank, ranks;
    int width, height;        /* every frame's image */
    cli_destination dest;     /* rank 0: where frames go, the path each frame's own */
    glint_image_write_options write_options;
    char pattern[4096];       /* rank 0: the output's name, its #s the frame's number */
    int *todo;                /* the frames to render, first to last */
    int count;
    display *window;          /* rank 0's, or NULL */
    cli_progress progress;    /* rank 0's: frames taken, of count */
    bool show_progress;
    int taken;                /* rank 0: frames written whole */
} sequence;

bool sequence_wanted(const cli_options *o, const cli_frames *f)
{
    return f->last != f->first || cli_frame_time(f, f->first) != 0 || o->resume;
}

/* What a frame's load needs. */
typedef struct frame_load {
    const cli_options *o;
    double time;
    cli_run *run;
    FILE *messages;
} frame_load;

/* A scene_loader: the scene as the flags ask, at the frame's time, its
 * problems kept in l->messages. */
static glint_status load_at_time(void *user, bool rank0, glint_error *err)
{
    frame_load *l = user;
    cli_send_messages(l->messages);
    int code = cli_prepare(l->o, false, l->time, l->run);
    cli_send_messages(NULL);
    return code < 0 ? GLINT_OK
                    : error_set(err, code == CLI_EXIT_INTERNAL ? GLINT_ERR_NOMEM : GLINT_ERR_INVALID,
                                "the scene could not be loaded");
}

/* What a load said, as one message: its lines joined, each without the
 * command's "glint: ". */
static void message_of(const char *said, glint_error *err)
{
    char *to = err->message, *end = err->message + sizeof err->message - 1;
    while (*said && to < end) {
        if (strncmp(said, "glint: ", 7) == 0)
            said += 7;
        const char *line_end = strchr(said, '\n');
        size_t n = line_end ? (size_t)(line_end - said) : strlen(said);
        for (size_t i = 0; i < n && to < end; i++)
            *to++ = said[i];
        said += n + (line_end != NULL);
        if (*said && to + 2 < end) {
            *to++ = ';';
            *to++ = ' ';
        }
    }
    *to = '\0';
}

/* Loads frame `frame` into *run, as glint loads it, from the files rank 0
 * sent; on rank 0 with the frame's file as its destination (path, room
 * for 4096 bytes). */
static glint_status load_frame(const sequence *q, int frame, cli_run *run, char *path, glint_error *err)
{
    *run = (cli_run){0};
    if (!q->log)
        return error_set(err, GLINT_ERR_INVALID, "it could not load the scene rank 0 loaded");
    char *said = NULL;
    size_t said_size = 0;
    frame_load l = {.o = q->o, .time = cli_frame_time(&q->frames, frame), .run = run,
                    .messages = open_memstream(&said, &said_size)};
    if (!l.messages)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory loading the frame");
    glint_status st = load_again(q->log, load_at_time, &l, q->rank == 0, err);
    fclose(l.messages);
    if (st && said && *said)
        message_of(said, err);
    free(said);
    if (st)
        return st;
    /* The frame moves the random patterns: its noise is its own. */
    run->settings.frame = frame;
    if ((st = glint_scene_set_settings(run->scene, &run->settings, err))) {
        glint_scene_free(run->scene);
        run->scene = NULL;
        return st;
    }
    if (q->rank == 0) {
        run->dest = q->dest;
        run->write_options = q->write_options;
        cli_frame_path(q->pattern, frame, path, 4096); /* fits: checked by pick_frames */
        run->dest.path = run->dest.shown = path;
    }
    return GLINT_OK;
}

/* Rank 0: the frames to render into q->todo, each file name checked
 * against the scene's inputs (those of `scene`, loaded at time 0: every
 * frame reads the same files); -1, or the exit code after complaining. */
static int pick_frames(sequence *q, const glint_scene *scene)
{
    const cli_frames *f = &q->frames;
    q->todo = malloc(((size_t)f->last - (size_t)f->first + 1) * sizeof *q->todo);
    if (!q->todo)
        return cli_complain(CLI_EXIT_INTERNAL, "out of memory for the frames' list");
    bool to_stdout = strcmp(q->pattern, "-") == 0;
    for (int frame = f->first; frame <= f->last; frame++) {
        char path[4096];
        glint_error err = {0};
        if (!cli_frame_path(q->pattern, frame, path, sizeof path))
            return cli_complain(CLI_EXIT_USAGE, "the output name '%s' is too long", q->pattern);
        if (!to_stdout && glint_scene_check_output(scene, path, &err))
            return cli_complain(CLI_EXIT_IO, "%s", err.message);
        if (q->o->resume && !to_stdout && cli_frame_done(path)) {
            if (!q->o->quiet)
                fprintf(stderr, "glint-mpi: frame %d is done: %s\n", frame, path);
            continue;
        }
        q->todo[q->count++] = frame;
    }
    return -1;
}

/* The frames to render, rank 0's, on every rank; -1 or rank 0's exit code. */
static int agree_on_frames(sequence *q, const cli_run *r)
{
    int head[2] = {q->rank == 0 ? pick_frames(q, r->scene) : -1, q->count};
    agree_on_rank0_bytes(MPI_COMM_WORLD, head, (int)sizeof head);
    if (head[0] >= 0)
        return head[0];
    q->count = head[1];
    if (q->rank != 0 && !(q->todo = malloc(((size_t)q->count + 1) * sizeof *q->todo))) {
        fputs("glint-mpi: out of memory for the frames' list\n", stderr);
        MPI_Abort(MPI_COMM_WORLD, CLI_EXIT_INTERNAL); /* it cannot take part */
    }
    agree_on_rank0_bytes(MPI_COMM_WORLD, q->todo, q->count * (int)sizeof *q->todo);
    return -1;
}

static double seconds_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* A farm_render_fn: the frame loaded and rendered by this rank alone. */
static void render_frame(void *user, farm_frame *f, const volatile int *cancel)
{
    const sequence *q = user;
    double start = seconds_now();
    cli_run run;
    char path[4096];
    if (!(f->status = load_frame(q, f->frame, &run, path, &f->err))) {
        glint_render_options ro = {.threads = q->o->threads > 0 ? (int)q->o->threads : rank_threads(),
                                   .cancel = cancel, .keep_partial = q->o->partial};
        f->status = glint_render(run.scene, &ro, &f->image, &f->stats, &f->err);
        if (f->status && f->status != GLINT_ERR_CANCELLED)
            glint_image_free(&f->image);
    }
    glint_scene_free(run.scene);
    f->seconds = seconds_now() - start;
}

/* A farm_take_fn: a frame rendered, written to its file and shown, or a
 * cancelled one written as far as it got, with --partial. */
static glint_status take_frame(void *user, const farm_frame *f, glint_error *err)
{
    sequence *q = user;
    char path[4096];
    cli_frame_path(q->pattern, f->frame, path, sizeof path);
    cli_run r = {.dest = q->dest, .write_options = q->write_options};
    r.dest.path = r.dest.shown = path;
    if (q->show_progress)
        fputs("\r\033[K", stderr);
    if (f->status == GLINT_ERR_CANCELLED) {
        /* A frame stopped before its first tile has nothing to keep. */
        if (!q->o->partial || !f->image.pixels || f->stats.tiles_done == 0)
            return GLINT_OK;
        glint_status st = cli_write_image(&r, &f->image, err);
        if (!st)
            cli_complain(CLI_EXIT_INTERRUPTED, "frame %d interrupted: %d of %d tiles finished, written to %s (the "
                                               "rest black)", f->frame, f->stats.tiles_done, f->stats.tiles_total, path);
        return st;
    }
    if (q->window)
        display_tile(q->window, 0, 0, f->image.width, f->image.height, f->image.pixels, 3 * (size_t)f->image.width);
    glint_status st = cli_write_image(&r, &f->image, err);
    if (st)
        return st;
    q->taken++;
    cli_warn_nan(f->stats.nan_samples);
    if (!q->o->quiet)
        fprintf(stderr, "glint-mpi: frame %d (%d of %d), rank %d: %dx%d: %.3f s, %llu samples, %llu rays -> %s\n",
                f->frame, q->taken, q->count, f->rank, f->image.width, f->image.height, f->seconds,
                (unsigned long long)f->stats.samples, (unsigned long long)f->stats.rays, path);
    return GLINT_OK;
}

/* The farm's summary: the frames, the ranks, the time, and each rank's
 * frames and how busy it was (its time loading and rendering them over
 * the sequence's). */
static void print_farm_summary(const sequence *q, const farm_rank_stats *each, double seconds)
{
    uint64_t rays = 0;
    for (int r = 0; r < q->ranks; r++)
        rays += each[r].rays;
    fprintf(stderr, "glint-mpi: %d frame%s, %d rank%s: %.3f s, %.3f s a frame, %.1f Mrays/s -> %s; frames:",
            q->count, q->count == 1 ? "" : "s", q->ranks, q->ranks == 1 ? "" : "s", seconds, seconds / q->count,
            seconds > 0 ? rays / seconds * 1e-6 : 0.0, q->pattern);
    for (int r = 0; r < q->ranks; r++) {
        double busy = seconds > 0 ? each[r].busy / seconds : 0;
        fprintf(stderr, "%s rank %d %d (busy %.0f%%)", r ? "," : "", r, each[r].frames, 100 * (busy < 1 ? busy : 1));
    }
    fputc('\n', stderr);
}

/* Whole frames to each rank; the exit code. */
static int render_farm(sequence *q, const volatile int *cancel)
{
    farm_job job = {.frames = q->todo, .count = q->count, .render = render_frame, .take = take_frame, .user = q,
                    .cancel = cancel};
    if (q->rank != 0) {
        farm_follow(MPI_COMM_WORLD, &job);
        return CLI_EXIT_OK;
    }
    job.width = q->width;
    job.height = q->height;
    if (q->show_progress) {
        job.progress = cli_show_progress;
        job.progress_user = &q->progress;
        clock_gettime(CLOCK_MONOTONIC, &q->progress.start);
        q->progress.last_print = -1;
    }
    farm_rank_stats *each = calloc((size_t)q->ranks, sizeof *each);
    if (!each) {
        fputs("glint-mpi: out of memory for the ranks' reports\n", stderr);
        MPI_Abort(MPI_COMM_WORLD, CLI_EXIT_INTERNAL); /* the others cannot be told */
    }
    double start = seconds_now();
    int taken = 0;
    glint_error err = {0};
    glint_status st = farm_lead(MPI_COMM_WORLD, &job, each, &taken, &err);
    if (q->show_progress && st)
        fputs("\r\033[K", stderr); /* the progress line stopped short */
    int code = CLI_EXIT_OK;
    if (st == GLINT_ERR_CANCELLED)
        code = cli_complain(CLI_EXIT_INTERRUPTED, "interrupted: %d of %d frames written whole", taken, q->count);
    else if (st)
        code = cli_complain(cli_exit_code_of(st), "%s", err.message);
    else if (!q->o->quiet)
        print_farm_summary(q, each, seconds_now() - start);
    if (!st && q->window)
        display_finished(q->window, seconds_now() - start);
    free(each);
    return code;
}

/* Each frame by every rank, by tiles; the exit code. */
static int render_by_tiles(sequence *q, const volatile int *cancel)
{
    int code = CLI_EXIT_OK;
    for (int i = 0; i < q->count && code == CLI_EXIT_OK; i++) {
        int frame = q->todo[i];
        cli_run run;
        char path[4096];
        glint_error err = {0};
        glint_status st = load_frame(q, frame, &run, path, &err);
        /* Rank 0's failure ends the sequence here; another rank's fails
         * the render, which names it. */
        int failed = q->rank == 0 && st ? cli_complain(cli_exit_code_of(st), "frame %d: %s", frame, err.message) : -1;
        agree_on_rank0(MPI_COMM_WORLD, &failed);
        if (failed >= 0) {
            glint_scene_free(run.scene);
            return failed;
        }
        cli_progress place = {.frame = frame, .frames = q->count, .frames_done = i};
        code = render_across(q->o, &run, q->rank, q->ranks, q->window, cancel, q->count > 1 ? &place : NULL);
        glint_scene_free(run.scene);
        /* Rank 0 alone wrote the frame: its failure is every rank's. */
        agree_on_max(MPI_COMM_WORLD, &code);
    }
    return code;
}

int sequence_render(const cli_options *o, cli_run *r, const cli_frames *f, file_log *log, int rank, int ranks,
                    display *window, const volatile int *cancel)
{
    sequence q = {.o = o, .frames = *f, .log = log, .rank = rank, .ranks = ranks, .window = window,
                  .show_progress = rank == 0 && !o->quiet};
    if (rank == 0) {
        q.width = r->settings.width;
        q.height = r->settings.height;
        q.dest = r->dest;
        q.write_options = r->write_options;
        /* The path may point into the scene, which goes now. */
        snprintf(q.pattern, sizeof q.pattern, "%s", r->dest.path);
        q.dest.path = q.dest.shown = q.pattern;
    }
    int code = agree_on_frames(&q, r);
    glint_scene_free(r->scene);
    r->scene = NULL;
    if (code < 0 && q.count > 0)
        code = q.count >= ranks ? render_farm(&q, cancel) : render_by_tiles(&q, cancel);
    free(q.todo);
    code = code < 0 ? CLI_EXIT_OK : code;
    agree_on_max(MPI_COMM_WORLD, &code);
    return code;
}
