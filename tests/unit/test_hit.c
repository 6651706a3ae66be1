/* test_hit.c - the renderer's hit module (render/hit.h) on real hits: a
 * sphere, a moved mesh triangle and a plane found by the accelerator, each
 * asked for its material, surface, the shape a ray leaving it
 * may skip, and whether it blocks all light. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include "render/hit.h"

typedef struct fixture {
    glint_scene *scene;
    int red, green, blue, glass;
    int sphere, plane, see_through;
} fixture;

/* A red sphere of radius 1 at (0, 0, -5); a green mesh of one triangle in
 * the plane z = 0, facing +z, moved to z = -10; a blue floor y = -2; a glass
 * sphere far off to the side. */
static fixture make_scene(void)
{
    fixture f;
    glint_error err;
    f.scene = glint_scene_new();
    assert_non_null(f.scene);
    glint_material m = glint_material_default();
    m.color = (glint_color){1, 0, 0};
    f.red = glint_scene_add_material(f.scene, "red", &m, &err);
    m.color = (glint_color){0, 1, 0};
    f.green = glint_scene_add_material(f.scene, "green", &m, &err);
    m.color = (glint_color){0, 0, 1};
    f.blue = glint_scene_add_material(f.scene, "blue", &m, &err);
    m.transparency = 0.5;
    f.glass = glint_scene_add_material(f.scene, "glass", &m, &err);
    assert_true(f.red >= 0 && f.green >= 0 && f.blue >= 0 && f.glass >= 0);

    glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {0, 0, -5}, .radius = 1};
    f.sphere = glint_scene_add_shape(f.scene, &ball, f.red, NULL, &err);
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, -2, 0}, .normal = {0, 1, 0}};
    f.plane = glint_scene_add_shape(f.scene, &floor, f.blue, NULL, &err);
    glint_shape far = {.kind = GLINT_SHAPE_SPHERE, .center = {100, 0, -5}, .radius = 1};
    f.see_through = glint_scene_add_shape(f.scene, &far, f.glass, NULL, &err);
    assert_true(f.sphere >= 0 && f.plane >= 0 && f.see_through >= 0);

    static const float positions[] = {2, -1, 0, 6, -1, 0, 4, 1, 0};
    static const uint32_t indices[] = {0, 1, 2};
    glint_mesh_data d = {.positions = positions, .vertex_count = 3, .indices = indices, .triangle_count = 1,
                         .material = f.green};
    int triangle = glint_scene_add_mesh(f.scene, "triangle", &d, &err);
    assert_true(triangle >= 0);
    glint_transform t = glint_transform_translate(glint_transform_identity(), 0, 0, -10);
    assert_true(glint_scene_add_instance(f.scene, triangle, -1, &t, &err) >= 0);
    return f;
}

/* The hits of three rays from the origin: lane 0 towards the red sphere,
 * lane 1 towards the green triangle, lane 2 down to the floor. */
static void find_hits(const glint_scene *scene, ray8 *r, accel_hit hits[ACCEL_PACKET])
{
    bool *shape_opaque, *instance_opaque;
    assert_true(hit_opacity(scene, &shape_opaque, &instance_opaque));
    accel_geometry g = {1, scene->shapes, scene->shape_count, scene->meshes, scene->mesh_count,
                        scene->instances, scene->instance_count, shape_opaque, instance_opaque, NULL, 0, 0};
    accel *a;
    glint_error err;
    assert_int_equal(accel_build(&a, &g, &err), GLINT_OK);
    vec3 d[3] = {{0, 0, -1}, v3_normalize(v3(4, 0, -10)), v3_normalize(v3(0, -1, -0.1))};
    bool active[ACCEL_PACKET] = {true, true, true}, found[ACCEL_PACKET];
    int skip[ACCEL_PACKET] = {-1, -1, -1, -1, -1, -1, -1, -1};
    for (int i = 0; i < ACCEL_PACKET; i++)
        ray8_set(r, i, (ray){v3(0, 0, 0), d[i < 3 ? i : 0]});
    accel_intersect8(a, r, NULL, INFINITY, skip, true, active, hits, found);
    assert_true(found[0] && found[1] && found[2]);
    accel_free(a);
    free(shape_opaque);
    free(instance_opaque);
}

static void assert_vec_near(vec3 a, vec3 b)
{
    assert_true(v3_length(v3_sub(a, b)) < 1e-12);
}

static void test_material_and_surface(void **state)
{
    fixture f = make_scene();
    const glint_scene *s = f.scene;
    ray8 r;
    accel_hit h[ACCEL_PACKET];
    find_hits(s, &r, h);
    surface sf[3];
    for (int i = 0; i < 3; i++) {
        ray ri = ray8_get(&r, i);
        hit_surface(s, &ri, &h[i], &sf[i]);
        assert_vec_near(sf[i].p, ray_at(&ri, h[i].t));
    }

    /* The sphere: red, its normal out of the sphere where the ray meets
     * it; a ray leaving it outwards never meets it again. */
    assert_ptr_equal(hit_material(s, &h[0]), &s->materials[f.red].m);
    assert_vec_near(sf[0].p, v3(0, 0, -4));
    assert_vec_near(sf[0].n, v3(0, 0, 1));
    assert_int_equal(hit_left_behind(s, &h[0], sf[0].n, v3(0, 0, 1)), f.sphere);
    assert_int_equal(hit_left_behind(s, &h[0], sf[0].n, v3(0, 0, -1)), -1);

    /* The mesh: green, Embree's float distance refined to the exact one
     * in double precision, the normal from the winding (counter-clockwise
     * seen from +z); never skipped. */
    assert_ptr_equal(hit_material(s, &h[1]), &s->materials[f.green].m);
    assert_true(fabs(h[1].t - sqrt(116.0)) < 1e-12);
    assert_vec_near(sf[1].n, v3(0, 0, 1));
    assert_vec_near(sf[1].shading_n, v3(0, 0, 1));
    assert_int_equal(hit_left_behind(s, &h[1], sf[1].n, v3(0, 0, 1)), -1);

    /* The floor: blue, flat: any ray leaving it skips it. */
    assert_ptr_equal(hit_material(s, &h[2]), &s->materials[f.blue].m);
    assert_vec_near(sf[2].n, v3(0, 1, 0));
    assert_int_equal(hit_left_behind(s, &h[2], sf[2].n, v3(0, 1, 0)), f.plane);
    assert_int_equal(hit_left_behind(s, &h[2], sf[2].n, v3(0, -1, 0)), f.plane);

    /* Untextured: each surface's colour is its material's. */
    for (int i = 0; i < 3; i++) {
        const glint_material *m = hit_material(s, &h[i]);
        color c = hit_color(s, &h[i], m, &sf[i], v3(0, 0, -1), 0);
        assert_memory_equal(&c, &m->color, sizeof c);
    }
    glint_scene_free(f.scene);
}

static void test_opacity_lists(void **state)
{
    fixture f = make_scene();
    bool *shapes, *instances;
    assert_true(hit_opacity(f.scene, &shapes, &instances));
    assert_true(shapes[f.sphere] && shapes[f.plane]);
    assert_false(shapes[f.see_through]);
    assert_true(instances[0]);
    free(shapes);
    free(instances);
    /* The instance's own material replaces the mesh's. */
    glint_error err;
    assert_true(glint_scene_add_instance(f.scene, 0, f.glass, NULL, &err) >= 0);
    assert_true(hit_opacity(f.scene, &shapes, &instances));
    assert_true(instances[0]);
    assert_false(instances[1]);
    free(shapes);
    free(instances);
    glint_scene_free(f.scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_material_and_surface),
        cmocka_unit_test(test_opacity_lists),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
