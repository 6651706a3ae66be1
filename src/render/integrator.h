/* integrator.h - the Whitted integrator: the colour a ray brings back. */
#ifndef GLINT_RENDER_INTEGRATOR_H
#define GLINT_RENDER_INTEGRATOR_H

#include <stdint.h>
#include "accel/accel.h"
#include "scene/scene.h"

/* One thread's tracing state. */
typedef struct tracer {
    const glint_scene *scene;
    const accel *acc;
    uint64_t rays;            /* every ray this tracer has cast */
} tracer;

/* The colour seen along unit-direction ray r, at recursion depth `depth`
 * (0 for camera rays). */
color tracer_trace(tracer *t, const ray *r, int depth);

/* The colours seen along up to ACCEL_PACKET camera rays (depth 0) at once:
 * out[i] for each active[i], as tracer_trace would give them, with the
 * camera rays and their shadow rays traced as packets. Coherent rays (a
 * block of neighbouring pixels) gain most. */
void tracer_trace8(tracer *t, const ray r[ACCEL_PACKET], const bool active[ACCEL_PACKET],
                   color out[ACCEL_PACKET]);

#endif
