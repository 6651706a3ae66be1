/* test_shape_pieces.c - a long shape at a slant, which the accelerator
 * bounds with several boxes (shape_pieces), is found whole through each of
 * them: every hit along its length, exactly where the shape's own test
 * puts it; nothing beside it; a shadow segment blocked by it, or filtered
 * once at each of its crossings when it lets light through, however many
 * of its boxes the segment meets. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include "render/hit.h"

/* A cylinder of radius 0.1 and height 4 standing on the origin, turned 45
 * degrees about z: its axis runs from the origin to (-c 4, c 4, 0), c =
 * sqrt(1/2), in six slices (test_geometry.c works the count out). */
#define HEIGHT 4.0
#define PIECES 6

static glint_scene *slanted_scene(double transparency, int *cylinder)
{
    glint_scene *s = glint_scene_new();
    assert_non_null(s);
    glint_error err;
    glint_material m = glint_material_default();
    m.transparency = transparency;
    int mat = glint_scene_add_material(s, "stick", &m, &err);
    assert_true(mat >= 0);
    glint_shape d = {.kind = GLINT_SHAPE_CYLINDER, .radius = 0.1, .height = HEIGHT, .capped = false};
    glint_transform turn = glint_transform_rotate(glint_transform_identity(), v3(0, 0, 1), 45);
    *cylinder = glint_scene_add_shape(s, &d, mat, &turn, &err);
    assert_true(*cylinder >= 0);
    assert_int_equal(shape_pieces(&s->shapes[*cylinder]), PIECES);
    return s;
}

static accel *build(const glint_scene *s, bool **shape_opaque, bool **instance_opaque)
{
    assert_true(hit_opacity(s, shape_opaque, instance_opaque));
    accel_geometry g = {1, s->shapes, s->shape_count, s->meshes, s->mesh_count,
                        s->instances, s->instance_count, *shape_opaque, *instance_opaque, NULL, 0, 0};
    accel *a;
    glint_error err;
    assert_int_equal(accel_build(&a, &g, &err), GLINT_OK);
    return a;
}

/* Lane i: a ray down -z from 5 above the axis at height h_i, lane 0 at
 * the base and lane 7 at the top, the others on the slices' seams, where
 * two slices' boxes overlap. `aside` moves each off the axis by that much,
 * across it in the plane z = 0. */
static void rays_over_axis(ray8 *r, double aside)
{
    double c = sqrt(0.5);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        double h = i == 0 ? 0.01 : i == 7 ? HEIGHT - 0.01 : HEIGHT * i / PIECES;
        vec3 on_axis = v3(-c * h, c * h, 0), across = v3(c, c, 0);
        ray8_set(r, i, (ray){v3_add(v3_madd(on_axis, across, aside), v3(0, 0, 5)), v3(0, 0, -1)});
    }
}

static void test_found_all_along(void **state)
{
    int cylinder;
    glint_scene *s = slanted_scene(0, &cylinder);
    bool *shape_opaque, *instance_opaque;
    accel *a = build(s, &shape_opaque, &instance_opaque);
    ray8 r;
    bool active[ACCEL_PACKET], found[ACCEL_PACKET];
    int skip[ACCEL_PACKET];
    accel_hit hits[ACCEL_PACKET];
    for (int i = 0; i < ACCEL_PACKET; i++) {
        active[i] = true;
        skip[i] = -1;
    }
    rays_over_axis(&r, 0);
    accel_intersect8(a, &r, NULL, INFINITY, skip, true, active, hits, found);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        ray ri = ray8_get(&r, i);
        shape_hit own;
        assert_true(shape_intersect(&s->shapes[cylinder], &ri, 0, INFINITY, &own));
        assert_true(found[i]);
        assert_int_equal(hits[i].shape, cylinder);
        assert_memory_equal(&hits[i].t, &own.t, sizeof own.t);
        assert_true(fabs(hits[i].t - 4.9) < 1e-12);
    }
    /* 0.15 off the axis: inside the slices' boxes, outside the cylinder. */
    rays_over_axis(&r, 0.15);
    accel_intersect8(a, &r, NULL, INFINITY, skip, true, active, hits, found);
    for (int i = 0; i < ACCEL_PACKET; i++)
        assert_false(found[i]);
    accel_free(a);
    free(shape_opaque);
    free(instance_opaque);
    glint_scene_free(s);
}

/* Each crossing passes half. */
static color half(void *user, const ray *r, const accel_hit *hit, color *depth)
{
    (void)user, (void)r, (void)hit, (void)depth;
    return rgb(0.5, 0.5, 0.5);
}

/* Segments of length 10 straight through the cylinder: an opaque one
 * blocks each; one that lets light through filters each twice (in and
 * out), 0.25, though the seams' segments cross two slices' boxes. */
static void test_shadows_through_it(void **state)
{
    for (int see_through = 0; see_through < 2; see_through++) {
        int cylinder;
        glint_scene *s = slanted_scene(see_through ? 0.5 : 0, &cylinder);
        bool *shape_opaque, *instance_opaque;
        accel *a = build(s, &shape_opaque, &instance_opaque);
        assert_true(shape_opaque[cylinder] == !see_through);
        ray8 r;
        bool active[ACCEL_PACKET];
        int skip[ACCEL_PACKET];
        double tmax[ACCEL_PACKET];
        color through[ACCEL_PACKET];
        for (int i = 0; i < ACCEL_PACKET; i++) {
            active[i] = true;
            skip[i] = -1;
            tmax[i] = 10;
        }
        rays_over_axis(&r, 0);
        accel_transmission8(a, &r, NULL, tmax, skip, true, active, half, NULL, through);
        double want = see_through ? 0.25 : 0;
        for (int i = 0; i < ACCEL_PACKET; i++) {
            assert_true(through[i].r == want && through[i].g == want && through[i].b == want);
        }
        rays_over_axis(&r, 0.15);
        accel_transmission8(a, &r, NULL, tmax, skip, true, active, half, NULL, through);
        for (int i = 0; i < ACCEL_PACKET; i++)
            assert_true(through[i].r == 1 && through[i].g == 1 && through[i].b == 1);
        accel_free(a);
        free(shape_opaque);
        free(instance_opaque);
        glint_scene_free(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_found_all_along),
        cmocka_unit_test(test_shadows_through_it),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
