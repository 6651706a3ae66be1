/* first_crossing.h - whether a point is inside a combination, as the
 * renderer sees it: the first crossing of its surface along a ray from the
 * point leaves the solid (test_csg.c, test_mesh_part.c check it against the
 * analytic sets on grids of points). */
#ifndef GLINT_TESTS_FIRST_CROSSING_H
#define GLINT_TESTS_FIRST_CROSSING_H

#include <math.h>
#include "scene/scene.h"

/* Whether the first crossing of shape `top` of s along d from p goes out
 * of it (false when the ray meets it nowhere). */
static inline bool first_crossing_leaves(const glint_scene *s, int top, vec3 p, vec3 d)
{
    ray r = {p, d};
    shape_hit h;
    if (!shape_intersect(&s->shapes[top], &r, 0, INFINITY, &h))
        return false;
    surface sf;
    shape_surface(&s->shapes[h.leaf], &r, &h, &sf);
    return v3_dot(sf.n, d) > 0;
}

#endif
