/* shape_math.h - the arithmetic several shape kinds share: offering
 * candidate hits, quadratic roots, slabs, and the texture coordinates of
 * discs, planes and angles about an axis. */
#ifndef GLINT_GEOMETRY_SHAPE_MATH_H
#define GLINT_GEOMETRY_SHAPE_MATH_H

#include <math.h>
#include <stdbool.h>
#include "geometry/shape_kind.h"

/* Candidate hits are offered one by one to best, which starts as {tmax, 0}
 * and keeps the nearest in (tmin, tmax); the first offered wins a tie. */
static inline void hit_offer(shape_hit *best, double tmin, double t, int part)
{
    if (t > tmin && t < best->t) {
        best->t = t;
        best->part = part;
    }
}

static inline bool hit_take(const shape_hit *best, double tmax, shape_hit *hit)
{
    if (!(best->t < tmax))
        return false;
    *hit = *best;
    return true;
}

/* intersect's answer from a convex kind's span: its ends offered in turn. */
static inline bool span_hit(const shape_span *span, double tmin, double tmax, shape_hit *hit)
{
    shape_hit best = {.t = tmax};
    hit_offer(&best, tmin, span->t_in, span->part_in);
    hit_offer(&best, tmin, span->t_out, span->part_out);
    return hit_take(&best, tmax, hit);
}

static inline vec3 min3(vec3 a, vec3 b) { return v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
static inline vec3 max3(vec3 a, vec3 b) { return v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }

static inline bool within(double t, double lo, double hi) { return t >= lo && t <= hi; }

/* Which of n parts of areas area[0..n) the sample *u in [0, 1) falls in,
 * each chosen in proportion to its area, *u stretched back over [0, 1)
 * within it, so that strata of u stay strata; *total gets the sum. */
int pick_by_area(const double *area, int n, double *u, double *total);

/* The point of triangle (a, b, c) for (u1, u2) in [0, 1)^2, uniform by area. */
vec3 triangle_point(vec3 a, vec3 b, vec3 c, double u1, double u2);

/* The real roots t0 <= t1 of a t^2 + b t + c = 0, in the form that avoids
 * cancellation between b and the square root. A double root counts, so a
 * ray tangent to a surface hits it. With a == 0 (a ray parallel to a cone's
 * slant) the one linear root is returned twice. */
static inline bool quadratic(double a, double b, double c, double *t0, double *t1)
{
    if (a == 0) {
        if (b == 0)
            return false;
        *t0 = *t1 = -c / b;
        return true;
    }
    double disc = b * b - 4 * a * c;
    if (disc < 0)
        return false;
    double q = -0.5 * (b + copysign(sqrt(disc), b));
    if (q == 0) {
        /* b and the discriminant are both zero, so c is too. */
        *t0 = *t1 = 0;
        return true;
    }
    /* Neither root is NaN (a and q are not zero, the inputs finite) and at
     * most one is zero, so comparisons give fmin's and fmax's results
     * without their library calls. */
    double r0 = q / a, r1 = c / q;
    *t0 = r1 < r0 ? r1 : r0;
    *t1 = r1 < r0 ? r0 : r1;
    return true;
}

/* quadratic in four lanes, for a != 0: the mask of the lanes with real
 * roots that are not both zero, and there *t0 <= *t1, each lane the bits
 * quadratic gives. Elsewhere the roots are NaN or meaningless. */
static inline quad_mask quadratic4(quad_f64 a, quad_f64 b, quad_f64 c, quad_f64 *t0, quad_f64 *t1)
{
    quad_f64 disc = b * b - quad_splat(4) * a * c;
    /* copysign(sqrt(disc), b): the root's magnitude with b's sign bit. */
    quad_mask sign = (quad_mask)quad_splat(-0.0);
    quad_f64 root = quad_sqrt(disc);
    quad_f64 signed_root = (quad_f64)(((quad_mask)root & ~sign) | ((quad_mask)b & sign));
    quad_f64 q = quad_splat(-0.5) * (b + signed_root);
    quad_f64 r0 = q / a, r1 = c / q;
    quad_mask swap = r1 < r0;
    *t0 = quad_select(swap, r1, r0);
    *t1 = quad_select(swap, r0, r1);
    return (disc >= 0) & (q != 0);
}

/* The interval of t over which o + t d lies in [lo, hi] along one axis. A
 * ray parallel to the axis is inside for all t or for none; the infinite
 * ends that gives are safe to offer as hits, as hit_offer refuses them. */
static inline bool slab(double o, double d, double lo, double hi, double *t_in, double *t_out)
{
    if (d == 0) {
        *t_in = -INFINITY;
        *t_out = INFINITY;
        return o >= lo && o <= hi;
    }
    /* Neither is NaN (d is not zero, the inputs finite): comparisons give
     * fmin's and fmax's results without their library calls. */
    double a = (lo - o) / d, b = (hi - o) / d;
    *t_in = b < a ? b : a;
    *t_out = b < a ? a : b;
    return true;
}

/* slab for four lanes: the mask of the lanes it accepts, and there *t_in
 * and *t_out, each lane's bits as slab gives them. */
static inline quad_mask slab4(quad_f64 o, quad_f64 d, double lo, double hi, quad_f64 *t_in, quad_f64 *t_out)
{
    quad_mask level = d == quad_splat(0);
    quad_f64 a = (quad_splat(lo) - o) / d, b = (quad_splat(hi) - o) / d;
    *t_in = quad_select(level, quad_splat(-INFINITY), quad_select(b < a, b, a));
    *t_out = quad_select(level, quad_splat(INFINITY), quad_select(b < a, a, b));
    return ~level | ((o >= quad_splat(lo)) & (o <= quad_splat(hi)));
}

/* hit_offer for four lanes with tmin 0: the lanes `offered` take t and
 * part where t lies in (0, *best_t). */
static inline void hit_offer4(quad_f64 *best_t, quad_mask *best_part, quad_mask offered, quad_f64 t, quad_mask part)
{
    quad_mask take = offered & (t > quad_splat(0)) & (t < *best_t);
    *best_t = quad_select(take, t, *best_t);
    *best_part = quad_mask_select(take, part, *best_part);
}

/* The end of a kind's intersect4 whose arithmetic leaves out the lanes
 * `alone` (a rare case it does not take four lanes at a time): its answer
 * `hits`, with hit->t and hit->part from t and part, but in those lanes
 * the kind's one-lane intersect's (tmin 0). */
static inline quad_mask hits4_end(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_mask alone,
                                  quad_mask hits, quad_f64 t, quad_mask part, quad_hit *hit)
{
    for (int k = 0; k < QUAD; k++) {
        if (alone[k]) {
            ray lane = ray8_get(r, first + k);
            shape_hit one;
            hits[k] = s->kind->intersect(s, &lane, 0, tmax[k], &one) ? -1 : 0;
            t[k] = one.t;
            part[k] = one.part;
        }
        hit->part[k] = (int)part[k];
    }
    hit->t = t;
    return hits;
}

/* The angle about +y as u in [0, 1]: 0.5 towards +z, 0.75 towards +x, and
 * the seam where 0 meets 1 towards -z. */
static inline double polar_u(double x, double z) { return 0.5 + atan2(x, z) / (2 * M_PI); }

/* The (u, v) of unit direction d: u the angle about +y (polar_u), v from 0
 * at the north (+y) pole to 1 at the south pole. Spheres and the spherical
 * texture mapping share it. */
static inline void spherical_uv(vec3 d, double *u, double *v)
{
    *u = polar_u(d.x, d.z);
    /* Rounding can push |d.y| a hair past 1, where asin is NaN. */
    *v = 0.5 - asin(fmax(-1.0, fmin(1.0, d.y))) / M_PI;
}

/* Texture coordinates on a disc about the y axis: the disc's square of
 * side 2 * radius mapped to [0, 1]^2, u along +x, v along +z. */
static inline void disc_uv(vec3 local, double radius, surface *out)
{
    out->u = 0.5 + local.x / (2 * radius);
    out->v = 0.5 + local.z / (2 * radius);
}

/* The parameters cylinders and cones share: base centre, radius, height. */
#define AXIAL_PARAMS                                                                                          \
    {.key = "center", .type = PARAM_VEC3, .offset = offsetof(glint_shape, center),                          \
     .meaning = "the centre of the base"},                                                                   \
    {.key = "radius", .type = PARAM_NUMBER, .offset = offsetof(glint_shape, radius), .required = true,      \
     PARAM_POSITIVE, .meaning = "the radius of the base"},                                                   \
    {.key = "height", .type = PARAM_NUMBER, .offset = offsetof(glint_shape, height), .required = true,      \
     PARAM_POSITIVE, .meaning = "the height along +y"}

/* Bounds of a shape standing on its base centre: radius about the y axis,
 * height up. */
static inline void axial_bounds(const glint_shape *d, vec3 *lo, vec3 *hi)
{
    *lo = v3_add(d->center, v3(-d->radius, 0, -d->radius));
    *hi = v3_add(d->center, v3(d->radius, d->height, d->radius));
}

#endif
