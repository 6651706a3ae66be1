/* test_scene_file.c - the YAML scene loader: every key of the format and its
 * effect on the loaded scene (or on a tiny render), includes, anchors and
 * merge keys, and objects loaded as they are parsed. Broken scenes are
 * test_scene_errors.c's. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#define SCENE_TEST_NAME "glint-scene-file"
#include "scene_file_test_util.h"

/* ------------------------------------------------------------- settings */

static void test_settings_every_key(void **state)
{
    glint_scene *s = load_good("glint: 1\n"
                               "settings:\n"
                               "  width: 33\n"
                               "  height: 17\n"
                               "  samples: 9\n"
                               "  sampler: jittered\n"
                               "  seed: 4294967295\n"
                               "  depth: 0\n"
                               "  background: [0.5, 0.25, 1]\n"
                               "  ambient: [0.2, 0.4, 0.6]\n"
                               "  output: renders/out.ppm\n");
    glint_settings st = glint_scene_get_settings(s);
    assert_int_equal(st.width, 33);
    assert_int_equal(st.height, 17);
    assert_int_equal(st.samples_per_pixel, 9);
    assert_int_equal(st.sampler, GLINT_SAMPLER_JITTERED);
    assert_true(st.seed == 4294967295u);
    assert_int_equal(st.max_depth, 0);
    assert_rgb(st.background, lin(0.5), lin(0.25), 1, 0);
    assert_rgb(st.ambient_light, lin(0.2), lin(0.4), lin(0.6), 0);
    assert_string_equal(glint_scene_get_output(s), "renders/out.ppm");
    glint_scene_free(s);
}

/* settings.ambient_occlusion: off unless given; given, 16 samples and no
 * limit unless it says. */
static void test_settings_ambient_occlusion(void **state)
{
    glint_scene *s = load_good("settings: {width: 8}\n");
    assert_int_equal(glint_scene_get_settings(s).occlusion_samples, 0);
    glint_scene_free(s);
    s = load_good("settings:\n  ambient_occlusion: {}\n");
    assert_int_equal(glint_scene_get_settings(s).occlusion_samples, 16);
    assert_exact(glint_scene_get_settings(s).occlusion_distance, 0);
    glint_scene_free(s);
    s = load_good("settings:\n  ambient_occlusion: {samples: 9, distance: 2.5}\n");
    assert_int_equal(glint_scene_get_settings(s).occlusion_samples, 9);
    assert_exact(glint_scene_get_settings(s).occlusion_distance, 2.5);
    glint_scene_free(s);
}

/* settings.filter and settings.adaptive: the box and no adaptive sampling
 * unless given; adaptive given, a threshold of 0.05 and 64 samples at most
 * unless it says; a filter's radius 0 (its own) unless it says. */
static void test_settings_filter_and_adaptive(void **state)
{
    glint_scene *s = load_good("settings: {samples: 5, sampler: sobol}\n");
    glint_settings st = glint_scene_get_settings(s);
    assert_int_equal(st.samples_per_pixel, 5);
    assert_int_equal(st.sampler, GLINT_SAMPLER_SOBOL);
    assert_int_equal(st.filter, GLINT_FILTER_BOX);
    assert_int_equal(st.adaptive_max_samples, 0);
    glint_scene_free(s);
    s = load_good("settings:\n  sampler: sobol\n  filter: {type: mitchell}\n  adaptive: {}\n");
    st = glint_scene_get_settings(s);
    assert_int_equal(st.filter, GLINT_FILTER_MITCHELL);
    assert_exact(st.filter_radius, 0);
    assert_int_equal(st.adaptive_max_samples, 64);
    assert_exact(st.adaptive_threshold, 0.05);
    glint_scene_free(s);
    s = load_good("settings:\n  sampler: sobol\n  filter: {type: lanczos, radius: 2.5}\n"
                  "  adaptive: {threshold: 0.2, max_samples: 4096}\n");
    st = glint_scene_get_settings(s);
    assert_int_equal(st.filter, GLINT_FILTER_LANCZOS);
    assert_exact(st.filter_radius, 2.5);
    assert_int_equal(st.adaptive_max_samples, 4096);
    assert_exact(st.adaptive_threshold, 0.2);
    glint_scene_free(s);
}

static void test_settings_other_values(void **state)
{
    glint_scene *s = load_good("settings:\n"
                               "  width: 65536\n"
                               "  height: 1\n"
                               "  samples: 4096\n"
                               "  sampler: regular\n"
                               "  seed: 0\n"
                               "  depth: 64\n"
                               "  output: OUT.PNG\n");
    glint_settings st = glint_scene_get_settings(s);
    assert_int_equal(st.width, 65536);
    assert_int_equal(st.height, 1);
    assert_int_equal(st.samples_per_pixel, 4096);
    assert_int_equal(st.sampler, GLINT_SAMPLER_REGULAR);
    assert_int_equal(st.seed, 0);
    assert_int_equal(st.max_depth, 64);
    assert_string_equal(glint_scene_get_output(s), "OUT.PNG");
    glint_scene_free(s);
}

/* A file that sets nothing gives the API's defaults; so does an empty one. */
static void test_defaults_of_an_empty_scene(void **state)
{
    const char *texts[] = {"glint: 1\n", "glint: 1 # and a comment\n"};
    for (size_t i = 0; i < COUNT(texts); i++) {
        glint_scene *s = load_good(texts[i]);
        glint_settings st = glint_scene_get_settings(s), def = glint_settings_default();
        assert_same_settings(&st, &def);
        glint_camera cam = glint_scene_get_camera(s);
        assert_vec(cam.position, 0, 0, 0, 0);
        assert_vec(cam.look_at, 0, 0, -1, 0);
        assert_vec(cam.up, 0, 1, 0, 0);
        assert_exact(cam.vfov_degrees, 45);
        assert_int_equal(glint_scene_get_fog(s).kind, GLINT_FOG_NONE);
        assert_null(glint_scene_get_output(s));
        glint_scene_counts c = glint_scene_get_counts(s);
        assert_int_equal(c.textures + c.materials + c.shapes + c.lights, 0);
        glint_scene_free(s);
    }
}

/* A scene file with nothing in it, or only comments, is refused, not
 * rendered black: the file named is probably not the one meant. An empty
 * included file is fine. */
static void test_empty_file_holds_no_scene(void **state)
{
    const char *texts[] = {"", "# only a comment\n", "\n\n   \n", "---\n"};
    for (size_t i = 0; i < COUNT(texts); i++) {
        report_log log = {0};
        glint_error err = {0};
        load_bad(texts[i], 0, &log, &err);
        assert_string_equal(err.message, "bad.yaml: the file holds no scene");
        assert_int_equal(err.status, GLINT_ERR_INVALID);
        assert_int_equal(log.count, 1);
    }
    write_tmp("empty/nothing.yaml", "# nothing yet\n");
    write_tmp("empty/top.yaml", "include: nothing.yaml\nsettings: {width: 7}\n");
    char path[PATH_SIZE];
    tmp_path_made(path, "empty/top.yaml");
    glint_error err = {0};
    glint_scene *s = glint_scene_load_file(path, NULL, &err);
    assert_non_null(s);
    assert_int_equal(glint_scene_get_settings(s).width, 7);
    glint_scene_free(s);
}

/* A scene read from a stream (glint -) is read whole and loads as from a
 * file: problems at their line and column under the name given, an empty
 * stream refused, an empty include fine, and the stream left open. */
static void test_load_stream(void **state)
{
    static char bad[] = "settings: {width: 8}\nobjects:\n  - {type: sphere, radius: -1, material: {}}\n";
    FILE *in = fmemopen(bad, strlen(bad), "r");
    assert_non_null(in);
    report_log log = {0};
    glint_load_options o = {.report = log_report, .report_user = &log};
    glint_error err = {0};
    assert_null(glint_scene_load_stream(in, "<stdin>", &o, &err));
    assert_string_equal(err.message, "<stdin>:3:28: 'radius' must be positive, got -1");
    assert_int_equal(log.count, 1);
    assert_int_equal(fclose(in), 0);

    static char nothing[] = "# nothing\n";
    in = fmemopen(nothing, strlen(nothing), "r");
    assert_null(glint_scene_load_stream(in, NULL, NULL, &err));
    assert_string_equal(err.message, "<stream>: the file holds no scene");
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    fclose(in);

    write_tmp("stream/nothing.yaml", "# nothing yet\n");
    char text[2 * PATH_SIZE];
    with_tmp("include: @TMP@/stream/nothing.yaml\nsettings: {width: 7}\n", text, sizeof text);
    in = fmemopen(text, strlen(text), "r");
    glint_scene *s = glint_scene_load_stream(in, "<stdin>", NULL, &err);
    assert_non_null(s);
    assert_int_equal(glint_scene_get_settings(s).width, 7);
    glint_scene_free(s);
    fclose(in);
}

/* Renders s (21x21, 20 degrees from 10 units, a blue background) and
 * checks the middle row shows a red ring about the centre, reaching from
 * within 1.01 units of it to within 1.68, then frees s. Pixels are
 * 2 tan(10 deg) 10 / 21 = 0.168 units across: the centre pixel looks
 * through the hole, pixel 16 lands 1.01 from the centre, pixel 20 1.68. */
static void shows_a_ring(glint_scene *s)
{
    glint_image img = render(s);
    const float *centre = img.pixels + 3 * (10 * 21 + 10), *on = img.pixels + 3 * (10 * 21 + 16),
                *off = img.pixels + 3 * (10 * 21 + 20);
    assert_true(centre[0] == 0 && centre[1] == 0 && centre[2] == 1);
    assert_true(on[0] == 1 && on[1] == 0 && on[2] == 0);
    assert_true(off[0] == 0 && off[1] == 0 && off[2] == 1);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* A ring facing the camera: the hole and the outside show the background,
 * the ring its colour (shows_a_ring); the file's keys reach the shape, the
 * defaults fill the rest. */
static void test_disk_ring(void **state)
{
    glint_scene *s = load_good("settings: {width: 21, height: 21, background: [0, 0, 1]}\n"
                               "camera: {position: [0, 0, 10], look_at: [0, 0, 0], fov: 20}\n"
                               "materials: {red: {color: [1, 0, 0], ambient: 1, diffuse: 0, specular: 0}}\n"
                               "objects:\n"
                               "  - {type: disk, radius: 1.5, inner_radius: 0.5, normal: [0, 0, 1], material: red}\n"
                               "  - {type: disk, center: [0, 0, -50], radius: 0.25, material: red}\n");
    assert_int_equal(s->shape_count, 2);
    const glint_shape *ring = &s->shapes[0].desc, *disc = &s->shapes[1].desc;
    assert_int_equal(ring->kind, GLINT_SHAPE_DISK);
    assert_exact(ring->radius, 1.5);
    assert_exact(ring->inner_radius, 0.5);
    assert_vec(ring->normal, 0, 0, 1, 0);
    assert_vec(disc->normal, 0, 1, 0, 0); /* the default: facing up */
    assert_exact(disc->inner_radius, 0);
    shows_a_ring(s);
}

/* A torus turned to face the camera: the hole shows the background, the
 * tube its colour, the outside the background again (shows_a_ring). */
static void test_torus_ring(void **state)
{
    glint_scene *s = load_good("settings: {width: 21, height: 21, background: [0, 0, 1]}\n"
                               "camera: {position: [0, 0, 10], look_at: [0, 0, 0], fov: 20}\n"
                               "materials: {red: {color: [1, 0, 0], ambient: 1, diffuse: 0, specular: 0}}\n"
                               "objects:\n"
                               "  - {type: torus, major_radius: 1, minor_radius: 0.3, material: red,\n"
                               "     transform: [{rotate_x: 90}]}\n");
    assert_int_equal(s->shape_count, 1);
    const glint_shape *ring = &s->shapes[0].desc;
    assert_int_equal(ring->kind, GLINT_SHAPE_TORUS);
    assert_exact(ring->radius, 1);
    assert_exact(ring->minor_radius, 0.3);
    /* The tube spans 0.7 to 1.3 from the centre. */
    shows_a_ring(s);
}

static void test_camera_every_key(void **state)
{
    glint_scene *s = load_good("camera:\n"
                               "  position: [1, 2, 3]\n"
                               "  look_at: [4, 5.5, -6]\n"
                               "  up: [0, 0, 1]\n"
                               "  fov: 35.5\n");
    glint_camera cam = glint_scene_get_camera(s);
    assert_vec(cam.position, 1, 2, 3, 0);
    assert_vec(cam.look_at, 4, 5.5, -6, 0);
    assert_vec(cam.up, 0, 0, 1, 0);
    assert_exact(cam.vfov_degrees, 35.5);
    glint_scene_free(s);
}

/* ------------------------------------------------------------------ fog */

static void test_fog_none(void **state)
{
    glint_scene *s = load_good("fog:\n  type: none\n  color: [1, 0, 0]\n");
    glint_fog f = glint_scene_get_fog(s);
    assert_int_equal(f.kind, GLINT_FOG_NONE);
    glint_scene_free(s);
}

static void test_fog_linear(void **state)
{
    glint_scene *s = load_good("fog:\n"
                               "  type: linear\n"
                               "  color: [0.5, 0.5, 0.5]\n"
                               "  start: -2\n"
                               "  end: 10.5\n");
    glint_fog f = glint_scene_get_fog(s);
    assert_int_equal(f.kind, GLINT_FOG_LINEAR);
    assert_rgb(f.color, lin(0.5), lin(0.5), lin(0.5), 0);
    assert_exact(f.start, -2);
    assert_exact(f.end, 10.5);
    glint_scene_free(s);
}

static void test_fog_exponential(void **state)
{
    glint_scene *s = load_good("fog: {type: exponential, color: \"#808080\", density: 0.25}\n");
    glint_fog f = glint_scene_get_fog(s);
    assert_int_equal(f.kind, GLINT_FOG_EXPONENTIAL);
    assert_rgb(f.color, lin(128 / 255.0), lin(128 / 255.0), lin(128 / 255.0), 0);
    assert_exact(f.density, 0.25);
    glint_scene_free(s);
}

/* ------------------------------------------------------------- textures */

/* focus_on focuses a thin lens at that point's depth along the view. */
static void test_camera_focus_on(void **state)
{
    glint_scene *s = load_good("camera: {type: thin_lens, position: [0, 1, 6], look_at: [0, 1, 0], aperture: 0.2,"
                               " focus_on: [2, 3, -1]}\n");
    assert_exact(glint_scene_get_camera(s).focus_distance, 7);
    glint_scene_free(s);
}

/* f_number and sensor_width reach the camera as written. */
static void test_camera_f_number(void **state)
{
    glint_scene *s = load_good("camera: {type: thin_lens, position: [0, 1, 6], look_at: [0, 1, 0], f_number: 2.8,"
                               " sensor_width: 0.024}\n");
    glint_camera c = glint_scene_get_camera(s);
    assert_exact(c.f_number, 2.8);
    assert_exact(c.sensor_width, 0.024);
    assert_exact(c.aperture, 0);
    glint_scene_free(s);
}

/* The environment names a texture; its intensity and rotation default to 1 and 0. */
static void test_environment(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  sky: {type: checker, colors: [[0, 0, 1], [1, 1, 1]]}\n"
                               "environment: {texture: sky, rotation: 30}\n");
    glint_environment env = glint_scene_get_environment(s);
    assert_int_equal(env.texture, 0);
    assert_exact(env.intensity, 1);
    assert_exact(env.rotation, 30);
    glint_scene_free(s);
}

static void test_checker_texture(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  tiles:\n"
                               "    type: checker\n"
                               "    colors: [\"#ff0000\", [0, 0, 1]]\n"
                               "    size: 0.25\n"
                               "    mapping: planar\n"
                               "  plain: {type: checker}\n");
    assert_int_equal(glint_scene_get_counts(s).textures, 2);
    const texture *t = &s->textures[texture_named(s, "tiles")];
    assert_ptr_equal(t->kind, &checker_texture);
    assert_rgb(t->a, 1, 0, 0, 0);
    assert_rgb(t->b, 0, 0, 1, 0);
    assert_exact(t->cell, 0.25);
    assert_int_equal(t->mapping.kind, GLINT_MAP_PLANAR);
    /* Defaults: black and white cells of one unit, the shape's own (u, v). */
    t = &s->textures[texture_named(s, "plain")];
    assert_ptr_equal(t->kind, &checker_texture);
    assert_rgb(t->a, 0, 0, 0, 0);
    assert_rgb(t->b, 1, 1, 1, 0);
    assert_exact(t->cell, 1);
    assert_int_equal(t->mapping.kind, GLINT_MAP_UV);
    assert_vec(t->mapping.center, 0, 0, 0, 0);
    assert_exact(t->mapping.scale, 1);
    glint_scene_free(s);
}

static void test_mapping_as_a_word(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  a: {type: checker, mapping: uv}\n"
                               "  b: {type: checker, mapping: planar}\n"
                               "  c: {type: checker, mapping: spherical}\n"
                               "  d: {type: checker, mapping: cylindrical}\n");
    assert_int_equal(s->textures[texture_named(s, "a")].mapping.kind, GLINT_MAP_UV);
    assert_int_equal(s->textures[texture_named(s, "b")].mapping.kind, GLINT_MAP_PLANAR);
    assert_int_equal(s->textures[texture_named(s, "c")].mapping.kind, GLINT_MAP_SPHERICAL);
    assert_int_equal(s->textures[texture_named(s, "d")].mapping.kind, GLINT_MAP_CYLINDRICAL);
    /* Without a center, the mapping is centred on each shape it is on. */
    assert_false(s->textures[texture_named(s, "c")].mapping.center_given);
    glint_scene_free(s);
}

static void test_mapping_as_a_map(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  flat:\n"
                               "    type: checker\n"
                               "    mapping:\n"
                               "      type: planar\n"
                               "      center: [1, 2, 3]\n"
                               "      u_axis: [0, 0, 1]\n"
                               "      v_axis: [0, 1, 0]\n"
                               "      scale: 2.5\n"
                               "  can: {type: checker, mapping: {type: cylindrical, scale: 4, center: [0, -1, 0]}}\n"
                               "  ball: {type: checker, mapping: {type: spherical, center: [5, 5, 5]}}\n"
                               "  own: {type: checker, mapping: {type: uv}}\n");
    glint_mapping m = s->textures[texture_named(s, "flat")].mapping;
    assert_int_equal(m.kind, GLINT_MAP_PLANAR);
    assert_vec(m.center, 1, 2, 3, 0);
    assert_true(m.center_given);
    assert_vec(m.u_axis, 0, 0, 1, 0);
    assert_vec(m.v_axis, 0, 1, 0, 0);
    assert_exact(m.scale, 2.5);
    m = s->textures[texture_named(s, "can")].mapping;
    assert_int_equal(m.kind, GLINT_MAP_CYLINDRICAL);
    assert_exact(m.scale, 4);
    assert_vec(m.center, 0, -1, 0, 0);
    m = s->textures[texture_named(s, "ball")].mapping;
    assert_int_equal(m.kind, GLINT_MAP_SPHERICAL);
    assert_vec(m.center, 5, 5, 5, 0);
    assert_true(m.center_given);
    assert_int_equal(s->textures[texture_named(s, "own")].mapping.kind, GLINT_MAP_UV);
    glint_scene_free(s);
}

/* The texels of tiny.png below, as linear values. */
static void check_tiny_texels(const texture *t)
{
    assert_ptr_equal(t->kind, &image_texture);
    assert_int_equal(t->image.width, 2);
    assert_int_equal(t->image.height, 2);
    static const unsigned char want[12] = {255, 0, 0, 0, 128, 255, 10, 20, 30, 255, 255, 255};
    for (int i = 0; i < 12; i++)
        assert_exact(texture_image_at(&t->image, i), (float)glint_srgb_to_linear(want[i] / 255.0));
}

/* An image texture named relative to the scene file, in a folder beside
 * it, decoded once a material uses it; one no material uses is checked but
 * never decoded. */
static void test_image_texture_from_a_file(void **state)
{
    static const unsigned char rgb[12] = {255, 0, 0, 0, 128, 255, 10, 20, 30, 255, 255, 255};
    write_png("img/maps/tiny.png", 2, 2, rgb);
    write_tmp("img/maps/unused.png", "\x89PNG\r\n\x1a\n but nothing a PNG has after its signature");
    write_tmp("img/scene.yaml", "textures:\n"
                                "  tiny:\n"
                                "    type: image\n"
                                "    file: maps/tiny.png\n"
                                "    mapping: {type: planar, center: [0, 1, 0], scale: 3}\n"
                                "  plain: {type: image, file: maps/tiny.png}\n"
                                "  unused: {type: image, file: maps/unused.png}\n"
                                "materials: {a: {texture: tiny}, b: {texture: plain}}\n");
    glint_scene *s = load_good_file("img/scene.yaml");
    assert_null(s->textures[texture_named(s, "unused")].image.srgb);
    assert_int_equal(s->image_files.count, 1);
    const texture *t = &s->textures[texture_named(s, "tiny")];
    check_tiny_texels(t);
    assert_int_equal(t->mapping.kind, GLINT_MAP_PLANAR);
    assert_vec(t->mapping.center, 0, 1, 0, 0);
    assert_exact(t->mapping.scale, 3);
    t = &s->textures[texture_named(s, "plain")];
    check_tiny_texels(t);
    assert_int_equal(t->mapping.kind, GLINT_MAP_UV);
    glint_scene_free(s);

    /* From memory, paths resolve against the folder of the name given. */
    char name[PATH_SIZE];
    tmp_path(name, "img/memory.yaml");
    s = load_good_named("textures:\n  tiny: {type: image, file: maps/tiny.png}\nmaterials: {m: {texture: tiny}}\n",
                        name);
    check_tiny_texels(&s->textures[0]);
    glint_scene_free(s);
}

/* ------------------------------------------------------------ materials */

static void test_material_every_key(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  checks: {type: checker}\n"
                               "  other: {type: checker, size: 2}\n"
                               "materials:\n"
                               "  glass:\n"
                               "    color: [0.5, 0.25, 0.75]\n"
                               "    texture: other\n"
                               "    ambient: 0.3\n"
                               "    diffuse: 0.7\n"
                               "    specular: 0.4\n"
                               "    shininess: 12.5\n"
                               "    reflectivity: 0.25\n"
                               "    transparency: 0.2\n"
                               "    refraction: 0.6\n"
                               "    ior: 1.33\n"
                               "    tint: 0.8\n"
                               "    fresnel: true\n"
                               "  plain: {}\n"
                               "  unlit: {fresnel: false, diffuse: 0, specular: 0, ambient: 1}\n");
    assert_int_equal(glint_scene_get_counts(s).materials, 3);
    const glint_material *m = &s->materials[material_named(s, "glass")].m;
    assert_rgb(m->color, lin(0.5), lin(0.25), lin(0.75), 0);
    assert_int_equal(m->texture, texture_named(s, "other"));
    assert_int_equal(m->texture, 1);
    assert_exact(m->ambient, 0.3);
    assert_exact(m->diffuse, 0.7);
    assert_exact(m->specular, 0.4);
    assert_exact(m->shininess, 12.5);
    assert_exact(m->reflectivity, 0.25);
    assert_exact(m->transparency, 0.2);
    assert_exact(m->refraction, 0.6);
    assert_exact(m->ior, 1.33);
    assert_exact(m->tint, 0.8);
    assert_true(m->fresnel);

    /* Nothing given: glint_material_default(). */
    glint_material def = glint_material_default();
    m = &s->materials[material_named(s, "plain")].m;
    assert_same_material(m, &def);
    assert_int_equal(m->texture, -1);

    m = &s->materials[material_named(s, "unlit")].m;
    assert_false(m->fresnel);
    assert_exact(m->diffuse, 0);
    assert_exact(m->specular, 0);
    assert_exact(m->ambient, 1);
    assert_exact(m->shininess, def.shininess);
    glint_scene_free(s);
}

/* --------------------------------------------------------------- lights */

static void test_lights(void **state)
{
    glint_scene *s = load_good("lights:\n"
                               "  - {type: point, position: [1, 2, 3], color: [1, 0.5, 0], intensity: 2}\n"
                               "  - type: spot\n"
                               "    position: [0, 5, 0]\n"
                               "    direction: [0, -2, 0]\n"
                               "    color: \"#ffffff\"\n"
                               "    angle: 30\n"
                               "    falloff: 10\n"
                               "  - {type: directional, direction: [-1, -1, -1], color: {linear: [0.2, 0.4, 0.6]},"
                               " intensity: 0.5}\n"
                               "  - {type: spot, position: [0, 0, 0], direction: [1, 0, 0], angle: 90}\n"
                               "  - {type: point, position: [0, 0, 0]}\n"
                               "  - {type: point, position: [0, 0, 0], intensity: 0}\n");
    assert_int_equal(glint_scene_get_counts(s).lights, 6);
    const glint_light *l = &s->lights[0].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_POINT);
    assert_vec(l->position, 1, 2, 3, 0);
    assert_rgb(l->color, 2, 2 * lin(0.5), 0, 1e-15);

    l = &s->lights[1].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_SPOT);
    assert_vec(l->position, 0, 5, 0, 0);
    assert_vec(l->direction, 0, -2, 0, 0);
    assert_rgb(l->color, 1, 1, 1, 0);
    assert_exact(l->cone_angle, 30);
    assert_exact(l->falloff_angle, 10);

    l = &s->lights[2].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_DIRECTIONAL);
    assert_vec(l->direction, -1, -1, -1, 0);
    assert_rgb(l->color, 0.1, 0.2, 0.3, 1e-15);

    l = &s->lights[3].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_SPOT);
    assert_exact(l->cone_angle, 90);
    assert_exact(l->falloff_angle, 0);

    /* Defaults: white, intensity 1. */
    assert_rgb(s->lights[4].desc.color, 1, 1, 1, 0);
    assert_rgb(s->lights[5].desc.color, 0, 0, 0, 0);
    glint_scene_free(s);
}

/* Area lights: their shapes, their radiance and their sample counts. */
static void test_area_lights(void **state)
{
    glint_scene *s = load_good("lights:\n"
                               "  - {type: sphere, position: [1, 2, 3], radius: 0.5, intensity: 4}\n"
                               "  - {type: rectangle, corner: [-1, 5, -1], edge1: [2, 0, 0], edge2: [0, 0, 2],"
                               " color: [1, 0.5, 0], samples: 9}\n"
                               "  - {type: disk, position: [0, 3, 0], direction: [0, -1, 0], radius: 2, samples: 1}\n");
    assert_int_equal(glint_scene_get_counts(s).lights, 3);
    const glint_light *l = &s->lights[0].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_SPHERE);
    assert_vec(l->position, 1, 2, 3, 0);
    assert_exact(l->radius, 0.5);
    assert_rgb(l->color, 4, 4, 4, 0);
    assert_int_equal(l->samples, 16);
    l = &s->lights[1].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_RECTANGLE);
    assert_vec(l->position, -1, 5, -1, 0);
    assert_vec(l->edge1, 2, 0, 0, 0);
    assert_vec(l->edge2, 0, 0, 2, 0);
    assert_rgb(l->color, 1, lin(0.5), 0, 1e-15);
    assert_int_equal(l->samples, 9);
    assert_vec(s->lights[1].normal, 0, -1, 0, 0);
    l = &s->lights[2].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_DISK);
    assert_exact(l->radius, 2);
    assert_int_equal(l->samples, 1);
    glint_scene_free(s);
    /* Among delta lights, the area lights are listed by their index, as
     * camera rays look through that list alone. */
    s = load_good("lights:\n"
                  "  - {type: point, position: [0, 5, 0]}\n"
                  "  - {type: sphere, position: [1, 2, 3], radius: 0.5}\n"
                  "  - {type: directional, direction: [0, -1, 0]}\n"
                  "  - {type: disk, position: [0, 3, 0], direction: [0, -1, 0], radius: 2}\n");
    assert_int_equal(s->area_light_count, 2);
    assert_int_equal(s->area_lights[0], 1);
    assert_int_equal(s->area_lights[1], 3);
    glint_scene_free(s);
}

/* --------------------------------------------------------------- shapes */

static const char *const MATS = "materials:\n  m: {}\n  n: {color: [0, 1, 0]}\n";

static glint_scene *load_objects(const char *objects)
{
    char yaml[8192];
    snprintf(yaml, sizeof yaml, "%sobjects:\n%s", MATS, objects);
    return load_good(yaml);
}

static void test_sphere_and_plane(void **state)
{
    glint_scene *s = load_objects("  - {type: sphere, material: m, center: [1, 2, 3], radius: 0.5}\n"
                                  "  - {type: sphere, material: n, radius: 2}\n"
                                  "  - {type: plane, material: m, point: [0, -1, 0], normal: [0, 2, 0]}\n"
                                  "  - {type: plane, material: m, normal: [3, 0, 4]}\n");
    assert_int_equal(glint_scene_get_counts(s).shapes, 4);
    const glint_shape *d = &s->shapes[0].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_SPHERE);
    assert_vec(d->center, 1, 2, 3, 0);
    assert_exact(d->radius, 0.5);
    assert_int_equal(s->shapes[0].material, material_named(s, "m"));
    assert_false(s->shapes[0].has_transform);

    d = &s->shapes[1].desc;
    assert_vec(d->center, 0, 0, 0, 0);
    assert_exact(d->radius, 2);
    assert_int_equal(s->shapes[1].material, material_named(s, "n"));

    /* The plane's normal is kept as a unit vector. */
    d = &s->shapes[2].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_PLANE);
    assert_vec(d->center, 0, -1, 0, 0);
    assert_vec(d->normal, 0, 1, 0, 1e-15);
    d = &s->shapes[3].desc;
    assert_vec(d->center, 0, 0, 0, 0);
    assert_vec(d->normal, 0.6, 0, 0.8, 1e-15);
    glint_scene_free(s);
}

static void test_polygons(void **state)
{
    glint_scene *s = load_objects("  - type: polygon\n"
                                  "    material: m\n"
                                  "    points: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                                  "  - type: polygon\n"
                                  "    material: m\n"
                                  "    points:\n"
                                  "      - [-1, 0, -1]\n"
                                  "      - [1, 0, -1]\n"
                                  "      - [1, 0, 1]\n"
                                  "      - [-1, 0, 1]\n");
    const glint_shape *d = &s->shapes[0].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_POLYGON);
    assert_int_equal(d->point_count, 3);
    assert_vec(d->points[0], 0, 0, 0, 0);
    assert_vec(d->points[1], 1, 0, 0, 0);
    assert_vec(d->points[2], 0, 1, 0, 0);
    d = &s->shapes[1].desc;
    assert_int_equal(d->point_count, 4);
    assert_vec(d->points[0], -1, 0, -1, 0);
    assert_vec(d->points[1], 1, 0, -1, 0);
    assert_vec(d->points[2], 1, 0, 1, 0);
    assert_vec(d->points[3], -1, 0, 1, 0);
    /* Points running anticlockwise seen from -y face down. */
    assert_vec(s->shapes[1].poly_normal, 0, -1, 0, 1e-15);
    glint_scene_free(s);
}

static void test_box_cylinder_cone(void **state)
{
    glint_scene *s = load_objects("  - {type: box, material: m, min: [-1, -2, -3], max: [1, 2, 3.5]}\n"
                                  "  - {type: cylinder, material: m, center: [1, 0, 1], radius: 0.5, height: 2}\n"
                                  "  - {type: cylinder, material: m, radius: 1, height: 3, capped: false}\n"
                                  "  - {type: cone, material: m, center: [0, 1, 0], radius: 2, height: 4}\n"
                                  "  - {type: cone, material: n, radius: 1, height: 1, capped: false}\n"
                                  "  - {type: cylinder, material: m, radius: 1, height: 1, capped: true}\n");
    const glint_shape *d = &s->shapes[0].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_BOX);
    assert_vec(d->min, -1, -2, -3, 0);
    assert_vec(d->max, 1, 2, 3.5, 0);

    d = &s->shapes[1].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_CYLINDER);
    assert_vec(d->center, 1, 0, 1, 0);
    assert_exact(d->radius, 0.5);
    assert_exact(d->height, 2);
    assert_true(d->capped);

    d = &s->shapes[2].desc;
    assert_vec(d->center, 0, 0, 0, 0);
    assert_exact(d->radius, 1);
    assert_exact(d->height, 3);
    assert_false(d->capped);

    d = &s->shapes[3].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_CONE);
    assert_vec(d->center, 0, 1, 0, 0);
    assert_exact(d->radius, 2);
    assert_exact(d->height, 4);
    assert_true(d->capped);

    d = &s->shapes[4].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_CONE);
    assert_false(d->capped);
    assert_int_equal(s->shapes[4].material, material_named(s, "n"));
    assert_true(s->shapes[5].desc.capped);
    glint_scene_free(s);
}

/* ----------------------------------------------------------- transforms */

static void test_transform_each_step(void **state)
{
    glint_scene *s = load_objects("  - {type: sphere, material: m, radius: 1, transform: [{translate: [1, -2, 3.5]}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{scale: 2}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{scale: [2, 3, -4]}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{rotate_x: 90}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{rotate_y: 90}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{rotate_z: 90}]}\n"
                                  "  - type: sphere\n"
                                  "    material: m\n"
                                  "    radius: 1\n"
                                  "    transform:\n"
                                  "      - rotate: {axis: [0, 0, 2], angle: 90}\n"
                                  "  - type: sphere\n"
                                  "    material: m\n"
                                  "    radius: 1\n"
                                  "    transform:\n"
                                  "      - rotate: {axis: [1, 1, 1], angle: 120}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: []}\n");
    static const double translate[3][4] = {{1, 0, 0, 1}, {0, 1, 0, -2}, {0, 0, 1, 3.5}};
    static const double uniform[3][4] = {{2, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 2, 0}};
    static const double per_axis[3][4] = {{2, 0, 0, 0}, {0, 3, 0, 0}, {0, 0, -4, 0}};
    /* Right-handed turns by 90 degrees. */
    static const double about_x[3][4] = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}};
    static const double about_y[3][4] = {{0, 0, 1, 0}, {0, 1, 0, 0}, {-1, 0, 0, 0}};
    static const double about_z[3][4] = {{0, -1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}};
    /* A third of a turn about (1, 1, 1) sends x to y, y to z and z to x. */
    static const double cycle[3][4] = {{0, 0, 1, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}};
    static const double identity[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    assert_matrix(&s->shapes[0].to_world, translate, 0);
    assert_matrix(&s->shapes[1].to_world, uniform, 0);
    assert_matrix(&s->shapes[2].to_world, per_axis, 0);
    assert_matrix(&s->shapes[3].to_world, about_x, 1e-15);
    assert_matrix(&s->shapes[4].to_world, about_y, 1e-15);
    assert_matrix(&s->shapes[5].to_world, about_z, 1e-15);
    assert_matrix(&s->shapes[6].to_world, about_z, 1e-15);
    assert_matrix(&s->shapes[7].to_world, cycle, 1e-15);
    assert_matrix(&s->shapes[8].to_world, identity, 0);
    assert_false(s->shapes[8].has_transform);
    glint_scene_free(s);
}

/* Steps apply in the order written: the first step acts first. */
static void test_transform_order(void **state)
{
    glint_scene *s = load_objects("  - {type: sphere, material: m, radius: 1, transform: [{scale: 2}, {translate: [1, 2, 3]}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{translate: [1, 2, 3]}, {scale: [2, 3, 4]}]}\n"
                                  "  - type: sphere\n"
                                  "    material: m\n"
                                  "    radius: 1\n"
                                  "    transform:\n"
                                  "      - rotate_z: 90\n"
                                  "      - translate: [5, 0, 0]\n"
                                  "      - scale: [1, 2, 1]\n");
    static const double scale_then_move[3][4] = {{2, 0, 0, 1}, {0, 2, 0, 2}, {0, 0, 2, 3}};
    static const double move_then_scale[3][4] = {{2, 0, 0, 2}, {0, 3, 0, 6}, {0, 0, 4, 12}};
    assert_matrix(&s->shapes[0].to_world, scale_then_move, 0);
    assert_matrix(&s->shapes[1].to_world, move_then_scale, 0);
    /* (1, 0, 0) turns to (0, 1, 0), moves to (5, 1, 0), stretches to (5, 2, 0). */
    glint_vec3 p = glint_transform_point(&s->shapes[2].to_world, (glint_vec3){1, 0, 0});
    assert_vec(p, 5, 2, 0, 1e-15);
    p = glint_transform_point(&s->shapes[2].to_world, (glint_vec3){0, 0, 1});
    assert_vec(p, 5, 0, 1, 1e-15);
    glint_scene_free(s);
}

/* A combination's objects are its parts, in order, placed by its transform
 * after their own and given its material unless they have one; a group
 * inside a combination is one part, the union of its objects (so an
 * intersection with a group is not an intersection with each). */
static void test_combinations(void **state)
{
    glint_scene *s = load_objects("  - type: intersection\n"
                                  "    material: n\n"
                                  "    transform: [{translate: [10, 0, 0]}]\n"
                                  "    objects:\n"
                                  "      - {type: sphere, radius: 1, material: m}\n"
                                  "      - type: group\n"
                                  "        objects:\n"
                                  "          - {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"
                                  "          - {type: difference, objects: [{type: sphere, radius: 2}]}\n"
                                  "  - {type: sphere, material: m, radius: 1}\n");
    int m = material_named(s, "m"), n = material_named(s, "n");
    assert_int_equal(glint_scene_get_counts(s).shapes, 7);
    const shape *sh = s->shapes;
    assert_int_equal(sh[0].desc.kind, GLINT_SHAPE_INTERSECTION);
    assert_int_equal(sh[0].part_count, 2);
    assert_int_equal(sh[0].parts[0], 1);
    assert_int_equal(sh[0].parts[1], 2);
    assert_int_equal(sh[1].material, m);
    assert_int_equal(sh[2].desc.kind, GLINT_SHAPE_UNION);
    assert_int_equal(sh[2].part_of, 0);
    assert_int_equal(sh[2].part_count, 2);
    assert_int_equal(sh[3].material, n);
    assert_int_equal(sh[4].desc.kind, GLINT_SHAPE_DIFFERENCE);
    assert_int_equal(sh[5].part_of, 4);
    assert_int_equal(sh[6].part_of, -1);
    static const double moved[3][4] = {{1, 0, 0, 10}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    assert_matrix(&sh[5].to_world, moved, 0);
    assert_false(sh[0].has_transform || sh[2].has_transform || sh[4].has_transform);
    glint_scene_free(s);
}

/* A group's transform applies after each child's own; its material goes to
 * children without one, through nested groups; a child's own material wins. */
static void test_groups(void **state)
{
    glint_scene *s = load_objects("  - type: group\n"
                                  "    material: n\n"
                                  "    transform: [{translate: [10, 0, 0]}]\n"
                                  "    objects:\n"
                                  "      - {type: sphere, radius: 1, transform: [{scale: 2}]}\n"
                                  "      - {type: sphere, radius: 1, material: m}\n"
                                  "      - type: group\n"
                                  "        transform: [{rotate_z: 90}]\n"
                                  "        objects:\n"
                                  "          - {type: box, min: [0, 0, 0], max: [1, 1, 1], transform: [{translate: [1, 0, 0]}]}\n"
                                  "          - {type: sphere, radius: 1, material: {color: [1, 0, 0]}}\n"
                                  "  - type: group\n"
                                  "    material: {ambient: 0.75}\n"
                                  "    objects:\n"
                                  "      - {type: sphere, radius: 3}\n"
                                  "      - {type: sphere, radius: 4}\n"
                                  "  - {type: sphere, material: m, radius: 1}\n");
    int m = material_named(s, "m"), n = material_named(s, "n");
    assert_int_equal(glint_scene_get_counts(s).shapes, 7);
    /* Scaled by 2 first, then moved by 10: (1, 0, 0) lands at (12, 0, 0). */
    static const double scaled_moved[3][4] = {{2, 0, 0, 10}, {0, 2, 0, 0}, {0, 0, 2, 0}};
    assert_matrix(&s->shapes[0].to_world, scaled_moved, 0);
    assert_int_equal(s->shapes[0].material, n);
    static const double moved[3][4] = {{1, 0, 0, 10}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    assert_matrix(&s->shapes[1].to_world, moved, 0);
    assert_int_equal(s->shapes[1].material, m);
    /* Box: moved by 1, turned by the inner group, moved by the outer. */
    glint_vec3 p = glint_transform_point(&s->shapes[2].to_world, (glint_vec3){0, 0, 0});
    assert_vec(p, 10, 1, 0, 1e-15);
    p = glint_transform_point(&s->shapes[2].to_world, (glint_vec3){1, 0, 0});
    assert_vec(p, 10, 2, 0, 1e-15);
    assert_int_equal(s->shapes[2].material, n);
    /* An inline material is a new, unnamed material. */
    int inline_red = s->shapes[3].material;
    assert_true(inline_red != m && inline_red != n);
    assert_null(s->materials[inline_red].name);
    assert_rgb(s->materials[inline_red].m.color, 1, 0, 0, 0);
    assert_exact(s->materials[inline_red].m.ambient, glint_material_default().ambient);
    /* A group's inline material is one material shared by its children. */
    int shared = s->shapes[4].material;
    assert_int_equal(s->shapes[5].material, shared);
    assert_null(s->materials[shared].name);
    assert_exact(s->materials[shared].m.ambient, 0.75);
    assert_false(s->shapes[4].has_transform);
    assert_int_equal(s->shapes[6].material, m);
    assert_int_equal(glint_scene_get_counts(s).materials, 4);
    glint_scene_free(s);
}

/* -------------------------------------------------------------- colours */

static void test_colours(void **state)
{
    glint_scene *s = load_good("materials:\n"
                               "  display: {color: [0.5, 0.2, 1]}\n"
                               "  hex: {color: \"#ff8000\"}\n"
                               "  upper: {color: \"#ABCDEF\"}\n"
                               "  linear: {color: {linear: [0.5, 0.2, 3]}}\n"
                               "  black: {color: [0, 0, 0]}\n");
    assert_rgb(s->materials[material_named(s, "display")].m.color, lin(0.5), lin(0.2), 1, 0);
    assert_near(lin(0.5), 0.21404114048223255, 1e-15);
    assert_rgb(s->materials[material_named(s, "hex")].m.color, 1, lin(128 / 255.0), 0, 0);
    assert_rgb(s->materials[material_named(s, "upper")].m.color, lin(0xab / 255.0), lin(0xcd / 255.0),
               lin(0xef / 255.0), 0);
    assert_rgb(s->materials[material_named(s, "linear")].m.color, 0.5, 0.2, 3, 0);
    assert_rgb(s->materials[material_named(s, "black")].m.color, 0, 0, 0, 0);
    glint_scene_free(s);
}

/* ------------------------------------------------------------- includes */

static void test_includes(void **state)
{
    write_tmp("inc/main.yaml", "glint: 1\n"
                               "include: [parts/base.yaml, parts/materials.yaml]\n"
                               "settings:\n"
                               "  height: 20\n"
                               "camera:\n"
                               "  position: [0, 0, 9]\n"
                               "materials:\n"
                               "  blue: {color: [0, 0, 1], texture: checks}\n"
                               "objects:\n"
                               "  - {type: sphere, material: red, radius: 1}\n"
                               "  - {type: sphere, material: blue, radius: 2}\n");
    write_tmp("inc/parts/base.yaml", "include: more/textures.yaml   # relative to parts/\n"
                                     "settings:\n"
                                     "  width: 40\n"
                                     "  height: 30\n"
                                     "  samples: 4\n"
                                     "camera: {position: [0, 0, 5], fov: 50}\n"
                                     "lights:\n"
                                     "  - {type: point, position: [1, 1, 1]}\n");
    write_tmp("inc/parts/more/textures.yaml", "textures:\n  checks: {type: checker, size: 3}\n");
    write_tmp("inc/parts/materials.yaml", "materials:\n"
                                          "  red: {color: [1, 0, 0], texture: checks}\n"
                                          "objects:\n"
                                          "  - {type: box, material: red, min: [0, 0, 0], max: [1, 1, 1]}\n");
    glint_scene *s = load_good_file("inc/main.yaml");
    glint_settings st = glint_scene_get_settings(s);
    assert_int_equal(st.width, 40);   /* from the include */
    assert_int_equal(st.height, 20);  /* the including file wins, key by key */
    assert_int_equal(st.samples_per_pixel, 4);
    glint_camera cam = glint_scene_get_camera(s);
    assert_vec(cam.position, 0, 0, 9, 0);
    assert_exact(cam.vfov_degrees, 50);
    glint_scene_counts c = glint_scene_get_counts(s);
    assert_int_equal(c.textures, 1);
    assert_int_equal(c.materials, 2);
    assert_int_equal(c.shapes, 3);
    assert_int_equal(c.lights, 1);
    /* Names are shared across files, in both directions of the include. */
    int checks = texture_named(s, "checks");
    assert_exact(s->textures[checks].cell, 3);
    int red = material_named(s, "red"), blue = material_named(s, "blue");
    assert_int_equal(s->materials[red].m.texture, checks);
    assert_int_equal(s->materials[blue].m.texture, checks);
    /* Included objects come first. */
    assert_int_equal(s->shapes[0].desc.kind, GLINT_SHAPE_BOX);
    assert_int_equal(s->shapes[0].material, red);
    assert_int_equal(s->shapes[1].material, red);
    assert_int_equal(s->shapes[2].material, blue);
    glint_scene_free(s);
}

/* --------------------------------------------------- anchors and merges */

static void test_anchors_and_aliases(void **state)
{
    glint_scene *s = load_good("camera:\n"
                               "  position: &eye [0, 1, 5]\n"
                               "  look_at: [0, 0, 0]\n"
                               "materials:\n"
                               "  m: &plain {specular: 0.125}\n"
                               "  again: *plain\n"
                               "lights:\n"
                               "  - {type: point, position: *eye}\n"
                               "objects:\n"
                               "  - &ball {type: sphere, material: m, radius: 2, center: [1, 1, 1]}\n"
                               "  - *ball\n");
    assert_vec(s->lights[0].desc.position, 0, 1, 5, 0);
    assert_exact(s->materials[material_named(s, "again")].m.specular, 0.125);
    assert_int_equal(glint_scene_get_counts(s).shapes, 2);
    assert_exact(s->shapes[1].desc.radius, 2);
    assert_vec(s->shapes[1].desc.center, 1, 1, 1, 0);
    glint_scene_free(s);
}

static void test_merge_keys(void **state)
{
    glint_scene *s = load_good("materials:\n"
                               "  base: &base {color: [1, 0, 0], specular: 0.5, shininess: 10}\n"
                               "  shiny:\n"
                               "    <<: *base\n"
                               "    shininess: 99\n"
                               "  both: {<<: [*base, {reflectivity: 0.25, specular: 0.75}], ambient: 0.125}\n"
                               "objects:\n"
                               "  - &ball {type: sphere, material: base, radius: 2}\n"
                               "  - {<<: *ball, center: [5, 0, 0], material: shiny}\n");
    const glint_material *m = &s->materials[material_named(s, "shiny")].m;
    assert_rgb(m->color, 1, 0, 0, 0);
    assert_exact(m->specular, 0.5);
    assert_exact(m->shininess, 99); /* a key written in the map wins */
    m = &s->materials[material_named(s, "both")].m;
    assert_exact(m->specular, 0.5); /* the earlier merge wins */
    assert_exact(m->reflectivity, 0.25);
    assert_exact(m->ambient, 0.125);
    assert_exact(m->shininess, 10);
    assert_int_equal(s->shapes[1].desc.kind, GLINT_SHAPE_SPHERE);
    assert_exact(s->shapes[1].desc.radius, 2);
    assert_vec(s->shapes[1].desc.center, 5, 0, 0, 0);
    assert_int_equal(s->shapes[1].material, material_named(s, "shiny"));
    glint_scene_free(s);
}

static void test_version_and_comments(void **state)
{
    glint_scene *s = load_good("# A scene with comments everywhere.\n"
                               "glint: 1        # the format version\n"
                               "settings:       # the image\n"
                               "  width: 8      # eight pixels\n"
                               "  # height: 999\n"
                               "materials: {m: {}}  # one material\n"
                               "objects:\n"
                               "  # - {type: sphere, material: m, radius: 1}\n"
                               "  - {type: sphere, material: m, radius: 3}  # radius: 4\n");
    assert_int_equal(glint_scene_get_settings(s).width, 8);
    assert_int_equal(glint_scene_get_settings(s).height, 480);
    assert_int_equal(glint_scene_get_counts(s).shapes, 1);
    assert_exact(s->shapes[0].desc.radius, 3);
    glint_scene_free(s);
}

/* --------------------------------------------------------- tiny renders */

/* Settings ambient times material ambient times colour, nothing else lit. */
static void test_render_ambient(void **state)
{
    glint_scene *s = load_good("settings: {width: 2, height: 2, ambient: {linear: [0.5, 1, 1]}, background: [1, 1, 1]}\n"
                               "camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 10}\n"
                               "materials:\n"
                               "  flat: {color: {linear: [0.5, 0.25, 1]}, ambient: 0.5, diffuse: 0, specular: 0}\n"
                               "objects:\n"
                               "  - {type: plane, material: flat, point: [0, 0, -5], normal: [0, 0, 1]}\n");
    glint_image img = render(s);
    assert_int_equal(img.width, 2);
    assert_int_equal(img.height, 2);
    for (int i = 0; i < 4; i++) {
        assert_near(img.pixels[3 * i], 0.125, 1e-6);
        assert_near(img.pixels[3 * i + 1], 0.125, 1e-6);
        assert_near(img.pixels[3 * i + 2], 0.5, 1e-6);
    }
    glint_image_free(&img);
    glint_scene_free(s);
}

/* Background alone; exponential fog hides it; linear fog by distance. */
static void test_render_background_and_fog(void **state)
{
    glint_scene *s = load_good("settings: {width: 1, height: 1, background: [0.5, 0.5, 0.5]}\n");
    glint_image img = render(s);
    for (int c = 0; c < 3; c++)
        assert_near(img.pixels[c], lin(0.5), 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);

    s = load_good("settings: {width: 1, height: 1, background: [1, 0, 0]}\n"
                  "fog: {type: exponential, color: {linear: [0, 0.5, 0]}, density: 0.1}\n");
    img = render(s);
    assert_near(img.pixels[0], 0, 1e-6);
    assert_near(img.pixels[1], 0.5, 1e-6);
    assert_near(img.pixels[2], 0, 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);

    /* The single pixel's one sample sees the wall 5 units away: halfway from 0 to 10. */
    s = load_good("settings: {width: 1, height: 1, samples: 1}\n"
                  "fog: {type: linear, color: {linear: [0, 0, 0.5]}, start: 0, end: 10}\n"
                  "materials:\n"
                  "  glow: {color: {linear: [1, 1, 1]}, ambient: 1, diffuse: 0, specular: 0}\n"
                  "objects:\n"
                  "  - {type: plane, material: glow, point: [0, 0, -5], normal: [0, 0, 1]}\n");
    img = render(s);
    assert_near(img.pixels[0], 0.5, 1e-6);
    assert_near(img.pixels[1], 0.5, 1e-6);
    assert_near(img.pixels[2], 0.75, 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* ------------------------------------------- objects read while parsed */

/* What a load gave in one of the loader's modes (scenefile/scene_file.h):
 * the scene written back as a file, or what was reported. */
typedef struct outcome {
    char *written;            /* NULL when the scene was refused */
    report_log log;
    glint_error err;
} outcome;

/* Loads yaml, or the file tmp_dir/file when yaml is NULL, in mode m. */
static outcome load_in_mode(scene_file_mode m, const char *yaml, const char *file)
{
    outcome out = {0};
    glint_load_options o = {.report = log_report, .report_user = &out.log};
    char path[PATH_SIZE];
    scene_file_set_mode(m);
    glint_scene *s;
    if (yaml) {
        s = glint_scene_load_memory(yaml, strlen(yaml), "streamed.yaml", &o, &out.err);
    } else {
        tmp_path(path, file);
        s = glint_scene_load_file(path, &o, &out.err);
    }
    scene_file_set_mode(SCENE_FILE_STREAMED);
    if (s) {
        size_t size;
        FILE *f = open_memstream(&out.written, &size);
        assert_non_null(f);
        glint_error err;
        assert_int_equal(glint_scene_write_yaml(s, f, &err), GLINT_OK);
        assert_int_equal(fclose(f), 0);
        glint_scene_free(s);
    }
    return out;
}

/* Loads yaml (or tmp_dir/file) with its objects read while it is parsed,
 * the default, and from its whole tree: the same scene, written back byte
 * for byte, or the same reports, all of them. Then the streamed attempt
 * alone: it loads the same scene when `streams`, and otherwise gives up,
 * silently. Returns the whole tree's reports. */
static report_log check_streaming(const char *yaml, const char *file, bool streams)
{
    outcome whole = load_in_mode(SCENE_FILE_WHOLE, yaml, file);
    outcome dflt = load_in_mode(SCENE_FILE_STREAMED, yaml, file);
    outcome only = load_in_mode(SCENE_FILE_STREAMED_ONLY, yaml, file);
    assert_int_equal(!dflt.written, !whole.written);
    if (whole.written)
        assert_string_equal(dflt.written, whole.written);
    else
        assert_string_equal(dflt.err.message, whole.err.message);
    assert_string_equal(dflt.log.all, whole.log.all);
    if (streams && !only.written)
        fail_msg("the streamed attempt gave up: %s", only.err.message);
    if (!streams && only.written)
        fail_msg("the streamed attempt did not give up");
    if (streams)
        assert_string_equal(only.written, whole.written);
    assert_int_equal(only.log.count, 0);
    free(whole.written);
    free(dflt.written);
    free(only.written);
    return whole.log;
}

/* Every section, then the objects: read one by one as they are parsed,
 * to the very scene the whole tree gives. */
static void test_objects_streamed_after_every_section(void **state)
{
    const char *yaml = "glint: 1\n"
                       "settings: {width: 32, height: 24, background: [0.1, 0.2, 0.3]}\n"
                       "camera: {position: [0, 1, 9], look_at: [0, 0, 0]}\n"
                       "fog: {type: linear, start: 1, end: 30}\n"
                       "textures:\n  checks: {type: checker, size: 2}\n"
                       "materials:\n  m: {color: [1, 0, 0]}\n  t: {texture: checks, specular: 0.25}\n"
                       "lights:\n  - {type: point, position: [1, 5, 1]}\n"
                       "objects:\n"
                       "  - {type: sphere, material: m, center: [0, 1, 0], radius: 0.5}\n"
                       "  - type: box\n"
                       "    material: t\n"
                       "    min: [-1, -1, -1]\n"
                       "    max: [1, 0, 1]\n"
                       "    transform: [{rotate_y: 30}, {translate: [0, 0, -2]}]\n"
                       "  - {type: group, material: t, transform: [{scale: 2}], objects: [\n"
                       "      {type: sphere, radius: 0.25},\n"
                       "      {type: group, objects: [{type: cylinder, material: m, radius: 1, height: 2}]}]}\n"
                       "  - {type: plane, normal: [0, 1, 0], material: {color: \"#336699\"}}\n";
    check_streaming(yaml, NULL, true);
}

/* A section after the objects, which the whole tree reads before them:
 * the streamed attempt gives up (its objects named a material not yet
 * read, or a key followed them) and the scene loads as it always did. */
static void test_section_after_objects_loads_the_same(void **state)
{
    check_streaming("objects:\n  - {type: sphere, material: m, radius: 1}\n  - {type: sphere, material: m, radius: 2}\n"
                    "materials:\n  m: {color: [0, 1, 0]}\n",
                    NULL, false);
    check_streaming("materials: {m: {}}\nobjects:\n  - {type: sphere, material: m, radius: 1}\nlights:\n"
                    "  - {type: point, position: [0, 4, 0]}\n",
                    NULL, false);
    report_log log = check_streaming("materials: {m: {}}\nobjects: [{type: sphere, material: m, radius: 1}]\n"
                                     "objects: [{type: sphere, material: m, radius: 2}]\n",
                                     NULL, false);
    assert_string_equal(log.first, "streamed.yaml:3:1: duplicate key 'objects' in the scene");
}

/* A problem in the third object, a syntax error further on: the whole
 * tree reports only the syntax error, and so does the default; with two
 * problems in objects and no syntax error, both, in order. */
static void test_problems_in_streamed_objects(void **state)
{
    const char *head = "materials: {m: {}}\n"
                       "objects:\n"
                       "  - {type: sphere, material: m, radius: 1}\n"
                       "  - {type: sphere, material: m, radius: 1}\n"
                       "  - {type: sphere, material: nosuch, radius: 1}\n"
                       "  - {type: sphere, material: m, radius: 1}\n";
    char yaml[1024];
    snprintf(yaml, sizeof yaml, "%s  - {type: sphere, radius: [}\n  - {type: sphere, material: m, radius: 1}\n", head);
    report_log log = check_streaming(yaml, NULL, false);
    assert_int_equal(log.count, 1);
    assert_non_null(strstr(log.first, "streamed.yaml:7:"));
    assert_non_null(strstr(log.first, "syntax error"));
    snprintf(yaml, sizeof yaml, "%s  - {type: sphere, material: m, radius: -1}\n", head);
    log = check_streaming(yaml, NULL, false);
    assert_int_equal(log.count, 2);
    assert_string_equal(log.all, "streamed.yaml:5:30: unknown material 'nosuch'\n"
                                 "streamed.yaml:7:41: 'radius' must be positive, got -1\n");
}

/* Anchors in objects, aliased by later objects, among objects whose nodes
 * are given back: an object that defines an anchor is kept, whole or
 * only a part of it named; a name anchored again names the later node. */
static void test_anchors_in_streamed_objects(void **state)
{
    char *yaml = malloc(200000);
    assert_non_null(yaml);
    char *p = yaml + sprintf(yaml, "materials: {m: {}}\n"
                                   "objects:\n"
                                   "  - &ball {type: sphere, material: m, radius: 2}\n"
                                   "  - {type: sphere, material: m, radius: 1, center: &spot [1, 2, 3]}\n");
    for (int i = 0; i < 2000; i++)
        p += sprintf(p, "  - {type: box, material: m, min: [%d, 0, 0], max: [%d, 1, 1]}\n", i, i + 1);
    sprintf(p, "  - *ball\n"
               "  - {type: sphere, material: m, radius: 1, transform: [{translate: *spot}]}\n"
               "  - {type: group, objects: [*ball, {<<: *ball, radius: 3}]}\n"
               "  - &ball {type: sphere, material: m, radius: 4}\n"
               "  - *ball\n");
    check_streaming(yaml, NULL, true);
    free(yaml);
}

/* An include read while the including file is parsed defines the
 * materials of both files' objects; its own objects are streamed too. */
static void test_include_streamed(void **state)
{
    write_tmp("streamed/main.yaml", "include: parts/looks.yaml\n"
                                    "materials: {blue: {color: [0, 0, 1]}}\n"
                                    "objects:\n"
                                    "  - {type: sphere, material: red, radius: 1}\n"
                                    "  - {type: sphere, material: blue, radius: 1, center: [2, 0, 0]}\n");
    write_tmp("streamed/parts/looks.yaml", "materials:\n  red: {color: [1, 0, 0]}\n"
                                           "objects:\n  - {type: box, material: red, min: [0, 0, 0], max: [1, 1, 1]}\n");
    check_streaming(NULL, "streamed/main.yaml", true);
}

/* Writes a file whose objects are `count` aliases of one sphere of a
 * 1000-step transform: 6009 nodes each that the aliases add. */
static void write_aliased_spheres(const char *name, const char *head, int count)
{
    size_t room = 64000;
    char *text = malloc(room), *p = text;
    assert_non_null(text);
    p += sprintf(p, "%sobjects:\n  - &s {type: sphere, material: m, radius: 1, transform: [", head);
    for (int i = 0; i < 1000; i++)
        p += sprintf(p, "%s{translate: [0, 0, 0]}", i ? ", " : "");
    p += sprintf(p, "]}\n");
    for (int i = 0; i < count; i++)
        p += sprintf(p, "  - *s\n");
    assert_true((size_t)(p - text) < room);
    write_tmp(name, text);
    free(text);
}

/* The alias limit is the scene's: an include read while the including
 * file is parsed counts against it with what that file's aliases add
 * before and after. Each file alone is within the limit, both are not. */
static void test_alias_limit_while_streaming(void **state)
{
    write_aliased_spheres("alias-limit/main.yaml", "include: more.yaml\n", 90);
    write_aliased_spheres("alias-limit/more.yaml", "materials: {m: {}}\n", 90);
    report_log log = check_streaming(NULL, "alias-limit/main.yaml", false);
    assert_non_null(strstr(log.first, "more.yaml:80:5: scene too large after alias expansion"));
    write_aliased_spheres("alias-limit/main.yaml", "include: more.yaml\n", 60);
    check_streaming(NULL, "alias-limit/main.yaml", true);
}

/* Standard input is read once: a load that the streamed attempt gives up
 * reads its bytes again. */
static void test_stream_read_again(void **state)
{
    static char text[] = "objects: [{type: sphere, material: m, radius: 1}]\nmaterials: {m: {}}\n";
    FILE *in = fmemopen(text, strlen(text), "r");
    assert_non_null(in);
    glint_error err = {0};
    glint_scene *s = glint_scene_load_stream(in, "<stdin>", NULL, &err);
    if (!s)
        fail_msg("refused: %s", err.message);
    assert_int_equal(glint_scene_get_counts(s).shapes, 1);
    glint_scene_free(s);
    fclose(in);
}

/* ------------------------------------------------------------------ main */

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_settings_every_key),
        cmocka_unit_test(test_settings_other_values),
        cmocka_unit_test(test_defaults_of_an_empty_scene),
        cmocka_unit_test(test_empty_file_holds_no_scene),
        cmocka_unit_test(test_load_stream),
        cmocka_unit_test(test_disk_ring),
        cmocka_unit_test(test_torus_ring),
        cmocka_unit_test(test_camera_every_key),
        cmocka_unit_test(test_fog_none),
        cmocka_unit_test(test_fog_linear),
        cmocka_unit_test(test_fog_exponential),
        cmocka_unit_test(test_checker_texture),
        cmocka_unit_test(test_mapping_as_a_word),
        cmocka_unit_test(test_mapping_as_a_map),
        cmocka_unit_test(test_image_texture_from_a_file),
        cmocka_unit_test(test_material_every_key),
        cmocka_unit_test(test_settings_ambient_occlusion),
        cmocka_unit_test(test_settings_filter_and_adaptive),
        cmocka_unit_test(test_environment),
        cmocka_unit_test(test_camera_focus_on),
        cmocka_unit_test(test_camera_f_number),
        cmocka_unit_test(test_lights),
        cmocka_unit_test(test_area_lights),
        cmocka_unit_test(test_sphere_and_plane),
        cmocka_unit_test(test_polygons),
        cmocka_unit_test(test_box_cylinder_cone),
        cmocka_unit_test(test_transform_each_step),
        cmocka_unit_test(test_transform_order),
        cmocka_unit_test(test_groups),
        cmocka_unit_test(test_combinations),
        cmocka_unit_test(test_colours),
        cmocka_unit_test(test_includes),
        cmocka_unit_test(test_anchors_and_aliases),
        cmocka_unit_test(test_merge_keys),
        cmocka_unit_test(test_version_and_comments),
        cmocka_unit_test(test_render_ambient),
        cmocka_unit_test(test_render_background_and_fog),
        cmocka_unit_test(test_objects_streamed_after_every_section),
        cmocka_unit_test(test_section_after_objects_loads_the_same),
        cmocka_unit_test(test_problems_in_streamed_objects),
        cmocka_unit_test(test_anchors_in_streamed_objects),
        cmocka_unit_test(test_include_streamed),
        cmocka_unit_test(test_alias_limit_while_streaming),
        cmocka_unit_test(test_stream_read_again),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
