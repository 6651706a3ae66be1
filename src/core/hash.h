/* hash.h - stateless random numbers: a hash of (pixel, sample, seed), so
 * every sample's randomness is the same whichever thread computes it. */
#ifndef GLINT_CORE_HASH_H
#define GLINT_CORE_HASH_H

#include <stdint.h>

/* The steps of a 32-bit integer finaliser with good avalanche (lowbias32
 * constants) on x, in place: an unsigned 32-bit integer or a vector of
 * them, so that hash_u32 and its four-lane form (noise.c) are one
 * definition. */
#define HASH_U32_STEPS(x) \
    ((x) ^= (x) >> 16, (x) *= 0x7feb352dU, (x) ^= (x) >> 15, (x) *= 0x846ca68bU, (x) ^= (x) >> 16)

static inline uint32_t hash_u32(uint32_t x)
{
    HASH_U32_STEPS(x);
    return x;
}

/* Combines four values into one well-mixed hash. */
static inline uint32_t hash4(uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
    return hash_u32(hash_u32(hash_u32(hash_u32(a) ^ b) ^ c) ^ d);
}

/* Maps a hash to [0, 1) with 24 bits of precision. */
static inline double hash_unit(uint32_t h) { return (h >> 8) * (1.0 / 16777216.0); }

#endif
