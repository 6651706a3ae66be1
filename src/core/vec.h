/* vec.h - 3-vectors in double precision: the arithmetic every module shares. */
#ifndef GLINT_CORE_VEC_H
#define GLINT_CORE_VEC_H

#include <math.h>
#include "glint.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef glint_vec3 vec3;

/* A ray: origin o, direction d (not necessarily unit length). */
typedef struct ray {
    vec3 o, d;
} ray;

static inline vec3 v3(double x, double y, double z) { vec3 v = {x, y, z}; return v; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_scale(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_neg(vec3 a) { return v3(-a.x, -a.y, -a.z); }
static inline double v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double v3_length(vec3 a) { return sqrt(v3_dot(a, a)); }
static inline vec3 v3_normalize(vec3 a)
{
    double l = v3_length(a);
    return l > 0 ? v3_scale(a, 1.0 / l) : a;
}
/* The point a fraction t of the way from a to b: a + (b - a) t. */
static inline vec3 v3_lerp(vec3 a, vec3 b, double t)
{
    return v3(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
}
/* a + b * s, the step along a ray. */
static inline vec3 v3_madd(vec3 a, vec3 b, double s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
static inline vec3 ray_at(const ray *r, double t) { return v3_madd(r->o, r->d, t); }
static inline int v3_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

/* Unit vectors u and v that make an orthonormal frame with unit vector n.
 * It is the one frame glint builds about a direction: the texture axes of
 * planes and box faces, and the frame in which a sphere light's cone, a
 * rough surface's lobe and ambient occlusion's hemisphere are sampled. As
 * texture axes, seen from the side n points to, u runs right and v runs
 * down, as in an image. Planes more than 45 degrees from horizontal are
 * walls: u is horizontal, and v is -y on a vertical wall. The rest are
 * floors and ceilings: u is +x on a floor, -x on a ceiling, and v is +z on
 * both. */
static inline void plane_basis(vec3 n, vec3 *u, vec3 *v)
{
    /* Walls measure u from up; floors from -z, which makes their u +x.
     * Either reference is at least 45 degrees from n, so the cross product
     * stays well conditioned. */
    vec3 ref = n.y * n.y > 0.5 ? v3(0, 0, -1) : v3(0, 1, 0);
    *u = v3_normalize(v3_cross(ref, n));
    *v = v3_cross(*u, n);
}

/* Rays side by side in a packet. */
#define RAY8 8

/* RAY8 rays as a structure of arrays: lane i has origin (ox[i], oy[i],
 * oz[i]) and direction (dx[i], dy[i], dz[i]), so that a loop over the lanes
 * can be one vector operation per step. */
typedef struct ray8 {
    double ox[RAY8], oy[RAY8], oz[RAY8];
    double dx[RAY8], dy[RAY8], dz[RAY8];
} ray8;

/* Lane i of a packet as a ray. */
static inline ray ray8_get(const ray8 *p, int i)
{
    ray r = {{p->ox[i], p->oy[i], p->oz[i]}, {p->dx[i], p->dy[i], p->dz[i]}};
    return r;
}

/* Lane i's direction. */
static inline vec3 ray8_dir(const ray8 *p, int i) { return v3(p->dx[i], p->dy[i], p->dz[i]); }

/* Stores r in lane i of a packet. */
static inline void ray8_set(ray8 *p, int i, ray r)
{
    p->ox[i] = r.o.x;
    p->oy[i] = r.o.y;
    p->oz[i] = r.o.z;
    p->dx[i] = r.d.x;
    p->dy[i] = r.d.y;
    p->dz[i] = r.d.z;
}

#endif
