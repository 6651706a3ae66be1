/* lit_lanes.c - a packet's hits as arrays of lanes (lit_lanes.h), and
 * each light sample's steps on them a quad of lanes at a time: the tests
 * of shadow_segment and phong_reaches, the shadow packet, then light_share
 * and phong_light, in the order and with the operations of the
 * integrator's lane-by-lane steps, so the same bits (lanes.h). */
#include <string.h>
#include "render/hit.h"
#include "render/lit_lanes.h"
#include "render/shadow_filter.h"
#include "shading/phong_lanes.h"

void lit_lanes_clear(lit_lanes *ll)
{
    memset(ll, 0, offsetof(lit_lanes, direct));
    for (int i = 0; i < ACCEL_PACKET; i++)
        ll->leaves_behind[i] = -1;
}

void lit_lanes_set_none(lit_lanes *ll, int i)
{
    for (int c = 0; c < 3; c++)
        ll->p[c][i] = ll->n[c][i] = ll->ns[c][i] = ll->surface_n[c][i] = ll->to_eye[c][i] = ll->base[c][i] = 0;
    ll->leaves_behind[i] = -1;
    ll->always_behind[i] = ll->behind_when_leaving[i] = false;
}

/* Whether m's specular lobe, if it has one, is lit on the quads: a whole
 * exponent (quad_lobe_pow's squarings) and no metallic tint, which
 * phong_light gives a lane at a time. */
static bool quad_lobe(const glint_material *m)
{
    return lobe_exponent_whole(m->shininess) && !(m->metallic > 0);
}

void lit_lanes_set_material(lit_lanes *ll, int i, const glint_material *m, color base)
{
    const double channels[3] = {base.r, base.g, base.b};
    for (int c = 0; c < 3; c++) {
        ll->base[c][i] = channels[c];
        ll->diffuse_in[c][i] = m->diffuse > 0 && channels[c] > 0;
    }
    ll->m[i] = m;
    ll->diffuse[i] = m->diffuse;
    ll->specular[i] = m->specular;
    ll->shininess[i] = m->shininess;
    bool on_quads = quad_lobe(m);
    ll->lobe[i] = m->specular > 0 && on_quads;
    ll->by_phong[i] = m->specular > 0 && !on_quads;
    ll->any_by_phong |= ll->by_phong[i];
}

void lit_lanes_set_one_material(lit_lanes *ll, const glint_material *m)
{
    bool on_quads = quad_lobe(m), diffuse = m->diffuse > 0;
    for (int i = 0; i < ACCEL_PACKET; i++) {
        for (int c = 0; c < 3; c++)
            ll->diffuse_in[c][i] = diffuse && ll->base[c][i] > 0;
        ll->m[i] = m;
        ll->diffuse[i] = m->diffuse;
        ll->specular[i] = m->specular;
        ll->shininess[i] = m->shininess;
        ll->lobe[i] = m->specular > 0 && on_quads;
        ll->by_phong[i] = m->specular > 0 && !on_quads;
    }
    ll->any_by_phong = m->specular > 0 && !on_quads;
}

/* Lane i of an array of a packet's vectors (or colours), by coordinate. */
static vec3 lane_vec(const double a[3][ACCEL_PACKET], int i) { return v3(a[0][i], a[1][i], a[2][i]); }
static color lane_color(const double a[3][ACCEL_PACKET], int i) { return rgb(a[0][i], a[1][i], a[2][i]); }

/* quad_lobe_cos for the lanes h to h + 3 of ll's hits. */
static inline quad_f64 lanes_lobe_cos(const lit_lanes *ll, int h, const quad_f64 to_light[3])
{
    const quad_f64 ns[3] = {LANES(ll->ns[0], h), LANES(ll->ns[1], h), LANES(ll->ns[2], h)};
    const quad_f64 to_eye[3] = {LANES(ll->to_eye[0], h), LANES(ll->to_eye[1], h), LANES(ll->to_eye[2], h)};
    return quad_lobe_cos(ns, to_light, to_eye);
}

void lit_lanes_light(tracer *t, const ray8 *r, lit_lanes *ll, int depth, const light_samples8 *ls, double share)
{
    ray8 shadow;
    double n_dot_l[ACCEL_PACKET], lobe_cosine[ACCEL_PACKET];
    int skip[ACCEL_PACKET];
    bool lit[ACCEL_PACKET];
    int count = 0;
    for (int h = 0; h < ACCEL_PACKET; h += QUAD) {
        const quad_f64 d[3] = {LANES(ls->to_light[0], h), LANES(ls->to_light[1], h), LANES(ls->to_light[2], h)};
        const quad_f64 radiance[3] = {LANES(ls->radiance[0], h), LANES(ls->radiance[1], h),
                                      LANES(ls->radiance[2], h)};
        quad_f64 facing = quad_dot(LANES(ll->n[0], h), LANES(ll->n[1], h), LANES(ll->n[2], h), d[0], d[1], d[2]);
        quad_f64 shading = quad_dot(LANES(ll->ns[0], h), LANES(ll->ns[1], h), LANES(ll->ns[2], h), d[0], d[1], d[2]);
        quad_f64 cosine = lanes_lobe_cos(ll, h, d);
        /* shadow_segment's tests (NaN passes them as it did there), then
         * phong_reaches's: the diffuse term, or else the lobe. */
        quad_mask faces = quad_from_bools(ls->ok + h) & ~(facing <= 0) & ~(shading <= 0);
        quad_mask diffuse = (quad_from_bools(ll->diffuse_in[0] + h) & (radiance[0] > 0)) |
                            (quad_from_bools(ll->diffuse_in[1] + h) & (radiance[1] > 0)) |
                            (quad_from_bools(ll->diffuse_in[2] + h) & (radiance[2] > 0));
        quad_mask shiny = (quad_from_bools(ll->lobe + h) | quad_from_bools(ll->by_phong + h)) &
                          quad_rgb_max_positive(radiance) & (cosine > 0);
        quad_mask on = faces & (diffuse | shiny);
        quad_mask_store(lit + h, on);
        quad_store(n_dot_l + h, shading);
        quad_store(lobe_cosine + h, cosine);
        /* hit_left_behind's shape to skip. */
        quad_f64 leaving = quad_dot(LANES(ll->surface_n[0], h), LANES(ll->surface_n[1], h),
                                    LANES(ll->surface_n[2], h), d[0], d[1], d[2]);
        quad_mask behind = quad_from_bools(ll->always_behind + h) |
                           (quad_from_bools(ll->behind_when_leaving + h) & (leaving > 0));
        for (int k = 0; k < QUAD; k++) {
            skip[h + k] = on[k] && behind[k] ? ll->leaves_behind[h + k] : -1;
            count += on[k] != 0;
        }
        /* A lane without a segment keeps its own ray. */
        quad_store(shadow.ox + h, quad_select(on, LANES(ll->origin[0], h), LANES(r->ox, h)));
        quad_store(shadow.oy + h, quad_select(on, LANES(ll->origin[1], h), LANES(r->oy, h)));
        quad_store(shadow.oz + h, quad_select(on, LANES(ll->origin[2], h), LANES(r->oz, h)));
        quad_store(shadow.dx + h, quad_select(on, d[0], LANES(r->dx, h)));
        quad_store(shadow.dy + h, quad_select(on, d[1], LANES(r->dy, h)));
        quad_store(shadow.dz + h, quad_select(on, d[2], LANES(r->dz, h)));
    }
    if (!count)
        return;
    t->rays += (unsigned)count;
    color through[ACCEL_PACKET];
    accel_transmission8(t->acc, &shadow, t->time, ls->distance, skip, depth == 0, lit, shadow_filter, t, through);
    for (int h = 0; h < ACCEL_PACKET; h += QUAD) {
        const color *th = through + h;
        const quad_f64 passed[3] = {{th[0].r, th[1].r, th[2].r, th[3].r}, {th[0].g, th[1].g, th[2].g, th[3].g},
                                    {th[0].b, th[1].b, th[2].b, th[3].b}};
        /* light_share: black unless something passed; then phong_light,
         * (base * arriving) * (diffuse * n . l) + arriving * (specular *
         * lobe_pow(cosine, shininess)) where the cosine is above 0, with
         * arriving = radiance * share * through. */
        quad_mask adds = quad_from_bools(lit + h) & ~quad_from_bools(ll->by_phong + h);
        quad_mask passes = quad_rgb_max_positive(passed);
        quad_f64 weight = LANES(ll->diffuse, h) * LANES(n_dot_l, h);
        quad_f64 cosine = LANES(lobe_cosine, h);
        quad_mask shines = quad_from_bools(ll->lobe + h) & (cosine > 0);
        /* Other lanes' exponents are 0, not whatever a conversion makes of them. */
        quad_f64 exponent = quad_select(shines, LANES(ll->shininess, h), quad_splat(0));
        quad_f64 gloss = quad_any(shines) ? LANES(ll->specular, h) * quad_lobe_pow(cosine, exponent) : quad_splat(0);
        for (int c = 0; c < 3; c++) {
            quad_f64 arriving = LANES(ls->radiance[c], h) * share * passed[c];
            quad_f64 out = LANES(ll->base[c], h) * arriving * weight;
            out = quad_select(shines, out + arriving * gloss, out);
            /* Black, not left out, where nothing passed: + 0 as there. */
            out = quad_select(passes, out, quad_splat(0));
            quad_f64 sum = LANES(ll->direct[c], h);
            quad_store(ll->direct[c] + h, quad_select(adds, sum + out, sum));
        }
    }
    for (int i = 0; i < ACCEL_PACKET && ll->any_by_phong; i++) {
        if (!lit[i] || !ll->by_phong[i])
            continue;
        /* light_share: black, still added, unless something passed. */
        color arriving = rgb_mul(rgb_scale(light_samples8_radiance(ls, i), share), through[i]), add = rgb(0, 0, 0);
        if (rgb_max(through[i]) > 0)
            add = phong_light(ll->m[i], lane_color(ll->base, i), lane_vec(ll->ns, i), ray8_dir(&shadow, i),
                              lane_vec(ll->to_eye, i), arriving);
        ll->direct[0][i] += add.r;
        ll->direct[1][i] += add.g;
        ll->direct[2][i] += add.b;
    }
}
