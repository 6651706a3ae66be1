/* crease_normals.h - vertex normals for a model's faces that have none: at
 * each corner, the average of the normals of the faces around its position,
 * weighted by the faces' angles there, over the faces within the crease
 * angle of the corner's own face. Angle weights make the result the same
 * however a polygon was split into triangles (a cube's corner normal is
 * its diagonal), which area weights would not. */
#ifndef GLINT_MODEL_CREASE_NORMALS_H
#define GLINT_MODEL_CREASE_NORMALS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "glint.h"

/* Sets weld[i] to the index of the first of the `count` positions (3
 * floats each) equal to position i, so that faces meeting at copies of one
 * point count as neighbours; 0 and -0 are equal. False when out of memory. */
bool crease_weld(const float *positions, size_t count, uint32_t *weld);

/* Receives the normal of corner k of triangle t: unit length, or zero
 * where no face that counts has area. */
typedef glint_status (*crease_emit_fn)(void *ctx, size_t t, int k, const float normal[3]);

/* Computes the normal of each corner of `count` triangles whose corners
 * are the positions at[3t], at[3t + 1], at[3t + 2] (welded, all below
 * position_count) and hands it to emit, triangle by triangle. With a crease
 * angle of 180 degrees every face around a position counts. count is at
 * most 2^30, so that corner numbers (3t + k) fit in 32 bits. Returns what
 * emit returns when it fails, or GLINT_ERR_NOMEM with "FILE: out of
 * memory" in err. */
glint_status crease_normals(const float *positions, size_t position_count, const uint32_t *at, size_t count,
                            double crease_degrees, crease_emit_fn emit, void *ctx, const char *file,
                            glint_error *err);

#endif
