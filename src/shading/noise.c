/* noise.c - hashed gradient noise and its fractal sums (noise.h). */
#include <math.h>
#include "core/hash.h"
#include "shading/noise.h"

/* The quintic fade 6t^5 - 15t^4 + 10t^3: its first and second derivatives
 * vanish at 0 and 1, so the noise is smooth across cells. */
static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

/* The dot product of (x, y, z) with corner gradient h % 12: the twelve
 * (+-1, +-1, 0) directions and their turns. */
static double gradient_dot(uint32_t h, double x, double y, double z)
{
    switch (h % 12) {
    case 0: return x + y;
    case 1: return -x + y;
    case 2: return x - y;
    case 3: return -x - y;
    case 4: return x + z;
    case 5: return -x + z;
    case 6: return x - z;
    case 7: return -x - z;
    case 8: return y + z;
    case 9: return -y + z;
    case 10: return y - z;
    default: return -y - z;
    }
}

static double lerp(double a, double b, double t) { return a + t * (b - a); }

/* A lattice coordinate as the hash takes it: two's complement, wrapping. */
static uint32_t lattice(double whole) { return (uint32_t)(int64_t)whole; }

double noise_at(vec3 p, uint32_t layer)
{
    const double far = 1e15; /* past this, a double has no fraction left to vary */
    if (!(fabs(p.x) < far && fabs(p.y) < far && fabs(p.z) < far))
        return 0;
    double fx = floor(p.x), fy = floor(p.y), fz = floor(p.z);
    double x = p.x - fx, y = p.y - fy, z = p.z - fz;
    uint32_t ix = lattice(fx), iy = lattice(fy), iz = lattice(fz);
    double corner[8];
    for (int c = 0; c < 8; c++) {
        int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
        uint32_t h = hash4(ix + (uint32_t)dx, iy + (uint32_t)dy, iz + (uint32_t)dz, layer);
        corner[c] = gradient_dot(h, x - dx, y - dy, z - dz);
    }
    double u = fade(x), v = fade(y), w = fade(z);
    double y0 = lerp(lerp(corner[0], corner[1], u), lerp(corner[2], corner[3], u), v);
    double y1 = lerp(lerp(corner[4], corner[5], u), lerp(corner[6], corner[7], u), v);
    return lerp(y0, y1, w);
}

/* The octaves' sum of noise or of its magnitude, over their amplitudes. */
static double octave_sum(vec3 p, noise_octaves o, bool magnitude)
{
    double sum = 0, amplitude = 1, total = 0, frequency = 1;
    for (int i = 0; i < o.count; i++) {
        double n = noise_at(v3_scale(p, frequency), (uint32_t)i);
        sum += amplitude * (magnitude ? fabs(n) : n);
        total += amplitude;
        amplitude *= o.gain;
        frequency *= o.lacunarity;
    }
    return total > 0 ? sum / total : 0;
}

double noise_fbm(vec3 p, noise_octaves o) { return octave_sum(p, o, false); }

double noise_turbulence(vec3 p, noise_octaves o) { return octave_sum(p, o, true); }
