/* file_set.h - a set of files as the file system knows them (device and
 * inode), each with its index in the order entered, found in constant time:
 * a scene remembers every file it was read from, and shares one decoding
 * of each image file, however many thousands of files it names. Another
 * name for the same file (a link, a "./" more) is the same file. */
#ifndef GLINT_CORE_FILE_SET_H
#define GLINT_CORE_FILE_SET_H

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>
#include "core/id_table.h"

typedef struct file_id {
    dev_t dev;
    ino_t ino;
} file_id;

typedef struct file_set {
    file_id *files;           /* in the order entered */
    size_t count, cap;
    id_table index;
} file_set;

/* The index of file (dev, ino) in the set, or -1 when it is not in it. */
long file_set_find(const file_set *s, dev_t dev, ino_t ino);

/* The index of file (dev, ino), entering it at index s->count when it is
 * not in the set yet; -1 when out of memory (the set is then unchanged). */
long file_set_add(file_set *s, dev_t dev, ino_t ino);

/* Frees the set and empties it. */
void file_set_free(file_set *s);

#endif
