/* corner_angle.h - the angle of a triangle's corner from its edges' cross
 * product length and dot product, as the float that (float)atan2 gives,
 * in about a third of atan2's instructions: generated normals weigh every
 * face by its angle at every corner, and atan2 was a sixth of loading a
 * large model. */
#ifndef GLINT_MODEL_CORNER_ANGLE_H
#define GLINT_MODEL_CORNER_ANGLE_H

/* (float)atan2(cross, dot) for finite arguments, bit for bit; 0 when
 * either is not finite. cross is a length: never negative (a negative one
 * is still answered, by atan2 itself). */
float corner_angle(double cross, double dot);

#endif
