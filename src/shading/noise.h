/* noise.h - gradient noise and its fractal sums, the ground of the solid
 * textures (noise, marble, wood, granite).
 *
 * The noise is Perlin's gradient noise with his quintic fade: each corner
 * of the unit lattice around a point holds a gradient, one of the twelve
 * directions to the middles of a cube's edges, chosen by a hash of the
 * corner's coordinates (core/hash.h) rather than a table of random numbers,
 * so it needs no state and gives the same values on every machine. It is
 * 0 at every lattice point and smooth (C2) everywhere. */
#ifndef GLINT_SHADING_NOISE_H
#define GLINT_SHADING_NOISE_H

#include <stdint.h>
#include "core/lanes.h"
#include "core/vec.h"

/* The noise at p, from about -1 to 1 (never beyond +-1.04); `layer` picks
 * one of many unrelated noises. 0 where p is not finite or beyond 1e15. */
double noise_at(vec3 p, uint32_t layer);

/* noise_at of four points, the lanes of p[0] (x), p[1] (y) and p[2] (z):
 * the same value in each lane as noise_at's for it. */
quad_f64 noise_at4(const quad_f64 p[3], uint32_t layer);

/* How octaves of noise are layered: octave i is noise at p * lacunarity^i
 * with amplitude gain^i, its own layer. */
typedef struct noise_octaves {
    int count;          /* 1 to 16 */
    double lacunarity;  /* > 1 */
    double gain;        /* from 0 to 1 */
} noise_octaves;

/* Fractal Brownian motion at four points (noise_at4's lanes): the
 * octaves' sum divided by the sum of their amplitudes, so from about -1
 * to 1, as one octave is. */
quad_f64 noise_fbm4(const quad_f64 p[3], noise_octaves o);

/* Turbulence: as noise_fbm4, but of each octave's magnitude, so from 0 to
 * about 1, with sharp creases where an octave crosses 0. */
quad_f64 noise_turbulence4(const quad_f64 p[3], noise_octaves o);

#endif
