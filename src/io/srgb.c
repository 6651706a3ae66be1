/* srgb.c - the sRGB transfer curve (IEC 61966-2-1) between linear light and
 * encoded values: images are written in it and textures are read from it. */
#include <math.h>
#include "glint.h"

/* NaN goes to 0 rather than through the comparisons below, so a stray NaN
 * pixel comes out black instead of as whatever a cast of NaN gives. */
static double clamp_unit(double x)
{
    if (!(x > 0.0))
        return 0.0;
    return x < 1.0 ? x : 1.0;
}

double glint_linear_to_srgb(double linear)
{
    double x = clamp_unit(linear);
    return x < 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

double glint_srgb_to_linear(double srgb)
{
    double x = clamp_unit(srgb);
    return x < 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}
