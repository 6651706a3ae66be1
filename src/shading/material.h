/* material.h - Phong materials with reflection, transparency and refraction. */
#ifndef GLINT_SHADING_MATERIAL_H
#define GLINT_SHADING_MATERIAL_H

#include "core/color.h"
#include "core/vec.h"

typedef struct material {
    char *name;               /* may be NULL */
    glint_material m;
} material;

/* Checks every value of m against texture_count textures; fills err naming
 * the first bad value. */
glint_status material_validate(const glint_material *m, int texture_count, glint_error *err);

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
