/* shape_kind.h - one record per kind of analytic shape, and the registry
 * that lists them.
 *
 * A kind is one file (sphere.c, disk.c, ...) that exports one shape_kind:
 * its scene-file name, its parameter table (the fields of glint_shape it
 * reads, with defaults and ranges: core/params.h), what the accelerator and
 * the integrator may assume of it, and its operations, all in object space.
 * shape.c moves rays and results between world and object space; the
 * scene-file loader, the C API's checks and the docs test all read the
 * parameter table. Adding a kind: docs/architecture.md. */
#ifndef GLINT_GEOMETRY_SHAPE_KIND_H
#define GLINT_GEOMETRY_SHAPE_KIND_H

#include <stdbool.h>
#include "core/params.h"
#include "core/error.h"
#include "geometry/shape.h"

struct shape_kind {
    const char *name;         /* the scene file's `type` */
    glint_shape_kind id;
    param_table params;
    /* The most times one line crosses the surface: 1 for flat kinds, 2 for
     * convex ones (a ray leaving such a surface outwards never meets it
     * again), 4 for a torus. Shadow rays look for this many crossings. */
    int max_crossings;
    /* Lies in one plane: its normal is the same at every point, and a ray
     * leaving it never meets it again. */
    bool flat;
    /* Not convex though no line crosses it more than twice (a hyperboloid
     * of two sheets): a ray leaving it outwards may still meet it. */
    bool saddle;
    /* A combination of other shapes (csg.c): its hits are on its parts. */
    bool csg;
    /* Whether s encloses a solid, so it can be a part of a combination (a
     * plane encloses the half-space behind it); NULL: never (a disk). */
    bool (*closed)(const shape *s);
    /* For a kind whose solid is unbounded (a plane's half-space): whether
     * object-space point p is inside it, which a ray that never crosses its
     * surface may be. NULL: a bounded solid, which such a ray is outside. */
    bool (*contains)(const shape *s, vec3 p);
    /* Checks what the table cannot (rules across fields) and fills the
     * fields of s derived from s->desc; NULL: nothing to do. */
    glint_status (*init)(shape *s, glint_error *err);
    /* shape_intersect for a ray already in object space (NULL only for a
     * sphere set). */
    bool (*intersect)(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit);
    /* For a convex solid: where r's whole line is inside it (out->t_in,
     * t_out, part_in, part_out), in one go; false when the line misses
     * it. A combination walks its convex parts by their spans instead of
     * their crossings one at a time. NULL: not convex. */
    bool (*span)(const shape *s, const ray *r, shape_span *out);
    /* span for four rays at once, in object space: each lane's bits as span
     * gives them (leaf_in and leaf_out left alone), and the mask of the
     * lanes for which span says true. NULL: lanes one at a time. A
     * combination whose parts all have it finds its hits four lanes at a
     * time. */
    quad_mask (*span4)(const shape *s, const quad_ray *r, quad_span *out);
    /* intersect with tmin 0 for the four lanes of *r (in object space) from
     * `first` on, each lane's bits as intersect gives them: hit->t, for a
     * kind of several parts (a cylinder's caps) hit->part, and for a
     * combination hit->part and hit->leaf (shape_intersect4 sets the
     * others' to 0 and -1). NULL: the accelerator tests lanes one by one.
     * Unbounded kinds must have it. */
    quad_mask (*intersect4)(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit);
    /* Fills out->n (object space, any length) from out->p_obj and part. */
    void (*surface)(const shape *s, int part, surface *out);
    /* The normal to shade with at out->p_obj (object space, any length,
     * either side) where it is not the surface's own: a mesh's vertex
     * normals, blended. NULL, or false: the surface's. */
    bool (*shading)(const shape *s, int part, const surface *at, vec3 *n);
    /* Fills out->u and out->v, only when a texture asks for them. */
    void (*uv)(const shape *s, int part, surface *out);
    /* Object-space bounds; NULL: unbounded (a plane), which the
     * accelerator tests itself rather than through its hierarchy. */
    void (*bounds)(const shape *s, vec3 *lo, vec3 *hi);
    /* The shape's centre in object space, where spherical and cylindrical
     * mappings are centred (shape_center); NULL: the description's
     * `center` (a sphere's or disk's centre, a cylinder's or cone's base
     * centre, a plane's point). */
    vec3 (*center)(const shape *s);
    /* A point of the surface, uniform by area, for (u1, u2) in [0, 1)^2,
     * in object space, *n its unit outward (front) normal; returns the
     * surface's whole area. NULL: the surface has no finite area (a plane). */
    double (*sample)(const shape *s, double u1, double u2, vec3 *p, vec3 *n);
};

extern const shape_kind sphere_kind, plane_kind, polygon_kind, box_kind, cylinder_kind, cone_kind, disk_kind,
    torus_kind, quadric_kind, union_kind, intersection_kind, difference_kind;

/* A closed mesh as a part of a combination (mesh_part.c): not in the
 * registry, as a scene file's `mesh` is no shape and only
 * glint_scene_add_mesh_part makes one. */
extern const shape_kind mesh_part_kind;

/* Many spheres as one shape (sphere_set.c): not in the registry either,
 * as only glint_scene_add_spheres makes one. It has no intersect: the
 * accelerator tests its spheres one by one (accel_spheres.c). */
extern const shape_kind sphere_set_kind;

/* "a" or "an", as the name of a kind of object takes it in a message ("an
 * intersection"). */
static inline const char *object_article(const char *name)
{
    return name[0] == 'i' ? "an" : "a";
}

/* Whether count points (3 or 4) make a convex planar polygon, as a
 * polygon shape needs. */
bool polygon_is_convex(const glint_vec3 *points, int count);

/* The `closed` of kinds that always are (spheres, boxes, tori, planes). */
bool shape_always_closed(const shape *s);

/* The `center` of kinds whose description has no centre (boxes,
 * polygons): the middle of their object-space bounds. */
vec3 shape_bounds_middle(const shape *s);

/* The kind with that public id, or NULL for an id no kind has. */
const shape_kind *shape_kind_of(glint_shape_kind id);

/* The number of kinds, and kind i of them, in the order the docs list them. */
int shape_kind_count(void);
const shape_kind *shape_kind_at(int i);

#endif
