/* test_nff.c - the NFF reader: every entity of a small file mapped onto
 * glint's settings, camera, materials, lights and shapes as docs/nff.md
 * says; a rendered sphere against the background; the broken files, each
 * with its exact message; and the seven SPD scenes, which load with the
 * number of primitives each is made of and look like the SPD's own
 * renderings (skipped without the shared data). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "core/transform.h"
#include "image/srgb.h"
#include "image/texture_image.h"
#include "scene/scene.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

static const char VIEW[] = "v\nfrom 0 -5 1\nat 0 0 0.5\nup 0 0 1\nangle 40\nhither 0.1\nresolution 8 6\n";

static glint_scene *load(const char *text, glint_error *err)
{
    return glint_scene_load_memory(text, strlen(text), "t.nff", NULL, err);
}

/* Every entity: the view's camera and size, the background, lights with
 * and without colour (each sqrt(L) / (2 L) of it; no ambient light),
 * a fill's material, a sphere (its radius's size), a cone and a cylinder along their axes,
 * open, a polygon and a smooth patch. */
static void test_every_entity(void **state)
{
    char text[1024];
    snprintf(text, sizeof text,
             "%s# a comment\nb 0.5 0 1\nl 3 -4 5\nl -3 -4 5 0.5 1 1  # coloured\n"
             "f 1 0.5 0.2 0.8 0.3 20 0.25 1.5\ns 0 0 0.5 -0.5\nc 1 0 0 0.3 1 0 2 0.1\nc -1 0 0 0.2 -1 2 0 0.2\n"
             "p 4\n-2 -2 0\n2 -2 0\n2 2 0\n-2 2 0\npp 3\n0 0 1 0 0 1\n1 0 1 0 0 1\n0 1 1 0 0 1\n",
             VIEW);
    glint_error err;
    glint_scene *s = load(text, &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_int_equal(s->settings.width, 8);
    assert_int_equal(s->settings.height, 6);
    assert_int_equal(s->settings.samples_per_pixel, 1);
    assert_int_equal(s->settings.max_depth, 5);
    assert_near(s->settings.background.r, glint_srgb_to_linear(0.5), 1e-15);
    assert_true(s->settings.background.g == 0 && s->settings.background.b == 1);
    double share = sqrt(2) / 4;
    assert_true(s->settings.ambient_light.r == 0 && s->settings.ambient_light.g == 0);
    /* 40 degrees between the middles of the top and bottom rows of 6. */
    assert_near(s->camera.vfov_degrees, 2 * atan(tan(20 * M_PI / 180) * 6 / 5) * 180 / M_PI, 1e-12);
    assert_near(s->camera.position.y, -5, 0);
    assert_int_equal(s->light_count, 2);
    assert_near(s->lights[0].desc.color.g, share, 1e-15);
    assert_near(s->lights[1].desc.color.r, share * glint_srgb_to_linear(0.5), 1e-15);
    assert_near(s->lights[1].desc.color.b, share, 1e-15);
    assert_int_equal(s->material_count, 1);
    const glint_material *m = &s->materials[0].m;
    assert_near(m->color.g, glint_srgb_to_linear(0.5), 1e-15);
    assert_true(m->diffuse == 0.8 && m->specular == 0.3 && m->reflectivity == 0.3 && m->shininess == 20);
    assert_true(m->refraction == 0.25 && m->ior == 1.5 && m->transparency == 0 && m->tint == 1);
    /* The spheres are one sphere set, added last. */
    assert_int_equal(s->shape_count, 3);
    const sphere_set *balls = s->shapes[2].set;
    assert_non_null(balls);
    assert_int_equal(balls->count, 1);
    assert_true(balls->balls[0][2] == 0.5 && balls->balls[0][3] == 0.5 && balls->materials[0] == 0);
    const shape *cone = &s->shapes[0], *tube = &s->shapes[1];
    assert_int_equal(cone->desc.kind, GLINT_SHAPE_CONE);
    assert_true(cone->desc.radius == 0.3 && cone->desc.top_radius == 0.1 && cone->desc.height == 2);
    assert_false(cone->desc.capped || cone->desc.top_capped);
    vec3 apex = xf_point(&cone->to_world, v3(0, 2, 0)), rim = xf_point(&cone->to_world, v3(0.3, 0, 0));
    assert_near(apex.x, 1, 1e-15);
    assert_near(apex.z, 2, 1e-15);
    assert_near(sqrt((rim.x - 1) * (rim.x - 1) + rim.y * rim.y + rim.z * rim.z), 0.3, 1e-15);
    assert_int_equal(tube->desc.kind, GLINT_SHAPE_CYLINDER);
    assert_false(tube->desc.capped);
    vec3 top = xf_point(&tube->to_world, v3(0, 2, 0));
    assert_near(top.x, -1, 1e-15);
    assert_near(top.y, 2, 1e-15);
    /* The polygons of a fill are one flat mesh, its patches one smooth. */
    assert_int_equal(s->mesh_count, 2);
    assert_int_equal(s->meshes[0].triangle_count, 2);
    assert_null(s->meshes[0].normals);
    assert_int_equal(s->meshes[1].triangle_count, 1);
    assert_non_null(s->meshes[1].normals);
    glint_scene_free(s);
}

/* A white sphere filling the middle of the frame, lit from the eye, is
 * half its light where it faces it; a corner shows the background, as
 * written. */
static void test_sphere_on_background(void **state)
{
    const char *text = "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 30\nhither 1\nresolution 32 32\n"
                       "b 0 0.25 0\nl 0 0 -10\nf 1 1 1 1 0 0 0 0\ns 0 0 0 1\n";
    glint_error err;
    glint_scene *s = load(text, &err);
    if (!s)
        fail_msg("%s", err.message);
    glint_render_options o = {.threads = 1};
    glint_image im;
    assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
    const float *middle = &im.pixels[3 * (16 * 32 + 16)], *corner = im.pixels;
    /* The one light's half (sqrt(1) / 2), almost head on. */
    assert_near(middle[0], 0.5, 0.01);
    assert_near(middle[1], middle[0], 0);
    assert_near(corner[0], 0, 0);
    assert_near(corner[1], glint_srgb_to_linear(0.25), 1e-6);
    glint_image_free(&im);
    glint_scene_free(s);
}

/* A broken file and its message. */
typedef struct bad_nff {
    const char *text;
    const char *message;
} bad_nff;

static void test_broken_files(void **state)
{
    static const bad_nff BAD[] = {
        {"", "t.nff: no view: an NFF file starts with 'v'"},
        {"s 0 0 0 1\n", "t.nff:1:1: 's' before the view: an NFF file gives its 'v' before any object"},
        {"v\nfrom 0 0 0\nto 1 1 1\n", "t.nff:3:1: the view's next line should start with 'at', got 'to'"},
        {"v\nfrom 0 0 0\nat 0 0 1\nup 0 1 0\nangle 200\nhither 1\nresolution 4 4\n",
         "t.nff:7:14: the view's angle must be between 0 and 180 degrees, got 200"},
        {"v\nfrom 0 0 0\nat 0 0 1\nup 0 1 0\nangle 40\nhither 1\nresolution 4.5 4\n",
         "t.nff:7:16: the view's resolution must be two whole numbers from 1 to 65536, got 4.5 4"},
        {"V\n", "t.nff:1:1: unknown entity 'V' (NFF has v, b, l, f, c, s, p, pp and # comments)"},
        {"b 0 zero 1\n", "t.nff:1:5: the background's colour should be a number, got 'zero'"},
        {"b 0 1e999 1\n", "t.nff:1:5: the background's colour must be finite, got '1e999'"},
        {"b 0 1\n", "t.nff:2:1: the file ends where the background's colour should be"},
        {"f 1 1 1 -1 0 0 0 1\n", NULL},
        {"l 1 2 3 0.5 x 1\n", "t.nff:1:13: a light's colour should be a number, got 'x'"},
    };
    for (size_t i = 0; i < sizeof BAD / sizeof BAD[0]; i++) {
        glint_error err;
        glint_scene *s = load(BAD[i].text, &err);
        assert_null(s);
        if (BAD[i].message)
            assert_string_equal(err.message, BAD[i].message);
        else /* the API's own check, at the value */
            assert_true(strncmp(err.message, "t.nff:1:", 8) == 0 && strstr(err.message, "diffuse"));
    }
    char text[512];
    const struct {
        const char *body, *message;
    } AFTER_VIEW[] = {
        {"c 0 0 0 1 0 0 0 1\n", "t.nff:8:17: a cone's base and apex are the same point"},
        {"s 1 2 3 -0\n", "t.nff:8:9: a sphere's radius must not be 0"},
        {"p 2\n0 0 0\n1 0 0\n", "t.nff:8:3: a polygon's vertex count must be a whole number from 3 to 1048576, got 2"},
        {"p 3\n0 0 0\n1 0 0\n2 0 0\n", NULL},
        {"pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n", "t.nff:11:1: the file ends where a patch's vertex or normal should be"},
    };
    for (size_t i = 0; i < sizeof AFTER_VIEW / sizeof AFTER_VIEW[0]; i++) {
        snprintf(text, sizeof text, "%s%s", VIEW, AFTER_VIEW[i].body);
        glint_error err;
        assert_null(load(text, &err));
        if (AFTER_VIEW[i].message)
            assert_string_equal(err.message, AFTER_VIEW[i].message);
        else /* three points in a line: the API's message, at the last of them */
            assert_true(strncmp(err.message, "t.nff:11:", 9) == 0 && strstr(err.message, "line"));
    }
}

/* The shared data folder (GLINT_SHARED_DATA), or the test skipped when
 * its file `probe` is not there. */
static const char *shared_data_or_skip(const char *probe)
{
    const char *data = getenv("GLINT_SHARED_DATA");
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", data ? data : "", probe);
    FILE *f = data ? fopen(path, "r") : NULL;
    if (!f)
        skip();
    fclose(f);
    return data;
}

/* The seven SPD scenes load, each with its primitives: cylinders or cones
 * as shapes, the spheres as sphere sets (those that let light through
 * apart), a fill's polygons one flat mesh and its smooth patches one
 * smooth mesh. */
static void test_spd_scenes(void **state)
{
    const char *data = shared_data_or_skip("spd/balls.nff");
    const struct {
        const char *name;
        int shapes, sets, spheres, lights, meshes, triangles;
    } SPD[] = {
        {"balls", 1, 1, 7381, 3, 1, 2},    {"gears", 0, 0, 0, 5, 65, 36610}, {"mount", 1, 1, 4, 1, 1, 8192},
        {"rings", 4201, 1, 4200, 3, 1, 2}, {"teapot", 0, 0, 0, 2, 3, 2328},  {"tetra", 0, 0, 0, 1, 1, 4096},
        {"tree", 4096, 1, 4095, 7, 1, 2},
    };
    for (size_t i = 0; i < sizeof SPD / sizeof SPD[0]; i++) {
        char path[4200];
        snprintf(path, sizeof path, "%s/spd/%s.nff", data, SPD[i].name);
        glint_error err;
        glint_scene *s = glint_scene_load_file(path, NULL, &err);
        if (!s)
            fail_msg("%s", err.message);
        glint_scene_counts c = glint_scene_get_counts(s);
        assert_int_equal(c.shapes, SPD[i].shapes);
        assert_int_equal(c.sphere_sets, SPD[i].sets);
        assert_int_equal(c.set_spheres, SPD[i].spheres);
        assert_int_equal(s->light_count, SPD[i].lights);
        assert_int_equal(s->mesh_count, SPD[i].meshes);
        int triangles = 0;
        for (int k = 0; k < s->mesh_count; k++)
            triangles += s->meshes[k].triangle_count;
        assert_int_equal(triangles, SPD[i].triangles);
        assert_int_equal(s->settings.width, 512);
        glint_scene_free(s);
    }
}

/* The mean of each f x f block of an 8-bit sRGB image, as 0..1. */
static double *shrink(const unsigned char *srgb, int width, int height, int f)
{
    int w = width / f, h = height / f;
    double *out = calloc(3 * (size_t)w * (size_t)h, sizeof *out);
    assert_non_null(out);
    for (int y = 0; y < h * f; y++)
        for (int x = 0; x < w * f; x++)
            for (int c = 0; c < 3; c++)
                out[3 * ((size_t)(y / f) * (size_t)w + (size_t)(x / f)) + (size_t)c] +=
                    srgb[3 * ((size_t)y * (size_t)width + (size_t)x) + (size_t)c] / (255.0 * f * f);
    return out;
}

/* The seven SPD scenes look like the SPD's own renderings: each rendered
 * at 128 x 128 (4 samples) and its reference at 512 x 512, both shrunk by
 * averaging to 64 x 64, differ by at most the RMSE below (over the sRGB
 * channels, 0 to 1). The references were made with a lighting model of
 * their own (brighter where many lights add up, as in balls and tree);
 * the bounds are what glint's documented mapping gives, measured, plus
 * 0.01. Lights 1.5 times as bright overshoot rings' and tetra's (0.155,
 * 0.045); mount without its four glass balls is at 0.138. */
static void test_spd_look_like_references(void **state)
{
    const char *data = shared_data_or_skip("spd/balls-reference.png");
    const struct {
        const char *name;
        double most;
    } SPD[] = {
        {"balls", 0.18}, {"gears", 0.126}, {"mount", 0.059}, {"rings", 0.135},
        {"teapot", 0.082}, {"tetra", 0.038}, {"tree", 0.174},
    };
    enum { SIDE = 128, SHOWN = 64 };
    for (size_t i = 0; i < sizeof SPD / sizeof SPD[0]; i++) {
        char path[4200];
        snprintf(path, sizeof path, "%s/spd/%s.nff", data, SPD[i].name);
        glint_error err;
        glint_scene *s = glint_scene_load_file(path, NULL, &err);
        if (!s)
            fail_msg("%s", err.message);
        glint_settings set = glint_scene_get_settings(s);
        set.width = set.height = SIDE;
        set.samples_per_pixel = 4;
        assert_int_equal(glint_scene_set_settings(s, &set, &err), GLINT_OK);
        glint_render_options o = {.threads = 0};
        glint_image im;
        assert_int_equal(glint_render(s, &o, &im, NULL, &err), GLINT_OK);
        unsigned char *mine = malloc(3 * SIDE * SIDE);
        assert_non_null(mine);
        srgb_encode(mine, im.pixels, 3 * SIDE * SIDE);
        snprintf(path, sizeof path, "%s/spd/%s-reference.png", data, SPD[i].name);
        texture_image ref;
        assert_int_equal(texture_image_load_file(&ref, path, &err), GLINT_OK);
        assert_true(ref.width == 512 && ref.height == 512 && ref.srgb);
        double *a = shrink(mine, SIDE, SIDE, SIDE / SHOWN), *b = shrink(ref.srgb, 512, 512, 512 / SHOWN);
        double sum = 0;
        for (int k = 0; k < 3 * SHOWN * SHOWN; k++)
            sum += (a[k] - b[k]) * (a[k] - b[k]);
        double rmse = sqrt(sum / (3 * SHOWN * SHOWN));
        print_message("%s: RMSE %.4f against its reference (at most %.3f)\n", SPD[i].name, rmse, SPD[i].most);
        assert_true(rmse <= SPD[i].most);
        free(a);
        free(b);
        free(mine);
        texture_image_free(&ref);
        glint_image_free(&im);
        glint_scene_free(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_entity),
        cmocka_unit_test(test_sphere_on_background),
        cmocka_unit_test(test_broken_files),
        cmocka_unit_test(test_spd_scenes),
        cmocka_unit_test(test_spd_look_like_references),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
