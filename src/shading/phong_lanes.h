/* phong_lanes.h - steps of material.h's Phong model on a quad of lanes,
 * each the same bits as its one-lane form, for the integrator's code that
 * shades four hits at a time (integrator.c's area lights, plain_packet.c). */
#ifndef GLINT_SHADING_PHONG_LANES_H
#define GLINT_SHADING_PHONG_LANES_H

#include "core/lanes.h"

/* rgb_max(c) > 0 for a quad of colours c[channel], NaN as there. */
static inline quad_mask quad_rgb_max_positive(const quad_f64 c[3])
{
    quad_f64 m = quad_select(c[0] > c[1], c[0], c[1]);
    return quad_select(m > c[2], m, c[2]) > 0;
}

/* lobe_pow(x, e) for a quad, each lane's e a whole number in [0, 65536]:
 * the same squarings and products, so the same bits. */
static inline quad_f64 quad_lobe_pow(quad_f64 x, quad_f64 e)
{
    quad_mask n = __builtin_convertvector(e, quad_mask);
    quad_f64 result = quad_splat(1);
    while (quad_any(n)) {
        result = quad_select((n & 1) != 0, result * x, result);
        x *= x;
        n >>= 1;
    }
    return result;
}

/* lobe_cos(ns, to_light, to_eye) for a quad, each vector by coordinate:
 * the cosine between the light's mirror direction about ns and the eye. */
static inline quad_f64 quad_lobe_cos(const quad_f64 ns[3], const quad_f64 to_light[3], const quad_f64 to_eye[3])
{
    const quad_f64 from[3] = {-to_light[0], -to_light[1], -to_light[2]};
    quad_f64 k = -2 * quad_dot(from[0], from[1], from[2], ns[0], ns[1], ns[2]);
    return quad_dot(from[0] + ns[0] * k, from[1] + ns[1] * k, from[2] + ns[2] * k, to_eye[0], to_eye[1], to_eye[2]);
}

/* Whether a material's specular exponent is one quad_lobe_pow takes. */
static inline bool lobe_exponent_whole(double shininess)
{
    return shininess >= 0 && shininess <= 65536 && shininess == floor(shininess);
}

#endif
