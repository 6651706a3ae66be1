/* surface_detail.c - bump maps and tangent-space normal maps: a hit's
 * shading normal tilted by the slope of a texture's heights, or replaced by
 * a texture's normals in the frame of the surface's (u, v), both measured
 * from how the texture coordinates change across the surface
 * (surface_coords.h). */
#include <math.h>
#include "render/surface_detail.h"
#include "render/surface_coords.h"
#include "render/hit.h"

/* t's value at texture coordinates (u, v): an image's texels as data. */
static color lookup(const texture *t, double u, double v)
{
    if (t->kind != &image_texture)
        return t->kind->eval(t, u, v, (uv_extent){0, 0});
    texture_image data = texture_image_as_data(&t->image);
    return image_eval(&data, u, v, t->desc.wrap_u, t->desc.wrap_v);
}

static double brightness(color c) { return (c.r + c.g + c.b) / 3; }

/* The world gradient of the bump texture's height at the hit. */
static vec3 height_gradient(const coord_spot *at, const texture *t, vec3 n)
{
    vec3 p = at->s->p;
    if (t->kind->solid) {
        vec3 t1, t2, g = v3(0, 0, 0);
        coord_tangents(n, &t1, &t2);
        vec3 dirs[2] = {t1, t2};
        double e = coord_step(p);
        /* A step back and a step on along each tangent: four points, read
         * together. */
        vec3 steps[QUAD];
        for (int k = 0; k < 2; k++)
            for (int on = 0; on < 2; on++)
                steps[2 * k + on] = texture_place(t, coord_object_point(at, v3_madd(p, dirs[k], on ? e : -e)));
        color heights[QUAD];
        texture_solid_points(t, steps, QUAD, heights);
        for (int k = 0; k < 2; k++)
            g = v3_madd(g, dirs[k], (brightness(heights[2 * k + 1]) - brightness(heights[2 * k])) / (2 * e));
        return g;
    }
    double u, v;
    coord_at(at, t, p, &u, &v);
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
static vec3 mapped_normal(const coord_spot *at, const texture *t, vec3 n)
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
    coord_at(at, t, at->s->p, &u, &v);
    color texel = lookup(t, u, v);
    vec3 tilted = v3_add(v3_add(v3_scale(tu, 2 * texel.r - 1), v3_scale(up, 2 * texel.g - 1)),
                         v3_scale(n, 2 * texel.b - 1));
    return v3_normalize(tilted);
}

void surface_detail(const glint_scene *scene, const accel_hit *h, const glint_material *m, vec3 d, surface *s)
{
    coord_spot at;
    coord_spot_init(scene, h, s, &at);
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
