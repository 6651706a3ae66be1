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

void agree_on_rank0_bytes(MPI_Comm comm, void *bytes, int n)
{
    MPI_Request request;
    MPI_Ibcast(bytes, n, MPI_BYTE, 0, comm, &request);
    wait_quietly(&request);
}

void agree_on_rank0(MPI_Comm comm, int *value)
{
    agree_on_rank0_bytes(comm, value, sizeof *value);
}

/* The ranks' *value combined by op, on every rank. */
static void agree_by(MPI_Comm comm, int *value, MPI_Op op)
{
    int mine = *value;
    MPI_Request request;
    MPI_Iallreduce(&mine, value, 1, MPI_INT, op, comm, &request);
    wait_quietly(&request);
}

void agree_on_max(MPI_Comm comm, int *value)
{
    agree_by(comm, value, MPI_MAX);
}

void agree_on_min(MPI_Comm comm, int *value)
{
    agree_by(comm, value, MPI_MIN);
}
