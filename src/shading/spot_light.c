/* spot_light.c - a light at a point shining into a cone, with an optional
 * soft edge inside it: a delta light (light.h) with a cone. */
#include <math.h>
#include <stddef.h>
#include "core/error.h"
#include "shading/light.h"

static glint_status spot_init(light *l, glint_error *err)
{
    const glint_light *d = &l->desc;
    if (d->falloff_angle > d->cone_angle)
        return error_set(err, GLINT_ERR_INVALID, "spot light falloff must not exceed its angle %g, got %g",
                         d->cone_angle, d->falloff_angle);
    l->cos_outer = cos(d->cone_angle * M_PI / 180);
    l->cos_inner = cos((d->cone_angle - d->falloff_angle) * M_PI / 180);
    l->dir = v3_normalize(d->direction);
    l->has_cone = true;
    return GLINT_OK;
}

static const param SPOT_PARAMS[] = {
    {.key = "position", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.position), .required = true,
     .meaning = "where the light is"},
    {.key = "direction", .type = PARAM_DIRECTION, .offset = offsetof(light_spec, light.direction),
     .required = true, .meaning = "where the cone's axis points"},
    LIGHT_COLOR_PARAMS,
    LIGHT_FALLOFF_PARAMS,
    {.key = "angle", .type = PARAM_NUMBER, .offset = offsetof(light_spec, light.cone_angle), .required = true,
     .lo = 0, .hi = 90, .bounds = PARAM_OPEN_LOW, .unit = "degrees", .meaning = "half-angle of the cone"},
    {.key = "falloff", .type = PARAM_NUMBER, .offset = offsetof(light_spec, light.falloff_angle), .lo = 0,
     .hi = 90, .unit = "degrees", .meaning = "width of the soft edge inside the cone, at most angle; 0 is hard"},
};

const light_kind spot_light = {
    .name = "spot", .id = GLINT_LIGHT_SPOT, .params = PARAM_TABLE(SPOT_PARAMS), .init = spot_init, .delta = true,
    .sample = light_delta_sample_fn,
};
