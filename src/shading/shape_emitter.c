/* shape_emitter.c - an emissive shape as a light (light.h): its surface
 * sampled uniformly by area (shape_sample), each point glowing with the
 * material's emission from the shape's front. */
#include "shading/light.h"

static void shape_emitter_surface(const light *l, double u1, double u2, surface_point *out)
{
    out->density = shape_sample(&l->glow, u1, u2, &out->q, &out->n);
    out->radiance = l->desc.color;
}

const light_kind shape_emitter = {.name = "emissive shape", .sample = light_surface_sample,
                                  .sample_lanes = light_surface_lanes, .surface = shape_emitter_surface,
                                  .in_scene = true};

bool emitter_for_shape(light *l, const shape *s, int index, color radiance)
{
    vec3 q, n;
    /* Uniform by area: the density is 1 / area. */
    double density = shape_sample(s, 0.5, 0.5, &q, &n);
    if (!(density > 0))
        return false;
    *l = (light){.kind = &shape_emitter, .desc = {.color = radiance}, .glow = *s, .power = rgb_mean(radiance) / density,
                 .shape_index = index};
    return true;
}

void emitters_follow_shape(light *emitters, int count, int index, const shape *s)
{
    for (int i = 0; i < count; i++)
        if (emitters[i].kind == &shape_emitter && emitters[i].shape_index == index)
            emitters[i].glow = *s;
}
