/* accel.c - one Embree user geometry holding every analytic shape, one
 * primitive per shape. Embree's rays are single precision; each query keeps
 * the double-precision ray in an extended intersection context, and the
 * callbacks test shapes exactly with it. */
#include <embree3/rtcore.h>
#include <math.h>
#include <stdlib.h>
#include "accel/accel.h"
#include "core/error.h"

struct accel {
    RTCDevice device;
    RTCScene scene;
    const shape *shapes;
    int count;
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
    shape_hit h;
    if (!shape_intersect(&q->acc->shapes[args->primID], q->r, q->tmin, q->tmax, &h))
        return;
    q->tmax = h.t;
    q->hit = h;
    q->index = (int)args->primID;
    struct RTCRayHit *rh = (struct RTCRayHit *)args->rayhit;
    rh->ray.tfar = nextafterf((float)h.t, INFINITY);
    rh->hit.geomID = args->geomID;
    rh->hit.primID = args->primID;
}

static void occluded_fn(const struct RTCOccludedFunctionNArguments *args)
{
    if (!args->valid[0])
        return;
    query *q = (query *)args->context;
    const shape *s = &q->acc->shapes[args->primID];
    double tmin = q->tmin;
    shape_hit h;
    /* Shapes are convex, so a ray crosses one at most twice. */
    for (int crossing = 0; crossing < 2 && shape_intersect(s, q->r, tmin, q->tmax, &h); crossing++) {
        q->through = rgb_mul(q->through, q->filter(q->user, (int)args->primID, q->r, &h));
        if (rgb_max(q->through) < TRANSMISSION_CUTOFF) {
            ((struct RTCRay *)args->ray)->tfar = -INFINITY;
            return;
        }
        tmin = h.t;
    }
}

static void error_fn(void *user, enum RTCError code, const char *str)
{
    glint_error *err = user;
    if (err && err->message[0] == '\0')
        error_set(err, GLINT_ERR_EMBREE, "embree error %d: %s", (int)code, str ? str : "");
}

glint_status accel_build(accel **out, const shape *shapes, int count, glint_error *err)
{
    *out = NULL;
    accel *a = calloc(1, sizeof *a);
    if (!a)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory building the accelerator");
    a->shapes = shapes;
    a->count = count;
    glint_error embree_err = {{0}};
    a->device = rtcNewDevice(NULL);
    if (!a->device) {
        free(a);
        return error_set(err, GLINT_ERR_EMBREE, "cannot create the Embree device: error %d",
                         (int)rtcGetDeviceError(NULL));
    }
    rtcSetDeviceErrorFunction(a->device, error_fn, &embree_err);
    a->scene = rtcNewScene(a->device);
    if (a->scene && count > 0) {
        RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, (unsigned)count);
        rtcSetGeometryUserData(g, a);
        rtcSetGeometryBoundsFunction(g, bounds_fn, a);
        rtcSetGeometryIntersectFunction(g, intersect_fn);
        rtcSetGeometryOccludedFunction(g, occluded_fn);
        rtcCommitGeometry(g);
        rtcAttachGeometry(a->scene, g);
        rtcReleaseGeometry(g);
    }
    if (a->scene)
        rtcCommitScene(a->scene);
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

bool accel_intersect(const accel *a, const ray *r, double tmin, double tmax, int *index, shape_hit *hit)
{
    if (a->count == 0)
        return false;
    query q = {.acc = a, .r = r, .tmin = tmin, .tmax = tmax, .index = -1};
    rtcInitIntersectContext(&q.ctx);
    struct RTCRayHit rh;
    embree_ray(&rh.ray, r, tmin, tmax);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(a->scene, &q.ctx, &rh);
    if (q.index < 0)
        return false;
    *index = q.index;
    *hit = q.hit;
    return true;
}

color accel_transmission(const accel *a, const ray *r, double tmin, double tmax, accel_filter_fn filter,
                         void *user)
{
    if (a->count == 0)
        return rgb(1, 1, 1);
    query q = {.acc = a, .r = r, .tmin = tmin, .tmax = tmax, .filter = filter, .user = user, .through = {1, 1, 1}};
    rtcInitIntersectContext(&q.ctx);
    struct RTCRay er;
    embree_ray(&er, r, tmin, tmax);
    rtcOccluded1(a->scene, &q.ctx, &er);
    return er.tfar == -INFINITY ? rgb(0, 0, 0) : q.through;
}
