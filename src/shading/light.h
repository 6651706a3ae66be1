/* light.h - point, spot and directional lights: where a light is seen from a
 * point and how much of it arrives there before shadowing. */
#ifndef GLINT_SHADING_LIGHT_H
#define GLINT_SHADING_LIGHT_H

#include <stdbool.h>
#include "core/color.h"
#include "core/vec.h"

/* A light with its derived values precomputed. */
typedef struct light {
    glint_light desc;
    vec3 dir;                 /* unit direction (spot: its axis; directional: travel) */
    double cos_outer;         /* spot: cosine of the cone half-angle */
    double cos_inner;         /* spot: cosine of the half-angle where falloff begins */
} light;

/* What a light offers to point p. */
typedef struct light_sample {
    vec3 to_light;            /* unit direction from p towards the light */
    double distance;          /* to the light; INFINITY for directional lights */
    color radiance;           /* arriving light before shadows */
} light_sample;

/* Validates desc and fills *l; fills err naming a bad value. */
glint_status light_init(light *l, const glint_light *desc, glint_error *err);

/* Fills *out for point p; false when the light gives p nothing. */
bool light_illuminate(const light *l, vec3 p, light_sample *out);

/* Spotlight factor in [0, 1] for a point whose direction from the light makes
 * cosine cos_angle with the axis: 1 inside the inner cone, 0 outside the
 * outer, a smoothstep between. */
double spot_factor(const light *l, double cos_angle);

#endif
