/* test_animation.c - scene files with keyed values (docs/animation.md):
 * the scene loaded at a time has each keyed value as its keys give it
 * then (the camera, a light, a material, transform steps of an object and
 * of its group), a scene without keys is the same at every time, and
 * settings.frames reads and writes back. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#define SCENE_TEST_NAME "glint-animation"
#include "scene_file_test_util.h"

static glint_scene *load_at(const char *yaml, double time)
{
    report_log log = {0};
    glint_load_options o = {.report = log_report, .report_user = &log, .time = time};
    glint_error err = {0};
    glint_scene *s = glint_scene_load_memory(yaml, strlen(yaml), "anim.yaml", &o, &err);
    if (!s)
        fail_msg("the scene did not load at %g s (%d problems):\n%s", time, log.count, log.all);
    return s;
}

static const char BOUNCE[] =
    "settings: {frames: {start: 0, end: 47, fps: 24}}\n"
    "camera:\n"
    "  position: {keys: [[0, [0, 1, 6]], [2, [4, 1, 6]]]}\n"
    "  fov: {keys: [[0, 40], [1, 60], [2, 40]], interpolate: step}\n"
    "materials:\n"
    "  m: {color: {keys: [[0, {linear: [1, 0, 0]}], [1, {linear: [0, 0, 1]}]]}, transparency: {keys: [[0, 0], [2, 0.5]]}}\n"
    "lights:\n"
    "  - {type: point, position: [0, 5, 0], intensity: {keys: [[0, 2], [1, 1]], interpolate: smooth}}\n"
    "objects:\n"
    "  - type: group\n"
    "    transform: [{rotate_y: {keys: [[0, 0], [2, 90]]}}]\n"
    "    objects:\n"
    "      - type: sphere\n"
    "        radius: 1\n"
    "        material: m\n"
    "        transform: [{translate: {keys: [[0, [1, 0, 0]], [1, [1, 2, 0]]]}}, {scale: {keys: [[0, 1], [1, 3]]}}]\n";

/* Each keyed value at and between its keys, and clamped past the last. */
static void test_values_at_a_time(void **state)
{
    glint_scene *s = load_at(BOUNCE, 0.5);
    assert_exact(s->camera.position.x, 1);
    assert_exact(s->camera.vfov_degrees, 40);
    assert_exact(s->materials[0].m.color.r, 0.5);
    assert_exact(s->materials[0].m.color.b, 0.5);
    assert_exact(s->materials[0].m.transparency, 0.125);
    /* smooth between two keys: the smoothstep, 1/2 of the way at 1/2 */
    assert_near(s->lights[0].desc.color.r, 1.5, 1e-12);
    /* translate (1, 1, 0) then scale 2, then rotated 22.5 degrees about y */
    double c = cos(22.5 * M_PI / 180), n = sin(22.5 * M_PI / 180);
    const double want[3][4] = {{2 * c, 0, 2 * n, 2 * c}, {0, 2, 0, 2}, {-2 * n, 0, 2 * c, -2 * n}};
    assert_matrix(&s->shapes[0].to_world, want, 1e-14);
    glint_scene_free(s);

    s = load_at(BOUNCE, 1);
    assert_exact(s->camera.vfov_degrees, 60);
    assert_exact(s->materials[0].m.color.b, 1);
    assert_exact(s->lights[0].desc.color.r, 1);
    glint_scene_free(s);

    s = load_at(BOUNCE, 100);
    assert_exact(s->camera.position.x, 4);
    assert_exact(s->camera.vfov_degrees, 40);
    assert_exact(s->materials[0].m.transparency, 0.5);
    glint_scene_free(s);
}

/* settings.frames is read, and written back by --print-scene's writer. */
static void test_frames_setting(void **state)
{
    glint_scene *s = load_at(BOUNCE, 0);
    assert_int_equal(s->settings.frame_start, 0);
    assert_int_equal(s->settings.frame_end, 47);
    assert_exact(s->settings.fps, 24);
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    glint_error err = {0};
    assert_int_equal(glint_scene_write_yaml(s, f, &err), GLINT_OK);
    fclose(f);
    assert_non_null(strstr(text, "frames: {start: 0, end: 47, fps: 24}"));
    free(text);
    glint_scene_free(s);
    glint_settings d = glint_settings_default();
    assert_int_equal(d.frame_start, 0);
    assert_int_equal(d.frame_end, 0);
    assert_exact(d.fps, 24);
}

/* A scene without keys is the same scene whatever the time. */
static void test_still_scene_ignores_time(void **state)
{
    static const char still[] = "camera: {position: [1, 2, 3]}\n"
                                "materials: {m: {color: [0.5, 0.5, 0.5]}}\n"
                                "objects: [{type: sphere, radius: 1, material: m, transform: [{translate: [1, 0, 0]}]}]\n";
    glint_scene *a = load_at(still, 0), *b = load_at(still, 1234.5);
    assert_memory_equal(&a->camera, &b->camera, sizeof a->camera);
    assert_same_material(&a->materials[0].m, &b->materials[0].m);
    assert_memory_equal(&a->shapes[0].to_world, &b->shapes[0].to_world, sizeof a->shapes[0].to_world);
    glint_scene_free(a);
    glint_scene_free(b);
}

/* A time that is no number of seconds is refused. */
static void test_bad_time(void **state)
{
    glint_load_options o = {.time = NAN};
    glint_error err = {0};
    assert_null(glint_scene_load_memory("glint: 1\n", 9, "t.yaml", &o, &err));
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    assert_string_equal(err.message, "the time to load 't.yaml' at must be a finite number of seconds");
}

/* A direction keyed through zero is told at the time it is zero. */
static void test_direction_through_zero(void **state)
{
    static const char flip[] = "lights: [{type: directional, direction: {keys: [[0, [0, -1, 0]], [2, [0, 1, 0]]]}}]\n";
    report_log log = {0};
    glint_load_options o = {.report = log_report, .report_user = &log, .time = 1};
    glint_error err = {0};
    assert_null(glint_scene_load_memory(flip, strlen(flip), "flip.yaml", &o, &err));
    assert_string_equal(log.first, "flip.yaml:1:41: 'direction' is zero at 1 s, where its keys pass through zero");
    glint_scene_free(load_at(flip, 0.5));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values_at_a_time),
        cmocka_unit_test(test_frames_setting),
        cmocka_unit_test(test_still_scene_ignores_time),
        cmocka_unit_test(test_bad_time),
        cmocka_unit_test(test_direction_through_zero),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
