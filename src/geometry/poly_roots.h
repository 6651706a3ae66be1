/* poly_roots.h - the real roots of a polynomial of low degree within an
 * interval, found so that none is lost to cancellation: the torus's
 * quartic, whose near-double roots where a ray grazes the tube defeat the
 * closed-form (Ferrari) solution. */
#ifndef GLINT_GEOMETRY_POLY_ROOTS_H
#define GLINT_GEOMETRY_POLY_ROOTS_H

/* The highest degree poly_roots takes. */
#define POLY_MAX_DEGREE 4

/* The real roots of c[0] + c[1] x + ... + c[degree] x^degree (degree at
 * most POLY_MAX_DEGREE) in [lo, hi], lo and hi finite, ascending, into
 * roots (room for degree + 1: rounding may make a root of an end and of
 * a turn both), the first `most` of them (the pieces past those are not
 * searched); returns how many. Between two neighbouring
 * roots of its derivative (found the same way) a polynomial is monotone,
 * so each piece whose ends differ in sign holds exactly one root, which
 * bisection and false position narrow to the last bit. A double root
 * counts only where rounding gives the polynomial a sign change. */
int poly_roots(const double *c, int degree, double lo, double hi, double *roots, int most);

#endif
