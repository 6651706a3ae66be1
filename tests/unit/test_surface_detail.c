/* test_surface_detail.c - bump and normal maps against the normals they
 * stand for: a quad facing the camera, lit head-on or from the side, whose
 * brightness is the cosine between the light and the tilted normal. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include "glint.h"
#include "one_sample_scene.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

enum { SIDE = 21 };

/* A 2 x 2 quad at z = 0 facing +z, its u along +x and v down (-y), seen
 * straight on by an orthographic camera of SIDE x SIDE pixels, white and
 * matte, lit only by a directional light towards `to_light`; m gives its
 * bump or normal map, textures[0] being `detail`. */
static glint_image lit_quad(glint_texture detail, glint_material m, glint_vec3 to_light)
{
    glint_camera cam = {.kind = GLINT_CAMERA_ORTHOGRAPHIC, .position = {0, 0, 5}, .look_at = {0, 0, 0},
                        .up = {0, 1, 0}, .vfov_degrees = 40, .view_width = 2};
    glint_scene *s = one_sample_scene(SIDE, SIDE, (glint_color){0, 0, 0}, cam);
    glint_error err;
    assert_true(glint_scene_add_texture(s, "detail", &detail, &err) == 0);
    m.color = (glint_color){1, 1, 1};
    m.ambient = m.specular = 0;
    int mat = glint_scene_add_material(s, NULL, &m, &err);
    if (mat < 0)
        fail_msg("%s", err.message);
    glint_shape quad = {.kind = GLINT_SHAPE_POLYGON, .point_count = 4,
                        .points = {{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}}};
    assert_true(glint_scene_add_shape(s, &quad, mat, NULL, NULL) >= 0);
    glint_light sun = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {-to_light.x, -to_light.y, -to_light.z},
                       .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &sun, &err) >= 0);
    glint_image im;
    glint_render_options o = {.threads = 1};
    assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
    glint_scene_free(s);
    return im;
}

/* A texture of one colour everywhere (a checker of two equal colours):
 * a normal map's texel, read as it is. */
static glint_texture flat_texture(double r, double g, double b)
{
    glint_texture t = glint_texture_default(GLINT_TEXTURE_CHECKER);
    t.colors[0] = t.colors[1] = (glint_color){r, g, b};
    return t;
}

/* Red along +u, green towards the image's top (against v), blue out of the
 * surface, each 0..1 for -1..1: texel (0.8, 0.5, 0.9) is the normal
 * (0.6, 0, 0.8), towards +x here, and (0.5, 0.8, 0.9) is (0, 0.6, 0.8),
 * towards +y; a light from 45 degrees on that side meets it at cos 8.13
 * degrees, 0.98995, where the plain quad's cosine is 0.70711. */
static void test_normal_map_frame(void **state)
{
    const double r = sqrt(0.5), tilted = (0.6 + 0.8) * r;
    glint_material m = glint_material_default();
    glint_image plain = lit_quad(flat_texture(0.5, 0.5, 1), m, (glint_vec3){r, 0, r});
    m.normal_texture = 0;
    glint_image neutral = lit_quad(flat_texture(0.5, 0.5, 1), m, (glint_vec3){r, 0, r});
    glint_image right = lit_quad(flat_texture(0.8, 0.5, 0.9), m, (glint_vec3){r, 0, r});
    glint_image up = lit_quad(flat_texture(0.5, 0.8, 0.9), m, (glint_vec3){0, r, r});
    glint_image away = lit_quad(flat_texture(0.8, 0.5, 0.9), m, (glint_vec3){-r, 0, r});
    for (int i = 0; i < SIDE * SIDE; i++) {
        assert_near(plain.pixels[3 * i], r, 1e-6);
        assert_near(neutral.pixels[3 * i], r, 1e-6);
        assert_near(right.pixels[3 * i], tilted, 1e-6);
        assert_near(up.pixels[3 * i], tilted, 1e-6);
        assert_near(away.pixels[3 * i], (0.8 - 0.6) * r, 1e-6);
    }
    glint_image_free(&plain);
    glint_image_free(&neutral);
    glint_image_free(&right);
    glint_image_free(&up);
    glint_image_free(&away);
}

/* A bump map of height h(x) = 0.5 - 0.5 cos(2 pi x / 2) (a marble without
 * turbulence, black to white, scale 2) and strength s tilts the normal to
 * unit(-s h'(x), 0, 1): lit head-on, each pixel shows 1 / sqrt(1 + (s
 * h')^2), and a negative strength tilts it the other way alike. */
static void test_bump_slope(void **state)
{
    glint_texture marble = glint_texture_default(GLINT_TEXTURE_MARBLE);
    marble.turbulence = 0;
    marble.scale = 2;
    glint_material m = glint_material_default();
    m.bump_texture = 0;
    const double strengths[] = {0.3, -0.3};
    for (int k = 0; k < 2; k++) {
        m.bump_strength = strengths[k];
        glint_image head_on = lit_quad(marble, m, (glint_vec3){0, 0, 1});
        glint_image side = lit_quad(marble, m, (glint_vec3){sqrt(0.5), 0, sqrt(0.5)});
        for (int i = 0; i < SIDE; i++) {
            double x = (i + 0.5) * 2.0 / SIDE - 1, slope = M_PI / 2 * sin(M_PI * x);
            double sx = -strengths[k] * slope, length = sqrt(1 + sx * sx);
            for (int j = 0; j < SIDE; j += 5) {
                assert_near(head_on.pixels[3 * (j * SIDE + i)], 1 / length, 1e-6);
                assert_near(side.pixels[3 * (j * SIDE + i)], fmax(0, (sx + 1) / length * sqrt(0.5)), 1e-6);
            }
        }
        glint_image_free(&head_on);
        glint_image_free(&side);
    }
}

/* A normal map must give (u, v): a solid texture is refused, in words. */
static void test_normal_map_needs_uv(void **state)
{
    glint_scene *s = glint_scene_new();
    glint_texture noise = glint_texture_default(GLINT_TEXTURE_NOISE);
    glint_error err;
    assert_int_equal(glint_scene_add_texture(s, NULL, &noise, &err), 0);
    glint_material m = glint_material_default();
    m.normal_texture = 0;
    assert_int_equal(glint_scene_add_material(s, NULL, &m, &err), -1);
    assert_string_equal(err.message, "a normal map needs a texture of (u, v), not a solid noise texture");
    m.normal_texture = -1;
    m.bump_texture = 1;
    assert_int_equal(glint_scene_add_material(s, NULL, &m, &err), -1);
    assert_string_equal(err.message, "material bump texture 1 does not exist");
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_normal_map_frame),
        cmocka_unit_test(test_bump_slope),
        cmocka_unit_test(test_normal_map_needs_uv),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
