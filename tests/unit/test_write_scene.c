/* test_write_scene.c - glint_scene_write_yaml: a scene written and read back
 * holds the same values bit for bit (awkward numbers, negative zeros,
 * composed transforms, colours, names YAML would misread), and a scene a
 * file cannot say is refused with nothing written. The command line's
 * round trip through whole renders is tests/cli/print_scene.sh. */
#define _GNU_SOURCE /* open_memstream */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glint.h"
#include "scene/scene.h"

/* The scene written by glint_scene_write_yaml, as text (freed by the
 * caller), or NULL with *status set when it refused. */
static char *written(const glint_scene *s, glint_status *status, glint_error *err)
{
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    assert_non_null(f);
    *status = glint_scene_write_yaml(s, f, err);
    fclose(f);
    if (*status) {
        assert_int_equal(size, 0); /* nothing written */
        free(text);
        return NULL;
    }
    return text;
}

/* s written and loaded back; fails the test if either step fails. */
static glint_scene *round_trip(const glint_scene *s)
{
    glint_error err = {0};
    glint_status st;
    char *text = written(s, &st, &err);
    if (!text)
        fail_msg("not written: %s", err.message);
    glint_scene *back = glint_scene_load_memory(text, strlen(text), "written.yaml", NULL, &err);
    if (!back)
        fail_msg("not read back: %s\n%s", err.message, text);
    free(text);
    return back;
}

static void assert_same_bits(const void *a, const void *b, size_t size)
{
    assert_memory_equal(a, b, size);
}

static int add_material(glint_scene *s, const char *name, glint_color c)
{
    glint_material m = glint_material_default();
    m.color = c;
    glint_error err;
    int i = glint_scene_add_material(s, name, &m, &err);
    assert_true(i >= 0);
    return i;
}

/* Numbers that need all 17 digits, tiny and huge ones and negative zeros
 * come back as the same bits, and so does a transform composed of turns
 * and scales that no list of simple steps writes exactly. */
static void test_numbers_and_transforms(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    int m = add_material(s, "m", (glint_color){0.1, 0.2, 0.3});
    glint_shape sphere = glint_shape_default(GLINT_SHAPE_SPHERE);
    sphere.center = (glint_vec3){0.1 + 0.2, -0.0, 1e-300};
    sphere.radius = 1.0 / 3.0;
    glint_transform t = glint_transform_rotate(glint_transform_identity(), (glint_vec3){1, 2, 3}, 37);
    t = glint_transform_scale(t, 1.5, -0.25, 2);
    t = glint_transform_translate(t, -0.0, 1e17, 3.14159);
    glint_error err;
    assert_true(glint_scene_add_shape(s, &sphere, m, &t, &err) >= 0);
    glint_shape box = glint_shape_default(GLINT_SHAPE_BOX);
    box.min = (glint_vec3){-1e-9, -2, -3};
    box.max = (glint_vec3){123456789.125, 2, 3};
    assert_true(glint_scene_add_shape(s, &box, m, NULL, &err) >= 0);
    glint_camera cam = {.position = {0.7, 1.1, 9.9}, .look_at = {0, 0.5, 0}, .up = {0, 1, 0}, .vfov_degrees = 33.3};
    assert_int_equal(glint_scene_set_camera(s, &cam, &err), GLINT_OK);

    glint_scene *back = round_trip(s);
    assert_int_equal(back->shape_count, 2);
    assert_same_bits(&back->shapes[0].desc, &s->shapes[0].desc, sizeof(glint_shape));
    assert_same_bits(&back->shapes[0].to_world, &s->shapes[0].to_world, sizeof(glint_transform));
    assert_same_bits(&back->shapes[1].desc, &s->shapes[1].desc, sizeof(glint_shape));
    assert_false(back->shapes[1].has_transform);
    assert_same_bits(&back->camera, &s->camera, sizeof cam);
    glint_scene_free(back);
    glint_scene_free(s);
}

/* Every setting comes back as the same bits, the anti-aliasing maps
 * included. */
static void test_settings(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_settings st = glint_settings_default();
    st.samples_per_pixel = 7;
    st.sampler = GLINT_SAMPLER_SOBOL;
    st.filter = GLINT_FILTER_GAUSSIAN;
    st.filter_radius = 1.0 / 3.0 + 1;
    st.adaptive_max_samples = 77;
    st.adaptive_threshold = 0.1 + 0.2;
    st.occlusion_samples = 5;
    st.occlusion_distance = 2.5;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_scene *back = round_trip(s);
    glint_settings got = glint_scene_get_settings(back);
    assert_same_bits(&got, &st, sizeof st);
    glint_scene_free(back);
    /* A tent of its own radius is written too. */
    st.filter = GLINT_FILTER_TENT;
    st.filter_radius = 0;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    back = round_trip(s);
    got = glint_scene_get_settings(back);
    assert_same_bits(&got, &st, sizeof st);
    glint_scene_free(back);
    glint_scene_free(s);
}

/* Linear colours come back exactly, whether a display value gives them
 * ([r, g, b]) or only {linear: ...} does (above 1, or no display value
 * converts to them). */
static void test_colors(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    srand(20);
    enum { N = 200 };
    for (int i = 0; i < N; i++) {
        char name[16];
        snprintf(name, sizeof name, "c%d", i);
        glint_color c = {rand() / (double)RAND_MAX, glint_srgb_to_linear(i / 199.0), i == 0 ? 7.5 : 0.0};
        add_material(s, name, c);
    }
    glint_scene *back = round_trip(s);
    assert_int_equal(back->material_count, N);
    for (int i = 0; i < N; i++)
        assert_same_bits(&back->materials[i].m, &s->materials[i].m, sizeof(glint_material));
    glint_scene_free(back);
    glint_scene_free(s);
}

/* Names with YAML's indicators, words YAML gives meanings and numbers are
 * quoted and come back as the same text; an unnamed texture gets a name
 * of its own that no other texture has. */
static void test_names(void **state)
{
    (void)state;
    static const char *const NAMES[] = {"a: b", "#hash", "true", "123", "quote\"back\\slash", "-x", "", "tab\there"};
    glint_scene *s = glint_scene_new();
    glint_error err;
    for (size_t i = 0; i < sizeof NAMES / sizeof NAMES[0]; i++)
        if (NAMES[i][0])
            add_material(s, NAMES[i], (glint_color){0.5, 0.5, 0.5});
    glint_mapping uv = {.kind = GLINT_MAP_UV};
    assert_true(glint_scene_add_checker(s, "texture-1", (glint_color){0, 0, 0}, (glint_color){1, 1, 1}, 1, uv,
                                        &err) >= 0);
    assert_true(glint_scene_add_checker(s, NULL, (glint_color){1, 0, 0}, (glint_color){0, 1, 0}, 2, uv, &err) >= 0);
    glint_material m = glint_material_default();
    m.texture = 1;
    assert_true(glint_scene_add_material(s, "checked", &m, &err) >= 0);

    glint_scene *back = round_trip(s);
    for (int i = 0; i < s->material_count; i++)
        assert_string_equal(back->materials[i].name, s->materials[i].name);
    int checked = scene_find_material(back, "checked");
    assert_true(checked >= 0);
    const texture *t = &back->textures[back->materials[checked].m.texture];
    assert_string_equal(t->name, "texture-2");
    assert_same_bits(&t->a, &s->textures[1].a, sizeof t->a);
    glint_scene_free(back);
    glint_scene_free(s);
}

/* A transform step written as a matrix is that matrix exactly, negative
 * zeros included, whatever group it is in. */
static void test_matrix_step(void **state)
{
    (void)state;
    static const char SCENE[] = "materials: {m: {}}\n"
                                "objects:\n"
                                "  - type: group\n"
                                "    objects:\n"
                                "      - {type: sphere, radius: 1, material: m,\n"
                                "         transform: [{matrix: [[-0, 2, 0, 1], [1, -0, 0, -0], [0, 0, 3, 0.1]]}]}\n";
    glint_error err;
    glint_scene *s = glint_scene_load_memory(SCENE, sizeof SCENE - 1, "m.yaml", NULL, &err);
    if (!s)
        fail_msg("%s", err.message);
    glint_transform want = {{{-0.0, 2, 0, 1}, {1, -0.0, 0, -0.0}, {0, 0, 3, 0.1}}};
    assert_same_bits(&s->shapes[0].to_world, &want, sizeof want);
    glint_scene_free(s);

    static const char BAD[] = "materials: {m: {}}\n"
                              "objects: [{type: sphere, radius: 1, material: m, transform: [{matrix: [[1, 0, 0]]}]}]\n";
    assert_null(glint_scene_load_memory(BAD, sizeof BAD - 1, "bad.yaml", NULL, &err));
    assert_string_equal(err.message,
                        "bad.yaml:2:71: 'matrix' must be 3 rows of 4 numbers, [[a, b, c, d], [e, f, g, h], [i, j, k, l]]");
}

/* What a scene file cannot say is refused, naming it, with nothing
 * written: a placed mesh built from arrays, an image from memory. */
/* A mapping's center comes back as given: [0, 0, 0] written out when it
 * was given (a spherical mapping then goes around the origin, not around
 * its shape), and left out when it was not. */
static void test_mapping_center(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_error err;
    glint_mapping given = {.kind = GLINT_MAP_SPHERICAL, .center_given = true};
    glint_mapping around_shape = {.kind = GLINT_MAP_SPHERICAL};
    glint_color a = {1, 1, 1}, b = {0, 0, 0};
    assert_true(glint_scene_add_checker(s, "given", a, b, 0.25, given, &err) >= 0);
    assert_true(glint_scene_add_checker(s, "shape", a, b, 0.25, around_shape, &err) >= 0);
    glint_status st;
    char *text = written(s, &st, &err);
    assert_non_null(text);
    assert_non_null(strstr(text, "  given: {type: checker, mapping: {type: spherical, center: [0, 0, 0]}"));
    assert_non_null(strstr(text, "  shape: {type: checker, mapping: spherical"));
    free(text);
    glint_scene *back = round_trip(s);
    assert_int_equal(back->texture_count, 2);
    assert_true(back->textures[0].desc.mapping.center_given);
    assert_false(back->textures[1].desc.mapping.center_given);
    glint_scene_free(back);
    glint_scene_free(s);
}

/* A solid texture's colour map and a texture's transform come back bit
 * for bit; an unplaced texture writes no transform. */
static void test_color_map_and_placement(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_error err;
    glint_texture m = glint_texture_default(GLINT_TEXTURE_MARBLE);
    m.stop_count = 3;
    m.stops[0] = (glint_color_stop){0.1, {0.9, 0.85, 0.8}};
    m.stops[1] = (glint_color_stop){1.0 / 3, {0.123456789, 0.2, 0.3}};
    m.stops[2] = (glint_color_stop){1, {0, 0, 0.05}};
    m.turbulence = 0.7;
    m.transform = glint_transform_rotate(glint_transform_scale(glint_transform_identity(), 2, 1, 3),
                                         (glint_vec3){1, 2, 3}, 37);
    assert_true(glint_scene_add_texture(s, "veins", &m, &err) >= 0);
    glint_texture w = glint_texture_default(GLINT_TEXTURE_WOOD);
    assert_true(glint_scene_add_texture(s, "plain", &w, &err) >= 0);
    glint_status st;
    char *text = written(s, &st, &err);
    assert_non_null(text);
    assert_non_null(strstr(text, "  plain: {type: wood}\n"));
    free(text);
    glint_scene *back = round_trip(s);
    const glint_texture *b = &back->textures[0].desc;
    assert_int_equal(b->stop_count, 3);
    assert_same_bits(b->stops, m.stops, sizeof m.stops[0] * 3);
    assert_same_bits(&b->turbulence, &m.turbulence, sizeof m.turbulence);
    assert_same_bits(&b->transform, &m.transform, sizeof m.transform);
    assert_true(back->textures[0].placed && !back->textures[1].placed);
    glint_scene_free(back);
    glint_scene_free(s);
}

/* A material's absorption, metallic, bump and normal maps come back bit
 * for bit; one that absorbs nothing writes no absorption. */
static void test_absorption_and_metallic(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_error err;
    glint_material m = glint_material_default();
    m.refraction = 1;
    m.metallic = 0.3;
    m.absorption = (glint_absorption){{0.2, 1.0 / 3, 0.9}, 0.7};
    glint_texture grain = glint_texture_default(GLINT_TEXTURE_NOISE);
    glint_texture tiles = glint_texture_default(GLINT_TEXTURE_CHECKER);
    m.bump_texture = glint_scene_add_texture(s, "grain", &grain, &err);
    m.normal_texture = glint_scene_add_texture(s, "tiles", &tiles, &err);
    m.bump_strength = -0.03;
    assert_true(glint_scene_add_material(s, "glass", &m, &err) >= 0);
    glint_material plain = glint_material_default();
    assert_true(glint_scene_add_material(s, "plain", &plain, &err) >= 0);
    glint_status st;
    char *text = written(s, &st, &err);
    assert_non_null(text);
    assert_non_null(strstr(text, "  plain: {}\n"));
    free(text);
    glint_scene *back = round_trip(s);
    const glint_material *b = &back->materials[0].m;
    assert_same_bits(&b->absorption, &m.absorption, sizeof m.absorption);
    assert_same_bits(&b->metallic, &m.metallic, sizeof m.metallic);
    assert_same_bits(&b->bump_strength, &m.bump_strength, sizeof m.bump_strength);
    assert_string_equal(back->textures[b->bump_texture].name, "grain");
    assert_string_equal(back->textures[b->normal_texture].name, "tiles");
    assert_true(back->materials[1].m.absorption.distance == 0);
    glint_scene_free(back);
    glint_scene_free(s);
}

/* Combinations come back nested as they were, each part with its own
 * transform and material, a combination without a material without one,
 * a closed mesh's part as its arrays; one of no parts is refused. */
static void test_combinations(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_error err;
    int red = add_material(s, "red", (glint_color){1, 0, 0}), blue = add_material(s, "blue", (glint_color){0, 0, 1});
    glint_shape diff = glint_shape_default(GLINT_SHAPE_DIFFERENCE), join = glint_shape_default(GLINT_SHAPE_UNION);
    glint_shape ball = glint_shape_default(GLINT_SHAPE_SPHERE);
    ball.radius = 1;
    int d = glint_scene_add_shape(s, &diff, -1, NULL, &err);
    glint_transform up = glint_transform_rotate(glint_transform_translate(glint_transform_identity(), 0, 0.3, 0),
                                                (glint_vec3){1, 1, 0}, 33);
    assert_true(glint_scene_add_part(s, d, &ball, red, &up, &err) >= 0);
    int u = glint_scene_add_part(s, d, &join, blue, NULL, &err);
    assert_true(glint_scene_add_part(s, u, &ball, blue, NULL, &err) >= 0);
    static const float corners[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.5f};
    static const uint32_t faces[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    glint_mesh_data tetra = {corners, NULL, NULL, 4, faces, 4, NULL, blue};
    int made = glint_scene_add_mesh(s, NULL, &tetra, &err);
    assert_true(glint_scene_add_mesh_part(s, u, made, red, &up, &err) >= 0);
    assert_true(glint_scene_add_shape(s, &ball, red, NULL, &err) >= 0);
    glint_scene *back = round_trip(s);
    assert_int_equal(back->shape_count, 6);
    assert_non_null(back->shapes[4].solid);
    assert_int_equal(back->shapes[4].material, red);
    assert_same_bits(back->shapes[4].solid->view.positions, corners, sizeof corners);
    assert_same_bits(back->shapes[4].solid->view.indices, faces, sizeof faces);
    for (int i = 0; i < 6; i++) {
        assert_int_equal(back->shapes[i].desc.kind, s->shapes[i].desc.kind);
        assert_int_equal(back->shapes[i].part_of, s->shapes[i].part_of);
        assert_int_equal(back->shapes[i].part_count, s->shapes[i].part_count);
        assert_same_bits(&back->shapes[i].to_world, &s->shapes[i].to_world, sizeof(glint_transform));
    }
    assert_int_equal(back->shapes[0].material, -1);
    assert_int_equal(back->shapes[1].material, red);
    assert_int_equal(back->shapes[3].material, blue);
    glint_scene_free(back);
    int empty = glint_scene_add_shape(s, &join, red, NULL, &err);
    glint_status st;
    assert_null(written(s, &st, &err));
    assert_int_equal(st, GLINT_ERR_INVALID);
    char want[80];
    snprintf(want, sizeof want, "shape %d is a union of nothing, which a scene file cannot say", empty);
    assert_string_equal(err.message, want);
    glint_scene_free(s);
}

/* A mesh made from arrays is written out as them (vertices, normals,
 * uvs, faces), and comes back with the same floats; so does a polygon of
 * many points, made into triangles. */
static void test_meshes_from_arrays(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    int m = add_material(s, "m", (glint_color){1, 1, 1});
    static const float positions[] = {0, 0, 0, 1.1f, 0, 0, 0, 1.0f / 3, 0, 1, 1, 0.25f};
    static const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0.1f, 1, 0, 0, 1};
    static const float uvs[] = {0, 0, 1, 0, 0, 1, 1, 1e-7f};
    static const uint32_t indices[] = {0, 1, 2, 1, 3, 2};
    glint_mesh_data d = {positions, normals, uvs, 4, indices, 2, NULL, m};
    glint_error err;
    int made = glint_scene_add_mesh(s, NULL, &d, &err);
    glint_transform up = glint_transform_translate(glint_transform_identity(), 0, 2, 0);
    assert_true(glint_scene_add_instance(s, made, -1, &up, &err) >= 0);
    const glint_vec3 star[] = {{0, 2, 0}, {0.3, 1.4, 0}, {1, 1.3, 0}, {0.5, 0.9, 0}, {0.6, 0.2, 0}, {0, 0.5, 0}};
    assert_true(glint_scene_add_polygon(s, star, 6, m, NULL, &err) >= 0);
    glint_scene *back = round_trip(s);
    assert_int_equal(back->mesh_count, 2);
    assert_int_equal(back->instance_count, 2);
    for (int i = 0; i < 2; i++) {
        const mesh *a = &s->meshes[i], *b = &back->meshes[i];
        assert_int_equal(a->vertex_count, b->vertex_count);
        assert_int_equal(a->triangle_count, b->triangle_count);
        assert_same_bits(a->positions, b->positions, sizeof(float) * 3 * (size_t)a->vertex_count);
        assert_same_bits(a->uvs, b->uvs, sizeof(float) * 2 * (size_t)a->vertex_count);
        assert_same_bits(a->indices, b->indices, sizeof(uint32_t) * 3 * (size_t)a->triangle_count);
        assert_int_equal(b->material, m);
    }
    assert_same_bits(back->meshes[0].normals, normals, sizeof normals);
    assert_null(back->meshes[1].normals);
    assert_same_bits(&back->instances[0].to_world, &up, sizeof up);
    glint_scene_free(back);
    glint_scene_free(s);
}

static void test_refusals(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    int m = add_material(s, "m", (glint_color){1, 1, 1});
    static const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const uint32_t indices[] = {0, 1, 2};
    const int own[] = {m};
    glint_mesh_data d = {.positions = positions, .vertex_count = 3, .indices = indices, .triangle_count = 1,
                         .materials = own};
    glint_error err;
    int tri = glint_scene_add_mesh(s, "tri", &d, &err);
    assert_true(tri >= 0);
    glint_status st;
    char *text = written(s, &st, &err); /* not placed: nothing to say */
    assert_non_null(text);
    assert_null(strstr(text, "tri"));
    free(text);
    assert_true(glint_scene_add_instance(s, tri, -1, NULL, &err) >= 0);
    assert_null(written(s, &st, &err));
    assert_int_equal(st, GLINT_ERR_INVALID);
    assert_string_equal(err.message, "mesh 0 ('tri') gives its triangles materials of their own: a scene file can "
                                     "give only a model file's that");
    glint_scene_free(s);

    /* A PNG's bytes, from a file glint writes. */
    char path[1024];
    const char *dir = getenv("GLINT_TEST_TMP");
    snprintf(path, sizeof path, "%s/write_scene.png", dir ? dir : "/tmp");
    float pixels[12] = {0};
    glint_image image = {2, 2, pixels};
    assert_int_equal(glint_image_write(&image, path, &err), GLINT_OK);
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    unsigned char bytes[4096];
    size_t size = fread(bytes, 1, sizeof bytes, f);
    fclose(f);
    remove(path);
    s = glint_scene_new();
    glint_mapping uv = {.kind = GLINT_MAP_UV};
    assert_true(glint_scene_add_image_memory(s, "pic", bytes, size, uv, &err) >= 0);
    assert_null(written(s, &st, &err));
    assert_int_equal(st, GLINT_ERR_INVALID);
    assert_string_equal(err.message,
                        "texture 'pic' was decoded from bytes in memory: a scene file can name only image files");
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_numbers_and_transforms),
        cmocka_unit_test(test_settings),
        cmocka_unit_test(test_colors),
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_matrix_step),
        cmocka_unit_test(test_mapping_center),
        cmocka_unit_test(test_color_map_and_placement),
        cmocka_unit_test(test_absorption_and_metallic),
        cmocka_unit_test(test_combinations),
        cmocka_unit_test(test_meshes_from_arrays),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
