/* scene.c - the scene's C API: creating a scene and adding to it. Every
 * value is checked here, so the renderer can trust what it reads. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "geometry/shape_kind.h"
#include "scene/scene.h"
#include "shading/fog.h"

/* The most of any one kind of thing a scene may hold. */
#define SCENE_MAX_ITEMS (1 << 24)

const char *glint_version(void)
{
    return GLINT_VERSION;
}

glint_scene *glint_scene_new(void)
{
    glint_scene *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->settings = glint_settings_default();
    s->camera = camera_default();
    s->fog.kind = GLINT_FOG_NONE;
    s->environment = (glint_environment){.texture = -1, .intensity = 1};
    return s;
}

void glint_scene_free(glint_scene *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->texture_count; i++)
        texture_release(&s->textures[i]);
    for (int i = 0; i < s->material_count; i++)
        free(s->materials[i].name);
    free(s->textures);
    scene_free_images(s);
    free(s->materials);
    id_table_free(&s->texture_names);
    id_table_free(&s->material_names);
    scene_motion_free(s);
    for (int i = 0; i < s->shape_count; i++) {
        free(s->shapes[i].parts);
        sphere_set *set = s->shapes[i].set;
        if (set) {
            free(set->balls);
            free(set->materials);
            free(set);
        }
    }
    free(s->shapes);
    free(s->lights);
    free(s->area_lights);
    for (int i = 0; i < s->emitter_count; i++)
        light_release(&s->emitters[i]);
    free(s->emitters);
    for (int i = 0; i < s->mesh_count; i++)
        mesh_release(&s->meshes[i]);
    free(s->meshes);
    free(s->instances);
    free(s->output);
    scene_files_free(s);
    free(s);
}

/* Makes room for one more element in a growing array, up to the limit. */
static glint_status grow(void **items, size_t *cap, int count, size_t size, const char *what, glint_error *err)
{
    if (count >= SCENE_MAX_ITEMS)
        return error_set(err, GLINT_ERR_INVALID, "too many %s (limit %d)", what, SCENE_MAX_ITEMS);
    if (!array_reserve(items, cap, (size_t)count + 1, size))
        return error_set(err, GLINT_ERR_NOMEM, "out of memory adding %s", what);
    return GLINT_OK;
}

static glint_status copy_name(char **out, const char *name, glint_error *err)
{
    *out = NULL;
    if (!name)
        return GLINT_OK;
    *out = strdup(name);
    return *out ? GLINT_OK : error_set(err, GLINT_ERR_NOMEM, "out of memory");
}

glint_status glint_scene_set_settings(glint_scene *scene, const glint_settings *s, glint_error *err)
{
    glint_status st = settings_validate(s, err);
    if (st == GLINT_OK)
        scene->settings = *s;
    return st;
}

glint_settings glint_scene_get_settings(const glint_scene *scene)
{
    return scene->settings;
}

glint_status glint_scene_set_camera(glint_scene *scene, const glint_camera *cam, glint_error *err)
{
    glint_status s = camera_validate(cam, err);
    if (s == GLINT_OK) {
        scene->camera = *cam;
        /* Poses of the camera it replaces are not this camera's. */
        free(scene->camera_poses);
        scene->camera_poses = NULL;
        scene->camera_pose_count = 0;
    }
    return s;
}

glint_camera glint_scene_get_camera(const glint_scene *scene)
{
    return scene->camera;
}

glint_fog glint_scene_get_fog(const glint_scene *scene)
{
    return scene->fog;
}

glint_environment glint_scene_get_environment(const glint_scene *scene)
{
    return scene->environment;
}

glint_status glint_scene_set_environment(glint_scene *scene, const glint_environment *env, glint_error *err)
{
    glint_status s = environment_validate(env, scene->texture_count, err);
    if (s == GLINT_OK && env->texture >= 0)
        s = scene_use_texture(scene, env->texture, err);
    if (s == GLINT_OK)
        scene->environment = *env;
    return s;
}

glint_status glint_scene_set_fog(glint_scene *scene, const glint_fog *fog, glint_error *err)
{
    glint_status s = fog_validate(fog, err);
    if (s == GLINT_OK)
        scene->fog = *fog;
    return s;
}

/* The name tables' comparisons: keys are the scene's arrays of textures
 * or materials, ids their indices. */
static bool texture_name_equal(const void *keys, uint32_t id, const void *name)
{
    return strcmp(((const texture *)keys)[id].name, name) == 0;
}

static bool material_name_equal(const void *keys, uint32_t id, const void *name)
{
    return strcmp(((const material *)keys)[id].name, name) == 0;
}

int scene_find_texture(const glint_scene *scene, const char *name)
{
    uint32_t id;
    return name && id_table_find(&scene->texture_names, id_hash_text(name), name, texture_name_equal,
                                 scene->textures, &id) ? (int)id : -1;
}

int scene_find_material(const glint_scene *scene, const char *name)
{
    uint32_t id;
    return name && id_table_find(&scene->material_names, id_hash_text(name), name, material_name_equal,
                                 scene->materials, &id) ? (int)id : -1;
}

/* Appends texture t, built and checked, under `name` (or none); on failure
 * releases what t owns. */
static int append_texture(glint_scene *scene, texture *t, const char *name, glint_error *err)
{
    glint_status s =
        grow((void **)&scene->textures, &scene->texture_cap, scene->texture_count, sizeof *t, "textures", err);
    if (!s)
        s = copy_name(&t->name, name, err);
    if (!s && name &&
        !id_table_reserve(&scene->texture_names, scene->texture_names.count + 1))
        s = error_set(err, GLINT_ERR_NOMEM, "out of memory adding textures");
    if (s) {
        texture_release(t);
        return -1;
    }
    scene->textures[scene->texture_count] = *t;
    /* Room was reserved above: entering cannot fail. */
    if (name)
        id_table_add(&scene->texture_names, id_hash_text(name), (uint32_t)scene->texture_count);
    return scene->texture_count++;
}

/* Refuses a texture name already taken. */
static bool name_free(const glint_scene *scene, const char *name, glint_error *err)
{
    if (scene_find_texture(scene, name) < 0)
        return true;
    error_set(err, GLINT_ERR_INVALID, "texture '%s' is defined twice", name);
    return false;
}

int glint_scene_add_texture(glint_scene *scene, const char *name, const glint_texture *desc, glint_error *err)
{
    texture t;
    if (!name_free(scene, name, err) || texture_init(&t, desc, scene_check_image, scene, err))
        return -1;
    if (desc->file && scene_note_path(scene, desc->file, err)) {
        texture_release(&t);
        return -1;
    }
    return append_texture(scene, &t, name, err);
}

int glint_scene_add_checker(glint_scene *scene, const char *name, glint_color a, glint_color b, double cell,
                            glint_mapping mapping, glint_error *err)
{
    glint_texture t = glint_texture_default(GLINT_TEXTURE_CHECKER);
    t.mapping = mapping;
    t.colors[0] = a;
    t.colors[1] = b;
    t.size = cell;
    return glint_scene_add_texture(scene, name, &t, err);
}

int glint_scene_add_image_file(glint_scene *scene, const char *name, const char *path, glint_mapping mapping,
                               glint_error *err)
{
    glint_texture t = glint_texture_default(GLINT_TEXTURE_IMAGE);
    t.mapping = mapping;
    t.file = path;
    return glint_scene_add_texture(scene, name, &t, err);
}

/* Adds an image texture over an image decoded here or borrowed, which it
 * then owns, remembering `file` (NULL: bytes from memory) as the image's
 * source; the mapping is checked as any texture's. */
static int add_decoded_image(glint_scene *scene, const char *name, texture_image image, glint_mapping mapping,
                             const char *file, glint_error *err)
{
    texture t = {.kind = &image_texture, .mapping = mapping, .image = image,
                 .desc = glint_texture_default(GLINT_TEXTURE_IMAGE)};
    t.desc.mapping = mapping;
    if (!texture_set_file(&t, file)) {
        texture_release(&t);
        error_set(err, GLINT_ERR_NOMEM, "out of memory");
        return -1;
    }
    if (!name_free(scene, name, err) || mapping_validate(&mapping, err)) {
        texture_release(&t);
        return -1;
    }
    return append_texture(scene, &t, name, err);
}

int glint_scene_add_image_memory(glint_scene *scene, const char *name, const void *data, size_t size,
                                 glint_mapping mapping, glint_error *err)
{
    texture_image image;
    if (texture_image_load_memory(&image, data, size, name ? name : "image", err))
        return -1;
    return add_decoded_image(scene, name, image, mapping, NULL, err);
}

int scene_add_image_pixels(glint_scene *scene, const char *name, int width, int height,
                           const unsigned char *srgb, const char *file, glint_mapping mapping, glint_error *err)
{
    /* Its levels are built here, as a decoded file's are, so the image
     * looks the same either way. */
    texture_image image = texture_image_borrow(width, height, srgb);
    if (texture_image_build_levels(&image, err))
        return -1;
    return add_decoded_image(scene, name, image, mapping, file, err);
}

glint_status glint_scene_replace_image(glint_scene *scene, const char *name, const char *path, glint_error *err)
{
    int i = scene_find_texture(scene, name);
    if (i < 0 || scene->textures[i].kind != &image_texture)
        return error_set(err, GLINT_ERR_INVALID, "no image texture named '%s'", name ? name : "");
    texture_image img;
    glint_status s = texture_image_load_file(&img, path, err);
    if (!s && (s = scene_note_path(scene, path, err)))
        texture_image_free(&img);
    if (s)
        return s;
    if (!texture_set_file(&scene->textures[i], path)) {
        texture_image_free(&img);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory");
    }
    texture_image_free(&scene->textures[i].image);
    scene->textures[i].image = img;
    return GLINT_OK;
}

int glint_scene_add_material(glint_scene *scene, const char *name, const glint_material *m, glint_error *err)
{
    if (scene_find_material(scene, name) >= 0) {
        error_set(err, GLINT_ERR_INVALID, "material '%s' is defined twice", name);
        return -1;
    }
    if (m->normal_texture >= 0 && m->normal_texture < scene->texture_count &&
        scene->textures[m->normal_texture].kind->solid) {
        error_set(err, GLINT_ERR_INVALID, "a normal map needs a texture of (u, v), not a solid %s texture",
                  scene->textures[m->normal_texture].kind->name);
        return -1;
    }
    if (material_validate(m, scene->texture_count, err) ||
        (m->texture >= 0 && scene_use_texture(scene, m->texture, err)) ||
        (m->bump_texture >= 0 && scene_use_texture(scene, m->bump_texture, err)) ||
        (m->normal_texture >= 0 && scene_use_texture(scene, m->normal_texture, err)) ||
        grow((void **)&scene->materials, &scene->material_cap, scene->material_count, sizeof(material),
             "materials", err))
        return -1;
    if (name && !id_table_reserve(&scene->material_names, scene->material_names.count + 1)) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory adding materials");
        return -1;
    }
    material *slot = &scene->materials[scene->material_count];
    if (copy_name(&slot->name, name, err))
        return -1;
    slot->m = *m;
    /* Room was reserved above: entering cannot fail. */
    if (name)
        id_table_add(&scene->material_names, id_hash_text(name), (uint32_t)scene->material_count);
    return scene->material_count++;
}

/* Why combination `csg` cannot take another part, into err; GLINT_OK when
 * it can. */
static glint_status part_room(const glint_scene *scene, int csg, glint_error *err)
{
    if (csg < 0 || csg >= scene->shape_count || !scene->shapes[csg].kind->csg)
        return error_set(err, GLINT_ERR_INVALID, "shape %d is not a union, intersection or difference", csg);
    const shape *c = &scene->shapes[csg];
    if (c->part_count >= SHAPE_MAX_PARTS)
        return error_set(err, GLINT_ERR_INVALID, "%s %s holds at most %d parts: gather some in %s %s of their own",
                         object_article(c->kind->name), c->kind->name, SHAPE_MAX_PARTS, object_article(c->kind->name),
                         c->kind->name);
    int depth = 1;
    for (int up = c->part_of; up >= 0; up = scene->shapes[up].part_of)
        depth++;
    if (depth >= SHAPE_MAX_NESTING)
        return error_set(err, GLINT_ERR_INVALID, "combinations nested too deep (limit %d)", SHAPE_MAX_NESTING);
    return GLINT_OK;
}

/* Gives part s the transform number of the part added before it (past
 * the combinations between) when their transforms are the same, as those
 * of a combination's parts are when only the combination was placed. */
static void share_transform(glint_scene *scene, shape *s)
{
    if (!s->has_transform || s->csg)
        return;
    int k = scene->shape_count - 1;
    while (k >= 0 && scene->shapes[k].csg)
        k--;
    const shape *before = k >= 0 ? &scene->shapes[k] : NULL;
    if (before && before->transform_id && memcmp(&before->to_world, &s->to_world, sizeof s->to_world) == 0)
        s->transform_id = before->transform_id;
    else
        s->transform_id = ++scene->transform_ids;
}

/* glint_scene_add_shape, or with csg >= 0 glint_scene_add_part; with
 * `solid` (a mesh whose solid is made) and no desc, glint_scene_add_mesh_part.
 * mat -1 is a combination's (its parts have their own) or a mesh part's
 * (its triangles have theirs). */
static int add_shape(glint_scene *scene, int csg, const glint_shape *desc, const mesh *solid, int mat,
                     const glint_transform *xf, glint_error *err)
{
    const shape_kind *kind = solid ? &mesh_part_kind : shape_kind_of(desc->kind);
    bool combination = kind && kind->csg;
    if (!((combination || solid) && mat == -1) && (mat < 0 || mat >= scene->material_count)) {
        error_set(err, GLINT_ERR_INVALID, "material %d does not exist", mat);
        return -1;
    }
    if (solid && mat == -1 && !solid->materials)
        mat = solid->material;
    if (!solid && desc->kind == GLINT_SHAPE_MESH) {
        error_set(err, GLINT_ERR_INVALID, "a mesh is placed by glint_scene_add_instance, or made a part of a "
                  "combination by glint_scene_add_mesh_part");
        return -1;
    }
    if (combination && xf && !xf_is_identity(xf)) {
        error_set(err, GLINT_ERR_INVALID, "%s %s takes no transform: its parts carry theirs", object_article(kind->name),
                  kind->name);
        return -1;
    }
    const shape *before = scene->shapes;
    if (grow((void **)&scene->shapes, &scene->shape_cap, scene->shape_count, sizeof(shape), "shapes", err))
        return -1;
    /* Growing may have moved the array, which every combination points at
     * (and only they: a scene of thousands of plain shapes is not walked
     * again at each doubling). */
    for (int i = 0; scene->shapes != before && scene->combinations && i < scene->shape_count; i++)
        if (scene->shapes[i].csg)
            scene->shapes[i].family = scene->shapes;
    shape *parent = csg >= 0 ? &scene->shapes[csg] : NULL;
    if (parent && !array_reserve((void **)&parent->parts, &parent->part_cap, (size_t)parent->part_count + 1,
                                 sizeof *parent->parts)) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory adding shapes");
        return -1;
    }
    shape *s = &scene->shapes[scene->shape_count];
    if (solid ? shape_init_mesh_part(s, solid->solid, xf, mat, err) : shape_init(s, desc, xf, mat, err))
        return -1;
    s->family = scene->shapes;
    if (parent && !(s->kind->closed && s->kind->closed(s))) {
        error_set(err, GLINT_ERR_INVALID, "a %s is not closed, so it cannot be a part of %s %s (a cylinder or cone "
                  "needs its caps)", s->kind->name, object_article(parent->kind->name), parent->kind->name);
        return -1;
    }
    if (parent) {
        s->part_of = csg;
        parent->parts[parent->part_count++] = scene->shape_count;
        shape_parts_changed(scene->shapes, csg);
        share_transform(scene, s);
    }
    color glow = mat >= 0 ? material_emission(&scene->materials[mat].m) : rgb(0, 0, 0);
    if (parent && rgb_max(glow) > 0) {
        if (scene_warn(scene, err, "an emissive %s in a %s glows but lights nothing: only whole shapes light the "
                       "scene", s->kind->name, parent->kind->name))
            return -1;
    } else if (rgb_max(glow) > 0) {
        light emitter;
        if (!emitter_for_shape(&emitter, s, scene->shape_count, glow)) {
            if (scene_warn(scene, err, "an emissive %s glows but lights nothing: it has no end (a polygon or "
                           "disk does)", s->kind->name))
                return -1;
        } else {
            if (grow((void **)&scene->emitters, &scene->emitter_cap, scene->emitter_count, sizeof(light),
                     "emissive shapes", err))
                return -1;
            scene->emitters[scene->emitter_count++] = emitter;
        }
    }
    scene->combinations += s->csg;
    return scene->shape_count++;
}

int glint_scene_add_shape(glint_scene *scene, const glint_shape *desc, int mat, const glint_transform *xf,
                          glint_error *err)
{
    return add_shape(scene, -1, desc, NULL, mat, xf, err);
}

/* Checks sphere k of glint_scene_add_spheres' arrays. */
static glint_status check_set_sphere(const glint_scene *scene, int k, glint_vec3 center, double radius, int mat,
                                     glint_error *err)
{
    if (!isfinite(center.x) || !isfinite(center.y) || !isfinite(center.z))
        return error_set(err, GLINT_ERR_INVALID, "sphere %d of the set: its centre is not finite", k);
    if (!(radius > 0) || !isfinite(radius))
        return error_set(err, GLINT_ERR_INVALID, "sphere %d of the set: radius must be positive, got %g", k, radius);
    if (mat < 0 || mat >= scene->material_count)
        return error_set(err, GLINT_ERR_INVALID, "sphere %d of the set: material %d does not exist", k, mat);
    if (rgb_max(material_emission(&scene->materials[mat].m)) > 0)
        return error_set(err, GLINT_ERR_INVALID,
                         "sphere %d of the set: material %d glows, and a set's spheres light nothing: add glowing "
                         "spheres one by one", k, mat);
    return GLINT_OK;
}

int glint_scene_add_spheres(glint_scene *scene, int count, const glint_vec3 *centers, const double *radii,
                            const int *materials, glint_error *err)
{
    if (count < 1 || count > SCENE_MAX_ITEMS) {
        error_set(err, GLINT_ERR_INVALID, "a sphere set holds 1 to %d spheres, got %d", SCENE_MAX_ITEMS, count);
        return -1;
    }
    if (!centers || !radii || !materials) {
        error_set(err, GLINT_ERR_INVALID, "a sphere set needs its centres, radii and materials");
        return -1;
    }
    for (int k = 0; k < count; k++)
        if (check_set_sphere(scene, k, centers[k], radii[k], materials[k], err))
            return -1;
    if (grow((void **)&scene->shapes, &scene->shape_cap, scene->shape_count, sizeof(shape), "shapes", err))
        return -1;
    sphere_set *set = calloc(1, sizeof *set);
    if (set) {
        set->balls = malloc((size_t)count * sizeof *set->balls);
        set->materials = malloc((size_t)count * sizeof *set->materials);
    }
    if (!set || !set->balls || !set->materials) {
        if (set) {
            free(set->balls);
            free(set->materials);
        }
        free(set);
        error_set(err, GLINT_ERR_NOMEM, "out of memory adding a sphere set");
        return -1;
    }
    set->count = count;
    for (int k = 0; k < count; k++) {
        set->balls[k][0] = centers[k].x;
        set->balls[k][1] = centers[k].y;
        set->balls[k][2] = centers[k].z;
        set->balls[k][3] = radii[k];
    }
    memcpy(set->materials, materials, (size_t)count * sizeof *materials);
    shape_init_sphere_set(&scene->shapes[scene->shape_count], set);
    return scene->shape_count++;
}

int glint_scene_add_part(glint_scene *scene, int csg, const glint_shape *desc, int mat, const glint_transform *xf,
                         glint_error *err)
{
    if (part_room(scene, csg, err))
        return -1;
    return add_shape(scene, csg, desc, NULL, mat, xf, err);
}

int glint_scene_add_mesh_part(glint_scene *scene, int csg, int mesh_index, int mat, const glint_transform *xf,
                              glint_error *err)
{
    if (part_room(scene, csg, err))
        return -1;
    if (mesh_index < 0 || mesh_index >= scene->mesh_count) {
        error_set(err, GLINT_ERR_INVALID, "mesh %d does not exist", mesh_index);
        return -1;
    }
    mesh *m = &scene->meshes[mesh_index];
    const char *named = m->name ? m->name : m->origin.file;
    char name[300];
    if (named)
        snprintf(name, sizeof name, "mesh '%.280s'", named);
    else
        snprintf(name, sizeof name, "mesh %d", mesh_index);
    if (mesh_make_solid(m, name, err))
        return -1;
    return add_shape(scene, csg, NULL, m, mat, xf, err);
}

int glint_scene_add_light(glint_scene *scene, const glint_light *desc, glint_error *err)
{
    if (grow((void **)&scene->lights, &scene->light_cap, scene->light_count, sizeof(light), "lights", err) ||
        light_init(&scene->lights[scene->light_count], desc, err))
        return -1;
    if (!scene->lights[scene->light_count].kind->delta) {
        if (grow((void **)&scene->area_lights, &scene->area_light_cap, scene->area_light_count, sizeof(int), "lights",
                 err))
            return -1;
        scene->area_lights[scene->area_light_count++] = scene->light_count;
    }
    return scene->light_count++;
}

glint_status glint_scene_set_output(glint_scene *scene, const char *path, glint_error *err)
{
    char *copy = NULL;
    glint_status s = copy_name(&copy, path, err);
    if (s)
        return s;
    free(scene->output);
    scene->output = copy;
    return GLINT_OK;
}

const char *glint_scene_get_output(const glint_scene *scene)
{
    return scene->output;
}

glint_scene_counts glint_scene_get_counts(const glint_scene *scene)
{
    glint_scene_counts c = {scene->texture_count, scene->material_count, scene->shape_count, scene->light_count,
                            scene->mesh_count, scene->instance_count, 0, 0, 0};
    for (int i = 0; i < scene->mesh_count; i++)
        c.triangles += scene->meshes[i].triangle_count;
    for (int i = 0; i < scene->shape_count; i++)
        if (scene->shapes[i].set) {
            c.sphere_sets++;
            c.set_spheres += scene->shapes[i].set->count;
        }
    return c;
}

int glint_scene_add_mesh(glint_scene *scene, const char *name, const glint_mesh_data *data, glint_error *err)
{
    if (grow((void **)&scene->meshes, &scene->mesh_cap, scene->mesh_count, sizeof(mesh), "meshes", err) ||
        mesh_init(&scene->meshes[scene->mesh_count], name, data, scene->material_count, err))
        return -1;
    return scene->mesh_count++;
}

int glint_scene_add_instance(glint_scene *scene, int mesh_index, int mat, const glint_transform *xf,
                             glint_error *err)
{
    if (mesh_index < 0 || mesh_index >= scene->mesh_count) {
        error_set(err, GLINT_ERR_INVALID, "mesh %d does not exist", mesh_index);
        return -1;
    }
    if (mat < -1 || mat >= scene->material_count) {
        error_set(err, GLINT_ERR_INVALID, "material %d does not exist", mat);
        return -1;
    }
    instance inst = {.mesh = mesh_index, .material = mat, .to_world = xf ? *xf : glint_transform_identity()};
    if (!xf_invert(&inst.to_world, &inst.to_object)) {
        error_set(err, GLINT_ERR_INVALID, "transform is singular or not finite");
        return -1;
    }
    inst.has_transform = !xf_is_identity(&inst.to_world);
    if (grow((void **)&scene->instances, &scene->instance_cap, scene->instance_count, sizeof inst, "instances",
             err) ||
        grow((void **)&scene->emitters, &scene->emitter_cap, scene->emitter_count, sizeof(light), "emissive meshes",
             err))
        return -1;
    bool out_of_memory;
    if (emitter_for_instance(&scene->emitters[scene->emitter_count], &scene->meshes[mesh_index], &inst,
                             scene->materials, &out_of_memory))
        scene->emitter_count++;
    else if (out_of_memory) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory adding an emissive mesh's triangles");
        return -1;
    }
    scene->instances[scene->instance_count] = inst;
    return scene->instance_count++;
}

bool glint_scene_mesh_is_bare(const glint_scene *scene, int mesh_index)
{
    return scene && mesh_index >= 0 && mesh_index < scene->mesh_count && scene->meshes[mesh_index].bare;
}

glint_status glint_scene_mesh_bounds(const glint_scene *scene, int mesh_index, glint_vec3 *lo, glint_vec3 *hi,
                                     glint_error *err)
{
    if (mesh_index < 0 || mesh_index >= scene->mesh_count)
        return error_set(err, GLINT_ERR_INVALID, "mesh %d does not exist", mesh_index);
    *lo = scene->meshes[mesh_index].lo;
    *hi = scene->meshes[mesh_index].hi;
    return GLINT_OK;
}

glint_status scene_set_mesh_origin(glint_scene *scene, int mesh_index, const char *path, const mesh_origin *origin,
                                   glint_error *err)
{
    mesh_origin *o = &scene->meshes[mesh_index].origin;
    char *file = NULL;
    glint_status s = copy_name(&file, path, err);
    if (s)
        return s;
    free(o->file);
    *o = *origin;
    o->file = file;
    return GLINT_OK;
}
