/* square_maps.h - maps from the unit square of random samples onto other
 * shapes, keeping strata together, shared by the lens and the lights. */
#ifndef GLINT_CORE_SQUARE_MAPS_H
#define GLINT_CORE_SQUARE_MAPS_H

#include <math.h>
#include <stdbool.h>
#include "core/vec.h"

/* sin t and cos t for |t| <= pi/4, by their Taylor series to t^17 and
 * t^16 (the next terms are below 1e-16 there): no range reduction and no
 * call, which the concentric map's angles never need. */
static inline void sincos_quarter(double t, double *s, double *c)
{
    double t2 = t * t;
    *s = t * (1 + t2 * (-1.0 / 6 + t2 * (1.0 / 120 + t2 * (-1.0 / 5040 + t2 * (1.0 / 362880 +
             t2 * (-1.0 / 39916800 + t2 * (1.0 / 6227020800 + t2 * (-1.0 / 1307674368000 +
             t2 * (1.0 / 355687428096000)))))))));
    *c = 1 + t2 * (-1.0 / 2 + t2 * (1.0 / 24 + t2 * (-1.0 / 720 + t2 * (1.0 / 40320 +
         t2 * (-1.0 / 3628800 + t2 * (1.0 / 479001600 + t2 * (-1.0 / 87178291200 +
         t2 * (1.0 / 20922789888000))))))));
}

/* The point of the unit disk for (u, v) in [0, 1)^2 (Shirley and Chiu's
 * concentric map): squares about the centre go to circles, so that
 * neighbouring samples stay neighbours, and equal areas to equal areas.
 * The square's two halves (|a| > |b| and not) are chosen by selects, not
 * branches: stratified samples fall on either side at random, and a
 * mispredicted branch cost more than the rest of the map. */
static inline void concentric_disk(double u, double v, double *x, double *y)
{
    double a = 2 * u - 1, b = 2 * v - 1;
    bool across = fabs(a) > fabs(b); /* angle within 45 degrees of the x axis */
    double r = across ? a : b, other = across ? b : a;
    double t = r != 0 ? M_PI / 4 * (other / r) : 0, s, c;
    sincos_quarter(t, &s, &c);
    /* Across: the angle is t; otherwise pi/2 - t, whose cosine is sin t. */
    *x = r * (across ? c : s);
    *y = r * (across ? s : c);
}

#endif
