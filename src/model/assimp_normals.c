/* assimp_normals.c - normals for the parts of an Assimp model that have
 * none, made as an OBJ's are: the merged mesh goes to obj_mesh.h as an OBJ
 * model whose every vertex is a face corner, and comes back joined. */
#include <stdlib.h>
#include "core/array.h"
#include "core/error.h"
#include "model/assimp_merge.h"
#include "model/obj_mesh.h"

glint_status assimp_make_normals(assimp_merged *mg, double crease, const char *file, glint_error *err)
{
    size_t nv = (size_t)mg->vertices, nt = (size_t)mg->triangles;
    obj_model m = {.corners = array_alloc(nv, sizeof(obj_corner))};
    if (!m.corners)
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    for (size_t i = 0; i < nv; i++) {
        bool normalled = mg->normals && !mg->unnormalled[i];
        m.corners[i] = (obj_corner){(int32_t)i, mg->uvs ? (int32_t)i : -1, normalled ? (int32_t)i : -1};
        m.generate |= !normalled;
    }
    /* The arrays move into the model, which frees each once it is used. */
    m.corner_count = m.corner_cap = nv;
    m.positions = mg->positions;
    m.position_count = m.position_cap = nv;
    m.normals = mg->normals;
    m.normal_count = m.normal_cap = mg->normals ? nv : 0;
    m.uvs = mg->uvs;
    m.uv_count = m.uv_cap = mg->uvs ? nv : 0;
    m.textured = mg->uvs != NULL;
    m.triangles = mg->indices;
    m.triangle_count = m.triangle_cap = nt;
    mg->positions = mg->normals = mg->uvs = NULL;
    mg->indices = NULL;
    free(mg->unnormalled);
    mg->unnormalled = NULL;
    obj_vertices v;
    glint_status s = obj_mesh_vertices(&m, crease, file, &v, err);
    mg->indices = m.triangles;
    m.triangles = NULL;
    obj_model_free(&m);
    if (s) {
        obj_vertices_free(&v);
        return s;
    }
    mg->positions = v.positions;
    mg->normals = v.normals;
    mg->uvs = v.uvs;
    mg->vertices = (long long)v.count;
    return GLINT_OK;
}
