/* backoff.h - how a rank's MPI thread waits when nothing happened: a
 * sleep that starts short (a message answered quickly keeps other ranks
 * busy) and doubles up to a millisecond while the rank stays idle, so that
 * polling MPI takes next to no processor time from the render threads. */
#ifndef GLINT_MPI_BACKOFF_H
#define GLINT_MPI_BACKOFF_H

#include <stdbool.h>
#include <time.h>

typedef struct backoff {
    long ns;                  /* the next sleep */
} backoff;

#define BACKOFF_MIN_NS 20000L
#define BACKOFF_MAX_NS 1000000L

/* After a turn of the loop: sleeps unless `busy` (something was sent or
 * received), longer each idle turn in a row. */
static inline void backoff_after(backoff *b, bool busy)
{
    if (busy || b->ns < BACKOFF_MIN_NS) {
        b->ns = BACKOFF_MIN_NS;
        if (busy)
            return;
    }
    struct timespec ts = {0, b->ns};
    nanosleep(&ts, NULL);
    b->ns = b->ns * 2 < BACKOFF_MAX_NS ? b->ns * 2 : BACKOFF_MAX_NS;
}

#endif
