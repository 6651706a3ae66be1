/* mesh_solid.c - whether a mesh is the closed surface of a solid, so that
 * it can be a part of a union, intersection or difference, and the solid
 * it then makes (mesh.h's mesh_solid): its hierarchy, and which way its
 * triangles face. */
#include <stdlib.h>
#include <string.h>
#include "geometry/mesh.h"

static vec3 position(const mesh *m, uint32_t vertex)
{
    const float *p = m->positions + 3 * (size_t)vertex;
    return v3(p[0], p[1], p[2]);
}

/* A vertex's position, with the vertex, for sorting. */
typedef struct spot {
    float p[3];
    uint32_t vertex;
} spot;

static int by_position(const void *a, const void *b)
{
    const float *p = ((const spot *)a)->p, *q = ((const spot *)b)->p;
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k])
            return p[k] < q[k] ? -1 : 1;
    return 0;
}

static int by_key(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* A number for each vertex, the same for vertices at the same position
 * (a model's seams split vertices by normal or uv), and for each number
 * a vertex that has it. */
static void weld(const mesh *m, spot *order, uint32_t *id, uint32_t *holder)
{
    for (int i = 0; i < m->vertex_count; i++) {
        memcpy(order[i].p, m->positions + 3 * (size_t)i, sizeof order[i].p);
        order[i].vertex = (uint32_t)i;
    }
    qsort(order, (size_t)m->vertex_count, sizeof *order, by_position);
    uint32_t next = 0;
    for (int i = 0; i < m->vertex_count; i++) {
        if (i > 0 && by_position(&order[i - 1], &order[i]) != 0)
            next++;
        id[order[i].vertex] = next;
        holder[next] = order[i].vertex;
    }
}

static uint64_t edge_key(uint32_t from, uint32_t to)
{
    return (uint64_t)from << 32 | to;
}

/* Checks the edges of m, its corners welded by id: each runs one way in
 * exactly one triangle and the other way in exactly one other. */
static glint_status check_edges(const mesh *m, const uint32_t *id, const uint32_t *holder, const char *name,
                                glint_error *err)
{
    uint64_t *keys = malloc(3 * (size_t)m->triangle_count * sizeof *keys);
    if (!keys)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory checking %s", name);
    size_t count = 0;
    for (int t = 0; t < m->triangle_count; t++) {
        const uint32_t *v = m->indices + 3 * (size_t)t;
        uint32_t a = id[v[0]], b = id[v[1]], c = id[v[2]];
        /* A triangle with two corners at one place covers nothing. */
        if (a == b || b == c || c == a)
            continue;
        keys[count++] = edge_key(a, b);
        keys[count++] = edge_key(b, c);
        keys[count++] = edge_key(c, a);
    }
    qsort(keys, count, sizeof *keys, by_key);
    glint_status st = GLINT_OK;
    for (size_t i = 0; i < count && !st; i++) {
        uint32_t from = (uint32_t)(keys[i] >> 32), to = (uint32_t)keys[i];
        uint64_t back = edge_key(to, from);
        bool twice = i + 1 < count && keys[i + 1] == keys[i];
        if (!twice && bsearch(&back, keys, count, sizeof *keys, by_key))
            continue;
        vec3 p = position(m, holder[from]), q = position(m, holder[to]);
        st = error_set(err, GLINT_ERR_INVALID,
                       twice ? "%s cannot be a part of a combination: two of its triangles run the same way "
                               "along its edge from (%g, %g, %g) to (%g, %g, %g), so they face opposite ways or more "
                               "than two meet there"
                             : "%s is not closed, so it cannot be a part of a combination: its edge from "
                               "(%g, %g, %g) to (%g, %g, %g) has a triangle on one side only",
                       name, p.x, p.y, p.z, q.x, q.y, q.z);
    }
    free(keys);
    return st;
}

/* Six times the volume m encloses, positive when its triangles run
 * anticlockwise seen from outside. */
static double signed_volume(const mesh *m)
{
    double sum = 0;
    for (int t = 0; t < m->triangle_count; t++) {
        const uint32_t *v = m->indices + 3 * (size_t)t;
        sum += v3_dot(position(m, v[0]), v3_cross(position(m, v[1]), position(m, v[2])));
    }
    return sum;
}

glint_status mesh_make_solid(mesh *m, const char *name, glint_error *err)
{
    if (m->solid)
        return GLINT_OK;
    size_t n = (size_t)m->vertex_count;
    spot *order = malloc(n * sizeof *order);
    uint32_t *id = malloc(n * sizeof *id), *holder = malloc(n * sizeof *holder);
    glint_status st = order && id && holder ? GLINT_OK
                                            : error_set(err, GLINT_ERR_NOMEM, "out of memory checking %s", name);
    if (!st) {
        weld(m, order, id, holder);
        st = check_edges(m, id, holder, name, err);
    }
    free(order);
    free(id);
    free(holder);
    if (st)
        return st;
    double volume = signed_volume(m);
    if (volume == 0)
        return error_set(err, GLINT_ERR_INVALID, "%s encloses no volume, so it cannot be a part of a combination",
                         name);
    mesh_solid *solid = calloc(1, sizeof *solid);
    if (!solid)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for %s", name);
    st = triangle_tree_build(&solid->tree, m->positions, m->indices, m->triangle_count, err);
    if (st) {
        free(solid);
        return st;
    }
    solid->view = *m;
    solid->inward = volume < 0;
    m->solid = solid;
    return GLINT_OK;
}
