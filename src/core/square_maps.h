/* square_maps.h - maps from the unit square of random samples onto other
 * shapes, keeping strata together, shared by the lens and the lights. */
#ifndef GLINT_CORE_SQUARE_MAPS_H
#define GLINT_CORE_SQUARE_MAPS_H

#include <math.h>
#include <stdbool.h>
#include "core/lanes.h"
#include "core/vec.h"

/* sin t and cos t for |t| <= pi/4 in each lane, by their Taylor series to
 * t^17 and t^16 (the next terms are below 1e-16 there): no range reduction
 * and no call, which the concentric map's angles never need. */
static inline void sincos_quarter_quad(quad_f64 t, quad_f64 *s, quad_f64 *c)
{
    quad_f64 t2 = t * t;
    *s = t * (1 + t2 * (-1.0 / 6 + t2 * (1.0 / 120 + t2 * (-1.0 / 5040 + t2 * (1.0 / 362880 +
             t2 * (-1.0 / 39916800 + t2 * (1.0 / 6227020800 + t2 * (-1.0 / 1307674368000 +
             t2 * (1.0 / 355687428096000)))))))));
    *c = 1 + t2 * (-1.0 / 2 + t2 * (1.0 / 24 + t2 * (-1.0 / 720 + t2 * (1.0 / 40320 +
         t2 * (-1.0 / 3628800 + t2 * (1.0 / 479001600 + t2 * (-1.0 / 87178291200 +
         t2 * (1.0 / 20922789888000))))))));
}

/* The point of the unit disk for (u, v) in [0, 1)^2, in each lane
 * (Shirley and Chiu's concentric map): squares about the centre go to
 * circles, so that neighbouring samples stay neighbours, and equal areas
 * to equal areas. The square's two halves (|a| > |b| and not) are chosen
 * by selects, not branches: stratified samples fall on either side at
 * random, and a mispredicted branch cost more than the rest of the map. */
static inline void concentric_disk_quad(quad_f64 u, quad_f64 v, quad_f64 *x, quad_f64 *y)
{
    quad_f64 a = 2 * u - 1, b = 2 * v - 1;
    quad_mask across = quad_abs(a) > quad_abs(b); /* angle within 45 degrees of the x axis */
    quad_f64 r = quad_select(across, a, b), other = quad_select(across, b, a);
    quad_f64 t = quad_select(r != 0, M_PI / 4 * (other / r), quad_splat(0)), s, c;
    sincos_quarter_quad(t, &s, &c);
    /* Across: the angle is t; otherwise pi/2 - t, whose cosine is sin t. */
    *x = r * quad_select(across, c, s);
    *y = r * quad_select(across, s, c);
}

/* sincos_quarter_quad for one t. */
static inline void sincos_quarter(double t, double *s, double *c)
{
    quad_f64 qs, qc;
    sincos_quarter_quad(quad_splat(t), &qs, &qc);
    *s = qs[0];
    *c = qc[0];
}

/* concentric_disk_quad for one point. */
static inline void concentric_disk(double u, double v, double *x, double *y)
{
    quad_f64 qx, qy;
    concentric_disk_quad(quad_splat(u), quad_splat(v), &qx, &qy);
    *x = qx[0];
    *y = qy[0];
}

#endif
