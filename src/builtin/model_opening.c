/* model_opening.c - finding the open side of a room-like model. The rays
 * from the sides of the bounding box all run along an axis, so instead of
 * tracing them one at a time each triangle is projected along each axis
 * onto that axis's grid of rays, and marks in the cells it covers its
 * nearest points to both ends: one pass over the triangles per axis, with
 * no acceleration structure, and exact for rays through the cells'
 * centres. */
#include <math.h>
#include <stdbool.h>
#include "builtin/model_opening.h"

/* Rays along each side, in both directions across it. */
#define GRID 32
#define CELLS (GRID * GRID)

/* A wall stops rays within WALL_DEPTH of the depth; an opening lets them
 * reach past DEEP. The shares, of all the side's rays, that make a wall or
 * an opening are in model_opening.h. */
static const double WALL_DEPTH = 0.05, DEEP = 0.5;

static double coord(vec3 v, int axis)
{
    return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/* The nearest hits along one axis: for each cell (its rays pass through
 * the cell's centre), the least and the greatest coordinate along the
 * axis where a triangle covers it; +inf and -inf where none does. */
typedef struct axis_hits {
    double least[CELLS], most[CELLS];
} axis_hits;

/* Marks the triangle p (its corners, 3 floats each) in the cells it covers
 * when projected along `axis` onto that axis's grid: the grid's corner `lo`
 * and its cells' `size` are in the box's two other coordinates, the one
 * after `axis` first (y and z for x, z and x for y, x and y for z). */
static void mark_triangle(axis_hits *h, int axis, const float *p[3], const double lo[2], const double size[2])
{
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    double pu[3], pv[3], pa[3];
    for (int k = 0; k < 3; k++) {
        pu[k] = p[k][u];
        pv[k] = p[k][v];
        pa[k] = p[k][axis];
    }
    double area = (pu[1] - pu[0]) * (pv[2] - pv[0]) - (pu[2] - pu[0]) * (pv[1] - pv[0]);
    /* Seen edge on, a triangle stops no ray: walls along the axis are met
     * from the other sides. */
    if (fabs(area) <= 1e-12 * size[0] * size[1] * CELLS)
        return;
    int first[2], last[2];
    for (int d = 0; d < 2; d++) {
        const double *q = d == 0 ? pu : pv;
        double least = fmin(q[0], fmin(q[1], q[2])), most = fmax(q[0], fmax(q[1], q[2]));
        first[d] = (int)fmax(0, ceil((least - lo[d]) / size[d] - 0.5));
        last[d] = (int)fmin(GRID - 1, floor((most - lo[d]) / size[d] - 0.5));
    }
    for (int j = first[1]; j <= last[1]; j++)
        for (int i = first[0]; i <= last[0]; i++) {
            double x = lo[0] + (i + 0.5) * size[0], y = lo[1] + (j + 0.5) * size[1], w[3];
            bool inside = true;
            for (int k = 0; k < 3; k++) {
                int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
                w[k] = ((pu[k2] - pu[k1]) * (y - pv[k1]) - (x - pu[k1]) * (pv[k2] - pv[k1])) / area;
                /* A little slack, so that a ray along an edge two triangles
                 * share meets one of them. */
                inside = inside && w[k] >= -1e-9;
            }
            if (!inside)
                continue;
            double at = w[0] * pa[0] + w[1] * pa[1] + w[2] * pa[2];
            int cell = j * GRID + i;
            h->least[cell] = fmin(h->least[cell], at);
            h->most[cell] = fmax(h->most[cell], at);
        }
}

/* What the rays from one side find. */
typedef enum side_kind { SIDE_OTHER, SIDE_WALL, SIDE_OPENING } side_kind;

/* Classifies the side of the box at the + end of the axis (plus) or the -
 * end, from the depths its rays reach (as shares of the box's depth). */
static side_kind classify(const axis_hits *h, bool plus, double lo, double hi)
{
    int shallow = 0, deep = 0;
    for (int cell = 0; cell < CELLS; cell++) {
        double depth = plus ? (hi - h->most[cell]) / (hi - lo) : (h->least[cell] - lo) / (hi - lo);
        if (!isfinite(depth))
            continue; /* the ray met nothing */
        shallow += depth <= WALL_DEPTH;
        deep += depth >= DEEP;
    }
    if (shallow * 4 >= CELLS * 3)
        return SIDE_WALL;
    if (shallow * 4 <= CELLS && deep * 2 >= CELLS)
        return SIDE_OPENING;
    return SIDE_OTHER;
}

int model_open_side(const mesh *m)
{
    double extent = fmax(m->hi.x - m->lo.x, fmax(m->hi.y - m->lo.y, m->hi.z - m->lo.z));
    /* A flat model is no room (and its grids would have cells of no size). */
    for (int axis = 0; axis < 3; axis++)
        if (!(coord(m->hi, axis) - coord(m->lo, axis) > 1e-6 * extent))
            return -1;
    int walls = 0, openings = 0, opening = -1;
    for (int axis = 0; axis < 3; axis++) {
        double lo = coord(m->lo, axis), hi = coord(m->hi, axis);
        int u = (axis + 1) % 3, v = (axis + 2) % 3;
        double corner[2] = {coord(m->lo, u), coord(m->lo, v)};
        double size[2] = {(coord(m->hi, u) - corner[0]) / GRID, (coord(m->hi, v) - corner[1]) / GRID};
        axis_hits h;
        for (int cell = 0; cell < CELLS; cell++) {
            h.least[cell] = INFINITY;
            h.most[cell] = -INFINITY;
        }
        for (int t = 0; t < m->triangle_count; t++) {
            const uint32_t *index = m->indices + 3 * (size_t)t;
            const float *p[3] = {m->positions + 3 * (size_t)index[0], m->positions + 3 * (size_t)index[1],
                                 m->positions + 3 * (size_t)index[2]};
            mark_triangle(&h, axis, p, corner, size);
        }
        for (int plus = 0; plus < 2; plus++) {
            side_kind kind = classify(&h, plus, lo, hi);
            walls += kind == SIDE_WALL;
            if (kind == SIDE_OPENING) {
                openings++;
                opening = 2 * axis + plus;
            }
        }
    }
    return walls == 5 && openings == 1 ? opening : -1;
}
