/* triangulate.c - ear clipping of polygons in their best-fit plane. */
#include <math.h>
#include <stdlib.h>
#include "core/array.h"
#include "model/triangulate.h"

/* Steps allowed for one polygon, each a corner tried or a point-in-triangle
 * test: enough to clip any of up to about a thousand corners in full, and
 * then a few hundred a corner, which bounds the time a large, noisy or
 * hostile polygon may take. */
#define TESTS_FLOOR (1u << 20)
#define TESTS_PER_CORNER 256

/* Twice the signed area of triangle a b c: positive when counter-clockwise. */
static double area2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static bool same_point(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1];
}

/* Projects the corners on the coordinate plane most nearly parallel to the
 * polygon, oriented so that its winding is counter-clockwise there. False
 * when the Newell normal is zero or not finite. */
static bool project(triangulate_work *w, const float *positions, const uint32_t *corners, size_t n)
{
    double normal[3] = {0, 0, 0};
    for (size_t i = 0; i < n; i++) {
        const float *a = positions + 3 * (size_t)corners[i], *b = positions + 3 * (size_t)corners[(i + 1) % n];
        for (int k = 0; k < 3; k++) {
            int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            normal[k] += ((double)a[k1] - b[k1]) * ((double)a[k2] + b[k2]);
        }
    }
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(normal[k]) > fabs(normal[axis]))
            axis = k;
    if (!(fabs(normal[axis]) > 0) || !isfinite(normal[axis]))
        return false;
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    if (normal[axis] < 0) {
        int t = u;
        u = v;
        v = t;
    }
    for (size_t i = 0; i < n; i++) {
        const float *p = positions + 3 * (size_t)corners[i];
        w->xy[2 * i] = p[u];
        w->xy[2 * i + 1] = p[v];
    }
    return true;
}

/* The ring of corners still to be cut, and the list of its reflex
 * corners (turning the other way, or not at all): only those can lie in
 * an ear's triangle when the polygon is simple, so only those are tested. */
enum { PREV, NEXT, REFLEX_PREV, REFLEX_NEXT };
#define NONE UINT32_MAX

static uint32_t *link_of(const triangulate_work *w, uint32_t i)
{
    return w->link + 4 * (size_t)i;
}

static bool turns_back(const triangulate_work *w, uint32_t i)
{
    const uint32_t *l = link_of(w, i);
    return !(area2(w->xy + 2 * (size_t)l[PREV], w->xy + 2 * (size_t)i, w->xy + 2 * (size_t)l[NEXT]) > 0);
}

/* Puts corner i in or out of the reflex list, as it now turns. */
static void classify(triangulate_work *w, uint32_t *head, uint32_t i)
{
    bool reflex = turns_back(w, i);
    uint32_t *l = link_of(w, i);
    if (reflex == (w->reflex[i] != 0))
        return;
    w->reflex[i] = reflex;
    if (reflex) {
        l[REFLEX_PREV] = NONE;
        l[REFLEX_NEXT] = *head;
        if (*head != NONE)
            link_of(w, *head)[REFLEX_PREV] = i;
        *head = i;
        return;
    }
    if (l[REFLEX_PREV] != NONE)
        link_of(w, l[REFLEX_PREV])[REFLEX_NEXT] = l[REFLEX_NEXT];
    else
        *head = l[REFLEX_NEXT];
    if (l[REFLEX_NEXT] != NONE)
        link_of(w, l[REFLEX_NEXT])[REFLEX_PREV] = l[REFLEX_PREV];
}

/* True when corner i, with its neighbours p and q in the ring, is an ear:
 * convex, with no reflex corner inside or on its triangle (corners at one
 * of its points aside). Counts the tests in *tests. */
static bool is_ear(const triangulate_work *w, uint32_t head, uint32_t p, uint32_t i, uint32_t q, size_t *tests)
{
    const double *a = w->xy + 2 * (size_t)p, *b = w->xy + 2 * (size_t)i, *c = w->xy + 2 * (size_t)q;
    if (!(area2(a, b, c) > 0))
        return false;
    for (uint32_t r = head; r != NONE; r = link_of(w, r)[REFLEX_NEXT]) {
        const double *x = w->xy + 2 * (size_t)r;
        ++*tests;
        if (r == p || r == q || same_point(x, a) || same_point(x, b) || same_point(x, c))
            continue;
        if (area2(a, b, x) >= 0 && area2(b, c, x) >= 0 && area2(c, a, x) >= 0)
            return false;
    }
    return true;
}

static void emit(uint32_t **out, uint32_t a, uint32_t b, uint32_t c)
{
    (*out)[0] = a;
    (*out)[1] = b;
    (*out)[2] = c;
    *out += 3;
}

/* Cuts ears from the ring, starting at corner 1 (so that a convex polygon
 * becomes a fan from corner 0), until three corners are left, no corner is
 * an ear or the budget of tests is spent. Returns the corner where it
 * stopped. */
static uint32_t clip(triangulate_work *w, size_t n, uint32_t **out)
{
    uint32_t head = NONE;
    for (uint32_t i = 0; i < n; i++)
        classify(w, &head, i);
    size_t left = n, misses = 0, tests = 0, budget = TESTS_FLOOR + TESTS_PER_CORNER * n;
    uint32_t i = 1;
    /* Every corner tried is charged, an ear or not: a ring whose ears lie
     * far apart is walked round again and again. */
    while (left > 3 && misses < left && tests++ < budget) {
        uint32_t p = link_of(w, i)[PREV], q = link_of(w, i)[NEXT];
        if (is_ear(w, head, p, i, q, &tests)) {
            emit(out, p, i, q);
            link_of(w, p)[NEXT] = q;
            link_of(w, q)[PREV] = p;
            classify(w, &head, p);
            classify(w, &head, q);
            left--;
            misses = 0;
        } else {
            misses++;
        }
        i = q;
    }
    return i;
}

bool triangulate_polygon(triangulate_work *w, const float *positions, const uint32_t *corners, size_t n,
                         uint32_t *out)
{
    size_t cap = w->cap, flags = w->cap;
    if (n > w->cap && (!array_reserve((void **)&w->xy, &cap, n, 2 * sizeof *w->xy) ||
                       !array_reserve((void **)&w->reflex, &flags, n, 1) ||
                       !array_reserve((void **)&w->link, &w->cap, n, 4 * sizeof *w->link)))
        return false;
    for (size_t i = 0; i < n; i++) {
        uint32_t *l = link_of(w, (uint32_t)i);
        l[PREV] = (uint32_t)((i + n - 1) % n);
        l[NEXT] = (uint32_t)((i + 1) % n);
        w->reflex[i] = 0;
    }
    uint32_t i = n > 3 && project(w, positions, corners, n) ? clip(w, n, &out) : 0;
    /* What is left (all of it when clipping could not start) as a fan. */
    for (uint32_t b = link_of(w, i)[NEXT]; link_of(w, b)[NEXT] != i; b = link_of(w, b)[NEXT])
        emit(&out, i, b, link_of(w, b)[NEXT]);
    return true;
}

void triangulate_free(triangulate_work *w)
{
    free(w->xy);
    free(w->link);
    free(w->reflex);
    *w = (triangulate_work){0};
}
