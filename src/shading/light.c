/* light.c - light validation and illumination of a point. */
#include <math.h>
#include "core/error.h"
#include "shading/light.h"

glint_status light_init(light *l, const glint_light *d, glint_error *err)
{
    l->desc = *d;
    l->dir = v3(0, -1, 0);
    l->cos_outer = l->cos_inner = -1;
    if (!rgb_is_valid(d->color))
        return error_set(err, GLINT_ERR_INVALID, "light colour must be finite and not negative");
    if (d->kind != GLINT_LIGHT_POINT && d->kind != GLINT_LIGHT_SPOT && d->kind != GLINT_LIGHT_DIRECTIONAL)
        return error_set(err, GLINT_ERR_INVALID, "unknown light kind %d", (int)d->kind);
    if (d->kind == GLINT_LIGHT_SPOT) {
        if (!(d->cone_angle > 0 && d->cone_angle <= 90))
            return error_set(err, GLINT_ERR_INVALID,
                             "spotlight cone angle must be in (0, 90] degrees, got %g", d->cone_angle);
        if (!(d->falloff_angle >= 0 && d->falloff_angle <= d->cone_angle))
            return error_set(err, GLINT_ERR_INVALID,
                             "spotlight falloff angle must be in [0, cone angle], got %g", d->falloff_angle);
        l->cos_outer = cos(d->cone_angle * M_PI / 180);
        l->cos_inner = cos((d->cone_angle - d->falloff_angle) * M_PI / 180);
    }
    if (d->kind != GLINT_LIGHT_POINT) {
        if (!v3_is_finite(d->direction) || v3_length(d->direction) == 0)
            return error_set(err, GLINT_ERR_INVALID, "light direction must be finite and not zero");
        l->dir = v3_normalize(d->direction);
    }
    if (d->kind != GLINT_LIGHT_DIRECTIONAL && !v3_is_finite(d->position))
        return error_set(err, GLINT_ERR_INVALID, "light position must be finite");
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

bool light_illuminate(const light *l, vec3 p, light_sample *out)
{
    double factor = 1;
    if (l->desc.kind == GLINT_LIGHT_DIRECTIONAL) {
        out->to_light = v3_neg(l->dir);
        out->distance = INFINITY;
    } else {
        vec3 d = v3_sub(l->desc.position, p);
        if (l->desc.kind == GLINT_LIGHT_SPOT && outside_cone(l, d))
            return false;
        out->distance = v3_length(d);
        if (out->distance == 0)
            return false;
        out->to_light = v3_scale(d, 1.0 / out->distance);
        if (l->desc.kind == GLINT_LIGHT_SPOT)
            factor = spot_factor(l, -v3_dot(out->to_light, l->dir));
    }
    out->radiance = rgb_scale(l->desc.color, factor);
    return factor > 0;
}
