/* mesh_import.h - the parts of the model importer (docs/meshes.md): which
 * formats it takes, reading files, glint's own OBJ importer, the checks
 * made before Assimp sees a file of another format, the file system Assimp
 * reads through, and turning a model's materials into glint's. */
#ifndef GLINT_MODEL_MESH_IMPORT_H
#define GLINT_MODEL_MESH_IMPORT_H

#include <stdbool.h>
#include <stddef.h>
#include <assimp/cfileio.h>
#include <assimp/scene.h>
#include "glint.h"
#include "model/mtl_read.h"

/* The most vertices, and triangles, an imported mesh may have. */
#define MESH_IMPORT_MAX_COUNT (1LL << 30)

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
 * reader it has), a glTF or GLB image media type without its '/', and a PLY
 * file whose header or data do not follow the format (Assimp's reader
 * corrupts memory, loops or allocates whatever counts it claims). `file`
 * names the model in messages. */
glint_status mesh_import_check(mesh_format f, const unsigned char *data, size_t size, const char *file,
                               glint_error *err);

/* Refuses glTF JSON text (size bytes) in which an image's mimeType, or a
 * data URI's media type, has no '/': Assimp's reader crashes on them.
 * Messages start with `where` and then "line:column: ", the position in
 * the text. */
glint_status gltf_check_media_types(const unsigned char *text, size_t size, const char *where, glint_error *err);

/* Opens `path` for reading into *fd: a regular file (opening a FIFO does
 * not block, and it is refused); *size is its size. */
glint_status mesh_import_open(const char *path, int *fd, size_t *size, glint_error *err);

/* Reads the `size` bytes of the open file fd (named `path` in messages)
 * into *data, which the caller frees. */
glint_status mesh_import_read_fd(int fd, size_t size, const char *path, unsigned char **data, glint_error *err);

/* Opens and reads a whole file; *data is freed by the caller. */
glint_status mesh_import_read_file(const char *path, unsigned char **data, size_t *size, glint_error *err);

/* The path of a file a model names, `ref` as written, relative to the
 * model's directory `dir` unless absolute, its backslashes read as '/' (as
 * models made on Windows separate folders). NULL when out of memory. */
char *mesh_import_path(const char *dir, const char *ref);

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

/* A model's material, as glint is to add it. */
typedef struct import_material {
    const char *name;         /* the file's name for it; NULL for triangles the file gives no material */
    glint_material m;         /* its texture is set from `texture` */
    const char *texture;      /* its image: a file relative to the model's directory ('\\' read as '/'),
                                 "*N" for image N embedded in ai, or NULL */
} import_material;

/* Adds the `count` materials, their image textures first (each once), and
 * sets index[i] to material i's. A material without a name gets
 * ctx->default_material, or, when that is -1, a grey "<stem>/default"
 * made on first need. `ai` holds embedded images, or is NULL. */
glint_status mesh_import_add_materials(glint_scene *scene, const import_material *mats, size_t count,
                                       const struct aiScene *ai, const mesh_import_ctx *ctx, int *index,
                                       glint_error *err);

/* Adds a glint material for each Assimp (glTF, PLY, STL) material with
 * used[i] set, with the image textures they name, and sets index[i] to it. */
glint_status mesh_import_materials(glint_scene *scene, const struct aiScene *ai, const bool *used, int *index,
                                   const mesh_import_ctx *ctx, glint_error *err);

/* The glint material of an MTL material, by the table of docs/meshes.md;
 * no texture. */
glint_material mesh_import_from_mtl(const mtl_material *m);

/* Adds the mesh d named after the model, with a message naming the model
 * when glint refuses it. */
int mesh_import_add_mesh(glint_scene *scene, const mesh_import_ctx *ctx, const glint_mesh_data *d, glint_error *err);

/* Imports an OBJ model with glint's own reader, streaming it from the open
 * file fd, or, when fd is -1, from the `size` bytes at data. Its MTL files
 * and textures are read only when ctx->dir is set. Returns the mesh's index
 * or -1 with err filled. */
int mesh_import_obj(glint_scene *scene, const mesh_import_ctx *ctx, int fd, const unsigned char *data, size_t size,
                    double crease, glint_error *err);

#endif
