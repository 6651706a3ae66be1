/* pinhole_camera.c - the pinhole camera: every ray starts at the camera's
 * position and passes through its image position on an image plane at
 * distance 1 along the view direction, spanning the vertical field of
 * view. It ignores the lens sample and the time. */
#include <math.h>
#include "core/lanes.h"
#include "render/camera_kind.h"

static void pinhole_init(camera *c, const glint_camera *d, int width, int height)
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

/* The unit directions through the image positions (x[k], y[k]) of four
 * rays: no division but the normalisation's, and the image centre and every
 * pixel edge there map exactly onto the view axis. Each lane is what the
 * same steps in scalar code would give. */
static inline void directions(const camera *c, quad_f64 x, quad_f64 y, quad_f64 *dx, quad_f64 *dy, quad_f64 *dz)
{
    vec3 f = c->forward, r = c->right, u = c->up;
    quad_f64 sx = (quad_splat(2) * x - quad_splat(c->width)) * quad_splat(c->per_x);
    quad_f64 sy = (quad_splat(c->height) - quad_splat(2) * y) * quad_splat(c->per_y);
    quad_f64 ex = quad_splat(f.x) + (quad_splat(r.x) * sx + quad_splat(u.x) * sy);
    quad_f64 ey = quad_splat(f.y) + (quad_splat(r.y) * sx + quad_splat(u.y) * sy);
    quad_f64 ez = quad_splat(f.z) + (quad_splat(r.z) * sx + quad_splat(u.z) * sy);
    quad_f64 l = quad_sqrt(ex * ex + ey * ey + ez * ez);
    quad_f64 inv = quad_select(l > 0, quad_splat(1) / l, quad_splat(1));
    *dx = ex * inv;
    *dy = ey * inv;
    *dz = ez * inv;
}

static void pinhole_rays8(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                          const double time[RAY8], ray8 *out)
{
    for (int i = 0; i < RAY8; i += QUAD) {
        quad_f64 dx, dy, dz;
        directions(c, quad_load(x + i), quad_load(y + i), &dx, &dy, &dz);
        quad_store(out->dx + i, dx);
        quad_store(out->dy + i, dy);
        quad_store(out->dz + i, dz);
        quad_store(out->ox + i, quad_splat(c->position.x));
        quad_store(out->oy + i, quad_splat(c->position.y));
        quad_store(out->oz + i, quad_splat(c->position.z));
    }
}

const camera_kind pinhole_camera = {
    .name = "pinhole",
    .init = pinhole_init,
    .rays8 = pinhole_rays8,
};
