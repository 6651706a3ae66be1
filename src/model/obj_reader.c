/* obj_reader.c - the OBJ reader: an OBJ model into the scene with glint's
 * own readers, the OBJ text (obj_read.c, streamed from a file), its
 * vertices (obj_mesh.c), the MTL files it names (mtl_read.c) and the
 * materials and textures its faces use, then one mesh (model_build.c). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "core/file_log.h"
#include "core/array.h"
#include "core/error.h"
#include "model/model_build.h"
#include "model/model_file.h"
#include "model/mtl_read.h"
#include "model/obj_mesh.h"
#include "model/obj_read.h"
#include "scene/scene.h"

static glint_status out_of_memory(const model_import *job, glint_error *err)
{
    return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", job->file);
}

/* Reads the MTL file `name` into lib. One that does not exist is left
 * out with a warning, as other readers do: its materials are then
 * undefined, and grey. One that exists but cannot be read (a folder, a
 * FIFO, no permission, no descriptors left) is an error, as is one outside
 * the model's folder or one that does not follow the format. */
static glint_status read_library(glint_scene *scene, mtl_library *lib, const model_import *job, const char *name,
                                 glint_error *err)
{
    char *path = model_file_path(job->dir, name);
    if (!path)
        return out_of_memory(job, err);
    unsigned char *data = NULL;
    size_t size;
    glint_error inner;
    glint_status s = model_file_check_inside(job->dir, path, job->file, "MTL file", name, err);
    if (!s && (s = model_file_read(path, &data, &size, &inner))) {
        if (s == GLINT_ERR_IO && errno == ENOENT)
            s = scene_warn(scene, err, "%s: MTL file '%s' does not exist: its materials are grey", job->file, name);
        else
            s = error_set(err, s, "%s: MTL file: %s", job->file, inner.message);
    } else if (!s && !(s = scene_note_path(scene, path, err))) {
        s = mtl_read(lib, (const char *)data, size, path, err);
    }
    free(data);
    free(path);
    return s;
}

/* True when `name`, relative to the model, is a regular file. */
static bool is_file(const model_import *job, const char *name)
{
    char *path = model_file_path(job->dir, name);
    struct stat st;
    bool yes = path && file_stat(path, &st) == 0 && S_ISREG(st.st_mode);
    free(path);
    return yes;
}

/* Reads the MTL files of an mtllib line: the whole line when it names a
 * file (its name may have blanks), and otherwise each of its words. */
static glint_status read_libraries_of(glint_scene *scene, mtl_library *lib, const model_import *job,
                                      const char *line, glint_error *err)
{
    if (!strpbrk(line, " \t") || is_file(job, line))
        return read_library(scene, lib, job, line, err);
    char *word = malloc(strlen(line) + 1);
    if (!word)
        return out_of_memory(job, err);
    glint_status s = GLINT_OK;
    for (const char *p = line + strspn(line, " \t"); !s && *p; p += strspn(p, " \t")) {
        size_t n = strcspn(p, " \t");
        memcpy(word, p, n);
        word[n] = '\0';
        s = read_library(scene, lib, job, word, err);
        p += n;
    }
    free(word);
    return s;
}

/* What faces of material `id` (an index of m->materials, or -1 for none)
 * become. */
static model_material material_of(const obj_model *m, const mtl_library *lib, int32_t id)
{
    model_material im = {0};
    if (id < 0)
        return im;
    im.name = m->text + m->materials[id];
    const mtl_material *def = mtl_find(lib, im.name);
    mtl_material given = def ? *def : mtl_default();
    im.m = mtl_to_glint(&given);
    im.texture = given.map_kd != MTL_NO_TEXT ? lib->text + given.map_kd : NULL;
    im.bump = given.bump != MTL_NO_TEXT ? lib->text + given.bump : NULL;
    im.normals = given.norm != MTL_NO_TEXT ? lib->text + given.norm : NULL;
    /* -bm scales the height, from glint's own default. */
    im.m.bump_strength *= given.bump_multiplier;
    return im;
}

/* Adds the materials the faces use, in the order they are first used, and
 * sets run_material[r] to the glint material of run r. */
static glint_status add_materials(glint_scene *scene, const obj_model *m, const mtl_library *lib,
                                  const model_import *job, int *run_material, glint_error *err)
{
    size_t n = m->material_count + 1, count = 0;
    int *slot = array_alloc(n, sizeof *slot), *added = array_alloc(n, sizeof *added);
    model_material *mats = array_alloc(n, sizeof *mats);
    glint_status s = slot && added && mats ? GLINT_OK : out_of_memory(job, err);
    for (size_t i = 0; !s && i < n; i++)
        slot[i] = -1;
    for (size_t r = 0; !s && r < m->run_count; r++) {
        size_t k = (size_t)(m->runs[r].material + 1);
        if (slot[k] < 0) {
            slot[k] = (int)count;
            mats[count++] = material_of(m, lib, m->runs[r].material);
        }
    }
    if (!s)
        s = model_add_materials(scene, mats, count, model_add_texture_file, NULL, job, added, err);
    for (size_t r = 0; !s && r < m->run_count; r++)
        run_material[r] = added[slot[m->runs[r].material + 1]];
    free(slot);
    free(added);
    free(mats);
    return s;
}

/* The material of each triangle from those of the runs, into *out; NULL
 * when all runs have one. */
static glint_status triangle_materials(const obj_model *m, const int *run_material, const model_import *job,
                                       int **out, glint_error *err)
{
    *out = NULL;
    size_t r = 1;
    while (r < m->run_count && run_material[r] == run_material[0])
        r++;
    if (r == m->run_count)
        return GLINT_OK;
    if (!(*out = array_alloc(m->triangle_count, sizeof **out)))
        return out_of_memory(job, err);
    for (r = 0; r < m->run_count; r++) {
        size_t end = r + 1 < m->run_count ? m->runs[r + 1].first : m->triangle_count;
        for (size_t t = m->runs[r].first; t < end; t++)
            (*out)[t] = run_material[r];
    }
    return GLINT_OK;
}

/* Builds the mesh of a read model: its vertices, then its materials, then
 * the mesh itself. */
static int build(glint_scene *scene, obj_model *m, const model_import *job, glint_error *err)
{
    obj_vertices v = {0};
    mtl_library lib = {0};
    int *run_material = array_alloc(m->run_count, sizeof *run_material), *materials = NULL;
    glint_status s = run_material ? GLINT_OK : out_of_memory(job, err);
    if (!s)
        s = obj_mesh_vertices(m, job->crease, job->file, &v, err);
    for (size_t i = 0; !s && job->dir && i < m->library_count; i++)
        s = read_libraries_of(scene, &lib, job, m->text + m->libraries[i], err);
    if (!s)
        s = add_materials(scene, m, &lib, job, run_material, err);
    mtl_free(&lib);
    if (!s)
        s = triangle_materials(m, run_material, job, &materials, err);
    int mesh_index = -1;
    if (!s) {
        glint_mesh_data d = {
            .positions = v.positions, .normals = v.normals, .uvs = v.uvs, .vertex_count = (int)v.count,
            .indices = m->triangles, .triangle_count = (int)m->triangle_count, .materials = materials,
            .material = run_material[0],
        };
        mesh_index = model_add_mesh(scene, job, &d, err);
    }
    obj_vertices_free(&v);
    free(run_material);
    free(materials);
    return mesh_index;
}

/* Builds the model that reading gave with status s, when it has
 * triangles, and frees it. */
static int build_read(glint_scene *scene, obj_model *m, glint_status s, const model_import *job, glint_error *err)
{
    if (!s && m->triangle_count == 0)
        s = error_set(err, GLINT_ERR_INVALID, "%s: no triangles", job->file);
    int mesh_index = s ? -1 : build(scene, m, job, err);
    obj_model_free(m);
    return mesh_index;
}

static int import_file(glint_scene *scene, int fd, const model_import *job, glint_error *err)
{
    obj_model m;
    glint_status s = obj_read_fd(&m, fd, job->file, err);
    return build_read(scene, &m, s, job, err);
}

static int import_memory(glint_scene *scene, const unsigned char *data, size_t size, const model_import *job,
                         glint_error *err)
{
    obj_model m;
    glint_status s = obj_read_memory(&m, data, size, job->file, err);
    return build_read(scene, &m, s, job, err);
}

/* OBJ alone: its MTL files are named by its mtllib lines, and read only
 * when the model may read files (job->dir). */
static const model_format formats[] = {
    {.extension = "obj", .names_materials = true},
    {0},
};

const model_reader obj_reader = {.formats = formats, .import_file = import_file, .import_memory = import_memory};
