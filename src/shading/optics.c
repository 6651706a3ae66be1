/* optics.c - the laws of reflection and refraction. */
#include <math.h>
#include "shading/optics.h"

vec3 optics_reflect(vec3 d, vec3 n)
{
    return v3_madd(d, n, -2 * v3_dot(d, n));
}

bool optics_refract(vec3 d, vec3 n, double eta, vec3 *out)
{
    double cos_i = -v3_dot(d, n);
    double sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t > 1)
        return false;
    double cos_t = sqrt(1 - sin2_t);
    *out = v3_normalize(v3_add(v3_scale(d, eta), v3_scale(n, eta * cos_i - cos_t)));
    return true;
}

vec3 optics_lobe(vec3 d, vec3 side, double exponent, double u1, double u2)
{
    double cos_t = pow(1 - u1, 1 / (exponent + 1)), sin_t = sqrt(fmax(0, 1 - cos_t * cos_t)), phi = 2 * M_PI * u2;
    vec3 u, v;
    plane_basis(d, &u, &v);
    vec3 out = v3_add(v3_scale(d, cos_t), v3_add(v3_scale(u, sin_t * cos(phi)), v3_scale(v, sin_t * sin(phi))));
    double behind = v3_dot(out, side);
    return behind < 0 ? v3_madd(out, side, -2 * behind) : out;
}

double optics_fresnel(double cos_i, double eta)
{
    double sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t >= 1)
        return 1;
    double cos_t = sqrt(1 - sin2_t);
    /* With n_from = eta and n_to = 1 (only the ratio matters). */
    double rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    double rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}
