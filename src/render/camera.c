/* camera.c - pinhole projection. */
#include <math.h>
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

ray camera_ray(const camera *c, double x, double y)
{
    ray r;
    camera_rays(c, 1, &x, &y, &r);
    return r;
}

void camera_rays(const camera *c, int count, const double *x, const double *y, ray *out)
{
    /* No division but the normalisation's, and the image centre and every
     * pixel edge there map exactly onto the view axis. A few rays at a time
     * go through arrays the compiler can turn into vectors. */
    enum { CHUNK = 8 };
    vec3 f = c->forward, r = c->right, u = c->up;
    for (int base = 0; base < count; base += CHUNK) {
        int m = count - base < CHUNK ? count - base : CHUNK;
        double dx[CHUNK], dy[CHUNK], dz[CHUNK], inv[CHUNK];
        for (int i = 0; i < m; i++) {
            double sx = (2 * x[base + i] - c->width) * c->per_x;
            double sy = (c->height - 2 * y[base + i]) * c->per_y;
            dx[i] = f.x + (r.x * sx + u.x * sy);
            dy[i] = f.y + (r.y * sx + u.y * sy);
            dz[i] = f.z + (r.z * sx + u.z * sy);
            double l = sqrt(dx[i] * dx[i] + dy[i] * dy[i] + dz[i] * dz[i]);
            inv[i] = l > 0 ? 1.0 / l : 1.0;
        }
        for (int i = 0; i < m; i++) {
            out[base + i].o = c->position;
            out[base + i].d = v3(dx[i] * inv[i], dy[i] * inv[i], dz[i] * inv[i]);
        }
    }
}
