/* color.h - linear RGB colour arithmetic. */
#ifndef GLINT_CORE_COLOR_H
#define GLINT_CORE_COLOR_H

#include <math.h>
#include "glint.h"

typedef glint_color color;

static inline color rgb(double r, double g, double b) { color c = {r, g, b}; return c; }
static inline color rgb_add(color a, color b) { return rgb(a.r + b.r, a.g + b.g, a.b + b.b); }
static inline color rgb_mul(color a, color b) { return rgb(a.r * b.r, a.g * b.g, a.b * b.b); }
static inline color rgb_scale(color a, double s) { return rgb(a.r * s, a.g * s, a.b * s); }
/* a + b * s */
static inline color rgb_madd(color a, color b, double s) { return rgb(a.r + b.r * s, a.g + b.g * s, a.b + b.b * s); }
static inline color rgb_lerp(color a, color b, double t) { return rgb_madd(rgb_scale(a, 1.0 - t), b, t); }
/* The mean of the channels: a colour's brightness, to weigh lights by. */
static inline double rgb_mean(color a) { return (a.r + a.g + a.b) / 3; }
static inline double rgb_max(color a) { double m = a.r > a.g ? a.r : a.g; return m > a.b ? m : a.b; }
/* True for a colour with finite, non-negative channels. */
static inline int rgb_is_valid(color c)
{
    return isfinite(c.r) && isfinite(c.g) && isfinite(c.b) && c.r >= 0 && c.g >= 0 && c.b >= 0;
}

#endif
