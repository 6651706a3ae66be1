/* seen_set.h - the surfaces a shadow segment has already been filtered by.
 * Embree may report the same primitive to a query more than once (packet
 * traversal does, for user geometry), and each must filter the light only
 * once: a shadow query keeps one set per lane. Keys are (geometry ID << 32
 * | primitive ID); the first few live inline, so most sets never allocate. */
#ifndef GLINT_ACCEL_SEEN_SET_H
#define GLINT_ACCEL_SEEN_SET_H

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define SEEN_INLINE 16
typedef struct seen_set {
    uint64_t inline_keys[SEEN_INLINE];
    uint64_t *keys;           /* inline_keys, or a heap array once those are full */
    int count, cap;
} seen_set;

/* Adds key; false when it was there already. When memory runs out the key
 * is not kept, and a repeat would filter twice. */
static inline bool seen_add(seen_set *s, uint64_t key)
{
    if (!s->keys) {
        s->keys = s->inline_keys;
        s->cap = SEEN_INLINE;
    }
    for (int k = 0; k < s->count; k++)
        if (s->keys[k] == key)
            return false;
    if (s->count == s->cap) {
        uint64_t *grown = malloc(2 * (size_t)s->cap * sizeof *grown);
        if (!grown)
            return true;
        memcpy(grown, s->keys, (size_t)s->count * sizeof *grown);
        if (s->keys != s->inline_keys)
            free(s->keys);
        s->keys = grown;
        s->cap *= 2;
    }
    s->keys[s->count++] = key;
    return true;
}

/* An empty set; cheap, as every lane of every shadow query starts one. */
static inline void seen_init(seen_set *s)
{
    s->keys = NULL;
    s->count = s->cap = 0;
}

/* Frees what the set allocated. */
static inline void seen_free(seen_set *s)
{
    /* Most sets were never used: no call to free(NULL) for them. */
    if (s->keys && s->keys != s->inline_keys)
        free(s->keys);
}

#endif
