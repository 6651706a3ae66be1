/* test_sphere_set.c - sphere sets (glint_scene_add_spheres): their hits
 * found exactly and named by sphere, the same image as the spheres added
 * one by one (textures, glass, shadows through it, mirrors), the checks on
 * their values with the exact messages, a scene file written from a set
 * that renders the same, and which spheres of a scene file become sets. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "one_sample_scene.h"
#include "render/hit.h"

enum { WIDTH = 96, HEIGHT = 64, BALLS = 5 };

/* Five balls of five materials: matte red, a checker by the sphere's own
 * (u, v), a checker mapped spherically about each ball's centre, glass
 * (refracting, and half transparent so shadows through it are tinted) and
 * a mirror. */
static const glint_vec3 CENTERS[BALLS] = {{-2.4, 0, -6}, {-1.2, 0.3, -5}, {0, -0.2, -6}, {1.2, 0.1, -4.5}, {2.5, 0, -6}};
static const double RADII[BALLS] = {0.6, 0.5, 0.8, 0.55, 0.7};

/* A scene of the five balls (as a set when `as_set`, else a shape each)
 * above a floor, lit by a point light: mats receives their materials. */
static glint_scene *balls_scene(bool as_set, int mats[BALLS])
{
    glint_camera cam = {.position = {0, 1, 2}, .look_at = {0, 0, -5}, .up = {0, 1, 0}, .vfov_degrees = 45};
    glint_scene *s = one_sample_scene(WIDTH, HEIGHT, glint_settings_default().ambient_light, cam);
    glint_error err;
    glint_texture checker = glint_texture_default(GLINT_TEXTURE_CHECKER);
    checker.size = 0.125;
    int by_uv = glint_scene_add_texture(s, "uv", &checker, &err);
    checker.mapping.kind = GLINT_MAP_SPHERICAL;
    int spherical = glint_scene_add_texture(s, "spherical", &checker, &err);
    assert_true(by_uv >= 0 && spherical >= 0);
    glint_material m = glint_material_default();
    m.color = (glint_color){0.8, 0.1, 0.1};
    mats[0] = glint_scene_add_material(s, "red", &m, &err);
    m.texture = by_uv;
    mats[1] = glint_scene_add_material(s, "uv", &m, &err);
    m.texture = spherical;
    mats[2] = glint_scene_add_material(s, "spherical", &m, &err);
    m = glint_material_default();
    m.color = (glint_color){0.6, 0.9, 0.6};
    m.refraction = 0.5;
    m.transparency = 0.4;
    m.ior = 1.5;
    mats[3] = glint_scene_add_material(s, "glass", &m, &err);
    m = glint_material_default();
    m.reflectivity = 0.9;
    mats[4] = glint_scene_add_material(s, "mirror", &m, &err);
    m = glint_material_default();
    m.color = (glint_color){0.5, 0.5, 0.9};
    int floor_material = glint_scene_add_material(s, "floor", &m, &err);
    for (int k = 0; k < BALLS; k++)
        assert_true(mats[k] >= 0);
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, -0.8, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &floor, floor_material, NULL, &err) >= 0);
    if (as_set) {
        assert_int_equal(glint_scene_add_spheres(s, BALLS, CENTERS, RADII, mats, &err), 1);
    } else {
        for (int k = 0; k < BALLS; k++) {
            glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = CENTERS[k], .radius = RADII[k]};
            assert_true(glint_scene_add_shape(s, &ball, mats[k], NULL, &err) >= 0);
        }
    }
    glint_light l = glint_light_default(GLINT_LIGHT_POINT);
    l.position = (glint_vec3){3, 5, 0};
    assert_true(glint_scene_add_light(s, &l, &err) >= 0);
    return s;
}

static glint_image render(const glint_scene *s, int threads)
{
    glint_image img;
    glint_render_options o = {.threads = threads};
    glint_error err;
    assert_int_equal(glint_render(s, &o, &img, NULL, &err), GLINT_OK);
    return img;
}

/* Rays from the origin towards each ball's centre meet it at its near side
 * (t = distance - radius), named by the sphere as the hit's part, with
 * its material, the normal facing back along the ray; a ray leaving a
 * ball skips nothing, as it may meet the others. */
static void test_hits_name_their_sphere(void **state)
{
    int mats[BALLS];
    glint_scene *s = balls_scene(true, mats);
    bool *shape_opaque, *instance_opaque;
    assert_true(hit_opacity(s, &shape_opaque, &instance_opaque));
    assert_false(shape_opaque[1]); /* the glass ball lets light through */
    accel_geometry g = {1, s->shapes, s->shape_count, s->meshes, s->mesh_count,
                        s->instances, s->instance_count, shape_opaque, instance_opaque, NULL, 0, 0};
    accel *a;
    glint_error err;
    assert_int_equal(accel_build(&a, &g, &err), GLINT_OK);
    ray8 r;
    bool active[ACCEL_PACKET], found[ACCEL_PACKET];
    int skip[ACCEL_PACKET];
    accel_hit hits[ACCEL_PACKET];
    for (int i = 0; i < ACCEL_PACKET; i++) {
        vec3 c = CENTERS[i % BALLS];
        ray8_set(&r, i, (ray){v3(0, 0, 0), v3_normalize(c)});
        active[i] = true;
        skip[i] = -1;
    }
    accel_intersect8(a, &r, NULL, INFINITY, skip, true, active, hits, found);
    for (int i = 0; i < ACCEL_PACKET; i++) {
        int k = i % BALLS;
        assert_true(found[i]);
        assert_int_equal(hits[i].shape, 1);
        assert_int_equal(hits[i].on_shape.part, k);
        assert_true(fabs(hits[i].t - (v3_length(CENTERS[k]) - RADII[k])) < 1e-12);
        assert_ptr_equal(hit_material(s, &hits[i]), &s->materials[mats[k]].m);
        ray ri = ray8_get(&r, i);
        surface sf;
        hit_surface(s, &ri, &hits[i], &sf);
        assert_true(v3_length(v3_add(sf.n, ri.d)) < 1e-12);
        assert_int_equal(hit_left_behind(s, &hits[i], sf.n, v3_neg(ri.d)), -1);
    }
    accel_free(a);
    free(shape_opaque);
    free(instance_opaque);
    glint_scene_free(s);
}

/* A set renders the bytes its spheres give one by one: each textured by
 * its own (u, v) and centre, the glass refracting and tinting the shadow
 * it casts, the mirror showing the others, on any number of threads. */
static void test_renders_as_its_spheres(void **state)
{
    int mats[BALLS];
    glint_scene *one_by_one = balls_scene(false, mats), *set = balls_scene(true, mats);
    glint_image want = render(one_by_one, 1), got = render(set, 2);
    size_t values = (size_t)WIDTH * HEIGHT * 3;
    assert_memory_equal(want.pixels, got.pixels, values * sizeof(float));
    /* The balls are in the picture: the middle row is not all one colour. */
    const float *row = want.pixels + (size_t)(HEIGHT / 2) * WIDTH * 3;
    int changes = 0;
    for (int x = 1; x < WIDTH; x++)
        changes += row[3 * x] != row[3 * (x - 1)];
    assert_true(changes > WIDTH / 2);
    glint_image_free(&want);
    glint_image_free(&got);
    glint_scene_free(one_by_one);
    glint_scene_free(set);
}

/* Written as a scene file, a set is its spheres, which render the same. */
static void test_scene_file_keeps_the_picture(void **state)
{
    int mats[BALLS];
    glint_scene *set = balls_scene(true, mats);
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    assert_non_null(f);
    glint_error err;
    assert_int_equal(glint_scene_write_yaml(set, f, &err), GLINT_OK);
    fclose(f);
    int spheres = 0;
    for (const char *p = text; (p = strstr(p, "type: sphere")) != NULL; p++)
        spheres++;
    assert_int_equal(spheres, BALLS);
    glint_scene *again = glint_scene_load_memory(text, size, "set.yaml", NULL, &err);
    if (!again)
        fail_msg("%s", err.message);
    glint_image want = render(set, 2), got = render(again, 2);
    assert_memory_equal(want.pixels, got.pixels, (size_t)WIDTH * HEIGHT * 3 * sizeof(float));
    glint_image_free(&want);
    glint_image_free(&got);
    glint_scene_free(again);
    glint_scene_free(set);
    free(text);
}

/* Appends `count` plain spheres, on a line from x, to the scene text at *p. */
static void put_spheres(char **p, int count, double x, const char *indent)
{
    for (int i = 0; i < count; i++)
        *p += sprintf(*p, "%s- {type: sphere, center: [%g, 0, -9], radius: 0.2, material: m}\n", indent, x + 0.5 * i);
}

/* A scene file's runs of 256 or more plain spheres become sphere sets, in
 * their place among the objects; shorter runs, glowing spheres, moved ones
 * and any sphere of an animated scene stay a shape each. */
static void test_scene_file_runs_become_sets(void **state)
{
    char *text = malloc(200000), *p = text;
    assert_non_null(text);
    p += sprintf(p, "materials:\n  m: {color: [1, 1, 1]}\n  lamp: {emission: [1, 1, 1]}\nobjects:\n");
    put_spheres(&p, 300, -70, "");
    p += sprintf(p, "- {type: box, min: [-1, -1, -12], max: [1, 1, -10], material: m}\n");
    put_spheres(&p, 10, 0, "");
    p += sprintf(p, "- {type: sphere, radius: 0.5, center: [0, 3, -9], material: lamp}\n");
    p += sprintf(p, "- type: group\n  transform: [{translate: [0, 1, 0]}]\n  objects:\n");
    put_spheres(&p, 300, -70, "  ");
    put_spheres(&p, 256, -60, "");
    glint_error err;
    glint_scene *s = glint_scene_load_memory(text, strlen(text), "runs.yaml", NULL, &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_int_equal(s->shape_count, 1 + 1 + 10 + 1 + 300 + 1);
    assert_non_null(s->shapes[0].set);
    assert_int_equal(s->shapes[0].set->count, 300);
    assert_true(s->shapes[0].set->balls[299][0] == -70 + 0.5 * 299);
    assert_int_equal(s->shapes[1].desc.kind, GLINT_SHAPE_BOX);
    for (int i = 2; i < 2 + 10 + 1 + 300; i++)
        assert_null(s->shapes[i].set);
    assert_int_equal(s->emitter_count, 1);
    assert_int_equal(s->shapes[313].set->count, 256);
    glint_scene_free(s);

    /* Something keyed before the spheres: a shape each. */
    p = text + sprintf(text, "camera: {position: {keys: [[0, [0, 0, 5]], [1, [0, 0, 6]]]}}\n"
                             "materials:\n  m: {color: [1, 1, 1]}\nobjects:\n");
    put_spheres(&p, 300, -70, "");
    s = glint_scene_load_memory(text, strlen(text), "keyed.yaml", NULL, &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_int_equal(s->shape_count, 300);
    assert_null(s->shapes[0].set);
    glint_scene_free(s);
    free(text);
}

/* Adds a set of one sphere and checks the error it gets. */
static void expect_refused(glint_scene *s, glint_vec3 center, double radius, int mat, const char *message)
{
    glint_error err;
    glint_vec3 centers[2] = {{0, 0, 0}, center};
    double radii[2] = {1, radius};
    int materials[2] = {0, mat};
    assert_int_equal(glint_scene_add_spheres(s, 2, centers, radii, materials, &err), -1);
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    assert_string_equal(err.message, message);
}

static void test_values_are_checked(void **state)
{
    glint_scene *s = glint_scene_new();
    assert_non_null(s);
    glint_error err;
    glint_material m = glint_material_default();
    assert_int_equal(glint_scene_add_material(s, "plain", &m, &err), 0);
    m.emission = (glint_color){1, 1, 1};
    assert_int_equal(glint_scene_add_material(s, "lamp", &m, &err), 1);
    expect_refused(s, (glint_vec3){0, NAN, 0}, 1, 0, "sphere 1 of the set: its centre is not finite");
    expect_refused(s, (glint_vec3){0, 0, 0}, -1, 0, "sphere 1 of the set: radius must be positive, got -1");
    expect_refused(s, (glint_vec3){0, 0, 0}, INFINITY, 0, "sphere 1 of the set: radius must be positive, got inf");
    expect_refused(s, (glint_vec3){0, 0, 0}, 1, 2, "sphere 1 of the set: material 2 does not exist");
    expect_refused(s, (glint_vec3){0, 0, 0}, 1, 1,
                   "sphere 1 of the set: material 1 glows, and a set's spheres light nothing: add glowing spheres "
                   "one by one");
    glint_vec3 center = {0, 0, 0};
    double radius = 1;
    int plain = 0;
    assert_int_equal(glint_scene_add_spheres(s, 0, &center, &radius, &plain, &err), -1);
    assert_string_equal(err.message, "a sphere set holds 1 to 16777216 spheres, got 0");
    assert_int_equal(glint_scene_add_spheres(s, 1, &center, NULL, &plain, &err), -1);
    assert_string_equal(err.message, "a sphere set needs its centres, radii and materials");
    assert_int_equal(s->shape_count, 0);

    /* A set is one shape, which cannot move; the counts say what it holds. */
    assert_int_equal(glint_scene_add_spheres(s, 1, &center, &radius, &plain, &err), 0);
    glint_transform poses[2] = {glint_transform_identity(), glint_transform_identity()};
    assert_int_equal(glint_scene_move_shape(s, 0, 2, poses, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "a sphere set cannot move over the shutter: add moving spheres one by one");
    glint_scene_counts c = glint_scene_get_counts(s);
    assert_int_equal(c.shapes, 1);
    assert_int_equal(c.sphere_sets, 1);
    assert_int_equal(c.set_spheres, 1);
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hits_name_their_sphere),
        cmocka_unit_test(test_renders_as_its_spheres),
        cmocka_unit_test(test_scene_file_keeps_the_picture),
        cmocka_unit_test(test_scene_file_runs_become_sets),
        cmocka_unit_test(test_values_are_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
