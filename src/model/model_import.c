/* model_import.c - glint_scene_import_mesh and _memory: a model file into
 * one glint mesh with its materials and textures, built with the public
 * API only (docs/meshes.md). The file name's extension picks the reader
 * (model_registry.c); a reader that wants the bytes whole gets them read
 * and checked against the format first. Only a model from a file may read
 * the files it names. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "core/error.h"
#include "model/model_file.h"
#include "model/model_format.h"
#include "scene/scene.h"

#define DEFAULT_CREASE_DEGREES 80.0

/* Checks the options; fills job->crease and job->default_material. */
static glint_status read_options(const glint_scene *scene, const glint_import_options *o, model_import *job,
                                 glint_error *err)
{
    job->crease = o && o->crease_angle != 0 ? o->crease_angle : DEFAULT_CREASE_DEGREES;
    if (!(job->crease > 0 && job->crease <= 180))
        return error_set(err, GLINT_ERR_INVALID, "%s: crease angle must be in (0, 180] degrees, got %g", job->file,
                         job->crease);
    job->default_material = o ? o->default_material : -1;
    if (job->default_material < -1 || job->default_material >= glint_scene_get_counts(scene).materials)
        return error_set(err, GLINT_ERR_INVALID, "%s: default material %d does not exist", job->file,
                         job->default_material);
    return GLINT_OK;
}

/* Sets *stem to the file name less directory and extension, and, when the
 * files it names may be read, *dir to its directory (else NULL); the
 * caller frees both. */
static glint_status name_parts(const char *file, bool disk, char **stem, char **dir, glint_error *err)
{
    const char *slash = strrchr(file, '/');
    const char *base = slash ? slash + 1 : file;
    const char *dot = strrchr(base, '.');
    *stem = strndup(base, dot && dot != base ? (size_t)(dot - base) : strlen(base));
    *dir = !disk ? NULL : slash == file ? strdup("/") : strndup(file, slash ? (size_t)(slash - file) : 0);
    if (!*stem || (disk && !*dir))
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    return GLINT_OK;
}

/* Hands the reader the model's bytes whole: those of the open file fd when
 * fd >= 0, else the `size` bytes at data, once they pass the format's
 * check. */
static int import_bytes(glint_scene *scene, const model_reader *reader, int fd, const unsigned char *data,
                        size_t size, const model_import *job, glint_error *err)
{
    unsigned char *read = NULL;
    glint_status s = fd >= 0 ? model_file_read_fd(fd, size, job->file, &read, err) : GLINT_OK;
    if (read)
        data = read;
    if (!s && job->format->check)
        s = job->format->check(data, size, job->file, err);
    int mesh_index = s ? -1 : reader->import_memory(scene, data, size, job, err);
    free(read);
    return mesh_index;
}

/* Imports the model in the open file fd, of `size` bytes, or, when fd is
 * -1, in the `size` bytes at data; `file` names it. */
static int import(glint_scene *scene, int fd, const unsigned char *data, size_t size, const char *file,
                  const glint_import_options *options, glint_error *err)
{
    const model_reader *reader = NULL;
    int stand_in = -1;
    model_import job = {.file = file, .format = model_format_of(file, &reader), .stand_in = &stand_in};
    char *stem = NULL, *dir = NULL;
    glint_status s = read_options(scene, options, &job, err);
    if (!s && !job.format) {
        char formats[128];
        model_format_list(formats, sizeof formats);
        s = error_set(err, GLINT_ERR_INVALID, "%s: unsupported format (glint imports %s)", file, formats);
    }
    if (!s)
        s = name_parts(file, fd >= 0, &stem, &dir, err);
    job.stem = stem;
    job.dir = dir;
    glint_scene_counts before = glint_scene_get_counts(scene);
    int mesh_index = -1;
    if (!s && fd >= 0 && reader->import_file)
        mesh_index = reader->import_file(scene, fd, &job, err);
    else if (!s)
        mesh_index = import_bytes(scene, reader, fd, data, size, &job, err);
    if (mesh_index >= 0) {
        /* What a scene file needs to import it again, and what it added. */
        glint_scene_counts after = glint_scene_get_counts(scene);
        mesh_origin origin = {NULL, job.crease, job.default_material, before.materials,
                              after.materials - before.materials, before.textures,
                              after.textures - before.textures};
        if (scene_set_mesh_origin(scene, mesh_index, fd >= 0 ? file : NULL, &origin, err))
            mesh_index = -1;
    }
    free(stem);
    free(dir);
    return mesh_index;
}

int glint_scene_import_mesh(glint_scene *scene, const char *path, const glint_import_options *options,
                            glint_error *err)
{
    if (!scene || !path) {
        error_set(err, GLINT_ERR_INVALID, "import needs a scene and a file name");
        return -1;
    }
    int fd;
    size_t size;
    if (model_file_open(path, &fd, &size, err))
        return -1;
    int mesh_index = import(scene, fd, NULL, size, path, options, err);
    struct stat st;
    if (mesh_index >= 0 && fstat(fd, &st) == 0 && scene_note_file(scene, &st, err))
        mesh_index = -1;
    close(fd);
    return mesh_index;
}

int glint_scene_import_mesh_memory(glint_scene *scene, const void *data, size_t size, const char *name,
                                   const glint_import_options *options, glint_error *err)
{
    if (!scene || !name || (!data && size > 0)) {
        error_set(err, GLINT_ERR_INVALID, "import needs a scene, a name and data");
        return -1;
    }
    return import(scene, -1, data ? data : "", size, name, options, err);
}
