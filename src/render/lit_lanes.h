/* lit_lanes.h - a packet's hits as arrays of lanes, and the light one
 * light's samples bring them, a quad of lanes at a time: the integrator
 * gathers its hits so once for all the samples they take of the area
 * lights (one lane at a time those steps were a quarter of a Cornell box),
 * and a plain packet (plain_packet.c) for its delta lights. */
#ifndef GLINT_RENDER_LIT_LANES_H
#define GLINT_RENDER_LIT_LANES_H

#include "render/integrator.h"
#include "shading/light.h"

/* The hits of a packet's lanes by coordinate, lane i of each array, and the
 * direct light they gather. A lane not described holds no hit: zeros,
 * shape -1. */
typedef struct lit_lanes {
    double p[3][ACCEL_PACKET];        /* the hit */
    double origin[3][ACCEL_PACKET];   /* where its shadow segments start */
    double n[3][ACCEL_PACKET], ns[3][ACCEL_PACKET]; /* geometric and shading normals, on the viewer's side */
    double surface_n[3][ACCEL_PACKET]; /* the surface's own normal, for hit_left_behind */
    double to_eye[3][ACCEL_PACKET];
    double base[3][ACCEL_PACKET];     /* the surface colour */
    const glint_material *m[ACCEL_PACKET];
    double diffuse[ACCEL_PACKET], specular[ACCEL_PACKET], shininess[ACCEL_PACKET];
    bool diffuse_in[3][ACCEL_PACKET]; /* the diffuse term has channel c: diffuse and base's c above 0 */
    bool lobe[ACCEL_PACKET];          /* an untinted specular lobe of a whole exponent (lobe_pow's squarings) */
    bool by_phong[ACCEL_PACKET];      /* a lobe of another exponent or with a metallic tint: that lane's
                                         light by phong_light */
    bool any_by_phong;
    int leaves_behind[ACCEL_PACKET];  /* the shape a ray leaving the hit may skip, or -1, */
    bool always_behind[ACCEL_PACKET]; /* and when (shape_left_behind_by's answers) */
    bool behind_when_leaving[ACCEL_PACKET];
    double direct[3][ACCEL_PACKET];   /* the light gathered, */
    bool gathering;                   /* while the integrator gathers it here */
    bool described;                   /* the fields above direct are filled */
} lit_lanes;

/* The quad of lanes h to h + 3 of an array of a packet's lanes. */
#define LANES(array, h) quad_load((array) + (h))

/* Clears ll's description of its hits: no lane holds one. */
void lit_lanes_clear(lit_lanes *ll);

/* Lane i of ll holds no hit. */
void lit_lanes_set_none(lit_lanes *ll, int i);

/* Lane i of ll describes the hit h at p, with normals n and ns turned to
 * the viewer, the surface's own normal surface_n, seen from to_eye: all
 * but its material, colour and origin. Inline: it runs for every lane of
 * a plain packet that is not flat. */
static inline void lit_lanes_set_hit(lit_lanes *ll, int i, const glint_scene *scene, const accel_hit *h, vec3 p, vec3 n,
                                     vec3 ns, vec3 surface_n, vec3 to_eye)
{
    const double pv[3] = {p.x, p.y, p.z}, nv[3] = {n.x, n.y, n.z}, nsv[3] = {ns.x, ns.y, ns.z};
    const double sn[3] = {surface_n.x, surface_n.y, surface_n.z}, eye[3] = {to_eye.x, to_eye.y, to_eye.z};
    for (int c = 0; c < 3; c++) {
        ll->p[c][i] = pv[c];
        ll->n[c][i] = nv[c];
        ll->ns[c][i] = nsv[c];
        ll->surface_n[c][i] = sn[c];
        ll->to_eye[c][i] = eye[c];
    }
    ll->leaves_behind[i] = -1;
    ll->always_behind[i] = ll->behind_when_leaving[i] = false;
    if (h->shape >= 0)
        ll->leaves_behind[i] = shape_left_behind_by(scene->shapes, h->shape, &ll->always_behind[i],
                                                    &ll->behind_when_leaving[i]);
}

/* Lane i of ll is of material m and surface colour base. */
void lit_lanes_set_material(lit_lanes *ll, int i, const glint_material *m, color base);

/* Every lane of ll is of material m, its surface colour already in
 * ll->base. */
void lit_lanes_set_one_material(lit_lanes *ll, const glint_material *m);

/* Adds to ll's direct light what one light's samples ls bring to each
 * lane's hit (lane i where ls->ok[i]), their radiance weighed by `share`,
 * as the integrator's steps lane by lane would (the same bits): one
 * packet of shadow segments from the origins over the lanes they light
 * (t->rays counts them), for hits of the rays r at recursion depth
 * `depth`. */
void lit_lanes_light(tracer *t, const ray8 *r, lit_lanes *ll, int depth, const light_samples8 *ls, double share);

#endif
