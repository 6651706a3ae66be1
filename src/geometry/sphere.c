/* sphere.c - spheres in object space: centre and radius. */
#include <stddef.h>
#include "geometry/shape_kind.h"
#include "geometry/sphere_math.h"

static bool sphere_span(const shape *s, const ray *r, shape_span *out)
{
    *out = (shape_span){0};
    return sphere_span_at(s->desc.center, s->desc.radius, r, &out->t_in, &out->t_out);
}

/* sphere_span for four rays: the same arithmetic in each lane. A lane
 * whose roots are both 0 (quadratic4 leaves those out) or whose direction
 * is zero spans nothing, as the combinations that read spans take it:
 * quadratic's span there, one point at most, is empty too. */
static quad_mask sphere_span4(const shape *s, const quad_ray *r, quad_span *out)
{
    const glint_shape *d = &s->desc;
    quad_f64 ocx = r->ox - quad_splat(d->center.x);
    quad_f64 ocy = r->oy - quad_splat(d->center.y);
    quad_f64 ocz = r->oz - quad_splat(d->center.z);
    quad_f64 a = quad_dot(r->dx, r->dy, r->dz, r->dx, r->dy, r->dz);
    quad_f64 b = quad_splat(2) * quad_dot(ocx, ocy, ocz, r->dx, r->dy, r->dz);
    quad_f64 c = quad_dot(ocx, ocy, ocz, ocx, ocy, ocz) - quad_splat(d->radius * d->radius);
    out->part_in = out->part_out = (quad_mask){0};
    return quadratic4(a, b, c, &out->t_in, &out->t_out) & (a != quad_splat(0));
}

static bool sphere_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    return sphere_hit_at(s->desc.center, s->desc.radius, r, tmin, tmax, hit);
}

static quad_mask sphere_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit)
{
    return sphere_hits4_at(s->desc.center, s->desc.radius, r, first, tmax, &hit->t);
}

/* About shape_center, the sphere's centre (a set's sphere `part`'s). u is
 * the longitude (0.5 at +z, seam at -z), v runs from 0 at the north (+y)
 * pole to 1 at the south pole. */
void sphere_surface(const shape *s, int part, surface *out)
{
    out->n = v3_sub(out->p_obj, shape_center(s, part));
}

void sphere_uv(const shape *s, int part, surface *out)
{
    spherical_uv(v3_normalize(v3_sub(out->p_obj, shape_center(s, part))), &out->u, &out->v);
}

static void sphere_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    const glint_shape *d = &s->desc;
    *lo = v3_sub(d->center, v3(d->radius, d->radius, d->radius));
    *hi = v3_add(d->center, v3(d->radius, d->radius, d->radius));
}

static const param SPHERE_PARAMS[] = {
    {.key = "center", .type = PARAM_VEC3, .offset = offsetof(glint_shape, center), .meaning = "the centre"},
    {.key = "radius", .type = PARAM_NUMBER, .offset = offsetof(glint_shape, radius), .required = true,
     PARAM_POSITIVE, .meaning = "the radius"},
};

static double sphere_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    const glint_shape *d = &s->desc;
    double z = 1 - 2 * u1, ring = sqrt(fmax(0, 1 - z * z)), phi = 2 * M_PI * u2;
    *n = v3(ring * cos(phi), z, ring * sin(phi));
    *p = v3_madd(d->center, *n, d->radius);
    return 4 * M_PI * d->radius * d->radius;
}

const shape_kind sphere_kind = {
    .closed = shape_always_closed,
    .name = "sphere", .id = GLINT_SHAPE_SPHERE, .params = PARAM_TABLE(SPHERE_PARAMS), .max_crossings = 2,
    .intersect = sphere_intersect, .span = sphere_span, .span4 = sphere_span4, .intersect4 = sphere_intersect4,
    .surface = sphere_surface, .uv = sphere_uv, .bounds = sphere_bounds, .sample = sphere_sample,
};
