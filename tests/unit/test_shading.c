/* test_shading.c - optics, lights, textures, mappings, fog and materials,
 * each checked against values worked out by hand. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "shading/environment.h"
#include "shading/fog.h"
#include "shading/light.h"
#include "shading/material.h"
#include "shading/optics.h"
#include "shading/texture.h"

#define EPS 1e-12
#define ORIGIN v3(0, 0, 0)
#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

static void assert_vec_near(vec3 a, vec3 b, double eps)
{
    assert_near(a.x, b.x, eps);
    assert_near(a.y, b.y, eps);
    assert_near(a.z, b.z, eps);
}

static double deg(double radians) { return radians * 180 / M_PI; }

static void test_reflection_direction(void **state)
{
    vec3 d = v3_normalize(v3(1, -1, 0));
    assert_vec_near(optics_reflect(d, v3(0, 1, 0)), v3_normalize(v3(1, 1, 0)), EPS);
    /* Straight on comes straight back. */
    assert_vec_near(optics_reflect(v3(0, 0, -1), v3(0, 0, 1)), v3(0, 0, 1), EPS);
}

static void test_snell_angle(void **state)
{
    /* 45 degrees from air into glass of index 1.5: sin t = sin 45 / 1.5. */
    vec3 d = v3_normalize(v3(1, -1, 0)), t;
    assert_true(optics_refract(d, v3(0, 1, 0), 1 / 1.5, &t));
    double expected = asin(sin(M_PI / 4) / 1.5);
    assert_near(atan2(t.x, -t.y), expected, 1e-12);
    assert_near(v3_length(t), 1, 1e-12);
    assert_true(t.y < 0);
    /* Normal incidence passes straight through. */
    assert_true(optics_refract(v3(0, -1, 0), v3(0, 1, 0), 1 / 1.5, &t));
    assert_vec_near(t, v3(0, -1, 0), EPS);
}

static void test_total_internal_reflection(void **state)
{
    vec3 t;
    /* Leaving glass (1.5) into air: critical angle asin(1/1.5) = 41.81 degrees. */
    double crit = asin(1 / 1.5);
    vec3 steep = v3(sin(crit - 0.01), -cos(crit - 0.01), 0);
    vec3 shallow = v3(sin(crit + 0.01), -cos(crit + 0.01), 0);
    assert_true(optics_refract(steep, v3(0, 1, 0), 1.5, &t));
    assert_false(optics_refract(shallow, v3(0, 1, 0), 1.5, &t));
    assert_near(optics_fresnel(cos(crit + 0.01), 1.5), 1, 0);
    assert_near(deg(crit), 41.8103148957786, 1e-9);
}

static void test_fresnel(void **state)
{
    /* Normal incidence: ((n1 - n2) / (n1 + n2))^2 = 0.04 for 1 -> 1.5. */
    assert_near(optics_fresnel(1, 1 / 1.5), 0.04, 1e-12);
    assert_near(optics_fresnel(1, 1.5), 0.04, 1e-12);
    /* Grazing incidence reflects everything. */
    assert_near(optics_fresnel(1e-9, 1 / 1.5), 1, 1e-6);
    /* Brewster's angle: p-polarised reflectance vanishes, so R = Rs / 2. */
    double b = atan(1.5), ct = cos(M_PI / 2 - b);
    double rs = (cos(b) - 1.5 * ct) / (cos(b) + 1.5 * ct);
    assert_near(optics_fresnel(cos(b), 1 / 1.5), 0.5 * rs * rs, 1e-12);
}

static light make_spot(double cone, double falloff)
{
    glint_light d = {.kind = GLINT_LIGHT_SPOT, .position = {0, 10, 0}, .direction = {0, -1, 0},
                     .color = {1, 1, 1}, .cone_angle = cone, .falloff_angle = falloff};
    light l;
    assert_int_equal(light_init(&l, &d, NULL), GLINT_OK);
    return l;
}

static void test_spotlight(void **state)
{
    light l = make_spot(20, 10);
    light_sample s = {0};
    /* Straight below: full light, at distance 10. */
    assert_true(light_delta_sample(&l, v3(0, 0, 0), &s));
    assert_near(s.distance, 10, EPS);
    assert_vec_near(s.to_light, v3(0, 1, 0), EPS);
    assert_near(s.radiance.r, 1, EPS);
    /* 5 degrees off axis: inside the inner cone (10 degrees). */
    assert_true(light_delta_sample(&l, v3(10 * tan(5 * M_PI / 180), 0, 0), &s));
    assert_near(s.radiance.g, 1, EPS);
    /* 25 degrees off axis: outside the cone. */
    assert_false(light_delta_sample(&l, v3(10 * tan(25 * M_PI / 180), 0, 0), &s));
    /* In the falloff, halfway in cosine: smoothstep(0.5) = 0.5. */
    double c = 0.5 * (cos(20 * M_PI / 180) + cos(10 * M_PI / 180));
    assert_near(spot_factor(&l, c), 0.5, 1e-12);
    double c2 = cos(20 * M_PI / 180) + 0.25 * (cos(10 * M_PI / 180) - cos(20 * M_PI / 180));
    assert_near(spot_factor(&l, c2), 0.15625, 1e-12);
    /* Hard edge when falloff is 0: the original's cut-off. */
    light hard = make_spot(8.5, 0);
    assert_near(spot_factor(&hard, cos(8.49 * M_PI / 180)), 1, 0);
    assert_near(spot_factor(&hard, cos(8.51 * M_PI / 180)), 0, 0);
    /* The same edge through light_delta_sample, whose quick rejection of
     * points outside the cone must leave those just inside lit. */
    assert_true(light_delta_sample(&hard, v3(10 * tan(8.4999 * M_PI / 180), 0, 0), &s));
    assert_near(s.radiance.r, 1, 0);
    assert_false(light_delta_sample(&hard, v3(10 * tan(8.5001 * M_PI / 180), 0, 0), &s));
    assert_false(light_delta_sample(&hard, v3(0, 10, 5), &s));
    /* Behind the spot: nothing. */
    assert_false(light_delta_sample(&l, v3(0, 20, 0), &s));
}

static void test_point_and_directional(void **state)
{
    glint_light pd = {.kind = GLINT_LIGHT_POINT, .position = {3, 4, 0}, .color = {0.5, 1, 2}};
    glint_light dd = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {0, -2, 0}, .color = {1, 1, 1}};
    light p, d;
    light_sample s = {0};
    assert_int_equal(light_init(&p, &pd, NULL), GLINT_OK);
    assert_true(light_delta_sample(&p, v3(0, 0, 0), &s));
    assert_near(s.distance, 5, EPS);
    assert_vec_near(s.to_light, v3(0.6, 0.8, 0), EPS);
    assert_near(s.radiance.b, 2, EPS);
    assert_int_equal(light_init(&d, &dd, NULL), GLINT_OK);
    assert_true(light_delta_sample(&d, v3(7, 7, 7), &s));
    assert_true(isinf(s.distance));
    assert_vec_near(s.to_light, v3(0, 1, 0), EPS);
}

static void test_light_errors(void **state)
{
    glint_error err;
    light l;
    glint_light bad = {.kind = GLINT_LIGHT_SPOT, .direction = {0, -1, 0}, .color = {1, 1, 1}, .cone_angle = 95};
    assert_int_equal(light_init(&l, &bad, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "spot light angle must be more than 0 and at most 90 degrees, got 95");
    bad.cone_angle = 10;
    bad.direction = v3(0, 0, 0);
    assert_int_equal(light_init(&l, &bad, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "spot light direction must not be zero");
    bad.direction = v3(0, -1, 0);
    bad.color.g = NAN;
    assert_int_equal(light_init(&l, &bad, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "spot light color must be finite and not negative");
    bad.color.g = 1;
    bad.falloff_angle = 12;
    assert_int_equal(light_init(&l, &bad, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "spot light falloff must not exceed its angle 10, got 12");
    glint_light far = {.kind = GLINT_LIGHT_POINT, .position = {0, INFINITY, 0}, .color = {1, 1, 1}};
    assert_int_equal(light_init(&l, &far, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "point light position is not finite");
    glint_light odd = {.kind = (glint_light_kind)7};
    assert_int_equal(light_init(&l, &odd, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "unknown light kind 7");
}

static void test_checker(void **state)
{
    color a = {1, 1, 1}, b = {0, 0, 0};
    /* The original floor: 5-unit cells. */
    assert_near(checker_eval(a, b, 5, 0.1, 0.1).r, 1, 0);
    assert_near(checker_eval(a, b, 5, 5.1, 0.1).r, 0, 0);
    assert_near(checker_eval(a, b, 5, 5.1, 5.1).r, 1, 0);
    assert_near(checker_eval(a, b, 5, -0.1, 0.1).r, 0, 0);
    assert_near(checker_eval(a, b, 5, -0.1, -0.1).r, 1, 0);
    assert_near(checker_eval(a, b, 5, -12, -3).r, 1, 0); /* cells -3 and -1: even */
    assert_near(checker_eval(a, b, 5, -12, 3).r, 0, 0);  /* cells -3 and 0: odd */
    assert_near(checker_eval(a, b, 5, -7, 14).r, 1, 0);  /* cells -2 and 2 */
    /* Any two colours, any size. */
    color red = {1, 0, 0}, blue = {0, 0, 1};
    assert_near(checker_eval(red, blue, 0.25, 0.3, 0.1).b, 1, 0);
    assert_near(checker_eval(red, blue, 0.25, 0.6, 0.1).r, 1, 0);
}

static surface at_object_point(vec3 p)
{
    surface s;
    memset(&s, 0, sizeof s);
    s.p = s.p_obj = p;
    return s;
}

static void test_spherical_mapping(void **state)
{
    glint_mapping m = {.kind = GLINT_MAP_SPHERICAL, .center = {3, 2, -80}, .center_given = true};
    double u, v;
    surface s = at_object_point(v3(3, 6, -80)); /* north pole */
    mapping_apply(&m, &s, ORIGIN, &u, &v);
    assert_near(v, 0, 1e-12);
    s = at_object_point(v3(3, -2, -80)); /* south pole */
    mapping_apply(&m, &s, ORIGIN, &u, &v);
    assert_near(v, 1, 1e-12);
    s = at_object_point(v3(3, 2, -76)); /* facing +z: centre of the map */
    mapping_apply(&m, &s, ORIGIN, &u, &v);
    assert_near(u, 0.5, 1e-12);
    assert_near(v, 0.5, 1e-12);
    s = at_object_point(v3(7, 2, -80)); /* +x: a quarter turn on */
    mapping_apply(&m, &s, ORIGIN, &u, &v);
    assert_near(u, 0.75, 1e-12);
    /* Across the seam at -z, u jumps from 1 to 0. */
    s = at_object_point(v3(3 + 1e-9, 2, -84));
    mapping_apply(&m, &s, ORIGIN, &u, &v);
    assert_near(u, 1, 1e-9);
    s = at_object_point(v3(3 - 1e-9, 2, -84));
    mapping_apply(&m, &s, ORIGIN, &u, &v);
    assert_near(u, 0, 1e-9);
}

static void test_planar_and_cylindrical_mapping(void **state)
{
    double u, v;
    glint_mapping planar = {.kind = GLINT_MAP_PLANAR};
    surface s = at_object_point(v3(7, -15, -12));
    mapping_apply(&planar, &s, ORIGIN, &u, &v);
    assert_near(u, 7, EPS);
    assert_near(v, -12, EPS);
    glint_mapping wall = {.kind = GLINT_MAP_PLANAR, .center = {0, 2, 0}, .center_given = true, .u_axis = {0, 0, 2},
                          .v_axis = {0, -1, 0}, .scale = 2};
    s = at_object_point(v3(1, 4, 6));
    mapping_apply(&wall, &s, ORIGIN, &u, &v);
    assert_near(u, 3, EPS);
    assert_near(v, -1, EPS);
    glint_mapping cyl = {.kind = GLINT_MAP_CYLINDRICAL, .center = {0, 1, 0}, .center_given = true, .scale = 4};
    s = at_object_point(v3(0, 3, 2));
    mapping_apply(&cyl, &s, ORIGIN, &u, &v);
    assert_near(u, 0.5, EPS);
    assert_near(v, 0.5, EPS);
    s = at_object_point(v3(-2, 1, 0));
    mapping_apply(&cyl, &s, ORIGIN, &u, &v);
    assert_near(u, 0.25, EPS);
    assert_near(v, 0, EPS);
    glint_error err;
    glint_mapping bad = {.kind = GLINT_MAP_PLANAR, .u_axis = {1, 0, 0}, .v_axis = {2, 0, 0}};
    assert_int_equal(mapping_validate(&bad, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "planar mapping axes must not be parallel");
}

/* The (u, v) a mapping gives at object point p of shape d (untransformed). */
static void uv_on(const glint_shape *d, glint_mapping m, vec3 p, double *u, double *v)
{
    shape s;
    glint_error err;
    assert_int_equal(shape_init(&s, d, NULL, 0, &err), GLINT_OK);
    surface at = at_object_point(p);
    mapping_apply(&m, &at, shape_center(&s, 0), u, v);
}

/* Spherical and cylindrical mappings without a center go around the shape
 * they are on: a sphere away from the origin shows its map as one at the
 * origin does, pole at the top. A planar mapping still starts from the
 * origin, and a given center still means that point. */
static void test_mapping_centred_on_the_shape(void **state)
{
    glint_mapping sph = {.kind = GLINT_MAP_SPHERICAL};
    glint_shape home = {.kind = GLINT_SHAPE_SPHERE, .radius = 1};
    glint_shape away = {.kind = GLINT_SHAPE_SPHERE, .center = {-3, 1, 0}, .radius = 1};
    double u, v, u0, v0;
    uv_on(&away, sph, v3(-3, 2, 0), &u, &v); /* the top: the north pole */
    assert_near(v, 0, EPS);
    uv_on(&away, sph, v3(-3, 1, 1), &u, &v); /* facing +z: the middle of the map */
    assert_near(u, 0.5, EPS);
    assert_near(v, 0.5, EPS);
    vec3 dirs[] = {v3(0.6, 0.8, 0), v3(-0.48, 0.6, 0.64), v3(0, -0.28, -0.96), v3(0.36, -0.48, 0.8)};
    for (int i = 0; i < 4; i++) {
        uv_on(&home, sph, dirs[i], &u0, &v0);
        uv_on(&away, sph, v3_add(away.center, dirs[i]), &u, &v);
        assert_near(u, u0, 1e-12);
        assert_near(v, v0, 1e-12);
    }
    /* A cylinder's centre is its base's: v is the height above it. */
    glint_mapping cyl = {.kind = GLINT_MAP_CYLINDRICAL, .scale = 2};
    glint_shape can = {.kind = GLINT_SHAPE_CYLINDER, .center = {2, -1, 5}, .radius = 1, .height = 2, .capped = true};
    uv_on(&can, cyl, v3(2, 0, 6), &u, &v);
    assert_near(u, 0.5, EPS);
    assert_near(v, 0.5, EPS);
    glint_shape cone = {.kind = GLINT_SHAPE_CONE, .center = {2, -1, 5}, .radius = 1, .height = 2};
    uv_on(&cone, cyl, v3(1.5, 0, 5), &u, &v);
    assert_near(u, 0.25, EPS);
    assert_near(v, 0.5, EPS);
    /* A box's is the middle of its bounds. */
    glint_shape box = {.kind = GLINT_SHAPE_BOX, .min = {4, 0, 0}, .max = {6, 2, 2}};
    uv_on(&box, sph, v3(5, 2, 1), &u, &v);
    assert_near(v, 0, EPS);
    /* Planar: u = x, v = z from the origin, wherever the shape is. */
    glint_mapping planar = {.kind = GLINT_MAP_PLANAR};
    uv_on(&away, planar, v3(-3, 2, 0.5), &u, &v);
    assert_near(u, -3, EPS);
    assert_near(v, 0.5, EPS);
    /* A given center is that point in the shape's coordinates: the top of
     * the sphere away is seen from the origin, 2 up and 3 across. */
    glint_mapping given = {.kind = GLINT_MAP_SPHERICAL, .center_given = true};
    uv_on(&away, given, v3(-3, 2, 0), &u, &v);
    assert_near(v, 0.5 - asin(2 / sqrt(13.0)) / M_PI, EPS);
    /* A center without the flag would be ignored: it is refused. */
    glint_error err;
    glint_mapping unflagged = {.kind = GLINT_MAP_SPHERICAL, .center = {0, 1, 0}};
    assert_int_equal(mapping_validate(&unflagged, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "mapping center is set but center_given is false");
}

static const glint_wrap R = GLINT_WRAP_REPEAT, C = GLINT_WRAP_CLAMP, M = GLINT_WRAP_MIRROR;

/* Two texels, red then blue, as a width x height image (2x1 or 1x2). Its
 * bytes map to linear values through the image's own table. */
static texture_image red_then_blue(int width, int height)
{
    static const unsigned char px[6] = {255, 0, 0, 0, 0, 255};
    static float linear[256];
    for (int i = 0; i < 256; i++)
        linear[i] = (float)i / 255;
    return (texture_image){.width = width, .height = height, .srgb = px, .linear = linear};
}

static void test_image_lookup(void **state)
{
    /* Red then blue along u: texel centres at u = 0.25 and 0.75. */
    texture_image img = red_then_blue(2, 1);
    color c = image_eval(&img, 0.25, 0.5, R, C);
    assert_near(c.r, 1, 1e-7);
    assert_near(c.b, 0, 1e-7);
    c = image_eval(&img, 0.5, 0.5, R, C);
    assert_near(c.r, 0.5, 1e-7);
    assert_near(c.b, 0.5, 1e-7);
    /* u wraps: 0 sits halfway between the last and first texel. */
    c = image_eval(&img, 0, 0.5, R, C);
    assert_near(c.r, 0.5, 1e-7);
    c = image_eval(&img, 1.25, 0.5, R, C);
    assert_near(c.r, 1, 1e-7);
    /* v clamps. */
    c = image_eval(&img, 0.75, -3, R, C);
    assert_near(c.b, 1, 1e-7);
}

/* Past the edges, each wrap: a 2x1 image red then blue along u, a 1x2 one
 * red over blue along v; texel centres at 0.25 and 0.75. */
static void test_image_wraps(void **state)
{
    texture_image wide = red_then_blue(2, 1), tall = red_then_blue(1, 2);
    /* 1.25: repeat reads 0.25 (red), clamp the edge (blue), mirror 0.75
     * (blue); -0.25: repeat reads 0.75, clamp the first edge, mirror 0.25;
     * 2.25: mirror reads 0.25 again. */
    const struct {
        double at;
        glint_wrap wrap;
        double red;
    } cases[] = {{1.25, R, 1}, {1.25, C, 0}, {1.25, M, 0}, {-0.25, R, 0}, {-0.25, C, 1},
                 {-0.25, M, 1}, {2.25, M, 1}, {1.75, M, 1}, {-0.75, R, 1}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        color along_u = image_eval(&wide, cases[i].at, 0.5, cases[i].wrap, C);
        color along_v = image_eval(&tall, 0.5, cases[i].at, R, cases[i].wrap);
        assert_near(along_u.r, cases[i].red, 1e-7);
        assert_near(along_v.r, cases[i].red, 1e-7);
        assert_near(along_u.b, 1 - cases[i].red, 1e-7);
    }
}

/* The solid checker, cells of 0.25: the parity of the sum of the three
 * cell indices of the point in the thing's own coordinates, whatever the
 * mapping says; as a sky, its colour at the direction. */
static void test_checker_3d(void **state)
{
    glint_texture d = glint_texture_default(GLINT_TEXTURE_CHECKER_3D);
    d.colors[0] = (glint_color){1, 0, 0};
    d.colors[1] = (glint_color){0, 0, 1};
    d.size = 0.25;
    d.mapping.kind = GLINT_MAP_PLANAR;
    texture t;
    glint_error err = {0};
    assert_int_equal(texture_init(&t, &d, NULL, NULL, &err), GLINT_OK);
    const struct {
        vec3 p;
        double red;
    } cases[] = {{{0.1, 0.1, 0.1}, 1},  /* 0 + 0 + 0 */
                 {{0.3, 0.1, 0.1}, 0},  /* 1 + 0 + 0 */
                 {{-0.1, 0.1, 0.1}, 0}, /* -1 + 0 + 0 */
                 {{0.3, 0.3, 0.1}, 1},  /* 1 + 1 + 0 */
                 {{0.3, 0.3, 0.3}, 0},  /* 1 + 1 + 1 */
                 {{-0.3, 0.6, 0.1}, 1}}; /* -2 + 2 + 0 */
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        color c = t.kind->solid(&t, texture_place(&t, cases[i].p));
        assert_true(c.r == cases[i].red && c.b == 1 - cases[i].red);
    }
    /* Straight up, (0, 1, 0): cell indices 0, 4 and 0. */
    glint_environment sky = {.texture = 0, .intensity = 2};
    color up = environment_color(&sky, &t, v3(0, 1, 0));
    assert_true(up.r == 2 && up.b == 0);
    texture_release(&t);
}

static void test_fog(void **state)
{
    glint_fog f = {.kind = GLINT_FOG_LINEAR, .color = {0.8, 0.8, 0.8}, .start = -16, .end = 284};
    assert_near(fog_factor(&f, -20), 0, 0);           /* before its range */
    assert_near(fog_factor(&f, 134), 0.5, 1e-12);     /* inside */
    assert_near(fog_factor(&f, 54), 70.0 / 300, 1e-12);
    assert_near(fog_factor(&f, 1000), 1, 0);          /* beyond: clamped */
    assert_near(fog_factor(&f, INFINITY), 1, 0);
    color c = fog_apply(&f, rgb(0, 0.4, 1), 134);
    assert_near(c.r, 0.4, 1e-12);
    assert_near(c.g, 0.6, 1e-12);
    assert_near(c.b, 0.9, 1e-12);
    glint_fog e = {.kind = GLINT_FOG_EXPONENTIAL, .color = {1, 1, 1}, .density = 0.1};
    assert_near(fog_factor(&e, 0), 0, 0);
    assert_near(fog_factor(&e, 10), 1 - exp(-1), 1e-12);
    glint_fog none = {.kind = GLINT_FOG_NONE};
    assert_near(fog_factor(&none, 1e9), 0, 0);
    glint_error err;
    f.start = 300;
    assert_int_equal(fog_validate(&f, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "linear fog needs start < end, got 300 and 284");
    e.density = 0;
    assert_int_equal(fog_validate(&e, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "fog density must be positive, got 0");
}

/* Where fog hides a surface completely, fog_apply gives exactly the fog
 * colour, whatever the surface showed, so shading can be skipped. */
static void test_fog_hides(void **state)
{
    glint_fog f = {.kind = GLINT_FOG_LINEAR, .color = {0.8, 0.3, 0.1}, .start = -16, .end = 284};
    assert_false(fog_hides(&f, 283.999));
    assert_true(fog_hides(&f, 284));
    assert_true(fog_hides(&f, INFINITY));
    const color shown[] = {{0, 0, 0}, {0.123456789, 7.5, 1e-300}, {1e300, 0.3, 0.8}};
    for (int i = 0; i < 3; i++) {
        color c = fog_apply(&f, shown[i], 300);
        assert_true(c.r == 0.8 && c.g == 0.3 && c.b == 0.1);
    }
    glint_fog e = {.kind = GLINT_FOG_EXPONENTIAL, .color = {1, 1, 1}, .density = 0.1};
    assert_false(fog_hides(&e, 10));
    assert_false(fog_hides(&e, 300));          /* 1 - exp(-30) rounds below 1 */
    assert_true(fog_hides(&e, 1e4));           /* exp(-1000) is 0 */
    glint_fog none = {.kind = GLINT_FOG_NONE};
    assert_false(fog_hides(&none, INFINITY));
}

static void test_phong(void **state)
{
    glint_material m = glint_material_default();
    color white = {1, 1, 1}, c = {0.5, 0.25, 1};
    vec3 n = v3(0, 1, 0);
    /* Light at 60 degrees: diffuse cos = 0.5; the eye on the mirror direction
     * sees the full highlight. */
    vec3 l = v3(sin(M_PI / 3), cos(M_PI / 3), 0), eye = v3(-sin(M_PI / 3), cos(M_PI / 3), 0);
    color out = phong_light(&m, c, n, l, eye, white);
    assert_near(out.r, 0.25 + 1, 1e-12);
    assert_near(out.g, 0.125 + 1, 1e-12);
    /* Away from the mirror direction, the highlight falls as cos^50. */
    vec3 eye2 = n; /* 60 degrees from the reflection: r.v = 0.5 */
    out = phong_light(&m, c, n, l, eye2, white);
    assert_near(out.b, 0.5 + pow(0.5, 50), 1e-12);
    /* Light behind the surface: nothing. */
    out = phong_light(&m, c, n, v3(0, -1, 0), eye, white);
    assert_near(rgb_max(out), 0, 0);
    /* A metal's highlight takes its colour: all of it at metallic 1, a
     * quarter of the way from white at 0.25. */
    m.metallic = 1;
    out = phong_light(&m, c, n, l, eye, white);
    assert_near(out.r, 0.25 + 0.5, 1e-12);
    assert_near(out.g, 0.125 + 0.25, 1e-12);
    assert_near(out.b, 0.5 + 1, 1e-12);
    m.metallic = 0.25;
    out = phong_light(&m, c, n, l, eye, white);
    assert_near(out.g, 0.125 + 0.75 + 0.25 * 0.25, 1e-12);
}

/* phong_reaches says no only where phong_light is black, and stays black
 * however a shadow dims the light: then no shadow ray is traced. */
static void test_phong_reaches(void **state)
{
    glint_material m = glint_material_default();
    color black = {0, 0, 0}, red = {1, 0, 0}, green_light = {0, 1, 0}, white = {1, 1, 1};
    vec3 n = v3(0, 1, 0), l = v3(sin(M_PI / 3), cos(M_PI / 3), 0);
    vec3 facing = v3(-sin(M_PI / 3), cos(M_PI / 3), 0); /* on the mirror direction: r.v = 1 */
    vec3 behind = v3(sin(M_PI / 3), cos(M_PI / 3), 0);  /* r.v = -0.5: no highlight */
    struct {
        double specular, diffuse;
        color c, radiance;
        vec3 eye;
        bool reaches;
    } cases[] = {
        {1, 1, red, white, behind, true},          /* diffuse */
        {0, 1, red, green_light, facing, false},   /* red surface, green light, no highlight */
        {1, 1, red, green_light, facing, true},    /* ... but a highlight of the green light */
        {1, 1, black, white, facing, true},        /* a black mirror's highlight */
        {1, 1, black, white, behind, false},       /* and away from it */
        {0, 0, red, white, facing, false},         /* neither diffuse nor specular */
        {1, 1, red, black, facing, false},         /* no light */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        m.specular = cases[i].specular;
        m.diffuse = cases[i].diffuse;
        assert_int_equal(phong_reaches(&m, cases[i].c, n, l, cases[i].eye, cases[i].radiance), cases[i].reaches);
        color dimmed = rgb_scale(cases[i].radiance, 0.37);
        color out = phong_light(&m, cases[i].c, n, l, cases[i].eye, dimmed);
        if (!cases[i].reaches)
            assert_true(out.r == 0 && out.g == 0 && out.b == 0);
        else
            assert_true(rgb_max(out) > 0);
    }
}

static void test_material_validation(void **state)
{
    glint_error err;
    glint_material m = glint_material_default();
    assert_int_equal(material_validate(&m, 0, &err), GLINT_OK);
    m.ior = 0;
    assert_int_equal(material_validate(&m, 0, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "material ior must be positive, got 0");
    m = glint_material_default();
    m.transparency = 0.6;
    m.refraction = 0.6;
    assert_int_equal(material_validate(&m, 0, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "material transparency + refraction must not exceed 1, got 1.2");
    m = glint_material_default();
    m.reflectivity = NAN;
    assert_int_equal(material_validate(&m, 0, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "material reflectivity is not finite");
    m = glint_material_default();
    m.ambient = 1.5;
    assert_int_equal(material_validate(&m, 0, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "material ambient must be from 0 to 1, got 1.5");
    m = glint_material_default();
    m.color.g = -0.25;
    assert_int_equal(material_validate(&m, 0, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "material color must be finite and not negative");
    m = glint_material_default();
    m.texture = 2;
    assert_int_equal(material_validate(&m, 2, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, "material texture 2 does not exist");
    /* The transmission filter: tint 0 is clear, tint 1 the colour. */
    m = glint_material_default();
    m.tint = 0.5;
    color f = material_filter(&m, rgb(1, 0, 0));
    assert_near(f.r, 1, EPS);
    assert_near(f.g, 0.5, EPS);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_reflection_direction),
        cmocka_unit_test(test_snell_angle),
        cmocka_unit_test(test_total_internal_reflection),
        cmocka_unit_test(test_fresnel),
        cmocka_unit_test(test_spotlight),
        cmocka_unit_test(test_point_and_directional),
        cmocka_unit_test(test_light_errors),
        cmocka_unit_test(test_checker),
        cmocka_unit_test(test_spherical_mapping),
        cmocka_unit_test(test_planar_and_cylindrical_mapping),
        cmocka_unit_test(test_mapping_centred_on_the_shape),
        cmocka_unit_test(test_image_lookup),
        cmocka_unit_test(test_image_wraps),
        cmocka_unit_test(test_checker_3d),
        cmocka_unit_test(test_fog),
        cmocka_unit_test(test_fog_hides),
        cmocka_unit_test(test_phong),
        cmocka_unit_test(test_phong_reaches),
        cmocka_unit_test(test_material_validation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
