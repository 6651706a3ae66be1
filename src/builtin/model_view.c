/* model_view.c - a ready-made scene around one model file, for `glint
 * model.obj`: the model on a floor, framed by the camera, lit from the
 * front. Built with the public API only. */
#include <math.h>
#include "core/color.h"
#include "core/error.h"
#include "core/vec.h"

/* The camera sits on this direction from the model's centre. */
static const vec3 VIEW_FROM = {0.45, 0.35, 1.0};
static const double VIEW_FOV = 35;

static bool add_floor(glint_scene *s, vec3 lo, double radius, glint_error *err)
{
    glint_mapping planar = {.kind = GLINT_MAP_PLANAR};
    glint_material floor = glint_material_default();
    floor.specular = 0.2;
    floor.texture = glint_scene_add_checker(s, "model-view/floor", rgb(0.55, 0.55, 0.55), rgb(0.35, 0.35, 0.35),
                                            radius / 3, planar, err);
    int m = floor.texture < 0 ? -1 : glint_scene_add_material(s, "model-view/floor", &floor, err);
    glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .center = lo, .normal = {0, 1, 0}};
    return m >= 0 && glint_scene_add_shape(s, &plane, m, NULL, err) >= 0;
}

static bool frame(glint_scene *s, vec3 centre, double radius, glint_error *err)
{
    double distance = radius / sin(VIEW_FOV * M_PI / 360) * 1.05;
    glint_camera cam = {v3_madd(centre, v3_normalize(VIEW_FROM), distance), centre, {0, 1, 0}, VIEW_FOV};
    glint_settings st = glint_settings_default();
    st.width = 800;
    st.height = 600;
    st.samples_per_pixel = 4;
    st.background = rgb(0.18, 0.2, 0.23);
    glint_light key = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {-0.5, -1, -0.6}, .color = {0.85, 0.85, 0.8}};
    glint_light fill = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {0.7, -0.4, -0.3}, .color = {0.2, 0.22, 0.25}};
    return !glint_scene_set_camera(s, &cam, err) && !glint_scene_set_settings(s, &st, err) &&
           glint_scene_add_light(s, &key, err) >= 0 && glint_scene_add_light(s, &fill, err) >= 0;
}

glint_scene *glint_scene_for_model(const char *path, glint_error *err)
{
    glint_scene *s = glint_scene_new();
    if (!s) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory");
        return NULL;
    }
    vec3 lo, hi;
    int mesh = glint_scene_import_mesh(s, path, NULL, err);
    bool ok = mesh >= 0 && !glint_scene_mesh_bounds(s, mesh, &lo, &hi, err) &&
              glint_scene_add_instance(s, mesh, -1, NULL, err) >= 0;
    if (ok) {
        vec3 centre = v3_scale(v3_add(lo, hi), 0.5);
        double radius = fmax(0.5 * v3_length(v3_sub(hi, lo)), 1e-6);
        ok = add_floor(s, lo, radius, err) && frame(s, centre, radius, err);
    }
    if (!ok) {
        glint_scene_free(s);
        return NULL;
    }
    return s;
}
