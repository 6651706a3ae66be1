/* filter.c - the pixel reconstruction filters' profiles, and the tables
 * that spread a pixel's samples as each profile (filter.h). */
#include <math.h>
#include "core/vec.h"
#include "render/filter.h"

double pixel_filter_default_radius(glint_filter type)
{
    static const double radius[] = {[GLINT_FILTER_BOX] = 0.5, [GLINT_FILTER_TENT] = 1,
                                    [GLINT_FILTER_GAUSSIAN] = 1.5, [GLINT_FILTER_MITCHELL] = 2,
                                    [GLINT_FILTER_LANCZOS] = 3};
    return radius[type];
}

static double sinc(double x)
{
    return fabs(x) < 1e-9 ? 1 : sin(M_PI * x) / (M_PI * x);
}

/* Mitchell and Netravali's cubic with B = C = 1/3, the pair they found
 * best balanced between blur and ringing, on |t| < 2. */
static double mitchell(double t)
{
    const double b = 1.0 / 3, c = 1.0 / 3;
    t = fabs(t);
    if (t < 1)
        return ((12 - 9 * b - 6 * c) * t * t * t + (-18 + 12 * b + 6 * c) * t * t + (6 - 2 * b)) / 6;
    if (t < 2)
        return ((-b - 6 * c) * t * t * t + (6 * b + 30 * c) * t * t + (-12 * b - 48 * c) * t + (8 * b + 24 * c)) / 6;
    return 0;
}

/* The profile before scaling, at x pixels from the centre. */
static double profile(const pixel_filter *f, double x)
{
    double r = f->radius;
    x = fabs(x);
    if (x >= r)
        return 0;
    switch (f->type) {
    case GLINT_FILTER_TENT: return 1 - x / r;
    /* A standard deviation of a third of the radius, shifted down to meet
     * zero at the radius. */
    case GLINT_FILTER_GAUSSIAN: {
        double sigma = r / 3;
        return exp(-x * x / (2 * sigma * sigma)) - exp(-r * r / (2 * sigma * sigma));
    }
    /* Stretched from its natural radius of 2 to the one asked for. */
    case GLINT_FILTER_MITCHELL: return mitchell(2 * x / r);
    /* The windowed sinc: a lobe a pixel wide, the window as wide as the radius. */
    case GLINT_FILTER_LANCZOS: return sinc(x) * sinc(x / r);
    default: return 1;
    }
}

/* Steps of the midpoint rule that build a filter's table. */
#define FILTER_STEPS (16 * FILTER_TABLE)

/* Tabulates the inverse of |f|'s integral from 0 over [0, radius], and
 * f's own integral: one pass for the totals, a second walking the same
 * steps to where the integral reaches each entry's share. */
static void tabulate(pixel_filter *f)
{
    double step = f->radius / FILTER_STEPS, total = 0, signed_sum = 0;
    for (int i = 0; i < FILTER_STEPS; i++) {
        double v = profile(f, (i + 0.5) * step);
        total += fabs(v) * step;
        signed_sum += v * step;
    }
    f->integral = 2 * signed_sum;
    double below = 0; /* |f|'s integral up to step i */
    int i = 0, k = 0;
    while (k <= FILTER_TABLE) {
        double target = total * k / FILTER_TABLE;
        double width = fabs(profile(f, (i + 0.5) * step)) * step;
        if (below + width < target && i < FILTER_STEPS - 1) {
            below += width;
            i++;
            continue;
        }
        double within = width > 0 ? (target - below) / width : 0;
        f->offset[k++] = (float)((i + fmin(fmax(within, 0), 1)) * step);
    }
}

void pixel_filter_init(pixel_filter *f, glint_filter type, double radius)
{
    *f = (pixel_filter){.type = type, .radius = radius > 0 ? radius : pixel_filter_default_radius(type)};
    f->has_negative_lobes = type == GLINT_FILTER_MITCHELL || type == GLINT_FILTER_LANCZOS;
    if (type == GLINT_FILTER_BOX)
        f->integral = 2 * f->radius;
    else if (type == GLINT_FILTER_TENT)
        f->integral = f->radius;
    else
        tabulate(f);
}

double pixel_filter_value(const pixel_filter *f, double x)
{
    return fabs(x) < f->radius ? profile(f, x) / f->integral : 0;
}

double pixel_filter_offset(const pixel_filter *f, double u, bool *negative)
{
    double r = f->radius, t = 2 * u - 1, s = fabs(t), x;
    *negative = false;
    switch (f->type) {
    /* The box's samples fall as the pixel grid's: exactly, so that the
     * default filter keeps every image's bytes. */
    case GLINT_FILTER_BOX: return t * r;
    case GLINT_FILTER_TENT: x = r * (1 - sqrt(1 - s)); break;
    default: {
        double at = s * FILTER_TABLE;
        int k = (int)at;
        if (k >= FILTER_TABLE)
            k = FILTER_TABLE - 1;
        x = f->offset[k] + (at - k) * (f->offset[k + 1] - f->offset[k]);
        *negative = f->has_negative_lobes && profile(f, x) < 0;
    }
    }
    return t < 0 ? -x : x;
}
