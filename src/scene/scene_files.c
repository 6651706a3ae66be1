/* scene_files.c - what a scene remembers of the files it was built from:
 * each one's device and inode, so that an output path naming one of them
 * (a scene whose `output:` is itself, a texture, a model) is refused before
 * a render would replace it; and the warnings of things it went on
 * without (a model's MTL file that does not exist). Files are compared by
 * device and inode, so that another name for the same file (a link, a
 * "./" more) is still that file. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "core/array.h"
#include "core/error.h"
#include "core/file_log.h"
#include "core/message_fit.h"
#include "scene/scene.h"

#define MAX_WARNINGS 100

glint_status scene_note_file(glint_scene *scene, const struct stat *st, glint_error *err)
{
    if (file_set_add(&scene->inputs, st->st_dev, st->st_ino) < 0)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory");
    return GLINT_OK;
}

glint_status scene_note_path(glint_scene *scene, const char *path, glint_error *err)
{
    struct stat st;
    return file_stat(path, &st) == 0 ? scene_note_file(scene, &st, err) : GLINT_OK;
}

glint_status glint_scene_check_output(const glint_scene *scene, const char *path, glint_error *err)
{
    struct stat st;
    if (!scene || !path || stat(path, &st) != 0)
        return GLINT_OK;
    if (file_set_find(&scene->inputs, st.st_dev, st.st_ino) >= 0)
        return error_set(err, GLINT_ERR_INVALID,
                         "will not write '%s': it is one of the files this scene was read from", path);
    return GLINT_OK;
}

glint_status scene_warn(glint_scene *scene, glint_error *err, const char *format, ...)
{
    if (scene->warning_count >= MAX_WARNINGS)
        return GLINT_OK;
    char text[MESSAGE_ROOM];
    va_list ap;
    va_start(ap, format);
    message_vformat(text, sizeof err->message, format, ap);
    va_end(ap);
    char *copy = strdup(text);
    if (!copy || !array_reserve((void **)&scene->warnings, &scene->warning_cap, (size_t)scene->warning_count + 1,
                                sizeof *scene->warnings)) {
        free(copy);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory");
    }
    scene->warnings[scene->warning_count++] = copy;
    return GLINT_OK;
}

int glint_scene_warning_count(const glint_scene *scene)
{
    return scene ? scene->warning_count : 0;
}

const char *glint_scene_warning(const glint_scene *scene, int index)
{
    return scene && index >= 0 && index < scene->warning_count ? scene->warnings[index] : NULL;
}

void scene_files_free(glint_scene *scene)
{
    for (int i = 0; i < scene->warning_count; i++)
        free(scene->warnings[i]);
    free(scene->warnings);
    file_set_free(&scene->inputs);
}
