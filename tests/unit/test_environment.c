/* test_environment.c - the environment: an image wrapped around the scene
 * as equirectangular images are stored, seen by rays that miss everything,
 * read from OpenEXR with its high dynamic range; a panorama of it rendered
 * from the origin gives the image back; its rotation, intensity and checks;
 * a mirror shows it. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include "glint.h"
#include "one_sample_scene.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

enum { W = 64, H = 32 };

/* An OpenEXR file of W x H pixels whose values tell them apart, some far
 * brighter than white: pixel (x, y) is (x + 1, y + 1, 100 + x) / 8. */
static void write_sky(const char *path)
{
    float *px = malloc(sizeof(float) * 3 * W * H);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float *p = px + 3 * (y * W + x);
            p[0] = (x + 1) / 8.0f;
            p[1] = (y + 1) / 8.0f;
            p[2] = (100 + x) / 8.0f;
        }
    glint_image im = {.width = W, .height = H, .pixels = px};
    glint_image_write_options o = {.exr_pixel = GLINT_EXR_FLOAT};
    glint_error err;
    if (glint_image_write_ex(&im, path, &o, &err))
        fail_msg("%s", err.message);
    free(px);
}

static const char *sky_path(void)
{
    static char path[4096];
    const char *tmp = getenv("GLINT_TEST_TMP");
    snprintf(path, sizeof path, "%s/environment-sky.exr", tmp ? tmp : ".");
    return path;
}

/* A scene of nothing but the environment `env` (its texture the sky),
 * seen by camera cam over W x H pixels, one sample each. */
static glint_image render_sky(glint_camera cam, glint_environment env, int threads)
{
    glint_scene *s = one_sample_scene(W, H, (glint_color){1, 1, 1}, cam);
    glint_texture t = glint_texture_default(GLINT_TEXTURE_IMAGE);
    t.file = sky_path();
    glint_error err;
    env.texture = glint_scene_add_texture(s, "sky", &t, &err);
    if (env.texture < 0 || glint_scene_set_environment(s, &env, &err))
        fail_msg("%s", err.message);
    glint_image im;
    glint_render_options o = {.threads = threads};
    assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
    glint_scene_free(s);
    return im;
}

static const glint_camera panorama = {.kind = GLINT_CAMERA_EQUIRECTANGULAR, .position = {0, 0, 0},
                                      .look_at = {0, 0, -1}, .up = {0, 1, 0}, .vfov_degrees = 45};

/* The panorama from the origin looking along -z is the image itself, its
 * values above 1 kept; turned by 90 degrees, a quarter of the width along;
 * at intensity 2, twice as bright. */
static void test_panorama_gives_the_image_back(void **state)
{
    (void)state;
    write_sky(sky_path());
    glint_image im = render_sky(panorama, (glint_environment){.intensity = 1}, 2);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const float *p = im.pixels + 3 * (y * W + x);
            assert_near(p[0], (x + 1) / 8.0, 1e-4);
            assert_near(p[1], (y + 1) / 8.0, 1e-4);
            assert_near(p[2], (100 + x) / 8.0, 1e-3);
        }
    glint_image_free(&im);
    im = render_sky(panorama, (glint_environment){.intensity = 2, .rotation = 90}, 1);
    for (int x = 0; x < W; x++) {
        int from = (x - W / 4 + W) % W;
        assert_near(im.pixels[3 * (5 * W + x)], 2 * (from + 1) / 8.0, 1e-4);
    }
    glint_image_free(&im);
}

/* A perfect mirror facing the camera shows what lies behind the camera:
 * the image's +z edge, its first and last columns. */
static void test_mirror_shows_the_environment(void **state)
{
    (void)state;
    write_sky(sky_path());
    glint_camera cam = {.position = {0, 0, 5}, .look_at = {0, 0, 0}, .up = {0, 1, 0}, .vfov_degrees = 10};
    glint_scene *s = one_sample_scene(1, 1, (glint_color){1, 1, 1}, cam);
    glint_material m = glint_material_default();
    m.ambient = m.diffuse = m.specular = 0;
    m.reflectivity = 1;
    glint_shape wall = {.kind = GLINT_SHAPE_PLANE, .normal = {0, 0, 1}};
    assert_true(glint_scene_add_shape(s, &wall, glint_scene_add_material(s, NULL, &m, NULL), NULL, NULL) >= 0);
    glint_texture t = glint_texture_default(GLINT_TEXTURE_IMAGE);
    t.file = sky_path();
    glint_environment env = {.texture = glint_scene_add_texture(s, "sky", &t, NULL), .intensity = 1};
    assert_int_equal(glint_scene_set_environment(s, &env, NULL), GLINT_OK);
    glint_image im;
    assert_int_equal(glint_render(s, NULL, &im, NULL, NULL), GLINT_OK);
    /* +z is u = 0 or 1: the mean of the first and last columns, rows 15 and 16. */
    assert_near(im.pixels[0], (1 + W) / 2.0 / 8, 1e-3);
    assert_near(im.pixels[1], 16.5 / 8, 1e-3);
    glint_image_free(&im);
    glint_scene_free(s);
}

static void test_environment_values_checked(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_error err;
    glint_environment env = {.texture = 0, .intensity = 1};
    assert_int_equal(glint_scene_set_environment(s, &env, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "environment texture 0 does not exist");
    env = (glint_environment){.texture = -1, .intensity = -1};
    assert_int_equal(glint_scene_set_environment(s, &env, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "environment intensity must be from 0 to 1e300, got -1");
    assert_int_equal(glint_scene_get_environment(s).texture, -1);
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_panorama_gives_the_image_back),
        cmocka_unit_test(test_mirror_shows_the_environment),
        cmocka_unit_test(test_environment_values_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
