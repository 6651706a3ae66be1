/* embed_mpi.c - the smallest MPI program that embeds libglint_mpi: a scene
 * file loaded on rank 0 and sent to every rank with its files, rendered by
 * all of them, and written by rank 0.
 *   usage: mpirun -np N embed_mpi SCENE.yaml OUTPUT.png */
#include <mpi.h>
#include <stdio.h>
#include "glint_mpi.h"

int main(int argc, char **argv)
{
    int provided, rank;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    int code = 0;
    if (argc != 3) {
        if (rank == 0)
            fprintf(stderr, "usage: mpirun -np N embed_mpi SCENE.yaml OUTPUT.png\n");
        code = 2;
    } else {
        glint_error err;
        glint_image image = {0};
        glint_scene *scene = glint_mpi_scene_load_file(MPI_COMM_WORLD, argv[1], NULL, &err);
        /* Every rank learns the same outcome: none leaves the others waiting. */
        if (!scene || glint_mpi_render(MPI_COMM_WORLD, scene, NULL, &image, NULL, NULL, &err) ||
            (rank == 0 && glint_image_write(&image, argv[2], &err))) {
            fprintf(stderr, "embed_mpi: rank %d: %s\n", rank, err.message);
            code = 1;
        }
        glint_image_free(&image);
        glint_scene_free(scene);
    }
    MPI_Finalize();
    return code;
}
