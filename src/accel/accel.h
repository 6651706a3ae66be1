/* accel.h - Embree answers every ray query: the nearest hit along a ray, and
 * how much light passes along a shadow segment. The accelerator knows shapes
 * but not materials: what a crossed surface lets through is asked of the
 * caller. */
#ifndef GLINT_ACCEL_ACCEL_H
#define GLINT_ACCEL_ACCEL_H

#include <stdbool.h>
#include "core/color.h"
#include "geometry/shape.h"

typedef struct accel accel;

/* Builds the Embree device and scene over `count` shapes (which must outlive
 * the accelerator). */
glint_status accel_build(accel **out, const shape *shapes, int count, glint_error *err);

/* Releases the Embree objects. NULL is allowed. */
void accel_free(accel *a);

/* Finds the nearest shape hit by r with t in (tmin, tmax); sets *index and
 * *hit. */
bool accel_intersect(const accel *a, const ray *r, double tmin, double tmax, int *index, shape_hit *hit);

/* Returns what a surface crossing lets through: black for opaque. */
typedef color (*accel_filter_fn)(void *user, int index, const ray *r, const shape_hit *hit);

/* Returns the product of filter() over every surface crossing of r with t
 * in (tmin, tmax), stopping early at black: the light that survives a
 * shadow segment. */
color accel_transmission(const accel *a, const ray *r, double tmin, double tmax, accel_filter_fn filter,
                         void *user);

#endif
