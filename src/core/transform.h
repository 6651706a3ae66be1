/* transform.h - affine transforms: composing, inverting, mapping points,
 * directions and normals between object and world space. */
#ifndef GLINT_CORE_TRANSFORM_H
#define GLINT_CORE_TRANSFORM_H

#include <stdbool.h>
#include "core/vec.h"

typedef glint_transform transform;

/* Returns a * b: b is applied first. */
transform xf_mul(const transform *a, const transform *b);

/* Inverts t into *inv; false when t is singular or not finite. */
bool xf_invert(const transform *t, transform *inv);

/* The transform `count` poses (evenly spaced over time [0, 1]) give at
 * `time`, each number blended in a straight line between the poses about
 * it, into *to_world, and its inverse into *to_object; where the blend is
 * not invertible, the nearer pose. */
void xf_between(const transform *poses, int count, double time, transform *to_world, transform *to_object);

/* True when t is the identity exactly. */
bool xf_is_identity(const transform *t);

static inline vec3 xf_point(const transform *t, vec3 p)
{
    const double (*m)[4] = t->m;
    return v3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
              m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
              m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

static inline vec3 xf_vector(const transform *t, vec3 v)
{
    const double (*m)[4] = t->m;
    return v3(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
              m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
              m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
}

/* Maps an object-space normal to world space given the INVERSE transform
 * (normals go by the inverse transpose); the result is not normalised. */
static inline vec3 xf_normal(const transform *inv, vec3 n)
{
    const double (*m)[4] = inv->m;
    return v3(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z,
              m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
              m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z);
}

#endif
