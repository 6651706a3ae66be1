/* polygon_split.c - a polygon's points checked and split exactly into
 * triangles (ear clipping where it is concave). */
#include <math.h>
#include <stdlib.h>
#include "core/array.h"
#include "scene/polygon_split.h"

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

glint_status polygon_split(polygon_work *w, const vec3 *points, int count, float *positions, vec3 *normal,
                           uint32_t *triangles, glint_error *err)
{
    glint_status status = check_points(points, count, normal, err);
    if (status)
        return status;
    size_t n = (size_t)count;
    if (!array_reserve((void **)&w->corners, &w->corner_cap, n, sizeof *w->corners))
        return error_set(err, GLINT_ERR_NOMEM, "out of memory adding a polygon of %d points", count);
    for (size_t i = 0; i < n; i++) {
        positions[3 * i] = (float)points[i].x;
        positions[3 * i + 1] = (float)points[i].y;
        positions[3 * i + 2] = (float)points[i].z;
        w->corners[i] = (uint32_t)i;
    }
    if (!triangulate_polygon(&w->triangulate, positions, w->corners, n, triangles))
        return error_set(err, GLINT_ERR_NOMEM, "out of memory adding a polygon of %d points", count);
    return GLINT_OK;
}

void polygon_work_free(polygon_work *w)
{
    triangulate_free(&w->triangulate);
    free(w->corners);
    *w = (polygon_work){0};
}
