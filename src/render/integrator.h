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
    double reach;             /* how far along a ray hits are looked for: tracer_reach */
} tracer;

/* How far along a ray a tracer of the scene needs to look for hits: past
 * fog_reach (with a margin for Embree's single-precision distances, which a
 * mesh hit's refinement may still move) everything shows the fog colour,
 * found or not. INFINITY without such fog. */
double tracer_reach(const glint_scene *scene);

/* The colours seen along up to ACCEL_PACKET unit-direction camera rays, the
 * lanes of *r (recursion depth 0): out[i] for each active[i]. The rays, their shadow
 * rays and the reflected, refracted and transmitted rays they lead to are
 * all traced as packets; coherent rays (a block of neighbouring pixels)
 * gain most. */
void tracer_trace8(tracer *t, const ray8 *r, const bool active[ACCEL_PACKET],
                   color out[ACCEL_PACKET]);

#endif
