/* srgb.c - the sRGB transfer curve (IEC 61966-2-1) between linear light and
 * encoded values: images are written in it and textures are read from it. */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <string.h>
#include "glint.h"
#include "io/srgb.h"

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

/* The 8-bit code of a linear value, as glint_linear_to_srgb rounds it. */
static int code_of(float linear)
{
    return (int)(glint_linear_to_srgb(linear) * 255.0 + 0.5);
}

/* thresholds[k - 1] is the smallest float whose code is k (k = 1..255).
 * The curve rises monotonically, so a value's code is the number of
 * thresholds at or below it: the same byte as code_of, without a pow. */
static float thresholds[255];
static pthread_once_t thresholds_once = PTHREAD_ONCE_INIT;

static float float_of_bits(uint32_t b)
{
    float f;
    memcpy(&f, &b, sizeof f);
    return f;
}

static void find_thresholds(void)
{
    /* Non-negative floats sort as their bit patterns do. */
    const uint32_t one = 0x3f800000u;
    for (int k = 1; k <= 255; k++) {
        uint32_t lo = 0, hi = one; /* code_of(lo) < k <= code_of(hi) */
        while (hi - lo > 1) {
            uint32_t mid = lo + (hi - lo) / 2;
            if (code_of(float_of_bits(mid)) >= k)
                hi = mid;
            else
                lo = mid;
        }
        thresholds[k - 1] = float_of_bits(hi);
    }
}

unsigned char srgb_byte(float linear)
{
    pthread_once(&thresholds_once, find_thresholds);
    if (!(linear > 0))
        return 0;
    int lo = 0, hi = 255; /* the answer lies in [lo, hi] */
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (thresholds[mid - 1] <= linear)
            lo = mid;
        else
            hi = mid - 1;
    }
    return (unsigned char)lo;
}
