/* shadow_filter.h - what a surface a shadow ray crosses lets through: the
 * filter the integrator passes to accel_transmission8. */
#ifndef GLINT_RENDER_SHADOW_FILTER_H
#define GLINT_RENDER_SHADOW_FILTER_H

#include "accel/accel.h"

/* What the hit `hit` of shadow ray r passes, per channel; adds to *depth
 * the optical depth it changes. `user` is the tracing thread's tracer
 * (integrator.h). An accel_filter_fn. */
color shadow_filter(void *user, const ray *r, const accel_hit *hit, color *depth);

#endif
