/* test_ray_limits.c - the bounds on one sample's tree of rays: a branch too
 * light to change a pixel is not traced (TRACER_MIN_WEIGHT), and no sample
 * traces more than TRACER_MAX_BRANCH_RAYS branches, whatever the depth.
 * Counted with the render's own ray count, in scenes without lights, where
 * every ray counted is a camera ray or a branch. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdbool.h>
#include "glint.h"
#include "one_sample_scene.h"
#include "render/integrator.h"

/* A one-pixel, one-sample scene at the deepest recursion, its camera at the
 * origin looking down -z. */
static glint_scene *deep_scene(void)
{
    glint_camera cam = {.position = {0, 0, 0}, .look_at = {0, 0, -1}, .up = {0, 1, 0}, .vfov_degrees = 30};
    glint_scene *s = one_sample_scene(1, 1, (glint_color){1, 1, 1}, cam);
    glint_settings st = glint_scene_get_settings(s);
    st.max_depth = 64;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    return s;
}

/* A material that shows nothing of its own, passing on `reflectivity` by
 * mirror and `transparency` straight through, unfiltered. */
static int passing(glint_scene *s, double reflectivity, double transparency)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){1, 1, 1};
    m.ambient = m.diffuse = m.specular = 0;
    m.reflectivity = reflectivity;
    m.transparency = transparency;
    m.tint = 0;
    int i = glint_scene_add_material(s, NULL, &m, NULL);
    assert_true(i >= 0);
    return i;
}

static uint64_t rays_of(const glint_scene *s)
{
    glint_image img;
    glint_render_stats stats;
    glint_render_options o = {.threads = 1};
    assert_int_equal(glint_render(s, &o, &img, &stats, NULL), GLINT_OK);
    glint_image_free(&img);
    return stats.rays;
}

/* Between two facing half mirrors, the k-th reflection weighs 0.5^k: the
 * camera ray and every reflection down to TRACER_MIN_WEIGHT are traced (13
 * of them), not the 64 the depth allows. */
static void test_light_branches_are_not_traced(void **state)
{
    (void)state;
    glint_scene *s = deep_scene();
    int half = passing(s, 0.5, 0);
    glint_shape near = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 1}, .normal = {0, 0, -1}};
    glint_shape far = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, -1}, .normal = {0, 0, 1}};
    assert_true(glint_scene_add_shape(s, &near, half, NULL, NULL) >= 0);
    assert_true(glint_scene_add_shape(s, &far, half, NULL, NULL) >= 0);
    int reflections = 0;
    for (double w = 0.5; w >= TRACER_MIN_WEIGHT; w *= 0.5)
        reflections++;
    assert_int_equal(reflections, 13);
    assert_int_equal(rays_of(s), 1 + reflections);
    glint_scene_free(s);
}

/* Inside two nested spheres that mirror all and pass half, each hit sends
 * on more than it receives, and the tree of rays grows about 1.5 times a
 * level for 64 levels: the sample stops at the budget. */
static void test_a_sample_traces_a_bounded_number_of_branches(void **state)
{
    (void)state;
    glint_scene *s = deep_scene();
    int both = passing(s, 1, 0.5);
    glint_shape outer = {.kind = GLINT_SHAPE_SPHERE, .center = {0, 0, -5}, .radius = 2};
    glint_shape inner = {.kind = GLINT_SHAPE_SPHERE, .center = {0, 0, -5}, .radius = 1};
    assert_true(glint_scene_add_shape(s, &outer, both, NULL, NULL) >= 0);
    assert_true(glint_scene_add_shape(s, &inner, both, NULL, NULL) >= 0);
    assert_int_equal(rays_of(s), 1 + TRACER_MAX_BRANCH_RAYS);
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_light_branches_are_not_traced),
        cmocka_unit_test(test_a_sample_traces_a_bounded_number_of_branches),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
