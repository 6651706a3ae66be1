/* backoff.h - how rank 0's MPI thread, and any rank's waiting for the
 * others, waits when nothing happened: a sleep that starts short and
 * doubles up to a millisecond, so that polling MPI takes next to no
 * processor time from the render threads, while rank 0 still answers
 * within a millisecond (a worker holds enough tiles to cover that,
 * follow.c). */
#ifndef GLINT_MPI_BACKOFF_H
#define GLINT_MPI_BACKOFF_H

#include <stdbool.h>
#include <time.h>

typedef struct backoff {
    long ns;                  /* the next sleep */
} backoff;

#define BACKOFF_MIN_NS 20000L
#define BACKOFF_MAX_NS 1000000L

/* After a turn of the loop: returns at once when `busy` (something was
 * sent or received, and more may be waiting), else sleeps, twice as long
 * as last time up to BACKOFF_MAX_NS. A message handled is no reason to
 * poll faster: each wake-up takes a core from a render thread. */
static inline void backoff_after(backoff *b, bool busy)
{
    if (b->ns < BACKOFF_MIN_NS)
        b->ns = BACKOFF_MIN_NS;
    if (busy)
        return;
    struct timespec ts = {0, b->ns};
    nanosleep(&ts, NULL);
    b->ns = b->ns * 2 < BACKOFF_MAX_NS ? b->ns * 2 : BACKOFF_MAX_NS;
}

#endif
