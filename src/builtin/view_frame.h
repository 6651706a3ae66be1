/* view_frame.h - placing a camera so that a box fills a share of the
 * picture, for the model view. */
#ifndef GLINT_BUILTIN_VIEW_FRAME_H
#define GLINT_BUILTIN_VIEW_FRAME_H

#include "core/vec.h"

/* The pinhole camera looking along `forward` (any length), with `up` (not
 * along forward) up in the picture and a vertical field of view of vfov
 * degrees, for a picture `aspect` (width / height) wide, placed so that the
 * 8 corners of the box [lo, hi], projected, are centred in the picture and
 * span `share` (in (0, 1]) of its width or of its height, whichever limits.
 * It looks at the box's centre's depth. */
glint_camera view_frame_box(vec3 lo, vec3 hi, vec3 forward, vec3 up, double vfov, double aspect, double share);

#endif
