/* camera.h - the camera the renderer traces through: for each lane of a
 * packet, an image position, a lens sample and a time become a primary
 * ray. What kind of camera makes the rays (a pinhole today; a thin lens for
 * depth of field, a moving one for motion blur) is its camera_kind
 * (camera_kind.h); camera_init takes the kind the scene asks for. */
#ifndef GLINT_RENDER_CAMERA_H
#define GLINT_RENDER_CAMERA_H

#include "core/vec.h"

typedef struct camera_kind camera_kind;

/* What a camera is asked for the RAY8 lanes of a packet. */
typedef struct camera_sample8 {
    /* Image positions in pixels: (0, 0) is the top-left corner of the
     * image and (width, height) the bottom-right. */
    double x[RAY8], y[RAY8];
    /* Where on the lens, each in [0, 1) (the lens's centre at 0.5, 0.5). */
    double lens_u[RAY8], lens_v[RAY8];
    /* When in the shutter's interval, in [0, 1). */
    double time[RAY8];
} camera_sample8;

/* A camera set up for one image: its kind, and the values its kind's
 * init derives from the scene's camera (a kind with more, such as a thin
 * lens's aperture and focal distance, adds them here). */
typedef struct camera {
    const camera_kind *kind;
    vec3 position, forward, right, up;   /* orthonormal frame */
    int width, height;
    /* Half the image plane's width (at distance 1) over the image width,
     * and likewise its height: a pixel is twice these across. */
    double per_x, per_y;
} camera;

/* Sets c up, as the kind the scene's camera asks for (camera_kind_for),
 * for an image of width x height pixels; desc must have passed
 * camera_validate. */
void camera_init(camera *c, const glint_camera *desc, int width, int height);

/* The unit-direction rays for the lanes of *s, into the lanes of *out. */
void camera_rays8(const camera *c, const camera_sample8 *s, ray8 *out);

#endif
