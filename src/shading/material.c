/* material.c - material validation and the Phong lighting model. */
#include <math.h>
#include <stddef.h>
#include <string.h>
#include "core/error.h"
#include "shading/material.h"
#include "shading/optics.h"
#include "shading/spectrum.h"

/* The share of something, from 0 to 1. */
#define SHARE .lo = 0, .hi = 1
/* A strength with no upper limit but a finite one. */
#define STRENGTH .lo = 0, .hi = 1e300

#define FIELD(name) .offset = offsetof(glint_material, name)

static const param MATERIAL_PARAMS[] = {
    {.key = "color", .type = PARAM_COLOR, FIELD(color), .def = {1, 1, 1}, .lo = 0, .hi = DBL_MAX,
     .meaning = "base colour"},
    {.key = "ambient", .type = PARAM_NUMBER, FIELD(ambient), .def = {0.2}, SHARE,
     .meaning = "share of the base colour lit by the ambient light"},
    {.key = "diffuse", .type = PARAM_NUMBER, FIELD(diffuse), .def = {1}, STRENGTH,
     .meaning = "diffuse (Lambert) strength"},
    {.key = "specular", .type = PARAM_NUMBER, FIELD(specular), .def = {1}, STRENGTH,
     .meaning = "strength of the white Phong highlight"},
    {.key = "shininess", .type = PARAM_NUMBER, FIELD(shininess), .def = {50}, STRENGTH,
     .meaning = "Phong exponent: higher is a smaller, sharper highlight"},
    {.key = "reflectivity", .type = PARAM_NUMBER, FIELD(reflectivity), SHARE,
     .meaning = "mirror reflection, added on top of the rest"},
    {.key = "transparency", .type = PARAM_NUMBER, FIELD(transparency), SHARE,
     .meaning = "light passing straight through, unbent"},
    {.key = "refraction", .type = PARAM_NUMBER, FIELD(refraction), SHARE,
     .meaning = "light passing through, bent by ior; transparency + refraction <= 1"},
    {.key = "ior", .type = PARAM_NUMBER, FIELD(ior), .def = {1.5}, PARAM_POSITIVE,
     .meaning = "index of refraction (water 1.33, glass 1.5, diamond 2.4)"},
    {.key = "tint", .type = PARAM_NUMBER, FIELD(tint), .def = {1}, SHARE,
     .meaning = "how much the base colour filters transmitted light and shadows"},
    {.key = "fresnel", .type = PARAM_BOOL, FIELD(fresnel),
     .meaning = "split the refraction share between refraction and reflection by the Fresnel equations"},
    {.key = "emission", .type = PARAM_COLOR, FIELD(emission), .lo = 0, .hi = DBL_MAX,
     .meaning = "light the surface gives off from its front side (black: none); an emissive shape or mesh "
                "lights the scene as an area light"},
    {.key = "emission_strength", .type = PARAM_NUMBER, FIELD(emission_strength), .def = {1}, STRENGTH,
     .meaning = "multiplies emission: their product is the surface's radiance"},
    {.key = "roughness", .type = PARAM_NUMBER, FIELD(roughness), SHARE,
     .meaning = "blurs reflection and refraction: 0 is a sharp mirror or clear glass, more spreads the rays "
                "over a lobe about the sharp direction (a Phong lobe of exponent 2 / roughness^4 - 2)"},
    {.key = "glossy_samples", .type = PARAM_INTEGER, FIELD(glossy_samples), .def = {16}, .lo = 1, .hi = 1024,
     .meaning = "rough reflection or refraction: the rays a camera ray's is spread over (a ray of less weight, "
                "seen in another, fewer)"},
    {.key = "metallic", .type = PARAM_NUMBER, FIELD(metallic), SHARE,
     .meaning = "how much reflections and highlights take the base colour, as a metal's do: 0 white, 1 the "
                "base colour"},
    {.key = "dispersion", .type = PARAM_NUMBER, FIELD(dispersion), .lo = 0, .hi = 1e6,
     .meaning = "the Abbe number, (n_d - 1) / (n_F - n_C) with ior as n_d: refracted light splits into the "
                "colours of the spectrum, more for lower numbers (dense flint glass 30, crown glass 60, diamond "
                "55, water 55); 0: none"},
};

static const param ABSORPTION_PARAMS[] = {
    {.key = "color", .type = PARAM_COLOR, .offset = offsetof(glint_absorption, color), .required = true, .lo = 0,
     .hi = 1, .meaning = "what is left of light that has travelled `distance` inside"},
    {.key = "distance", .type = PARAM_NUMBER, .offset = offsetof(glint_absorption, distance), .def = {1},
     PARAM_POSITIVE, .meaning = "the distance at which `color` is left; length L leaves color^(L / distance)"},
};

param_table absorption_params(void)
{
    return PARAM_TABLE(ABSORPTION_PARAMS);
}

static const param BUMP_PARAMS[] = {
    {.key = "strength", .type = PARAM_NUMBER, FIELD(bump_strength), .def = {0.1}, .lo = -1000, .hi = 1000,
     .meaning = "the height of brightness 1, in the thing's own units; negative dents"},
};

param_table bump_params(void)
{
    return PARAM_TABLE(BUMP_PARAMS);
}

param_table material_params(void)
{
    return PARAM_TABLE(MATERIAL_PARAMS);
}

glint_material glint_material_default(void)
{
    glint_material m;
    memset(&m, 0, sizeof m);
    params_defaults(material_params(), &m);
    params_defaults(bump_params(), &m);
    m.texture = m.bump_texture = m.normal_texture = -1;
    return m;
}

glint_status material_validate(const glint_material *m, int texture_count, glint_error *err)
{
    glint_status s = params_check(material_params(), m, "material", err);
    if (s)
        return s;
    if (m->texture < -1 || m->texture >= texture_count)
        return error_set(err, GLINT_ERR_INVALID, "material texture %d does not exist", m->texture);
    if (m->bump_texture < -1 || m->bump_texture >= texture_count)
        return error_set(err, GLINT_ERR_INVALID, "material bump texture %d does not exist", m->bump_texture);
    if (m->normal_texture < -1 || m->normal_texture >= texture_count)
        return error_set(err, GLINT_ERR_INVALID, "material normal_map texture %d does not exist", m->normal_texture);
    s = params_check(bump_params(), m, "material bump", err);
    if (s)
        return s;
    if (m->transparency + m->refraction > 1)
        return error_set(err, GLINT_ERR_INVALID, "material transparency + refraction must not exceed 1, got %g",
                         m->transparency + m->refraction);
    if (m->dispersion > 0) {
        double least = material_index_at(m, SPECTRUM_LONGEST), most = material_index_at(m, SPECTRUM_SHORTEST);
        if (!(least > 0 && most > 0))
            return error_set(err, GLINT_ERR_INVALID,
                             "material dispersion %g with ior %g gives an index of %g at %g nm; it must stay above 0",
                             m->dispersion, m->ior, least > 0 ? most : least, least > 0 ? SPECTRUM_SHORTEST : SPECTRUM_LONGEST);
    }
    if (m->absorption.distance != 0)
        return params_check(absorption_params(), &m->absorption, "material absorption", err);
    return GLINT_OK;
}

/* The optical depth of one unit of length in one channel that keeps c of
 * the light after `distance`. */
static double per_unit(double c, double distance)
{
    const double least = 1e-12; /* a black channel, kept finite so depths can be summed */
    return -log(c > least ? c : least) / distance;
}

color material_optical_depth(const glint_material *m, double length)
{
    double d = m->absorption.distance;
    return rgb(per_unit(m->absorption.color.r, d) * length, per_unit(m->absorption.color.g, d) * length,
               per_unit(m->absorption.color.b, d) * length);
}

color material_absorbed(const glint_material *m, double length)
{
    color depth = material_optical_depth(m, length);
    return rgb(exp(-depth.r), exp(-depth.g), exp(-depth.b));
}

color material_metal_tint(const glint_material *m, color base)
{
    double w = 1 - m->metallic;
    return rgb_madd(rgb(w, w, w), base, m->metallic);
}

double material_lobe_exponent(const glint_material *m)
{
    double r4 = m->roughness * m->roughness * m->roughness * m->roughness;
    return 2 / r4 - 2;
}

color material_emission(const glint_material *m)
{
    return rgb_scale(m->emission, m->emission_strength);
}

bool material_is_opaque(const glint_material *m)
{
    return m->transparency + m->refraction <= 0;
}

color material_filter(const glint_material *m, color c)
{
    return rgb_madd(rgb(1 - m->tint, 1 - m->tint, 1 - m->tint), c, m->tint);
}

