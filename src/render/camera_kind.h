/* camera_kind.h - one record per kind of camera, and the registry that
 * lists them.
 *
 * A kind is one file (pinhole_camera.c, ...) that exports one camera_kind:
 * its name and its two operations. Adding a kind: write its file, add a
 * line to camera.c's list, and have camera_kind_for choose it from the
 * scene's camera (glint_camera, in the public API, names no kind yet). */
#ifndef GLINT_RENDER_CAMERA_KIND_H
#define GLINT_RENDER_CAMERA_KIND_H

#include "render/camera.h"

struct camera_kind {
    const char *name;
    /* Fills c's values (all but c->kind) from the scene's camera, which
     * has passed camera_validate, for an image of width x height pixels. */
    void (*init)(camera *c, const glint_camera *desc, int width, int height);
    /* camera_rays8: called for every packet of camera rays, so it works
     * on the lanes side by side. */
    void (*rays8)(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                  const double time[RAY8], ray8 *out);
};

/* A pinhole: every ray starts at the camera's position; the lens sample
 * and the time are ignored. */
extern const camera_kind pinhole_camera;

/* The kind with that name, or NULL. */
const camera_kind *camera_kind_named(const char *name);

/* The kind the scene's camera asks for: always the pinhole, until
 * glint_camera names a kind. */
const camera_kind *camera_kind_for(const glint_camera *desc);

#endif
