/* model_build.h - what every model reader ends with, through the public
 * API only: the materials its triangles use, their images as UV-mapped
 * textures (each added once), then one mesh, named after the model
 * (docs/meshes.md). */
#ifndef GLINT_MODEL_MODEL_BUILD_H
#define GLINT_MODEL_MODEL_BUILD_H

#include <stddef.h>
#include "glint.h"
#include "model/model_format.h"

/* The most vertices, and triangles, an imported mesh may have: glint's
 * mesh limit. */
#define MODEL_MAX_COUNT (1LL << 30)

/* The highest Phong exponent a model's material is given. */
#define MODEL_MAX_SHININESS 10000.0

/* x clamped into [lo, hi]: a file's values outside glint's ranges are
 * brought into them, so that its materials never fail to be added. */
static inline double model_clamp(double x, double lo, double hi)
{
    return x < lo ? lo : x > hi ? hi : x;
}

/* A model's material, as glint is to add it. */
typedef struct model_material {
    const char *name;         /* the file's name for it; NULL for triangles the file gives no material */
    glint_material m;         /* its textures are set from the images below */
    const char *texture;      /* its colour image as the file names it, or NULL */
    const char *bump;         /* its height map, or NULL */
    const char *normals;      /* its tangent-space normal map, or NULL */
} model_material;

/* Adds the image a material names as `ref` as a texture, and sets *out to
 * its index, or to -1 when it is not to be used; `user` is what the reader
 * handed to model_add_materials. */
typedef glint_status (*model_texture_fn)(glint_scene *scene, const char *ref, const model_import *job, void *user,
                                         int *out, glint_error *err);

/* The model_texture_fn of image files: `ref` is a file relative to the
 * model's directory ('\\' read as '/'); -1 when the model may read no
 * other file. `user` is not used. */
glint_status model_add_texture_file(glint_scene *scene, const char *ref, const model_import *job, void *user,
                                    int *out, glint_error *err);

/* Adds the `count` materials, their textures first (each ref once, through
 * add_texture with `user`), and sets index[i] to material i's. Materials
 * are named "<stem>/<name>", or "<stem>/<name>#N" when that is taken. A
 * material without a name gets job->default_material, or, when that is -1,
 * a grey "<stem>/default" made on first need; *job->stand_in is then set to
 * it. */
glint_status model_add_materials(glint_scene *scene, const model_material *mats, size_t count,
                                 model_texture_fn add_texture, void *user, const model_import *job, int *index,
                                 glint_error *err);

/* Adds the mesh d named after the model, with a message naming the model
 * when glint refuses it, and marks it bare when every triangle has the
 * stand-in material (glint_scene_mesh_is_bare). Returns its index or -1. */
int model_add_mesh(glint_scene *scene, const model_import *job, const glint_mesh_data *d, glint_error *err);

#endif
