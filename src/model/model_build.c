/* model_build.c - a read model into the scene, as every reader ends: its
 * materials' images as UV-mapped image textures, each added once, then
 * its materials named after the model, then its mesh. Textures go first:
 * they are what a good file most often fails on, and a failure then leaves
 * behind only unnamed textures, never named materials. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "model/model_build.h"
#include "model/model_file.h"
#include "scene/scene.h"

#define MAX_NAME_TRIES 1000

/* The textures added so far, by the name the file gives them. */
typedef struct texture_cache {
    const char **refs;
    int *index;
    size_t count;
} texture_cache;

static glint_material grey(void)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){0.5, 0.5, 0.5};
    return m;
}

glint_status model_add_texture_file(glint_scene *scene, const char *ref, const model_import *job, void *user,
                                    int *out, glint_error *err)
{
    *out = -1;
    if (!job->dir)
        return GLINT_OK;
    char *path = model_file_path(job->dir, ref);
    if (!path)
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", job->file);
    glint_status s = model_file_check_inside(job->dir, path, job->file, "texture", ref, err);
    if (s) {
        free(path);
        return s;
    }
    glint_mapping uv = {.kind = GLINT_MAP_UV};
    glint_error inner;
    *out = glint_scene_add_image_file(scene, NULL, path, uv, &inner);
    free(path);
    /* A model's textures are all used: decoded now, so that a bad one is
     * named with its model. */
    if (*out < 0 || scene_use_texture(scene, *out, &inner))
        return error_set(err, inner.status, "%s: texture '%s': %s", job->file, ref, inner.message);
    return GLINT_OK;
}

/* Sets *out to the texture of image `ref`, adding it the first time: -1
 * when ref is NULL or add_texture does not use it. */
static glint_status material_texture(glint_scene *scene, const char *ref, model_texture_fn add_texture, void *user,
                                     const model_import *job, texture_cache *cache, int *out, glint_error *err)
{
    *out = -1;
    if (!ref)
        return GLINT_OK;
    for (size_t i = 0; i < cache->count; i++)
        if (strcmp(cache->refs[i], ref) == 0) {
            *out = cache->index[i];
            return GLINT_OK;
        }
    glint_status s = add_texture(scene, ref, job, user, out, err);
    if (s)
        return s;
    cache->refs[cache->count] = ref;
    cache->index[cache->count++] = *out;
    return GLINT_OK;
}

/* Adds m as "<stem>/<what>", or "<stem>/<what>#N" when that name is taken
 * (the same model imported twice), or unnamed after that. */
static glint_status add_material(glint_scene *scene, const char *what, const glint_material *m,
                                 const model_import *job, int *out, glint_error *err)
{
    size_t len = strlen(job->stem) + strlen(what) + 16;
    char *name = malloc(len);
    if (!name)
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", job->file);
    snprintf(name, len, "%s/%s", job->stem, what);
    for (int n = 2; scene_find_material(scene, name) >= 0 && n <= MAX_NAME_TRIES + 1; n++)
        snprintf(name, len, "%s/%s#%d", job->stem, what, n);
    glint_error inner;
    *out = glint_scene_add_material(scene, scene_find_material(scene, name) >= 0 ? NULL : name, m, &inner);
    free(name);
    if (*out < 0)
        return error_set(err, inner.status, "%s: %s", job->file, inner.message);
    return GLINT_OK;
}

glint_status model_add_materials(glint_scene *scene, const model_material *mats, size_t count,
                                 model_texture_fn add_texture, void *user, const model_import *job, int *index,
                                 glint_error *err)
{
    /* Each material's colour image, height map and normal map. */
    size_t n = 3 * (count ? count : 1);
    texture_cache cache = {calloc(n, sizeof *cache.refs), calloc(n, sizeof *cache.index), 0};
    int *tex = calloc(n, sizeof *tex);
    glint_status s = GLINT_OK;
    if (!cache.refs || !cache.index || !tex)
        s = error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", job->file);
    for (size_t i = 0; !s && i < count; i++) {
        const char *refs[3] = {mats[i].texture, mats[i].bump, mats[i].normals};
        for (int k = 0; !s && k < 3; k++)
            s = material_texture(scene, mats[i].name ? refs[k] : NULL, add_texture, user, job, &cache,
                                 &tex[3 * i + k], err);
    }
    int fallback = job->default_material;
    for (size_t i = 0; !s && i < count; i++) {
        if (mats[i].name) {
            glint_material m = mats[i].m;
            m.texture = tex[3 * i];
            m.bump_texture = tex[3 * i + 1];
            m.normal_texture = tex[3 * i + 2];
            s = add_material(scene, mats[i].name, &m, job, &index[i], err);
            continue;
        }
        if (fallback < 0) {
            glint_material m = grey();
            s = add_material(scene, "default", &m, job, &fallback, err);
        }
        index[i] = *job->stand_in = fallback;
    }
    free(cache.refs);
    free(cache.index);
    free(tex);
    return s;
}

int model_add_mesh(glint_scene *scene, const model_import *job, const glint_mesh_data *d, glint_error *err)
{
    glint_error inner;
    int added = glint_scene_add_mesh(scene, job->stem, d, &inner);
    if (added < 0)
        error_set(err, inner.status, "%s: %s", job->file, inner.message);
    else
        scene->meshes[added].bare = !d->materials && d->material == *job->stand_in;
    return added;
}
