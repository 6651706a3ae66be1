/* accel.h - Embree answers every ray query: the nearest hit along a ray, and
 * how much light passes along a shadow segment. The accelerator knows shapes
 * and meshes but not materials: what a crossed surface lets through is
 * asked of the caller. */
#ifndef GLINT_ACCEL_ACCEL_H
#define GLINT_ACCEL_ACCEL_H

#include <stdbool.h>
#include "core/color.h"
#include "geometry/mesh.h"
#include "geometry/shape.h"

typedef struct accel accel;

/* Rays in a packet query: a ray8's lanes. */
#define ACCEL_PACKET RAY8

/* What a ray hit: an analytic shape, or a triangle of a mesh instance. */
typedef struct accel_hit {
    double t;
    int shape;                /* shape index, or -1 for a mesh */
    shape_hit on_shape;       /* shapes: t and part */
    int instance;             /* meshes: the instance index */
    unsigned triangle;        /* meshes: the triangle in the instance's mesh */
    double b1, b2;            /* meshes: barycentric coordinates of vertices 1 and 2 */
    double time;              /* when over the shutter, in [0, 1]: where a moving shape was */
} accel_hit;

/* The geometry an accelerator is built over; it must outlive it. */
typedef struct accel_geometry {
    int threads;              /* threads Embree may build with (its own pool); 0: every core */
    const shape *shapes;
    int shape_count;
    const mesh *meshes;
    int mesh_count;
    const instance *instances;
    int instance_count;
    /* What the caller knows to block all light (NULL: nothing known): per
     * shape, and per instance (every triangle of it). A shadow segment
     * stops at an opaque surface without asking the filter, and an opaque
     * mesh's triangles need no filter callback at all. */
    const bool *shape_opaque;
    const bool *instance_opaque;
    /* When non-NULL and set non-zero, the build stops early: accel_build
     * then returns GLINT_ERR_CANCELLED. */
    const volatile int *cancel;
    /* The camera samples the render will take (width x height x samples a
     * pixel, whatever the threads, tiles or ranks), and how many bounces
     * each may take beyond its first hit (the scene's max_depth when some
     * material reflects, refracts or lets light through, else 0): with few
     * samples for each triangle, bounces counted as samples too, a quicker
     * build of a looser BVH saves more time than its rays lose. */
    double camera_samples;
    int bounces;
} accel_geometry;

/* Builds the Embree device and scenes: one user geometry for every shape;
 * a mesh placed once as world-space triangles in the top scene (its arrays
 * shared when the placement is the identity, else a moved copy of its
 * vertices); a mesh placed more often as one triangle scene sharing its
 * arrays and one Embree instance per placement. Embree's thread pool is
 * limited to g->threads, the threads that will render, so its workers do not
 * compete with them. */
glint_status accel_build(accel **out, const accel_geometry *g, glint_error *err);

/* Releases the Embree objects. NULL is allowed. */
void accel_free(accel *a);

/* Returns what a surface crossing lets through: black for opaque. A
 * crossing into or out of an absorbing thing adds to *depth, the lane's
 * optical depth, what the segment keeps of it being exp(-depth): crossings
 * come in any order, and a sum of depths needs none, where the product of
 * their exponentials could overflow on the way. */
typedef color (*accel_filter_fn)(void *user, const ray *r, const accel_hit *hit, color *depth);

/* Finds the nearest hit of each of up to ACCEL_PACKET rays, the lanes of
 * *r, at time[i] over the shutter (where moving shapes are then; NULL:
 * nothing moves), with t in (0, tmax) (tmax may be INFINITY): found[i] says whether
 * ray i, if active[i], hit, and hit[i] is then its nearest hit. Inactive
 * lanes find nothing. skip[i] is a shape ray i cannot meet (the one it
 * leaves, or the combination holding it, when hit_left_behind says so),
 * which is then not tested at
 * all, or -1. `coherent` says the rays are neighbours (a camera's, and
 * their shadow rays), which Embree's packet traversal can exploit. */
void accel_intersect8(const accel *a, const ray8 *r, const double *time, double tmax, const int skip[ACCEL_PACKET],
                      bool coherent,
                      const bool active[ACCEL_PACKET], accel_hit hit[ACCEL_PACKET], bool found[ACCEL_PACKET]);

/* The light that survives each of up to ACCEL_PACKET shadow segments
 * (0, tmax[i]) along the lanes of *r, at time[i] as for accel_intersect8: the product of filter() over the
 * surface crossings of segment i, times exp(-depth) of the optical depth
 * they add up, black as soon as something opaque blocks it, and black for
 * inactive lanes. skip[i] and `coherent` as for
 * accel_intersect8. */
void accel_transmission8(const accel *a, const ray8 *r, const double *time, const double tmax[ACCEL_PACKET],
                         const int skip[ACCEL_PACKET], bool coherent, const bool active[ACCEL_PACKET],
                         accel_filter_fn filter, void *user, color through[ACCEL_PACKET]);

#endif
