/* keyframes.c - values that change with time (glint_keys, glint.h): the
 * value at a time from the keys about it, by straight lines, by steps, or
 * by Steffen's monotone cubic ("A simple method for monotonic
 * interpolation in one dimension", 1990), chosen because a camera or a
 * ball keyed to stop must not swing past its key as Catmull-Rom's cubic
 * does. Each number of a value is interpolated on its own. */
#include <math.h>
#include "core/error.h"
#include "glint.h"

glint_status glint_keys_check(const glint_keys *keys, glint_error *err)
{
    if (keys->count < 1)
        return error_set(err, GLINT_ERR_INVALID, "keys need at least one key, got %d", keys->count);
    if (keys->width < 1 || keys->width > GLINT_KEY_WIDTH_MAX)
        return error_set(err, GLINT_ERR_INVALID, "a keyed value has 1 to %d numbers, got %d", GLINT_KEY_WIDTH_MAX,
                         keys->width);
    if (keys->interpolate < GLINT_INTERPOLATE_LINEAR || keys->interpolate > GLINT_INTERPOLATE_STEP)
        return error_set(err, GLINT_ERR_INVALID, "unknown interpolation %d", (int)keys->interpolate);
    for (int i = 0; i < keys->count; i++) {
        double t = keys->times[i];
        if (!isfinite(t))
            return error_set(err, GLINT_ERR_INVALID, "key %d's time is not a finite number", i + 1);
        if (i > 0 && !(t > keys->times[i - 1]))
            return error_set(err, GLINT_ERR_INVALID, "key times must increase: key %d at %g s comes after %g s",
                             i + 1, t, keys->times[i - 1]);
        for (int c = 0; c < keys->width; c++)
            if (!isfinite(keys->values[i * keys->width + c]))
                return error_set(err, GLINT_ERR_INVALID, "key %d's value is not finite", i + 1);
    }
    return GLINT_OK;
}

/* The slope of number c at key i for the smooth cubic: 0 at the first and
 * last key (the value holds still beyond them, so the slope stays
 * continuous there too) and where the value turns; otherwise Steffen's,
 * the slope of the parabola through the three keys about it, limited so
 * that no interval's cubic leaves the values at its ends. */
static double smooth_slope(const glint_keys *k, int i, int c)
{
    if (i == 0 || i == k->count - 1)
        return 0;
    const double *v = k->values;
    int w = k->width;
    double h0 = k->times[i] - k->times[i - 1], h1 = k->times[i + 1] - k->times[i];
    double s0 = (v[i * w + c] - v[(i - 1) * w + c]) / h0, s1 = (v[(i + 1) * w + c] - v[i * w + c]) / h1;
    if (!(s0 * s1 > 0))
        return 0;
    double parabola = (s0 * h1 + s1 * h0) / (h0 + h1);
    double least = fmin(fabs(s0), fmin(fabs(s1), 0.5 * fabs(parabola)));
    return s0 > 0 ? 2 * least : -2 * least;
}

void glint_keys_value(const glint_keys *keys, double time, double *out)
{
    int n = keys->count, w = keys->width;
    const double *v = keys->values;
    /* The last key at or before time, clamped to the first. */
    int lo = 0, hi = n - 1;
    if (!(time > keys->times[0]))
        hi = 0;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (keys->times[mid] <= time)
            lo = mid;
        else
            hi = mid - 1;
    }
    int i = lo;
    if (i == n - 1 || keys->interpolate == GLINT_INTERPOLATE_STEP || time <= keys->times[i]) {
        for (int c = 0; c < w; c++)
            out[c] = v[i * w + c];
        return;
    }
    double h = keys->times[i + 1] - keys->times[i], s = (time - keys->times[i]) / h;
    for (int c = 0; c < w; c++) {
        double a = v[i * w + c], b = v[(i + 1) * w + c];
        if (keys->interpolate == GLINT_INTERPOLATE_LINEAR) {
            out[c] = a + (b - a) * s;
            continue;
        }
        /* Cubic Hermite from a to b with the keys' slopes. */
        double s2 = s * s, s3 = s2 * s;
        double from_a = 2 * s3 - 3 * s2 + 1, from_b = 3 * s2 - 2 * s3;
        double along_a = s3 - 2 * s2 + s, along_b = s3 - s2;
        double x = from_a * a + from_b * b + h * (along_a * smooth_slope(keys, i, c) + along_b * smooth_slope(keys, i + 1, c));
        /* Steffen's slopes keep the cubic between a and b; this keeps its
         * rounding there too, so a value keyed within a range stays in it. */
        double least = fmin(a, b), most = fmax(a, b);
        out[c] = x < least ? least : x > most ? most : x;
    }
}
