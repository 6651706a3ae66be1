/* light.h - lights: where a light is seen from a point and how much of it
 * arrives there before shadowing.
 *
 * Each kind of light is one file (point_light.c, sphere_light.c, ...) that
 * exports one light_kind record: its scene-file name, its parameter table
 * and its operations; light.c lists them. A light is sampled at a point
 * with a 2-D random sample in [0, 1)^2 and gives a direction, a distance,
 * the radiance arriving and the probability density of that direction.
 *
 * Delta lights shine from one point (or one direction, at infinity),
 * optionally limited to a cone: they ignore the sample and give density 1.
 * Their kinds set up that description in their init and the integrator
 * samples them all with one inlined rule (light_delta_sample), as a call
 * through the record for every shading point and light cost the seed room
 * 2.6% of its instructions.
 *
 * Area lights (sphere, rectangle, disk) glow over a surface of radiance
 * desc.color and sample it through their record, desc.samples times at
 * each shading point. Each has the exact shape it glows over, which camera,
 * reflected and refracted rays see (light_seen) but which casts no shadow.
 * Emissive shapes and meshes are lights too (emitters: shape_emitter.c,
 * mesh_emitter.c), which the scene makes when one is added and keeps apart
 * from the lights it was given: they sample the surface that glows, which
 * is in the scene and so needs no light_seen, and their shadow rays stop
 * just short of it. Adding a kind: docs/architecture.md. */
#ifndef GLINT_SHADING_LIGHT_H
#define GLINT_SHADING_LIGHT_H

#include <stdbool.h>
#include "core/color.h"
#include "core/lanes.h"
#include "core/params.h"
#include "core/vec.h"
#include "geometry/mesh.h"
#include "geometry/shape.h"
#include "shading/material.h"

typedef struct light_kind light_kind;

/* A triangle of an emissive mesh, in world space. */
typedef struct emitter_triangle {
    vec3 a, b, c;             /* with parallelogram, the corner a and its neighbours b and c */
    vec3 normal;              /* unit, on the side it glows: by the winding */
    double area;              /* found once: every sample of it divides by it */
    color radiance;
    bool parallelogram;       /* two triangles of a quad joined: a + u (b - a) + v (c - a), u, v in [0, 1) */
} emitter_triangle;

/* A light with its derived values precomputed. */
typedef struct light {
    const light_kind *kind;
    glint_light desc;
    vec3 dir;                 /* unit direction (spot: its axis; directional: travel) */
    bool at_infinity;         /* a delta light from direction -dir, not from desc.position */
    bool has_cone;            /* a delta light limited to the cone about dir: */
    double cos_outer;         /* the cosine of the cone half-angle */
    double cos_inner;         /* the cosine of the half-angle where falloff begins */
    shape glow;               /* an area light: the surface it glows over, */
    vec3 normal;              /* its lit side's unit normal when it is flat, */
    double area;              /* and its area, */
    double density;           /* 1 / area: a point's density, chosen uniformly over it */
    emitter_triangle *triangles; /* an emissive mesh's triangles that glow (a quad's two as one), */
    double *cumulative;       /* the sum of their powers up to each, the last 1, */
    int triangle_count;       /* and their number */
    double power;             /* an area light's or emitter's brightness (rgb_mean) times the area
                                 it glows over, to choose among them by (light_choice.h) */
    struct light *poses;      /* a moving light's over the shutter (light_move), evenly */
    int pose_count;           /* spaced, or 0: it stands still; owned by the scene */
    int shape_index;          /* an emissive shape's: the scene's shape it glows over */
} light;

/* What a light offers to point p for one sample. */
typedef struct light_sample {
    vec3 to_light;            /* unit direction from p towards the light */
    double distance;          /* to the light; INFINITY for directional lights */
    color radiance;           /* arriving light before shadows, as the colour of a point
                                 light in to_light (phong_light's radiance): for an area
                                 light, its radiance / (pi pdf), pdf the density of to_light
                                 among the directions the light is sampled in
                                 (docs/scene-format.md) */
} light_sample;

/* An area light's samples at the lanes of a packet, lane i of each
 * array: what light_sample says, by coordinate and by channel. A lane
 * that is not ok holds numbers (perhaps infinite or NaN), never
 * uninitialised memory. */
typedef struct light_samples8 {
    double to_light[3][RAY8];
    double distance[RAY8];
    double radiance[3][RAY8];
    bool ok[RAY8];
} light_samples8;

/* A point of the surface an area light or emitter glows over, chosen for
 * one sample: the same whatever point it lights. */
typedef struct surface_point {
    vec3 q;                   /* the point */
    vec3 n;                   /* the unit normal of its glowing side */
    double density;           /* with which q was chosen, per unit area */
    color radiance;           /* its glow */
} surface_point;

/* What a scene file says of a light: the public description and the
 * intensity its colour is scaled by. The kinds' parameter tables give
 * offsets into this. */
typedef struct light_spec {
    glint_light light;
    double intensity;
} light_spec;

struct light_kind {
    const char *name;         /* the scene file's `type` */
    glint_light_kind id;
    param_table params;       /* offsets into light_spec */
    /* Fills the fields of l derived from l->desc after the table's checks
     * (for a delta light: at_infinity, has_cone, dir and the cone's
     * cosines), checking rules across keys; NULL: nothing to do. */
    glint_status (*init)(light *l, glint_error *err);
    /* Shines from one point or one direction: sampled by light_delta_sample. */
    bool delta;
    /* An area light whose surface is flat and glows on the side of normal only. */
    bool one_sided;
    /* Samples the light from point p with (u1, u2) in [0, 1)^2: false when
     * it gives p nothing. light_delta_sample for delta kinds;
     * light_surface_sample for kinds with a surface. */
    bool (*sample)(const light *l, vec3 p, double u1, double u2, light_sample *out);
    /* An area light's samples for the lanes of a packet: lane i of *out is
     * sample's answer at lane i of p with lane i of u for each active
     * lane, not ok for the rest. One call and one loop
     * (light_surface_lanes, LIGHT_SAMPLE_LANES), so that the lanes' square
     * roots and divisions overlap where a call a lane waited for each in
     * turn; lanes in arrays, as the integrator works on them a quad at a
     * time. NULL for delta kinds. */
    void (*sample_lanes)(const light *l, const double p[3][RAY8], const double u[2][RAY8], const bool active[RAY8],
                         light_samples8 *out);
    /* A kind sampled by area over the surface it glows over (all area
     * kinds but the sphere's, which samples the cone of directions it
     * fills): the point for (u1, u2), whose sample at any p
     * light_surface_sample and light_surface_lanes then work out. */
    void (*surface)(const light *l, double u1, double u2, surface_point *out);
    /* surface for a quad of samples, lane k's (u1[k], u2[k]), into the
     * quads q, n (the points and normals by coordinate), density and glow
     * (the radiance by channel), the same bits as four calls of surface;
     * false, with nothing written, when this light has no such shortcut,
     * and surface then runs lane by lane. NULL: never. Four calls cost a
     * tenth of a Cornell box; these lights, a quad in a few instructions. */
    bool (*surface_quad)(const light *l, quad_f64 u1, quad_f64 u2, quad_f64 q[3], quad_f64 n[3], quad_f64 *density,
                         quad_f64 glow[3]);
    /* The surface is in the scene (an emitter's), so that its shadow
     * segments stop just short of it. */
    bool in_scene;
};

/* light_kind.sample and .sample_lanes of a kind with a surface: the
 * surface's point for (u1, u2) seen from p, as light_surface_point makes
 * it; the lanes four at a time in vector instructions (the same bits). */
bool light_surface_sample(const light *l, vec3 p, double u1, double u2, light_sample *out);
void light_surface_lanes(const light *l, const double p[3][RAY8], const double u[2][RAY8], const bool active[RAY8],
                         light_samples8 *out);

/* Defines `name`, a light_kind.sample_lanes that runs the kind's own
 * sample function `one` (defined before it, in the same file) over the
 * lanes. */
#define LIGHT_SAMPLE_LANES(name, one)                                                                        \
    static void name(const light *l, const double p[3][RAY8], const double u[2][RAY8], const bool active[RAY8], \
                     light_samples8 *out)                                                                    \
    {                                                                                                        \
        for (int i = 0; i < RAY8; i++) {                                                                     \
            light_sample s = {{0, 0, 0}, 0, {0, 0, 0}};                                                      \
            out->ok[i] = active[i] && one(l, v3(p[0][i], p[1][i], p[2][i]), u[0][i], u[1][i], &s);           \
            light_samples8_set(out, i, &s);                                                                  \
        }                                                                                                    \
    }

/* Lane i of *out becomes *s (its ok flag aside). */
static inline void light_samples8_set(light_samples8 *out, int i, const light_sample *s)
{
    out->to_light[0][i] = s->to_light.x;
    out->to_light[1][i] = s->to_light.y;
    out->to_light[2][i] = s->to_light.z;
    out->distance[i] = s->distance;
    out->radiance[0][i] = s->radiance.r;
    out->radiance[1][i] = s->radiance.g;
    out->radiance[2][i] = s->radiance.b;
}
/* Lane i's radiance. */
static inline color light_samples8_radiance(const light_samples8 *s, int i)
{
    return rgb(s->radiance[0][i], s->radiance[1][i], s->radiance[2][i]);
}

extern const light_kind point_light, spot_light, directional_light, sphere_light, rectangle_light, disk_light;

/* The kind with that public id, or NULL. */
const light_kind *light_kind_of(glint_light_kind id);

/* The number of kinds, and kind i, in the order the docs list them. */
int light_kind_count(void);
const light_kind *light_kind_at(int i);

/* The description a scene file starts from for a light of kind id: every
 * parameter at its default (intensity 1). */
light_spec light_spec_default(glint_light_kind id);

/* Validates desc against its kind's table and rules and fills *l; fills
 * err naming a bad value. */
glint_status light_init(light *l, const glint_light *desc, glint_error *err);

/* Cone factor in [0, 1] of a delta light with a cone, for a point whose
 * direction from the light makes cosine cos_angle with the axis: 1 inside
 * the inner cone, 0 outside the outer, a smoothstep between. */
double spot_factor(const light *l, double cos_angle);

/* True when p, at d from light l with a cone, is clearly outside the cone:
 * most points of a scene are, and this needs no square root or division.
 * The margin leaves every point the exact test might light to that test. */
static inline bool light_outside_cone(const light *l, vec3 d)
{
    double along = -v3_dot(d, l->dir); /* |d| times the cosine from the axis */
    if (along < 0)
        return true;
    return along * along < l->cos_outer * l->cos_outer * v3_dot(d, d) * (1 - 1e-9);
}

/* The share of its light that light l (not at infinity) gives at
 * distance d, by its falloff: 1 for none. */
double light_falloff(const light *l, double d);

/* The sample of a delta light at p: its position, or its direction when at
 * infinity, and its colour, scaled inside a cone by spot_factor. */
static inline bool light_delta_sample(const light *l, vec3 p, light_sample *out)
{
    double factor = 1;
    if (l->at_infinity) {
        out->to_light = v3_neg(l->dir);
        out->distance = INFINITY;
    } else {
        vec3 d = v3_sub(l->desc.position, p);
        if (l->has_cone && light_outside_cone(l, d))
            return false;
        out->distance = v3_length(d);
        if (out->distance == 0)
            return false;
        out->to_light = v3_scale(d, 1.0 / out->distance);
        if (l->has_cone)
            factor = spot_factor(l, -v3_dot(out->to_light, l->dir));
        if (l->desc.falloff != GLINT_FALLOFF_NONE)
            factor *= light_falloff(l, out->distance);
    }
    out->radiance = rgb_scale(l->desc.color, factor);
    return factor > 0;
}

/* light_delta_sample of delta light l at the lanes of a packet, lane i
 * at (p[0][i], p[1][i], p[2][i]) for each active[i], not ok for the rest:
 * the same bits, four lanes at a time. */
void light_delta_lanes(const light *l, const double p[3][RAY8], const bool active[RAY8], light_samples8 *out);

/* Makes light l move over the shutter through `count` (2 or more)
 * initialised lights of its kind, evenly spaced: l keeps `poses`, which
 * the caller frees after it, and takes the first's place. */
void light_move(light *l, light *poses, int count);

/* Whether l moves over the shutter: a light with poses, or an emitter
 * glowing over a moving shape. */
static inline bool light_moves(const light *l)
{
    return l->pose_count > 0 || l->glow.pose_count > 0;
}

/* The moving light l (light_moves) as it is at `time` in [0, 1] over the
 * shutter, into *out, which it returns: a delta light's position,
 * direction, colour and cone, an area light's position, direction, edges,
 * radius and colour, blended in a straight line between the poses about
 * that time (an area light's surface made anew from them); an emitter's
 * surface, its shape as shape_at gives it. */
const light *light_moved(const light *l, double time, light *out);

/* An area light's or emitter's samples for a packet, as sample_lanes, of
 * the moving light l, lane i's as it is at time[i]: one lane at a time,
 * through its kind's sample. */
void light_moved_lanes(const light *l, const double *time, const double p[3][RAY8], const double u[2][RAY8],
                       const bool active[RAY8], light_samples8 *out);

/* light_delta_sample of the moving delta light l as it is at `time`:
 * apart, so that the common path keeps no room for a moved copy. */
bool light_moved_sample(const light *l, double time, vec3 p, light_sample *out);

/* light_delta_sample as a light_kind.sample, for the records of delta
 * kinds (the sample (u1, u2) is not used). */
bool light_delta_sample_fn(const light *l, vec3 p, double u1, double u2, light_sample *out);


/* The words of falloff_mode, in glint_falloff's order. */
extern const char *const LIGHT_FALLOFF_WORDS[3];

/* The parameters of a light at a point: how its light weakens with distance. */
#define LIGHT_FALLOFF_PARAMS                                                                                   \
    {.key = "falloff_mode", .type = PARAM_CHOICE, .offset = offsetof(light_spec, light.falloff),             \
     .words = LIGHT_FALLOFF_WORDS, .word_count = 3,                                                          \
     .meaning = "how the light weakens with distance d: none; inverse_square (color / d^2, color arriving "  \
                "at distance 1); fade (POV-Ray's: color * 2 / (1 + (d / fade_distance)^fade_power))"},      \
    {.key = "fade_distance", .type = PARAM_NUMBER, .offset = offsetof(light_spec, light.fade_distance),     \
     .lo = 0, .hi = DBL_MAX, .meaning = "fade: where the light is its colour, brighter nearer; more than 0"}, \
    {.key = "fade_power", .type = PARAM_NUMBER, .offset = offsetof(light_spec, light.fade_power), .lo = 0,     \
     .hi = 1000, .meaning = "fade: how fast it fades beyond fade_distance (2: as the square); more than 0"}

/* Checks a light's falloff values across keys: fade needs fade_distance
 * and fade_power above 0, and a light at infinity has none. */
glint_status light_falloff_check(const light *l, glint_error *err);

/* Sets up area light l to glow over the shape `glow` of area `area` (for a
 * one-sided kind, on the side of l->normal, which its init sets). */
glint_status light_area_init(light *l, const glint_shape *glow, double area, glint_error *err);

/* Fills *out with the surface point of one-sided area light l (uniform by
 * area over it) at q, field by field: a struct built and copied whole
 * waited on its parts' stores. */
void light_area_point(const light *l, vec3 q, surface_point *out);

/* Lane k of q becomes corner + (edge1 u1[k] + edge2 u2[k]): a point of a
 * parallelogram, as v3_add and v3_scale give it, for a quad of samples. */
void light_parallelogram_quad(vec3 corner, vec3 edge1, vec3 edge2, quad_f64 u1, quad_f64 u2, quad_f64 q[3]);

/* light_area_point's normal, density and glow for a quad of points. */
void light_area_quad(const light *l, quad_f64 n[3], quad_f64 *density, quad_f64 glow[3]);

/* Whether ray r meets area light l's glowing side before tmax, and where:
 * *t. A camera, reflected or refracted ray that does sees desc.color. */
bool light_seen(const light *l, const ray *r, double tmax, double *t);

/* The sample of a light at p through the point q of a surface that glows
 * with `radiance` towards unit normal n_q, q chosen with `density` per unit
 * area: false when p is behind it. `in_scene`: the surface is in the scene,
 * so the shadow segment stops just short of it. */
bool light_surface_point(vec3 p, vec3 q, vec3 n_q, double density, color radiance, bool in_scene,
                         light_sample *out);

/* The light of shape s, the scene's shape number `index`, glowing with
 * `radiance` from its front (an emitter): false, and *l untouched, for a
 * shape of no finite area (a plane). */
bool emitter_for_shape(light *l, const shape *s, int index, color radiance);

/* Makes every emitter of the `count` at `emitters` that glows over the
 * scene's shape number `index` glow over s, as it now is: moving with it. */
void emitters_follow_shape(light *emitters, int count, int index, const shape *s);

/* The light of the triangles of mesh m placed by inst whose materials
 * (materials[i].m) emit: false when none does, or when out of memory
 * (*out_of_memory set). */
bool emitter_for_instance(light *l, const mesh *m, const instance *inst, const material *materials,
                          bool *out_of_memory);

/* Frees what an emitter owns. */
void light_release(light *l);

extern const light_kind shape_emitter, mesh_emitter;

/* The parameters every light has: its colour and intensity. */
#define LIGHT_COLOR_PARAMS                                                                                     \
    {.key = "color", .type = PARAM_COLOR, .offset = offsetof(light_spec, light.color), .def = {1, 1, 1},     \
     .lo = 0, .hi = DBL_MAX, .meaning = "the light's colour"},                                                \
    {.key = "intensity", .type = PARAM_NUMBER, .offset = offsetof(light_spec, intensity), .def = {1},        \
     .lo = 0, .hi = 1e300, .meaning = "multiplies color"}

/* The colour, intensity and sample count of an area light. */
#define AREA_LIGHT_PARAMS                                                                                      \
    {.key = "color", .type = PARAM_COLOR, .offset = offsetof(light_spec, light.color), .def = {1, 1, 1},     \
     .lo = 0, .hi = DBL_MAX, .meaning = "the radiance of its surface: what a camera sees of it"},             \
    {.key = "intensity", .type = PARAM_NUMBER, .offset = offsetof(light_spec, intensity), .def = {1},        \
     .lo = 0, .hi = 1e300, .meaning = "multiplies color"},                                                    \
    {.key = "samples", .type = PARAM_INTEGER, .offset = offsetof(light_spec, light.samples), .def = {16},    \
     .lo = 1, .hi = 4096, .meaning = "shadow rays towards it from each point it lights: more is smoother"}

#endif
