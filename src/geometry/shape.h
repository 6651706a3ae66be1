/* shape.h - the common interface of the analytic shapes.
 *
 * Every shape is exact (never tessellated). Each kind lives in its own file
 * behind one record (shape_kind.h) and works in object space; shape.c
 * validates descriptions and moves rays and results between world and
 * object space through the shape's transform. Embree sees shapes only
 * through shape_piece_bounds (shape_bounds) and shape_intersect. */
#ifndef GLINT_GEOMETRY_SHAPE_H
#define GLINT_GEOMETRY_SHAPE_H

#include <stdbool.h>
#include "core/lanes.h"
#include "core/transform.h"
#include "core/vec.h"

/* Where r crosses the plane through point with normal n, *t, and whether
 * that is in (tmin, tmax); a ray parallel to the plane misses it. Planes
 * and polygons test with it. */
static inline bool plane_hit(vec3 point, vec3 n, const ray *r, double tmin, double tmax, double *t)
{
    double along = v3_dot(r->d, n);
    *t = v3_dot(v3_sub(point, r->o), n) / along;
    return along != 0 && *t > tmin && *t < tmax;
}

/* plane_hit for the four rays of *r from lane `first` on, in its order of
 * operations, so each lane gets its bits: the mask of the lanes that hit in
 * (tmin, tmax[k]), and *t. The accelerator tests a packet's lanes with it. */
static inline quad_mask plane_hit4(vec3 point, vec3 n, const ray8 *r, int first, double tmin, quad_f64 tmax, quad_f64 *t)
{
    quad_f64 nx = quad_splat(n.x), ny = quad_splat(n.y), nz = quad_splat(n.z);
    quad_f64 along = quad_dot(quad_load(r->dx + first), quad_load(r->dy + first), quad_load(r->dz + first), nx, ny, nz);
    *t = quad_dot(quad_splat(point.x) - quad_load(r->ox + first), quad_splat(point.y) - quad_load(r->oy + first),
                  quad_splat(point.z) - quad_load(r->oz + first), nx, ny, nz) /
         along;
    return (along != 0) & (*t > quad_splat(tmin)) & (*t < tmax);
}

/* Planes are bounded to this many units from the origin for the BVH. */
#define SHAPE_PLANE_EXTENT 1e6

typedef struct shape_kind shape_kind;

/* The spheres of a sphere set (glint_scene_add_spheres, sphere_set.c):
 * plain spheres without a transform, each with its own material, held as
 * one shape at a fraction of the memory a shape each would take. Its
 * shape's hits name the sphere as their part. */
typedef struct sphere_set {
    int count;
    double (*balls)[4];       /* each sphere's centre x, y, z and radius */
    int *materials;           /* each sphere's material */
} sphere_set;

/* A combination (csg.c) holds at most this many parts, nested at most this
 * deep: its walk keeps each part's next crossing on the stack. */
#define SHAPE_MAX_PARTS 256
#define SHAPE_MAX_NESTING 32

typedef struct shape {
    const shape_kind *kind;
    glint_shape desc;         /* object-space description, validated */
    vec3 poly_normal;         /* polygon: unit normal from the point order */
    vec3 plane_u, plane_v;    /* plane and polygon: unit tangents (u, v axes) */
    vec3 edge_in[4];          /* polygon: poly_normal x edge i, pointing inside */
    transform to_world, to_object;
    bool has_transform;       /* false: to_world is the identity */
    bool quad;                /* shape_intersect4 takes it */
    bool flat;                /* a flat kind (shape_kind.flat) without a transform: */
    vec3 flat_n;              /* its surface normal, the same at every hit */
    vec3 center;              /* shape_center's */
    int material;
    transform *poses;         /* moving (shape_move): its world transforms over the shutter, */
    int pose_count;           /* evenly spaced (0: it stands still); owned by the scene. A
                                 combination whose parts move has a count and no poses */
    double time;              /* a moving shape's copy (shape_moved): the time it is at, at
                                 which a combination takes its parts */
    /* A union, intersection or difference: its parts, indices into family
     * (the scene's shape array, which the scene keeps pointing there), in
     * order; owned by the scene. */
    int *parts;
    int part_count;
    size_t part_cap;
    const struct shape *family; /* a combination's (only they read it) */
    int part_of;              /* the combination it is a part of, or -1: it stands alone */
    /* A closed mesh as a part (mesh_part.c): its mesh's solid, owned by
     * the mesh; its triangles' materials when `material` is -1. */
    const struct mesh_solid *solid;
    sphere_set *set;          /* a sphere set's spheres, owned by the scene */
    bool csg;                 /* it is a combination (its kind's csg) */
    /* Its solid is convex, so shape_span_of answers for it: a kind with a
     * span, or an intersection of convex parts (shape_parts_changed). */
    bool convex;
    /* Non-zero: shapes with the same number have the same transform, so a
     * combination maps a ray into their space once for them all (csg.c).
     * Zero: no transform, or one of its own (a moving shape's). */
    unsigned transform_id;
} shape;

/* A hit found by shape_intersect: the ray parameter and which part of the
 * shape (0 for the main surface; caps and box faces number from 1), with
 * SHAPE_PART_FLIPPED set where a difference turned the surface to face the
 * other way. A combination's hit is on one of its parts' shapes: leaf,
 * that shape's index in the scene (only a combination sets it). */
typedef struct shape_hit {
    double t;
    int part;
    int leaf;
} shape_hit;

#define SHAPE_PART_FLIPPED (1 << 30)

/* Where a whole line is inside a convex solid (shape_span_of): from t_in
 * to t_out, either of which may be infinite (a plane's half-space), in
 * through part_in of shape leaf_in and out through part_out of leaf_out
 * (leaves as in shape_hit: a combination's parts). */
typedef struct shape_span {
    double t_in, t_out;
    int part_in, part_out;
    int leaf_in, leaf_out;
} shape_span;

/* Four rays at once, lane k of each field ray k's: four lanes of a packet
 * as the parts of a combination see them (in their object space). */
typedef struct quad_ray {
    quad_f64 ox, oy, oz, dx, dy, dz;
} quad_ray;

/* Lanes `first` to first + 3 of packet r. */
static inline quad_ray quad_ray_of(const ray8 *r, int first)
{
    return (quad_ray){quad_load(r->ox + first), quad_load(r->oy + first), quad_load(r->oz + first),
                      quad_load(r->dx + first), quad_load(r->dy + first), quad_load(r->dz + first)};
}

/* quad_ray *w mapped by transform t, as shape_object_ray maps each lane
 * (xf_point's and xf_vector's operations in their order: the same bits). */
static inline quad_ray quad_object_ray(const transform *t, const quad_ray *w)
{
    const double (*m)[4] = t->m;
#define ROW(i, x, y, z) (quad_splat(m[i][0]) * (x) + quad_splat(m[i][1]) * (y) + quad_splat(m[i][2]) * (z))
    return (quad_ray){ROW(0, w->ox, w->oy, w->oz) + quad_splat(m[0][3]), ROW(1, w->ox, w->oy, w->oz) + quad_splat(m[1][3]),
                      ROW(2, w->ox, w->oy, w->oz) + quad_splat(m[2][3]), ROW(0, w->dx, w->dy, w->dz),
                      ROW(1, w->dx, w->dy, w->dz), ROW(2, w->dx, w->dy, w->dz)};
#undef ROW
}

/* shape_span for four rays at once, lane k of each field ray k's. */
typedef struct quad_span {
    quad_f64 t_in, t_out;
    quad_mask part_in, part_out;
    quad_mask leaf_in, leaf_out;
} quad_span;

/* shape_intersect4's hits: lane k's t, part and leaf as in shape_hit (part
 * 0 and leaf -1 for a shape that is no combination). */
typedef struct quad_hit {
    quad_f64 t;
    int part[QUAD];
    int leaf[QUAD];
} quad_hit;

/* What shading needs to know about a hit point. */
typedef struct surface {
    vec3 p;         /* world position */
    vec3 n;         /* world unit normal, pointing out of the shape (for planes and
                       polygons: the side given by the normal or point order) */
    vec3 shading_n; /* world unit normal for lighting: n, or for meshes the
                       interpolated vertex normal on n's side */
    vec3 p_obj;     /* object-space position, for texture mappings */
    int part;       /* as in shape_hit */
    double u, v;    /* the shape's own texture coordinates, once shape_surface_uv
                       has filled them */
} surface;

/* Fills *s from desc and transform (NULL: identity) after checking every
 * value against its kind's parameter table and rules (3 or 4 coplanar
 * convex polygon points, box min < max, ...) and that the transform is
 * invertible. On failure fills err with a message naming the problem (e.g.
 * "sphere radius must be positive, got -1"). */
glint_status shape_init(shape *s, const glint_shape *desc, const glint_transform *transform,
                        int material, glint_error *err);

/* shape_init for a closed mesh's part of a combination: the mesh's solid
 * (mesh_make_solid's), placed by transform (NULL: identity), with
 * `material` or, -1, its triangles' own. */
glint_status shape_init_mesh_part(shape *s, const struct mesh_solid *solid, const glint_transform *transform,
                                  int material, glint_error *err);

/* shape_init for a sphere set: s holds `set`'s spheres, whose values the
 * caller has checked, and names one by its index as a hit's part. */
void shape_init_sphere_set(shape *s, sphere_set *set);

/* Makes s move over the shutter through `count` (2 or more) invertible
 * world transforms, evenly spaced, in straight lines between them (each
 * number interpolated): s keeps `poses`, which the caller frees after s.
 * A moving shape takes the general paths: it has a transform, no quad
 * test, no fixed normal. */
void shape_move(shape *s, transform *poses, int count);

/* shape_at for a moving shape (pose_count > 0): *out, a copy of s with the
 * transform its poses give at `time`. */
const shape *shape_moved(const shape *s, double time, shape *out);

/* The shape s is at `time` in [0, 1] over the shutter: s itself when it
 * stands still, else shape_moved's copy in *out. Inline: every hit asks. */
static inline const shape *shape_at(const shape *s, double time, shape *out)
{
    return s->pose_count ? shape_moved(s, time, out) : s;
}

/* World ray r in the object space of s, a shape with a transform. The
 * direction is mapped but not normalised, so a point's ray parameter t is
 * the same in both spaces and hits need no conversion back. */
static inline ray shape_object_ray(const shape *s, const ray *r)
{
    ray o = {xf_point(&s->to_object, r->o), xf_vector(&s->to_object, r->d)};
    return o;
}

/* Where world ray r's whole line is inside s, for a convex s (s->convex)
 * that is not a combination (csg.c spans those); false when the line
 * misses it. */
bool shape_span_of(const shape *s, const ray *r, shape_span *span);

/* Recomputes which combinations are convex from `combination` (whose
 * parts changed) up to the outermost it is in: an intersection whose
 * parts all are. */
void shape_parts_changed(shape *family, int combination);

/* Finds the nearest hit of world ray r with t in (tmin, tmax). A ray that
 * starts inside a closed shape finds the surface on its way out. */
bool shape_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit);

/* Whether shape_intersect4 takes s: a shape that does not move whose kind
 * tests four lanes at once (spheres, polygons, discs, planes, cylinders and
 * cones: the shapes most rays meet in the example and SPD scenes), under a
 * transform or not, or a combination of still parts whose kinds give their
 * spans four lanes at once (csg.c). */
static inline bool shape_has_intersect4(const shape *s)
{
    return s->quad;
}

/* shape_intersect with tmin 0 for the four rays of *r from lane `first` on,
 * lane k with its own tmax[k], for a shape shape_has_intersect4 takes: the
 * mask of the lanes that hit and, in those lanes, hit's t, part and leaf.
 * Each lane gets the bits shape_intersect gives, as its arithmetic is the
 * same, in the same order. The accelerator's shape callbacks test a
 * packet's lanes with it. */
quad_mask shape_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit);

/* Describes the surface at hit on world ray r, all but u and v. */
void shape_surface(const shape *s, const ray *r, const shape_hit *hit, surface *out);

/* shape_surface for a moving shape (pose_count > 0) as it is at `time`:
 * apart, so that the common path keeps no room for a moved copy. */
void shape_surface_moved(const shape *s, double time, const ray *r, const shape_hit *hit, surface *out);

/* Whether world ray r goes into s at hit (its normal there faces the
 * ray), as shape_surface's normal would say, without the rest of it. */
bool shape_hit_enters(const shape *s, const ray *r, const shape_hit *hit);

/* Fills out->u and out->v, the shape's own texture coordinates, for a
 * surface filled by shape_surface. */
void shape_surface_uv(const shape *s, surface *out);

/* World-space axis-aligned bounds, over all its poses for a moving shape;
 * for an unbounded shape (a plane) a box SHAPE_PLANE_EXTENT from the origin
 * each way. */
void shape_bounds(const shape *s, vec3 *lo, vec3 *hi);

/* The most boxes shape_pieces bounds a shape with. */
#define SHAPE_MAX_PIECES 8

/* How many boxes the accelerator bounds s with, 1 to SHAPE_MAX_PIECES: a
 * long shape at a slant (an SPD ring's cylinders) fills little of its one
 * world box, which many rays then enter only to miss it. Its object box
 * is cut across its longest axis into equal slices, as many as make the
 * slices' world boxes' total area (what a ray crossing them meets) least,
 * a slice more only for a tenth less. 1 for a shape without a transform,
 * a moving shape and an unbounded one. */
int shape_pieces(const shape *s);

/* The world box of slice `piece` of `pieces` (shape_pieces' count, or 1:
 * the whole of shape_bounds) of s. Each bounds part of the shape; a ray
 * meeting the box is tested against the whole shape. */
void shape_piece_bounds(const shape *s, int piece, int pieces, vec3 *lo, vec3 *hi);

/* False for shapes with no bounds (planes): the accelerator tests those
 * itself, as a hierarchy would offer them to every ray. */
bool shape_is_bounded(const shape *s);

/* The most times a ray can cross s (its kind's max_crossings; a
 * combination's parts', added up). */
int shape_max_crossings(const shape *s);

/* True when a ray leaving the surface of s at a point whose outward normal
 * is n, along d, can never meet s again: s is flat, or d points out of s
 * and s is convex (no line crosses it more than twice). */
bool shape_is_left_behind(const shape *s, vec3 n, vec3 d);

/* shape_is_left_behind's rule for s, for callers that apply it to many
 * directions at once: *always (s is flat), or else *when_leaving (s is
 * convex: left behind when n . d > 0). */
void shape_left_behind_rule(const shape *s, bool *always, bool *when_leaving);

/* The shape a ray leaving the surface of shape k of `family` (the scene's
 * shapes) may skip, under the rule *always or *when_leaving as
 * shape_left_behind_rule gives them, or -1. A shape standing alone: k
 * itself, by its own rule. A part of a combination (hits name such
 * leaves): the outermost combination, when k is convex and every
 * combination above it is an intersection, or a difference whose first
 * part holds k. That combination then lies within k, and its surface at
 * the hit is k's own (not a cut, turned round), so a ray leaving k outward
 * never meets it again: skipped when leaving only. -1 for other parts. */
int shape_left_behind_by(const shape *family, int k, bool *always, bool *when_leaving);

/* A point of s's surface in world space for (u1, u2) in [0, 1)^2, *n its
 * unit outward (front) normal; returns the density of such points per
 * unit of world area (the same everywhere for a shape without a transform
 * or with a rigid or uniformly scaling one), or 0 for a surface of no
 * finite area (a plane), which fills neither. */
double shape_sample(const shape *s, double u1, double u2, vec3 *p, vec3 *n);

/* The centre of s in object space (its kind's `center`; for a sphere set,
 * that of its sphere `part`): where spherical and cylindrical mappings are
 * centred unless they give their own. */
static inline vec3 shape_center(const shape *s, int part)
{
    if (!s->set)
        return s->center;
    const double *ball = s->set->balls[part & ~SHAPE_PART_FLIPPED];
    return v3(ball[0], ball[1], ball[2]);
}


#endif
