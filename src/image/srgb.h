/* srgb.h - fast 8-bit sRGB encoding for image output. */
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

#endif
