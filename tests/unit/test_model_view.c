/* test_model_view.c - the scene glint_scene_for_model_ex builds around a
 * model: its camera looks from the view asked for, and the 8 corners of the
 * model's bounding box, projected through that camera as the pinhole
 * camera projects them, are centred in the picture and span 85% of its
 * width or height, whichever limits, for every view and picture shape; a
 * room open on one side is looked into straight through its opening and is
 * lit inside, and models that are no such room are seen from the front. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "glint.h"
#include "core/vec.h"
#include "tmp_tree.h"

static char dir[2048]; /* short enough that dir/name fits a path of 4096 */

static int setup(void **state)
{
    (void)state;
    return make_tmp_tree(dir, sizeof dir, "model_view");
}

static int teardown(void **state)
{
    (void)state;
    remove_tree(dir);
    return 0;
}

/* Writes text to dir/name; the path is left in path. */
static void write_file(char *path, size_t size, const char *name, const char *text)
{
    snprintf(path, size, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

typedef struct text {
    char s[8192];
    size_t n;
} text;

static void add(text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    t->n += (size_t)vsnprintf(t->s + t->n, sizeof t->s - t->n, fmt, ap);
    va_end(ap);
    assert_true(t->n < sizeof t->s);
}

/* Adds to t the faces of the box [lo, hi] but the sides in the mask `open`
 * (bit 2 * axis + 1 for the + side, 2 * axis for the - side), as quads;
 * vertices count from *v. */
static void add_box(text *t, const double lo[3], const double hi[3], unsigned open, int *v)
{
    for (int side = 0; side < 6; side++) {
        if (open & (1u << side))
            continue;
        int axis = side / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (int k = 0; k < 4; k++) {
            double p[3];
            p[axis] = side % 2 ? hi[axis] : lo[axis];
            p[a] = (k == 1 || k == 2) ? hi[a] : lo[a];
            p[b] = k >= 2 ? hi[b] : lo[b];
            add(t, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
        }
        add(t, "f %d %d %d %d\n", *v, *v + 1, *v + 2, *v + 3);
        *v += 4;
    }
}

/* The room every open-box test uses: 2 x 1.5 x 1.2, away from the origin,
 * with a block in one corner, white (Kd 1, no highlight). */
static const double ROOM_LO[3] = {3, -1, 5}, ROOM_HI[3] = {5, 0.5, 6.2};

/* Writes a model file: the room open on the sides in the mask `open` (0:
 * a closed box), and its material; returns the path in path. */
static void write_room(char *path, size_t size, unsigned open)
{
    char mtl[4096];
    write_file(mtl, sizeof mtl, "room.mtl", "newmtl white\nKd 1 1 1\nKs 0 0 0\n");
    text t = {.n = 0};
    add(&t, "mtllib room.mtl\nusemtl white\n");
    int v = 1;
    add_box(&t, ROOM_LO, ROOM_HI, open, &v);
    double lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
        lo[k] = ROOM_LO[k] + 0.05 * (ROOM_HI[k] - ROOM_LO[k]);
        hi[k] = ROOM_LO[k] + 0.25 * (ROOM_HI[k] - ROOM_LO[k]);
    }
    add_box(&t, lo, hi, 0, &v);
    char name[32];
    snprintf(name, sizeof name, "room%u.obj", open);
    write_file(path, size, name, t.s);
}

static glint_scene *model_scene(const char *path, glint_model_view view, int width, int height)
{
    glint_model_view_options o = {.view = view, .width = width, .height = height};
    glint_error err = {0};
    glint_scene *s = glint_scene_for_model_ex(path, &o, &err);
    if (!s)
        fail_msg("%s: %s", path, err.message);
    return s;
}

/* The camera's frame as the pinhole camera builds it. */
typedef struct frame {
    glint_vec3 forward, right, up;
} frame;

static frame camera_frame(const glint_camera *c)
{
    frame f;
    f.forward = v3_normalize(v3_sub(c->look_at, c->position));
    f.right = v3_normalize(v3_cross(f.forward, c->up));
    f.up = v3_cross(f.right, f.forward);
    return f;
}

/* Checks that the model's bounding box, projected, is centred in s's
 * picture within 0.5% of its size and spans 85% of its width or height,
 * within 0.5%, and no more of the other. */
static void assert_framed(const glint_scene *s)
{
    glint_vec3 lo, hi;
    assert_int_equal(glint_scene_mesh_bounds(s, 0, &lo, &hi, NULL), GLINT_OK);
    glint_camera c = glint_scene_get_camera(s);
    glint_settings st = glint_scene_get_settings(s);
    frame f = camera_frame(&c);
    double ty = tan(c.vfov_degrees * M_PI / 360), tx = ty * st.width / st.height;
    double least[2] = {INFINITY, INFINITY}, most[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 8; i++) {
        glint_vec3 p = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        glint_vec3 d = v3_sub(p, c.position);
        double depth = v3_dot(d, f.forward);
        assert_true(depth > 0);
        double q[2] = {v3_dot(d, f.right) / (depth * tx), v3_dot(d, f.up) / (depth * ty)};
        for (int k = 0; k < 2; k++) {
            least[k] = fmin(least[k], q[k]);
            most[k] = fmax(most[k], q[k]);
        }
    }
    /* The picture spans -1..1 across and up: 0.01 is 0.5% of it. */
    for (int k = 0; k < 2; k++) {
        if (fabs(least[k] + most[k]) > 0.01)
            fail_msg("not centred on axis %d: %g..%g", k, least[k], most[k]);
        assert_true(most[k] - least[k] <= 2 * 0.85 + 0.01);
    }
    double span = fmax(most[0] - least[0], most[1] - least[1]);
    if (fabs(span - 2 * 0.85) > 0.01)
        fail_msg("spans %g of the picture, not 0.85", span / 2);
}

/* Checks that s's camera looks along `along` (any length) with `up` up. */
static void assert_looks(const glint_scene *s, glint_vec3 along, glint_vec3 up)
{
    glint_camera c = glint_scene_get_camera(s);
    frame f = camera_frame(&c);
    if (v3_dot(f.forward, v3_normalize(along)) < 1 - 1e-9)
        fail_msg("looks along (%g, %g, %g), not (%g, %g, %g)", f.forward.x, f.forward.y, f.forward.z, along.x,
                 along.y, along.z);
    assert_true(v3_dot(f.up, v3_normalize(up)) > 0.5);
}

/* Where each named view looks along (from the camera to the model), and
 * its up: 20 degrees above the horizon, the top view with -z up. */
static void view_direction(glint_model_view v, glint_vec3 *along, glint_vec3 *up)
{
    double c = cos(20 * M_PI / 180), s = sin(20 * M_PI / 180);
    *up = (glint_vec3){0, 1, 0};
    switch (v) {
    case GLINT_VIEW_BACK: *along = (glint_vec3){0, -s, c}; break;
    case GLINT_VIEW_LEFT: *along = (glint_vec3){c, -s, 0}; break;
    case GLINT_VIEW_RIGHT: *along = (glint_vec3){-c, -s, 0}; break;
    case GLINT_VIEW_TOP:
        *along = (glint_vec3){0, -1, 0};
        *up = (glint_vec3){0, 0, -1};
        break;
    case GLINT_VIEW_ISO: *along = (glint_vec3){-1, -1, -1}; break;
    default: *along = (glint_vec3){0, -s, -c}; break; /* front, and auto for what is no room */
    }
}

/* The model at path, with the automatic view, is seen from the front and
 * framed. */
static void assert_seen_from_front(const char *path)
{
    glint_scene *s = model_scene(path, GLINT_VIEW_AUTO, 0, 0);
    glint_vec3 along, up;
    view_direction(GLINT_VIEW_FRONT, &along, &up);
    assert_looks(s, along, up);
    assert_framed(s);
    glint_scene_free(s);
}

/* Renders s with one sample per pixel into *img. */
static void render_one_sample(glint_scene *s, glint_image *img)
{
    glint_settings st = glint_scene_get_settings(s);
    st.samples_per_pixel = 1;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_error err = {0};
    if (glint_render(s, NULL, img, NULL, &err))
        fail_msg("%s", err.message);
}

/* Every view of a model, in pictures of three shapes (the default 4:3, tall
 * and wide): framed, and from where the view says. */
static void assert_every_view(const char *path)
{
    static const int SIZES[3][2] = {{0, 0}, {300, 600}, {1000, 200}};
    for (int v = GLINT_VIEW_AUTO; v <= GLINT_VIEW_ISO; v++)
        for (int k = 0; k < 3; k++) {
            glint_scene *s = model_scene(path, (glint_model_view)v, SIZES[k][0], SIZES[k][1]);
            glint_vec3 along, up;
            view_direction((glint_model_view)v, &along, &up);
            assert_looks(s, along, up);
            assert_framed(s);
            glint_settings st = glint_scene_get_settings(s);
            assert_int_equal(st.width, k ? SIZES[k][0] : 800);
            assert_int_equal(st.height, k ? SIZES[k][1] : 600);
            glint_scene_free(s);
        }
}

/* A closed box (a model with six walls is no room) and a small mesh that
 * is not a box at all. */
static void test_every_view_frames_the_model(void **state)
{
    (void)state;
    char path[4096];
    write_room(path, sizeof path, 0);
    assert_every_view(path);
    write_file(path, sizeof path, "wedge.obj",
               "v -1 0 0\nv 3 0 0\nv 0 2 0\nv 0 0 -0.5\nf 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n");
    assert_every_view(path);
}

/* The room, open on each side in turn, is seen straight in through its
 * opening (from above or below, with -z up), framed; a view named
 * explicitly is that view all the same. */
static void test_room_seen_through_its_opening(void **state)
{
    (void)state;
    for (int side = 0; side < 6; side++) {
        char path[4096];
        write_room(path, sizeof path, 1u << side);
        glint_scene *s = model_scene(path, GLINT_VIEW_AUTO, 0, 0);
        double in = side % 2 ? -1 : 1;
        glint_vec3 along = {side / 2 == 0 ? in : 0, side / 2 == 1 ? in : 0, side / 2 == 2 ? in : 0};
        glint_vec3 up = side / 2 == 1 ? (glint_vec3){0, 0, -1} : (glint_vec3){0, 1, 0};
        assert_looks(s, along, up);
        assert_framed(s);
        glint_scene_free(s);
        s = model_scene(path, GLINT_VIEW_FRONT, 0, 0);
        view_direction(GLINT_VIEW_FRONT, &along, &up);
        assert_looks(s, along, up);
        glint_scene_free(s);
    }
}

/* What is no room open on one side is seen from the front: a box open on
 * two opposite sides (a tube), one open on two sides that meet, a flat
 * square, a single triangle. */
static void test_not_rooms_seen_from_the_front(void **state)
{
    (void)state;
    char path[4096];
    static const unsigned OPEN[] = {(1u << 4) | (1u << 5), (1u << 5) | (1u << 3)};
    for (size_t k = 0; k < 2; k++) {
        write_room(path, sizeof path, OPEN[k]);
        assert_seen_from_front(path);
    }
    static const char *const FLAT[] = {"v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"};
    for (size_t k = 0; k < 2; k++) {
        write_file(path, sizeof path, "flat.obj", FLAT[k]);
        assert_seen_from_front(path);
    }
}

/* The room open at +z, rendered: the pixel at the picture's centre sees
 * the back wall (white, no highlight) lit by the point light just outside
 * the opening's centre, 30% of the room's height up, and by the ambient
 * term; the key and fill lights are kept out by the walls. */
static void test_room_lit_inside(void **state)
{
    (void)state;
    char path[4096];
    write_room(path, sizeof path, 1u << 5);
    /* Odd sizes: the centre pixel's one sample is on the view's axis. */
    glint_scene *s = model_scene(path, GLINT_VIEW_AUTO, 81, 61);
    glint_camera c = glint_scene_get_camera(s);
    glint_vec3 d = v3_normalize(v3_sub(c.look_at, c.position));
    double t = (ROOM_LO[2] - c.position.z) / d.z;
    glint_vec3 wall = {c.position.x + t * d.x, c.position.y + t * d.y, ROOM_LO[2]};
    double depth = ROOM_HI[2] - ROOM_LO[2], height = ROOM_HI[1] - ROOM_LO[1];
    glint_vec3 light = {0.5 * (ROOM_LO[0] + ROOM_HI[0]), 0.5 * (ROOM_LO[1] + ROOM_HI[1]) + 0.3 * height,
                        ROOM_HI[2] + 0.05 * depth};
    double lit = 0.2 + 0.8 * v3_normalize(v3_sub(light, wall)).z;
    glint_image img;
    render_one_sample(s, &img);
    const float *centre = img.pixels + 3 * (30 * 81 + 40);
    for (int k = 0; k < 3; k++)
        if (fabs(centre[k] - lit) > 1e-5)
            fail_msg("the back wall is %g, not %g", centre[k], lit);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* The lights turn with the view: a cube about the y axis seen from the
 * front, back, left and right looks the same at the picture's centre (with
 * lights fixed in the world, the back view would see the unlit side). */
static void test_lights_follow_the_view(void **state)
{
    (void)state;
    static const double LO[3] = {-1, 0, -1}, HI[3] = {1, 2, 1};
    text t = {.n = 0};
    int v = 1;
    add_box(&t, LO, HI, 0, &v);
    char path[4096];
    write_file(path, sizeof path, "cube.obj", t.s);
    float first[3] = {0};
    for (int view = GLINT_VIEW_FRONT; view <= GLINT_VIEW_RIGHT; view++) {
        glint_scene *s = model_scene(path, (glint_model_view)view, 41, 31);
        glint_image img;
        render_one_sample(s, &img);
        const float *centre = img.pixels + 3 * (15 * 41 + 20);
        for (int k = 0; k < 3; k++) {
            if (view == GLINT_VIEW_FRONT)
                first[k] = centre[k];
            else if (fabsf(centre[k] - first[k]) > 1e-5f)
                fail_msg("view %d: the centre is %g, from the front %g", view, centre[k], first[k]);
        }
        assert_true(first[0] > 0.25f); /* lit by the key light (the ambient term alone: 0.1) */
        glint_image_free(&img);
        glint_scene_free(s);
    }
}

/* Opens $GLINT_SHARED_DATA/name into path, or skips when it is absent. */
static void shared_model(char *path, size_t size, const char *name)
{
    const char *data = getenv("GLINT_SHARED_DATA");
    snprintf(path, size, "%s/%s", data ? data : "", name);
    FILE *f = data ? fopen(path, "r") : NULL;
    if (!f)
        skip();
    fclose(f);
}

static void test_teapot_every_view(void **state)
{
    (void)state;
    char path[4096];
    shared_model(path, sizeof path, "teapot.obj");
    assert_every_view(path);
}

static void test_bunny_from_the_front(void **state)
{
    (void)state;
    char path[4096];
    shared_model(path, sizeof path, "stanford-bunny.obj");
    assert_seen_from_front(path);
}

/* The Cornell box is open at +z: seen straight in, framed, and its back
 * wall lit by the box's own warm lamp (Ke 17 12 4) and no light of the
 * view's: the ambient term alone gives the wall 0.2 of its colour (Kd
 * 0.725 in sRGB, 0.48 linear), 0.1 in every channel; the lamp adds more
 * red than blue. */
static void test_cornell_box_seen_inside(void **state)
{
    (void)state;
    char path[4096];
    shared_model(path, sizeof path, "CornellBox-Original.obj");
    glint_scene *s = model_scene(path, GLINT_VIEW_AUTO, 81, 61);
    assert_looks(s, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0});
    assert_framed(s);
    glint_image img;
    render_one_sample(s, &img);
    /* Up from the centre, above the tall block: the back wall. */
    const float *wall = img.pixels + 3 * (15 * 81 + 40);
    if (!(wall[0] > 0.12f && wall[0] > wall[1] + 0.01f && wall[1] > wall[2] + 0.01f))
        fail_msg("the back wall is %g, %g, %g", wall[0], wall[1], wall[2]);
    assert_int_equal(glint_scene_get_counts(s).lights, 0);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* A view that is none of glint_model_view's is refused, naming it. */
static void test_unknown_view_refused(void **state)
{
    (void)state;
    char path[4096];
    write_room(path, sizeof path, 0);
    glint_model_view_options o = {.view = (glint_model_view)7};
    glint_error err = {0};
    assert_null(glint_scene_for_model_ex(path, &o, &err));
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    assert_string_equal(err.message, "model view 7 is not a glint_model_view");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_view_frames_the_model),
        cmocka_unit_test(test_room_seen_through_its_opening),
        cmocka_unit_test(test_not_rooms_seen_from_the_front),
        cmocka_unit_test(test_room_lit_inside),
        cmocka_unit_test(test_lights_follow_the_view),
        cmocka_unit_test(test_teapot_every_view),
        cmocka_unit_test(test_bunny_from_the_front),
        cmocka_unit_test(test_cornell_box_seen_inside),
        cmocka_unit_test(test_unknown_view_refused),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
