/* disk_light.c - a glowing disc (a lamp's opening, a round panel): an
 * area light (light.h) lit on the side it faces, sampled uniformly over
 * its area by a mapping from the square that keeps strata together. */
#include <math.h>
#include <stddef.h>
#include "core/square_maps.h"
#include "shading/light.h"

static glint_status disk_light_init(light *l, glint_error *err)
{
    glint_shape disc = glint_shape_default(GLINT_SHAPE_DISK);
    disc.center = l->desc.position;
    disc.normal = l->desc.direction;
    disc.radius = l->desc.radius;
    glint_status s = light_area_init(l, &disc, M_PI * disc.radius * disc.radius, err);
    l->normal = l->glow.desc.normal;
    return s;
}

static void disk_light_surface(const light *l, double u1, double u2, surface_point *out)
{
    double x, y, r = l->desc.radius;
    concentric_disk(u1, u2, &x, &y);
    const shape *g = &l->glow;
    light_area_point(l, v3_add(g->desc.center, v3_add(v3_scale(g->plane_u, r * x), v3_scale(g->plane_v, r * y))), out);
}

static const param DISK_LIGHT_PARAMS[] = {
    {.key = "position", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.position), .required = true,
     .meaning = "the disc's centre"},
    {.key = "direction", .type = PARAM_DIRECTION, .offset = offsetof(light_spec, light.direction),
     .required = true, .meaning = "the side it faces and glows towards"},
    {.key = "radius", .type = PARAM_NUMBER, .offset = offsetof(light_spec, light.radius), .required = true,
     PARAM_POSITIVE, .meaning = "the disc's radius"},
    AREA_LIGHT_PARAMS,
};

const light_kind disk_light = {
    .name = "disk", .id = GLINT_LIGHT_DISK, .params = PARAM_TABLE(DISK_LIGHT_PARAMS), .init = disk_light_init,
    .one_sided = true, .sample = light_surface_sample, .sample_lanes = light_surface_lanes,
    .surface = disk_light_surface,
};
