/* point_light.c - a light at a point, shining every way alike. */
#include <stddef.h>
#include "shading/light.h"

static bool point_sample(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    vec3 d = v3_sub(l->desc.position, p);
    out->distance = v3_length(d);
    if (out->distance == 0)
        return false;
    out->to_light = v3_scale(d, 1.0 / out->distance);
    out->radiance = l->desc.color;
    out->pdf = 1;
    return true;
}

static const param POINT_PARAMS[] = {
    {.key = "position", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.position), .required = true,
     .meaning = "where the light is"},
    LIGHT_COLOR_PARAMS,
};

const light_kind point_light = {
    .name = "point", .id = GLINT_LIGHT_POINT, .params = PARAM_TABLE(POINT_PARAMS), .sample = point_sample,
};
