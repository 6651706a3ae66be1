/* read_sections.c - the scene file's settings, camera and fog sections. */
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include "scenefile/loader.h"

void read_settings(loader *l, const ynode *n)
{
    static const char *const keys[] = {"width", "height", "samples", "sampler", "seed", "depth",
                                       "background", "ambient", "output"};
    static const char *const samplers[] = {"regular", "jittered"};
    if (!yr_is_map(&l->r, n, "settings"))
        return;
    l->settings_node = n;
    yr_check_keys(&l->r, n, "settings", keys, COUNT(keys));
    glint_settings *s = &l->settings;
    long long v;
    if (present_integer(l, n, "width", 1, 65536, &v))
        s->width = (int)v;
    if (present_integer(l, n, "height", 1, 65536, &v))
        s->height = (int)v;
    const ynode *spp = yr_get(&l->r, n, "samples");
    if (spp && yr_integer(&l->r, spp, "samples", 1, 4096, &v)) {
        long long root = 0;
        while ((root + 1) * (root + 1) <= v)
            root++;
        if (root * root != v)
            diag_at(&l->d, spp, "'samples' must be a square number (1, 4, 9, 16, ...), got %lld", v);
        else
            s->samples_per_pixel = (int)v;
    }
    const ynode *sampler = yr_get(&l->r, n, "sampler");
    int k = sampler ? word(l, sampler, "sampler", samplers, COUNT(samplers)) : -1;
    if (k >= 0)
        s->sampler = k == 0 ? GLINT_SAMPLER_REGULAR : GLINT_SAMPLER_JITTERED;
    if (present_integer(l, n, "seed", 0, 4294967295LL, &v))
        s->seed = (uint32_t)v;
    if (present_integer(l, n, "depth", 0, 64, &v))
        s->max_depth = (int)v;
    yr_opt_color(&l->r, n, "background", &s->background);
    yr_opt_color(&l->r, n, "ambient", &s->ambient_light);
    const ynode *out = yr_get(&l->r, n, "output");
    const char *path;
    if (out && yr_text(&l->r, out, "output", &path)) {
        size_t len = strlen(path);
        if (len < 5 || (strcasecmp(path + len - 4, ".png") != 0 && strcasecmp(path + len - 4, ".ppm") != 0))
            diag_at(&l->d, out, "'output' must name a .png or .ppm file, got '%.100s'", path);
        else
            l->output = path;
    }
}

void read_camera(loader *l, const ynode *n)
{
    static const char *const keys[] = {"position", "look_at", "up", "fov"};
    if (!yr_is_map(&l->r, n, "camera"))
        return;
    l->camera_node = n;
    yr_check_keys(&l->r, n, "camera", keys, COUNT(keys));
    yr_opt_vec3(&l->r, n, "position", &l->camera.position);
    yr_opt_vec3(&l->r, n, "look_at", &l->camera.look_at);
    yr_opt_vec3(&l->r, n, "up", &l->camera.up);
    ranged(l, n, "fov", 0, 180, OPEN_BOTH, "between 0 and 180 degrees", &l->camera.vfov_degrees);
}

void read_fog(loader *l, const ynode *n)
{
    static const char *const kinds[] = {"none", "linear", "exponential"};
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
    const ynode *type = yr_get(&l->r, n, "type");
    int k = type ? word(l, type, "type", kinds, COUNT(kinds)) : 3;
    if (k >= 0 && k < 3)
        l->fog.kind = k == 0 ? GLINT_FOG_NONE : k == 1 ? GLINT_FOG_LINEAR : GLINT_FOG_EXPONENTIAL;
    char what[32];
    snprintf(what, sizeof what, k >= 0 && k < 3 ? "%s fog" : "fog", k >= 0 && k < 3 ? kinds[k] : "");
    yr_check_keys(&l->r, n, what, keys[k < 0 ? 3 : k], key_count[k < 0 ? 3 : k]);
    yr_opt_color(&l->r, n, "color", &l->fog.color);
    yr_opt_number(&l->r, n, "start", &l->fog.start);
    yr_opt_number(&l->r, n, "end", &l->fog.end);
    ranged(l, n, "density", 0, 1e300, OPEN_LOW, "positive", &l->fog.density);
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

