/* accel_query.c - the packet queries: the nearest hit of each of a packet's
 * rays (accel_intersect8), and the light each of a packet's shadow segments
 * lets through (accel_transmission8). Each fills Embree's float packet from
 * glint's double rays, tests the planes itself first, in double, four lanes
 * at a time, and lets Embree look only nearer; shadow segments are filtered
 * through the planes, the shapes (accel_shapes.c) and the triangles they
 * cross, each surface once. Rays that are not neighbours go through
 * Embree one at a time in scenes of many analytic shapes (rays_apart). */
#include <math.h>
#include <string.h>
#include "accel/accel_internal.h"

/* Each valid lane's triangle is filtered once (the seen set), and stays a
 * blocker only once nothing passes it. */
void accel_triangle_occluded(const struct RTCFilterFunctionNArguments *args)
{
    query *q = (query *)args->context;
    for (unsigned i = 0; i < args->N; i++) {
        if (!args->valid[i])
            continue;
        unsigned lane = query_lane(q, args->N, i);
        accel_hit h = {
            .t = *ray_lane_tfar(args->ray, args->N, i),
            .shape = -1,
            .instance = instance_of(hit_lane_uint(args->hit, args->N, HIT_GEOM, i),
                                    hit_lane_uint(args->hit, args->N, HIT_INST, i)),
            .triangle = hit_lane_uint(args->hit, args->N, HIT_PRIM, i),
            .b1 = hit_lane_float(args->hit, args->N, HIT_U, i),
            .b2 = hit_lane_float(args->hit, args->N, HIT_V, i),
            .time = lane_time(q, lane),
        };
        uint64_t key = (uint64_t)(h.instance + 1) << 32 | h.triangle;
        if (!seen_add(&q->seen[lane], key) || pass_through(q, lane, &h))
            args->valid[i] = 0;
    }
}

/* Lane i's hit once Embree is done with it, into *out: a triangle's, or
 * else the shape the callbacks or the plane test recorded. Field by field:
 * a whole struct built and then copied is stored in pieces and loaded back
 * in one, which waits for the stores (1-2% of a depth of field's time). */
static void lane_hit(const query *q, const struct RTCRayHit8 *rh, unsigned i, bool triangle, accel_hit *out)
{
    out->time = lane_time(q, i);
    if (!triangle) {
        out->t = out->on_shape.t = q->hit_t[i];
        out->shape = q->index[i];
        out->on_shape.part = q->hit_part[i];
        out->instance = -1;
        out->triangle = 0;
        out->b1 = out->b2 = 0;
        return;
    }
    out->t = rh->ray.tfar[i];
    out->shape = -1;
    out->on_shape.t = 0;
    out->on_shape.part = 0;
    out->instance = instance_of(rh->hit.geomID[i], rh->hit.instID[0][i]);
    out->triangle = rh->hit.primID[i];
    out->b1 = rh->hit.u[i];
    out->b2 = rh->hit.v[i];
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
            shape_hit h = {0};
            shape moved;
            const shape *at = shape_at(s, lane_time(q, (unsigned)(first + j)), &moved);
            hit[j] = shape_intersect(at, &r, 0, tmax[j], &h) ? -1 : 0;
            (*t)[j] = h.t;
        }
    } else {
        quad_hit h;
        hit = shape_intersect4(s, q->r, first, tmax, &h);
        *t = h.t;
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
                accel_hit h = {.t = t[j], .shape = a->planes[k], .on_shape = {.t = t[j]}, .instance = -1,
                               .time = lane_time(q, (unsigned)(i + j))};
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

/* The square of the largest coordinate of a ray's origin and direction
 * Embree takes (its FLT_LARGE, 1.844e18). */
#define EMBREE_LARGEST_SQUARED 3.4e36f

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
    q->alone = -1;
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
    memset(q->tested, 0xff, sizeof q->tested);
    for (int i = 0; i < ACCEL_PACKET; i += QUAD) {
        quad_mask on = quad_from_bools(active + i);
        quad_i32 lane_valid = __builtin_convertvector(on, quad_i32);
        memcpy(valid + i, &lane_valid, sizeof lane_valid);
        quad_store(q->tmax + i, quad_select(on, quad_load(tmax + i), quad_splat(0)));
        quad_f32 f[6] = {quad_to_floats(quad_load(r->ox + i)), quad_to_floats(quad_load(r->oy + i)),
                         quad_to_floats(quad_load(r->oz + i)), quad_to_floats(quad_load(r->dx + i)),
                         quad_to_floats(quad_load(r->dy + i)), quad_to_floats(quad_load(r->dz + i))};
        /* Embree takes no ray with a coordinate of its origin or direction
         * past its FLT_LARGE, 1.844e18 (Debian's build asserts it, ending
         * the process): a camera placed, or a hit found, that far from the
         * origin. Such a ray meets no triangle and no bounded shape; the
         * planes, tested in double precision, it still meets. The squares
         * of the origin's coordinates and of the direction's sum (infinite
         * or NaN where a coordinate is) add up to under the bound's square
         * only when each coordinate is under the bound, and always when
         * each of the origin's is under half of it (a unit direction's sum
         * squared is at most 3). */
        quad_f32 d = f[3] + f[4] + f[5];
        quad_f32 size = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] + d * d;
        quad_i32 reachable = size <= (quad_f32){EMBREE_LARGEST_SQUARED, EMBREE_LARGEST_SQUARED,
                                                EMBREE_LARGEST_SQUARED, EMBREE_LARGEST_SQUARED};
        memcpy(q->reachable + i, &reachable, sizeof reachable);
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
    if (q->time) /* where Embree's moving instances are */
        for (int i = 0; i < ACCEL_PACKET; i++)
            p->time[i] = (float)q->time[i];
    else
        memset(p->time, 0, sizeof p->time);
    memset(p->mask, 0xFF, sizeof p->mask);
    memset(p->id, 0, sizeof p->id);
    memset(p->flags, 0, sizeof p->flags);
}

/* Lane i of Embree's packet p as one ray. */
static struct RTCRay lane_ray(const struct RTCRay8 *p, int i)
{
    return (struct RTCRay){.org_x = p->org_x[i], .org_y = p->org_y[i], .org_z = p->org_z[i],
                           .tnear = p->tnear[i], .dir_x = p->dir_x[i], .dir_y = p->dir_y[i],
                           .dir_z = p->dir_z[i], .time = p->time[i], .tfar = p->tfar[i],
                           .mask = p->mask[i], .id = p->id[i], .flags = p->flags[i]};
}

/* Takes out of valid the lanes Embree cannot take (packet_init's
 * q->reachable). */
static void embree_lanes(const query *q, int valid[ACCEL_PACKET])
{
    for (int i = 0; i < ACCEL_PACKET; i++)
        valid[i] &= q->reachable[i];
}

/* Embree's nearest hit for each valid lane of rh: the packet at once, or,
 * for rays that are not neighbours where the accelerator traces them
 * apart (rays_apart), each lane alone. */
static void nearest_hits(query *q, int valid[ACCEL_PACKET], bool coherent, struct RTCRayHit8 *rh)
{
    const accel *a = q->acc;
    embree_lanes(q, valid);
    if (coherent || !a->apart) {
        rtcIntersect8(valid, a->scene, &q->ctx, rh);
        return;
    }
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!valid[i])
            continue;
        struct RTCRayHit one = {.ray = lane_ray(&rh->ray, i),
                                .hit = {.geomID = RTC_INVALID_GEOMETRY_ID,
                                        .primID = RTC_INVALID_GEOMETRY_ID,
                                        .instID = {RTC_INVALID_GEOMETRY_ID}}};
        q->alone = i;
        rtcIntersect1(a->scene, &q->ctx, &one);
        rh->ray.tfar[i] = one.ray.tfar;
        rh->hit.u[i] = one.hit.u;
        rh->hit.v[i] = one.hit.v;
        rh->hit.primID[i] = one.hit.primID;
        rh->hit.geomID[i] = one.hit.geomID;
        rh->hit.instID[0][i] = one.hit.instID[0];
    }
    q->alone = -1;
}

/* Whether Embree finds each valid lane of p blocked (its tfar then
 * -INFINITY), as nearest_hits traces them. */
static void blocked_lanes(query *q, int valid[ACCEL_PACKET], bool coherent, struct RTCRay8 *p)
{
    const accel *a = q->acc;
    embree_lanes(q, valid);
    if (coherent || !a->apart) {
        rtcOccluded8(valid, a->scene, &q->ctx, p);
        return;
    }
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!valid[i])
            continue;
        struct RTCRay one = lane_ray(p, i);
        q->alone = i;
        rtcOccluded1(a->scene, &q->ctx, &one);
        p->tfar[i] = one.tfar;
    }
    q->alone = -1;
}

void accel_intersect8(const accel *a, const ray8 *r, const double *time, double tmax, const int skip[ACCEL_PACKET],
                      bool coherent, const bool active[ACCEL_PACKET], accel_hit hit[ACCEL_PACKET],
                      bool found[ACCEL_PACKET])
{
    double far[ACCEL_PACKET];
    for (int i = 0; i < ACCEL_PACKET; i++)
        far[i] = tmax;
    query q;
    _Alignas(32) int valid[ACCEL_PACKET];
    struct RTCRayHit8 rh;
    q.acc = a;
    q.time = time;
    packet_init(&q, r, far, skip, coherent, active, valid, &rh.ray);
    for (unsigned i = 0; i < ACCEL_PACKET; i++)
        rh.hit.geomID[i] = rh.hit.primID[i] = rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    if (a->plane_count > 0) {
        nearest_planes(&q);
        packet_far(&q, &rh.ray);
    }
    nearest_hits(&q, valid, coherent, &rh);
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
                lane_hit(&q, &rh, (unsigned)(i + j), triangle[j] != 0, &hit[i + j]);
        }
    }
}

void accel_transmission8(const accel *a, const ray8 *r, const double *time, const double tmax[ACCEL_PACKET],
                         const int skip[ACCEL_PACKET], bool coherent, const bool active[ACCEL_PACKET],
                         accel_filter_fn filter, void *user, color through[ACCEL_PACKET])
{
    query q;
    seen_set seen[ACCEL_PACKET];
    _Alignas(32) int valid[ACCEL_PACKET];
    struct RTCRay8 p;
    q.acc = a;
    q.time = time;
    packet_init(&q, r, tmax, skip, coherent, active, valid, &p);
    q.filter = filter;
    q.user = user;
    /* In a scene where everything blocks all light, no surface filters a
     * segment: it passes whole or not at all, and the lanes need no record
     * of what they passed (7% of the instructions of a floor's samples). */
    bool filtered = !a->all_opaque;
    if (filtered) {
        q.seen = seen;
        for (unsigned i = 0; i < ACCEL_PACKET; i++) {
            q.through[i] = rgb(1, 1, 1);
            q.depth[i] = rgb(0, 0, 0);
            seen_init(&seen[i]);
        }
    }
    if (a->plane_count > 0)
        through_planes(&q, valid, &p);
    blocked_lanes(&q, valid, coherent, &p);
    for (int i = 0; filtered && i < ACCEL_PACKET; i++) {
        seen_free(&seen[i]);
        color d = q.depth[i];
        if (d.r != 0 || d.g != 0 || d.b != 0) /* a sum of rounded depths may fall a hair below 0 */
            q.through[i] = rgb_mul(q.through[i], rgb(exp(-fmax(d.r, 0)), exp(-fmax(d.g, 0)), exp(-fmax(d.b, 0))));
    }
    /* What passed, or black: each channel's bits kept or cleared to +0 by
     * the lane's mask, without a branch. */
    for (int i = 0; i < ACCEL_PACKET; i += QUAD) {
        quad_mask passes = quad_from_bools(active + i) & (quad_from_floats(p.tfar + i) != quad_splat(-INFINITY));
        for (int j = 0; j < QUAD; j++) {
            uint64_t bits[3];
            _Static_assert(sizeof bits == sizeof(color), "a colour is three doubles");
            color passed = filtered ? q.through[i + j] : rgb(1, 1, 1);
            memcpy(bits, &passed, sizeof bits);
            for (int k = 0; k < 3; k++)
                bits[k] &= (uint64_t)passes[j];
            memcpy(&through[i + j], bits, sizeof bits);
        }
    }
}
