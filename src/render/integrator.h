/* integrator.h - the Whitted integrator: the colour a ray brings back. */
#ifndef GLINT_RENDER_INTEGRATOR_H
#define GLINT_RENDER_INTEGRATOR_H

#include <stdint.h>
#include "shading/light_choice.h"
#include "shading/spectrum.h"
#include "accel/accel.h"
#include "scene/scene.h"

/* A branch (a reflected, refracted or see-through ray) whose weight, the
 * product of the filters and shares along its path from the camera, is
 * below this in every channel is not traced. Where what it would see is no
 * brighter than 1, it could move its sample by less than this, under half
 * of the finest 8-bit sRGB step (the one above black: 1 / (255 x 12.92),
 * about 1/3295). Brighter highlights seen through many surfaces can still
 * move a pixel by one step; see docs/robustness.md. */
#define TRACER_MIN_WEIGHT (1.0 / 8192)

/* The reflected, refracted and see-through rays one camera sample may
 * trace, its camera ray not counted: a bound on the work of a pixel that
 * the weight cut-off alone does not give where shares add up to more than
 * one (reflectivity 1 with transparency 0.5). The rays of a sample are
 * traced depth first, straight through before refracted before mirrored,
 * and a branch met once the budget is spent is left black, so which rays
 * are cut depends only on the sample. */
#define TRACER_MAX_BRANCH_RAYS 4096

/* One thread's tracing state. */
typedef struct tracer {
    const glint_scene *scene;
    const accel *acc;
    uint64_t rays;            /* every ray this tracer has cast */
    double reach;             /* how far along a ray hits are looked for: tracer_reach */
    const volatile int *cancel; /* when non-NULL and set, tracing stops at the next packet */
    bool stopped;             /* the flag was seen set: every colour since is meaningless */
    bool keys;                /* tracer_needs_keys: without, no key is hashed, no ray spread */
    const light_choice *choice; /* settings.light_samples: the area lights and emitters by power; else NULL */
    const spectrum *spectrum; /* the bands dispersive materials split light into (settings.dispersion_bands) */
    double cone_width, cone_spread; /* a sample's footprint at distance d along its path: width +
                                       spread d (the camera's pixel over the square root of the
                                       samples a pixel takes), over which textures are averaged */
    int budget[ACCEL_PACKET]; /* each lane's branch rays left in its sample */
    const double *time;       /* each lane's time over the shutter, where moving shapes are
                                 (tracer_trace8's), or NULL: nothing moves */
    bool plain;               /* plain_packet_scene: packets of one plain surface may be shaded as one */
} tracer;

/* Whether the render has been asked to stop: read at every packet, and
 * for every light's shadow packet, since one packet's tree of branches or
 * one shadow packet through millions of surfaces can take seconds. Once
 * seen, it stays seen for the rest of this tracer's tile. */
static inline bool tracer_stopping(tracer *t)
{
    if (t->cancel && *t->cancel)
        t->stopped = true;
    return t->stopped;
}

/* How far along a ray a tracer of the scene needs to look for hits: past
 * fog_reach (with a margin for Embree's single-precision distances, which a
 * mesh hit's refinement may still move) everything shows the fog colour,
 * found or not. INFINITY without such fog. */
double tracer_reach(const glint_scene *scene);

/* Whether tracing the scene uses random numbers, so the keys passed to
 * tracer_trace8: with area lights, emissive surfaces, rough or dispersive
 * materials or ambient occlusion.
 * Without, every key may be 0. */
bool tracer_needs_keys(const glint_scene *scene);

/* The colours seen along up to ACCEL_PACKET unit-direction camera rays, the
 * lanes of *r (recursion depth 0), lane i at time[i] over the shutter (NULL:
 * nothing moves): out[i] for each active[i]. Every random
 * number lane i uses (an area light's samples, at every surface its rays
 * meet) is a hash of key[i], which the caller makes from the pixel, the
 * sample and the seed. The rays, their shadow
 * rays and the reflected, refracted and transmitted rays they lead to are
 * all traced as packets; coherent rays (a block of neighbouring pixels)
 * gain most. Branches lighter than TRACER_MIN_WEIGHT are not traced, and
 * each lane traces at most TRACER_MAX_BRANCH_RAYS of them. Once *t->cancel
 * is set, every packet still to trace returns at once with meaningless
 * colours (the caller drops them): a stop never waits for a deep tree. */
void tracer_trace8(tracer *t, const ray8 *r, const double *time, const bool active[ACCEL_PACKET],
                   const uint32_t key[ACCEL_PACKET], color out[ACCEL_PACKET]);

#endif
