/* light_choice.c - a scene's area lights and emitters weighed by their
 * power, and one picked by a random number (light_choice.h). */
#include <stdlib.h>
#include "shading/light_choice.h"

bool light_choice_init(light_choice *c, const light *lights, const int *area_lights, int area_light_count,
                       const light *emitters, int emitter_count)
{
    *c = (light_choice){0};
    int most = area_light_count + emitter_count;
    if (most == 0)
        return true;
    c->lights = malloc((size_t)most * sizeof *c->lights);
    c->cumulative = malloc((size_t)most * sizeof *c->cumulative);
    if (!c->lights || !c->cumulative) {
        light_choice_free(c);
        return false;
    }
    double total = 0;
    for (int k = 0; k < most; k++) {
        const light *l = k < area_light_count ? &lights[area_lights[k]] : &emitters[k - area_light_count];
        if (!(l->power > 0))
            continue;
        total += l->power;
        c->lights[c->count] = l;
        c->cumulative[c->count++] = total;
    }
    for (int k = 0; k < c->count; k++)
        c->cumulative[k] /= total;
    if (c->count > 0)
        c->cumulative[c->count - 1] = 1;
    return true;
}

void light_choice_free(light_choice *c)
{
    free(c->lights);
    free(c->cumulative);
    *c = (light_choice){0};
}

int light_choice_pick(const light_choice *c, double u)
{
    /* The first light whose running sum passes u. */
    int lo = 0, hi = c->count - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (c->cumulative[mid] > u)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

double light_choice_chance(const light_choice *c, int index)
{
    return c->cumulative[index] - (index > 0 ? c->cumulative[index - 1] : 0);
}
