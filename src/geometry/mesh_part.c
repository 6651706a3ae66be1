/* mesh_part.c - a closed mesh as a part of a union, intersection or
 * difference: a shape kind whose surface is the mesh's triangles, found
 * through the mesh's own hierarchy (triangle_tree.h), so that the walk of
 * csg.c can ask it for one crossing after another. A hit's part is the
 * triangle's index; its normal points out of the solid whichever way the
 * mesh winds, and it shades with the mesh's vertex normals and uv. Only
 * glint_scene_add_mesh_part makes one (mesh_make_solid first checks the
 * mesh is closed). */
#include <limits.h>
#include "geometry/mesh.h"
#include "geometry/shape_kind.h"

static const mesh *mesh_of(const shape *s)
{
    return &s->solid->view;
}

static vec3 corner(const mesh *m, int triangle, int k)
{
    const float *p = m->positions + 3 * (size_t)m->indices[3 * (size_t)triangle + (size_t)k];
    return v3(p[0], p[1], p[2]);
}

static bool mesh_part_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    uint32_t triangle;
    double t;
    if (!triangle_tree_hit(&s->solid->tree, r, tmin, tmax, &t, &triangle))
        return false;
    *hit = (shape_hit){t, (int)triangle, 0};
    return true;
}

static void mesh_part_surface(const shape *s, int part, surface *out)
{
    const mesh *m = mesh_of(s);
    vec3 p0 = corner(m, part, 0);
    vec3 n = v3_cross(v3_sub(corner(m, part, 1), p0), v3_sub(corner(m, part, 2), p0));
    out->n = s->solid->inward ? v3_neg(n) : n;
}

static bool mesh_part_shading(const shape *s, int part, const surface *at, vec3 *n)
{
    const mesh *m = mesh_of(s);
    double b1, b2;
    if (!m->normals || !mesh_weights_at(m, (unsigned)part, at->p_obj, &b1, &b2))
        return false;
    const uint32_t *idx = m->indices + 3 * (size_t)part;
    vec3 sum = v3(0, 0, 0);
    double weight[3] = {1 - b1 - b2, b1, b2};
    for (int k = 0; k < 3; k++) {
        const float *v = m->normals + 3 * (size_t)idx[k];
        sum = v3_madd(sum, v3(v[0], v[1], v[2]), weight[k]);
    }
    *n = sum;
    return true;
}

static void mesh_part_uv(const shape *s, int part, surface *out)
{
    mesh_uv_at(mesh_of(s), (unsigned)part, out->p_obj, &out->u, &out->v);
}

static void mesh_part_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    *lo = mesh_of(s)->lo;
    *hi = mesh_of(s)->hi;
}

static vec3 mesh_part_center(const shape *s)
{
    return mesh_center(mesh_of(s));
}

const shape_kind mesh_part_kind = {
    .name = "mesh",
    .id = GLINT_SHAPE_MESH,
    /* As many as it has triangles (shape_max_crossings). */
    .max_crossings = INT_MAX,
    .closed = shape_always_closed,
    .intersect = mesh_part_intersect,
    .surface = mesh_part_surface,
    .shading = mesh_part_shading,
    .uv = mesh_part_uv,
    .bounds = mesh_part_bounds,
    .center = mesh_part_center,
};
