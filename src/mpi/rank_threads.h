/* rank_threads.h - how many render threads a glint-mpi rank runs when it
 * is not told: one per processor the rank may run on. */
#ifndef GLINT_MPI_RANK_THREADS_H
#define GLINT_MPI_RANK_THREADS_H

/* The processors this process may run on (its affinity), at least 1. */
int rank_threads(void);

#endif
