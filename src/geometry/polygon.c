/* polygon.c - convex planar triangles and quads in object space, their
 * points anticlockwise when seen from the side the normal points to. */
#include <stddef.h>
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

static vec3 corner(const glint_shape *d, int i)
{
    int n = d->point_count;
    vec3 a = d->points[i], b = d->points[(i + 1) % n], c = d->points[(i + 2) % n];
    return v3_cross(v3_sub(b, a), v3_sub(c, b));
}

/* The longest edge of d, 0 when two points in a row coincide (*at: the
 * first of them). */
static double longest_edge(const glint_shape *d, int *at)
{
    int n = d->point_count;
    double size = 0;
    for (int i = 0; i < n; i++) {
        double edge = v3_length(v3_sub(d->points[(i + 1) % n], d->points[i]));
        if (edge == 0) {
            *at = i;
            return 0;
        }
        size = fmax(size, edge);
    }
    return size;
}

/* Why the points of d are not a convex polygon's (the problem's message),
 * or NULL when they are; *normal is then its unit normal. */
static const char *convex_problem(const glint_shape *d, vec3 *normal)
{
    const vec3 *p = d->points;
    int n = d->point_count, at = 0;
    double size = longest_edge(d, &at);
    /* Areas below this, relative to the longest edge, count as zero. */
    double tiny = 1e-9 * size * size;
    double largest = 0;
    for (int i = 0; i < n; i++)
        largest = fmax(largest, v3_length(corner(d, i)));
    if (largest <= tiny)
        return "polygon points are collinear";
    /* A quad's diagonals give its normal even when three of its points are
     * nearly in line; parallel diagonals mean the quad crosses itself. */
    *normal = n == 3 ? corner(d, 0) : v3_cross(v3_sub(p[2], p[0]), v3_sub(p[3], p[1]));
    if (v3_length(*normal) <= tiny)
        return "polygon is not convex";
    *normal = v3_normalize(*normal);
    if (n == 4 && fabs(v3_dot(v3_sub(p[3], p[0]), *normal)) >= 1e-6 * size)
        return "polygon is not planar";
    /* A straight corner is refused too: it would leave the uv axes (the
     * edges at point 0) parallel, and such a quad is a triangle anyway. */
    for (int i = 0; i < n; i++)
        if (v3_dot(corner(d, i), *normal) <= tiny)
            return "polygon is not convex";
    return NULL;
}

bool polygon_is_convex(const glint_vec3 *points, int count)
{
    glint_shape d = {.kind = GLINT_SHAPE_POLYGON, .point_count = count};
    for (int i = 0; i < count && i < 4; i++)
        d.points[i] = points[i];
    int at = 0;
    vec3 normal;
    return count >= 3 && count <= 4 && longest_edge(&d, &at) > 0 && !convex_problem(&d, &normal);
}

/* The table has checked the count and that every point is finite. */
static glint_status polygon_init(shape *s, glint_error *err)
{
    const glint_shape *d = &s->desc;
    const vec3 *p = d->points;
    int n = d->point_count, at = 0;
    if (longest_edge(d, &at) == 0)
        return error_set(err, GLINT_ERR_INVALID, "polygon points %d and %d coincide", at, (at + 1) % n);
    vec3 normal;
    const char *problem = convex_problem(d, &normal);
    if (problem)
        return error_set(err, GLINT_ERR_INVALID, "%s", problem);
    s->poly_normal = normal;
    for (int i = 0; i < n; i++)
        s->edge_in[i] = v3_cross(normal, v3_sub(p[(i + 1) % n], p[i]));
    s->plane_u = v3_normalize(v3_sub(p[1], p[0]));
    s->plane_v = v3_normalize(v3_sub(p[n - 1], p[0]));
    return GLINT_OK;
}

static bool polygon_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    const glint_shape *d = &s->desc;
    int n = d->point_count;
    double t;
    if (!plane_hit(d->points[0], s->poly_normal, r, tmin, tmax, &t))
        return false;
    vec3 p = ray_at(r, t);
    /* Inside a convex polygon is to the left of every edge, on the side
     * its inward normal points to; on an edge counts. */
    for (int i = 0; i < n; i++) {
        if (v3_dot(v3_sub(p, d->points[i]), s->edge_in[i]) < 0)
            return false;
    }
    hit->t = t;
    hit->part = 0;
    return true;
}

static quad_mask polygon_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit)
{
    quad_f64 *t = &hit->t;
    const glint_shape *d = &s->desc;
    quad_mask inside = plane_hit4(d->points[0], s->poly_normal, r, first, 0, tmax, t);
    /* p = ray_at(r, t), then polygon_intersect's edge tests: a lane is out
     * where a dot product is below 0 (not where it is NaN). */
    quad_f64 px = quad_load(r->ox + first) + quad_load(r->dx + first) * *t;
    quad_f64 py = quad_load(r->oy + first) + quad_load(r->dy + first) * *t;
    quad_f64 pz = quad_load(r->oz + first) + quad_load(r->dz + first) * *t;
    for (int i = 0; i < d->point_count; i++) {
        vec3 a = d->points[i], e = s->edge_in[i];
        quad_f64 side = quad_dot(px - quad_splat(a.x), py - quad_splat(a.y), pz - quad_splat(a.z), quad_splat(e.x),
                                 quad_splat(e.y), quad_splat(e.z));
        inside &= ~(side < quad_splat(0));
    }
    return inside;
}

/* (u, v) are the affine coordinates of the point along the edges from point
 * 0 to point 1 and from point 0 to the last point, so a parallelogram spans
 * [0, 1]^2 and a triangle's (u, v) are the barycentric weights of its
 * points 1 and 2. */
static void polygon_surface(const shape *s, int part, surface *out)
{
    out->n = s->poly_normal;
}

static void polygon_uv(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 n = s->poly_normal, p0 = d->points[0];
    vec3 e1 = v3_sub(d->points[1], p0), e2 = v3_sub(d->points[d->point_count - 1], p0);
    vec3 q = v3_sub(out->p_obj, p0);
    /* Cramer's rule for q = u e1 + v e2 within the plane. */
    double det = v3_dot(v3_cross(e1, e2), n);
    out->u = v3_dot(v3_cross(q, e2), n) / det;
    out->v = v3_dot(v3_cross(e1, q), n) / det;
}

static void polygon_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    const glint_shape *d = &s->desc;
    *lo = *hi = d->points[0];
    for (int i = 1; i < d->point_count; i++) {
        *lo = min3(*lo, d->points[i]);
        *hi = max3(*hi, d->points[i]);
    }
}

static const param POLYGON_PARAMS[] = {
    {.key = "points", .type = PARAM_POINTS, .offset = offsetof(glint_shape, points), .required = true,
     .min_count = 3, .max_count = 4, .count_offset = offsetof(glint_shape, point_count),
     .meaning = "corners, anticlockwise seen from its front: 3, or 4 of a convex quad, make a shape; more, or a "
                "concave quad, triangles (below)"},
};

static double polygon_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    const vec3 *q = s->desc.points;
    double area[2] = {v3_length(v3_cross(v3_sub(q[1], q[0]), v3_sub(q[2], q[0]))) / 2, 0}, total;
    if (s->desc.point_count == 4)
        area[1] = v3_length(v3_cross(v3_sub(q[2], q[0]), v3_sub(q[3], q[0]))) / 2;
    int half = pick_by_area(area, 2, &u1, &total);
    *p = triangle_point(q[0], q[1 + half], q[2 + half], u1, u2);
    *n = s->poly_normal;
    return total;
}

const shape_kind polygon_kind = {
    .name = "polygon", .id = GLINT_SHAPE_POLYGON, .params = PARAM_TABLE(POLYGON_PARAMS), .max_crossings = 1,
    .flat = true, .init = polygon_init, .intersect = polygon_intersect, .intersect4 = polygon_intersect4,
    .surface = polygon_surface, .uv = polygon_uv, .bounds = polygon_bounds, .center = shape_bounds_middle,
    .sample = polygon_sample,
};
