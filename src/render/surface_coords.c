/* surface_coords.c - texture coordinates near a hit, measured by small
 * steps across the surface (surface_coords.h says why). */
#include <math.h>
#include "render/surface_coords.h"
#include "render/hit.h"

void coord_spot_init(const glint_scene *scene, const accel_hit *h, const surface *s, coord_spot *at)
{
    at->s = s;
    at->sh = NULL;
    at->me = NULL;
    at->triangle = 0;
    if (h->shape >= 0) {
        at->sh = shape_at(&scene->shapes[h->shape], h->time, &at->moved_shape);
        at->to_object = at->sh->has_transform ? &at->sh->to_object : NULL;
        at->center = shape_center(at->sh, s->part);
    } else {
        const instance *inst = instance_at(&scene->instances[h->instance], h->time, &at->moved_instance);
        at->me = hit_mesh(scene, h);
        at->triangle = h->triangle;
        at->to_object = inst->has_transform ? &inst->to_object : NULL;
        at->center = mesh_center(at->me);
    }
}

vec3 coord_object_point(const coord_spot *at, vec3 q)
{
    return at->to_object ? xf_point(at->to_object, q) : q;
}

void coord_at(const coord_spot *at, const texture *t, vec3 q, double *u, double *v)
{
    surface near = *at->s;
    near.p_obj = coord_object_point(at, q);
    if (t->mapping.kind == GLINT_MAP_UV) {
        if (at->sh)
            shape_surface_uv(at->sh, &near);
        else
            mesh_uv_at(at->me, at->triangle, near.p_obj, &near.u, &near.v);
    }
    texture_uv(t, &near, at->center, u, v);
}

void coord_tangents(vec3 n, vec3 *t1, vec3 *t2)
{
    vec3 other = fabs(n.x) < 0.6 ? v3(1, 0, 0) : v3(0, 1, 0);
    *t1 = v3_normalize(v3_cross(n, other));
    *t2 = v3_cross(n, *t1);
}

double coord_step(vec3 p)
{
    double scale = fmax(fmax(fabs(p.x), fabs(p.y)), fmax(fabs(p.z), 1.0));
    return 1e-6 * scale;
}

/* A difference of coordinates across a step, unwrapped where it crossed a
 * seam (a sphere's u from 0.999 to 0.001). */
static double unwrapped(double d) { return d > 0.5 ? d - 1 : d < -0.5 ? d + 1 : d; }

void coord_gradients(const coord_spot *at, const texture *t, vec3 n, vec3 *g_u, vec3 *g_v)
{
    vec3 t1, t2, p = at->s->p;
    coord_tangents(n, &t1, &t2);
    double e = coord_step(p), du[2], dv[2];
    vec3 dirs[2] = {t1, t2};
    for (int k = 0; k < 2; k++) {
        double u0, v0, u1, v1;
        coord_at(at, t, v3_madd(p, dirs[k], -e), &u0, &v0);
        coord_at(at, t, v3_madd(p, dirs[k], e), &u1, &v1);
        du[k] = unwrapped(u1 - u0) / (2 * e);
        dv[k] = unwrapped(v1 - v0) / (2 * e);
    }
    *g_u = v3_add(v3_scale(t1, du[0]), v3_scale(t2, du[1]));
    *g_v = v3_add(v3_scale(t1, dv[0]), v3_scale(t2, dv[1]));
}

/* How far a linear function of gradient g reaches over the footprint,
 * squared: a point q of the disc square to d lands on the surface at
 * q - d (q . n) / (d . n), where g gives q . h, h = g - n (g . d) / (d . n);
 * the most that reaches over a disc of radius 1 is the length of h's part
 * square to d. No normalised axes, so no square root. */
static double linear_reach2(vec3 g, vec3 n, vec3 d, double inv_cos)
{
    vec3 h = v3_madd(g, n, -v3_dot(g, d) * inv_cos);
    vec3 square = v3_madd(h, d, -v3_dot(h, d));
    return v3_dot(square, square);
}

uv_extent coord_footprint(const coord_spot *at, const texture *t, vec3 n, vec3 d, double width, double u,
                          double v)
{
    vec3 g_u, g_v;
    if (mapping_gradients(t, at->s->p_obj, at->center, &g_u, &g_v)) {
        /* The mapping's gradients at the hit (a planar mapping's are its
         * linear map's), carried to the world as normals are. */
        if (at->to_object) {
            g_u = xf_normal(at->to_object, g_u);
            g_v = xf_normal(at->to_object, g_v);
        }
        /* A ray nearly along the surface stretches the footprint a million
         * times at most. */
        double cos_t = v3_dot(d, n);
        double inv_cos = 1 / (fabs(cos_t) > 1e-6 ? cos_t : copysign(1e-6, cos_t));
        double width2 = width * width;
        return (uv_extent){width2 * linear_reach2(g_u, n, d, inv_cos), width2 * linear_reach2(g_v, n, d, inv_cos)};
    }
    /* The ellipse's axes: `width` across the ray's slant, and stretched by
     * 1 / cos along it; a ray nearly square to the surface has no slant. */
    vec3 across, along, p = at->s->p;
    double cos_t = fabs(v3_dot(d, n));
    vec3 slant = v3_madd(d, n, -v3_dot(d, n));
    if (v3_dot(slant, slant) < 1e-12) {
        coord_tangents(n, &across, &along);
    } else {
        along = v3_normalize(slant);
        across = v3_cross(n, along);
    }
    /* One step along each axis from the hit, whose coordinates are known,
     * gives how u and v change along it: a level needs no more precision,
     * and each step is a mapping (often trigonometry) of its own. */
    double stretch = width / fmax(cos_t, 1e-6), e = coord_step(p), u1, v1, u2, v2;
    coord_at(at, t, v3_madd(p, across, e), &u1, &v1);
    coord_at(at, t, v3_madd(p, along, e), &u2, &v2);
    double ua = unwrapped(u1 - u) / e * width, va = unwrapped(v1 - v) / e * width;
    double ub = unwrapped(u2 - u) / e * stretch, vb = unwrapped(v2 - v) / e * stretch;
    /* A linear function over an ellipse of axes a and b spans
     * sqrt((g . a)^2 + (g . b)^2). */
    return (uv_extent){ua * ua + ub * ub, va * va + vb * vb};
}
