/* environment.c - the environment: a texture seen by rays that miss
 * everything, wrapped around the scene as equirectangular images are
 * stored (longitude across, latitude down), as the equirectangular camera
 * makes them: a panorama rendered at the origin looking along -z is an
 * environment the same way round. */
#include <math.h>
#include <stddef.h>
#include "core/error.h"
#include "shading/environment.h"

#define FIELD(name) .offset = offsetof(glint_environment, name)

static const param ENVIRONMENT_PARAMS[] = {
    {.key = "intensity", .type = PARAM_NUMBER, FIELD(intensity), .def = {1}, .lo = 0, .hi = 1e300,
     .meaning = "multiplies the texture's colour"},
    {.key = "rotation", .type = PARAM_NUMBER, FIELD(rotation), .lo = -1e6, .hi = 1e6, .unit = "degrees",
     .meaning = "turns the image about +y, anticlockwise seen from above"},
};

param_table environment_params(void)
{
    return PARAM_TABLE(ENVIRONMENT_PARAMS);
}

glint_status environment_validate(const glint_environment *env, int texture_count, glint_error *err)
{
    if (env->texture < -1 || env->texture >= texture_count)
        return error_set(err, GLINT_ERR_INVALID, "environment texture %d does not exist", env->texture);
    return params_check(environment_params(), env, "environment", err);
}

color environment_color(const glint_environment *env, const texture *t, vec3 d)
{
    /* A solid texture colours the sky as it is on the unit sphere. */
    if (t->kind->solid)
        return rgb_scale(t->kind->solid(t, texture_place(t, d)), env->intensity);
    double longitude = atan2(d.x, -d.z) - env->rotation * (M_PI / 180);
    double u = 0.5 + longitude / (2 * M_PI), v = 0.5 - asin(d.y < -1 ? -1 : d.y > 1 ? 1 : d.y) / M_PI;
    return rgb_scale(texture_at_uv(t, u, v, (uv_extent){0, 0}), env->intensity);
}
