/* material.h - Phong materials with reflection, transparency and refraction. */
#ifndef GLINT_SHADING_MATERIAL_H
#define GLINT_SHADING_MATERIAL_H

#include "core/color.h"
#include "core/params.h"
#include "core/vec.h"

typedef struct material {
    char *name;               /* may be NULL */
    glint_material m;
} material;

/* The keys of a material, with their defaults and ranges (all but its
 * texture, which a scene file names). */
param_table material_params(void);

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

/* Ambient, diffuse and specular shares of one light: the Phong model.
 * n is the unit normal facing the viewer, to_light and to_eye unit vectors. */
color phong_light(const glint_material *m, color surface_color, vec3 n, vec3 to_light,
                  vec3 to_eye, color radiance);

/* False only when phong_light with these arguments, n . to_light > 0, is
 * exactly black, and stays so for any radiance that is black wherever
 * `radiance` is (what a shadow ray lets through only dims it): then the
 * light adds nothing there, and its shadow ray need not be traced. */
bool phong_reaches(const glint_material *m, color surface_color, vec3 n, vec3 to_light, vec3 to_eye,
                   color radiance);

#endif
