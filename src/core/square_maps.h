/* square_maps.h - maps from the unit square of random samples onto other
 * shapes, keeping strata together, shared by the lens and the lights. */
#ifndef GLINT_CORE_SQUARE_MAPS_H
#define GLINT_CORE_SQUARE_MAPS_H

#include <math.h>
#include "core/vec.h"

/* The point of the unit disk for (u, v) in [0, 1)^2 (Shirley and Chiu's
 * concentric map): squares about the centre go to circles, so that
 * neighbouring samples stay neighbours, and equal areas to equal areas. */
static inline void concentric_disk(double u, double v, double *x, double *y)
{
    double a = 2 * u - 1, b = 2 * v - 1;
    if (a == 0 && b == 0) {
        *x = *y = 0;
        return;
    }
    double r, phi;
    if (fabs(a) > fabs(b)) {
        r = a;
        phi = M_PI / 4 * (b / a);
    } else {
        r = b;
        phi = M_PI / 2 - M_PI / 4 * (a / b);
    }
    *x = r * cos(phi);
    *y = r * sin(phi);
}

#endif
