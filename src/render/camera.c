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
    /* No division (this runs for every camera ray), and the image centre
     * and every pixel edge there map exactly onto the view axis. */
    double sx = (2 * x - c->width) * c->per_x;
    double sy = (c->height - 2 * y) * c->per_y;
    vec3 d = v3_add(c->forward, v3_add(v3_scale(c->right, sx), v3_scale(c->up, sy)));
    ray r = {c->position, v3_normalize(d)};
    return r;
}
