/* accel_spheres.c - a sphere set inside Embree: a user geometry of its
 * own, one primitive per sphere, whose callbacks test the sphere exactly
 * with the double-precision rays of the query and the arithmetic sphere
 * shapes use (sphere_math.h), four lanes at a time for glint's packets.
 * A hit is recorded as the set's shape, the sphere its part; a shadow
 * query blocks the lane or filters its light as for shapes
 * (accel_shapes.c). A set never moves and is never skipped: a ray leaving
 * one sphere may meet the others. */
#include "accel/accel_internal.h"
#include "geometry/sphere_math.h"

/* Set apart from the shapes' keys (their index) and the triangles'
 * ((instance + 1) << 32 | triangle) in a lane's seen set. */
#define SPHERE_KEY (UINT64_C(1) << 63)

/* Sphere primID of the set whose shape is `s`: its centre and radius. */
static inline vec3 ball_center(const shape *s, unsigned prim, double *radius)
{
    const double *ball = s->set->balls[prim];
    *radius = ball[3];
    return v3(ball[0], ball[1], ball[2]);
}

void accel_spheres_bounds(const struct RTCBoundsFunctionArguments *args)
{
    double radius;
    vec3 c = ball_center(args->geometryUserPtr, args->primID, &radius);
    vec3 r = v3(radius, radius, radius);
    accel_pad_bounds(v3_sub(c, r), v3_add(c, r), args->bounds_o);
}

void accel_spheres_intersect(const struct RTCIntersectFunctionNArguments *args)
{
    query *q = (query *)args->context;
    const shape *s = args->geometryUserPtr;
    int index = (int)(s - q->acc->shapes), part = (int)args->primID;
    double radius;
    vec3 c = ball_center(s, args->primID, &radius);
    if (args->N == ACCEL_PACKET) {
        const float *tfar = ray_lane_tfar((struct RTCRayN *)args->rayhit, ACCEL_PACKET, 0);
        for (int k = 0; k < ACCEL_PACKET; k += QUAD) {
            quad_f64 mine = quad_load(q->tmax + k), far = quad_from_floats(tfar + k), t;
            quad_mask hit = sphere_hits4_at(c, radius, q->r, k, quad_select(mine < far, mine, far), &t) &
                            quad_int_ne(args->valid + k, 0);
            for (int j = 0; j < QUAD; j++)
                if (hit[j])
                    record_hit(args, ACCEL_PACKET, (unsigned)(k + j), index, t[j], part);
        }
        return;
    }
    for (unsigned i = 0; i < args->N; i++) {
        if (!args->valid[i])
            continue;
        unsigned lane = query_lane(q, args->N, i);
        float tfar = *ray_lane_tfar((struct RTCRayN *)args->rayhit, args->N, i);
        /* A triangle found first may have shortened the ray below q->tmax. */
        double tmax = q->tmax[lane] < tfar ? q->tmax[lane] : (double)tfar;
        ray r = ray8_get(q->r, (int)lane);
        shape_hit h;
        if (sphere_hit_at(c, radius, &r, 0, tmax, &h))
            record_hit(args, args->N, i, index, h.t, part);
    }
}

void accel_spheres_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    query *q = (query *)args->context;
    const shape *s = args->geometryUserPtr;
    int index = (int)(s - q->acc->shapes);
    double radius;
    vec3 c = ball_center(s, args->primID, &radius);
    bool opaque = shape_opaque(q->acc, index);
    if (opaque && args->N == ACCEL_PACKET) {
        for (int k = 0; k < ACCEL_PACKET; k += QUAD) {
            quad_f64 t;
            quad_mask hit = sphere_hits4_at(c, radius, q->r, k, quad_load(q->tmax + k), &t) &
                            quad_int_ne(args->valid + k, 0);
            for (int j = 0; j < QUAD; j++)
                if (hit[j])
                    *ray_lane_tfar(args->ray, ACCEL_PACKET, (unsigned)(k + j)) = -INFINITY;
        }
        return;
    }
    for (unsigned i = 0; i < args->N; i++) {
        if (!args->valid[i])
            continue;
        unsigned lane = query_lane(q, args->N, i);
        ray r = ray8_get(q->r, (int)lane);
        accel_hit h = {.shape = index, .instance = -1, .time = lane_time(q, lane)};
        if (opaque) {
            if (sphere_hit_at(c, radius, &r, 0, q->tmax[lane], &h.on_shape))
                *ray_lane_tfar(args->ray, args->N, i) = -INFINITY;
            continue;
        }
        if (!seen_add(&q->seen[lane], SPHERE_KEY | (uint64_t)index << 32 | args->primID))
            continue;
        /* Each of the sphere's two crossings in the segment filters the light. */
        double tmin = 0;
        for (int crossing = 0; crossing < 2 && sphere_hit_at(c, radius, &r, tmin, q->tmax[lane], &h.on_shape);
             crossing++) {
            h.t = tmin = h.on_shape.t;
            h.on_shape.part = (int)args->primID;
            if (!pass_through(q, lane, &h)) {
                *ray_lane_tfar(args->ray, args->N, i) = -INFINITY;
                break;
            }
        }
    }
}
