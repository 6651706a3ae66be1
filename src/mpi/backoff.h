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
    long max_ns;              /* the longest; 0: BACKOFF_MAX_NS */
} backoff;

#define BACKOFF_MIN_NS 20000L
#define BACKOFF_MAX_NS 1000000L
/* The longest sleep of a rank whose own render is over: its cores are
 * idle, and the job ends when the last messages are through. */
#define BACKOFF_IDLE_NS 50000L

/* After a turn of the loop: returns at once when `busy` (something was
 * sent or received, and more may be waiting), else sleeps, twice as long
 * as last time up to its longest. A message handled is no reason to
 * poll faster: each wake-up takes a core from a render thread. */
static inline void backoff_after(backoff *b, bool busy)
{
    long max = b->max_ns ? b->max_ns : BACKOFF_MAX_NS;
    b->ns = b->ns < BACKOFF_MIN_NS ? BACKOFF_MIN_NS : b->ns > max ? max : b->ns;
    if (busy)
        return;
    struct timespec ts = {0, b->ns};
    nanosleep(&ts, NULL);
    b->ns = b->ns * 2 < max ? b->ns * 2 : max;
}

#endif
