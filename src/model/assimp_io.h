/* assimp_io.h - the file system Assimp reads a model through
 * (assimp_io.c). */
#ifndef GLINT_MODEL_ASSIMP_IO_H
#define GLINT_MODEL_ASSIMP_IO_H

#include <stdbool.h>
#include <stddef.h>
#include <assimp/cfileio.h>

/* What Assimp may read: the model itself, served from memory under `name`,
 * and, when `disk` is set, any regular file it names (glTF buffers). */
typedef struct assimp_source {
    const char *name;
    const unsigned char *data;
    size_t size;
    bool disk;
} assimp_source;

/* Fills an Assimp file system that reads through src, which must outlive
 * it. */
void assimp_io_init(struct aiFileIO *io, assimp_source *src);

#endif
