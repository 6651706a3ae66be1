/* spot_light.c - a light at a point shining into a cone, with an optional
 * soft edge inside it. */
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
    return GLINT_OK;
}

double spot_factor(const light *l, double cos_angle)
{
    if (cos_angle < l->cos_outer)
        return 0;
    if (cos_angle >= l->cos_inner)
        return 1;
    double t = (cos_angle - l->cos_outer) / (l->cos_inner - l->cos_outer);
    return t * t * (3 - 2 * t);
}

/* True when p, at d from spotlight l, is clearly outside its cone: most
 * points of a scene are, and this needs no square root or division. The
 * margin leaves every point the exact test might light to that test. */
static bool outside_cone(const light *l, vec3 d)
{
    double along = -v3_dot(d, l->dir); /* |d| times the cosine from the axis */
    if (along < 0)
        return true;
    return along * along < l->cos_outer * l->cos_outer * v3_dot(d, d) * (1 - 1e-9);
}

static bool spot_sample(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    vec3 d = v3_sub(l->desc.position, p);
    if (outside_cone(l, d))
        return false;
    out->distance = v3_length(d);
    if (out->distance == 0)
        return false;
    out->to_light = v3_scale(d, 1.0 / out->distance);
    double factor = spot_factor(l, -v3_dot(out->to_light, l->dir));
    out->radiance = rgb_scale(l->desc.color, factor);
    out->pdf = 1;
    return factor > 0;
}

static const param SPOT_PARAMS[] = {
    {.key = "position", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.position), .required = true,
     .meaning = "where the light is"},
    {.key = "direction", .type = PARAM_DIRECTION, .offset = offsetof(light_spec, light.direction),
     .required = true, .meaning = "where the cone's axis points"},
    LIGHT_COLOR_PARAMS,
    {.key = "angle", .type = PARAM_NUMBER, .offset = offsetof(light_spec, light.cone_angle), .required = true,
     .lo = 0, .hi = 90, .bounds = PARAM_OPEN_LOW, .unit = "degrees", .meaning = "half-angle of the cone"},
    {.key = "falloff", .type = PARAM_NUMBER, .offset = offsetof(light_spec, light.falloff_angle), .lo = 0,
     .hi = 90, .unit = "degrees", .meaning = "width of the soft edge inside the cone, at most angle; 0 is hard"},
};

const light_kind spot_light = {
    .name = "spot", .id = GLINT_LIGHT_SPOT, .params = PARAM_TABLE(SPOT_PARAMS), .init = spot_init,
    .sample = spot_sample,
};
