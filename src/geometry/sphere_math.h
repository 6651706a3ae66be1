/* sphere_math.h - what sphere shapes (sphere.c) and sphere sets
 * (sphere_set.c and the accelerator's callbacks for them) share, so that a
 * sphere gives the same bits whichever holds it: the exact ray test of a
 * sphere given by its centre and radius (inline: it runs for every
 * candidate), and its normal and (u, v). */
#ifndef GLINT_GEOMETRY_SPHERE_MATH_H
#define GLINT_GEOMETRY_SPHERE_MATH_H

#include "geometry/shape_math.h"

/* Where r's whole line is inside the sphere, (*t_in, *t_out); false when
 * it misses. */
static inline bool sphere_span_at(vec3 center, double radius, const ray *r, double *t_in, double *t_out)
{
    vec3 oc = v3_sub(r->o, center);
    return quadratic(v3_dot(r->d, r->d), 2 * v3_dot(oc, r->d), v3_dot(oc, oc) - radius * radius, t_in, t_out);
}

/* The nearest crossing of r with the sphere in (tmin, tmax), into *hit
 * (part 0). */
static inline bool sphere_hit_at(vec3 center, double radius, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    shape_span span = {0};
    return sphere_span_at(center, radius, r, &span.t_in, &span.t_out) && span_hit(&span, tmin, tmax, hit);
}

/* sphere_hit_at with tmin 0 for the four rays of *r from lane `first` on,
 * lane k with its own tmax[k]: the mask of the lanes that hit, and there
 * *t, each lane the bits sphere_hit_at gives. */
static inline quad_mask sphere_hits4_at(vec3 center, double radius, const ray8 *r, int first, quad_f64 tmax,
                                        quad_f64 *t)
{
    quad_f64 dx = quad_load(r->dx + first), dy = quad_load(r->dy + first), dz = quad_load(r->dz + first);
    quad_f64 ocx = quad_load(r->ox + first) - quad_splat(center.x);
    quad_f64 ocy = quad_load(r->oy + first) - quad_splat(center.y);
    quad_f64 ocz = quad_load(r->oz + first) - quad_splat(center.z);
    quad_f64 a = quad_dot(dx, dy, dz, dx, dy, dz);
    quad_f64 b = quad_splat(2) * quad_dot(ocx, ocy, ocz, dx, dy, dz);
    quad_f64 c = quad_dot(ocx, ocy, ocz, ocx, ocy, ocz) - quad_splat(radius * radius);
    quad_f64 t0, t1;
    quad_mask real = quadratic4(a, b, c, &t0, &t1);
    /* sphere_hit_at's offers with tmin 0: t0 if it lies in (0, tmax), else
     * t1 if that does (t1 < t0 is never true). Roots both zero are refused
     * by either. */
    quad_mask near = (t0 > quad_splat(0)) & (t0 < tmax), far = (t1 > quad_splat(0)) & (t1 < tmax);
    *t = quad_select(near, t0, t1);
    quad_mask hits = real & (near | far);
    /* A zero direction (never from glint's own rays) takes the scalar path. */
    quad_mask flat = a == quad_splat(0);
    for (int k = 0; k < QUAD; k++) {
        if (!flat[k])
            continue;
        ray one = ray8_get(r, first + k);
        shape_hit h = {0};
        hits[k] = sphere_hit_at(center, radius, &one, 0, tmax[k], &h) ? -1 : 0;
        (*t)[k] = h.t;
    }
    return hits;
}

/* The sphere kind's surface and uv (sphere.c): about shape_center(s,
 * part), so that a sphere set's sphere `part` takes them too. */
void sphere_surface(const shape *s, int part, surface *out);
void sphere_uv(const shape *s, int part, surface *out);

#endif
