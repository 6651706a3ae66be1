/* integrator.c - Whitted ray tracing: Phong shading with shadows that pass
 * through transparent objects, mirror reflection, straight-through
 * transparency, refraction with optional Fresnel, and fog per segment. */
#include <math.h>
#include "render/integrator.h"
#include "shading/fog.h"
#include "shading/optics.h"

/* New rays start this far off the surface, relative to the scene scale at
 * the point, so they do not hit the surface they leave. */
static vec3 offset_point(vec3 p, vec3 n)
{
    double scale = fmax(1.0, fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
    return v3_madd(p, n, 1e-7 * scale);
}

/* The material hit, whether a shape or a mesh triangle. */
static const glint_material *hit_material(const glint_scene *scene, const accel_hit *h)
{
    if (h->shape >= 0)
        return &scene->materials[scene->shapes[h->shape].material].m;
    const instance *inst = &scene->instances[h->instance];
    return &scene->materials[mesh_material(&scene->meshes[inst->mesh], inst, h->triangle)].m;
}

/* Describes the surface at a hit; for meshes this refines h->t. */
static void hit_surface(const glint_scene *scene, const ray *r, accel_hit *h, surface *s)
{
    if (h->shape >= 0) {
        shape_surface(&scene->shapes[h->shape], r, &h->on_shape, s);
        return;
    }
    const instance *inst = &scene->instances[h->instance];
    mesh_surface(&scene->meshes[inst->mesh], inst, r, h->triangle, h->b1, h->b2, &h->t, s);
}

static color surface_color(const glint_scene *scene, const accel_hit *h, const glint_material *m, surface *s)
{
    if (m->texture < 0)
        return m->color;
    const texture *t = &scene->textures[m->texture];
    /* Meshes carry their uv already; shapes compute it only when asked. */
    if (t->mapping.kind == GLINT_MAP_UV && h->shape >= 0)
        shape_surface_uv(&scene->shapes[h->shape], s);
    return texture_eval(t, s);
}

/* What one surface crossing passes to a shadow ray. A closed shape, and any
 * mesh, filters once, where the ray enters it (through its front). */
static color shadow_filter(void *user, const ray *r, const accel_hit *hit)
{
    const glint_scene *scene = ((tracer *)user)->scene;
    const glint_material *m = hit_material(scene, hit);
    double amount = m->transparency + m->refraction;
    if (amount <= 0)
        return rgb(0, 0, 0);
    accel_hit h = *hit;
    surface s;
    hit_surface(scene, r, &h, &s);
    bool closed = h.shape < 0 || shape_is_closed(&scene->shapes[h.shape]);
    if (closed && v3_dot(r->d, s.n) > 0)
        return rgb(1, 1, 1);
    return rgb_scale(material_filter(m, surface_color(scene, &h, m, &s)), amount);
}

/* Ambient light plus every light that reaches p. n is the geometric normal
 * on the viewer's side, which decides what is in front of the surface; ns
 * the shading normal on the same side. */
static color direct_light(tracer *t, const glint_material *m, color base, vec3 p, vec3 n, vec3 ns, vec3 to_eye)
{
    const glint_scene *scene = t->scene;
    color out = rgb_scale(rgb_mul(base, scene->settings.ambient_light), m->ambient);
    vec3 origin = offset_point(p, n);
    for (int i = 0; i < scene->light_count; i++) {
        light_sample ls;
        if (!light_illuminate(&scene->lights[i], p, &ls) || v3_dot(n, ls.to_light) <= 0 ||
            v3_dot(ns, ls.to_light) <= 0)
            continue;
        ray shadow = {origin, ls.to_light};
        t->rays++;
        color through = accel_transmission(t->acc, &shadow, 0, ls.distance, shadow_filter, t);
        if (rgb_max(through) > 0)
            out = rgb_add(out, phong_light(m, base, ns, ls.to_light, to_eye, rgb_mul(ls.radiance, through)));
    }
    return out;
}

/* Traces a secondary ray leaving p along unit direction d, starting on the
 * side of the surface that d points to. */
static color trace_from(tracer *t, vec3 p, vec3 n, vec3 d, int depth)
{
    ray r = {offset_point(p, v3_dot(d, n) > 0 ? n : v3_neg(n)), d};
    return tracer_trace(t, &r, depth);
}

color tracer_trace(tracer *t, const ray *r, int depth)
{
    const glint_scene *scene = t->scene;
    accel_hit hit;
    t->rays++;
    if (!accel_intersect(t->acc, r, 0, INFINITY, &hit))
        return fog_apply(&scene->fog, scene->settings.background, INFINITY);

    const glint_material *m = hit_material(scene, &hit);
    surface s;
    hit_surface(scene, r, &hit, &s);
    bool front = v3_dot(r->d, s.n) < 0;
    vec3 n = front ? s.n : v3_neg(s.n), ns = front ? s.shading_n : v3_neg(s.shading_n);
    color base = surface_color(scene, &hit, m, &s);
    double transmitted = m->transparency + m->refraction;
    color out = rgb_scale(direct_light(t, m, base, s.p, n, ns, v3_neg(r->d)), 1 - transmitted);

    if (depth < scene->settings.max_depth) {
        double mirror = m->reflectivity;
        /* Rays bend about the shading normal, unless interpolation turned it
         * away from the ray, where only the geometric one makes sense. */
        vec3 bend = v3_dot(r->d, ns) < 0 ? ns : n;
        color filter = material_filter(m, base);
        if (m->transparency > 0)
            out = rgb_add(out, rgb_scale(rgb_mul(filter, trace_from(t, s.p, n, r->d, depth + 1)), m->transparency));
        if (m->refraction > 0) {
            double eta = front ? 1.0 / m->ior : m->ior;
            double share = 1;
            vec3 dir;
            if (!optics_refract(r->d, bend, eta, &dir))
                share = 0;
            else if (m->fresnel)
                share = 1 - optics_fresnel(-v3_dot(r->d, bend), eta);
            if (share > 0) {
                color refracted = trace_from(t, s.p, n, dir, depth + 1);
                out = rgb_add(out, rgb_scale(rgb_mul(filter, refracted), m->refraction * share));
            }
            mirror += m->refraction * (1 - share);
        }
        if (mirror > 0)
            out = rgb_madd(out, trace_from(t, s.p, n, optics_reflect(r->d, bend), depth + 1), mirror);
    }
    return fog_apply(&scene->fog, out, hit.t);
}
