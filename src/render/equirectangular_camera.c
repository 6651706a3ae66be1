/* equirectangular_camera.c - the 360-degree panorama: every direction from
 * the camera's position, longitude across the image (the view direction in
 * its middle, behind the camera at both edges, right to the right) and
 * latitude down it (up at the top row, down at the bottom), as
 * environment maps are stored. The field of view is unused. It ignores the
 * lens sample and the time. */
#include <math.h>
#include "render/camera_kind.h"

static void equirectangular_init(camera *c, const glint_camera *d, int width, int height)
{
    camera_frame_init(c, d, width, height);
    c->cone_spread = 2 * M_PI / width; /* a pixel's angle of longitude */
}

static void equirectangular_rays8(const camera *c, const double x[RAY8], const double y[RAY8],
                                  const camera_lens8 *lens, const double time[RAY8], ray8 *out)
{
    (void)lens;
    (void)time;
    for (int i = 0; i < RAY8; i++) {
        double longitude = 2 * M_PI * (x[i] / c->width - 0.5), latitude = M_PI * (0.5 - y[i] / c->height);
        vec3 level = v3_add(v3_scale(c->forward, cos(longitude)), v3_scale(c->right, sin(longitude)));
        vec3 d = v3_add(v3_scale(level, cos(latitude)), v3_scale(c->up, sin(latitude)));
        camera_ray_put(out, i, c->position, d);
    }
}

const camera_kind equirectangular_camera = {
    .name = "equirectangular",
    .id = GLINT_CAMERA_EQUIRECTANGULAR,
    .init = equirectangular_init,
    .rays8 = equirectangular_rays8,
};
