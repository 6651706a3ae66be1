/* arena.h - a bump allocator for many small pieces freed all at once: a
 * YAML tree of millions of nodes costs their bytes, not a malloc header
 * and a rounded-up block each. A mark taken before some pieces gives them
 * back at once, so that a reader done with part of a tree reuses its
 * memory for the next part. */
#ifndef GLINT_CORE_ARENA_H
#define GLINT_CORE_ARENA_H

#include <stddef.h>

typedef struct arena {
    struct arena_chunk *chunks;   /* newest first; NULL when empty */
} arena;

/* A place in an arena's allocations, from arena_mark. */
typedef struct arena_point {
    struct arena_chunk *chunk;    /* the newest chunk then, or NULL */
    struct arena_chunk *behind;   /* the chunk behind it then */
    size_t used;                  /* and how much of it was cut */
} arena_point;

/* `size` bytes aligned for any pointer or double, uninitialised; NULL when
 * out of memory. They live until arena_free, or arena_rollback to a mark
 * taken before them. */
void *arena_alloc(arena *a, size_t size);

/* Where the arena is now, for arena_rollback. */
arena_point arena_mark(const arena *a);

/* Gives back every piece allocated since `mark` was taken: their memory
 * is reused by the next pieces, and chunks made since are freed. A mark
 * stays good through later marks and rollbacks to them, but not through a
 * rollback to an earlier mark or arena_free. */
void arena_rollback(arena *a, arena_point mark);

/* Frees every piece and empties the arena. */
void arena_free(arena *a);

#endif
