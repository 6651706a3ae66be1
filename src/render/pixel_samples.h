/* pixel_samples.h - where a pixel's samples fall: their positions in the
 * pixel (the sampler, settings.sampler, spread by the reconstruction
 * filter, filter.h) and where they pass a thin lens. Every position is a
 * function of the pixel, the sample's number and the seed alone, so a
 * pixel is the same whichever thread, tile or rank renders it.
 *
 * The regular and jittered samplers lay an n x n grid over the pixel (one
 * point in each cell: its centre, or a hashed point within it); a lens
 * takes one sample in each of its own n x n cells, the cells shuffled per
 * pixel so that a sample's lens cell does not follow its image cell. The
 * sobol sampler takes any count: the pixel's own scrambled Sobol points
 * (core/sobol.h), one sequence for the image position and another,
 * shuffled apart, for the lens, so that a pixel taking more samples
 * (adaptive sampling) keeps them well spread. */
#ifndef GLINT_RENDER_PIXEL_SAMPLES_H
#define GLINT_RENDER_PIXEL_SAMPLES_H

#include <stdbool.h>
#include <stdint.h>
#include "core/sobol.h"
#include "render/camera.h"
#include "render/filter.h"

typedef struct pixel_sampler {
    glint_sampler kind;
    int grid;               /* the regular and jittered samplers': n of the n x n grid */
    uint32_t seed;
    bool lens;              /* the camera takes lens samples */
    bool plain_box;         /* the default box of radius 0.5: a sample's position is its point in the pixel */
    bool motion;            /* samples take times over the shutter (pixel_samples_time) */
    pixel_filter filter;
} pixel_sampler;

/* What the samples of a block's RAY8 pixels share: each lane's pixel, and
 * the hashes its pattern derives from. */
typedef struct pixel_block_samples {
    int px[RAY8], py[RAY8];
    uint32_t pattern[RAY8];        /* the pixel's own scramble (sobol, and the lens cells' points) */
    sobol_lanes scramble[4];       /* sobol: the scrambles of the four dimensions (image x, y; lens u, v) */
    sobol_lanes time_scramble;     /* with motion: the scramble of the samples' times */
    uint32_t shuffle_a[RAY8], shuffle_b[RAY8]; /* the grid's lens cells: k goes to (a k + b) mod n^2 */
} pixel_block_samples;

/* Sets ps up for the settings (which must have passed validation), for a
 * camera that takes lens samples or not, and for a scene where something
 * moves over the shutter or not. */
void pixel_sampler_init(pixel_sampler *ps, const glint_settings *s, bool lens, bool motion);

/* Sample k's time over the shutter in each lane's pixel, in [0, 1): point
 * k of the pixel's own scrambled van der Corput sequence (Owen's
 * scrambling, core/sobol.h), so that any number of samples spread evenly
 * over the shutter, whatever the sampler. Needs ps->motion. */
void pixel_samples_time(const pixel_block_samples *b, int k, double time[RAY8]);

/* Starts the block of pixels (px[i], py[i]). */
void pixel_samples_start(const pixel_sampler *ps, const int px[RAY8], const int py[RAY8], pixel_block_samples *b);

/* pixel_samples_at for any sampler, filter and camera. */
void pixel_samples_at_any(const pixel_sampler *ps, const pixel_block_samples *b, int k, double x[RAY8],
                          double y[RAY8], camera_lens8 *lens, bool negative[RAY8]);

/* Sample k's point in the pixel, in [0, 1)^2, on the regular n x n grid:
 * the centre of cell k, the cells row by row. */
static inline void regular_point(int n, int k, double *u, double *v)
{
    *u = (k % n + 0.5) / n;
    *v = (k / n + 0.5) / n;
}

/* Sample k of each lane's pixel: its image position (x[i], y[i]) in pixels
 * from the image's top-left corner, its lens point in *lens (set only when
 * ps->lens), and whether it counts negatively (a filter's negative lobe).
 * Inline for the default, the seed room's regular grid through the plain
 * box with no lens, where every pixel's sample is at the same point: the
 * call alone cost it 0.9% of its instructions. */
static inline void pixel_samples_at(const pixel_sampler *ps, const pixel_block_samples *b, int k, double x[RAY8],
                                    double y[RAY8], camera_lens8 *lens, bool negative[RAY8])
{
    if (ps->kind != GLINT_SAMPLER_REGULAR || !ps->plain_box || ps->lens) {
        pixel_samples_at_any(ps, b, k, x, y, lens, negative);
        return;
    }
    double u, v;
    regular_point(ps->grid, k, &u, &v);
    for (int i = 0; i < RAY8; i++) {
        x[i] = b->px[i] + u;
        y[i] = b->py[i] + v;
        negative[i] = false;
    }
}

#endif
