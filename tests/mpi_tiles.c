/* mpi_tiles.c - glint_mpi_render's tile_done under mpirun (run by
 * tests/cli/mpi.sh): on rank 0 it is told of every tile of the image once,
 * every rank's, with the pixels the image ends up with; on the other ranks
 * it is never called. Exit 0 when so, 1 with the reason on stderr. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glint_mpi.h"
#include "unit/tiles_told.h"

#define WIDTH 90
#define HEIGHT 70

int main(int argc, char **argv)
{
    int provided, rank;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    tiles_told s;
    if (!tiles_told_init(&s, WIDTH, HEIGHT))
        return 1;
    glint_error err;
    glint_scene *scene = glint_scene_seed_room(&err);
    glint_settings settings = glint_scene_get_settings(scene);
    settings.width = WIDTH; /* edge tiles narrower and shorter than the rest */
    settings.height = HEIGHT;
    glint_scene_set_settings(scene, &settings, NULL);
    glint_render_options options = {.threads = 2, .tile_size = 16, .tile_done = tiles_told_note, .tile_user = &s};
    glint_image image = {0};
    glint_render_stats stats;
    const char *wrong = NULL;
    if (glint_mpi_render(MPI_COMM_WORLD, scene, &options, &image, &stats, NULL, &err))
        wrong = err.message;
    else if (rank != 0 && s.calls != 0)
        wrong = "tile_done was called on a rank other than 0";
    else if (rank == 0 && s.calls != stats.tiles_total)
        wrong = "tile_done was not called once for each tile";
    else if (rank == 0 && memcmp(s.pixels, image.pixels, (size_t)WIDTH * HEIGHT * 3 * sizeof(float)) != 0)
        wrong = "the pixels tile_done was given are not the image's";
    else if (rank == 0 && !tiles_told_once_each(&s))
        wrong = "a pixel was told of other than once";
    if (wrong)
        fprintf(stderr, "mpi_tiles: rank %d: %s\n", rank, wrong);
    tiles_told_free(&s);
    glint_image_free(&image);
    glint_scene_free(scene);
    MPI_Finalize();
    return wrong ? 1 : 0;
}
