/* model_view.c - a ready-made scene around one model file, for `glint
 * model.obj`: the model on a floor, lit, and a camera that looks at it
 * from the view asked for (by default from the front, or into a room
 * through its opening) and frames its bounding box (view_frame.c). */
#include <math.h>
#include "builtin/model_opening.h"
#include "builtin/view_frame.h"
#include "core/color.h"
#include "core/error.h"
#include "scene/scene.h"

/* The camera's vertical field of view, and the share of the picture's
 * width or height the model's projected bounding box spans. */
static const double VIEW_FOV = 35, VIEW_SHARE = 0.85;
/* How far above the horizon the front, back, left and right views are. */
static const double ELEVATION = 20 * M_PI / 180;

/* A direction to look from (from the model towards the camera) and the
 * model's direction that is up in the picture. */
typedef struct view_dir {
    vec3 from, up;
} view_dir;

/* Where a named view looks from. */
static view_dir named_view(glint_model_view view)
{
    double c = cos(ELEVATION), s = sin(ELEVATION);
    vec3 y = {0, 1, 0};
    switch (view) {
    case GLINT_VIEW_BACK: return (view_dir){{0, s, -c}, y};
    case GLINT_VIEW_LEFT: return (view_dir){{-c, s, 0}, y};
    case GLINT_VIEW_RIGHT: return (view_dir){{c, s, 0}, y};
    case GLINT_VIEW_TOP: return (view_dir){{0, 1, 0}, {0, 0, -1}};
    case GLINT_VIEW_ISO: return (view_dir){v3_normalize(v3(1, 1, 1)), y};
    default: return (view_dir){{0, s, c}, y};
    }
}

/* Straight into a room through its open side (model_open_side's number),
 * the model's up up in the picture; looking down or up into it, -z. */
static view_dir into_opening(int side)
{
    double sign = side % 2 ? 1 : -1;
    vec3 from = {side / 2 == 0 ? sign : 0, side / 2 == 1 ? sign : 0, side / 2 == 2 ? sign : 0};
    return (view_dir){from, side / 2 == 1 ? v3(0, 0, -1) : v3(0, 1, 0)};
}

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

/* The key light comes from above, to the right of and in front of the
 * camera, the fill from its left, whatever the view, so that the side seen
 * is lit: their directions are given across (right), up and towards the
 * camera, level (the picture's right, the model's up, and what is left of
 * the view's direction). Under a room's ceiling neither reaches, so the
 * inside is lit by a point light just outside the opening, a little up (in
 * the picture) from its centre. */
static bool add_lights(glint_scene *s, vec3 lo, vec3 hi, int side, view_dir v, glint_error *err)
{
    vec3 right = v3_normalize(v3_cross(v.up, v.from)), back = v3_cross(right, v.up);
    vec3 key_from = v3_madd(v3_madd(v3_scale(right, 0.5), v.up, 1), back, 0.6);
    vec3 fill_from = v3_madd(v3_madd(v3_scale(right, -0.7), v.up, 0.4), back, 0.3);
    glint_light key = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = v3_neg(key_from), .color = {0.85, 0.85, 0.8}};
    glint_light fill = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = v3_neg(fill_from), .color = {0.2, 0.22, 0.25}};
    if (glint_scene_add_light(s, &key, err) < 0 || glint_scene_add_light(s, &fill, err) < 0)
        return false;
    if (side < 0)
        return true;
    vec3 out = v.from, size = v3_sub(hi, lo);
    vec3 at = v3_scale(v3_add(lo, hi), 0.5);
    double depth = fabs(v3_dot(size, out)), height = fabs(v3_dot(size, v.up));
    at = v3_madd(v3_madd(at, out, (0.5 + 0.05) * depth), v.up, 0.3 * height); /* 5% of the depth outside */
    glint_light inside = {.kind = GLINT_LIGHT_POINT, .position = at, .color = {0.8, 0.8, 0.8}};
    return glint_scene_add_light(s, &inside, err) >= 0;
}

/* Sets the camera, lights and settings for looking at mesh m: a model
 * with lamps of its own (emissive triangles, the Cornell box's ceiling
 * light) is lit by them alone, as its author lit it. */
static bool look(glint_scene *s, const mesh *m, const glint_model_view_options *o, glint_error *err)
{
    glint_settings st = glint_settings_default();
    st.width = o->width ? o->width : 800;
    st.height = o->height ? o->height : 600;
    st.samples_per_pixel = 4;
    st.background = rgb(0.18, 0.2, 0.23);
    if (glint_scene_set_settings(s, &st, err))
        return false;
    int side = o->view == GLINT_VIEW_AUTO ? model_open_side(m) : -1;
    view_dir v = side >= 0 ? into_opening(side) : named_view(o->view);
    glint_camera cam = view_frame_box(m->lo, m->hi, v3_neg(v.from), v.up, VIEW_FOV, (double)st.width / st.height,
                                      VIEW_SHARE);
    return !glint_scene_set_camera(s, &cam, err) && (s->emitter_count > 0 || add_lights(s, m->lo, m->hi, side, v, err));
}

glint_scene *glint_scene_for_model_ex(const char *path, const glint_model_view_options *options, glint_error *err)
{
    glint_model_view_options o = options ? *options : (glint_model_view_options){0};
    if ((int)o.view < GLINT_VIEW_AUTO || (int)o.view > GLINT_VIEW_ISO) {
        error_set(err, GLINT_ERR_INVALID, "model view %d is not a glint_model_view", (int)o.view);
        return NULL;
    }
    glint_scene *s = glint_scene_new();
    if (!s) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory");
        return NULL;
    }
    int index = glint_scene_import_mesh(s, path, NULL, err);
    bool ok = index >= 0 && glint_scene_add_instance(s, index, -1, NULL, err) >= 0;
    if (ok) {
        const mesh *m = &s->meshes[index];
        ok = add_floor(s, m->lo, fmax(0.5 * v3_length(v3_sub(m->hi, m->lo)), 1e-6), err) && look(s, m, &o, err);
    }
    if (!ok) {
        glint_scene_free(s);
        return NULL;
    }
    return s;
}

glint_scene *glint_scene_for_model(const char *path, glint_error *err)
{
    return glint_scene_for_model_ex(path, NULL, err);
}
