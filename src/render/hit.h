/* hit.h - what the renderer knows of a hit: given the accelerator's
 * accel_hit and the ray that found it, the material there, the surface (a
 * mesh hit's distance refined), its colour, which shape a ray leaving it
 * need not test, and which shapes
 * and mesh placements block all light. Whether a hit is an analytic shape's
 * or a mesh triangle's is asked here and nowhere else in the renderer, so
 * the integrator is written once for both (and for any kind of thing a
 * scene gains later).
 *
 * The per-hit calls are defined here, static, for the integrator to
 * compile as its own: they run for every hit of every ray. Not `inline`:
 * with the keyword GCC inlined them early, then left shape_surface and the
 * texture look-up out of line in the shading (seed room +1.2%, bunny +1.3%
 * instructions); as functions in hit.c, even with link-time optimisation,
 * +2.2% and +2.3%. Static without it they cost what they did inside the
 * integrator. (`unused`: a file that includes this and calls only some of
 * them is no mistake.) */
#ifndef GLINT_RENDER_HIT_H
#define GLINT_RENDER_HIT_H

#include <stdbool.h>
#include "accel/accel.h"
#include "scene/scene.h"

/* The mesh of a mesh triangle's hit (h->shape < 0), for the calls below. */
static __attribute__((unused)) const mesh *hit_mesh(const glint_scene *scene, const accel_hit *h)
{
    return &scene->meshes[scene->instances[h->instance].mesh];
}

/* The material at hit h. */
static __attribute__((unused)) const glint_material *hit_material(const glint_scene *scene, const accel_hit *h)
{
    if (h->shape >= 0)
        return &scene->materials[shape_material(&scene->shapes[h->shape], h->on_shape.part)].m;
    return &scene->materials[mesh_material(hit_mesh(scene, h), &scene->instances[h->instance], h->triangle)].m;
}

/* Describes the surface at hit h of ray r, all but a shape's uv (which
 * hit_texture_where computes when a texture asks). A mesh hit's h->t is Embree's
 * single-precision distance until this refines it in double precision, so
 * anything that compares the distance exactly (fog) comes after it. */
static __attribute__((unused)) void hit_surface(const glint_scene *scene, const ray *r, accel_hit *h, surface *s)
{
    if (h->shape >= 0) {
        const shape *sh = &scene->shapes[h->shape];
        if (sh->pose_count)
            shape_surface_moved(sh, h->time, r, &h->on_shape, s);
        else
            shape_surface(sh, r, &h->on_shape, s);
        return;
    }
    const instance *inst = &scene->instances[h->instance];
    if (inst->pose_count)
        mesh_surface_moved(hit_mesh(scene, h), inst, h->time, r, h->triangle, h->b1, h->b2, &h->t, s);
    else
        mesh_surface(hit_mesh(scene, h), inst, r, h->triangle, h->b1, h->b2, &h->t, s);
}

/* Where a textured hit reads its texture t: a solid texture at its placed
 * point `at`; any other at placed (u, v) = (at.x, at.y), over a footprint
 * reaching `covered` about them. */
typedef struct texture_read {
    const texture *t;
    vec3 at;
    uv_extent covered;
} texture_read;

/* Where the hit h (hit_surface's s) on material m, which has a texture,
 * reads it, seen along unit direction d by a sample whose footprint there
 * is `width` across (0: a point, no filtering). A shape's uv is filled
 * into s only when the texture maps by it; a mesh carries its own. Apart
 * from the look-up (texture_read_color) so that a packet finds where all
 * its lanes read before it reads any: each lane's chain from hit to texel
 * is long, and the processor overlaps the lanes' look-ups only when they
 * no longer wait behind each other's (a tiled image floor: 26% faster). */
void hit_texture_where(const glint_scene *scene, const accel_hit *h, const glint_material *m, surface *s, vec3 d,
                       double width, texture_read *out);

/* The colour read at r (hit_texture_where's). */
static inline color texture_read_color(const texture_read *r)
{
    if (r->t->kind->solid)
        return r->t->kind->solid(r->t, r->at);
    return texture_at_placed(r->t, r->at.x, r->at.y, r->covered);
}

/* texture_read_color of reads[i] into out[i], for each lane i of a packet
 * in `wanted`: lanes reading one noise texture (a kind with solid4) four
 * at a time, whose hashes and blends then run on four lanes' points in one
 * go, where one lane's noise alone leaves most of the processor idle; and
 * lanes reading one image (a kind with eval4) four at a time, their levels
 * and texels found together. */
void texture_read_colors8(const texture_read reads[ACCEL_PACKET], const bool wanted[ACCEL_PACKET],
                          color out[ACCEL_PACKET]);

/* The colour of material m at the hit h (hit_surface's s), as
 * hit_texture_where's arguments say, for one hit alone. */
static inline color hit_color(const glint_scene *scene, const accel_hit *h, const glint_material *m, surface *s,
                              vec3 d, double width)
{
    if (m->texture < 0)
        return m->color;
    texture_read r;
    hit_texture_where(scene, h, m, s, d, width, &r);
    return texture_read_color(&r);
}

/* The shape a ray leaving hit h along d cannot meet again, which the
 * accelerator then need not test (accel_intersect8's skip), or -1: the
 * shape hit, or the combination it is a part of (shape_left_behind_by). n
 * is the surface's outward normal there (hit_surface's s.n). Mesh
 * triangles are never skipped: a ray may meet the same mesh again. */
static __attribute__((unused)) int hit_left_behind(const glint_scene *scene, const accel_hit *h, vec3 n, vec3 d)
{
    if (h->shape < 0)
        return -1;
    bool always, when_leaving;
    int skip = shape_left_behind_by(scene->shapes, h->shape, &always, &when_leaving);
    return always || (when_leaving && v3_dot(n, d) > 0) ? skip : -1;
}

/* Asks the processor to start loading what hit_surface will read of h: a
 * large mesh's vertices are seldom in cache, and the loads of a packet's
 * hits then overlap. Nothing to do for a shape. */
static __attribute__((unused)) void hit_prefetch(const glint_scene *scene, const accel_hit *h)
{
    if (h->shape < 0)
        mesh_prefetch(hit_mesh(scene, h), h->triangle);
}

/* The accelerator's opacity lists (accel_geometry's shape_opaque and
 * instance_opaque): which shapes, and which mesh placements over all their
 * triangles, block all light, so that a shadow ray stops at them without
 * asking what passes. *shapes and *instances are the caller's to free
 * (both, even on failure); false when memory runs out. */
bool hit_opacity(const glint_scene *scene, bool **shapes, bool **instances);

#endif
