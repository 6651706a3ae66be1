/* test_sampling.c - anti-aliasing: the scrambled Sobol points' strata, the
 * reconstruction filters (each integrates to 1, its samples fall as it
 * does, and an edge seen through it has the filter's integral as its
 * profile), adaptive sampling spending samples only where a pixel's
 * samples differ, and identical bytes for any thread count and tile size
 * with every one of them on. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdbool.h>
#include <string.h>
#include "glint.h"
#include "core/sobol.h"
#include "core/square_maps.h"
#include "render/filter.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

/* Every aligned run of 2^m of the first 256 points, for m up to 8, puts
 * one point in each box 2^-a x 2^-(m-a) of the square, for any seed. */
static void test_sobol_points_fill_every_stratum(void **state)
{
    (void)state;
    for (uint32_t seed = 0; seed < 64; seed++) {
        double x[256], y[256];
        for (uint32_t i = 0; i < 256; i++)
            sobol2_scrambled(i, seed * 0x9e3779b9U, &x[i], &y[i]);
        for (int m = 0; m <= 8; m++) {
            int run = 1 << m;
            for (int start = 0; start < 256; start += run) {
                for (int a = 0; a <= m; a++) {
                    int across = 1 << a, down = 1 << (m - a), seen[256] = {0};
                    for (int i = start; i < start + run; i++)
                        seen[(int)(x[i] * across) * down + (int)(y[i] * down)]++;
                    for (int box = 0; box < run; box++)
                        assert_int_equal(seen[box], 1);
                }
            }
        }
    }
}

/* Eight sequences at once give each lane the very point the sequence
 * gives alone, for indices from 0 to past 2^20 and seeds across the word. */
static void test_sobol_eight_lanes_are_eight_sequences(void **state)
{
    (void)state;
    for (uint32_t round = 0; round < 64; round++) {
        sobol2_seeds one[8];
        sobol2_seeds8 lanes;
        for (int k = 0; k < 8; k++) {
            one[k] = sobol2_seeds_of(hash_u32(round * 8 + (uint32_t)k));
            sobol2_seeds8_set(&lanes, k, one[k]);
        }
        for (uint32_t i = 0; i < 1200000; i += 1 + i / 7 + round) {
            double x[8], y[8];
            sobol2_points8(i, &lanes, x, y);
            for (int k = 0; k < 8; k++) {
                double ex, ey;
                sobol2_point(i, one[k], &ex, &ey);
                assert_true(x[k] == ex && y[k] == ey);
            }
        }
    }
}

/* Whether the aligned runs of 2^m of the n points p (s coordinates each)
 * are (t, m, s)-nets: every box of 2^-k[0] x ... x 2^-k[s-1] with
 * k[0] + ... = m - t holds exactly 2^t of a run's points. */
static bool runs_are_nets(const double (*p)[4], int n, int s, int m, int t)
{
    int k[4] = {0}, split = m - t;
    for (;;) {
        int total = 0;
        for (int d = 0; d < s; d++)
            total += k[d];
        if (total == split) {
            for (int start = 0; start < n; start += 1 << m) {
                int seen[256] = {0};
                for (int i = start; i < start + (1 << m); i++) {
                    int box = 0;
                    for (int d = 0; d < s; d++)
                        box = (box << k[d]) | (int)(p[i][d] * (1 << k[d]));
                    seen[box]++;
                }
                for (int box = 0; box < 1 << split; box++)
                    if (seen[box] != 1 << t)
                        return false;
            }
        }
        int d = 0;
        while (d < s && ++k[d] > split)
            k[d++] = 0;
        if (d == s)
            return true;
    }
}

/* The tabled columns of Sobol's third and fourth dimensions are those of
 * the primitive polynomials x^2 + x + 1 and x^3 + x + 1 with initial
 * direction numbers 1, 3 and 1, 3, 1 (Joe and Kuo), built by the
 * polynomials' recurrences: every index's coordinates, bit-reversed, are
 * the XOR of the columns of its bits. */
static void test_sobol_third_fourth_are_the_recurrence(void **state)
{
    (void)state;
    uint32_t v3[32], v4[32];
    for (int q = 0; q < 32; q++) {
        v3[q] = q == 0 ? 1U << 31 : q == 1 ? 3U << 30 : v3[q - 1] ^ v3[q - 2] ^ (v3[q - 2] >> 2);
        v4[q] = q == 0 ? 1U << 31 : q == 1 ? 3U << 30 : q == 2 ? 1U << 29 : v4[q - 2] ^ v4[q - 3] ^ (v4[q - 3] >> 3);
    }
    for (uint32_t round = 0; round < 100000; round++) {
        uint32_t i = round < 4096 ? round : hash_u32(round), c3 = 0, c4 = 0, third, fourth;
        for (int q = 0; q < 32; q++)
            if (i >> q & 1) {
                c3 ^= v3[q];
                c4 ^= v4[q];
            }
        sobol_third_fourth_reversed(i, &third, &fourth);
        assert_int_equal(third, reverse_bits32(c3));
        assert_int_equal(fourth, reverse_bits32(c4));
    }
    /* The first points of the third dimension, as fractions: 0, 1/2, 3/4, 1/4, 3/8. */
    static const uint32_t first[5] = {0, 0x80000000U, 0xc0000000U, 0x40000000U, 0x60000000U};
    for (uint32_t i = 0; i < 5; i++) {
        uint32_t third, fourth;
        sobol_third_fourth_reversed(i, &third, &fourth);
        assert_int_equal(reverse_bits32(third), first[i]);
    }
}

/* The Sobol sampler's four dimensions (image x and y, lens u and v) for
 * eight pixels' scrambles: in every lane the image pair's runs of 2^m are
 * (0, m, 2)-nets, and the four together (t, m, 4)-nets with the t of
 * Sobol's first four dimensions (worked out from the same direction
 * numbers by another program: 0, 1, 2, 2, 2, 2, 2, 3 for m = 1 to 8), which
 * Owen's scrambling keeps. */
static void test_sobol_four_dimensions_are_nets(void **state)
{
    (void)state;
    static const int t4[9] = {0, 0, 1, 2, 2, 2, 2, 2, 3};
    for (uint32_t round = 0; round < 8; round++) {
        sobol_lanes scramble[4];
        for (int d = 0; d < 4; d++)
            for (int lane = 0; lane < 8; lane++)
                scramble[d][lane] = hash_u32(round * 32 + (uint32_t)(d * 8 + lane));
        static double p[8][256][4];
        for (uint32_t i = 0; i < 256; i++) {
            double c[4][8];
            uint32_t third, fourth;
            sobol_third_fourth_reversed(i, &third, &fourth);
            sobol_scrambled8(sobol_same(i), scramble[0], c[0]);
            sobol_scrambled8(sobol_same(sobol_second_reversed(i)), scramble[1], c[1]);
            sobol_scrambled8(sobol_same(third), scramble[2], c[2]);
            sobol_scrambled8(sobol_same(fourth), scramble[3], c[3]);
            for (int lane = 0; lane < 8; lane++)
                for (int d = 0; d < 4; d++)
                    p[lane][i][d] = c[d][lane];
        }
        for (int lane = 0; lane < 8; lane++)
            for (int m = 1; m <= 8; m++) {
                assert_true(runs_are_nets((const double(*)[4])p[lane], 256, 2, m, 0));
                assert_true(runs_are_nets((const double(*)[4])p[lane], 256, 4, m, t4[m]));
                if (t4[m] > 0) /* and not better: the t is the sequence's own */
                    assert_false(runs_are_nets((const double(*)[4])p[lane], 256, 4, m, t4[m] - 1));
            }
    }
}

static const glint_filter FILTERS[] = {GLINT_FILTER_BOX, GLINT_FILTER_TENT, GLINT_FILTER_GAUSSIAN,
                                       GLINT_FILTER_MITCHELL, GLINT_FILTER_LANCZOS};

/* The concentric map's sine and cosine, a series without libm, agree with
 * libm's to within 2 units in the last place over its whole range, and the
 * map is Shirley and Chiu's: each point of a fine grid lands where the
 * map's formula with libm's sin and cos puts it, inside the unit disk. */
static void test_concentric_disk_is_the_formula(void **state)
{
    (void)state;
    for (int k = -1000; k <= 1000; k++) {
        double t = M_PI / 4 * k / 1000, s, c;
        sincos_quarter(t, &s, &c);
        assert_near(s, sin(t), 4.5e-16);
        assert_near(c, cos(t), 4.5e-16);
    }
    for (int i = 0; i <= 64; i++)
        for (int j = 0; j <= 64; j++) {
            double u = i / 64.0, v = j / 64.0, x, y, a = 2 * u - 1, b = 2 * v - 1, wx = 0, wy = 0;
            if (fabs(a) > fabs(b)) {
                wx = a * cos(M_PI / 4 * b / a);
                wy = a * sin(M_PI / 4 * b / a);
            } else if (b != 0) {
                wx = b * cos(M_PI / 2 - M_PI / 4 * a / b);
                wy = b * sin(M_PI / 2 - M_PI / 4 * a / b);
            }
            concentric_disk(u, v, &x, &y);
            assert_near(x, wx, 1e-15);
            assert_near(y, wy, 1e-15);
            assert_true(x * x + y * y <= 1 + 1e-15);
        }
}

/* The integral of the filter's profile from -radius to x, by the midpoint rule. */
static double integral_to(const pixel_filter *f, double x)
{
    const int steps = 200000;
    double from = -f->radius, step = (x - from) / steps, sum = 0;
    for (int i = 0; i < steps; i++)
        sum += pixel_filter_value(f, from + (i + 0.5) * step) * step;
    return sum;
}

static void test_filters_integrate_to_one(void **state)
{
    (void)state;
    for (size_t t = 0; t < sizeof FILTERS / sizeof FILTERS[0]; t++) {
        for (int r = 0; r < 3; r++) {
            pixel_filter f;
            pixel_filter_init(&f, FILTERS[t], (double[]){0, 1.25, 4}[r]);
            assert_near(integral_to(&f, f.radius), 1, 1e-4);
            assert_near(pixel_filter_value(&f, f.radius), 0, 0);
        }
    }
    /* The defaults, and the lobes that go below zero. */
    pixel_filter f;
    pixel_filter_init(&f, GLINT_FILTER_MITCHELL, 0);
    assert_near(f.radius, 2, 0);
    assert_true(pixel_filter_value(&f, 1.5) < 0);
    pixel_filter_init(&f, GLINT_FILTER_LANCZOS, 0);
    assert_near(f.radius, 3, 0);
    assert_true(pixel_filter_value(&f, 1.5) < 0 && pixel_filter_value(&f, 2.5) > 0);
}

/* A filter's offsets, for evenly spread numbers, counted with their signs,
 * fall as the filter does: their signed share below x times the whole of
 * |f| is f's integral up to x. */
static void test_filter_offsets_fall_as_the_filter(void **state)
{
    (void)state;
    enum { N = 100000 };
    for (size_t t = 0; t < sizeof FILTERS / sizeof FILTERS[0]; t++) {
        pixel_filter f;
        pixel_filter_init(&f, FILTERS[t], 0);
        double magnitude = 0, step = 2 * f.radius / 200000;
        for (int i = 0; i < 200000; i++)
            magnitude += fabs(pixel_filter_value(&f, -f.radius + (i + 0.5) * step)) * step;
        for (double x = -f.radius; x <= f.radius; x += f.radius / 4) {
            long below = 0;
            double previous = -INFINITY;
            for (int k = 0; k < N; k++) {
                bool negative;
                double offset = pixel_filter_offset(&f, (k + 0.5) / N, &negative);
                assert_true(offset >= previous && fabs(offset) <= f.radius);
                previous = offset;
                below += offset < x ? (negative ? -1 : 1) : 0;
            }
            assert_near(magnitude * below / N, integral_to(&f, x), 2e-3);
        }
    }
}

/* A 32 x 4 image, one unit a pixel, of a grey background and a lighter
 * wall on the right of x = EDGE pixels, through the given filter with 1024
 * Sobol samples a pixel. */
#define EDGE 16.3
static glint_image edge_image(glint_filter filter, double radius, int samples, int adaptive_max,
                              glint_render_stats *stats)
{
    glint_scene *s = glint_scene_new();
    assert_non_null(s);
    glint_settings st = glint_settings_default();
    st.width = 32;
    st.height = 4;
    st.samples_per_pixel = samples;
    st.sampler = GLINT_SAMPLER_SOBOL;
    st.filter = filter;
    st.filter_radius = radius;
    st.background = (glint_color){0.25, 0.25, 0.25};
    st.adaptive_max_samples = adaptive_max;
    st.adaptive_threshold = 0.05;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_camera cam = {.position = {0, 0, 10}, .look_at = {0, 0, 0}, .up = {0, 1, 0}, .vfov_degrees = 45,
                        .kind = GLINT_CAMERA_ORTHOGRAPHIC, .view_width = 32};
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    glint_material m = glint_material_default();
    m.color = (glint_color){0.75, 0.75, 0.75};
    m.ambient = 1;
    m.diffuse = m.specular = 0;
    int wall = glint_scene_add_material(s, NULL, &m, NULL);
    double x = EDGE - 16;
    glint_shape quad = {.kind = GLINT_SHAPE_POLYGON,
                        .point_count = 4,
                        .points = {{x, -50, 0}, {x + 100, -50, 0}, {x + 100, 50, 0}, {x, 50, 0}}};
    assert_true(glint_scene_add_shape(s, &quad, wall, NULL, NULL) >= 0);
    glint_image img;
    glint_render_options o = {.threads = 2};
    glint_error err;
    if (glint_render(s, &o, &img, stats, &err))
        fail_msg("render failed: %s", err.message);
    glint_scene_free(s);
    return img;
}

/* Across a sharp edge each pixel is the filter's integral over the wall's
 * side: 0.25 + 0.5 x the share of the filter about the pixel's centre
 * that lies right of the edge, overshoot and ringing included. */
static void test_edge_profile_is_the_filters_integral(void **state)
{
    (void)state;
    for (size_t t = 0; t < sizeof FILTERS / sizeof FILTERS[0]; t++) {
        glint_image img = edge_image(FILTERS[t], 0, 1024, 0, NULL);
        pixel_filter f;
        pixel_filter_init(&f, FILTERS[t], 0);
        for (int x = 8; x < 24; x++) {
            double centre = x + 0.5, right = 1 - integral_to(&f, fmin(fmax(EDGE - centre, -f.radius), f.radius));
            for (int y = 0; y < 4; y++)
                assert_near(img.pixels[3 * (y * 32 + x)], 0.25 + 0.5 * right, 0.006);
        }
        glint_image_free(&img);
    }
    /* Mitchell's overshoot is really there: a pixel past the edge is lighter than the wall. */
    glint_image img = edge_image(GLINT_FILTER_MITCHELL, 0, 1024, 0, NULL);
    assert_true(img.pixels[3 * 17] > 0.755);
    glint_image_free(&img);
}

/* Adaptive sampling: only the pixels the edge crosses (column 16, with
 * the box of radius 0.5) see samples that differ, and the blocks of 4 x 2
 * pixels holding them, columns 16 to 19 of all four rows, take the most
 * allowed; the others keep the first 4. The wall's pixels in those blocks
 * stay exactly the wall's colour. */
static void test_adaptive_sampling_spends_samples_on_the_edge(void **state)
{
    (void)state;
    glint_render_stats stats;
    glint_image img = edge_image(GLINT_FILTER_BOX, 0, 4, 40, &stats);
    assert_int_equal(stats.samples, 32 * 4 * 4 + 4 * 4 * (40 - 4));
    for (int y = 0; y < 4; y++) {
        /* With its 40 samples the edge pixel is within a sample's worth of the wall's share, 0.7. */
        assert_near(img.pixels[3 * (y * 32 + 16)], 0.25 + 0.5 * 0.7, 0.5 / 40 + 1e-6);
        for (int x = 17; x < 20; x++)
            assert_true(img.pixels[3 * (y * 32 + x)] == 0.75f);
        assert_true(img.pixels[3 * (y * 32 + 15)] == 0.25f);
    }
    glint_image_free(&img);
}

/* Every new sampling feature at once, with a thin lens: the same bytes for
 * 1, 2 and 7 threads and another tile size; and not the image without them. */
static void test_identical_bytes_with_every_sampling_feature(void **state)
{
    (void)state;
    glint_error err;
    glint_scene *s = glint_scene_seed_room(&err);
    assert_non_null(s);
    glint_settings st = glint_scene_get_settings(s);
    st.width = 72;
    st.height = 56;
    glint_image images[5];
    glint_render_stats stats[5];
    size_t bytes = (size_t)st.width * st.height * 3 * sizeof(float);
    for (int f = GLINT_FILTER_TENT; f <= GLINT_FILTER_LANCZOS; f++) {
        st.samples_per_pixel = 3;
        st.sampler = GLINT_SAMPLER_SOBOL;
        st.filter = (glint_filter)f;
        st.adaptive_max_samples = 12;
        st.adaptive_threshold = 0.1;
        assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
        glint_camera cam = glint_scene_get_camera(s);
        cam.kind = GLINT_CAMERA_THIN_LENS;
        cam.aperture = 0.5;
        assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
        glint_render_options o[] = {{.threads = 1}, {.threads = 2}, {.threads = 7}, {.threads = 3, .tile_size = 7}};
        for (int i = 0; i < 4; i++) {
            assert_int_equal(glint_render(s, &o[i], &images[i], &stats[i], NULL), GLINT_OK);
            if (i > 0) {
                assert_memory_equal(images[0].pixels, images[i].pixels, bytes);
                assert_int_equal(stats[0].samples, stats[i].samples);
            }
        }
        /* Some pixels, not all, took more samples. */
        uint64_t pixels = (uint64_t)st.width * st.height;
        assert_true(stats[0].samples > 3 * pixels && stats[0].samples < 12 * pixels);
        st.adaptive_max_samples = 0;
        assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
        assert_int_equal(glint_render(s, &o[1], &images[4], &stats[4], NULL), GLINT_OK);
        assert_int_equal(stats[4].samples, 3 * pixels);
        assert_memory_not_equal(images[0].pixels, images[4].pixels, bytes);
        for (int i = 0; i < 5; i++)
            glint_image_free(&images[i]);
    }
    glint_scene_free(s);
}

/* The rules between the sampling settings, with the words a user sees. */
static void test_sampling_settings_are_checked(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_settings st = glint_settings_default();
    glint_error err;
    st.samples_per_pixel = 8;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "samples 8 is not a square number: the regular sampler lays an N x N grid "
                                     "(1, 4, 9, 16, ...); sampler sobol takes any count");
    st.sampler = GLINT_SAMPLER_SOBOL;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_OK);
    st.adaptive_max_samples = 4;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "adaptive max_samples 4 is fewer than samples 8");
    st.sampler = GLINT_SAMPLER_JITTERED;
    st.samples_per_pixel = 4;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "adaptive sampling needs sampler sobol, whose points stay well spread as a "
                                     "pixel takes more; this scene's is jittered");
    st.adaptive_max_samples = 0;
    st.filter_radius = 17;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "filter radius must be from 0 to 16 pixels, got 17");
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sobol_points_fill_every_stratum),
        cmocka_unit_test(test_sobol_eight_lanes_are_eight_sequences),
        cmocka_unit_test(test_sobol_third_fourth_are_the_recurrence),
        cmocka_unit_test(test_sobol_four_dimensions_are_nets),
        cmocka_unit_test(test_concentric_disk_is_the_formula),
        cmocka_unit_test(test_filters_integrate_to_one),
        cmocka_unit_test(test_filter_offsets_fall_as_the_filter),
        cmocka_unit_test(test_edge_profile_is_the_filters_integral),
        cmocka_unit_test(test_adaptive_sampling_spends_samples_on_the_edge),
        cmocka_unit_test(test_identical_bytes_with_every_sampling_feature),
        cmocka_unit_test(test_sampling_settings_are_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
