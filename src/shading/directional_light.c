/* directional_light.c - light from infinitely far away, all of it
 * travelling one way (the sun): a delta light (light.h) at infinity. */
#include <stddef.h>
#include "shading/light.h"

static glint_status directional_init(light *l, glint_error *err)
{
    l->dir = v3_normalize(l->desc.direction);
    l->at_infinity = true;
    return GLINT_OK;
}

static const param DIRECTIONAL_PARAMS[] = {
    {.key = "direction", .type = PARAM_DIRECTION, .offset = offsetof(light_spec, light.direction),
     .required = true, .meaning = "where the light travels"},
    LIGHT_COLOR_PARAMS,
};

const light_kind directional_light = {
    .name = "directional", .id = GLINT_LIGHT_DIRECTIONAL, .params = PARAM_TABLE(DIRECTIONAL_PARAMS),
    .init = directional_init, .delta = true, .sample = light_delta_sample_fn,
};
