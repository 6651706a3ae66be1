/* image_levels.c - an image's pyramid of smaller copies (a mipmap), so
 * that a texture seen from far away, where one sample covers many of its
 * texels, is looked up where they are already averaged instead of at one
 * texel that stands for them all (which shimmers as the view moves). */
#include <stdlib.h>
#include <string.h>
#include "core/big_alloc.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/processors.h"
#include "image/texture_image.h"

/* Row y of level `to` (allocated, floats) filled from level `from`, twice
 * its size: each texel the mean of the linear values below it. Inlined
 * where `hdr` (the format of `from`) is a constant, so the test for it
 * runs once a row. */
static inline void halve_row(const texture_image *from, texture_image *to, bool hdr, int y)
{
    int y0 = 2 * y, y1 = 2 * y + 1 < from->height ? 2 * y + 1 : 2 * y;
    size_t top = (size_t)y0 * from->width, bottom = (size_t)y1 * from->width;
    float *row = (float *)to->owned + 3 * (size_t)y * to->width;
    for (int x = 0; x < to->width; x++) {
        int x0 = 2 * x, x1 = 2 * x + 1 < from->width ? 2 * x + 1 : 2 * x;
        size_t corners[4] = {3 * (top + x0), 3 * (top + x1), 3 * (bottom + x0), 3 * (bottom + x1)};
        for (int c = 0; c < 3; c++) {
            float sum = 0;
            for (int k = 0; k < 4; k++)
                sum += hdr ? from->hdr[corners[k] + c] : from->linear[from->srgb[corners[k] + c]];
            row[3 * x + c] = sum / 4;
        }
    }
}

/* Rows y0 to y1 - 1 of level `to`, halved from level `from`: one band of
 * a level, on a thread of its own. */
typedef struct halving {
    const texture_image *from;
    texture_image *to;
    int y0, y1;
} halving;

static void *halve_band(void *arg)
{
    const halving *h = arg;
    for (int y = h->y0; y < h->y1; y++) {
        if (h->from->hdr)
            halve_row(h->from, h->to, true, y);
        else
            halve_row(h->from, h->to, false, y);
    }
    return NULL;
}

/* The most threads a level is halved on. */
#define HALVING_THREADS 8

/* Level `to` (allocated) filled from level `from`, twice its size, in
 * bands of rows on up to `threads` threads. A small level is halved on one:
 * starting threads would cost more than they save. With a row at a time
 * and two threads, a scene of the Earth's 5400 x 2700 map loads and
 * renders a pixel in 246 ms, where each texel alone through srgb_byte, on
 * one thread, took 298 ms. */
static void halve(const texture_image *from, texture_image *to, int threads)
{
    int bands = (size_t)to->width * (size_t)to->height >= (1u << 18) ? threads : 1;
    halving h[HALVING_THREADS];
    for (int i = 0; i < bands; i++)
        h[i] = (halving){from, to, (int)((long)to->height * i / bands),
                         (int)((long)to->height * (i + 1) / bands)};
    parallel_run(bands, halve_band, h, sizeof h[0]);
}

glint_status texture_image_build_levels(texture_image *img, glint_error *err)
{
    int count = 1;
    for (int w = img->width, h = img->height; w > 1 || h > 1; w = (w + 1) / 2, h = (h + 1) / 2)
        count++;
    img->level_count = 0;
    if (count == 1)
        return GLINT_OK;
    img->levels = calloc((size_t)count - 1, sizeof *img->levels);
    if (!img->levels)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for a texture's smaller levels");
    img->owns_levels = true;
    int threads = processors_online(HALVING_THREADS);
    const texture_image *from = img;
    for (int k = 0; k < count - 1; k++) {
        texture_image *to = &img->levels[k];
        *to = (texture_image){.width = (from->width + 1) / 2, .height = (from->height + 1) / 2, .linear = img->linear};
        size_t floats = 3 * (size_t)to->width * (size_t)to->height;
        to->owned = big_alloc(floats * sizeof(float) + TEXEL_SLACK);
        if (!to->owned) {
            img->level_count = k + 1;
            texture_image_free_levels(img);
            return error_set(err, GLINT_ERR_NOMEM, "out of memory for a texture's smaller levels");
        }
        memset((float *)to->owned + floats, 0, TEXEL_SLACK);
        to->hdr = to->owned;
        halve(from, to, threads);
        from = to;
    }
    img->level_count = count;
    return GLINT_OK;
}
