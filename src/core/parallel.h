/* parallel.h - one call made on several threads at once, the caller's
 * among them. */
#ifndef GLINT_CORE_PARALLEL_H
#define GLINT_CORE_PARALLEL_H

#include <stddef.h>

/* Calls fn(args + i * stride) for each i in 0..count-1 (a stride of 0
 * gives every call the same argument): i = 0 on the calling thread, the
 * others each on a thread of its own, and returns once all have returned.
 * A call whose thread cannot start, for want of memory or threads, is made
 * on the calling thread after the first; work shared through a queue then
 * simply goes to the threads that did start. */
void parallel_run(int count, void *(*fn)(void *arg), void *args, size_t stride);

#endif
