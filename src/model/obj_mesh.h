/* obj_mesh.h - the vertices of a read OBJ model as glint's mesh wants
 * them: one per distinct face corner when the file gives every face its
 * normals, and otherwise with normals generated (crease_normals.h) and
 * corners of equal position, texture coordinates and normal joined. */
#ifndef GLINT_MODEL_OBJ_MESH_H
#define GLINT_MODEL_OBJ_MESH_H

#include <stddef.h>
#include "glint.h"
#include "model/obj_read.h"

/* A mesh's vertex arrays. */
typedef struct obj_vertices {
    float *positions;         /* 3 per vertex */
    float *normals;           /* 3 per vertex */
    float *uvs;               /* 2 per vertex, or NULL when no face has texture coordinates */
    size_t count;
} obj_vertices;

/* Builds the vertices of m into *out and turns m->triangles' corners into
 * their indices. The model's positions, uvs, normals and corners are freed
 * as soon as they are no longer needed, to keep the peak of memory low.
 * `file` names the model in messages. On failure *out still needs
 * obj_vertices_free. */
glint_status obj_mesh_vertices(obj_model *m, double crease_degrees, const char *file, obj_vertices *out,
                               glint_error *err);

/* Frees the arrays and empties *v. */
void obj_vertices_free(obj_vertices *v);

#endif
