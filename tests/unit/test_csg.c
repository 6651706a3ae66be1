/* test_csg.c - unions, intersections and differences against the sets they
 * stand for: which points of a grid are inside, the silhouettes of two
 * overlapping balls combined each way, a lens of two spheres focusing at
 * the lensmaker's focal length, shadows through a glass combination, the
 * four-lane test against the one-ray one, the combinations a ray leaving
 * them may skip, and the parts a combination refuses. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include "glint.h"
#include "first_crossing.h"
#include "one_sample_scene.h"
#include "geometry/shape.h"
#include "scene/scene.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

/* A material that shows exactly its colour under white ambient light. */
static int flat(glint_scene *s, double r, double g, double b)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){r, g, b};
    m.ambient = 1;
    m.diffuse = m.specular = 0;
    int i = glint_scene_add_material(s, NULL, &m, NULL);
    assert_true(i >= 0);
    return i;
}

static int add_ball(glint_scene *s, int csg, glint_vec3 c, double r, int mat)
{
    glint_shape sh = glint_shape_default(GLINT_SHAPE_SPHERE);
    sh.center = c;
    sh.radius = r;
    glint_error err;
    int i = csg >= 0 ? glint_scene_add_part(s, csg, &sh, mat, NULL, &err) : glint_scene_add_shape(s, &sh, mat, NULL, &err);
    if (i < 0)
        fail_msg("%s", err.message);
    return i;
}

static int add_combination(glint_scene *s, int csg, glint_shape_kind kind, int mat)
{
    glint_shape sh = glint_shape_default(kind);
    glint_error err;
    int i = csg >= 0 ? glint_scene_add_part(s, csg, &sh, mat, NULL, &err) : glint_scene_add_shape(s, &sh, mat, NULL, &err);
    if (i < 0)
        fail_msg("%s", err.message);
    return i;
}

/* Two unit balls at x = -0.5 and x = +0.5, combined by kind. */
static glint_scene *two_balls(glint_shape_kind kind, glint_scene *s, int mat)
{
    int csg = add_combination(s, -1, kind, mat);
    add_ball(s, csg, (glint_vec3){-0.5, 0, 0}, 1, mat);
    add_ball(s, csg, (glint_vec3){0.5, 0, 0}, 1, mat);
    return s;
}

static bool in_ball(double x, double y, double z, double cx) { return (x - cx) * (x - cx) + y * y + z * z < 1; }

/* Whether p is inside the two balls combined by kind. */
static bool in_set(glint_shape_kind kind, double x, double y, double z)
{
    bool a = in_ball(x, y, z, -0.5), b = in_ball(x, y, z, 0.5);
    return kind == GLINT_SHAPE_UNION ? a || b : kind == GLINT_SHAPE_INTERSECTION ? a && b : a && !b;
}

/* Adds the half-space behind the plane through p facing n to csg. */
static void add_half_space(glint_scene *s, int csg, glint_vec3 p, glint_vec3 n, int mat)
{
    glint_shape sh = glint_shape_default(GLINT_SHAPE_PLANE);
    sh.center = p;
    sh.normal = n;
    glint_error err;
    if (glint_scene_add_part(s, csg, &sh, mat, NULL, &err) < 0)
        fail_msg("%s", err.message);
}

/* From each point of a grid, the first crossing of the combination along
 * a slanted ray leaves it exactly when the point is inside the set; a
 * point within 1e-9 of a sphere is left out. A nested difference, (A u B)
 * minus a ball around the origin, is checked the same way, and ball A cut
 * by two half-spaces, y < 0.3 and x > -0.2, which the ray goes away from
 * (or along) where it never crosses their planes. */
static void test_inside_outside_on_a_grid(void **state)
{
    const glint_shape_kind kinds[] = {GLINT_SHAPE_UNION, GLINT_SHAPE_INTERSECTION, GLINT_SHAPE_DIFFERENCE};
    for (int k = 0; k < 5; k++) {
        glint_scene *s = glint_scene_new();
        int mat = flat(s, 1, 1, 1), top;
        if (k < 3) {
            two_balls(kinds[k], s, mat);
            top = 0;
        } else if (k == 4) {
            top = add_combination(s, -1, GLINT_SHAPE_INTERSECTION, mat);
            add_ball(s, top, (glint_vec3){-0.5, 0, 0}, 1, mat);
            add_half_space(s, top, (glint_vec3){0, 0.3, 0}, (glint_vec3){0, 1, 0}, mat);
            add_half_space(s, top, (glint_vec3){-0.2, 0, 0}, (glint_vec3){-1, 0, 0}, mat);
        } else {
            top = add_combination(s, -1, GLINT_SHAPE_DIFFERENCE, mat);
            int both = add_combination(s, top, GLINT_SHAPE_UNION, mat);
            add_ball(s, both, (glint_vec3){-0.5, 0, 0}, 1, mat);
            add_ball(s, both, (glint_vec3){0.5, 0, 0}, 1, mat);
            add_ball(s, top, (glint_vec3){0, 0, 0}, 0.4, mat);
        }
        vec3 d = v3_normalize(v3(0.31, 0.17, 0.93));
        int inside = 0, checked = 0;
        for (double x = -1.7; x <= 1.7; x += 0.1)
            for (double y = -1.1; y <= 1.1; y += 0.1)
                for (double z = -1.1; z <= 1.1; z += 0.1) {
                    double near = fmin(fabs(sqrt((x + 0.5) * (x + 0.5) + y * y + z * z) - 1),
                                       fabs(sqrt((x - 0.5) * (x - 0.5) + y * y + z * z) - 1));
                    near = fmin(near, fabs(sqrt(x * x + y * y + z * z) - 0.4));
                    near = fmin(near, fmin(fabs(y - 0.3), fabs(x + 0.2)));
                    if (near < 1e-9)
                        continue;
                    bool want = k < 3    ? in_set(kinds[k], x, y, z)
                                : k == 4 ? in_ball(x, y, z, -0.5) && y < 0.3 && x > -0.2
                                         : in_set(GLINT_SHAPE_UNION, x, y, z) && x * x + y * y + z * z >= 0.16;
                    assert_int_equal(first_crossing_leaves(s, top, v3(x, y, z), d), want);
                    inside += want;
                    checked++;
                }
        assert_true(inside > 20 && inside < checked);
        glint_scene_free(s);
    }
}

enum { SIDE = 120 };
#define VIEW 4.0 /* units across the picture */

/* What an orthographic camera looking down -z sees of the two balls
 * combined by kind, white on black. */
static glint_image silhouette(glint_shape_kind kind)
{
    glint_scene *s = silhouette_scene(SIDE, VIEW);
    two_balls(kind, s, flat(s, 1, 1, 1));
    return render_and_free(s);
}

/* The silhouettes against the analytic sets, pixel by pixel: the union is
 * either disc, the lens both, and the crescent A - B the points of disc A
 * that B's chord does not cover: outside disc B, or left of x = 0 (where
 * A's chord is the longer). Pixels within half a pixel's diagonal of an
 * edge are left out. */
static void test_silhouettes_of_two_balls(void **state)
{
    const glint_shape_kind kinds[] = {GLINT_SHAPE_UNION, GLINT_SHAPE_INTERSECTION, GLINT_SHAPE_DIFFERENCE};
    const double px = VIEW / SIDE, margin = px * 0.75;
    for (int k = 0; k < 3; k++) {
        glint_image im = silhouette(kinds[k]);
        int white = 0;
        for (int j = 0; j < SIDE; j++)
            for (int i = 0; i < SIDE; i++) {
                double x = (i + 0.5) * px - VIEW / 2, y = VIEW / 2 - (j + 0.5) * px;
                double ra = sqrt((x + 0.5) * (x + 0.5) + y * y), rb = sqrt((x - 0.5) * (x - 0.5) + y * y);
                bool a = ra < 1, b = rb < 1;
                bool want = k == 0 ? a || b : k == 1 ? a && b : a && (!b || x < 0);
                bool edge = fabs(ra - 1) < margin || fabs(rb - 1) < margin || (k == 2 && fabs(x) < margin);
                float v = im.pixels[3 * (j * SIDE + i)];
                if (!edge)
                    assert_true(v == (want ? 1.0f : 0.0f));
                white += v > 0.5f;
            }
        /* Areas in pixels: a lens of two unit discs 1 apart has area
         * 2 acos(1/2) - sqrt(3)/2 (about 1.228), the union 2 pi less that. */
        double lens = 2 * acos(0.5) - sqrt(3) / 2, want_area = k == 0 ? 2 * M_PI - lens : k == 1 ? lens : M_PI - lens / 2;
        assert_near(white * px * px, want_area, 0.03);
        glint_image_free(&im);
    }
}

/* A biconvex lens made as the intersection of two balls of radius R = 1.2
 * whose centres are 1.8 apart (thickness d = 0.6, glass n = 1.5) brings
 * parallel light to a focus at its back focal length, from the lensmaker's
 * equation: 1/f = (n - 1)(2/R - (n - 1) d / (n R^2)), BFL = f (1 - (n - 1)
 * d / (n R)), 1.0909 past its back. An orthographic camera sees through
 * the lens's middle (within 0.05 of the axis) a small white disc there,
 * and only there: moved 10% nearer or farther, the outer rays miss it. */
static void test_lens_focuses_at_its_focal_length(void **state)
{
    const double n = 1.5, R = 1.2, d = 0.6;
    double f = 1 / ((n - 1) * (2 / R - (n - 1) * d / (n * R * R))), bfl = f * (1 - (n - 1) * d / (n * R));
    const double scales[] = {1, 0.9, 1.1};
    for (int k = 0; k < 3; k++) {
        glint_camera cam = {.kind = GLINT_CAMERA_ORTHOGRAPHIC, .position = {0, 0, 5}, .look_at = {0, 0, 0},
                            .up = {0, 1, 0}, .vfov_degrees = 40, .view_width = 0.1};
        glint_scene *s = one_sample_scene(9, 9, (glint_color){1, 1, 1}, cam);
        glint_settings st = glint_scene_get_settings(s);
        st.background = (glint_color){0, 0, 0};
        assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
        glint_material glass = glint_material_default();
        glass.ambient = glass.diffuse = glass.specular = 0;
        glass.refraction = 1;
        glass.ior = n;
        glass.tint = 0;
        int lens = add_combination(s, -1, GLINT_SHAPE_INTERSECTION, glint_scene_add_material(s, NULL, &glass, NULL));
        add_ball(s, lens, (glint_vec3){0, 0, -(R - d / 2)}, R, s->shapes[lens].material);
        add_ball(s, lens, (glint_vec3){0, 0, R - d / 2}, R, s->shapes[lens].material);
        glint_shape target = glint_shape_default(GLINT_SHAPE_DISK);
        target.center = (glint_vec3){0, 0, -d / 2 - bfl * scales[k]};
        target.normal = (glint_vec3){0, 0, 1};
        target.radius = 0.002;
        assert_true(glint_scene_add_shape(s, &target, flat(s, 1, 1, 1), NULL, NULL) >= 0);
        glint_image im;
        glint_render_options o = {.threads = 1};
        assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
        int white = 0;
        for (int i = 0; i < 81; i++)
            white += im.pixels[3 * i] > 0.5f;
        if (k == 0)
            assert_int_equal(white, 81);
        else
            assert_true(white < 20);
        glint_image_free(&im);
        glint_scene_free(s);
    }
}

/* Light through a glass combination is filtered at each crossing of its
 * surface, as through a plain ball: a lens between a light and the floor
 * lets f^2 through its middle, f = 0.8 * colour, the two surfaces it
 * crosses; a difference whose parts are of different glass filters by
 * each surface's own material. */
static void test_shadow_through_a_combination(void **state)
{
    glint_camera cam = {.position = {0, 8, 12}, .look_at = {0, 0, 0}, .up = {0, 1, 0}, .vfov_degrees = 20};
    for (int k = 0; k < 2; k++) {
        glint_scene *s = one_sample_scene(11, 11, (glint_color){1, 1, 1}, cam);
        glint_material white = glint_material_default();
        white.specular = 0;
        glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
        assert_true(glint_scene_add_shape(s, &floor, glint_scene_add_material(s, NULL, &white, NULL), NULL, NULL) >= 0);
        glint_light l = {.kind = GLINT_LIGHT_POINT, .position = {0, 10, 0}, .color = {1, 1, 1}};
        assert_true(glint_scene_add_light(s, &l, NULL) >= 0);
        glint_material amber = glint_material_default();
        amber.color = (glint_color){1, 0.5, 0.25};
        amber.ambient = amber.diffuse = amber.specular = 0;
        amber.transparency = 0.8;
        glint_material blue = amber;
        blue.color = (glint_color){0.25, 0.5, 1};
        int a = glint_scene_add_material(s, NULL, &amber, NULL), b = glint_scene_add_material(s, NULL, &blue, NULL);
        glint_shape_kind kind = k == 0 ? GLINT_SHAPE_INTERSECTION : GLINT_SHAPE_DIFFERENCE;
        int csg = add_combination(s, -1, kind, -1);
        /* The lens spans y 4.5..5.5; the difference is a ball from 4 to 6
         * with a bite from 5.5 up taken by a ball of the other glass. */
        add_ball(s, csg, (glint_vec3){0, k == 0 ? 4 : 5, 0}, k == 0 ? 1.5 : 1, a);
        add_ball(s, csg, (glint_vec3){0, k == 0 ? 6 : 6.5, 0}, k == 0 ? 1.5 : 1, k == 0 ? a : b);
        glint_image im;
        glint_render_options o = {.threads = 1};
        assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
        const float *c = im.pixels + 3 * (5 * 11 + 5);
        const double fa[3] = {0.8, 0.4, 0.2}, fb[3] = {0.2, 0.4, 0.8};
        for (int ch = 0; ch < 3; ch++)
            assert_near(c[ch], 0.2 + fa[ch] * (k == 0 ? fa[ch] : fb[ch]), 1e-5);
        glint_image_free(&im);
        glint_scene_free(s);
    }
}

/* A mirror ball shows the other ball of its union as it shows a ball
 * beside it that is no part of it: a ray leaving one part may meet
 * another. The image is the same either way, and the reflection is there. */
static void test_parts_see_each_other(void **state)
{
    glint_camera cam = {.kind = GLINT_CAMERA_PINHOLE, .position = {0, 0, 6}, .look_at = {-1, 0, 0},
                        .up = {0, 1, 0}, .vfov_degrees = 30};
    glint_image im[2];
    for (int k = 0; k < 2; k++) {
        glint_scene *s = one_sample_scene(32, 32, (glint_color){1, 1, 1}, cam);
        glint_material mirror = glint_material_default();
        mirror.color = (glint_color){0, 0, 0};
        mirror.ambient = mirror.diffuse = mirror.specular = 0;
        mirror.reflectivity = 1;
        int shiny = glint_scene_add_material(s, NULL, &mirror, NULL), white = flat(s, 1, 1, 1);
        int csg = k ? add_combination(s, -1, GLINT_SHAPE_UNION, -1) : -1;
        add_ball(s, csg, (glint_vec3){-1.2, 0, 0}, 1, shiny);
        add_ball(s, csg, (glint_vec3){1.2, 0, 0}, 1, white);
        glint_render_options o = {.threads = 1};
        assert_int_equal(glint_render(s, &o, &im[k], NULL, NULL), GLINT_OK);
        glint_scene_free(s);
    }
    int reflected = 0;
    for (int i = 0; i < 3 * 32 * 32; i++) {
        assert_true(im[1].pixels[i] == im[0].pixels[i]);
        reflected += i % 3 == 0 && im[0].pixels[i] == 1 && (i / 3) % 32 < 24; /* left of the white ball */
    }
    assert_true(reflected > 0);
    glint_image_free(&im[0]);
    glint_image_free(&im[1]);
}

/* A number in [-1, 1) from a small xorshift generator. */
static double unit_noise(uint32_t *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 17;
    *state ^= *state << 5;
    return *state / 2147483648.0 - 1;
}

static int add_part(glint_scene *s, int csg, glint_shape sh, const glint_transform *xf, int mat)
{
    glint_error err;
    int i = glint_scene_add_part(s, csg, &sh, mat, xf, &err);
    if (i < 0)
        fail_msg("%s", err.message);
    return i;
}

/* A die as bench/csg.yaml makes it, turned and moved: a cube rounded by a
 * ball (an intersection) minus three pips, all placed by one transform. */
static int add_die(glint_scene *s, const glint_transform *xf, int ivory, int pip)
{
    int die = add_combination(s, -1, GLINT_SHAPE_DIFFERENCE, -1);
    int rounded = add_combination(s, die, GLINT_SHAPE_INTERSECTION, -1);
    glint_shape cube = glint_shape_default(GLINT_SHAPE_BOX), ball = glint_shape_default(GLINT_SHAPE_SPHERE);
    cube.min = (glint_vec3){-0.4, -0.4, -0.4};
    cube.max = (glint_vec3){0.4, 0.4, 0.4};
    ball.radius = 0.55;
    add_part(s, rounded, cube, xf, ivory);
    add_part(s, rounded, ball, xf, ivory);
    const glint_vec3 pips[3] = {{0, 0.46, 0}, {-0.2, 0.2, 0.46}, {0.46, 0.1, 0.1}};
    for (int i = 0; i < 3; i++) {
        ball.center = pips[i];
        ball.radius = 0.09;
        add_part(s, die, ball, xf, pip);
    }
    return die;
}

/* Combinations of still balls and boxes find their hits four lanes at a
 * time (shape_intersect4), each lane bit for bit what shape_intersect
 * finds one ray at a time: the hit's t, part (flipped where a difference
 * cut it) and leaf, for rays from outside and inside, across a die, a
 * union of a turned box and a ball, a lens, a difference of two
 * intersections, and an intersection whose parts miss each other (a
 * difference's lanes whose cut parts lie clear of its first part skip the
 * walk, so the die checks that shortcut against the walk too). A
 * combination holding a cylinder, or a part that moves, takes lanes one at
 * a time. */
static void test_four_lanes_match_one(void **state)
{
    glint_scene *s = glint_scene_new();
    int ivory = flat(s, 1, 1, 1), pip = flat(s, 0, 0, 0);
    glint_transform turned = glint_transform_rotate(glint_transform_identity(), (glint_vec3){0, 1, 0}, 23);
    turned = glint_transform_rotate(turned, (glint_vec3){1, 0, 0}, 31);
    turned = glint_transform_translate(turned, 0.2, -0.1, 0.3);
    int die = add_die(s, &turned, ivory, pip);
    int both = add_combination(s, -1, GLINT_SHAPE_UNION, -1);
    glint_shape cube = glint_shape_default(GLINT_SHAPE_BOX);
    cube.min = (glint_vec3){-0.6, -0.3, -0.5};
    cube.max = (glint_vec3){0.2, 0.5, 0.4};
    add_part(s, both, cube, &turned, ivory);
    add_ball(s, both, (glint_vec3){0.3, 0.1, 0}, 0.5, pip);
    int lens = add_combination(s, -1, GLINT_SHAPE_INTERSECTION, -1);
    add_ball(s, lens, (glint_vec3){0, 0, 0.7}, 1, ivory);
    add_ball(s, lens, (glint_vec3){0, 0, -0.7}, 1, pip);
    int cut = add_combination(s, -1, GLINT_SHAPE_DIFFERENCE, -1);
    int outer = add_combination(s, cut, GLINT_SHAPE_INTERSECTION, -1), inner = add_combination(s, cut, GLINT_SHAPE_INTERSECTION, -1);
    add_part(s, outer, cube, NULL, ivory);
    add_ball(s, outer, (glint_vec3){-0.2, 0.1, 0}, 0.6, ivory);
    add_ball(s, inner, (glint_vec3){-0.2, 0.3, 0.1}, 0.4, pip);
    add_part(s, inner, cube, &turned, pip);
    int apart = add_combination(s, -1, GLINT_SHAPE_INTERSECTION, -1);
    add_ball(s, apart, (glint_vec3){-0.6, 0, 0}, 0.5, ivory);
    add_ball(s, apart, (glint_vec3){0.6, 0, 0}, 0.5, pip);
    const int quads[] = {die, both, lens, cut, apart};
    uint32_t seed = 7;
    for (int c = 0; c < 5; c++) {
        const shape *sh = &s->shapes[quads[c]];
        assert_true(shape_has_intersect4(sh));
        int hits = 0, misses = 0, flipped = 0;
        for (int round = 0; round < 2000; round++) {
            ray8 r;
            double tmax[RAY8];
            for (int i = 0; i < RAY8; i++) {
                /* From a unit or two away, or from inside, towards a
                 * point within the combination's reach. */
                double reach = round % 4 ? 2.5 : 0.3;
                vec3 o = v3(reach * unit_noise(&seed), reach * unit_noise(&seed), reach * unit_noise(&seed));
                vec3 aim = v3(0.7 * unit_noise(&seed), 0.7 * unit_noise(&seed), 0.7 * unit_noise(&seed));
                ray8_set(&r, i, (ray){o, v3_sub(aim, o)});
                tmax[i] = i % 3 ? INFINITY : 1 + unit_noise(&seed);
            }
            for (int q = 0; q < RAY8; q += QUAD) {
                quad_hit qh;
                quad_mask m = shape_intersect4(sh, &r, q, quad_load(tmax + q), &qh);
                for (int k = 0; k < QUAD; k++) {
                    ray one = ray8_get(&r, q + k);
                    shape_hit h;
                    bool want = shape_intersect(sh, &one, 0, tmax[q + k], &h);
                    assert_int_equal(m[k] != 0, want);
                    if (!want) {
                        misses++;
                        continue;
                    }
                    double t = qh.t[k];
                    assert_memory_equal(&t, &h.t, sizeof t);
                    assert_int_equal(qh.part[k], h.part);
                    assert_int_equal(qh.leaf[k], h.leaf);
                    hits++;
                    flipped += (h.part & SHAPE_PART_FLIPPED) != 0;
                }
            }
        }
        /* The balls of `apart` share no point: nothing to hit. */
        assert_true(quads[c] == apart ? hits == 0 : hits > 1000);
        assert_true(misses > 1000);
        if (quads[c] == die || quads[c] == cut)
            assert_true(flipped > 20);
    }
    int mixed = add_combination(s, -1, GLINT_SHAPE_UNION, -1);
    add_ball(s, mixed, (glint_vec3){0, 0, 0}, 1, ivory);
    glint_shape tube = glint_shape_default(GLINT_SHAPE_CYLINDER);
    tube.radius = tube.height = 1;
    add_part(s, mixed, tube, NULL, ivory);
    assert_false(shape_has_intersect4(&s->shapes[mixed]));
    int rolling = add_combination(s, -1, GLINT_SHAPE_UNION, -1);
    int ball = add_ball(s, rolling, (glint_vec3){0, 0, 0}, 1, ivory);
    add_ball(s, rolling, (glint_vec3){1, 0, 0}, 1, ivory);
    assert_true(shape_has_intersect4(&s->shapes[rolling]));
    glint_transform poses[2] = {glint_transform_identity(), glint_transform_translate(glint_transform_identity(), 0, 1, 0)};
    glint_error err;
    assert_int_equal(glint_scene_move_shape(s, ball, 2, poses, &err), GLINT_OK);
    assert_false(shape_has_intersect4(&s->shapes[rolling]));
    glint_scene_free(s);
}

/* A ray leaving a combination's surface where that surface is a convex
 * part's own, within which the whole combination lies, never meets the
 * combination again, so it may skip it (shape_left_behind_by): the die's
 * rounded cube (a difference's first part, an intersection), not its
 * pips' hollows, nor a union's parts, nor a torus's. Checked from hits all
 * over a turned die, in many directions: every leaving ray that skips the
 * die meets it nowhere, and the hollows are seen and never skipped. */
static void test_leaving_skips_the_die(void **state)
{
    glint_scene *s = glint_scene_new();
    int ivory = flat(s, 1, 1, 1), pip = flat(s, 0, 0, 0);
    glint_transform turned = glint_transform_rotate(glint_transform_identity(), (glint_vec3){0, 1, 0}, 23);
    turned = glint_transform_rotate(turned, (glint_vec3){1, 0, 0}, 31);
    int die = add_die(s, &turned, ivory, pip);
    const shape *d = &s->shapes[die];
    int rounded = d->parts[0], cube = s->shapes[rounded].parts[0], first_pip = d->parts[1];
    bool always, when_leaving;
    assert_int_equal(shape_left_behind_by(s->shapes, cube, &always, &when_leaving), die);
    assert_false(always);
    assert_true(when_leaving);
    assert_int_equal(shape_left_behind_by(s->shapes, first_pip, &always, &when_leaving), -1);
    assert_false(always || when_leaving);
    int both = add_combination(s, -1, GLINT_SHAPE_UNION, -1);
    int one_of_two = add_ball(s, both, (glint_vec3){4, 0, 0}, 1, ivory);
    add_ball(s, both, (glint_vec3){5, 0, 0}, 1, ivory);
    assert_int_equal(shape_left_behind_by(s->shapes, one_of_two, &always, &when_leaving), -1);
    int ring = add_combination(s, -1, GLINT_SHAPE_DIFFERENCE, -1);
    glint_shape torus = glint_shape_default(GLINT_SHAPE_TORUS);
    torus.radius = 1;
    torus.minor_radius = 0.25;
    int tube = add_part(s, ring, torus, NULL, ivory);
    add_ball(s, ring, (glint_vec3){2, 0, 0}, 0.5, ivory);
    assert_int_equal(shape_left_behind_by(s->shapes, tube, &always, &when_leaving), -1);
    /* A ball standing alone is its own rule's. */
    int alone = add_ball(s, -1, (glint_vec3){9, 0, 0}, 1, ivory);
    assert_int_equal(shape_left_behind_by(s->shapes, alone, &always, &when_leaving), alone);
    assert_true(when_leaving && !always);

    d = &s->shapes[die];
    uint32_t seed = 11;
    int skipped = 0, hollows = 0;
    for (int round = 0; round < 4000; round++) {
        vec3 o = v3_scale(v3(unit_noise(&seed), unit_noise(&seed), unit_noise(&seed)), 3);
        vec3 aim = v3_scale(v3(unit_noise(&seed), unit_noise(&seed), unit_noise(&seed)), 0.45);
        ray in = {o, v3_sub(aim, o)};
        shape_hit h;
        if (!shape_intersect(d, &in, 0, INFINITY, &h))
            continue;
        surface sf;
        shape_surface(&s->shapes[h.leaf], &in, &h, &sf);
        int skip = shape_left_behind_by(s->shapes, h.leaf, &always, &when_leaving);
        hollows += (h.part & SHAPE_PART_FLIPPED) != 0;
        if ((h.part & SHAPE_PART_FLIPPED) != 0)
            assert_int_equal(skip, -1);
        for (int b = 0; b < 8 && skip >= 0; b++) {
            vec3 dir = v3_normalize(v3(unit_noise(&seed), unit_noise(&seed), unit_noise(&seed)));
            if (!(v3_dot(sf.n, dir) > 1e-3))
                continue;
            ray leave = {sf.p, dir};
            shape_hit again;
            if (shape_intersect(d, &leave, 1e-9, INFINITY, &again))
                fail_msg("the die met again at t = %g", again.t);
            skipped++;
        }
    }
    assert_true(skipped > 2000);
    assert_true(hollows > 10);
    glint_scene_free(s);
}

/* What a combination refuses, in words: a part that is not closed, a part
 * of something that is not a combination, a transform of its own, and a
 * part that would move. */
static void test_refusals(void **state)
{
    glint_scene *s = glint_scene_new();
    int mat = flat(s, 1, 1, 1), csg = add_combination(s, -1, GLINT_SHAPE_UNION, -1), ball = add_ball(s, csg, (glint_vec3){0, 0, 0}, 1, mat);
    glint_error err;
    glint_shape disk = glint_shape_default(GLINT_SHAPE_DISK);
    disk.radius = 1;
    assert_int_equal(glint_scene_add_part(s, csg, &disk, mat, NULL, &err), -1);
    assert_string_equal(err.message, "a disk is not closed, so it cannot be a part of a union (a cylinder or cone "
                                     "needs its caps)");
    glint_shape tube = glint_shape_default(GLINT_SHAPE_CYLINDER);
    tube.radius = tube.height = 1;
    tube.capped = false;
    assert_int_equal(glint_scene_add_part(s, csg, &tube, mat, NULL, &err), -1);
    tube.capped = true;
    assert_true(glint_scene_add_part(s, csg, &tube, mat, NULL, &err) >= 0);
    assert_int_equal(glint_scene_add_part(s, ball, &tube, mat, NULL, &err), -1);
    assert_string_equal(err.message, "shape 1 is not a union, intersection or difference");
    glint_shape inner = glint_shape_default(GLINT_SHAPE_DIFFERENCE);
    glint_transform up = glint_transform_translate(glint_transform_identity(), 0, 1, 0);
    assert_int_equal(glint_scene_add_part(s, csg, &inner, -1, &up, &err), -1);
    assert_string_equal(err.message, "a difference takes no transform: its parts carry theirs");
    glint_transform poses[2] = {up, glint_transform_identity()};
    assert_int_equal(glint_scene_move_shape(s, csg, 2, poses, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "a union cannot move over the shutter: move its parts");
    assert_int_equal(glint_scene_move_shape(s, ball, 2, poses, &err), GLINT_OK);
    assert_int_equal(glint_scene_add_shape(s, &disk, -1, NULL, &err), -1);
    assert_string_equal(err.message, "material -1 does not exist");
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inside_outside_on_a_grid),
        cmocka_unit_test(test_silhouettes_of_two_balls),
        cmocka_unit_test(test_lens_focuses_at_its_focal_length),
        cmocka_unit_test(test_shadow_through_a_combination),
        cmocka_unit_test(test_parts_see_each_other),
        cmocka_unit_test(test_four_lanes_match_one),
        cmocka_unit_test(test_leaving_skips_the_die),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
