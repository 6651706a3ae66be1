/* surface_detail.c - bump maps and tangent-space normal maps: a hit's
 * shading normal tilted by the slope of a texture's heights, or replaced by
 * a texture's normals in the frame of the surface's (u, v).
 *
 * Both need to know how the texture coordinates change across the surface.
 * Rather than every kind of shape giving its derivatives, they are measured:
 * the coordinates of two points a small step either way along two tangent
 * directions (a mesh triangle's uv carried on affinely, a shape's own uv
 * or any mapping of the point) give the gradients of u and of v in the
 * tangent plane, and from those the directions in which u and v grow. */
#include <math.h>
#include "render/surface_detail.h"
#include "render/hit.h"

/* Where on what the hit is: enough to find the texture coordinates of
 * points near it. */
typedef struct spot {
    const glint_scene *scene;
    const shape *sh;          /* the shape hit, as it is at the hit's time; NULL for a mesh */
    const mesh *me;
    unsigned triangle;
    const transform *to_object; /* NULL: object space is world space */
    vec3 center;              /* the thing's centre, for mappings */
    const surface *s;
} spot;

/* World point q in the thing's own coordinates. */
static vec3 object_point(const spot *at, vec3 q)
{
    return at->to_object ? xf_point(at->to_object, q) : q;
}

/* The texture coordinates t looks up at world point q near the hit: its
 * mapping's, carried into its own space. */
static void coords(const spot *at, const texture *t, vec3 q, double *u, double *v)
{
    surface near = *at->s;
    near.p_obj = object_point(at, q);
    if (t->mapping.kind == GLINT_MAP_UV) {
        if (at->sh)
            shape_surface_uv(at->sh, &near);
        else
            mesh_uv_at(at->me, at->triangle, near.p_obj, &near.u, &near.v);
    }
    double mu, mv;
    mapping_apply(&t->mapping, &near, at->center, &mu, &mv);
    vec3 placed = texture_place(t, v3(mu, mv, 0));
    *u = placed.x;
    *v = placed.y;
}

/* t's value at texture coordinates (u, v): an image's texels as data. */
static color lookup(const texture *t, double u, double v)
{
    if (t->kind != &image_texture)
        return t->kind->eval(t, u, v);
    texture_image data = texture_image_as_data(&t->image);
    return image_eval(&data, u, v, t->desc.wrap_u, t->desc.wrap_v);
}

static double brightness(color c) { return (c.r + c.g + c.b) / 3; }

/* Two unit tangents, at right angles, across unit normal n. */
static void tangents(vec3 n, vec3 *t1, vec3 *t2)
{
    vec3 other = fabs(n.x) < 0.6 ? v3(1, 0, 0) : v3(0, 1, 0);
    *t1 = v3_normalize(v3_cross(n, other));
    *t2 = v3_cross(n, *t1);
}

/* The step the differences take along the surface: small against the
 * point's distance from the origin, as offset_point's is. */
static double step_at(vec3 p)
{
    double scale = fmax(fmax(fabs(p.x), fabs(p.y)), fmax(fabs(p.z), 1.0));
    return 1e-6 * scale;
}

/* A difference of coordinates across a step, unwrapped where it crossed a
 * seam (a sphere's u from 0.999 to 0.001). */
static double unwrapped(double d) { return d > 0.5 ? d - 1 : d < -0.5 ? d + 1 : d; }

/* The world gradients of u and of v at the hit: g_u . d is how much u
 * grows along a short step d in the tangent plane. */
static void coord_gradients(const spot *at, const texture *t, vec3 n, vec3 *g_u, vec3 *g_v)
{
    vec3 t1, t2, p = at->s->p;
    tangents(n, &t1, &t2);
    double e = step_at(p), du[2], dv[2];
    vec3 dirs[2] = {t1, t2};
    for (int k = 0; k < 2; k++) {
        double u0, v0, u1, v1;
        coords(at, t, v3_madd(p, dirs[k], -e), &u0, &v0);
        coords(at, t, v3_madd(p, dirs[k], e), &u1, &v1);
        du[k] = unwrapped(u1 - u0) / (2 * e);
        dv[k] = unwrapped(v1 - v0) / (2 * e);
    }
    *g_u = v3_add(v3_scale(t1, du[0]), v3_scale(t2, du[1]));
    *g_v = v3_add(v3_scale(t1, dv[0]), v3_scale(t2, dv[1]));
}

/* The world gradient of the bump texture's height at the hit. */
static vec3 height_gradient(const spot *at, const texture *t, vec3 n)
{
    vec3 p = at->s->p;
    if (t->kind->solid) {
        vec3 t1, t2, g = v3(0, 0, 0);
        tangents(n, &t1, &t2);
        vec3 dirs[2] = {t1, t2};
        double e = step_at(p);
        for (int k = 0; k < 2; k++) {
            double below = brightness(t->kind->solid(t, texture_place(t, object_point(at, v3_madd(p, dirs[k], -e)))));
            double above = brightness(t->kind->solid(t, texture_place(t, object_point(at, v3_madd(p, dirs[k], e)))));
            g = v3_madd(g, dirs[k], (above - below) / (2 * e));
        }
        return g;
    }
    double u, v;
    coords(at, t, p, &u, &v);
    /* Differences over a texel of an image, or a small step of a pattern. */
    double hu = t->kind == &image_texture ? 1.0 / t->image.width : 1e-4;
    double hv = t->kind == &image_texture ? 1.0 / t->image.height : 1e-4;
    double slope_u = (brightness(lookup(t, u + hu, v)) - brightness(lookup(t, u - hu, v))) / (2 * hu);
    double slope_v = (brightness(lookup(t, u, v + hv)) - brightness(lookup(t, u, v - hv))) / (2 * hv);
    vec3 g_u, g_v;
    coord_gradients(at, t, n, &g_u, &g_v);
    return v3_add(v3_scale(g_u, slope_u), v3_scale(g_v, slope_v));
}

/* The shading normal a tangent-space normal map gives at the hit, or n
 * where the surface's (u, v) do not span it. */
static vec3 mapped_normal(const spot *at, const texture *t, vec3 n)
{
    vec3 g_u, g_v;
    coord_gradients(at, t, n, &g_u, &g_v);
    /* The directions along which u and v grow are the dual basis of their
     * gradients: d(p)/du . g_u = 1 and d(p)/du . g_v = 0. */
    double a = v3_dot(g_u, g_u), b = v3_dot(g_u, g_v), c = v3_dot(g_v, g_v), det = a * c - b * b;
    if (!(det > 0))
        return n;
    vec3 along_u = v3_scale(v3_sub(v3_scale(g_u, c), v3_scale(g_v, b)), 1 / det);
    vec3 along_v = v3_scale(v3_sub(v3_scale(g_v, a), v3_scale(g_u, b)), 1 / det);
    vec3 tu = v3_normalize(v3_madd(along_u, n, -v3_dot(n, along_u)));
    /* Green points to the image's top, where v is 0: against v. */
    vec3 up = v3_neg(along_v);
    up = v3_normalize(v3_madd(v3_madd(up, n, -v3_dot(n, up)), tu, -v3_dot(tu, up)));
    double u, v;
    coords(at, t, at->s->p, &u, &v);
    color texel = lookup(t, u, v);
    vec3 tilted = v3_add(v3_add(v3_scale(tu, 2 * texel.r - 1), v3_scale(up, 2 * texel.g - 1)),
                         v3_scale(n, 2 * texel.b - 1));
    return v3_normalize(tilted);
}

void surface_detail(const glint_scene *scene, const accel_hit *h, const glint_material *m, vec3 d, surface *s)
{
    spot at = {.scene = scene, .s = s};
    shape moved_shape;
    instance moved_instance;
    if (h->shape >= 0) {
        at.sh = shape_at(&scene->shapes[h->shape], h->time, &moved_shape);
        at.to_object = at.sh->has_transform ? &at.sh->to_object : NULL;
        at.center = shape_center(at.sh);
    } else {
        const instance *inst = instance_at(&scene->instances[h->instance], h->time, &moved_instance);
        at.me = hit_mesh(scene, h);
        at.triangle = h->triangle;
        at.to_object = inst->has_transform ? &inst->to_object : NULL;
        at.center = mesh_center(at.me);
    }
    /* The relief rises towards whoever sees it, from either side. */
    double side = v3_dot(d, s->n) < 0 ? 1 : -1;
    vec3 n = v3_scale(s->shading_n, side);
    if (m->normal_texture >= 0)
        n = mapped_normal(&at, &scene->textures[m->normal_texture], n);
    if (m->bump_texture >= 0) {
        vec3 g = height_gradient(&at, &scene->textures[m->bump_texture], n);
        n = v3_normalize(v3_madd(n, v3_madd(g, n, -v3_dot(g, n)), -m->bump_strength));
    }
    /* A normal tilted past the surface would light its back: keep the one
     * it had. */
    if (isfinite(n.x) && isfinite(n.y) && isfinite(n.z) && v3_dot(n, s->n) * side > 0)
        s->shading_n = v3_scale(n, side);
}
