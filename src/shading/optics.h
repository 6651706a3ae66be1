/* optics.h - mirror reflection, Snell refraction and Fresnel reflectance. */
#ifndef GLINT_SHADING_OPTICS_H
#define GLINT_SHADING_OPTICS_H

#include <stdbool.h>
#include "core/vec.h"

/* Reflects unit direction d about unit normal n. */
vec3 optics_reflect(vec3 d, vec3 n);

/* Refracts unit direction d through a surface with unit normal n facing the
 * incoming ray (dot(d, n) < 0); eta = n_from / n_to. Returns false on total
 * internal reflection. */
bool optics_refract(vec3 d, vec3 n, double eta, vec3 *out);

/* Fraction of light reflected by a dielectric boundary for unpolarised light,
 * cos_i = cosine of the incidence angle (> 0), eta = n_from / n_to. Returns 1
 * on total internal reflection. */
double optics_fresnel(double cos_i, double eta);

/* A direction about unit direction d for (u1, u2) in [0, 1)^2, with
 * density proportional to cos^exponent of its angle to d (a Phong lobe),
 * kept on the side of a surface that unit normal `side` points to: a
 * direction the lobe puts behind the surface is mirrored across it. */
vec3 optics_lobe(vec3 d, vec3 side, double exponent, double u1, double u2);

#endif
