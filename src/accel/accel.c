/* accel.c - the Embree scenes. Analytic shapes are one user geometry, one
 * primitive per shape; Embree's rays are single precision, so each query
 * keeps the double-precision ray in an extended intersection context and
 * the callbacks test shapes exactly with it. Each mesh is a triangle scene
 * over its own arrays, placed by Embree instances. */
#include <embree3/rtcore.h>
#include <math.h>
#include <stdlib.h>
#include "accel/accel.h"
#include "core/error.h"

/* Geometry IDs in the top scene: the shapes, then instance i at 1 + i. */
#define SHAPES_ID 0u

struct accel {
    RTCDevice device;
    RTCScene scene;
    RTCScene *mesh_scenes;
    int mesh_count;
    const shape *shapes;
    int shape_count;
};

/* Below this a shadow segment is taken as fully blocked. */
#define TRANSMISSION_CUTOFF 1e-4f

/* A query's state; Embree passes &ctx back to the callbacks, and ctx comes
 * first so the callbacks can recover the whole query from it. */
typedef struct query {
    struct RTCIntersectContext ctx;
    const accel *acc;
    const ray *r;
    double tmin, tmax;
    int index;
    shape_hit hit;
    accel_filter_fn filter;
    void *user;
    color through;
} query;

/* Pads float bounds so the float ray in Embree's traversal never misses a
 * box that the exact double test would hit. */
static float pad_down(double v, double pad) { return nextafterf((float)(v - pad), -INFINITY); }
static float pad_up(double v, double pad) { return nextafterf((float)(v + pad), INFINITY); }

static void bounds_fn(const struct RTCBoundsFunctionArguments *args)
{
    const accel *a = args->geometryUserPtr;
    vec3 lo, hi;
    shape_bounds(&a->shapes[args->primID], &lo, &hi);
    double pad = 1e-6 * (v3_length(v3_sub(hi, lo)) + fmax(v3_length(lo), v3_length(hi)));
    struct RTCBounds *b = args->bounds_o;
    b->lower_x = pad_down(lo.x, pad);
    b->lower_y = pad_down(lo.y, pad);
    b->lower_z = pad_down(lo.z, pad);
    b->upper_x = pad_up(hi.x, pad);
    b->upper_y = pad_up(hi.y, pad);
    b->upper_z = pad_up(hi.z, pad);
}

static void intersect_fn(const struct RTCIntersectFunctionNArguments *args)
{
    if (!args->valid[0])
        return;
    query *q = (query *)args->context;
    struct RTCRayHit *rh = (struct RTCRayHit *)args->rayhit;
    shape_hit h;
    /* A triangle found first may have shortened the ray below q->tmax. */
    double tmax = fmin(q->tmax, (double)rh->ray.tfar);
    if (!shape_intersect(&q->acc->shapes[args->primID], q->r, q->tmin, tmax, &h))
        return;
    q->tmax = h.t;
    q->hit = h;
    q->index = (int)args->primID;
    rh->ray.tfar = nextafterf((float)h.t, INFINITY);
    rh->hit.geomID = args->geomID;
    rh->hit.primID = args->primID;
    rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

/* Multiplies in what one crossing passes; false once nothing passes. */
static bool pass_through(query *q, const accel_hit *h)
{
    q->through = rgb_mul(q->through, q->filter(q->user, q->r, h));
    return rgb_max(q->through) >= TRANSMISSION_CUTOFF;
}

static void occluded_fn(const struct RTCOccludedFunctionNArguments *args)
{
    if (!args->valid[0])
        return;
    query *q = (query *)args->context;
    const shape *s = &q->acc->shapes[args->primID];
    double tmin = q->tmin;
    accel_hit h = {.shape = (int)args->primID, .instance = -1};
    /* Shapes are convex, so a ray crosses one at most twice. */
    for (int crossing = 0; crossing < 2 && shape_intersect(s, q->r, tmin, q->tmax, &h.on_shape); crossing++) {
        h.t = h.on_shape.t;
        if (!pass_through(q, &h)) {
            ((struct RTCRay *)args->ray)->tfar = -INFINITY;
            return;
        }
        tmin = h.t;
    }
}

/* Lane i of Embree's structure-of-arrays rays and hits, as its C++ helpers
 * (RTCRayN_tfar, RTCHitN_u, ...) index them. */
static float ray_lane_tfar(const struct RTCRayN *rays, unsigned n, unsigned i) { return ((const float *)rays)[8 * n + i]; }
static float hit_lane_float(const struct RTCHitN *hit, unsigned n, unsigned field, unsigned i)
{
    return ((const float *)hit)[field * n + i];
}
static unsigned hit_lane_uint(const struct RTCHitN *hit, unsigned n, unsigned field, unsigned i)
{
    return ((const unsigned *)hit)[field * n + i];
}

/* Embree found a triangle on a shadow segment: reject the hit (so the
 * search goes on) while light still passes. */
static void triangle_occlusion_filter(const struct RTCFilterFunctionNArguments *args)
{
    if (!args->valid[0])
        return;
    query *q = (query *)args->context;
    accel_hit h = {
        .t = ray_lane_tfar(args->ray, args->N, 0),
        .shape = -1,
        .instance = (int)hit_lane_uint(args->hit, args->N, 7, 0) - 1, /* instID[0] */
        .triangle = hit_lane_uint(args->hit, args->N, 5, 0),          /* primID */
        .b1 = hit_lane_float(args->hit, args->N, 3, 0),               /* u */
        .b2 = hit_lane_float(args->hit, args->N, 4, 0),               /* v */
    };
    if (pass_through(q, &h))
        args->valid[0] = 0;
}

static void error_fn(void *user, enum RTCError code, const char *str)
{
    glint_error *err = user;
    if (err && err->message[0] == '\0')
        error_set(err, GLINT_ERR_EMBREE, "embree error %d: %s", (int)code, str ? str : "");
}

static void add_shapes(accel *a)
{
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, (unsigned)a->shape_count);
    rtcSetGeometryUserData(g, a);
    rtcSetGeometryBoundsFunction(g, bounds_fn, a);
    rtcSetGeometryIntersectFunction(g, intersect_fn);
    rtcSetGeometryOccludedFunction(g, occluded_fn);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(a->scene, g, SHAPES_ID);
    rtcReleaseGeometry(g);
}

/* A triangle scene over the mesh's own arrays: shared, not copied. */
static RTCScene mesh_scene(accel *a, const mesh *m)
{
    RTCScene s = rtcNewScene(a->device);
    RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, m->positions, 0,
                               3 * sizeof(float), (size_t)m->vertex_count);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m->indices, 0,
                               3 * sizeof(uint32_t), (size_t)m->triangle_count);
    rtcSetGeometryOccludedFilterFunction(g, triangle_occlusion_filter);
    rtcCommitGeometry(g);
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

glint_status accel_build(accel **out, const accel_geometry *geo, glint_error *err)
{
    *out = NULL;
    accel *a = calloc(1, sizeof *a);
    if (!a || !(a->mesh_scenes = calloc((size_t)geo->mesh_count + 1, sizeof(RTCScene)))) {
        free(a);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
    }
    a->shapes = geo->shapes;
    a->shape_count = geo->shape_count;
    a->device = rtcNewDevice(NULL);
    if (!a->device) {
        free(a->mesh_scenes);
        free(a);
        return error_set(err, GLINT_ERR_EMBREE, "cannot create the Embree device: error %d",
                         (int)rtcGetDeviceError(NULL));
    }
    glint_error embree_err = {{0}};
    rtcSetDeviceErrorFunction(a->device, error_fn, &embree_err);
    a->scene = rtcNewScene(a->device);
    if (a->scene) {
        if (a->shape_count > 0)
            add_shapes(a);
        for (; a->mesh_count < geo->mesh_count; a->mesh_count++)
            a->mesh_scenes[a->mesh_count] = mesh_scene(a, &geo->meshes[a->mesh_count]);
        for (int i = 0; i < geo->instance_count; i++)
            add_instance(a, &geo->instances[i], 1u + (unsigned)i);
        rtcCommitScene(a->scene);
    }
    rtcSetDeviceErrorFunction(a->device, NULL, NULL);
    if (!a->scene || embree_err.message[0]) {
        accel_free(a);
        if (!embree_err.message[0])
            error_set(&embree_err, GLINT_ERR_EMBREE, "cannot create the Embree scene");
        return error_set(err, GLINT_ERR_EMBREE, "%s", embree_err.message);
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
    if (a->device)
        rtcReleaseDevice(a->device);
    free(a);
}

/* Fills Embree's single-precision ray so that it covers [tmin, tmax]. */
static void embree_ray(struct RTCRay *er, const ray *r, double tmin, double tmax)
{
    er->org_x = (float)r->o.x;
    er->org_y = (float)r->o.y;
    er->org_z = (float)r->o.z;
    er->dir_x = (float)r->d.x;
    er->dir_y = (float)r->d.y;
    er->dir_z = (float)r->d.z;
    er->tnear = tmin > 0 ? nextafterf((float)tmin, 0) : 0;
    er->tfar = isfinite(tmax) ? nextafterf((float)tmax, INFINITY) : INFINITY;
    er->time = 0;
    er->mask = 0xFFFFFFFFu;
    er->id = 0;
    er->flags = 0;
}

bool accel_intersect(const accel *a, const ray *r, double tmin, double tmax, accel_hit *hit)
{
    query q = {.acc = a, .r = r, .tmin = tmin, .tmax = tmax, .index = -1};
    rtcInitIntersectContext(&q.ctx);
    struct RTCRayHit rh;
    embree_ray(&rh.ray, r, tmin, tmax);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(a->scene, &q.ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return false;
    if (rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID) {
        *hit = (accel_hit){.t = q.hit.t, .shape = q.index, .on_shape = q.hit, .instance = -1};
        return true;
    }
    *hit = (accel_hit){.t = rh.ray.tfar, .shape = -1, .instance = (int)rh.hit.instID[0] - 1,
                       .triangle = rh.hit.primID, .b1 = rh.hit.u, .b2 = rh.hit.v};
    return true;
}

color accel_transmission(const accel *a, const ray *r, double tmin, double tmax, accel_filter_fn filter,
                         void *user)
{
    query q = {.acc = a, .r = r, .tmin = tmin, .tmax = tmax, .filter = filter, .user = user, .through = {1, 1, 1}};
    rtcInitIntersectContext(&q.ctx);
    struct RTCRay er;
    embree_ray(&er, r, tmin, tmax);
    rtcOccluded1(a->scene, &q.ctx, &er);
    return er.tfar == -INFINITY ? rgb(0, 0, 0) : q.through;
}
