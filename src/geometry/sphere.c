/* sphere.c - spheres in object space: centre and radius. */
#include "geometry/kinds.h"

glint_status sphere_init(shape *s, glint_error *err)
{
    const glint_shape *d = &s->desc;
    bool ok = finite_ok(d->center, "sphere", "centre", err) && positive_ok(d->radius, "sphere", "radius", err);
    return ok ? GLINT_OK : GLINT_ERR_INVALID;
}

bool sphere_intersect(const shape *s, const ray *r, double tmin, double tmax, shape_hit *hit)
{
    const glint_shape *d = &s->desc;
    vec3 oc = v3_sub(r->o, d->center);
    double t0, t1;
    if (!quadratic(v3_dot(r->d, r->d), 2 * v3_dot(oc, r->d), v3_dot(oc, oc) - d->radius * d->radius, &t0, &t1))
        return false;
    shape_hit best = {tmax, 0};
    hit_offer(&best, tmin, t0, 0);
    hit_offer(&best, tmin, t1, 0);
    return hit_take(&best, tmax, hit);
}

/* u is the longitude (0.5 at +z, seam at -z), v runs from 0 at the north
 * (+y) pole to 1 at the south pole. */
void sphere_surface(const shape *s, int part, surface *out)
{
    out->n = v3_sub(out->p_obj, s->desc.center);
}

void sphere_uv(const shape *s, int part, surface *out)
{
    vec3 n = v3_normalize(v3_sub(out->p_obj, s->desc.center));
    out->u = polar_u(n.x, n.z);
    /* Rounding can push |n.y| a hair past 1, where asin is NaN. */
    out->v = 0.5 - asin(fmax(-1.0, fmin(1.0, n.y))) / M_PI;
}

void sphere_bounds(const shape *s, vec3 *lo, vec3 *hi)
{
    const glint_shape *d = &s->desc;
    *lo = v3_sub(d->center, v3(d->radius, d->radius, d->radius));
    *hi = v3_add(d->center, v3(d->radius, d->radius, d->radius));
}
