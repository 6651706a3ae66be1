/* triangulate.h - splitting a model's polygons into triangles: ear clipping
 * in the plane that fits the polygon best, so that concave polygons come
 * out right, and a fan where the polygon is degenerate or crosses itself. */
#ifndef GLINT_MODEL_TRIANGULATE_H
#define GLINT_MODEL_TRIANGULATE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Scratch space, reused from one polygon to the next. Zero it to start. */
typedef struct triangulate_work {
    double *xy;               /* corners projected on the plane, 2 each */
    uint32_t *link;           /* per corner: the previous and next corner still in the ring, and the
                                 previous and next in the list of reflex corners */
    unsigned char *reflex;    /* per corner: in that list */
    size_t cap;               /* corners there is room for */
} triangulate_work;

/* Splits the polygon of n >= 3 corners, corner i at positions + 3 *
 * corners[i], into n - 2 triangles written to out as corner numbers
 * (0 .. n-1), three a triangle, each in the polygon's winding. A convex
 * polygon becomes a fan from corner 0. A concave one is cut by ear
 * clipping in the plane of its Newell normal; where the polygon is
 * degenerate (no normal), crosses itself (no ear left) or is so large and
 * concave that clipping would take more than a million steps and 256 a
 * corner (each corner tried and each point tested is a step), the rest
 * becomes a fan. False when out of memory. */
bool triangulate_polygon(triangulate_work *w, const float *positions, const uint32_t *corners, size_t n,
                         uint32_t *out);

/* Frees the scratch space. */
void triangulate_free(triangulate_work *w);

#endif
