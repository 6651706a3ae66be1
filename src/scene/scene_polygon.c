/* scene_polygon.c - polygons of any number of points, convex or not: the
 * triangles that cover one exactly, as a mesh placed once, carrying a
 * polygon shape's (u, v). */
#include <math.h>
#include <stdlib.h>
#include "core/error.h"
#include "scene/polygon_split.h"
#include "scene/scene.h"

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
    size_t n = (size_t)count;
    float *positions = malloc(3 * n * sizeof *positions), *uvs = malloc(2 * n * sizeof *uvs);
    uint32_t *triangles = malloc(3 * (n - 2) * sizeof *triangles);
    polygon_work work = {0};
    int placed = -1;
    if (!positions || !uvs || !triangles) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory adding a polygon of %d points", count);
    } else if (polygon_split(&work, points, count, positions, &normal, triangles, err) == GLINT_OK) {
        for (int i = 0; i < count; i++)
            affine_uv(points, count, normal, points[i], uvs + 2 * i);
        glint_mesh_data d = {.positions = positions, .uvs = uvs, .vertex_count = count, .indices = triangles,
                             .triangle_count = count - 2, .material = mat};
        int made = glint_scene_add_mesh(scene, NULL, &d, err);
        if (made >= 0)
            placed = glint_scene_add_instance(scene, made, -1, xf, err);
    }
    polygon_work_free(&work);
    free(positions);
    free(uvs);
    free(triangles);
    return placed;
}
