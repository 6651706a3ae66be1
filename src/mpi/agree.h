/* agree.h - what every rank of glint-mpi must agree on (whether the scene
 * loaded and why not, the exit code), shared through MPI's non-blocking
 * collectives and waited for with backoff.h's sleeps: OpenMPI's blocking
 * calls spin, which would take a core from a rank still loading or
 * writing on the same machine. Called by every rank's MPI thread alike. */
#ifndef GLINT_MPI_AGREE_H
#define GLINT_MPI_AGREE_H

#include <mpi.h>

/* Rank 0's n bytes, on every rank of comm. */
void agree_on_rank0_bytes(MPI_Comm comm, void *bytes, int n);

/* Rank 0's *value, on every rank of comm. */
void agree_on_rank0(MPI_Comm comm, int *value);

/* The largest of the ranks' *value, on every rank. */
void agree_on_max(MPI_Comm comm, int *value);

/* The smallest of the ranks' *value, on every rank. */
void agree_on_min(MPI_Comm comm, int *value);

#endif
