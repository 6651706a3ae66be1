/* surface_coords.h - the texture coordinates of points near a hit, and how
 * they change across the surface, for what needs more than the hit's own:
 * bump and normal maps (surface_detail.c) and the footprint a sample
 * covers of an image, which picks its mipmap level.
 *
 * Rather than every kind of shape giving its derivatives, they are
 * measured: the coordinates of two points a small step either way along
 * two tangent directions (a mesh triangle's uv carried on affinely, a
 * shape's own uv or any mapping of the point) give the gradients of u and
 * of v in the tangent plane. */
#ifndef GLINT_RENDER_SURFACE_COORDS_H
#define GLINT_RENDER_SURFACE_COORDS_H

#include "accel/accel.h"
#include "scene/scene.h"

/* Where on what a hit is: enough to find the texture coordinates of
 * points near it. */
typedef struct coord_spot {
    const shape *sh;          /* the shape hit, as it is at the hit's time; NULL for a mesh */
    const mesh *me;
    unsigned triangle;
    const transform *to_object; /* NULL: object space is world space */
    vec3 center;              /* the thing's centre, for mappings */
    const surface *s;
    shape moved_shape;        /* where a moving shape or mesh is at the hit's time */
    instance moved_instance;
} coord_spot;

/* Fills *at for hit h of the scene, whose surface is s (which must outlive
 * it). */
void coord_spot_init(const glint_scene *scene, const accel_hit *h, const surface *s, coord_spot *at);

/* World point q in the coordinates of the thing hit. */
vec3 coord_object_point(const coord_spot *at, vec3 q);

/* The texture coordinates t looks up at world point q near the hit: its
 * mapping's, carried into its own space. */
void coord_at(const coord_spot *at, const texture *t, vec3 q, double *u, double *v);

/* Two unit tangents, at right angles, across unit normal n. */
void coord_tangents(vec3 n, vec3 *t1, vec3 *t2);

/* The step the differences take along the surface at p: small against
 * the point's distance from the origin, as a ray's offset is. */
double coord_step(vec3 p);

/* The world gradients of t's u and v at the hit, in the plane across unit
 * normal n: g_u . d is how much u grows along a short step d. */
void coord_gradients(const coord_spot *at, const texture *t, vec3 n, vec3 *g_u, vec3 *g_v);

/* How far along t's u and v the footprint of a sample reaches at the hit,
 * squared (uv_extent), whose coordinates (coord_at's) are (u, v): a disc
 * `width` across, square to the unit ray direction d, laid on the surface
 * of unit normal n (an ellipse, longer the more the surface is slanted to
 * the ray), seen through the gradients of u and v. */
uv_extent coord_footprint(const coord_spot *at, const texture *t, vec3 n, vec3 d, double width, double u,
                          double v);

#endif
