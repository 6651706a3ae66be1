/* polygon_split.h - a polygon of any number of points, checked and split
 * into triangles: for the scene's polygons (one mesh each) and for readers
 * that gather many polygons into one mesh, which Embree traces faster than
 * a mesh a polygon. */
#ifndef GLINT_SCENE_POLYGON_SPLIT_H
#define GLINT_SCENE_POLYGON_SPLIT_H

#include "core/error.h"
#include "core/vec.h"
#include "model/triangulate.h"

/* Scratch space, reused from one polygon to the next. Zero it to start. */
typedef struct polygon_work {
    triangulate_work triangulate;
    uint32_t *corners;          /* 0 .. n-1, the corner numbers triangulate_polygon takes */
    size_t corner_cap;
} polygon_work;

/* Checks the count points (finite, no two in a row the same, not all in a
 * line, in one plane), writes them to positions (3 floats a point), their
 * unit (Newell) normal to *normal, and the count - 2 triangles that cover
 * the polygon exactly to triangles, as corner numbers 0 .. count-1, three a
 * triangle, in the polygon's winding. GLINT_OK, or the problem in err
 * (GLINT_ERR_INVALID, or GLINT_ERR_NOMEM). */
glint_status polygon_split(polygon_work *w, const vec3 *points, int count, float *positions, vec3 *normal,
                           uint32_t *triangles, glint_error *err);

/* Frees the scratch space. */
void polygon_work_free(polygon_work *w);

#endif
