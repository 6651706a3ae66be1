/* camera.c - pinhole projection. */
#include <math.h>
#include "core/lanes.h"
#include "render/camera.h"

void camera_init(camera *c, const glint_camera *d, int width, int height)
{
    c->position = d->position;
    c->forward = v3_normalize(v3_sub(d->look_at, d->position));
    c->right = v3_normalize(v3_cross(c->forward, d->up));
    c->up = v3_cross(c->right, c->forward);
    double half_height = tan(d->vfov_degrees * M_PI / 360.0);
    c->width = width;
    c->height = height;
    c->per_x = half_height * width / height / width;
    c->per_y = half_height / height;
}

/* The unit direction through image position (x, y): no division but the
 * normalisation's, and the image centre and every pixel edge there map
 * exactly onto the view axis. */
static inline void direction(const camera *c, double x, double y, double *dx, double *dy, double *dz)
{
    vec3 f = c->forward, r = c->right, u = c->up;
    double sx = (2 * x - c->width) * c->per_x;
    double sy = (c->height - 2 * y) * c->per_y;
    double ex = f.x + (r.x * sx + u.x * sy);
    double ey = f.y + (r.y * sx + u.y * sy);
    double ez = f.z + (r.z * sx + u.z * sy);
    double l = sqrt(ex * ex + ey * ey + ez * ez);
    double inv = l > 0 ? 1.0 / l : 1.0;
    *dx = ex * inv;
    *dy = ey * inv;
    *dz = ez * inv;
}

ray camera_ray(const camera *c, double x, double y)
{
    ray r = {c->position, {0, 0, 0}};
    direction(c, x, y, &r.d.x, &r.d.y, &r.d.z);
    return r;
}

void camera_rays8(const camera *c, const double x[RAY8], const double y[RAY8], ray8 *out)
{
    /* direction() on four lanes at once, in its order of operations */
    vec3 f = c->forward, r = c->right, u = c->up;
    for (int i = 0; i < RAY8; i += QUAD) {
        quad sx = (quad_splat(2) * quad_load(x + i) - quad_splat(c->width)) * quad_splat(c->per_x);
        quad sy = (quad_splat(c->height) - quad_splat(2) * quad_load(y + i)) * quad_splat(c->per_y);
        quad ex = quad_splat(f.x) + (quad_splat(r.x) * sx + quad_splat(u.x) * sy);
        quad ey = quad_splat(f.y) + (quad_splat(r.y) * sx + quad_splat(u.y) * sy);
        quad ez = quad_splat(f.z) + (quad_splat(r.z) * sx + quad_splat(u.z) * sy);
        quad l = quad_sqrt(ex * ex + ey * ey + ez * ez);
        quad inv = quad_select(l > 0, quad_splat(1) / l, quad_splat(1));
        quad_store(out->dx + i, ex * inv);
        quad_store(out->dy + i, ey * inv);
        quad_store(out->dz + i, ez * inv);
        quad_store(out->ox + i, quad_splat(c->position.x));
        quad_store(out->oy + i, quad_splat(c->position.y));
        quad_store(out->oz + i, quad_splat(c->position.z));
    }
}
