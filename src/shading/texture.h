/* texture.h - procedural and image textures and the mappings that give them
 * (u, v) coordinates on a surface. */
#ifndef GLINT_SHADING_TEXTURE_H
#define GLINT_SHADING_TEXTURE_H

#include "core/color.h"
#include "geometry/shape.h"
#include "image/texture_image.h"

typedef enum texture_kind { TEXTURE_CHECKER, TEXTURE_IMAGE } texture_kind;

typedef struct texture {
    char *name;                /* may be NULL */
    texture_kind kind;
    glint_mapping mapping;
    color a, b;                /* checker colours */
    double cell;               /* checker cell size */
    texture_image image;       /* image texture, linear RGB */
} texture;

/* Checks a mapping's values; fills err naming the bad one. */
glint_status mapping_validate(const glint_mapping *m, glint_error *err);

/* Computes the texture coordinates of surface s under mapping m. */
void mapping_apply(const glint_mapping *m, const surface *s, double *u, double *v);

/* The colour of checker cells at (u, v): a where floor(u/cell) + floor(v/cell) is even. */
color checker_eval(color a, color b, double cell, double u, double v);

/* Bilinearly filtered colour of an image at (u, v): u wraps, v clamps;
 * v = 0 is the top row. */
color image_eval(const texture_image *img, double u, double v);

/* The colour of texture t at surface s. */
color texture_eval(const texture *t, const surface *s);

/* Frees what t owns. */
void texture_release(texture *t);

#endif
