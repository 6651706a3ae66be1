/* test_area_lights.c - sphere, rectangle and disk lights, and emissive
 * shapes and meshes, against their analytic answers: the light arriving
 * under them (irradiance by the form factor), the umbra and penumbra a
 * ball casts, what camera and mirror rays see of them, their checks, the
 * Cornell box's own lamp, and the same bytes for any thread count. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "one_sample_scene.h"
#include "scene/scene.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))
#define assert_within(a, b, rel) assert_true(fabs((double)(a) - (double)(b)) <= (rel) * fabs((double)(b)))

/* A w x h scene of one sample a pixel, no ambient light, seen by an
 * orthographic camera `view` units wide looking from `eye` at the origin
 * (from straight above, (0, 20, 0), image x is world x), with a matte
 * white floor (diffuse 1, no highlight) at y = 0. */
static glint_scene *floor_seen(int w, int h, double view, glint_vec3 eye)
{
    glint_camera cam = {.kind = GLINT_CAMERA_ORTHOGRAPHIC, .position = eye, .look_at = {0, 0, 0},
                        .up = {0, 0, -1}, .vfov_degrees = 40, .view_width = view};
    glint_scene *s = one_sample_scene(w, h, (glint_color){0, 0, 0}, cam);
    glint_material m = glint_material_default();
    m.specular = 0;
    int white = glint_scene_add_material(s, NULL, &m, NULL);
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &floor, white, NULL, NULL) >= 0);
    return s;
}

static glint_image render(const glint_scene *s, int threads)
{
    glint_image img;
    glint_render_options o = {.threads = threads};
    glint_error err;
    if (glint_render(s, &o, &img, NULL, &err))
        fail_msg("render failed: %s", err.message);
    return img;
}

static double red_at(const glint_image *im, int x, int y)
{
    return im->pixels[3 * ((size_t)y * im->width + x)];
}

static glint_scene *floor_from_above(int w, int h, double view)
{
    return floor_seen(w, h, view, (glint_vec3){0, 20, 0});
}

/* What the one pixel of a floor_seen scene shows; frees the scene. */
static double origin_seen(glint_scene *s)
{
    glint_image im = render(s, 1);
    double v = red_at(&im, 0, 0);
    glint_image_free(&im);
    glint_scene_free(s);
    return v;
}

/* The floor point at the origin lit only by light l: what it shows, which
 * for a white diffuse floor is E / pi, E the irradiance. The camera looks
 * from the side, at 45 degrees, clear of the lights above the point. */
static double under(glint_light l)
{
    glint_scene *s = floor_seen(1, 1, 0.1, (glint_vec3){20, 20, 0});
    glint_error err;
    if (glint_scene_add_light(s, &l, &err) < 0)
        fail_msg("%s", err.message);
    return origin_seen(s);
}

/* The form factor from a point to an a x b rectangle parallel to it at
 * height c, one corner straight above the point. */
static double corner_form_factor(double a, double b, double c)
{
    double x = a / c, y = b / c, sx = sqrt(1 + x * x), sy = sqrt(1 + y * y);
    return (x / sx * atan(y / sx) + y / sy * atan(x / sy)) / (2 * M_PI);
}

/* E = pi L sin^2(theta) under a disc of radiance L, theta the half-angle
 * it subtends; under a ball, E = pi L (r / d)^2, so four times further is
 * sixteen times darker; under a square, four corner form factors. */
static void test_irradiance_under_area_lights(void **state)
{
    (void)state;
    glint_light disk = glint_light_default(GLINT_LIGHT_DISK);
    disk.position = (glint_vec3){0, 2, 0};
    disk.direction = (glint_vec3){0, -1, 0};
    disk.radius = 1;
    disk.color = (glint_color){3, 3, 3};
    disk.samples = 256;
    assert_within(under(disk), 3 * 1.0 / (1 + 4), 0.02);
    /* Facing away, it lights nothing. */
    disk.direction = (glint_vec3){0, 1, 0};
    assert_near(under(disk), 0, 0);

    glint_light ball = glint_light_default(GLINT_LIGHT_SPHERE);
    ball.radius = 0.5;
    ball.samples = 64;
    ball.position = (glint_vec3){0, 2, 0};
    double near = under(ball);
    assert_within(near, 0.25 * 0.25, 0.02);
    ball.position = (glint_vec3){0, 8, 0};
    double far = under(ball);
    assert_within(far, 0.0625 * 0.0625, 0.02);
    assert_within(near / far, 16, 0.02);

    glint_light square = glint_light_default(GLINT_LIGHT_RECTANGLE);
    square.position = (glint_vec3){-1, 1.5, -1};
    square.edge1 = (glint_vec3){2, 0, 0};
    square.edge2 = (glint_vec3){0, 0, 2}; /* x then z: it faces down */
    square.samples = 256;
    assert_within(under(square), 4 * corner_form_factor(1, 1, 1.5), 0.02);
}

/* Where a line from light point (lx, ly) tangent to the circle of radius
 * a about (0, cy), on its side towards +x, meets y = 0. */
static double tangent_on_floor(double lx, double ly, double a, double cy)
{
    double vx = -lx, vy = cy - ly, d = hypot(vx, vy), along = atan2(vy, vx), turn = asin(a / d);
    double best = -INFINITY;
    for (int side = -1; side <= 1; side += 2) {
        double dx = cos(along + side * turn), dy = sin(along + side * turn);
        best = fmax(best, lx + dx * (ly / -dy));
    }
    return best;
}

/* A ball of radius 1 at height 2 under a disc light of radius 0.5 at
 * height 6: the floor is dark out to the umbra's radius and fully lit
 * from the penumbra's, the lines from the disc's rim tangent to the ball,
 * measured in the image within 2 pixels (50 pixels a unit). */
static void test_penumbra_of_a_ball(void **state)
{
    (void)state;
    const double R = 0.5, H = 6, a = 1, h = 2, px_per_unit = 50;
    glint_light disk = glint_light_default(GLINT_LIGHT_DISK);
    disk.position = (glint_vec3){0, H, 0};
    disk.direction = (glint_vec3){0, -1, 0};
    disk.radius = R;
    disk.samples = 1024;
    glint_image shadowed, open;
    for (int with_ball = 0; with_ball < 2; with_ball++) {
        glint_scene *s = floor_from_above(400, 2, 400 / px_per_unit);
        assert_true(glint_scene_add_light(s, &disk, NULL) >= 0);
        if (with_ball) {
            glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {0, h, 0}, .radius = a};
            assert_true(glint_scene_add_shape(s, &ball, 0, NULL, NULL) >= 0);
        }
        *(with_ball ? &shadowed : &open) = render(s, 2);
        glint_scene_free(s);
    }
    double umbra = tangent_on_floor(R, H, a, h), penumbra = tangent_on_floor(-R, H, a, h);
    assert_true(umbra > a + 0.2); /* seen beyond the ball itself */
    for (int dir = -1; dir <= 1; dir += 2) {
        double first_light = -1, first_full = -1;
        for (int step = 0; step < 200; step++) {
            int x = dir < 0 ? 199 - step : 200 + step;
            double ratio = red_at(&shadowed, x, 0) / red_at(&open, x, 0);
            double r = fabs(x + 0.5 - 200) / px_per_unit;
            if (r <= a)
                continue; /* the ball itself, seen from above */
            if (first_light < 0 && ratio > 0.003)
                first_light = r;
            if (first_full < 0 && ratio > 0.997)
                first_full = r;
        }
        assert_near(first_light * px_per_unit, umbra * px_per_unit, 2);
        assert_near(first_full * px_per_unit, penumbra * px_per_unit, 2);
    }
    glint_image_free(&shadowed);
    glint_image_free(&open);
}

/* A camera looking along -z at the origin, one sample a pixel, no ambient,
 * a grey background. */
static glint_scene *looking_down_z(int w, int h)
{
    glint_camera cam = {.position = {0, 0, 10}, .look_at = {0, 0, 0}, .up = {0, 1, 0}, .vfov_degrees = 30};
    glint_scene *s = one_sample_scene(w, h, (glint_color){0, 0, 0}, cam);
    glint_settings st = glint_scene_get_settings(s);
    st.background = (glint_color){0.25, 0.25, 0.25};
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    return s;
}

/* A camera sees a light's glowing side as its colour and looks through
 * its back; a mirror shows it; it casts no shadow of another light. */
static void test_lights_are_seen_but_cast_no_shadow(void **state)
{
    (void)state;
    glint_light panel = glint_light_default(GLINT_LIGHT_RECTANGLE);
    panel.position = (glint_vec3){-1, -1, 0};
    panel.edge1 = (glint_vec3){2, 0, 0};
    panel.edge2 = (glint_vec3){0, 2, 0}; /* x then y: it faces +z, the camera */
    panel.color = (glint_color){0.5, 2, 7};
    glint_scene *s = looking_down_z(11, 11);
    assert_true(glint_scene_add_light(s, &panel, NULL) >= 0);
    glint_image im = render(s, 1);
    assert_near(im.pixels[3 * 60 + 0], 0.5, 0);
    assert_near(im.pixels[3 * 60 + 1], 2, 0);
    assert_near(im.pixels[3 * 60 + 2], 7, 0);
    assert_near(im.pixels[0], 0.25, 0); /* the corner pixel misses it */
    glint_image_free(&im);
    glint_scene_free(s);

    panel.edge1 = (glint_vec3){0, 2, 0};
    panel.edge2 = (glint_vec3){2, 0, 0}; /* now it faces away */
    s = looking_down_z(11, 11);
    assert_true(glint_scene_add_light(s, &panel, NULL) >= 0);
    im = render(s, 1);
    assert_near(im.pixels[3 * 60], 0.25, 0);
    glint_image_free(&im);
    glint_scene_free(s);

    /* A perfect mirror facing the camera at z = -5 shows a ball light
     * beside the view's axis, at the ball's colour, as the camera sees the
     * ball itself; the centre shows the mirrored background. */
    s = looking_down_z(41, 41);
    glint_material mirror = glint_material_default();
    mirror.diffuse = 0;
    mirror.specular = 0;
    mirror.ambient = 0;
    mirror.reflectivity = 1;
    int m = glint_scene_add_material(s, NULL, &mirror, NULL);
    glint_shape wall = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, -5}, .normal = {0, 0, 1}};
    assert_true(glint_scene_add_shape(s, &wall, m, NULL, NULL) >= 0);
    glint_light ball = glint_light_default(GLINT_LIGHT_SPHERE);
    ball.position = (glint_vec3){1.5, 0, 0};
    ball.radius = 0.3;
    ball.color = (glint_color){4, 4, 4};
    assert_true(glint_scene_add_light(s, &ball, NULL) >= 0);
    im = render(s, 1);
    /* The camera sees the ball directly at x = 1.5 (its centre column),
     * and its reflection: the mirror image at (1.5, 0, -10) seen from z =
     * 10 is at x = 1.5 * 10 / 20 in the plane z = 0, nearer the centre. */
    double px_per_unit = 41 / (2 * 10 * tan(15 * M_PI / 180));
    int direct = 20 + (int)lround(1.5 * px_per_unit), mirrored = 20 + (int)lround(0.75 * px_per_unit);
    assert_near(red_at(&im, direct, 20), 4, 0);
    assert_near(red_at(&im, mirrored, 20), 4, 0);
    assert_near(red_at(&im, 20, 20), 0.25, 0); /* the mirrored background */
    glint_image_free(&im);
    glint_scene_free(s);

    /* A square light between a point light and the floor shadows nothing. */
    s = floor_from_above(11, 11, 0.1);
    glint_light lamp = {.kind = GLINT_LIGHT_POINT, .position = {0, 4, 0}, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &lamp, NULL) >= 0);
    glint_light square = glint_light_default(GLINT_LIGHT_RECTANGLE);
    square.position = (glint_vec3){-1, 2, -1};
    square.edge1 = (glint_vec3){0, 0, 2};
    square.edge2 = (glint_vec3){2, 0, 0}; /* facing up: it lights nothing below */
    assert_true(glint_scene_add_light(s, &square, NULL) >= 0);
    im = render(s, 1);
    assert_near(red_at(&im, 5, 5), 1, 1e-9);
    glint_image_free(&im);
    glint_scene_free(s);
}

/* What a light's values must be, in the C API's words. */
static void test_area_light_values_checked(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_error err;
    glint_light l = glint_light_default(GLINT_LIGHT_RECTANGLE);
    l.edge1 = (glint_vec3){1, 0, 0};
    l.edge2 = (glint_vec3){-2, 0, 0};
    assert_int_equal(glint_scene_add_light(s, &l, &err), -1);
    assert_string_equal(err.message, "rectangle light edge1 and edge2 must be of finite length and not parallel");
    l.edge2 = (glint_vec3){0, 0, 1};
    l.samples = 0;
    assert_int_equal(glint_scene_add_light(s, &l, &err), -1);
    assert_string_equal(err.message, "rectangle light samples must be from 1 to 4096, got 0");
    glint_light ball = glint_light_default(GLINT_LIGHT_SPHERE);
    assert_int_equal(glint_scene_add_light(s, &ball, &err), -1);
    assert_string_equal(err.message, "sphere light radius must be positive, got 0");
    ball.radius = 1;
    ball.falloff = GLINT_FALLOFF_INVERSE_SQUARE;
    assert_int_equal(glint_scene_add_light(s, &ball, &err), -1);
    assert_string_equal(err.message, "a sphere light weakens with distance by its size: its falloff_mode must be none");
    glint_light disk = glint_light_default(GLINT_LIGHT_DISK);
    disk.radius = 1;
    assert_int_equal(glint_scene_add_light(s, &disk, &err), -1);
    assert_string_equal(err.message, "disk light direction must not be zero");
    disk.direction = (glint_vec3){0, -1, 0};
    assert_true(glint_scene_add_light(s, &disk, &err) >= 0);
    glint_scene_free(s);
}

/* A material that gives off `glow` and reflects nothing. */
static int glowing(glint_scene *s, double glow)
{
    glint_material m = glint_material_default();
    m.diffuse = m.specular = m.ambient = 0;
    m.emission = (glint_color){1, 1, 1};
    m.emission_strength = glow;
    int i = glint_scene_add_material(s, NULL, &m, NULL);
    assert_true(i >= 0);
    return i;
}

/* Soft shadows of area lights and of an emissive box are the same bytes
 * for 1, 2 and 7 threads and any tile size; another seed gives other
 * samples. */
static void test_area_light_bytes_independent_of_threads(void **state)
{
    (void)state;
    glint_scene *s = looking_down_z(64, 48);
    glint_camera cam = glint_scene_get_camera(s);
    cam.position = (glint_vec3){0, 6, 8};
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    glint_material m = glint_material_default();
    int white = glint_scene_add_material(s, NULL, &m, NULL);
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, -1, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &floor, white, NULL, NULL) >= 0);
    glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {0, 0, 0}, .radius = 1};
    assert_true(glint_scene_add_shape(s, &ball, white, NULL, NULL) >= 0);
    glint_light lights[3] = {glint_light_default(GLINT_LIGHT_SPHERE), glint_light_default(GLINT_LIGHT_RECTANGLE),
                             glint_light_default(GLINT_LIGHT_DISK)};
    lights[0].position = (glint_vec3){2, 3, 0};
    lights[0].radius = 0.5;
    lights[1].position = (glint_vec3){-3, 4, -1};
    lights[1].edge1 = (glint_vec3){1, 0, 0};
    lights[1].edge2 = (glint_vec3){0, 0, 1};
    lights[1].samples = 7;
    lights[2].position = (glint_vec3){0, 5, 2};
    lights[2].direction = (glint_vec3){0, -1, -0.3};
    lights[2].radius = 1;
    for (int i = 0; i < 3; i++)
        assert_true(glint_scene_add_light(s, &lights[i], NULL) >= 0);
    glint_shape lamp = {.kind = GLINT_SHAPE_BOX, .min = {-3, 0, -2}, .max = {-2.5, 0.5, -1.5}};
    assert_true(glint_scene_add_shape(s, &lamp, glowing(s, 3), NULL, NULL) >= 0);
    size_t bytes = 64 * 48 * 3 * sizeof(float);
    glint_image one = render(s, 1), two = render(s, 2), seven = render(s, 7), tiled;
    assert_memory_equal(one.pixels, two.pixels, bytes);
    assert_memory_equal(one.pixels, seven.pixels, bytes);
    glint_render_options o = {.threads = 3, .tile_size = 12};
    assert_int_equal(glint_render(s, &o, &tiled, NULL, NULL), GLINT_OK);
    assert_memory_equal(one.pixels, tiled.pixels, bytes);
    glint_settings st = glint_scene_get_settings(s);
    st.seed = 7;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_image seeded = render(s, 2);
    assert_memory_not_equal(one.pixels, seeded.pixels, bytes);
    /* The lights chosen by power, likewise. */
    st.light_samples = 5;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_image chosen1 = render(s, 1), chosen7 = render(s, 7);
    assert_memory_equal(chosen1.pixels, chosen7.pixels, bytes);
    assert_memory_not_equal(chosen1.pixels, seeded.pixels, bytes);
    glint_image_free(&chosen1);
    glint_image_free(&chosen7);
    glint_image_free(&one);
    glint_image_free(&two);
    glint_image_free(&seven);
    glint_image_free(&tiled);
    glint_image_free(&seeded);
    glint_scene_free(s);
}

/* Many lamps: twelve disks of different sizes and colours and a glowing
 * ball over the floor point. Sampled together, 1024 samples chosen by
 * power, they give the light each gives sampled on its own, 256 samples
 * each, within 2%, with a quarter of the shadow rays. */
static void test_many_lights_chosen_by_power(void **state)
{
    (void)state;
    glint_render_stats stats[2];
    double seen[2];
    for (int chosen = 0; chosen < 2; chosen++) {
        glint_scene *s = floor_seen(1, 1, 0.1, (glint_vec3){20, 20, 0});
        glint_settings st = glint_scene_get_settings(s);
        st.emission_samples = 256;
        st.light_samples = chosen ? 1024 : 0;
        assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
        for (int k = 0; k < 12; k++) {
            glint_light disk = glint_light_default(GLINT_LIGHT_DISK);
            double angle = k * 2 * M_PI / 12;
            disk.position = (glint_vec3){2 * cos(angle), 1.5 + 0.25 * (k % 3), 2 * sin(angle)};
            disk.direction = (glint_vec3){-cos(angle), -1, -sin(angle)};
            disk.radius = 0.2 + 0.1 * (k % 4);
            disk.color = (glint_color){0.5 + k % 2, 1, 0.2 * k};
            disk.samples = 256;
            assert_true(glint_scene_add_light(s, &disk, NULL) >= 0);
        }
        glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {0.5, 2, 0.5}, .radius = 0.3};
        assert_true(glint_scene_add_shape(s, &ball, glowing(s, 2), NULL, NULL) >= 0);
        glint_image im;
        assert_int_equal(glint_render(s, &(glint_render_options){.threads = 1}, &im, &stats[chosen], NULL),
                         GLINT_OK);
        seen[chosen] = red_at(&im, 0, 0);
        glint_image_free(&im);
        glint_scene_free(s);
    }
    assert_within(seen[1], seen[0], 0.02);
    assert_true(stats[1].rays * 3 < stats[0].rays);
}

/* The floor point at the origin lit only by shape sh of a material
 * glowing at `glow` (placed by xf, NULL: as it is), its light sampled
 * `samples` times at each point. */
static double under_shape(glint_shape sh, const glint_transform *xf, double glow, int samples)
{
    glint_scene *s = floor_seen(1, 1, 0.1, (glint_vec3){20, 20, 0});
    glint_settings st = glint_scene_get_settings(s);
    st.emission_samples = samples;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_error err;
    if (glint_scene_add_shape(s, &sh, glowing(s, glow), xf, &err) < 0)
        fail_msg("%s", err.message);
    return origin_seen(s);
}

/* An emissive shape lights as the area light of its shape does: a square
 * by its form factor, a ball by (r / d)^2, scaled by a transform (the
 * density of points it samples follows the stretch), a disc squashed into
 * an ellipse far away by its area. */
static void test_emissive_shapes_light_the_scene(void **state)
{
    (void)state;
    glint_shape square = {.kind = GLINT_SHAPE_POLYGON, .point_count = 4,
                          .points = {{-1, 1.5, -1}, {1, 1.5, -1}, {1, 1.5, 1}, {-1, 1.5, 1}}}; /* facing down */
    assert_within(under_shape(square, NULL, 3, 256), 3 * 4 * corner_form_factor(1, 1, 1.5), 0.02);
    glint_shape ball = glint_shape_default(GLINT_SHAPE_SPHERE);
    ball.center = (glint_vec3){0, 2, 0};
    ball.radius = 0.5;
    assert_within(under_shape(ball, NULL, 1, 1024), 0.0625, 0.02);
    glint_transform grow = {{{2, 0, 0, 0}, {0, 2, 0, 1}, {0, 0, 2, 0}}}; /* twice the size, 1 up */
    ball.center = (glint_vec3){0, 0.5, 0};
    ball.radius = 0.25;
    assert_within(under_shape(ball, &grow, 1, 1024), 0.0625, 0.02);
    glint_shape disc = glint_shape_default(GLINT_SHAPE_DISK);
    disc.center = (glint_vec3){0, 40, 0};
    disc.normal = (glint_vec3){0, -1, 0};
    disc.radius = 1;
    glint_transform wide = {{{2, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}}; /* an ellipse of area 2 pi */
    assert_within(under_shape(disc, &wide, 100, 64), 100 * 2 / (40.0 * 40), 0.01);
    /* A plane has no end to sample: it glows, lights nothing, and says so. */
    glint_scene *s = glint_scene_new();
    glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &plane, glowing(s, 1), NULL, NULL) >= 0);
    assert_int_equal(glint_scene_warning_count(s), 1);
    assert_string_equal(glint_scene_warning(s, 0),
                        "an emissive plane glows but lights nothing: it has no end (a polygon or disk does)");
    glint_scene_free(s);
}

/* A camera sees an emissive surface's front at its radiance, its back
 * not glowing; the triangles of an emissive mesh light the floor by their
 * form factor, wherever an instance puts them. */
static void test_emissive_meshes(void **state)
{
    (void)state;
    const float square[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    const uint32_t down[] = {0, 1, 2, 0, 2, 3}; /* clockwise seen from above: facing down */
    for (int placed = 0; placed < 2; placed++) {
        glint_scene *s = floor_seen(1, 1, 0.1, (glint_vec3){20, 20, 0});
        glint_settings st = glint_scene_get_settings(s);
        st.emission_samples = 256;
        assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
        glint_mesh_data d = {.positions = square, .vertex_count = 4, .indices = down, .triangle_count = 2,
                             .material = glowing(s, 2)};
        int square_mesh = glint_scene_add_mesh(s, NULL, &d, NULL);
        glint_transform up = {{{1, 0, 0, 0}, {0, 1, 0, placed ? 3 : 1.5}, {0, 0, 1, 0}}};
        assert_true(glint_scene_add_instance(s, square_mesh, -1, &up, NULL) >= 0);
        assert_int_equal(s->emitter_count, 1);
        glint_image im = render(s, 2);
        assert_within(red_at(&im, 0, 0), 2 * 4 * corner_form_factor(1, 1, placed ? 3 : 1.5), 0.02);
        glint_image_free(&im);
        glint_scene_free(s);
    }
    /* Seen from below, the glowing side; from above, the dark back. */
    glint_scene *s = looking_down_z(5, 5);
    glint_camera cam = glint_scene_get_camera(s);
    for (int below = 0; below < 2; below++) {
        cam.position = (glint_vec3){0, below ? -5 : 5, 0.001};
        assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
        if (!below) {
            glint_mesh_data d = {.positions = square, .vertex_count = 4, .indices = down, .triangle_count = 2,
                                 .material = glowing(s, 2)};
            assert_true(glint_scene_add_instance(s, glint_scene_add_mesh(s, NULL, &d, NULL), -1, NULL, NULL) >= 0);
        }
        glint_image im = render(s, 1);
        assert_near(red_at(&im, 2, 2), below ? 2 : 0, 0);
        glint_image_free(&im);
    }
    glint_scene_free(s);
}

/* A quad lamp split into two triangles is sampled as one parallelogram,
 * its stratified samples spread over the whole lamp: with 16 of them the
 * irradiance under it is within 1.2% of its form factor on average, over
 * heights and seeds (0.8% measured; sampled as two triangles apart, 2.3%). */
static void test_quad_lamp_sampled_whole(void **state)
{
    (void)state;
    const float square[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    const uint32_t down[] = {0, 1, 2, 0, 2, 3};
    double error = 0;
    int renders = 0;
    for (uint32_t seed = 0; seed < 4; seed++)
        for (int k = 0; k < 8; k++) {
            double height = 1.2 + 0.3 * k; /* above the camera's line of sight */
            glint_scene *s = floor_seen(1, 1, 0.1, (glint_vec3){20, 20, 0});
            glint_settings st = glint_scene_get_settings(s);
            st.emission_samples = 16;
            st.seed = seed;
            assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
            glint_mesh_data d = {.positions = square, .vertex_count = 4, .indices = down, .triangle_count = 2,
                                 .material = glowing(s, 2)};
            glint_transform up = {{{1, 0, 0, 0}, {0, 1, 0, height}, {0, 0, 1, 0}}};
            assert_true(glint_scene_add_instance(s, glint_scene_add_mesh(s, NULL, &d, NULL), -1, &up, NULL) >= 0);
            double expected = 2 * 4 * corner_form_factor(1, 1, height);
            error += fabs(origin_seen(s) / expected - 1);
            renders++;
        }
    assert_true(error / renders <= 0.012);
}

/* A number in [lo, hi) from *state, a 64-bit LCG's high bits. */
static double uniform(uint64_t *state, double lo, double hi)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(*state >> 11) * 0x1.0p-53;
}

/* Each area light's samples for a packet's lanes (kind->sample_lanes:
 * four lanes at a time by the parallelogram shortcuts of the rectangle
 * light and a one-quad lamp; a lane at a time for the disk and sphere
 * lights, a lamp of three triangles and a glowing ball) are its samples
 * one at a time (kind->sample), to the bit, whichever way a render takes
 * them. */
static void test_light_lanes_are_its_samples(void **state)
{
    (void)state;
    glint_scene *s = floor_from_above(1, 1, 1);
    glint_light lights[3] = {glint_light_default(GLINT_LIGHT_RECTANGLE), glint_light_default(GLINT_LIGHT_DISK),
                             glint_light_default(GLINT_LIGHT_SPHERE)};
    lights[0].position = (glint_vec3){-1, 3, -0.5};
    lights[0].edge1 = (glint_vec3){2, 0.3, 0.4}; /* every coordinate a sum of three */
    lights[0].edge2 = (glint_vec3){-0.25, 0.1, 1.5};
    lights[1].position = (glint_vec3){0.5, 2, 1};
    lights[1].direction = (glint_vec3){0.2, -1, 0.1};
    lights[1].radius = 0.7;
    lights[2].position = (glint_vec3){-2, 1.5, 0};
    lights[2].radius = 0.4;
    for (int k = 0; k < 3; k++)
        assert_true(glint_scene_add_light(s, &lights[k], NULL) >= 0);
    /* A tilted quad lamp (one parallelogram: the first and third corners
     * add up to the others) facing down, and a lamp of three triangles. */
    const float square[] = {-1, 0.1f, -1, 1, 0.3f, -0.9f, 1.2f, 0.5f, 1.1f, -0.8f, 0.3f, 1, 0, 0.2f, 2};
    const uint32_t quad[] = {0, 1, 2, 0, 2, 3}, three[] = {0, 1, 2, 0, 2, 3, 3, 2, 4};
    glint_transform up = {{{1, 0, 0, 0}, {0, 1, 0, 2.5}, {0, 0, 1, 0}}};
    for (int k = 0; k < 2; k++) {
        glint_mesh_data d = {.positions = square, .vertex_count = 5, .indices = k ? three : quad,
                             .triangle_count = k ? 3 : 2, .material = glowing(s, 2)};
        assert_true(glint_scene_add_instance(s, glint_scene_add_mesh(s, NULL, &d, NULL), -1, &up, NULL) >= 0);
    }
    /* An emissive ball: a shape emitter, sampled by its surface lane by lane. */
    glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {1.5, 2, -1}, .radius = 0.5};
    assert_true(glint_scene_add_shape(s, &ball, glowing(s, 3), NULL, NULL) >= 0);
    assert_int_equal(s->light_count, 3);
    assert_int_equal(s->emitter_count, 3);
    assert_int_equal(s->emitters[0].triangle_count, 1); /* the parallelogram */
    assert_int_equal(s->emitters[1].triangle_count, 2);
    uint64_t rng = 7;
    int compared = 0;
    for (int l = 0; l < s->light_count + s->emitter_count; l++) {
        const light *li = l < s->light_count ? &s->lights[l] : &s->emitters[l - s->light_count];
        for (int round = 0; round < 500; round++) {
            double p[3][RAY8], u[2][RAY8];
            bool active[RAY8];
            for (int i = 0; i < RAY8; i++) {
                for (int c = 0; c < 3; c++)
                    p[c][i] = uniform(&rng, -3, 4);
                u[0][i] = uniform(&rng, 0, 1);
                u[1][i] = uniform(&rng, 0, 1);
                active[i] = uniform(&rng, 0, 1) < 0.8;
            }
            light_samples8 lanes;
            li->kind->sample_lanes(li, p, u, active, &lanes);
            for (int i = 0; i < RAY8; i++) {
                light_sample one;
                bool ok = active[i] && li->kind->sample(li, (vec3){p[0][i], p[1][i], p[2][i]}, u[0][i], u[1][i], &one);
                assert_int_equal(lanes.ok[i], ok);
                if (!ok)
                    continue;
                const double lane[7] = {lanes.to_light[0][i], lanes.to_light[1][i], lanes.to_light[2][i],
                                        lanes.distance[i],    lanes.radiance[0][i], lanes.radiance[1][i],
                                        lanes.radiance[2][i]};
                const double alone[7] = {one.to_light.x, one.to_light.y, one.to_light.z, one.distance,
                                         one.radiance.r, one.radiance.g, one.radiance.b};
                assert_memory_equal(lane, alone, sizeof lane);
                compared++;
            }
        }
    }
    assert_true(compared > 6 * 500 * RAY8 / 4); /* a quarter of the lanes, at least, compared */
    glint_scene_free(s);
}

/* A 16 x 12 view of an orange floor of that specular, shininess and
 * metallic tint under a bright rectangle lamp, whose highlight lies in
 * the view, rendered. */
static glint_image glossy_floor(double shininess, double specular, double metallic)
{
    glint_camera cam = {.kind = GLINT_CAMERA_PINHOLE, .position = {0, 2, 4}, .look_at = {0, 0, 0},
                        .up = {0, 1, 0}, .vfov_degrees = 50};
    glint_scene *s = one_sample_scene(16, 12, (glint_color){0, 0, 0}, cam);
    glint_material m = glint_material_default();
    m.color = (glint_color){1, 0.5, 0.2};
    m.specular = specular;
    m.shininess = shininess;
    m.metallic = metallic;
    int glossy = glint_scene_add_material(s, NULL, &m, NULL);
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &floor, glossy, NULL, NULL) >= 0);
    glint_light lamp = glint_light_default(GLINT_LIGHT_RECTANGLE);
    lamp.position = (glint_vec3){-0.5, 1.5, -2};
    lamp.edge1 = (glint_vec3){1, 0, 0};
    lamp.edge2 = (glint_vec3){0, 0, 1}; /* x then z: facing down */
    lamp.samples = 16;
    lamp.color = (glint_color){8, 8, 8};
    assert_true(glint_scene_add_light(s, &lamp, NULL) >= 0);
    glint_image im = render(s, 1);
    glint_scene_free(s);
    return im;
}

/* A highlight under an area light is the same whether its exponent is a
 * whole number (worked out four lanes at a time by squarings) or not
 * (pow, a lane at a time): shininess 9 and 9 + 1e-9 differ by rounding
 * only, while the highlight itself is plain to see. So is a metallic
 * highlight, tinted by the floor's colour: its blue is a fifth of its red
 * (a whole exponent's had been left white). */
static void test_glossy_lanes_agree(void **state)
{
    (void)state;
    for (int metal = 0; metal <= 1; metal++) {
        glint_image whole = glossy_floor(9, 0.6, metal), fractional = glossy_floor(9 + 1e-9, 0.6, metal);
        glint_image matte = glossy_floor(9, 0, metal);
        double most = 0, highlight = 0, red = 0, blue = 0;
        for (size_t k = 0; k < (size_t)3 * whole.width * whole.height; k++) {
            double d = fabs(whole.pixels[k] - fractional.pixels[k]);
            most = d > most ? d : most;
            double shine = whole.pixels[k] - matte.pixels[k];
            if (shine > highlight && k % 3 == 0) {
                highlight = shine;
                red = shine;
                blue = whole.pixels[k + 2] - matte.pixels[k + 2];
            }
        }
        assert_true(most <= 1e-6);
        assert_true(highlight > 0.05);
        assert_near(blue, metal ? 0.2 * red : red, 1e-6 * red);
        glint_image_free(&whole);
        glint_image_free(&fractional);
        glint_image_free(&matte);
    }
}

/* glint CornellBox-Original.obj: lit by its own ceiling lamp (MTL Ke 17
 * 12 4) alone, which the camera sees at that radiance (its ambient term,
 * 0.2 of its Kd, on top). */
static void test_cornell_box_lit_by_its_lamp(void **state)
{
    (void)state;
    const char *data = getenv("GLINT_SHARED_DATA");
    char path[4096];
    snprintf(path, sizeof path, "%s/CornellBox-Original.obj", data ? data : ".");
    FILE *f = fopen(path, "r");
    if (!f)
        skip();
    fclose(f);
    glint_error err;
    glint_scene *s = glint_scene_for_model(path, &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_int_equal(glint_scene_get_counts(s).lights, 0);
    assert_int_equal(s->emitter_count, 1);
    /* The lamp's two triangles make a rectangle: sampled as one. */
    assert_int_equal(s->emitters[0].triangle_count, 1);
    assert_true(s->emitters[0].triangles[0].parallelogram);
    glint_settings st = glint_scene_get_settings(s);
    st.width = 80;
    st.height = 60;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_image im = render(s, 2);
    /* The lamp, at the top of the box: its Ke, and its own faint ambient term. */
    const float *lamp = im.pixels + 3 * (10 * 80 + 40);
    assert_near(lamp[0], 17 + 0.1, 0.1);
    assert_near(lamp[1], 12 + 0.1, 0.1);
    assert_near(lamp[2], 4 + 0.1, 0.1);
    glint_image_free(&im);
    glint_scene_free(s);
}

/* The floor point at the origin under a ball of radius 1 at height 2, lit
 * by the ambient light alone with ambient occlusion of `samples` rays
 * looking `distance` far: the ball hides a cap of half-angle 30 degrees
 * from it, a share sin^2(30) = 1/4 of the cosine-weighted sky, so the
 * floor (ambient 1, white) shows 3/4 when the rays reach the ball, 1 when
 * they stop short of it. */
static double occluded_floor(int samples, double distance)
{
    glint_scene *s = floor_seen(1, 1, 0.1, (glint_vec3){20, 20, 0});
    glint_settings st = glint_scene_get_settings(s);
    st.ambient_light = (glint_color){1, 1, 1};
    st.occlusion_samples = samples;
    st.occlusion_distance = distance;
    glint_error err;
    if (glint_scene_set_settings(s, &st, &err))
        fail_msg("%s", err.message);
    glint_material m = glint_material_default();
    m.ambient = 1;
    m.diffuse = m.specular = 0;
    int flat = glint_scene_add_material(s, NULL, &m, NULL);
    s->shapes[0].material = flat; /* the floor, ambient only */
    glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {0, 2, 0}, .radius = 1};
    assert_true(glint_scene_add_shape(s, &ball, flat, NULL, NULL) >= 0);
    return origin_seen(s);
}

static void test_ambient_occlusion_under_a_ball(void **state)
{
    (void)state;
    assert_near(occluded_floor(0, 0), 1, 0);          /* flat ambient */
    assert_near(occluded_floor(1024, 0), 0.75, 0.01);  /* the ball, as far as the scene goes */
    assert_near(occluded_floor(1024, 5), 0.75, 0.01);
    assert_near(occluded_floor(1024, 0.9), 1, 1e-9);   /* the ball is 1 away */
    glint_scene *s = glint_scene_new();
    glint_settings st = glint_settings_default();
    st.occlusion_samples = 5000;
    glint_error err;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "ambient_occlusion samples must be from 1 to 4096, got 5000");
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_irradiance_under_area_lights),
        cmocka_unit_test(test_penumbra_of_a_ball),
        cmocka_unit_test(test_lights_are_seen_but_cast_no_shadow),
        cmocka_unit_test(test_area_light_values_checked),
        cmocka_unit_test(test_area_light_bytes_independent_of_threads),
        cmocka_unit_test(test_emissive_shapes_light_the_scene),
        cmocka_unit_test(test_emissive_meshes),
        cmocka_unit_test(test_quad_lamp_sampled_whole),
        cmocka_unit_test(test_light_lanes_are_its_samples),
        cmocka_unit_test(test_glossy_lanes_agree),
        cmocka_unit_test(test_many_lights_chosen_by_power),
        cmocka_unit_test(test_cornell_box_lit_by_its_lamp),
        cmocka_unit_test(test_ambient_occlusion_under_a_ball),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
