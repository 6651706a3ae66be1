/* mesh_import.h - the parts of the model importer (docs/meshes.md): which
 * formats it takes, the checks made before Assimp sees a file, the file
 * system Assimp reads through, and the materials it turns into glint's. */
#ifndef GLINT_IO_MESH_IMPORT_H
#define GLINT_IO_MESH_IMPORT_H

#include <stdbool.h>
#include <stddef.h>
#include <assimp/cfileio.h>
#include <assimp/scene.h>
#include "glint.h"

/* The formats glint imports, told apart by the file name's extension. */
typedef enum mesh_format {
    MESH_FORMAT_NONE = 0,
    MESH_FORMAT_OBJ,
    MESH_FORMAT_PLY,
    MESH_FORMAT_STL,
    MESH_FORMAT_GLTF,
    MESH_FORMAT_GLB
} mesh_format;

/* The format named by the extension of `name` (any case), or NONE. */
mesh_format mesh_import_format(const char *name);

/* Extension of a format, without the dot, as Assimp's hint. */
const char *mesh_import_extension(mesh_format f);

/* Refuses bytes that would send Assimp astray before it parses them: a GLB
 * without its magic or a glTF that is not JSON (Assimp would try every other
 * reader it has), and a PLY file whose header or data do not follow the
 * format (Assimp's reader corrupts memory, loops or allocates whatever
 * counts it claims). `file` names the model in messages. */
glint_status mesh_import_check(mesh_format f, const unsigned char *data, size_t size, const char *file,
                               glint_error *err);

/* Reads a whole model file; *data is freed by the caller. */
glint_status mesh_import_read_file(const char *path, unsigned char **data, size_t *size, glint_error *err);

/* What Assimp may read: the model itself, served from memory under `name`,
 * and, when `disk` is set, any regular file it names (MTL, glTF buffers). */
typedef struct mesh_source {
    const char *name;
    const unsigned char *data;
    size_t size;
    bool disk;
} mesh_source;

/* Fills an Assimp file system that reads through src, which must outlive it. */
void mesh_import_io(struct aiFileIO *io, mesh_source *src);

/* What the material mapping needs to know about the import. */
typedef struct mesh_import_ctx {
    const char *file;         /* the model, as named in messages */
    char *stem;               /* file name less directory and extension: material name prefix */
    char *dir;                /* directory that texture paths are relative to; NULL: no texture files */
    mesh_format format;
    int default_material;     /* for triangles without a material in the file; -1: a grey one */
} mesh_import_ctx;

/* Adds a glint material for each Assimp material with used[i] set, with the
 * image textures they name, and sets index[i] to it. */
glint_status mesh_import_materials(glint_scene *scene, const struct aiScene *ai, const bool *used, int *index,
                                   const mesh_import_ctx *ctx, glint_error *err);

#endif
