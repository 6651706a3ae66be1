/* shape.c - the shape interface: checks a description, then sends rays and
 * results between world space and the object space where each kind works. */
#include <string.h>
#include "geometry/kinds.h"

typedef struct kind_ops {
    glint_status (*init)(shape *s, glint_error *err);
    bool (*intersect)(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit);
    void (*surface)(const shape *s, int part, surface *out);
    void (*uv)(const shape *s, int part, surface *out);
    void (*bounds)(const shape *s, vec3 *lo, vec3 *hi);
} kind_ops;

static const kind_ops KINDS[] = {
    [GLINT_SHAPE_SPHERE] = {sphere_init, sphere_intersect, sphere_surface, sphere_uv, sphere_bounds},
    [GLINT_SHAPE_PLANE] = {plane_init, plane_intersect, plane_surface, plane_uv, NULL},
    [GLINT_SHAPE_POLYGON] = {polygon_init, polygon_intersect, polygon_surface, polygon_uv, polygon_bounds},
    [GLINT_SHAPE_BOX] = {box_init, box_intersect, box_surface, box_uv, box_bounds},
    [GLINT_SHAPE_CYLINDER] = {cylinder_init, cylinder_intersect, cylinder_surface, cylinder_uv, cylinder_bounds},
    [GLINT_SHAPE_CONE] = {cone_init, cone_intersect, cone_surface, cone_uv, cone_bounds},
};

glint_status shape_init(shape *s, const glint_shape *desc, const glint_transform *to_world,
                        int material, glint_error *err)
{
    memset(s, 0, sizeof *s);
    /* The cast also catches negative values of the enum. */
    if ((unsigned)desc->kind >= sizeof KINDS / sizeof KINDS[0])
        return error_set(err, GLINT_ERR_INVALID, "unknown shape kind %d", (int)desc->kind);
    s->desc = *desc;
    s->material = material;
    s->to_world = to_world ? *to_world : glint_transform_identity();
    if (!xf_invert(&s->to_world, &s->to_object))
        return error_set(err, GLINT_ERR_INVALID, "transform is singular or not finite");
    s->has_transform = !xf_is_identity(&s->to_world);
    glint_status st = KINDS[desc->kind].init(s, err);
    if (st == GLINT_OK && !s->has_transform && (desc->kind == GLINT_SHAPE_PLANE || desc->kind == GLINT_SHAPE_POLYGON)) {
        /* What shape_surface would compute at every hit, computed once:
         * the same bits. */
        surface one = {.p_obj = s->desc.center};
        KINDS[desc->kind].surface(s, 0, &one);
        s->flat = true;
        s->flat_n = v3_normalize(one.n);
    }
    return st;
}

/* For a shape with a transform. The direction is mapped but not
 * normalised, so a point's ray parameter t is the same in both spaces and
 * hits need no conversion back. */
static ray object_ray(const shape *s, const ray *r)
{
    ray o = {xf_point(&s->to_object, r->o), xf_vector(&s->to_object, r->d)};
    return o;
}

bool shape_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    /* Most shapes have no transform: their rays need no copy. */
    if (!s->has_transform)
        return KINDS[s->desc.kind].intersect(s, r, tmin, tmax, hit);
    ray o = object_ray(s, r);
    return KINDS[s->desc.kind].intersect(s, &o, tmin, tmax, hit);
}

quad_mask shape_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_f64 *t)
{
    return s->desc.kind == GLINT_SHAPE_SPHERE ? sphere_intersect4(s, r, first, tmax, t)
                                              : polygon_intersect4(s, r, first, tmax, t);
}

bool shape_intersect_plane(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    if (!s->has_transform)
        return plane_intersect(s, r, tmin, tmax, hit);
    ray o = object_ray(s, r);
    return plane_intersect(s, &o, tmin, tmax, hit);
}

void shape_surface(const shape *s, const ray *r, const shape_hit *hit, surface *out)
{
    out->p = ray_at(r, hit->t);
    if (s->has_transform) {
        ray o = object_ray(s, r);
        out->p_obj = ray_at(&o, hit->t);
    } else {
        out->p_obj = out->p;
    }
    out->part = hit->part;
    out->u = out->v = 0;
    if (s->flat) {
        /* The bits the lines below would give, computed once by
         * shape_init instead of a square root and a division a hit. */
        out->n = out->shading_n = s->flat_n;
        return;
    }
    KINDS[s->desc.kind].surface(s, hit->part, out);
    if (s->has_transform)
        out->n = xf_normal(&s->to_object, out->n);
    out->n = out->shading_n = v3_normalize(out->n);
}

void shape_surface_uv(const shape *s, surface *out)
{
    KINDS[s->desc.kind].uv(s, out->part, out);
}

void shape_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    const kind_ops *k = &KINDS[s->desc.kind];
    if (!k->bounds) {
        *lo = v3(-SHAPE_PLANE_EXTENT, -SHAPE_PLANE_EXTENT, -SHAPE_PLANE_EXTENT);
        *hi = v3(SHAPE_PLANE_EXTENT, SHAPE_PLANE_EXTENT, SHAPE_PLANE_EXTENT);
        return;
    }
    vec3 a, b;
    k->bounds(s, &a, &b);
    if (!s->has_transform) {
        *lo = a;
        *hi = b;
        return;
    }
    /* An affine map sends the object box to a parallelepiped whose extremes
     * are among the images of its eight corners. */
    *lo = v3(INFINITY, INFINITY, INFINITY);
    *hi = v3(-INFINITY, -INFINITY, -INFINITY);
    for (int i = 0; i < 8; i++) {
        vec3 c = xf_point(&s->to_world, v3(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y, i & 4 ? b.z : a.z));
        *lo = min3(*lo, c);
        *hi = max3(*hi, c);
    }
}

bool shape_is_left_behind(const shape *s, vec3 n, vec3 d)
{
    glint_shape_kind k = s->desc.kind;
    return k == GLINT_SHAPE_PLANE || k == GLINT_SHAPE_POLYGON || v3_dot(n, d) > 0;
}

bool shape_is_closed(const shape *s)
{
    switch (s->desc.kind) {
    case GLINT_SHAPE_SPHERE:
    case GLINT_SHAPE_BOX:
        return true;
    case GLINT_SHAPE_CYLINDER:
    case GLINT_SHAPE_CONE:
        return s->desc.capped;
    default:
        return false;
    }
}
