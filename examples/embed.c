/* embed.c - the smallest program that embeds libglint: a glass ball and a
 * mirror ball on a checkered floor under a spotlight, written to a PNG.
 *   usage: embed OUTPUT.png */
#include <stdio.h>
#include "glint.h"

static int report(glint_error *err)
{
    fprintf(stderr, "embed: %s\n", err->message);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: embed OUTPUT.png\n");
        return 2;
    }
    glint_error err;
    glint_scene *scene = glint_scene_new();
    if (!scene)
        return 1;

    glint_settings settings = glint_settings_default();
    settings.width = 320;
    settings.height = 240;
    settings.samples_per_pixel = 4;
    glint_camera camera = {.position = {0, 2, 6}, .look_at = {0, 0.5, 0}, .up = {0, 1, 0}, .vfov_degrees = 40};
    if (glint_scene_set_settings(scene, &settings, &err) || glint_scene_set_camera(scene, &camera, &err))
        return report(&err);

    glint_mapping floor_map = {.kind = GLINT_MAP_PLANAR};
    glint_material floor = glint_material_default();
    floor.texture = glint_scene_add_checker(scene, "checks", (glint_color){0.05, 0.05, 0.05},
                                            (glint_color){0.8, 0.8, 0.8}, 1, floor_map, &err);
    glint_material glass = glint_material_default();
    glass.color = (glint_color){0, 0, 0};
    glass.refraction = 0.9;
    glass.ior = 1.5;
    glass.tint = 0;
    glass.fresnel = true;
    glint_material mirror = glint_material_default();
    mirror.color = (glint_color){0.1, 0.1, 0.1};
    mirror.reflectivity = 0.9;
    int m_floor = floor.texture < 0 ? -1 : glint_scene_add_material(scene, "floor", &floor, &err);
    int m_glass = glint_scene_add_material(scene, "glass", &glass, &err);
    int m_mirror = glint_scene_add_material(scene, "mirror", &mirror, &err);
    if (m_floor < 0 || m_glass < 0 || m_mirror < 0)
        return report(&err);

    glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .center = {0, 0, 0}, .normal = {0, 1, 0}};
    glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {0, 0, 0}, .radius = 1};
    glint_transform left = glint_transform_translate(glint_transform_identity(), -1.2, 1, 0);
    glint_transform right = glint_transform_translate(glint_transform_identity(), 1.2, 1, -0.5);
    glint_light spot = {.kind = GLINT_LIGHT_SPOT, .position = {0, 8, 2}, .direction = {0, -8, -2},
                        .color = {1, 1, 1}, .cone_angle = 30, .falloff_angle = 10};
    glint_light fill = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {1, -1, -1}, .color = {0.3, 0.3, 0.35}};
    if (glint_scene_add_shape(scene, &plane, m_floor, NULL, &err) < 0 ||
        glint_scene_add_shape(scene, &ball, m_glass, &left, &err) < 0 ||
        glint_scene_add_shape(scene, &ball, m_mirror, &right, &err) < 0 ||
        glint_scene_add_light(scene, &spot, &err) < 0 || glint_scene_add_light(scene, &fill, &err) < 0)
        return report(&err);

    glint_image image;
    glint_status st = glint_render(scene, NULL, &image, NULL, &err);
    glint_scene_free(scene);
    if (st)
        return report(&err);
    st = glint_image_write(&image, argv[1], &err);
    glint_image_free(&image);
    return st ? report(&err) : 0;
}
