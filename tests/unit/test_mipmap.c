/* test_mipmap.c - image textures seen from far away: each level of an
 * image's pyramid the mean of the one below, the level a footprint picks,
 * trilinear blending between levels, and a floor of fine stripes that
 * stays an even grey far off under the default filter where the bilinear
 * one alone aliases; under a texel, the plain bilinear look-up. */
#define TMP_TREE_NAME "mipmap"
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>
#include <math.h>
#include "image_test_files.h"
#include "core/vec.h"
#include "image/srgb.h"
#include "shading/texture.h"
#include "render/surface_coords.h"
#include "scene/scene.h"


/* A 5 x 3 image of linear floats halves to 3 x 2, 2 x 1 and 1 x 1, each
 * texel the mean of the 2 x 2 below it, an odd size's edge texel counted
 * twice; an sRGB image's means are of linear values, kept as floats. */
static void test_levels_are_means(void **state)
{
    (void)state;
    float px[5 * 3 * 3 + 1] = {0}; /* and TEXEL_SLACK */
    for (int i = 0; i < 5 * 3 * 3; i++)
        px[i] = (float)(i % 7) + 0.25f * (float)(i % 3);
    texture_image img = {.width = 5, .height = 3, .hdr = px};
    assert_int_equal(texture_image_build_levels(&img, NULL), GLINT_OK);
    assert_int_equal(img.level_count, 4);
    const int sizes[3][2] = {{3, 2}, {2, 1}, {1, 1}};
    const texture_image *below = &img;
    for (int k = 0; k < 3; k++) {
        const texture_image *l = &img.levels[k];
        assert_int_equal(l->width, sizes[k][0]);
        assert_int_equal(l->height, sizes[k][1]);
        for (int y = 0; y < l->height; y++)
            for (int x = 0; x < l->width; x++)
                for (int c = 0; c < 3; c++) {
                    int x1 = 2 * x + 1 < below->width ? 2 * x + 1 : 2 * x;
                    int y1 = 2 * y + 1 < below->height ? 2 * y + 1 : 2 * y;
                    double sum = below->hdr[3 * (2 * y * below->width + 2 * x) + c] +
                                 below->hdr[3 * (2 * y * below->width + x1) + c] +
                                 below->hdr[3 * (y1 * below->width + 2 * x) + c] +
                                 below->hdr[3 * (y1 * below->width + x1) + c];
                    assert_near(l->hdr[3 * (y * l->width + x) + c], sum / 4, 1e-6);
                }
        below = l;
    }
    texture_image_free_levels(&img);
    assert_int_equal(img.level_count, 0);

    /* Black and white: the mean is half the light (sRGB 188, not 128), kept
     * as a linear float, not rounded to a byte. */
    unsigned char bw[2 * 2 * 3] = {0, 0, 0, 255, 255, 255, 255, 255, 255, 0, 0, 0};
    texture_image srgb = texture_image_borrow(2, 2, bw);
    assert_int_equal(texture_image_build_levels(&srgb, NULL), GLINT_OK);
    assert_int_equal(srgb.level_count, 2);
    assert_null(srgb.levels[0].srgb);
    for (int c = 0; c < 3; c++)
        assert_true(srgb.levels[0].hdr[c] == 0.5f);
    assert_int_equal(srgb_byte(srgb.levels[0].hdr[0]), 188);
    texture_image_free(&srgb);

    /* A level of 513 x 513 texels, large enough to be halved in bands of
     * rows on several threads: every texel the mean below it, once. */
    enum { SIDE = 1026 };
    unsigned char *noise = malloc(SIDE * SIDE * 3);
    assert_non_null(noise);
    for (int i = 0; i < SIDE * SIDE * 3; i++)
        noise[i] = (unsigned char)((i * 2654435761u) >> 24);
    texture_image big = texture_image_borrow(SIDE, SIDE, noise);
    assert_int_equal(texture_image_build_levels(&big, NULL), GLINT_OK);
    const texture_image *half = &big.levels[0];
    assert_int_equal(half->width, SIDE / 2);
    for (int y = 0; y < half->height; y++)
        for (int x = 0; x < half->width; x++)
            for (int c = 0; c < 3; c++) {
                float sum = 0;
                for (int k = 0; k < 4; k++)
                    sum += big.linear[noise[3 * ((2 * y + k / 2) * SIDE + 2 * x + k % 2) + c]];
                assert_true(half->hdr[3 * (y * half->width + x) + c] == sum / 4);
            }
    texture_image_free(&big);
    free(noise);
}

/* The level is log2 of the texels a footprint spans along u or v, the
 * larger, within the levels there are: exactly at whole and half levels,
 * within 0.043 between; at level 0 the look-up is the plain bilinear one,
 * and between levels a blend of the two either side. */
static void test_level_and_blend(void **state)
{
    (void)state;
    float px[8 * 4 * 3 + 1] = {0}; /* and TEXEL_SLACK */
    for (int i = 0; i < 8 * 4 * 3; i++)
        px[i] = (float)((i * 37) % 11);
    texture_image img = {.width = 8, .height = 4, .hdr = px};
    assert_int_equal(texture_image_build_levels(&img, NULL), GLINT_OK);
    assert_int_equal(img.level_count, 4);
    /* Extents squared: 0.5 across is 4 texels, 1 down is 4 texels. */
    assert_near(image_level(&img, (uv_extent){0.25, 0}), 2, 1e-12);  /* 4 texels across */
    assert_near(image_level(&img, (uv_extent){0, 1}), 2, 1e-12);     /* 4 texels down */
    assert_near(image_level(&img, (uv_extent){0.125, 0}), 1.5, 1e-12); /* 2 sqrt 2 across */
    assert_near(image_level(&img, (uv_extent){12.0 / 64, 0}), 1.75, 1e-12); /* sqrt 12 across */
    assert_near(image_level(&img, (uv_extent){12.0 / 64, 0}), log2(sqrt(12)), 0.043);
    assert_near(image_level(&img, (uv_extent){0.01, 0}), 0, 0);      /* under a texel */
    assert_near(image_level(&img, (uv_extent){1e4, 1e4}), 3, 0);     /* past the last level */
    for (double u = -0.3; u < 1.3; u += 0.071)
        for (double v = 0.02; v < 1; v += 0.13) {
            color a = image_eval(&img, u, v, GLINT_WRAP_REPEAT, GLINT_WRAP_CLAMP);
            color b = image_eval_level(&img, u, v, GLINT_WRAP_REPEAT, GLINT_WRAP_CLAMP, 0);
            assert_memory_equal(&a, &b, sizeof a);
            color l1 = image_eval(&img.levels[0], u, v, GLINT_WRAP_REPEAT, GLINT_WRAP_CLAMP);
            color l2 = image_eval(&img.levels[1], u, v, GLINT_WRAP_REPEAT, GLINT_WRAP_CLAMP);
            color mid = image_eval_level(&img, u, v, GLINT_WRAP_REPEAT, GLINT_WRAP_CLAMP, 1.25);
            assert_near(mid.r, 0.75 * l1.r + 0.25 * l2.r, 1e-9);
            assert_near(mid.b, 0.75 * l1.b + 0.25 * l2.b, 1e-9);
        }
    texture_image_free_levels(&img);
}

/* Four lanes at a time (image_level4, image_eval_level4), the levels and
 * colours are those of one lane at a time, bit for bit: sRGB and linear
 * images, every wrap, points in and far out of [0, 1], between and past
 * the levels, at every lane count, and at points that are not finite. */
static void test_four_lanes_as_one(void **state)
{
    (void)state;
    float hdr[13 * 7 * 3 + 1] = {0}; /* and TEXEL_SLACK */
    unsigned char bytes[13 * 7 * 3];
    float linear[256];
    for (int i = 0; i < 256; i++)
        linear[i] = (float)(i * i) / 65025.0f;
    for (int i = 0; i < 13 * 7 * 3; i++) {
        hdr[i] = (float)((i * 29) % 17) * 0.125f;
        bytes[i] = (unsigned char)((i * 53) % 256);
    }
    texture_image images[2] = {{.width = 13, .height = 7, .hdr = hdr},
                               {.width = 13, .height = 7, .srgb = bytes, .linear = linear}};
    const glint_wrap wraps[3] = {GLINT_WRAP_REPEAT, GLINT_WRAP_CLAMP, GLINT_WRAP_MIRROR};
    for (int im = 0; im < 2; im++) {
        texture_image *img = &images[im];
        assert_int_equal(texture_image_build_levels(img, NULL), GLINT_OK);
        int compared = 0;
        for (int w = 0; w < 9; w++)
            for (int j = 0; j < 240; j += 4) {
                quad_f64 u, v, u2, v2;
                for (int k = 0; k < QUAD; k++) {
                    double x = (j + k) * 0.0371;
                    u[k] = 3.7 * sin(x * 1.3) - 0.4;
                    v[k] = 2.9 * cos(x * 0.7) + 0.3;
                    u2[k] = pow(10, fmod(x * 5.3, 7) - 5);
                    v2[k] = pow(10, fmod(x * 3.1, 7) - 5);
                }
                if (j == 100)
                    u[2] = NAN;
                if (j == 104)
                    v[0] = INFINITY;
                quad_f64 level = image_level4(img, u2, v2);
                for (int lanes = 1; lanes <= QUAD; lanes++) {
                    quad_f64 four[3];
                    image_eval_level4(img, u, v, wraps[w % 3], wraps[w / 3], level, lanes, four);
                    for (int k = 0; k < lanes; k++) {
                        double one_level = image_level(img, (uv_extent){u2[k], v2[k]});
                        assert_memory_equal(&one_level, &level[k], sizeof one_level);
                        color one = image_eval_level(img, u[k], v[k], wraps[w % 3], wraps[w / 3], one_level);
                        color lane = rgb(four[0][k], four[1][k], four[2][k]);
                        assert_memory_equal(&one, &lane, sizeof one);
                        compared += one_level > 0 && one_level != floor(one_level);
                    }
                }
            }
        assert_true(compared > 1000); /* blends between levels were compared */
        texture_image_free_levels(img);
    }
}

/* The image texture file of 64 x 64 texels in one-texel black and white
 * columns. */
static void write_stripes(const char *path)
{
    float px[64 * 64 * 3];
    for (int i = 0; i < 64 * 64; i++)
        px[3 * i] = px[3 * i + 1] = px[3 * i + 2] = (float)(i % 2);
    glint_image im = {.width = 64, .height = 64, .pixels = px};
    assert_int_equal(glint_image_write(&im, path, NULL), GLINT_OK);
}

/* A floor of the stripes, 0.25 units a tile, seen from just above it by
 * one sample a pixel, lit so that it shows its texture's values. */
static glint_image floor_of_stripes(const char *file, glint_image_filter filter)
{
    glint_scene *s = glint_scene_new();
    glint_settings st = glint_settings_default();
    st.width = 160;
    st.height = 80;
    st.samples_per_pixel = 1;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_camera cam = {.kind = GLINT_CAMERA_PINHOLE, .position = {0, 0.5, 0}, .look_at = {0, 0.3, -4},
                        .up = {0, 1, 0}, .vfov_degrees = 40};
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    glint_texture t = glint_texture_default(GLINT_TEXTURE_IMAGE);
    t.file = file;
    t.filter = filter;
    t.wrap_v = GLINT_WRAP_REPEAT;
    t.mapping.kind = GLINT_MAP_PLANAR;
    t.mapping.scale = 0.25;
    glint_error err;
    int tex = glint_scene_add_texture(s, NULL, &t, &err);
    assert_true(tex >= 0);
    glint_material m = glint_material_default();
    m.texture = tex;
    m.ambient = 1;
    m.diffuse = m.specular = 0;
    glint_shape plane = glint_shape_default(GLINT_SHAPE_PLANE);
    plane.normal = (glint_vec3){0, 1, 0};
    assert_true(glint_scene_add_shape(s, &plane, glint_scene_add_material(s, NULL, &m, NULL), NULL, &err) >= 0);
    glint_image im;
    glint_render_options o = {.threads = 2};
    assert_int_equal(glint_render(s, &o, &im, NULL, &err), GLINT_OK);
    glint_scene_free(s);
    return im;
}

/* Far off (the rows just below the horizon, a dozen tiles away and more,
 * where a pixel spans tens of texels) the trilinear floor is the stripes'
 * mean, within 0.06 of 0.5, in every pixel; the bilinear one reads single
 * texels and swings far from it. */
static void test_far_floor_does_not_shimmer(void **state)
{
    (void)state;
    char file[PATH_SIZE];
    tmp_path(file, "stripes.png");
    write_stripes(file);
    glint_image tri = floor_of_stripes(file, GLINT_IMAGE_TRILINEAR);
    glint_image bi = floor_of_stripes(file, GLINT_IMAGE_BILINEAR);
    double worst_tri = 0, worst_bi = 0;
    int far_pixels = 0;
    for (int y = 0; y < tri.height; y++)
        for (int x = 0; x < tri.width; x++) {
            size_t i = 3 * ((size_t)y * tri.width + x);
            /* Where the floor is: below the horizon. Each row's distance:
             * the ray's drop over its length. */
            double drop = (y + 0.5 - tri.height / 2.0) / (tri.height / 2.0) * tan(20 * M_PI / 180);
            double slope = (0.2 / 4 + drop) / (1 - 0.2 / 4 * drop), distance = 0.5 / slope;
            if (!(slope > 0))
                continue;
            if (distance > 3 && distance < 40) {
                worst_tri = fmax(worst_tri, fabs(tri.pixels[i] - 0.5));
                worst_bi = fmax(worst_bi, fabs(bi.pixels[i] - 0.5));
                far_pixels++;
            }
        }
    assert_true(far_pixels > 500);
    assert_true(worst_tri < 0.06);
    assert_true(worst_bi > 0.3);
    glint_image_free(&tri);
    glint_image_free(&bi);
}

/* Ray r's hit on scene s's shape 0, described into *at_hit, and *spot
 * (which points at *at_hit). */
static void hit_shape0(glint_scene *s, ray r, accel_hit *h, surface *at_hit, coord_spot *spot)
{
    *h = (accel_hit){.shape = 0, .instance = -1};
    assert_true(shape_intersect(&s->shapes[0], &r, 0, INFINITY, &h->on_shape));
    h->t = h->on_shape.t;
    shape_surface(&s->shapes[0], &r, &h->on_shape, at_hit);
    coord_spot_init(s, h, at_hit, spot);
}

/* The footprint of a sample `width` across, seen along d, at a hit
 * (hit_shape0's) under texture t, measured by central steps of the
 * mapping itself along the ellipse's axes in the tangent plane: across the
 * ray's slant, width long; along it, width over the cosine. */
static uv_extent stepped_footprint(const coord_spot *spot, const texture *t, const surface *at_hit, vec3 d,
                                   double width)
{
    vec3 n = at_hit->n, along = v3_normalize(v3_madd(d, n, -v3_dot(d, n))), across = v3_cross(n, along);
    vec3 axes[2] = {across, along};
    double e = 1e-6, reach[2] = {width, width / fabs(v3_dot(d, n))};
    uv_extent sum = {0, 0};
    for (int k = 0; k < 2; k++) {
        double u0, v0, u1, v1;
        coord_at(spot, t, v3_madd(at_hit->p, axes[k], -e), &u0, &v0);
        coord_at(spot, t, v3_madd(at_hit->p, axes[k], e), &u1, &v1);
        double su = (u1 - u0) / (2 * e) * reach[k], sv = (v1 - v0) / (2 * e) * reach[k];
        sum.u2 += su * su;
        sum.v2 += sv * sv;
    }
    return sum;
}

/* The footprint coord_footprint gives a sample 0.01 across along ray r at
 * its hit on scene s's shape 0 under texture t, checked against
 * stepped_footprint's within `tolerance` (relative). */
static uv_extent checked_footprint(glint_scene *s, const texture *t, ray r, double tolerance)
{
    accel_hit h;
    surface at_hit;
    coord_spot spot;
    hit_shape0(s, r, &h, &at_hit, &spot);
    double u, v;
    coord_at(&spot, t, at_hit.p, &u, &v);
    uv_extent got = coord_footprint(&spot, t, at_hit.n, r.d, 0.01, u, v);
    uv_extent want = stepped_footprint(&spot, t, &at_hit, r.d, 0.01);
    assert_true(fabs(got.u2 - want.u2) < tolerance * want.u2);
    assert_true(fabs(got.v2 - want.v2) < tolerance * want.v2);
    return got;
}

/* A planar mapping's footprint comes from its gradients, carried through
 * the plane's own transform (stretched twice along x) and the texture's
 * (0.25-unit tiles, turned 30 degrees): each axis of the footprint
 * ellipse changes u and v as much as stepping the mapping itself along it
 * says, within 2e-6. */
static void test_planar_footprint_from_gradients(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_texture desc = glint_texture_default(GLINT_TEXTURE_CHECKER);
    desc.mapping.kind = GLINT_MAP_PLANAR;
    desc.mapping.scale = 0.25;
    desc.transform = glint_transform_rotate(glint_transform_identity(), (glint_vec3){0, 0, 1}, 30);
    glint_error err;
    int tex = glint_scene_add_texture(s, NULL, &desc, &err);
    assert_true(tex >= 0);
    glint_material m = glint_material_default();
    glint_shape plane = glint_shape_default(GLINT_SHAPE_PLANE);
    plane.normal = (glint_vec3){0, 1, 0};
    glint_transform wide = glint_transform_scale(glint_transform_identity(), 2, 1, 1);
    assert_true(glint_scene_add_shape(s, &plane, glint_scene_add_material(s, NULL, &m, NULL), &wide, &err) >= 0);
    const texture *t = &s->textures[tex];
    uv_extent got = checked_footprint(s, t, (ray){v3(0.7, 2, 1.1), v3_normalize(v3(0.3, -0.5, -0.8))}, 2e-6);
    /* Not a trivial answer: the turn and the stretch mix both axes in. */
    assert_true(got.u2 > 0.03 * 0.03 && got.v2 > 0.07 * 0.07 && got.v2 > 4 * got.u2);
    glint_scene_free(s);
}

/* The footprint a spherical mapping's gradients give, at a hit on a ball
 * at (0.3, -0.2, 0.1) of radius 0.9 stretched to (1.5, 1, 0.8) and turned
 * 20 degrees, under a texture turned 30 degrees and doubled along u: each
 * axis of the footprint ellipse changes u and v as much as steps of the
 * mapping itself along it say, within 1e-5; at the ball's pole,
 * where u turns without bound, the last level (the image's mean), never
 * NaN. */
static void test_spherical_footprint_from_gradients(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_texture desc = glint_texture_default(GLINT_TEXTURE_CHECKER);
    desc.mapping.kind = GLINT_MAP_SPHERICAL;
    desc.transform = glint_transform_scale(glint_transform_rotate(glint_transform_identity(), (glint_vec3){0, 0, 1}, 30),
                                           2, 1, 1);
    glint_error err;
    int tex = glint_scene_add_texture(s, NULL, &desc, &err);
    assert_true(tex >= 0);
    glint_material m = glint_material_default();
    glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {0.3, -0.2, 0.1}, .radius = 0.9};
    glint_transform place = glint_transform_rotate(glint_transform_scale(glint_transform_identity(), 1.5, 1, 0.8),
                                                   (glint_vec3){0, 1, 0}, 20);
    assert_true(glint_scene_add_shape(s, &ball, glint_scene_add_material(s, NULL, &m, NULL), &place, &err) >= 0);
    const texture *t = &s->textures[tex];
    const vec3 eyes[] = {{3, 1.2, 4}, {-2, -1.5, 3}, {0.5, 0.4, -4}};
    for (size_t i = 0; i < sizeof eyes / sizeof eyes[0]; i++) {
        uv_extent got = checked_footprint(s, t, (ray){eyes[i], v3_normalize(v3_sub(v3(0.2, -0.1, 0.15), eyes[i]))}, 1e-5);
        assert_true(got.u2 > 1e-6 && got.v2 > 1e-6);
    }
    /* Straight down onto the pole, in the ball's own frame its top. */
    vec3 top = xf_point(&s->shapes[0].to_world, v3(0.3, 0.7, 0.1));
    accel_hit h;
    surface pole;
    coord_spot spot;
    hit_shape0(s, (ray){v3_add(top, v3(0, 2, 0)), v3(0, -1, 0)}, &h, &pole, &spot);
    uv_extent at_pole = coord_footprint(&spot, t, pole.n, v3(0, -1, 0), 0.01, 0.5, 0);
    texture_image img = {.width = 1024, .height = 512, .level_count = 11};
    assert_true(image_level(&img, at_pole) == 10);
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_levels_are_means),
        cmocka_unit_test(test_level_and_blend),
        cmocka_unit_test(test_four_lanes_as_one),
        cmocka_unit_test(test_far_floor_does_not_shimmer),
        cmocka_unit_test(test_planar_footprint_from_gradients),
        cmocka_unit_test(test_spherical_footprint_from_gradients),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
