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

static color surface_color(const glint_scene *scene, const shape *sh, const glint_material *m, surface *s)
{
    if (m->texture < 0)
        return m->color;
    const texture *t = &scene->textures[m->texture];
    if (t->mapping.kind == GLINT_MAP_UV)
        shape_surface_uv(sh, s);
    return texture_eval(t, s);
}

/* What one surface crossing passes to a shadow ray. A closed shape filters
 * once, where the ray enters it. */
static color shadow_filter(void *user, int index, const ray *r, const shape_hit *hit)
{
    const glint_scene *scene = ((tracer *)user)->scene;
    const shape *sh = &scene->shapes[index];
    const glint_material *m = &scene->materials[sh->material].m;
    double amount = m->transparency + m->refraction;
    if (amount <= 0)
        return rgb(0, 0, 0);
    surface s;
    shape_surface(sh, r, hit, &s);
    if (shape_is_closed(sh) && v3_dot(r->d, s.n) > 0)
        return rgb(1, 1, 1);
    return rgb_scale(material_filter(m, surface_color(scene, sh, m, &s)), amount);
}

static color direct_light(tracer *t, const glint_material *m, color base, vec3 p, vec3 n, vec3 to_eye)
{
    const glint_scene *scene = t->scene;
    color out = rgb_scale(rgb_mul(base, scene->settings.ambient_light), m->ambient);
    vec3 origin = offset_point(p, n);
    for (int i = 0; i < scene->light_count; i++) {
        light_sample ls;
        if (!light_illuminate(&scene->lights[i], p, &ls) || v3_dot(n, ls.to_light) <= 0)
            continue;
        ray shadow = {origin, ls.to_light};
        t->rays++;
        color through = accel_transmission(t->acc, &shadow, 0, ls.distance, shadow_filter, t);
        if (rgb_max(through) > 0)
            out = rgb_add(out, phong_light(m, base, n, ls.to_light, to_eye, rgb_mul(ls.radiance, through)));
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
    int index;
    shape_hit hit;
    t->rays++;
    if (!accel_intersect(t->acc, r, 0, INFINITY, &index, &hit))
        return fog_apply(&scene->fog, scene->settings.background, INFINITY);

    const shape *sh = &scene->shapes[index];
    const glint_material *m = &scene->materials[sh->material].m;
    surface s;
    shape_surface(sh, r, &hit, &s);
    bool front = v3_dot(r->d, s.n) < 0;
    vec3 n = front ? s.n : v3_neg(s.n);
    color base = surface_color(scene, sh, m, &s);
    double transmitted = m->transparency + m->refraction;
    color out = rgb_scale(direct_light(t, m, base, s.p, n, v3_neg(r->d)), 1 - transmitted);

    if (depth < scene->settings.max_depth) {
        double mirror = m->reflectivity;
        color filter = material_filter(m, base);
        if (m->transparency > 0)
            out = rgb_add(out, rgb_scale(rgb_mul(filter, trace_from(t, s.p, n, r->d, depth + 1)), m->transparency));
        if (m->refraction > 0) {
            double eta = front ? 1.0 / m->ior : m->ior;
            double share = 1;
            vec3 dir;
            if (!optics_refract(r->d, n, eta, &dir))
                share = 0;
            else if (m->fresnel)
                share = 1 - optics_fresnel(-v3_dot(r->d, n), eta);
            if (share > 0) {
                color refracted = trace_from(t, s.p, n, dir, depth + 1);
                out = rgb_add(out, rgb_scale(rgb_mul(filter, refracted), m->refraction * share));
            }
            mirror += m->refraction * (1 - share);
        }
        if (mirror > 0)
            out = rgb_madd(out, trace_from(t, s.p, n, optics_reflect(r->d, n), depth + 1), mirror);
    }
    return fog_apply(&scene->fog, out, hit.t);
}
