/* assimp_check.h - the checks a model's bytes pass before Assimp parses
 * them (model_check_fn, model_format.h): Assimp's readers allocate what a
 * file claims, loop or crash on some malformed files, and try every reader
 * they have on bytes the named one refuses. Each refuses with a message
 * starting with `file`. */
#ifndef GLINT_MODEL_ASSIMP_CHECK_H
#define GLINT_MODEL_ASSIMP_CHECK_H

#include <stdbool.h>
#include <stddef.h>
#include "glint.h"

/* A PLY file's header follows the grammar of docs/meshes.md, no element
 * claims more items than the data can hold, and the data matches the
 * header (ply_check.c). */
glint_status ply_check(const unsigned char *data, size_t size, const char *file, glint_error *err);

/* A glTF file starts with a JSON object, each image media type in it
 * has its '/', and its node hierarchy passes gltf_check_nodes
 * (gltf_check.c). */
glint_status gltf_check(const unsigned char *data, size_t size, const char *file, glint_error *err);

/* A GLB file starts with its magic, its chunks fit in it, and each image
 * media type in its JSON has its '/', and its node hierarchy passes
 * gltf_check_nodes (gltf_check.c). */
glint_status glb_check(const unsigned char *data, size_t size, const char *file, glint_error *err);

/* The JSON of a GLB that passed glb_check, its chunk 0, in *json and
 * *json_size; false when the file is too short to have one (Assimp
 * refuses it). */
bool glb_json(const unsigned char *data, size_t size, const unsigned char **json, size_t *json_size);

/* The most nodes a glTF's hierarchy may expand to, each node counted once
 * for every path to it from a root (docs/robustness.md): Assimp makes a
 * node of about 1 KB for each. */
#define GLTF_MAX_NODES 1000000

/* The bytes a vertex or an index of a glTF mesh takes, about, once Assimp
 * has copied it for a placement and glint has merged it. */
#define GLTF_PLACED_BYTES 64

/* Refuses glTF JSON text (size bytes) whose node hierarchy has a cycle or
 * expands to more than GLTF_MAX_NODES nodes, or (glTF 2) whose nodes place
 * their meshes' vertices and indices (their accessors' counts, once per
 * placement) more times than half of the machine's memory holds at
 * GLTF_PLACED_BYTES each (gltf_nodes.c). */
glint_status gltf_check_nodes(const unsigned char *text, size_t size, const char *file, glint_error *err);

#endif
