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

#endif
