/* lanes.h - four doubles as one GCC vector, for code that works on a
 * packet's lanes (RAY8 = 8, so two quads): arithmetic on a quad is one
 * operation whatever the processor (one AVX instruction, or two SSE2 ones
 * in a generic x86-64 build). Quads, not 8-wide vectors: on processors with
 * AVX-512 those become 512-bit instructions, whose divisions and square
 * roots lower the clock of the whole core (measured: slower). Each lane's
 * result is the correctly rounded IEEE result of the same operation on that
 * lane alone, so code written on quads gives the same bits as scalar code
 * with the same operations in the same order (nothing is fused: every build
 * has -ffp-contract=off). */
#ifndef GLINT_CORE_LANES_H
#define GLINT_CORE_LANES_H

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>
#include "core/vec.h"

#define QUAD 4
_Static_assert(RAY8 % QUAD == 0, "a packet is whole quads");

/* Four doubles, a quad, and the masks that comparing them gives: all bits set in a
 * lane where the comparison holds, none where it does not (nor where either
 * side is NaN, except for !=). */
typedef double quad_f64 __attribute__((vector_size(QUAD * sizeof(double))));
typedef int64_t quad_mask __attribute__((vector_size(QUAD * sizeof(int64_t))));
/* Four floats, and four 32-bit integers (also a float comparison's mask). */
typedef float quad_f32 __attribute__((vector_size(QUAD * sizeof(float))));
typedef int32_t quad_i32 __attribute__((vector_size(QUAD * sizeof(int32_t))));

/* The four doubles at p, which need no more than double alignment. */
static inline quad_f64 quad_load(const double *p)
{
    quad_f64 v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* Stores the lanes of v at p. */
static inline void quad_store(double *p, quad_f64 v) { memcpy(p, &v, sizeof v); }

/* x in every lane (x + a zero quad would turn -0 into +0; this keeps it). */
static inline quad_f64 quad_splat(double x) { return (quad_f64){x, x, x, x}; }

/* Lane by lane, m ? a : b. */
static inline quad_f64 quad_select(quad_mask m, quad_f64 a, quad_f64 b)
{
    quad_mask ai, bi;
    memcpy(&ai, &a, sizeof ai);
    memcpy(&bi, &b, sizeof bi);
    quad_mask r = (ai & m) | (bi & ~m);
    quad_f64 v;
    memcpy(&v, &r, sizeof v);
    return v;
}

/* Lane by lane, m ? a : b, for masks (and the integers kept in them). */
static inline quad_mask quad_mask_select(quad_mask m, quad_mask a, quad_mask b) { return (a & m) | (b & ~m); }

/* Lane by lane, m ? a : b, for 32-bit integers and their comparisons' masks. */
static inline quad_i32 quad_i32_select(quad_i32 m, quad_i32 a, quad_i32 b) { return (a & m) | (b & ~m); }

/* The absolute value of every lane, as fabs's: the sign bit cleared. */
static inline quad_f64 quad_abs(quad_f64 v)
{
    quad_mask bits;
    memcpy(&bits, &v, sizeof bits);
    bits &= INT64_MAX;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* The square root of every lane, correctly rounded as sqrt's. */
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
static inline quad_f64 quad_sqrt(quad_f64 v)
{
#if defined(__AVX__)
    return (quad_f64)_mm256_sqrt_pd((__m256d)v);
#else
    __m128d lo = _mm_sqrt_pd((__m128d){v[0], v[1]}), hi = _mm_sqrt_pd((__m128d){v[2], v[3]});
    return (quad_f64){lo[0], lo[1], hi[0], hi[1]};
#endif
}
#else
static inline quad_f64 quad_sqrt(quad_f64 v) { return (quad_f64){sqrt(v[0]), sqrt(v[1]), sqrt(v[2]), sqrt(v[3])}; }
#endif

/* floor of every lane, as floor's. */
static inline quad_f64 quad_floor(quad_f64 v)
{
#if defined(__AVX__)
    return (quad_f64)_mm256_round_pd((__m256d)v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
#elif defined(__SSE4_1__)
    /* The halves named first: _mm_floor_pd is a macro, and a compound
     * literal's commas would split its argument. */
    const __m128d low = {v[0], v[1]}, high = {v[2], v[3]};
    __m128d lo = _mm_floor_pd(low), hi = _mm_floor_pd(high);
    return (quad_f64){lo[0], lo[1], hi[0], hi[1]};
#else
    return (quad_f64){floor(v[0]), floor(v[1]), floor(v[2]), floor(v[3])};
#endif
}

/* flags[i] = lane i of m is set (m a mask: each lane all bits set or
 * none, as comparisons give). With AVX, the lanes' sign bits as four
 * bits, each multiplied to the bottom of its own byte (bit i lands on bit
 * 8i, and no other sum of shifts does): GCC 12 narrows a quad to bytes a
 * lane at a time, through general registers (20 instructions, where these
 * take 4). */
static inline void quad_mask_store(bool flags[QUAD], quad_mask m)
{
#if defined(__AVX__)
    uint32_t bits = (uint32_t)_mm256_movemask_pd((__m256d)m);
    uint32_t bytes = (bits * 0x00204081u) & 0x01010101u;
    memcpy(flags, &bytes, sizeof bytes);
#else
    typedef uint8_t quad_bytes __attribute__((vector_size(QUAD)));
    quad_bytes b = __builtin_convertvector(m, quad_bytes) & 1;
    memcpy(flags, &b, sizeof b);
#endif
}

/* The mask of the lanes where flags[i] is true. */
static inline quad_mask quad_from_bools(const bool flags[QUAD])
{
    typedef uint8_t quad_bytes __attribute__((vector_size(QUAD)));
    quad_bytes b;
    memcpy(&b, flags, sizeof b);
    return __builtin_convertvector(b != 0, quad_mask);
}

/* Whether any lane of m is set. */
static inline bool quad_any(quad_mask m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

/* The mask of the lanes where a[i] != b. */
static inline quad_mask quad_int_ne(const int a[QUAD], int b)
{
    quad_i32 v;
    memcpy(&v, a, sizeof v);
    return __builtin_convertvector(v != b, quad_mask);
}

/* Each lane of v widened to double (exactly): one instruction with AVX,
 * where GCC 12 converts each half and joins them, through memory when
 * its registers are short. */
static inline quad_f64 quad_widen(quad_f32 v)
{
#if defined(__AVX__)
    return (quad_f64)_mm256_cvtps_pd((__m128)v);
#else
    return __builtin_convertvector(v, quad_f64);
#endif
}

/* The four floats at p, each widened to double (exactly). */
static inline quad_f64 quad_from_floats(const float *p)
{
    quad_f32 v;
    memcpy(&v, p, sizeof v);
    return quad_widen(v);
}

/* Each lane of v rounded to float, as a cast rounds it. */
static inline quad_f32 quad_to_floats(quad_f64 v) { return __builtin_convertvector(v, quad_f32); }

/* A float bound for a double-precision distance t >= 0, such as Embree's
 * far end for a ray tested exactly in double: the next float above
 * (float)t, so float traversal never stops short of t, or infinity past
 * float's range. nextafterf((float)t, INFINITY) without the library call,
 * as this runs for every ray: the bits of a non-negative float count up
 * with its value, from +0 (bits 0) to the smallest subnormal (bits 1). */
static inline float float_far(double t)
{
    float x = (float)t;
    if (!(x < FLT_MAX))
        return INFINITY;
    uint32_t b;
    memcpy(&b, &x, sizeof b);
    b += 1;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* float_far of every lane of t, stored at out: the same steps on four
 * lanes at once, the same bits. */
static inline void quad_float_far(quad_f64 t, float out[QUAD])
{
    quad_f32 x = quad_to_floats(t), infinite = {INFINITY, INFINITY, INFINITY, INFINITY};
    quad_i32 bits, inf;
    memcpy(&bits, &x, sizeof bits);
    memcpy(&inf, &infinite, sizeof inf);
    quad_i32 finite = x < FLT_MAX;
    bits = ((bits + 1) & finite) | (inf & ~finite);
    memcpy(out, &bits, sizeof bits);
}

/* The dot product of (ax, ay, az) and (bx, by, bz) in every lane, added in
 * v3_dot's order. */
static inline quad_f64 quad_dot(quad_f64 ax, quad_f64 ay, quad_f64 az, quad_f64 bx, quad_f64 by, quad_f64 bz)
{
    return ax * bx + ay * by + az * bz;
}

#endif
