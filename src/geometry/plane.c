/* plane.c - infinite planes in object space: a point and a normal. */
#include "geometry/kinds.h"

glint_status plane_init(shape *s, glint_error *err)
{
    glint_shape *d = &s->desc;
    if (!finite_ok(d->center, "plane", "point", err) || !finite_ok(d->normal, "plane", "normal", err))
        return GLINT_ERR_INVALID;
    vec3 n = d->normal;
    /* Dividing by the largest component first keeps tiny and huge normals
     * from underflowing or overflowing when squared. */
    double m = fmax(fabs(n.x), fmax(fabs(n.y), fabs(n.z)));
    if (m == 0)
        return error_set(err, GLINT_ERR_INVALID, "plane normal must not be zero");
    /* Kept in desc so every later use sees a unit normal. */
    d->normal = v3_normalize(v3(n.x / m, n.y / m, n.z / m));
    plane_basis(d->normal, &s->plane_u, &s->plane_v);
    return GLINT_OK;
}

void plane_basis(vec3 n, vec3 *u, vec3 *v)
{
    /* Walls measure u from up; floors from -z, which makes their u +x.
     * Either reference is at least 45 degrees from n, so the cross product
     * stays well conditioned. */
    vec3 ref = n.y * n.y > 0.5 ? v3(0, 0, -1) : v3(0, 1, 0);
    *u = v3_normalize(v3_cross(ref, n));
    *v = v3_cross(*u, n);
}

bool plane_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    double t;
    if (!plane_hit(s->desc.center, s->desc.normal, r, tmin, tmax, &t))
        return false;
    hit->t = t;
    hit->part = 0;
    return true;
}

/* u and v are distances from the plane's point along plane_u and plane_v. */
void plane_surface(const shape *s, int part, surface *out)
{
    out->n = s->desc.normal;
}

void plane_uv(const shape *s, int part, surface *out)
{
    vec3 q = v3_sub(out->p_obj, s->desc.center);
    out->u = v3_dot(q, s->plane_u);
    out->v = v3_dot(q, s->plane_v);
}
