/* sphere_light.c - a glowing ball: an area light (light.h) sampled by the
 * cone of directions it fills as seen from the shading point, so that
 * every sample lands on the half facing the point and none is wasted. */
#include <math.h>
#include <stddef.h>
#include "shading/light.h"

static glint_status sphere_light_init(light *l, glint_error *err)
{
    glint_shape ball = glint_shape_default(GLINT_SHAPE_SPHERE);
    ball.center = l->desc.position;
    ball.radius = l->desc.radius;
    return light_area_init(l, &ball, 4 * M_PI * ball.radius * ball.radius, err);
}

static bool sphere_light_sample(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    vec3 to_center = v3_sub(l->desc.position, p);
    double d2 = v3_dot(to_center, to_center), r = l->desc.radius;
    double sin2_max = r * r / d2; /* of the cone's half-angle */
    if (!(sin2_max < 1))
        return false; /* p is inside the ball */
    double d = sqrt(d2);
    vec3 axis = v3_scale(to_center, 1 / d), a, b;
    plane_basis(axis, &a, &b);
    /* 1 - cos of the half-angle, written so that a small far ball keeps its digits. */
    double cap = sin2_max / (1 + sqrt(1 - sin2_max));
    double one_minus_cos = u1 * cap, cos_t = 1 - one_minus_cos;
    double sin_t = sqrt(fmax(0, one_minus_cos * (2 - one_minus_cos))), phi = 2 * M_PI * u2;
    out->to_light = v3_add(v3_scale(axis, cos_t), v3_add(v3_scale(a, sin_t * cos(phi)), v3_scale(b, sin_t * sin(phi))));
    /* The near side of the ball along that direction. */
    out->distance = d * cos_t - sqrt(fmax(0, r * r - d2 * sin_t * sin_t));
    out->radiance = rgb_scale(l->desc.color, 2 * cap);
    return true;
}

LIGHT_SAMPLE_LANES(sphere_light_lanes, sphere_light_sample)

static const param SPHERE_LIGHT_PARAMS[] = {
    {.key = "position", .type = PARAM_VEC3, .offset = offsetof(light_spec, light.position), .required = true,
     .meaning = "the ball's centre"},
    {.key = "radius", .type = PARAM_NUMBER, .offset = offsetof(light_spec, light.radius), .required = true,
     PARAM_POSITIVE, .meaning = "the ball's radius"},
    AREA_LIGHT_PARAMS,
};

const light_kind sphere_light = {
    .name = "sphere", .id = GLINT_LIGHT_SPHERE, .params = PARAM_TABLE(SPHERE_LIGHT_PARAMS),
    .init = sphere_light_init, .sample = sphere_light_sample, .sample_lanes = sphere_light_lanes,
};
