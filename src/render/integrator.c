/* integrator.c - Whitted ray tracing: Phong shading with shadows that pass
 * through transparent objects, mirror reflection, straight-through
 * transparency, refraction with optional Fresnel, and fog per segment. */
#include <math.h>
#include <stddef.h>
#include <string.h>
#include "core/hash.h"
#include "core/sobol.h"
#include "core/square_maps.h"
#include "render/hit.h"
#include "render/integrator.h"
#include "render/lit_lanes.h"
#include "render/plain_packet.h"
#include "render/shadow_filter.h"
#include "render/surface_detail.h"
#include "shading/environment.h"
#include "shading/fog.h"
#include "shading/optics.h"
#include "shading/phong_lanes.h"
#include "shading/spectrum.h"

/* New rays start this far off the surface, relative to the scene scale at
 * the point, so they do not hit the surface they leave. */
static vec3 offset_point(vec3 p, vec3 n)
{
    /* Comparisons, not fmax: this runs for every ray, and fmax is a call. */
    double ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);
    double scale = ax > ay ? ax : ay;
    scale = az > scale ? az : scale;
    scale = scale > 1.0 ? scale : 1.0;
    return v3_madd(p, n, 1e-7 * scale);
}

/* What shading needs of a hit, between finding it and finishing its colour. */
typedef struct shade_point {
    accel_hit hit;
    const glint_material *m;
    surface s;
    vec3 n, ns;               /* geometric and shading normals on the viewer's side */
    bool front;               /* the viewer is on the surface's front (outside) */
    vec3 origin;              /* where shadow rays start: p moved off the surface along n */
    color base;               /* the surface colour */
} shade_point;

/* What each lane of a packet carries from the camera: its weight in its
 * sample (the product of the filters and shares along its path), the
 * wavelength of its light (0: white; see spectrum.h) and the length of
 * its path to where it starts, along which a pixel's footprint widens. */
typedef struct paths {
    color weight[ACCEL_PACKET];
    double wavelength[ACCEL_PACKET];
    double travelled[ACCEL_PACKET];
} paths;

/* Describes the hit h of ray r for shading, its distance refined where
 * Embree's was single precision (hit_surface), all but its colour
 * (shade_colors). */
static void shade_begin(const tracer *t, const ray *r, const accel_hit *h, shade_point *sp)
{
    const glint_scene *scene = t->scene;
    sp->hit = *h;
    sp->m = hit_material(scene, h);
    hit_surface(scene, r, &sp->hit, &sp->s);
    if (material_has_detail(sp->m))
        surface_detail(scene, &sp->hit, sp->m, r->d, &sp->s);
    bool front = sp->front = v3_dot(r->d, sp->s.n) < 0;
    sp->n = front ? sp->s.n : v3_neg(sp->s.n);
    sp->ns = front ? sp->s.shading_n : v3_neg(sp->s.shading_n);
    sp->origin = offset_point(sp->s.p, sp->n);
}

/* The surface colours of a packet's lanes in `found` (shade_begin's), seen
 * along rays r that have travelled path->travelled before them (the
 * footprint a texture is averaged over widens with the whole path): where
 * every textured lane reads is found before any reads (hit.h says why). */
static void shade_colors(const tracer *t, const ray r[ACCEL_PACKET], const bool found[ACCEL_PACKET],
                         const paths *path, shade_point sp[ACCEL_PACKET])
{
    texture_read reads[ACCEL_PACKET];
    bool textured[ACCEL_PACKET] = {false}, any = false;
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!found[i])
            continue;
        if (sp[i].m->texture < 0) {
            sp[i].base = sp[i].m->color;
            continue;
        }
        double width = t->cone_width + t->cone_spread * (path->travelled[i] + sp[i].hit.t);
        hit_texture_where(t->scene, &sp[i].hit, sp[i].m, &sp[i].s, r[i].d, width, &reads[i]);
        textured[i] = any = true;
    }
    if (!any)
        return;
    color base[ACCEL_PACKET];
    texture_read_colors8(reads, textured, base);
    for (int i = 0; i < ACCEL_PACKET; i++)
        if (textured[i])
            sp[i].base = base[i];
}

/* The shadow segment from sp, seen along ray r, towards light l sampled
 * with (u1, u2), when l lights sp's front and its light there is not black
 * before any shadow. */
__attribute__((always_inline)) static inline bool shadow_segment(const ray *r, const shade_point *sp,
                                                                  const light_sample *ls, ray *shadow)
{
    if (v3_dot(sp->n, ls->to_light) <= 0 || v3_dot(sp->ns, ls->to_light) <= 0 ||
        !phong_reaches(sp->m, sp->base, sp->ns, ls->to_light, v3_neg(r->d), ls->radiance))
        return false;
    *shadow = (ray){sp->origin, ls->to_light};
    return true;
}

/* Light l's share at sp, given what passes the shadow segment. */
__attribute__((always_inline)) static inline color light_share(const shade_point *sp, const light_sample *ls, color through, vec3 to_eye)
{
    if (!(rgb_max(through) > 0))
        return rgb(0, 0, 0);
    return phong_light(sp->m, sp->base, sp->ns, ls->to_light, to_eye, rgb_mul(ls->radiance, through));
}

/* The ambient term at sp, before any occlusion. */
static color ambient_term(const glint_scene *scene, const shade_point *sp)
{
    return rgb_scale(rgb_mul(sp->base, scene->settings.ambient_light), sp->m->ambient);
}

/* What sp gives off towards a viewer on its front. */
static color glow(const shade_point *sp)
{
    return sp->front && sp->m->emission_strength > 0 ? material_emission(sp->m) : rgb(0, 0, 0);
}

/* The rays a hit sends on, in the order their light is added: straight
 * through, refracted, mirrored. Each brings back its colour times `filter`
 * times `scale`, and `weight` is what its colour counts for in the sample. */
enum { BRANCH_PASS, BRANCH_REFRACT, BRANCH_MIRROR, BRANCHES };

typedef struct branches {
    ray r[BRANCHES];
    vec3 side[BRANCHES];      /* the side of the surface each leaves to (its offset normal) */
    int skip[BRANCHES];       /* the shape each cannot meet again, or -1 */
    color filter[BRANCHES];
    double scale[BRANCHES];
    color weight[BRANCHES];
    unsigned on;              /* bit k: branch k is open */
} branches;

/* The ray leaving sp along unit direction d, starting on the side of the
 * surface that d points to (*side, its offset normal), and the shape it
 * cannot meet again (*skip, or -1). */
static ray leaving_ray(const glint_scene *scene, const shade_point *sp, vec3 d, vec3 *side, int *skip)
{
    vec3 n = sp->n;
    *side = v3_dot(d, n) > 0 ? n : v3_neg(n);
    *skip = hit_left_behind(scene, &sp->hit, sp->s.n, d);
    return (ray){offset_point(sp->s.p, *side), d};
}

/* Opens branch k of b: a ray leaving sp along unit direction d; unless,
 * for a ray whose own weight is `weight`, it would weigh less than
 * TRACER_MIN_WEIGHT. */
static void branch(const glint_scene *scene, const shade_point *sp, branches *b, int k, vec3 d, color filter,
                   double scale, color weight)
{
    color w = rgb_scale(rgb_mul(weight, filter), scale);
    if (!(rgb_max(w) >= TRACER_MIN_WEIGHT))
        return;
    b->weight[k] = w;
    b->r[k] = leaving_ray(scene, sp, d, &b->side[k], &b->skip[k]);
    b->filter[k] = filter;
    b->scale[k] = scale;
    b->on |= 1u << k;
}

/* The normal a ray along d bends about at sp: the shading normal, unless
 * interpolation turned it away from the ray, where only the geometric one
 * makes sense. */
static vec3 bend_normal(const shade_point *sp, vec3 d)
{
    return v3_dot(d, sp->ns) < 0 ? sp->ns : sp->n;
}

/* n_from / n_to for light of `wavelength` (0: white) crossing sp's surface
 * along d. */
static double crossing_eta(const shade_point *sp, vec3 d, double wavelength)
{
    double ior = material_index_at(sp->m, wavelength);
    return v3_dot(d, sp->s.n) < 0 ? 1.0 / ior : ior;
}

/* Whether white light along a ray that sees sp splits into the spectrum's
 * bands as it refracts there. */
static bool splits(const shade_point *sp, double wavelength)
{
    return wavelength == 0 && sp->m->dispersion > 0;
}

/* The ray that light of `wavelength` along d refracts into at sp, bent by
 * that wavelength's index, or mirrored where it is reflected whole; *side
 * and *skip as leaving_ray's. */
static ray band_ray(const glint_scene *scene, const shade_point *sp, vec3 d, double wavelength, vec3 *side,
                    int *skip)
{
    vec3 bend = bend_normal(sp, d), out;
    if (!optics_refract(d, bend, crossing_eta(sp, d, wavelength), &out))
        out = optics_reflect(d, bend);
    return leaving_ray(scene, sp, out, side, skip);
}

/* What ray r, of weight `weight` and light of `wavelength` (0: white),
 * keeps at sp of its direct light, the rest being passed on; below
 * max_depth, fills *b with the rays that carry transparency, refraction
 * and reflection. White light meeting a dispersive material opens one
 * refracted branch, which trace_branch splits by band. */
static color shade_local(const glint_scene *scene, const ray *r, const shade_point *sp, color direct, int depth,
                         color weight, double wavelength, branches *b)
{
    const glint_material *m = sp->m;
    double transmitted = m->transparency + m->refraction;
    color kept = transmitted > 0 ? rgb_scale(direct, 1 - transmitted) : direct;
    b->on = 0;
    if (depth >= scene->settings.max_depth || !material_branches(m))
        return kept;

    double mirror = m->reflectivity;
    vec3 bend = bend_normal(sp, r->d);
    color filter = material_filter(m, sp->base);
    if (m->transparency > 0)
        branch(scene, sp, b, BRANCH_PASS, r->d, filter, m->transparency, weight);
    if (m->refraction > 0) {
        double eta = crossing_eta(sp, r->d, wavelength);
        double share = 1;
        vec3 dir;
        if (!optics_refract(r->d, bend, eta, &dir))
            share = 0;
        else if (m->fresnel)
            share = 1 - optics_fresnel(-v3_dot(r->d, bend), eta);
        if (share > 0)
            branch(scene, sp, b, BRANCH_REFRACT, dir, filter, m->refraction * share, weight);
        mirror += m->refraction * (1 - share);
    }
    if (mirror > 0) {
        color tint = m->metallic > 0 ? material_metal_tint(m, sp->base) : rgb(1, 1, 1);
        branch(scene, sp, b, BRANCH_MIRROR, optics_reflect(r->d, bend), tint, mirror, weight);
    }
    return kept;
}

/* What a ray that hits nothing brings back without an environment. */
static color miss(const glint_scene *scene)
{
    return fog_apply(&scene->fog, scene->settings.background, INFINITY);
}

/* With an environment, each active lane of r that found nothing sees it
 * along its ray: it becomes a hit at infinity of that colour, local[i],
 * which fog then covers as it covers a miss. */
static void environment_seen(const glint_scene *scene, const ray8 *r, const bool active[ACCEL_PACKET],
                             bool found[ACCEL_PACKET], accel_hit hits[ACCEL_PACKET], color local[ACCEL_PACKET])
{
    const glint_environment *env = &scene->environment;
    const texture *t = &scene->textures[env->texture];
    /* A solid sky is read as a solid texture is at hits, so a noise sky's
     * lanes go four at a time (texture_read_colors8): one at a time it
     * took twice as long. */
    texture_read reads[ACCEL_PACKET];
    bool sky[ACCEL_PACKET] = {false};
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (found[i] || !active[i])
            continue;
        found[i] = true;
        hits[i].t = INFINITY;
        vec3 d = v3(r->dx[i], r->dy[i], r->dz[i]);
        if (t->kind->solid)
            reads[i] = (texture_read){t, texture_place(t, d), {0, 0}};
        else
            local[i] = environment_color(env, t, d);
        sky[i] = t->kind->solid != NULL;
    }
    if (!t->kind->solid)
        return;
    color seen[ACCEL_PACKET];
    texture_read_colors8(reads, sky, seen);
    for (int i = 0; i < ACCEL_PACKET; i++)
        if (sky[i])
            local[i] = rgb_scale(seen[i], env->intensity);
}

/* Adds to direct[i] the light of delta light l that reaches the hit
 * sp[i] of each lane found[i]: one packet of shadow segments over the
 * lanes it lights, for hits of rays at recursion depth `depth`. */
__attribute__((always_inline)) static inline void light_packet(tracer *t, const ray8 *r, const bool found[ACCEL_PACKET],
                                                                const shade_point sp[ACCEL_PACKET], int depth,
                                                                const light *l, color direct[ACCEL_PACKET])
{
    const glint_scene *scene = t->scene;
    light_sample ls[ACCEL_PACKET];
    /* A lane without a segment keeps its own ray. Copied only once some
     * lane has one: a spotlight lights few packets. */
    ray8 shadow;
    double dist[ACCEL_PACKET] = {0};
    int skip[ACCEL_PACKET] = {-1, -1, -1, -1, -1, -1, -1, -1};
    bool lit[ACCEL_PACKET] = {false}, any = false, moving = t->time && l->pose_count;
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!found[i])
            continue;
        ray ri = ray8_get(r, i), si;
        bool sampled = moving ? light_moved_sample(l, t->time[i], sp[i].s.p, &ls[i])
                              : light_delta_sample(l, sp[i].s.p, &ls[i]);
        if (!sampled || !shadow_segment(&ri, &sp[i], &ls[i], &si))
            continue;
        if (!any)
            shadow = *r;
        lit[i] = any = true;
        dist[i] = ls[i].distance;
        skip[i] = hit_left_behind(scene, &sp[i].hit, sp[i].s.n, ls[i].to_light);
        ray8_set(&shadow, i, si);
        t->rays++;
    }
    if (!any)
        return;
    color through[ACCEL_PACKET];
    accel_transmission8(t->acc, &shadow, t->time, dist, skip, depth == 0, lit, shadow_filter, t, through);
    for (int i = 0; i < ACCEL_PACKET; i++)
        if (lit[i])
            direct[i] = rgb_add(direct[i], light_share(&sp[i], &ls[i], through[i], v3(-r->dx[i], -r->dy[i], -r->dz[i])));
}

/* Fills ll's description of the lanes' hits, seen along r. */
static void lit_lanes_describe(const glint_scene *scene, const ray8 *r, const shade_point sp[ACCEL_PACKET],
                               const bool found[ACCEL_PACKET], lit_lanes *ll)
{
    lit_lanes_clear(ll);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!found[i])
            continue;
        const shade_point *s = &sp[i];
        lit_lanes_set_hit(ll, i, scene, &s->hit, s->s.p, s->n, s->ns, s->s.n, v3(-r->dx[i], -r->dy[i], -r->dz[i]));
        lit_lanes_set_material(ll, i, s->m, s->base);
        ll->origin[0][i] = s->origin.x;
        ll->origin[1][i] = s->origin.y;
        ll->origin[2][i] = s->origin.z;
    }
}

/* Unless ll is gathering already, it starts from direct's light (lane i
 * where found[i]), its hits described the first time. */
static void lit_lanes_take(lit_lanes *ll, const glint_scene *scene, const ray8 *r, const shade_point sp[ACCEL_PACKET],
                           const bool found[ACCEL_PACKET], const color direct[ACCEL_PACKET])
{
    if (ll->gathering)
        return;
    if (!ll->described)
        lit_lanes_describe(scene, r, sp, found, ll);
    ll->described = ll->gathering = true;
    for (int i = 0; i < ACCEL_PACKET; i++) {
        color d = found[i] ? direct[i] : rgb(0, 0, 0);
        ll->direct[0][i] = d.r;
        ll->direct[1][i] = d.g;
        ll->direct[2][i] = d.b;
    }
}

/* If ll is gathering, direct[i] becomes its light where found[i], and it
 * stops. */
static void lit_lanes_give(lit_lanes *ll, const bool found[ACCEL_PACKET], color direct[ACCEL_PACKET])
{
    if (!ll->gathering)
        return;
    ll->gathering = false;
    for (int i = 0; i < ACCEL_PACKET; i++)
        if (found[i])
            direct[i] = rgb(ll->direct[0][i], ll->direct[1][i], ll->direct[2][i]);
}

/* Adds to ll's direct light the light of area light l that reaches each
 * lane's hit through its sample u (lane i of u[0] and u[1]) where lanes[i]
 * is set, weighed by `share`. */
static void area_light_packet(tracer *t, const ray8 *r, const bool lanes[ACCEL_PACKET],
                              const shade_point sp[ACCEL_PACKET], lit_lanes *ll, int depth, const light *l,
                              const double u[2][ACCEL_PACKET], double share)
{
    light_samples8 ls;
    if (t->time && light_moves(l))
        light_moved_lanes(l, t->time, ll->p, u, lanes, &ls);
    else
        l->kind->sample_lanes(l, ll->p, u, lanes, &ls);
    lit_lanes_light(t, r, ll, depth, &ls, share);
}

/* Sample j of a point's 2-D pattern, scrambled by seeds (sobol2_seeds_of
 * the point's own number, worked out once for all its samples): the
 * point's own Owen-scrambled Sobol points (core/sobol.h), stratified in
 * every aligned run of a power of two. Against the shifted Hammersley
 * points they replaced, a soft shadow of 64 samples has 31% less noise for
 * 15-20% more time (bench/README.md). */
static void pattern_point(sobol2_seeds seeds, int j, double u[2])
{
    sobol2_point((uint32_t)j, seeds, &u[0], &u[1]);
}

/* Adds to ll's direct light the light of area light l (the scene's light
 * number `index`, emitters numbered after the lights) that reaches the hit
 * sp[i] of each lane found[i], whose random numbers come from key[i]: one
 * packet of shadow segments per sample, n of them, sample j of lane i
 * pattern_point's j of its own pattern, the eight lanes' at once. Out of
 * line, so that the delta lights' packet stays inlined in direct_light8
 * (the seed room's every shading point) as it was. */
__attribute__((noinline)) static void area_light_packets(tracer *t, const ray8 *r, const bool found[ACCEL_PACKET],
                                                         const shade_point sp[ACCEL_PACKET], lit_lanes *ll,
                                                         int depth, const light *l, int index, int n,
                                                         const uint32_t key[ACCEL_PACKET])
{
    sobol2_seeds8 seeds;
    for (int i = 0; i < ACCEL_PACKET; i++)
        sobol2_seeds8_set(&seeds, i, sobol2_seeds_of(hash_u32(key[i] ^ hash_u32((uint32_t)index + 1))));
    for (int j = 0; j < n && !tracer_stopping(t); j++) {
        double u[2][ACCEL_PACKET];
        sobol2_points8((uint32_t)j, &seeds, u[0], u[1]);
        area_light_packet(t, r, found, sp, ll, depth, l, u, 1.0 / n);
    }
}

/* The radical inverse of j in base 3, a coordinate apart from the base-2
 * Sobol points, so that which light a sample goes to does not follow
 * where on the light it falls. */
static double radical_inverse3(uint32_t j)
{
    double inverse = 0, digit = 1.0 / 3;
    for (; j; j /= 3, digit /= 3)
        inverse += (j % 3) * digit;
    return inverse;
}

/* How many of a point's samples chosen_light_packets chooses lights for
 * at a time, before tracing them. */
#define CHOICE_RUN 32

/* Adds to ll's direct light the light of the area lights and emitters that
 * reaches the hit sp[i] of each lane found[i] with settings.light_samples samples
 * in all (light_choice.h): sample j of lane i goes to the light its
 * number chooses by power, counted divided by that light's chance. The
 * lanes choose their lights for a run of samples first; then each packet
 * of shadow segments goes to one light, holding each lane's next sample
 * that chose it: with many lights, the lanes seldom choose the same one
 * at the same sample, and a packet a sample would hold one or two lanes
 * (30 lamps, 16 samples: a third of the rays a second). */
__attribute__((noinline)) static void chosen_light_packets(tracer *t, const ray8 *r, const bool found[ACCEL_PACKET],
                                                           const shade_point sp[ACCEL_PACKET], lit_lanes *ll,
                                                           int depth, const uint32_t key[ACCEL_PACKET])
{
    const light_choice *choice = t->choice;
    int n = t->scene->settings.light_samples;
    sobol2_seeds seeds[ACCEL_PACKET];
    double shift[ACCEL_PACKET];
    for (int i = 0; i < ACCEL_PACKET; i++) {
        uint32_t rot = hash_u32(key[i] ^ 0x504f5752U);
        seeds[i] = sobol2_seeds_of(rot);
        shift[i] = hash_unit(hash_u32(rot ^ 0x2c1b3c6dU));
    }
    for (int first = 0; first < n && !tracer_stopping(t); first += CHOICE_RUN) {
        int run = n - first < CHOICE_RUN ? n - first : CHOICE_RUN;
        int pick[ACCEL_PACKET][CHOICE_RUN], next[ACCEL_PACKET] = {0};
        for (int k = 0; k < run; k++) {
            /* The same for every lane; each lane shifts it by its own. */
            double base = radical_inverse3((uint32_t)(first + k));
            for (int i = 0; i < ACCEL_PACKET; i++) {
                double v = base + shift[i];
                pick[i][k] = found[i] ? light_choice_pick(choice, v - (v >= 1)) : -1;
            }
        }
        for (;;) {
            /* The light of the first lane's next sample still to trace. */
            int chosen = -1;
            for (int i = 0; i < ACCEL_PACKET; i++) {
                while (next[i] < run && pick[i][next[i]] < 0)
                    next[i]++;
                if (chosen < 0 && next[i] < run)
                    chosen = pick[i][next[i]];
            }
            if (chosen < 0 || tracer_stopping(t))
                break;
            bool chose[ACCEL_PACKET];
            double u[2][ACCEL_PACKET] = {{0}};
            for (int i = 0; i < ACCEL_PACKET; i++) {
                chose[i] = false;
                for (int k = next[i]; k < run && !chose[i]; k++) {
                    if (pick[i][k] != chosen)
                        continue;
                    chose[i] = true;
                    pick[i][k] = -1;
                    sobol2_point((uint32_t)(first + k), seeds[i], &u[0][i], &u[1][i]);
                }
            }
            area_light_packet(t, r, chose, sp, ll, depth, choice->lights[chosen], u,
                              1.0 / (n * light_choice_chance(choice, chosen)));
        }
    }
}

/* Adds to direct[i] the light of every light source, emissive shapes and
 * meshes too, that reaches the hit sp[i] of each lane found[i], whose
 * random numbers come from key[i]: one packet of shadow segments per light
 * (per sample of an area light or emitter), or with settings.light_samples
 * the area lights and emitters sampled together, chosen by power. */
static void direct_light8(tracer *t, const ray8 *r, const bool found[ACCEL_PACKET],
                          const shade_point sp[ACCEL_PACKET], int depth, const uint32_t key[ACCEL_PACKET],
                          color direct[ACCEL_PACKET])
{
    const glint_scene *scene = t->scene;
    /* The area lights' light gathers in ll from the first area light on,
     * and goes back into direct before a delta light adds its own: their
     * lanes one at a time, which four at a time were 6% slower on the
     * depth of field and 12% on the seed room, gathering their hits for
     * one or two lights. */
    lit_lanes ll;
    ll.described = ll.gathering = false;
    for (int l = 0; l < scene->light_count + scene->emitter_count && !tracer_stopping(t); l++) {
        bool emitter = l >= scene->light_count;
        const light *li = emitter ? &scene->emitters[l - scene->light_count] : &scene->lights[l];
        if (li->kind->delta) {
            lit_lanes_give(&ll, found, direct);
            light_packet(t, r, found, sp, depth, li, direct);
        } else if (!t->choice) {
            lit_lanes_take(&ll, scene, r, sp, found, direct);
            area_light_packets(t, r, found, sp, &ll, depth, li, l,
                               emitter ? scene->settings.emission_samples : li->desc.samples, key);
        }
    }
    if (t->choice && t->choice->count > 0 && !tracer_stopping(t)) {
        lit_lanes_take(&ll, scene, r, sp, found, direct);
        chosen_light_packets(t, r, found, sp, &ll, depth, key);
    }
    lit_lanes_give(&ll, found, direct);
}

/* Adds to local[i] the ambient term of the hit sp[i] of each lane found[i]
 * times the share of the sky it sees (ambient occlusion): rays spread over
 * the hemisphere about its shading normal as the cosine, looking as far as
 * occlusion_distance, each bringing back what passes the surfaces it
 * crosses (shadow_filter). A ray of weight 1 sends occlusion_samples of
 * them, one of less weight fewer, at least 1; random numbers from key[i]. */
__attribute__((noinline)) static void ambient_occlusion8(tracer *t, const bool found[ACCEL_PACKET],
                                                         const shade_point sp[ACCEL_PACKET], int depth,
                                                         const color weight[ACCEL_PACKET],
                                                         const uint32_t key[ACCEL_PACKET], color local[ACCEL_PACKET])
{
    const glint_scene *scene = t->scene;
    const glint_settings *st = &scene->settings;
    double reach = st->occlusion_distance > 0 ? st->occlusion_distance : INFINITY;
    int rays[ACCEL_PACKET] = {0}, most = 0;
    sobol2_seeds seeds[ACCEL_PACKET];
    color seen[ACCEL_PACKET];
    vec3 e1[ACCEL_PACKET], e2[ACCEL_PACKET]; /* each lane's frame about its normal */
    for (int i = 0; i < ACCEL_PACKET; i++) {
        seen[i] = rgb(0, 0, 0);
        if (!found[i])
            continue;
        double n = ceil(st->occlusion_samples * rgb_max(weight[i]));
        rays[i] = n < 1 ? 1 : n > st->occlusion_samples ? st->occlusion_samples : (int)n;
        most = rays[i] > most ? rays[i] : most;
        seeds[i] = sobol2_seeds_of(hash_u32(key[i] ^ 0x41f3a9c7U));
        /* Built here, not for each of the lane's rays: the normal is the same for all. */
        plane_basis(sp[i].ns, &e1[i], &e2[i]);
    }
    for (int j = 0; j < most && !tracer_stopping(t); j++) {
        ray8 shadow;
        double dist[ACCEL_PACKET] = {0};
        int skip[ACCEL_PACKET] = {-1, -1, -1, -1, -1, -1, -1, -1};
        bool lit[ACCEL_PACKET] = {false}, any = false;
        for (int i = 0; i < ACCEL_PACKET; i++) {
            if (j >= rays[i])
                continue;
            double u[2], x, y;
            pattern_point(seeds[i], j, u);
            concentric_disk(u[0], u[1], &x, &y);
            vec3 d = v3_add(v3_scale(sp[i].ns, sqrt(fmax(0, 1 - x * x - y * y))),
                            v3_add(v3_scale(e1[i], x), v3_scale(e2[i], y)));
            if (!(v3_dot(d, sp[i].n) > 0))
                continue; /* into the surface: blocked */
            if (!any)
                for (int k = 0; k < ACCEL_PACKET; k++)
                    ray8_set(&shadow, k, (ray){sp[i].origin, d});
            ray8_set(&shadow, i, (ray){sp[i].origin, d});
            lit[i] = any = true;
            dist[i] = reach;
            skip[i] = hit_left_behind(scene, &sp[i].hit, sp[i].s.n, d);
            t->rays++;
        }
        if (!any)
            continue;
        color through[ACCEL_PACKET];
        accel_transmission8(t->acc, &shadow, t->time, dist, skip, depth == 0, lit, shadow_filter, t, through);
        for (int i = 0; i < ACCEL_PACKET; i++)
            if (lit[i])
                seen[i] = rgb_add(seen[i], rgb_scale(through[i], 1.0 / rays[i]));
    }
    for (int i = 0; i < ACCEL_PACKET; i++)
        if (found[i])
            local[i] = rgb_add(local[i], rgb_mul(ambient_term(scene, &sp[i]), seen[i]));
}

/* Which area light, if any, each active lane of r sees before what it hit
 * (found[i], at sp[i].hit.t) or, having hit nothing, before `reach`: then
 * glows[i], and the lane looks like a hit of colour local[i] at
 * sp[i].hit.t, found[i] false until its shading is done. (A hit hidden by
 * fog is not found, and a light behind it is as hidden.) */
__attribute__((noinline)) static void area_lights_seen(const tracer *t, const ray8 *r, const bool active[ACCEL_PACKET],
                                                       bool found[ACCEL_PACKET], shade_point sp[ACCEL_PACKET],
                                                       bool glows[ACCEL_PACKET], color local[ACCEL_PACKET])
{
    const glint_scene *scene = t->scene;
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!active[i])
            continue;
        ray ri = ray8_get(r, i);
        double nearest = found[i] ? sp[i].hit.t : t->reach, at;
        for (int l = 0; l < scene->area_light_count; l++) {
            const light *li = &scene->lights[scene->area_lights[l]];
            light moved;
            if (t->time && li->pose_count)
                li = light_moved(li, t->time[i], &moved);
            if (light_seen(li, &ri, nearest, &at)) {
                nearest = sp[i].hit.t = at;
                glows[i] = true;
                found[i] = false;
                local[i] = li->desc.color;
            }
        }
    }
}

static void trace8(tracer *t, const ray8 *r, const int skip[ACCEL_PACKET], const bool active[ACCEL_PACKET],
                   int depth, const paths *path, const uint32_t key[ACCEL_PACKET], color out[ACCEL_PACKET]);

/* Traces ray j of branch kind k of every lane that sends one (b[i], at
 * the hit sp[i] of a lane found[i], along `path`) as one packet, adding
 * what each brings back to local[i]. rays[i]: the rays lane i spreads the
 * branch over, ray j in the lobe about the sharp direction when its
 * material is rough; NULL: one sharp ray each, and no key is needed. White
 * light refracting into a dispersive material spreads over the spectrum's
 * bands too (rays[i] a multiple of their count): ray j is band j % count's,
 * at a wavelength drawn within it, bent by that wavelength's index and
 * carrying that band's colour. */
static void trace_branch(tracer *t, const ray8 *r, const bool found[ACCEL_PACKET], const shade_point sp[ACCEL_PACKET],
                         const branches b[ACCEL_PACKET], int k, int j, const int *rays, int depth,
                         const paths *path, const uint32_t key[ACCEL_PACKET], color local[ACCEL_PACKET])
{
    ray8 next;
    int next_skip[ACCEL_PACKET];
    uint32_t next_key[ACCEL_PACKET] = {0};
    bool on[ACCEL_PACKET], any = false, banded[ACCEL_PACKET] = {false};
    paths next_path;
    int bands = t->spectrum->count;
    /* A band's ray carries its band's colour, `bands` times over as it
     * stands for one ray in `bands`. */
    color band_tint = rgb_scale(t->spectrum->weight[j % bands], bands);
    /* Each lane's budget is spent as its own branches are met, depth first,
     * so what it cuts does not depend on the other lanes. */
    for (int i = 0; i < ACCEL_PACKET; i++) {
        on[i] = found[i] && (b[i].on >> k & 1) && (!rays || j < rays[i]) && t->budget[i] > 0;
        t->budget[i] -= on[i];
        any |= on[i];
    }
    if (!any)
        return;
    for (int i = 0; i < ACCEL_PACKET; i++) {
        ray ri = on[i] ? b[i].r[k] : ray8_get(r, i);
        vec3 side = on[i] ? b[i].side[k] : v3(0, 0, 0);
        next_skip[i] = on[i] ? b[i].skip[k] : -1;
        next_path.wavelength[i] = path->wavelength[i];
        next_path.travelled[i] = on[i] ? path->travelled[i] + sp[i].hit.t : path->travelled[i];
        int lobe_ray = j;
        if (rays) {
            uint32_t branch_key = hash_u32(key[i] ^ (uint32_t)(k + 1) * 0x9e3779b9U);
            next_key[i] = j ? hash_u32(branch_key ^ (uint32_t)j * 0x85ebca6bU) : branch_key;
            banded[i] = on[i] && k == BRANCH_REFRACT && splits(&sp[i], path->wavelength[i]);
            if (banded[i]) {
                lobe_ray = j / bands;
                double u = hash_unit(hash_u32(next_key[i] ^ 0x3c6ef372U));
                next_path.wavelength[i] = spectrum_wavelength(t->spectrum, j % bands, u);
                ri = band_ray(t->scene, &sp[i], ray8_get(r, i).d, next_path.wavelength[i], &side, &next_skip[i]);
            }
            if (on[i] && k != BRANCH_PASS && sp[i].m->roughness > 0) {
                double u[2];
                pattern_point(sobol2_seeds_of(hash_u32(branch_key ^ 0x7a3c1f55U)), lobe_ray, u);
                ri.d = optics_lobe(ri.d, side, material_lobe_exponent(sp[i].m), u[0], u[1]);
            }
        }
        ray8_set(&next, i, ri);
        color *w = &next_path.weight[i];
        *w = on[i] ? (rays ? rgb_scale(b[i].weight[k], 1.0 / rays[i]) : b[i].weight[k]) : path->weight[i];
        if (banded[i])
            *w = rgb_mul(*w, band_tint);
    }
    color c[ACCEL_PACKET];
    trace8(t, &next, next_skip, on, depth + 1, &next_path, next_key, c);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!on[i])
            continue;
        color seen = rgb_mul(b[i].filter[k], c[i]);
        if (banded[i])
            seen = rgb_mul(seen, band_tint);
        local[i] = rgb_add(local[i], rgb_scale(seen, rays ? b[i].scale[k] / rays[i] : b[i].scale[k]));
    }
}

/* Shades the hits hits[i] of the lanes found[i] of packet r (each lane's
 * ray also as lane_ray[i]) at recursion depth `depth`, along `path`, keys
 * as for trace8, each lane by its own steps, and traces the rays they send
 * on: local[i] is lane i's colour before fog, seen at hits[i].t (a mesh
 * hit's distance refined), found[i] false where fog hides the hit, and
 * set, with local[i] the light's colour, where an area light lies
 * before what the lane hit or, for an active lane, in place of nothing. */
static void shade_hits(tracer *t, const ray8 *r, const ray lane_ray[ACCEL_PACKET], const bool active[ACCEL_PACKET],
                       accel_hit hits[ACCEL_PACKET], bool found[ACCEL_PACKET], int depth, const paths *path,
                       const uint32_t key[ACCEL_PACKET], color local[ACCEL_PACKET])
{
    const glint_scene *scene = t->scene;
    shade_point sp[ACCEL_PACKET];
    branches b[ACCEL_PACKET];
    bool fog = scene->fog.kind != GLINT_FOG_NONE, occlusion = scene->settings.occlusion_samples > 0;
    /* A hit the fog hides completely looks like a miss, the fog colour
     * exactly (fog_apply gives it at factor 1 whatever the light), so it
     * is not shaded further. Its distance is exact only once described (a
     * mesh hit's is refined). */
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!found[i])
            continue;
        shade_begin(t, &lane_ray[i], &hits[i], &sp[i]);
        if (fog && fog_hides(&scene->fog, sp[i].hit.t))
            found[i] = false;
    }
    shade_colors(t, lane_ray, found, path, sp);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (!found[i])
            continue;
        if (occlusion)
            local[i] = glow(&sp[i]);
        else
            local[i] = rgb_add(ambient_term(scene, &sp[i]), glow(&sp[i]));
    }
    bool glows[ACCEL_PACKET] = {false};
    if (scene->area_light_count > 0)
        area_lights_seen(t, r, active, found, sp, glows, local);
    if (occlusion)
        ambient_occlusion8(t, found, sp, depth, path->weight, key, local);
    direct_light8(t, r, found, sp, depth, key, local);
    unsigned sent = 0; /* bit k: some lane sends a ray of kind k */
    for (int i = 0; i < ACCEL_PACKET; i++) {
        if (found[i]) {
            local[i] = shade_local(scene, &lane_ray[i], &sp[i], local[i], depth, path->weight[i], path->wavelength[i],
                                   &b[i]);
            sent |= b[i].on;
        }
    }
    for (int k = 0; k < BRANCHES; k++) {
        if (!(sent >> k & 1))
            continue;
        if (!t->keys) {
            trace_branch(t, r, found, sp, b, k, 0, NULL, depth, path, key, local);
            continue;
        }
        /* A rough surface spreads its reflected and refracted rays over a
         * lobe: as many as the material's glossy_samples for a ray of
         * weight 1, fewer for a ray of less, at least 1. White light
         * refracting into a dispersive material sends that many per band. */
        int rays[ACCEL_PACKET] = {1, 1, 1, 1, 1, 1, 1, 1}, most = 1;
        for (int i = 0; i < ACCEL_PACKET; i++) {
            if (!found[i])
                continue;
            if (k != BRANCH_PASS && sp[i].m->roughness > 0) {
                double n = ceil(sp[i].m->glossy_samples * rgb_max(path->weight[i]));
                rays[i] = n < 1 ? 1 : n > sp[i].m->glossy_samples ? sp[i].m->glossy_samples : (int)n;
            }
            if (k == BRANCH_REFRACT && splits(&sp[i], path->wavelength[i]))
                rays[i] *= t->spectrum->count;
            most = rays[i] > most ? rays[i] : most;
        }
        for (int j = 0; j < most && !tracer_stopping(t); j++)
            trace_branch(t, r, found, sp, b, k, j, rays, depth, path, key, local);
    }
    /* A ray that reaches a surface from inside an absorbing thing has
     * crossed it: what it brings back is dimmed by that length. */
    for (int i = 0; i < ACCEL_PACKET; i++)
        if (found[i] && !sp[i].front && material_absorbs(sp[i].m))
            local[i] = rgb_mul(local[i], material_absorbed(sp[i].m, sp[i].hit.t));
    for (int i = 0; i < ACCEL_PACKET; i++) {
        found[i] |= glows[i];
        if (found[i])
            hits[i].t = sp[i].hit.t;
    }
}

/* The colours of up to ACCEL_PACKET rays at recursion depth `depth`, of
 * weights `weight` in their samples, whose random numbers come from
 * key[i]. The rays each hit sends on are traced as packets too, one per
 * kind of branch, over the lanes that send one and have budget left
 * (tracer_trace8), each with a key of its own made from its ray's. */
static void trace8(tracer *t, const ray8 *r, const int skip[ACCEL_PACKET], const bool active[ACCEL_PACKET],
                   int depth, const paths *path, const uint32_t key[ACCEL_PACKET], color out[ACCEL_PACKET])
{
    const glint_scene *scene = t->scene;
    if (tracer_stopping(t)) {
        for (int i = 0; i < ACCEL_PACKET; i++)
            out[i] = rgb(0, 0, 0);
        return;
    }
    accel_hit hits[ACCEL_PACKET];
    bool found[ACCEL_PACKET];
    color local[ACCEL_PACKET];
    /* Each lane's ray as a struct, copied out of the packet before the
     * search, so that shading reads it long after its stores: copied just
     * before, its 8-byte stores were still on their way when
     * shape_surface loaded it 16 bytes at a time, and the loads waited. */
    ray lane_ray[ACCEL_PACKET];
    for (int i = 0; i < ACCEL_PACKET; i++)
        lane_ray[i] = ray8_get(r, i);
    accel_intersect8(t->acc, r, t->time, t->reach, skip, depth == 0, active, hits, found);
    /* A large mesh's vertices are seldom in cache: fetch every lane's
     * together rather than one lane's at a time. */
    if (scene->instance_count > 0)
        for (int i = 0; i < ACCEL_PACKET; i++)
            if (found[i])
                hit_prefetch(scene, &hits[i]);
    /* bools are bytes of 0 or 1: their bits counted are the active lanes. */
    uint64_t lanes;
    _Static_assert(sizeof lanes == ACCEL_PACKET * sizeof active[0], "a packet's flags are eight bytes");
    memcpy(&lanes, active, sizeof lanes);
    t->rays += (uint64_t)__builtin_popcountll(lanes);
    /* A packet that hit nothing, where no area light can be seen in its
     * stead, has nothing to shade: the sky is all it shows (shade_hits'
     * loops over no lanes were 5% of a scene of balls against the sky). */
    uint64_t hit_lanes;
    memcpy(&hit_lanes, found, sizeof hit_lanes);
    bool shaded = hit_lanes != 0 || scene->area_light_count > 0;
    if (shaded && !(t->plain && plain_packet_shade(t, r, lane_ray, hits, found, depth, path->travelled, local)))
        shade_hits(t, r, lane_ray, active, hits, found, depth, path, key, local);
    /* Inactive lanes get the sky too, which nothing reads. Without fog,
     * fog_apply would give a hit's colour back as it is. */
    if (scene->environment.texture >= 0)
        environment_seen(scene, r, active, found, hits, local);
    color sky = miss(scene);
    if (scene->fog.kind != GLINT_FOG_NONE)
        for (int i = 0; i < ACCEL_PACKET; i++)
            out[i] = found[i] ? fog_apply(&scene->fog, local[i], hits[i].t) : sky;
    else
        for (int i = 0; i < ACCEL_PACKET; i++)
            out[i] = found[i] ? local[i] : sky;
}

bool tracer_needs_keys(const glint_scene *scene)
{
    if (scene->area_light_count > 0 || scene->emitter_count > 0 || scene->settings.occlusion_samples > 0)
        return true;
    for (int i = 0; i < scene->material_count; i++)
        if (scene->materials[i].m.roughness > 0 || scene->materials[i].m.dispersion > 0)
            return true;
    return false;
}

double tracer_reach(const glint_scene *scene)
{
    double reach = fog_reach(&scene->fog);
    /* mesh_surface moves Embree's t by up to 1e-3 t + 1e-6 when it refines
     * it, so a hit Embree puts that far past the reach may still lie
     * nearer; twice that margin covers it. */
    reach += 2e-3 * fabs(reach) + 2e-6;
    return reach > 0 ? reach : 0;
}

void tracer_trace8(tracer *t, const ray8 *r, const double *time, const bool active[ACCEL_PACKET],
                   const uint32_t key[ACCEL_PACKET], color out[ACCEL_PACKET])
{
    t->time = time;
    static const int none[ACCEL_PACKET] = {-1, -1, -1, -1, -1, -1, -1, -1};
    paths start; /* whole, white, from the camera */
    for (int i = 0; i < ACCEL_PACKET; i++) {
        start.weight[i] = rgb(1, 1, 1);
        start.wavelength[i] = start.travelled[i] = 0;
        t->budget[i] = TRACER_MAX_BRANCH_RAYS;
    }
    trace8(t, r, none, active, 0, &start, key, out);
}
