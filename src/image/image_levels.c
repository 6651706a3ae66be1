/* image_levels.c - an image's pyramid of smaller copies (a mipmap), so
 * that a texture seen from far away, where one sample covers many of its
 * texels, is looked up where they are already averaged instead of at one
 * texel that stands for them all (which shimmers as the view moves). */
#include <stdlib.h>
#include "core/error.h"
#include "image/srgb.h"
#include "image/texture_image.h"

/* Level `to` (allocated) filled from level `from`, twice its size. */
static void halve(const texture_image *from, texture_image *to)
{
    for (int y = 0; y < to->height; y++) {
        int y0 = 2 * y, y1 = 2 * y + 1 < from->height ? 2 * y + 1 : 2 * y;
        for (int x = 0; x < to->width; x++) {
            int x0 = 2 * x, x1 = 2 * x + 1 < from->width ? 2 * x + 1 : 2 * x;
            size_t corners[4] = {(size_t)y0 * from->width + x0, (size_t)y0 * from->width + x1,
                                 (size_t)y1 * from->width + x0, (size_t)y1 * from->width + x1};
            size_t at = 3 * ((size_t)y * to->width + x);
            for (int c = 0; c < 3; c++) {
                float sum = 0;
                for (int k = 0; k < 4; k++)
                    sum += texture_image_at(from, 3 * corners[k] + c);
                if (from->hdr)
                    ((float *)to->owned)[at + c] = sum / 4;
                else
                    ((unsigned char *)to->owned)[at + c] = srgb_byte(sum / 4);
            }
        }
    }
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
    const texture_image *from = img;
    size_t texel = img->hdr ? 3 * sizeof(float) : 3;
    for (int k = 0; k < count - 1; k++) {
        texture_image *to = &img->levels[k];
        *to = (texture_image){.width = (from->width + 1) / 2, .height = (from->height + 1) / 2, .linear = img->linear};
        to->owned = malloc(texel * (size_t)to->width * (size_t)to->height);
        if (!to->owned) {
            img->level_count = k + 1;
            texture_image_free_levels(img);
            return error_set(err, GLINT_ERR_NOMEM, "out of memory for a texture's smaller levels");
        }
        if (img->hdr)
            to->hdr = to->owned;
        else
            to->srgb = to->owned;
        halve(from, to);
        from = to;
    }
    img->level_count = count;
    return GLINT_OK;
}
