/* directional_light.c - light from infinitely far away, all of it
 * travelling one way: the sun. */
#include <stddef.h>
#include "shading/light.h"

static glint_status directional_init(light *l, glint_error *err)
{
    l->dir = v3_normalize(l->desc.direction);
    return GLINT_OK;
}

static bool directional_sample(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    out->to_light = v3_neg(l->dir);
    out->distance = INFINITY;
    out->radiance = l->desc.color;
    out->pdf = 1;
    return true;
}

static const param DIRECTIONAL_PARAMS[] = {
    {.key = "direction", .type = PARAM_DIRECTION, .offset = offsetof(light_spec, light.direction),
     .required = true, .meaning = "where the light travels"},
    LIGHT_COLOR_PARAMS,
};

const light_kind directional_light = {
    .name = "directional", .id = GLINT_LIGHT_DIRECTIONAL, .params = PARAM_TABLE(DIRECTIONAL_PARAMS),
    .init = directional_init, .sample = directional_sample,
};
