/* arena.h - a bump allocator for many small pieces freed all at once: a
 * YAML tree of millions of nodes costs their bytes, not a malloc header
 * and a rounded-up block each. */
#ifndef GLINT_CORE_ARENA_H
#define GLINT_CORE_ARENA_H

#include <stddef.h>

typedef struct arena {
    struct arena_chunk *chunks;   /* newest first; NULL when empty */
} arena;

/* `size` bytes aligned for any pointer or double, uninitialised; NULL when
 * out of memory. They live until arena_free. */
void *arena_alloc(arena *a, size_t size);

/* Frees every piece and empties the arena. */
void arena_free(arena *a);

#endif
