/* noise.c - hashed gradient noise and its fractal sums (noise.h). */
#include <math.h>
#include "core/hash.h"
#include "shading/noise.h"

/* The quintic fade 6t^5 - 15t^4 + 10t^3: its first and second derivatives
 * vanish at 0 and 1, so the noise is smooth across cells. */
static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

/* The corner gradients: the twelve (+-1, +-1, 0) directions and their
 * turns, four of them twice over to make sixteen, so that four bits of a
 * hash choose one without a division (and, read from a table, without a
 * branch the processor cannot predict). */
static const double GRADIENT[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {-1, 1, 0}, {0, -1, 1}, {0, -1, -1},
};

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
    /* A corner's hash is built an axis at a time, so corners sharing x (and
     * then y) share that much of it: 14 rounds for the 8 corners. */
    uint32_t seed = hash_u32(layer ^ 0x9e3779b9U), hx[2], hxy[4];
    for (int dx = 0; dx < 2; dx++)
        hx[dx] = hash_u32(seed ^ (ix + (uint32_t)dx));
    for (int c = 0; c < 4; c++)
        hxy[c] = hash_u32(hx[c & 1] ^ (iy + (uint32_t)(c >> 1)));
    double corner[8];
    for (int c = 0; c < 8; c++) {
        int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
        const double *g = GRADIENT[hash_u32(hxy[c & 3] ^ (iz + (uint32_t)dz)) >> 28];
        corner[c] = g[0] * (x - dx) + g[1] * (y - dy) + g[2] * (z - dz);
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
