/* array.c - growing arrays by doubling. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/big_alloc.h"

bool array_grow(void **items, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return true;
    size_t ncap = *cap ? *cap : 16, bytes;
    while (ncap < need) {
        if (ncap > SIZE_MAX / 2)
            return false;
        ncap *= 2;
    }
    if (!size_mul(ncap, size, &bytes))
        return false;
    /* From BIG_ALLOC_MIN up the room is big_alloc's, on huge pages, and the
     * items are copied there. realloc would move them without a copy, but
     * onto 4 KiB pages, each cleared at its first write by a page fault of
     * about 10 us on the machines glint is measured on: 2,300 of them
     * went with the bunny's load, 660 with SPD rings'. A copy at each
     * doubling costs far less (bench/README.md). */
    void *p;
    if (bytes < BIG_ALLOC_MIN)
        p = realloc(*items, bytes);
    else if ((p = big_alloc(bytes)) != NULL) {
        if (*items)
            memcpy(p, *items, *cap * size);
        free(*items);
    }
    if (!p)
        return false;
    *items = p;
    *cap = ncap;
    return true;
}

void *array_alloc(size_t count, size_t size)
{
    size_t bytes;
    if (!size_mul(count, size, &bytes))
        return NULL;
    /* big_alloc gives small buffers malloc's memory and large ones huge
     * pages: a million-triangle model's arrays, each written whole once,
     * took 6,000 page faults on 4 KiB pages. */
    return big_alloc(bytes);
}
