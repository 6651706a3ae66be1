/* processors.h - how many threads "one per processor" means. */
#ifndef GLINT_CORE_PROCESSORS_H
#define GLINT_CORE_PROCESSORS_H

#include <unistd.h>

/* The processors online, at least 1 and at most `most`. */
static inline int processors_online(int most)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > most ? most : (int)n;
}

#endif
