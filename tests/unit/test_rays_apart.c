/* test_rays_apart.c - rays that are not neighbours, in a scene of over a
 * thousand analytic shapes, which the accelerator traces one lane at a
 * time (rays_apart in accel_build.c): each lane's nearest hit is the one a
 * test of every shape finds, to the bit, and each shadow segment lets
 * through what its crossings pass, lane by lane, whichever lanes of the
 * packet are active and whatever shape a lane skips. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include "accel/accel_internal.h"
#include "core/hash.h"
#include "geometry/sphere_math.h"
#include "render/hit.h"

/* A cloud of small balls (one sphere set, half of them clear) and of
 * slanted open cylinders (shapes, every third clear) in the cube
 * [-5, 5]^3: 1,200 primitives at least, the cylinders' pieces besides. */
#define BALLS 800
#define STICKS 400

typedef struct cloud {
    glint_scene *scene;
    int set;                   /* the set's shape index */
    int first_stick;           /* the sticks are shapes first_stick on */
    bool *shape_opaque, *instance_opaque;
    accel *acc;
} cloud;

/* A number in [lo, hi) from the hash of (k, salt). */
static double spread(uint32_t k, uint32_t salt, double lo, double hi)
{
    return lo + (hi - lo) * hash_unit(hash_u32(k * 0x9e3779b9U ^ salt));
}

static void cloud_build(cloud *c)
{
    glint_scene *s = c->scene = glint_scene_new();
    assert_non_null(s);
    glint_error err;
    glint_material m = glint_material_default();
    int solid = glint_scene_add_material(s, "solid", &m, &err);
    m.transparency = 0.5;
    int clear = glint_scene_add_material(s, "clear", &m, &err);
    assert_true(solid >= 0 && clear >= 0);
    static glint_vec3 centers[BALLS];
    static double radii[BALLS];
    static int materials[BALLS];
    for (int k = 0; k < BALLS; k++) {
        centers[k] = v3(spread(k, 1, -5, 5), spread(k, 2, -5, 5), spread(k, 3, -5, 5));
        radii[k] = spread(k, 4, 0.1, 0.3);
        materials[k] = k % 2 ? clear : solid;
    }
    c->set = glint_scene_add_spheres(s, BALLS, centers, radii, materials, &err);
    assert_true(c->set >= 0);
    c->first_stick = s->shape_count;
    for (int k = 0; k < STICKS; k++) {
        glint_shape d = {.kind = GLINT_SHAPE_CYLINDER, .radius = spread(k, 5, 0.05, 0.15),
                         .height = spread(k, 6, 0.5, 2), .capped = false};
        glint_transform t = glint_transform_rotate(glint_transform_identity(),
                                                   v3_normalize(v3(spread(k, 7, -1, 1), spread(k, 8, -1, 1), 1)),
                                                   spread(k, 9, 0, 180));
        t = glint_transform_translate(t, spread(k, 10, -5, 5), spread(k, 11, -5, 5), spread(k, 12, -5, 5));
        assert_int_equal(glint_scene_add_shape(s, &d, k % 3 ? solid : clear, &t, &err), c->first_stick + k);
    }
    assert_true(hit_opacity(s, &c->shape_opaque, &c->instance_opaque));
    accel_geometry g = {1, s->shapes, s->shape_count, s->meshes, s->mesh_count,
                        s->instances, s->instance_count, c->shape_opaque, c->instance_opaque, NULL, 0, 0};
    assert_int_equal(accel_build(&c->acc, &g, &err), GLINT_OK);
    assert_true(c->acc->apart);
}

static void cloud_free(cloud *c)
{
    accel_free(c->acc);
    free(c->shape_opaque);
    free(c->instance_opaque);
    glint_scene_free(c->scene);
}

/* Packet p's rays: from anywhere in and about the cloud, each its own
 * way through it; every third packet with lanes 2 and 5 off, every fourth with each
 * lane skipping a stick (the one it would leave). */
static void packet(int p, ray8 *r, bool active[ACCEL_PACKET], int skip[ACCEL_PACKET], int first_stick)
{
    for (int i = 0; i < ACCEL_PACKET; i++) {
        uint32_t k = (uint32_t)(p * ACCEL_PACKET + i);
        vec3 o = v3(spread(k, 13, -7, 7), spread(k, 14, -7, 7), spread(k, 15, -7, 7));
        vec3 towards = v3(spread(k, 16, -4, 4), spread(k, 17, -4, 4), spread(k, 18, -4, 4));
        vec3 d = v3_normalize(v3_sub(towards, o));
        ray8_set(r, i, (ray){o, d});
        active[i] = !(p % 3 == 0 && (i == 2 || i == 5));
        skip[i] = p % 4 == 0 ? first_stick + (int)(k % STICKS) : -1;
    }
}

/* The nearest crossing of r in (0, tmax) with anything but shape `skip`,
 * testing every ball and stick: the shape, the part (a ball's number) and
 * *hit; -1 for none. */
static int nearest_by_hand(const cloud *c, const ray *r, double tmax, int skip, shape_hit *hit)
{
    const glint_scene *s = c->scene;
    const sphere_set *set = s->shapes[c->set].set;
    int found = -1;
    for (int k = 0; k < set->count; k++) {
        const double *b = set->balls[k];
        if (sphere_hit_at(v3(b[0], b[1], b[2]), b[3], r, 0, tmax, hit)) {
            tmax = hit->t;
            hit->part = k;
            found = c->set;
        }
    }
    shape_hit h;
    int part = hit->part;
    double t = hit->t;
    for (int k = c->first_stick; k < s->shape_count; k++) {
        if (k != skip && shape_intersect(&s->shapes[k], r, 0, tmax, &h)) {
            tmax = t = h.t;
            part = h.part;
            found = k;
        }
    }
    hit->t = t;
    hit->part = part;
    return found;
}

static void test_nearest_hits(void **state)
{
    (void)state;
    cloud c;
    cloud_build(&c);
    int hits_found = 0;
    for (int p = 0; p < 64; p++) {
        ray8 r;
        bool active[ACCEL_PACKET], found[ACCEL_PACKET];
        int skip[ACCEL_PACKET];
        accel_hit hits[ACCEL_PACKET];
        packet(p, &r, active, skip, c.first_stick);
        accel_intersect8(c.acc, &r, NULL, INFINITY, skip, false, active, hits, found);
        for (int i = 0; i < ACCEL_PACKET; i++) {
            ray ri = ray8_get(&r, i);
            shape_hit want = {0};
            int want_shape = active[i] ? nearest_by_hand(&c, &ri, INFINITY, skip[i], &want) : -1;
            assert_int_equal(found[i], want_shape >= 0);
            if (want_shape < 0)
                continue;
            hits_found++;
            assert_int_equal(hits[i].shape, want_shape);
            assert_int_equal(hits[i].on_shape.part, want.part);
            assert_memory_equal(&hits[i].t, &want.t, sizeof want.t);
        }
    }
    /* Most rays through the cloud meet something. */
    assert_true(hits_found > 256);
    cloud_free(&c);
}

/* Each crossing of a clear thing passes half, of a solid one nothing (a
 * solid ball of the set, which as a whole lets light through, is
 * filtered). */
static color half(void *user, const ray *r, const accel_hit *hit, color *depth)
{
    (void)r, (void)depth;
    return material_is_opaque(hit_material(user, hit)) ? rgb(0, 0, 0) : rgb(0.5, 0.5, 0.5);
}

/* What a segment r of length tmax lets through, by hand: 0 if a solid
 * thing crosses it; else half for each crossing of a clear one, and 0 once
 * that falls below the accelerator's cutoff. */
static double passed_by_hand(const cloud *c, const ray *r, double tmax, int skip)
{
    const glint_scene *s = c->scene;
    const sphere_set *set = s->shapes[c->set].set;
    double passed = 1;
    for (int k = 0; k < set->count; k++) {
        const double *b = set->balls[k];
        shape_hit h;
        double tmin = 0;
        for (int crossing = 0; crossing < 2 && sphere_hit_at(v3(b[0], b[1], b[2]), b[3], r, tmin, tmax, &h);
             crossing++) {
            if (k % 2 == 0)
                return 0;
            passed *= 0.5;
            tmin = h.t;
        }
    }
    for (int k = c->first_stick; k < s->shape_count; k++) {
        shape_hit h;
        double tmin = 0;
        for (int crossing = 0; k != skip && crossing < 2 && shape_intersect(&s->shapes[k], r, tmin, tmax, &h);
             crossing++) {
            if (c->shape_opaque[k])
                return 0;
            passed *= 0.5;
            tmin = h.t;
        }
    }
    return passed < TRANSMISSION_CUTOFF ? 0 : passed;
}

static void test_shadow_segments(void **state)
{
    (void)state;
    cloud c;
    cloud_build(&c);
    int partly = 0, blocked = 0, clear = 0;
    for (int p = 0; p < 64; p++) {
        ray8 r;
        bool active[ACCEL_PACKET];
        int skip[ACCEL_PACKET];
        double tmax[ACCEL_PACKET];
        color through[ACCEL_PACKET];
        packet(p, &r, active, skip, c.first_stick);
        for (int i = 0; i < ACCEL_PACKET; i++)
            tmax[i] = spread((uint32_t)(p * ACCEL_PACKET + i), 19, 0.5, 4);
        accel_transmission8(c.acc, &r, NULL, tmax, skip, false, active, half, c.scene, through);
        for (int i = 0; i < ACCEL_PACKET; i++) {
            ray ri = ray8_get(&r, i);
            double want = active[i] ? passed_by_hand(&c, &ri, tmax[i], skip[i]) : 0;
            assert_true(through[i].r == want && through[i].g == want && through[i].b == want);
            partly += want > 0 && want < 1;
            blocked += active[i] && want == 0;
            clear += want == 1;
        }
    }
    /* The segments are of all three kinds. */
    assert_true(partly > 16 && blocked > 16 && clear > 16);
    cloud_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nearest_hits),
        cmocka_unit_test(test_shadow_segments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
