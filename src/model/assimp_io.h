/* assimp_io.h - the file system Assimp reads a model through
 * (assimp_io.c). */
#ifndef GLINT_MODEL_ASSIMP_IO_H
#define GLINT_MODEL_ASSIMP_IO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <assimp/cfileio.h>
#include "glint.h"

/* What Assimp may read: the model itself, served from memory under `name`,
 * and, when `dir` is set, the regular files it names (glTF buffers) in
 * that folder or below, each noted in `scene` as one it was read from.
 * Assimp reads each buffer whole, so the model and its buffers together
 * may take at most model_file_memory_limit; `read` counts them, and is
 * reset to `size` before each import.
 * A file refused for any other reason than not existing fills `refusal`
 * (`refused` then set), which says more than Assimp's message would. */
typedef struct assimp_source {
    const char *name;
    const unsigned char *data;
    size_t size;
    const char *dir;
    const char *file;         /* the model as named in messages */
    glint_scene *scene;
    uint64_t read;            /* bytes of the model and the buffers opened so far in this import */
    bool refused;
    glint_error refusal;
} assimp_source;

/* Fills an Assimp file system that reads through src, which must outlive
 * it. */
void assimp_io_init(struct aiFileIO *io, assimp_source *src);

#endif
