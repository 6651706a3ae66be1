/* agree.h - a number every rank of glint-mpi must agree on (whether the
 * scene loaded, the exit code), shared through MPI's non-blocking
 * collectives and waited for with backoff.h's sleeps: OpenMPI's blocking
 * calls spin, which would take a core from a rank still loading or
 * writing on the same machine. Called by every rank's MPI thread alike. */
#ifndef GLINT_MPI_AGREE_H
#define GLINT_MPI_AGREE_H

/* Rank 0's *value, on every rank. */
void agree_on_rank0(int *value);

/* The largest of the ranks' *value, on every rank. */
void agree_on_max(int *value);

/* The smallest of the ranks' *value, on every rank. */
void agree_on_min(int *value);

#endif
