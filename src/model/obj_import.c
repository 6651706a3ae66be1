/* obj_import.c - an OBJ model into the scene with glint's own readers: the
 * OBJ text (obj_read.c), its vertices (obj_mesh.c), the MTL files it names
 * (mtl_read.c) and the materials and textures its faces use, then one mesh,
 * all through the public API. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "core/array.h"
#include "core/error.h"
#include "model/mesh_import.h"
#include "model/obj_mesh.h"
#include "model/obj_read.h"

static glint_status out_of_memory(const mesh_import_ctx *ctx, glint_error *err)
{
    return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", ctx->file);
}

/* Reads the MTL file `name` into lib. One that cannot be read is left out,
 * as other readers do: its materials are then undefined. One that does not
 * follow the format is an error. */
static glint_status read_library(mtl_library *lib, const mesh_import_ctx *ctx, const char *name, glint_error *err)
{
    char *path = mesh_import_path(ctx->dir, name);
    if (!path)
        return out_of_memory(ctx, err);
    unsigned char *data;
    size_t size;
    glint_error ignored;
    glint_status s = mesh_import_read_file(path, &data, &size, &ignored);
    if (s == GLINT_ERR_NOMEM)
        s = out_of_memory(ctx, err);
    else if (s)
        s = GLINT_OK;
    else
        s = mtl_read(lib, (const char *)data, size, path, err);
    free(data);
    free(path);
    return s;
}

/* True when `name`, relative to the model, is a regular file. */
static bool is_file(const mesh_import_ctx *ctx, const char *name)
{
    char *path = mesh_import_path(ctx->dir, name);
    struct stat st;
    bool yes = path && stat(path, &st) == 0 && S_ISREG(st.st_mode);
    free(path);
    return yes;
}

/* Reads the MTL files of an mtllib line: the whole line when it names a
 * file (its name may have blanks), and otherwise each of its words. */
static glint_status read_libraries_of(mtl_library *lib, const mesh_import_ctx *ctx, const char *line,
                                      glint_error *err)
{
    if (!strpbrk(line, " \t") || is_file(ctx, line))
        return read_library(lib, ctx, line, err);
    char *word = malloc(strlen(line) + 1);
    if (!word)
        return out_of_memory(ctx, err);
    glint_status s = GLINT_OK;
    for (const char *p = line + strspn(line, " \t"); !s && *p; p += strspn(p, " \t")) {
        size_t n = strcspn(p, " \t");
        memcpy(word, p, n);
        word[n] = '\0';
        s = read_library(lib, ctx, word, err);
        p += n;
    }
    free(word);
    return s;
}

/* What faces of material `id` (an index of m->materials, or -1 for none)
 * become. */
static import_material material_of(const obj_model *m, const mtl_library *lib, int32_t id)
{
    import_material im = {0};
    if (id < 0)
        return im;
    im.name = m->text + m->materials[id];
    const mtl_material *def = mtl_find(lib, im.name);
    mtl_material given = def ? *def : mtl_default();
    im.m = mesh_import_from_mtl(&given);
    im.texture = given.map_kd != MTL_NO_TEXT ? lib->text + given.map_kd : NULL;
    return im;
}

/* Adds the materials the faces use, in the order they are first used, and
 * sets run_material[r] to the glint material of run r. */
static glint_status add_materials(glint_scene *scene, const obj_model *m, const mtl_library *lib,
                                  const mesh_import_ctx *ctx, int *run_material, glint_error *err)
{
    size_t n = m->material_count + 1, count = 0;
    int *slot = array_alloc(n, sizeof *slot), *added = array_alloc(n, sizeof *added);
    import_material *mats = array_alloc(n, sizeof *mats);
    glint_status s = slot && added && mats ? GLINT_OK : out_of_memory(ctx, err);
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
        s = mesh_import_add_materials(scene, mats, count, NULL, ctx, added, err);
    for (size_t r = 0; !s && r < m->run_count; r++)
        run_material[r] = added[slot[m->runs[r].material + 1]];
    free(slot);
    free(added);
    free(mats);
    return s;
}

/* The material of each triangle from those of the runs, into *out; NULL
 * when all runs have one. */
static glint_status triangle_materials(const obj_model *m, const int *run_material, const mesh_import_ctx *ctx,
                                       int **out, glint_error *err)
{
    *out = NULL;
    size_t r = 1;
    while (r < m->run_count && run_material[r] == run_material[0])
        r++;
    if (r == m->run_count)
        return GLINT_OK;
    if (!(*out = array_alloc(m->triangle_count, sizeof **out)))
        return out_of_memory(ctx, err);
    for (r = 0; r < m->run_count; r++) {
        size_t end = r + 1 < m->run_count ? m->runs[r + 1].first : m->triangle_count;
        for (size_t t = m->runs[r].first; t < end; t++)
            (*out)[t] = run_material[r];
    }
    return GLINT_OK;
}

/* Builds the mesh of a read model: its vertices, then its materials, then
 * the mesh itself. */
static int build(glint_scene *scene, obj_model *m, const mesh_import_ctx *ctx, double crease, glint_error *err)
{
    obj_vertices v = {0};
    mtl_library lib = {0};
    int *run_material = array_alloc(m->run_count, sizeof *run_material), *materials = NULL;
    glint_status s = run_material ? GLINT_OK : out_of_memory(ctx, err);
    if (!s)
        s = obj_mesh_vertices(m, crease, ctx->file, &v, err);
    for (size_t i = 0; !s && ctx->dir && i < m->library_count; i++)
        s = read_libraries_of(&lib, ctx, m->text + m->libraries[i], err);
    if (!s)
        s = add_materials(scene, m, &lib, ctx, run_material, err);
    mtl_free(&lib);
    if (!s)
        s = triangle_materials(m, run_material, ctx, &materials, err);
    int mesh = -1;
    if (!s) {
        glint_mesh_data d = {
            .positions = v.positions, .normals = v.normals, .uvs = v.uvs, .vertex_count = (int)v.count,
            .indices = m->triangles, .triangle_count = (int)m->triangle_count, .materials = materials,
            .material = run_material[0],
        };
        mesh = mesh_import_add_mesh(scene, ctx, &d, err);
    }
    obj_vertices_free(&v);
    free(run_material);
    free(materials);
    return mesh;
}

int mesh_import_obj(glint_scene *scene, const mesh_import_ctx *ctx, int fd, const unsigned char *data, size_t size,
                    double crease, glint_error *err)
{
    obj_model m;
    glint_status s = fd >= 0 ? obj_read_fd(&m, fd, ctx->file, err) : obj_read_memory(&m, data, size, ctx->file, err);
    if (!s && m.triangle_count == 0)
        s = error_set(err, GLINT_ERR_INVALID, "%s: no triangles", ctx->file);
    int mesh = s ? -1 : build(scene, &m, ctx, crease, err);
    obj_model_free(&m);
    return mesh;
}
