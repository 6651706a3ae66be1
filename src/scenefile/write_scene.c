/* write_scene.c - glint_scene_write_yaml: a scene as a YAML scene file that
 * loads back to the same scene and so renders to the same bytes.
 *
 * Everything goes through the parameter tables and the registries: a
 * shape, light or texture kind is written by its table, so a new kind
 * needs nothing here. The settings and the camera are written whole (they
 * are short, and their defaults are worth seeing); every other map gives
 * only the keys whose values are not their defaults, bit for bit. Objects
 * are written placed: a group is a way of writing, not a thing in the
 * scene, so each shape and mesh carries its own composed transform as one
 * exact `matrix` step. A mesh is its model file, imported again on
 * reading, and the materials and textures that import made are left for
 * it to make. */
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "geometry/shape_kind.h"
#include "scene/scene.h"
#include "scenefile/yaml_write.h"
#include "shading/fog.h"

/* What the writer decides before writing: the texture names (those the
 * scene gives, and made-up ones for unnamed textures) and which textures
 * and materials a mesh's import made (NULL names: not written). */
typedef struct plan {
    const glint_scene *scene;
    char **texture_names;
    bool *texture_from_mesh, *material_from_mesh;
    FILE *f;
} plan;

static void plan_free(plan *p)
{
    for (int i = 0; p->texture_names && i < p->scene->texture_count; i++)
        free(p->texture_names[i]);
    free(p->texture_names);
    free(p->texture_from_mesh);
    free(p->material_from_mesh);
}

/* Whether mesh m is placed at all, or a part of a combination: a mesh
 * nobody placed is not written. */
static bool is_placed(const glint_scene *s, int m)
{
    for (int i = 0; i < s->instance_count; i++)
        if (s->instances[i].mesh == m)
            return true;
    for (int i = 0; i < s->shape_count; i++)
        if (s->shapes[i].solid && s->shapes[i].solid == s->meshes[m].solid)
            return true;
    return false;
}

/* Marks the textures and materials mesh imports made; refuses a placed mesh
 * a scene file cannot make again. */
static glint_status plan_meshes(plan *p, glint_error *err)
{
    const glint_scene *s = p->scene;
    for (int m = 0; m < s->mesh_count; m++) {
        const mesh_origin *o = &s->meshes[m].origin;
        const char *name = s->meshes[m].name ? s->meshes[m].name : "";
        if (!o->file) {
            if (is_placed(s, m) && s->meshes[m].materials)
                return error_set(err, GLINT_ERR_INVALID,
                                 "mesh %d ('%s') gives its triangles materials of their own: a scene file can give "
                                 "only a model file's that",
                                 m, name);
            continue;
        }
        if (o->default_material >= 0)
            return error_set(err, GLINT_ERR_INVALID,
                             "mesh '%s' was imported with a default material, which a scene file cannot give",
                             o->file);
        for (int i = 0; i < o->material_count; i++)
            p->material_from_mesh[o->first_material + i] = true;
        for (int i = 0; i < o->texture_count; i++)
            p->texture_from_mesh[o->first_texture + i] = true;
    }
    return GLINT_OK;
}

/* Whether a texture has `name`, or one of the first i made-up names is it. */
static bool name_taken(const plan *p, int i, const char *name)
{
    for (int k = 0; k < i; k++)
        if (p->texture_names[k] && strcmp(p->texture_names[k], name) == 0)
            return true;
    return scene_find_texture(p->scene, name) >= 0;
}

/* A name for unnamed texture i that no other texture has: "texture-N". */
static char *made_up_name(const plan *p, int i)
{
    char buf[64];
    int n = i + 1;
    do
        snprintf(buf, sizeof buf, "texture-%d", n++);
    while (name_taken(p, i, buf));
    return strdup(buf);
}

static glint_status plan_textures(plan *p, glint_error *err)
{
    const glint_scene *s = p->scene;
    for (int i = 0; i < s->texture_count; i++) {
        const texture *t = &s->textures[i];
        if (p->texture_from_mesh[i])
            continue;
        if (t->kind == &image_texture && !t->desc.file)
            return error_set(err, GLINT_ERR_INVALID,
                             "texture '%s' was decoded from bytes in memory: a scene file can name only image files",
                             t->name ? t->name : "");
        p->texture_names[i] = t->name ? strdup(t->name) : made_up_name(p, i);
        if (!p->texture_names[i])
            return error_set(err, GLINT_ERR_NOMEM, "out of memory");
    }
    for (int i = 0; i < s->material_count; i++) {
        const glint_material *m = &s->materials[i].m;
        int used[3] = {m->texture, m->bump_texture, m->normal_texture};
        for (int k = 0; k < 3; k++)
            if (!p->material_from_mesh[i] && used[k] >= 0 && !p->texture_names[used[k]])
                return error_set(err, GLINT_ERR_INVALID, "material %d uses a texture of a model's own", i);
    }
    if (s->environment.texture >= 0 && !p->texture_names[s->environment.texture])
        return error_set(err, GLINT_ERR_INVALID, "the environment is a texture of a model's own");
    return GLINT_OK;
}

static glint_status plan_make(plan *p, const glint_scene *s, FILE *f, glint_error *err)
{
    *p = (plan){.scene = s, .f = f};
    size_t textures = (size_t)s->texture_count + 1, materials = (size_t)s->material_count + 1;
    p->texture_names = calloc(textures, sizeof *p->texture_names);
    p->texture_from_mesh = calloc(textures, sizeof *p->texture_from_mesh);
    p->material_from_mesh = calloc(materials, sizeof *p->material_from_mesh);
    if (!p->texture_names || !p->texture_from_mesh || !p->material_from_mesh)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory");
    for (int i = 0; i < s->shape_count; i++)
        if (s->shapes[i].csg && s->shapes[i].part_count == 0)
            return error_set(err, GLINT_ERR_INVALID, "shape %d is %s %s of nothing, which a scene file cannot say", i,
                             object_article(s->shapes[i].kind->name), s->shapes[i].kind->name);
    glint_status st = plan_meshes(p, err);
    return st ? st : plan_textures(p, err);
}

/* Whether material i is written in the materials section, by its name. */
static bool named_material(const plan *p, int i)
{
    return p->scene->materials[i].name && !p->material_from_mesh[i];
}

/* A map of table t's keys of obj under its own key, every key, on one
 * line: settings' ambient_occlusion, a material's absorption. */
static void write_sub_map(const plan *p, ymap *m, const char *key, param_table t, const void *obj)
{
    ymap_key(m, key);
    ymap sub = ymap_begin(p->f, true, 0);
    yw_params(&sub, t, obj, true);
    ymap_end(&sub);
}

/* A material's keys (and its texture's name) into m. */
static void material_keys(const plan *p, ymap *m, const glint_material *mat)
{
    yw_params(m, material_params(), mat, false);
    if (material_absorbs(mat))
        write_sub_map(p, m, "absorption", absorption_params(), &mat->absorption);
    if (mat->texture >= 0) {
        ymap_key(m, "texture");
        yw_text(p->f, p->texture_names[mat->texture]);
    }
    if (mat->bump_texture >= 0) {
        ymap_key(m, "bump");
        ymap bump = ymap_begin(p->f, true, 0);
        ymap_key(&bump, "texture");
        yw_text(p->f, p->texture_names[mat->bump_texture]);
        yw_params(&bump, bump_params(), mat, true);
        ymap_end(&bump);
    }
    if (mat->normal_texture >= 0) {
        ymap_key(m, "normal_map");
        yw_text(p->f, p->texture_names[mat->normal_texture]);
    }
}

/* An object's material: its name, or the material written in place. */
static void material_value(const plan *p, int i)
{
    if (named_material(p, i)) {
        yw_text(p->f, p->scene->materials[i].name);
        return;
    }
    ymap m = ymap_begin(p->f, true, 0);
    material_keys(p, &m, &p->scene->materials[i].m);
    ymap_end(&m);
}

static void write_settings(const plan *p)
{
    const glint_scene *s = p->scene;
    fputs("settings:\n  ", p->f);
    ymap m = ymap_begin(p->f, false, 2);
    yw_params(&m, settings_params(), &s->settings, true);
    if (s->settings.occlusion_samples > 0)
        write_sub_map(p, &m, "ambient_occlusion", occlusion_params(), &s->settings);
    if (s->settings.filter != GLINT_FILTER_BOX || s->settings.filter_radius != 0)
        write_sub_map(p, &m, "filter", filter_params(), &s->settings);
    if (s->settings.adaptive_max_samples > 0)
        write_sub_map(p, &m, "adaptive", adaptive_params(), &s->settings);
    if (s->settings.frame_start != 0 || s->settings.frame_end != 0 || s->settings.fps != 24)
        write_sub_map(p, &m, "frames", frames_params(), &s->settings);
    if (s->settings.shutter_open != s->settings.shutter_close)
        write_sub_map(p, &m, "shutter", shutter_params(), &s->settings);
    if (s->output) {
        ymap_key(&m, "output");
        yw_text(p->f, s->output);
    }
    ymap_end(&m);
    fputs("camera:\n  ", p->f);
    m = ymap_begin(p->f, false, 2);
    yw_params(&m, camera_params(), &s->camera, true);
    ymap_end(&m);
}

/* The environment, after the textures it names. */
static void write_environment(const plan *p)
{
    const glint_environment *env = &p->scene->environment;
    if (env->texture < 0)
        return;
    fputs("environment: ", p->f);
    ymap m = ymap_begin(p->f, true, 0);
    ymap_key(&m, "texture");
    yw_text(p->f, p->texture_names[env->texture]);
    yw_params(&m, environment_params(), env, false);
    ymap_end(&m);
    fputc('\n', p->f);
}

static void write_fog(const plan *p)
{
    const glint_fog *fog = &p->scene->fog;
    if (fog->kind == GLINT_FOG_NONE)
        return;
    fputs("fog: ", p->f);
    ymap m = ymap_begin(p->f, true, 0);
    param_table t = fog_params();
    for (int i = 0; i < t.count; i++)
        if (fog_reads(fog->kind, &t.params[i])) {
            ymap_key(&m, t.params[i].key);
            yw_param(p->f, &t.params[i], fog);
        }
    ymap_end(&m);
    fputc('\n', p->f);
}

/* A texture's mapping, when it is not the default uv: its type alone, or
 * with the keys its type reads that are not at their defaults. */
static void write_mapping(const plan *p, ymap *m, const glint_mapping *given)
{
    glint_mapping map = *given;
    if (map.scale == 0)
        map.scale = 1; /* what a scale of 0 means (glint_mapping) */
    param_table t = mapping_params();
    param_table read = {t.params, mapping_key_count(map.kind)};
    /* A center given as [0, 0, 0] still says something: without it, a
     * spherical or cylindrical mapping goes around its shape. */
    const param *center = params_find(read, "center");
    bool zero_center_given = center && map.center_given && param_is_default(center, &map);
    bool type_only = !zero_center_given;
    for (int i = 1; i < read.count; i++)
        type_only = type_only && param_is_default(&read.params[i], &map);
    if (map.kind == GLINT_MAP_UV && type_only)
        return;
    ymap_key(m, "mapping");
    if (type_only) {
        yw_param(p->f, &t.params[0], &map);
        return;
    }
    ymap keys = ymap_begin(p->f, true, 0);
    yw_params(&keys, read, &map, false);
    if (zero_center_given) {
        ymap_key(&keys, center->key);
        yw_param(p->f, center, &map);
    }
    ymap_end(&keys);
}

/* An object's or texture's transform, the last key of block map m, as one matrix step
 * with a row a line. */
static void write_transform(const plan *p, ymap *m, const glint_transform *t)
{
    ymap_key_block(m, "transform");
    fprintf(p->f, "\n%*s- matrix:", m->indent + 2, "");
    for (int i = 0; i < 3; i++) {
        fprintf(p->f, "\n%*s- [", m->indent + 6, "");
        for (int j = 0; j < 4; j++) {
            fputs(j ? ", " : "", p->f);
            yw_number(p->f, t->m[i][j]);
        }
        fputc(']', p->f);
    }
}

static void write_textures(const plan *p)
{
    const glint_scene *s = p->scene;
    bool any = false;
    for (int i = 0; i < s->texture_count; i++) {
        const texture *t = &s->textures[i];
        if (!p->texture_names[i])
            continue;
        fputs(any ? "  " : "textures:\n  ", p->f);
        any = true;
        yw_text(p->f, p->texture_names[i]);
        /* On one line, or with a transform, a key a line. */
        fputs(t->placed ? ":\n    " : ": ", p->f);
        ymap m = ymap_begin(p->f, !t->placed, 4);
        ymap_key(&m, "type");
        fputs(t->kind->name, p->f);
        write_mapping(p, &m, &t->desc.mapping);
        yw_params(&m, t->kind->params, &t->desc, false);
        if (t->placed)
            write_transform(p, &m, &t->desc.transform);
        ymap_end(&m);
        if (!t->placed)
            fputc('\n', p->f);
    }
}

static void write_materials(const plan *p)
{
    const glint_scene *s = p->scene;
    bool any = false;
    for (int i = 0; i < s->material_count; i++) {
        if (!named_material(p, i))
            continue;
        fputs(any ? "  " : "materials:\n  ", p->f);
        any = true;
        yw_text(p->f, s->materials[i].name);
        fputs(": ", p->f);
        ymap m = ymap_begin(p->f, true, 0);
        material_keys(p, &m, &s->materials[i].m);
        ymap_end(&m);
        fputc('\n', p->f);
    }
}

static void write_lights(const plan *p)
{
    const glint_scene *s = p->scene;
    for (int i = 0; i < s->light_count; i++) {
        const light *l = &s->lights[i];
        /* The colour is stored scaled by the intensity: intensity 1. */
        light_spec spec = {l->desc, 1};
        fputs(i ? "  - " : "lights:\n  - ", p->f);
        ymap m = ymap_begin(p->f, true, 0);
        ymap_key(&m, "type");
        fputs(l->kind->name, p->f);
        yw_params(&m, l->kind->params, &spec, false);
        ymap_end(&m);
        fputc('\n', p->f);
    }
}

/* Starts an item of an objects list indented by `indent`: a map on one
 * line, or (`block`, with a transform or parts) a key a line. */
static ymap object_begin(const plan *p, int indent, bool block)
{
    fprintf(p->f, "%*s- ", indent, "");
    return ymap_begin(p->f, !block, indent + 2);
}

static void object_end(const plan *p, ymap *m)
{
    bool flow = m->flow;
    ymap_end(m);
    if (flow)
        fputc('\n', p->f);
}

/* A list of `count` rows of `width` floats under `key` of m, on one line. */
static void write_rows(const plan *p, ymap *m, const char *key, const float *rows, int count, int width)
{
    ymap_key(m, key);
    fputc('[', p->f);
    for (int i = 0; i < count; i++) {
        fputs(i ? ", [" : "[", p->f);
        for (int k = 0; k < width; k++) {
            fputs(k ? ", " : "", p->f);
            yw_float(p->f, rows[i * width + k]);
        }
        fputc(']', p->f);
    }
    fputc(']', p->f);
}

/* A mesh made from arrays, written out as them: its vertices, normals and
 * uvs, and its triangles as faces. */
static void write_mesh_arrays(const plan *p, ymap *m, const mesh *me)
{
    write_rows(p, m, "vertices", me->positions, me->vertex_count, 3);
    if (me->normals)
        write_rows(p, m, "normals", me->normals, me->vertex_count, 3);
    if (me->uvs)
        write_rows(p, m, "uvs", me->uvs, me->vertex_count, 2);
    ymap_key(m, "faces");
    fputc('[', p->f);
    for (int t = 0; t < me->triangle_count; t++) {
        const uint32_t *v = me->indices + 3 * (size_t)t;
        fprintf(p->f, "%s[%u, %u, %u]", t ? ", " : "", (unsigned)v[0], (unsigned)v[1], (unsigned)v[2]);
    }
    fputc(']', p->f);
}

/* Mesh `index` as an item of an objects list indented by `indent`: placed
 * by to_world (when `moved`) with material `look` (-1: the mesh's own). */
static void write_mesh(const plan *p, int index, int indent, int look, bool moved, const transform *to_world)
{
    const mesh *me = &p->scene->meshes[index];
    const mesh_origin *o = &me->origin;
    ymap m = object_begin(p, indent, moved || !o->file);
    ymap_key(&m, "type");
    fputs("mesh", p->f);
    if (o->file) {
        ymap_key(&m, "file");
        yw_text(p->f, o->file);
        glint_import_options options = {.crease_angle = o->crease_angle};
        yw_params(&m, import_params(), &options, false);
    } else {
        write_mesh_arrays(p, &m, me);
    }
    /* A file's mesh is read with its own material again; arrays have one. */
    if (!o->file && look < 0)
        look = me->material;
    if (look >= 0 && !(o->file && look == me->material && !me->materials)) {
        ymap_key(&m, "material");
        material_value(p, look);
    }
    if (moved)
        write_transform(p, &m, to_world);
    object_end(p, &m);
}

/* The mesh whose solid a mesh part is. */
static int mesh_of_part(const glint_scene *s, const shape *part)
{
    int m = 0;
    while (s->meshes[m].solid != part->solid)
        m++;
    return m;
}

/* A sphere set's spheres as items of the objects list, a sphere each:
 * loaded again, they render the same. */
static void write_sphere_set(const plan *p, const sphere_set *set, int indent)
{
    glint_shape sphere = glint_shape_default(GLINT_SHAPE_SPHERE);
    for (int k = 0; k < set->count; k++) {
        sphere.center = (glint_vec3){set->balls[k][0], set->balls[k][1], set->balls[k][2]};
        sphere.radius = set->balls[k][3];
        ymap m = object_begin(p, indent, false);
        ymap_key(&m, "type");
        fputs(sphere_kind.name, p->f);
        yw_params(&m, sphere_kind.params, &sphere, false);
        ymap_key(&m, "material");
        material_value(p, set->materials[k]);
        object_end(p, &m);
    }
}

/* Shape i as an item of an objects list indented by `indent`, and a
 * combination's parts as its own objects list. */
static void write_shape(const plan *p, int i, int indent)
{
    const shape *sh = &p->scene->shapes[i];
    if (sh->set) {
        write_sphere_set(p, sh->set, indent);
        return;
    }
    if (sh->solid) {
        write_mesh(p, mesh_of_part(p->scene, sh), indent, sh->material, sh->has_transform, &sh->to_world);
        return;
    }
    ymap m = object_begin(p, indent, sh->has_transform || sh->csg);
    ymap_key(&m, "type");
    fputs(sh->kind->name, p->f);
    yw_params(&m, sh->kind->params, &sh->desc, false);
    if (sh->material >= 0) {
        ymap_key(&m, "material");
        material_value(p, sh->material);
    }
    if (sh->has_transform)
        write_transform(p, &m, &sh->to_world);
    if (!sh->csg) {
        object_end(p, &m);
        return;
    }
    /* The parts end their own lines: the map needs no end of its own. */
    ymap_key_block(&m, "objects");
    fputc('\n', p->f);
    for (int k = 0; k < sh->part_count; k++)
        write_shape(p, sh->parts[k], m.indent + 2);
}

static void write_objects(const plan *p)
{
    const glint_scene *s = p->scene;
    if (s->shape_count > 0 || s->instance_count > 0)
        fputs("objects:\n", p->f);
    for (int i = 0; i < s->shape_count; i++)
        if (s->shapes[i].part_of < 0)
            write_shape(p, i, 2);
    for (int i = 0; i < s->instance_count; i++) {
        const instance *in = &s->instances[i];
        write_mesh(p, in->mesh, 2, in->material, in->has_transform, &in->to_world);
    }
}

glint_status glint_scene_write_yaml(const glint_scene *scene, FILE *out, glint_error *err)
{
    if (!scene || !out)
        return error_set(err, GLINT_ERR_INVALID, "writing a scene needs a scene and a file");
    plan p;
    glint_status st = plan_make(&p, scene, out, err);
    if (!st) {
        fputs("# A glint scene file (docs/scene-format.md). Settings and camera list every key;\n"
              "# elsewhere a key at its default is left out.\n"
              "glint: 1\n",
              out);
        write_settings(&p);
        write_fog(&p);
        write_textures(&p);
        write_environment(&p);
        write_materials(&p);
        write_lights(&p);
        write_objects(&p);
        if (fflush(out) || ferror(out))
            st = error_set(err, GLINT_ERR_IO, "the scene could not be written");
    }
    plan_free(&p);
    return st;
}
