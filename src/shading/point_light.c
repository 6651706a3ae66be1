/* point_light.c - a light at a point, shining every way alike: a delta
 * light (light.h) with neither cone nor infinity. */
#include <stddef.h>
#include "shading/light.h"

static const param POINT_PARAMS[] = {
    {.key = "position", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.position), .required = true,
     .meaning = "where the light is"},
    LIGHT_COLOR_PARAMS,
    LIGHT_FALLOFF_PARAMS,
};

const light_kind point_light = {
    .name = "point", .id = GLINT_LIGHT_POINT, .params = PARAM_TABLE(POINT_PARAMS), .delta = true,
    .sample = light_delta_sample_fn,
};
