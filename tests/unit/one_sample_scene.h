/* one_sample_scene.h - the empty scene the rendering tests build their
 * cases in: a small image of one sample a pixel, where a test can check
 * each pixel against an analytic value (test_area_lights.c,
 * test_environment.c, test_glossy.c, test_ray_limits.c, test_render.c). */
#ifndef GLINT_TESTS_ONE_SAMPLE_SCENE_H
#define GLINT_TESTS_ONE_SAMPLE_SCENE_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include "glint.h"

/* A new scene of width x height pixels, each sampled once at its centre
 * (where the analytic values hold), under ambient light `ambient` (black:
 * none, so that only the lights show; white is the settings' default), seen
 * by cam, with nothing in it yet. Fails the test when the scene cannot be
 * made or refuses the values. */
static inline glint_scene *one_sample_scene(int width, int height, glint_color ambient, glint_camera cam)
{
    glint_scene *s = glint_scene_new();
    assert_non_null(s);
    glint_settings st = glint_settings_default();
    st.width = width;
    st.height = height;
    st.samples_per_pixel = 1;
    st.ambient_light = ambient;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    return s;
}

/* A one-sample scene of side x side pixels seen by an orthographic camera
 * looking down -z from z = 5 at a square `view` units across, under white
 * ambient light against a black background: a thing of a material that
 * shows exactly its colour is its silhouette. */
static inline glint_scene *silhouette_scene(int side, double view)
{
    glint_camera cam = {.kind = GLINT_CAMERA_ORTHOGRAPHIC, .position = {0, 0, 5}, .look_at = {0, 0, 0},
                        .up = {0, 1, 0}, .vfov_degrees = 40, .view_width = view};
    glint_scene *s = one_sample_scene(side, side, (glint_color){1, 1, 1}, cam);
    glint_settings st = glint_scene_get_settings(s);
    st.background = (glint_color){0, 0, 0};
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    return s;
}

/* Renders s on two threads and frees it: the picture, which the caller
 * frees. Fails the test when the render does. */
static inline glint_image render_and_free(glint_scene *s)
{
    glint_image im;
    glint_render_options o = {.threads = 2};
    assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
    glint_scene_free(s);
    return im;
}

#endif
