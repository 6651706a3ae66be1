/* srgb.h - fast 8-bit sRGB encoding for image output. */
#ifndef GLINT_IO_SRGB_H
#define GLINT_IO_SRGB_H

/* The 8-bit sRGB code of a linear value: exactly
 * (int)(glint_linear_to_srgb(linear) * 255 + 0.5), found by a binary search
 * over the 255 thresholds between codes (computed once, thread-safely)
 * instead of a pow per value. NaN and values <= 0 give 0, >= 1 give 255. */
unsigned char srgb_byte(float linear);

#endif
