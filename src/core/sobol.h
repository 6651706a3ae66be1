/* sobol.h - Sobol's sequence, scrambled: well spread sample points for
 * any count, that stay well spread as a pixel takes more of them (adaptive
 * sampling), each pixel with its own pattern. Two dimensions for a light's
 * or a lobe's samples; the first four for the camera's (the pixel and the
 * lens, spread evenly in all four at once: 12% less noise in a depth of
 * field at 64 samples than two pairs drawn apart).
 *
 * The first two dimensions of Sobol's sequence form a (0, 2)-sequence:
 * every run of 2^m points starting at a multiple of 2^m puts exactly one
 * point in each of the 2^m boxes of any shape 2^-a x 2^-b (a + b = m)
 * that tile the square. Owen's scrambling (random flips of each bit, each
 * flip chosen by the bits above it) keeps that property and makes every
 * pixel's points an independent random pattern, so averages stay unbiased;
 * it is done here as Laine and Karras's hash (Burley 2020, "Practical
 * Hash-based Owen Scrambling"): on the bits reversed, multiplications by
 * even numbers and additions carry each bit's influence only towards the
 * more significant ones, which is a flip of each bit chosen by those
 * below it. Shuffling a sequence's sample numbers the same way keeps every
 * aligned run of 2^m together, and gives each pair of dimensions (a
 * light's, a lobe's) its own order, so that the pairs do not follow one
 * another. */
#ifndef GLINT_CORE_SOBOL_H
#define GLINT_CORE_SOBOL_H

#include <stdint.h>
#include "core/hash.h"

/* Eight 32-bit words, one a lane: eight sequences' points at once
 * (sobol2_points8). Aligned as a word, so that a struct holding them may
 * sit anywhere malloc puts it. Integer steps are exact, so each lane has
 * the bits one sobol2_point gives. */
typedef uint32_t sobol_lanes __attribute__((vector_size(8 * sizeof(uint32_t)), aligned(sizeof(uint32_t))));

/* The bit steps below, written once for one word (T uint32_t, no suffix)
 * and for eight (sobol_lanes, suffix _lanes): GCC's vectors take the same
 * operators, a scalar operand standing for all lanes.
 *
 * reverse_bits32: i's bits in the opposite order.
 *
 * scramble_upwards: a bijection of 32-bit words in which bit b of the
 * result depends only on bits 0..b of x: a nested random flip of x's bits
 * from the least significant up, different for every seed.
 *
 * sobol_second_reversed: the second Sobol coordinate of index i,
 * bit-reversed (bit 0 the most significant bit of the fraction): i times
 * the generator matrix, Pascal's triangle modulo 2, whose entry (r, c) is 1
 * when the bits of r are among those of c (Lucas's theorem). Bit r of the
 * product is then the parity of i's bits at the positions holding r's,
 * which five shifted XORs gather over the five bits of a position (a
 * subset-sum transform), where a loop over i's bits took up to 32 steps. */
#define SOBOL_BIT_STEPS(T, suffix)                                                                           \
    __attribute__((always_inline)) static inline T reverse_bits32##suffix(T i)                               \
    {                                                                                                        \
        i = (i << 16) | (i >> 16);                                                                           \
        i = ((i & 0x00ff00ffU) << 8) | ((i & 0xff00ff00U) >> 8);                                             \
        i = ((i & 0x0f0f0f0fU) << 4) | ((i & 0xf0f0f0f0U) >> 4);                                             \
        i = ((i & 0x33333333U) << 2) | ((i & 0xccccccccU) >> 2);                                             \
        return ((i & 0x55555555U) << 1) | ((i & 0xaaaaaaaaU) >> 1);                                          \
    }                                                                                                        \
    __attribute__((always_inline)) static inline T scramble_upwards##suffix(T x, T seed)                     \
    {                                                                                                        \
        x += seed;                                                                                           \
        x ^= x * 0x6c50b47cU;                                                                                \
        x ^= x * 0xb82f1e52U;                                                                                \
        x ^= x * 0xc7afe638U;                                                                                \
        x ^= x * 0x8d22f6e6U;                                                                                \
        return x;                                                                                            \
    }                                                                                                        \
    __attribute__((always_inline)) static inline T sobol_second_reversed##suffix(T i)                        \
    {                                                                                                        \
        i ^= (i >> 1) & 0x55555555U;                                                                         \
        i ^= (i >> 2) & 0x33333333U;                                                                         \
        i ^= (i >> 4) & 0x0f0f0f0fU;                                                                         \
        i ^= (i >> 8) & 0x00ff00ffU;                                                                         \
        i ^= (i >> 16) & 0x0000ffffU;                                                                        \
        return i;                                                                                            \
    }

SOBOL_BIT_STEPS(uint32_t, )
SOBOL_BIT_STEPS(sobol_lanes, _lanes)

/* The third and fourth coordinates of Sobol's sequence at index i,
 * bit-reversed as sobol_second_reversed's: i times the generator matrices
 * of the primitive polynomials x^2 + x + 1 and x^3 + x + 1 with Joe and
 * Kuo's initial direction numbers (1, 3 and 1, 3, 1). The matrices'
 * columns, bit-reversed, are tabled (test_sampling.c works them out again
 * from the polynomials' recurrences) rather than built by the recurrence
 * at every sample of every camera packet; with the thin lens's quads side
 * by side, a depth of field's camera rays are 4% faster. Column q is XORed
 * in for bit q of i. */
static inline void sobol_third_fourth_reversed(uint32_t i, uint32_t *third, uint32_t *fourth)
{
    static const uint32_t columns[2][32] = {
        {0x00000001U, 0x00000003U, 0x00000006U, 0x00000009U, 0x00000017U, 0x0000003aU, 0x00000071U, 0x000000a3U,
         0x00000116U, 0x00000339U, 0x00000677U, 0x000009aaU, 0x00001601U, 0x00003903U, 0x00007706U, 0x0000aa09U,
         0x00010117U, 0x0003033aU, 0x00060671U, 0x000909a3U, 0x00171616U, 0x003a3939U, 0x00717777U, 0x00a3aaaaU,
         0x01170001U, 0x033a0003U, 0x06710006U, 0x09a30009U, 0x16160017U, 0x3939003aU, 0x77770071U, 0xaaaa00a3U},
        {0x00000001U, 0x00000003U, 0x00000004U, 0x0000000aU, 0x0000001fU, 0x0000002eU, 0x00000045U, 0x000000c9U,
         0x0000011bU, 0x000002a4U, 0x0000079aU, 0x00000b67U, 0x0000101eU, 0x0000302dU, 0x00004041U, 0x0000a0c3U,
         0x0001f104U, 0x0002e28aU, 0x000457dfU, 0x000c9baeU, 0x0011a105U, 0x002a7289U, 0x0079e7dbU, 0x00b6dba4U,
         0x0100011aU, 0x030002a7U, 0x0400079eU, 0x0a000b6dU, 0x1f001001U, 0x2e003003U, 0x45004004U, 0xc900a00aU},
    };
    uint32_t c3 = 0, c4 = 0;
    for (; i; i &= i - 1) {
        int q = __builtin_ctz(i);
        c3 ^= columns[0][q];
        c4 ^= columns[1][q];
    }
    *third = c3;
    *fourth = c4;
}

/* A scalar in every lane: one index's coordinate for eight sequences. */
static inline sobol_lanes sobol_same(uint32_t word) { return (sobol_lanes){0} + word; }

/* One coordinate of a point of eight Owen-scrambled Sobol sequences, from
 * each lane's coordinate bit-reversed and its scramble of that dimension,
 * as fractions in [0, 1). */
__attribute__((always_inline)) static inline void sobol_scrambled8(sobol_lanes reversed, sobol_lanes scramble,
                                                                   double out[8])
{
    sobol_lanes bits = reverse_bits32_lanes(scramble_upwards_lanes(reversed, scramble)) >> 8;
    for (int k = 0; k < 8; k++)
        out[k] = (int32_t)bits[k] * (1.0 / 16777216.0);
}

/* The three scrambles a seed's sequence uses: of the index, and of each
 * coordinate. A caller taking many points of one sequence works them out
 * once (sobol2_seeds_of) and passes them to each sobol2_point. */
typedef struct sobol2_seeds {
    uint32_t index, x, y;
} sobol2_seeds;

static inline sobol2_seeds sobol2_seeds_of(uint32_t seed)
{
    return (sobol2_seeds){.index = hash_u32(seed), .x = hash_u32(seed ^ 0x5851f42dU),
                          .y = hash_u32(seed ^ 0x4c957f2dU)};
}

/* Point i of the scrambled two-dimensional Sobol sequence of the seeds s,
 * in [0, 1)^2: index i shuffled within its aligned runs of each power of
 * two, then each coordinate scrambled. The first coordinate's generator is
 * the identity (van der Corput: the index reversed), the second's Pascal's
 * triangle modulo 2 (Sobol's direction numbers for the polynomial x + 1).
 * Each step is Owen's scrambling of a fraction (reverse_bits32 of
 * scramble_upwards of the fraction reversed) written out, so that
 * reversals that undo each other are left out. */
static inline void sobol2_point(uint32_t i, sobol2_seeds s, double *x, double *y)
{
    uint32_t index = reverse_bits32(scramble_upwards(reverse_bits32(i), s.index));
    uint32_t first = reverse_bits32(scramble_upwards(index, s.x));
    uint32_t second = reverse_bits32(scramble_upwards(sobol_second_reversed(index), s.y));
    *x = (first >> 8) * (1.0 / 16777216.0);
    *y = (second >> 8) * (1.0 / 16777216.0);
}

/* The scrambles of eight sequences, lane by lane. */
typedef struct sobol2_seeds8 {
    sobol_lanes index, x, y;
} sobol2_seeds8;

/* Puts one sequence's scrambles in lane `lane` of *s. */
static inline void sobol2_seeds8_set(sobol2_seeds8 *s, int lane, sobol2_seeds one)
{
    s->index[lane] = one.index;
    s->x[lane] = one.x;
    s->y[lane] = one.y;
}

/* Point i of each of the eight sequences of s: lane k is sobol2_point of
 * lane k's seeds, bit for bit, for about the time of two of them (the
 * scalar steps wait on eight multiplications in a row). */
__attribute__((always_inline)) static inline void sobol2_points8(uint32_t i, const sobol2_seeds8 *s, double x[8],
                                                                 double y[8])
{
    sobol_lanes reversed = sobol_same(reverse_bits32(i));
    sobol_lanes index = reverse_bits32_lanes(scramble_upwards_lanes(reversed, s->index));
    sobol_scrambled8(index, s->x, x);
    sobol_scrambled8(sobol_second_reversed_lanes(index), s->y, y);
}

/* Point i of the scrambled two-dimensional Sobol sequence with the given
 * seed (sobol2_point of sobol2_seeds_of(seed)). */
static inline void sobol2_scrambled(uint32_t i, uint32_t seed, double *x, double *y)
{
    sobol2_point(i, sobol2_seeds_of(seed), x, y);
}

#endif
