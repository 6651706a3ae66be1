/* srgb.h - sRGB encoding for image output: fast 8-bit codes, and 16-bit. */
#ifndef GLINT_IMAGE_SRGB_H
#define GLINT_IMAGE_SRGB_H

#include <stddef.h>

/* The 8-bit sRGB code of a linear value: exactly
 * (int)(glint_linear_to_srgb(linear) * 255 + 0.5), from tables of the
 * thresholds between codes (computed once, thread-safely) instead of a pow
 * per value. NaN and values <= 0 give 0, >= 1 give 255. */
unsigned char srgb_byte(float linear);

/* dst[i] = srgb_byte(src[i]) for i < n. */
void srgb_encode(unsigned char *dst, const float *src, size_t n);

/* The 16-bit sRGB codes of src[i] for i < n, each
 * (int)(glint_linear_to_srgb(src[i]) * 65535 + 0.5), as 2 * n bytes at
 * dst, the high byte first (as PNG and PPM store them). */
void srgb_encode16(unsigned char *dst, const float *src, size_t n);

/* The bytes srgb_encode (depth 8) or srgb_encode16 (depth 16) writes. */
void srgb_encode_depth(unsigned char *dst, const float *src, size_t n, int depth);

#endif
