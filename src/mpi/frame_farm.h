/* frame_farm.h - the frames of a sequence spread over the ranks of an MPI
 * job, a whole frame to a rank: rank 0 hands them out one at a time as the
 * ranks finish theirs (a pull queue, in order), renders frames itself on a
 * thread of its own meanwhile, and takes in every finished frame to write
 * it. A frame is loaded and rendered by one rank alone, with all of its
 * threads, so its bytes are what glint gives for it. */
#ifndef GLINT_MPI_FRAME_FARM_H
#define GLINT_MPI_FRAME_FARM_H

#include <mpi.h>
#include <stdint.h>
#include "glint.h"

/* One frame, and once rendered how it went. */
typedef struct farm_frame {
    int frame;
    int rank;                 /* the rank that rendered it */
    glint_status status;      /* GLINT_OK; GLINT_ERR_CANCELLED (stopped); or why it failed, in err */
    glint_error err;
    glint_image image;        /* the frame: whole, or cancelled with the tiles finished kept (the
                                 rest black); empty otherwise */
    glint_render_stats stats; /* its render's */
    double seconds;           /* loading and rendering it */
} farm_frame;

/* Loads frame f->frame and renders it into f (status, err, image, stats,
 * seconds), on a thread beside the one that calls MPI; `cancel` is set
 * when the render is to stop. */
typedef void (*farm_render_fn)(void *user, farm_frame *f, const volatile int *cancel);

/* On rank 0, on the thread that called farm_lead, one frame at a time: a
 * frame rendered (GLINT_OK), or cancelled, by any rank; writes it, say.
 * GLINT_OK, or a failure (err) that stops the farm. f->image is freed
 * after it returns. */
typedef glint_status (*farm_take_fn)(void *user, const farm_frame *f, glint_error *err);

/* The work, the same on every rank (frames, width and height are rank
 * 0's alone). */
typedef struct farm_job {
    const int *frames;        /* to render, in the order handed out */
    int count;
    int width, height;        /* every frame's image */
    farm_render_fn render;
    farm_take_fn take;        /* rank 0's */
    glint_progress_fn progress; /* rank 0's, when not NULL: frames taken, of count */
    void *progress_user;
    void *user;               /* render's and take's */
    const volatile int *cancel; /* a signal's flag, when not NULL: set on any rank, it stops every rank */
} farm_job;

/* What one rank did. */
typedef struct farm_rank_stats {
    int frames;               /* frames it rendered (or began) */
    double busy;              /* seconds it spent loading and rendering them */
    uint64_t samples, rays, nan_samples;
} farm_rank_stats;

/* Rank 0's side, while every other rank of comm runs farm_follow: hands
 * out job->frames, renders its share and takes each finished frame in
 * (job->take). Fills per_rank[r] for each rank and *taken, the frames
 * taken whole. GLINT_OK when every frame was taken; GLINT_ERR_CANCELLED
 * when the signal's flag was set, or a rank's render was cancelled; else
 * the first failure (a rank's frame, a take), err naming the rank and the
 * frame. Every rank has stopped when it returns. Called on the thread
 * that initialised MPI, the only one that calls it. */
glint_status farm_lead(MPI_Comm comm, const farm_job *job, farm_rank_stats *per_rank, int *taken, glint_error *err);

/* Every other rank's side: renders the frames rank 0 hands it, one at a
 * time, each sent back when finished (cancelled or failed included),
 * until rank 0 has no more. Called on the thread that initialised MPI. */
void farm_follow(MPI_Comm comm, const farm_job *job);

#endif
