/* csg.c - constructive solid geometry: the union, intersection and
 * difference of closed shapes (and of other such combinations, nested).
 *
 * A combination is a shape whose parts are shapes of the same scene
 * (shape.parts, indices into shape.family, the scene's array). It finds
 * where a ray crosses its own surface by walking the crossings of its parts
 * along the ray in order: a part's state (inside or out) flips at each of
 * its crossings, the combination's is the set operation of its parts'
 * states, and the first crossing that changes that is the hit. A part's
 * state where the walk starts is read from its first crossing ahead, which
 * leaves it when the walk starts inside; a part the ray no longer crosses
 * is outside, unless it is unbounded (a plane's half-space, stays_inside).
 * Parts that move over the shutter are taken where they are at the time
 * of the combination's moved copy (shape_at). The hit names the part's own
 * shape (the leaf), so shading, materials and textures are the part's;
 * the surfaces a difference cuts with its other parts face the other way
 * (SHAPE_PART_FLIPPED). In the common case of a ray that meets the
 * combination from outside, that is one intersection a part. */
#include <math.h>
#include "geometry/shape_kind.h"

/* One crossing of a part's (or a combination's) surface along a ray. */
typedef struct crossing {
    double t;
    bool entering;            /* into the solid, as the ray goes */
    int leaf;                 /* the shape crossed, in the family */
    int part;                 /* its part, with SHAPE_PART_FLIPPED where it faces the other way */
} crossing;

static bool next_crossing(const shape *s, int index, const ray *r, double after, crossing *c, int depth,
                          double time);
static bool stays_inside(const shape *s, const ray *r, double after, int depth, double time);

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

/* The first crossing of combination s after `after` (to any distance),
 * its parts as they are at `time`: the walk described at the top. */
static bool combination_crossing(const shape *s, const ray *r, double after, crossing *out, int depth, double time)
{
    int n = s->part_count;
    crossing ahead[SHAPE_MAX_PARTS];
    bool has[SHAPE_MAX_PARTS], inside[SHAPE_MAX_PARTS] = {false};
    for (int i = 0; i < n; i++) {
        const shape *part = &s->family[s->parts[i]];
        has[i] = next_crossing(part, s->parts[i], r, after, &ahead[i], depth + 1, time);
        inside[i] = has[i] ? !ahead[i].entering : stays_inside(part, r, after, depth + 1, time);
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
        has[first] = next_crossing(&s->family[s->parts[first]], s->parts[first], r, ahead[first].t,
                                   &ahead[first], depth + 1, time);
    }
}

/* The first crossing of shape s (number `index` of the family) after
 * `after`, as it is at `time`: a combination's, or a plain shape's, whose
 * normal there says whether the ray goes in or out. */
static bool next_crossing(const shape *s, int index, const ray *r, double after, crossing *c, int depth,
                          double time)
{
    if (s->kind->csg)
        return depth < SHAPE_MAX_NESTING && combination_crossing(s, r, after, c, depth, time);
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
static bool stays_inside(const shape *s, const ray *r, double after, int depth, double time)
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
        inside[i] = next_crossing(part, s->parts[i], r, after, &c, depth + 1, time)
                        ? !c.entering
                        : stays_inside(part, r, after, depth + 1, time);
    }
    return combined(s->desc.kind, inside, s->part_count);
}

static bool csg_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    crossing c;
    if (!combination_crossing(s, r, tmin, &c, 0, s->time) || !(c.t < tmax))
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

#define CSG_KIND(kind_name, kind_id)                                                                           \
    {.name = kind_name, .id = kind_id, .csg = true, .closed = shape_always_closed, .intersect = csg_intersect, \
     .bounds = csg_bounds, .center = shape_bounds_middle}

const shape_kind union_kind = CSG_KIND("union", GLINT_SHAPE_UNION);
const shape_kind intersection_kind = CSG_KIND("intersection", GLINT_SHAPE_INTERSECTION);
const shape_kind difference_kind = CSG_KIND("difference", GLINT_SHAPE_DIFFERENCE);
