/* accel.c - the Embree scenes. Analytic shapes are one user geometry, one
 * primitive per shape; Embree's rays are single precision, so each query
 * keeps the double-precision ray in an extended intersection context and
 * the callbacks test shapes exactly with it. Planes, unbounded, would be a
 * candidate for every ray; the queries test them first, in double, and let
 * Embree look only nearer. A mesh placed once is a
 * triangle geometry of the top scene, in world space; a mesh placed more
 * often is a triangle scene over its own arrays, placed by Embree instances.
 * Either way geometry 1 + i is instance i. */
#include <embree3/rtcore.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "accel/accel.h"
#include "core/error.h"
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
    int prim_count;
    int *planes;              /* shape indices of the planes, tested outside Embree */
    int plane_count;
    bool instanced;           /* some mesh is placed through Embree instances */
    const bool *shape_opaque; /* per shape, or NULL */
    const volatile int *cancel; /* the build stops once it is set, or NULL */
};

/* True when shape `index` is known to block all light. */
static bool shape_opaque(const accel *a, int index)
{
    return a->shape_opaque && a->shape_opaque[index];
}

/* Below this a shadow segment is taken as fully blocked. */
#define TRANSMISSION_CUTOFF 1e-4f

/* The surfaces a shadow segment has already been filtered by: Embree may
 * report the same primitive to a query more than once (packet traversal
 * does, for user geometry), and each must filter the light only once. Keys
 * are (geometry ID << 32 | primitive ID); the first few live inline. */
#define SEEN_INLINE 16
typedef struct seen_set {
    uint64_t inline_keys[SEEN_INLINE];
    uint64_t *keys;           /* inline_keys, or a heap array once those are full */
    int count, cap;
} seen_set;

/* Adds key; false when it was there already. When memory runs out the key
 * is not kept, and a repeat would filter twice. */
static bool seen_add(seen_set *s, uint64_t key)
{
    if (!s->keys) {
        s->keys = s->inline_keys;
        s->cap = SEEN_INLINE;
    }
    for (int k = 0; k < s->count; k++)
        if (s->keys[k] == key)
            return false;
    if (s->count == s->cap) {
        uint64_t *grown = malloc(2 * (size_t)s->cap * sizeof *grown);
        if (!grown)
            return true;
        memcpy(grown, s->keys, (size_t)s->count * sizeof *grown);
        if (s->keys != s->inline_keys)
            free(s->keys);
        s->keys = grown;
        s->cap *= 2;
    }
    s->keys[s->count++] = key;
    return true;
}

static void seen_init(seen_set *s)
{
    s->keys = NULL;
    s->count = s->cap = 0;
}

static void seen_free(seen_set *s)
{
    /* Most sets were never used: no call to free(NULL) for them. */
    if (s->keys && s->keys != s->inline_keys)
        free(s->keys);
}

/* A query's state, for a packet of ACCEL_PACKET rays; Embree passes
 * &ctx back to the callbacks, and ctx comes first so the callbacks can
 * recover the whole query from it. Lane i holds the double-precision ray
 * of Embree's lane i. */
typedef struct query {
    struct RTCIntersectContext ctx;
    const accel *acc;
    accel_filter_fn filter;
    void *user;
    const ray8 *r;            /* the packet's rays */
    double tmax[ACCEL_PACKET];   /* every query starts at t = 0 */
    int skip[ACCEL_PACKET];      /* a shape lane i cannot meet, or -1 */
    int index[ACCEL_PACKET];     /* the shape lane i hit, or -1 */
    double hit_t[ACCEL_PACKET];  /* and where: its shape_hit, by field */
    int hit_part[ACCEL_PACKET];
    color through[ACCEL_PACKET];
    seen_set *seen;           /* shadow queries: what each lane was filtered by */
} query;

/* Lane i of Embree's structure-of-arrays rays and hits, as its C++ helpers
 * (RTCRayN_tfar, RTCHitN_u, RTCRayHitN_RayN, ...) index them: a ray is 12
 * fields of n lanes, tfar the ninth; a hit is 8 fields, after the ray in a
 * RTCRayHitN. */
enum { RAY_TFAR = 8, RAY_FIELDS = 12, HIT_NG_X = 0, HIT_U = 3, HIT_V = 4, HIT_PRIM = 5, HIT_GEOM = 6, HIT_INST = 7 };
static float *ray_lane_tfar(struct RTCRayN *rays, unsigned n, unsigned i) { return &((float *)rays)[RAY_TFAR * n + i]; }
static unsigned *rayhit_lane_uint(struct RTCRayHitN *rh, unsigned n, unsigned field, unsigned i)
{
    return &((unsigned *)rh)[(RAY_FIELDS + field) * n + i];
}
static float hit_lane_float(const struct RTCHitN *hit, unsigned n, unsigned field, unsigned i)
{
    return ((const float *)hit)[field * n + i];
}
static unsigned hit_lane_uint(const struct RTCHitN *hit, unsigned n, unsigned field, unsigned i)
{
    return ((const unsigned *)hit)[field * n + i];
}

/* Pads float bounds so the float ray in Embree's traversal never misses a
 * box that the exact double test would hit. */
static float pad_down(double v, double pad) { return nextafterf((float)(v - pad), -INFINITY); }
static float pad_up(double v, double pad) { return nextafterf((float)(v + pad), INFINITY); }

static void bounds_fn(const struct RTCBoundsFunctionArguments *args)
{
    const accel *a = args->geometryUserPtr;
    vec3 lo, hi;
    shape_bounds(&a->shapes[a->prim_shape[args->primID]], &lo, &hi);
    double pad = 1e-6 * (v3_length(v3_sub(hi, lo)) + fmax(v3_length(lo), v3_length(hi)));
    struct RTCBounds *b = args->bounds_o;
    b->lower_x = pad_down(lo.x, pad);
    b->lower_y = pad_down(lo.y, pad);
    b->lower_z = pad_down(lo.z, pad);
    b->upper_x = pad_up(hi.x, pad);
    b->upper_y = pad_up(hi.y, pad);
    b->upper_z = pad_up(hi.z, pad);
}

/* Records in lane i of a packet of n that it hit shape `index` at (t, part). */
static inline void record_hit(const struct RTCIntersectFunctionNArguments *args, unsigned n, unsigned i, int index,
                              double t, int part)
{
    query *q = (query *)args->context;
    struct RTCRayHitN *rh = args->rayhit;
    q->tmax[i] = t;
    q->hit_t[i] = t;
    q->hit_part[i] = part;
    q->index[i] = index;
    *ray_lane_tfar((struct RTCRayN *)rh, n, i) = float_far(t);
    *rayhit_lane_uint(rh, n, HIT_GEOM, i) = args->geomID;
    *rayhit_lane_uint(rh, n, HIT_PRIM, i) = args->primID;
    *rayhit_lane_uint(rh, n, HIT_INST, i) = RTC_INVALID_GEOMETRY_ID;
}

/* intersect_fn's work for n = args->N lanes, one at a time: inlined twice,
 * once with n a constant for the packets glint sends, whose lanes are then
 * cheaper to address. */
static inline void intersect_lanes(const struct RTCIntersectFunctionNArguments *args, unsigned n, int index,
                                   const shape *s)
{
    query *q = (query *)args->context;
    for (unsigned i = 0; i < n; i++) {
        if (!args->valid[i] || q->skip[i] == index)
            continue;
        float tfar = *ray_lane_tfar((struct RTCRayN *)args->rayhit, n, i);
        shape_hit h;
        /* A triangle found first may have shortened the ray below q->tmax. */
        double tmax = q->tmax[i] < tfar ? q->tmax[i] : (double)tfar;
        ray r = ray8_get(q->r, (int)i);
        if (shape_intersect(s, &r, 0, tmax, &h))
            record_hit(args, n, i, index, h.t, h.part);
    }
}

/* Shape `index` (s, which shape_intersect4 takes) for the four lanes of a
 * packet of glint's from lane `first` on: the mask of the valid lanes that
 * hit it in (0, tmax) and do not skip it, and *t. Every lane is tested,
 * the invalid ones too, which costs less than picking them out. */
static inline quad_mask shape_quad(const query *q, const int *valid, int index, const shape *s, int first,
                                   quad_f64 tmax, quad_f64 *t)
{
    return shape_intersect4(s, q->r, first, tmax, t) & quad_int_ne(valid + first, 0) &
           quad_int_ne(q->skip + first, index);
}

/* intersect_lanes for a packet of glint's and a shape that
 * shape_intersect4 takes: four lanes at a time. */
static void intersect_quads(const struct RTCIntersectFunctionNArguments *args, int index, const shape *s)
{
    query *q = (query *)args->context;
    const float *tfar = ray_lane_tfar((struct RTCRayN *)args->rayhit, ACCEL_PACKET, 0);
    for (int k = 0; k < ACCEL_PACKET; k += QUAD) {
        quad_f64 mine = quad_load(q->tmax + k), far = quad_from_floats(tfar + k);
        quad_f64 t;
        quad_mask hit = shape_quad(q, args->valid, index, s, k, quad_select(mine < far, mine, far), &t);
        for (int j = 0; j < QUAD; j++)
            if (hit[j])
                record_hit(args, ACCEL_PACKET, (unsigned)(k + j), index, t[j], 0);
    }
}

static void intersect_fn(const struct RTCIntersectFunctionNArguments *args)
{
    const query *q = (const query *)args->context;
    int index = q->acc->prim_shape[args->primID];
    const shape *s = &q->acc->shapes[index];
    if (args->N != ACCEL_PACKET)
        intersect_lanes(args, args->N, index, s);
    else if (shape_has_intersect4(s))
        intersect_quads(args, index, s);
    else
        intersect_lanes(args, ACCEL_PACKET, index, s);
}

/* Multiplies into lane i what one crossing passes; false once nothing
 * passes. */
static bool pass_through(query *q, unsigned i, const accel_hit *h)
{
    ray r = ray8_get(q->r, (int)i);
    q->through[i] = rgb_mul(q->through[i], q->filter(q->user, &r, h));
    return rgb_max(q->through[i]) >= TRANSMISSION_CUTOFF;
}

static void occluded_fn(const struct RTCOccludedFunctionNArguments *args)
{
    query *q = (query *)args->context;
    int index = q->acc->prim_shape[args->primID];
    const shape *s = &q->acc->shapes[index];
    bool opaque = shape_opaque(q->acc, index);
    if (opaque && args->N == ACCEL_PACKET && shape_has_intersect4(s)) {
        /* As below, four lanes at a time. */
        for (int k = 0; k < ACCEL_PACKET; k += QUAD) {
            quad_f64 t;
            quad_mask hit = shape_quad(q, args->valid, index, s, k, quad_load(q->tmax + k), &t);
            for (int j = 0; j < QUAD; j++)
                if (hit[j])
                    *ray_lane_tfar(args->ray, ACCEL_PACKET, (unsigned)(k + j)) = -INFINITY;
        }
        return;
    }
    for (unsigned i = 0; i < args->N; i++) {
        if (!args->valid[i] || q->skip[i] == index)
            continue;
        ray r = ray8_get(q->r, (int)i);
        if (opaque) {
            /* Blocking twice is harmless, so no record of it is kept. */
            shape_hit h;
            if (shape_intersect(s, &r, 0, q->tmax[i], &h))
                *ray_lane_tfar(args->ray, args->N, i) = -INFINITY;
            continue;
        }
        if (!seen_add(&q->seen[i], (uint64_t)index))
            continue;
        double tmin = 0;
        accel_hit h = {.shape = index, .instance = -1};
        int crossings = shape_max_crossings(s);
        for (int crossing = 0; crossing < crossings && shape_intersect(s, &r, tmin, q->tmax[i], &h.on_shape);
             crossing++) {
            h.t = h.on_shape.t;
            if (!pass_through(q, i, &h)) {
                *ray_lane_tfar(args->ray, args->N, i) = -INFINITY;
                break;
            }
            tmin = h.t;
        }
    }
}

/* The instance of a triangle hit: an Embree instance's ID, or for a mesh
 * placed flat its geometry's ID, is 1 + the instance index. */
static int instance_of(unsigned geom, unsigned inst)
{
    return (int)(inst != RTC_INVALID_GEOMETRY_ID ? inst : geom) - 1;
}

/* Embree found a triangle on a shadow segment: reject the hit (so the
 * search goes on) while light still passes. */
static void triangle_occlusion_filter(const struct RTCFilterFunctionNArguments *args)
{
    query *q = (query *)args->context;
    for (unsigned i = 0; i < args->N; i++) {
        if (!args->valid[i])
            continue;
        accel_hit h = {
            .t = *ray_lane_tfar(args->ray, args->N, i),
            .shape = -1,
            .instance = instance_of(hit_lane_uint(args->hit, args->N, HIT_GEOM, i),
                                    hit_lane_uint(args->hit, args->N, HIT_INST, i)),
            .triangle = hit_lane_uint(args->hit, args->N, HIT_PRIM, i),
            .b1 = hit_lane_float(args->hit, args->N, HIT_U, i),
            .b2 = hit_lane_float(args->hit, args->N, HIT_V, i),
        };
        uint64_t key = (uint64_t)(h.instance + 1) << 32 | h.triangle;
        if (!seen_add(&q->seen[i], key) || pass_through(q, i, &h))
            args->valid[i] = 0;
    }
}

static void error_fn(void *user, enum RTCError code, const char *str)
{
    glint_error *err = user;
    if (!err || err->message[0] != '\0')
        return;
    if (code == RTC_ERROR_CANCELLED)
        error_set(err, GLINT_ERR_CANCELLED, "render cancelled");
    else if (code == RTC_ERROR_OUT_OF_MEMORY)
        error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
    else
        error_set(err, GLINT_ERR_EMBREE, "embree error %d: %s", (int)code, str ? str : "");
}

/* Embree's build progress: false (stop building) once the caller's cancel
 * flag is set, so an interrupted render does not wait for a large mesh's
 * BVH. */
static bool build_progress(void *user, double done)
{
    (void)done;
    const accel *a = user;
    return !(a->cancel && *a->cancel);
}

/* Sorts the shapes into planes, which the queries test themselves (an
 * unbounded plane would be a candidate for every ray, through a callback),
 * and the rest, one user-geometry primitive each. False when memory runs
 * out. */
static bool sort_shapes(accel *a)
{
    a->prim_shape = malloc(((size_t)a->shape_count + 1) * sizeof *a->prim_shape);
    a->planes = malloc(((size_t)a->shape_count + 1) * sizeof *a->planes);
    if (!a->prim_shape || !a->planes)
        return false;
    for (int i = 0; i < a->shape_count; i++) {
        if (!shape_is_bounded(&a->shapes[i]))
            a->planes[a->plane_count++] = i;
        else
            a->prim_shape[a->prim_count++] = i;
    }
    return true;
}

static void add_shapes(accel *a)
{
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, (unsigned)a->prim_count);
    rtcSetGeometryUserData(g, a);
    rtcSetGeometryBoundsFunction(g, bounds_fn, a);
    rtcSetGeometryIntersectFunction(g, intersect_fn);
    rtcSetGeometryOccludedFunction(g, occluded_fn);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(a->scene, g, SHAPES_ID);
    rtcReleaseGeometry(g);
}

/* A triangle geometry over the mesh's indices, with the given vertices and,
 * unless every placement of it is opaque, the shadow filter. */
static RTCGeometry triangles(accel *a, const mesh *m, const float *positions, bool opaque)
{
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, positions, 0, 3 * sizeof(float),
                               (size_t)m->vertex_count);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m->indices, 0, 3 * sizeof(uint32_t),
                               (size_t)m->triangle_count);
    if (!opaque)
        rtcSetGeometryOccludedFilterFunction(g, triangle_occlusion_filter);
    rtcCommitGeometry(g);
    return g;
}

/* A triangle scene over the mesh's own arrays: shared, not copied. */
static RTCScene mesh_scene(accel *a, const mesh *m, bool opaque)
{
    RTCScene s = rtcNewScene(a->device);
    rtcSetSceneProgressMonitorFunction(s, build_progress, a);
    RTCGeometry g = triangles(a, m, m->positions, opaque);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(s);
    return s;
}

static void add_instance(accel *a, const instance *inst, unsigned id)
{
    float m[12];
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 4; col++)
            m[row * 4 + col] = (float)inst->to_world.m[row][col];
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, a->mesh_scenes[inst->mesh]);
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(a->scene, g, id);
    rtcReleaseGeometry(g);
}

/* A mesh placed once goes straight into the top scene, in world space:
 * Embree traces a flat scene about twice as fast as one instance (measured
 * with bench_ceiling on the bunny, 8-wide packets). Its arrays are shared
 * when the placement is the identity; otherwise the vertices are moved into
 * a copy (12 bytes a vertex, padded as Embree reads). False when memory
 * runs out. */
static bool add_flat(accel *a, const mesh *m, const instance *inst, int index, bool opaque)
{
    const float *positions = m->positions;
    if (inst->has_transform) {
        float *v = malloc((3 * (size_t)m->vertex_count + 1) * sizeof *v);
        if (!v)
            return false;
        for (int k = 0; k < m->vertex_count; k++) {
            const float *p = m->positions + 3 * (size_t)k;
            vec3 w = xf_point(&inst->to_world, v3(p[0], p[1], p[2]));
            v[3 * k] = (float)w.x;
            v[3 * k + 1] = (float)w.y;
            v[3 * k + 2] = (float)w.z;
        }
        v[3 * (size_t)m->vertex_count] = 0;
        a->flat_vertices[index] = v;
        positions = v;
    }
    RTCGeometry g = triangles(a, m, positions, opaque);
    rtcAttachGeometryByID(a->scene, g, 1u + (unsigned)index);
    rtcReleaseGeometry(g);
    return true;
}

/* Adds the meshes: each placed once flat, the others as instances of one
 * triangle scene per mesh, which is opaque when every placement is. False
 * when memory runs out. */
static bool add_meshes(accel *a, const accel_geometry *geo)
{
    int *uses = calloc((size_t)geo->mesh_count + 1, sizeof *uses);
    bool *see_through = calloc((size_t)geo->mesh_count + 1, sizeof *see_through);
    bool ok = uses && see_through;
    for (int i = 0; ok && i < geo->instance_count; i++) {
        uses[geo->instances[i].mesh]++;
        see_through[geo->instances[i].mesh] |= !(geo->instance_opaque && geo->instance_opaque[i]);
    }
    for (; ok && a->mesh_count < geo->mesh_count; a->mesh_count++)
        if (uses[a->mesh_count] > 1)
            a->mesh_scenes[a->mesh_count] = mesh_scene(a, &geo->meshes[a->mesh_count], !see_through[a->mesh_count]);
    for (int i = 0; ok && i < geo->instance_count; i++) {
        const instance *inst = &geo->instances[i];
        if (uses[inst->mesh] == 1) {
            ok = add_flat(a, &geo->meshes[inst->mesh], inst, i, !see_through[inst->mesh]);
        } else {
            add_instance(a, inst, 1u + (unsigned)i);
            a->instanced = true;
        }
    }
    free(uses);
    free(see_through);
    return ok;
}

glint_status accel_build(accel **out, const accel_geometry *geo, glint_error *err)
{
    *out = NULL;
    accel *a = calloc(1, sizeof *a);
    if (!a || !(a->mesh_scenes = calloc((size_t)geo->mesh_count + 1, sizeof(RTCScene))) ||
        !(a->flat_vertices = calloc((size_t)geo->instance_count + 1, sizeof(float *)))) {
        if (a)
            free(a->mesh_scenes);
        free(a);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
    }
    a->instance_count = geo->instance_count;
    a->shapes = geo->shapes;
    a->shape_count = geo->shape_count;
    a->shape_opaque = geo->shape_opaque;
    a->cancel = geo->cancel;
    /* Embree's threads start with the device (start_threads), not lazily in
     * the build or, worse, as the scene is released: there, TBB failing to
     * start one (memory running short) throws from a destructor and ends
     * the process; here, the device reports it. Measured: no slower. */
    char config[48] = "start_threads=1";
    if (geo->threads > 0)
        snprintf(config, sizeof config, "threads=%d,start_threads=1", geo->threads);
    a->device = rtcNewDevice(config);
    if (!a->device) {
        free(a->mesh_scenes);
        free(a->flat_vertices);
        free(a);
        enum RTCError code = rtcGetDeviceError(NULL);
        if (code == RTC_ERROR_OUT_OF_MEMORY)
            return error_set(err, GLINT_ERR_NOMEM, "cannot create the Embree device: out of memory");
        /* Embree says no more when its threads cannot start, which in
         * practice is memory (their stacks) running short. */
        if (code == RTC_ERROR_UNKNOWN)
            return error_set(err, GLINT_ERR_NOMEM,
                             "cannot create the Embree device: its threads could not start (out of memory?)");
        return error_set(err, GLINT_ERR_EMBREE, "cannot create the Embree device: error %d", (int)code);
    }
    glint_error embree_err = {0};
    rtcSetDeviceErrorFunction(a->device, error_fn, &embree_err);
    a->scene = rtcNewScene(a->device);
    if (a->scene) {
        rtcSetSceneProgressMonitorFunction(a->scene, build_progress, a);
        if (!sort_shapes(a) || !add_meshes(a, geo)) {
            rtcSetDeviceErrorFunction(a->device, NULL, NULL);
            accel_free(a);
            return error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
        }
        if (a->prim_count > 0)
            add_shapes(a);
        rtcCommitScene(a->scene);
    }
    rtcSetDeviceErrorFunction(a->device, NULL, NULL);
    if (!a->scene || embree_err.message[0]) {
        accel_free(a);
        if (!embree_err.message[0])
            error_set(&embree_err, GLINT_ERR_EMBREE, "cannot create the Embree scene");
        return error_set(err, embree_err.status, "%s", embree_err.message);
    }
    *out = a;
    return GLINT_OK;
}

void accel_free(accel *a)
{
    if (!a)
        return;
    if (a->scene)
        rtcReleaseScene(a->scene);
    for (int i = 0; i < a->mesh_count; i++)
        if (a->mesh_scenes[i])
            rtcReleaseScene(a->mesh_scenes[i]);
    free(a->mesh_scenes);
    for (int i = 0; i < a->instance_count; i++)
        free(a->flat_vertices[i]);
    free(a->flat_vertices);
    free(a->prim_shape);
    free(a->planes);
    if (a->device)
        rtcReleaseDevice(a->device);
    free(a);
}

/* Lane i's hit once Embree is done with it: a triangle's, or else the
 * shape the callbacks or the plane test recorded. */
static accel_hit lane_hit(const query *q, const struct RTCRayHit8 *rh, unsigned i, bool triangle)
{
    if (!triangle)
        return (accel_hit){.t = q->hit_t[i], .shape = q->index[i], .on_shape = {q->hit_t[i], q->hit_part[i]},
                           .instance = -1};
    return (accel_hit){.t = rh->ray.tfar[i], .shape = -1,
                       .instance = instance_of(rh->hit.geomID[i], rh->hit.instID[0][i]),
                       .triangle = rh->hit.primID[i], .b1 = rh->hit.u[i], .b2 = rh->hit.v[i]};
}

/* Plane k (of a->planes: the unbounded shapes) for the four lanes from
 * lane `first` on: the mask of the lanes that cross it in (0, tmax[j]) as
 * shape_intersect finds it, never for the lane's skipped shape, and *t. A
 * moved plane is tested lane by lane in its own space. */
static inline quad_mask plane_quad(const query *q, int k, int first, quad_f64 tmax, quad_f64 *t)
{
    int index = q->acc->planes[k];
    const shape *s = &q->acc->shapes[index];
    quad_mask hit;
    if (!shape_has_intersect4(s)) {
        for (int j = 0; j < QUAD; j++) {
            ray r = ray8_get(q->r, first + j);
            shape_hit h = {0, 0};
            hit[j] = shape_intersect(s, &r, 0, tmax[j], &h) ? -1 : 0;
            (*t)[j] = h.t;
        }
    } else {
        hit = shape_intersect4(s, q->r, first, tmax, t);
    }
    return hit & quad_int_ne(q->skip + first, index);
}

/* The nearest plane each lane crosses in (0, tmax): records it as the
 * lane's hit and shortens the lane's tmax to just past it, so Embree looks
 * only for something nearer, or as near: a shape touching the plane (a box
 * standing on a floor) wins the tie, as it would inside Embree. A quad at
 * a time, each lane's planes in order. */
static void nearest_planes(query *q)
{
    const accel *a = q->acc;
    for (int i = 0; i < ACCEL_PACKET; i += QUAD) {
        quad_f64 nearest = quad_load(q->tmax + i), hit_t = quad_load(q->hit_t + i);
        quad_mask index = {-1, -1, -1, -1};
        for (int k = 0; k < a->plane_count; k++) {
            quad_f64 t;
            quad_mask hit = plane_quad(q, k, i, nearest, &t);
            nearest = quad_select(hit, t, nearest);
            hit_t = quad_select(hit, t, hit_t);
            index = (hit & (quad_mask){a->planes[k], a->planes[k], a->planes[k], a->planes[k]}) | (index & ~hit);
        }
        /* Every plane hit is part 0; other lanes' parts are not read. */
        quad_store(q->hit_t + i, hit_t);
        quad_i32 lane_index = __builtin_convertvector(index, quad_i32);
        memcpy(q->index + i, &lane_index, sizeof lane_index);
        memset(q->hit_part + i, 0, QUAD * sizeof q->hit_part[0]);
        /* nextafter(nearest, INFINITY) for positive finite nearest, inline */
        quad_mask bits;
        memcpy(&bits, &nearest, sizeof bits);
        bits -= index >= 0; /* a true lane of a comparison is -1 */
        memcpy(q->tmax + i, &bits, sizeof bits);
    }
}

/* Filters each lane's shadow segment through the planes it crosses, a plane
 * at most once, in the planes' order. A lane nothing passes is blocked:
 * taken out of valid, with Embree's far end set as if Embree had found it
 * blocked, so that it needs no search. */
static void through_planes(query *q, int valid[ACCEL_PACKET], struct RTCRay8 *p)
{
    const accel *a = q->acc;
    for (int k = 0; k < a->plane_count; k++) {
        for (int i = 0; i < ACCEL_PACKET; i += QUAD) {
            quad_f64 t;
            quad_mask hit = plane_quad(q, k, i, quad_load(q->tmax + i), &t);
            /* Most quads cross no plane: shadow rays leave a floor upwards. */
            if (!quad_any(hit))
                continue;
            for (int j = 0; j < QUAD; j++) {
                if (!hit[j] || !valid[i + j])
                    continue;
                accel_hit h = {.t = t[j], .shape = a->planes[k], .on_shape = {t[j], 0}, .instance = -1};
                if (shape_opaque(a, h.shape) || !pass_through(q, (unsigned)(i + j), &h)) {
                    valid[i + j] = 0;
                    p->tfar[i + j] = -INFINITY;
                }
            }
        }
    }
}

/* Embree's far ends from the query's. */
static void packet_far(const query *q, struct RTCRay8 *p)
{
    for (int i = 0; i < ACCEL_PACKET; i += QUAD)
        quad_float_far(quad_load(q->tmax + i), p->tfar + i);
}

/* Fills the query's lanes and Embree's packet from the active rays, each
 * covering (0, tmax[i]): Embree's float tfar is rounded up so the float
 * traversal never stops short of the exact double test. Inactive lanes are
 * left for Embree to skip. */
static void packet_init(query *q, const ray8 *r, const double tmax[ACCEL_PACKET],
                        const int skip[ACCEL_PACKET], bool coherent, const bool active[ACCEL_PACKET],
                        int valid[ACCEL_PACKET], struct RTCRay8 *p)
{
    rtcInitIntersectContext(&q->ctx);
    q->seen = NULL;
    /* Embree's coherent packet traversal pays only for neighbouring rays
     * through a flat scene of triangles (the bunny: 15% fewer instructions).
     * Where analytic shapes are candidates (each lane then calls the shape
     * callbacks apart: 10% faster on the seed room), where meshes are
     * instanced (7% on scenes/models/bunnies.yaml), and for rays that are
     * not neighbours (reflections and refractions: a third of that scene's
     * instructions), rays traversed apart are faster. */
    const accel *a = q->acc;
    q->ctx.flags = coherent && a->prim_count == 0 && !a->instanced ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                                    : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    q->r = r;
    /* A quad of lanes at a time; Embree's fields are floats and ints. */
    memcpy(q->skip, skip, sizeof q->skip);
    for (int i = 0; i < ACCEL_PACKET; i += QUAD) {
        quad_mask on = quad_from_bools(active + i);
        quad_i32 lane_valid = __builtin_convertvector(on, quad_i32);
        memcpy(valid + i, &lane_valid, sizeof lane_valid);
        quad_store(q->tmax + i, quad_select(on, quad_load(tmax + i), quad_splat(0)));
        quad_f32 f[6] = {quad_to_floats(quad_load(r->ox + i)), quad_to_floats(quad_load(r->oy + i)),
                         quad_to_floats(quad_load(r->oz + i)), quad_to_floats(quad_load(r->dx + i)),
                         quad_to_floats(quad_load(r->dy + i)), quad_to_floats(quad_load(r->dz + i))};
        memcpy(p->org_x + i, &f[0], sizeof f[0]);
        memcpy(p->org_y + i, &f[1], sizeof f[1]);
        memcpy(p->org_z + i, &f[2], sizeof f[2]);
        memcpy(p->dir_x + i, &f[3], sizeof f[3]);
        memcpy(p->dir_y + i, &f[4], sizeof f[4]);
        memcpy(p->dir_z + i, &f[5], sizeof f[5]);
    }
    for (int i = 0; i < ACCEL_PACKET; i++)
        q->index[i] = -1;
    packet_far(q, p);
    memset(p->tnear, 0, sizeof p->tnear);
    memset(p->time, 0, sizeof p->time);
    memset(p->mask, 0xFF, sizeof p->mask);
    memset(p->id, 0, sizeof p->id);
    memset(p->flags, 0, sizeof p->flags);
}

void accel_intersect8(const accel *a, const ray8 *r, double tmax, const int skip[ACCEL_PACKET], bool coherent,
                      const bool active[ACCEL_PACKET], accel_hit hit[ACCEL_PACKET], bool found[ACCEL_PACKET])
{
    double far[ACCEL_PACKET];
    for (int i = 0; i < ACCEL_PACKET; i++)
        far[i] = tmax;
    query q;
    _Alignas(32) int valid[ACCEL_PACKET];
    struct RTCRayHit8 rh;
    q.acc = a;
    packet_init(&q, r, far, skip, coherent, active, valid, &rh.ray);
    for (unsigned i = 0; i < ACCEL_PACKET; i++)
        rh.hit.geomID[i] = rh.hit.primID[i] = rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    if (a->plane_count > 0) {
        nearest_planes(&q);
        packet_far(&q, &rh.ray);
    }
    rtcIntersect8(valid, a->scene, &q.ctx, &rh);
    /* Which lanes found something, and which of those a triangle, a quad
     * at a time; then each found lane's hit. */
    for (int i = 0; i < ACCEL_PACKET; i += QUAD) {
        quad_i32 geom, inst, index;
        memcpy(&geom, rh.hit.geomID + i, sizeof geom);
        memcpy(&inst, rh.hit.instID[0] + i, sizeof inst);
        memcpy(&index, q.index + i, sizeof index);
        quad_i32 none = geom == (int32_t)RTC_INVALID_GEOMETRY_ID;
        quad_i32 triangle = ~none & ((geom != (int32_t)SHAPES_ID) | (inst != (int32_t)RTC_INVALID_GEOMETRY_ID));
        quad_i32 hits = __builtin_convertvector(quad_from_bools(active + i), quad_i32) & (~none | (index >= 0));
        for (int j = 0; j < QUAD; j++) {
            found[i + j] = hits[j] != 0;
            if (hits[j])
                hit[i + j] = lane_hit(&q, &rh, (unsigned)(i + j), triangle[j] != 0);
        }
    }
}

void accel_transmission8(const accel *a, const ray8 *r, const double tmax[ACCEL_PACKET],
                         const int skip[ACCEL_PACKET], bool coherent, const bool active[ACCEL_PACKET],
                         accel_filter_fn filter, void *user, color through[ACCEL_PACKET])
{
    query q;
    seen_set seen[ACCEL_PACKET];
    _Alignas(32) int valid[ACCEL_PACKET];
    struct RTCRay8 p;
    q.acc = a;
    packet_init(&q, r, tmax, skip, coherent, active, valid, &p);
    q.filter = filter;
    q.user = user;
    q.seen = seen;
    for (unsigned i = 0; i < ACCEL_PACKET; i++) {
        q.through[i] = rgb(1, 1, 1);
        seen_init(&seen[i]);
    }
    if (a->plane_count > 0)
        through_planes(&q, valid, &p);
    rtcOccluded8(valid, a->scene, &q.ctx, &p);
    for (int i = 0; i < ACCEL_PACKET; i++)
        seen_free(&seen[i]);
    /* What passed, or black: each channel's bits kept or cleared to +0 by
     * the lane's mask, without a branch. */
    for (int i = 0; i < ACCEL_PACKET; i += QUAD) {
        quad_mask passes = quad_from_bools(active + i) & (quad_from_floats(p.tfar + i) != quad_splat(-INFINITY));
        for (int j = 0; j < QUAD; j++) {
            uint64_t bits[3];
            _Static_assert(sizeof bits == sizeof(color), "a colour is three doubles");
            memcpy(bits, &q.through[i + j], sizeof bits);
            for (int k = 0; k < 3; k++)
                bits[k] &= (uint64_t)passes[j];
            memcpy(&through[i + j], bits, sizeof bits);
        }
    }
}
