/* srgb.c - the sRGB transfer curve (IEC 61966-2-1) between linear light and
 * encoded values: images are written in it and textures are read from it. */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <string.h>
#include "glint.h"
#include "image/srgb.h"

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
 * thresholds at or below it. bucket_code[b] is the code of the smallest
 * non-negative float whose bits shifted right by BUCKET_SHIFT are b; a bucket
 * is narrower than the gap between two thresholds, so it holds at most one
 * and a value's code is its bucket's, or one more. */
#define BUCKET_SHIFT 14
#define ONE_BITS 0x3f800000u
static float thresholds[256];
static unsigned char bucket_code[(ONE_BITS >> BUCKET_SHIFT) + 1];
static pthread_once_t tables_once = PTHREAD_ONCE_INIT;

static float float_of_bits(uint32_t b)
{
    float f;
    memcpy(&f, &b, sizeof f);
    return f;
}

static uint32_t bits_of_float(float f)
{
    uint32_t b;
    memcpy(&b, &f, sizeof b);
    return b;
}

static void make_tables(void)
{
    /* Non-negative floats sort as their bit patterns do. Each threshold
     * starts from the inverse curve at the midpoint between codes k - 1 and
     * k, within an ulp or two of it, and steps to the first float whose code
     * is k: a few calls to code_of each, where a search over all floats
     * below 1 took thirty (0.45 ms, waited for by the first image written). */
    for (int k = 1; k <= 255; k++) {
        uint32_t b = bits_of_float((float)glint_srgb_to_linear((k - 0.5) / 255.0));
        while (b > 0 && code_of(float_of_bits(b - 1)) >= k)
            b--;
        while (code_of(float_of_bits(b)) < k)
            b++;
        thresholds[k - 1] = float_of_bits(b);
    }
    thresholds[255] = INFINITY; /* no code above 255 */
    int code = 0;
    for (uint32_t b = 0; b <= ONE_BITS >> BUCKET_SHIFT; b++) {
        float lowest = float_of_bits(b << BUCKET_SHIFT);
        while (code < 255 && thresholds[code] <= lowest)
            code++;
        bucket_code[b] = (unsigned char)code;
    }
}

/* srgb_byte once the tables exist. */
static inline unsigned char encode(float linear)
{
    if (!(linear > 0))
        return 0;
    if (linear >= 1)
        return 255;
    uint32_t bits;
    memcpy(&bits, &linear, sizeof bits);
    int code = bucket_code[bits >> BUCKET_SHIFT];
    return (unsigned char)(code + (linear >= thresholds[code]));
}

unsigned char srgb_byte(float linear)
{
    pthread_once(&tables_once, make_tables);
    return encode(linear);
}

void srgb_encode(unsigned char *dst, const float *src, size_t n)
{
    pthread_once(&tables_once, make_tables);
    for (size_t i = 0; i < n; i++)
        dst[i] = encode(src[i]);
}

void srgb_encode16(unsigned char *dst, const float *src, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        unsigned code = (unsigned)(glint_linear_to_srgb(src[i]) * 65535.0 + 0.5);
        dst[2 * i] = (unsigned char)(code >> 8);
        dst[2 * i + 1] = (unsigned char)code;
    }
}

void srgb_encode_depth(unsigned char *dst, const float *src, size_t n, int depth)
{
    if (depth == 16)
        srgb_encode16(dst, src, n);
    else
        srgb_encode(dst, src, n);
}
