/* test_motion_blur.c - a shutter open while things move: a small ball
 * moving sideways at a known speed leaves a streak whose ends (where it is
 * half as bright as along its middle) lie where the pinhole projects the
 * ball's path's ends, within a pixel; a ball that stands still in the same
 * image is bit for bit what it is without a shutter; a camera panning
 * streaks a still ball by as much as the ball moving past a still camera;
 * a light changing colour or moving lights by its mean over the shutter;
 * so do a moving area light and a moving emissive ball (their light the
 * mean of stills along the path), and a visible lamp moving streaks as
 * the ball does; a mesh moved as Embree moves instances streaks as the
 * ball does;
 * the same bytes for any thread count; and a shutter with nothing keyed
 * changes nothing. */
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

enum { WIDTH = 400, HEIGHT = 120 };

/* tan(15 degrees): half the 30-degree view's height at distance 1. */
#define TAN15 0.2679491924311227

/* The camera: at z = 10 looking down -z, 30 degrees high: a point (x, y, 0)
 * is at pixel column WIDTH / 2 + x / (10 tan 15) * HEIGHT / 2. */
static double column_of(double x)
{
    return WIDTH / 2.0 + x / (10 * TAN15) * HEIGHT / 2.0;
}

static glint_image render(const char *yaml, int threads)
{
    glint_error err = {0};
    glint_scene *scene = glint_scene_load_memory(yaml, strlen(yaml), "motion.yaml", NULL, &err);
    if (!scene)
        fail_msg("the scene did not load: %s", err.message);
    glint_render_options o = {.threads = threads};
    glint_image image;
    assert_int_equal(glint_render(scene, &o, &image, NULL, &err), GLINT_OK);
    glint_scene_free(scene);
    return image;
}

/* The shutter open a whole second (fps 1) or, with `shutter` false, not at
 * all; the moving ball's translate and the camera's position and look_at
 * as given. */
static char *scene_text(bool shutter, const char *moving_ball, const char *camera)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "settings: {width: %d, height: %d, samples: 256, sampler: sobol, frames: {fps: 1}%s}\n"
             "camera: {position: %s, fov: 30}\n"
             "materials: {white: {color: {linear: [1, 1, 1]}, ambient: 1, diffuse: 0, specular: 0}}\n"
             "objects:\n"
             "  - {type: sphere, radius: 0.25, material: white, transform: [{translate: %s}]}\n"
             "  - {type: sphere, radius: 0.25, center: [0, -0.8, 0], material: white}\n",
             WIDTH, HEIGHT, shutter ? ", shutter: {open: 0, close: 1}" : "", camera, moving_ball);
    return text;
}

static const char STILL_CAMERA[] = "[0, 0, 10], look_at: [0, 0, 0]";
static const char MOVING[] = "{keys: [[0, [-2, 0.8, 0]], [1, [2, 0.8, 0]]]}";

/* Where along row y the brightness first rises through, and last falls
 * through, half of its value at the row's middle: linearly between pixels. */
static void half_max_ends(const glint_image *im, int y, double *left, double *right)
{
    const float *row = im->pixels + (size_t)y * WIDTH * 3;
    double half = row[(WIDTH / 2) * 3] / 2;
    assert_true(half > 0.01);
    int a = 0, b = WIDTH - 1;
    while (row[a * 3] < half)
        a++;
    while (row[b * 3] < half)
        b--;
    *left = a - (row[a * 3] - half) / (row[a * 3] - row[(a - 1) * 3]) + 0.5;
    *right = b + (row[b * 3] - half) / (row[b * 3] - row[(b + 1) * 3]) + 0.5;
}

/* The row through the moving ball's centre (y = 0.8). */
static int streak_row(void)
{
    return (int)(HEIGHT / 2.0 - 0.8 / (10 * TAN15) * HEIGHT / 2.0);
}

static void test_streak_length(void **state)
{
    glint_image im = render(scene_text(true, MOVING, STILL_CAMERA), 2);
    double left, right;
    half_max_ends(&im, streak_row(), &left, &right);
    assert_true(fabs(left - column_of(-2)) < 1);
    assert_true(fabs(right - column_of(2)) < 1);
    /* Along the middle the ball covers a point for 0.5 of the 4 units it
     * moves: an eighth of the time, so an eighth of its light. */
    double middle = im.pixels[((size_t)streak_row() * WIDTH + WIDTH / 2) * 3];
    assert_true(fabs(middle - 0.125) < 0.02);
    glint_image_free(&im);
}

/* The still ball's pixels are those of the same scene without a shutter,
 * bit for bit; the moving ball's path is lit only with the shutter. */
static void test_still_ball_unchanged(void **state)
{
    glint_image blurred = render(scene_text(true, MOVING, STILL_CAMERA), 2);
    glint_image sharp = render(scene_text(false, MOVING, STILL_CAMERA), 2);
    size_t half = (size_t)WIDTH * HEIGHT / 2 * 3; /* the lower half: the still ball */
    assert_memory_equal(blurred.pixels + half, sharp.pixels + half, half * sizeof(float));
    size_t at = ((size_t)streak_row() * WIDTH + WIDTH / 2) * 3;
    assert_true(blurred.pixels[at] > 0.1 && sharp.pixels[at] == 0);
    glint_image_free(&blurred);
    glint_image_free(&sharp);
}

/* The camera moving 4 units to the left over the shutter streaks the
 * still ball at (0, 0.8) as the ball moving 4 to the right did. */
static void test_camera_pan(void **state)
{
    glint_image im = render(scene_text(true, "[0, 0.8, 0]", "{keys: [[0, [2, 0, 10]], [1, [-2, 0, 10]]]}, "
                                                            "look_at: {keys: [[0, [2, 0, 0]], [1, [-2, 0, 0]]]}"),
                            2);
    double left, right;
    half_max_ends(&im, streak_row(), &left, &right);
    assert_true(fabs(left - column_of(-2)) < 1);
    assert_true(fabs(right - column_of(2)) < 1);
    glint_image_free(&im);
}

/* The same bytes with 1 and 3 threads. */
static void test_threads(void **state)
{
    const char *yaml = scene_text(true, MOVING, STILL_CAMERA);
    glint_image a = render(yaml, 1), b = render(yaml, 3);
    assert_memory_equal(a.pixels, b.pixels, sizeof(float) * WIDTH * HEIGHT * 3);
    glint_image_free(&a);
    glint_image_free(&b);
}

/* A point light over a white floor, seen from above. */
static const char *lit_floor(bool shutter, const char *light)
{
    static char text[1024];
    snprintf(text, sizeof text,
             "settings: {width: 16, height: 16, samples: 256, sampler: sobol, frames: {fps: 1}%s}\n"
             "camera: {position: [0, 10, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 2}\n"
             "materials: {floor: {color: {linear: [1, 1, 1]}, ambient: 0, diffuse: 1, specular: 0}}\n"
             "lights: [%s]\n"
             "objects: [{type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: floor}]\n",
             shutter ? ", shutter: {open: 0, close: 1}" : "", light);
    return text;
}

/* A light whose colour rises from black to white over the shutter lights
 * as much as half the white light; one moving from 4 units straight above
 * the floor's middle to 4 units aside lights it by the cosine's mean over
 * its path, worked out below by the midpoint rule (no falloff: only the
 * cosine changes). */
static void test_moving_light(void **state)
{
    glint_image full = render(lit_floor(false, "{type: point, position: [0, 4, 0], color: {linear: [1, 1, 1]}}"), 2);
    glint_image rising = render(lit_floor(true, "{type: point, position: [0, 4, 0], "
                                                "color: {keys: [[0, {linear: [0, 0, 0]}], [1, {linear: [1, 1, 1]}]]}}"),
                                2);
    glint_image moving = render(lit_floor(true, "{type: point, position: {keys: [[0, [0, 4, 0]], [1, [4, 4, 0]]]}, "
                                                "color: {linear: [1, 1, 1]}}"),
                                2);
    size_t middle = (8 * 16 + 8) * 3;
    assert_true(fabs(rising.pixels[middle] / full.pixels[middle] - 0.5) < 0.01);
    /* The floor's point seen at the middle pixel, a hair off the centre. */
    double mean = 0;
    for (int i = 0; i < 10000; i++) {
        double x = 4 * (i + 0.5) / 10000;
        mean += 4 / sqrt(x * x + 16) / 10000;
    }
    assert_true(fabs(moving.pixels[middle] / full.pixels[middle] - mean) < 0.01);
    glint_image_free(&full);
    glint_image_free(&rising);
    glint_image_free(&moving);
}

/* The floor under a small sphere light at `where`. */
static const char *sphere_light_over(bool shutter, const char *where)
{
    char light[256];
    snprintf(light, sizeof light, "{type: sphere, position: %s, radius: 0.05, samples: 4}", where);
    return lit_floor(shutter, light);
}

/* The floor under a small ball at `where` glowing by its material. */
static const char *glowing_ball_over(bool shutter, const char *where)
{
    static char text[1024];
    snprintf(text, sizeof text,
             "settings: {width: 16, height: 16, samples: 256, sampler: sobol, frames: {fps: 1}%s}\n"
             "camera: {position: [0, 10, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 2}\n"
             "materials: {floor: {color: {linear: [1, 1, 1]}, ambient: 0, diffuse: 1, specular: 0},\n"
             "            glow: {color: [0, 0, 0], emission: {linear: [20, 20, 20]}}}\n"
             "objects: [{type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: floor},\n"
             "          {type: sphere, radius: 0.05, material: glow, transform: [{translate: %s}]}]\n",
             shutter ? ", shutter: {open: 0, close: 1}" : "", where);
    return text;
}

/* The floor's middle pixel with scene(shutter, where) moving from (0.5, 4,
 * 0) to (4.5, 4, 0) over the shutter (aside from the camera's view of the
 * floor, so that it is not seen), and the mean of `stills` stills at the
 * midpoints of the path. */
static void moving_and_stills(const char *(*scene)(bool, const char *), int stills, double *moving, double *mean)
{
    size_t middle = (8 * 16 + 8) * 3;
    glint_image im = render(scene(true, "{keys: [[0, [0.5, 4, 0]], [1, [4.5, 4, 0]]]}"), 2);
    *moving = im.pixels[middle];
    glint_image_free(&im);
    *mean = 0;
    for (int k = 0; k < stills; k++) {
        char where[64];
        snprintf(where, sizeof where, "[%.17g, 4, 0]", 0.5 + 4 * (k + 0.5) / stills);
        im = render(scene(false, where), 2);
        *mean += im.pixels[middle] / stills;
        glint_image_free(&im);
    }
}

/* A small sphere light moving 4 units over the floor lights it by the
 * mean of its light over the path (stills at 32 points of it), within 1%;
 * so does a small ball glowing by its material's emission, its light
 * moving with it. */
static void test_moving_area_light(void **state)
{
    double moving, mean;
    moving_and_stills(sphere_light_over, 32, &moving, &mean);
    assert_true(mean > 0);
    assert_true(fabs(moving / mean - 1) < 0.01);
    moving_and_stills(glowing_ball_over, 32, &moving, &mean);
    assert_true(mean > 0);
    assert_true(fabs(moving / mean - 1) < 0.01);
}

/* A lamp seen by the camera, a disk light facing it, moving as the ball
 * did, leaves the same streak. */
static void test_moving_lamp_seen(void **state)
{
    char text[1024];
    snprintf(text, sizeof text,
             "settings: {width: %d, height: %d, samples: 256, sampler: sobol, frames: {fps: 1}, shutter: {open: 0, close: 1}}\n"
             "camera: {position: %s, fov: 30}\n"
             "lights: [{type: disk, position: %s, direction: [0, 0, 1], radius: 0.25, color: {linear: [1, 1, 1]}}]\n",
             WIDTH, HEIGHT, STILL_CAMERA, MOVING);
    glint_image im = render(text, 2);
    double left, right;
    half_max_ends(&im, streak_row(), &left, &right);
    assert_true(fabs(left - column_of(-2)) < 1);
    assert_true(fabs(right - column_of(2)) < 1);
    glint_image_free(&im);
}

/* A ball moving inside combinations (a difference of an intersection of
 * it and a box, and a far ball; the transform keyed on the outer one, so
 * that every part moves) leaves the streak the moving ball leaves, bit for
 * bit: its parts are taken where they are at each sample's time. */
static void test_moving_combination(void **state)
{
    glint_image ball = render(scene_text(true, MOVING, STILL_CAMERA), 2);
    char text[2048];
    snprintf(text, sizeof text,
             "settings: {width: %d, height: %d, samples: 256, sampler: sobol, frames: {fps: 1}, "
             "shutter: {open: 0, close: 1}}\n"
             "camera: {position: %s, fov: 30}\n"
             "materials: {white: {color: {linear: [1, 1, 1]}, ambient: 1, diffuse: 0, specular: 0}}\n"
             "objects:\n"
             "  - type: difference\n"
             "    material: white\n"
             "    transform: [{translate: %s}]\n"
             "    objects:\n"
             "      - {type: intersection, objects: [{type: sphere, radius: 0.25}, {type: box, min: [-1, -1, -1], "
             "max: [1, 1, 1]}]}\n"
             "      - {type: sphere, radius: 0.1, center: [0, 0, 5]}\n"
             "  - {type: sphere, radius: 0.25, center: [0, -0.8, 0], material: white}\n",
             WIDTH, HEIGHT, STILL_CAMERA, MOVING);
    glint_image combined = render(text, 2);
    assert_memory_equal(combined.pixels, ball.pixels, sizeof(float) * 3 * WIDTH * HEIGHT);
    glint_image_free(&combined);
    glint_image_free(&ball);
}

/* A mesh moved through the C API (Embree's instance motion blur): a small
 * square of two triangles crossing the view as the ball did leaves a
 * streak whose ends are the projected ends of its path. */
static void test_moving_mesh(void **state)
{
    glint_error err = {0};
    glint_scene *scene = glint_scene_load_memory(scene_text(true, "[0, -5, 0]", STILL_CAMERA),
                                                 strlen(scene_text(true, "[0, -5, 0]", STILL_CAMERA)), "mesh.yaml",
                                                 NULL, &err);
    assert_non_null(scene);
    static const float square[] = {-0.25f, -0.25f, 0, 0.25f, -0.25f, 0, 0.25f, 0.25f, 0, -0.25f, 0.25f, 0};
    static const uint32_t corners[] = {0, 1, 2, 0, 2, 3};
    glint_mesh_data data = {.positions = square, .vertex_count = 4, .indices = corners, .triangle_count = 2};
    int mesh = glint_scene_add_mesh(scene, "square", &data, &err);
    assert_true(mesh >= 0);
    int placed = glint_scene_add_instance(scene, mesh, 0, NULL, &err);
    assert_true(placed >= 0);
    glint_transform poses[2] = {glint_transform_translate(glint_transform_identity(), -2, 0.8, 0),
                                glint_transform_translate(glint_transform_identity(), 2, 0.8, 0)};
    assert_int_equal(glint_scene_move_instance(scene, placed, 2, poses, &err), GLINT_OK);
    glint_render_options o = {.threads = 2};
    glint_image im;
    assert_int_equal(glint_render(scene, &o, &im, NULL, &err), GLINT_OK);
    double left, right;
    half_max_ends(&im, streak_row(), &left, &right);
    assert_true(fabs(left - column_of(-2)) < 1);
    assert_true(fabs(right - column_of(2)) < 1);
    glint_image_free(&im);
    glint_transform singular = {{{0}}};
    poses[1] = singular;
    assert_int_equal(glint_scene_move_instance(scene, placed, 2, poses, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "pose 2's transform is singular or not finite");
    glint_scene_free(scene);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_streak_length),
        cmocka_unit_test(test_still_ball_unchanged),
        cmocka_unit_test(test_camera_pan),
        cmocka_unit_test(test_threads),
        cmocka_unit_test(test_moving_light),
        cmocka_unit_test(test_moving_area_light),
        cmocka_unit_test(test_moving_lamp_seen),
        cmocka_unit_test(test_moving_mesh),
        cmocka_unit_test(test_moving_combination),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
