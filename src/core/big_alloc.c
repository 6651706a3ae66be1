/* big_alloc.c - large buffers on huge pages (big_alloc.h says why). */
#define _DEFAULT_SOURCE /* madvise */
#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>
#include "core/big_alloc.h"

/* The huge page size of x86-64 and arm64 kernels with 4 KiB pages. */
#define HUGE_PAGE ((size_t)2 << 20)

void *big_alloc(size_t bytes)
{
    if (bytes < BIG_ALLOC_MIN)
        return malloc(bytes ? bytes : 1);
    if (bytes > SIZE_MAX - HUGE_PAGE)
        return NULL;
    size_t span = (bytes + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
    void *p = NULL;
    if (posix_memalign(&p, HUGE_PAGE, span) != 0)
        return NULL;
    madvise(p, span, MADV_HUGEPAGE);
    return p;
}
