/* rank_threads.c - a rank's render threads when it is not told how many
 * (rank_threads.h). mpirun binds each rank to one core by default when
 * there are at most two ranks, to a socket beyond: a thread per core of
 * the machine would then share the cores bound to. */
#define _GNU_SOURCE /* sched_getaffinity */
#include <sched.h>
#include "core/processors.h"
#include "mpi/rank_threads.h"

int rank_threads(void)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    int n = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 0;
    return n > 0 ? n : processors_online(1024);
}
