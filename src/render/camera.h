/* camera.h - the pinhole camera: pixel positions to primary rays. */
#ifndef GLINT_RENDER_CAMERA_H
#define GLINT_RENDER_CAMERA_H

#include "core/vec.h"

typedef struct camera {
    vec3 position, forward, right, up;   /* orthonormal frame */
    int width, height;
    /* Half the image plane's width (at distance 1) over the image width,
     * and likewise its height: a pixel is twice these across. */
    double per_x, per_y;
} camera;

/* Sets up the frame for an image of width x height pixels; the camera must
 * have passed camera_validate. */
void camera_init(camera *c, const glint_camera *desc, int width, int height);

/* The unit-direction ray through image position (x, y) in pixels, where
 * (0, 0) is the top-left corner of the image and (width, height) the
 * bottom-right. */
ray camera_ray(const camera *c, double x, double y);

/* camera_ray for the image positions (x[i], y[i]) of a packet's RAY8
 * lanes, into lane i of *out, with exactly its results; the lanes are
 * computed side by side, as vectors where the compiler can. */
void camera_rays8(const camera *c, const double x[RAY8], const double y[RAY8], ray8 *out);

#endif
