/* fisheye_camera.c - the equidistant fisheye: a ray's angle from the view
 * direction grows evenly with its image position's distance from the
 * image's centre, reaching fov / 2 at the middle of the left and right
 * edges (fov up to 360 degrees: at 180 the edges look sideways, beyond it
 * behind), around the view direction as the position is around the
 * centre. Every pixel sees something: the frame is filled, not a circle.
 * It ignores the lens sample and the time. */
#include <math.h>
#include "render/camera_kind.h"

static void fisheye_init(camera *c, const glint_camera *d, int width, int height)
{
    camera_frame_init(c, d, width, height);
    /* The angle a pixel spans, in radians. */
    c->per_x = c->per_y = d->vfov_degrees * M_PI / 180 / width;
    c->cone_spread = c->per_x;
}

static void fisheye_rays8(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                          const double time[RAY8], ray8 *out)
{
    (void)lens;
    (void)time;
    for (int i = 0; i < RAY8; i++) {
        double across = x[i] - 0.5 * c->width, upward = 0.5 * c->height - y[i];
        double r = sqrt(across * across + upward * upward), angle = r * c->per_x;
        vec3 d = c->forward;
        if (r > 0) {
            vec3 side = v3_add(v3_scale(c->right, across / r), v3_scale(c->up, upward / r));
            d = v3_add(v3_scale(c->forward, cos(angle)), v3_scale(side, sin(angle)));
        }
        camera_ray_put(out, i, c->position, d);
    }
}

const camera_kind fisheye_camera = {
    .name = "fisheye",
    .id = GLINT_CAMERA_FISHEYE,
    .init = fisheye_init,
    .rays8 = fisheye_rays8,
};
