/* film.c - the image a render fills: allocating and clearing it, and
 * counting and finding the NaN that film.h's rule keeps out of it. Adding
 * samples and writing a block's pixels are inline in film.h. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "core/big_alloc.h"
#include "render/film.h"

float *film_pixels_alloc(int width, int height, bool black)
{
    size_t bytes = (size_t)width * (size_t)height * 3 * sizeof(float);
    /* An image is written once, page after page, by the render threads:
     * with 4 KiB pages a 1920x1080 image took 6,000 page faults, 8% of a
     * one-sample render's time, and a 512x512 one's 700 were 14% of the
     * whole SPD tetra (bench/README.md). */
    float *pixels = big_alloc(bytes);
    if (pixels && black)
        memset(pixels, 0, bytes);
    return pixels;
}

bool film_init(film *f, int width, int height, int samples, bool black)
{
    *f = (film){.width = width, .height = height, .samples = samples, .exposure_scale = 1};
    f->pixels = film_pixels_alloc(width, height, black);
    return f->pixels != NULL;
}

void film_free(film *f)
{
    free(f->pixels);
    f->pixels = NULL;
}

uint64_t film_block_nan_samples(const film_block *b)
{
    uint64_t n = 0;
    for (int i = 0; i < RAY8; i++)
        n += (uint64_t)b->bad[i];
    return n;
}

bool film_has_nan(const film *f, int x0, int y0, int x1, int y1)
{
    typedef float floats8 __attribute__((vector_size(8 * sizeof(float))));
    typedef int32_t mask8 __attribute__((vector_size(8 * sizeof(int32_t))));
    size_t width = (size_t)f->width, row = 3 * (size_t)(x1 - x0);
    mask8 any = {0};
    bool scalar_nan = false;
    for (int y = y0; y < y1; y++) {
        const float *p = f->pixels + 3 * ((size_t)(y - f->y0) * width + (size_t)(x0 - f->x0));
        size_t k = 0;
        for (; k + 8 <= row; k += 8) {
            floats8 v;
            memcpy(&v, p + k, sizeof v);
            any |= v != v;
        }
        for (; k < row; k++)
            scalar_nan |= isnan(p[k]);
    }
    for (int i = 0; i < 8; i++)
        scalar_nan |= any[i] != 0;
    return scalar_nan;
}

void film_clear(film *f, int x0, int y0, int x1, int y1)
{
    for (int y = y0; y < y1; y++)
        memset(f->pixels + 3 * ((size_t)(y - f->y0) * f->width + (size_t)(x0 - f->x0)), 0,
               3 * sizeof(float) * (size_t)(x1 - x0));
}
