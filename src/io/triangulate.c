/* triangulate.c - ear clipping of polygons in their best-fit plane. */
#include <math.h>
#include <stdlib.h>
#include "core/array.h"
#include "io/triangulate.h"

/* Point-in-triangle tests allowed per corner beyond a floor that lets
 * every polygon of a few hundred corners be clipped in full. */
#define TESTS_PER_CORNER 1024
#define TESTS_FLOOR 65536

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

/* True when corner i, with its neighbours p and q in the ring, is an ear:
 * convex, with no other corner of the ring inside or on its triangle
 * (corners at one of its points aside). Counts the tests in *tests. */
static bool is_ear(const triangulate_work *w, uint32_t p, uint32_t i, uint32_t q, size_t *tests)
{
    const double *a = w->xy + 2 * (size_t)p, *b = w->xy + 2 * (size_t)i, *c = w->xy + 2 * (size_t)q;
    if (!(area2(a, b, c) > 0))
        return false;
    for (uint32_t r = w->link[2 * q + 1]; r != p; r = w->link[2 * r + 1]) {
        const double *x = w->xy + 2 * (size_t)r;
        ++*tests;
        if (same_point(x, a) || same_point(x, b) || same_point(x, c))
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

bool triangulate_polygon(triangulate_work *w, const float *positions, const uint32_t *corners, size_t n,
                         uint32_t *out)
{
    size_t cap = w->cap;
    if (n > w->cap && (!array_reserve((void **)&w->xy, &cap, n, 2 * sizeof *w->xy) ||
                       !array_reserve((void **)&w->link, &w->cap, n, 2 * sizeof *w->link)))
        return false;
    for (size_t i = 0; i < n; i++) {
        w->link[2 * i] = (uint32_t)((i + n - 1) % n);
        w->link[2 * i + 1] = (uint32_t)((i + 1) % n);
    }
    size_t left = n, misses = 0, tests = 0, budget = TESTS_FLOOR + TESTS_PER_CORNER * n;
    /* Starting at corner 1 makes a convex polygon a fan from corner 0. */
    uint32_t i = 1;
    if (n > 3 && project(w, positions, corners, n)) {
        while (left > 3 && misses < left && tests < budget) {
            uint32_t p = w->link[2 * i], q = w->link[2 * i + 1];
            if (is_ear(w, p, i, q, &tests)) {
                emit(&out, p, i, q);
                w->link[2 * p + 1] = q;
                w->link[2 * q] = p;
                left--;
                misses = 0;
            } else {
                misses++;
            }
            i = q;
        }
    } else {
        i = 0;
    }
    /* What is left (all of it when clipping could not start) as a fan. */
    for (uint32_t b = w->link[2 * i + 1]; w->link[2 * b + 1] != i; b = w->link[2 * b + 1])
        emit(&out, i, b, w->link[2 * b + 1]);
    return true;
}

void triangulate_free(triangulate_work *w)
{
    free(w->xy);
    free(w->link);
    *w = (triangulate_work){0};
}
