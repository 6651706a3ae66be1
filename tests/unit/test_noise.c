/* test_noise.c - gradient noise and the solid textures built on it
 * (noise, marble, wood, granite): the noise's defining properties, its
 * values on every machine, and each pattern's colour where its formula
 * gives it exactly. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include "core/hash.h"
#include "shading/environment.h"
#include "shading/noise.h"
#include "shading/texture.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

/* A point of the cube [-50, 50)^3 from a hash of i. */
static vec3 scattered(uint32_t i)
{
    return v3(100 * hash_unit(hash4(i, 1, 0, 0)) - 50, 100 * hash_unit(hash4(i, 2, 0, 0)) - 50,
              100 * hash_unit(hash4(i, 3, 0, 0)) - 50);
}

/* Four points as the lanes of x, y and z quads. */
static void quad_points(const vec3 p[QUAD], quad_f64 q[3])
{
    for (int l = 0; l < QUAD; l++) {
        q[0][l] = p[l].x;
        q[1][l] = p[l].y;
        q[2][l] = p[l].z;
    }
}

/* fBm and turbulence at one point (every lane alike). */
static double fbm_at(vec3 p, noise_octaves o)
{
    vec3 four[QUAD] = {p, p, p, p};
    quad_f64 q[3];
    quad_points(four, q);
    return noise_fbm4(q, o)[0];
}

static double turbulence_at(vec3 p, noise_octaves o)
{
    vec3 four[QUAD] = {p, p, p, p};
    quad_f64 q[3];
    quad_points(four, q);
    return noise_turbulence4(q, o)[0];
}

/* Gradient noise is 0 at every lattice point, and its slope there is the
 * corner's gradient: one of the twelve (+-1, +-1, 0) directions, so two
 * components of 1 in size and one of 0. */
static void test_noise_lattice(void **state)
{
    const double h = 1e-6;
    for (int x = -3; x <= 3; x++)
        for (int y = -3; y <= 3; y++)
            for (int z = -3; z <= 3; z++) {
                vec3 p = v3(x, y, z);
                assert_true(noise_at(p, 0) == 0);
                double slope[3] = {noise_at(v3(x + h, y, z), 0) / h, noise_at(v3(x, y + h, z), 0) / h,
                                   noise_at(v3(x, y, z + h), 0) / h};
                int ones = 0, zeros = 0;
                for (int k = 0; k < 3; k++) {
                    ones += fabs(fabs(slope[k]) - 1) < 1e-5;
                    zeros += fabs(slope[k]) < 1e-5;
                }
                assert_int_equal(ones, 2);
                assert_int_equal(zeros, 1);
            }
}

/* Within +-1.04 everywhere, centred on 0, and different layers differ. */
static void test_noise_range(void **state)
{
    double most = 0, sum = 0, differ = 0;
    const int n = 200000;
    for (int i = 0; i < n; i++) {
        vec3 p = scattered((uint32_t)i);
        double v = noise_at(p, 0);
        most = fmax(most, fabs(v));
        sum += v;
        differ += fabs(v - noise_at(p, 1));
    }
    assert_true(most <= 1.04 && most > 0.8);
    assert_near(sum / n, 0, 0.01);
    assert_true(differ / n > 0.1);
    noise_octaves o = {6, 2, 0.5};
    for (int i = 0; i < 20000; i++) {
        double t = turbulence_at(scattered((uint32_t)i), o), f = fbm_at(scattered((uint32_t)i), o);
        assert_true(t >= 0 && t <= 1.04 && fabs(f) <= 1.04);
    }
    assert_true(noise_at(v3(NAN, 0, 0), 0) == 0 && noise_at(v3(0, INFINITY, 0), 0) == 0);
    assert_true(noise_at(v3(2e15, 0.5, 0.5), 0) == 0);
}

/* No jumps across the faces of lattice cells: a step of 1e-9 across one
 * changes the noise by no more than its slope allows (at most about 3),
 * and single precision's rounding (an offset in a cell is a float; the
 * two sides' sums round apart, by a unit in the last place of 1, 1.2e-7,
 * at worst seen). */
static void test_noise_continuous(void **state)
{
    const double e = 1e-9;
    for (int i = 0; i < 2000; i++) {
        vec3 p = scattered((uint32_t)i);
        double faces[3] = {floor(p.x), floor(p.y), floor(p.z)};
        for (int k = 0; k < 3; k++) {
            vec3 below = p, above = p;
            (&below.x)[k] = faces[k] - e;
            (&above.x)[k] = faces[k] + e;
            assert_true(fabs(noise_at(above, 0) - noise_at(below, 0)) < 5e-7);
        }
    }
}

/* The same values on every machine and in every build: a table of them,
 * each to the last bit. */
static void test_noise_values(void **state)
{
    const struct {
        vec3 p;
        double layer0, layer3, fbm5;
    } table[] = {
        {{0.5, 0.5, 0.5}, 0.375, 0.125, 0.19354838709677419},
        {{1.25, -2.75, 3.125}, -0.42973518371582031, -0.37722951173782349, -0.32802360288558469},
        {{-7.3, 0.01, 12.9}, 0.31077224016189575, -0.053163573145866394, 0.16004700141568337},
        {{100.1, 200.2, -300.3}, 0.18259415030479431, -0.34777700901031494, 0.021819229087521954},
        {{0.3, 0.7, 0.2}, 0.20999476313591003, -0.22281301021575928, 0.14845270146766015},
    };
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++) {
        assert_true(noise_at(table[i].p, 0) == table[i].layer0);
        assert_true(noise_at(table[i].p, 3) == table[i].layer3);
        assert_true(fbm_at(table[i].p, (noise_octaves){5, 2, 0.5}) == table[i].fbm5);
    }
    /* One octave of fBm is the noise itself. */
    assert_true(fbm_at(table[1].p, (noise_octaves){1, 2, 0.5}) == table[1].layer0);
}

/* Four points at once give each point's own values, whatever the others
 * are (lattice cells apart, on a lattice point, not finite, too far): the
 * lanes never mix. */
static void test_noise_lanes(void **state)
{
    noise_octaves o = {6, 2, 0.5};
    for (uint32_t i = 0; i < 2000; i++) {
        vec3 p[QUAD] = {scattered(4 * i), scattered(4 * i + 1), scattered(4 * i + 2), scattered(4 * i + 3)};
        if (i % 7 == 0)
            p[i % QUAD] = i % 2 ? v3(NAN, 1, 2) : v3(3e15, 0.5, 0.5);
        if (i % 11 == 0)
            p[(i + 1) % QUAD] = v3(-3, 4, -5);
        quad_f64 q[3];
        quad_points(p, q);
        quad_f64 n = noise_at4(q, i % 5), f = noise_fbm4(q, o), t = noise_turbulence4(q, o);
        for (int l = 0; l < QUAD; l++) {
            assert_true(n[l] == noise_at(p[l], i % 5));
            assert_true(f[l] == fbm_at(p[l], o));
            assert_true(t[l] == turbulence_at(p[l], o));
        }
    }
}

/* A texture of `kind` from black at 0 to white at 1, made with desc's
 * other fields as given. */
static texture grey_map(glint_texture d)
{
    d.stop_count = 2;
    d.stops[0] = (glint_color_stop){0, {0, 0, 0}};
    d.stops[1] = (glint_color_stop){1, {1, 1, 1}};
    texture t;
    glint_error err = {0};
    assert_int_equal(texture_init(&t, &d, NULL, NULL, &err), GLINT_OK);
    return t;
}

static color at(const texture *t, vec3 p) { return t->kind->solid(t, texture_place(t, p)); }

/* Without turbulence the patterns are their plain formulas: marble
 * 0.5 - 0.5 cos(2 pi x / scale), wood the fraction of r / scale. */
static void test_patterns_exact(void **state)
{
    glint_texture d = glint_texture_default(GLINT_TEXTURE_MARBLE);
    d.turbulence = 0;
    d.scale = 2;
    texture marble = grey_map(d);
    assert_near(at(&marble, v3(0, 5, 7)).r, 0, 1e-15);
    assert_near(at(&marble, v3(1.0 / 3, 0, 0)).g, 0.25, 1e-15); /* 0.5 - 0.5 cos(pi / 3) */
    assert_near(at(&marble, v3(1, 0, 0)).b, 1, 1e-15);
    assert_near(at(&marble, v3(-2.5, 0, 0)).r, 0.5, 1e-15);
    texture_release(&marble);

    d = glint_texture_default(GLINT_TEXTURE_WOOD);
    d.turbulence = 0;
    d.scale = 0.5;
    texture wood = grey_map(d);
    assert_near(at(&wood, v3(0.15, 9, 0.2)).r, 0.5, 1e-12);   /* r = 0.25 / 0.5 */
    assert_near(at(&wood, v3(0.6, -1, 0.8)).r, 0, 1e-12);     /* r = 2: a ring's start */
    assert_near(at(&wood, v3(0, 0, 0.9)).r, 0.8, 1e-12);
    texture_release(&wood);
}

/* The noise texture is 0.5 + 0.5 fbm through its colour map; granite is
 * twice the turbulence, capped at 1. */
static void test_noise_and_granite(void **state)
{
    glint_texture d = glint_texture_default(GLINT_TEXTURE_NOISE);
    d.scale = 0.5;
    texture noise = grey_map(d);
    noise_octaves o = {d.octaves, d.lacunarity, d.gain};
    vec3 p = v3(0.3, 1.7, -2.2), q = v3_scale(p, 2);
    assert_near(at(&noise, p).r, 0.5 + 0.5 * fbm_at(q, o), 1e-15);
    texture_release(&noise);
    d = glint_texture_default(GLINT_TEXTURE_GRANITE);
    texture granite = grey_map(d);
    o = (noise_octaves){d.octaves, d.lacunarity, d.gain};
    q = v3_scale(p, 1 / d.scale);
    assert_near(at(&granite, p).r, fmin(1, 2 * turbulence_at(q, o)), 1e-15);
    texture_release(&granite);
}

/* Each noise kind's colours at up to four points read together are each
 * point's read alone; and so for a kind that reads one point at a time
 * (the solid checker). */
static void test_points_together(void **state)
{
    const glint_texture_kind kinds[] = {GLINT_TEXTURE_NOISE, GLINT_TEXTURE_MARBLE, GLINT_TEXTURE_WOOD,
                                        GLINT_TEXTURE_GRANITE, GLINT_TEXTURE_CHECKER_3D};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        texture t = grey_map(glint_texture_default(kinds[k]));
        for (int lanes = 1; lanes <= QUAD; lanes++) {
            vec3 p[QUAD] = {scattered(1), scattered(2), scattered(3), scattered(4)};
            color c[QUAD];
            texture_solid_points(&t, p, lanes, c);
            for (int l = 0; l < lanes; l++) {
                color alone = t.kind->solid(&t, p[l]);
                assert_true(c[l].r == alone.r && c[l].g == alone.g && c[l].b == alone.b);
            }
        }
        texture_release(&t);
    }
}

/* Between stops the colour is blended; before the first and past the last
 * it is theirs; two stops at one value make a hard edge. */
static void test_color_map(void **state)
{
    glint_texture d = glint_texture_default(GLINT_TEXTURE_WOOD);
    d.turbulence = 0;
    d.stop_count = 4;
    d.stops[0] = (glint_color_stop){0.2, {1, 0, 0}};
    d.stops[1] = (glint_color_stop){0.6, {0, 1, 0}};
    d.stops[2] = (glint_color_stop){0.6, {0, 0, 1}};
    d.stops[3] = (glint_color_stop){0.8, {1, 1, 1}};
    d.scale = 1;
    texture t;
    glint_error err = {0};
    assert_int_equal(texture_init(&t, &d, NULL, NULL, &err), GLINT_OK);
    color c = at(&t, v3(0.1, 0, 0));          /* before the first stop */
    assert_true(c.r == 1 && c.g == 0 && c.b == 0);
    c = at(&t, v3(0.5, 0, 0));                /* 3/4 of the way from red to green */
    assert_near(c.r, 0.25, 1e-12);
    assert_near(c.g, 0.75, 1e-12);
    c = at(&t, v3(0.65, 0, 0));               /* past the hard edge: blue to white */
    assert_near(c.r, 0.25, 1e-12);
    assert_near(c.b, 1, 1e-12);
    c = at(&t, v3(0.9, 0, 0));                /* past the last */
    assert_true(c.r == 1 && c.g == 1 && c.b == 1);
    texture_release(&t);

    d.stops[2].at = 0.5; /* out of order */
    assert_int_equal(texture_init(&t, &d, NULL, NULL, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "wood texture colors stop 2 is at 0.5: stops go from 0 to 1, in order");
    d.stop_count = 1;
    assert_int_equal(texture_init(&t, &d, NULL, NULL, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "wood texture colors needs 2 to 16 stops, got 1");
}

/* A texture's transform moves its pattern: a marble moved by 0.25 along x
 * shows at x what the unmoved one shows at x - 0.25; a checker scaled by 2
 * has cells twice as large in (u, v); and the sky sees it too. */
static void test_texture_transform(void **state)
{
    glint_texture d = glint_texture_default(GLINT_TEXTURE_MARBLE);
    texture still = grey_map(d);
    d.transform = glint_transform_translate(glint_transform_identity(), 0.25, 0, 0);
    texture moved = grey_map(d);
    for (int i = 0; i < 100; i++) {
        vec3 p = scattered((uint32_t)i);
        assert_near(at(&moved, p).r, at(&still, v3(p.x - 0.25, p.y, p.z)).r, 1e-12);
    }
    glint_environment sky = {.texture = 0, .intensity = 1};
    vec3 up = v3(0, 1, 0);
    assert_near(environment_color(&sky, &moved, up).r, at(&still, v3(-0.25, 1, 0)).r, 1e-12);
    texture_release(&still);
    texture_release(&moved);

    glint_texture c = glint_texture_default(GLINT_TEXTURE_CHECKER);
    c.colors[0] = (glint_color){1, 1, 1};
    c.colors[1] = (glint_color){0, 0, 0};
    c.transform = glint_transform_scale(glint_transform_identity(), 2, 2, 1);
    texture checks;
    glint_error err = {0};
    assert_int_equal(texture_init(&checks, &c, NULL, NULL, &err), GLINT_OK);
    surface s = {.u = 1.5, .v = 0.5}; /* cell (0, 0), white, when doubled; (1, 0), black, otherwise */
    double u, v;
    texture_uv(&checks, &s, v3(0, 0, 0), &u, &v);
    assert_true(texture_at_placed(&checks, u, v, (uv_extent){0, 0}).r == 1);
    texture_release(&checks);

    c.transform = glint_transform_scale(glint_transform_identity(), 0, 1, 1);
    assert_int_equal(texture_init(&checks, &c, NULL, NULL, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "checker texture transform is singular or not finite");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_noise_lattice),     cmocka_unit_test(test_noise_range),
        cmocka_unit_test(test_noise_continuous),  cmocka_unit_test(test_noise_values),
        cmocka_unit_test(test_noise_lanes),       cmocka_unit_test(test_points_together),
        cmocka_unit_test(test_patterns_exact),    cmocka_unit_test(test_noise_and_granite),
        cmocka_unit_test(test_color_map),         cmocka_unit_test(test_texture_transform),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
