/* camera.h - the camera the renderer traces through: for each lane of a
 * packet, an image position, a lens sample and a time become a primary
 * ray. What kind of camera makes the rays (a pinhole today; a thin lens for
 * depth of field, a moving one for motion blur) is its camera_kind
 * (camera_kind.h); camera_init takes the kind the scene asks for. */
#ifndef GLINT_RENDER_CAMERA_H
#define GLINT_RENDER_CAMERA_H

#include <stdbool.h>
#include "core/vec.h"

typedef struct camera_kind camera_kind;

/* Where the lanes of a packet pass the lens: lane i at (u[i], v[i]), each
 * in [0, 1), the lens's centre at (0.5, 0.5). */
typedef struct camera_lens8 {
    double u[RAY8], v[RAY8];
} camera_lens8;

/* A camera set up for one image: its kind, and the values its kind's
 * init derives from the scene's camera (a kind with more, such as a thin
 * lens's aperture and focal distance, adds them here). */
typedef struct camera {
    const camera_kind *kind;
    bool uses_lens;                      /* its kind's rays depend on the lens sample */
    vec3 position, forward, right, up;   /* orthonormal frame */
    int width, height;
    /* Half the image plane's width (at distance 1) over the image width,
     * and likewise its height: a pixel is twice these across. */
    double per_x, per_y;
    /* How wide a pixel's footprint is at distance t along a ray, for
     * texture filtering: cone_width + cone_spread t (a pixel's width on the
     * image plane, or its angle). */
    double cone_width, cone_spread;
    double lens_radius, focus_distance;  /* a thin lens's */
    int blades;                          /* a thin lens's: 0 round, else a regular polygon */
} camera;

/* Sets c up, as the kind the scene's camera asks for (camera_kind_for),
 * for an image of width x height pixels; desc must have passed
 * camera_validate. */
void camera_init(camera *c, const glint_camera *desc, int width, int height);

/* The unit-direction rays of a packet's RAY8 lanes, into the lanes of
 * *out. Lane i's ray goes through image position (x[i], y[i]) in pixels,
 * where (0, 0) is the top-left corner of the image and (width, height) the
 * bottom-right; it passes the lens at lane i of *lens, at time[i] in the
 * shutter's interval, [0, 1). */
void camera_rays8(const camera *c, const double x[RAY8], const double y[RAY8], const camera_lens8 *lens,
                  const double time[RAY8], ray8 *out);

/* The most poses a moving camera takes over the shutter. */
#define CAMERA_MAX_POSES 64

/* camera_rays8 for a camera moving through `count` poses (2 or more),
 * evenly spaced over the shutter: lane i's ray goes in a straight line
 * from its ray through the pose before time[i] to its ray through the one
 * after (the origin blended, the direction blended and made unit). */
void camera_moving_rays8(const camera *poses, int count, const double x[RAY8], const double y[RAY8],
                         const camera_lens8 *lens, const double time[RAY8], ray8 *out);

/* The lens's centre and the shutter's middle in every lane: what a caller
 * that samples neither passes to camera_rays8. */
extern const camera_lens8 camera_lens_centre;
extern const double camera_shutter_middle[RAY8];

#endif
