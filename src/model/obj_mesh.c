/* obj_mesh.c - from OBJ face corners to vertex arrays. */
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "model/crease_normals.h"
#include "core/id_table.h"
#include "model/model_build.h"
#include "model/obj_mesh.h"

/* A vertex joined by value: its welded position, texture coordinates and
 * normal. 24 bytes without padding, so compared as bytes. */
typedef struct vertex_key {
    uint32_t position;
    float uv[2];
    float normal[3];
} vertex_key;

/* Joining vertices while normals are generated. */
typedef struct joiner {
    obj_model *m;
    const uint32_t *weld;     /* each position's first equal one */
    const uint32_t *smooth;   /* the triangles without normals of their own, in order */
    vertex_key *keys;
    size_t count, cap;
    uint32_t *last;           /* per welded position: the vertex last joined there, UINT32_MAX for none */
    id_table index;
    const char *file;
    glint_error *err;
} joiner;

static glint_status out_of_memory(const char *file, glint_error *err)
{
    return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
}

/* The hash of a key: its words folded by multiplying, then mixed once,
 * in a third of id_hash_words' instructions. */
static uint32_t vertex_hash(const vertex_key *key)
{
    uint32_t w[6];
    memcpy(w, key, sizeof w);
    uint64_t h = w[0];
    for (int i = 1; i < 6; i++)
        h = h * 0x9e3779b97f4a7c15u + w[i];
    return hash_u32((uint32_t)(h >> 32) ^ (uint32_t)h);
}

static bool key_equal(const void *keys, uint32_t id, const void *key)
{
    return memcmp((const vertex_key *)keys + id, key, sizeof(vertex_key)) == 0;
}

/* Sets *slot to the vertex of `key`, entering it when it is new. Out of
 * line, so that join's quick path saves no registers for it. */
static __attribute__((noinline)) glint_status join_key(joiner *j, const vertex_key *key, uint32_t *slot)
{
    if (!array_reserve((void **)&j->keys, &j->cap, j->count + 1, sizeof *j->keys))
        return out_of_memory(j->file, j->err);
    if (!id_table_intern(&j->index, vertex_hash(key), key, (uint32_t)j->count, key_equal, j->keys, slot))
        return out_of_memory(j->file, j->err);
    if (*slot == j->count) {
        if (j->count >= MODEL_MAX_COUNT)
            return error_set(j->err, GLINT_ERR_INVALID, "%s: too many vertices (more than %lld)", j->file,
                             MODEL_MAX_COUNT);
        j->keys[j->count++] = *key;
    }
    j->last[key->position] = *slot;
    return GLINT_OK;
}

/* Replaces corner k of triangle t by the vertex of that corner with
 * `normal`, entering the vertex when it is new. On a smooth surface the
 * corners at a point are mostly one vertex: the one last joined there is
 * tried before the hash table (join_key), which then sees little more than
 * the new vertices. */
static inline glint_status join(joiner *j, size_t t, int k, const float *normal)
{
    obj_model *m = j->m;
    uint32_t *slot = m->triangles + 3 * t + k;
    const obj_corner *c = &m->corners[*slot];
    vertex_key key = {.position = j->weld[c->v]};
    if (c->vt >= 0)
        memcpy(key.uv, m->uvs + 2 * (size_t)c->vt, sizeof key.uv);
    memcpy(key.normal, normal, sizeof key.normal);
    uint32_t last = j->last[key.position];
    if (last != UINT32_MAX && key_equal(j->keys, last, &key)) {
        *slot = last;
        return GLINT_OK;
    }
    return join_key(j, &key, slot);
}

/* crease_emit_fn: the n-th triangle without normals. */
static glint_status join_generated(void *ctx, size_t n, int k, const float normal[3])
{
    joiner *j = ctx;
    return join(j, j->smooth[n], k, normal);
}

/* Copies the joined vertices' values into out. */
static glint_status fill_joined(const joiner *j, obj_vertices *out)
{
    const obj_model *m = j->m;
    out->count = j->count;
    out->positions = array_alloc(j->count, 3 * sizeof(float));
    out->normals = array_alloc(j->count, 3 * sizeof(float));
    out->uvs = m->textured ? array_alloc(j->count, 2 * sizeof(float)) : NULL;
    if (!out->positions || !out->normals || (m->textured && !out->uvs))
        return out_of_memory(j->file, j->err);
    for (size_t i = 0; i < j->count; i++) {
        const vertex_key *key = &j->keys[i];
        memcpy(out->positions + 3 * i, m->positions + 3 * (size_t)key->position, 3 * sizeof(float));
        memcpy(out->normals + 3 * i, key->normal, sizeof key->normal);
        if (out->uvs)
            memcpy(out->uvs + 2 * i, key->uv, sizeof key->uv);
    }
    return GLINT_OK;
}

/* Some faces have no normals: generate theirs, then join every corner by
 * value. */
static glint_status generate(obj_model *m, double crease, const char *file, obj_vertices *out, glint_error *err)
{
    size_t nt = m->triangle_count, smooth_count = 0;
    joiner j = {.m = m, .file = file, .err = err};
    uint32_t *weld = array_alloc(m->position_count, sizeof *weld), *at = NULL;
    uint32_t *smooth = array_alloc(nt, sizeof *smooth);
    j.last = array_alloc(m->position_count, sizeof *j.last);
    glint_status s = weld && smooth && j.last && crease_weld(m->positions, m->position_count, weld)
                         ? GLINT_OK
                         : out_of_memory(file, err);
    j.weld = weld;
    j.smooth = smooth;
    for (size_t i = 0; !s && i < m->position_count; i++)
        j.last[i] = UINT32_MAX;
    for (size_t t = 0; !s && t < nt; t++)
        if (m->corners[m->triangles[3 * t]].vn < 0)
            smooth[smooth_count++] = (uint32_t)t;
    if (!s && !(at = array_alloc(smooth_count, 3 * sizeof *at)))
        s = out_of_memory(file, err);
    for (size_t n = 0; !s && n < smooth_count; n++)
        for (int k = 0; k < 3; k++)
            at[3 * n + k] = weld[m->corners[m->triangles[3 * (size_t)smooth[n] + k]].v];
    /* Sized for about one vertex a position, as on a smooth surface. */
    if (!s && !id_table_reserve(&j.index, m->position_count))
        s = out_of_memory(file, err);
    /* The faces with normals, those between the ones listed as smooth. */
    for (size_t t = 0, n = 0; !s && t < nt; t++) {
        if (n < smooth_count && smooth[n] == t) {
            n++;
            continue;
        }
        for (int k = 0; !s && k < 3; k++)
            s = join(&j, t, k, m->normals + 3 * (size_t)m->corners[m->triangles[3 * t + k]].vn);
    }
    if (!s)
        s = crease_normals(m->positions, m->position_count, at, smooth_count, crease, join_generated, &j, file, err);
    free(at);
    free(weld);
    free(smooth);
    free(j.last);
    id_table_free(&j.index);
    if (!s)
        s = fill_joined(&j, out);
    free(j.keys);
    return s;
}

/* Every face has normals: each distinct corner is a vertex. */
static glint_status corners_as_vertices(obj_model *m, const char *file, obj_vertices *out, glint_error *err)
{
    size_t n = m->corner_count;
    out->count = n;
    /* One array at a time, each source freed once copied. */
    if (!(out->positions = array_alloc(n, 3 * sizeof(float))))
        return out_of_memory(file, err);
    for (size_t i = 0; i < n; i++)
        memcpy(out->positions + 3 * i, m->positions + 3 * (size_t)m->corners[i].v, 3 * sizeof(float));
    obj_model_drop((void **)&m->positions, &m->position_count, &m->position_cap);
    if (!(out->normals = array_alloc(n, 3 * sizeof(float))))
        return out_of_memory(file, err);
    for (size_t i = 0; i < n; i++)
        memcpy(out->normals + 3 * i, m->normals + 3 * (size_t)m->corners[i].vn, 3 * sizeof(float));
    obj_model_drop((void **)&m->normals, &m->normal_count, &m->normal_cap);
    if (m->textured && !(out->uvs = array_alloc(n, 2 * sizeof(float))))
        return out_of_memory(file, err);
    for (size_t i = 0; out->uvs && i < n; i++) {
        float *uv = out->uvs + 2 * i;
        if (m->corners[i].vt >= 0)
            memcpy(uv, m->uvs + 2 * (size_t)m->corners[i].vt, 2 * sizeof(float));
        else
            uv[0] = uv[1] = 0;
    }
    return GLINT_OK;
}

glint_status obj_mesh_vertices(obj_model *m, double crease_degrees, const char *file, obj_vertices *out,
                               glint_error *err)
{
    *out = (obj_vertices){0};
    glint_status s = m->generate ? generate(m, crease_degrees, file, out, err)
                                 : corners_as_vertices(m, file, out, err);
    obj_model_drop((void **)&m->positions, &m->position_count, &m->position_cap);
    obj_model_drop((void **)&m->normals, &m->normal_count, &m->normal_cap);
    obj_model_drop((void **)&m->uvs, &m->uv_count, &m->uv_cap);
    obj_model_drop((void **)&m->corners, &m->corner_count, &m->corner_cap);
    return s;
}

void obj_vertices_free(obj_vertices *v)
{
    free(v->positions);
    free(v->normals);
    free(v->uvs);
    *v = (obj_vertices){0};
}
