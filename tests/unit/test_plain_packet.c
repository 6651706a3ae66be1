/* test_plain_packet.c - packets of one plain material shaded as one
 * (render/plain_packet.c) give the same bits as the integrator's steps
 * lane by lane: a scene's camera packets traced with the shortcut and
 * without, every colour and the count of rays compared, over a plane, a
 * polygon, balls, a smooth mesh, checkers by uv and by plane, the Moon
 * mapped by plane (trilinear and tiled, bilinear and mirrored, placed) and
 * noise textures (placed and not), point, spot and directional lights
 * with falloff, fog, highlights and shadows through glass; and the
 * shortcut taken only where it may be. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render/hit.h"
#include "render/integrator.h"
#include "render/plain_packet.h"

static int add_material(glint_scene *s, glint_material m)
{
    glint_error err;
    int k = glint_scene_add_material(s, NULL, &m, &err);
    assert_true(k >= 0);
    return k;
}

static void add_shape(glint_scene *s, glint_shape desc, int material_index)
{
    glint_error err;
    assert_true(glint_scene_add_shape(s, &desc, material_index, NULL, &err) >= 0);
}

static void add_light(glint_scene *s, glint_light l)
{
    glint_error err;
    assert_true(glint_scene_add_light(s, &l, &err) >= 0);
}

/* What the floor (and the wall) of make_scene wear. */
typedef enum floor_look {
    CHECKS_BY_UV,      /* a checker by the plane's own (u, v); the wall red */
    CHECKS_PLANAR,     /* a checker mapped by plane */
    MOON_PLANAR,       /* the Moon, trilinear, tiled; the wall the Moon too,
                        * placed (turned and moved), bilinear and mirrored */
    NOISE,             /* noise at the hit itself; the wall noise placed */
} floor_look;

/* The Moon map of glint's sources, as a planar-mapped image texture of
 * `scale`, or -1 where the sources are not found. */
static int add_moon(glint_scene *s, double scale, glint_image_filter filter, glint_wrap wrap, bool turned)
{
    const char *src = getenv("GLINT_SOURCE_DIR");
    char path[4096];
    snprintf(path, sizeof path, "%s/assets/moon.jpg", src ? src : ".");
    glint_texture t = glint_texture_default(GLINT_TEXTURE_IMAGE);
    t.file = path;
    t.filter = filter;
    t.wrap_u = t.wrap_v = wrap;
    t.mapping.kind = GLINT_MAP_PLANAR;
    t.mapping.scale = scale;
    if (turned) {
        t.mapping.u_axis = (glint_vec3){1, 0, 0};
        t.mapping.v_axis = (glint_vec3){0, 1, 0};
        t.transform = glint_transform_rotate(glint_transform_identity(), (glint_vec3){0, 0, 1}, 30);
        t.transform = glint_transform_translate(t.transform, 0.2, 0.1, 0);
    }
    glint_error err;
    int k = glint_scene_add_texture(s, NULL, &t, &err);
    assert_true(k >= 0);
    return k;
}

/* A floor of the given look, a ball with noise and highlights, a glass
 * ball whose shadow is tinted, a polygon wall, a smooth mesh (a tent of two
 * triangles with bent normals), each plain but the glass. */
static glint_scene *make_scene(floor_look look)
{
    glint_scene *s = glint_scene_new();
    assert_non_null(s);
    glint_error err;
    glint_settings st = glint_settings_default();
    st.ambient_light = (glint_color){0.2, 0.25, 0.3};
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);

    glint_texture checker = glint_texture_default(GLINT_TEXTURE_CHECKER);
    checker.size = 0.7;
    if (look == CHECKS_PLANAR)
        checker.mapping.kind = GLINT_MAP_PLANAR;
    int checks = glint_scene_add_texture(s, "checks", &checker, &err);
    glint_texture noise = glint_texture_default(GLINT_TEXTURE_NOISE);
    noise.scale = 0.3;
    int clouds = glint_scene_add_texture(s, "clouds", &noise, &err);
    noise.transform = glint_transform_rotate(glint_transform_identity(), (glint_vec3){0, 1, 0}, 20);
    int placed_clouds = glint_scene_add_texture(s, "placed clouds", &noise, &err);
    assert_true(checks >= 0 && clouds >= 0 && placed_clouds >= 0);

    glint_material m = glint_material_default();
    m.specular = 0;
    m.texture = look == MOON_PLANAR ? add_moon(s, 1.5, GLINT_IMAGE_TRILINEAR, GLINT_WRAP_REPEAT, false)
                : look == NOISE     ? clouds
                                    : checks;
    int floor = add_material(s, m);
    m.texture = look == MOON_PLANAR ? add_moon(s, 3, GLINT_IMAGE_BILINEAR, GLINT_WRAP_MIRROR, true)
                : look == NOISE     ? placed_clouds
                                    : -1;
    m.color = (glint_color){0.9, 0.3, 0.2};
    m.specular = 0.4;
    m.shininess = 12;
    int wall_look = add_material(s, m);
    m = glint_material_default();
    m.texture = clouds;
    m.specular = 0.6;
    m.shininess = 30;
    int cloudy = add_material(s, m);
    m = glint_material_default();
    m.color = (glint_color){0.9, 0.3, 0.2};
    m.shininess = 7;
    int red = add_material(s, m);
    m.color = (glint_color){0.6, 0.9, 0.7};
    m.transparency = 0.6;
    int glass = add_material(s, m);

    add_shape(s, (glint_shape){.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}}, floor);
    add_shape(s, (glint_shape){.kind = GLINT_SHAPE_SPHERE, .center = {-1, 1, -1}, .radius = 1}, cloudy);
    add_shape(s, (glint_shape){.kind = GLINT_SHAPE_SPHERE, .center = {1.5, 0.8, 0}, .radius = 0.8}, glass);
    glint_shape wall = glint_shape_default(GLINT_SHAPE_POLYGON);
    wall.points[0] = (glint_vec3){-4, 0, -4};
    wall.points[1] = (glint_vec3){4, 0, -4};
    wall.points[2] = (glint_vec3){4, 4, -4};
    wall.points[3] = (glint_vec3){-4, 4, -4};
    wall.point_count = 4;
    add_shape(s, wall, wall_look);

    static const float positions[] = {2, 0, -3, 4, 0, -3, 3, 2, -2, 3, 0, -1};
    static const float normals[] = {-1, 1, 0, 1, 1, 0, 0, 1, 0.3f, 0, 1, 1};
    static const uint32_t indices[] = {0, 1, 2, 1, 3, 2};
    glint_mesh_data tent = {.positions = positions, .normals = normals, .vertex_count = 4, .indices = indices,
                            .triangle_count = 2, .material = red};
    int tent_mesh = glint_scene_add_mesh(s, "tent", &tent, &err);
    assert_true(tent_mesh >= 0);
    glint_transform identity = glint_transform_identity();
    assert_true(glint_scene_add_instance(s, tent_mesh, -1, &identity, &err) >= 0);

    glint_light point = glint_light_default(GLINT_LIGHT_POINT);
    point.position = (glint_vec3){3, 6, 4};
    point.falloff = GLINT_FALLOFF_FADE;
    point.fade_distance = 5;
    point.fade_power = 2;
    add_light(s, point);
    glint_light spot = glint_light_default(GLINT_LIGHT_SPOT);
    spot.position = (glint_vec3){-2, 5, 2};
    spot.direction = (glint_vec3){0.3, -1, -0.4};
    spot.cone_angle = 25;
    spot.falloff_angle = 8;
    spot.color = (glint_color){0.8, 0.7, 0.3};
    add_light(s, spot);
    glint_light sun = glint_light_default(GLINT_LIGHT_DIRECTIONAL);
    sun.direction = (glint_vec3){-0.5, -1, -0.3};
    sun.color = (glint_color){0.3, 0.3, 0.4};
    add_light(s, sun);
    return s;
}

/* Traces the scene's camera packets, 4 x 2 neighbouring directions each,
 * from (0, 2.5, 7) over the view, with plain packets or without, into
 * colours (w * h of them) and *rays. */
static void trace_view(const glint_scene *scene, const accel *a, bool plain, int w, int h, color *colours,
                       uint64_t *rays)
{
    spectrum bands;
    spectrum_init(&bands, scene->settings.dispersion_bands);
    tracer t = {.scene = scene, .acc = a, .reach = tracer_reach(scene), .keys = tracer_needs_keys(scene),
                .spectrum = &bands, .cone_width = 1e-3, .cone_spread = 2e-3, .plain = plain};
    bool active[ACCEL_PACKET] = {true, true, true, true, true, true, true, true};
    uint32_t key[ACCEL_PACKET] = {0};
    for (int y = 0; y < h; y += 2)
        for (int x = 0; x < w; x += 4) {
            ray8 r;
            for (int i = 0; i < ACCEL_PACKET; i++) {
                double u = (x + i % 4 + 0.5) / w - 0.5, v = 0.5 - (y + i / 4 + 0.5) / h;
                ray8_set(&r, i, (ray){v3(0, 2.5, 7), v3_normalize(v3(1.2 * u, 0.9 * v - 0.25, -1))});
            }
            color out[ACCEL_PACKET];
            tracer_trace8(&t, &r, NULL, active, key, out);
            for (int i = 0; i < ACCEL_PACKET; i++)
                colours[(y + i / 4) * w + x + i % 4] = out[i];
        }
    *rays = t.rays;
}

static accel *build(const glint_scene *scene, bool **shape_opaque, bool **instance_opaque)
{
    assert_true(hit_opacity(scene, shape_opaque, instance_opaque));
    accel_geometry g = {1, scene->shapes, scene->shape_count, scene->meshes, scene->mesh_count, scene->instances,
                        scene->instance_count, *shape_opaque, *instance_opaque, NULL, 0, 0};
    accel *a;
    glint_error err;
    assert_int_equal(accel_build(&a, &g, &err), GLINT_OK);
    return a;
}

/* The scene traced both ways: the same colours, bit for bit, and rays. */
static void assert_same_both_ways(const glint_scene *scene)
{
    assert_true(plain_packet_scene(scene));
    bool *shape_opaque, *instance_opaque;
    accel *a = build(scene, &shape_opaque, &instance_opaque);
    enum { W = 96, H = 64 };
    static color plain[W * H], general[W * H];
    uint64_t plain_rays, general_rays;
    trace_view(scene, a, true, W, H, plain, &plain_rays);
    trace_view(scene, a, false, W, H, general, &general_rays);
    assert_memory_equal(plain, general, sizeof plain);
    assert_int_equal(plain_rays, general_rays);
    /* Something was lit, so the lights' steps were compared. */
    double brightest = 0;
    for (int i = 0; i < W * H; i++)
        brightest = fmax(brightest, plain[i].r);
    assert_true(brightest > 0.5);
    accel_free(a);
    free(shape_opaque);
    free(instance_opaque);
}

static void test_same_bits_as_lane_by_lane(void **state)
{
    (void)state;
    for (floor_look look = CHECKS_BY_UV; look <= NOISE; look++) {
        glint_scene *s = make_scene(look);
        assert_same_both_ways(s);
        glint_scene_free(s);
    }
}

static void test_same_bits_in_fog(void **state)
{
    (void)state;
    for (floor_look look = CHECKS_BY_UV; look <= MOON_PLANAR; look += MOON_PLANAR - CHECKS_BY_UV) {
        glint_scene *s = make_scene(look);
        glint_fog fog = {.kind = GLINT_FOG_LINEAR, .color = {0.5, 0.5, 0.55}, .start = 2, .end = 9};
        assert_int_equal(glint_scene_set_fog(s, &fog, NULL), GLINT_OK);
        assert_same_both_ways(s);
        glint_scene_free(s);
    }
}

/* A packet of eight rays straight down from above (x, z), a hundredth
 * apart along x, and each lane's ray. */
static void down_at(ray8 *r, double x, double z, ray lanes[ACCEL_PACKET])
{
    for (int i = 0; i < ACCEL_PACKET; i++) {
        lanes[i] = (ray){v3(x + 0.01 * i, 3, z), v3(0, -1, 0)};
        ray8_set(r, i, lanes[i]);
    }
}

static void test_taken_only_where_it_may_be(void **state)
{
    (void)state;
    glint_scene *s = make_scene(CHECKS_BY_UV);
    bool *shape_opaque, *instance_opaque;
    accel *a = build(s, &shape_opaque, &instance_opaque);
    spectrum bands;
    spectrum_init(&bands, 3);
    tracer t = {.scene = s, .acc = a, .reach = INFINITY, .spectrum = &bands, .plain = true};
    bool active[ACCEL_PACKET] = {true, true, true, true, true, true, true, true}, found[ACCEL_PACKET];
    int skip[ACCEL_PACKET] = {-1, -1, -1, -1, -1, -1, -1, -1};
    accel_hit hits[ACCEL_PACKET];
    double travelled[ACCEL_PACKET] = {0};
    color local[ACCEL_PACKET];
    ray8 r;
    ray lane_ray[ACCEL_PACKET];

    /* All on the checkered floor: taken. */
    down_at(&r, -3, 3, lane_ray);
    accel_intersect8(a, &r, NULL, INFINITY, skip, true, active, hits, found);
    assert_true(plain_packet_shade(&t, &r, lane_ray, hits, found, 0, travelled, local));
    /* Half on the glass ball (it sends rays on): not taken. */
    down_at(&r, 2.27, 0, lane_ray);
    accel_intersect8(a, &r, NULL, INFINITY, skip, true, active, hits, found);
    assert_true(found[0] && found[7] && hits[0].shape != hits[7].shape);
    assert_false(plain_packet_shade(&t, &r, lane_ray, hits, found, 0, travelled, local));
    accel_free(a);
    free(shape_opaque);
    free(instance_opaque);

    /* An area light: never. */
    glint_light lamp = glint_light_default(GLINT_LIGHT_SPHERE);
    lamp.position = (glint_vec3){0, 5, 0};
    lamp.radius = 0.5;
    add_light(s, lamp);
    assert_false(plain_packet_scene(s));
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_bits_as_lane_by_lane),
        cmocka_unit_test(test_same_bits_in_fog),
        cmocka_unit_test(test_taken_only_where_it_may_be),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
