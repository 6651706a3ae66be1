/* csg.c - constructive solid geometry: the union, intersection and
 * difference of closed shapes (and of other such combinations, nested).
 *
 * A combination is a shape whose parts are shapes of the same scene
 * (shape.parts, indices into shape.family, the scene's array). It finds
 * where a ray crosses its own surface by walking the crossings of its parts
 * along the ray in order: a part's state (inside or out) flips at each of
 * its crossings, the combination's is the set operation of its parts'
 * states, and the first crossing that changes that is the hit. A convex
 * part (a sphere, box, half-space, or an intersection of such) gives
 * where the line is inside it in one go (its span: shape_span_of, or
 * convex_span for an intersection), which holds its state and both its
 * crossings, so it is tested once a walk however often the walk passes
 * it. Another part's state where the walk starts is read from its first
 * crossing ahead, which leaves it when the walk starts inside; a part the
 * ray no longer crosses is outside, unless it is unbounded (stays_inside).
 * Parts that move over the shutter are taken where they are at the time
 * of the combination's moved copy (shape_at). The hit names the part's own
 * shape (the leaf), so shading, materials and textures are the part's;
 * the surfaces a difference cuts with its other parts face the other way
 * (SHAPE_PART_FLIPPED). In the common case of a ray that meets the
 * combination from outside, that is one intersection a part. */
#include <math.h>
#include <string.h>
#include "geometry/shape_kind.h"

/* One crossing of a part's (or a combination's) surface along a ray. */
typedef struct crossing {
    double t;
    bool entering;            /* into the solid, as the ray goes */
    int leaf;                 /* the shape crossed, in the family */
    int part;                 /* its part, with SHAPE_PART_FLIPPED where it faces the other way */
} crossing;

/* r mapped into the space of the transform numbered `id` (shape
 * transform_id), kept through a walk: the parts of a combination placed
 * as a whole share one transform, which then maps the ray once. */
typedef struct mapped_ray {
    unsigned id;
    ray r;
} mapped_ray;

static bool next_crossing(const shape *s, int index, const ray *r, mapped_ray *mapped, double after,
                          crossing *c, int depth, double time);
static bool stays_inside(const shape *s, const ray *r, mapped_ray *mapped, double after, int depth,
                         double time);

/* Whether the combination of kind k is solid where its parts' states are
 * inside[0..n). */
static bool combined(glint_shape_kind k, const bool *inside, int n)
{
    if (k == GLINT_SHAPE_UNION) {
        for (int i = 0; i < n; i++)
            if (inside[i])
                return true;
        return false;
    }
    if (k == GLINT_SHAPE_INTERSECTION) {
        for (int i = 0; i < n; i++)
            if (!inside[i])
                return false;
        return n > 0;
    }
    if (n == 0 || !inside[0])
        return false;
    for (int i = 1; i < n; i++)
        if (inside[i])
            return false;
    return true;
}

/* A plain convex shape's span, through the mapped ray when it shares its
 * transform. */
static bool leaf_span(const shape *s, const ray *r, mapped_ray *mapped, shape_span *span)
{
    if (!s->transform_id)
        return shape_span_of(s, r, span);
    if (mapped->id != s->transform_id) {
        mapped->id = s->transform_id;
        mapped->r = shape_object_ray(s, r);
    }
    return s->kind->span(s, &mapped->r, span);
}

/* Where r's line is inside convex shape s (number `index` of the family),
 * as it is at `time`: its own span, or an intersection's, the overlap of
 * its parts' (the part entered last and the part left first name its
 * ends, the first of them on a tie, as the walk would). False when the
 * line misses it, or only touches it. */
static bool convex_span(const shape *s, int index, const ray *r, mapped_ray *mapped, double time, shape_span *span,
                        int depth)
{
    if (!s->kind->csg) {
        shape moved;
        if (!leaf_span(shape_at(s, time, &moved), r, mapped, span))
            return false;
        span->leaf_in = span->leaf_out = index;
        return span->t_in < span->t_out;
    }
    if (depth >= SHAPE_MAX_NESTING)
        return false;
    *span = (shape_span){-INFINITY, INFINITY, 0, 0, index, index};
    for (int i = 0; i < s->part_count; i++) {
        shape_span part;
        if (!convex_span(&s->family[s->parts[i]], s->parts[i], r, mapped, time, &part, depth + 1))
            return false;
        if (part.t_in >= span->t_in) {
            span->t_in = part.t_in;
            span->part_in = part.part_in;
            span->leaf_in = part.leaf_in;
        }
        if (part.t_out < span->t_out) {
            span->t_out = part.t_out;
            span->part_out = part.part_out;
            span->leaf_out = part.leaf_out;
        }
    }
    return span->t_in < span->t_out;
}

/* The first crossing of a convex part's span after `after`: its way in,
 * or its way out, where those are finite. */
static bool span_next(const shape_span *span, double after, crossing *c)
{
    if (span->t_in > after && span->t_in < INFINITY) {
        *c = (crossing){span->t_in, true, span->leaf_in, span->part_in};
        return true;
    }
    if (span->t_out > after && span->t_out < INFINITY) {
        *c = (crossing){span->t_out, false, span->leaf_out, span->part_out};
        return true;
    }
    return false;
}

/* A convex part's state where a walk starts at `after`, from its span:
 * whether the walk starts inside it, and its first crossing ahead (*ahead,
 * if it has one). */
static bool span_start(const shape_span *span, double after, bool *inside, crossing *ahead)
{
    *inside = span->t_in <= after && after < span->t_out;
    return span_next(span, after, ahead);
}

/* Whether every solid point of combination s is inside its part i (a
 * difference's first, any of an intersection's): a ray outside that part
 * that never enters it never meets the solid, and the rest need no test. */
static bool part_needed(const shape *s, int i)
{
    return s->desc.kind == GLINT_SHAPE_INTERSECTION || (i == 0 && s->desc.kind == GLINT_SHAPE_DIFFERENCE);
}

/* The walk of combination s from its parts' states where it starts
 * (inside[i]; has[i] and ahead[i], the next crossing of each; spans[i] of
 * the convex ones): the first crossing that changes the combination's
 * state. Parts that are not convex find their next crossings along r, as
 * they are at `time`. */
static bool walk(const shape *s, const ray *r, mapped_ray *mapped, const shape_span *spans, crossing *ahead,
                 bool *has, bool *inside, crossing *out, int depth, double time)
{
    int n = s->part_count;
    bool solid = combined(s->desc.kind, inside, n);
    /* Each step passes one crossing of one part, which has finitely many. */
    for (;;) {
        int first = -1;
        for (int i = 0; i < n; i++)
            if (has[i] && (first < 0 || ahead[i].t < ahead[first].t))
                first = i;
        if (first < 0)
            return false;
        inside[first] = ahead[first].entering;
        bool now = combined(s->desc.kind, inside, n);
        if (now != solid) {
            *out = ahead[first];
            out->entering = now;
            if (s->desc.kind == GLINT_SHAPE_DIFFERENCE && first > 0)
                out->part ^= SHAPE_PART_FLIPPED;
            return true;
        }
        const shape *part = &s->family[s->parts[first]];
        has[first] = part->convex ? span_next(&spans[first], ahead[first].t, &ahead[first])
                                  : next_crossing(part, s->parts[first], r, mapped, ahead[first].t, &ahead[first],
                                                  depth + 1, time);
    }
}

/* The first crossing of combination s after `after` (to any distance),
 * its parts as they are at `time`: the walk described at the top. */
static bool combination_crossing(const shape *s, const ray *r, mapped_ray *mapped, double after, crossing *out,
                                 int depth, double time)
{
    int n = s->part_count;
    crossing ahead[SHAPE_MAX_PARTS];
    shape_span spans[SHAPE_MAX_PARTS];
    bool has[SHAPE_MAX_PARTS], inside[SHAPE_MAX_PARTS];
    /* Each is set below; cleared first only so the compiler can tell. */
    memset(inside, 0, (size_t)n);
    for (int i = 0; i < n; i++) {
        const shape *part = &s->family[s->parts[i]];
        if (part->convex) {
            /* A line that misses it leaves an empty span, after every end. */
            if (!convex_span(part, s->parts[i], r, mapped, time, &spans[i], depth + 1))
                spans[i] = (shape_span){INFINITY, INFINITY, 0, 0, 0, 0};
            has[i] = span_start(&spans[i], after, &inside[i], &ahead[i]);
        } else {
            has[i] = next_crossing(part, s->parts[i], r, mapped, after, &ahead[i], depth + 1, time);
            inside[i] = has[i] ? !ahead[i].entering : stays_inside(part, r, mapped, after, depth + 1, time);
        }
        if (part_needed(s, i) && !has[i] && !inside[i])
            return false;
    }
    return walk(s, r, mapped, spans, ahead, has, inside, out, depth, time);
}

/* The first crossing of shape s (number `index` of the family) after
 * `after`, as it is at `time`: a combination's, or a plain shape's, whose
 * normal there says whether the ray goes in or out. */
static bool next_crossing(const shape *s, int index, const ray *r, mapped_ray *mapped, double after,
                          crossing *c, int depth, double time)
{
    if (s->kind->csg)
        return depth < SHAPE_MAX_NESTING && combination_crossing(s, r, mapped, after, c, depth, time);
    shape moved;
    const shape *at = shape_at(s, time, &moved);
    shape_hit h;
    if (!shape_intersect(at, r, after, INFINITY, &h))
        return false;
    *c = (crossing){h.t, shape_hit_enters(at, r, &h), index, h.part};
    return true;
}

/* Whether s holds an unbounded part (a plane's half-space), which a ray
 * may be inside without crossing it. */
static bool unbounded(const shape *s)
{
    if (!s->kind->csg)
        return s->kind->contains != NULL;
    for (int i = 0; i < s->part_count; i++)
        if (unbounded(&s->family[s->parts[i]]))
            return true;
    return false;
}

/* Whether the point at `after` along r is inside s, which r crosses no
 * more after it: outside, unless s is unbounded (a ray in a plane's
 * half-space going away from the plane, or along the inside of a prism
 * made of three). */
static bool stays_inside(const shape *s, const ray *r, mapped_ray *mapped, double after, int depth,
                         double time)
{
    if (depth >= SHAPE_MAX_NESTING || !unbounded(s))
        return false;
    if (!s->kind->csg) {
        vec3 p = ray_at(r, after);
        shape moved;
        const shape *at = shape_at(s, time, &moved);
        return s->kind->contains(at, at->has_transform ? xf_point(&at->to_object, p) : p);
    }
    bool inside[SHAPE_MAX_PARTS] = {false};
    for (int i = 0; i < s->part_count; i++) {
        const shape *part = &s->family[s->parts[i]];
        crossing c;
        inside[i] = next_crossing(part, s->parts[i], r, mapped, after, &c, depth + 1, time)
                        ? !c.entering
                        : stays_inside(part, r, mapped, after, depth + 1, time);
    }
    return combined(s->desc.kind, inside, s->part_count);
}

static bool csg_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    crossing c;
    shape_span span;
    mapped_ray mapped = {0};
    /* A convex combination (a lens of two balls) is its span's ends. */
    if (s->convex) {
        if (!convex_span(s, -1, r, &mapped, s->time, &span, 0) || !span_next(&span, tmin, &c) || !(c.t < tmax))
            return false;
        *hit = (shape_hit){c.t, c.part, c.leaf};
        return true;
    }
    if (!combination_crossing(s, r, &mapped, tmin, &c, 0, s->time) || !(c.t < tmax))
        return false;
    *hit = (shape_hit){c.t, c.part, c.leaf};
    return true;
}

/* A combination finds its hits four lanes at a time when its parts are at
 * most this many, each convex and giving its span four lanes at once (a
 * still sphere or box, or an intersection of such): their spans on the
 * stack, a quad a part. */
#define QUAD_PARTS 16

/* The four world rays as leaf s sees them, mapped once for all the leaves
 * of one transform (leaf_span's cache, four lanes wide). */
typedef struct mapped_quad {
    unsigned id;
    quad_ray r;
} mapped_quad;

/* convex_span for four world rays w at once, s and its parts still and
 * giving their spans four lanes at once (spans_four): the mask of the
 * lanes convex_span says true for, each lane's span its bits. (Nesting is
 * below SHAPE_MAX_NESTING, which glint_scene_add_part enforces.) */
static quad_mask convex_span4(const shape *s, int index, const quad_ray *w, mapped_quad *mapped, quad_span *span)
{
    quad_mask me = (quad_mask){0} + index;
    if (!s->kind->csg) {
        quad_ray own;
        const quad_ray *r = w;
        if (s->has_transform && !s->transform_id) {
            own = quad_object_ray(&s->to_object, w);
            r = &own;
        } else if (s->has_transform) {
            if (mapped->id != s->transform_id) {
                mapped->id = s->transform_id;
                mapped->r = quad_object_ray(&s->to_object, w);
            }
            r = &mapped->r;
        }
        quad_mask meets = s->kind->span4(s, r, span);
        span->leaf_in = span->leaf_out = me;
        return meets & (span->t_in < span->t_out);
    }
    *span = (quad_span){quad_splat(-INFINITY), quad_splat(INFINITY), {0}, {0}, me, me};
    quad_mask meets = ~(quad_mask){0};
    for (int i = 0; i < s->part_count && quad_any(meets); i++) {
        quad_span part;
        meets &= convex_span4(&s->family[s->parts[i]], s->parts[i], w, mapped, &part);
        quad_mask in = part.t_in >= span->t_in, out = part.t_out < span->t_out;
        span->t_in = quad_select(in, part.t_in, span->t_in);
        span->part_in = quad_mask_select(in, part.part_in, span->part_in);
        span->leaf_in = quad_mask_select(in, part.leaf_in, span->leaf_in);
        span->t_out = quad_select(out, part.t_out, span->t_out);
        span->part_out = quad_mask_select(out, part.part_out, span->part_out);
        span->leaf_out = quad_mask_select(out, part.leaf_out, span->leaf_out);
    }
    return meets & (span->t_in < span->t_out);
}

/* Lane k of a quad span, or the empty span after every end where the
 * lane's line misses the part. */
static shape_span span_lane(const quad_span *q, quad_mask meets, int k)
{
    if (!meets[k])
        return (shape_span){INFINITY, INFINITY, 0, 0, 0, 0};
    return (shape_span){q->t_in[k], q->t_out[k], (int)q->part_in[k], (int)q->part_out[k], (int)q->leaf_in[k],
                        (int)q->leaf_out[k]};
}

/* Records crossing c as lane k's hit when it is nearer than tmax[k]. */
static void quad_offer(const crossing *c, quad_f64 tmax, int k, quad_hit *hit, quad_mask *found)
{
    if (!(c->t < tmax[k]))
        return;
    hit->t[k] = c->t;
    hit->part[k] = c->part;
    hit->leaf[k] = c->leaf;
    (*found)[k] = -1;
}

/* csg_intersect for four lanes, for a combination shape_parts_changed
 * marked quad: every part's spans four lanes at once, then each lane's
 * walk over them, as combination_crossing's (the same bits). */
static quad_mask csg_intersect4(const shape *s, const ray8 *r, int first, quad_f64 tmax, quad_hit *hit)
{
    const quad_ray w = quad_ray_of(r, first);
    mapped_quad mapped;
    mapped.id = 0; /* nothing mapped yet: the rays need no clearing */
    quad_mask found = {0};
    crossing c;
    if (s->convex) {
        quad_span span;
        quad_mask meets = convex_span4(s, -1, &w, &mapped, &span);
        for (int k = 0; k < QUAD; k++) {
            shape_span one = span_lane(&span, meets, k);
            if (meets[k] && span_next(&one, 0, &c))
                quad_offer(&c, tmax, k, hit, &found);
        }
        return found;
    }
    int n = s->part_count;
    quad_span spans[QUAD_PARTS];
    quad_mask meets[QUAD_PARTS];
    for (int i = 0; i < n; i++) {
        meets[i] = convex_span4(&s->family[s->parts[i]], s->parts[i], &w, &mapped, &spans[i]);
        /* No lane can meet the solid when none meets this part. */
        if (part_needed(s, i) && !quad_any(meets[i]))
            return found;
    }
    /* Where every part a difference takes away lies clear of its first
     * part, along a lane's line, the difference there is that first part:
     * the walk would pass the others' crossings outside it, changing
     * nothing. Most rays at a die miss its pips so, and skip the walk. */
    quad_mask first_alone = {0};
    if (s->desc.kind == GLINT_SHAPE_DIFFERENCE && n > 0) {
        first_alone = meets[0];
        for (int i = 1; i < n; i++)
            first_alone &= ~meets[i] | (spans[i].t_out < spans[0].t_in) | (spans[i].t_in > spans[0].t_out);
    }
    for (int k = 0; k < QUAD; k++) {
        if (first_alone[k]) {
            shape_span alone = span_lane(&spans[0], meets[0], k);
            if (span_next(&alone, 0, &c))
                quad_offer(&c, tmax, k, hit, &found);
            continue;
        }
        crossing ahead[QUAD_PARTS];
        shape_span lane[QUAD_PARTS];
        bool has[QUAD_PARTS], inside[QUAD_PARTS], open = true;
        for (int i = 0; i < n && open; i++) {
            lane[i] = span_lane(&spans[i], meets[i], k);
            has[i] = span_start(&lane[i], 0, &inside[i], &ahead[i]);
            open = !(part_needed(s, i) && !has[i] && !inside[i]);
        }
        if (open && walk(s, NULL, NULL, lane, ahead, has, inside, &c, 0, 0))
            quad_offer(&c, tmax, k, hit, &found);
    }
    return found;
}

/* Whether s, a part of a combination, gives its span four lanes at once:
 * a still shape whose kind does, or an intersection of such. */
static bool spans_four(const shape *s)
{
    if (!s->csg)
        return s->kind->span4 && !s->pose_count;
    for (int i = 0; i < s->part_count; i++)
        if (!spans_four(&s->family[s->parts[i]]))
            return false;
    return s->convex;
}

/* The bounds of the union of the parts' bounds, of their intersection, or
 * of the first part's (a difference is within what it cuts from). A
 * plane's, unbounded, is a box SHAPE_PLANE_EXTENT each way. */
static void csg_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    bool meet = s->desc.kind == GLINT_SHAPE_INTERSECTION;
    int n = s->desc.kind == GLINT_SHAPE_DIFFERENCE && s->part_count > 0 ? 1 : s->part_count;
    *lo = v3(0, 0, 0);
    *hi = v3(0, 0, 0);
    for (int i = 0; i < n; i++) {
        vec3 a, b;
        shape_bounds(&s->family[s->parts[i]], &a, &b);
        if (i == 0) {
            *lo = a;
            *hi = b;
        } else if (meet) {
            *lo = v3(fmax(lo->x, a.x), fmax(lo->y, a.y), fmax(lo->z, a.z));
            *hi = v3(fmin(hi->x, b.x), fmin(hi->y, b.y), fmin(hi->z, b.z));
        } else {
            *lo = v3(fmin(lo->x, a.x), fmin(lo->y, a.y), fmin(lo->z, a.z));
            *hi = v3(fmax(hi->x, b.x), fmax(hi->y, b.y), fmax(hi->z, b.z));
        }
    }
    /* An intersection of parts that do not overlap is empty: a point. */
    if (meet && (lo->x > hi->x || lo->y > hi->y || lo->z > hi->z))
        *hi = *lo;
}

void shape_parts_changed(shape *family, int combination)
{
    for (int up = combination; up >= 0; up = family[up].part_of) {
        shape *c = &family[up];
        bool convex = c->desc.kind == GLINT_SHAPE_INTERSECTION && c->part_count > 0;
        for (int i = 0; convex && i < c->part_count; i++)
            convex = family[c->parts[i]].convex;
        c->convex = convex;
        c->quad = c->part_count > 0 && c->part_count <= QUAD_PARTS && !c->pose_count;
        for (int i = 0; c->quad && i < c->part_count; i++)
            c->quad = spans_four(&family[c->parts[i]]);
    }
}

#define CSG_KIND(kind_name, kind_id)                                                                           \
    {.name = kind_name, .id = kind_id, .csg = true, .closed = shape_always_closed, .intersect = csg_intersect, .intersect4 = csg_intersect4, \
     .bounds = csg_bounds, .center = shape_bounds_middle}

const shape_kind union_kind = CSG_KIND("union", GLINT_SHAPE_UNION);
const shape_kind intersection_kind = CSG_KIND("intersection", GLINT_SHAPE_INTERSECTION);
const shape_kind difference_kind = CSG_KIND("difference", GLINT_SHAPE_DIFFERENCE);
