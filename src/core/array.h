/* array.h - arrays that grow by doubling, with every size computed in
 * checked arithmetic, for readers that append items one at a time. */
#ifndef GLINT_CORE_ARRAY_H
#define GLINT_CORE_ARRAY_H

#include <stdbool.h>
#include <stddef.h>

/* Makes room for `need` items of `size` bytes in *items, whose room is *cap
 * items, doubling it (from 16) until it fits; room of BIG_ALLOC_MIN bytes
 * or more is big_alloc's, on huge pages (core/big_alloc.h). *items is
 * freed with free(). False, with *items and *cap unchanged, when the bytes
 * would not fit in a size_t or memory runs out. */
static inline bool array_reserve(void **items, size_t *cap, size_t need, size_t size);

/* array_reserve when the room has to grow. */
bool array_grow(void **items, size_t *cap, size_t need, size_t size);

static inline bool array_reserve(void **items, size_t *cap, size_t need, size_t size)
{
    return need <= *cap || array_grow(items, cap, need, size);
}

/* Room for count items of `size` bytes (at least one byte, so that NULL
 * always means failure), not cleared, freed with free(): big_alloc's, so
 * on huge pages from BIG_ALLOC_MIN bytes up; NULL when the product
 * overflows or memory runs out. */
void *array_alloc(size_t count, size_t size);

/* a * b into *out; false when it does not fit in a size_t. */
static inline bool size_mul(size_t a, size_t b, size_t *out)
{
    return !__builtin_mul_overflow(a, b, out);
}

#endif
