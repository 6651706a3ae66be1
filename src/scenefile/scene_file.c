/* scene_file.c - the YAML scene loader: walks each file's tree and builds
 * the scene through the public API, reporting every problem at its place.
 * The reference for every key is docs/scene-format.md. */
/* realpath() is X/Open. */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include "core/error.h"
#include "core/transform.h"
#include "scenefile/yaml_read.h"
#include "scene/scene.h"

#define MAX_INCLUDE_DEPTH 16
#define MAX_FILES 1000            /* files read for one scene, includes counted */
#define MAX_GROUP_DEPTH 32
#define MAX_SCENE_FILE_BYTES (64L << 20)
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

typedef struct loader {
    glint_scene *scene;
    diag d;
    reader r;
    glint_settings settings;
    glint_camera camera;
    glint_fog fog;
    const ynode *settings_node, *camera_node, *fog_node;  /* the last file's, for messages */
    unsigned fog_keys;                                   /* FOG_* keys given in any file */
    const char *output;
    const char *chain[MAX_INCLUDE_DEPTH + 1];   /* canonical paths of the files being read */
    int depth;
    ydoc *docs;                                  /* kept until the end: nodes name their file */
    int doc_count, doc_cap;
    int files;                                   /* files read so far */
    struct imported *imports;                    /* models read so far: each once */
    int import_count, import_cap;
    long bytes;                                  /* bytes read so far, all files */
} loader;

/* A model file already imported, so that every object placing it shares
 * one mesh. */
struct imported {
    char *path;               /* canonical */
    double crease_angle;
    int mesh;
};

enum { FOG_TYPE = 1, FOG_START = 2, FOG_END = 4, FOG_DENSITY = 8 };

/* What an object inherits from the groups around it. */
typedef struct context {
    glint_transform to_world;
    int material;             /* -1: none yet */
    int depth;
} context;

static bool ok(const loader *l)
{
    return !diag_full(&l->d) && !l->r.exhausted;
}

/* ------------------------------------------------------------ small reads */

static bool need_number(loader *l, const ynode *map, const char *key, const char *what, double *out)
{
    const ynode *n = yr_need(&l->r, map, key, what);
    return n && yr_number(&l->r, n, key, out);
}

/* A required number above 0, reported at its value when it is not. */
static bool need_positive(loader *l, const ynode *map, const char *key, const char *what, double *out)
{
    const ynode *n = yr_need(&l->r, map, key, what);
    if (!n || !yr_number(&l->r, n, key, out))
        return false;
    if (*out > 0)
        return true;
    diag_at(&l->d, n, "'%s' must be positive, got %g", key, *out);
    return false;
}

static bool need_vec3(loader *l, const ynode *map, const char *key, const char *what, vec3 *out)
{
    const ynode *n = yr_need(&l->r, map, key, what);
    return n && yr_vec3(&l->r, n, key, out);
}

/* Which ends of a range are excluded. */
typedef enum bounds { CLOSED, OPEN_LOW, OPEN_BOTH } bounds;

/* Reads an optional number and checks it lies between lo and hi, reporting
 * "'key' must be <range>, got v" where range is the human wording. */
static bool ranged(loader *l, const ynode *map, const char *key, double lo, double hi, bounds open,
                   const char *range, double *out)
{
    const ynode *n = yr_get(&l->r, map, key);
    double v = *out;
    if (!n)
        return true;
    if (!yr_number(&l->r, n, key, &v))
        return false;
    if (v < lo || v > hi || (open != CLOSED && v == lo) || (open == OPEN_BOTH && v == hi)) {
        diag_at(&l->d, n, "'%s' must be %s, got %g", key, range, v);
        return false;
    }
    *out = v;
    return true;
}

/* True when key is present in map and a whole number in [lo, hi]. */
static bool present_integer(loader *l, const ynode *map, const char *key, long long lo, long long hi, long long *v)
{
    const ynode *n = yr_get(&l->r, map, key);
    return n && yr_integer(&l->r, n, key, lo, hi, v);
}

/* Matches a scalar against a list of words; reports with a hint. */
static int word(loader *l, const ynode *n, const char *key, const char *const *words, int count)
{
    if (n->kind == YNODE_SCALAR)
        for (int i = 0; i < count; i++)
            if (strcmp(n->value, words[i]) == 0)
                return i;
    char list[200] = "";
    for (int i = 0; i < count; i++) {
        strcat(list, i == 0 ? "" : i == count - 1 ? " or " : ", ");
        strcat(list, words[i]);
    }
    const char *hint = n->kind == YNODE_SCALAR ? diag_suggest(n->value, words, count) : NULL;
    if (hint)
        diag_at(&l->d, n, "'%s' must be %s, got '%.60s' (did you mean '%s'?)", key, list, n->value, hint);
    else if (n->kind == YNODE_SCALAR)
        diag_at(&l->d, n, "'%s' must be %s, got '%.60s'", key, list, n->value);
    else
        diag_at(&l->d, n, "'%s' must be %s, got %s", key, list, ynode_describe(n));
    return -1;
}

/* The kind of a map that must say its `type`: the index of that word among
 * `kinds`, or -1 after a report. `what` names the map ("a light"). */
static int typed_map(loader *l, const ynode *n, const char *what, const char *const *kinds, int count)
{
    if (!yr_is_map(&l->r, n, what))
        return -1;
    const ynode *type = yr_need(&l->r, n, "type", what);
    return type ? word(l, type, "type", kinds, count) : -1;
}

/* Joins a path named in file `from` to that file's directory. */
static char *relative_to(const char *from, const char *path)
{
    const char *slash = strrchr(from, '/');
    size_t dir = path[0] == '/' || !slash ? 0 : (size_t)(slash - from) + 1;
    char *out = malloc(dir + strlen(path) + 1);
    if (out) {
        memcpy(out, from, dir);
        strcpy(out + dir, path);
    }
    return out;
}

/* ------------------------------------------------------------- settings */

static void read_settings(loader *l, const ynode *n)
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

static void read_camera(loader *l, const ynode *n)
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

static void read_fog(loader *l, const ynode *n)
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
static bool fog_complete(loader *l)
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

/* ------------------------------------------------------------- textures */

static bool read_mapping(loader *l, const ynode *n, glint_mapping *m)
{
    static const char *const kinds[] = {"uv", "planar", "spherical", "cylindrical"};
    /* The keys each kind of mapping reads, by kind. */
    static const char *const keys[] = {"type", "center", "scale", "u_axis", "v_axis"};
    static const int key_count[] = {1, 5, 2, 3};
    const ynode *type = n;
    if (n->kind == YNODE_MAPPING) {
        type = yr_need(&l->r, n, "type", "mapping");
        if (!type)
            return false;
    }
    int k = word(l, type, n == type ? "mapping" : "type", kinds, COUNT(kinds));
    if (k < 0)
        return false;
    m->kind = (glint_mapping_kind)k;
    if (n->kind != YNODE_MAPPING)
        return true;
    char what[40];
    snprintf(what, sizeof what, "a %s mapping", kinds[k]);
    yr_check_keys(&l->r, n, what, keys, key_count[k]);
    bool good = yr_opt_vec3(&l->r, n, "center", &m->center) && yr_opt_vec3(&l->r, n, "u_axis", &m->u_axis) &&
                yr_opt_vec3(&l->r, n, "v_axis", &m->v_axis) &&
                ranged(l, n, "scale", 0, 1e300, OPEN_LOW, "positive", &m->scale);
    if (good && k == GLINT_MAP_PLANAR && (!yr_get(&l->r, n, "u_axis")) != (!yr_get(&l->r, n, "v_axis"))) {
        diag_at(&l->d, n, "a planar mapping needs both 'u_axis' and 'v_axis', or neither");
        return false;
    }
    return good;
}

static void add_texture(loader *l, const char *name, const ynode *n)
{
    static const char *const kinds[] = {"checker", "image"};
    static const char *const keys[2][4] = {{"type", "mapping", "colors", "size"}, {"type", "mapping", "file"}};
    char what[160];
    snprintf(what, sizeof what, "texture '%.100s'", name);
    int kind = typed_map(l, n, what, kinds, COUNT(kinds));
    if (kind >= 0)
        yr_check_keys(&l->r, n, what, keys[kind], kind == 0 ? 4 : 3);
    glint_mapping mapping = {.kind = GLINT_MAP_UV};
    const ynode *m = yr_get(&l->r, n, "mapping");
    if (kind < 0 || (m && !read_mapping(l, m, &mapping)))
        return;
    glint_error err;
    if (scene_find_texture(l->scene, name) >= 0) {
        diag_at(&l->d, n, "texture '%.100s' is defined twice", name);
        return;
    }
    if (kind == 0) {
        color c[2] = {{0, 0, 0}, {1, 1, 1}};
        double size = 1;
        const ynode *colors = yr_get(&l->r, n, "colors");
        if (colors && (colors->kind != YNODE_SEQUENCE || colors->count != 2)) {
            diag_at(&l->d, colors, "'colors' must be a list of two colours");
            return;
        }
        if ((colors && (!yr_color(&l->r, colors->items[0], "colors", &c[0]) ||
                        !yr_color(&l->r, colors->items[1], "colors", &c[1]))) ||
            !ranged(l, n, "size", 0, 1e300, OPEN_LOW, "positive", &size))
            return;
        if (glint_scene_add_checker(l->scene, name, c[0], c[1], size, mapping, &err) < 0)
            diag_at(&l->d, n, "%s", err.message);
        return;
    }
    const ynode *file = yr_need(&l->r, n, "file", what);
    const char *path;
    if (!file || !yr_text(&l->r, file, "file", &path))
        return;
    char *full = relative_to(n->file, path);
    if (!full) {
        diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
        return;
    }
    if (glint_scene_add_image_file(l->scene, name, full, mapping, &err) < 0)
        diag_at(&l->d, file, "%s", err.message);
    free(full);
}

static void read_texture(loader *l, const char *name, const ynode *n)
{
    add_texture(l, name, n);
    if (scene_find_texture(l->scene, name) < 0) {
        /* A stand-in keeps the name known: no second report at each use. */
        glint_mapping uv = {.kind = GLINT_MAP_UV};
        glint_scene_add_checker(l->scene, name, rgb(0, 0, 0), rgb(1, 1, 1), 1, uv, NULL);
    }
}

/* ------------------------------------------------------------ materials */

/* Reports an unknown texture or material name at n, with the nearest
 * defined name as a hint. */
static void unknown_name(loader *l, const ynode *n, bool is_texture, const char *name)
{
    const glint_scene *sc = l->scene;
    int total = is_texture ? sc->texture_count : sc->material_count, count = 0;
    const char **names = malloc((size_t)(total ? total : 1) * sizeof *names);
    for (int i = 0; names && i < total; i++) {
        const char *candidate = is_texture ? sc->textures[i].name : sc->materials[i].name;
        if (candidate)
            names[count++] = candidate;
    }
    const char *hint = names ? diag_suggest(name, names, count) : NULL;
    const char *kind = is_texture ? "texture" : "material";
    if (hint)
        diag_at(&l->d, n, "unknown %s '%.100s' (did you mean '%s'?)", kind, name, hint);
    else
        diag_at(&l->d, n, "unknown %s '%.100s'", kind, name);
    free(names);
}

/* Reads a material map's keys over *m (which holds the defaults). */
static bool read_material_keys(loader *l, const ynode *n, const char *what, glint_material *m)
{
    static const char *const keys[] = {"color", "texture", "ambient", "diffuse", "specular", "shininess",
                                       "reflectivity", "transparency", "refraction", "ior", "tint", "fresnel"};
    if (!yr_is_map(&l->r, n, what))
        return false;
    int before = l->d.count;
    yr_check_keys(&l->r, n, what, keys, COUNT(keys));
    yr_opt_color(&l->r, n, "color", &m->color);
    ranged(l, n, "ambient", 0, 1, CLOSED, "from 0 to 1", &m->ambient);
    ranged(l, n, "diffuse", 0, 1e300, CLOSED, "from 0 to 1e300", &m->diffuse);
    ranged(l, n, "specular", 0, 1e300, CLOSED, "from 0 to 1e300", &m->specular);
    ranged(l, n, "shininess", 0, 1e300, CLOSED, "from 0 to 1e300", &m->shininess);
    ranged(l, n, "reflectivity", 0, 1, CLOSED, "from 0 to 1", &m->reflectivity);
    ranged(l, n, "transparency", 0, 1, CLOSED, "from 0 to 1", &m->transparency);
    ranged(l, n, "refraction", 0, 1, CLOSED, "from 0 to 1", &m->refraction);
    ranged(l, n, "ior", 0, 1e300, OPEN_LOW, "above 0", &m->ior);
    ranged(l, n, "tint", 0, 1, CLOSED, "from 0 to 1", &m->tint);
    yr_opt_bool(&l->r, n, "fresnel", &m->fresnel);
    const ynode *tex = yr_get(&l->r, n, "texture");
    const char *name;
    if (tex && yr_text(&l->r, tex, "texture", &name)) {
        m->texture = scene_find_texture(l->scene, name);
        if (m->texture < 0)
            unknown_name(l, tex, true, name);
    }
    if (l->d.count == before && m->transparency + m->refraction > 1) {
        diag_at(&l->d, n, "transparency + refraction must not exceed 1, got %g", m->transparency + m->refraction);
    }
    return l->d.count == before;
}

static void read_material(loader *l, const char *name, const ynode *n)
{
    char what[160];
    snprintf(what, sizeof what, "material '%.100s'", name);
    glint_material m = glint_material_default();
    glint_error err;
    if (scene_find_material(l->scene, name) >= 0) {
        diag_at(&l->d, n, "material '%.100s' is defined twice", name);
        return;
    }
    if (!read_material_keys(l, n, what, &m))
        m = glint_material_default(); /* keeps the name known: no second report at each use */
    if (glint_scene_add_material(l->scene, name, &m, &err) < 0)
        diag_at(&l->d, n, "%s", err.message);
}

/* An object's material: a name, or an inline map. -1 when it is wrong. */
static int object_material(loader *l, const ynode *n)
{
    if (n->kind == YNODE_MAPPING) {
        glint_material m = glint_material_default();
        glint_error err;
        int i = -1;
        if (read_material_keys(l, n, "material", &m) && (i = glint_scene_add_material(l->scene, NULL, &m, &err)) < 0)
            diag_at(&l->d, n, "%s", err.message);
        return i;
    }
    const char *name;
    if (!yr_text(&l->r, n, "material", &name))
        return -1;
    int i = scene_find_material(l->scene, name);
    if (i < 0)
        unknown_name(l, n, false, name);
    return i;
}

/* --------------------------------------------------------------- lights */

static void read_light(loader *l, const ynode *n)
{
    static const char *const kinds[] = {"point", "spot", "directional"};
    static const char *const keys[3][7] = {
        {"type", "color", "intensity", "position"},
        {"type", "color", "intensity", "position", "direction", "angle", "falloff"},
        {"type", "color", "intensity", "direction"},
    };
    static const int key_count[] = {4, 7, 4};
    int k = typed_map(l, n, "a light", kinds, COUNT(kinds));
    if (k < 0)
        return;
    char kind_name[32];
    snprintf(kind_name, sizeof kind_name, "a %s light", kinds[k]);
    yr_check_keys(&l->r, n, kind_name, keys[k], key_count[k]);
    glint_light lt = {.kind = (glint_light_kind)k, .color = {1, 1, 1}};
    double intensity = 1;
    const char *what = kinds[k];
    char label[32];
    snprintf(label, sizeof label, "a %s light", what);
    bool good = yr_opt_color(&l->r, n, "color", &lt.color) &&
                ranged(l, n, "intensity", 0, 1e300, CLOSED, "from 0 to 1e300", &intensity);
    if (k != GLINT_LIGHT_DIRECTIONAL)
        good = need_vec3(l, n, "position", label, &lt.position) && good;
    if (k != GLINT_LIGHT_POINT)
        good = need_vec3(l, n, "direction", label, &lt.direction) && good;
    if (k == GLINT_LIGHT_SPOT) {
        good = yr_need(&l->r, n, "angle", label) &&
               ranged(l, n, "angle", 0, 90, OPEN_LOW, "above 0 and at most 90 degrees", &lt.cone_angle) && good;
        good = good && ranged(l, n, "falloff", 0, lt.cone_angle, CLOSED, "from 0 to the cone angle",
                              &lt.falloff_angle);
    }
    lt.color = rgb_scale(lt.color, intensity);
    glint_error err;
    if (good && glint_scene_add_light(l->scene, &lt, &err) < 0)
        diag_at(&l->d, n, "%s", err.message);
}

/* -------------------------------------------------------------- objects */

static bool read_transform(loader *l, const ynode *n, glint_transform *t)
{
    static const char *const steps[] = {"translate", "rotate", "rotate_x", "rotate_y", "rotate_z", "scale"};
    static const char *const rotate_keys[] = {"axis", "angle"};
    if (!yr_is_list(&l->r, n, "'transform'"))
        return false;
    for (int i = 0; i < n->count; i++) {
        const ynode *step = n->items[i];
        if (!yr_visit(&l->r, step))
            return false;
        if (step->kind != YNODE_MAPPING || step->count != 2) {
            diag_at(&l->d, step, "each transform step is a map with one key: translate, rotate, rotate_x, "
                                 "rotate_y, rotate_z or scale");
            return false;
        }
        const ynode *key = step->items[0], *v = step->items[1];
        int k = word(l, key, "transform step", steps, COUNT(steps));
        vec3 vec;
        double a;
        if (k == 0) {
            if (!yr_vec3(&l->r, v, "translate", &vec))
                return false;
            *t = glint_transform_translate(*t, vec.x, vec.y, vec.z);
        } else if (k == 1) {
            if (!yr_is_map(&l->r, v, "'rotate'"))
                return false;
            yr_check_keys(&l->r, v, "rotate", rotate_keys, COUNT(rotate_keys));
            if (!need_vec3(l, v, "axis", "rotate", &vec) || !need_number(l, v, "angle", "rotate", &a))
                return false;
            if (v3_length(vec) == 0) {
                diag_at(&l->d, yr_get(&l->r, v, "axis"), "'axis' must not be zero");
                return false;
            }
            *t = glint_transform_rotate(*t, vec, a);
        } else if (k >= 2 && k <= 4) {
            if (!yr_number(&l->r, v, steps[k], &a))
                return false;
            vec3 axis = v3(k == 2, k == 3, k == 4);
            *t = glint_transform_rotate(*t, axis, a);
        } else if (k == 5) {
            if (v->kind == YNODE_SCALAR) {
                if (!yr_number(&l->r, v, "scale", &a))
                    return false;
                vec = v3(a, a, a);
            } else if (!yr_vec3(&l->r, v, "scale", &vec)) {
                return false;
            }
            if (vec.x == 0 || vec.y == 0 || vec.z == 0) {
                diag_at(&l->d, v, "'scale' must not be zero");
                return false;
            }
            *t = glint_transform_scale(*t, vec.x, vec.y, vec.z);
        } else {
            return false;
        }
    }
    return true;
}

static void read_objects(loader *l, const ynode *list, const context *ctx);

/* The keys of each shape beyond those every object has. */
static const char *const SHAPE_NAMES[] = {"sphere", "plane", "polygon", "box", "cylinder", "cone", "group", "mesh"};
enum { KIND_GROUP = 6, KIND_MESH = 7 };

static bool read_shape(loader *l, const ynode *n, int kind, glint_shape *s)
{
    const char *what = SHAPE_NAMES[kind];
    s->kind = (glint_shape_kind)kind;
    switch (kind) {
    case GLINT_SHAPE_SPHERE:
        return yr_opt_vec3(&l->r, n, "center", &s->center) && need_positive(l, n, "radius", what, &s->radius);
    case GLINT_SHAPE_PLANE:
        return yr_opt_vec3(&l->r, n, "point", &s->center) && need_vec3(l, n, "normal", what, &s->normal);
    case GLINT_SHAPE_POLYGON: {
        const ynode *pts = yr_need(&l->r, n, "points", what);
        if (!pts || !yr_is_list(&l->r, pts, "'points'"))
            return false;
        if (pts->count != 3 && pts->count != 4) {
            diag_at(&l->d, pts, "'points' must hold 3 or 4 points, got %d", pts->count);
            return false;
        }
        s->point_count = pts->count;
        for (int i = 0; i < pts->count; i++)
            if (!yr_vec3(&l->r, pts->items[i], "points", &s->points[i]))
                return false;
        return true;
    }
    case GLINT_SHAPE_BOX:
        return need_vec3(l, n, "min", what, &s->min) && need_vec3(l, n, "max", what, &s->max);
    default: /* cylinder, cone */
        s->capped = true;
        return yr_opt_vec3(&l->r, n, "center", &s->center) && need_positive(l, n, "radius", what, &s->radius) &&
               need_positive(l, n, "height", what, &s->height) && yr_opt_bool(&l->r, n, "capped", &s->capped);
    }
}

/* The mesh of a model file, imported on first use. */
static int import_model(loader *l, const ynode *file, const char *path, double crease)
{
    char canonical[PATH_MAX];
    if (!realpath(path, canonical)) {
        diag_at(&l->d, file, "cannot read model '%s': %s", path, strerror(errno));
        return -1;
    }
    for (int i = 0; i < l->import_count; i++)
        if (l->imports[i].crease_angle == crease && strcmp(l->imports[i].path, canonical) == 0)
            return l->imports[i].mesh;
    glint_import_options o = {.crease_angle = crease, .default_material = -1};
    glint_error err;
    int mesh_index = glint_scene_import_mesh(l->scene, path, &o, &err);
    if (mesh_index < 0) {
        diag_at(&l->d, file, "%s", err.message);
        return -1;
    }
    if (l->import_count == l->import_cap) {
        int ncap = l->import_cap ? 2 * l->import_cap : 8;
        struct imported *p = realloc(l->imports, (size_t)ncap * sizeof *p);
        if (!p)
            return mesh_index;
        l->imports = p;
        l->import_cap = ncap;
    }
    char *copy = strdup(canonical);
    if (copy)
        l->imports[l->import_count++] = (struct imported){copy, crease, mesh_index};
    return mesh_index;
}

/* A mesh object: its model file's triangles, placed; `override` (>= 0)
 * replaces the file's own materials. */
static void place_mesh(loader *l, const ynode *n, int override, const glint_transform *to_world)
{
    const ynode *file = yr_need(&l->r, n, "file", "mesh");
    const char *path;
    double crease = 80;
    if (!file || !yr_text(&l->r, file, "file", &path) ||
        !ranged(l, n, "crease_angle", 0, 180, CLOSED, "from 0 to 180 degrees", &crease))
        return;
    char *full = relative_to(n->file, path);
    if (!full) {
        diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
        return;
    }
    int mesh_index = import_model(l, file, full, crease);
    free(full);
    glint_error err;
    if (mesh_index >= 0 && glint_scene_add_instance(l->scene, mesh_index, override, to_world, &err) < 0)
        diag_at(&l->d, n, "%s", err.message);
}

static void read_object(loader *l, const ynode *n, const context *outer)
{
    static const char *const common[] = {"type", "material", "transform"};
    static const char *const extra[][4] = {
        {"center", "radius"}, {"point", "normal"}, {"points"}, {"min", "max"},
        {"center", "radius", "height", "capped"}, {"center", "radius", "height", "capped"}, {"objects"},
        {"file", "crease_angle"},
    };
    int kind = typed_map(l, n, "an object", SHAPE_NAMES, COUNT(SHAPE_NAMES));
    if (kind < 0)
        return;
    const char *keys[8];
    int count = 0;
    for (int i = 0; i < COUNT(common); i++)
        keys[count++] = common[i];
    for (int i = 0; i < 4 && extra[kind][i]; i++)
        keys[count++] = extra[kind][i];
    yr_check_keys(&l->r, n, SHAPE_NAMES[kind], keys, count);

    context ctx = *outer;
    glint_transform own = glint_transform_identity();
    const ynode *xf = yr_get(&l->r, n, "transform");
    if (xf && !read_transform(l, xf, &own))
        return;
    ctx.to_world = xf_mul(&outer->to_world, &own);
    const ynode *mat = yr_get(&l->r, n, "material");
    if (mat && (ctx.material = object_material(l, mat)) < 0)
        return;

    if (kind == KIND_MESH) {
        place_mesh(l, n, mat ? ctx.material : -1, &ctx.to_world);
        return;
    }
    if (kind == KIND_GROUP) {
        if (outer->depth >= MAX_GROUP_DEPTH) {
            diag_at(&l->d, n, "groups nested too deep (limit %d)", MAX_GROUP_DEPTH);
            return;
        }
        const ynode *children = yr_need(&l->r, n, "objects", "group");
        ctx.depth++;
        if (children)
            read_objects(l, children, &ctx);
        return;
    }
    glint_shape s;
    memset(&s, 0, sizeof s);
    if (!read_shape(l, n, kind, &s))
        return;
    if (ctx.material < 0) {
        diag_at(&l->d, n, "%s needs 'material'", SHAPE_NAMES[kind]);
        return;
    }
    glint_error err;
    if (glint_scene_add_shape(l->scene, &s, ctx.material, &ctx.to_world, &err) < 0)
        diag_at(&l->d, n, "%s", err.message);
}

static void read_objects(loader *l, const ynode *list, const context *ctx)
{
    if (!yr_is_list(&l->r, list, "'objects'"))
        return;
    for (int i = 0; i < list->count && ok(l); i++)
        if (yr_visit(&l->r, list->items[i]))
            read_object(l, list->items[i], ctx);
}

/* ---------------------------------------------------------------- files */

static void read_file(loader *l, const char *path, const ynode *from);

static void read_includes(loader *l, const ynode *n)
{
    if (n->kind == YNODE_SCALAR) {
        const char *path;
        if (!yr_text(&l->r, n, "include", &path))
            return;
        char *full = relative_to(n->file, path);
        if (!full) {
            diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
            return;
        }
        read_file(l, full, n);
        free(full);
        return;
    }
    if (!yr_is_list(&l->r, n, "'include'"))
        return;
    for (int i = 0; i < n->count && ok(l); i++) {
        if (n->items[i]->kind != YNODE_SCALAR) {
            diag_at(&l->d, n->items[i], "'include' must name files, got %s", ynode_describe(n->items[i]));
            continue;
        }
        read_includes(l, n->items[i]);
    }
}

/* Applies each named item of a map section: textures and materials. */
static void read_named(loader *l, const ynode *section, const char *what,
                       void (*read_one)(loader *, const char *, const ynode *))
{
    if (!yr_is_map(&l->r, section, what))
        return;
    for (int i = 0; i + 1 < section->count && ok(l); i += 2) {
        const ynode *k = section->items[i];
        if (!yr_visit(&l->r, k))
            return;
        if (k->kind != YNODE_SCALAR || k->value[0] == '\0') {
            diag_at(&l->d, k, "a name in %s must be a word, got %s", what, ynode_describe(k));
            continue;
        }
        read_one(l, k->value, section->items[i + 1]);
    }
}

static void read_root(loader *l, const ynode *root)
{
    static const char *const keys[] = {"glint", "include", "settings", "camera", "fog",
                                       "textures", "materials", "lights", "objects"};
    if (!root)
        return;
    if (!yr_is_map(&l->r, root, "a scene file"))
        return;
    yr_check_keys(&l->r, root, "the scene", keys, COUNT(keys));
    const ynode *n;
    double version;
    if ((n = yr_get(&l->r, root, "glint")) && yr_number(&l->r, n, "glint", &version) && version != 1) {
        diag_at(&l->d, n, "format version %g is not supported (this glint reads version 1)", version);
        return;
    }
    if ((n = yr_get(&l->r, root, "include")))
        read_includes(l, n);
    if ((n = yr_get(&l->r, root, "settings")))
        read_settings(l, n);
    if ((n = yr_get(&l->r, root, "camera")))
        read_camera(l, n);
    if ((n = yr_get(&l->r, root, "fog")))
        read_fog(l, n);
    if ((n = yr_get(&l->r, root, "textures")))
        read_named(l, n, "'textures'", read_texture);
    if ((n = yr_get(&l->r, root, "materials")))
        read_named(l, n, "'materials'", read_material);
    if ((n = yr_get(&l->r, root, "lights")) && yr_is_list(&l->r, n, "'lights'"))
        for (int i = 0; i < n->count && ok(l); i++)
            if (yr_visit(&l->r, n->items[i]))
                read_light(l, n->items[i]);
    context top = {glint_transform_identity(), -1, 0};
    if ((n = yr_get(&l->r, root, "objects")))
        read_objects(l, n, &top);
}

/* Parses bytes named `name` and walks them; the tree stays alive in l. */
static void read_bytes(loader *l, const char *data, size_t size, const char *name)
{
    if (l->doc_count == l->doc_cap) {
        int ncap = l->doc_cap ? l->doc_cap * 2 : 4;
        ydoc *p = realloc(l->docs, (size_t)ncap * sizeof *p);
        if (!p) {
            diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
            return;
        }
        l->docs = p;
        l->doc_cap = ncap;
    }
    glint_error err;
    ydoc *doc = &l->docs[l->doc_count];
    glint_status s = ydoc_parse(doc, data, size, name, &err);
    if (s) {
        diag_raw(&l->d, s, err.message);
        return;
    }
    l->doc_count++;
    read_root(l, doc->root);
}

/* Reads a whole file (bounded); NULL with a message in err on failure. */
static char *slurp(const char *path, size_t *size, glint_error *err)
{
    /* stat first: opening a FIFO named by a hostile include would block. */
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        error_set(err, GLINT_ERR_IO, "cannot read scene '%s': not a regular file", path);
        return NULL;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        error_set(err, GLINT_ERR_IO, "cannot read scene '%s': %s", path, strerror(errno));
        return NULL;
    }
    char *data = NULL;
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode))
        error_set(err, GLINT_ERR_IO, "cannot read scene '%s': not a regular file", path);
    else if (st.st_size > MAX_SCENE_FILE_BYTES)
        error_set(err, GLINT_ERR_INVALID, "scene '%s' is too large: %lld bytes (limit %ld)", path,
                  (long long)st.st_size, MAX_SCENE_FILE_BYTES);
    else if (!(data = malloc((size_t)st.st_size + 1)))
        error_set(err, GLINT_ERR_NOMEM, "out of memory reading '%s'", path);
    else if ((*size = fread(data, 1, (size_t)st.st_size, f)) != (size_t)st.st_size || ferror(f)) {
        error_set(err, GLINT_ERR_IO, "cannot read scene '%s': read error", path);
        free(data);
        data = NULL;
    }
    fclose(f);
    return data;
}

static void read_file(loader *l, const char *path, const ynode *from)
{
    char canonical[PATH_MAX];
    if (!realpath(path, canonical)) {
        if (from)
            diag_at(&l->d, from, "cannot include '%s': %s", path, strerror(errno));
        else {
            char msg[600];
            snprintf(msg, sizeof msg, "cannot read scene '%s': %s", path, strerror(errno));
            diag_raw(&l->d, GLINT_ERR_IO, msg);
        }
        return;
    }
    for (int i = 0; i < l->depth; i++) {
        if (strcmp(l->chain[i], canonical) != 0)
            continue;
        char cycle[400] = "";
        for (int k = i; k < l->depth; k++) {
            strncat(cycle, strrchr(l->chain[k], '/') + 1, sizeof cycle - strlen(cycle) - 1);
            strncat(cycle, " -> ", sizeof cycle - strlen(cycle) - 1);
        }
        strncat(cycle, strrchr(canonical, '/') + 1, sizeof cycle - strlen(cycle) - 1);
        diag_at(&l->d, from, "include cycle: %s", cycle);
        return;
    }
    if (l->depth >= MAX_INCLUDE_DEPTH) {
        diag_at(&l->d, from, "includes nested too deep (limit %d)", MAX_INCLUDE_DEPTH);
        return;
    }
    /* Includes can fan out (a list of files each including a list...), so
     * the files and bytes of one scene are bounded as a whole. */
    if (++l->files > MAX_FILES) {
        diag_at(&l->d, from, "too many included files (limit %d)", MAX_FILES);
        l->d.closed = true;
        return;
    }
    glint_error err;
    size_t size = 0;
    char *data = slurp(path, &size, &err);
    if (!data) {
        if (from)
            diag_at(&l->d, from, "%s", err.message);
        else
            diag_raw(&l->d, GLINT_ERR_IO, err.message);
        return;
    }
    l->bytes += (long)size;
    if (l->bytes > MAX_SCENE_FILE_BYTES) {
        diag_at(&l->d, from, "scene files too large together (limit %ld bytes)", MAX_SCENE_FILE_BYTES);
        l->d.closed = true;
        free(data);
        return;
    }
    l->chain[l->depth++] = canonical;
    read_bytes(l, data, size, path);
    l->depth--;
    free(data);
}

/* Hands the gathered settings, camera and fog to the scene. */
static void finish(loader *l, const char *name)
{
    glint_error err;
    const ynode *where[] = {l->settings_node, l->camera_node, l->fog_node};
    glint_status s[] = {glint_scene_set_settings(l->scene, &l->settings, &err), GLINT_OK, GLINT_OK};
    for (int i = 0; i < 3; i++) {
        if (i == 1)
            s[1] = glint_scene_set_camera(l->scene, &l->camera, &err);
        if (i == 2 && (!l->fog_node || fog_complete(l)))
            s[2] = glint_scene_set_fog(l->scene, &l->fog, &err);
        if (s[i] && where[i])
            diag_at(&l->d, where[i], "%s", err.message);
        else if (s[i]) {
            char msg[600];
            snprintf(msg, sizeof msg, "%s: %s", name, err.message);
            diag_raw(&l->d, s[i], msg);
        }
    }
    if (l->output && glint_scene_set_output(l->scene, l->output, &err))
        diag_raw(&l->d, GLINT_ERR_NOMEM, err.message);
}

static glint_scene *load(const glint_load_options *o, glint_error *err, const char *name,
                         void (*body)(loader *, const void *, size_t, const char *), const void *data, size_t size)
{
    loader l;
    memset(&l, 0, sizeof l);
    l.scene = glint_scene_new();
    if (!l.scene) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory");
        return NULL;
    }
    l.d = (diag){.report = o ? o->report : NULL, .user = o ? o->report_user : NULL,
                 .max = o && o->max_errors > 0 ? o->max_errors : 20, .first = err};
    l.r.d = &l.d;
    l.settings = glint_scene_get_settings(l.scene);
    l.camera = glint_scene_get_camera(l.scene);
    l.fog = (glint_fog){.kind = GLINT_FOG_NONE, .color = {1, 1, 1}};
    body(&l, data, size, name);
    if (l.d.count == 0)
        finish(&l, name);
    for (int i = 0; i < l.doc_count; i++)
        ydoc_free(&l.docs[i]);
    free(l.docs);
    for (int i = 0; i < l.import_count; i++)
        free(l.imports[i].path);
    free(l.imports);
    if (l.d.count > 0) {
        glint_scene_free(l.scene);
        return NULL;
    }
    return l.scene;
}

static void body_file(loader *l, const void *data, size_t size, const char *name)
{
    read_file(l, name, NULL);
}

static void body_memory(loader *l, const void *data, size_t size, const char *name)
{
    read_bytes(l, data, size, name);
}

glint_scene *glint_scene_load_file(const char *path, const glint_load_options *options, glint_error *err)
{
    return load(options, err, path, body_file, NULL, 0);
}

glint_scene *glint_scene_load_memory(const char *data, size_t size, const char *name,
                                     const glint_load_options *options, glint_error *err)
{
    return load(options, err, name ? name : "<memory>", body_memory, data, size);
}
