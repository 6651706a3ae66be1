/* assimp_merge.c - the meshes of a model Assimp read merged into one:
 * its triangles (points and lines are dropped), with every index and
 * position checked again, so that a malformed file is an error naming it,
 * never a crash. */
#include <math.h>
#include <stdlib.h>
#include "core/error.h"
#include "model/assimp_merge.h"
#include "model/model_build.h"

void assimp_merged_free(assimp_merged *m)
{
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->unnormalled);
    free(m->indices);
    free(m->materials);
}

/* How many faces of m are triangles with their indices; none when m has
 * no vertices. */
static long long triangle_faces(const struct aiMesh *m)
{
    long long n = 0;
    for (unsigned f = 0; m->mFaces && f < m->mNumFaces; f++)
        n += m->mFaces[f].mNumIndices == 3 && m->mFaces[f].mIndices;
    return m->mVertices ? n : 0;
}

/* Counts what the merged mesh will hold and allocates it. */
static glint_status merge_alloc(const struct aiScene *ai, const char *file, assimp_merged *out, glint_error *err)
{
    bool normals = false, all_normals = true, uvs = false;
    for (unsigned i = 0; i < ai->mNumMeshes; i++) {
        const struct aiMesh *m = ai->mMeshes[i];
        long long tris = m ? triangle_faces(m) : 0;
        if (!tris)
            continue;
        if (m->mMaterialIndex >= ai->mNumMaterials)
            return error_set(err, GLINT_ERR_INVALID, "%s: a part uses material %u of %u", file, m->mMaterialIndex,
                             ai->mNumMaterials);
        out->vertices += m->mNumVertices;
        out->triangles += tris;
        normals |= m->mNormals != NULL;
        all_normals &= m->mNormals != NULL;
        uvs |= m->mTextureCoords[0] != NULL;
        if (out->vertices > MODEL_MAX_COUNT || out->triangles > MODEL_MAX_COUNT)
            return error_set(err, GLINT_ERR_INVALID, "%s: too many %s (more than %lld)", file,
                             out->vertices > MODEL_MAX_COUNT ? "vertices" : "triangles", MODEL_MAX_COUNT);
    }
    if (out->triangles == 0)
        return error_set(err, GLINT_ERR_INVALID, "%s: no triangles", file);
    size_t nv = (size_t)out->vertices, nt = (size_t)out->triangles;
    out->positions = malloc(nv * 3 * sizeof(float));
    out->normals = normals ? calloc(nv * 3, sizeof(float)) : NULL;
    out->uvs = uvs ? calloc(nv * 2, sizeof(float)) : NULL;
    out->unnormalled = all_normals ? NULL : malloc(nv * sizeof(bool));
    out->indices = malloc(nt * 3 * sizeof(uint32_t));
    out->materials = malloc(nt * sizeof(int));
    if (!out->positions || (normals && !out->normals) || (uvs && !out->uvs) || !out->indices || !out->materials ||
        (!all_normals && !out->unnormalled))
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory for %lld vertices and %lld triangles", file,
                         out->vertices, out->triangles);
    return GLINT_OK;
}

static float finite_or_zero(float x)
{
    return isfinite(x) ? x : 0.0f;
}

/* Copies mesh m's vertices to index v0 on. Normals and texture coordinates
 * that are not finite become zero (a zero normal falls back to the
 * triangle's own); v is flipped, as Assimp's v = 0 is the image's bottom
 * row and glint's its top. */
static glint_status copy_vertices(const struct aiMesh *m, long long v0, const char *file, assimp_merged *out,
                                  glint_error *err)
{
    for (unsigned v = 0; v < m->mNumVertices; v++) {
        size_t o = (size_t)(v0 + v);
        struct aiVector3D p = m->mVertices[v];
        if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z))
            return error_set(err, GLINT_ERR_INVALID, "%s: vertex %lld is not finite", file, v0 + v);
        out->positions[3 * o] = p.x;
        out->positions[3 * o + 1] = p.y;
        out->positions[3 * o + 2] = p.z;
        if (out->normals && m->mNormals) {
            out->normals[3 * o] = finite_or_zero(m->mNormals[v].x);
            out->normals[3 * o + 1] = finite_or_zero(m->mNormals[v].y);
            out->normals[3 * o + 2] = finite_or_zero(m->mNormals[v].z);
        }
        if (out->unnormalled)
            out->unnormalled[o] = !m->mNormals;
        if (out->uvs && m->mTextureCoords[0]) {
            out->uvs[2 * o] = finite_or_zero(m->mTextureCoords[0][v].x);
            out->uvs[2 * o + 1] = finite_or_zero(1.0f - m->mTextureCoords[0][v].y);
        }
    }
    return GLINT_OK;
}

glint_status assimp_merge(const struct aiScene *ai, const char *file, assimp_merged *out, bool *used,
                          glint_error *err)
{
    glint_status s = merge_alloc(ai, file, out, err);
    long long v0 = 0, t = 0;
    for (unsigned i = 0; !s && i < ai->mNumMeshes; i++) {
        const struct aiMesh *m = ai->mMeshes[i];
        if (!m || !triangle_faces(m))
            continue;
        if ((s = copy_vertices(m, v0, file, out, err)))
            break;
        for (unsigned f = 0; !s && f < m->mNumFaces; f++) {
            const struct aiFace *face = &m->mFaces[f];
            if (face->mNumIndices != 3 || !face->mIndices)
                continue;
            for (int k = 0; k < 3 && !s; k++) {
                if (face->mIndices[k] >= m->mNumVertices)
                    s = error_set(err, GLINT_ERR_INVALID, "%s: a triangle uses vertex %u of a part with %u", file,
                                  face->mIndices[k], m->mNumVertices);
                else
                    out->indices[3 * t + k] = (uint32_t)(v0 + face->mIndices[k]);
            }
            out->materials[t++] = (int)m->mMaterialIndex;
        }
        used[m->mMaterialIndex] = true;
        v0 += m->mNumVertices;
    }
    return s;
}

