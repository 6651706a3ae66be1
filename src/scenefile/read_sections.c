/* read_sections.c - the scene file's settings, camera and fog sections. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "image/image_format.h"
#include "scenefile/loader.h"
#include "shading/fog.h"

void read_settings(loader *l, const ynode *n)
{
    static const char *const extra_keys[] = {"output", "ambient_occlusion", "filter", "adaptive", "frames", "shutter"};
    if (!yr_is_map(&l->r, n, "settings"))
        return;
    l->settings_node = n;
    const char *keys[24];
    int count = param_keys(settings_params(), extra_keys, COUNT(extra_keys), keys, COUNT(keys));
    yr_check_keys(&l->r, n, "settings", keys, count);
    read_params(l, n, settings_params(), "settings", &l->settings);
    read_sub_map(l, n, "ambient_occlusion", occlusion_params(), &l->settings);
    read_sub_map(l, n, "filter", filter_params(), &l->settings);
    read_sub_map(l, n, "adaptive", adaptive_params(), &l->settings);
    read_sub_map(l, n, "frames", frames_params(), &l->settings);
    read_sub_map(l, n, "shutter", shutter_params(), &l->settings);
    const ynode *shutter = yr_get(&l->r, n, "shutter");
    if (shutter && l->settings.shutter_close < l->settings.shutter_open)
        diag_at(&l->d, shutter, "shutter: 'close' (%g) comes before 'open' (%g)", l->settings.shutter_close,
                l->settings.shutter_open);
    const ynode *frames = yr_get(&l->r, n, "frames");
    if (frames && l->settings.frame_end < l->settings.frame_start)
        diag_at(&l->d, frames, "frames: 'end' (%d) comes before 'start' (%d)", l->settings.frame_end,
                l->settings.frame_start);
    /* Told at the key it is about, and mended so that it is told once. */
    glint_error err;
    const char *key = sampling_rule_broken(&l->settings, &err);
    if (key) {
        const ynode *adaptive = yr_get(&l->r, n, "adaptive");
        const ynode *at = strcmp(key, "samples") == 0 ? yr_get(&l->r, n, "samples")
                          : strcmp(key, "adaptive") == 0 ? adaptive
                                                          : yr_get(&l->r, adaptive, "max_samples");
        diag_error(&l->d, at ? at : n, &err);
        l->settings.sampler = GLINT_SAMPLER_SOBOL;
        l->settings.adaptive_max_samples = 0;
    }
    const ynode *out = yr_get(&l->r, n, "output");
    const char *path;
    if (out && yr_text(&l->r, out, "output", &path)) {
        char known[64];
        if (!image_writer_for_path(path))
            diag_at(&l->d, out, "'output' must name a %s file, got '%.100s'",
                    image_writer_extensions(known, sizeof known), path);
        else
            l->output = path;
    }
}

void read_camera(loader *l, const ynode *n)
{
    static const char *const focus_key[] = {"focus_on"};
    if (!yr_is_map(&l->r, n, "camera"))
        return;
    l->camera_node = n;
    const char *keys[16];
    int count = param_keys(camera_params(), focus_key, COUNT(focus_key), keys, COUNT(keys));
    yr_check_keys(&l->r, n, "camera", keys, count);
    read_params(l, n, camera_params(), "camera", &l->camera);
    const ynode *focus = yr_get(&l->r, n, "focus_on");
    static const param focus_on = {.key = "focus_on", .type = PARAM_VEC3};
    if (focus && read_param(l, focus, &focus_on, &l->focus_on))
        l->focus_on_node = focus;
}

bool focus_on_resolve(loader *l)
{
    glint_camera *c = &l->camera;
    const ynode *at = l->focus_on_node;
    if (!at)
        return true;
    if (c->kind != GLINT_CAMERA_THIN_LENS) {
        diag_at(&l->d, at, "camera focus_on is for type thin_lens");
        return false;
    }
    if (c->focus_distance != 0) {
        diag_at(&l->d, at, "camera takes focus_on or focus_distance, not both");
        return false;
    }
    vec3 view = v3_sub(c->look_at, c->position);
    double depth = v3_dot(v3_sub(l->focus_on, c->position), v3_normalize(view));
    if (!(depth > 0) || !isfinite(depth)) {
        diag_at(&l->d, at, "camera focus_on must lie in front of the camera (its depth along the view is %g)", depth);
        return false;
    }
    c->focus_distance = depth;
    return true;
}

void read_fog(loader *l, const ynode *n)
{
    /* The keys each type reads; without a type (one that an included file
     * gave), any of them. */
    static const char *const keys[4][5] = {
        {"type", "color"}, {"type", "color", "start", "end"}, {"type", "color", "density"},
        {"type", "color", "start", "end", "density"},
    };
    static const int key_count[] = {2, 4, 3, 5};
    if (!yr_is_map(&l->r, n, "fog"))
        return;
    l->fog_node = n;
    param_table t = fog_params();
    const param *kind = &t.params[0];
    const ynode *type = yr_get(&l->r, n, "type");
    int k = type ? word(l, type, "type", kind->words, kind->word_count) : 3;
    if (k >= 0 && k < 3)
        l->fog.kind = (glint_fog_kind)k;
    char what[32];
    snprintf(what, sizeof what, k >= 0 && k < 3 ? "%s fog" : "fog", k >= 0 && k < 3 ? kind->words[k] : "");
    yr_check_keys(&l->r, n, what, keys[k < 0 ? 3 : k], key_count[k < 0 ? 3 : k]);
    /* Every key but the type, each where the file gives it. */
    read_params(l, n, (param_table){t.params + 1, t.count - 1}, what, &l->fog);
    static const char *const tracked[] = {"type", "start", "end", "density"};
    for (int i = 0; i < COUNT(tracked); i++)
        if (yr_get(&l->r, n, tracked[i]))
            l->fog_keys |= 1u << i;
}

/* The keys fog needs, checked once every file has had its say. */
bool fog_complete(loader *l)
{
    const char *missing = !(l->fog_keys & FOG_TYPE) ? "fog needs 'type'"
                          : l->fog.kind == GLINT_FOG_LINEAR && (~l->fog_keys & (FOG_START | FOG_END))
                              ? "linear fog needs 'start' and 'end'"
                          : l->fog.kind == GLINT_FOG_EXPONENTIAL && !(l->fog_keys & FOG_DENSITY)
                              ? "exponential fog needs 'density'"
                              : NULL;
    if (missing)
        diag_at(&l->d, l->fog_node, "%s", missing);
    return !missing;
}

