/* disk.c - discs and annuli in object space: a centre, the normal of the
 * side they face, an outer radius and an optional inner radius (a ring).
 * The cap that NFF and Tachyon scenes close their cylinders with, and the
 * shape of a disc light. Flat, so both sides are shaded alike: the
 * integrator turns the normal to face each ray. */
#include <stddef.h>
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

static glint_status disk_init(shape *s, glint_error *err)
{
    glint_shape *d = &s->desc;
    if (!(d->inner_radius < d->radius))
        return error_set(err, GLINT_ERR_INVALID, "disk inner_radius must be below its radius %g, got %g", d->radius,
                         d->inner_radius);
    /* As for planes: scaled by the largest component first, so tiny and
     * huge normals neither underflow nor overflow; kept unit in desc. */
    vec3 n = d->normal;
    double m = fmax(fabs(n.x), fmax(fabs(n.y), fabs(n.z)));
    d->normal = v3_normalize(v3(n.x / m, n.y / m, n.z / m));
    plane_basis(d->normal, &s->plane_u, &s->plane_v);
    return GLINT_OK;
}

/* Whether a point at squared distance d2 from the centre lies on the disc:
 * its rims count. */
static bool on_disk(const glint_shape *d, double d2)
{
    return d2 <= d->radius * d->radius && d2 >= d->inner_radius * d->inner_radius;
}

static bool disk_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    const glint_shape *d = &s->desc;
    double t;
    if (!plane_hit(d->center, d->normal, r, tmin, tmax, &t))
        return false;
    vec3 q = v3_sub(ray_at(r, t), d->center);
    if (!on_disk(d, v3_dot(q, q)))
        return false;
    hit->t = t;
    hit->part = 0;
    return true;
}

/* disk_intersect for four lanes, each lane's arithmetic in its order. */
static quad_mask disk_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit)
{
    quad_f64 *t = &hit->t;
    const glint_shape *d = &s->desc;
    quad_mask crosses = plane_hit4(d->center, d->normal, r, first, 0, tmax, t);
    quad_f64 qx = (quad_load(r->ox + first) + quad_load(r->dx + first) * *t) - quad_splat(d->center.x);
    quad_f64 qy = (quad_load(r->oy + first) + quad_load(r->dy + first) * *t) - quad_splat(d->center.y);
    quad_f64 qz = (quad_load(r->oz + first) + quad_load(r->dz + first) * *t) - quad_splat(d->center.z);
    quad_f64 d2 = quad_dot(qx, qy, qz, qx, qy, qz);
    return crosses & (d2 <= quad_splat(d->radius * d->radius)) & (d2 >= quad_splat(d->inner_radius * d->inner_radius));
}

static void disk_surface(const shape *s, int part, surface *out)
{
    out->n = s->desc.normal;
}

/* The disc's square of side 2 * radius mapped to [0, 1]^2 along the axes
 * plane_basis gives its normal, as on a plane: u right and v down seen
 * from the front. */
static void disk_uv(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 q = v3_sub(out->p_obj, d->center);
    out->u = 0.5 + v3_dot(q, s->plane_u) / (2 * d->radius);
    out->v = 0.5 + v3_dot(q, s->plane_v) / (2 * d->radius);
}

/* Along each axis a disc reaches radius times the sine of the angle between
 * that axis and its normal. */
static void disk_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    const glint_shape *d = &s->desc;
    vec3 n = d->normal;
    vec3 reach = v3(d->radius * sqrt(fmax(0.0, 1 - n.x * n.x)), d->radius * sqrt(fmax(0.0, 1 - n.y * n.y)),
                    d->radius * sqrt(fmax(0.0, 1 - n.z * n.z)));
    *lo = v3_sub(d->center, reach);
    *hi = v3_add(d->center, reach);
}

static const param DISK_PARAMS[] = {
    {.key = "center", .type = PARAM_VEC3, .offset = offsetof(glint_shape, center), .meaning = "the centre"},
    {.key = "normal", .type = PARAM_DIRECTION, .offset = offsetof(glint_shape, normal), .def = {0, 1, 0},
     .meaning = "the side the disc faces"},
    {.key = "radius", .type = PARAM_NUMBER, .offset = offsetof(glint_shape, radius), .required = true,
     PARAM_POSITIVE, .meaning = "the outer radius"},
    {.key = "inner_radius", .type = PARAM_NUMBER, .offset = offsetof(glint_shape, inner_radius), .lo = 0,
     .hi = DBL_MAX, .meaning = "the radius of the hole, below radius: 0 for a full disc, more for a ring"},
};

static double disk_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    const glint_shape *d = &s->desc;
    double inner2 = d->inner_radius * d->inner_radius, outer2 = d->radius * d->radius;
    double r = sqrt(inner2 + u1 * (outer2 - inner2)), phi = 2 * M_PI * u2;
    *p = v3_add(d->center, v3_add(v3_scale(s->plane_u, r * cos(phi)), v3_scale(s->plane_v, r * sin(phi))));
    *n = d->normal;
    return M_PI * (outer2 - inner2);
}

const shape_kind disk_kind = {
    .name = "disk", .id = GLINT_SHAPE_DISK, .params = PARAM_TABLE(DISK_PARAMS), .max_crossings = 1, .flat = true,
    .init = disk_init, .intersect = disk_intersect, .intersect4 = disk_intersect4, .surface = disk_surface,
    .uv = disk_uv, .bounds = disk_bounds, .sample = disk_sample,
};
