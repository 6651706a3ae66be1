/* texture_image.h - decoding PNG, JPEG and OpenEXR images for image
 * textures: PNG and JPEG kept as the file's 8-bit sRGB values, 3 bytes a
 * pixel, and made linear through a table when looked up (a quarter of the
 * memory of float RGB, and the same linear values to the bit); OpenEXR
 * (high dynamic range: a sky a hundred times brighter than white) as
 * linear floats. */
#ifndef GLINT_IMAGE_TEXTURE_IMAGE_H
#define GLINT_IMAGE_TEXTURE_IMAGE_H

#include <stdbool.h>
#include <stddef.h>
#include "glint.h"

/* The largest image decoded: a side longer, more pixels in all, or more
 * bytes of decoded pixels (1.5 GiB: an OpenEXR image of 16384 x 8192 at 12
 * bytes a pixel) is refused as too large before any pixel memory is
 * allocated. */
#define TEXTURE_IMAGE_MAX_SIDE 32768UL
#ifndef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
#define TEXTURE_IMAGE_MAX_PIXELS (1UL << 28)
#define TEXTURE_IMAGE_MAX_BYTES (3UL << 29)
#else
/* The fuzz targets' limits, 2048 x 2048 pixels (and half that in floats):
 * decoding the largest image allowed and building its levels took 12 s
 * under the sanitizers at the limits above, and a fuzzer that keeps such
 * images ran 18 inputs a second instead of thousands. The unit tests check
 * the limits above. */
#define TEXTURE_IMAGE_MAX_PIXELS (1UL << 22)
#define TEXTURE_IMAGE_MAX_BYTES (3UL << 23)
#endif
/* The largest texture file read, 2 GiB: twice the 16-bit RGBA pixels of the
 * largest image, more than any PNG or JPEG of it takes. A file is read
 * whole before it is decoded, so a larger one is refused unread. */
#define TEXTURE_IMAGE_MAX_FILE (2ULL << 30)

/* A decoded image: srgb[3 * (y * width + x) + c], top row first, each an
 * sRGB-encoded byte whose linear value is linear[byte]; or, for a high
 * dynamic range image and for every smaller level, hdr[3 * (y * width + x)
 * + c], linear floats (srgb NULL), followed by TEXEL_SLACK bytes more, so
 * that any texel's three floats are read as one load of four. The pixels
 * are the image's own (owned, freed with it) or borrowed from memory that
 * outlives it, such as pixels compiled into the program or another
 * image's (owned NULL). */
#define TEXEL_SLACK sizeof(float)

typedef struct texture_image {
    int width, height;
    const unsigned char *srgb;
    const float *hdr;
    void *owned;              /* srgb or hdr when the image allocated them, else NULL */
    const float *linear;      /* 256 entries, shared by every image */
    /* The image halved again and again down to one texel
     * (texture_image_build_levels): level k + 1 is levels[k], level 0 the
     * image itself; level_count of them, 0 when none are built. Freed with
     * the image when owns_levels, else borrowed like its pixels. */
    struct texture_image *levels;
    int level_count;
    bool owns_levels;
} texture_image;

/* The linear value of channel i % 3 of pixel i / 3 of img. */
static inline float texture_image_at(const texture_image *img, size_t i)
{
    return img->hdr ? img->hdr[i] : img->linear[img->srgb[i]];
}

/* Whether img holds pixels (it has been decoded). */
static inline bool texture_image_decoded(const texture_image *img)
{
    return img->srgb || img->hdr;
}

/* The bytes img's pixels take. */
static inline unsigned long long texture_image_bytes(const texture_image *img)
{
    return (img->hdr ? 3 * sizeof(float) : 3ULL) * (unsigned long long)img->width * (unsigned long long)img->height;
}

/* img's pixels borrowed: the same image, which frees nothing. */
static inline texture_image texture_image_share(const texture_image *img)
{
    texture_image shared = *img;
    shared.owned = NULL;
    shared.owns_levels = false;
    return shared;
}

/* Builds img's smaller levels, each half the size of the one before
 * (rounded up) down to 1 x 1, each texel the mean of the linear values of
 * the 2 x 2 below it (an edge texel of an odd size counted twice), kept as
 * linear floats whatever img keeps: a third more memory than an image of
 * floats, 4/3 of the image's own for one of sRGB bytes, and read a texel a
 * load where bytes take six (a tiled floor's look-ups, almost all from
 * these levels). GLINT_ERR_NOMEM, and no levels, when memory runs out. */
glint_status texture_image_build_levels(texture_image *img, glint_error *err);

/* The most levels an image has: its own and 15 halvings of the longest
 * side, TEXTURE_IMAGE_MAX_SIDE. */
#define TEXTURE_IMAGE_MAX_LEVELS 16

/* img's pixels borrowed and read as data rather than colours: a byte b as
 * b / 255, not made linear (a normal map's or a height map's values);
 * floats as they are. */
texture_image texture_image_as_data(const texture_image *img);

/* Decodes the PNG, JPEG or OpenEXR file at path, told apart by its first
 * bytes, not its name, and builds its levels. Alpha is ignored. On failure *out is left empty and err names
 * the file: GLINT_ERR_IO when it cannot be read, GLINT_ERR_INVALID when it
 * is not a PNG or JPEG, is corrupt or is too large, GLINT_ERR_NOMEM. */
glint_status texture_image_load_file(texture_image *out, const char *path, glint_error *err);

/* The checks texture_image_load_file makes before decoding: that path is a
 * regular file it can read, within the size limit, beginning as a PNG or a
 * JPEG does; the same messages. Nothing is decoded: a scene decodes a
 * texture's file only once a material uses it. */
glint_status texture_image_check_file(const char *path, glint_error *err);

/* As texture_image_load_file, from size bytes at data; `what` names the
 * source in messages. */
glint_status texture_image_load_memory(texture_image *out, const void *data, size_t size,
                                       const char *what, glint_error *err);

/* An image over width x height pixels of sRGB bytes at srgb (3 a pixel, top
 * row first), which are not copied: they must outlive the image, and
 * texture_image_free leaves them alone. For pixels decoded ahead of time,
 * such as the seed room's Moon map, so that no decoding runs at start-up. */
texture_image texture_image_borrow(int width, int height, const unsigned char *srgb);

/* Frees the levels img owns (none are left). */
void texture_image_free_levels(texture_image *img);

/* Frees the pixels and levels it owns and empties the image. NULL is allowed. */
void texture_image_free(texture_image *img);

#endif
