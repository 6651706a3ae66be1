/* same_build.h - glint-mpi refuses to start when its ranks run different
 * builds: a rank of another version, or of the same version built by
 * another compiler or with other flags, could compute other pixels (the
 * image would then depend on which rank rendered which tile) or read the
 * other ranks' messages wrongly. A build is known by glint's version and
 * the executable's GNU build ID, the linker's hash of its code. */
#ifndef GLINT_MPI_SAME_BUILD_H
#define GLINT_MPI_SAME_BUILD_H

#include <mpi.h>
#include "glint.h"

/* Every rank of comm calls it at once: GLINT_OK when all run rank 0's
 * build, else GLINT_ERR_INVALID on every rank with err naming the first
 * rank that differs (on rank 0, with both builds). */
glint_status check_same_build(MPI_Comm comm, glint_error *err);

#endif
