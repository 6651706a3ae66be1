/* quadric.c - any second-order surface, f(p) = A x^2 + B y^2 + C z^2 +
 * D xy + E xz + F yz + G x + H y + I z + J = 0, kept within the box min..max
 * (POV-Ray's quadric; Tachyon's, written out): ellipsoids, paraboloids,
 * hyperboloids, cones and cylinders about any axis, and the planes they
 * degenerate to. Its front is where f > 0, the side its gradient points
 * to. A ray is clipped to the box first and measured from where it
 * enters, at unit speed, so the quadratic's coefficients stay of the box's
 * size however far the ray comes from. */
#include <stddef.h>
#include "core/error.h"
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

static glint_status quadric_init(shape *s, glint_error *err)
{
    const glint_shape *d = &s->desc;
    if (!(d->min.x < d->max.x && d->min.y < d->max.y && d->min.z < d->max.z))
        return error_set(err, GLINT_ERR_INVALID, "quadric min must be below max on every axis");
    bool any = false;
    for (int i = 0; i < 9; i++)
        any |= d->coefficients[i] != 0;
    if (!any)
        return error_set(err, GLINT_ERR_INVALID, "quadric coefficients A to I are all 0: it has no surface");
    return GLINT_OK;
}

/* f at p, and its gradient. */
static double quadric_f(const double *k, vec3 p)
{
    return k[0] * p.x * p.x + k[1] * p.y * p.y + k[2] * p.z * p.z + k[3] * p.x * p.y + k[4] * p.x * p.z +
           k[5] * p.y * p.z + k[6] * p.x + k[7] * p.y + k[8] * p.z + k[9];
}

static vec3 quadric_gradient(const double *k, vec3 p)
{
    return v3(2 * k[0] * p.x + k[3] * p.y + k[4] * p.z + k[6], 2 * k[1] * p.y + k[3] * p.x + k[5] * p.z + k[7],
              2 * k[2] * p.z + k[4] * p.x + k[5] * p.y + k[8]);
}

static bool quadric_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    const glint_shape *d = &s->desc;
    const double *k = d->coefficients;
    double speed = v3_length(r->d);
    if (!(speed > 0))
        return false;
    vec3 u = v3_scale(r->d, 1 / speed);
    double x0, x1, y0, y1, z0, z1;
    if (!slab(r->o.x, u.x, d->min.x, d->max.x, &x0, &x1) || !slab(r->o.y, u.y, d->min.y, d->max.y, &y0, &y1) ||
        !slab(r->o.z, u.z, d->min.z, d->max.z, &z0, &z1))
        return false;
    double enter = fmax(fmax(x0, y0), fmax(z0, tmin * speed)), leave = fmin(fmin(x1, y1), fmin(z1, tmax * speed));
    if (!(enter <= leave))
        return false;
    vec3 p = v3_madd(r->o, u, enter);
    /* f(p + s u) = a s^2 + b s + c. */
    double a = quadric_f(k, u) - quadric_f(k, v3(0, 0, 0)) - (k[6] * u.x + k[7] * u.y + k[8] * u.z);
    double b = v3_dot(quadric_gradient(k, p), u), c = quadric_f(k, p);
    double s0, s1;
    if (!quadratic(a, b, c, &s0, &s1))
        return false;
    shape_hit best = {.t = tmax};
    double roots[2] = {s0, s1};
    for (int i = 0; i < 2; i++)
        if (roots[i] >= 0 && roots[i] <= leave - enter)
            hit_offer(&best, tmin, (enter + roots[i]) / speed, 0);
    return hit_take(&best, tmax, hit);
}

static void quadric_surface(const shape *s, int part, surface *out)
{
    out->n = quadric_gradient(s->desc.coefficients, out->p_obj);
}

/* u the angle about the box's vertical middle line (polar_u), v the height
 * in the box, 0 at its bottom and 1 at its top. */
static void quadric_uv(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 mid = v3_scale(v3_add(d->min, d->max), 0.5), p = out->p_obj;
    out->u = polar_u(p.x - mid.x, p.z - mid.z);
    out->v = (p.y - d->min.y) / (d->max.y - d->min.y);
}

static void quadric_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    *lo = s->desc.min;
    *hi = s->desc.max;
}

static const param QUADRIC_PARAMS[] = {
    {.key = "coefficients", .type = PARAM_NUMBERS, .offset = offsetof(glint_shape, coefficients), .required = true,
     .max_count = 10, .meaning = "A to J of A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0"},
    {.key = "min", .type = PARAM_VEC3, .offset = offsetof(glint_shape, min), .required = true,
     .meaning = "the clipping box's corner with the least x, y and z"},
    {.key = "max", .type = PARAM_VEC3, .offset = offsetof(glint_shape, max), .required = true,
     .meaning = "its opposite corner, above min on every axis"},
};

const shape_kind quadric_kind = {
    .name = "quadric", .id = GLINT_SHAPE_QUADRIC, .params = PARAM_TABLE(QUADRIC_PARAMS), .max_crossings = 2,
    .saddle = true, .init = quadric_init, .intersect = quadric_intersect, .surface = quadric_surface,
    .uv = quadric_uv, .bounds = quadric_bounds, .center = shape_bounds_middle,
};
