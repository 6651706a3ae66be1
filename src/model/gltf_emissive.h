/* gltf_emissive.h - the emissive strength of a glTF 2 model's materials
 * (the extension KHR_materials_emissive_strength), which Debian's Assimp
 * (5.2.5) does not read: read from the JSON before Assimp reads the file,
 * and numbered as Assimp numbers its materials (gltf_emissive.c). */
#ifndef GLINT_MODEL_GLTF_EMISSIVE_H
#define GLINT_MODEL_GLTF_EMISSIVE_H

#include <stddef.h>
#include "glint.h"

/* glint's highest emission_strength: a larger one of a file is brought
 * down to it. */
#define GLTF_MAX_EMISSIVE_STRENGTH 1e300

/* Sets *strengths (malloc'd, *count of them, freed by the caller; NULL when
 * none) so that (*strengths)[k] is the emissiveStrength of the glTF
 * material that Assimp numbers k, for every material the model's scene
 * uses. Assimp does not keep the file's order: it numbers the materials as
 * it first meets them, reading the scene ("scene", or the first) root by
 * root, each node's children before the node's own mesh, a mesh's
 * primitives in order; then those of nodes outside the scene, which are
 * never placed, and then a default material. A material without the
 * extension, or whose strength is not a number, has 1. Refuses, with a
 * message starting with `file`, a strength that is negative or not finite
 * in any material. JSON text (size bytes) the scan cannot follow gives
 * none: Assimp's parser refuses it. */
glint_status gltf_emissive_strengths(const unsigned char *text, size_t size, const char *file, double **strengths,
                                     size_t *count, glint_error *err);

#endif
