/* accel_internal.h - what the accelerator's files share: the accelerator's
 * record, a query's state (which Embree hands back to the callbacks), lane
 * access to Embree's packets, and how a shadow segment's light is filtered.
 *
 * The files: accel_build.c builds the Embree device and scenes (shapes,
 * meshes placed flat or as instances); accel_shapes.c holds the analytic
 * shapes' user-geometry callbacks; accel_query.c runs the packet queries,
 * with the planes tested outside Embree, and the triangles' shadow filter.
 *
 * Analytic shapes are one user geometry, one primitive per piece of a
 * shape's bounds (one box, or slices of a long shape at a slant, each of
 * which tests the whole shape), but for
 * sphere sets, each a user geometry of its own, one primitive per sphere,
 * at 1 + instance_count + j for set j (accel_spheres.c); Embree's
 * rays are single precision, so each query keeps the double-precision ray in
 * an extended intersection context and the callbacks test shapes exactly
 * with it. Planes, unbounded, would be a candidate for every ray; the
 * queries test them first, in double, and let Embree look only nearer. A
 * mesh placed once is a triangle geometry of the top scene, in world space;
 * a mesh placed more often is a triangle scene over its own arrays, placed
 * by Embree instances. Either way geometry 1 + i is instance i. */
#ifndef GLINT_ACCEL_ACCEL_INTERNAL_H
#define GLINT_ACCEL_ACCEL_INTERNAL_H

#include <math.h>
#include <embree3/rtcore.h>
#include "accel/accel.h"
#include "accel/seen_set.h"
#include "core/lanes.h"

/* Geometry IDs in the top scene: the shapes, then instance i at 1 + i. */
#define SHAPES_ID 0u

struct accel {
    RTCDevice device;
    RTCScene scene;
    RTCScene *mesh_scenes;    /* per mesh placed more than once, else NULL */
    int mesh_count;
    float **flat_vertices;    /* per instance: its world-space vertex copy, or NULL */
    int instance_count;
    const shape *shapes;
    int shape_count;
    int *prim_shape;          /* user geometry primitive -> shape index (planes left out) */
    unsigned char *prim_piece;  /* and which piece of the shape's bounds it is */
    unsigned char *prim_pieces; /* of how many (shape_pieces) */
    int prim_count;
    int *planes;              /* shape indices of the planes, tested outside Embree */
    int plane_count;
    bool instanced;           /* some mesh is placed through Embree instances */
    bool apart;               /* incoherent queries trace each lane alone (rays_apart) */
    const bool *shape_opaque; /* per shape, or NULL */
    bool all_opaque;          /* every shape and mesh placement blocks all light: no shadow
                                 segment is filtered, only blocked or not */
    const volatile int *cancel; /* the build stops once it is set, or NULL */
    enum RTCBuildQuality quality; /* of every BVH built (build_quality) */
};

/* True when shape `index` is known to block all light. */
static inline bool shape_opaque(const accel *a, int index)
{
    return a->shape_opaque && a->shape_opaque[index];
}

/* Below this a shadow segment is taken as fully blocked. */
#define TRANSMISSION_CUTOFF 1e-4f

/* A query's state, for a packet of ACCEL_PACKET rays; Embree passes
 * &ctx back to the callbacks, and ctx comes first so the callbacks can
 * recover the whole query from it. Lane i holds the double-precision ray
 * of Embree's lane i, or of its one ray when lane i is traced alone
 * (query_lane). */
typedef struct query {
    struct RTCIntersectContext ctx;
    const accel *acc;
    accel_filter_fn filter;
    void *user;
    const ray8 *r;            /* the packet's rays */
    const double *time;       /* and their times over the shutter, or NULL: nothing moves */
    double tmax[ACCEL_PACKET];   /* every query starts at t = 0 */
    int skip[ACCEL_PACKET];      /* a shape lane i cannot meet, or -1 */
    int tested[ACCEL_PACKET];    /* the shape lane i was last tested against, or -1: another
                                    piece of it (prim_piece) need not test it again */
    int index[ACCEL_PACKET];     /* the shape lane i hit, or -1 */
    double hit_t[ACCEL_PACKET];  /* and where: its shape_hit, by field */
    int hit_part[ACCEL_PACKET];
    color through[ACCEL_PACKET];
    color depth[ACCEL_PACKET];   /* optical depth each lane's crossings add up */
    seen_set *seen;           /* shadow queries: what each lane was filtered by */
    int alone;                /* the lane traced alone (accel->apart), or -1 */
    int reachable[ACCEL_PACKET]; /* -1 where Embree can take lane i's ray, else 0 */
} query;

/* The query's lane for lane i of a callback's n rays: i itself for glint's
 * packets; for a lane traced alone, Embree's one ray is that lane. */
static inline unsigned query_lane(const query *q, unsigned n, unsigned i)
{
    return n == 1 && q->alone >= 0 ? (unsigned)q->alone : i;
}

/* Lane i of Embree's structure-of-arrays rays and hits, as its C++ helpers
 * (RTCRayN_tfar, RTCHitN_u, RTCRayHitN_RayN, ...) index them: a ray is 12
 * fields of n lanes, tfar the ninth; a hit is 8 fields, after the ray in a
 * RTCRayHitN. */
enum { RAY_TFAR = 8, RAY_FIELDS = 12, HIT_NG_X = 0, HIT_U = 3, HIT_V = 4, HIT_PRIM = 5, HIT_GEOM = 6, HIT_INST = 7 };

/* Lane i's far end, which a callback shortens to a hit or sets to -INFINITY
 * when the lane is blocked. */
static inline float *ray_lane_tfar(struct RTCRayN *rays, unsigned n, unsigned i)
{
    return &((float *)rays)[RAY_TFAR * n + i];
}

/* Lane i's unsigned hit field (HIT_PRIM, HIT_GEOM, HIT_INST) of a ray and
 * hit packet, which an intersect callback writes. */
static inline unsigned *rayhit_lane_uint(struct RTCRayHitN *rh, unsigned n, unsigned field, unsigned i)
{
    return &((unsigned *)rh)[(RAY_FIELDS + field) * n + i];
}

/* Lane i's float (HIT_U, HIT_V) and unsigned fields of a hit packet, which
 * a filter callback reads. */
static inline float hit_lane_float(const struct RTCHitN *hit, unsigned n, unsigned field, unsigned i)
{
    return ((const float *)hit)[field * n + i];
}
static inline unsigned hit_lane_uint(const struct RTCHitN *hit, unsigned n, unsigned field, unsigned i)
{
    return ((const unsigned *)hit)[field * n + i];
}

/* Box lo..hi into *out, padded so the float ray in Embree's traversal
 * never misses a box that the exact double test would hit. */
static inline void accel_pad_bounds(vec3 lo, vec3 hi, struct RTCBounds *out)
{
    double pad = 1e-6 * (v3_length(v3_sub(hi, lo)) + fmax(v3_length(lo), v3_length(hi)));
    out->lower_x = nextafterf((float)(lo.x - pad), -INFINITY);
    out->lower_y = nextafterf((float)(lo.y - pad), -INFINITY);
    out->lower_z = nextafterf((float)(lo.z - pad), -INFINITY);
    out->upper_x = nextafterf((float)(hi.x + pad), INFINITY);
    out->upper_y = nextafterf((float)(hi.y + pad), INFINITY);
    out->upper_z = nextafterf((float)(hi.z + pad), INFINITY);
}

/* Records in lane i of a callback's n rays that it hit shape `index` at
 * (t, part): for a combination, the part's shape it hit. A sphere set's
 * hits, though from a geometry of their own, are marked as the shapes'
 * (SHAPES_ID). */
static inline void record_hit(const struct RTCIntersectFunctionNArguments *args, unsigned n, unsigned i, int index,
                              double t, int part)
{
    query *q = (query *)args->context;
    struct RTCRayHitN *rh = args->rayhit;
    unsigned lane = query_lane(q, n, i);
    q->tmax[lane] = t;
    q->hit_t[lane] = t;
    q->hit_part[lane] = part;
    q->index[lane] = index;
    *ray_lane_tfar((struct RTCRayN *)rh, n, i) = float_far(t);
    *rayhit_lane_uint(rh, n, HIT_GEOM, i) = SHAPES_ID;
    *rayhit_lane_uint(rh, n, HIT_PRIM, i) = args->primID;
    *rayhit_lane_uint(rh, n, HIT_INST, i) = RTC_INVALID_GEOMETRY_ID;
}

/* Multiplies into lane i what one crossing passes; false once nothing
 * passes. */
static inline bool pass_through(query *q, unsigned i, const accel_hit *h)
{
    ray r = ray8_get(q->r, (int)i);
    q->through[i] = rgb_mul(q->through[i], q->filter(q->user, &r, h, &q->depth[i]));
    return rgb_max(q->through[i]) >= TRANSMISSION_CUTOFF;
}

/* Lane i's time over the shutter: 0 when nothing moves. */
static inline double lane_time(const query *q, unsigned i)
{
    return q->time ? q->time[i] : 0;
}

/* The instance of a triangle hit: an Embree instance's ID, or for a mesh
 * placed flat its geometry's ID, is 1 + the instance index. */
static inline int instance_of(unsigned geom, unsigned inst)
{
    return (int)(inst != RTC_INVALID_GEOMETRY_ID ? inst : geom) - 1;
}

/* The shapes' user-geometry callbacks (accel_shapes.c), which accel_build
 * gives Embree: a shape's padded bounds; its nearest hit for each valid lane
 * of a query, recorded in the query; and for a shadow query, whether it
 * blocks each lane, or what it lets through. */
void accel_shape_bounds(const struct RTCBoundsFunctionArguments *args);
void accel_shape_intersect(const struct RTCIntersectFunctionNArguments *args);
void accel_shape_occluded(const struct RTCOccludedFunctionNArguments *args);

/* The same callbacks for a sphere set's user geometry (accel_spheres.c),
 * whose user data is the set's shape and whose primitives are its spheres. */
void accel_spheres_bounds(const struct RTCBoundsFunctionArguments *args);
void accel_spheres_intersect(const struct RTCIntersectFunctionNArguments *args);
void accel_spheres_occluded(const struct RTCOccludedFunctionNArguments *args);

/* The occlusion filter of a mesh some placement of which lets light through
 * (accel_query.c): Embree found a triangle on a shadow segment; the hit is
 * rejected (so the search goes on) while light still passes. */
void accel_triangle_occluded(const struct RTCFilterFunctionNArguments *args);

#endif
