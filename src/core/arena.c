/* arena.c - chunks of 1 MiB cut into pieces front to back; a rollback
 * frees the chunks made since its mark and cuts its chunk back. */
#include <stdint.h>
#include <stdlib.h>
#include "core/arena.h"

#define CHUNK_BYTES ((size_t)1 << 20)
#define ALIGN 8

struct arena_chunk {
    struct arena_chunk *next;
    size_t used, size;
    _Alignas(ALIGN) unsigned char data[];
};

void *arena_alloc(arena *a, size_t size)
{
    if (size > SIZE_MAX - ALIGN - sizeof(struct arena_chunk))
        return NULL;
    size = (size + ALIGN - 1) & ~(size_t)(ALIGN - 1);
    struct arena_chunk *c = a->chunks;
    if (c && c->size - c->used >= size) {
        void *p = c->data + c->used;
        c->used += size;
        return p;
    }
    /* A large piece gets a chunk of its own, behind the current one, so
     * that the room left in the current one is not thrown away. */
    size_t room = size > CHUNK_BYTES / 4 ? size : CHUNK_BYTES;
    struct arena_chunk *fresh = malloc(sizeof *fresh + room);
    if (!fresh)
        return NULL;
    fresh->used = size;
    fresh->size = room;
    if (c && room == size) {
        fresh->next = c->next;
        c->next = fresh;
    } else {
        fresh->next = c;
        a->chunks = fresh;
    }
    return fresh->data;
}

arena_point arena_mark(const arena *a)
{
    struct arena_chunk *c = a->chunks;
    return (arena_point){c, c ? c->next : NULL, c ? c->used : 0};
}

void arena_rollback(arena *a, arena_point mark)
{
    /* Chunks made since the mark are all in front of its chunk, except the
     * large pieces cut while it was the newest: those went right behind
     * it, in front of the chunk that was behind it then. */
    while (a->chunks != mark.chunk) {
        struct arena_chunk *c = a->chunks;
        a->chunks = c->next;
        free(c);
    }
    if (!mark.chunk)
        return;
    mark.chunk->used = mark.used;
    while (mark.chunk->next != mark.behind) {
        struct arena_chunk *c = mark.chunk->next;
        mark.chunk->next = c->next;
        free(c);
    }
}

void arena_free(arena *a)
{
    for (struct arena_chunk *c = a->chunks, *next; c; c = next) {
        next = c->next;
        free(c);
    }
    a->chunks = NULL;
}
