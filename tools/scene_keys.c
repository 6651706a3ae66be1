/* scene_keys.c - prints the scene-file key tables of docs/scene-format.md
 * from the parameter tables the loader reads, so the reference cannot drift
 * from the code: `scene_keys` lists the sections, `scene_keys SECTION`
 * prints one as Markdown. tools/scene_docs.sh writes them into the docs and
 * checks them (a test runs the check). */
#include <stdio.h>
#include <string.h>
#include "geometry/shape_kind.h"
#include "scene/scene.h"
#include "shading/environment.h"
#include "shading/fog.h"
#include "shading/light.h"
#include "shading/texture.h"

/* A section of the docs: its name and the table behind it. */
typedef struct section {
    char name[48];
    param_table table;
} section;

/* Every section, in the order the docs take them; returns how many. */
static int sections(section *out, int room)
{
    int n = 0;
#define ADD(label, t)                                                                                              \
    do {                                                                                                           \
        if (n < room) {                                                                                            \
            snprintf(out[n].name, sizeof out[n].name, "%s", label);                                                \
            out[n++].table = (t);                                                                                  \
        }                                                                                                          \
    } while (0)
    ADD("settings", settings_params());
    ADD("ambient_occlusion", occlusion_params());
    ADD("filter", filter_params());
    ADD("adaptive", adaptive_params());
    ADD("frames", frames_params());
    ADD("shutter", shutter_params());
    ADD("camera", camera_params());
    ADD("fog", fog_params());
    ADD("environment", environment_params());
    ADD("mapping", mapping_params());
    ADD("material", material_params());
    ADD("absorption", absorption_params());
    ADD("bump", bump_params());
    char label[48];
    for (int i = 0; i < texture_kind_count(); i++) {
        snprintf(label, sizeof label, "texture %s", texture_kind_at(i)->name);
        ADD(label, texture_kind_at(i)->params);
    }
    for (int i = 0; i < light_kind_count(); i++) {
        snprintf(label, sizeof label, "light %s", light_kind_at(i)->name);
        ADD(label, light_kind_at(i)->params);
    }
    for (int i = 0; i < shape_kind_count(); i++) {
        /* A combination's only key is its list of objects, as a group's. */
        if (shape_kind_at(i)->csg)
            continue;
        snprintf(label, sizeof label, "shape %s", shape_kind_at(i)->name);
        ADD(label, shape_kind_at(i)->params);
    }
#undef ADD
    return n;
}

static const char *type_name(const param *p)
{
    switch (p->type) {
    case PARAM_NUMBER:
        return "number";
    case PARAM_INTEGER:
    case PARAM_UINT32:
        return "whole";
    case PARAM_CHOICE:
        return "word";
    case PARAM_VEC3:
    case PARAM_DIRECTION:
        return "vector";
    case PARAM_COLOR:
        return "colour";
    case PARAM_COLOR_PAIR:
        return "[colour, colour]";
    case PARAM_BOOL:
        return "boolean";
    case PARAM_POINTS:
        return "list of vectors";
    case PARAM_NUMBERS:
        return "list of numbers";
    case PARAM_COLOR_STOPS:
        return "list of [number, colour]";
    case PARAM_PATH:
        return "path";
    }
    return "?";
}

static void default_text(const param *p, char *buf, size_t size)
{
    const double *d = p->def;
    if (p->required || p->default_text) {
        snprintf(buf, size, "%s", p->required ? "required" : p->default_text);
        return;
    }
    switch (p->type) {
    case PARAM_NUMBER:
    case PARAM_INTEGER:
    case PARAM_UINT32:
        snprintf(buf, size, "%g", d[0]);
        return;
    case PARAM_CHOICE:
        snprintf(buf, size, "`%s`", p->words[(int)d[0]]);
        return;
    case PARAM_BOOL:
        snprintf(buf, size, "%s", d[0] != 0 ? "true" : "false");
        return;
    case PARAM_VEC3:
    case PARAM_DIRECTION:
    case PARAM_COLOR:
        snprintf(buf, size, "`[%g, %g, %g]`", d[0], d[1], d[2]);
        return;
    case PARAM_COLOR_PAIR:
        snprintf(buf, size, "`[[%g, %g, %g], [%g, %g, %g]]`", d[0], d[1], d[2], d[3], d[4], d[5]);
        return;
    case PARAM_COLOR_STOPS:
        snprintf(buf, size, "`[[0, [%g, %g, %g]], [1, [%g, %g, %g]]]`", d[0], d[1], d[2], d[3], d[4], d[5]);
        return;
    case PARAM_NUMBERS:
        snprintf(buf, size, "%s", p->required ? "required" : "all 0");
        return;
    case PARAM_POINTS:
    case PARAM_PATH:
        snprintf(buf, size, "none");
        return;
    }
}

static void range_text(const param *p, char *buf, size_t size)
{
    buf[0] = '\0';
    switch (p->type) {
    case PARAM_NUMBER:
    case PARAM_INTEGER:
        if (p->rule_text || p->lo > -DBL_MAX || p->hi < DBL_MAX)
            param_range_text(p, buf, size);
        return;
    case PARAM_UINT32:
        snprintf(buf, size, "from 0 to 4294967295");
        return;
    case PARAM_CHOICE: {
        size_t used = 0;
        for (int i = 0; i < p->word_count && used < size; i++)
            used += (size_t)snprintf(buf + used, size - used, "%s`%s`", i ? ", " : "", p->words[i]);
        return;
    }
    case PARAM_DIRECTION:
        snprintf(buf, size, "not zero");
        return;
    case PARAM_POINTS:
        snprintf(buf, size, "%d %s %d points", p->min_count, p->max_count == p->min_count + 1 ? "or" : "to",
                 p->max_count);
        return;
    case PARAM_COLOR_STOPS:
        snprintf(buf, size, "%d to %d stops, values from 0 to 1 in order", p->min_count, p->max_count);
        return;
    case PARAM_NUMBERS:
        snprintf(buf, size, "%d numbers", p->max_count);
        return;
    default:
        return;
    }
}

static void print_table(param_table t)
{
    printf("| key | type | default | range | meaning |\n| --- | --- | --- | --- | --- |\n");
    for (int i = 0; i < t.count; i++) {
        const param *p = &t.params[i];
        char def[160], range[160];
        default_text(p, def, sizeof def);
        range_text(p, range, sizeof range);
        printf("| `%s` | %s | %s | %s | %s |\n", p->key, type_name(p), def, range, p->meaning ? p->meaning : "");
    }
}

int main(int argc, char **argv)
{
    section all[64];
    int n = sections(all, 64);
    if (argc == 1) {
        for (int i = 0; i < n; i++)
            printf("%s\n", all[i].name);
        return 0;
    }
    for (int i = 0; i < n; i++) {
        if (strcmp(all[i].name, argv[1]) == 0) {
            print_table(all[i].table);
            return 0;
        }
    }
    fprintf(stderr, "scene_keys: no section '%s'\n", argv[1]);
    return 1;
}
