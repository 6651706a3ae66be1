/* test_keyframes.c - keyed values (glint_keys): each interpolation at and
 * between its keys against the value worked out by hand, clamping before
 * the first key and after the last, the smooth cubic's promises (monotone
 * where the keys are, never past a key, a continuous slope, flat at the
 * ends), and the checks' messages. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include "glint.h"

static double value_at(const glint_keys *k, double t)
{
    double out[GLINT_KEY_WIDTH_MAX];
    glint_keys_value(k, t, out);
    return out[0];
}

/* Straight lines: the keys' values exactly at their times, the line's
 * value between, nonuniform times and each number of a vector alone. */
static void test_linear(void **state)
{
    const double times[] = {0, 1, 3};
    const double values[] = {0, 10, -1, 4, 20, -1, 8, 0, 5};
    glint_keys k = {times, values, 3, 3, GLINT_INTERPOLATE_LINEAR};
    assert_int_equal(glint_keys_check(&k, NULL), GLINT_OK);
    double v[3];
    glint_keys_value(&k, 1, v);
    assert_true(v[0] == 4 && v[1] == 20 && v[2] == -1);
    glint_keys_value(&k, 0.25, v);
    assert_true(v[0] == 1 && v[1] == 12.5 && v[2] == -1);
    glint_keys_value(&k, 2, v); /* halfway from key 2 to key 3 */
    assert_true(v[0] == 6 && v[1] == 10 && v[2] == 2);
    glint_keys_value(&k, 3, v);
    assert_true(v[0] == 8 && v[1] == 0 && v[2] == 5);
}

/* Before the first key the first value, after the last the last, in
 * every mode; one key is a constant. */
static void test_clamped_outside_the_keys(void **state)
{
    const double times[] = {1, 2}, values[] = {3, 7};
    for (int mode = GLINT_INTERPOLATE_LINEAR; mode <= GLINT_INTERPOLATE_STEP; mode++) {
        glint_keys k = {times, values, 2, 1, (glint_interpolation)mode};
        assert_true(value_at(&k, -100) == 3);
        assert_true(value_at(&k, 1) == 3);
        assert_true(value_at(&k, 2) == 7);
        assert_true(value_at(&k, 1e9) == 7);
        glint_keys one = {times, values, 1, 1, (glint_interpolation)mode};
        assert_true(value_at(&one, 0) == 3 && value_at(&one, 5) == 3);
    }
}

/* Steps: a key's value holds until the next key's time. */
static void test_step(void **state)
{
    const double times[] = {0, 1, 2}, values[] = {5, 6, 9};
    glint_keys k = {times, values, 3, 1, GLINT_INTERPOLATE_STEP};
    assert_true(value_at(&k, 0.999) == 5);
    assert_true(value_at(&k, 1) == 6);
    assert_true(value_at(&k, 1.5) == 6);
    assert_true(value_at(&k, 2) == 9);
}

/* Smooth, two keys: flat at both, so the cubic is the smoothstep
 * 3s^2 - 2s^3 between the values: at a quarter, 0.15625 of the way. */
static void test_smooth_eases_in_and_out(void **state)
{
    const double times[] = {0, 4}, values[] = {2, 10};
    glint_keys k = {times, values, 2, 1, GLINT_INTERPOLATE_SMOOTH};
    assert_true(fabs(value_at(&k, 1) - (2 + 8 * 0.15625)) < 1e-12);
    assert_true(fabs(value_at(&k, 2) - 6) < 1e-12);
    assert_true(fabs(value_at(&k, 3) - (2 + 8 * 0.84375)) < 1e-12);
}

/* Smooth, three keys in a straight line at equal times: the middle slope
 * is the line's (2 per second), so the middle key's neighbourhood is that
 * line to first order; at 1.5 s the cubic from 2 (slope 2) to 4 (slope 0)
 * over 1 s is 2 * 0.5 + 4 * 0.5 + (0.125 * 2 - 0) = 3.25. */
static void test_smooth_three_keys(void **state)
{
    const double times[] = {0, 1, 2}, values[] = {0, 2, 4};
    glint_keys k = {times, values, 3, 1, GLINT_INTERPOLATE_SMOOTH};
    assert_true(fabs(value_at(&k, 1.5) - 3.25) < 1e-12);
    double slope = (value_at(&k, 1 + 1e-6) - value_at(&k, 1 - 1e-6)) / 2e-6;
    assert_true(fabs(slope - 2) < 1e-5);
}

/* Monotone keys give a monotone curve that never leaves the keys' range,
 * even where Catmull-Rom's would swing past (a jump between flat runs);
 * the slope is continuous at every key. */
static void test_smooth_is_monotone_and_c1(void **state)
{
    const double times[] = {0, 0.5, 1, 1.1, 3, 3.2}, values[] = {0, 0, 0.1, 5, 5.01, 9};
    glint_keys k = {times, values, 6, 1, GLINT_INTERPOLATE_SMOOTH};
    assert_int_equal(glint_keys_check(&k, NULL), GLINT_OK);
    double last = value_at(&k, -1);
    for (double t = -1; t <= 4; t += 1e-3) {
        double v = value_at(&k, t);
        assert_true(v >= last);
        assert_true(v >= 0 && v <= 9);
        last = v;
    }
    for (int i = 0; i < 6; i++) {
        double e = 1e-8, t = times[i];
        double left = (value_at(&k, t) - value_at(&k, t - e)) / e;
        double right = (value_at(&k, t + e) - value_at(&k, t)) / e;
        assert_true(fabs(left - right) < 1e-3 * (1 + fabs(left)));
        assert_true(value_at(&k, t) == values[i]);
    }
    /* A turn at a key: flat there, and the key is the extreme. */
    const double up_down[] = {0, 3, 1};
    glint_keys turn = {times, up_down, 3, 1, GLINT_INTERPOLATE_SMOOTH};
    for (double t = 0; t <= 1; t += 1e-3)
        assert_true(value_at(&turn, t) <= 3);
}

/* The checks and their messages. */
static void test_bad_keys(void **state)
{
    glint_error err;
    const double times[] = {0, 2, 1}, values[] = {1, 2, 3};
    glint_keys k = {times, values, 3, 1, GLINT_INTERPOLATE_LINEAR};
    assert_int_equal(glint_keys_check(&k, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "key times must increase: key 3 at 1 s comes after 2 s");
    const double same[] = {0, 0};
    k = (glint_keys){same, values, 2, 1, GLINT_INTERPOLATE_LINEAR};
    assert_int_equal(glint_keys_check(&k, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "key times must increase: key 2 at 0 s comes after 0 s");
    const double nan_value[] = {1, NAN};
    k = (glint_keys){times, nan_value, 2, 1, GLINT_INTERPOLATE_LINEAR};
    assert_int_equal(glint_keys_check(&k, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "key 2's value is not finite");
    k = (glint_keys){times, values, 0, 1, GLINT_INTERPOLATE_LINEAR};
    assert_int_equal(glint_keys_check(&k, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "keys need at least one key, got 0");
    k = (glint_keys){times, values, 1, 5, GLINT_INTERPOLATE_LINEAR};
    assert_int_equal(glint_keys_check(&k, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "a keyed value has 1 to 4 numbers, got 5");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_linear),
        cmocka_unit_test(test_clamped_outside_the_keys),
        cmocka_unit_test(test_step),
        cmocka_unit_test(test_smooth_eases_in_and_out),
        cmocka_unit_test(test_smooth_three_keys),
        cmocka_unit_test(test_smooth_is_monotone_and_c1),
        cmocka_unit_test(test_bad_keys),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
