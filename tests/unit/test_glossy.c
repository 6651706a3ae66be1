/* test_glossy.c - rough reflection and refraction: the share of a blurred
 * mirror's (or a frosted sheet's) rays that reach a white half-plane,
 * against the Phong lobe integrated numerically; sharp surfaces stay sharp;
 * the same bytes for any thread count. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdbool.h>
#include "glint.h"
#include "one_sample_scene.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

/* The share of directions about +y, of density proportional to cos^e of
 * their angle to it, whose slope along x (dx / dy) exceeds tan(alpha): by
 * quadrature over the angle theta from the axis, the share of azimuths at
 * each given in closed form. */
static double lobe_share(double e, double alpha)
{
    const int steps = 20000;
    double sum = 0, h = (M_PI / 2) / steps;
    for (int s = 0; s < steps; s++) {
        double theta = (s + 0.5) * h, c = tan(alpha) / tan(theta);
        double azimuths = c <= -1 ? 1 : c >= 1 ? 0 : acos(c) / M_PI;
        sum += (e + 1) * pow(cos(theta), e) * sin(theta) * azimuths * h;
    }
    return sum;
}

enum { WIDTH = 200 };
#define VIEW 4.0 /* units across the image: 50 pixels a unit */

/* A row of WIDTH pixels looking straight down from y = 1 at a surface at
 * y = 0 of material m (a mirror, or a sheet light passes through), with a
 * white card covering x > 0 at y = card_y (above for a mirror, below for a
 * sheet) and black elsewhere: what each pixel shows. */
static glint_image half_plane_seen(glint_material m, double card_y, int threads)
{
    glint_camera cam = {.kind = GLINT_CAMERA_ORTHOGRAPHIC, .position = {0, 1, 0}, .look_at = {0, 0, 0},
                        .up = {0, 0, -1}, .vfov_degrees = 40, .view_width = VIEW};
    /* The white card shows the ambient light, white. */
    glint_scene *s = one_sample_scene(WIDTH, 1, (glint_color){1, 1, 1}, cam);
    glint_error err;
    int surface = glint_scene_add_material(s, NULL, &m, &err);
    if (surface < 0)
        fail_msg("%s", err.message);
    glint_material white = glint_material_default();
    white.ambient = 1;
    white.diffuse = white.specular = 0;
    int card = glint_scene_add_material(s, NULL, &white, NULL);
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &floor, surface, NULL, NULL) >= 0);
    glint_shape half = {.kind = GLINT_SHAPE_POLYGON, .point_count = 4,
                        .points = {{0, card_y, -1e3}, {1e3, card_y, -1e3}, {1e3, card_y, 1e3}, {0, card_y, 1e3}}};
    assert_true(glint_scene_add_shape(s, &half, card, NULL, NULL) >= 0);
    glint_image im;
    glint_render_options o = {.threads = threads};
    assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
    glint_scene_free(s);
    return im;
}

/* Pixel x looks at floor point (x + 0.5 - WIDTH / 2) / 50; the card's edge,
 * at height h above or below, is at angle atan(-that / h) from the axis. */
static void assert_lobe_profile(glint_material m, double card_y)
{
    glint_image im = half_plane_seen(m, card_y, 2);
    double e = 2 / pow(m.roughness, 4) - 2, worst = 0;
    for (int x = 0; x < WIDTH; x += 5) {
        double at = (x + 0.5 - WIDTH / 2.0) * VIEW / WIDTH;
        double want = m.roughness > 0 ? lobe_share(e, atan(-at / fabs(card_y))) : at > 0;
        worst = fmax(worst, fabs(im.pixels[3 * x] - want));
    }
    glint_image_free(&im);
    assert_true(worst < 0.02);
}

static glint_material blank(void)
{
    glint_material m = glint_material_default();
    m.ambient = m.diffuse = m.specular = 0;
    m.glossy_samples = 256;
    return m;
}

/* A rough mirror's rays spread over the lobe about the mirror direction:
 * the edge of a white card above it blurs as the lobe's integral, within
 * 0.02 at every pixel; a sharp mirror keeps the step. */
static void test_rough_mirror_blurs_by_its_lobe(void **state)
{
    (void)state;
    glint_material mirror = blank();
    mirror.reflectivity = 1;
    for (int i = 0; i < 3; i++) {
        mirror.roughness = (double[]){0, 0.35, 0.6}[i];
        assert_lobe_profile(mirror, 2);
    }
}

/* Frosted glass: a sheet that passes light unbent (ior 1) spreads it over
 * the same lobe about the straight-through direction. */
static void test_rough_refraction_frosts(void **state)
{
    (void)state;
    glint_material sheet = blank();
    sheet.refraction = 1;
    sheet.ior = 1;
    for (int i = 0; i < 2; i++) {
        sheet.roughness = (double[]){0, 0.5}[i];
        assert_lobe_profile(sheet, -2);
    }
}

/* The spread rays come from each sample's key: the same bytes for 1 and 7
 * threads. */
static void test_glossy_bytes_independent_of_threads(void **state)
{
    (void)state;
    glint_material mirror = blank();
    mirror.reflectivity = 1;
    mirror.roughness = 0.4;
    mirror.glossy_samples = 9;
    glint_image one = half_plane_seen(mirror, 2, 1), seven = half_plane_seen(mirror, 2, 7);
    assert_memory_equal(one.pixels, seven.pixels, sizeof(float) * 3 * WIDTH);
    glint_image_free(&one);
    glint_image_free(&seven);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rough_mirror_blurs_by_its_lobe),
        cmocka_unit_test(test_rough_refraction_frosts),
        cmocka_unit_test(test_glossy_bytes_independent_of_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
