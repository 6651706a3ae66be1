/* glint_mpi.c - glint's C API across the ranks of an MPI job
 * (include/glint_mpi.h): the scene loaded everywhere from rank 0's files
 * (load_everywhere.c), and the render split between rank 0 (lead.c) and
 * the others (follow.c), every rank returning rank 0's outcome. */
#include <stdio.h>
#include <stdlib.h>
#include "core/error.h"
#include "glint_mpi.h"
#include "mpi/agree.h"
#include "mpi/follow.h"
#include "mpi/lead.h"
#include "mpi/load_everywhere.h"
#include "mpi/rank_threads.h"
#include "mpi/same_build.h"

/* What a scene_loader of glint_mpi_scene_load_file needs. */
typedef struct file_load {
    const char *path;
    const glint_load_options *options;
    glint_scene *scene;
} file_load;

static glint_status load_file(void *user, bool rank0, glint_error *err)
{
    file_load *f = user;
    /* Only rank 0 reports problems: the others load what it loaded. */
    glint_load_options quiet = {0};
    if (f->options)
        quiet = *f->options;
    quiet.report = NULL;
    f->scene = glint_scene_load_file(f->path, rank0 ? f->options : &quiet, err);
    return f->scene ? GLINT_OK : err->status;
}

glint_scene *glint_mpi_scene_load_file(MPI_Comm comm, const char *path, const glint_load_options *options,
                                       glint_error *err)
{
    glint_error mine = {0};
    file_load f = {.path = path, .options = options};
    int failed_rank;
    if (!check_same_build(comm, &mine) && load_everywhere(comm, load_file, &f, false, true, NULL, &failed_rank, &mine)) {
        glint_scene_free(f.scene);
        f.scene = NULL;
    }
    if (err)
        *err = mine;
    return f.scene;
}

/* Rank 0's share and the whole render's outcome on rank 0. */
static glint_status render_lead(MPI_Comm comm, const glint_scene *scene, const glint_render_options *options,
                                glint_image *out, glint_render_stats *stats, glint_mpi_rank_stats *rank_stats,
                                glint_error *err)
{
    int ranks;
    MPI_Comm_size(comm, &ranks);
    rank_report *reports = calloc((size_t)ranks, sizeof *reports);
    if (!reports) {
        /* Not even the others can be told: MPI ends the job. */
        fputs("glint: out of memory for the ranks' reports\n", stderr);
        MPI_Abort(comm, 5);
    }
    glint_render_stats total;
    glint_status status = lead_render(comm, scene, options, ranks, out, &total, reports, err);
    for (int r = 0; rank_stats && r < ranks; r++)
        rank_stats[r] = reports[r].stats;
    free(reports);
    if (stats)
        *stats = total;
    if (status == GLINT_ERR_CANCELLED && !options->keep_partial)
        glint_image_free(out);
    return status;
}

glint_status glint_mpi_render(MPI_Comm comm, const glint_scene *scene, const glint_render_options *options,
                              glint_image *out, glint_render_stats *stats, glint_mpi_rank_stats *rank_stats,
                              glint_error *err)
{
    int rank;
    MPI_Comm_rank(comm, &rank);
    *out = (glint_image){0};
    glint_error outcome = {0};
    glint_render_options o = options ? *options : (glint_render_options){0};
    if (o.threads <= 0)
        o.threads = rank_threads();
    /* No collective before the render: rank 0 begins at once, while the
     * others may still be loading the scene. */
    if (rank == 0) {
        render_lead(comm, scene, &o, out, stats, rank_stats, &outcome);
    } else {
        rank_report own = follow_render(comm, scene, &o);
        if (stats)
            *stats = (glint_render_stats){.seconds = own.stats.seconds, .samples = own.stats.samples,
                                          .rays = own.stats.rays, .nan_samples = own.stats.nan_samples,
                                          .tiles_done = own.stats.tiles};
    }
    /* Every rank returns rank 0's outcome. */
    agree_on_rank0_bytes(comm, &outcome, (int)sizeof outcome);
    if (err)
        *err = outcome;
    return outcome.status;
}
