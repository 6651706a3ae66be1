/* film.h - the image a render fills: a float buffer of linear RGB, and how
 * a block's samples become its pixels.
 *
 * render.c traces a block of pixels (a packet's lanes) one sample of each
 * at a time; the samples go into a film_block, which film_block_put turns
 * into the block's pixels. A sample counts only in its own pixel: the
 * reconstruction filter is applied by where samples fall (filter.h). So
 * on the common path every pixel averages the same number of samples, all
 * alike (film_block_add, film_block_put); the signed path
 * (film_block_add_signed, film_block_put_signed) serves pixels whose
 * samples vary in number (adaptive sampling) or count negatively (a
 * filter's negative lobes), and keeps each pixel's range of samples for
 * adaptive sampling to judge.
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
 * sum[i] over the samples added to it, bad[i] of them left out as NaN.
 * The signed path adds the rest. */
typedef struct film_block {
    color sum[RAY8];          /* signed path: negative samples subtracted */
    int bad[RAY8];
    int count[RAY8];          /* signed path: samples added */
    int weight[RAY8];         /* signed path: samples added less twice those counting negatively */
    color plain[RAY8];        /* signed path: the samples' unsigned sum */
    color lo[RAY8], hi[RAY8]; /* signed path: the samples' least and greatest value in each channel */
} film_block;

/* The pixels of a width x height image, 3 floats each, freed with free();
 * NULL when memory runs out. Backed by huge pages from 1 MiB (big_alloc),
 * as an image is written in full once. `black`: every pixel 0; else the
 * pixels are left as they come, for a caller that writes each before any
 * is read: a large image's pages are then first touched, and cleared by
 * the kernel, in the render threads that write them, not all in one thread
 * before the render starts (12 ms at 2048 x 2048). */
float *film_pixels_alloc(int width, int height, bool black);

/* A film of width x height pixels, each to be the average of `samples`
 * samples, black or left as film_pixels_alloc says; false when memory
 * runs out. */
bool film_init(film *f, int width, int height, int samples, bool black);

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

/* Starts a block for the signed path. */
static inline void film_block_start_signed(film_block *b)
{
    film_block_start(b);
    for (int i = 0; i < RAY8; i++) {
        b->count[i] = b->weight[i] = 0;
        b->plain[i] = rgb(0, 0, 0);
        b->lo[i] = rgb(INFINITY, INFINITY, INFINITY);
        b->hi[i] = rgb(0, 0, 0);
    }
}

/* film_block_add for the signed path: sample c[i] counts negatively in
 * lane i's pixel where negative[i]. */
static inline void film_block_add_signed(film_block *b, const bool active[RAY8], const color c[RAY8],
                                         const bool negative[RAY8], bool careful)
{
    for (int i = 0; i < RAY8; i++) {
        if (!active[i])
            continue;
        if (careful && isnan(c[i].r + c[i].g + c[i].b)) {
            b->bad[i]++;
            continue;
        }
        b->count[i]++;
        b->weight[i] += negative[i] ? -1 : 1;
        b->sum[i] = rgb_madd(b->sum[i], c[i], negative[i] ? -1 : 1);
        b->plain[i] = rgb_add(b->plain[i], c[i]);
        b->lo[i] = rgb(fmin(b->lo[i].r, c[i].r), fmin(b->lo[i].g, c[i].g), fmin(b->lo[i].b, c[i].b));
        b->hi[i] = rgb(fmax(b->hi[i].r, c[i].r), fmax(b->hi[i].g, c[i].g), fmax(b->hi[i].b, c[i].b));
    }
}

/* How far apart lane i's samples are as displayed: the largest difference
 * in any channel between them, each scaled by `scale` (the exposure) and
 * clipped to 1 as an image shows it; 0 before two samples. */
static inline double film_block_spread(const film_block *b, int i, double scale)
{
    if (b->count[i] < 2)
        return 0;
    double r = fmin(b->hi[i].r * scale, 1) - fmin(b->lo[i].r * scale, 1);
    double g = fmin(b->hi[i].g * scale, 1) - fmin(b->lo[i].g * scale, 1);
    double bl = fmin(b->hi[i].b * scale, 1) - fmin(b->lo[i].b * scale, 1);
    return fmax(r, fmax(g, bl));
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

/* Stores pixel (x, y), in the image's coordinates. */
static inline void film_store(film *f, int x, int y, color c)
{
    float *p = f->pixels + 3 * ((size_t)(y - f->y0) * f->width + (x - f->x0));
    p[0] = (float)c.r;
    p[1] = (float)c.g;
    p[2] = (float)c.b;
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
        film_store(f, px[i], py[i], avg);
    }
}

/* film_block_put for the signed path: each pixel its samples' signed
 * average, or, should the negative ones outweigh the others (a few samples
 * through a filter's negative lobes), their plain average; no channel
 * below zero. */
static inline void film_block_put_signed(film *f, const film_block *b, const int px[RAY8], const int py[RAY8],
                                         const bool active[RAY8])
{
    for (int i = 0; i < RAY8; i++) {
        if (!active[i])
            continue;
        color avg = b->weight[i] > 0 ? rgb_scale(b->sum[i], 1.0 / b->weight[i])
                    : b->count[i] > 0 ? rgb_scale(b->plain[i], 1.0 / b->count[i])
                                      : rgb(0, 0, 0);
        avg = rgb_scale(rgb(fmax(avg.r, 0), fmax(avg.g, 0), fmax(avg.b, 0)), f->exposure_scale);
        film_store(f, px[i], py[i], avg);
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
