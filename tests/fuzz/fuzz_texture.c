/* fuzz_texture.c - libFuzzer target for the texture decoder: feeds arbitrary
 * bytes to texture_image_load_memory (PNG, JPEG or OpenEXR, told apart by
 * their magic bytes) and checks what the API promises. A refused image must
 * come with a message naming its source and leave the image empty; a
 * decoded one must have a size within the decoder's limits (sides, pixels and
 * bytes) and all of its
 * width x height x 3 bytes (or floats, finite and not negative, for
 * OpenEXR) of pixels, which ASan checks. A broken promise aborts, which
 * libFuzzer counts as a crash.
 *
 * libpng refuses a critical chunk whose CRC is wrong, which nearly every
 * mutation of a PNG makes it; so a PNG whose CRCs are wrong is decoded a
 * second time with them made right, to reach what lies past the check. */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sanitizer/asan_interface.h>
#include <zlib.h>
#include "glint.h"
#include "image/texture_image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void check_refused(const texture_image *img, glint_status st, const glint_error *err)
{
    if ((st != GLINT_ERR_INVALID && st != GLINT_ERR_NOMEM) || !strstr(err->message, "'fuzz-texture'"))
        abort();
    if (img->width != 0 || img->height != 0 || img->srgb || img->hdr || img->owned || img->linear)
        abort();
}

static void check_decoded(const texture_image *img)
{
    if (img->width < 1 || img->height < 1 || (unsigned long)img->width > TEXTURE_IMAGE_MAX_SIDE ||
        (unsigned long)img->height > TEXTURE_IMAGE_MAX_SIDE ||
        (unsigned long)img->width * (unsigned long)img->height > TEXTURE_IMAGE_MAX_PIXELS)
        abort();
    bool hdr = img->hdr != NULL;
    size_t n = 3 * (size_t)img->width * (size_t)img->height;
    if (n * (hdr ? sizeof(float) : 1) > TEXTURE_IMAGE_MAX_BYTES)
        abort();
    if (hdr == (img->srgb != NULL) || img->owned != (hdr ? (const void *)img->hdr : (const void *)img->srgb) ||
        !img->linear)
        abort();
    /* Every byte of the pixels must be there, and after floats TEXEL_SLACK.
     * ASan checks the whole buffer at once: reading its bytes one by one
     * would find the same short buffer, but took 4 to 9 s more for the
     * largest image glint allows (which a valid arithmetic-coded JPEG of
     * 300 bytes can be). */
    const volatile unsigned char *missing =
        __asan_region_is_poisoned(img->owned, hdr ? n * sizeof(float) + TEXEL_SLACK : n);
    if (missing) {
        (void)*missing; /* ASan's report: where the buffer ends and who allocated it */
        abort();
    }
    float first = texture_image_at(img, 0), last = texture_image_at(img, n - 1);
    float top = hdr ? 3.0e38f : 1;
    if (!(first >= 0 && first <= top && last >= 0 && last <= top))
        abort();
}

static void decode_and_check(const uint8_t *data, size_t size)
{
    texture_image img;
    glint_error err;
    /* Garbage in both, so that a field the decoder forgets to set shows. */
    memset(&img, 0xa5, sizeof img);
    err.message[0] = '\0';
    glint_status st = texture_image_load_memory(&img, data, size, "fuzz-texture", &err);
    if (st == GLINT_OK)
        check_decoded(&img);
    else
        check_refused(&img, st, &err);
    texture_image_free(&img);
}

static uint32_t read_be32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Rewrites the CRC of each whole chunk of the PNG in data, after its
 * 8-byte signature; returns whether any was wrong. */
static bool png_fix_crcs(uint8_t *data, size_t size)
{
    bool fixed = false;
    size_t at = 8;
    while (size - at >= 12 && read_be32(data + at) <= size - at - 12) {
        size_t len = read_be32(data + at);
        uint8_t *crc = data + at + 8 + len;
        uint32_t want = (uint32_t)crc32(0, data + at + 4, (uInt)(4 + len));
        if (read_be32(crc) != want) {
            crc[0] = (uint8_t)(want >> 24);
            crc[1] = (uint8_t)(want >> 16);
            crc[2] = (uint8_t)(want >> 8);
            crc[3] = (uint8_t)want;
            fixed = true;
        }
        at += 12 + len;
    }
    return fixed;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    decode_and_check(data, size);
    if (size < sizeof png_magic || memcmp(data, png_magic, sizeof png_magic) != 0)
        return 0;
    uint8_t *copy = malloc(size);
    if (!copy)
        return 0;
    memcpy(copy, data, size);
    if (png_fix_crcs(copy, size))
        decode_and_check(copy, size);
    free(copy);
    return 0;
}
