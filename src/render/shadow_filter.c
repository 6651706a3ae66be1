/* shadow_filter.c - what one surface crossing passes to a shadow ray:
 * every crossing filters, on the way into a thing and on the way out, as a
 * camera ray through it is filtered at both surfaces (the integrator's
 * branches), so a glass ball's shadow is as dark as the ball looks against
 * the sky. Inside an absorbing thing, the segment from where the ray goes
 * in (or starts) to where it comes out absorbs: its optical depth is the
 * exit's distance less the entry's, so the exit adds the depth of its
 * distance and the entry takes away the depth of its own. Only a textured
 * or absorbing surface needs its point described. */
#include "render/hit.h"
#include "render/integrator.h"
#include "render/shadow_filter.h"

color shadow_filter(void *user, const ray *r, const accel_hit *hit, color *depth)
{
    const glint_scene *scene = ((tracer *)user)->scene;
    const glint_material *m = hit_material(scene, hit);
    if (material_is_opaque(m))
        return rgb(0, 0, 0);
    color base = m->color;
    if (m->texture >= 0 || material_absorbs(m)) {
        accel_hit h = *hit;
        surface s;
        hit_surface(scene, r, &h, &s);
        if (m->texture >= 0)
            base = hit_color(scene, &h, m, &s, r->d, 0);
        if (material_absorbs(m)) {
            color d = material_optical_depth(m, h.t);
            *depth = rgb_madd(*depth, d, v3_dot(r->d, s.n) > 0 ? 1 : -1);
        }
    }
    return rgb_scale(material_filter(m, base), m->transparency + m->refraction);
}
