/* noise.c - hashed gradient noise and its fractal sums (noise.h), four
 * points at a time: a packet's lanes on one noise-textured thing are read
 * together, and one point is read as four alike. */
#include <math.h>
#include <string.h>
#include "core/hash.h"
#include "shading/noise.h"

typedef uint32_t quad_u32 __attribute__((vector_size(QUAD * sizeof(uint32_t))));

/* hash_u32 of every lane. */
static inline quad_u32 quad_hash(quad_u32 x)
{
    HASH_U32_STEPS(x);
    return x;
}

/* The quintic fade 6t^5 - 15t^4 + 10t^3: its first and second derivatives
 * vanish at 0 and 1, so the noise is smooth across cells. */
static inline quad_f64 fade(quad_f64 t)
{
    return t * t * t * (t * (t * quad_splat(6) - quad_splat(15)) + quad_splat(10));
}

static inline quad_f64 lerp(quad_f64 a, quad_f64 b, quad_f64 t) { return a + t * (b - a); }

/* A lattice coordinate as the hash takes it: the whole number's low 32
 * bits, two's complement. Adding 1.5 2^52 to a whole number under 2^51 in
 * magnitude leaves it, so, in the low bits of the sum's. */
static inline quad_u32 lattice(quad_f64 whole)
{
    quad_f64 shifted = whole + quad_splat(0x1.8p52);
    quad_mask bits;
    memcpy(&bits, &shifted, sizeof bits);
    return __builtin_convertvector(bits, quad_u32);
}

typedef uint64_t quad_u64 __attribute__((vector_size(QUAD * sizeof(uint64_t))));

/* The dot product of corner gradient g (a hash's top four bits, 0 to 15)
 * with the offset (x, y, z) from its corner. The gradients are the twelve
 * (+-1, +-1, 0) directions and their turns, four of them twice over to
 * make sixteen; index by index:
 *    0 ( 1, 1, 0)   4 ( 1, 0, 1)   8 (0,  1,  1)  12 ( 1, 1, 0)
 *    1 (-1, 1, 0)   5 (-1, 0, 1)   9 (0, -1,  1)  13 (-1, 1, 0)
 *    2 ( 1,-1, 0)   6 ( 1, 0,-1)  10 (0,  1, -1)  14 (0, -1, 1)
 *    3 (-1,-1, 0)   7 (-1, 0,-1)  11 (0, -1, -1)  15 (0, -1,-1)
 * so the product is a + b, a the first axis the gradient has (x or y) and
 * b the second (y or z), each of its sign: the value of the three
 * products' sum, whose other product is a zero, which adds nothing (its
 * sign aside). a is x for 0 to 7, 12 and 13, b is y for 0 to 3, 12 and
 * 13; a is negative for 1, 3, 5, 7, 9, 11, 13, 14 and 15, b for 2, 3, 6,
 * 7, 10, 11 and 15. Each index's four choices are a nibble of one
 * constant (bit 0: a is x, 1: b is y, 2: a negative, 3: b negative),
 * shifted out by the index: one shift a lane, where four lanes' look-ups
 * would be one at a time, and four shifts (a set of indices as bits for
 * each choice) had cost the noise 5% more. */
#define GRADIENT_NIBBLES 0xc473c840d951fb73ULL
static inline quad_f64 gradient_dot(quad_u32 g32, quad_f64 x, quad_f64 y, quad_f64 z)
{
    const quad_u64 nibbles = {GRADIENT_NIBBLES, GRADIENT_NIBBLES, GRADIENT_NIBBLES, GRADIENT_NIBBLES};
    quad_u64 choice = nibbles >> (__builtin_convertvector(g32, quad_u64) << 2);
    quad_f64 a = quad_select((quad_mask)((choice & 1) != 0), x, y);
    quad_f64 b = quad_select((quad_mask)((choice & 2) != 0), y, z);
    quad_u64 a_bits, b_bits, sign = {1ULL << 63, 1ULL << 63, 1ULL << 63, 1ULL << 63};
    memcpy(&a_bits, &a, sizeof a_bits);
    memcpy(&b_bits, &b, sizeof b_bits);
    a_bits ^= choice << 61 & sign;
    b_bits ^= choice << 60 & sign;
    memcpy(&a, &a_bits, sizeof a);
    memcpy(&b, &b_bits, sizeof b);
    return a + b;
}

quad_f64 noise_at4(const quad_f64 p[3], uint32_t layer)
{
    const double far = 1e15; /* past this, a double has no fraction left to vary */
    quad_mask near = (quad_abs(p[0]) < far) & (quad_abs(p[1]) < far) & (quad_abs(p[2]) < far);
    quad_f64 zero = quad_splat(0), one = quad_splat(1);
    quad_f64 px = quad_select(near, p[0], zero), py = quad_select(near, p[1], zero), pz = quad_select(near, p[2], zero);
    quad_f64 fx = quad_floor(px), fy = quad_floor(py), fz = quad_floor(pz);
    quad_f64 x = px - fx, y = py - fy, z = pz - fz;
    quad_u32 ix = lattice(fx), iy = lattice(fy), iz = lattice(fz);
    /* A corner's hash is built an axis at a time, so corners sharing x (and
     * then y) share that much of it: 14 rounds for the 8 corners. */
    uint32_t seed = hash_u32(layer ^ 0x9e3779b9U);
    quad_u32 hx[2], hxy[4];
    for (int dx = 0; dx < 2; dx++)
        hx[dx] = quad_hash(seed ^ (ix + (uint32_t)dx));
    for (int c = 0; c < 4; c++)
        hxy[c] = quad_hash(hx[c & 1] ^ (iy + (uint32_t)(c >> 1)));
    /* The offsets from the cell's near and far corners along each axis. */
    quad_f64 xs[2] = {x, x - one}, ys[2] = {y, y - one}, zs[2] = {z, z - one}, corner[8];
    for (int c = 0; c < 8; c++) {
        quad_u32 g = quad_hash(hxy[c & 3] ^ (iz + (uint32_t)(c >> 2))) >> 28;
        corner[c] = gradient_dot(g, xs[c & 1], ys[(c >> 1) & 1], zs[c >> 2]);
    }
    quad_f64 u = fade(x), v = fade(y), w = fade(z);
    quad_f64 y0 = lerp(lerp(corner[0], corner[1], u), lerp(corner[2], corner[3], u), v);
    quad_f64 y1 = lerp(lerp(corner[4], corner[5], u), lerp(corner[6], corner[7], u), v);
    return quad_select(near, lerp(y0, y1, w), zero);
}

double noise_at(vec3 p, uint32_t layer)
{
    quad_f64 q[3] = {quad_splat(p.x), quad_splat(p.y), quad_splat(p.z)};
    return noise_at4(q, layer)[0];
}

/* The octaves' sum of noise or of its magnitude, over their amplitudes. */
static inline quad_f64 octave_sum(const quad_f64 p[3], noise_octaves o, bool magnitude)
{
    quad_f64 sum = quad_splat(0);
    double amplitude = 1, total = 0, frequency = 1;
    for (int i = 0; i < o.count; i++) {
        quad_f64 f = quad_splat(frequency), at[3] = {p[0] * f, p[1] * f, p[2] * f};
        quad_f64 n = noise_at4(at, (uint32_t)i);
        sum += quad_splat(amplitude) * (magnitude ? quad_abs(n) : n);
        total += amplitude;
        amplitude *= o.gain;
        frequency *= o.lacunarity;
    }
    return total > 0 ? sum / quad_splat(total) : quad_splat(0);
}

quad_f64 noise_fbm4(const quad_f64 p[3], noise_octaves o) { return octave_sum(p, o, false); }

quad_f64 noise_turbulence4(const quad_f64 p[3], noise_octaves o) { return octave_sum(p, o, true); }
