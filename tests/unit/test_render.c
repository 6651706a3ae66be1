/* test_render.c - whole-image properties of small renders through the public
 * API: silhouettes, shadows (opaque and tinted), mirrors, refraction, and
 * identical bytes whatever the thread count, or when the render keeps no
 * image and hands each tile out as it is finished (render_tiles.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <malloc.h>
#include <math.h>
#include <stdbool.h>
#include <string.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include "glint.h"
#include "one_sample_scene.h"
#include "render/render_tiles.h"
#include "tiles_told.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

/* A one-sample scene under white ambient light (flat's materials show
 * their colour by it), seen from eye towards at. */
static glint_scene *new_scene(int w, int h, glint_vec3 eye, glint_vec3 at, glint_vec3 up, double fov)
{
    glint_camera cam = {.position = eye, .look_at = at, .up = up, .vfov_degrees = fov};
    return one_sample_scene(w, h, (glint_color){1, 1, 1}, cam);
}

/* A material that shows exactly its colour: ambient only, under white ambient light. */
static int flat(glint_scene *s, double r, double g, double b)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){r, g, b};
    m.ambient = 1;
    m.diffuse = 0;
    m.specular = 0;
    int i = glint_scene_add_material(s, NULL, &m, NULL);
    assert_true(i >= 0);
    return i;
}

static int matte(glint_scene *s, double r, double g, double b)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){r, g, b};
    m.specular = 0;
    int i = glint_scene_add_material(s, NULL, &m, NULL);
    assert_true(i >= 0);
    return i;
}

static void add_sphere(glint_scene *s, double x, double y, double z, double r, int mat)
{
    glint_shape sh = {.kind = GLINT_SHAPE_SPHERE, .center = {x, y, z}, .radius = r};
    assert_true(glint_scene_add_shape(s, &sh, mat, NULL, NULL) >= 0);
}

static void add_quad(glint_scene *s, glint_vec3 a, glint_vec3 b, glint_vec3 c, glint_vec3 d, int mat)
{
    glint_shape sh = {.kind = GLINT_SHAPE_POLYGON, .point_count = 4, .points = {a, b, c, d}};
    assert_true(glint_scene_add_shape(s, &sh, mat, NULL, NULL) >= 0);
}

static glint_image render(const glint_scene *s, int threads)
{
    glint_image img;
    glint_render_options o = {.threads = threads};
    glint_error err;
    glint_status st = glint_render(s, &o, &img, NULL, &err);
    if (st)
        fail_msg("render failed: %s", err.message);
    return img;
}

static const float *pixel(const glint_image *img, int x, int y)
{
    return img->pixels + 3 * ((size_t)y * img->width + x);
}

static void test_sphere_silhouette_area(void **state)
{
    /* A sphere of radius 1 at distance 10 subtends a disc of radius
     * tan(asin(1/10)) = 1/sqrt(99) on the image plane at distance 1. */
    glint_scene *s = new_scene(400, 400, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    add_sphere(s, 0, 0, -10, 1, flat(s, 1, 1, 1));
    glint_image img = render(s, 0);
    int covered = 0;
    for (int i = 0; i < img.width * img.height; i++)
        covered += img.pixels[3 * i] > 0.5f;
    double radius_px = (1 / sqrt(99.0)) / tan(15 * M_PI / 180) * 200;
    double expected = M_PI * radius_px * radius_px;
    assert_true(fabs(covered - expected) / expected < 0.01);
    /* Outside the disc is the black background, inside exactly white. */
    assert_near(pixel(&img, 0, 0)[0], 0, 0);
    assert_near(pixel(&img, 200, 200)[1], 1, 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* A white matte floor under a light straight above the origin, seen by a
 * camera whose centre pixel (odd image size) looks exactly at `target`. */
static glint_scene *floor_scene(glint_vec3 target)
{
    glint_scene *s = new_scene(11, 11, (glint_vec3){0, 8, 12}, target, (glint_vec3){0, 1, 0}, 20);
    glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &plane, matte(s, 1, 1, 1), NULL, NULL) >= 0);
    glint_light l = {.kind = GLINT_LIGHT_POINT, .position = {0, 10, 0}, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &l, NULL) >= 0);
    return s;
}

static const float *centre(const glint_image *img)
{
    return pixel(img, img->width / 2, img->height / 2);
}

static void test_shadow_ratio(void **state)
{
    glint_scene *lit = floor_scene((glint_vec3){3, 0, 0});
    glint_scene *shadowed = floor_scene((glint_vec3){0, 0, 0});
    add_sphere(lit, 0, 5, 0, 1, matte(lit, 1, 1, 1));
    add_sphere(shadowed, 0, 5, 0, 1, matte(shadowed, 1, 1, 1));
    glint_image a = render(lit, 1), b = render(shadowed, 1);
    double lit_value = 0.2 + 10 / sqrt(109.0); /* ambient + cos of the light's angle */
    assert_near(centre(&a)[0], lit_value, 1e-5);
    assert_near(centre(&b)[0], 0.2, 1e-6);       /* ambient only: never black */
    assert_near(centre(&b)[0] / centre(&a)[0], 0.2 / lit_value, 1e-5);
    glint_image_free(&a);
    glint_image_free(&b);
    glint_scene_free(lit);
    glint_scene_free(shadowed);
}

/* Planes are tested outside Embree: they are infinite, seen from anywhere,
 * and a shape touching a plane wins the tie where they meet. */
static void test_planes_are_infinite_and_lose_ties(void **state)
{
    /* From three million units up, looking at a point 30 million away: the
     * ray never comes within a million units of the origin. */
    glint_scene *far = new_scene(5, 5, (glint_vec3){0, 3e6, 0}, (glint_vec3){3e7, 0, 0}, (glint_vec3){0, 1, 0}, 1);
    glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(far, &plane, flat(far, 0, 1, 0), NULL, NULL) >= 0);
    glint_image a = render(far, 1);
    assert_near(centre(&a)[1], 1, 1e-6);
    glint_image_free(&a);
    glint_scene_free(far);
    /* From inside a box standing on the floor, looking down: the box's
     * bottom face and the floor are the same distance away; the box wins. */
    glint_scene *tie = new_scene(5, 5, (glint_vec3){0, 0.5, 0}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, 30);
    assert_true(glint_scene_add_shape(tie, &plane, flat(tie, 0, 1, 0), NULL, NULL) >= 0);
    glint_shape box = {.kind = GLINT_SHAPE_BOX, .min = {-1, 0, -1}, .max = {1, 1, 1}};
    assert_true(glint_scene_add_shape(tie, &box, flat(tie, 1, 0, 0), NULL, NULL) >= 0);
    glint_image b = render(tie, 1);
    for (int i = 0; i < 25; i++) {
        assert_near(b.pixels[3 * i], 1, 1e-6);
        assert_near(b.pixels[3 * i + 1], 0, 1e-6);
    }
    glint_image_free(&b);
    glint_scene_free(tie);
}

/* Embree takes no ray with a coordinate past 1.844e18 (Debian's build
 * asserts it, ending the process): from a camera 1e19 units away, every
 * camera ray and the outer pixels' shadow rays are such rays. They still
 * meet the plane, lit by a light straight above it (ambient 0.2 + 1); the
 * ball at the origin is far smaller than a pixel. */
static void test_rays_past_embree_still_meet_planes(void **state)
{
    (void)state;
    glint_scene *s = new_scene(4, 4, (glint_vec3){0, 0, 1e19}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 40);
    glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 0, 1}};
    assert_true(glint_scene_add_shape(s, &plane, matte(s, 1, 1, 1), NULL, NULL) >= 0);
    add_sphere(s, 0, 0, 0, 1, matte(s, 1, 0, 0));
    glint_light sun = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {0, 0, -1}, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &sun, NULL) >= 0);
    glint_image img = render(s, 1);
    for (int i = 0; i < 3 * 16; i++)
        assert_near(img.pixels[i], 1.2, 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* A sphere of radius 1 at c with a spherical checker of 8 x 8 cells (no
 * center given), seen from 4 units in front of it. */
static glint_image checked_ball(glint_vec3 c)
{
    glint_vec3 eye = {c.x, c.y, c.z + 4};
    glint_scene *s = new_scene(64, 64, eye, c, (glint_vec3){0, 1, 0}, 35);
    glint_mapping sph = {.kind = GLINT_MAP_SPHERICAL};
    int tex = glint_scene_add_checker(s, NULL, (glint_color){1, 0, 0}, (glint_color){0, 0, 1}, 0.125, sph, NULL);
    assert_true(tex >= 0);
    glint_material m = glint_material_default();
    m.texture = tex;
    m.ambient = 1;
    m.diffuse = m.specular = 0;
    add_sphere(s, c.x, c.y, c.z, 1, glint_scene_add_material(s, NULL, &m, NULL));
    glint_image img = render(s, 1);
    glint_scene_free(s);
    return img;
}

/* A spherical mapping goes around the sphere it is on: a ball away from
 * the origin, seen from the same place relative to it, shows the same
 * cells as one at the origin. The few pixels allowed to differ are those
 * whose point lies on a cell's edge, within rounding. */
static void test_spherical_mapping_follows_the_sphere(void **state)
{
    glint_image home = checked_ball((glint_vec3){0, 0, 0}), away = checked_ball((glint_vec3){-3, 1, 0});
    int differ = 0, red = 0;
    for (int i = 0; i < 3 * 64 * 64; i++)
        differ += fabsf(home.pixels[i] - away.pixels[i]) > 1e-6f;
    for (int i = 0; i < 64 * 64; i++)
        red += home.pixels[3 * i] > 0.5f;
    assert_true(differ <= 64);
    assert_true(red > 500); /* the ball shows both colours, not one */
    glint_image_free(&home);
    glint_image_free(&away);
}

/* Coloured glass that shows nothing of its own (no ambient, diffuse or
 * specular term): light through it is only filtered. With `refract` its
 * 0.8 is refraction (without Fresnel), else transparency; either way each
 * surface passes 0.8 * colour = (0.8, 0.4, 0.2) with tint 1. */
static int amber_glass(glint_scene *s, bool refract)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){1, 0.5, 0.25};
    m.ambient = m.diffuse = m.specular = 0;
    if (refract) {
        m.refraction = 0.8;
        m.ior = 1.5;
    } else {
        m.transparency = 0.8;
    }
    m.tint = 1;
    int i = glint_scene_add_material(s, NULL, &m, NULL);
    assert_true(i >= 0);
    return i;
}

/* Every surface a ray crosses filters it, camera and shadow rays alike:
 * through a glass ball, in at one side and out at the other, light keeps
 * f^2 with f = 0.8 * colour, whether the camera looks through the ball's
 * centre at a white sky (the refracted ray goes straight there) or the
 * ball stands between a light and the floor. */
static void test_tinted_shadows_match_what_the_camera_sees(void **state)
{
    const double f[3] = {0.8, 0.4, 0.2};
    for (int refract = 0; refract < 2; refract++) {
        /* The floor straight below the ball and the light: ambient 0.2 plus
         * the light, cos 0 = 1, through the ball. */
        glint_scene *floor = floor_scene((glint_vec3){0, 0, 0});
        add_sphere(floor, 0, 5, 0, 1, amber_glass(floor, refract));
        glint_image a = render(floor, 1);
        /* The ball seen through its centre against a white background. */
        glint_scene *sky = new_scene(11, 11, (glint_vec3){0, 0, 10}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 20);
        glint_settings st = glint_scene_get_settings(sky);
        st.background = (glint_color){1, 1, 1};
        assert_int_equal(glint_scene_set_settings(sky, &st, NULL), GLINT_OK);
        add_sphere(sky, 0, 0, 0, 1, amber_glass(sky, refract));
        glint_image b = render(sky, 1);
        for (int c = 0; c < 3; c++) {
            assert_near(centre(&a)[c], 0.2 + f[c] * f[c], 1e-5);
            assert_near(centre(&b)[c], f[c] * f[c], 1e-5);
        }
        glint_image_free(&a);
        glint_image_free(&b);
        glint_scene_free(floor);
        glint_scene_free(sky);
    }
    /* Two balls in a row multiply: f^4. */
    glint_scene *two = floor_scene((glint_vec3){0, 0, 0});
    add_sphere(two, 0, 5, 0, 1, amber_glass(two, false));
    add_sphere(two, 0, 2.5, 0, 1, amber_glass(two, false));
    glint_image c = render(two, 1);
    for (int k = 0; k < 3; k++)
        assert_near(centre(&c)[k], 0.2 + pow(f[k], 4), 1e-5);
    glint_image_free(&c);
    glint_scene_free(two);
}

/* Beer-Lambert glass that shows nothing of its own and bends nothing (ior
 * 1, tint 0): light through it keeps only what its absorption leaves. */
static int absorbing_glass(glint_scene *s, glint_color keeps, double distance)
{
    glint_material m = glint_material_default();
    m.ambient = m.diffuse = m.specular = 0;
    m.refraction = 1;
    m.ior = 1;
    m.tint = 0;
    m.absorption = (glint_absorption){keeps, distance};
    int i = glint_scene_add_material(s, NULL, &m, NULL);
    assert_true(i >= 0);
    return i;
}

static void add_box(glint_scene *s, glint_vec3 lo, glint_vec3 hi, int mat)
{
    glint_shape sh = {.kind = GLINT_SHAPE_BOX, .min = lo, .max = hi};
    assert_true(glint_scene_add_shape(s, &sh, mat, NULL, NULL) >= 0);
}

/* Through a slab of thickness d, light keeps color^(d / distance) in each
 * channel: exp(-d / distance) when color is 1/e. The camera sees it so
 * against a white sky, and a shadow ray through the slab between a light
 * and the floor lets as much through; two slabs multiply. */
static void test_absorption_follows_beer_lambert(void **state)
{
    const glint_color keeps = {0.3, 0.6, 0.9}, one_over_e = {exp(-1), exp(-1), exp(-1)};
    const double d = 1.3, distance = 0.7;
    const double *k = &keeps.r;
    glint_scene *sky = new_scene(11, 11, (glint_vec3){0, 0, 10}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 20);
    glint_settings st = glint_scene_get_settings(sky);
    st.background = (glint_color){1, 1, 1};
    assert_int_equal(glint_scene_set_settings(sky, &st, NULL), GLINT_OK);
    add_box(sky, (glint_vec3){-5, -5, -d / 2}, (glint_vec3){5, 5, d / 2}, absorbing_glass(sky, keeps, distance));
    glint_image seen = render(sky, 1);
    for (int c = 0; c < 3; c++)
        assert_near(centre(&seen)[c], pow(k[c], d / distance), 1e-6);
    glint_image_free(&seen);
    glint_scene_free(sky);

    glint_scene *floor = floor_scene((glint_vec3){0, 0, 0});
    add_box(floor, (glint_vec3){-3, 4, -3}, (glint_vec3){3, 4 + d, 3}, absorbing_glass(floor, one_over_e, distance));
    glint_image shadow = render(floor, 1);
    for (int c = 0; c < 3; c++)
        assert_near(centre(&shadow)[c], 0.2 + exp(-d / distance), 1e-6);
    glint_image_free(&shadow);
    add_box(floor, (glint_vec3){-3, 6, -3}, (glint_vec3){3, 6.5, 3}, absorbing_glass(floor, keeps, distance));
    glint_image two = render(floor, 1);
    for (int c = 0; c < 3; c++)
        assert_near(centre(&two)[c], 0.2 + exp(-d / distance) * pow(k[c], 0.5 / distance), 1e-6);
    glint_image_free(&two);
    glint_scene_free(floor);
}

/* A metal's mirror takes its colour: a white wall seen in a sphere of
 * colour (1, 0.5, 0.25) comes back that colour when metallic is 1, half
 * way to white when it is 0.5, and white when it is 0. */
static void test_metallic_mirror_takes_its_colour(void **state)
{
    const double shares[] = {0, 0.5, 1};
    for (int i = 0; i < 3; i++) {
        glint_scene *s = new_scene(21, 21, (glint_vec3){0, 0, 5}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 10);
        glint_material metal = glint_material_default();
        metal.color = (glint_color){1, 0.5, 0.25};
        metal.ambient = metal.diffuse = metal.specular = 0;
        metal.reflectivity = 1;
        metal.metallic = shares[i];
        add_sphere(s, 0, 0, -5, 2, glint_scene_add_material(s, NULL, &metal, NULL));
        add_quad(s, (glint_vec3){-50, -50, 10}, (glint_vec3){50, -50, 10}, (glint_vec3){50, 50, 10},
                 (glint_vec3){-50, 50, 10}, flat(s, 1, 1, 1));
        glint_image img = render(s, 1);
        assert_near(centre(&img)[0], 1, 1e-6);
        assert_near(centre(&img)[1], 1 - 0.5 * shares[i], 1e-6);
        assert_near(centre(&img)[2], 1 - 0.75 * shares[i], 1e-6);
        glint_image_free(&img);
        glint_scene_free(s);
    }
}

static void test_mirror_shows_facing_wall(void **state)
{
    glint_scene *s = new_scene(21, 21, (glint_vec3){0, 0, 5}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 10);
    glint_material mirror = glint_material_default();
    mirror.color = (glint_color){0, 0, 0};
    mirror.ambient = 0;
    mirror.specular = 0;
    mirror.reflectivity = 1;
    add_sphere(s, 0, 0, -5, 2, glint_scene_add_material(s, NULL, &mirror, NULL));
    int red = flat(s, 1, 0, 0), green = flat(s, 0, 1, 0);
    /* Behind the camera, facing the sphere: red. To the left: green. */
    add_quad(s, (glint_vec3){-50, -50, 10}, (glint_vec3){50, -50, 10}, (glint_vec3){50, 50, 10},
             (glint_vec3){-50, 50, 10}, red);
    add_quad(s, (glint_vec3){-20, -50, -50}, (glint_vec3){-20, -50, 50}, (glint_vec3){-20, 50, 50},
             (glint_vec3){-20, 50, -50}, green);
    glint_image img = render(s, 2);
    assert_near(centre(&img)[0], 1, 1e-6);
    assert_near(centre(&img)[1], 0, 0);
    assert_near(centre(&img)[2], 0, 0);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* Clear glass that shows nothing of its own: all refraction. */
static glint_material clear_glass(bool fresnel)
{
    glint_material glass = glint_material_default();
    glass.color = (glint_color){0, 0, 0};
    glass.ambient = 0;
    glass.specular = 0;
    glass.refraction = 1;
    glass.ior = 1.5;
    glass.tint = 0;
    glass.fresnel = fresnel;
    return glass;
}

static void test_refraction_inverts(void **state)
{
    /* A glass ball in front of a backdrop red above y = 0 and blue below:
     * through the ball, which focuses well before the backdrop, up and down
     * swap. */
    glint_scene *s = new_scene(101, 101, (glint_vec3){0, 0, 10}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 20);
    glint_material glass = clear_glass(false);
    add_sphere(s, 0, 0, 0, 1, glint_scene_add_material(s, NULL, &glass, NULL));
    int red = flat(s, 1, 0, 0), blue = flat(s, 0, 0, 1);
    add_quad(s, (glint_vec3){-50, 0, -20}, (glint_vec3){50, 0, -20}, (glint_vec3){50, 50, -20},
             (glint_vec3){-50, 50, -20}, red);
    add_quad(s, (glint_vec3){-50, -50, -20}, (glint_vec3){50, -50, -20}, (glint_vec3){50, 0, -20},
             (glint_vec3){-50, 0, -20}, blue);
    glint_image img = render(s, 2);
    /* Outside the ball: upright. */
    assert_near(pixel(&img, 50, 2)[0], 1, 1e-6);
    assert_near(pixel(&img, 50, 98)[2], 1, 1e-6);
    /* Inside the ball (radius about 28 pixels): inverted. */
    assert_near(pixel(&img, 50, 40)[2], 1, 1e-6);
    assert_near(pixel(&img, 50, 40)[0], 0, 0);
    assert_near(pixel(&img, 50, 60)[0], 1, 1e-6);
    assert_near(pixel(&img, 50, 60)[2], 0, 0);
    glint_image_free(&img);
    glint_scene_free(s);
}

static void test_transparency_passes_light_straight_through(void **state)
{
    /* A transparent sphere (0.8, tint 0.5, red) in front of a flat green
     * wall: the centre pixel is 0.2 of its own flat colour plus 0.8 of the
     * wall filtered by (1 - 0.5) + 0.5 * red; the ray is not bent, so the
     * wall behind is exactly the wall on the axis. */
    glint_scene *s = new_scene(11, 11, (glint_vec3){0, 0, 10}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 20);
    glint_material m = glint_material_default();
    m.color = (glint_color){1, 0, 0};
    m.ambient = 1;
    m.diffuse = 0;
    m.specular = 0;
    m.transparency = 0.8;
    m.tint = 0.5;
    add_sphere(s, 0, 0, 0, 1, glint_scene_add_material(s, NULL, &m, NULL));
    add_quad(s, (glint_vec3){-50, -50, -20}, (glint_vec3){50, -50, -20}, (glint_vec3){50, 50, -20},
             (glint_vec3){-50, 50, -20}, flat(s, 0.2, 1, 0.4));
    glint_image img = render(s, 1);
    /* Front surface: 0.2 * red + 0.8 * filter * (what the back surface shows),
     * and the back surface likewise in front of the wall. */
    double fr = 1, fg = 0.5, fb = 0.5;
    double back_r = 0.2 * 1 + 0.8 * fr * 0.2, back_g = 0.8 * fg * 1, back_b = 0.8 * fb * 0.4;
    assert_near(centre(&img)[0], 0.2 + 0.8 * fr * back_r, 1e-6);
    assert_near(centre(&img)[1], 0.8 * fg * back_g, 1e-6);
    assert_near(centre(&img)[2], 0.8 * fb * back_b, 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);
}

static void test_supersamples_are_four_distinct_points(void **state)
{
    /* A white quad covering the quarter x < 0, y > 0 of the view, its corner
     * on the centre of the middle pixel of a 3x3 image: of a 2x2 grid, one
     * sample lands on it (the original repeated its first sample, giving 0.5
     * or 0). Half-covered edge pixels give exactly 0.5. */
    glint_scene *s = new_scene(3, 3, (glint_vec3){0, 0, 1}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 90);
    glint_settings st = glint_scene_get_settings(s);
    st.samples_per_pixel = 4;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    add_quad(s, (glint_vec3){-10, 0, -1}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 10, -1}, (glint_vec3){-10, 10, -1},
             flat(s, 1, 1, 1));
    glint_image img = render(s, 1);
    assert_near(pixel(&img, 1, 1)[0], 0.25, 1e-7);
    assert_near(pixel(&img, 0, 1)[0], 0.5, 1e-7);
    assert_near(pixel(&img, 1, 0)[0], 0.5, 1e-7);
    assert_near(pixel(&img, 0, 0)[0], 1, 1e-7);
    assert_near(pixel(&img, 2, 2)[0], 0, 0);
    /* 3x3 samples: 4 of 9 fall on the quad in the middle pixel, two of
     * them exactly on its edges, which count as inside. */
    st.samples_per_pixel = 9;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_image_free(&img);
    img = render(s, 1);
    assert_near(pixel(&img, 1, 1)[0], 4.0 / 9, 1e-7);
    glint_image_free(&img);
    glint_scene_free(s);
}

static void test_fresnel_reflects_more_at_grazing_angles(void **state)
{
    /* A glass floor with Fresnel over a red ground far below, under a blue
     * sky of flat quads: looking straight down shows mostly the refracted
     * red; looking along the floor shows mostly the reflected blue. */
    glint_material glass = clear_glass(true);
    glint_vec3 eyes[2] = {{0, 5, 0.001}, {0, 0.05, 5}};
    double blue[2];
    for (int k = 0; k < 2; k++) {
        glint_scene *s = new_scene(1, 1, eyes[k], (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 1);
        glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
        assert_true(glint_scene_add_shape(s, &plane, glint_scene_add_material(s, NULL, &glass, NULL), NULL, NULL) >= 0);
        glint_shape ground = {.kind = GLINT_SHAPE_PLANE, .center = {0, -100, 0}, .normal = {0, 1, 0}};
        glint_shape sky = {.kind = GLINT_SHAPE_PLANE, .center = {0, 1000, 0}, .normal = {0, -1, 0}};
        assert_true(glint_scene_add_shape(s, &ground, flat(s, 1, 0, 0), NULL, NULL) >= 0);
        assert_true(glint_scene_add_shape(s, &sky, flat(s, 0, 0, 1), NULL, NULL) >= 0);
        glint_image img = render(s, 1);
        blue[k] = img.pixels[2];
        /* Energy is split, never lost or created. */
        assert_near(img.pixels[0] + img.pixels[2], 1, 1e-6);
        glint_image_free(&img);
        glint_scene_free(s);
    }
    assert_near(blue[0], 0.04, 1e-4);   /* ((1.5 - 1) / (1.5 + 1))^2 */
    assert_true(blue[1] > 0.9);
}

/* A wall 50 away under a light, behind linear fog that ends at fog_end. */
static glint_scene *fogged_wall(double fog_end)
{
    glint_scene *s = new_scene(10, 10, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    add_quad(s, (glint_vec3){-100, -100, -50}, (glint_vec3){100, -100, -50}, (glint_vec3){100, 100, -50},
             (glint_vec3){-100, 100, -50}, matte(s, 0.3, 0.6, 0.9));
    glint_light l = {.kind = GLINT_LIGHT_POINT, .position = {0, 0, -10}, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &l, NULL) >= 0);
    glint_fog f = {.kind = GLINT_FOG_LINEAR, .color = {0.7, 0.2, 0.1}, .start = 0, .end = fog_end};
    assert_int_equal(glint_scene_set_fog(s, &f, NULL), GLINT_OK);
    return s;
}

/* Fog that hides a surface completely shows exactly its colour there, and
 * the surface is not shaded: no shadow ray is traced for it. */
static void test_fog_hides_unshaded(void **state)
{
    for (int pass = 0; pass < 2; pass++) {
        glint_scene *s = fogged_wall(pass == 0 ? 40 : 80);
        glint_image img;
        glint_render_stats st;
        glint_render_options o = {.threads = 1};
        assert_int_equal(glint_render(s, &o, &img, &st, NULL), GLINT_OK);
        const float *p = pixel(&img, 4, 6);
        if (pass == 0) {
            /* 100 camera rays and nothing else. */
            assert_int_equal(st.rays, 100);
            for (int i = 0; i < img.width * img.height; i++) {
                assert_true(img.pixels[3 * i] == 0.7f);
                assert_true(img.pixels[3 * i + 1] == 0.2f);
                assert_true(img.pixels[3 * i + 2] == 0.1f);
            }
        } else {
            /* Partly hidden: the wall shows through, lit by shadow rays. */
            assert_int_equal(st.rays, 200);
            assert_true(p[2] > 0.1f + 0.05f);
        }
        glint_image_free(&img);
        glint_scene_free(s);
    }
}

/* A wall facing the camera at distance -z, as an analytic quad or as a
 * two-triangle mesh, under a light, behind linear fog that ends at 50. */
static glint_scene *wall_at_fog_end(double z, bool mesh)
{
    glint_scene *s = new_scene(11, 11, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    int mat = matte(s, 0.3, 0.6, 0.9);
    if (mesh) {
        float p[] = {-100, -100, (float)z, 100, -100, (float)z, 100, 100, (float)z, -100, 100, (float)z};
        static const uint32_t idx[] = {0, 1, 2, 0, 2, 3};
        glint_mesh_data md = {p, NULL, NULL, 4, idx, 2, NULL, mat};
        int m = glint_scene_add_mesh(s, "wall", &md, NULL);
        assert_true(m >= 0);
        assert_true(glint_scene_add_instance(s, m, -1, NULL, NULL) >= 0);
    } else {
        add_quad(s, (glint_vec3){-100, -100, z}, (glint_vec3){100, -100, z}, (glint_vec3){100, 100, z},
                 (glint_vec3){-100, 100, z}, mat);
    }
    glint_light l = {.kind = GLINT_LIGHT_POINT, .position = {0, 0, -10}, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &l, NULL) >= 0);
    glint_fog f = {.kind = GLINT_FOG_LINEAR, .color = {0.7, 0.2, 0.1}, .start = 0, .end = 50};
    assert_int_equal(glint_scene_set_fog(s, &f, NULL), GLINT_OK);
    return s;
}

/* Hits are looked for only as far as linear fog leaves anything to see: a
 * wall just short of the fog's end is still found and lit, one just past
 * it shows exactly the fog colour and sends no shadow ray; analytic shapes
 * and meshes alike. The centre pixel's ray runs along the axis, so its
 * distance to the wall is exactly -z; every other ray's is longer. */
static void test_fog_end_bounds_the_search(void **state)
{
    for (int mesh = 0; mesh < 2; mesh++) {
        for (int past = 0; past < 2; past++) {
            glint_scene *s = wall_at_fog_end(past ? -50.0001 : -49.9999, mesh);
            glint_image img;
            glint_render_stats st;
            glint_render_options o = {.threads = 1};
            assert_int_equal(glint_render(s, &o, &img, &st, NULL), GLINT_OK);
            const float *c = pixel(&img, 5, 5);
            bool fog = c[0] == 0.7f && c[1] == 0.2f && c[2] == 0.1f;
            if (past) {
                assert_true(fog);
                assert_int_equal(st.rays, 121);
            } else {
                assert_false(fog);
                assert_int_equal(st.rays, 122);
            }
            glint_image_free(&img);
            glint_scene_free(s);
        }
    }
}

/* The seed room at width x height. */
static glint_scene *small_seed_room(int width, int height)
{
    glint_error err;
    glint_scene *s = glint_scene_seed_room(&err);
    assert_non_null(s);
    glint_settings st = glint_scene_get_settings(s);
    st.width = width;
    st.height = height;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    return s;
}

static void test_identical_bytes_for_any_thread_count(void **state)
{
    glint_scene *s = small_seed_room(96, 80);
    glint_settings st = glint_scene_get_settings(s);
    glint_image one = render(s, 1), two = render(s, 2), seven = render(s, 7);
    size_t bytes = (size_t)st.width * st.height * 3 * sizeof(float);
    assert_memory_equal(one.pixels, two.pixels, bytes);
    assert_memory_equal(one.pixels, seven.pixels, bytes);
    /* Another tile size too. */
    glint_image tiled;
    glint_render_options o = {.threads = 3, .tile_size = 7};
    assert_int_equal(glint_render(s, &o, &tiled, NULL, NULL), GLINT_OK);
    assert_memory_equal(one.pixels, tiled.pixels, bytes);
    /* The jittered sampler is as deterministic, and its seed matters. */
    st.sampler = GLINT_SAMPLER_JITTERED;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_image j1 = render(s, 1), j2 = render(s, 2);
    assert_memory_equal(j1.pixels, j2.pixels, bytes);
    assert_memory_not_equal(j1.pixels, one.pixels, bytes);
    glint_image_free(&one);
    glint_image_free(&two);
    glint_image_free(&seven);
    glint_image_free(&tiled);
    /* Every camera kind, the thin lens's samples included, with the jittered sampler. */
    for (int kind = GLINT_CAMERA_THIN_LENS; kind <= GLINT_CAMERA_FISHEYE; kind++) {
        glint_camera cam = glint_scene_get_camera(s);
        cam.kind = (glint_camera_kind)kind;
        cam.aperture = kind == GLINT_CAMERA_THIN_LENS ? 0.3 : 0;
        assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
        glint_image k1 = render(s, 1), k7 = render(s, 7);
        assert_memory_equal(k1.pixels, k7.pixels, bytes);
        assert_memory_not_equal(k1.pixels, j1.pixels, bytes);
        glint_image_free(&k1);
        glint_image_free(&k7);
    }
    glint_image_free(&j1);
    glint_image_free(&j2);
    glint_scene_free(s);
}

typedef struct progress_log {
    int calls, last, total;
    bool in_order;
} progress_log;

static void log_progress(void *user, int done, int total)
{
    progress_log *p = user;
    p->in_order = p->in_order && done == p->last + 1;
    p->last = done;
    p->total = total;
    p->calls++;
}

static void test_progress_reports_every_tile_in_order(void **state)
{
    glint_scene *s = new_scene(100, 70, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    add_sphere(s, 0, 0, -10, 1, flat(s, 1, 1, 1));
    progress_log log = {.in_order = true};
    glint_render_options o = {.threads = 4, .tile_size = 20, .progress = log_progress, .progress_user = &log};
    glint_image img;
    assert_int_equal(glint_render(s, &o, &img, NULL, NULL), GLINT_OK);
    assert_int_equal(log.total, 5 * 4);
    assert_int_equal(log.calls, 5 * 4);
    assert_int_equal(log.last, 5 * 4);
    assert_true(log.in_order);
    glint_image_free(&img);
    /* Tiles hold whole 4 x 2 packets: 10 is rounded up to 12. */
    log = (progress_log){.in_order = true};
    o.tile_size = 10;
    assert_int_equal(glint_render(s, &o, &img, NULL, NULL), GLINT_OK);
    assert_int_equal(log.total, 9 * 6);
    assert_int_equal(log.calls, 9 * 6);
    assert_true(log.in_order);
    glint_image_free(&img);
    glint_scene_free(s);
}

static void test_cancel_flag_stops_the_render(void **state)
{
    glint_scene *s = new_scene(64, 64, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    volatile int cancel = 1;
    glint_render_options o = {.threads = 2, .cancel = &cancel};
    glint_image img;
    glint_error err;
    assert_int_equal(glint_render(s, &o, &img, NULL, &err), GLINT_ERR_CANCELLED);
    assert_string_equal(err.message, "render cancelled");
    assert_null(img.pixels);
    glint_scene_free(s);
}

/* A progress callback that cancels the render once `after` tiles are done. */
typedef struct cancel_after {
    volatile int cancel;
    int after;
} cancel_after;

static void cancel_when_done(void *user, int done, int total)
{
    cancel_after *c = user;
    if (done >= c->after)
        c->cancel = 1;
}

/* With keep_partial, a cancelled render still gives an image: one thread
 * takes the tiles in order, so tiles 0 to 2 (of 5 x 4, 20 pixels square)
 * are finished and exactly as in a whole render, and every other pixel is
 * black. (A tile cut off halfway is black too: tests/cli/interrupt.sh.) */
static void test_cancel_keeps_finished_tiles(void **state)
{
    glint_scene *s = new_scene(100, 70, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    add_quad(s, (glint_vec3){-10, -10, -5}, (glint_vec3){10, -10, -5}, (glint_vec3){10, 10, -5},
             (glint_vec3){-10, 10, -5}, flat(s, 0.25, 0.5, 0.75));
    glint_render_options o = {.threads = 1, .tile_size = 20};
    glint_image whole, part;
    assert_int_equal(glint_render(s, &o, &whole, NULL, NULL), GLINT_OK);

    cancel_after c = {0, 3};
    o.progress = cancel_when_done;
    o.progress_user = &c;
    o.cancel = &c.cancel;
    o.keep_partial = 1;
    glint_render_stats stats;
    glint_error err;
    assert_int_equal(glint_render(s, &o, &part, &stats, &err), GLINT_ERR_CANCELLED);
    assert_string_equal(err.message, "render cancelled");
    assert_non_null(part.pixels);
    assert_int_equal(part.width, 100);
    assert_int_equal(part.height, 70);
    assert_int_equal(stats.tiles_done, 3);
    assert_int_equal(stats.tiles_total, 20);
    assert_int_equal(stats.samples, 3 * 20 * 20);
    for (int y = 0; y < 70; y++) {
        for (int x = 0; x < 100; x++) {
            const float *p = pixel(&part, x, y), *w = pixel(&whole, x, y);
            bool finished = y < 20 && x < 60;
            for (int k = 0; k < 3; k++) {
                assert_true(w[k] > 0);
                assert_true(p[k] == (finished ? w[k] : 0.0f));
            }
        }
    }
    glint_image_free(&part);

    /* Without keep_partial: no image, as before. */
    c.cancel = 0;
    o.keep_partial = 0;
    assert_int_equal(glint_render(s, &o, &part, &stats, NULL), GLINT_ERR_CANCELLED);
    assert_null(part.pixels);
    glint_image_free(&whole);
    glint_scene_free(s);
}

/* A render's image is not cleared before it starts: every pixel is
 * written once its tile is done. glibc is asked to fill what it hands out
 * with 0xaa bytes (a negative float) and to keep large blocks on its heap,
 * where that applies; the image must then be exactly the one a render
 * keeping partial tiles (which starts black) gives, with several threads,
 * small tiles and odd edges. */
static void test_every_pixel_written(void **state)
{
    enum { W = 1001, H = 777 };
    glint_scene *s = new_scene(W, H, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    add_quad(s, (glint_vec3){-1, -1, -5}, (glint_vec3){1, -1, -5}, (glint_vec3){1, 1, -5},
             (glint_vec3){-1, 1, -5}, flat(s, 0.25, 0.5, 0.75));
    glint_render_options o = {.threads = 2, .tile_size = 13};
    glint_image fresh, black;
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_PERTURB, 0x55);
    glint_status st = glint_render(s, &o, &fresh, NULL, NULL);
    mallopt(M_PERTURB, 0);
    assert_int_equal(st, GLINT_OK);
    o.keep_partial = 1;
    assert_int_equal(glint_render(s, &o, &black, NULL, NULL), GLINT_OK);
    assert_memory_equal(fresh.pixels, black.pixels, (size_t)W * H * 3 * sizeof(float));
    glint_image_free(&fresh);
    glint_image_free(&black);
    glint_scene_free(s);
}

static void test_bad_transforms_are_refused(void **state)
{
    glint_scene *s = new_scene(8, 8, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    int m = flat(s, 1, 1, 1);
    glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .radius = 1};
    glint_error err;
    glint_transform t = glint_transform_rotate(glint_transform_identity(), (glint_vec3){0, 0, 0}, 60);
    assert_int_equal(glint_scene_add_shape(s, &ball, m, &t, &err), -1);
    assert_string_equal(err.message, "transform is singular or not finite");
    t = glint_transform_scale(glint_transform_identity(), 1, 0, 1);
    assert_int_equal(glint_scene_add_shape(s, &ball, m, &t, &err), -1);
    assert_string_equal(err.message, "transform is singular or not finite");
    assert_int_equal(glint_scene_add_shape(s, &ball, 5, NULL, &err), -1);
    assert_string_equal(err.message, "material 5 does not exist");
    glint_scene_free(s);
}

/* A scene of extreme but valid values whose sphere shades to NaN (a light
 * of 1e300 times a diffuse factor of 1e300 overflows to infinity, which
 * full transparency then scales by zero). Each pixel averages only its
 * samples that are not NaN, so every pixel is the backdrop's colour
 * exactly, or black where all four samples met the sphere, and the count
 * of NaN samples is the count of samples that met it: the same scene with
 * a black sphere, the backdrop white, shows that count as the missing
 * quarters of each pixel. */
static glint_scene *nan_scene(bool ghost)
{
    glint_scene *s = new_scene(16, 16, (glint_vec3){0, 0, 5}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 1, 0}, 40);
    glint_settings st = glint_scene_get_settings(s);
    st.samples_per_pixel = 4;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    add_quad(s, (glint_vec3){-10, -10, -2}, (glint_vec3){10, -10, -2}, (glint_vec3){10, 10, -2},
             (glint_vec3){-10, 10, -2}, ghost ? flat(s, 0.25, 0.5, 0.75) : flat(s, 1, 1, 1));
    glint_material m = glint_material_default();
    m.diffuse = 1e300;
    m.transparency = 1;
    m.specular = 0;
    int sphere = ghost ? glint_scene_add_material(s, NULL, &m, NULL) : flat(s, 0, 0, 0);
    assert_true(sphere >= 0);
    add_sphere(s, 0, 0, 0, 1, sphere);
    glint_light l = {.kind = GLINT_LIGHT_POINT, .position = {0, 0, 10}, .color = {1e300, 1e300, 1e300}};
    assert_true(glint_scene_add_light(s, &l, NULL) >= 0);
    return s;
}

static void test_nan_samples_never_reach_a_pixel(void **state)
{
    glint_scene *s = nan_scene(false);
    glint_image img = render(s, 1);
    double covered = 0; /* samples on the sphere */
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++)
            covered += 4 * (1 - pixel(&img, x, y)[0]);
    glint_image_free(&img);
    glint_scene_free(s);
    assert_true(covered > 16 && covered < 4 * 16 * 16 / 2);

    s = nan_scene(true);
    for (int threads = 1; threads <= 2; threads++) {
        glint_render_options o = {.threads = threads};
        glint_render_stats stats;
        assert_int_equal(glint_render(s, &o, &img, &stats, NULL), GLINT_OK);
        assert_int_equal(stats.nan_samples, (uint64_t)covered);
        assert_int_equal(stats.samples, 16 * 16 * 4);
        int black = 0;
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 16; x++) {
                const float *p = pixel(&img, x, y);
                if (p[0] == 0 && p[1] == 0 && p[2] == 0) {
                    black++;
                    continue;
                }
                assert_true(p[0] == 0.25f && p[1] == 0.5f && p[2] == 0.75f);
            }
        }
        assert_true(black > 0 && black * 4 <= covered);
        const float *centre = pixel(&img, 8, 8), *corner = pixel(&img, 0, 0);
        assert_true(centre[0] == 0 && centre[1] == 0 && centre[2] == 0);
        assert_true(corner[0] == 0.25f && corner[1] == 0.5f && corner[2] == 0.75f);
        glint_image_free(&img);
    }
    glint_scene_free(s);
}

/* A render feed of every tile in order, copying each finished tile into
 * an image of its own. */
typedef struct tile_copier {
    atomic_int next;
    render_layout layout;
    float *pixels;
} tile_copier;

static int copier_next(void *user)
{
    return atomic_fetch_add(&((tile_copier *)user)->next, 1);
}

static void copier_done(void *user, int tile, const float *pixels, size_t stride)
{
    tile_copier *c = user;
    int x0, y0, x1, y1;
    render_tile_bounds(&c->layout, tile, &x0, &y0, &x1, &y1);
    for (int y = y0; y < y1; y++)
        memcpy(c->pixels + 3 * ((size_t)y * c->layout.width + x0), pixels + stride * (size_t)(y - y0),
               3 * sizeof(float) * (size_t)(x1 - x0));
}

/* Rendered tile by tile into the threads' own buffers (glint-mpi's workers
 * do), the pixels handed out are glint_render's to the byte, NaN samples
 * left out alike, and no image is returned. */
static void test_tiles_alone_give_the_image_bytes(void **state)
{
    glint_error err;
    glint_scene *scenes[] = {glint_scene_seed_room(&err), nan_scene(true)};
    glint_settings st = glint_scene_get_settings(scenes[0]);
    st.width = 90; /* edge tiles narrower and shorter than the rest */
    st.height = 70;
    assert_int_equal(glint_scene_set_settings(scenes[0], &st, NULL), GLINT_OK);
    for (int i = 0; i < 4; i++) {
        /* Tiles smaller than the image, and one tile larger than it. */
        glint_render_options o = {.threads = 3, .tile_size = i < 2 ? 12 : 4000};
        glint_image whole, alone;
        glint_render_stats whole_stats, alone_stats;
        glint_scene *scene = scenes[i % 2];
        assert_int_equal(glint_render(scene, &o, &whole, &whole_stats, NULL), GLINT_OK);
        tile_copier c = {.pixels = calloc((size_t)whole.width * whole.height * 3, sizeof(float))};
        assert_non_null(c.pixels);
        atomic_init(&c.next, 0);
        assert_int_equal(render_layout_for(scene, o.tile_size, &c.layout, NULL), GLINT_OK);
        render_feed feed = {.next = copier_next, .done = copier_done, .user = &c, .tiles_only = true};
        assert_int_equal(render_tiles(scene, &o, &feed, &alone, &alone_stats, NULL), GLINT_OK);
        assert_null(alone.pixels);
        assert_int_equal(alone.width, 0);
        assert_memory_equal(c.pixels, whole.pixels, (size_t)whole.width * whole.height * 3 * sizeof(float));
        assert_int_equal(alone_stats.nan_samples, whole_stats.nan_samples);
        assert_int_equal(alone_stats.rays, whole_stats.rays);
        assert_int_equal(alone_stats.tiles_done, c.layout.tiles_total);
        free(c.pixels);
        glint_image_free(&whole);
    }
    glint_scene_free(scenes[0]);
    glint_scene_free(scenes[1]);
}

/* tile_done is told of every tile once, from the render threads, with the
 * pixels the image ends up with. */
static void test_tile_done_tells_each_tile_once(void **state)
{
    glint_error err;
    glint_scene *s = glint_scene_seed_room(&err);
    glint_settings st = glint_scene_get_settings(s);
    st.width = 90;
    st.height = 70;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    tiles_told t;
    assert_true(tiles_told_init(&t, st.width, st.height));
    glint_render_options o = {.threads = 3, .tile_size = 12, .tile_done = tiles_told_note, .tile_user = &t};
    glint_image img;
    glint_render_stats stats;
    assert_int_equal(glint_render(s, &o, &img, &stats, NULL), GLINT_OK);
    assert_int_equal(t.calls, stats.tiles_total);
    assert_memory_equal(t.pixels, img.pixels, (size_t)st.width * st.height * 3 * sizeof(float));
    assert_true(tiles_told_once_each(&t));
    tiles_told_free(&t);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* An image is refused above GLINT_MAX_PIXELS in all, before anything is
 * allocated, and the settings stay as they were; the limit itself passes. */
static void test_image_size_limit(void **state)
{
    glint_scene *s = new_scene(8, 8, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 30);
    glint_settings st = glint_scene_get_settings(s);
    glint_error err;
    st.width = st.height = 16384;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_OK);
    st.width = 16385;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message,
                        "image size 16385x16384 is 268451840 pixels, more than the limit of 268435456 (16384 x 16384)");
    st.width = st.height = 65536;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message,
                        "image size 65536x65536 is 4294967296 pixels, more than the limit of 268435456 (16384 x 16384)");
    st = glint_scene_get_settings(s);
    assert_int_equal(st.width, 16384);
    assert_int_equal(st.height, 16384);
    glint_scene_free(s);
}

/* The spread of a small white sphere's light across the image: the
 * variance of x about its mean, in pixels squared, weighted by brightness. */
static double spread_x(const glint_image *im)
{
    double sum = 0, sx = 0, sxx = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            double v = im->pixels[3 * ((size_t)y * im->width + x)];
            sum += v;
            sx += v * (x + 0.5);
            sxx += v * (x + 0.5) * (x + 0.5);
        }
    double mean = sx / sum;
    return sxx / sum - mean * mean;
}

/* A small sphere seen through a camera at the origin looking down -z
 * (10 degrees of view over 101 x 101 pixels, 16 x 16 samples): its spread. */
static double sphere_spread(glint_camera_kind kind, double aperture, double focus, double depth, double radius,
                            int blades, double f_number)
{
    glint_scene *s = new_scene(101, 101, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 10);
    glint_settings st = glint_scene_get_settings(s);
    st.samples_per_pixel = 256;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_camera cam = glint_scene_get_camera(s);
    cam.kind = kind;
    cam.aperture = aperture;
    cam.focus_distance = focus;
    cam.blades = blades;
    cam.f_number = f_number;
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    add_sphere(s, 0, 0, -depth, radius, flat(s, 1, 1, 1));
    glint_image im;
    glint_render_options ro = {.threads = 2};
    assert_int_equal(glint_render(s, &ro, &im, NULL, NULL), GLINT_OK);
    double spread = spread_x(&im);
    glint_image_free(&im);
    glint_scene_free(s);
    return spread;
}

/* Depth of field: a sphere 2 units behind the plane of focus (4 units
 * away) blurs into the thin lens's circle of confusion, whose diameter on
 * the image plane at distance 1 is 2 * aperture * (1/4 - 1/6): measured
 * from the light's spread (a disk of radius R spreads R^2 / 4 along x,
 * added to the sharp sphere's own) within 10%. On the plane of focus the
 * sphere is as sharp as through the pinhole. */
static void test_thin_lens_circle_of_confusion(void **state)
{
    (void)state;
    double aperture = 0.1, pixel = 2 * tan(5 * M_PI / 180) / 101;
    double expected = 2 * aperture * (1.0 / 4 - 1.0 / 6) / pixel; /* 9.6 pixels across */
    double sharp = sphere_spread(GLINT_CAMERA_PINHOLE, 0, 0, 6, 0.02, 0, 0);
    double blurred = sphere_spread(GLINT_CAMERA_THIN_LENS, aperture, 4, 6, 0.02, 0, 0);
    double diameter = 4 * sqrt(blurred - sharp);
    assert_true(fabs(diameter - expected) <= 0.1 * expected);
    double focused = sphere_spread(GLINT_CAMERA_THIN_LENS, aperture, 6, 6, 0.02, 0, 0);
    assert_near(focused, sharp, 0.05 * sharp);
    /* Focus 0 is look_at's distance: 1 here, so the sphere at 6 blurs by 2 * 0.1 * (1 - 1/6). */
    double to_look_at = sphere_spread(GLINT_CAMERA_THIN_LENS, aperture, 0, 6, 0.02, 0, 0);
    double near_expected = 2 * aperture * (1.0 - 1.0 / 6) / pixel;
    assert_true(fabs(4 * sqrt(to_look_at - sharp) - near_expected) <= 0.1 * near_expected);
    /* Six blades: a regular hexagon of the disk's radius spreads 5/24 of
     * its radius squared along x where the disk spreads 6/24. */
    double hexagon = sphere_spread(GLINT_CAMERA_THIN_LENS, aperture, 4, 6, 0.02, 6, 0);
    assert_true(fabs((hexagon - sharp) / (blurred - sharp) - 5.0 / 6) <= 0.05 * 5 / 6);
}

/* An f-number N sizes the lens as a camera's does: radius f / (2 N), f the
 * focal length at which a 36 mm (0.036 units) sensor spans the 10 degrees
 * across: 0.036 / (2 tan 5 degrees) = 0.2057. At N = 1.0287 that is the
 * radius 0.1 above, and the sphere blurs into the same circle. */
static void test_thin_lens_f_number(void **state)
{
    (void)state;
    double focal = 0.036 / (2 * tan(5 * M_PI / 180)), n = focal / (2 * 0.1);
    double pixel = 2 * tan(5 * M_PI / 180) / 101;
    double expected = 2 * 0.1 * (1.0 / 4 - 1.0 / 6) / pixel;
    double sharp = sphere_spread(GLINT_CAMERA_PINHOLE, 0, 0, 6, 0.02, 0, 0);
    double by_f_number = sphere_spread(GLINT_CAMERA_THIN_LENS, 0, 4, 6, 0.02, 0, n);
    assert_true(fabs(4 * sqrt(by_f_number - sharp) - expected) <= 0.1 * expected);
    assert_near(by_f_number, sphere_spread(GLINT_CAMERA_THIN_LENS, 0.1, 4, 6, 0.02, 0, 0), 1e-6 * by_f_number);
    /* Twice the f-number, half the lens: a circle half as wide. */
    double stopped_down = sphere_spread(GLINT_CAMERA_THIN_LENS, 0, 4, 6, 0.02, 0, 2 * n);
    assert_true(fabs(4 * sqrt(stopped_down - sharp) - expected / 2) <= 0.1 * expected / 2);
}

/* Exposure in stops: +1 doubles every pixel exactly, -1 halves it; 0 is
 * the image as rendered. */
static void test_exposure_scales_every_pixel(void **state)
{
    (void)state;
    glint_scene *s = small_seed_room(40, 30);
    glint_settings st = glint_scene_get_settings(s);
    glint_image plain = render(s, 2);
    for (int stops = -1; stops <= 1; stops += 2) {
        st.exposure = stops;
        assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
        glint_image exposed = render(s, 2);
        for (size_t i = 0; i < (size_t)3 * st.width * st.height; i++)
            assert_true(exposed.pixels[i] == plain.pixels[i] * (stops > 0 ? 2.0f : 0.5f));
        glint_image_free(&exposed);
    }
    st.exposure = 65;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_ERR_INVALID);
    glint_image_free(&plain);
    glint_scene_free(s);
}

/* The centre pixel of a matte white floor seen from straight above, lit
 * only by light l straight above it at height h: the light arriving there. */
static double floor_under_light(glint_light l, double h)
{
    glint_scene *s = new_scene(11, 11, (glint_vec3){0, 20, 0}, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, 10);
    glint_material m = glint_material_default();
    m.ambient = 0;
    m.specular = 0;
    int white = glint_scene_add_material(s, NULL, &m, NULL);
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &floor, white, NULL, NULL) >= 0);
    l.position = (glint_vec3){0, h, 0};
    l.color = (glint_color){1, 1, 1};
    assert_true(glint_scene_add_light(s, &l, NULL) >= 0);
    glint_image im;
    glint_render_options ro = {.threads = 1};
    assert_int_equal(glint_render(s, &ro, &im, NULL, NULL), GLINT_OK);
    double v = pixel(&im, 5, 5)[0];
    glint_image_free(&im);
    glint_scene_free(s);
    return v;
}

/* Distance falloff: none keeps the light whatever the height; the inverse
 * square gives 1/h^2; POV-Ray's fade gives 2 / (1 + (h / fade_distance)^
 * fade_power): the colour at fade_distance, up to twice it nearer. */
static void test_light_falloff_modes(void **state)
{
    (void)state;
    glint_light l = {.kind = GLINT_LIGHT_POINT};
    assert_near(floor_under_light(l, 2), 1, 1e-6);
    assert_near(floor_under_light(l, 4), 1, 1e-6);
    l.falloff = GLINT_FALLOFF_INVERSE_SQUARE;
    assert_near(floor_under_light(l, 2), 0.25, 1e-6);
    assert_near(floor_under_light(l, 4), 0.0625, 1e-6);
    l.falloff = GLINT_FALLOFF_FADE;
    l.fade_distance = 2;
    l.fade_power = 3;
    assert_near(floor_under_light(l, 2), 1, 1e-6);
    assert_near(floor_under_light(l, 4), 2.0 / 9, 1e-6);
    assert_near(floor_under_light(l, 1), 2.0 / 1.125, 1e-6);
    /* A spot light weakens alike; a directional one cannot, nor a fade without its distance. */
    glint_scene *s = glint_scene_new();
    glint_error err = {0};
    glint_light sun = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {0, -1, 0}, .color = {1, 1, 1},
                       .falloff = GLINT_FALLOFF_INVERSE_SQUARE};
    assert_int_equal(glint_scene_add_light(s, &sun, &err), -1);
    assert_string_equal(err.message, "a directional light is at infinity: its falloff_mode must be none");
    l.fade_distance = 0;
    l.position = (glint_vec3){0, 1, 0};
    assert_int_equal(glint_scene_add_light(s, &l, &err), -1);
    assert_string_equal(err.message,
                        "point light falloff_mode fade needs fade_distance and fade_power above 0, got 0 and 3");
    glint_scene_free(s);
    glint_light spot = {.kind = GLINT_LIGHT_SPOT, .direction = {0, -1, 0}, .cone_angle = 30,
                        .falloff = GLINT_FALLOFF_INVERSE_SQUARE};
    assert_near(floor_under_light(spot, 2), 0.25, 1e-6);
}

/* A lens given to a pinhole is refused, as are negative lens values. */
static void test_thin_lens_values_checked(void **state)
{
    (void)state;
    glint_scene *s = new_scene(8, 8, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 40);
    glint_camera cam = glint_scene_get_camera(s);
    cam.aperture = 0.1;
    glint_error err = {0};
    assert_int_equal(glint_scene_set_camera(s, &cam, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "camera aperture is for type thin_lens, and this camera is a pinhole");
    cam.kind = GLINT_CAMERA_THIN_LENS;
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    cam.focus_distance = -1;
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_ERR_INVALID);
    cam.focus_distance = 0;
    cam.f_number = 2.8;
    assert_int_equal(glint_scene_set_camera(s, &cam, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "camera takes aperture or f_number, not both (aperture is the lens's radius, "
                                     "f_number the same size as a photographer gives it)");
    cam.aperture = 0;
    cam.sensor_width = 0.024;
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    cam.f_number = 0;
    assert_int_equal(glint_scene_set_camera(s, &cam, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "camera sensor_width only sizes the lens of an f_number: give f_number too, "
                                     "or leave sensor_width out");
    cam.f_number = -1;
    cam.sensor_width = 0;
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_ERR_INVALID);
    cam.f_number = 2;
    cam.kind = GLINT_CAMERA_PINHOLE;
    assert_int_equal(glint_scene_set_camera(s, &cam, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "camera f_number is for type thin_lens, and this camera is a pinhole");
    glint_scene_free(s);
}

/* The brightness-weighted centre of an image, in pixels, and the count of
 * pixels brighter than half. */
static void image_centre(const glint_image *im, double *cx, double *cy, int *lit)
{
    double sum = 0, sx = 0, sy = 0;
    *lit = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            double v = im->pixels[3 * ((size_t)y * im->width + x)];
            sum += v;
            sx += v * (x + 0.5);
            sy += v * (y + 0.5);
            *lit += v > 0.5;
        }
    *cx = sx / sum;
    *cy = sy / sum;
}

/* A white sphere of radius r at (x, y, z) seen by a camera of that kind at
 * the origin looking down -z, over w x h pixels: its centre and lit pixels. */
static void seen_sphere(glint_camera_kind kind, double fov, double view_width, int w, int h, double x, double y,
                        double z, double r, double *cx, double *cy, int *lit)
{
    glint_scene *s = new_scene(w, h, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 40);
    glint_camera cam = glint_scene_get_camera(s);
    cam.kind = kind;
    cam.vfov_degrees = fov;
    cam.view_width = view_width;
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    add_sphere(s, x, y, z, r, flat(s, 1, 1, 1));
    glint_image im;
    glint_render_options ro = {.threads = 2};
    assert_int_equal(glint_render(s, &ro, &im, NULL, NULL), GLINT_OK);
    image_centre(&im, cx, cy, lit);
    glint_image_free(&im);
    glint_scene_free(s);
}

/* The orthographic camera has no perspective: a sphere of radius 1 under a
 * view 4 units wide over 100 pixels is a disc 50 pixels across (1963
 * pixels of area) whether 5 or 50 units away, centred where its offset
 * puts it. */
static void test_orthographic_camera_keeps_sizes(void **state)
{
    (void)state;
    double cx, cy;
    int near_lit, far_lit;
    seen_sphere(GLINT_CAMERA_ORTHOGRAPHIC, 40, 4, 100, 100, 0, 0, -5, 1, &cx, &cy, &near_lit);
    assert_near(cx, 50, 0.01);
    assert_near(cy, 50, 0.01);
    seen_sphere(GLINT_CAMERA_ORTHOGRAPHIC, 40, 4, 100, 100, 0.8, 0, -50, 1, &cx, &cy, &far_lit);
    assert_near(cx, 70, 0.01); /* 0.8 units right: 20 pixels */
    assert_near(near_lit, M_PI * 25 * 25, 20);
    assert_near(far_lit, near_lit, 4);
}

/* The panorama: longitude across, latitude down. A sphere to the right
 * (+x) is a quarter of the width right of the centre, one to the left a
 * quarter left of it, one overhead along the top row. */
static void test_equirectangular_camera_sees_every_direction(void **state)
{
    (void)state;
    double cx, cy;
    int lit;
    seen_sphere(GLINT_CAMERA_EQUIRECTANGULAR, 40, 0, 200, 100, 10, 0, 0, 1, &cx, &cy, &lit);
    assert_near(cx, 150, 0.5);
    assert_near(cy, 50, 0.5);
    assert_true(lit > 0);
    seen_sphere(GLINT_CAMERA_EQUIRECTANGULAR, 40, 0, 200, 100, -10, 0, 0, 1, &cx, &cy, &lit);
    assert_near(cx, 50, 0.5);
    seen_sphere(GLINT_CAMERA_EQUIRECTANGULAR, 40, 0, 200, 100, 0, 10, 0, 1, &cx, &cy, &lit);
    assert_true(cy < 5);
}

/* The equidistant fisheye: with 360 degrees across the width, a sphere
 * 90 degrees to the right is halfway from the centre to the right edge,
 * one 45 degrees up a quarter of the way from the centre to the top. */
static void test_fisheye_camera_spreads_angles_evenly(void **state)
{
    (void)state;
    double cx, cy;
    int lit;
    seen_sphere(GLINT_CAMERA_FISHEYE, 360, 0, 200, 200, 10, 0, 0, 0.5, &cx, &cy, &lit);
    assert_near(cx, 150, 0.5);
    assert_near(cy, 100, 0.5);
    seen_sphere(GLINT_CAMERA_FISHEYE, 360, 0, 200, 200, 0, 10, -10, 0.5, &cx, &cy, &lit);
    assert_near(cx, 100, 0.5);
    assert_near(cy, 75, 0.5);
}

/* A key of another kind of camera is refused, as is a perspective view of
 * 180 degrees or more; a fisheye takes up to 360. */
static void test_camera_kinds_keys_checked(void **state)
{
    (void)state;
    glint_scene *s = new_scene(8, 8, (glint_vec3){0, 0, 0}, (glint_vec3){0, 0, -1}, (glint_vec3){0, 1, 0}, 40);
    glint_camera cam = glint_scene_get_camera(s);
    glint_error err = {0};
    cam.view_width = 2;
    assert_int_equal(glint_scene_set_camera(s, &cam, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "camera view_width is for type orthographic, and this camera is a pinhole");
    cam.view_width = 0;
    cam.kind = GLINT_CAMERA_EQUIRECTANGULAR;
    cam.aperture = 1;
    assert_int_equal(glint_scene_set_camera(s, &cam, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "camera aperture is for type thin_lens, and this camera is an equirectangular");
    cam.aperture = 0;
    cam.kind = GLINT_CAMERA_PINHOLE;
    cam.vfov_degrees = 200;
    assert_int_equal(glint_scene_set_camera(s, &cam, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message,
                        "camera fov must be less than 180 degrees for a pinhole (got 200; a fisheye takes up to 360)");
    cam.kind = GLINT_CAMERA_FISHEYE;
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_image_size_limit),
        cmocka_unit_test(test_nan_samples_never_reach_a_pixel),
        cmocka_unit_test(test_sphere_silhouette_area),
        cmocka_unit_test(test_thin_lens_circle_of_confusion),
        cmocka_unit_test(test_thin_lens_f_number),
        cmocka_unit_test(test_thin_lens_values_checked),
        cmocka_unit_test(test_exposure_scales_every_pixel),
        cmocka_unit_test(test_light_falloff_modes),
        cmocka_unit_test(test_orthographic_camera_keeps_sizes),
        cmocka_unit_test(test_equirectangular_camera_sees_every_direction),
        cmocka_unit_test(test_fisheye_camera_spreads_angles_evenly),
        cmocka_unit_test(test_camera_kinds_keys_checked),
        cmocka_unit_test(test_shadow_ratio),
        cmocka_unit_test(test_spherical_mapping_follows_the_sphere),
        cmocka_unit_test(test_tinted_shadows_match_what_the_camera_sees),
        cmocka_unit_test(test_absorption_follows_beer_lambert),
        cmocka_unit_test(test_metallic_mirror_takes_its_colour),
        cmocka_unit_test(test_mirror_shows_facing_wall),
        cmocka_unit_test(test_refraction_inverts),
        cmocka_unit_test(test_transparency_passes_light_straight_through),
        cmocka_unit_test(test_supersamples_are_four_distinct_points),
        cmocka_unit_test(test_fresnel_reflects_more_at_grazing_angles),
        cmocka_unit_test(test_fog_hides_unshaded),
        cmocka_unit_test(test_fog_end_bounds_the_search),
        cmocka_unit_test(test_identical_bytes_for_any_thread_count),
        cmocka_unit_test(test_tiles_alone_give_the_image_bytes),
        cmocka_unit_test(test_tile_done_tells_each_tile_once),
        cmocka_unit_test(test_progress_reports_every_tile_in_order),
        cmocka_unit_test(test_cancel_flag_stops_the_render),
        cmocka_unit_test(test_cancel_keeps_finished_tiles),
        cmocka_unit_test(test_every_pixel_written),
        cmocka_unit_test(test_bad_transforms_are_refused),
        cmocka_unit_test(test_planes_are_infinite_and_lose_ties),
        cmocka_unit_test(test_rays_past_embree_still_meet_planes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
