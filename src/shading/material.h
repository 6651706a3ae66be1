/* material.h - Phong materials with reflection, transparency and refraction. */
#ifndef GLINT_SHADING_MATERIAL_H
#define GLINT_SHADING_MATERIAL_H

#include "core/color.h"
#include "core/params.h"
#include <math.h>
#include "core/vec.h"
#include "shading/optics.h"

typedef struct material {
    char *name;               /* may be NULL */
    glint_material m;
} material;

/* The keys of a material, with their defaults and ranges (all but its
 * texture, which a scene file names). */
param_table material_params(void);

/* The keys of a material's absorption map. */
param_table absorption_params(void);

/* The keys of a material's bump map but its texture (the field offsets are
 * glint_material's). */
param_table bump_params(void);

/* Checks every value of m against the table and texture_count textures, and
 * that transparency + refraction is at most 1; fills err naming the first
 * bad value. */
glint_status material_validate(const glint_material *m, int texture_count, glint_error *err);

/* The Phong exponent of the lobe a rough (roughness > 0) material spreads
 * its reflected and refracted rays over: 2 / roughness^4 - 2, whose lobe
 * matches a microfacet (Beckmann) roughness alpha = roughness^2, as glTF
 * roughness is read (docs/meshes.md): 0.5 gives 30, 1 gives 0 (a whole
 * hemisphere). */
double material_lobe_exponent(const glint_material *m);

/* The radiance the material gives off from a surface's front: emission
 * times emission_strength (black for most). */
color material_emission(const glint_material *m);

/* True when no light passes the material: no transparency, no refraction. */
bool material_is_opaque(const glint_material *m);

/* Colour a material transmits: (1 - tint) + tint * surface colour. */
color material_filter(const glint_material *m, color surface_color);

/* Whether light travelling inside m is absorbed. */
static inline bool material_absorbs(const glint_material *m) { return m->absorption.distance > 0; }

/* Whether a ray hitting m sends rays on: reflected, refracted or straight
 * through. */
static inline bool material_branches(const glint_material *m)
{
    return m->reflectivity > 0 || m->refraction > 0 || m->transparency > 0;
}

/* What `length` inside absorbing m leaves of light, per channel:
 * color^(length / distance), as exp(-material_optical_depth). */
color material_absorbed(const glint_material *m, double length);

/* The optical depth of `length` inside absorbing m, per channel: it adds
 * along a path, and what is left is exp(-depth). */
color material_optical_depth(const glint_material *m, double length);

/* The colour m's reflections and highlights take on a surface of colour
 * base: white blended towards base by metallic. */
color material_metal_tint(const glint_material *m, color base);

/* x^e for the specular lobe: by repeated squaring when e is a whole number
 * up to 65536 (every shininess a scene file usually gives), which is several
 * times faster than pow and as exact to a few ulps; pow otherwise. */
static inline double lobe_pow(double x, double e)
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
static inline double lobe_cos(vec3 n, vec3 to_light, vec3 to_eye)
{
    return v3_dot(optics_reflect(v3_neg(to_light), n), to_eye);
}

/* Ambient, diffuse and specular shares of one light: the Phong model.
 * n is the unit normal facing the viewer, to_light and to_eye unit vectors.
 * Inline, as phong_reaches: they run for every light sample of every
 * lane, and as calls they cost the Cornell box 9% and a soft light 17%. */
static inline color phong_light(const glint_material *m, color c, vec3 n, vec3 to_light, vec3 to_eye,
                                color radiance)
{
    double n_dot_l = v3_dot(n, to_light);
    if (n_dot_l <= 0)
        return rgb(0, 0, 0);
    color out = rgb_scale(rgb_mul(c, radiance), m->diffuse * n_dot_l);
    if (m->specular > 0) {
        double r_dot_v = lobe_cos(n, to_light, to_eye);
        if (r_dot_v > 0)
            out = rgb_madd(out, m->metallic > 0 ? rgb_mul(radiance, material_metal_tint(m, c)) : radiance,
                           m->specular * lobe_pow(r_dot_v, m->shininess));
    }
    return out;
}

/* False only when phong_light with these arguments, n . to_light > 0, is
 * exactly black, and stays so for any radiance that is black wherever
 * `radiance` is (what a shadow ray lets through only dims it): then the
 * light adds nothing there, and its shadow ray need not be traced. */
static inline bool phong_reaches(const glint_material *m, color c, vec3 n, vec3 to_light, vec3 to_eye,
                                 color radiance)
{
    /* A zero factor in every channel makes the diffuse term exactly zero. */
    if (m->diffuse > 0 &&
        ((c.r > 0 && radiance.r > 0) || (c.g > 0 && radiance.g > 0) || (c.b > 0 && radiance.b > 0)))
        return true;
    if (!(m->specular > 0) || !(rgb_max(radiance) > 0))
        return false;
    return lobe_cos(n, to_light, to_eye) > 0;
}

#endif
