/* accel_shapes.c - the analytic shapes inside Embree: one user geometry,
 * one primitive per piece of a bounded shape's bounds (shape_pieces),
 * whose callbacks Embree calls during a
 * query. They test each lane's double-precision ray (kept in the query)
 * exactly, four lanes at a time where the shape allows, and record the hit
 * in the query; for a shadow query they block the lane, or filter its light
 * through each crossing of a shape that lets some pass. */
#include <math.h>
#include "accel/accel_internal.h"

/* The bounds of primitive primID's piece of its shape, padded
 * (accel_pad_bounds). */
void accel_shape_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const accel *a = args->geometryUserPtr;
    vec3 lo, hi;
    shape_piece_bounds(&a->shapes[a->prim_shape[args->primID]], a->prim_piece[args->primID],
                       a->prim_pieces[args->primID], &lo, &hi);
    accel_pad_bounds(lo, hi, args->bounds_o);
}

/* accel_shape_intersect's work for n = args->N lanes (or one lane traced
 * alone), one at a time: inlined twice,
 * once with n a constant for the packets glint sends, whose lanes are then
 * cheaper to address. */
static inline void intersect_lanes(const struct RTCIntersectFunctionNArguments *args, unsigned n, int index,
                                   const shape *s)
{
    query *q = (query *)args->context;
    for (unsigned i = 0; i < n; i++) {
        unsigned lane = query_lane(q, n, i);
        if (!args->valid[i] || q->skip[lane] == index || q->tested[lane] == index)
            continue;
        q->tested[lane] = index;
        float tfar = *ray_lane_tfar((struct RTCRayN *)args->rayhit, n, i);
        shape_hit h;
        /* A triangle found first may have shortened the ray below q->tmax. */
        double tmax = q->tmax[lane] < tfar ? q->tmax[lane] : (double)tfar;
        ray r = ray8_get(q->r, (int)lane);
        shape moved;
        if (shape_intersect(shape_at(s, lane_time(q, lane), &moved), &r, 0, tmax, &h))
            record_hit(args, n, i, s->csg ? h.leaf : index, h.t, h.part);
    }
}

/* Shape `index` (s, which shape_intersect4 takes) for the four lanes of a
 * packet of glint's from lane `first` on: the mask of the valid lanes that
 * hit it in (0, tmax) and do not skip it, and *t. Every lane is tested,
 * the invalid ones too, which costs less than picking them out; but not
 * when no valid lane wants it: the shadow rays leaving a shape (a die,
 * skipped as a whole) met its bounds first, and tested it to no end. */
static inline quad_mask shape_quad(const query *q, const int *valid, int index, const shape *s, int first,
                                   quad_f64 tmax, quad_hit *hit)
{
    quad_mask wanted = quad_int_ne(valid + first, 0) & quad_int_ne(q->skip + first, index);
    return quad_any(wanted) ? shape_intersect4(s, q->r, first, tmax, hit) & wanted : wanted;
}

/* intersect_lanes for a packet of glint's and a shape that
 * shape_intersect4 takes: four lanes at a time. */
static void intersect_quads(const struct RTCIntersectFunctionNArguments *args, int index, const shape *s)
{
    query *q = (query *)args->context;
    const float *tfar = ray_lane_tfar((struct RTCRayN *)args->rayhit, ACCEL_PACKET, 0);
    for (int k = 0; k < ACCEL_PACKET; k += QUAD) {
        quad_f64 mine = quad_load(q->tmax + k), far = quad_from_floats(tfar + k);
        quad_hit h;
        quad_mask hit = shape_quad(q, args->valid, index, s, k, quad_select(mine < far, mine, far), &h);
        for (int j = 0; j < QUAD; j++)
            if (hit[j])
                record_hit(args, ACCEL_PACKET, (unsigned)(k + j), s->csg ? h.leaf[j] : index, h.t[j], h.part[j]);
    }
}

/* Glint's packets meet a shape that allows it four lanes at a time. */
void accel_shape_intersect(const struct RTCIntersectFunctionNArguments *args)
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

/* An opaque shape blocks the lanes it crosses, four at a time where it
 * can; any other filters each lane's light through each of its crossings
 * in the segment, once a lane (the seen set). */
void accel_shape_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    query *q = (query *)args->context;
    int index = q->acc->prim_shape[args->primID];
    const shape *s = &q->acc->shapes[index];
    bool opaque = shape_opaque(q->acc, index);
    if (opaque && args->N == ACCEL_PACKET && shape_has_intersect4(s)) {
        /* As below, four lanes at a time. */
        for (int k = 0; k < ACCEL_PACKET; k += QUAD) {
            quad_hit h;
            quad_mask hit = shape_quad(q, args->valid, index, s, k, quad_load(q->tmax + k), &h);
            for (int j = 0; j < QUAD; j++)
                if (hit[j])
                    *ray_lane_tfar(args->ray, ACCEL_PACKET, (unsigned)(k + j)) = -INFINITY;
        }
        return;
    }
    for (unsigned i = 0; i < args->N; i++) {
        unsigned lane = query_lane(q, args->N, i);
        if (!args->valid[i] || q->skip[lane] == index)
            continue;
        ray r = ray8_get(q->r, (int)lane);
        shape moved;
        const shape *at = shape_at(s, lane_time(q, lane), &moved);
        if (opaque) {
            /* Blocking twice is harmless, so no record of it is kept. */
            shape_hit h;
            if (q->tested[lane] == index)
                continue;
            q->tested[lane] = index;
            if (shape_intersect(at, &r, 0, q->tmax[lane], &h))
                *ray_lane_tfar(args->ray, args->N, i) = -INFINITY;
            continue;
        }
        if (!seen_add(&q->seen[lane], (uint64_t)index))
            continue;
        double tmin = 0;
        accel_hit h = {.shape = index, .instance = -1, .time = lane_time(q, lane)};
        int crossings = shape_max_crossings(s);
        for (int crossing = 0; crossing < crossings && shape_intersect(at, &r, tmin, q->tmax[lane], &h.on_shape);
             crossing++) {
            h.t = h.on_shape.t;
            if (s->csg)
                h.shape = h.on_shape.leaf;
            if (!pass_through(q, lane, &h)) {
                *ray_lane_tfar(args->ray, args->N, i) = -INFINITY;
                break;
            }
            tmin = h.t;
        }
    }
}
