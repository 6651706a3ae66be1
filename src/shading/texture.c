/* texture.c - checkerboards, image lookups and the uv mappings. */
#include <math.h>
#include <stdlib.h>
#include "core/error.h"
#include "geometry/shape_math.h"
#include "shading/texture.h"

glint_status mapping_validate(const glint_mapping *m, glint_error *err)
{
    if (m->kind < GLINT_MAP_UV || m->kind > GLINT_MAP_CYLINDRICAL)
        return error_set(err, GLINT_ERR_INVALID, "unknown texture mapping %d", (int)m->kind);
    if (!v3_is_finite(m->center) || !v3_is_finite(m->u_axis) || !v3_is_finite(m->v_axis) ||
        !isfinite(m->scale))
        return error_set(err, GLINT_ERR_INVALID, "texture mapping values must be finite");
    if (m->scale < 0)
        return error_set(err, GLINT_ERR_INVALID, "texture mapping scale must not be negative, got %g", m->scale);
    if (m->kind == GLINT_MAP_PLANAR) {
        bool u0 = v3_length(m->u_axis) == 0, v0 = v3_length(m->v_axis) == 0;
        if (u0 != v0)
            return error_set(err, GLINT_ERR_INVALID, "planar mapping needs both axes or neither");
        if (!u0 && v3_length(v3_cross(m->u_axis, m->v_axis)) == 0)
            return error_set(err, GLINT_ERR_INVALID, "planar mapping axes must not be parallel");
    }
    return GLINT_OK;
}

void mapping_apply(const glint_mapping *m, const surface *s, double *u, double *v)
{
    double scale = m->scale > 0 ? m->scale : 1.0;
    vec3 d = v3_sub(s->p_obj, m->center);
    switch (m->kind) {
    case GLINT_MAP_UV:
        *u = s->u;
        *v = s->v;
        return;
    case GLINT_MAP_PLANAR:
        if (v3_length(m->u_axis) == 0) {
            /* x / 1 is x: no division for the default scale. */
            *u = scale == 1 ? d.x : d.x / scale;
            *v = scale == 1 ? d.z : d.z / scale;
        } else {
            *u = v3_dot(d, v3_normalize(m->u_axis)) / scale;
            *v = v3_dot(d, v3_normalize(m->v_axis)) / scale;
        }
        return;
    case GLINT_MAP_SPHERICAL:
        spherical_uv(v3_normalize(d), u, v);
        return;
    case GLINT_MAP_CYLINDRICAL: {
        vec3 around = v3_normalize(v3(d.x, 0, d.z));
        *u = polar_u(around.x, around.z);
        *v = d.y / scale;
        return;
    }
    }
    *u = *v = 0;
}

color checker_eval(color a, color b, double cell, double u, double v)
{
    double k = floor(u / cell) + floor(v / cell);
    /* k is a whole number: even exactly when half of it is whole too (every
     * double from 2^53 up is even), without fmod's library call. */
    double half = 0.5 * k;
    return half == floor(half) ? a : b;
}

static color texel(const texture_image *img, int x, int y)
{
    size_t i = 3 * ((size_t)y * img->width + x);
    return rgb(texture_image_at(img, i), texture_image_at(img, i + 1), texture_image_at(img, i + 2));
}

color image_eval(const texture_image *img, double u, double v)
{
    if (!isfinite(u) || !isfinite(v))
        return rgb(0, 0, 0);
    double fx = (u - floor(u)) * img->width - 0.5;
    double fy = (v < 0 ? 0 : v > 1 ? 1 : v) * img->height - 0.5;
    double x0f = floor(fx), y0f = floor(fy);
    double tx = fx - x0f, ty = fy - y0f;
    int x0 = (int)x0f, y0 = (int)y0f;
    int x1 = x0 + 1, y1 = y0 + 1;
    x0 = (x0 % img->width + img->width) % img->width;
    x1 = x1 % img->width;
    y0 = y0 < 0 ? 0 : y0;
    y1 = y1 >= img->height ? img->height - 1 : y1;
    color top = rgb_lerp(texel(img, x0, y0), texel(img, x1, y0), tx);
    color bottom = rgb_lerp(texel(img, x0, y1), texel(img, x1, y1), tx);
    return rgb_lerp(top, bottom, ty);
}

color texture_eval(const texture *t, const surface *s)
{
    double u, v;
    mapping_apply(&t->mapping, s, &u, &v);
    if (t->kind == TEXTURE_CHECKER)
        return checker_eval(t->a, t->b, t->cell, u, v);
    return image_eval(&t->image, u, v);
}

void texture_release(texture *t)
{
    free(t->name);
    t->name = NULL;
    texture_image_free(&t->image);
}
