/* test_camera.c - the camera kinds: the registry, and the pinhole's rays:
 * where they point, and that each lane is, to the bit, the pinhole formula
 * glint has always used, whatever the lens sample and time. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include "render/camera_kind.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

static const glint_camera DESC = {.position = {1, 2, 3}, .look_at = {1, 2, -7}, .up = {0, 1, 0}, .vfov_degrees = 90};

static camera make(const glint_camera *d, int width, int height)
{
    camera c;
    camera_init(&c, d, width, height);
    return c;
}

/* The ray through image position (x, y): lane 0 of a packet of such lanes. */
static ray ray_at_position(const camera *c, double x, double y)
{
    double xs[RAY8], ys[RAY8];
    for (int i = 0; i < RAY8; i++) {
        xs[i] = x;
        ys[i] = y;
    }
    ray8 out;
    camera_rays8(c, xs, ys, &camera_lens_centre, camera_shutter_middle, &out);
    return ray8_get(&out, 0);
}

/* The pinhole formula, one ray in scalar code: the frame from the
 * description, the image position on the plane at distance 1, normalised
 * by one division. */
static ray pinhole_formula(const glint_camera *d, int width, int height, double x, double y)
{
    vec3 f = v3_normalize(v3_sub(d->look_at, d->position));
    vec3 r = v3_normalize(v3_cross(f, d->up));
    vec3 u = v3_cross(r, f);
    double half_height = tan(d->vfov_degrees * M_PI / 360.0);
    double per_x = half_height * width / height / width, per_y = half_height / height;
    double sx = (2 * x - width) * per_x, sy = (height - 2 * y) * per_y;
    vec3 e = v3(f.x + (r.x * sx + u.x * sy), f.y + (r.y * sx + u.y * sy), f.z + (r.z * sx + u.z * sy));
    double l = sqrt(e.x * e.x + e.y * e.y + e.z * e.z);
    double inv = l > 0 ? 1 / l : 1;
    return (ray){d->position, v3(e.x * inv, e.y * inv, e.z * inv)};
}

static void test_registry(void **state)
{
    assert_ptr_equal(camera_kind_named("pinhole"), &pinhole_camera);
    assert_ptr_equal(camera_kind_named("fisheye"), &fisheye_camera);
    assert_null(camera_kind_named("stereo"));
    assert_ptr_equal(camera_kind_for(&DESC), &pinhole_camera);
    glint_camera lens = DESC;
    lens.kind = GLINT_CAMERA_THIN_LENS;
    assert_ptr_equal(camera_kind_for(&lens), &thin_lens_camera);
    camera c = make(&DESC, 20, 10);
    assert_ptr_equal(c.kind, &pinhole_camera);
}

static void test_centre_and_corners(void **state)
{
    camera c = make(&DESC, 200, 100);
    /* The image centre looks down the view axis exactly. */
    ray r = ray_at_position(&c, 100, 50);
    assert_true(r.d.x == 0 && r.d.y == 0 && r.d.z == -1);
    assert_true(r.o.x == 1 && r.o.y == 2 && r.o.z == 3);
    /* A 90 degree vertical field: the top edge's centre is 45 degrees up,
     * and the image is twice as wide as high. */
    r = ray_at_position(&c, 100, 0);
    assert_near(r.d.y, sqrt(0.5), 1e-15);
    assert_near(r.d.z, -sqrt(0.5), 1e-15);
    r = ray_at_position(&c, 200, 50);
    assert_near(r.d.x, 2 / sqrt(5.0), 1e-15);
}

/* Every lane of three packets, at spread-out positions (the centre among
 * them), under two cameras, with lens samples and times that differ from
 * lane to lane: each lane's bits are the formula's. */
static void test_pinhole_lanes_are_the_formula(void **state)
{
    const glint_camera tilted = {.position = {-3, 0.5, 7}, .look_at = {2, -1, -4}, .up = {0.1, 1, 0.2},
                                 .vfov_degrees = 37};
    const glint_camera *descs[] = {&DESC, &tilted};
    for (int k = 0; k < 2; k++) {
        camera c = make(descs[k], 1000, 600);
        enum { N = 3 * RAY8 };
        double x[N], y[N];
        for (int i = 0; i < N; i++) {
            x[i] = 1000.0 * i / (N - 1) + 0.37 * (i % 3);
            y[i] = 600.0 * ((i * 7) % N) / N + 0.125;
        }
        x[5] = 500; /* the image centre */
        y[5] = 300;
        for (int base = 0; base < N; base += RAY8) {
            camera_lens8 lens;
            double time[RAY8];
            for (int i = 0; i < RAY8; i++) {
                lens.u[i] = i / 8.0;
                lens.v[i] = 1 - (i + 1) / 8.0;
                time[i] = (i * 3 % 8) / 8.0;
            }
            ray8 out;
            camera_rays8(&c, x + base, y + base, &lens, time, &out);
            for (int i = 0; i < RAY8; i++) {
                ray want = pinhole_formula(descs[k], 1000, 600, x[base + i], y[base + i]), lane = ray8_get(&out, i);
                assert_memory_equal(&lane, &want, sizeof want);
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_registry),
        cmocka_unit_test(test_centre_and_corners),
        cmocka_unit_test(test_pinhole_lanes_are_the_formula),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
