/* test_camera.c - the pinhole camera's rays: where they point, and that the
 * packet version camera_rays8 gives camera_ray's results to the bit. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "render/camera.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

static camera make(int width, int height)
{
    glint_camera d = {.position = {1, 2, 3}, .look_at = {1, 2, -7}, .up = {0, 1, 0}, .vfov_degrees = 90};
    camera c;
    camera_init(&c, &d, width, height);
    return c;
}

static void test_centre_and_corners(void **state)
{
    camera c = make(200, 100);
    /* The image centre looks down the view axis exactly. */
    ray r = camera_ray(&c, 100, 50);
    assert_true(r.d.x == 0 && r.d.y == 0 && r.d.z == -1);
    assert_true(r.o.x == 1 && r.o.y == 2 && r.o.z == 3);
    /* A 90 degree vertical field: the top edge's centre is 45 degrees up,
     * and the image is twice as wide as high. */
    r = camera_ray(&c, 100, 0);
    assert_near(r.d.y, sqrt(0.5), 1e-15);
    assert_near(r.d.z, -sqrt(0.5), 1e-15);
    r = camera_ray(&c, 200, 50);
    assert_near(r.d.x, 2 / sqrt(5.0), 1e-15);
}

static void test_batch_matches_single_rays(void **state)
{
    camera c = make(1000, 600);
    enum { N = 3 * RAY8 };
    double x[N], y[N];
    for (int i = 0; i < N; i++) {
        x[i] = 1000.0 * i / (N - 1) + 0.37 * (i % 3);
        y[i] = 600.0 * ((i * 7) % N) / N + 0.125;
    }
    x[5] = 500; /* the image centre */
    y[5] = 300;
    for (int base = 0; base < N; base += RAY8) {
        ray8 out;
        camera_rays8(&c, x + base, y + base, &out);
        for (int i = 0; i < RAY8; i++) {
            ray one = camera_ray(&c, x[base + i], y[base + i]), lane = ray8_get(&out, i);
            assert_memory_equal(&lane, &one, sizeof one);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_centre_and_corners),
        cmocka_unit_test(test_batch_matches_single_rays),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
