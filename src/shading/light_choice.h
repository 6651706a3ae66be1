/* light_choice.h - choosing among a scene's area lights and emissive
 * surfaces by their power (settings.light_samples): rather than every
 * one of them sending its own samples from each point lit, the point
 * sends a fixed number in all, each to a light chosen in proportion to
 * the light it gives off, and counts it divided by that chance. Scenes of
 * many lamps then cost what a scene of one does, the brighter lamps taking
 * the most samples. */
#ifndef GLINT_SHADING_LIGHT_CHOICE_H
#define GLINT_SHADING_LIGHT_CHOICE_H

#include <stdbool.h>
#include "shading/light.h"

typedef struct light_choice {
    const light **lights;     /* the area lights, then the emitters, that give off any light */
    double *cumulative;       /* their chances summed up to each, the last 1 */
    int count;
} light_choice;

/* The choice among the scene's area lights and emitters (lights of count
 * 0, and nothing to free, when none gives off light); false when memory
 * runs out. */
bool light_choice_init(light_choice *c, const light *lights, const int *area_lights, int area_light_count,
                       const light *emitters, int emitter_count);

/* Frees what light_choice_init took. */
void light_choice_free(light_choice *c);

/* The index of the light that u in [0, 1) chooses. */
int light_choice_pick(const light_choice *c, double u);

/* The chance that light `index` is chosen. */
double light_choice_chance(const light_choice *c, int index);

#endif
