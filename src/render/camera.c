/* camera.c - pinhole projection. */
#include <math.h>
#include "render/camera.h"

void camera_init(camera *c, const glint_camera *d, int width, int height)
{
    c->position = d->position;
    c->forward = v3_normalize(v3_sub(d->look_at, d->position));
    c->right = v3_normalize(v3_cross(c->forward, d->up));
    c->up = v3_cross(c->right, c->forward);
    c->half_height = tan(d->vfov_degrees * M_PI / 360.0);
    c->half_width = c->half_height * width / height;
    c->width = width;
    c->height = height;
}

ray camera_ray(const camera *c, double x, double y)
{
    double sx = (2.0 * x / c->width - 1.0) * c->half_width;
    double sy = (1.0 - 2.0 * y / c->height) * c->half_height;
    vec3 d = v3_add(c->forward, v3_add(v3_scale(c->right, sx), v3_scale(c->up, sy)));
    ray r = {c->position, v3_normalize(d)};
    return r;
}
