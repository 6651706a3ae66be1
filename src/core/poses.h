/* poses.h - where a moving thing is between its poses: `count` of them
 * evenly spaced over the shutter, time 0 at the first and 1 at the last,
 * a straight line from each to the next (shapes, lights, the camera). */
#ifndef GLINT_CORE_POSES_H
#define GLINT_CORE_POSES_H

/* For `time` in [0, 1]: *k, the pose before it (0 to count - 2), and *w,
 * how far it is towards the next, in [0, 1]. */
static inline void pose_stretch(double time, int count, int *k, double *w)
{
    double at = time * (count - 1);
    *k = at >= count - 1 ? count - 2 : at > 0 ? (int)at : 0;
    *w = at - *k;
}

#endif
