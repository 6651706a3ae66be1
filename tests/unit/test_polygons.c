/* test_polygons.c - polygons of any number of points, convex or not, and
 * meshes written out in a scene file: a star's and a dart's silhouettes
 * pixel by pixel against the point-in-polygon rule and their areas
 * against the formula, the triangles an inline mesh's faces make, and the
 * refusals in words. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "glint.h"
#include "one_sample_scene.h"
#include "scene/scene.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

enum { SIDE = 160 };
#define VIEW 2.4

/* Whether (x, y) is inside the polygon of n points (crossing number). */
static bool inside(const glint_vec3 *p, int n, double x, double y)
{
    bool in = false;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((p[i].y > y) != (p[j].y > y) && x < (p[j].x - p[i].x) * (y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
            in = !in;
    return in;
}

/* The distance from (x, y) to the polygon's nearest edge. */
static double edge_distance(const glint_vec3 *p, int n, double x, double y)
{
    double best = INFINITY;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        double ex = p[i].x - p[j].x, ey = p[i].y - p[j].y, t = ((x - p[j].x) * ex + (y - p[j].y) * ey) / (ex * ex + ey * ey);
        t = fmin(1, fmax(0, t));
        best = fmin(best, hypot(x - p[j].x - t * ex, y - p[j].y - t * ey));
    }
    return best;
}

/* The polygon of n points in the z = 0 plane seen straight on, white on
 * black; checks every pixel not within a pixel of an edge against the
 * crossing rule, and returns the area the white pixels cover. */
static double silhouette_area(const glint_vec3 *p, int n)
{
    glint_scene *s = silhouette_scene(SIDE, VIEW);
    glint_material white = glint_material_default();
    white.ambient = 1;
    white.diffuse = white.specular = 0;
    glint_error err;
    int placed = glint_scene_add_polygon(s, p, n, glint_scene_add_material(s, NULL, &white, NULL), NULL, &err);
    if (placed < 0)
        fail_msg("%s", err.message);
    glint_image im;
    glint_render_options o = {.threads = 2};
    assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
    const double px = VIEW / SIDE;
    int white_pixels = 0;
    for (int j = 0; j < SIDE; j++)
        for (int i = 0; i < SIDE; i++) {
            double x = (i + 0.5) * px - VIEW / 2, y = VIEW / 2 - (j + 0.5) * px;
            float v = im.pixels[3 * (j * SIDE + i)];
            if (edge_distance(p, n, x, y) > px)
                assert_true(v == (inside(p, n, x, y) ? 1.0f : 0.0f));
            white_pixels += v > 0.5f;
        }
    glint_image_free(&im);
    glint_scene_free(s);
    return white_pixels * px * px;
}

/* A five-pointed star, outer radius 1 and inner 0.4, anticlockwise, and
 * the same seen from behind (clockwise): both cover 5 R r sin 36 degrees.
 * A dart (a concave quad) covers its two triangles' area. */
static void test_star_and_dart(void **state)
{
    glint_vec3 star[10], back[10];
    for (int k = 0; k < 10; k++) {
        double a = M_PI / 2 + k * M_PI / 5, r = k % 2 ? 0.4 : 1;
        star[k] = (glint_vec3){r * cos(a), r * sin(a), 0};
        back[9 - k] = star[k];
    }
    double want = 5 * 1 * 0.4 * sin(M_PI / 5);
    assert_near(silhouette_area(star, 10), want, 0.01 * want);
    assert_near(silhouette_area(back, 10), want, 0.01 * want);
    const glint_vec3 dart[] = {{0, 1, 0}, {-0.8, -0.8, 0}, {0, -0.2, 0}, {0.8, -0.8, 0}};
    assert_near(silhouette_area(dart, 4), 0.8 * 1.2, 0.01);
}

/* A polygon's problems, in words. */
static void test_polygon_refusals(void **state)
{
    glint_scene *s = glint_scene_new();
    glint_material m = glint_material_default();
    int mat = glint_scene_add_material(s, NULL, &m, NULL);
    glint_error err;
    const glint_vec3 line[] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
    assert_int_equal(glint_scene_add_polygon(s, line, 5, mat, NULL, &err), -1);
    assert_string_equal(err.message, "polygon points are collinear");
    const glint_vec3 bent[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 1.5, 0.2}, {0, 1, 0}};
    assert_int_equal(glint_scene_add_polygon(s, bent, 5, mat, NULL, &err), -1);
    assert_string_equal(err.message, "polygon is not planar");
    const glint_vec3 twice[] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 1, 0}};
    assert_int_equal(glint_scene_add_polygon(s, twice, 5, mat, NULL, &err), -1);
    assert_string_equal(err.message, "polygon points 1 and 2 coincide");
    assert_int_equal(glint_scene_add_polygon(s, line, 2, mat, NULL, &err), -1);
    assert_string_equal(err.message, "a polygon needs 3 to 1048576 points, got 2");
    glint_scene_free(s);
}

/* An inline mesh's faces of 3, 4 and 5 vertices make 1, 2 and 3
 * triangles in their own winding; a polygon of six points in a scene
 * file is a placed mesh of 4 triangles, a concave quad one of 2, and a
 * convex quad stays a shape. */
static void test_scene_file_arrays(void **state)
{
    static const char text[] =
        "glint: 1\n"
        "materials: {m: {}}\n"
        "objects:\n"
        "  - type: mesh\n"
        "    material: m\n"
        "    vertices: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0], [2, 1, 0], [3, 0.5, 0]]\n"
        "    uvs: [[0, 0], [1, 0], [1, 1], [0, 1], [2, 0], [2, 1], [3, 0.5]]\n"
        "    faces: [[0, 1, 3], [1, 4, 5, 2], [4, 6, 5, 2, 1]]\n"
        "  - {type: polygon, material: m, points: [[0, 0, 0], [2, 0, 0], [3, 1, 0], [2, 2, 0], [0, 2, 0], [-1, 1, 0]]}\n"
        "  - {type: polygon, material: m, points: [[0, 1, 0], [-1, -1, 0], [0, 0, 0], [1, -1, 0]]}\n"
        "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]}\n";
    glint_error err;
    glint_scene *s = glint_scene_load_memory(text, strlen(text), "arrays.yaml", NULL, &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_int_equal(s->instance_count, 3);
    assert_int_equal(s->shape_count, 1);
    assert_int_equal(s->meshes[0].triangle_count, 6);
    assert_int_equal(s->meshes[0].vertex_count, 7);
    assert_int_equal(s->meshes[0].indices[0], 0);
    assert_int_equal(s->meshes[0].indices[1], 1);
    assert_int_equal(s->meshes[0].indices[2], 3);
    assert_near(s->meshes[0].uvs[2 * 6], 3, 0);
    assert_int_equal(s->meshes[1].triangle_count, 4);
    assert_int_equal(s->meshes[2].triangle_count, 2);
    glint_scene_free(s);
}

/* A scene of a white matte surface under a sun from the upper left, seen
 * from above at a slant: the heightfield of columns x rows heights h in
 * the box -1..1 (y 0..1), or (heights NULL) the quad of its corners. */
static glint_image lit_surface(const float *heights, int columns, int rows)
{
    glint_camera cam = {.position = {0.3, 3, 2.5}, .look_at = {0, 0.3, 0}, .up = {0, 1, 0}, .vfov_degrees = 40};
    glint_scene *s = one_sample_scene(64, 48, (glint_color){0, 0, 0}, cam);
    glint_material white = glint_material_default();
    white.specular = white.ambient = 0;
    int mat = glint_scene_add_material(s, NULL, &white, NULL);
    glint_light sun = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {0.6, -1, -0.3}, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &sun, NULL) >= 0);
    glint_error err;
    glint_vec3 lo = {-1, 0, -1}, hi = {1, 1, 1};
    if (heights) {
        if (glint_scene_add_heightfield(s, heights, columns, rows, lo, hi, mat, NULL, &err) < 0)
            fail_msg("%s", err.message);
    } else {
        /* The corners at x = -1 and x = 1, heights h(-1) and h(1) (a slope in x). */
        glint_vec3 quad[4] = {{-1, 0, -1}, {-1, 0, 1}, {1, 1, 1}, {1, 1, -1}};
        if (columns == 1)
            for (int k = 0; k < 4; k++)
                quad[k].y = 0.5;
        assert_true(glint_scene_add_polygon(s, quad, 4, mat, NULL, &err) >= 0);
    }
    glint_image im;
    glint_render_options o = {.threads = 2};
    assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
    glint_scene_free(s);
    return im;
}

/* A flat heightfield (every height 0.5) and a sloped one (height x / 2 +
 * 1/2 over x from -1 to 1) look as the polygon of their corners does, to
 * single precision, pixel for pixel: the same silhouette, the same light. */
static void test_heightfield_against_polygon(void **state)
{
    enum { N = 9 };
    float flat[N * N], slope[N * N];
    for (int r = 0; r < N; r++)
        for (int c = 0; c < N; c++) {
            flat[r * N + c] = 0.5f;
            slope[r * N + c] = (float)c / (N - 1);
        }
    for (int k = 0; k < 2; k++) {
        glint_image field = lit_surface(k ? slope : flat, N, N), quad = lit_surface(NULL, k ? 2 : 1, 0);
        int lit = 0;
        for (int i = 0; i < 64 * 48; i++) {
            assert_near(field.pixels[3 * i], quad.pixels[3 * i], 2e-5);
            lit += quad.pixels[3 * i] > 0;
        }
        assert_true(lit > 500);
        glint_image_free(&field);
        glint_image_free(&quad);
    }
}

/* A heightfield's problems, in words. */
static void test_heightfield_refusals(void **state)
{
    glint_scene *s = glint_scene_new();
    glint_material m = glint_material_default();
    int mat = glint_scene_add_material(s, NULL, &m, NULL);
    glint_error err;
    float h[4] = {0, 0.5f, 1, 1.5f};
    glint_vec3 lo = {-1, 0, -1}, hi = {1, 1, 1};
    assert_int_equal(glint_scene_add_heightfield(s, h, 2, 2, lo, hi, mat, NULL, &err), -1);
    assert_string_equal(err.message, "heightfield height 3 (row 1) must be from 0 to 1, got 1.5");
    assert_int_equal(glint_scene_add_heightfield(s, h, 1, 4, lo, hi, mat, NULL, &err), -1);
    assert_string_equal(err.message, "a heightfield needs 2 to 16384 samples a side, got 1 x 4");
    h[3] = 1;
    assert_int_equal(glint_scene_add_heightfield(s, h, 2, 2, hi, lo, mat, NULL, &err), -1);
    assert_string_equal(err.message, "heightfield min must be below max in x and z, and at most max in y, all finite");
    assert_true(glint_scene_add_heightfield(s, h, 2, 2, lo, hi, mat, NULL, &err) >= 0);
    assert_int_equal(s->meshes[0].triangle_count, 2);
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_star_and_dart),
        cmocka_unit_test(test_polygon_refusals),
        cmocka_unit_test(test_scene_file_arrays),
        cmocka_unit_test(test_heightfield_against_polygon),
        cmocka_unit_test(test_heightfield_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
