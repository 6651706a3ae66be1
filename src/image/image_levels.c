/* image_levels.c - an image's pyramid of smaller copies (a mipmap), so
 * that a texture seen from far away, where one sample covers many of its
 * texels, is looked up where they are already averaged instead of at one
 * texel that stands for them all (which shimmers as the view moves). */
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "core/parallel.h"
#include "core/processors.h"
#include "image/srgb.h"
#include "image/texture_image.h"

/* Row y of level `to` (allocated) filled from level `from`, twice its
 * size: each texel's mean of the linear values below it into `row` (3
 * floats a texel), then stored as the image keeps its texels. Inlined
 * where `hdr` is a constant, so the test for the format runs once a row. */
static inline void halve_row(const texture_image *from, texture_image *to, bool hdr, int y, float *row)
{
    int y0 = 2 * y, y1 = 2 * y + 1 < from->height ? 2 * y + 1 : 2 * y;
    size_t top = (size_t)y0 * from->width, bottom = (size_t)y1 * from->width;
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
    size_t at = 3 * (size_t)y * to->width, n = 3 * (size_t)to->width;
    if (hdr)
        memcpy((float *)to->owned + at, row, n * sizeof *row);
    else
        srgb_encode((unsigned char *)to->owned + at, row, n);
}

/* Rows y0 to y1 - 1 of level `to`, halved from level `from` through `row`
 * (3 floats a texel of `to`): one band of a level, on a thread of its own. */
typedef struct halving {
    const texture_image *from;
    texture_image *to;
    float *row;
    int y0, y1;
} halving;

static void *halve_band(void *arg)
{
    const halving *h = arg;
    for (int y = h->y0; y < h->y1; y++) {
        if (h->from->hdr)
            halve_row(h->from, h->to, true, y, h->row);
        else
            halve_row(h->from, h->to, false, y, h->row);
    }
    return NULL;
}

/* The most threads a level is halved on. */
#define HALVING_THREADS 8

/* Level `to` (allocated) filled from level `from`, twice its size, in
 * bands of rows on up to `threads` threads, each with its row of `rows`
 * (HALVING_THREADS rows of `row_floats`). A small level is halved on one:
 * starting threads would cost more than they save. With a row at a time
 * and two threads, a scene of the Earth's 5400 x 2700 map loads and
 * renders a pixel in 246 ms, where each texel alone through srgb_byte, on
 * one thread, took 298 ms. */
static void halve(const texture_image *from, texture_image *to, float *rows, size_t row_floats, int threads)
{
    int bands = (size_t)to->width * (size_t)to->height >= (1u << 18) ? threads : 1;
    halving h[HALVING_THREADS];
    for (int i = 0; i < bands; i++)
        h[i] = (halving){from, to, rows + (size_t)i * row_floats, (int)((long)to->height * i / bands),
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
    /* A row of the first level, the widest, as floats, for each thread. */
    int threads = processors_online(HALVING_THREADS);
    size_t row_floats = 3 * (size_t)((img->width + 1) / 2);
    float *row = malloc(sizeof *row * row_floats * (size_t)threads);
    if (!row) {
        texture_image_free_levels(img);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for a texture's smaller levels");
    }
    const texture_image *from = img;
    size_t texel = img->hdr ? 3 * sizeof(float) : 3;
    for (int k = 0; k < count - 1; k++) {
        texture_image *to = &img->levels[k];
        *to = (texture_image){.width = (from->width + 1) / 2, .height = (from->height + 1) / 2, .linear = img->linear};
        to->owned = malloc(texel * (size_t)to->width * (size_t)to->height);
        if (!to->owned) {
            img->level_count = k + 1;
            texture_image_free_levels(img);
            free(row);
            return error_set(err, GLINT_ERR_NOMEM, "out of memory for a texture's smaller levels");
        }
        if (img->hdr)
            to->hdr = to->owned;
        else
            to->srgb = to->owned;
        halve(from, to, row, row_floats, threads);
        from = to;
    }
    free(row);
    img->level_count = count;
    return GLINT_OK;
}
