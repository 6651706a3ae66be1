/* box.c - axis-aligned boxes in object space, between min and max.
 *
 * Parts 1 to 6 are the faces -x, +x, -y, +y, -z, +z. Each face's (u, v)
 * follow plane_basis for its outward normal, scaled to [0, 1] across the
 * box: seen from outside, u runs right and v runs down, so the four side
 * faces all have v = 0 along their top edge. */
#include <stddef.h>
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

static double component(vec3 v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

static glint_status box_init(shape *s, glint_error *err)
{
    const glint_shape *d = &s->desc;
    if (!(d->min.x < d->max.x && d->min.y < d->max.y && d->min.z < d->max.z))
        return error_set(err, GLINT_ERR_INVALID, "box min must be below max on every axis");
    return GLINT_OK;
}

/* The slab method: the ray is inside the box where it is inside all three
 * slabs at once; the slab entered last names the face it came in by. Rays
 * that only touch an edge or a face still hit. */
static bool box_span(const shape *s, const ray *r, shape_span *out)
{
    const glint_shape *d = &s->desc;
    double t_near = -INFINITY, t_far = INFINITY;
    int near_part = 0, far_part = 0;
    for (int axis = 0; axis < 3; axis++) {
        double dir = component(r->d, axis), t_in, t_out;
        if (!slab(component(r->o, axis), dir, component(d->min, axis), component(d->max, axis), &t_in, &t_out))
            return false;
        int low_face = 1 + 2 * axis;
        if (t_in > t_near) {
            t_near = t_in;
            near_part = dir > 0 ? low_face : low_face + 1;
        }
        if (t_out < t_far) {
            t_far = t_out;
            far_part = dir > 0 ? low_face + 1 : low_face;
        }
    }
    *out = (shape_span){t_near, t_far, near_part, far_part, 0, 0};
    return t_near <= t_far;
}

/* box_span for four rays: the same arithmetic in each lane, a lane parallel
 * to an axis taking slab's infinite ends for it. */
static quad_mask box_span4(const shape *s, const quad_ray *r, quad_span *out)
{
    const glint_shape *d = &s->desc;
    const quad_f64 o[3] = {r->ox, r->oy, r->oz}, dir[3] = {r->dx, r->dy, r->dz};
    const double lo[3] = {d->min.x, d->min.y, d->min.z}, hi[3] = {d->max.x, d->max.y, d->max.z};
    quad_f64 t_near = quad_splat(-INFINITY), t_far = quad_splat(INFINITY);
    quad_mask near_part = {0}, far_part = {0}, meets = ~(quad_mask){0};
    for (int axis = 0; axis < 3; axis++) {
        quad_f64 t_in, t_out;
        meets &= slab4(o[axis], dir[axis], lo[axis], hi[axis], &t_in, &t_out);
        quad_mask low_face = (quad_mask){0} + (1 + 2 * axis), up = dir[axis] > quad_splat(0);
        quad_mask enters = t_in > t_near, leaves = t_out < t_far;
        t_near = quad_select(enters, t_in, t_near);
        near_part = quad_mask_select(enters, quad_mask_select(up, low_face, low_face + 1), near_part);
        t_far = quad_select(leaves, t_out, t_far);
        far_part = quad_mask_select(leaves, quad_mask_select(up, low_face + 1, low_face), far_part);
    }
    out->t_in = t_near;
    out->t_out = t_far;
    out->part_in = near_part;
    out->part_out = far_part;
    return meets & (t_near <= t_far);
}

static bool box_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    shape_span span;
    return box_span(s, r, &span) && span_hit(&span, tmin, tmax, hit);
}

/* Where p lies along a (a coordinate axis of either sign) across the box:
 * 0 at the end a points away from, 1 at the end it points to. */
static double across(const glint_shape *d, vec3 p, vec3 a)
{
    vec3 mid = v3_scale(v3_add(d->min, d->max), 0.5), size = v3_sub(d->max, d->min);
    return 0.5 + v3_dot(v3_sub(p, mid), a) / v3_dot(size, v3(fabs(a.x), fabs(a.y), fabs(a.z)));
}

/* The outward normal of face `part`: parts 1..6 are -x, +x, -y, +y, -z, +z. */
static vec3 face_normal(int part)
{
    int axis = (part - 1) / 2;
    double sign = (part - 1) % 2 ? 1.0 : -1.0;
    return v3(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
}

static void box_surface(const shape *s, int part, surface *out)
{
    out->n = face_normal(part);
}

static void box_uv(const shape *s, int part, surface *out)
{
    vec3 u, v;
    plane_basis(face_normal(part), &u, &v);
    out->u = across(&s->desc, out->p_obj, u);
    out->v = across(&s->desc, out->p_obj, v);
}

static void box_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    *lo = s->desc.min;
    *hi = s->desc.max;
}

static const param BOX_PARAMS[] = {
    {.key = "min", .type = PARAM_VEC3, .offset = offsetof(glint_shape, min), .required = true,
     .meaning = "the corner with the least x, y and z"},
    {.key = "max", .type = PARAM_VEC3, .offset = offsetof(glint_shape, max), .required = true,
     .meaning = "the opposite corner, above min on every axis"},
};

/* Faces 1 to 6 (parts: -x, +x, -y, +y, -z, +z), each by its area. */
static double box_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    vec3 lo = s->desc.min, hi = s->desc.max, size = v3_sub(hi, lo);
    double side[3] = {size.y * size.z, size.x * size.z, size.x * size.y};
    double area[6] = {side[0], side[0], side[1], side[1], side[2], side[2]}, total;
    int face = pick_by_area(area, 6, &u1, &total), axis = face / 2;
    double t[3], uv[2] = {u1, u2};
    for (int a = 0, k = 0; a < 3; a++)
        t[a] = a == axis ? face % 2 : uv[k++];
    *p = v3(lo.x + t[0] * size.x, lo.y + t[1] * size.y, lo.z + t[2] * size.z);
    *n = face_normal(face + 1);
    return total;
}

const shape_kind box_kind = {
    .closed = shape_always_closed,
    .name = "box", .id = GLINT_SHAPE_BOX, .params = PARAM_TABLE(BOX_PARAMS), .max_crossings = 2,
    .init = box_init, .intersect = box_intersect, .span = box_span, .span4 = box_span4, .surface = box_surface,
    .uv = box_uv, .bounds = box_bounds, .center = shape_bounds_middle, .sample = box_sample,
};
