/* pinhole_camera.c - the pinhole camera: every ray starts at the camera's
 * position and passes through its image position on an image plane at
 * distance 1 along the view direction, spanning the vertical field of
 * view. It ignores the lens sample and the time. */
#include "render/camera_kind.h"

static void pinhole_rays8(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                          const double time[RAY8], ray8 *out)
{
    for (int i = 0; i < RAY8; i += QUAD) {
        quad_f64 dx, dy, dz;
        camera_plane_directions(c, quad_load(x + i), quad_load(y + i), &dx, &dy, &dz);
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
    .id = GLINT_CAMERA_PINHOLE,
    .init = camera_frame_init,
    .rays8 = pinhole_rays8,
};
