/* orthographic_camera.c - the orthographic camera: parallel rays along the
 * view direction, each starting where its image position falls on a
 * rectangle view_width across, centred on the camera's position: no
 * perspective, as for plans and elevations. view_width 0 takes the width
 * the pinhole's view has at look_at's distance, so that changing only the
 * type keeps the subject framed. It ignores the lens sample and the time. */
#include <math.h>
#include "render/camera_kind.h"

static void orthographic_init(camera *c, const glint_camera *d, int width, int height)
{
    camera_frame_init(c, d, width, height);
    double view_width = d->view_width > 0 ? d->view_width
                                          : 2 * c->per_x * width * v3_length(v3_sub(d->look_at, d->position));
    /* Half the view's width over the image width: a pixel is twice this across, as for per_x. */
    c->per_x = c->per_y = view_width / 2 / width;
    c->cone_width = view_width / width;
    c->cone_spread = 0;
}

static void orthographic_rays8(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                               const double time[RAY8], ray8 *out)
{
    (void)lens;
    (void)time;
    for (int i = 0; i < RAY8; i++) {
        double across = (2 * x[i] - c->width) * c->per_x, upward = (c->height - 2 * y[i]) * c->per_y;
        vec3 from = v3_add(c->position, v3_add(v3_scale(c->right, across), v3_scale(c->up, upward)));
        camera_ray_put(out, i, from, c->forward);
    }
}

const camera_kind orthographic_camera = {
    .name = "orthographic",
    .id = GLINT_CAMERA_ORTHOGRAPHIC,
    .init = orthographic_init,
    .rays8 = orthographic_rays8,
};
