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

#endif
