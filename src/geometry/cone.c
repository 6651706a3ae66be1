/* cone.c - cones in object space: base centre, base radius and height, the
 * apex straight above the base centre; or, with a top radius, a cone cut
 * off at the height (a frustum: the NFF and Tachyon cone, a lamp shade),
 * narrower or wider at the top; optionally capped at the base and the top.
 *
 * Part 0 is the side, 1 the base cap, 2 the top cap. Only the piece of the
 * nappe between base and top is part of the shape. The radius at height y
 * is k (H - y): the apex at height H, above the base for a top narrower
 * than the base, below it for a wider one. */
#include <stddef.h>
#include "geometry/shape_kind.h"
#include "geometry/shape_math.h"

/* The coefficients and roots of F(t) = x^2 + z^2 - k^2 (H - y)^2 along the
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
    double k = (d->radius - d->top_radius) / d->height, k2 = k * k;
    /* r / (r - 0) is 1 exactly: a pointed cone's apex is at its height. */
    double below_apex = d->height * (d->radius / (d->radius - d->top_radius)) - o.y;
    double y_in, y_out;
    if (!slab(o.y, dir.y, 0, d->height, &y_in, &y_out))
        return false;
    cone_roots q = {0}; /* the roots stay 0 when there are none */
    q.a = dir.x * dir.x + dir.z * dir.z - k2 * dir.y * dir.y;
    q.b = 2 * (o.x * dir.x + o.z * dir.z + k2 * below_apex * dir.y);
    q.c = o.x * o.x + o.z * o.z - k2 * below_apex * below_apex;
    q.real = quadratic(q.a, q.b, q.c, &q.t0, &q.t1);
    shape_hit best = {.t = tmax};
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
    if (d->top_capped && d->top_radius > 0) {
        double t_top = dir.y > 0 ? y_out : y_in;
        if (inside_at(&q, t_top))
            hit_offer(&best, tmin, t_top, 2);
    }
    return hit_take(&best, tmax, hit);
}

/* inside_at for four lanes whose roots are real where `real`, a != 0. */
static inline quad_mask inside_at4(quad_mask real, quad_f64 a, quad_f64 t0, quad_f64 t1, quad_f64 t)
{
    quad_mask opens_up = a > quad_splat(0);
    quad_mask between = (t >= t0) & (t <= t1), outside = (t <= t0) | (t >= t1);
    return quad_mask_select(real, quad_mask_select(opens_up, between, outside), a < quad_splat(0));
}

/* cone_intersect for four lanes (tmin 0): the same arithmetic in each. A
 * lane whose quadratic is linear (a == 0, a ray along the slant) or whose
 * b is 0 (then both roots may be 0) takes the one-lane test. */
static quad_mask cone_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit)
{
    const glint_shape *d = &s->desc;
    double k = (d->radius - d->top_radius) / d->height, k2 = k * k;
    double apex = d->height * (d->radius / (d->radius - d->top_radius));
    quad_f64 ox = quad_load(r->ox + first) - d->center.x, oy = quad_load(r->oy + first) - d->center.y;
    quad_f64 oz = quad_load(r->oz + first) - d->center.z;
    quad_f64 dx = quad_load(r->dx + first), dy = quad_load(r->dy + first), dz = quad_load(r->dz + first);
    quad_f64 below_apex = quad_splat(apex) - oy, y_in, y_out, t0, t1;
    quad_mask spans = slab4(oy, dy, 0, d->height, &y_in, &y_out);
    quad_f64 a = dx * dx + dz * dz - quad_splat(k2) * dy * dy;
    quad_f64 b = quad_splat(2) * (ox * dx + oz * dz + quad_splat(k2) * below_apex * dy);
    quad_f64 c = ox * ox + oz * oz - quad_splat(k2) * below_apex * below_apex;
    quad_mask real = quadratic4(a, b, c, &t0, &t1);
    quad_f64 best = tmax;
    quad_mask part = {0}, side = {0}, up = dy > quad_splat(0);
    hit_offer4(&best, &part, spans & real & (t0 >= y_in) & (t0 <= y_out), t0, side);
    hit_offer4(&best, &part, spans & real & (t1 >= y_in) & (t1 <= y_out), t1, side);
    if (d->capped) {
        quad_f64 t_base = quad_select(up, y_in, y_out);
        hit_offer4(&best, &part, spans & inside_at4(real, a, t0, t1, t_base), t_base, side + 1);
    }
    if (d->top_capped && d->top_radius > 0) {
        quad_f64 t_top = quad_select(up, y_out, y_in);
        hit_offer4(&best, &part, spans & inside_at4(real, a, t0, t1, t_top), t_top, side + 2);
    }
    quad_mask alone = (a == quad_splat(0)) | (b == quad_splat(0));
    return hits4_end(s, r, first, tmax, alone, spans & (best < tmax), best, part, hit);
}

/* Side: u is the angle about the axis (see polar_u), v the height from 0 at
 * the base to 1 at the apex. Cap: see disc_uv. */
static void cone_surface(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 l = v3_sub(out->p_obj, d->center);
    if (part > 0) {
        out->n = v3(0, part == 1 ? -1 : 1, 0);
        return;
    }
    /* grad F = 2 (x, k^2 (H - y), z), and on the surface k (H - y) = r, so
     * it is parallel to (x / r, k, z / r). The apex has no gradient. */
    double r = sqrt(l.x * l.x + l.z * l.z);
    out->n = r > 0 ? v3(l.x / r, (d->radius - d->top_radius) / d->height, l.z / r) : v3(0, 1, 0);
}

static void cone_uv(const shape *s, int part, surface *out)
{
    const glint_shape *d = &s->desc;
    vec3 l = v3_sub(out->p_obj, d->center);
    if (part > 0) {
        disc_uv(l, part == 1 ? d->radius : d->top_radius, out);
        return;
    }
    out->u = polar_u(l.x, l.z);
    out->v = l.y / d->height;
}

static void cone_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    glint_shape widest = s->desc;
    widest.radius = fmax(widest.radius, widest.top_radius);
    axial_bounds(&widest, lo, hi);
}

static glint_status cone_init(shape *s, glint_error *err)
{
    const glint_shape *d = &s->desc;
    if (d->top_radius == d->radius)
        return error_set(err, GLINT_ERR_INVALID, "cone top_radius must differ from its radius %g (one radius all "
                         "the way up is a cylinder)", d->radius);
    return GLINT_OK;
}

static const param CONE_PARAMS[] = {
    AXIAL_PARAMS,
    {.key = "capped", .type = PARAM_BOOL, .offset = offsetof(glint_shape, capped), .def = {1},
     .meaning = "whether it has the base cap"},
    {.key = "top_radius", .type = PARAM_NUMBER, .offset = offsetof(glint_shape, top_radius), .lo = 0,
     .hi = DBL_MAX, .meaning = "the radius at the top: 0 for a point, more for a cone cut off there (a frustum), not radius"},
    {.key = "top_capped", .type = PARAM_BOOL, .offset = offsetof(glint_shape, top_capped), .def = {1},
     .meaning = "whether a cut-off cone has the top cap"},
};

/* The side, then the caps it has, by area. The side's radius grows
 * linearly along it, so its points are uniform by area when the radius
 * squared is uniform between the ends': radius t r, t^2 uniform between
 * 1 and (top / r)^2 (from 0 for a pointed cone). */
static double cone_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n)
{
    const glint_shape *d = &s->desc;
    double r = d->radius, top = d->top_radius, h = d->height, drop = r - top;
    double slant = sqrt(drop * drop + h * h), total, q = (top / r) * (top / r);
    double area[3] = {M_PI * (r + top) * slant, d->capped ? M_PI * r * r : 0,
                      d->top_capped ? M_PI * top * top : 0};
    int part = pick_by_area(area, 3, &u1, &total);
    double phi = 2 * M_PI * u2, c = cos(phi), sn = sin(phi);
    if (part == 0) {
        double t = sqrt(u1 + (1 - u1) * q);
        *n = v3_scale(v3(h * c, drop, h * sn), 1 / slant);
        /* The height where the radius is t r: (1 - t) of the apex's. */
        *p = v3_add(d->center, v3(t * r * c, (1 - t) * (h * (r / drop)), t * r * sn));
    } else {
        double rim = part == 1 ? r : top, t = sqrt(u1);
        *n = v3(0, part == 1 ? -1 : 1, 0);
        *p = v3_add(d->center, v3(t * rim * c, part == 1 ? 0 : h, t * rim * sn));
    }
    return total;
}

/* Closed by its base cap, and a cut-off cone by its top cap too. */
static bool cone_closed(const shape *s) { return s->desc.capped && (s->desc.top_radius == 0 || s->desc.top_capped); }

const shape_kind cone_kind = {
    .closed = cone_closed,
    .name = "cone", .id = GLINT_SHAPE_CONE, .params = PARAM_TABLE(CONE_PARAMS), .max_crossings = 2,
    .init = cone_init, .intersect = cone_intersect, .intersect4 = cone_intersect4, .surface = cone_surface, .uv = cone_uv,
    .bounds = cone_bounds, .sample = cone_sample,
};
