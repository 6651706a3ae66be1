/* torus.c - tori in object space: a ring about the y axis through the
 * centre, in the xz plane, of major radius R (centre to the middle of the
 * tube) and minor radius r (the tube's), r < R.
 *
 * A point p (from the centre) is on it where (|p|^2 + R^2 - r^2)^2 =
 * 4 R^2 (p.x^2 + p.z^2): a quartic along a ray. Its roots are isolated
 * between those of its derivative (poly_roots.c) rather than taken from
 * Ferrari's formula, whose cancellation loses the two close roots of a ray
 * grazing the tube (speckles along the rims). The ray is first clipped to
 * the torus's box and measured from where it enters, at unit speed, so the
 * quartic's coefficients stay of the torus's size however far the ray
 * comes from. */
#include <stddef.h>
#include "core/error.h"
#include "geometry/poly_roots.h"
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

static glint_status torus_init(shape *s, glint_error *err)
{
    const glint_shape *d = &s->desc;
    if (!(d->minor_radius < d->radius))
        return error_set(err, GLINT_ERR_INVALID, "torus minor_radius must be below its major_radius %g, got %g",
                         d->radius, d->minor_radius);
    return GLINT_OK;
}

static bool torus_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    const glint_shape *d = &s->desc;
    double big = d->radius, small = d->minor_radius, outer = big + small;
    double speed = v3_length(r->d);
    if (!(speed > 0))
        return false;
    vec3 o = v3_sub(r->o, d->center), u = v3_scale(r->d, 1 / speed);
    /* Where the ray is within the box, in distance along it. */
    double x0, x1, y0, y1, z0, z1;
    if (!slab(o.x, u.x, -outer, outer, &x0, &x1) || !slab(o.y, u.y, -small, small, &y0, &y1) ||
        !slab(o.z, u.z, -outer, outer, &z0, &z1))
        return false;
    double enter = fmax(fmax(x0, y0), fmax(z0, tmin * speed)), leave = fmin(fmin(x1, y1), fmin(z1, tmax * speed));
    if (!(enter <= leave))
        return false;
    vec3 p = v3_madd(o, u, enter);
    /* Along the ray from p at unit speed: |p + s u|^2 + R^2 - r^2 =
     * s^2 + b s + c, and its distance from the axis squared is
     * a' s^2 + b' s + c'. */
    double b = 2 * v3_dot(p, u), c = v3_dot(p, p) + big * big - small * small;
    double a_axis = u.x * u.x + u.z * u.z, b_axis = 2 * (p.x * u.x + p.z * u.z), c_axis = p.x * p.x + p.z * p.z;
    double four_r2 = 4 * big * big;
    double quartic[5] = {c * c - four_r2 * c_axis, 2 * b * c - four_r2 * b_axis, b * b + 2 * c - four_r2 * a_axis, 2 * b,
                         1};
    /* The nearest hit is the first root, unless rounding put that at the
     * ray's start, which the offer refuses: then the next. The pieces past
     * the one wanted are not searched. */
    double roots[POLY_MAX_DEGREE + 1];
    shape_hit best = {.t = tmax};
    for (int most = 1; most <= 4; most++) {
        int n = poly_roots(quartic, 4, 0, leave - enter, roots, most);
        for (int i = 0; i < n; i++)
            hit_offer(&best, tmin, (enter + roots[i]) / speed, 0);
        /* Found, no more roots, or the last one refused as too far. */
        if (best.t < tmax || n < most || (enter + roots[n - 1]) / speed > tmin)
            break;
    }
    return hit_take(&best, tmax, hit);
}

/* The normal points from the nearest point of the tube's middle circle. */
static void torus_surface(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 p = v3_sub(out->p_obj, d->center);
    double axis = sqrt(p.x * p.x + p.z * p.z);
    vec3 middle = axis > 0 ? v3(p.x * d->radius / axis, 0, p.z * d->radius / axis) : v3(d->radius, 0, 0);
    out->n = v3_sub(p, middle);
}

/* u the angle about the y axis (polar_u), v the angle about the tube: 0
 * and 1 at its outer equator, 0.25 at its top, 0.5 at its inner equator. */
static void torus_uv(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 p = v3_sub(out->p_obj, d->center);
    out->u = polar_u(p.x, p.z);
    double v = atan2(p.y, sqrt(p.x * p.x + p.z * p.z) - d->radius) / (2 * M_PI);
    out->v = v < 0 ? v + 1 : v;
}

static void torus_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    const glint_shape *d = &s->desc;
    double outer = d->radius + d->minor_radius;
    *lo = v3_add(d->center, v3(-outer, -d->minor_radius, -outer));
    *hi = v3_add(d->center, v3(outer, d->minor_radius, outer));
}

/* Uniform by area: the angle about the axis uniform, the angle theta about
 * the tube with density in proportion to the ring's length there,
 * R + r cos theta: theta solves R theta + r sin theta = 2 pi R u2, found by
 * Newton's method kept within its bracket. */
static double torus_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    const glint_shape *d = &s->desc;
    double big = d->radius, small = d->minor_radius, goal = 2 * M_PI * big * u2;
    double lo = 0, hi = 2 * M_PI, theta = 2 * M_PI * u2;
    for (int i = 0; i < 60; i++) {
        double f = big * theta + small * sin(theta) - goal;
        if (f > 0)
            hi = theta;
        else
            lo = theta;
        double next = theta - f / (big + small * cos(theta));
        theta = next > lo && next < hi ? next : 0.5 * (lo + hi);
        if (hi - lo < 1e-15)
            break;
    }
    double phi = 2 * M_PI * u1, ring = big + small * cos(theta);
    *n = v3(cos(theta) * sin(phi), sin(theta), cos(theta) * cos(phi));
    *p = v3_add(d->center, v3(ring * sin(phi), small * sin(theta), ring * cos(phi)));
    return 4 * M_PI * M_PI * big * small;
}

static const param TORUS_PARAMS[] = {
    {.key = "center", .type = PARAM_VEC3, .offset = offsetof(glint_shape, center), .meaning = "the centre"},
    {.key = "major_radius", .type = PARAM_NUMBER, .offset = offsetof(glint_shape, radius), .required = true,
     PARAM_POSITIVE, .meaning = "from the centre to the middle of the tube, in the xz plane"},
    {.key = "minor_radius", .type = PARAM_NUMBER, .offset = offsetof(glint_shape, minor_radius), .required = true,
     PARAM_POSITIVE, .meaning = "the tube's radius, below major_radius"},
};

const shape_kind torus_kind = {
    .closed = shape_always_closed,
    .name = "torus", .id = GLINT_SHAPE_TORUS, .params = PARAM_TABLE(TORUS_PARAMS), .max_crossings = 4,
    .init = torus_init, .intersect = torus_intersect, .surface = torus_surface, .uv = torus_uv,
    .bounds = torus_bounds, .sample = torus_sample,
};
