/* noise.c - hashed gradient noise and its fractal sums (noise.h). A
 * packet's lanes on one noise-textured thing are read four at a time, and
 * two octaves of those four points in one eight-lane vector of floats:
 * each point's lattice cell and its offset in the cell are found in double
 * precision, and the hashing, gradients and blending (an offset's, from 0
 * to 1) in single, eight lanes a 256-bit instruction. In double, the
 * eight lanes were two vectors (or one of 512 bits) a step: the textured
 * bench row took 8% more time (profile-guided builds, one thread). */
#include "core/hash.h"
#include "shading/noise.h"

/* Eight lanes: the four points of one octave, then of the next. The
 * points come in as doubles; each is split into its lattice cell and its
 * offset in the cell, and the rest is single precision, where eight lanes
 * are one 256-bit vector: an offset is from 0 to 1, where a float keeps
 * seven digits, and the cell's number is hashed exactly. */
#define OCTO (2 * QUAD)
typedef float octo_f32 __attribute__((vector_size(OCTO * sizeof(float))));
typedef int32_t octo_i32 __attribute__((vector_size(OCTO * sizeof(int32_t))));
typedef uint32_t octo_u32 __attribute__((vector_size(OCTO * sizeof(uint32_t))));
typedef uint32_t quad_u32 __attribute__((vector_size(QUAD * sizeof(uint32_t))));

static inline octo_f32 octo_splat(float x) { return (octo_f32){x, x, x, x, x, x, x, x}; }

static inline octo_u32 octo_splat_u32(uint32_t x) { return (octo_u32){x, x, x, x, x, x, x, x}; }

/* Quads a (lanes 0 to 3) and b (4 to 7) of doubles, each rounded to
 * float as a cast rounds it. */
static inline octo_f32 octo_floats(quad_f64 a, quad_f64 b)
{
    return __builtin_shufflevector(quad_to_floats(a), quad_to_floats(b), 0, 1, 2, 3, 4, 5, 6, 7);
}

/* Lane by lane, m ? a : b, m's lanes all bits set or none (a cast between
 * vectors of one size keeps the bits). */
static inline octo_f32 octo_select(octo_i32 m, octo_f32 a, octo_f32 b)
{
    return (octo_f32)(((octo_i32)a & m) | ((octo_i32)b & ~m));
}

/* The absolute value of every lane: the sign bit cleared. */
static inline octo_f32 octo_abs(octo_f32 v) { return (octo_f32)((octo_i32)v & INT32_MAX); }

/* All bits set in each lane whose bit `bit` is set, none elsewhere. */
static inline octo_i32 bit_mask(octo_u32 v, int bit) { return (octo_i32)(v << (31 - bit)) >> 31; }

/* hash_u32 of every lane. */
static inline octo_u32 octo_hash(octo_u32 x)
{
    HASH_U32_STEPS(x);
    return x;
}

/* The quintic fade 6t^5 - 15t^4 + 10t^3: its first and second derivatives
 * vanish at 0 and 1, so the noise is smooth across cells. */
static inline octo_f32 fade(octo_f32 t) { return t * t * t * (t * (t * octo_splat(6) - octo_splat(15)) + octo_splat(10)); }

static inline octo_f32 lerp(octo_f32 a, octo_f32 b, octo_f32 t) { return a + t * (b - a); }

/* A lattice coordinate as the hash takes it: the whole number's low 32
 * bits, two's complement. Adding 1.5 2^52 to a whole number under 2^51 in
 * magnitude leaves it, so, in the low bits of the sum's. */
static inline quad_u32 lattice(quad_f64 whole)
{
    quad_f64 shifted = whole + quad_splat(0x1.8p52);
    return __builtin_convertvector((quad_mask)shifted, quad_u32);
}

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
 * shifted out by the index (from the half of the constant g's bit 3
 * picks): one shift a lane, where four lanes' look-ups would be one at a
 * time, and four shifts (a set of indices as bits for each choice) had
 * cost the noise 5% more. */
#define GRADIENT_NIBBLES 0xc473c840d951fb73ULL
static inline octo_f32 gradient_dot(octo_u32 g, octo_f32 x, octo_f32 y, octo_f32 z)
{
    const uint32_t low = (uint32_t)GRADIENT_NIBBLES, high = (uint32_t)(GRADIENT_NIBBLES >> 32);
    octo_u32 half = octo_splat_u32(low) ^ (octo_splat_u32(low ^ high) & (octo_u32)bit_mask(g, 3));
    octo_u32 choice = half >> ((g & 7) << 2);
    octo_f32 a = octo_select(bit_mask(choice, 0), x, y);
    octo_f32 b = octo_select(bit_mask(choice, 1), y, z);
    const octo_u32 sign = octo_splat_u32(1U << 31);
    a = (octo_f32)((octo_u32)a ^ (choice << 29 & sign));
    b = (octo_f32)((octo_u32)b ^ (choice << 28 & sign));
    return a + b;
}

/* The noise at eight points, lane by lane: the lanes of low[0] (x),
 * low[1] (y) and low[2] (z) of layer `layers[0]`, then high's of
 * `layers[1]`. Always inline: a call would pass its vectors through
 * memory. */
static inline __attribute__((always_inline)) octo_f32 noise_at8(const quad_f64 low[3], const quad_f64 high[3], const uint32_t layers[2])
{
    /* Past 1e15 a double has no fraction left to vary (and past 2^51 the
     * lattice's trick fails): those lanes, and those not finite, are 0.
     * Their cells and offsets are computed all the same, as garbage the
     * last step drops. */
    octo_i32 near = ~(octo_i32){0};
    octo_f32 offset[3];
    octo_u32 cell[3];
    for (int k = 0; k < 3; k++) {
        near &= octo_abs(octo_floats(low[k], high[k])) < octo_splat(1e15f);
        quad_f64 low_cell = quad_floor(low[k]), high_cell = quad_floor(high[k]);
        offset[k] = octo_floats(low[k] - low_cell, high[k] - high_cell);
        cell[k] = __builtin_shufflevector(lattice(low_cell), lattice(high_cell), 0, 1, 2, 3, 4, 5, 6, 7);
    }
    const octo_f32 x = offset[0], y = offset[1], z = offset[2];
    const octo_u32 ix = cell[0], iy = cell[1], iz = cell[2];
    /* A corner's hash is built an axis at a time, so corners sharing x (and
     * then y) share that much of it: 14 rounds for the 8 corners. */
    uint32_t s0 = hash_u32(layers[0] ^ 0x9e3779b9U), s1 = hash_u32(layers[1] ^ 0x9e3779b9U);
    const octo_u32 seed = {s0, s0, s0, s0, s1, s1, s1, s1};
    octo_u32 hx[2], hxy[4];
    for (int dx = 0; dx < 2; dx++)
        hx[dx] = octo_hash(seed ^ (ix + (uint32_t)dx));
    for (int c = 0; c < 4; c++)
        hxy[c] = octo_hash(hx[c & 1] ^ (iy + (uint32_t)(c >> 1)));
    /* The offsets from the cell's near and far corners along each axis. */
    const octo_f32 one = octo_splat(1);
    octo_f32 xs[2] = {x, x - one}, ys[2] = {y, y - one}, zs[2] = {z, z - one}, corner[8];
#pragma GCC unroll 8
    for (int c = 0; c < 8; c++) {
        octo_u32 g = octo_hash(hxy[c & 3] ^ (iz + (uint32_t)(c >> 2))) >> 28;
        corner[c] = gradient_dot(g, xs[c & 1], ys[(c >> 1) & 1], zs[c >> 2]);
    }
    octo_f32 u = fade(x), v = fade(y), w = fade(z);
    octo_f32 y0 = lerp(lerp(corner[0], corner[1], u), lerp(corner[2], corner[3], u), v);
    octo_f32 y1 = lerp(lerp(corner[4], corner[5], u), lerp(corner[6], corner[7], u), v);
    return octo_select(near, lerp(y0, y1, w), octo_splat(0));
}

/* Lanes 0 to 3 of v, widened to double. */
static inline quad_f64 octo_low(octo_f32 v) { return quad_widen(__builtin_shufflevector(v, v, 0, 1, 2, 3)); }

/* Lanes 4 to 7 of v, widened to double. */
static inline quad_f64 octo_high(octo_f32 v) { return quad_widen(__builtin_shufflevector(v, v, 4, 5, 6, 7)); }

quad_f64 noise_at4(const quad_f64 p[3], uint32_t layer)
{
    const uint32_t layers[2] = {layer, layer};
    return octo_low(noise_at8(p, p, layers));
}

double noise_at(vec3 p, uint32_t layer)
{
    quad_f64 q[3] = {quad_splat(p.x), quad_splat(p.y), quad_splat(p.z)};
    return noise_at4(q, layer)[0];
}

/* The octaves' sum of noise or of its magnitude, over their amplitudes,
 * two octaves a step and added one at a time, in order. */
static inline quad_f64 octave_sum(const quad_f64 p[3], noise_octaves o, bool magnitude)
{
    quad_f64 sum = quad_splat(0);
    double amplitude = 1, total = 0, frequency = 1;
    for (int i = 0; i < o.count; i += 2) {
        /* A last odd octave is paired with itself, its copy not added. */
        int pair = i + 1 < o.count ? 2 : 1;
        quad_f64 f = quad_splat(frequency), next_f = quad_splat(pair == 2 ? frequency * o.lacunarity : frequency);
        const quad_f64 low[3] = {p[0] * f, p[1] * f, p[2] * f}, high[3] = {p[0] * next_f, p[1] * next_f, p[2] * next_f};
        const uint32_t layers[2] = {(uint32_t)i, (uint32_t)(i + pair - 1)};
        octo_f32 n = noise_at8(low, high, layers);
        if (magnitude)
            n = octo_abs(n);
        const quad_f64 octave[2] = {octo_low(n), octo_high(n)};
        for (int k = 0; k < pair; k++) {
            sum += quad_splat(amplitude) * octave[k];
            total += amplitude;
            amplitude *= o.gain;
            frequency *= o.lacunarity;
        }
    }
    return total > 0 ? sum / quad_splat(total) : quad_splat(0);
}

quad_f64 noise_fbm4(const quad_f64 p[3], noise_octaves o) { return octave_sum(p, o, false); }

quad_f64 noise_turbulence4(const quad_f64 p[3], noise_octaves o) { return octave_sum(p, o, true); }
