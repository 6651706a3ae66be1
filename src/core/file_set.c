/* file_set.c - files by device and inode, in an id_table over the array
 * of them. */
#include <stdlib.h>
#include "core/array.h"
#include "core/file_set.h"

static uint32_t id_hash(file_id f)
{
    uint32_t words[4] = {(uint32_t)f.dev, (uint32_t)((uint64_t)f.dev >> 32), (uint32_t)f.ino,
                         (uint32_t)((uint64_t)f.ino >> 32)};
    return id_hash_words(words, 4);
}

static bool stored_equal(const void *files, uint32_t id, const void *key)
{
    const file_id *a = &((const file_id *)files)[id], *b = key;
    return a->dev == b->dev && a->ino == b->ino;
}

long file_set_find(const file_set *s, dev_t dev, ino_t ino)
{
    file_id key = {dev, ino};
    uint32_t id;
    return id_table_find(&s->index, id_hash(key), &key, stored_equal, s->files, &id) ? (long)id : -1;
}

long file_set_add(file_set *s, dev_t dev, ino_t ino)
{
    long found = file_set_find(s, dev, ino);
    if (found >= 0)
        return found;
    file_id key = {dev, ino};
    if (s->count >= UINT32_MAX - 1 || !array_reserve((void **)&s->files, &s->cap, s->count + 1, sizeof *s->files))
        return -1;
    s->files[s->count] = key;
    if (!id_table_add(&s->index, id_hash(key), (uint32_t)s->count))
        return -1;
    return (long)s->count++;
}

void file_set_free(file_set *s)
{
    free(s->files);
    id_table_free(&s->index);
    *s = (file_set){0};
}
