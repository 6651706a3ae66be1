/* camera.c - the list of camera kinds, one line per kind; the calls that go
 * to a camera's kind; and the lens sample and time that callers without
 * those samples pass. */
#include <math.h>
#include <string.h>
#include "core/poses.h"
#include "render/camera_kind.h"

static const camera_kind *const KINDS[] = {
    &pinhole_camera,
    &thin_lens_camera,
    &orthographic_camera,
    &equirectangular_camera,
    &fisheye_camera,
};

#define KIND_COUNT ((int)(sizeof KINDS / sizeof KINDS[0]))

const camera_lens8 camera_lens_centre = {{0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5},
                                         {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5}};
const double camera_shutter_middle[RAY8] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
_Static_assert(RAY8 == 8, "the lanes above are spelled out");

const camera_kind *camera_kind_named(const char *name)
{
    for (int i = 0; i < KIND_COUNT; i++)
        if (strcmp(KINDS[i]->name, name) == 0)
            return KINDS[i];
    return NULL;
}

const camera_kind *camera_kind_for(const glint_camera *desc)
{
    for (int i = 0; i < KIND_COUNT; i++)
        if (KINDS[i]->id == desc->kind)
            return KINDS[i];
    return &pinhole_camera; /* camera_validate lets no other kind through */
}

void camera_frame_init(camera *c, const glint_camera *d, int width, int height)
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
    c->cone_width = 0;
    c->cone_spread = 2 * c->per_y;
}

void camera_init(camera *c, const glint_camera *desc, int width, int height)
{
    c->kind = camera_kind_for(desc);
    c->kind->init(c, desc, width, height);
    c->uses_lens = c->kind->uses_lens;
}

void camera_rays8(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                  const double time[RAY8], ray8 *out)
{
    c->kind->rays8(c, x, y, lens, time, out);
}

void camera_moving_rays8(const camera *poses, int count, const double x[RAY8], const double y[RAY8],
                         const camera_lens8 *lens, const double time[RAY8], ray8 *out)
{
    int pose[RAY8];
    double w[RAY8];
    for (int i = 0; i < RAY8; i++)
        pose_stretch(time[i], count, &pose[i], &w[i]);
    /* Each stretch between two poses that some lane is in: both poses'
     * rays for the packet, blended in the lanes there. */
    for (int k = 0; k < count - 1; k++) {
        bool any = false;
        for (int i = 0; i < RAY8; i++)
            any |= pose[i] == k;
        if (!any)
            continue;
        ray8 a, b;
        camera_rays8(&poses[k], x, y, lens, time, &a);
        camera_rays8(&poses[k + 1], x, y, lens, time, &b);
        for (int i = 0; i < RAY8; i++) {
            if (pose[i] != k)
                continue;
            ray ra = ray8_get(&a, i), rb = ray8_get(&b, i);
            ray blend = {v3_lerp(ra.o, rb.o, w[i]), v3_normalize(v3_lerp(ra.d, rb.d, w[i]))};
            ray8_set(out, i, blend);
        }
    }
}

