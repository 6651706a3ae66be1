/* cone.c - cones in object space: base centre, base radius and height, the
 * apex straight above the base centre; optionally capped at the base.
 *
 * Part 0 is the side, 1 the base cap. Only the nappe between base and apex
 * is part of the shape. */
#include <stddef.h>
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

/* The coefficients and roots of F(t) = x^2 + z^2 - k^2 (h - y)^2 along the
 * ray, F <= 0 being inside the double cone through the apex. */
typedef struct cone_roots {
    double a, b, c, t0, t1;
    bool real;
} cone_roots;

/* Whether the ray is inside the double cone at t, read off the roots rather
 * than by evaluating F again, so that the cap and the side agree about the
 * rim and no ray slips between them. */
static bool inside_at(const cone_roots *q, double t)
{
    if (!q->real)
        return q->a < 0 || (q->a == 0 && q->c <= 0);
    if (q->a > 0)
        return within(t, q->t0, q->t1);
    if (q->a < 0)
        return t <= q->t0 || t >= q->t1;
    return q->b > 0 ? t <= q->t0 : t >= q->t0;
}

static bool cone_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    const glint_shape *d = &s->desc;
    vec3 o = v3_sub(r->o, d->center), dir = r->d;
    double k2 = (d->radius / d->height) * (d->radius / d->height);
    double below_apex = d->height - o.y;
    double y_in, y_out;
    if (!slab(o.y, dir.y, 0, d->height, &y_in, &y_out))
        return false;
    cone_roots q;
    q.a = dir.x * dir.x + dir.z * dir.z - k2 * dir.y * dir.y;
    q.b = 2 * (o.x * dir.x + o.z * dir.z + k2 * below_apex * dir.y);
    q.c = o.x * o.x + o.z * o.z - k2 * below_apex * below_apex;
    q.real = quadratic(q.a, q.b, q.c, &q.t0, &q.t1);
    shape_hit best = {tmax, 0};
    /* The height interval also rules out the upper nappe, above the apex. */
    if (q.real && within(q.t0, y_in, y_out))
        hit_offer(&best, tmin, q.t0, 0);
    if (q.real && within(q.t1, y_in, y_out))
        hit_offer(&best, tmin, q.t1, 0);
    if (d->capped) {
        double t_base = dir.y > 0 ? y_in : y_out;
        if (inside_at(&q, t_base))
            hit_offer(&best, tmin, t_base, 1);
    }
    return hit_take(&best, tmax, hit);
}

/* Side: u is the angle about the axis (see polar_u), v the height from 0 at
 * the base to 1 at the apex. Cap: see disc_uv. */
static void cone_surface(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 l = v3_sub(out->p_obj, d->center);
    if (part == 1) {
        out->n = v3(0, -1, 0);
        return;
    }
    /* grad F = 2 (x, k^2 (h - y), z), and on the surface k (h - y) = r, so
     * it is parallel to (x / r, k, z / r). The apex has no gradient. */
    double r = sqrt(l.x * l.x + l.z * l.z);
    out->n = r > 0 ? v3(l.x / r, d->radius / d->height, l.z / r) : v3(0, 1, 0);
}

static void cone_uv(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 l = v3_sub(out->p_obj, d->center);
    if (part == 1) {
        disc_uv(l, d->radius, out);
        return;
    }
    out->u = polar_u(l.x, l.z);
    out->v = l.y / d->height;
}

static void cone_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    axial_bounds(&s->desc, lo, hi);
}

static const param CONE_PARAMS[] = {
    AXIAL_PARAMS,
    {.key = "capped", .type = PARAM_BOOL, .offset = offsetof(glint_shape, capped), .def = {1},
     .meaning = "whether it has the base cap"},
};

/* The side, then the base cap when it has one, by area. A point of the
 * side at fraction t of the way down from the apex lies on a circle of
 * radius t r, so t goes as the square root to be uniform by area. */
static double cone_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    const glint_shape *d = &s->desc;
    double r = d->radius, h = d->height, slant = sqrt(r * r + h * h), total;
    double area[2] = {M_PI * r * slant, d->capped ? M_PI * r * r : 0};
    int part = pick_by_area(area, 2, &u1, &total);
    double phi = 2 * M_PI * u2, c = cos(phi), sn = sin(phi), t = sqrt(u1);
    if (part == 0) {
        *n = v3_scale(v3(h * c, r, h * sn), 1 / slant);
        *p = v3_add(d->center, v3(t * r * c, (1 - t) * h, t * r * sn));
    } else {
        *n = v3(0, -1, 0);
        *p = v3_add(d->center, v3(t * r * c, 0, t * r * sn));
    }
    return total;
}

const shape_kind cone_kind = {
    .name = "cone", .id = GLINT_SHAPE_CONE, .params = PARAM_TABLE(CONE_PARAMS), .max_crossings = 2,
    .intersect = cone_intersect, .surface = cone_surface, .uv = cone_uv,
    .bounds = cone_bounds, .sample = cone_sample,
};
