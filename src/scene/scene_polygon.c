/* scene_polygon.c - polygons of any number of points, convex or not: the
 * triangles that cover one exactly, as a mesh placed once, carrying a
 * polygon shape's (u, v). */
#include <math.h>
#include <stdlib.h>
#include "core/error.h"
#include "model/triangulate.h"
#include "scene/scene.h"

/* Checks the points: finite, no two in a row the same, not all in a line,
 * in one plane; fills *normal with the polygon's unit (Newell) normal. */
static glint_status check_points(const vec3 *p, int n, vec3 *normal, glint_error *err)
{
    vec3 sum = v3(0, 0, 0);
    double size = 0;
    for (int i = 0; i < n; i++) {
        vec3 a = p[i], b = p[(i + 1) % n];
        if (!isfinite(a.x) || !isfinite(a.y) || !isfinite(a.z))
            return error_set(err, GLINT_ERR_INVALID, "polygon point %d is not finite", i);
        if (a.x == b.x && a.y == b.y && a.z == b.z)
            return error_set(err, GLINT_ERR_INVALID, "polygon points %d and %d coincide", i, (i + 1) % n);
        sum = v3_add(sum, v3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)));
        size = fmax(size, v3_length(v3_sub(b, a)));
    }
    if (!(v3_length(sum) > 1e-9 * size * size))
        return error_set(err, GLINT_ERR_INVALID, "polygon points are collinear");
    *normal = v3_normalize(sum);
    for (int i = 1; i < n; i++)
        if (fabs(v3_dot(v3_sub(p[i], p[0]), *normal)) >= 1e-6 * size)
            return error_set(err, GLINT_ERR_INVALID, "polygon is not planar");
    return GLINT_OK;
}

/* The (u, v) of point q on the polygon, as a polygon shape gives them:
 * q = p0 + u e1 + v e2 in its plane, e1 and e2 the edges from point 0 to
 * point 1 and to the last point; where those are in line (a straight
 * corner), e2 is e1 turned a quarter about the normal. */
static void affine_uv(const vec3 *p, int n, vec3 normal, vec3 q, float *uv)
{
    vec3 e1 = v3_sub(p[1], p[0]), e2 = v3_sub(p[n - 1], p[0]), d = v3_sub(q, p[0]);
    double det = v3_dot(v3_cross(e1, e2), normal);
    if (fabs(det) <= 1e-12 * v3_length(e1) * v3_length(e2)) {
        e2 = v3_cross(normal, e1);
        det = v3_dot(v3_cross(e1, e2), normal);
    }
    uv[0] = (float)(v3_dot(v3_cross(d, e2), normal) / det);
    uv[1] = (float)(v3_dot(v3_cross(e1, d), normal) / det);
}

int glint_scene_add_polygon(glint_scene *scene, const glint_vec3 *points, int count, int mat,
                            const glint_transform *xf, glint_error *err)
{
    if (count < 3 || count > GLINT_MAX_POLYGON_POINTS) {
        error_set(err, GLINT_ERR_INVALID, "a polygon needs 3 to %d points, got %d", GLINT_MAX_POLYGON_POINTS, count);
        return -1;
    }
    vec3 normal = v3(0, 0, 0);
    if (check_points(points, count, &normal, err))
        return -1;
    size_t n = (size_t)count;
    float *positions = malloc(3 * n * sizeof *positions), *uvs = malloc(2 * n * sizeof *uvs);
    uint32_t *corners = malloc(n * sizeof *corners), *triangles = malloc(3 * (n - 2) * sizeof *triangles);
    triangulate_work work = {0};
    int placed = -1;
    bool room = positions && uvs && corners && triangles;
    for (size_t i = 0; room && i < n; i++) {
        positions[3 * i] = (float)points[i].x;
        positions[3 * i + 1] = (float)points[i].y;
        positions[3 * i + 2] = (float)points[i].z;
        affine_uv(points, count, normal, points[i], uvs + 2 * i);
        corners[i] = (uint32_t)i;
    }
    if (!room || !triangulate_polygon(&work, positions, corners, n, triangles)) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory adding a polygon of %d points", count);
    } else {
        glint_mesh_data d = {.positions = positions, .uvs = uvs, .vertex_count = count, .indices = triangles,
                             .triangle_count = count - 2, .material = mat};
        int made = glint_scene_add_mesh(scene, NULL, &d, err);
        if (made >= 0)
            placed = glint_scene_add_instance(scene, made, -1, xf, err);
    }
    triangulate_free(&work);
    free(positions);
    free(uvs);
    free(corners);
    free(triangles);
    return placed;
}
