/* mesh.c - copying and checking triangle meshes, and the surface at a hit. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "geometry/mesh.h"

#define MESH_MAX_COUNT (1 << 30)

/* Copies count items of size bytes, plus `extra` zeroed bytes, into
 * array_alloc's room (huge pages for a large model's arrays). */
static void *copy_array(const void *src, size_t count, size_t size, size_t extra)
{
    size_t bytes = count * size;
    unsigned char *p = array_alloc(bytes + extra, 1);
    if (p) {
        memcpy(p, src, bytes);
        memset(p + bytes, 0, extra);
    }
    return p;
}

glint_status mesh_init(mesh *m, const char *name, const glint_mesh_data *d, int material_count, glint_error *err)
{
    memset(m, 0, sizeof *m);
    if (!d->positions || !d->indices)
        return error_set(err, GLINT_ERR_INVALID, "mesh needs positions and indices");
    if (d->vertex_count < 1 || d->vertex_count > MESH_MAX_COUNT || d->triangle_count < 1 ||
        d->triangle_count > MESH_MAX_COUNT)
        return error_set(err, GLINT_ERR_INVALID, "mesh needs 1 to %d vertices and triangles, got %d and %d",
                         MESH_MAX_COUNT, d->vertex_count, d->triangle_count);
    if (!d->materials && (d->material < 0 || d->material >= material_count))
        return error_set(err, GLINT_ERR_INVALID, "material %d does not exist", d->material);
    size_t nv = (size_t)d->vertex_count, nt = (size_t)d->triangle_count;
    m->lo = v3(INFINITY, INFINITY, INFINITY);
    m->hi = v3(-INFINITY, -INFINITY, -INFINITY);
    for (size_t i = 0; i < nv; i++) {
        vec3 p = v3(d->positions[3 * i], d->positions[3 * i + 1], d->positions[3 * i + 2]);
        if (!v3_is_finite(p))
            return error_set(err, GLINT_ERR_INVALID, "mesh vertex %zu is not finite", i);
        m->lo = v3(fmin(m->lo.x, p.x), fmin(m->lo.y, p.y), fmin(m->lo.z, p.z));
        m->hi = v3(fmax(m->hi.x, p.x), fmax(m->hi.y, p.y), fmax(m->hi.z, p.z));
    }
    for (size_t i = 0; i < 3 * nt; i++)
        if (d->indices[i] >= (uint32_t)d->vertex_count)
            return error_set(err, GLINT_ERR_INVALID, "mesh triangle %zu uses vertex %u of %d", i / 3,
                             d->indices[i], d->vertex_count);
    for (size_t i = 0; d->materials && i < nt; i++)
        if (d->materials[i] < 0 || d->materials[i] >= material_count)
            return error_set(err, GLINT_ERR_INVALID, "mesh triangle %zu uses material %d, which does not exist", i,
                             d->materials[i]);
    for (size_t i = 0; d->normals && i < 3 * nv; i++)
        if (!isfinite(d->normals[i]))
            return error_set(err, GLINT_ERR_INVALID, "mesh normal %zu is not finite", i / 3);
    for (size_t i = 0; d->uvs && i < 2 * nv; i++)
        if (!isfinite(d->uvs[i]))
            return error_set(err, GLINT_ERR_INVALID, "mesh texture coordinate %zu is not finite", i / 2);
    /* Embree reads vertex buffers 16 bytes at a time: pad the last one. */
    m->positions = copy_array(d->positions, nv, 3 * sizeof(float), sizeof(float));
    m->indices = copy_array(d->indices, nt, 3 * sizeof(uint32_t), 0);
    m->normals = d->normals ? copy_array(d->normals, nv, 3 * sizeof(float), 0) : NULL;
    m->uvs = d->uvs ? copy_array(d->uvs, nv, 2 * sizeof(float), 0) : NULL;
    m->materials = d->materials ? copy_array(d->materials, nt, sizeof(int), 0) : NULL;
    m->name = name ? strdup(name) : NULL;
    m->material = d->material;
    m->vertex_count = d->vertex_count;
    m->triangle_count = d->triangle_count;
    if (!m->positions || !m->indices || (d->normals && !m->normals) || (d->uvs && !m->uvs) ||
        (d->materials && !m->materials) || (name && !m->name)) {
        mesh_release(m);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for a mesh of %d triangles", d->triangle_count);
    }
    return GLINT_OK;
}

void mesh_release(mesh *m)
{
    free(m->name);
    free(m->origin.file);
    free(m->positions);
    free(m->normals);
    free(m->uvs);
    free(m->indices);
    free(m->materials);
    if (m->solid)
        triangle_tree_free(&m->solid->tree);
    free(m->solid);
    memset(m, 0, sizeof *m);
}

int mesh_material(const mesh *m, const instance *inst, unsigned tri)
{
    if (inst->material >= 0)
        return inst->material;
    return m->materials ? m->materials[tri] : m->material;
}

static vec3 vertex3(const float *a, uint32_t i)
{
    return v3(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
}

void mesh_prefetch(const mesh *m, unsigned tri)
{
    const uint32_t *idx = m->indices + 3 * (size_t)tri;
    for (int k = 0; k < 3; k++) {
        __builtin_prefetch(m->positions + 3 * (size_t)idx[k]);
        if (m->normals)
            __builtin_prefetch(m->normals + 3 * (size_t)idx[k]);
    }
}

const instance *instance_moved(const instance *inst, double time, instance *out)
{
    *out = *inst;
    xf_between(inst->poses, inst->pose_count, time, &out->to_world, &out->to_object);
    out->has_transform = true;
    return out;
}

void mesh_surface(const mesh *m, const instance *inst, const ray *r, unsigned tri, double b1, double b2, double *t,
                  surface *out)
{
    const uint32_t *idx = m->indices + 3 * (size_t)tri;
    vec3 p0 = vertex3(m->positions, idx[0]), p1 = vertex3(m->positions, idx[1]), p2 = vertex3(m->positions, idx[2]);
    vec3 ng = v3_cross(v3_sub(p1, p0), v3_sub(p2, p0));
    /* Embree's t is single precision; redo it in double against the
     * triangle's plane so new rays can start close to the surface. A mesh
     * placed as it is (the usual case) needs no ray or normal mapped. */
    bool moved = inst->has_transform;
    ray o = moved ? (ray){xf_point(&inst->to_object, r->o), xf_vector(&inst->to_object, r->d)} : *r;
    double denom = v3_dot(ng, o.d);
    if (denom != 0) {
        double exact = v3_dot(ng, v3_sub(p0, o.o)) / denom;
        if (isfinite(exact) && fabs(exact - *t) <= 1e-3 * fabs(*t) + 1e-6)
            *t = exact;
    }
    out->p_obj = ray_at(&o, *t);
    out->p = ray_at(r, *t);
    out->part = 0;
    out->n = v3_normalize(moved ? xf_normal(&inst->to_object, ng) : ng);
    out->shading_n = out->n;
    double b0 = 1 - b1 - b2;
    if (m->normals) {
        vec3 ns = v3_add(v3_add(v3_scale(vertex3(m->normals, idx[0]), b0), v3_scale(vertex3(m->normals, idx[1]), b1)),
                         v3_scale(vertex3(m->normals, idx[2]), b2));
        if (moved)
            ns = xf_normal(&inst->to_object, ns);
        /* Vertex normals that cancel out leave the geometric normal. */
        double length = v3_length(ns);
        if (length > 0) {
            ns = v3_scale(ns, 1.0 / length);
            out->shading_n = v3_dot(ns, out->n) < 0 ? v3_neg(ns) : ns;
        }
    }
    out->u = out->v = 0;
    if (m->uvs) {
        const float *uv = m->uvs;
        out->u = b0 * uv[2 * idx[0]] + b1 * uv[2 * idx[1]] + b2 * uv[2 * idx[2]];
        out->v = b0 * uv[2 * idx[0] + 1] + b1 * uv[2 * idx[1] + 1] + b2 * uv[2 * idx[2] + 1];
    }
}

bool mesh_weights_at(const mesh *m, unsigned tri, vec3 p, double *b1, double *b2)
{
    const uint32_t *idx = m->indices + 3 * (size_t)tri;
    vec3 p0 = vertex3(m->positions, idx[0]);
    vec3 e1 = v3_sub(vertex3(m->positions, idx[1]), p0), e2 = v3_sub(vertex3(m->positions, idx[2]), p0);
    vec3 d = v3_sub(p, p0);
    /* The weights of p's projection: the 2x2 normal equations. */
    double a = v3_dot(e1, e1), b = v3_dot(e1, e2), c = v3_dot(e2, e2), det = a * c - b * b;
    if (!(det > 0))
        return false;
    double d1 = v3_dot(d, e1), d2 = v3_dot(d, e2);
    *b1 = (c * d1 - b * d2) / det;
    *b2 = (a * d2 - b * d1) / det;
    return true;
}

void mesh_uv_at(const mesh *m, unsigned tri, vec3 p, double *u, double *v)
{
    *u = *v = 0;
    double b1, b2;
    if (!m->uvs || !mesh_weights_at(m, tri, p, &b1, &b2))
        return;
    const uint32_t *idx = m->indices + 3 * (size_t)tri;
    double b0 = 1 - b1 - b2;
    const float *uv = m->uvs;
    *u = b0 * uv[2 * idx[0]] + b1 * uv[2 * idx[1]] + b2 * uv[2 * idx[2]];
    *v = b0 * uv[2 * idx[0] + 1] + b1 * uv[2 * idx[1] + 1] + b2 * uv[2 * idx[2] + 1];
}

__attribute__((noinline)) void mesh_surface_moved(const mesh *m, const instance *inst, double time, const ray *r,
                                                  unsigned tri, double b1, double b2, double *t, surface *out)
{
    instance moved;
    mesh_surface(m, instance_moved(inst, time, &moved), r, tri, b1, b2, t, out);
}
