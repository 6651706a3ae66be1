/* cylinder.c - cylinders in object space: standing on the centre of their
 * base, about +y, with radius and height, open or with both caps.
 *
 * Part 0 is the side, 1 the bottom cap, 2 the top cap. The side and the caps
 * are found from the same two intervals (where the ray is within the radius
 * and where it is within the height), so at the rim one of them always
 * claims a ray and none slips between. */
#include <stddef.h>
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

/* The interval of t where the ray is within radius of the y axis. */
static bool radius_span(const ray *r, double radius, double *t_in, double *t_out)
{
    double a = r->d.x * r->d.x + r->d.z * r->d.z;
    double b = 2 * (r->o.x * r->d.x + r->o.z * r->d.z);
    double c = r->o.x * r->o.x + r->o.z * r->o.z - radius * radius;
    if (a == 0) {
        *t_in = -INFINITY;
        *t_out = INFINITY;
        return c <= 0;
    }
    return quadratic(a, b, c, t_in, t_out);
}

static bool cylinder_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    const glint_shape *d = &s->desc;
    ray l = {v3_sub(r->o, d->center), r->d};
    double r_in, r_out, y_in, y_out;
    if (!radius_span(&l, d->radius, &r_in, &r_out) || !slab(l.o.y, l.d.y, 0, d->height, &y_in, &y_out))
        return false;
    shape_hit best = {.t = tmax};
    if (within(r_in, y_in, y_out))
        hit_offer(&best, tmin, r_in, 0);
    if (within(r_out, y_in, y_out))
        hit_offer(&best, tmin, r_out, 0);
    if (d->capped) {
        /* Going up, the ray meets the bottom cap first. */
        int cap_in = l.d.y > 0 ? 1 : 2;
        if (within(y_in, r_in, r_out))
            hit_offer(&best, tmin, y_in, cap_in);
        if (within(y_out, r_in, r_out))
            hit_offer(&best, tmin, y_out, 3 - cap_in);
    }
    return hit_take(&best, tmax, hit);
}

/* cylinder_intersect for four lanes (tmin 0): the same arithmetic in each.
 * A lane whose direction is parallel to the axis (radius_span's a == 0)
 * takes the one-lane test. */
static quad_mask cylinder_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit)
{
    const glint_shape *d = &s->desc;
    quad_f64 ox = quad_load(r->ox + first) - d->center.x, oy = quad_load(r->oy + first) - d->center.y;
    quad_f64 oz = quad_load(r->oz + first) - d->center.z;
    quad_f64 dx = quad_load(r->dx + first), dy = quad_load(r->dy + first), dz = quad_load(r->dz + first);
    /* radius_span */
    quad_f64 a = dx * dx + dz * dz, b = quad_splat(2) * (ox * dx + oz * dz);
    quad_f64 c = ox * ox + oz * oz - quad_splat(d->radius * d->radius), r_in, r_out;
    quad_f64 y_in, y_out;
    quad_mask spans = quadratic4(a, b, c, &r_in, &r_out) & slab4(oy, dy, 0, d->height, &y_in, &y_out);
    quad_f64 best = tmax;
    quad_mask part = {0}, side = {0};
    hit_offer4(&best, &part, spans & (r_in >= y_in) & (r_in <= y_out), r_in, side);
    hit_offer4(&best, &part, spans & (r_out >= y_in) & (r_out <= y_out), r_out, side);
    if (d->capped) {
        /* Going up, the ray meets the bottom cap first. */
        quad_mask cap_in = quad_mask_select(dy > quad_splat(0), side + 1, side + 2);
        hit_offer4(&best, &part, spans & (y_in >= r_in) & (y_in <= r_out), y_in, cap_in);
        hit_offer4(&best, &part, spans & (y_out >= r_in) & (y_out <= r_out), y_out, 3 - cap_in);
    }
    return hits4_end(s, r, first, tmax, a == quad_splat(0), spans & (best < tmax), best, part, hit);
}

/* Side: u is the angle about the axis (see polar_u), v the height from 0 at
 * the base to 1 at the top. Caps: see disc_uv. */
static void cylinder_surface(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 l = v3_sub(out->p_obj, d->center);
    out->n = part == 0 ? v3(l.x / d->radius, 0, l.z / d->radius) : v3(0, part == 1 ? -1 : 1, 0);
}

static void cylinder_uv(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 l = v3_sub(out->p_obj, d->center);
    if (part == 0) {
        out->u = polar_u(l.x, l.z);
        out->v = l.y / d->height;
        return;
    }
    disc_uv(l, d->radius, out);
}

static void cylinder_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    axial_bounds(&s->desc, lo, hi);
}

static const param CYLINDER_PARAMS[] = {
    AXIAL_PARAMS,
    {.key = "capped", .type = PARAM_BOOL, .offset = offsetof(glint_shape, capped), .def = {1},
     .meaning = "whether it has both caps"},
};

/* The side, then the bottom and top caps when it has them, by area. */
static double cylinder_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    const glint_shape *d = &s->desc;
    double cap = d->capped ? M_PI * d->radius * d->radius : 0, total;
    double area[3] = {2 * M_PI * d->radius * d->height, cap, cap};
    int part = pick_by_area(area, 3, &u1, &total);
    double phi = 2 * M_PI * u2, c = cos(phi), sn = sin(phi);
    if (part == 0) {
        *n = v3(c, 0, sn);
        *p = v3_add(d->center, v3(d->radius * c, u1 * d->height, d->radius * sn));
    } else {
        double r = d->radius * sqrt(u1);
        *n = v3(0, part == 1 ? -1 : 1, 0);
        *p = v3_add(d->center, v3(r * c, part == 1 ? 0 : d->height, r * sn));
    }
    return total;
}

/* Closed by its caps. */
static bool cylinder_closed(const shape *s) { return s->desc.capped; }

const shape_kind cylinder_kind = {
    .closed = cylinder_closed,
    .name = "cylinder", .id = GLINT_SHAPE_CYLINDER, .params = PARAM_TABLE(CYLINDER_PARAMS), .max_crossings = 2,
    .intersect = cylinder_intersect, .intersect4 = cylinder_intersect4, .surface = cylinder_surface, .uv = cylinder_uv,
    .bounds = cylinder_bounds, .sample = cylinder_sample,
};
