/* plain_packet.c - a packet whose hits are all of one plain material
 * (Phong and the ambient term, nothing sent on), under delta lights,
 * shaded as one: a floor, a wall or a ball seen by a block of pixels, most
 * packets of most scenes. Once each lane's hit is described, every step of
 * the integrator's shading (the side the hit is seen from, the shadow
 * segments' start, each light's sample and tests, Phong, the ambient term)
 * runs a quad of lanes at a time, on arrays by coordinate: the same
 * operations in the same order as integrator.c's steps lane by lane, so
 * the same bits (lanes.h). Lane by lane, those steps were 62% of a lit
 * floor's instructions (bench/README.md). Where every lane hit the same
 * flat shape, untextured or with a texture flat_texture.c reads (a tiled
 * or checkered floor), even the description runs on quads: the normal is
 * the shape's. Anything else (a mirror, glass, a bump map, area lights,
 * a packet over two materials) goes the general way. */
#include <math.h>
#include <string.h>
#include "render/flat_texture.h"
#include "render/hit.h"
#include "render/lit_lanes.h"
#include "render/plain_packet.h"
#include "render/surface_detail.h"
#include "shading/fog.h"
#include "shading/phong_lanes.h"

bool plain_packet_scene(const glint_scene *scene)
{
    if (scene->area_light_count > 0 || scene->emitter_count > 0 || scene->settings.occlusion_samples > 0)
        return false;
    for (int l = 0; l < scene->light_count; l++)
        if (!scene->lights[l].kind->delta || light_moves(&scene->lights[l]))
            return false;
    return true;
}

/* Whether m's hits are shaded by Phong and the ambient term alone, with
 * steps quads have: no ray sent on, nothing tilting the normal, nothing
 * absorbed, no metallic tint, a whole specular exponent. */
static bool plain_material(const glint_material *m)
{
    return !material_has_detail(m) && !material_branches(m) && !material_absorbs(m) && !(m->metallic > 0) &&
           (!(m->specular > 0) || lobe_exponent_whole(m->shininess));
}

/* Describes into ll the hits of the lanes found[i], all on flat shape k
 * of material m, untextured or with a texture flat_texture reads:
 * shade_begin's steps with the shape's normal, on quads, the footprint a
 * texture is averaged over widening with travelled[i]; front[i]: lane i
 * sees the shape's front. */
static void plain_describe_flat(const tracer *tr, const ray8 *r, const accel_hit hits[ACCEL_PACKET],
                                const bool found[ACCEL_PACKET], const double travelled[ACCEL_PACKET], int k,
                                const glint_material *m, lit_lanes *ll, bool front[ACCEL_PACKET])
{
    const glint_scene *scene = tr->scene;
    const texture *tex = m->texture >= 0 ? &scene->textures[m->texture] : NULL;
    const vec3 flat_n = scene->shapes[k].flat_n;
    const double fn[3] = {flat_n.x, flat_n.y, flat_n.z};
    for (int h = 0; h < ACCEL_PACKET; h += QUAD) {
        /* A lane without a hit has none to read: its values are left out
         * later. Each quad is built from its lanes' values, not stored lane
         * by lane and loaded whole (the load waits for the stores: 5% of
         * a tiled floor's packet time in the profile-guided build). */
#define HIT_LANE(j, field) (found[h + (j)] ? hits[h + (j)].field : 0)
        const quad_f64 t = {HIT_LANE(0, t), HIT_LANE(1, t), HIT_LANE(2, t), HIT_LANE(3, t)};
        const quad_mask part = {HIT_LANE(0, on_shape.part), HIT_LANE(1, on_shape.part), HIT_LANE(2, on_shape.part),
                                HIT_LANE(3, on_shape.part)};
#undef HIT_LANE
        const quad_mask flipped = (part & SHAPE_PART_FLIPPED) != 0;
        const quad_f64 d[3] = {LANES(r->dx, h), LANES(r->dy, h), LANES(r->dz, h)};
        const quad_f64 o[3] = {LANES(r->ox, h), LANES(r->oy, h), LANES(r->oz, h)};
        quad_f64 n[3], p[3];
        for (int c = 0; c < 3; c++) {
            p[c] = o[c] + d[c] * t;
            quad_store(ll->p[c] + h, p[c]);
            n[c] = quad_select(flipped, quad_splat(-fn[c]), quad_splat(fn[c]));
        }
        quad_mask faces = quad_dot(d[0], d[1], d[2], n[0], n[1], n[2]) < 0;
        quad_mask_store(front + h, faces);
        quad_f64 base[3] = {quad_splat(m->color.r), quad_splat(m->color.g), quad_splat(m->color.b)};
        if (tex) {
            quad_f64 width = tr->cone_width + tr->cone_spread * (LANES(travelled, h) + t);
            flat_texture_colors4(tex, p, n, d, width, quad_from_bools(found + h), base);
        }
        for (int c = 0; c < 3; c++) {
            n[c] = quad_select(faces, n[c], -n[c]);
            quad_store(ll->n[c] + h, n[c]);
            quad_store(ll->ns[c] + h, n[c]);
            quad_store(ll->surface_n[c] + h, quad_splat(0));
            quad_store(ll->to_eye[c] + h, -d[c]);
            quad_store(ll->base[c] + h, base[c]);
        }
    }
    /* A flat shape is always left behind (hit_left_behind), unless it is
     * a part of a combination. */
    bool always, when_leaving;
    int skip = shape_left_behind_by(scene->shapes, k, &always, &when_leaving);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        ll->leaves_behind[i] = skip;
        ll->always_behind[i] = always;
        ll->behind_when_leaving[i] = when_leaving;
    }
    lit_lanes_set_one_material(ll, m);
}

/* Describes into ll the hits of the lanes found[i] one at a time
 * (hit_surface, a mesh hit's distance refined into hits[i].t), dropping
 * those the fog hides from found, and reads their colours as the
 * integrator's shade_colors does, the footprint widening with
 * travelled[i]; front[i]: lane i sees the surface's front. */
static void plain_describe_each(const tracer *t, const ray8 *r, const ray lane_ray[ACCEL_PACKET],
                                accel_hit hits[ACCEL_PACKET], bool found[ACCEL_PACKET],
                                const double travelled[ACCEL_PACKET], const glint_material *m, lit_lanes *ll,
                                bool front[ACCEL_PACKET])
{
    const glint_scene *scene = t->scene;
    bool fog = scene->fog.kind != GLINT_FOG_NONE;
    surface s[ACCEL_PACKET];
    texture_read reads[ACCEL_PACKET];
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!found[i])
            continue;
        const ray *ri = &lane_ray[i];
        hit_surface(scene, ri, &hits[i], &s[i]);
        if (fog && fog_hides(&scene->fog, hits[i].t)) {
            found[i] = false;
            continue;
        }
        front[i] = v3_dot(ri->d, s[i].n) < 0;
        if (m->texture >= 0) {
            double width = t->cone_width + t->cone_spread * (travelled[i] + hits[i].t);
            hit_texture_where(scene, &hits[i], m, &s[i], ri->d, width, &reads[i]);
        }
    }
    color base[ACCEL_PACKET];
    if (m->texture >= 0)
        texture_read_colors8(reads, found, base);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!found[i]) {
            lit_lanes_set_none(ll, i);
            continue;
        }
        vec3 n = front[i] ? s[i].n : v3_neg(s[i].n), ns = front[i] ? s[i].shading_n : v3_neg(s[i].shading_n);
        lit_lanes_set_hit(ll, i, scene, &hits[i], s[i].p, n, ns, s[i].n, v3(-r->dx[i], -r->dy[i], -r->dz[i]));
        color c = m->texture >= 0 ? base[i] : m->color;
        ll->base[0][i] = c.r;
        ll->base[1][i] = c.g;
        ll->base[2][i] = c.b;
    }
    lit_lanes_set_one_material(ll, m);
}

/* Where ll's shadow segments start (offset_point's: along n, by the
 * largest coordinate, at least 1) and the colour each lane starts from:
 * the ambient term and, seen from the front (front[i]), the glow (the
 * integrator's ambient_term and glow). */
static void plain_start(const glint_scene *scene, const glint_material *m, const bool front[ACCEL_PACKET],
                        lit_lanes *ll)
{
    const color ambient = scene->settings.ambient_light;
    const color glow = m->emission_strength > 0 ? material_emission(m) : rgb(0, 0, 0);
    const double amb[3] = {ambient.r, ambient.g, ambient.b}, glows[3] = {glow.r, glow.g, glow.b};
    for (int h = 0; h < ACCEL_PACKET; h += QUAD) {
        const quad_f64 p[3] = {LANES(ll->p[0], h), LANES(ll->p[1], h), LANES(ll->p[2], h)};
        quad_f64 ax = quad_abs(p[0]), ay = quad_abs(p[1]), az = quad_abs(p[2]);
        quad_f64 scale = quad_select(ax > ay, ax, ay);
        scale = quad_select(az > scale, az, scale);
        scale = quad_select(scale > 1.0, scale, quad_splat(1.0));
        quad_f64 step = quad_splat(1e-7) * scale;
        quad_mask seen_front = quad_from_bools(front + h);
        for (int c = 0; c < 3; c++) {
            quad_store(ll->origin[c] + h, p[c] + LANES(ll->n[c], h) * step);
            quad_f64 lit_by_ambient = LANES(ll->base[c], h) * amb[c] * m->ambient;
            quad_store(ll->direct[c] + h,
                       lit_by_ambient + quad_select(seen_front, quad_splat(glows[c]), quad_splat(0)));
        }
    }
}

bool plain_packet_shade(tracer *t, const ray8 *r, const ray lane_ray[ACCEL_PACKET], accel_hit hits[ACCEL_PACKET],
                        bool found[ACCEL_PACKET], int depth, const double travelled[ACCEL_PACKET],
                        color local[ACCEL_PACKET])
{
    const glint_scene *scene = t->scene;
    const glint_material *m = NULL;
    int k = -1;
    bool one_shape = true;
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!found[i])
            continue;
        const glint_material *mi = hit_material(scene, &hits[i]);
        if (!m) {
            if (!plain_material(mi))
                return false;
            m = mi;
            k = hits[i].shape;
        }
        if (mi != m)
            return false;
        one_shape &= hits[i].shape == k;
    }
    if (!m)
        return false;
    lit_lanes ll; /* each lane filled by the description, found or not */
    bool front[ACCEL_PACKET] = {false};
    const shape *s = k >= 0 ? &scene->shapes[k] : NULL;
    if (one_shape && s && s->flat && !s->pose_count &&
        (m->texture < 0 || flat_texture_on_quads(&scene->textures[m->texture]))) {
        bool fog = scene->fog.kind != GLINT_FOG_NONE;
        for (int i = 0; i < ACCEL_PACKET; i++)
            found[i] &= !(fog && fog_hides(&scene->fog, hits[i].t));
        plain_describe_flat(t, r, hits, found, travelled, k, m, &ll, front);
    } else {
        plain_describe_each(t, r, lane_ray, hits, found, travelled, m, &ll, front);
    }
    plain_start(scene, m, front, &ll);
    for (int l = 0; l < scene->light_count && !tracer_stopping(t); l++) {
        light_samples8 ls;
        light_delta_lanes(&scene->lights[l], ll.p, found, &ls);
        lit_lanes_light(t, r, &ll, depth, &ls, 1);
    }
    for (int i = 0; i < ACCEL_PACKET; i++)
        if (found[i])
            local[i] = rgb(ll.direct[0][i], ll.direct[1][i], ll.direct[2][i]);
    return true;
}
