/* surface_detail.h - bump maps and tangent-space normal maps: the shading
 * normal tilted by a texture (surface_detail.c says how). */
#ifndef GLINT_RENDER_SURFACE_DETAIL_H
#define GLINT_RENDER_SURFACE_DETAIL_H

#include "accel/accel.h"
#include "scene/scene.h"

/* Whether material m tilts shading normals: it has a bump or normal map. */
static inline bool material_has_detail(const glint_material *m)
{
    return m->bump_texture >= 0 || m->normal_texture >= 0;
}

/* Tilts s->shading_n (hit_surface's, of hit h with material m, seen along
 * direction d) by m's normal map, then its bump map: the normal map's
 * normal in the frame of the surface's (u, v), then moved against the
 * slope of the bump texture's brightness times bump_strength. Either
 * works on the side of the surface d sees, so relief rises towards the
 * viewer from both sides of a sheet. A normal that would face away from
 * s->n is left as it was. */
void surface_detail(const glint_scene *scene, const accel_hit *h, const glint_material *m, vec3 d, surface *s);

#endif
