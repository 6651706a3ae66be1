/* material.c - material validation and the Phong lighting model. */
#include <math.h>
#include "core/error.h"
#include "shading/material.h"
#include "shading/optics.h"

glint_material glint_material_default(void)
{
    glint_material m = {
        .color = {1, 1, 1}, .texture = -1, .ambient = 0.2, .diffuse = 1, .specular = 1,
        .shininess = 50, .ior = 1.5, .tint = 1,
    };
    return m;
}

static glint_status check_unit(const char *what, double v, glint_error *err)
{
    if (!(v >= 0 && v <= 1))
        return error_set(err, GLINT_ERR_INVALID, "material %s must be in [0, 1], got %g", what, v);
    return GLINT_OK;
}

static glint_status check_positive(const char *what, double v, glint_error *err)
{
    if (!(v >= 0 && isfinite(v)))
        return error_set(err, GLINT_ERR_INVALID, "material %s must be finite and not negative, got %g", what, v);
    return GLINT_OK;
}

glint_status material_validate(const glint_material *m, int texture_count, glint_error *err)
{
    glint_status s;
    if (!rgb_is_valid(m->color))
        return error_set(err, GLINT_ERR_INVALID, "material colour must be finite and not negative");
    if (m->texture < -1 || m->texture >= texture_count)
        return error_set(err, GLINT_ERR_INVALID, "material texture %d does not exist", m->texture);
    if ((s = check_unit("ambient", m->ambient, err)) || (s = check_positive("diffuse", m->diffuse, err)) ||
        (s = check_positive("specular", m->specular, err)) ||
        (s = check_positive("shininess", m->shininess, err)) ||
        (s = check_unit("reflectivity", m->reflectivity, err)) ||
        (s = check_unit("transparency", m->transparency, err)) ||
        (s = check_unit("refraction", m->refraction, err)) || (s = check_unit("tint", m->tint, err)))
        return s;
    if (m->transparency + m->refraction > 1)
        return error_set(err, GLINT_ERR_INVALID,
                         "material transparency + refraction must not exceed 1, got %g",
                         m->transparency + m->refraction);
    if (!(m->ior > 0 && isfinite(m->ior)))
        return error_set(err, GLINT_ERR_INVALID, "material index of refraction must be above 0, got %g", m->ior);
    return GLINT_OK;
}

bool material_is_opaque(const glint_material *m)
{
    return m->transparency + m->refraction <= 0;
}

color material_filter(const glint_material *m, color c)
{
    return rgb_madd(rgb(1 - m->tint, 1 - m->tint, 1 - m->tint), c, m->tint);
}

/* x^e for the specular lobe: by repeated squaring when e is a whole number
 * up to 65536 (every shininess a scene file usually gives), which is several
 * times faster than pow and as exact to a few ulps; pow otherwise. */
static double lobe_pow(double x, double e)
{
    if (!(e >= 0 && e <= 65536 && e == floor(e)))
        return pow(x, e);
    unsigned n = (unsigned)e;
    double result = 1;
    while (n) {
        if (n & 1)
            result *= x;
        x *= x;
        n >>= 1;
    }
    return result;
}

/* The cosine between the mirror direction of the light about n and the
 * eye, the base of the specular lobe: it shows only where positive. */
static double lobe_cos(vec3 n, vec3 to_light, vec3 to_eye)
{
    return v3_dot(optics_reflect(v3_neg(to_light), n), to_eye);
}

color phong_light(const glint_material *m, color c, vec3 n, vec3 to_light, vec3 to_eye, color radiance)
{
    double n_dot_l = v3_dot(n, to_light);
    if (n_dot_l <= 0)
        return rgb(0, 0, 0);
    color out = rgb_scale(rgb_mul(c, radiance), m->diffuse * n_dot_l);
    if (m->specular > 0) {
        double r_dot_v = lobe_cos(n, to_light, to_eye);
        if (r_dot_v > 0)
            out = rgb_madd(out, radiance, m->specular * lobe_pow(r_dot_v, m->shininess));
    }
    return out;
}

bool phong_reaches(const glint_material *m, color c, vec3 n, vec3 to_light, vec3 to_eye, color radiance)
{
    /* A zero factor in every channel makes the diffuse term exactly zero. */
    if (m->diffuse > 0 &&
        ((c.r > 0 && radiance.r > 0) || (c.g > 0 && radiance.g > 0) || (c.b > 0 && radiance.b > 0)))
        return true;
    if (!(m->specular > 0) || !(rgb_max(radiance) > 0))
        return false;
    return lobe_cos(n, to_light, to_eye) > 0;
}
