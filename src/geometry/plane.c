/* plane.c - infinite planes in object space: a point and a normal. */
#include <stddef.h>
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

static glint_status plane_init(shape *s, glint_error *err)
{
    glint_shape *d = &s->desc;
    vec3 n = d->normal;
    /* Dividing by the largest component first keeps tiny and huge normals
     * from underflowing or overflowing when squared. The table has refused
     * a zero normal. */
    double m = fmax(fabs(n.x), fmax(fabs(n.y), fabs(n.z)));
    /* Kept in desc so every later use sees a unit normal. */
    d->normal = v3_normalize(v3(n.x / m, n.y / m, n.z / m));
    plane_basis(d->normal, &s->plane_u, &s->plane_v);
    return GLINT_OK;
}

static bool plane_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    double t;
    if (!plane_hit(s->desc.center, s->desc.normal, r, tmin, tmax, &t))
        return false;
    hit->t = t;
    hit->part = 0;
    return true;
}

static quad_mask plane_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit)
{
    return plane_hit4(s->desc.center, s->desc.normal, r, first, 0, tmax, &hit->t);
}

/* u and v are distances from the plane's point along plane_u and plane_v. */
static void plane_surface(const shape *s, int part, surface *out)
{
    out->n = s->desc.normal;
}

static void plane_uv(const shape *s, int part, surface *out)
{
    vec3 q = v3_sub(out->p_obj, s->desc.center);
    out->u = v3_dot(q, s->plane_u);
    out->v = v3_dot(q, s->plane_v);
}

/* The solid of a plane is the half-space behind it. */
static bool plane_contains(const shape *s, vec3 p)
{
    return v3_dot(v3_sub(p, s->desc.center), s->desc.normal) < 0;
}

/* A line crossing the plane is inside the half-space on one side of the
 * crossing; one along it, everywhere or nowhere. */
static bool plane_span(const shape *s, const ray *r, shape_span *out)
{
    double t;
    *out = (shape_span){-INFINITY, INFINITY, 0, 0, 0, 0};
    if (!plane_hit(s->desc.center, s->desc.normal, r, -INFINITY, INFINITY, &t))
        return v3_dot(r->d, s->desc.normal) == 0 && plane_contains(s, r->o);
    if (v3_dot(r->d, s->desc.normal) < 0)
        out->t_in = t;
    else
        out->t_out = t;
    return true;
}

static const param PLANE_PARAMS[] = {
    {.key = "point", .type = PARAM_VEC3, .offset = offsetof(glint_shape, center), .meaning = "a point on the plane"},
    {.key = "normal", .type = PARAM_DIRECTION, .offset = offsetof(glint_shape, normal), .required = true,
     .meaning = "the side the plane faces"},
};

const shape_kind plane_kind = {
    .closed = shape_always_closed,
    .name = "plane", .id = GLINT_SHAPE_PLANE, .params = PARAM_TABLE(PLANE_PARAMS), .max_crossings = 1,
    .flat = true, .init = plane_init, .intersect = plane_intersect, .span = plane_span, .intersect4 = plane_intersect4,
    .surface = plane_surface, .uv = plane_uv, .contains = plane_contains,
};
