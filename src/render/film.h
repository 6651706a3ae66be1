/* film.h - the image a render fills: a float buffer of linear RGB, and how
 * a block's samples become its pixels.
 *
 * render.c traces a block of pixels (a packet's lanes) one sample of each
 * at a time; the samples go into a film_block, which film_block_put turns
 * into the block's pixels. Each sample counts equally in its own pixel: a
 * box filter one pixel wide. Pixel reconstruction filters (tent, Gaussian,
 * Mitchell) plug in here: film_block_add would take each sample's position
 * in its pixel and weigh it, and film_block_put divide by the weights and
 * spread samples into neighbouring pixels; nothing else would change.
 *
 * The NaN rule. A NaN colour, which no valid scene should give but extreme
 * values can (an overflow to infinity times zero), never reaches a pixel:
 * the NaN sample is left out of its pixel's average and counted, and a
 * pixel whose samples were all NaN is black. Looking for NaN costs the
 * common path, so it is done only where one showed: film_has_nan checks a
 * whole tile once after it is rendered, and render.c traces again, with
 * film_block_add's `careful` on, only the blocks where it finds one. The
 * measurements behind this (bench/README.md): a check of each block as it
 * is written cost the bunny 1.6% more instructions; one block renderer
 * passing `careful` at run time cost the seed room 1% and the bunny 2%
 * (the profile-guided build inlined otherwise), hence render.c's two
 * block renderers, each with `careful` a constant. */
#ifndef GLINT_RENDER_FILM_H
#define GLINT_RENDER_FILM_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "core/color.h"
#include "core/vec.h"

typedef struct film {
    float *pixels;            /* width x height pixels of 3 floats, rows from the top; glint_render
                                 hands them to its image, else film_free frees them */
    int width, height;
    int x0, y0;               /* the image's pixel that pixels[0] is: 0, 0 for an image, a tile's
                                 corner for a film that holds one tile */
    int samples;              /* samples per pixel */
    double exposure_scale;    /* each pixel's average times this: 2^exposure (film_init: 1) */
} film;

/* A block's pixels while their samples are traced: lane i's pixel gets
 * sum[i] over the samples added to it, bad[i] of them left out as NaN. */
typedef struct film_block {
    color sum[RAY8];
    int bad[RAY8];
} film_block;

/* The pixels of a black width x height image, 3 floats each, freed with
 * free(); NULL when memory runs out. Backed by huge pages where the kernel
 * allows, as an image is written in full once. */
float *film_pixels_alloc(int width, int height);

/* A black film of width x height pixels, each to be the average of
 * `samples` samples; false when memory runs out. */
bool film_init(film *f, int width, int height, int samples);

/* Frees the pixels (NULL after glint_render took them). */
void film_free(film *f);

/* Starts a block with no samples. */
static inline void film_block_start(film_block *b)
{
    for (int i = 0; i < RAY8; i++) {
        b->sum[i] = rgb(0, 0, 0);
        b->bad[i] = 0;
    }
}

/* Adds sample c[i] to lane i's pixel for each active[i]. With `careful`
 * (a constant where it is called: see the header's comment), a sample
 * whose colour is NaN is left out and counted instead (NaN in any channel
 * makes the channels' sum NaN: colours are never negative, so no
 * infinities cancel). */
static inline void film_block_add(film_block *b, const bool active[RAY8], const color c[RAY8], bool careful)
{
    for (int i = 0; i < RAY8; i++) {
        if (!active[i])
            continue;
        if (careful && isnan(c[i].r + c[i].g + c[i].b))
            b->bad[i]++;
        else
            b->sum[i] = rgb_add(b->sum[i], c[i]);
    }
}

/* Writes each active lane's pixel (px[i], py[i]), in the image's
 * coordinates: its sum over the
 * f->samples samples less those left out, or black when every one was.
 * Inline: as a call into film.c, the pixel positions it is given escaped,
 * and GCC read and converted them again at every sample of the block (seed
 * room +0.5%, bunny +1% instructions). */
static inline void film_block_put(film *f, const film_block *b, const int px[RAY8], const int py[RAY8],
                                  const bool active[RAY8])
{
    int samples = f->samples;
    double share = 1.0 / samples;
    for (int i = 0; i < RAY8; i++) {
        if (!active[i])
            continue;
        int bad = b->bad[i];
        double k = (bad == 0 ? share : bad < samples ? 1.0 / (samples - bad) : 0) * f->exposure_scale;
        color avg = rgb_scale(b->sum[i], k);
        float *p = f->pixels + 3 * ((size_t)(py[i] - f->y0) * f->width + (px[i] - f->x0));
        p[0] = (float)avg.r;
        p[1] = (float)avg.g;
        p[2] = (float)avg.b;
    }
}

/* How many samples the block left out as NaN. */
uint64_t film_block_nan_samples(const film_block *b);

/* Whether any float of the pixels from x0 to x1 (excluded) on the rows from
 * y0 to y1, in the image's coordinates, is NaN: a whole tile is checked at once, eight floats a step. */
bool film_has_nan(const film *f, int x0, int y0, int x1, int y1);

/* Blackens the pixels from x0 to x1 (excluded) on the rows from y0 to y1,
 * in the image's coordinates:
 * a cancelled render's unfinished tiles. */
void film_clear(film *f, int x0, int y0, int x1, int y1);

#endif
