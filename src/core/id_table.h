/* id_table.h - a set of ids whose keys live in the caller's own arrays:
 * open addressing with linear probing over a power-of-two table of slots
 * (an id and its key's hash), so that readers can join equal keys (face
 * corners, names, positions) and the scene can find a texture or material
 * by name, each in constant time, with no allocation per key. The caller
 * stores key i at index i, gives each key's hash and hands the table a
 * function that compares a stored key with one being looked up. Hashes
 * have 32 bits, and the table at most 2^31 slots (1.6 billion ids). */
#ifndef GLINT_CORE_ID_TABLE_H
#define GLINT_CORE_ID_TABLE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "core/hash.h"

/* True when stored key `id` equals `key`. */
typedef bool (*id_equal_fn)(const void *keys, uint32_t id, const void *key);

/* A slot: id + 1 (0: empty) and its key's hash, side by side, so that a
 * probe reads a stored key (in the caller's records, most often a cache
 * miss) only when the hashes match, and growing needs no key at all. */
typedef struct id_slot {
    uint32_t id;
    uint32_t hash;
} id_slot;

typedef struct id_table {
    id_slot *slots;
    size_t mask;              /* slot count - 1; no slots yet when slots is NULL */
    size_t count;             /* ids entered */
} id_table;

/* Makes room for n ids in all without growing again (at most 3/4 full),
 * rehashing those entered. False when out of memory; the table is then
 * unchanged. */
bool id_table_reserve(id_table *t, size_t n);

/* Enters new_id, whose key has hash h and is not in the table yet. False
 * when the table could not grow (out of memory). */
bool id_table_add(id_table *t, uint32_t h, uint32_t new_id);

/* Looks up `key` (hash h) without entering it: true with *id set when
 * found. Inline, so that a caller's `equal` is inlined in the probe loop. */
static inline bool id_table_find(const id_table *t, uint32_t h, const void *key, id_equal_fn equal,
                                 const void *keys, uint32_t *id)
{
    if (!t->slots)
        return false;
    for (size_t i = (size_t)h & t->mask; t->slots[i].id; i = (i + 1) & t->mask)
        if (t->slots[i].hash == h && equal(keys, t->slots[i].id - 1, key)) {
            *id = t->slots[i].id - 1;
            return true;
        }
    return false;
}

/* Looks up `key`, whose hash is h: sets *id to the id of the stored key
 * equal to it, or, when there is none, enters new_id for it and sets *id to
 * new_id; the caller then stores the key at index new_id. False when the
 * table could not grow (out of memory). */
static inline bool id_table_intern(id_table *t, uint32_t h, const void *key, uint32_t new_id, id_equal_fn equal,
                                   const void *keys, uint32_t *id)
{
    if (id_table_find(t, h, key, equal, keys, id))
        return true;
    *id = new_id;
    return id_table_add(t, h, new_id);
}

/* Frees the slots and empties the table. */
void id_table_free(id_table *t);

/* A well-mixed hash of n 32-bit words (inline: it is in readers' inner
 * loops). */
static inline uint32_t id_hash_words(const uint32_t *words, size_t n)
{
    uint32_t h = (uint32_t)n;
    for (size_t i = 0; i < n; i++)
        h = hash_u32(h ^ words[i]);
    return h;
}

/* A well-mixed hash of a NUL-terminated string. */
uint32_t id_hash_text(const char *s);

#endif
