/* test_message_fit.c - messages too long for a glint_error keep their
 * subject and reason: the longest path loses its middle
 * (core/message_fit.h), in error_set, in the scene loader's reports and in
 * warnings, never the end. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdio.h>
#include <string.h>
#include "core/error.h"
#include "core/message_fit.h"
#include "scene/scene.h"

/* A path of `parts` folders of 60 letters each, then name. */
static void long_path(char *out, size_t size, int parts, const char *name)
{
    size_t n = 0;
    for (int i = 0; i < parts; i++)
        n += (size_t)snprintf(out + n, size - n, "/%060d", i);
    snprintf(out + n, size - n, "/%s", name);
}

static void test_short_message_is_kept(void **state)
{
    (void)state;
    char text[64] = "scene.yaml:3:4: unknown key 'widht'";
    message_fit(text, 64);
    assert_string_equal(text, "scene.yaml:3:4: unknown key 'widht'");
}

/* 10 folders make a path of 621 bytes, a word of 626 with ":3:4:", in a
 * message of 685: 177 bytes go (174 and the "..."), so of the 449 kept
 * the first 149 and the last 300 stay, and the reason stays whole. */
static void test_long_path_loses_its_middle(void **state)
{
    (void)state;
    char path[1024], text[2048], word[1100], expected[1024];
    long_path(path, sizeof path, 10, "scene.yaml");
    const char *reason = " 'fov' must be more than 0 and less than 180 degrees, got 0";
    snprintf(word, sizeof word, "%s:3:4:", path);
    snprintf(text, sizeof text, "%s%s", word, reason);
    assert_int_equal(strlen(text), 685);
    message_fit(text, 512);
    snprintf(expected, sizeof expected, "%.149s...%s%s", word, word + 626 - 300, reason);
    assert_string_equal(text, expected);
    assert_int_equal(strlen(text), 511);
}

/* Two long paths, each the longest in turn, both lose their middles. */
static void test_two_paths_both_shortened(void **state)
{
    (void)state;
    char a[1024], b[1024], text[4096];
    long_path(a, sizeof a, 12, "model.obj");
    long_path(b, sizeof b, 12, "wood.png");
    snprintf(text, sizeof text, "%s: texture '%s' lies outside the model's folder", a, b);
    message_fit(text, 512);
    assert_true(strlen(text) < 512);
    assert_non_null(strstr(text, "/model.obj: texture '"));
    assert_non_null(strstr(text, "/wood.png' lies outside the model's folder"));
    assert_non_null(strstr(strstr(text, "texture"), "..."));
    assert_true(strstr(text, "...") < strstr(text, "texture"));
}

/* No word long enough to shorten: the text after the first word loses its
 * middle, at characters' starts, and the first word and the end stay. 19
 * bytes of room: "été" (5), the "..." and 11 more, a third before it
 * (" é", 3 bytes) and two thirds after it (8 bytes, less the stray
 * continuation byte they start with: "té end"). */
static void test_no_long_word_keeps_first_word_and_end(void **state)
{
    (void)state;
    char text[700] = ""; /* 100 words of 6 bytes, and the NUL */
    for (int i = 0; i < 100; i++)
        strcat(text, "\xc3\xa9t\xc3\xa9 "); /* "été ", 6 bytes */
    strcat(text, "end");
    message_fit(text, 20);
    assert_string_equal(text, "\xc3\xa9t\xc3\xa9 \xc3\xa9...t\xc3\xa9 end");
}

/* A model of a short path naming a texture whose name has spaces in it
 * and is far too long: the model's path stays whole, the texture's name
 * loses its middle, and the reason stays (fuzzing found the model's path
 * shortened and the reason cut off). */
static void test_short_subject_spared_for_a_spaced_name(void **state)
{
    (void)state;
    char text[4096] = "/tmp/glint-fuzz-mesh-AbCdEf/model.gltf: texture '";
    for (int i = 0; i < 400; i++)
        strcat(text, "ab ");
    strcat(text, "ab' lies outside the model's folder");
    message_fit(text, 512);
    assert_int_equal(strlen(text), 511);
    assert_memory_equal(text, "/tmp/glint-fuzz-mesh-AbCdEf/model.gltf: texture 'ab ab", 54);
    const char *end = "ab ab' lies outside the model's folder";
    assert_string_equal(text + strlen(text) - strlen(end), end);
    assert_non_null(strstr(text, "..."));
}

/* A path of two-byte characters is cut between characters. */
static void test_cut_keeps_utf8_whole(void **state)
{
    (void)state;
    char text[2048] = "/";
    for (int i = 0; i < 400; i++)
        strcat(text, "\xc3\xa9");
    strcat(text, ": not a regular file");
    message_fit(text, 101);
    assert_true(strlen(text) <= 100);
    const char *dots = strstr(text, "...");
    assert_non_null(dots);
    assert_int_equal((unsigned char)dots[3], 0xc3);
    assert_int_equal(((unsigned char)dots[-1]), 0xa9);
    assert_string_equal(text + strlen(text) - 20, ": not a regular file");
}

/* error_set formats the whole message before fitting it. */
static void test_error_set_keeps_the_reason(void **state)
{
    (void)state;
    char path[4200];
    long_path(path, sizeof path, 60, "scene.yaml");
    glint_error err;
    assert_int_equal(error_set(&err, GLINT_ERR_IO, "cannot read scene '%s': %s", path, "not a regular file"),
                     GLINT_ERR_IO);
    assert_int_equal(err.status, GLINT_ERR_IO);
    assert_int_equal(strlen(err.message), sizeof err.message - 1);
    assert_memory_equal(err.message, "cannot read scene '/000", 23);
    const char *end = "/scene.yaml': not a regular file";
    assert_string_equal(err.message + strlen(err.message) - strlen(end), end);
}

/* The loader's first problem, at a file of a long name, keeps its reason. */
static void test_scene_problem_keeps_the_reason(void **state)
{
    (void)state;
    char name[1024];
    long_path(name, sizeof name, 12, "scene.yaml");
    const char *yaml = "camera:\n  fov: 0\n";
    glint_error err;
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), name, NULL, &err));
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    const char *end = "/scene.yaml:2:8: 'fov' must be more than 0 and at most 360 degrees, got 0";
    assert_true(strlen(err.message) > strlen(end));
    assert_string_equal(err.message + strlen(err.message) - strlen(end), end);
    assert_non_null(strstr(err.message, "..."));
}

/* A warning (a missing MTL file) is fitted the same way. */
static void test_warning_keeps_the_reason(void **state)
{
    (void)state;
    char path[1024];
    long_path(path, sizeof path, 12, "model.mtl");
    glint_scene *scene = glint_scene_new();
    assert_non_null(scene);
    glint_error err;
    assert_int_equal(scene_warn(scene, &err, "m.obj: MTL file '%s' does not exist: its materials are grey", path),
                     GLINT_OK);
    const char *warning = glint_scene_warning(scene, 0), *end = "/model.mtl' does not exist: its materials are grey";
    assert_int_equal(strlen(warning), sizeof err.message - 1);
    assert_memory_equal(warning, "m.obj: MTL file '/000", 21);
    assert_string_equal(warning + strlen(warning) - strlen(end), end);
    glint_scene_free(scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_short_message_is_kept),
        cmocka_unit_test(test_long_path_loses_its_middle),
        cmocka_unit_test(test_two_paths_both_shortened),
        cmocka_unit_test(test_no_long_word_keeps_first_word_and_end),
        cmocka_unit_test(test_short_subject_spared_for_a_spaced_name),
        cmocka_unit_test(test_cut_keeps_utf8_whole),
        cmocka_unit_test(test_error_set_keeps_the_reason),
        cmocka_unit_test(test_scene_problem_keeps_the_reason),
        cmocka_unit_test(test_warning_keeps_the_reason),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
