/* corner_angle.c - atan2 rounded to float, without atan2 but where the
 * rounding could go either way.
 *
 * The angle is computed in double to within a relative 2^-43 of the true
 * one: its tangent's octant, then atan(t) = atan(c) + atan(u) with c the
 * nearest eighth to t and u = (t - c) / (1 + t c), so |u| <= 1/16, and
 * atan(u) by its series to u^9 (the first term left out is below u^11 /
 * 11, a relative 2^-43.5). atan2 itself is within an ulp of the true angle,
 * a relative 2^-52. So when every double within a relative 2^-36 of the
 * computed angle rounds to the same float, (float)atan2 is that float;
 * otherwise, about one corner in three thousand, atan2 is asked. */
#include <math.h>
#include <stdbool.h>
#include "core/vec.h"
#include "model/corner_angle.h"

/* atan(i / 8) for i = 0 to 8, correctly rounded. */
static const double atan_eighths[9] = {
    0x0p+0,
    0x1.fd5ba9aac2f6ep-4,
    0x1.f5b75f92c80ddp-3,
    0x1.6f61941e4def1p-2,
    0x1.dac670561bb4fp-2,
    0x1.1e00babdefeb4p-1,
    0x1.4978fa3269ee1p-1,
    0x1.700a7c5784634p-1,
    0x1.921fb54442d18p-1,
};

/* The relative distance from the computed angle within which atan2's
 * angle surely lies. */
#define MARGIN 0x1p-36

/* corner_angle's answer outside the range of its reduction. */
static float far_angle(double cross, double dot)
{
    return isfinite(cross) && isfinite(dot) ? (float)atan2(cross, dot) : 0.0f;
}

float corner_angle(double cross, double dot)
{
    double y = cross, x = fabs(dot);
    bool steep = y > x;
    double num = steep ? x : y, den = steep ? y : x;
    /* A negative cross (-0 too), both zero, either not finite (num is
     * then not at most den, or den not below 2^900), and the far ends of
     * double's range (where the reduction below could overflow or lose
     * bits) go to far_angle. */
    if (signbit(cross) || !(num <= den) || !(den > 0x1p-900 && den < 0x1p900))
        return far_angle(cross, dot);
    int i = (int)(num / den * 8 + 0.5);
    double c = i * 0.125;
    double u = (num - c * den) / (den + c * num), u2 = u * u;
    double a = atan_eighths[i] + u * (1 + u2 * (-1.0 / 3 + u2 * (1.0 / 5 + u2 * (-1.0 / 7 + u2 * (1.0 / 9)))));
    if (steep)
        a = M_PI / 2 - a;
    if (dot < 0)
        a = M_PI - a;
    float lo = (float)(a - a * MARGIN), hi = (float)(a + a * MARGIN);
    return lo == hi ? lo : far_angle(cross, dot);
}
