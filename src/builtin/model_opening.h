/* model_opening.h - finding the open side of a model that is a room open
 * on one side (a Cornell box), for the model view to look in through. */
#ifndef GLINT_BUILTIN_MODEL_OPENING_H
#define GLINT_BUILTIN_MODEL_OPENING_H

#include "geometry/mesh.h"

/* The side of m's bounding box that is the opening of a room, as
 * 2 * axis + (1 for the + side, 0 for the - side): 0 is -x, 5 is +z; or -1
 * when m is no such room. Rays go straight in from each side, on a grid
 * over the side's face: a side is a wall when at least 75% of them meet a
 * triangle within 5% of the box's depth, and the opening when at most 25%
 * do and at least half reach past half the depth. m is a room when exactly
 * one side is the opening and the other five are walls. */
int model_open_side(const mesh *m);

#endif
