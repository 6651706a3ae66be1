/* seed_room.c - the built-in default scene: the room the original COSC363
 * ray tracer rendered, rebuilt from its facts (see README). Its colours were
 * display values; they are converted to linear here so the lit surfaces show
 * the original's colours. */
#include <stdlib.h>
#include "core/error.h"
#include "scene/scene.h"

/* assets/moon.jpg, decoded when glint was built (tools/embed_image.c): no
 * JPEG decoding at start-up, which took 4 ms of every render of this scene.
 * GLINT_MOON_FILE is where that file was (CMakeLists.txt). */
extern const int glint_asset_moon_width, glint_asset_moon_height;
extern const unsigned char glint_asset_moon_srgb[];

/* Builds the scene step by step, remembering the first failure so that the
 * description below reads as a list of facts. */
typedef struct builder {
    glint_scene *scene;
    glint_error *err;
    bool failed;
} builder;

static color display(double r, double g, double b)
{
    return rgb(glint_srgb_to_linear(r), glint_srgb_to_linear(g), glint_srgb_to_linear(b));
}

static int check(builder *b, int index)
{
    if (index < 0)
        b->failed = true;
    return index;
}

static int add_material(builder *b, color c, double specular)
{
    glint_material m = glint_material_default();
    m.color = c;
    m.specular = specular;
    return check(b, glint_scene_add_material(b->scene, NULL, &m, b->err));
}

static void add_shape(builder *b, glint_shape *s, int mat)
{
    if (mat >= 0)
        check(b, glint_scene_add_shape(b->scene, s, mat, NULL, b->err));
}

static void sphere(builder *b, vec3 centre, double radius, int mat)
{
    glint_shape s = {.kind = GLINT_SHAPE_SPHERE, .center = centre, .radius = radius};
    add_shape(b, &s, mat);
}

static void polygon(builder *b, int count, const vec3 *points, int mat)
{
    glint_shape s = {.kind = GLINT_SHAPE_POLYGON, .point_count = count};
    for (int i = 0; i < count; i++)
        s.points[i] = points[i];
    add_shape(b, &s, mat);
}

static void quad(builder *b, vec3 p0, vec3 p1, vec3 p2, vec3 p3, int mat)
{
    vec3 p[4] = {p0, p1, p2, p3};
    polygon(b, 4, p, mat);
}

static void triangle(builder *b, vec3 p0, vec3 p1, vec3 p2, int mat)
{
    vec3 p[3] = {p0, p1, p2};
    polygon(b, 3, p, mat);
}

static void upright(builder *b, glint_shape_kind kind, vec3 base, double radius, double height, int mat)
{
    glint_shape s = {.kind = kind, .center = base, .radius = radius, .height = height, .capped = true};
    add_shape(b, &s, mat);
}

static void room(builder *b)
{
    glint_mapping floor_map = {.kind = GLINT_MAP_PLANAR};
    int checks = check(b, glint_scene_add_checker(b->scene, "floor-checks", rgb(0, 0, 0), rgb(1, 1, 1), 5,
                                                  floor_map, b->err));
    glint_material floor = glint_material_default();
    floor.texture = checks;
    if (checks >= 0)
        quad(b, v3(-50, -15, 5), v3(50, -15, 5), v3(50, -15, -300), v3(-50, -15, -300),
             check(b, glint_scene_add_material(b->scene, "floor", &floor, b->err)));

    quad(b, v3(-50, -15, -300), v3(50, -15, -300), v3(50, 100, -300), v3(-50, 100, -300),
         add_material(b, display(0.192, 0.192, 0.192), 0));
    quad(b, v3(50, -15, -300), v3(50, -15, 5), v3(50, 100, 5), v3(50, 100, -300),
         add_material(b, display(1, 0, 0), 0));
    quad(b, v3(-50, -15, 5), v3(-50, -15, -300), v3(-50, 100, -300), v3(-50, 100, 5),
         add_material(b, display(0, 1, 1), 0));
    quad(b, v3(50, -15, 5), v3(-50, -15, 5), v3(-50, 100, 5), v3(50, 100, 5),
         add_material(b, display(0, 0, 1), 0));
    quad(b, v3(-50, 100, 5), v3(-50, 100, -300), v3(50, 100, -300), v3(50, 100, 5),
         add_material(b, display(0.8, 0.8, 0.8), 0));
}

static void props(builder *b)
{
    glint_material mirror = glint_material_default();
    mirror.color = rgb(0, 0, 0);
    mirror.reflectivity = 1;
    sphere(b, v3(-10, 1, -50), 3, check(b, glint_scene_add_material(b->scene, "mirror", &mirror, b->err)));
    upright(b, GLINT_SHAPE_CYLINDER, v3(-10, -15, -50), 2, 13, add_material(b, display(1, 0.4, 0.2), 1));

    glint_material clear_red = glint_material_default();
    clear_red.color = display(1, 0, 0);
    clear_red.specular = 0;
    clear_red.transparency = 0.8;
    clear_red.tint = 0.5;
    sphere(b, v3(3, -10, -60), 5, check(b, glint_scene_add_material(b->scene, "red-glass", &clear_red, b->err)));

    glint_mapping own_uv = {.kind = GLINT_MAP_UV};
    glint_material moon = glint_material_default();
    moon.specular = 0;
    moon.texture = check(b, scene_add_image_pixels(b->scene, "moon", glint_asset_moon_width, glint_asset_moon_height,
                                                    glint_asset_moon_srgb, GLINT_MOON_FILE, own_uv, b->err));
    if (moon.texture >= 0)
        sphere(b, v3(3, 2, -80), 4, check(b, glint_scene_add_material(b->scene, "moon", &moon, b->err)));
    upright(b, GLINT_SHAPE_CONE, v3(3, -5, -80), 4, 6, add_material(b, display(0.5, 0.5, 0.5), 1));

    glint_material glass = glint_material_default();
    glass.color = rgb(0, 0, 0);
    glass.refraction = 0.8;
    glass.ior = 1.2;
    glass.tint = 0;
    sphere(b, v3(15, -10, -70), 3, check(b, glint_scene_add_material(b->scene, "glass", &glass, b->err)));

    int face = add_material(b, display(0.6, 0, 0.01), 1), sides = add_material(b, display(0.6, 0.55, 0.01), 1);
    vec3 apex = v3(12, -10, -65);
    triangle(b, v3(12, -15, -60), v3(15, -15, -65), apex, face);
    triangle(b, v3(15, -15, -65), v3(12, -15, -70), apex, sides);
    triangle(b, v3(12, -15, -70), v3(9, -15, -65), apex, sides);
    triangle(b, v3(9, -15, -65), v3(12, -15, -60), apex, sides);

    int top = add_material(b, display(0.038, 0.248, 0.184), 1), wood = add_material(b, display(0.3, 0.2, 0.1), 1);
    quad(b, v3(-12, -4.9, -70), v3(12, -4.9, -70), v3(12, -4.9, -90), v3(-12, -4.9, -90), top);
    double legs[4][2] = {{-10, -73}, {10, -73}, {-10, -89}, {10, -89}};
    for (int i = 0; i < 4; i++)
        upright(b, GLINT_SHAPE_CYLINDER, v3(legs[i][0], -15, legs[i][1]), 0.5, 10, wood);

    upright(b, GLINT_SHAPE_CONE, v3(-5, -14, -60), 2, 15, add_material(b, display(1, 0, 0), 1));
}

static void lights(builder *b)
{
    glint_light point = {.kind = GLINT_LIGHT_POINT, .position = {10, 40, -3}, .color = {1, 1, 1}};
    check(b, glint_scene_add_light(b->scene, &point, b->err));
    glint_light spot = {.kind = GLINT_LIGHT_SPOT, .position = {3, 50, -80}, .direction = {0, -1, 0},
                        .color = {1, 1, 1}, .cone_angle = 8.5};
    check(b, glint_scene_add_light(b->scene, &spot, b->err));
}

glint_scene *glint_scene_seed_room(glint_error *err)
{
    builder b = {glint_scene_new(), err, false};
    if (!b.scene) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory creating the seed room");
        return NULL;
    }
    glint_settings s = glint_settings_default();
    s.width = s.height = 1000;
    s.samples_per_pixel = 4;
    glint_camera cam = {.position = {0, 0, 4}, .look_at = {0, 0, -1}, .up = {0, 1, 0},
                        .vfov_degrees = 2 * atan(10.0 / 40.0) * 180 / M_PI};
    glint_fog fog = {.kind = GLINT_FOG_LINEAR, .color = display(0.8, 0.8, 0.8), .start = -16, .end = 284};
    if (glint_scene_set_settings(b.scene, &s, err) || glint_scene_set_camera(b.scene, &cam, err) ||
        glint_scene_set_fog(b.scene, &fog, err))
        b.failed = true;
    room(&b);
    props(&b);
    lights(&b);
    if (b.failed) {
        glint_scene_free(b.scene);
        return NULL;
    }
    return b.scene;
}
