/* noise.c - hashed gradient noise and its fractal sums (noise.h). A
 * packet's lanes on one noise-textured thing are read four at a time, and
 * two octaves of those four points in one eight-lane vector: one 512-bit
 * instruction a step where the processor has them (the noise has no
 * division or square root, whose 512-bit forms slow the core: see
 * core/lanes.h), and elsewhere the narrower instructions two quads took
 * before. */
#include <math.h>
#include <string.h>
#include "core/hash.h"
#include "shading/noise.h"

/* Eight lanes: the four points of one octave, then of the next. */
#define OCTO (2 * QUAD)
typedef double octo_f64 __attribute__((vector_size(OCTO * sizeof(double))));
typedef int64_t octo_mask __attribute__((vector_size(OCTO * sizeof(int64_t))));
typedef uint64_t octo_u64 __attribute__((vector_size(OCTO * sizeof(uint64_t))));
typedef uint32_t octo_u32 __attribute__((vector_size(OCTO * sizeof(uint32_t))));

static inline octo_f64 octo_splat(double x) { return (octo_f64){x, x, x, x, x, x, x, x}; }

/* Quad a in lanes 0 to 3, b in 4 to 7. */
static inline octo_f64 octo_join(quad_f64 a, quad_f64 b) { return __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7); }

static inline quad_f64 octo_low(octo_f64 v) { return __builtin_shufflevector(v, v, 0, 1, 2, 3); }

static inline quad_f64 octo_high(octo_f64 v) { return __builtin_shufflevector(v, v, 4, 5, 6, 7); }

/* Lane by lane, m ? a : b (a cast between vectors of one size keeps the
 * bits). */
static inline octo_f64 octo_select(octo_mask m, octo_f64 a, octo_f64 b)
{
    return (octo_f64)(((octo_mask)a & m) | ((octo_mask)b & ~m));
}

/* All bits set in each lane whose bit 0 is set, none elsewhere. Masks are
 * made by arithmetic, not by comparing: without AVX-512, GCC splits a
 * comparison of eight 64-bit lanes into eight scalar ones (a compare, a
 * set and a move each), where a subtraction is two 256-bit instructions. */
static inline octo_mask low_bit_mask(octo_u64 v) { return (octo_mask)((octo_u64){0} - (v & 1)); }

/* All bits set in each lane whose non-negative (or NaN) double is below
 * `limit`, a positive finite one; by their bits, which order such doubles
 * as their values (a NaN's bits lie above every finite one's, so it is
 * not below, as `<` says). */
static inline octo_mask below(octo_f64 magnitude, double limit)
{
    uint64_t l;
    memcpy(&l, &limit, sizeof l);
    const octo_u64 lim = {l, l, l, l, l, l, l, l};
    return low_bit_mask(((octo_u64)magnitude - lim) >> 63);
}

/* The absolute value of every lane: the sign bit cleared. */
static inline octo_f64 octo_abs(octo_f64 v) { return (octo_f64)((octo_mask)v & INT64_MAX); }

/* floor of every lane, as floor's. */
static inline octo_f64 octo_floor(octo_f64 v)
{
#if defined(__AVX512F__)
    return (octo_f64)_mm512_roundscale_pd((__m512d)v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
#else
    return octo_join(quad_floor(octo_low(v)), quad_floor(octo_high(v)));
#endif
}

/* hash_u32 of every lane. */
static inline octo_u32 octo_hash(octo_u32 x)
{
    HASH_U32_STEPS(x);
    return x;
}

/* The quintic fade 6t^5 - 15t^4 + 10t^3: its first and second derivatives
 * vanish at 0 and 1, so the noise is smooth across cells. */
static inline octo_f64 fade(octo_f64 t) { return t * t * t * (t * (t * octo_splat(6) - octo_splat(15)) + octo_splat(10)); }

static inline octo_f64 lerp(octo_f64 a, octo_f64 b, octo_f64 t) { return a + t * (b - a); }

/* A lattice coordinate as the hash takes it: the whole number's low 32
 * bits, two's complement. Adding 1.5 2^52 to a whole number under 2^51 in
 * magnitude leaves it, so, in the low bits of the sum's. */
static inline octo_u32 lattice(octo_f64 whole)
{
    octo_f64 shifted = whole + octo_splat(0x1.8p52);
    return __builtin_convertvector((octo_mask)shifted, octo_u32);
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
 * shifted out by the index: one shift a lane, where four lanes' look-ups
 * would be one at a time, and four shifts (a set of indices as bits for
 * each choice) had cost the noise 5% more. */
#define GRADIENT_NIBBLES 0xc473c840d951fb73ULL
static inline octo_f64 gradient_dot(octo_u32 g32, octo_f64 x, octo_f64 y, octo_f64 z)
{
    const uint64_t n = GRADIENT_NIBBLES, s = 1ULL << 63;
    const octo_u64 nibbles = {n, n, n, n, n, n, n, n}, sign = {s, s, s, s, s, s, s, s};
    octo_u64 choice = nibbles >> (__builtin_convertvector(g32, octo_u64) << 2);
    octo_f64 a = octo_select(low_bit_mask(choice), x, y);
    octo_f64 b = octo_select(low_bit_mask(choice >> 1), y, z);
    a = (octo_f64)((octo_u64)a ^ (choice << 61 & sign));
    b = (octo_f64)((octo_u64)b ^ (choice << 60 & sign));
    return a + b;
}

/* The noise at eight points, (px, py, pz) lane by lane: lanes 0 to 3 of
 * layer `layers[0]`, 4 to 7 of `layers[1]`. Always inline: without
 * AVX-512 a call passes and returns its 512-bit vectors through memory
 * (textured row 5% slower so). */
static inline __attribute__((always_inline)) octo_f64 noise_at8(octo_f64 px, octo_f64 py, octo_f64 pz, const uint32_t layers[2])
{
    const double far = 1e15; /* past this, a double has no fraction left to vary */
    octo_mask near = below(octo_abs(px), far) & below(octo_abs(py), far) & below(octo_abs(pz), far);
    octo_f64 zero = octo_splat(0), one = octo_splat(1);
    px = octo_select(near, px, zero);
    py = octo_select(near, py, zero);
    pz = octo_select(near, pz, zero);
    octo_f64 fx = octo_floor(px), fy = octo_floor(py), fz = octo_floor(pz);
    octo_f64 x = px - fx, y = py - fy, z = pz - fz;
    octo_u32 ix = lattice(fx), iy = lattice(fy), iz = lattice(fz);
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
    octo_f64 xs[2] = {x, x - one}, ys[2] = {y, y - one}, zs[2] = {z, z - one}, corner[8];
    for (int c = 0; c < 8; c++) {
        octo_u32 g = octo_hash(hxy[c & 3] ^ (iz + (uint32_t)(c >> 2))) >> 28;
        corner[c] = gradient_dot(g, xs[c & 1], ys[(c >> 1) & 1], zs[c >> 2]);
    }
    octo_f64 u = fade(x), v = fade(y), w = fade(z);
    octo_f64 y0 = lerp(lerp(corner[0], corner[1], u), lerp(corner[2], corner[3], u), v);
    octo_f64 y1 = lerp(lerp(corner[4], corner[5], u), lerp(corner[6], corner[7], u), v);
    return octo_select(near, lerp(y0, y1, w), zero);
}

quad_f64 noise_at4(const quad_f64 p[3], uint32_t layer)
{
    const uint32_t layers[2] = {layer, layer};
    return octo_low(noise_at8(octo_join(p[0], p[0]), octo_join(p[1], p[1]), octo_join(p[2], p[2]), layers));
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
    const octo_f64 x = octo_join(p[0], p[0]), y = octo_join(p[1], p[1]), z = octo_join(p[2], p[2]);
    for (int i = 0; i < o.count; i += 2) {
        /* A last odd octave is paired with itself, its copy not added. */
        int pair = i + 1 < o.count ? 2 : 1;
        octo_f64 f = octo_join(quad_splat(frequency), quad_splat(pair == 2 ? frequency * o.lacunarity : frequency));
        const uint32_t layers[2] = {(uint32_t)i, (uint32_t)(i + pair - 1)};
        octo_f64 n = noise_at8(x * f, y * f, z * f, layers);
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
