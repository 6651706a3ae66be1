/* same_build.h - glint-mpi refuses to start when its ranks run different
 * builds: a rank of another version, or of the same version built by
 * another compiler or with other flags, could compute other pixels (the
 * image would then depend on which rank rendered which tile) or read the
 * other ranks' messages wrongly. A build is known by glint's version and
 * the executable's GNU build ID, the linker's hash of its code. */
#ifndef GLINT_MPI_SAME_BUILD_H
#define GLINT_MPI_SAME_BUILD_H

/* Every rank calls it at once: -1 when all run rank 0's build, else
 * CLI_EXIT_USAGE on every rank, rank 0 having said which rank differs. */
int check_same_build(int rank, int ranks);

#endif
