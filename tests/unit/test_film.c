/* test_film.c - the film (render/film.h): a block's samples averaged into
 * its pixels, and the NaN rule on a synthetic block: a NaN sample left out
 * of its pixel's average and counted, a pixel of only NaN samples black,
 * and the check that finds a NaN pixel anywhere in a rectangle. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include "render/film.h"

enum { WIDTH = 8, HEIGHT = 2, SAMPLES = 4 };

/* A 4 x 2 block at (x0, 0), all lanes active but the last. */
static void block(int x0, int px[RAY8], int py[RAY8], bool active[RAY8])
{
    for (int i = 0; i < RAY8; i++) {
        px[i] = x0 + i % 4;
        py[i] = i / 4;
        active[i] = i < RAY8 - 1;
    }
}

static const float *pixel(const film *f, int x, int y)
{
    return f->pixels + 3 * ((size_t)y * f->width + x);
}

/* Sample k of lane i: lane 0 always finite, lane 1 NaN at sample 2 (in
 * one channel), lane 2 NaN at every sample, the others finite. */
static void samples(int k, color c[RAY8])
{
    for (int i = 0; i < RAY8; i++)
        c[i] = rgb(i + k, 2 * k, 0.5);
    c[1].g = k == 2 ? NAN : c[1].g;
    c[2] = rgb(NAN, 0, 0);
    c[7] = rgb(NAN, NAN, NAN);
}

/* Adds the block's SAMPLES samples, with or without care, and writes it. */
static film_block render(film *f, int x0, bool careful)
{
    int px[RAY8], py[RAY8];
    bool active[RAY8];
    block(x0, px, py, active);
    film_block b;
    film_block_start(&b);
    for (int k = 0; k < SAMPLES; k++) {
        color c[RAY8];
        samples(k, c);
        film_block_add(&b, active, c, careful);
    }
    film_block_put(f, &b, px, py, active);
    return b;
}

static void test_average_and_nan_rule(void **state)
{
    film f;
    assert_true(film_init(&f, WIDTH, HEIGHT, SAMPLES, true));
    /* The inactive lane's pixel is never written. */
    float *p7 = f.pixels + 3 * (1 * WIDTH + 3);
    p7[0] = p7[1] = p7[2] = 7;
    assert_false(film_has_nan(&f, 0, 0, WIDTH, HEIGHT));

    /* Without care a NaN sample reaches its pixel; the check finds it. */
    film_block b = render(&f, 0, false);
    assert_int_equal(film_block_nan_samples(&b), 0);
    assert_true(isnan(pixel(&f, 1, 0)[1]) && isnan(pixel(&f, 2, 0)[0]));
    assert_true(film_has_nan(&f, 0, 0, WIDTH, HEIGHT));
    assert_true(film_has_nan(&f, 2, 0, 3, 1));
    assert_false(film_has_nan(&f, 3, 0, WIDTH, HEIGHT));

    /* With care: lane 1 averages its three finite samples, lane 2 (no
     * finite sample) is black, the others average all four. */
    b = render(&f, 0, true);
    assert_int_equal(film_block_nan_samples(&b), 1 + SAMPLES);
    assert_false(film_has_nan(&f, 0, 0, WIDTH, HEIGHT));
    assert_true(pixel(&f, 0, 0)[0] == 1.5f && pixel(&f, 0, 0)[1] == 3.0f && pixel(&f, 0, 0)[2] == 0.5f);
    assert_true(pixel(&f, 1, 0)[0] == (float)(7 * (1.0 / 3)) && pixel(&f, 1, 0)[1] == (float)(8 * (1.0 / 3)) &&
                pixel(&f, 1, 0)[2] == 0.5f);
    assert_true(pixel(&f, 2, 0)[0] == 0 && pixel(&f, 2, 0)[1] == 0 && pixel(&f, 2, 0)[2] == 0);
    assert_true(pixel(&f, 2, 1)[0] == 7.5f);
    assert_true(p7[0] == 7 && p7[1] == 7 && p7[2] == 7);
    film_free(&f);
}

/* The check reads eight floats a step and the rest one at a time: a NaN
 * in either part of a row, and only inside the rectangle, is found. */
static void test_nan_check_covers_every_float(void **state)
{
    film f;
    assert_true(film_init(&f, WIDTH, HEIGHT, 1, true));
    for (int x = 0; x < WIDTH; x++) {
        for (int k = 0; k < 3; k++) {
            float *p = (float *)pixel(&f, x, 1) + k;
            *p = NAN;
            assert_true(film_has_nan(&f, 0, 0, WIDTH, HEIGHT));
            assert_true(film_has_nan(&f, x, 1, x + 1, 2));
            assert_false(film_has_nan(&f, 0, 0, WIDTH, 1));
            assert_int_equal(film_has_nan(&f, 0, 1, 3, 2), x < 3);
            *p = 0;
        }
    }
    film_clear(&f, 0, 0, WIDTH, HEIGHT);
    assert_false(film_has_nan(&f, 0, 0, WIDTH, HEIGHT));
    film_free(&f);
}

/* film_clear blackens its rectangle and nothing else. */
static void test_clear(void **state)
{
    film f;
    assert_true(film_init(&f, WIDTH, HEIGHT, 1, true));
    for (int i = 0; i < 3 * WIDTH * HEIGHT; i++)
        f.pixels[i] = 1;
    film_clear(&f, 2, 1, 5, 2);
    for (int y = 0; y < HEIGHT; y++)
        for (int x = 0; x < WIDTH; x++)
            assert_true(pixel(&f, x, y)[2] == (y == 1 && x >= 2 && x < 5 ? 0 : 1));
    film_free(&f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_average_and_nan_rule),
        cmocka_unit_test(test_nan_check_covers_every_float),
        cmocka_unit_test(test_clear),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
