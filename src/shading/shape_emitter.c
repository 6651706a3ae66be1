/* shape_emitter.c - an emissive shape as a light (light.h): its surface
 * sampled uniformly by area (shape_sample), each point glowing with the
 * material's emission from the shape's front. */
#include "shading/light.h"

static bool shape_emitter_sample(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    vec3 q, n;
    double density = shape_sample(&l->glow, u1, u2, &q, &n);
    return light_surface_point(p, q, n, density, l->desc.color, true, out);
}

LIGHT_SAMPLE_LANES(shape_emitter_lanes, shape_emitter_sample)

const light_kind shape_emitter = {.name = "emissive shape", .sample = shape_emitter_sample, .sample_lanes = shape_emitter_lanes};

bool emitter_for_shape(light *l, const shape *s, color radiance)
{
    vec3 q, n;
    /* Uniform by area: the density is 1 / area. */
    double density = shape_sample(s, 0.5, 0.5, &q, &n);
    if (!(density > 0))
        return false;
    *l = (light){.kind = &shape_emitter, .desc = {.color = radiance}, .glow = *s, .power = rgb_mean(radiance) / density};
    return true;
}
