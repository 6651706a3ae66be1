/* glint_mpi.h - glint's C API across the ranks of an MPI job (libglint_mpi,
 * with libglint and the MPI library): a scene file loaded on one rank and
 * sent with its files to the others, and one image rendered by every
 * rank's threads, with the bytes glint_render gives on one machine.
 *
 * The program initialises MPI itself, with at least MPI_THREAD_FUNNELED
 * (glint's render threads never call MPI), and calls these functions from
 * that thread, on every rank of the communicator at once, as collectives:
 *
 *   MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
 *   glint_scene *scene = glint_mpi_scene_load_file(MPI_COMM_WORLD, "scene.yaml", NULL, &err);
 *   glint_image image;
 *   if (scene && !glint_mpi_render(MPI_COMM_WORLD, scene, NULL, &image, NULL, NULL, &err) && rank == 0)
 *       glint_image_write(&image, "out.png", &err);
 *
 * The communicator's messages use tags 1 to 5 and its collectives; a
 * program may use the communicator for its own messages before and after,
 * not during the calls. examples/embed_mpi.c is a whole program. */
#ifndef GLINT_MPI_H
#define GLINT_MPI_H

#include <mpi.h>
#include "glint.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Loads the scene file at `path` on rank 0 of comm (as
 * glint_scene_load_file, options there as there; the other ranks ignore
 * their options) and sends the bytes of every file it reads (the scene,
 * its includes, textures, models and their material files) to the other
 * ranks as it reads them; they load the same scene from them at the same
 * time, on a thread of their own, without opening any path of their own:
 * their machines need no copy of the files. Returns the scene
 * on every rank, or NULL on every rank with err saying why: rank 0's
 * failure as glint_scene_load_file says it, or the failure of another rank
 * (out of memory, say), on that rank in its own words and on the others as
 * "rank N could not load the scene rank 0 loaded". The ranks must run the
 * same build, or every rank fails with GLINT_ERR_INVALID: another build
 * (version or linker build ID) could compute other pixels. */
glint_scene *glint_mpi_scene_load_file(MPI_Comm comm, const char *path, const glint_load_options *options,
                                       glint_error *err);

/* How one rank's share of glint_mpi_render went. */
typedef struct glint_mpi_rank_stats {
    int threads;              /* its render threads */
    int tiles;                /* the tiles it rendered */
    double seconds;           /* its render's wall-clock time */
    double busy;              /* seconds its threads spent on tiles, all added */
    uint64_t samples, rays, nan_samples; /* as glint_render_stats counts them */
} glint_mpi_rank_stats;

/* Renders `scene` (the same scene on every rank: loaded with
 * glint_mpi_scene_load_file, or built alike) across the ranks of comm,
 * into *out on rank 0, with the bytes glint_render gives, whatever the
 * ranks and their threads. Rank 0 hands out tiles as the others ask for
 * them and renders tiles itself in between; every pixel comes back to it.
 *
 * options (NULL for the defaults) are each rank's own: threads (0: one per
 * processor the rank may run on), cancel (a flag, set by a signal handler
 * say, that stops every rank's render when set on any), keep_partial (rank
 * 0's); progress is called on rank 0 alone, counting every rank's tiles,
 * and tile_done on rank 0 alone, for every rank's tiles (from rank 0's
 * render threads and from the thread that called this, as they arrive).
 * The tile size must be the same on every rank (a rank with another fails
 * the render). A rank whose own scene could not be built may call it with
 * NULL: the render then fails on every rank, naming it. No rank waits for
 * the others before it begins: rank 0 renders while they finish loading.
 *
 * On rank 0, *out is the image (free it with glint_image_free), stats (when
 * not NULL) the whole render's (rays, samples and tiles of every rank,
 * rank 0's wall-clock time), and rank_stats (when not NULL, room for one
 * per rank of comm) each rank's share. On the other ranks *out is empty
 * and stats their own share; rank_stats is not touched. Every rank returns
 * the same status: GLINT_ERR_CANCELLED when a cancel flag stopped it (with
 * keep_partial, rank 0's *out then holds the tiles finished, the rest
 * black), or the first rank's failure (out of memory, say), err naming the
 * rank. */
glint_status glint_mpi_render(MPI_Comm comm, const glint_scene *scene, const glint_render_options *options,
                              glint_image *out, glint_render_stats *stats, glint_mpi_rank_stats *rank_stats,
                              glint_error *err);

#ifdef __cplusplus
}
#endif

#endif
