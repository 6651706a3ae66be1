/* agree.c - numbers every rank agrees on, waited for without spinning
 * (agree.h). */
#include <mpi.h>
#include "mpi/agree.h"
#include "mpi/backoff.h"

/* Waits for a started collective to complete. */
static void wait_quietly(MPI_Request *request)
{
    backoff b = {0};
    int done = 0;
    for (;;) {
        MPI_Test(request, &done, MPI_STATUS_IGNORE);
        if (done)
            return;
        backoff_after(&b, false);
    }
}

void agree_on_rank0(int *value)
{
    MPI_Request request;
    MPI_Ibcast(value, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
    wait_quietly(&request);
}

/* The ranks' *value combined by op, on every rank. */
static void agree_by(int *value, MPI_Op op)
{
    int mine = *value;
    MPI_Request request;
    MPI_Iallreduce(&mine, value, 1, MPI_INT, op, MPI_COMM_WORLD, &request);
    wait_quietly(&request);
}

void agree_on_max(int *value)
{
    agree_by(value, MPI_MAX);
}

void agree_on_min(int *value)
{
    agree_by(value, MPI_MIN);
}
