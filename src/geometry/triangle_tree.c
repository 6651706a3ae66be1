/* triangle_tree.c - building and walking the triangle hierarchy of
 * triangle_tree.h: binned surface-area splits, at most LEAF_MOST triangles
 * a leaf, and a watertight ray-triangle test in double precision. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "geometry/triangle_tree.h"

#define BINS 16
#define LEAF_MOST 4
/* Past this depth a range is split in half by count, so that no tree is
 * deeper than it plus 31 levels (2^30 triangles at most): the walk's stack. */
#define SAH_DEPTH 64
#define STACK (SAH_DEPTH + 40)

typedef struct box {
    double lo[3], hi[3];
} box;

static box box_empty(void)
{
    return (box){{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
}

static void box_grow(box *b, const box *with)
{
    for (int k = 0; k < 3; k++) {
        b->lo[k] = fmin(b->lo[k], with->lo[k]);
        b->hi[k] = fmax(b->hi[k], with->hi[k]);
    }
}

/* Half the surface area: what the heuristic weighs a box by. */
static double box_half_area(const box *b)
{
    double x = b->hi[0] - b->lo[0], y = b->hi[1] - b->lo[1], z = b->hi[2] - b->lo[2];
    return x > 0 || y > 0 || z > 0 ? x * y + y * z + z * x : 0;
}

/* What the build knows of each triangle. */
typedef struct item {
    box bounds;
    double middle[3];         /* the centre of its bounds */
} item;

typedef struct builder {
    item *items;
    uint32_t *order;          /* triangles, in the order their slots will have */
    tree_node *nodes;
    uint32_t node_count;
} builder;

/* Where along `axis` the triangles order[begin..end) split best, as a count
 * of those that go first after partitioning; 0: none is better than a leaf. */
static uint32_t split_by_area(builder *b, uint32_t begin, uint32_t end, const box *node, const box *middles,
                              int axis)
{
    double lo = middles->lo[axis], extent = middles->hi[axis] - lo;
    if (!(extent > 0))
        return 0;
    box bins[BINS];
    uint32_t counts[BINS] = {0};
    for (int i = 0; i < BINS; i++)
        bins[i] = box_empty();
    double scale = BINS / extent;
    for (uint32_t i = begin; i < end; i++) {
        const item *it = &b->items[b->order[i]];
        int bin = (int)((it->middle[axis] - lo) * scale);
        bin = bin < 0 ? 0 : bin >= BINS ? BINS - 1 : bin;
        counts[bin]++;
        box_grow(&bins[bin], &it->bounds);
    }
    /* The cost of each cut, below its bins and above them. */
    double below_cost[BINS];
    box sweep = box_empty();
    uint32_t below = 0;
    for (int i = 0; i < BINS - 1; i++) {
        box_grow(&sweep, &bins[i]);
        below += counts[i];
        below_cost[i] = box_half_area(&sweep) * below;
    }
    sweep = box_empty();
    uint32_t above = 0, best_below = 0;
    double best = box_half_area(node) * (double)(end - begin);
    int cut = -1;
    for (int i = BINS - 1; i > 0; i--) {
        box_grow(&sweep, &bins[i]);
        above += counts[i];
        double cost = below_cost[i - 1] + box_half_area(&sweep) * above;
        if (above < end - begin && cost < best) {
            best = cost;
            cut = i;
            best_below = end - begin - above;
        }
    }
    if (cut < 0)
        return 0;
    /* Partition: triangles of bins below `cut` first. */
    uint32_t i = begin, j = end;
    while (i < j) {
        const item *it = &b->items[b->order[i]];
        int bin = (int)((it->middle[axis] - lo) * scale);
        bin = bin < 0 ? 0 : bin >= BINS ? BINS - 1 : bin;
        if (bin < cut) {
            i++;
        } else {
            uint32_t swap = b->order[i];
            b->order[i] = b->order[--j];
            b->order[j] = swap;
        }
    }
    return best_below;
}

/* Fills node `at` over order[begin..end) and everything below it. */
static void build_node(builder *b, uint32_t at, uint32_t begin, uint32_t end, int depth)
{
    box bounds = box_empty(), middles = box_empty();
    for (uint32_t i = begin; i < end; i++) {
        const item *it = &b->items[b->order[i]];
        box_grow(&bounds, &it->bounds);
        box point = {{it->middle[0], it->middle[1], it->middle[2]}, {it->middle[0], it->middle[1], it->middle[2]}};
        box_grow(&middles, &point);
    }
    tree_node *n = &b->nodes[at];
    memcpy(n->lo, bounds.lo, sizeof n->lo);
    memcpy(n->hi, bounds.hi, sizeof n->hi);
    uint32_t count = end - begin, below = 0;
    if (count <= LEAF_MOST) {
        n->first = begin;
        n->count = count;
        return;
    }
    if (depth < SAH_DEPTH) {
        int axis = 0;
        for (int k = 1; k < 3; k++)
            if (middles.hi[k] - middles.lo[k] > middles.hi[axis] - middles.lo[axis])
                axis = k;
        below = split_by_area(b, begin, end, &bounds, &middles, axis);
        /* No cheaper cut: a small range stays a leaf, a large one (many
         * triangles at one place) is halved. */
        if (below == 0 && count <= 2 * LEAF_MOST) {
            n->first = begin;
            n->count = count;
            return;
        }
    }
    if (below == 0)
        below = count / 2;
    uint32_t children = b->node_count;
    b->node_count += 2;
    n->first = children;
    n->count = 0;
    build_node(b, children, begin, begin + below, depth + 1);
    build_node(b, children + 1, begin + below, end, depth + 1);
}

static vec3 corner(const float *positions, uint32_t vertex)
{
    const float *p = positions + 3 * (size_t)vertex;
    return v3(p[0], p[1], p[2]);
}

glint_status triangle_tree_build(triangle_tree *t, const float *positions, const uint32_t *indices,
                                 int triangle_count, glint_error *err)
{
    memset(t, 0, sizeof *t);
    size_t n = (size_t)triangle_count;
    builder b = {.items = malloc(n * sizeof *b.items), .order = malloc(n * sizeof *b.order),
                 .nodes = malloc((2 * n) * sizeof *b.nodes), .node_count = 1};
    t->corners = malloc(3 * n * sizeof *t->corners);
    t->triangle = b.order;
    t->nodes = b.nodes;
    if (!b.items || !b.order || !b.nodes || !t->corners) {
        free(b.items);
        triangle_tree_free(t);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for a mesh of %d triangles", triangle_count);
    }
    for (size_t i = 0; i < n; i++) {
        item *it = &b.items[i];
        it->bounds = box_empty();
        for (int c = 0; c < 3; c++) {
            vec3 p = corner(positions, indices[3 * i + (size_t)c]);
            box at = {{p.x, p.y, p.z}, {p.x, p.y, p.z}};
            box_grow(&it->bounds, &at);
        }
        for (int k = 0; k < 3; k++)
            it->middle[k] = 0.5 * (it->bounds.lo[k] + it->bounds.hi[k]);
        b.order[i] = (uint32_t)i;
    }
    build_node(&b, 0, 0, (uint32_t)n, 0);
    free(b.items);
    for (size_t slot = 0; slot < n; slot++)
        for (int c = 0; c < 3; c++)
            t->corners[3 * slot + (size_t)c] = corner(positions, indices[3 * (size_t)b.order[slot] + (size_t)c]);
    t->triangle_count = triangle_count;
    return GLINT_OK;
}

void triangle_tree_free(triangle_tree *t)
{
    free(t->nodes);
    free(t->corners);
    free(t->triangle);
    memset(t, 0, sizeof *t);
}

/* A ray as the watertight test sees it: its axes permuted so that z is
 * the one it runs most along, and sheared so that it runs along z. */
typedef struct sheared {
    int kx, ky, kz;
    double sx, sy, sz;
    double o[3];
} sheared;

static sheared shear(const ray *r)
{
    double d[3] = {r->d.x, r->d.y, r->d.z};
    sheared s = {.o = {r->o.x, r->o.y, r->o.z}};
    s.kz = fabs(d[0]) > fabs(d[1]) ? (fabs(d[0]) > fabs(d[2]) ? 0 : 2) : (fabs(d[1]) > fabs(d[2]) ? 1 : 2);
    s.kx = (s.kz + 1) % 3;
    s.ky = (s.kx + 1) % 3;
    /* Keeping the winding: a mirrored frame would flip every sign test. */
    if (d[s.kz] < 0) {
        int swap = s.kx;
        s.kx = s.ky;
        s.ky = swap;
    }
    s.sx = d[s.kx] / d[s.kz];
    s.sy = d[s.ky] / d[s.kz];
    s.sz = 1 / d[s.kz];
    return s;
}

/* The distance along the sheared ray to the triangle of corners c, or NaN
 * when it misses. Each edge's sign comes from that edge's corners alone,
 * computed the same in both triangles that share it (negated exactly), so
 * a ray through the edge is on the inside of at least one of them. */
static double crossing(const sheared *s, const vec3 *c)
{
    double x[3], y[3], z[3];
    for (int i = 0; i < 3; i++) {
        double p[3] = {c[i].x - s->o[0], c[i].y - s->o[1], c[i].z - s->o[2]};
        x[i] = p[s->kx] - s->sx * p[s->kz];
        y[i] = p[s->ky] - s->sy * p[s->kz];
        z[i] = s->sz * p[s->kz];
    }
    double u = x[2] * y[1] - y[2] * x[1];
    double v = x[0] * y[2] - y[0] * x[2];
    double w = x[1] * y[0] - y[1] * x[0];
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0))
        return NAN;
    double det = u + v + w;
    if (det == 0)
        return NAN;
    return (u * z[0] + v * z[1] + w * z[2]) / det;
}

/* The distances between which r is inside node n's box, widened by a
 * relative 1e-12 so that rounding never loses a triangle on its faces
 * (an axis-aligned mesh's faces lie on them); an axis the ray does not
 * run along and starts on a face of gives NaN there, which leaves that
 * axis out. */
static bool node_span(const tree_node *n, const double *o, const double *inverse, double tmin, double tmax,
                      double *near)
{
    double tn = tmin, tf = tmax;
    for (int k = 0; k < 3; k++) {
        double a = (n->lo[k] - o[k]) * inverse[k], b = (n->hi[k] - o[k]) * inverse[k];
        if (inverse[k] < 0) {
            double swap = a;
            a = b;
            b = swap;
        }
        a -= 1e-12 * fabs(a);
        b += 1e-12 * fabs(b);
        tn = a > tn ? a : tn;
        tf = b < tf ? b : tf;
    }
    *near = tn;
    return tn <= tf;
}

bool triangle_tree_hit(const triangle_tree *t, const ray *r, double tmin, double tmax, double *at,
                       uint32_t *triangle)
{
    if (t->triangle_count == 0)
        return false;
    sheared s = shear(r);
    double inverse[3] = {1 / r->d.x, 1 / r->d.y, 1 / r->d.z};
    double best = tmax, near;
    int64_t found = -1;
    if (!node_span(&t->nodes[0], s.o, inverse, tmin, best, &near))
        return false;
    uint32_t stack[STACK];
    int depth = 0;
    stack[depth++] = 0;
    while (depth > 0) {
        const tree_node *n = &t->nodes[stack[--depth]];
        if (n->count) {
            for (uint32_t i = n->first; i < n->first + n->count; i++) {
                double d = crossing(&s, &t->corners[3 * (size_t)i]);
                if (d > tmin && d < best) {
                    best = d;
                    found = i;
                }
            }
            continue;
        }
        double near_a, near_b;
        bool a = node_span(&t->nodes[n->first], s.o, inverse, tmin, best, &near_a);
        bool b = node_span(&t->nodes[n->first + 1], s.o, inverse, tmin, best, &near_b);
        /* The nearer child is taken first: its hits cut the other short. */
        uint32_t first = n->first, second = n->first + 1;
        if (a && b && near_b < near_a) {
            first = n->first + 1;
            second = n->first;
        }
        if (a && b) {
            stack[depth++] = second;
            stack[depth++] = first;
        } else if (a || b) {
            stack[depth++] = a ? n->first : n->first + 1;
        }
    }
    if (found < 0)
        return false;
    *at = best;
    *triangle = t->triangle[found];
    return true;
}
