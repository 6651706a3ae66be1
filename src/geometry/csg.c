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
    /* Past a part that every solid point must be in (a difference's first,
     * any of an intersection's), the ray never meets the solid if it is
     * outside that part and never enters it: the rest need no test. */
    bool needs_all = s->desc.kind == GLINT_SHAPE_INTERSECTION;
    for (int i = 0; i < n; i++) {
        const shape *part = &s->family[s->parts[i]];
        if (part->convex) {
            /* A line that misses it leaves an empty span, after every end. */
            if (!convex_span(part, s->parts[i], r, mapped, time, &spans[i], depth + 1))
                spans[i] = (shape_span){INFINITY, INFINITY, 0, 0, 0, 0};
            inside[i] = spans[i].t_in <= after && after < spans[i].t_out;
            has[i] = span_next(&spans[i], after, &ahead[i]);
        } else {
            has[i] = next_crossing(part, s->parts[i], r, mapped, after, &ahead[i], depth + 1, time);
            inside[i] = has[i] ? !ahead[i].entering : stays_inside(part, r, mapped, after, depth + 1, time);
        }
        if ((needs_all || (i == 0 && s->desc.kind == GLINT_SHAPE_DIFFERENCE)) && !has[i] && !inside[i])
            return false;
    }
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
    }
}

#define CSG_KIND(kind_name, kind_id)                                                                           \
    {.name = kind_name, .id = kind_id, .csg = true, .closed = shape_always_closed, .intersect = csg_intersect, \
     .bounds = csg_bounds, .center = shape_bounds_middle}

const shape_kind union_kind = CSG_KIND("union", GLINT_SHAPE_UNION);
const shape_kind intersection_kind = CSG_KIND("intersection", GLINT_SHAPE_INTERSECTION);
const shape_kind difference_kind = CSG_KIND("difference", GLINT_SHAPE_DIFFERENCE);
