/* assimp_material.h - the materials of a model Assimp read, as glint's
 * (assimp_material.c). */
#ifndef GLINT_MODEL_ASSIMP_MATERIAL_H
#define GLINT_MODEL_ASSIMP_MATERIAL_H

#include <stdbool.h>
#include <stddef.h>
#include <assimp/scene.h>
#include "glint.h"
#include "model/model_format.h"

/* Adds a glint material for each of Assimp's materials with used[i] set,
 * with the images they name (embedded in the file, or files beside it),
 * and sets index[i] to it. Material i's emission_strength is strengths[i]
 * when i < strength_count (a glTF's emissive strength, which Assimp does
 * not read: gltf_emissive.h), else 1. */
glint_status assimp_add_materials(glint_scene *scene, const struct aiScene *ai, const bool *used, int *index,
                                  const double *strengths, size_t strength_count, const model_import *job,
                                  glint_error *err);

#endif
