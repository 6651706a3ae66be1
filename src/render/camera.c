/* camera.c - the list of camera kinds, one line per kind, and the calls
 * that go to a camera's kind. */
#include <string.h>
#include "render/camera_kind.h"

static const camera_kind *const KINDS[] = {
    &pinhole_camera,
};

#define KIND_COUNT ((int)(sizeof KINDS / sizeof KINDS[0]))

const camera_kind *camera_kind_named(const char *name)
{
    for (int i = 0; i < KIND_COUNT; i++)
        if (strcmp(KINDS[i]->name, name) == 0)
            return KINDS[i];
    return NULL;
}

const camera_kind *camera_kind_for(const glint_camera *desc)
{
    (void)desc;
    return camera_kind_named("pinhole");
}

void camera_init(camera *c, const glint_camera *desc, int width, int height)
{
    c->kind = camera_kind_for(desc);
    c->kind->init(c, desc, width, height);
}

void camera_rays8(const camera *c, const camera_sample8 *s, ray8 *out)
{
    c->kind->rays8(c, s, out);
}
