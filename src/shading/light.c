/* light.c - the light interface: checks a description against its kind's
 * table, and the registry of kinds (one line each). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/poses.h"
#include "core/error.h"
#include "core/lanes.h"
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

void light_move(light *l, light *poses, int count)
{
    *l = poses[0];
    l->poses = poses;
    l->pose_count = count;
}

/* A moving area light as it is at `time`: its description blended
 * between the poses about that time, and its surface made from that. */
static const light *area_light_moved(const light *l, double time, light *out)
{
    int k;
    double w;
    pose_stretch(time, l->pose_count, &k, &w);
    const light *a = &l->poses[k], *b = &l->poses[k + 1];
    *out = *a;
    glint_light *d = &out->desc;
    d->position = v3_lerp(a->desc.position, b->desc.position, w);
    d->color = rgb_lerp(a->desc.color, b->desc.color, w);
    d->radius = a->desc.radius + (b->desc.radius - a->desc.radius) * w;
    d->edge1 = v3_lerp(a->desc.edge1, b->desc.edge1, w);
    d->edge2 = v3_lerp(a->desc.edge2, b->desc.edge2, w);
    d->direction = v3_lerp(a->desc.direction, b->desc.direction, w);
    glint_error ignored;
    /* A surface that blends through nothing (a half turn's edges, a
     * direction through zero) has none at that instant: the nearer pose
     * stands in. */
    if (out->kind->init(out, &ignored) != GLINT_OK)
        *out = w < 0.5 ? *a : *b;
    out->pose_count = 0;
    return out;
}

const light *light_moved(const light *l, double time, light *out)
{
    if (!l->pose_count) {
        /* An emitter glowing over a moving shape. */
        shape glow;
        const shape *at = shape_at(&l->glow, time, &glow);
        *out = *l;
        out->glow = *at;
        return out;
    }
    if (!l->kind->delta)
        return area_light_moved(l, time, out);
    int k;
    double w;
    pose_stretch(time, l->pose_count, &k, &w);
    const light *a = &l->poses[k], *b = &l->poses[k + 1];
    *out = *a;
    out->desc.position = v3_lerp(a->desc.position, b->desc.position, w);
    out->desc.color = rgb_lerp(a->desc.color, b->desc.color, w);
    vec3 dir = v3_lerp(a->dir, b->dir, w);
    /* Opposite directions blend through nothing: that instant keeps the nearer. */
    out->dir = v3_length(dir) > 0 ? v3_normalize(dir) : w < 0.5 ? a->dir : b->dir;
    out->cos_outer = a->cos_outer + (b->cos_outer - a->cos_outer) * w;
    out->cos_inner = a->cos_inner + (b->cos_inner - a->cos_inner) * w;
    out->pose_count = 0;
    return out;
}

__attribute__((noinline)) bool light_moved_sample(const light *l, double time, vec3 p, light_sample *out)
{
    light moved;
    return light_delta_sample(light_moved(l, time, &moved), p, out);
}

__attribute__((noinline)) void light_moved_lanes(const light *l, const double *time, const double p[3][RAY8],
                                                const double u[2][RAY8], const bool active[RAY8], light_samples8 *out)
{
    for (int i = 0; i < RAY8; i++) {
        light moved;
        light_sample s = {{0, 0, 0}, 0, {0, 0, 0}};
        const light *m = active[i] ? light_moved(l, time[i], &moved) : NULL;
        out->ok[i] = m && m->kind->sample(m, v3(p[0][i], p[1][i], p[2][i]), u[0][i], u[1][i], &s);
        const double to_light[3] = {s.to_light.x, s.to_light.y, s.to_light.z}, glow[3] = {s.radiance.r, s.radiance.g,
                                                                                           s.radiance.b};
        for (int c = 0; c < 3; c++) {
            out->to_light[c][i] = to_light[c];
            out->radiance[c][i] = glow[c];
        }
        out->distance[i] = s.distance;
    }
}

bool light_delta_sample_fn(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    return light_delta_sample(l, p, out);
}

glint_status light_area_init(light *l, const glint_shape *glow, double area, glint_error *err)
{
    l->area = area;
    l->density = 1 / area;
    l->power = rgb_mean(l->desc.color) * area;
    return shape_init(&l->glow, glow, NULL, -1, err);
}

/* How much shorter than the distance to a surface in the scene its shadow
 * segment is, so that Embree's single-precision hit on that surface is
 * not taken for a blocker. */
#define EMITTER_GAP 1e-4

/* light_surface_point's arithmetic for four lanes (k of each quad): the
 * vector from p to q and its length, the direction, the distance the
 * shadow segment runs, and the scale of the radiance, where the mask is
 * set (d^2, the density and the cosine at the light all above 0). The
 * cosine at the light times the distance comes from d itself: the scale
 * waits for one square root and one division, not for the direction's
 * division as well (four dependent ones, at about 15 cycles each, were a
 * quarter of a Cornell box render). By area, the density among directions
 * is density d^2 / cos. */
static inline quad_mask surface_point_quad(const quad_f64 p[3], const quad_f64 q[3], const quad_f64 n[3],
                                           quad_f64 density, bool in_scene, quad_f64 to_light[3],
                                           quad_f64 *distance, quad_f64 *scale)
{
    quad_f64 dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
    quad_f64 d2 = quad_dot(dx, dy, dz, dx, dy, dz);
    quad_f64 length = quad_sqrt(d2), cos_times_distance = -quad_dot(dx, dy, dz, n[0], n[1], n[2]);
    quad_f64 inverse = 1 / length;
    to_light[0] = dx * inverse;
    to_light[1] = dy * inverse;
    to_light[2] = dz * inverse;
    *distance = in_scene ? length * (1 - EMITTER_GAP) : length;
    quad_f64 per_area = density * d2 * length;
    *scale = cos_times_distance / (M_PI * per_area);
    return (d2 > 0) & (density > 0) & (cos_times_distance > 0);
}

/* Lane k of the quads' sample, into *out. */
static void surface_sample_lane(const quad_f64 to_light[3], quad_f64 distance, quad_f64 scale, int k,
                                color radiance, light_sample *out)
{
    out->to_light = v3(to_light[0][k], to_light[1][k], to_light[2][k]);
    out->distance = distance[k];
    out->radiance = rgb_scale(radiance, scale[k]);
}

bool light_surface_point(vec3 p, vec3 q, vec3 n_q, double density, color radiance, bool in_scene,
                         light_sample *out)
{
    const quad_f64 pq[3] = {quad_splat(p.x), quad_splat(p.y), quad_splat(p.z)};
    const quad_f64 qq[3] = {quad_splat(q.x), quad_splat(q.y), quad_splat(q.z)};
    const quad_f64 nq[3] = {quad_splat(n_q.x), quad_splat(n_q.y), quad_splat(n_q.z)};
    quad_f64 to_light[3], distance, scale;
    if (!surface_point_quad(pq, qq, nq, quad_splat(density), in_scene, to_light, &distance, &scale)[0])
        return false;
    surface_sample_lane(to_light, distance, scale, 0, radiance, out);
    return true;
}

bool light_surface_sample(const light *l, vec3 p, double u1, double u2, light_sample *out)
{
    surface_point s;
    l->kind->surface(l, u1, u2, &s);
    return light_surface_point(p, s.q, s.n, s.density, s.radiance, l->kind->in_scene, out);
}

/* The surface points of lanes `first` to first + 3 for their samples u,
 * into quads; an inactive lane's are any numbers (lane by lane, density 0). */
static void surface_points_quad(const light *l, const double u[2][RAY8], const bool active[RAY8], int first,
                                quad_f64 q[3], quad_f64 n[3], quad_f64 *density, quad_f64 glow[3])
{
    if (l->kind->surface_quad &&
        l->kind->surface_quad(l, quad_load(u[0] + first), quad_load(u[1] + first), q, n, density, glow))
        return; /* an inactive lane's sample is not ok whatever it holds */
    surface_point t[QUAD];
    for (int k = 0; k < QUAD; k++) {
        if (active[first + k])
            l->kind->surface(l, u[0][first + k], u[1][first + k], &t[k]);
        else
            memset(&t[k], 0, sizeof t[k]); /* density 0: nothing */
    }
    for (int k = 0; k < QUAD; k++) {
        q[0][k] = t[k].q.x;
        q[1][k] = t[k].q.y;
        q[2][k] = t[k].q.z;
        n[0][k] = t[k].n.x;
        n[1][k] = t[k].n.y;
        n[2][k] = t[k].n.z;
        (*density)[k] = t[k].density;
        glow[0][k] = t[k].radiance.r;
        glow[1][k] = t[k].radiance.g;
        glow[2][k] = t[k].radiance.b;
    }
}

void light_surface_lanes(const light *l, const double p[3][RAY8], const double u[2][RAY8], const bool active[RAY8],
                         light_samples8 *out)
{
    for (int i = 0; i < RAY8; i += QUAD) {
        const quad_f64 pq[3] = {quad_load(p[0] + i), quad_load(p[1] + i), quad_load(p[2] + i)};
        quad_f64 qq[3], nq[3], density, glow[3];
        surface_points_quad(l, u, active, i, qq, nq, &density, glow);
        quad_f64 to_light[3], distance, scale;
        quad_mask fine = surface_point_quad(pq, qq, nq, density, l->kind->in_scene, to_light, &distance, &scale);
        for (int c = 0; c < 3; c++) {
            quad_store(out->to_light[c] + i, to_light[c]);
            quad_store(out->radiance[c] + i, glow[c] * scale);
        }
        quad_store(out->distance + i, distance);
        for (int k = 0; k < QUAD; k++)
            out->ok[i + k] = active[i + k] && fine[k];
    }
}

void light_parallelogram_quad(vec3 corner, vec3 edge1, vec3 edge2, quad_f64 u1, quad_f64 u2, quad_f64 q[3])
{
    const double c[3] = {corner.x, corner.y, corner.z}, e1[3] = {edge1.x, edge1.y, edge1.z},
                 e2[3] = {edge2.x, edge2.y, edge2.z};
    for (int k = 0; k < 3; k++)
        q[k] = c[k] + (e1[k] * u1 + e2[k] * u2);
}

void light_area_quad(const light *l, quad_f64 n[3], quad_f64 *density, quad_f64 glow[3])
{
    n[0] = quad_splat(l->normal.x);
    n[1] = quad_splat(l->normal.y);
    n[2] = quad_splat(l->normal.z);
    *density = quad_splat(l->density);
    glow[0] = quad_splat(l->desc.color.r);
    glow[1] = quad_splat(l->desc.color.g);
    glow[2] = quad_splat(l->desc.color.b);
}

void light_area_point(const light *l, vec3 q, surface_point *out)
{
    out->q = q;
    out->n = l->normal;
    out->density = l->density;
    out->radiance = l->desc.color;
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

/* light_delta_lanes for the quad of hits p, lanes `on`: the direction to
 * the light, its distance and radiance, and the lanes it lights at all. */
static quad_mask delta_quad(const light *l, const quad_f64 p[3], quad_mask on, quad_f64 to_light[3],
                            quad_f64 *distance, quad_f64 radiance[3])
{
    const double colour[3] = {l->desc.color.r, l->desc.color.g, l->desc.color.b};
    quad_f64 factor = quad_splat(1);
    if (l->at_infinity) {
        to_light[0] = quad_splat(-l->dir.x);
        to_light[1] = quad_splat(-l->dir.y);
        to_light[2] = quad_splat(-l->dir.z);
        *distance = quad_splat(INFINITY);
    } else {
        const quad_f64 d[3] = {l->desc.position.x - p[0], l->desc.position.y - p[1], l->desc.position.z - p[2]};
        quad_f64 squared = quad_dot(d[0], d[1], d[2], d[0], d[1], d[2]);
        if (l->has_cone) {
            quad_f64 along = -quad_dot(d[0], d[1], d[2], quad_splat(l->dir.x), quad_splat(l->dir.y),
                                       quad_splat(l->dir.z));
            on &= ~((along < 0) | (along * along < l->cos_outer * l->cos_outer * squared * (1 - 1e-9)));
        }
        *distance = quad_sqrt(squared);
        on &= *distance != 0;
        quad_f64 inverse = 1.0 / *distance;
        for (int c = 0; c < 3; c++)
            to_light[c] = d[c] * inverse;
        if (l->has_cone || l->desc.falloff != GLINT_FALLOFF_NONE) {
            for (int k = 0; k < QUAD; k++) {
                if (!on[k])
                    continue;
                double f = 1;
                if (l->has_cone)
                    f = spot_factor(l, -v3_dot(v3(to_light[0][k], to_light[1][k], to_light[2][k]), l->dir));
                if (l->desc.falloff != GLINT_FALLOFF_NONE)
                    f *= light_falloff(l, (*distance)[k]);
                factor[k] = f;
            }
        }
    }
    for (int c = 0; c < 3; c++)
        radiance[c] = colour[c] * factor;
    return on & (factor > 0);
}

void light_delta_lanes(const light *l, const double p[3][RAY8], const bool active[RAY8], light_samples8 *out)
{
    for (int h = 0; h < RAY8; h += QUAD) {
        const quad_f64 at[3] = {quad_load(p[0] + h), quad_load(p[1] + h), quad_load(p[2] + h)};
        quad_f64 to_light[3], distance, radiance[3];
        quad_mask ok = delta_quad(l, at, quad_from_bools(active + h), to_light, &distance, radiance);
        for (int c = 0; c < 3; c++) {
            quad_store(out->to_light[c] + h, to_light[c]);
            quad_store(out->radiance[c] + h, radiance[c]);
        }
        quad_store(out->distance + h, distance);
        quad_mask_store(out->ok + h, ok);
    }
}
