/* poly_roots.c - real roots of a low-degree polynomial in an interval, each
 * isolated between the roots of its derivative (poly_roots.h). */
#include <math.h>
#include "geometry/poly_roots.h"

static double evaluate(const double *c, int degree, double x)
{
    double v = c[degree];
    for (int i = degree - 1; i >= 0; i--)
        v = v * x + c[i];
    return v;
}

/* The one root in [a, b] of a polynomial monotone there, fa and fb of
 * opposite signs: false position (the Illinois variant, which halves the
 * weight of an end kept twice, so that neither end sticks), falling back
 * to bisection when a step would leave the bracket, until the bracket
 * holds no double between its ends. */
static double bracketed_root(const double *c, int degree, double a, double b, double fa, double fb)
{
    int kept = 0;
    for (int i = 0; i < 200; i++) {
        double x = (a * fb - b * fa) / (fb - fa);
        if (!(x > a && x < b))
            x = a + 0.5 * (b - a);
        if (!(x > a && x < b))
            break; /* no double lies between a and b */
        double fx = evaluate(c, degree, x);
        if (fx == 0)
            return x;
        if ((fx < 0) == (fa < 0)) {
            a = x;
            fa = fx;
            if (kept == -1)
                fb *= 0.5;
            kept = -1;
        } else {
            b = x;
            fb = fx;
            if (kept == 1)
                fa *= 0.5;
            kept = 1;
        }
    }
    return fabs(fa) < fabs(fb) ? a : b;
}

int poly_roots(const double *c, int degree, double lo, double hi, double *roots, int most)
{
    while (degree > 0 && c[degree] == 0)
        degree--;
    if (degree == 0 || !(lo <= hi))
        return 0;
    if (degree == 1) {
        double x = -c[0] / c[1];
        roots[0] = x;
        return most > 0 && x >= lo && x <= hi;
    }
    /* The ends of the pieces: lo, the derivative's roots, hi. */
    double derivative[POLY_MAX_DEGREE] = {0}, ends[POLY_MAX_DEGREE + 2];
    for (int i = 1; i <= degree; i++)
        derivative[i - 1] = i * c[i];
    int turns = poly_roots(derivative, degree - 1, lo, hi, ends + 1, degree);
    ends[0] = lo;
    ends[turns + 1] = hi;
    int count = 0;
    double fa = evaluate(c, degree, lo);
    if (fa == 0 && most > 0)
        roots[count++] = lo;
    for (int k = 0; k <= turns && count <= degree && count < most; k++) {
        double a = ends[k], b = ends[k + 1], fb = evaluate(c, degree, b);
        if (fb == 0 && (count == 0 || roots[count - 1] < b))
            roots[count++] = b;
        else if (fa != 0 && fb != 0 && (fa < 0) != (fb < 0))
            roots[count++] = bracketed_root(c, degree, a, b, fa, fb);
        fa = fb;
    }
    return count;
}
