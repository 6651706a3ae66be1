/* assimp_merge.h - the meshes of a model Assimp read, merged into the
 * arrays of one glint mesh (assimp_merge.c). */
#ifndef GLINT_MODEL_ASSIMP_MERGE_H
#define GLINT_MODEL_ASSIMP_MERGE_H

#include <stdbool.h>
#include <stdint.h>
#include <assimp/scene.h>
#include "glint.h"

/* Assimp's meshes merged into arrays for glint_mesh_data. */
typedef struct assimp_merged {
    float *positions, *normals, *uvs;
    bool *unnormalled;        /* per vertex: its part gave no normals; NULL when every part did */
    uint32_t *indices;
    int *materials;           /* Assimp's material index per triangle, for the caller to make glint's */
    long long vertices, triangles;
} assimp_merged;

/* Merges every triangle of every mesh of ai into *out (zeroed first by the
 * caller) and sets used[i] for each material i a triangle uses. Positions
 * must be finite; normals and texture coordinates that are not become
 * zero, and v is flipped (Assimp's v = 0 is the image's bottom row,
 * glint's its top). `file` names the model in messages; on failure *out
 * still needs assimp_merged_free. */
glint_status assimp_merge(const struct aiScene *ai, const char *file, assimp_merged *out, bool *used,
                          glint_error *err);

/* Gives the vertices of parts without normals theirs, as an OBJ's are
 * made (crease_normals.h through obj_mesh.h: angle-weighted over the faces
 * within `crease` degrees, vertices joined by value), in time linear in
 * the mesh however many vertices share a point (Assimp's own smoothing is
 * quadratic there: minutes for 300,000 coincident vertices). Replaces the
 * arrays of *m; on failure fills err and *m still needs assimp_merged_free. */
glint_status assimp_make_normals(assimp_merged *m, double crease, const char *file, glint_error *err);

/* Frees the merged arrays. */
void assimp_merged_free(assimp_merged *m);

#endif
