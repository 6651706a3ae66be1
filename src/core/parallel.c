/* parallel.c - running one function on several threads (parallel.h). */
#include <pthread.h>
#include <stdbool.h>
#include <stdlib.h>
#include "core/parallel.h"

typedef struct helper {
    pthread_t id;
    bool started;
} helper;

void parallel_run(int count, void *(*fn)(void *arg), void *args, size_t stride)
{
    char *base = args;
    helper *h = count > 1 ? calloc((size_t)count - 1, sizeof *h) : NULL;
    for (int i = 1; h && i < count; i++)
        h[i - 1].started = pthread_create(&h[i - 1].id, NULL, fn, base + (size_t)i * stride) == 0;
    fn(base);
    for (int i = 1; i < count; i++) {
        if (h && h[i - 1].started)
            pthread_join(h[i - 1].id, NULL);
        else
            fn(base + (size_t)i * stride);
    }
    free(h);
}
