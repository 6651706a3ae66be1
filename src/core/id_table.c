/* id_table.c - open addressing over ids whose keys the caller keeps. */
#include <stdlib.h>
#include "core/array.h"
#include "core/id_table.h"

uint32_t id_hash_text(const char *s)
{
    /* FNV-1a over the bytes, then mixed. */
    uint32_t h = 2166136261u;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 16777619u;
    return hash_u32(h);
}

/* Enters id at its hash's first free slot; the table has a free slot. */
static void place(id_table *t, uint32_t h, uint32_t id)
{
    size_t i = (size_t)h & t->mask;
    while (t->slots[i].id)
        i = (i + 1) & t->mask;
    t->slots[i] = (id_slot){id + 1, h};
}

bool id_table_reserve(id_table *t, size_t n)
{
    size_t slots = t->slots ? t->mask + 1 : 0;
    if (n <= slots / 4 * 3)
        return true;
    size_t want = 16;
    while (want / 4 * 3 < n) {
        /* Hashes have 32 bits: more slots could never be reached. */
        if (want >= (size_t)1 << 31)
            return false;
        want *= 2;
    }
    size_t bytes;
    id_slot *fresh = size_mul(want, sizeof *fresh, &bytes) ? calloc(want, sizeof *fresh) : NULL;
    if (!fresh)
        return false;
    id_table old = *t;
    t->slots = fresh;
    t->mask = want - 1;
    for (size_t i = 0; i < slots; i++)
        if (old.slots[i].id)
            place(t, old.slots[i].hash, old.slots[i].id - 1);
    free(old.slots);
    return true;
}

bool id_table_add(id_table *t, uint32_t h, uint32_t new_id)
{
    if (!id_table_reserve(t, t->count + 1))
        return false;
    place(t, h, new_id);
    t->count++;
    return true;
}

void id_table_free(id_table *t)
{
    free(t->slots);
    *t = (id_table){0};
}
