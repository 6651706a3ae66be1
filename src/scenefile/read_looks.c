/* read_looks.c - the scene file's textures, materials and lights. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scenefile/loader.h"

/* A mapping: a word (its type) or a map of its type's keys. */
static bool read_mapping(loader *l, const ynode *n, glint_mapping *m)
{
    param_table t = mapping_params();
    const param *kind = &t.params[0];
    const ynode *type = n;
    if (n->kind == YNODE_MAPPING) {
        type = yr_need(&l->r, n, "type", "mapping");
        if (!type)
            return false;
    }
    int k = word(l, type, n == type ? "mapping" : "type", kind->words, kind->word_count);
    if (k < 0)
        return false;
    m->kind = (glint_mapping_kind)k;
    if (n->kind != YNODE_MAPPING)
        return true;
    char what[40];
    snprintf(what, sizeof what, "a %s mapping", kind->words[k]);
    const char *keys[8];
    int count = mapping_key_count(m->kind);
    for (int i = 0; i < count; i++)
        keys[i] = t.params[i].key;
    yr_check_keys(&l->r, n, what, keys, count);
    /* Every key but the type, each where the map gives it. */
    bool good = read_params(l, n, (param_table){t.params + 1, t.count - 1}, what, m);
    m->center_given = yr_get(&l->r, n, "center") != NULL;
    if (good && k == GLINT_MAP_PLANAR && (!yr_get(&l->r, n, "u_axis")) != (!yr_get(&l->r, n, "v_axis"))) {
        diag_at(&l->d, n, "a planar mapping needs both 'u_axis' and 'v_axis', or neither");
        return false;
    }
    return good;
}

/* The node of the first key of table t that names a file, or NULL: a file
 * that cannot be read is reported there. */
static const ynode *file_node(loader *l, const ynode *n, param_table t)
{
    for (int i = 0; i < t.count; i++)
        if (t.params[i].type == PARAM_PATH)
            return yr_get(&l->r, n, t.params[i].key);
    return NULL;
}

static void add_texture(loader *l, const char *name, const ynode *n)
{
    char what[160];
    snprintf(what, sizeof what, "texture '%.100s'", name);
    const char *names[16];
    int count = 0;
    for (int i = 0; i < texture_kind_count() && count < COUNT(names); i++)
        names[count++] = texture_kind_at(i)->name;
    int k = typed_map(l, n, what, names, count);
    if (k < 0)
        return;
    const texture_kind *kind = texture_kind_at(k);
    static const char *const common[] = {"type", "mapping", "transform"};
    const char *keys[24];
    int key_count = param_keys(kind->params, common, COUNT(common), keys, COUNT(keys));
    yr_check_keys(&l->r, n, what, keys, key_count);
    glint_texture t = glint_texture_default(kind->id);
    if (scene_find_texture(l->scene, name) >= 0) {
        diag_at(&l->d, n, "texture '%.100s' is defined twice", name);
        return;
    }
    /* A bad mapping does not hide the other keys' problems. */
    const ynode *m = yr_get(&l->r, n, "mapping"), *place = yr_get(&l->r, n, "transform");
    bool good = !m || read_mapping(l, m, &t.mapping);
    good = (!place || read_transform(l, place, &t.transform)) && good;
    if (!read_params(l, n, kind->params, what, &t) || !good)
        return;
    glint_error err;
    if (glint_scene_add_texture(l->scene, name, &t, &err) < 0) {
        const ynode *file = file_node(l, n, kind->params);
        diag_error(&l->d, file ? file : n, &err);
    }
}

void read_texture(loader *l, const char *name, const ynode *n)
{
    add_texture(l, name, n);
    if (scene_find_texture(l->scene, name) < 0) {
        /* A stand-in keeps the name known: no second report at each use. */
        glint_texture stand_in = glint_texture_default(GLINT_TEXTURE_CHECKER);
        glint_scene_add_texture(l->scene, name, &stand_in, NULL);
    }
}

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

void read_environment(loader *l, const ynode *n)
{
    static const char *const texture_key[] = {"texture"};
    if (!yr_is_map(&l->r, n, "'environment'"))
        return;
    const char *keys[8];
    int count = param_keys(environment_params(), texture_key, COUNT(texture_key), keys, COUNT(keys));
    yr_check_keys(&l->r, n, "environment", keys, count);
    glint_environment env = glint_scene_get_environment(l->scene);
    params_defaults(environment_params(), &env);
    if (!read_params(l, n, environment_params(), "environment", &env))
        return;
    const ynode *tex = yr_get(&l->r, n, "texture");
    const char *name;
    if (!tex) {
        diag_at(&l->d, n, "environment needs 'texture'");
        return;
    }
    if (!yr_text(&l->r, tex, "texture", &name))
        return;
    env.texture = scene_find_texture(l->scene, name);
    glint_error err;
    if (env.texture < 0)
        unknown_name(l, tex, true, name);
    else if (glint_scene_set_environment(l->scene, &env, &err))
        diag_error(&l->d, tex, &err);
}

/* The texture that node n (of `key`) names, its image decoded; -1 after a
 * report. */
static int texture_named(loader *l, const ynode *n, const char *key)
{
    const char *name;
    if (!yr_text(&l->r, n, key, &name))
        return -1;
    int index = scene_find_texture(l->scene, name);
    glint_error err;
    if (index < 0)
        unknown_name(l, n, true, name);
    /* Its image is decoded at its first use, and a bad one reported there. */
    else if (scene_use_texture(l->scene, index, &err)) {
        diag_error(&l->d, n, &err);
        return -1;
    }
    return index;
}

/* A material's bump map: {texture, strength}. */
static void read_bump(loader *l, const ynode *bump, glint_material *m)
{
    static const char *const bump_keys[] = {"texture", "strength"};
    if (!yr_is_map(&l->r, bump, "'bump'"))
        return;
    yr_check_keys(&l->r, bump, "bump", bump_keys, COUNT(bump_keys));
    const ynode *tex = yr_need(&l->r, bump, "texture", "bump");
    if (tex)
        m->bump_texture = texture_named(l, tex, "texture");
    read_params(l, bump, bump_params(), "bump", m);
}

/* Reads a material map's keys over *m (which holds the defaults). */
static bool read_material_keys(loader *l, const ynode *n, const char *what, glint_material *m)
{
    static const char *const own_keys[] = {"texture", "absorption", "bump", "normal_map"};
    if (!yr_is_map(&l->r, n, what))
        return false;
    int before = l->d.count;
    const char *keys[32];
    int count = param_keys(material_params(), own_keys, COUNT(own_keys), keys, COUNT(keys));
    yr_check_keys(&l->r, n, what, keys, count);
    read_params(l, n, material_params(), what, m);
    read_sub_map(l, n, "absorption", absorption_params(), &m->absorption);
    const ynode *tex = yr_get(&l->r, n, "texture"), *bump = yr_get(&l->r, n, "bump");
    const ynode *normals = yr_get(&l->r, n, "normal_map");
    if (tex)
        m->texture = texture_named(l, tex, "texture");
    if (bump)
        read_bump(l, bump, m);
    if (normals)
        m->normal_texture = texture_named(l, normals, "normal_map");
    return l->d.count == before;
}

void read_material(loader *l, const char *name, const ynode *n)
{
    char what[160];
    snprintf(what, sizeof what, "material '%.100s'", name);
    glint_material m = glint_material_default();
    glint_error err;
    if (scene_find_material(l->scene, name) >= 0) {
        diag_at(&l->d, n, "material '%.100s' is defined twice", name);
        return;
    }
    bool good = read_material_keys(l, n, what, &m);
    if (good && glint_scene_add_material(l->scene, name, &m, &err) >= 0)
        return;
    if (good) /* a rule across keys: transparency + refraction */
        diag_error(&l->d, n, &err);
    /* The name stays known, with the defaults: no second report at each use. */
    m = glint_material_default();
    glint_scene_add_material(l->scene, name, &m, NULL);
}

/* An object's material: a name, or an inline map. -1 when it is wrong. */
int object_material(loader *l, const ynode *n)
{
    if (n->kind == YNODE_MAPPING) {
        glint_material m = glint_material_default();
        glint_error err;
        int i = -1;
        if (read_material_keys(l, n, "material", &m) && (i = glint_scene_add_material(l->scene, NULL, &m, &err)) < 0)
            diag_error(&l->d, n, &err);
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

void read_light(loader *l, const ynode *n)
{
    const char *names[16];
    int count = 0;
    for (int i = 0; i < light_kind_count() && count < COUNT(names); i++)
        names[count++] = light_kind_at(i)->name;
    int k = typed_map(l, n, "a light", names, count);
    if (k < 0)
        return;
    const light_kind *kind = light_kind_at(k);
    char what[40];
    snprintf(what, sizeof what, "a %s light", kind->name);
    static const char *const type_key[] = {"type"};
    const char *keys[24];
    int key_count = param_keys(kind->params, type_key, COUNT(type_key), keys, COUNT(keys));
    yr_check_keys(&l->r, n, what, keys, key_count);
    light_spec spec = light_spec_default(kind->id);
    if (!read_params(l, n, kind->params, what, &spec))
        return;
    spec.light.color = rgb_scale(spec.light.color, spec.intensity);
    glint_error err;
    if (glint_scene_add_light(l->scene, &spec.light, &err) < 0)
        diag_error(&l->d, n, &err);
}

