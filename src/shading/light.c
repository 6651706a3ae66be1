/* light.c - the light interface: checks a description against its kind's
 * table, and the registry of kinds (one line each). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "core/registry.h"
#include "shading/light.h"

static const light_kind *const KINDS[] = {&point_light,  &spot_light,      &directional_light,
                                          &sphere_light, &rectangle_light, &disk_light};

REGISTRY_LOOKUPS(light_kind, light_kind, glint_light_kind, KINDS)

light_spec light_spec_default(glint_light_kind id)
{
    light_spec s;
    memset(&s, 0, sizeof s);
    s.light.kind = id;
    const light_kind *k = light_kind_of(id);
    if (k)
        params_defaults(k->params, &s);
    return s;
}

const char *const LIGHT_FALLOFF_WORDS[3] = {"none", "inverse_square", "fade"};

double light_falloff(const light *l, double d)
{
    if (l->desc.falloff == GLINT_FALLOFF_INVERSE_SQUARE)
        return 1 / (d * d);
    return 2 / (1 + pow(d / l->desc.fade_distance, l->desc.fade_power));
}

glint_status light_falloff_check(const light *l, glint_error *err)
{
    const glint_light *d = &l->desc;
    if (d->falloff == GLINT_FALLOFF_NONE)
        return GLINT_OK;
    if (!l->kind->delta)
        return error_set(err, GLINT_ERR_INVALID, "a %s light weakens with distance by its size: its falloff_mode "
                         "must be none", l->kind->name);
    if (l->at_infinity)
        return error_set(err, GLINT_ERR_INVALID, "a %s light is at infinity: its falloff_mode must be none",
                         l->kind->name);
    if (d->falloff == GLINT_FALLOFF_FADE && !(d->fade_distance > 0 && d->fade_power > 0))
        return error_set(err, GLINT_ERR_INVALID, "%s light falloff_mode fade needs fade_distance and fade_power "
                         "above 0, got %g and %g", l->kind->name, d->fade_distance, d->fade_power);
    return GLINT_OK;
}

double spot_factor(const light *l, double cos_angle)
{
    if (cos_angle < l->cos_outer)
        return 0;
    if (cos_angle >= l->cos_inner)
        return 1;
    double t = (cos_angle - l->cos_outer) / (l->cos_inner - l->cos_outer);
    return t * t * (3 - 2 * t);
}

bool light_delta_sample_fn(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    return light_delta_sample(l, p, out);
}

glint_status light_area_init(light *l, const glint_shape *glow, double area, glint_error *err)
{
    l->area = area;
    l->power = rgb_mean(l->desc.color) * area;
    return shape_init(&l->glow, glow, NULL, -1, err);
}

/* How much shorter than the distance to a surface in the scene its shadow
 * segment is, so that Embree's single-precision hit on that surface is
 * not taken for a blocker. */
#define EMITTER_GAP 1e-4

bool light_surface_point(vec3 p, vec3 q, vec3 n_q, double density, color radiance, bool in_scene,
                         light_sample *out)
{
    vec3 d = v3_sub(q, p);
    double d2 = v3_dot(d, d);
    if (!(d2 > 0) || !(density > 0))
        return false;
    /* The cosine at the light times the distance, from d itself: the
     * radiance's scale waits for one square root and one division, not for
     * the direction's division as well (four dependent ones, at about 15
     * cycles each, were a quarter of a Cornell box render). */
    double distance = sqrt(d2), cos_times_distance = -v3_dot(d, n_q);
    if (!(cos_times_distance > 0))
        return false;
    out->to_light = v3_scale(d, 1 / distance);
    out->distance = in_scene ? distance * (1 - EMITTER_GAP) : distance;
    /* By area, the density among directions is density d^2 / cos. */
    double per_area = density * d2 * distance;
    out->radiance = rgb_scale(radiance, cos_times_distance / (M_PI * per_area));
    return true;
}

bool light_area_point(const light *l, vec3 p, vec3 q, light_sample *out)
{
    return light_surface_point(p, q, l->normal, 1 / l->area, l->desc.color, false, out);
}

void light_release(light *l)
{
    free(l->triangles);
    free(l->cumulative);
    l->triangles = NULL;
    l->cumulative = NULL;
}

bool light_seen(const light *l, const ray *r, double tmax, double *t)
{
    shape_hit h;
    if (!shape_intersect(&l->glow, r, 0, tmax, &h))
        return false;
    if (l->kind->one_sided && !(v3_dot(r->d, l->normal) < 0))
        return false;
    *t = h.t;
    return true;
}

glint_light glint_light_default(glint_light_kind kind)
{
    light_spec s = light_spec_default(kind);
    s.light.color = rgb_scale(s.light.color, s.intensity);
    return s.light;
}

glint_status light_init(light *l, const glint_light *d, glint_error *err)
{
    memset(l, 0, sizeof *l);
    l->desc = *d;
    l->kind = light_kind_of(d->kind);
    if (!l->kind)
        return error_set(err, GLINT_ERR_INVALID, "unknown light kind %d", (int)d->kind);
    /* The C API gives the colour already scaled: intensity 1. */
    light_spec spec = {*d, 1};
    char what[40];
    snprintf(what, sizeof what, "%s light", l->kind->name);
    glint_status s = params_check(l->kind->params, &spec, what, err);
    if (s == GLINT_OK && l->kind->init)
        s = l->kind->init(l, err);
    if (s == GLINT_OK)
        s = light_falloff_check(l, err);
    return s;
}
